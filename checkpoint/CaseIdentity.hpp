#pragma once
// What a checkpoint set records of the case that wrote it: the case's restart fingerprint and
// the keys that fingerprint hashes, one "key = value" line each (the effective configuration
// flattened: fluid.openfoam.mpi_ranks = 2, structures[0].mesh.file = ...). A restart continues
// a set of the same fingerprint. When the fingerprints differ, the keys say why: a changed or
// removed key refuses the set and is named; a key the set's build did not have yet, in a section
// it had (a key a newer build added, with its default), is accepted and reported, since the case
// did not change, the program did (a restart across builds, as across any other change of code).
// Fingerprints that differ over keys that agree are refused (a manifest edited by hand).

#include <string>
#include <vector>

namespace fsi::checkpoint {

class CaseIdentity {
public:
  /// A fingerprint alone (no keys) can only tell that the case differs, not how.
  CaseIdentity(std::string fingerprint, std::string keys = {}) // NOLINT: a bare fingerprint converts
      : fingerprint_(std::move(fingerprint)), keys_(std::move(keys)) {}

  const std::string &fingerprint() const { return fingerprint_; }
  const std::string &keys() const { return keys_; }

  struct Verdict {
    bool accepted = false;
    /// Refused: why, naming the keys that differ (or the fingerprints, without keys).
    std::string refusal;
    /// Accepted across builds: "KEY = VALUE" of each key this build added.
    std::vector<std::string> added_keys;
  };
  /// Whether a set written by the case `then` may be continued by this one.
  Verdict admits(const CaseIdentity &then) const;

private:
  std::string fingerprint_;
  std::string keys_;
};

} // namespace fsi::checkpoint
