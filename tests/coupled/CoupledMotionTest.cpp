// The coupler is the only process of a coupled run that evaluates a prescribed rigid motion
// (section 2.3): a real fsi-structure --coupled, driven by a fake coupler on a raw ROUTER
// socket, corrects its points against the surface where the coupler says it is, not where the
// case file's motion would put it, and refuses a step whose poses do not match the case.

#include "ChildProcess.hpp"
#include "proto/BodyPose.hpp"
#include "proto/Protocol.hpp"

#include <gtest/gtest.h>
#include <zmq_addon.hpp>


#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using fsi::proto::Envelope;

// A sheet 10 mm above a floor that the case says turns slowly about the y axis (1 rad/s: a
// few microradians in two steps). The fake coupler sends another pose: the floor raised by
// 50 mm. Eq. (11) must push every point to 50 mm + d_t = 54 mm.
const char *const case_yaml = R"(run:
  end_time_s: 2.0e-4
  time_step_s: 1.0e-4
  output_interval_s: 1.0e-4
gravity_m_per_s2: [0, 0, 0]
collisions:
  threshold_m: 0.004
  target_distance_m: 0.004
  surfaces:
    - plane: {point_m: [0, 0, 0], normal: [0, 0, 1]}
      motion: {rotation: {axis_point_m: [0, 0, 0], axis_direction: [0, 1, 0], rate_rad_per_s: 1.0}}
structures:
  - name: sheet
    model: membrane
    size_m: [0.05, 0.05]
    n_points: [6, 6]
    origin_m: [0.0, 0.0, 0.01]
    material:
      mass_per_area_kg_per_m2: 0.08
      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}
    edges: {s1_min: free, s1_max: free, s2_min: free, s2_max: free}
fluid:
  prescribed:
    uniform: {velocity_m_per_s: [0.0, 0.0, 0.0]}
coupling:
  law: penalty
  stiffness_n_per_m_per_measure: 3.2e4
  heartbeat_interval_s: 0.1
  timeout_s: 2.0
  handshake_timeout_s: 10.0
)";
constexpr double raised_floor_m = 0.05;
constexpr double target_distance_m = 0.004;
constexpr double dt_s = 1.0e-4;

/// fsi-structure --coupled against the fake coupler.
std::unique_ptr<fsi::testing::ChildProcess> start_structure(const fs::path &case_dir, const std::string &endpoint) {
  return std::make_unique<fsi::testing::ChildProcess>(
      std::vector<std::string>{FSI_STRUCTURE_EXE, case_dir.string(), "--coupled", "--endpoint", endpoint, "-o",
                               (case_dir / "out").string()},
      case_dir / "structure.console");
}

