#pragma once
// The OpenFOAM fluid's part of a checkpoint set (docs/restart.md): the fields of the time
// folder the solver has just written (binary: U, p, phi, the old-time fields U_0 and phi_0 the
// backward scheme needs, the turbulence fields, uniform/time with the time index and the
// previous step), copied to <set>/fluid/<time>/, and fluid.ckpt: the step, the time folder's
// name, and every copied file with its FNV-1a hash, so that the part's checksum covers the
// fields. A restart copies the folder back into the prepared case and starts OpenFOAM from it
// (startFrom latestTime). With several MPI ranks the time folder is each rank's
// processor<k>/<time> (the same decomposition resumes). OpenFOAM-free: files only.

#include "checkpoint/CheckpointSet.hpp"

#include <filesystem>
#include <string>

namespace fsi::fluid {

class FoamCheckpoint {
public:
  static constexpr const char *part_name = "fluid.ckpt";

  /// Copies foam_case/<time_name> (n_ranks > 1: every processor<k>/<time_name>) into
  /// set_folder/fluid/ and writes fluid.ckpt; returns the part.
  static checkpoint::CheckpointPart write(const std::filesystem::path &foam_case, const std::string &time_name,
                                          int n_ranks, const std::filesystem::path &set_folder, long step);

  /// Checks the part of `set_folder` (its fields' hashes; the archive's checksum against
  /// `checksum` unless empty), copies its time folders into foam_case and makes the case start
  /// from them. Returns the time folder's name. Throws checkpoint::CheckpointError naming the
  /// file, or when the part was written with another number of ranks than n_ranks.
  static std::string install(const std::filesystem::path &set_folder, const std::filesystem::path &foam_case,
                             int n_ranks, long step, const std::string &checksum);
};

} // namespace fsi::fluid
