// Malformed but parseable replies (F3 of docs/security.md): valid Envelopes that no correct
// participant sends, at step 5 of a real fsi-coupler run driven by two fake participants in
// this process (a structure that moves its points by the load it gets, a fluid that answers a
// uniform velocity). Each row says what is sent and what the coupler must do:
// - a reply for another step, or the same reply twice: answered with an ErrorReport naming the
//   step the coupler waits for, and ignored: the run completes and every load the structure
//   received equals the clean run's, bit for bit (the coupler's state did not change);
// - an array of the wrong length, or holding NaN or infinity: the run stops (exit 1) with a
//   message naming the participant, the step, the field and the point, and the loads before
//   the bad step equal the clean run's (nothing was taken in).

#include "ChildProcess.hpp"
#include "proto/Message.hpp"
#include "proto/ParticipantChannel.hpp"
#include "proto/Protocol.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <mutex>
#include <regex>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace fsi::proto;
using fsi::testing::ChildProcess;
using fsi::testing::read_text;
using fsi::PointArray;

constexpr int n1 = 5, n2 = 5, n_points = n1 * n2, n_steps = 12, bad_step = 5;
constexpr double dt = 1e-4;

const char *const case_yaml = R"(run:
  end_time_s: 0.0012
  time_step_s: 1.0e-4
  output_interval_s: 0.0004
gravity_m_per_s2: [0, 0, 0]
structures:
  - name: sheet
    model: membrane
    size_m: [0.04, 0.04]
    n_points: [5, 5]
    material:
      mass_per_area_kg_per_m2: 0.08
      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}
    edges: {s1_min: free, s1_max: free, s2_min: free, s2_max: free}
fluid:
  prescribed:
    uniform: {velocity_m_per_s: [0.2, 0.0, 0.1]}
coupling:
  law: penalty
  stiffness_n_per_m_per_measure: 1.0e3
  heartbeat_interval_s: 0.2
  timeout_s: 5.0
  handshake_timeout_s: 10.0
)";

/// What a faulty participant does at bad_step instead of (or before) its normal reply.
enum class Who { structure, fluid };
struct Row {
  const char *name;
  Who who;
  /// Sends the faulty message(s) through `send`; returns true if the normal reply follows.
  /// `normal` is the reply a correct participant would send now.
  std::function<bool(const std::function<void(std::uint64_t step, const PointArray &, bool)> &send,
                     const PointArray &normal)>
      fault;
  bool run_completes;
  std::vector<std::string> coupler_says; ///< in the coupler's output (stopping rows) or the ErrorReport
};

PointArray initial_positions() {
  PointArray x(n_points, 3);
  for (int i = 0; i < n_points; ++i)
    x.row(i) << 0.01 * (i / n2), 0.01 * (i % n2), 0.0;
  return x;
}

/// Both fake participants, one thread each; records the loads the structure received.
class FakeRun {
public:
  FakeRun(const std::string &endpoint, const std::string &fingerprint, const Row *fault)
      : endpoint_(Endpoint::parse(endpoint)), fingerprint_(fingerprint), fault_(fault) {}

  void run() {
    std::thread fluid([this] { run_fluid(); });
    run_structure();
    fluid.join();
  }

  std::vector<PointArray> loads;         ///< per step, as received by the structure
  std::vector<std::string> errors;       ///< non-fatal ErrorReports received (either side)
  bool shut_down_with_success = false;

private:
  Envelope hello(Role role) const {
    Envelope envelope = make_envelope(role, 0);
    auto *h = envelope.mutable_hello();
    h->set_role(role);
    h->set_participant_name("main");
    h->set_protocol_version(current_protocol_version);
    h->set_case_fingerprint(fingerprint_);
    if (role == v2::ROLE_STRUCTURE) {
      auto *s = h->add_structures();
      s->set_name("sheet");
      s->set_model("membrane");
      s->set_n1(n1);
      s->set_n2(n2);
      for (int i = 0; i < n_points; ++i)
        s->add_point_measure(0.04 * 0.04 / n_points);
      s->set_mass_per_measure(0.08);
    }
    return envelope;
  }

  /// The next message that is not a heartbeat; records ErrorReports and goes on.
  Message &next(ParticipantChannel &channel, Message &message) {
    while (true) {
      if (!channel.receive_into(message, 10s))
        throw std::runtime_error("fake participant: nothing from the coupler for 10 s");
      const Envelope &e = message.envelope();
      if (e.has_heartbeat())
        continue;
      if (e.has_error() && !e.error().fatal()) {
        std::lock_guard lock(mutex_);
        errors.push_back(e.error().message());
        continue;
      }
      return message;
    }
  }

