// Array frames of a message <-> N x 3 point arrays (layout, views in place, size checks); small
// packed fields <-> vectors and rotations.

#include "proto/Message.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/Protocol.hpp"
#include "proto/TransportError.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>

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

TEST(MessageArrays, AFrameIsPointMajorDoubles) {
  Message message = make_envelope(v2::ROLE_COUPLER, 1);
  auto &ref = *message.envelope().mutable_interpolate_request()->mutable_position_m();
  message.add_points(ref, numbered_points(2));
  EXPECT_EQ(ref.frame(), 1U);
  EXPECT_EQ(ref.n_values(), 6U);
  const std::string_view bytes = message.array_frame(1);
  ASSERT_EQ(bytes.size(), 6 * sizeof(double));
  double values[6];
  std::memcpy(values, bytes.data(), bytes.size());
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(values[i], i + 0.25); // x0 y0 z0 x1 y1 z1
  }
}

TEST(MessageArrays, AddGivesAViewIntoTheFrameThatPointsReadsInPlace) {
  Message message = make_envelope(v2::ROLE_COUPLER, 1);
  auto *body = message.envelope().mutable_advance_reply();
  MutablePointsView x = message.add_points(*body->mutable_position_m(), 3);
  x = numbered_points(3);
  // A second frame must not move the first (small frames live inside their zmq message).
  message.add_points(*body->mutable_velocity_m_per_s(), 1).setConstant(-1.0);
  EXPECT_EQ(x(2, 2), 8.25);
  const PointsView view = message.points(body->position_m(), 3, "position_m");
  EXPECT_EQ(view.data(), x.data());
  EXPECT_EQ(PointArray(view), numbered_points(3));
  EXPECT_EQ(message.points(body->velocity_m_per_s(), "velocity_m_per_s")(0, 1), -1.0);
}

TEST(MessageArrays, AnUnsetOrEmptyFieldIsZeroPoints) {
  Message message = make_envelope(v2::ROLE_STRUCTURE, 1);
  auto *body = message.envelope().mutable_advance_reply();
  EXPECT_EQ(message.points(body->velocity_m_per_s(), "velocity_m_per_s").rows(), 0);
  EXPECT_EQ(message.points(body->velocity_m_per_s(), 0, "velocity_m_per_s").rows(), 0);
  message.add_points(*body->mutable_position_m(), PointArray(0, 3));
  EXPECT_EQ(message.points(body->position_m(), 0, "position_m").rows(), 0);
}

TEST(MessageArrays, WrongSizesNameTheField) {
  Message message = make_envelope(v2::ROLE_FLUID, 1);
  auto *body = message.envelope().mutable_interpolate_reply();
  message.add_points(*body->mutable_velocity_m_per_s(), numbered_points(4));
  const std::string wrong_count =
      error_of([&] { message.points(body->velocity_m_per_s(), 5, "interpolate_reply.velocity_m_per_s"); });
  EXPECT_NE(wrong_count.find("interpolate_reply.velocity_m_per_s holds 12 values, expected 5 points x 3"),
            std::string::npos)
      << wrong_count;
  body->mutable_velocity_m_per_s()->set_n_values(7);
  const std::string not_triples = error_of([&] { message.points(body->velocity_m_per_s(), "velocity_m_per_s"); });
  EXPECT_NE(not_triples.find("velocity_m_per_s holds 7 values, not a multiple of 3"), std::string::npos)
      << not_triples;
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
  EXPECT_EQ(role_name(v2::ROLE_STRUCTURE), "structure");
  Envelope envelope = make_envelope(v2::ROLE_FLUID, 12);
  EXPECT_EQ(envelope.protocol_version(), current_protocol_version);
  EXPECT_EQ(envelope.step(), 12U);
  EXPECT_EQ(body_name(envelope), "none");
  envelope.mutable_fluid_advance();
  EXPECT_EQ(body_name(envelope), "fluid_advance");
  EXPECT_EQ(routing_id(v2::ROLE_FLUID, "main"), "fluid:main");
  EXPECT_EQ(printable(std::string("\0ab\n", 4)), "\\x00ab\\x0a");
}

} // namespace
} // namespace fsi::proto::test
