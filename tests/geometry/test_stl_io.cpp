// STL round trips (ASCII exact, binary to float precision) and every documented load error,
// each naming the file.

#include "TestGeometry.hpp"

#include "geometry/MeshErrors.hpp"
#include "geometry/StlIo.hpp"
#include "geometry/TriangleMeshSurface.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fsi::geometry {
namespace {

using FluidSide = TriangleMeshSurface::FluidSide;

/// A fresh file path in the temporary folder, removed at the end of the test.
class StlFile : public ::testing::Test {
protected:
  std::string path(const std::string &name) {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto file = std::filesystem::temp_directory_path() /
                      (std::string("fsi_collision_") + info->name() + "_" + name);
    created_.push_back(file);
    return file.string();
  }
  void TearDown() override {
    for (const auto &file : created_)
      std::filesystem::remove(file);
  }

private:
  std::vector<std::filesystem::path> created_;
};

/// Corner k of triangle t, as stored in the soup.
Vec3 corner(const TriangleSoup &soup, Eigen::Index t, int k) {
  return soup.vertices_m.row(soup.triangles(t, k)).transpose();
}

template <typename Message> void expect_names_file(const Message &error, const std::string &path) {
  EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  EXPECT_EQ(error.source(), path);
}

TEST_F(StlFile, AsciiRoundTripIsExactAndMergesVertices) {
  const TriangleSoup original = testing::test_icosphere();
  const std::string file = path("sphere_ascii.stl");
  write_stl(file, original, StlFormat::ascii);
  const TriangleSoup loaded = read_stl(file);
  ASSERT_EQ(loaded.triangles.rows(), original.triangles.rows());
  EXPECT_EQ(loaded.vertices_m.rows(), original.vertices_m.rows());
  for (Eigen::Index t = 0; t < original.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(corner(loaded, t, k), corner(original, t, k)) << "triangle " << t;
    }
  }
}

TEST_F(StlFile, BinaryRoundTripKeepsFloatPrecision) {
  const TriangleSoup original = testing::test_torus();
  const std::string file = path("torus_binary.stl");
  write_stl(file, original, StlFormat::binary);
  const TriangleSoup loaded = read_stl(file);
  ASSERT_EQ(loaded.triangles.rows(), original.triangles.rows());
  EXPECT_EQ(loaded.vertices_m.rows(), original.vertices_m.rows());
  for (Eigen::Index t = 0; t < original.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 exact = corner(original, t, k);
      const Vec3 read_back = corner(loaded, t, k);
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_EQ(read_back[axis], static_cast<double>(static_cast<float>(exact[axis])))
            << "triangle " << t;
      }
    }
  }
}

TEST_F(StlFile, SurfaceFromFileEqualsSurfaceFromArrays) {
  const TriangleSoup soup = testing::test_icosphere();
  const std::string file = path("sphere.stl");
  write_stl(file, soup, StlFormat::ascii);
  const TriangleMeshSurface from_file(file, FluidSide::outside);
  const auto from_arrays =
      TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, FluidSide::outside);
  for (const Vec3 &p : testing::random_points_around(soup, 500, 0.2, 3)) {
    EXPECT_NEAR(from_file.distance(p).signed_distance_m, from_arrays->distance(p).signed_distance_m,
                1e-12);
  }
  EXPECT_NE(from_file.describe().find(file), std::string::npos);
}

TEST_F(StlFile, MissingFileRaisesNotFoundNamingTheFile) {
  const std::string file = path("does_not_exist.stl");
  try {
    TriangleMeshSurface surface(file);
    FAIL() << "no error raised";
  } catch (const MeshFileNotFoundError &error) {
    expect_names_file(error, file);
  }
}

TEST_F(StlFile, GarbageFileRaisesUnreadableNamingTheFile) {
  const std::string file = path("garbage.stl");
  std::ofstream(file, std::ios::binary) << "\x7f\x01 this is not a mesh \xff\xfe";
  try {
    TriangleMeshSurface surface(file);
    FAIL() << "no error raised";
  } catch (const MeshFileUnreadableError &error) {
    expect_names_file(error, file);
  }
}

TEST_F(StlFile, EmptyFileRaisesUnreadable) {
  const std::string file = path("empty.stl");
  std::ofstream{file};
  EXPECT_THROW(TriangleMeshSurface{file}, MeshFileUnreadableError);
}

TEST_F(StlFile, AsciiWithBadVertexRaisesUnreadable) {
  const std::string file = path("bad_vertex.stl");
  std::ofstream(file) << "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n";
  EXPECT_THROW(read_stl(file), MeshFileUnreadableError);
}

TEST_F(StlFile, OpenMeshRaisesNotClosedWithBorderEdgeCount) {
  TriangleSoup soup = testing::test_icosphere();
  soup.triangles.conservativeResize(soup.triangles.rows() - 1, 3); // one hole: 3 border edges
  const std::string file = path("open.stl");
  write_stl(file, soup, StlFormat::binary);
  try {
    TriangleMeshSurface surface(file);
    FAIL() << "no error raised";
  } catch (const MeshNotClosedError &error) {
    expect_names_file(error, file);
    EXPECT_EQ(error.n_border_edges(), 3u);
    EXPECT_NE(std::string(error.what()).find("3 border edge"), std::string::npos) << error.what();
  }
}

TEST_F(StlFile, ZeroAreaTriangleRaisesDegenerate) {
  TriangleSoup soup = testing::test_icosphere();
  soup.vertices_m.row(soup.triangles(0, 2)) =
      0.5 * (soup.vertices_m.row(soup.triangles(0, 0)) + soup.vertices_m.row(soup.triangles(0, 1)));
  const std::string file = path("degenerate.stl");
  write_stl(file, soup, StlFormat::ascii);
  try {
    TriangleMeshSurface surface(file);
    FAIL() << "no error raised";
  } catch (const MeshDegenerateError &error) {
    expect_names_file(error, file);
  }
}

} // namespace
} // namespace fsi::geometry