  void send_points(ParticipantChannel &channel, Role role, std::uint64_t step, bool interpolate,
                   const PointArray &values) {
    Message reply(make_envelope(role, step));
    if (interpolate)
      reply.add_points(*reply.envelope().mutable_interpolate_reply()->mutable_velocity_m_per_s(), values);
    else
      reply.add_points(*reply.envelope().mutable_advance_reply()->mutable_position_m(), values);
    channel.send(reply);
  }

  void run_structure() {
    ParticipantChannel channel(endpoint_, v2::ROLE_STRUCTURE, "main");
    channel.send(hello(v2::ROLE_STRUCTURE));
    Message message;
    next(channel, message); // Welcome
    PointArray x = initial_positions();
    Message initial(make_envelope(v2::ROLE_STRUCTURE, 0));
    initial.add_points(*initial.envelope().mutable_advance_reply()->mutable_position_m(), x);
    initial.add_points(*initial.envelope().mutable_advance_reply()->mutable_velocity_m_per_s(),
                       PointArray(PointArray::Zero(n_points, 3)));
    channel.send(initial);
    while (true) {
      Message &request = next(channel, message);
      if (request.envelope().has_shutdown()) {
        shut_down_with_success = request.envelope().shutdown().success();
        return;
      }
      const auto step = request.envelope().step();
      const PointArray load = request.points(request.envelope().structure_advance().load_density_n_per_measure(),
                                             n_points, "load");
      loads.push_back(load);
      x += 1e-3 * load; // any deterministic response to the load
      const auto send = [&](std::uint64_t s, const PointArray &values, bool) {
        send_points(channel, v2::ROLE_STRUCTURE, s, false, values);
      };
      if (fault_ && fault_->who == Who::structure && step == bad_step && !fault_->fault(send, x))
        continue; // the coupler stops the run: wait for its Shutdown
      send(step, x, false);
    }
  }

  void run_fluid() {
    ParticipantChannel channel(endpoint_, v2::ROLE_FLUID, "main");
    channel.send(hello(v2::ROLE_FLUID));
    Message message;
    try {
      next(channel, message); // Welcome
      PointArray u(n_points, 3);
      u.rowwise() = Eigen::RowVector3d(0.2, 0.0, 0.1);
      while (true) {
        Message &request = next(channel, message);
        const Envelope &e = request.envelope();
        if (e.has_shutdown())
          return;
        const auto step = e.step();
        if (e.has_interpolate_request()) {
          const auto send = [&](std::uint64_t s, const PointArray &values, bool) {
            send_points(channel, v2::ROLE_FLUID, s, true, values);
          };
          if (fault_ && fault_->who == Who::fluid && step == bad_step && !fault_->fault(send, u))
            continue;
          send(step, u, true);
        } else if (e.has_fluid_advance()) {
          Envelope reply = make_envelope(v2::ROLE_FLUID, step);
          reply.mutable_advance_reply()->set_time_s(static_cast<double>(step + 1) * dt);
          channel.send(reply);
        }
      }
    } catch (const std::exception &) {
      // The coupler went away after stopping the run: the structure side reports.
    }
  }

  Endpoint endpoint_;
  std::string fingerprint_;
  const Row *fault_;
  std::mutex mutex_;
};

class MalformedReplies : public ::testing::TestWithParam<Row> {
protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "fsi-malformed-replies-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    fs::create_directories(dir_ / "case");
    std::ofstream(dir_ / "case" / "case.yaml") << case_yaml;
  }
  void TearDown() override {
    if (!std::getenv("FSI_KEEP_TEST_DIRS"))
      fs::remove_all(dir_);
  }

  /// Runs the coupler with the fakes (one of them faulty if row is set); returns the fakes'
  /// record, the coupler's exit code and output.
  struct Outcome {
    std::vector<PointArray> loads;
    std::vector<std::string> errors;
    int code = -1;
    std::string output;
  };
  Outcome run(const Row *row, const std::string &name) {
    const fs::path out = dir_ / name;
    ChildProcess coupler({FSI_COUPLER_EXE, (dir_ / "case").string(), "-o", out.string()}, dir_ / (name + ".console"));
    std::string endpoint, fingerprint;
    const std::regex listening("listening on (\\S+) \\(protocol version \\d+, case fingerprint ([0-9a-f]+)");
    for (int i = 0; i < 2000 && fingerprint.empty(); ++i) {
      std::smatch match;
      const std::string text = coupler.output();
      if (std::regex_search(text, match, listening)) {
        endpoint = match[1];
        fingerprint = match[2];
      } else {
        std::this_thread::sleep_for(10ms);
      }
    }
    Outcome outcome;
    if (fingerprint.empty()) {
      ADD_FAILURE() << "the coupler did not start: " << coupler.output();
      return outcome;
    }
    FakeRun fakes(endpoint, fingerprint, row);
    fakes.run();
    const auto code = coupler.wait(20s);
    outcome.code = code ? *code : -1;
    outcome.output = coupler.output();
    outcome.loads = fakes.loads;
    outcome.errors = fakes.errors;
    return outcome;
  }

  fs::path dir_;
};

