// Contact between structures (StructureContact): a point over another sheet's face, between its
// points, is moved with the face apart to d_t with the mass-weighted centre of the pair fixed; a
// point that crossed the sheet within the step is put back on its side; a point beside the
// sheet's rim is pushed straight away from it; bad grids are refused.

#include "structure_solver/collision/StructureContact.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fsi::structure::collision {
namespace {

constexpr double kSpacing = 0.01, kDc = 0.004, kDt = 0.004;

/// A 3 x 3 sheet of 1 cm spacing in the plane z = 0, and its masses.
PointArray sheet() {
  PointArray x(9, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      x.row(i * 3 + j) << i * kSpacing, j * kSpacing, 0.0;
  return x;
}

/// The sheet (body 0, 1e-4 kg a point) and one free point (body 1, a 1 x 1 filament, 2e-4 kg).
StructureContact sheet_and_point() {
  return StructureContact({{3, 3, Eigen::VectorXd::Constant(9, 1e-4)}, {1, 1, Eigen::VectorXd::Constant(1, 2e-4)}},
                          kDc, kDt);
}

Vec3 mass_centre(const std::vector<PointArray> &x) {
  return (1e-4 * x[0].colwise().sum() + 2e-4 * x[1].row(0)).transpose() / (9e-4 + 2e-4);
}

/// Height of p over the sheet's triangle (0, 3, 4) (the quad at the origin, the half x > y) at
/// p's x, y: the contact moves points along z only, so the face's point there keeps its
/// barycentric coordinates.
double height_over_face(const std::vector<PointArray> &x, const Vec3 &p) {
  const double w_c = p.y() / kSpacing, w_b = (p.x() - p.y()) / kSpacing, w_a = 1.0 - p.x() / kSpacing;
  return p.z() - (w_a * x[0](0, 2) + w_b * x[0](3, 2) + w_c * x[0](4, 2));
}

TEST(StructureContact, APointBetweenASheetsPointsIsMovedWithItsFaceToTheTargetDistance) {
  // 1 mm over the face, more than 5 mm from each of the sheet's points: point pairs (self-
  // collision's rule) would not see it, d_c = 4 mm.
  const Vec3 p(0.006, 0.004, 0.001);
  std::vector<PointArray> x{sheet(), PointArray(p.transpose())};
  std::vector<PointArray> start{sheet(), PointArray(Vec3(0.006, 0.004, 0.01).transpose())};
  for (int k = 0; k < 9; ++k)
    ASSERT_GT((x[0].row(k).transpose() - p).norm(), kDc + 0.001);
  const Vec3 centre = mass_centre(x);
  const auto stats = sheet_and_point().correct(x, start);
  EXPECT_EQ(stats.n_contacts, 1u);
  EXPECT_EQ(stats.n_crossings, 0u);
  EXPECT_NEAR(height_over_face(x, x[1].row(0).transpose()), kDt, 1e-12);
  // Mass-weighted centre fixed: the 3 mm separation is shared between point and face.
  EXPECT_NEAR((mass_centre(x) - centre).norm(), 0.0, 1e-15);
  EXPECT_GT(x[1](0, 2), 0.001);
  EXPECT_LT(x[0].col(2).minCoeff(), 0.0);
  // Only z moves, and only the face's three points.
  EXPECT_NEAR(x[1](0, 0), 0.006, 1e-15);
  for (int k : {1, 2, 5, 6, 7, 8})
    EXPECT_EQ(x[0](k, 2), 0.0) << k;
}

TEST(StructureContact, APointThatCrossedTheSheetInTheStepIsPutBackOnItsSide) {
  std::vector<PointArray> x{sheet(), PointArray(Vec3(0.006, 0.004, -0.001).transpose())};
  const std::vector<PointArray> start{sheet(), PointArray(Vec3(0.006, 0.004, 0.002).transpose())};
  const auto stats = sheet_and_point().correct(x, start);
  EXPECT_EQ(stats.n_crossings, 1u);
  EXPECT_NEAR(height_over_face(x, x[1].row(0).transpose()), kDt, 1e-12); // above, where it came from
  // From below it would have been pushed further down.
  x = {sheet(), PointArray(Vec3(0.006, 0.004, -0.001).transpose())};
  const std::vector<PointArray> from_below{sheet(), PointArray(Vec3(0.006, 0.004, -0.002).transpose())};
  EXPECT_EQ(sheet_and_point().correct(x, from_below).n_crossings, 0u);
  EXPECT_NEAR(height_over_face(x, x[1].row(0).transpose()), -kDt, 1e-12);
}

TEST(StructureContact, APointBesideTheRimIsPushedStraightAway) {
  // 2 mm beyond the edge x = 0, in the sheet's plane.
  std::vector<PointArray> x{sheet(), PointArray(Vec3(-0.002, 0.013, 0.0).transpose())};
  const std::vector<PointArray> start = x;
  sheet_and_point().correct(x, start);
  EXPECT_NEAR(x[1](0, 1), 0.013, 1e-15);
  EXPECT_NEAR(x[1](0, 2), 0.0, 1e-15);
  // The rim's point at y = 0.013 (0.7 of point 1, 0.3 of point 2) moved with it, the other way.
  EXPECT_NEAR(x[1](0, 0) - (0.7 * x[0](1, 0) + 0.3 * x[0](2, 0)), -kDt, 1e-12);
  EXPECT_GT(x[0](1, 0), 0.0);
}

TEST(StructureContact, PointsFarFromOtherSheetsAndPointsOfTheSameSheetAreLeftAlone) {
  std::vector<PointArray> x{sheet(), PointArray(Vec3(0.006, 0.004, 0.0045).transpose())};
  const std::vector<PointArray> start = x;
  EXPECT_EQ(sheet_and_point().correct(x, start).n_contacts, 0u);
  EXPECT_EQ(x[0], sheet());
  // A single sheet has nothing to touch, however folded.
  StructureContact alone({{3, 3, Eigen::VectorXd::Constant(9, 1e-4)}}, kDc, kDt);
  std::vector<PointArray> folded{sheet()};
  folded[0](8, 2) = 0.0; // all coplanar: its own points are not contacts
  EXPECT_EQ(alone.correct(folded, folded).n_contacts, 0u);
}

TEST(StructureContact, BadInputIsRefused) {
  EXPECT_THROW(StructureContact({{3, 3, Eigen::VectorXd::Constant(8, 1e-4)}}, kDc, kDt), std::invalid_argument);
  EXPECT_THROW(StructureContact({{3, 3, Eigen::VectorXd::Zero(9)}}, kDc, kDt), std::invalid_argument);
  EXPECT_THROW(StructureContact({{3, 3, Eigen::VectorXd::Constant(9, 1e-4)}}, kDc, 0.5 * kDc), std::invalid_argument);
  std::vector<PointArray> x{sheet()};
  EXPECT_THROW(sheet_and_point().correct(x, x), std::invalid_argument);
}

} // namespace
} // namespace fsi::structure::collision
