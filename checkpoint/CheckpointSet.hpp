#pragma once
// The checkpoint sets of a run, in <output>/checkpoints/: one folder per checkpointed step,
// step-<9 digits>/, with one state archive per part of the run (structure.ckpt, coupler.ckpt,
// ...) and, written last, manifest.ckpt: the case's restart fingerprint, the step, the time,
// the set format and each part with its checksum. A set counts only with its manifest, and only
// when every part it lists is there with that checksum (MUSCLE3's rule: the parts of one
// snapshot must agree). The newest such set of this case is where a restart starts; newer sets
// that fail a check are skipped, each with a message naming the file and the fault.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fsi::checkpoint {

class CheckpointSet {
public:
  static constexpr int format_version = 1;

  /// root: <output>/checkpoints; fingerprint: the case's restart fingerprint; keep: the number
  /// of complete sets kept (older ones are removed when a new one completes; >= 1).
  CheckpointSet(std::filesystem::path root, std::string fingerprint, int keep);

  /// The folder of step n's set, made empty (an incomplete set of the same step is replaced).
  std::filesystem::path begin(long step) const;
  /// Declares step n's set complete: checks every part (its archive reads back), writes the
  /// manifest, then removes the sets beyond `keep`. Throws CheckpointError when a part fails.
  void complete(long step, double time_s, const std::vector<std::string> &parts) const;

  struct Found {
    long step = 0;
    double time_s = 0.0;
    std::filesystem::path folder;
  };
  /// The newest complete, verified set of this case, if any; every newer set passed over is
  /// described in `skipped` (the file and why).
  std::optional<Found> newest(std::vector<std::string> &skipped) const;

  std::filesystem::path folder(long step) const;
  const std::filesystem::path &root() const { return root_; }

private:
  /// Complete sets' steps, newest first (by the manifest's presence only).
  std::vector<long> steps_newest_first() const;
  Found verify(long step) const;

  std::filesystem::path root_;
  std::string fingerprint_;
  int keep_;
};

} // namespace fsi::checkpoint
