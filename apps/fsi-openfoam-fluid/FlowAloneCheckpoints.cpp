#include "FlowAloneCheckpoints.hpp"

#include <spdlog/spdlog.h>

namespace fsi::apps {

FlowAloneCheckpoints::FlowAloneCheckpoints(std::filesystem::path root, checkpoint::CaseIdentity identity, int keep,
                                           long every_steps, long first_step)
    : set_(std::move(root), std::move(identity), keep), every_(every_steps), first_step_(first_step) {}

void FlowAloneCheckpoints::write(fluid::OpenFoamFluidModel &model, int rank, long n, double time_s) const {
  if (rank == 0)
    set_.begin(n); // an incomplete set of the same step (a run stopped while writing it) is replaced
  const auto part = model.checkpoint_on_every_rank(n);
  if (rank != 0)
    return;
  set_.complete(n, time_s, {part});
  spdlog::info("checkpoint: step {} (t = {:.6g} s) in {}", n, time_s, set_.folder(n).string());
}

} // namespace fsi::apps
