// Fuzz target: the Envelope decoder and every reader a receiver applies to a decoded message
// (the arrays with and without the expected size, the finite check, vectors, rigid-body poses,
// the topology). Bad bytes must come back as a MalformedMessage or a MalformedMessageError,
// never as a crash, an undefined behaviour or another exception.

#include "FuzzFrames.hpp"
#include "proto/BodyPose.hpp"
#include "proto/EnvelopeCodec.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/TransportError.hpp"

#include <cstdlib>

namespace {

using namespace fsi::proto;

template <class F> void expect_rejected_or_fine(F &&read) {
  try {
    read();
  } catch (const MalformedMessageError &) {
  }
}

void read_arrays(const Message &message, const ArrayFrame &field) {
  expect_rejected_or_fine([&] { (void)message.points(field, "fuzz"); });
  const Eigen::Index n = static_cast<Eigen::Index>(field.n_values() / 3);
  expect_rejected_or_fine([&] { (void)message.points(field, n, "fuzz").sum(); });
  expect_rejected_or_fine([&] { (void)message.finite_points(field, n, "fuzz"); });
  expect_rejected_or_fine([&] { (void)message.finite_points(field, n + 1, "fuzz"); });
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  auto frames = fsi::fuzz::split_frames(data, size);
  if (frames.empty())
    return 0;
  Message message;
  if (EnvelopeCodec::decode_into(frames, 0, message))
    return 0; // malformed, and said why: fine
  const Envelope &e = message.envelope();
  (void)body_name(e);
  (void)role_name(e.sender_role());
  if (e.has_advance_reply()) {
    read_arrays(message, e.advance_reply().position_m());
    read_arrays(message, e.advance_reply().velocity_m_per_s());
    for (const auto &load : e.advance_reply().rigid_body_loads()) {
      expect_rejected_or_fine([&] { (void)read_vector3(load.force_n(), "force_n"); });
      expect_rejected_or_fine([&] { (void)read_vector3(load.torque_n_m(), "torque_n_m"); });
    }
  }
  if (e.has_interpolate_reply())
    read_arrays(message, e.interpolate_reply().velocity_m_per_s());
  if (e.has_interpolate_request()) {
    read_arrays(message, e.interpolate_request().position_m());
    for (const auto &pose : e.interpolate_request().rigid_bodies())
      expect_rejected_or_fine([&] { (void)read_body_pose(pose); });
  }
  if (e.has_fluid_advance()) {
    read_arrays(message, e.fluid_advance().force_density_n_per_measure());
    for (const auto &pose : e.fluid_advance().rigid_bodies())
      expect_rejected_or_fine([&] { (void)read_body_pose(pose); });
  }
  if (e.has_structure_advance()) {
    read_arrays(message, e.structure_advance().load_density_n_per_measure());
    for (const auto &pose : e.structure_advance().rigid_bodies())
      expect_rejected_or_fine([&] { (void)read_body_pose(pose); });
  }
  if (e.has_hello())
    for (const auto &s : e.hello().structures())
      (void)(s.n1() * s.n2() == static_cast<std::uint64_t>(s.point_measure_size()));
  for (std::size_t i = 1; i <= message.array_frame_count(); ++i)
    (void)message.array_frame(i).size();
  return 0;
}
