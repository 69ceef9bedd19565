#include "PrescribedFlowModel.hpp"

#include "checkpoint/ArchiveFile.hpp"
#include "checkpoint/CheckpointError.hpp"
#include "checkpoint/CheckpointSet.hpp"

namespace fsi::prescribed_flow {

namespace {
constexpr char part_name[] = "fluid.ckpt";
}

PrescribedFlowModel::PrescribedFlowModel(std::unique_ptr<FlowField> flow, std::filesystem::path checkpoints)
    : checkpoints_(std::move(checkpoints)), flow_(std::move(flow)) {}

checkpoint::CheckpointPart PrescribedFlowModel::write_checkpoint(long n_completed) {
  const auto folder = checkpoint::CheckpointSet::folder_of(checkpoints_, n_completed);
  std::filesystem::create_directories(folder);
  checkpoint::StateArchive archive;
  archive.put_integer("step", n_completed);
  archive.put_text("flow", flow_->describe());
  return {part_name, checkpoint::write_archive(folder / part_name, archive)};
}

void PrescribedFlowModel::resume(long step, const std::string &checksum) {
  const auto path = checkpoint::CheckpointSet::folder_of(checkpoints_, step) / part_name;
  const auto archive = checkpoint::read_archive(path);
  if (checkpoint::archive_checksum(path) != checksum)
    throw checkpoint::CheckpointError(path.string() + ": checksum " + checkpoint::archive_checksum(path) +
                                      ", the coupler's checkpoint says " + checksum);
  if (archive.integer("step") != step || archive.text("flow") != flow_->describe())
    throw checkpoint::CheckpointError(path.string() + ": of step " + std::to_string(archive.integer("step")) +
                                      " and the flow '" + archive.text("flow") + "'; this run resumes step " +
                                      std::to_string(step) + " of '" + flow_->describe() + "'");
}

std::string PrescribedFlowModel::describe() const {
  return "prescribed, " + flow_->describe() + " (one-way coupling: the FSI force does not act on this flow)";
}

void PrescribedFlowModel::interpolate(double time_s, PointsView x_m, participant::MutablePointsView u_m_per_s) {
  positions_ = x_m;
  velocities_.resize(positions_.rows(), 3);
  flow_->velocities(positions_, time_s, velocities_);
  u_m_per_s = velocities_;
}

} // namespace fsi::prescribed_flow
