#include "geometry/StlIo.hpp"

#include "geometry/MeshErrors.hpp"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace fsi::geometry {
namespace {

constexpr std::size_t kBinaryHeaderBytes = 84; // 80-byte header + uint32 triangle count
constexpr std::size_t kBinaryFacetBytes = 50;  // 12 floats + uint16 attribute

using Corner = std::array<double, 3>;

struct CornerHash {
  std::size_t operator()(const Corner &c) const {
    std::size_t seed = 0;
    for (double value : c) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &value, sizeof bits);
      seed ^= std::hash<std::uint64_t>{}(bits) + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
    }
    return seed;
  }
};

/// Turns a list of triangle corners (3 per triangle) into an indexed mesh, merging corners
/// with identical coordinates (-0.0 and 0.0 are the same corner).
TriangleSoup weld_corners(const std::vector<Corner> &corners) {
  std::unordered_map<Corner, int, CornerHash> index_of;
  std::vector<Corner> unique;
  TriangleSoup soup;
  soup.triangles.resize(static_cast<Eigen::Index>(corners.size() / 3), 3);
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Corner c{corners[k][0] + 0.0, corners[k][1] + 0.0, corners[k][2] + 0.0};
    const auto [it, inserted] = index_of.emplace(c, static_cast<int>(unique.size()));
    if (inserted) {
      unique.push_back(c);
    }
    soup.triangles(static_cast<Eigen::Index>(k / 3), static_cast<Eigen::Index>(k % 3)) = it->second;
  }
  soup.vertices_m.resize(static_cast<Eigen::Index>(unique.size()), 3);
  for (std::size_t v = 0; v < unique.size(); ++v) {
    soup.vertices_m.row(static_cast<Eigen::Index>(v)) << unique[v][0], unique[v][1], unique[v][2];
  }
  return soup;
}

std::string read_all_bytes(const std::string &path) {
  if (!std::filesystem::exists(path)) {
    throw MeshFileNotFoundError(path);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw MeshFileUnreadableError(path, "it cannot be opened for reading");
  }
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool looks_binary(const std::string &bytes) {
  if (bytes.size() < kBinaryHeaderBytes) {
    return false;
  }
  std::uint32_t n_triangles = 0;
  std::memcpy(&n_triangles, bytes.data() + 80, sizeof n_triangles); // little-endian host
  return bytes.size() == kBinaryHeaderBytes + kBinaryFacetBytes * std::size_t{n_triangles};
}

std::vector<Corner> parse_binary(const std::string &bytes) {
  const std::size_t n_triangles = (bytes.size() - kBinaryHeaderBytes) / kBinaryFacetBytes;
  std::vector<Corner> corners;
  corners.reserve(3 * n_triangles);
  for (std::size_t t = 0; t < n_triangles; ++t) {
    const char *facet = bytes.data() + kBinaryHeaderBytes + t * kBinaryFacetBytes;
    for (int corner = 0; corner < 3; ++corner) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 * (corner + 1), sizeof xyz); // skip the facet normal
      corners.push_back({xyz[0], xyz[1], xyz[2]});
    }
  }
  return corners;
}

std::vector<Corner> parse_ascii(const std::string &bytes, const std::string &path) {
  std::istringstream in(bytes);
  std::string word;
  if (!(in >> word) || word != "solid") {
    throw MeshFileUnreadableError(path, "it is neither binary STL nor ASCII STL starting "
                                        "with 'solid'");
  }
  std::vector<Corner> corners;
  while (in >> word) {
    if (word != "vertex") {
      continue;
    }
    Corner c{};
    if (!(in >> c[0] >> c[1] >> c[2])) {
      throw MeshFileUnreadableError(path, "vertex " + std::to_string(corners.size() + 1) +
                                              " does not have three numeric coordinates");
    }
    corners.push_back(c);
  }
  if (corners.size() % 3 != 0) {
    throw MeshFileUnreadableError(path, "its vertex count " + std::to_string(corners.size()) +
                                            " is not a multiple of three");
  }
  return corners;
}

void append_float(std::string &out, float value) {
  char raw[sizeof value];
  std::memcpy(raw, &value, sizeof value);
  out.append(raw, sizeof value);
}

Vec3 facet_normal(const TriangleSoup &soup, Eigen::Index t) {
  const Vec3 a = soup.vertices_m.row(soup.triangles(t, 0)).transpose();
  const Vec3 b = soup.vertices_m.row(soup.triangles(t, 1)).transpose();
  const Vec3 c = soup.vertices_m.row(soup.triangles(t, 2)).transpose();
  const Vec3 n = (b - a).cross(c - a);
  return n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
}

std::string encode_binary(const TriangleSoup &soup) {
  std::string out(80, '\0');
  std::memcpy(out.data(), "binary STL written by fsi_collision", 35);
  const auto n_triangles = static_cast<std::uint32_t>(soup.triangles.rows());
  out.append(reinterpret_cast<const char *>(&n_triangles), sizeof n_triangles);
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    const Vec3 n = facet_normal(soup, t);
    for (int k = 0; k < 3; ++k)
      append_float(out, static_cast<float>(n[k]));
    for (int corner = 0; corner < 3; ++corner) {
      for (int k = 0; k < 3; ++k) {
        append_float(out, static_cast<float>(soup.vertices_m(soup.triangles(t, corner), k)));
      }
    }
    out.append(2, '\0'); // attribute byte count
  }
  return out;
}

std::string encode_ascii(const TriangleSoup &soup) {
  std::ostringstream out;
  out.precision(17);
  out << "solid fsi_collision\n";
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    const Vec3 n = facet_normal(soup, t);
    out << "  facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n    outer loop\n";
    for (int corner = 0; corner < 3; ++corner) {
      const auto row = soup.vertices_m.row(soup.triangles(t, corner));
      out << "      vertex " << row(0) << ' ' << row(1) << ' ' << row(2) << '\n';
    }
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid fsi_collision\n";
  return out.str();
}

} // namespace

TriangleSoup read_stl(const std::string &path) {
  const std::string bytes = read_all_bytes(path);
  if (bytes.empty()) {
    throw MeshFileUnreadableError(path, "the file is empty");
  }
  const std::vector<Corner> corners =
      looks_binary(bytes) ? parse_binary(bytes) : parse_ascii(bytes, path);
  if (corners.empty()) {
    throw MeshFileUnreadableError(path, "it contains no triangle");
  }
  return weld_corners(corners);
}

void write_stl(const std::string &path, const TriangleSoup &soup, StlFormat format) {
  std::ofstream out(path, std::ios::binary);
  const std::string bytes = format == StlFormat::binary ? encode_binary(soup) : encode_ascii(soup);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    throw std::runtime_error("cannot write STL file '" + path +
                             "'; check that the folder exists and is writable.");
  }
}

} // namespace fsi::geometry
