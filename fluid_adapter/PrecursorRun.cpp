#include "PrecursorRun.hpp"

#include "common/ExitCodes.hpp"
#include "proto/FluidParticipant.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <fstream>

namespace fsi::fluid {

int run_precursor_steps(OpenFoamFluidModel &model, FoamFlow &flow, const Precursor &precursor) {
  using Clock = std::chrono::steady_clock;
  const double end = precursor.end_time_s();
  const std::vector<double> steps = precursor.step_sizes();
  const auto n_steps = static_cast<long>(steps.size());
  std::ofstream forces;
  const auto start = Clock::now();
  auto last_report = start;
  double t = 0.0;
  for (long step = 0; step < n_steps; ++step) {
    if (proto::FluidParticipant::stop_signal() != 0) {
      spdlog::warn("precursor interrupted at t = {:.6g} s; its result is not kept", t);
      return common::exit_code_interrupted;
    }
    const auto loads = model.advance_without_structure(t, steps[static_cast<std::size_t>(step)]);
    t += steps[static_cast<std::size_t>(step)];
    if (flow.rank() != 0)
      continue;
    if (step == 0 && !loads.empty()) {
      forces.open(precursor.folder() / "forces.csv");
      forces << "time_s";
      for (std::size_t b = 0; b < loads.size(); ++b)
        forces << ",body" << b << ".fx_n,body" << b << ".fy_n,body" << b << ".fz_n";
      forces << "\n";
    }
    if (forces.is_open()) {
      forces << flow.time_s();
      for (const auto &load : loads)
        forces << "," << load.force_n.x() << "," << load.force_n.y() << "," << load.force_n.z();
      forces << "\n";
    }
    const auto now = Clock::now();
    if (now - last_report > std::chrono::seconds(5) || step + 1 == n_steps) {
      last_report = now;
      const double wall = std::chrono::duration<double>(now - start).count();
      const double eta = wall / static_cast<double>(step + 1) * static_cast<double>(n_steps - step - 1);
      spdlog::info("precursor: t = {:.4g} of {:.4g} s, step {}/{}, {:.1f} ms/step, ETA {:.0f} s", flow.time_s(), end,
                   step + 1, n_steps, 1e3 * wall / static_cast<double>(step + 1), eta);
    }
  }
  flow.write_now();
  return 0;
}

} // namespace fsi::fluid