class FakeCoupler : public ::testing::Test {
protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "fsi-coupled-motion-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    std::ofstream(dir_ / "case.yaml") << case_yaml;
    router_.set(zmq::sockopt::linger, 0);
    router_.bind("tcp://127.0.0.1:*");
    structure_ = start_structure(dir_, router_.get(zmq::sockopt::last_endpoint));
  }
  void TearDown() override {
    structure_.reset();
    if (!std::getenv("FSI_KEEP_TEST_DIRS"))
      fs::remove_all(dir_);
  }

  /// The participant's next message that is not a heartbeat (5 s at most); its array frames
  /// (protocol version 2: after the Envelope's frame) are kept in arrays_.
  Envelope next() {
    const auto deadline = std::chrono::steady_clock::now() + 5s;
    while (std::chrono::steady_clock::now() < deadline) {
      zmq::pollitem_t item{router_.handle(), 0, ZMQ_POLLIN, 0};
      if (zmq::poll(&item, 1, 100ms) <= 0)
        continue;
      std::vector<zmq::message_t> frames;
      if (!zmq::recv_multipart(router_, std::back_inserter(frames)) || frames.size() < 2)
        continue;
      peer_ = frames[0].to_string();
      Envelope envelope;
      EXPECT_TRUE(envelope.ParseFromArray(frames[1].data(), static_cast<int>(frames[1].size())));
      if (!envelope.has_heartbeat()) {
        arrays_.clear();
        for (std::size_t i = 2; i < frames.size(); ++i)
          arrays_.emplace_back(frames[i].data<double>(), frames[i].data<double>() + frames[i].size() / sizeof(double));
        return envelope;
      }
    }
    ADD_FAILURE() << "the structure sent nothing within 5 s:\n" << structure_->output();
    return {};
  }

  void send(const Envelope &envelope, const std::vector<std::vector<double>> &arrays = {}) {
    std::vector<zmq::message_t> frames;
    frames.emplace_back(peer_.data(), peer_.size());
    const std::string bytes = envelope.SerializeAsString();
    frames.emplace_back(bytes.data(), bytes.size());
    for (const auto &array : arrays)
      frames.emplace_back(array.data(), sizeof(double) * array.size());
    zmq::send_multipart(router_, frames);
  }

  /// Hello -> Welcome -> the initial state; returns the number of points.
  int join() {
    const Envelope hello = next();
    EXPECT_TRUE(hello.has_hello()) << structure_->output();
    Envelope welcome = fsi::proto::make_envelope(fsi::proto::v2::ROLE_COUPLER, 0);
    welcome.mutable_welcome()->set_time_step_s(dt_s);
    welcome.mutable_welcome()->set_n_steps(2);
    welcome.mutable_welcome()->set_heartbeat_interval_s(0.1);
    welcome.mutable_welcome()->set_timeout_s(2.0);
    send(welcome);
    const Envelope initial = next();
    EXPECT_TRUE(initial.has_advance_reply()) << structure_->output();
    return static_cast<int>(initial.advance_reply().position_m().n_values() / 3);
  }

  /// StructureAdvance of step 0 (no load), with these poses of the moving surfaces.
  Envelope advance(int n_points, const std::vector<fsi::proto::BodyPose> &poses) {
    Envelope request = fsi::proto::make_envelope(fsi::proto::v2::ROLE_COUPLER, 0);
    auto *advance = request.mutable_structure_advance();
    advance->set_time_s(0.0);
    advance->set_dt_s(dt_s);
    advance->mutable_load_density_n_per_measure()->set_frame(1);
    advance->mutable_load_density_n_per_measure()->set_n_values(3 * static_cast<std::uint64_t>(n_points));
    for (const auto &pose : poses)
      fsi::proto::write_body_pose(pose, *advance->add_rigid_bodies());
    send(request, {std::vector<double>(3 * static_cast<std::size_t>(n_points), 0.0)});
    return next();
  }

  static fsi::proto::BodyPose raised_floor(const std::string &name) {
    fsi::proto::BodyPose pose;
    pose.name = name;
    pose.pose.translation() = Eigen::Vector3d(0.0, 0.0, raised_floor_m);
    return pose;
  }

  fs::path dir_;
  zmq::context_t context_;
  zmq::socket_t router_{context_, zmq::socket_type::router};
  std::unique_ptr<fsi::testing::ChildProcess> structure_;
  std::string peer_;
  std::vector<std::vector<double>> arrays_; ///< the array frames of the last message
};

TEST_F(FakeCoupler, TheStructureCollidesWithTheSurfaceWhereTheCouplerPutsIt) {
  const int n = join();
  ASSERT_EQ(n, 36);
  const Envelope reply = advance(n, {raised_floor("surface0")});
  ASSERT_TRUE(reply.has_advance_reply()) << structure_->output();
  const auto &x = arrays_.at(reply.advance_reply().position_m().frame() - 1);
  for (int i = 0; i < n; ++i) // the case's own motion would leave every point at z = 0.01 m
    EXPECT_NEAR(x[3 * i + 2], raised_floor_m + target_distance_m, 1e-12) << "point " << i;
}

TEST_F(FakeCoupler, AStepWithoutThePoseOfAMovingSurfaceIsRefused) {
  const int n = join();
  const Envelope reply = advance(n, {});
  ASSERT_TRUE(reply.has_error()) << structure_->output();
  EXPECT_NE(reply.error().message().find("sent 0 rigid-body poses; this case has 1 moving surfaces"),
            std::string::npos)
      << reply.error().message();
}

TEST_F(FakeCoupler, APoseOfASurfaceThatDoesNotMoveIsRefused) {
  const int n = join();
  const Envelope reply = advance(n, {raised_floor("surface7")});
  ASSERT_TRUE(reply.has_error()) << structure_->output();
  EXPECT_NE(reply.error().message().find("'surface7', which is not a moving surface of this case"), std::string::npos)
      << reply.error().message();
}

} // namespace
