#include "SampleEnvelopes.hpp"

#include <cmath>
#include <limits>

namespace fsi::proto::test {

namespace {

using Limits = std::numeric_limits<double>;

const std::vector<double> tricky_values = {
    0.1,      -0.0, 1e300,    -Limits::max(), Limits::denorm_min(), 3.141592653589793,
    -2.5e-12, 42.0, 1.0 / 3.0};

void fill(google::protobuf::RepeatedField<double> *field, std::size_t n, double offset = 0.0) {
  for (std::size_t i = 0; i < n; ++i) {
    field->Add(tricky_values[i % tricky_values.size()] + offset * static_cast<double>(i));
  }
}

/// A frame of n values (a multiple of 3) for `field`, the tricky values spread as in fill().
void fill(Message &message, ArrayFrame *field, std::size_t n, double offset = 0.0) {
  auto points = message.add_points(*field, static_cast<Eigen::Index>(n / 3));
  for (std::size_t i = 0; i < n; ++i) {
    points.data()[i] = tricky_values[i % tricky_values.size()] + offset * static_cast<double>(i);
  }
}

void fill_topology(v2::StructureTopology *topology, const char *name) {
  topology->set_name(name);
  topology->set_model("membrane");
  topology->set_n1(std::numeric_limits<std::uint32_t>::max());
  topology->set_n2(7);
  fill(topology->mutable_point_measure(), 5, 1e-3);
}

void fill_pose(v2::RigidBodyPose *pose) {
  pose->set_name("pôle");
  fill(pose->mutable_rotation(), 9);
  fill(pose->mutable_translation_m(), 3, 0.5);
  fill(pose->mutable_angular_velocity_rad_per_s(), 3, -1.0);
  fill(pose->mutable_linear_velocity_m_per_s(), 3, 2.0);
}

Message stamped(std::uint64_t step) { return make_envelope(v2::ROLE_COUPLER, step); }

Envelope hello() {
  Envelope e = make_envelope(v2::ROLE_STRUCTURE, 0);
  auto *body = e.mutable_hello();
  body->set_role(v2::ROLE_STRUCTURE);
  body->set_participant_name("drapeau ✓");
  body->set_protocol_version(current_protocol_version);
  body->set_case_fingerprint("sha256:0123456789abcdef");
  fill_topology(body->add_structures(), "flag");
  fill_topology(body->add_structures(), "filament");
  return e;
}

Envelope welcome() {
  Envelope e = make_envelope(v2::ROLE_COUPLER, 0);
  auto *body = e.mutable_welcome();
  body->set_time_step_s(1e-5);
  body->set_n_steps(std::numeric_limits<std::uint64_t>::max());
  fill_topology(body->add_structures(), "flag");
  body->set_heartbeat_interval_s(0.25);
  body->set_timeout_s(30.0);
  body->set_first_step(1250);
  body->set_checkpoint_checksum("fedcba9876543210");
  return e;
}

Message interpolate_request() {
  Message e = stamped(17);
  auto *body = e.envelope().mutable_interpolate_request();
  body->set_time_s(0.125);
  fill_pose(body->add_rigid_bodies());
  fill_pose(body->add_rigid_bodies());
  fill(e, body->mutable_position_m(), 30, 0.01);
  return e;
}

Message interpolate_reply() {
  Message e = make_envelope(v2::ROLE_FLUID, 17);
  fill(e, e.envelope().mutable_interpolate_reply()->mutable_velocity_m_per_s(), 30, -0.02);
  return e;
}

Message fluid_advance() {
  Message e = stamped(18);
  auto *body = e.envelope().mutable_fluid_advance();
  body->set_time_s(0.125);
  body->set_dt_s(1e-5);
  fill(e, body->mutable_force_density_n_per_measure(), 30, 3.0);
  return e;
}

Message structure_advance() {
  Message e = stamped(18);
  auto *body = e.envelope().mutable_structure_advance();
  body->set_time_s(0.125);
  body->set_dt_s(1e-5);
  fill(e, body->mutable_load_density_n_per_measure(), 30, -3.0);
  fill_pose(body->add_rigid_bodies());
  return e;
}

Message advance_reply() {
  Message e = make_envelope(v2::ROLE_STRUCTURE, 18);
  auto *body = e.envelope().mutable_advance_reply();
  body->set_time_s(0.12501);
  fill(e, body->mutable_position_m(), 30, 0.01);
  fill(e, body->mutable_velocity_m_per_s(), 30, 0.5);
  body->set_solve_wall_s(0.003);
  auto *load = body->add_rigid_body_loads();
  load->set_name("pole");
  fill(load->mutable_force_n(), 3, 1.0);
  fill(load->mutable_torque_n_m(), 3, -1.0);
  return e;
}

Envelope heartbeat() {
  Envelope e = make_envelope(v2::ROLE_FLUID, 19);
  e.mutable_heartbeat()->set_wall_time_s(1.7e9);
  return e;
}

Envelope error_report() {
  Envelope e = make_envelope(v2::ROLE_FLUID, 20);
  auto *body = e.mutable_error();
  body->set_message("fluid 'main' at step 20: the pressure solver diverged; reduce dt_s");
  body->set_fatal(true);
  return e;
}

Envelope shutdown() {
  Envelope e = make_envelope(v2::ROLE_COUPLER, 21);
  auto *body = e.mutable_shutdown();
  body->set_reason("end of run");
  body->set_success(true);
  return e;
}

Envelope checkpoint_request() {
  Envelope e = make_envelope(v2::ROLE_COUPLER, 500);
  e.mutable_checkpoint_request();
  return e;
}

Envelope checkpoint_done() {
  Envelope e = make_envelope(v2::ROLE_STRUCTURE, 500);
  auto *body = e.mutable_checkpoint_done();
  body->set_part("structure.ckpt");
  body->set_checksum("0123456789abcdef");
  return e;
}

} // namespace

std::vector<Message> sample_messages() {
  std::vector<Message> messages;
  messages.emplace_back(hello());
  messages.emplace_back(welcome());
  messages.push_back(interpolate_request());
  messages.push_back(interpolate_reply());
  messages.push_back(fluid_advance());
  messages.push_back(structure_advance());
  messages.push_back(advance_reply());
  messages.emplace_back(heartbeat());
  messages.emplace_back(error_report());
  messages.emplace_back(shutdown());
  messages.emplace_back(checkpoint_request());
  messages.emplace_back(checkpoint_done());
  return messages;
}

bool same_bytes(const Message &a, const Message &b) {
  if (a.envelope().SerializeAsString() != b.envelope().SerializeAsString() ||
      a.array_frame_count() != b.array_frame_count()) {
    return false;
  }
  for (std::size_t frame = 1; frame <= a.array_frame_count(); ++frame) {
    if (a.array_frame(frame) != b.array_frame(frame)) {
      return false;
    }
  }
  return true;
}

} // namespace fsi::proto::test
