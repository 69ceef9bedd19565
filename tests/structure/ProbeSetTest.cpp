// The probes' values from the point arrays alone: the centroid is the measure-weighted mean
// (the centre of mass), an edge centre the trapezoid-weighted mean along the edge as it is now
// (the midpoint of the edge however unevenly its points are spaced), a filament end and a grid
// point are those points; velocities use the same weights.

#include "structure_solver/LagrangianGrid.hpp"
#include "structure_solver/ProbeSet.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fsi::structure {
namespace {

constexpr double tolerance = 1e-12;

ProbeConfig probe(const std::string &name, const std::string &structure, ProbeLocation at, const std::string &edge = "",
                  std::vector<int> index = {}) {
  ProbeConfig config;
  config.name = name;
  config.structure = structure;
  config.at = at;
  config.edge = edge;
  config.index = std::move(index);
  return config;
}

ProbedStructure sheet_grid(const std::string &name, int n1, int n2, double length_1_m, double length_2_m) {
  return {name, n1, n2, LagrangianGrid(n1, n2, length_1_m, length_2_m).point_measures()};
}

/// A flat sheet on its rest grid: point (i1, i2) at origin + (i1 ds1, i2 ds2, 0).
PointArray flat_sheet(int n1, int n2, double ds1, double ds2, const Vec3 &origin) {
  PointArray x(n1 * n2, 3);
  for (int i1 = 0; i1 < n1; ++i1)
    for (int i2 = 0; i2 < n2; ++i2)
      x.row(i1 * n2 + i2) = (origin + Vec3(i1 * ds1, i2 * ds2, 0.0)).transpose();
  return x;
}

PointArray uniform(int n_points, const Vec3 &value) {
  PointArray v(n_points, 3);
  v.rowwise() = value.transpose();
  return v;
}

void expect_near(const Vec3 &actual, const Vec3 &expected) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(actual[k], expected[k], tolerance) << "component " << k << ": " << actual.transpose();
}

TEST(ProbeSet, CentroidOfAUniformSheetTranslatedWithUniformVelocity) {
  const ProbeSet probes({probe("c", "sheet", ProbeLocation::centroid)}, {sheet_grid("sheet", 5, 4, 0.4, 0.3)});
  const Vec3 translation(1.0, 2.0, 3.0), velocity(0.5, -0.2, 0.1);
  const PointArray x = flat_sheet(5, 4, 0.1, 0.1, translation), v = uniform(20, velocity);
  const auto samples = probes.sample({&x}, {&v});
  ASSERT_EQ(samples.size(), 1u);
  expect_near(samples[0].position_m, translation + Vec3(0.2, 0.15, 0.0));
  expect_near(samples[0].velocity_m_per_s, velocity);
}

TEST(ProbeSet, CentroidWeightsEachPointByTheMeasureItCarries) {
  // 3 x 3 points, spacing 1 m: measures 1/4 (corners), 1/2 (edges), 1 (centre), total 4 m^2.
  // Lifting the corner (0, 0) by 4 m moves the centre of mass by 1/4 * 4 / 4 = 0.25 m (a plain
  // mean of the points would give 4/9 m).
  const ProbeSet probes({probe("c", "sheet", ProbeLocation::centroid)}, {sheet_grid("sheet", 3, 3, 2.0, 2.0)});
  PointArray x = flat_sheet(3, 3, 1.0, 1.0, Vec3::Zero());
  PointArray v = uniform(9, Vec3::Zero());
  x(0, 2) = 4.0;
  v(0, 2) = 8.0;
  const auto samples = probes.sample({&x}, {&v});
  EXPECT_NEAR(samples[0].position_m.z(), 0.25, tolerance);
  EXPECT_NEAR(samples[0].velocity_m_per_s.z(), 0.5, tolerance);
}

TEST(ProbeSet, EdgeCentreOfAnUnevenlySpacedEdgeIsTheMidpointOfTheEdge) {
  // Edge s1_max of a 3 x 4 sheet: points (2, 0..3), here moved to x = 0, 0.1, 0.5, 1 on a
  // straight line. Trapezoid weights 0.05, 0.25, 0.45, 0.25: the centre is at x = 0.5 (the plain
  // mean would be 0.4) and the velocity w = 0, 1, 2, 3 averages to 1.9.
  const ProbeSet probes({probe("e", "sheet", ProbeLocation::edge_centre, "s1_max")}, {sheet_grid("sheet", 3, 4, 1, 1)});
  PointArray x = flat_sheet(3, 4, 0.5, 1.0 / 3.0, Vec3::Zero());
  PointArray v = uniform(12, Vec3(1.0, 0.0, 0.0));
  const double along[4] = {0.0, 0.1, 0.5, 1.0};
  for (int i2 = 0; i2 < 4; ++i2) {
    x.row(2 * 4 + i2) << along[i2], 0.2, 0.7;
    v(2 * 4 + i2, 2) = i2;
  }
  const auto samples = probes.sample({&x}, {&v});
  expect_near(samples[0].position_m, Vec3(0.5, 0.2, 0.7));
  expect_near(samples[0].velocity_m_per_s, Vec3(1.0, 0.0, 1.9));
}

