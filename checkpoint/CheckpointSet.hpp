#pragma once
// The checkpoint sets of a run, in <output>/checkpoints/: one folder per checkpointed step,
// step-<9 digits>/, with one state archive per part of the run (structure.ckpt, coupler.ckpt,
// ...) and, written last, manifest.ckpt: the case's identity (its restart fingerprint and keys,
// CaseIdentity), the step, the time, the set format and each part with its checksum. A set
// counts only with its manifest, and only when every part it lists is there with that checksum
// (MUSCLE3's rule: the parts of one snapshot must agree). The newest such set of this case is where a restart starts; newer sets
// that fail a check are skipped, each with a message naming the file and the fault.

#include "checkpoint/CaseIdentity.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fsi::checkpoint {

/// One part of a set: its file name in the set's folder and its checksum (16 hex digits).
struct CheckpointPart {
  std::string name, checksum;
};

class CheckpointSet {
public:
  static constexpr int format_version = 1;

  /// root: <output>/checkpoints; identity: the case's (CaseConfig::restart_identity); keep: the
  /// number of complete sets kept (older ones are removed when a new one completes; >= 1).
  CheckpointSet(std::filesystem::path root, CaseIdentity identity, int keep);

  /// The folder of step n's set, made empty (an incomplete set of the same step is replaced).
  std::filesystem::path begin(long step) const;
  /// Declares step n's set complete: writes the manifest with the parts (each written by its
  /// own process, which gave its checksum), then removes the sets beyond `keep`.
  void complete(long step, double time_s, const std::vector<CheckpointPart> &parts) const;

  struct Found {
    long step = 0;
    double time_s = 0.0;
    std::filesystem::path folder;
    std::vector<CheckpointPart> parts;
    /// What the caller should tell: the keys this build added since the set's (CaseIdentity).
    std::vector<std::string> notes;
    /// The checksum the manifest gives the part `name`; throws CheckpointError if it has none.
    const std::string &checksum_of(const std::string &name) const;
  };
  /// The newest complete, verified set of this case, if any; every newer set passed over is
  /// described in `skipped` (the file and why).
  std::optional<Found> newest(std::vector<std::string> &skipped) const;

  std::filesystem::path folder(long step) const { return folder_of(root_, step); }
  /// Whether step n of n_steps ends with a set when sets come every `every` steps (0: never):
  /// every interval, at the run's end (a later --restart with a later end time runs further),
  /// and when a signal stops the run.
  static bool due(long n, long every, long n_steps, bool stopping) {
    return every > 0 && (n % every == 0 || n == n_steps || stopping);
  }
  /// <root>/step-<9 digits>: where every process of a run puts its part of step n's set.
  static std::filesystem::path folder_of(const std::filesystem::path &root, long step);
  const std::filesystem::path &root() const { return root_; }

private:
  /// Complete sets' steps, newest first (by the manifest's presence only).
  std::vector<long> steps_newest_first() const;
  Found verify(long step) const;

  std::filesystem::path root_;
  CaseIdentity identity_;
  int keep_;
};

} // namespace fsi::checkpoint
