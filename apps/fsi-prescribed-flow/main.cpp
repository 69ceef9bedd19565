// fsi-prescribed-flow: the fluid participant of one-way coupled scenes. The velocity at the
// Lagrangian points comes from the case's `fluid.prescribed` field (quiescent, uniform, shear,
// rotation, table) instead of a Navier-Stokes solution.
//   fsi-prescribed-flow CASE_DIR [--endpoint E] [-o DIR] [-v]
// Exit codes: 0 success, 1 the run stopped (coupler lost or another participant failed),
// 2 bad input, 130 interrupted.

#include "prescribed_flow/FlowFactory.hpp"
#include "prescribed_flow/PrescribedFlowModel.hpp"
#include "participant/FluidParticipant.hpp"
#include "case/ParticipantSettings.hpp"
#include "common/Allocator.hpp"
#include "common/ConfigError.hpp"
#include "common/Logging.hpp"
#include "proto/TransportError.hpp"

#include "proto/ZmqContext.hpp"

#include "case/CaseOptions.hpp"
#include "common/ExitCodes.hpp"
#include "common/GuardedMain.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <csignal>

namespace {
extern "C" void on_stop_signal(int signal) { fsi::participant::FluidParticipant::stop_signal() = signal; }
} // namespace

int main(int argc, char **argv) {
  const fsi::proto::ZmqContextCloser zmq_closer; // outlives every channel: last messages get out
  CLI::App app{"fsi-prescribed-flow: fluid participant with a prescribed velocity field (one-way coupling)"};
  fsi::case_config::CaseOptions options;
  options.add_to(app);
  if (const int code = fsi::case_config::parse_command_line(app, argc, argv); code >= 0)
    return code;
  fsi::common::setup_logging("fluid", options.verbose);
  fsi::common::keep_freed_memory(); // before the solver allocates (common/Allocator.hpp)
  return fsi::common::guarded_main("prescribed flow", [&] {
    const auto config = options.load();
    const std::string &case_dir = options.case_dir;
    if (!config.fluid || !config.fluid->prescribed) {
      spdlog::error("case {} has no `fluid.prescribed` section: there is no prescribed flow to run", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    const std::filesystem::path out = options.output_directory(config);
    std::filesystem::create_directories(out);
    fsi::common::add_log_file(out / "fluid.log");
    auto settings =
        fsi::case_config::participant_settings(config, options.endpoint, case_dir, fsi::proto::v2::ROLE_FLUID);
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    fsi::prescribed_flow::PrescribedFlowModel model(fsi::prescribed_flow::make_flow(*config.fluid->prescribed),
                                                    out / "checkpoints");
    fsi::participant::FluidParticipant participant(model, std::move(settings));
    return participant.run();
  });
}