TEST(ProbeSet, EachEdgeNameSelectsItsEdge) {
  // A flat 3 x 4 sheet with ds1 = 1, ds2 = 2: s1 runs along x, s2 along y.
  const std::vector<ProbeConfig> configs = {probe("a", "sheet", ProbeLocation::edge_centre, "s1_min"),
                                            probe("b", "sheet", ProbeLocation::edge_centre, "s1_max"),
                                            probe("c", "sheet", ProbeLocation::edge_centre, "s2_min"),
                                            probe("d", "sheet", ProbeLocation::edge_centre, "s2_max")};
  const ProbeSet probes(configs, {sheet_grid("sheet", 3, 4, 2.0, 6.0)});
  const PointArray x = flat_sheet(3, 4, 1.0, 2.0, Vec3::Zero()), v = uniform(12, Vec3::Zero());
  const auto samples = probes.sample({&x}, {&v});
  expect_near(samples[0].position_m, Vec3(0.0, 3.0, 0.0));
  expect_near(samples[1].position_m, Vec3(2.0, 3.0, 0.0));
  expect_near(samples[2].position_m, Vec3(1.0, 0.0, 0.0));
  expect_near(samples[3].position_m, Vec3(1.0, 6.0, 0.0));
  EXPECT_EQ(probes.names(), (std::vector<std::string>{"a", "b", "c", "d"}));
}

TEST(ProbeSet, FilamentEndsAndGridPointsAreThosePoints) {
  // A hanging filament of 5 points (structure 1) beside a sheet (structure 0): probes read the
  // arrays of their own structure.
  const std::vector<ProbeConfig> configs = {probe("tip", "chain", ProbeLocation::edge_centre, "end"),
                                            probe("top", "chain", ProbeLocation::edge_centre, "start"),
                                            probe("third", "chain", ProbeLocation::point, "", {2}),
                                            probe("corner", "sheet", ProbeLocation::point, "", {1, 2})};
  const ProbedStructure chain{"chain", 5, 1, Eigen::VectorXd::Constant(5, 0.25)};
  const ProbeSet probes(configs, {sheet_grid("sheet", 3, 4, 1, 1), chain});
  PointArray chain_x(5, 3), chain_v(5, 3);
  for (int i = 0; i < 5; ++i) {
    chain_x.row(i) << 0.1 * i * i, 0.0, -0.25 * i;
    chain_v.row(i) << 0.3 * i, -0.1, 0.0;
  }
  const PointArray sheet_x = flat_sheet(3, 4, 1.0, 1.0, Vec3(0, 0, 1)), sheet_v = uniform(12, Vec3(0, 0, -1));
  const auto samples = probes.sample({&sheet_x, &chain_x}, {&sheet_v, &chain_v});
  expect_near(samples[0].position_m, Vec3(1.6, 0.0, -1.0));
  expect_near(samples[0].velocity_m_per_s, Vec3(1.2, -0.1, 0.0));
  expect_near(samples[1].position_m, Vec3::Zero());
  expect_near(samples[2].position_m, Vec3(0.4, 0.0, -0.5));
  expect_near(samples[3].position_m, Vec3(1.0, 2.0, 1.0));
  expect_near(samples[3].velocity_m_per_s, Vec3(0.0, 0.0, -1.0));
}

TEST(ProbeSet, WithoutProbesItIsEmpty) {
  const ProbeSet probes({}, {sheet_grid("sheet", 3, 3, 1, 1)});
  EXPECT_TRUE(probes.empty());
  const PointArray x = flat_sheet(3, 3, 1, 1, Vec3::Zero());
  EXPECT_TRUE(probes.sample({&x}, {&x}).empty());
}

TEST(ProbeSet, AProbeOnAMissingStructureOrEdgeIsAProgrammerError) {
  EXPECT_THROW(ProbeSet({probe("c", "nope", ProbeLocation::centroid)}, {sheet_grid("sheet", 3, 3, 1, 1)}),
               std::invalid_argument);
  EXPECT_THROW(ProbeSet({probe("e", "sheet", ProbeLocation::edge_centre, "end")}, {sheet_grid("sheet", 3, 3, 1, 1)}),
               std::invalid_argument);
  EXPECT_THROW(ProbeSet({probe("p", "sheet", ProbeLocation::point, "", {3, 0})}, {sheet_grid("sheet", 3, 3, 1, 1)}),
               std::invalid_argument);
}

} // namespace
} // namespace fsi::structure
