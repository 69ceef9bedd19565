#include "RunCheckpoints.hpp"

#include "CouplingErrors.hpp"
#include "common/Durations.hpp"
#include "checkpoint/ArchiveFile.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace fsi::coupler {

using common::Clock;
using common::seconds_since;
using common::to_ms;

RunCheckpoints::RunCheckpoints(const std::filesystem::path &output_dir, const CouplingSetup &setup)
    : set_(output_dir / "checkpoints", setup.restart_identity, setup.run.checkpoint_keep),
      every_(setup.run.checkpoint_every()), step_timeout_s_(setup.coupling.step_timeout_s) {}

void RunCheckpoints::find_restart(long n_steps) {
  std::vector<std::string> skipped;
  restart_ = set_.newest(skipped);
  for (const auto &why : skipped)
    spdlog::warn("restart: skipped a checkpoint: {}", why);
  for (const auto &note : restart_ ? restart_->notes : std::vector<std::string>{})
    spdlog::warn("restart: {}", note);
  if (!restart_)
    throw HandshakeRefused("--restart: no complete checkpoint of this case in " + set_.root().string() +
                           (skipped.empty() ? std::string(" (run.checkpoint_interval_s makes them)")
                                            : " (" + std::to_string(skipped.size()) + " skipped, above)"));
  first_step_ = restart_->step;
  if (first_step_ >= n_steps)
    throw HandshakeRefused("--restart: the newest checkpoint is of step " + std::to_string(first_step_) +
                           ", the end of this run (" + std::to_string(n_steps) +
                           " steps): give a later --end-time to run further");
}

checkpoint::StateArchive RunCheckpoints::restart_state() const {
  return checkpoint::read_archive(restart_->folder / "coupler.ckpt");
}

void RunCheckpoints::write(long n, double time_s, ParticipantTable &participants, const Roster &roster,
                           const checkpoint::StateArchive &own, CouplingResults &results) {
  const auto folder = set_.begin(n);
  auto parts = collect_parts(n, participants, roster);
  parts.push_back({"coupler.ckpt", checkpoint::write_archive(folder / "coupler.ckpt", own)});
  results.flush(); // coupling.h5 holds every step up to this one
  set_.complete(n, time_s, parts);
  spdlog::debug("checkpoint of step {} in {}", n, folder.string());
}

std::vector<checkpoint::CheckpointPart> RunCheckpoints::collect_parts(long n, ParticipantTable &participants,
                                                                      const Roster &roster) {
  for (const std::string *id : {&roster.structure_id, &roster.fluid_id}) {
    proto::Message request(proto::make_envelope(proto::v2::ROLE_COUPLER, static_cast<std::uint64_t>(n)));
    request.envelope().mutable_checkpoint_request();
    participants.send(*id, request, static_cast<std::uint64_t>(n));
  }
  std::vector<checkpoint::CheckpointPart> parts;
  std::string structure_part, fluid_part;
  const auto deadline = Clock::now() + to_ms(step_timeout_s_);
  while (structure_part.empty() || fluid_part.empty()) {
    const std::string &waited = structure_part.empty() ? roster.structure_id : roster.fluid_id;
    auto &incoming = participants.next(deadline, waited, "CheckpointDone", static_cast<std::uint64_t>(n));
    const auto &envelope = incoming.envelope();
    std::string &slot = incoming.peer() == roster.fluid_id ? fluid_part : structure_part;
    if (!envelope.has_checkpoint_done() || envelope.step() != static_cast<std::uint64_t>(n) || !slot.empty() ||
        envelope.checkpoint_done().part().empty()) {
      participants.answer_unexpected(incoming, n, "; the coupler waits for the CheckpointDone of step " +
                                                      std::to_string(n));
      continue;
    }
    slot = envelope.checkpoint_done().part();
    parts.push_back({slot, envelope.checkpoint_done().checksum()});
  }
  return parts;
}

} // namespace fsi::coupler