TEST_P(MalformedReplies, AreRejectedAndLeaveTheCouplersStateUnchanged) {
  const Row &row = GetParam();
  const Outcome clean = run(nullptr, "clean");
  ASSERT_EQ(clean.code, 0) << clean.output;
  ASSERT_EQ(clean.loads.size(), static_cast<std::size_t>(n_steps));
  ASSERT_TRUE(clean.errors.empty());

  const Outcome faulty = run(&row, "faulty");
  std::string said = faulty.output;
  for (const auto &e : faulty.errors)
    said += "\nErrorReport: " + e;
  for (const auto &text : row.coupler_says)
    EXPECT_NE(said.find(text), std::string::npos) << "expected '" << text << "' in:\n" << said;
  if (row.run_completes) {
    EXPECT_EQ(faulty.code, 0) << faulty.output;
    EXPECT_FALSE(faulty.errors.empty()) << "the bad message was not answered";
    ASSERT_EQ(faulty.loads.size(), clean.loads.size());
  } else {
    EXPECT_EQ(faulty.code, 1) << faulty.output;
    ASSERT_GE(faulty.loads.size(), static_cast<std::size_t>(bad_step));
  }
  const std::size_t compared = row.run_completes ? clean.loads.size() : bad_step + 1;
  for (std::size_t n = 0; n < std::min(compared, faulty.loads.size()); ++n)
    EXPECT_TRUE((faulty.loads[n].array() == clean.loads[n].array()).all()) << "the load of step " << n << " differs";
}

PointArray positions_with(double value, int point, int component) {
  PointArray x = initial_positions();
  x(point, component) = value;
  return x;
}

const Row rows[] = {
    {"WrongStep", Who::structure,
     [](const auto &send, const PointArray &) {
       send(bad_step + 3, initial_positions(), false);
       return true;
     },
     true, {"unexpected advance_reply for step 8; the coupler waits for the AdvanceReply of step 5"}},
    {"DuplicateStep", Who::structure,
     [](const auto &send, const PointArray &normal) {
       send(bad_step, normal, false); // taken as the reply of step 5 ...
       send(bad_step, normal, false); // ... and this one is a duplicate
       return false;
     },
     // Rejected while the coupler still collects step 5 ("...; the coupler waits for the
     // AdvanceReply of step 5") or once it has moved on ("... at step 6; the coupler waits for
     // InterpolateReply"): which, depends on when the fluid's reply of step 5 arrived.
     true, {"unexpected advance_reply for step 5"}},
    {"StaleFluidStep", Who::fluid,
     [](const auto &send, const PointArray &) {
       send(bad_step - 1, PointArray(PointArray::Zero(n_points, 3)), true);
       return true;
     },
     true, {"unexpected interpolate_reply for step 4 at step 5; the coupler waits for InterpolateReply from fluid:main"}},
    {"WrongLength", Who::structure,
     [](const auto &send, const PointArray &) {
       send(bad_step, PointArray(PointArray::Zero(n_points - 1, 3)), false);
       return false;
     },
     false, {"participant structure:main sent a bad AdvanceReply at step 5: AdvanceReply.position_m holds 72 values, "
             "expected 25 points x 3"}},
    {"NaNPosition", Who::structure,
     [](const auto &send, const PointArray &) {
       send(bad_step, positions_with(std::numeric_limits<double>::quiet_NaN(), 7, 1), false);
       return false;
     },
     false, {"sent a bad AdvanceReply at step 5: AdvanceReply.position_m holds nan at point 7 (y): a value that is "
             "not finite (its solver has most likely diverged"}},
    {"InfiniteVelocity", Who::fluid,
     [](const auto &send, const PointArray &) {
       send(bad_step, positions_with(std::numeric_limits<double>::infinity(), 3, 2), true);
       return false;
     },
     false, {"participant fluid:main sent a bad InterpolateReply at step 5: InterpolateReply.velocity_m_per_s holds "
             "inf at point 3 (z)"}},
};

INSTANTIATE_TEST_SUITE_P(Table, MalformedReplies, ::testing::ValuesIn(rows),
                         [](const ::testing::TestParamInfo<Row> &info) { return std::string(info.param.name); });

} // namespace
