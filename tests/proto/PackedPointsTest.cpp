// Packed double fields <-> N x 3 point arrays: layout, zero-copy views, size checks.

#include "proto/PackedPoints.hpp"
#include "proto/Protocol.hpp"
#include "proto/TransportError.hpp"

#include <gtest/gtest.h>

namespace fsi::proto::test {
namespace {

PointArray numbered_points(Eigen::Index n_points) {
  PointArray points(n_points, 3);
  for (Eigen::Index i = 0; i < points.size(); ++i) {
    points.data()[i] = static_cast<double>(i) + 0.25;
  }
  return points;
}

std::string error_of(const std::function<void()> &f) {
  try {
    f();
  } catch (const MalformedMessageError &error) {
    return error.what();
  }
  return "";
}

TEST(PackedPoints, WriteIsPointMajor) {
  PackedDoubles field;
  field.Add(99.0); // replaced, not appended to
  write_points(numbered_points(2), field);
  ASSERT_EQ(field.size(), 6);
  EXPECT_EQ(field.Get(0), 0.25); // x0
  EXPECT_EQ(field.Get(1), 1.25); // y0
  EXPECT_EQ(field.Get(3), 3.25); // x1
}

TEST(PackedPoints, ViewReadsInPlaceWithoutCopying) {
  PackedDoubles field;
  write_points(numbered_points(4), field);
  const PointsView view = view_points(field, 4, "position_m");
  EXPECT_EQ(view.data(), field.data());
  EXPECT_EQ(view(3, 2), 11.25);
  EXPECT_EQ(view_points(field, "position_m").rows(), 4);
}

TEST(PackedPoints, ResizeGivesAViewToFillInPlace) {
  PackedDoubles field;
  MutablePointsView view = resize_points(field, 3);
  view = numbered_points(3);
  EXPECT_EQ(field.size(), 9);
  EXPECT_EQ(field.Get(8), 8.25);
}

TEST(PackedPoints, ReadCopiesIntoAnArrayOfAnySize) {
  PackedDoubles field;
  write_points(numbered_points(5), field);
  PointArray points(1, 3);
  read_points(field, 5, "position_m", points);
  EXPECT_EQ(points, numbered_points(5));
  read_points(field, "position_m", points);
  EXPECT_EQ(points, numbered_points(5));
}

TEST(PackedPoints, EmptyFieldsAreZeroPoints) {
  PackedDoubles field;
  write_points(PointArray(0, 3), field);
  EXPECT_EQ(field.size(), 0);
  EXPECT_EQ(view_points(field, "position_m").rows(), 0);
  EXPECT_EQ(view_points(field, 0, "position_m").rows(), 0);
}

TEST(PackedPoints, WrongSizesNameTheField) {
  PackedDoubles field;
  for (int i = 0; i < 7; ++i) {
    field.Add(1.0);
  }
  const std::string not_triples = error_of([&] { view_points(field, "advance_reply.position_m"); });
  EXPECT_NE(not_triples.find("advance_reply.position_m holds 7 values"), std::string::npos)
      << not_triples;
  EXPECT_NE(not_triples.find("multiple of 3"), std::string::npos) << not_triples;

  write_points(numbered_points(4), field);
  const std::string wrong_count =
      error_of([&] { view_points(field, 5, "interpolate_reply.velocity_m_per_s"); });
  EXPECT_NE(wrong_count.find("interpolate_reply.velocity_m_per_s holds 12 values, expected 15"),
            std::string::npos)
      << wrong_count;
}

TEST(PackedPoints, VectorsAndRotationsRoundTrip) {
  PackedDoubles field;
  write_vector3(Vec3(1.0, -2.0, 3.5), field);
  EXPECT_EQ(read_vector3(field, "translation_m"), Vec3(1.0, -2.0, 3.5));

  Eigen::Matrix3d rotation;
  rotation << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  write_matrix3(rotation, field);
  EXPECT_EQ(field.Get(1), 2.0); // row-major on the wire
  EXPECT_EQ(read_matrix3(field, "rotation"), rotation);
  EXPECT_NE(error_of([&] { read_vector3(field, "translation_m"); }).find("translation_m"),
            std::string::npos);
}

TEST(Protocol, NamesRolesBodiesAndPeers) {
  EXPECT_EQ(role_name(v1::ROLE_STRUCTURE), "structure");
  Envelope envelope = make_envelope(v1::ROLE_FLUID, 12);
  EXPECT_EQ(envelope.protocol_version(), current_protocol_version);
  EXPECT_EQ(envelope.step(), 12U);
  EXPECT_EQ(body_name(envelope), "none");
  envelope.mutable_fluid_advance();
  EXPECT_EQ(body_name(envelope), "fluid_advance");
  EXPECT_EQ(routing_id(v1::ROLE_FLUID, "main"), "fluid:main");
  EXPECT_EQ(printable(std::string("\0ab\n", 4)), "\\x00ab\\x0a");
}

} // namespace
} // namespace fsi::proto::test
