// make_fuzz_seeds OUT_DIR: writes the seed corpus of the message fuzz targets, one file per
// valid message of each kind (the bodies the coupler and the participants exchange, with their
// array frames), in the frame format of FuzzFrames.hpp: OUT_DIR/envelope/<kind> and
// OUT_DIR/coupler_channel/<peer>-<kind> (first byte: the sending peer). Run it again when the
// protocol changes, and commit the result (tests/fuzz/corpus/).

#include "FuzzFrames.hpp"
#include "proto/BodyPose.hpp"
#include "proto/EnvelopeCodec.hpp"
#include "proto/Message.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>

namespace {

using namespace fsi;
using namespace fsi::proto;
constexpr int n = 9;

PointArray points(double scale) {
  PointArray x(n, 3);
  for (int i = 0; i < n; ++i)
    x.row(i) << scale * i, scale * (i % 3), 0.5 * scale;
  return x;
}

void pose(v2::RigidBodyPose &out) {
  BodyPose p;
  p.name = "surface0";
  p.pose.rotate(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
  p.angular_velocity_rad_per_s = Vec3(0, 0, 150.0);
  write_body_pose(p, out);
}

std::map<std::string, std::function<Message()>> kinds() {
  return {
      {"hello", [] {
         Message m(make_envelope(v2::ROLE_STRUCTURE, 0));
         auto *h = m.envelope().mutable_hello();
         h->set_role(v2::ROLE_STRUCTURE);
         h->set_participant_name("main");
         h->set_protocol_version(current_protocol_version);
         h->set_case_fingerprint("0123456789abcdef");
         auto *s = h->add_structures();
         s->set_name("rag");
         s->set_model("membrane");
         s->set_n1(3);
         s->set_n2(3);
         for (int i = 0; i < n; ++i)
           s->add_point_measure(1e-4);
         s->set_mass_per_measure(0.03);
         return m;
       }},
      {"welcome", [] {
         Message m(make_envelope(v2::ROLE_COUPLER, 0));
         auto *w = m.envelope().mutable_welcome();
         w->set_time_step_s(5e-5);
         w->set_n_steps(100);
         w->set_heartbeat_interval_s(0.5);
         w->set_timeout_s(10);
         return m;
       }},
      {"interpolate_request", [] {
         Message m(make_envelope(v2::ROLE_COUPLER, 3));
         auto *r = m.envelope().mutable_interpolate_request();
         r->set_time_s(1.5e-4);
         pose(*r->add_rigid_bodies());
         m.add_points(*r->mutable_position_m(), points(0.01));
         return m;
       }},
      {"interpolate_reply", [] {
         Message m(make_envelope(v2::ROLE_FLUID, 3));
         m.add_points(*m.envelope().mutable_interpolate_reply()->mutable_velocity_m_per_s(), points(0.1));
         return m;
       }},
      {"fluid_advance", [] {
         Message m(make_envelope(v2::ROLE_COUPLER, 3));
         auto *f = m.envelope().mutable_fluid_advance();
         f->set_time_s(1.5e-4);
         f->set_dt_s(5e-5);
         pose(*f->add_rigid_bodies());
         m.add_points(*f->mutable_force_density_n_per_measure(), points(2.0));
         return m;
       }},
      {"structure_advance", [] {
         Message m(make_envelope(v2::ROLE_COUPLER, 3));
         auto *s = m.envelope().mutable_structure_advance();
         s->set_time_s(1.5e-4);
         s->set_dt_s(5e-5);
         m.add_points(*s->mutable_load_density_n_per_measure(), points(-2.0));
         return m;
       }},
      {"advance_reply_structure", [] {
         Message m(make_envelope(v2::ROLE_STRUCTURE, 3));
         auto *a = m.envelope().mutable_advance_reply();
         a->set_time_s(2e-4);
         m.add_points(*a->mutable_position_m(), points(0.01));
         m.add_points(*a->mutable_velocity_m_per_s(), points(0.2));
         return m;
       }},
      {"advance_reply_fluid", [] {
         Message m(make_envelope(v2::ROLE_FLUID, 3));
         auto *a = m.envelope().mutable_advance_reply();
         a->set_time_s(2e-4);
         auto *load = a->add_rigid_body_loads();
         load->set_name("surface0");
         for (double v : {1.0, 2.0, 3.0}) {
           load->add_force_n(v);
           load->add_torque_n_m(0.1 * v);
         }
         return m;
       }},
      {"heartbeat", [] {
         Message m(make_envelope(v2::ROLE_FLUID, 0));
         m.envelope().mutable_heartbeat()->set_wall_time_s(12.5);
         return m;
       }},
      {"error", [] {
         Message m(make_envelope(v2::ROLE_STRUCTURE, 3));
         m.envelope().mutable_error()->set_message("diverged at step 3");
         m.envelope().mutable_error()->set_fatal(true);
         return m;
       }},
      {"shutdown", [] {
         Message m(make_envelope(v2::ROLE_COUPLER, 100));
         m.envelope().mutable_shutdown()->set_reason("run completed");
         m.envelope().mutable_shutdown()->set_success(true);
         return m;
       }},
      {"checkpoint_request", [] {
         Message m(make_envelope(v2::ROLE_COUPLER, 50));
         m.envelope().mutable_checkpoint_request();
         return m;
       }},
      {"checkpoint_done", [] {
         Message m(make_envelope(v2::ROLE_FLUID, 50));
         m.envelope().mutable_checkpoint_done()->set_part("fluid.ckpt");
         m.envelope().mutable_checkpoint_done()->set_checksum("00112233aabbccdd");
         return m;
       }},
  };
}

std::vector<std::uint8_t> encoded(Message message) {
  std::vector<zmq::message_t> frames;
  EnvelopeCodec::encode(message, frames);
  std::vector<std::uint8_t> out;
  for (const auto &frame : frames)
    fuzz::append_frame(out, frame.data(), frame.size());
  return out;
}

void write(const std::filesystem::path &file, const std::vector<std::uint8_t> &bytes) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char *>(bytes.data()),
                                             static_cast<std::streamsize>(bytes.size()));
}

} // namespace

int main(int argc, char **argv) {
  if (argc != 2) {
    std::cerr << "usage: make_fuzz_seeds OUT_DIR\n";
    return 2;
  }
  const std::filesystem::path out(argv[1]);
  int written = 0;
  for (const auto &[name, make] : kinds()) {
    const auto bytes = encoded(make());
    write(out / "envelope" / name, bytes);
    // coupler_channel: the same message from the structure, the fluid, the heartbeat socket, a stranger
    for (const std::uint8_t peer : {0, 1, 2, 4}) {
      std::vector<std::uint8_t> from{peer};
      from.insert(from.end(), bytes.begin(), bytes.end());
      write(out / "coupler_channel" / (std::to_string(peer) + "-" + name), from);
    }
    ++written;
  }
  std::cout << written << " message kinds written to " << out.string() << "\n";
  return 0;
}
