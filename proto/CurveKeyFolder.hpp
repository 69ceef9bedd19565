#pragma once
// The CURVE keys of a coupled run, one folder per case (coupling.keys_dir): for each process a
// key pair NAME.key_secret (readable only by its owner) and its public half NAME.key, in the
// ZPL certificate format of ZeroMQ's czmq (so its tools read them). The coupler needs its own
// pair and the participants' public keys; a participant needs its own pair and the coupler's
// public key. Copy to each host only what its process needs (docs/security.md).

#include <filesystem>
#include <string>
#include <vector>

namespace fsi::proto {

/// A Curve25519 key pair, each key as 40 Z85 characters.
struct CurveKeyPair {
  std::string public_key;
  std::string secret_key;

  /// A fresh pair from libsodium (through zmq_curve_keypair).
  static CurveKeyPair generate();
};

class CurveKeyFolder {
public:
  explicit CurveKeyFolder(std::filesystem::path folder) : folder_(std::move(folder)) {}

  const std::filesystem::path &folder() const { return folder_; }
  std::filesystem::path secret_file(const std::string &name) const { return folder_ / (name + ".key_secret"); }
  std::filesystem::path public_file(const std::string &name) const { return folder_ / (name + ".key"); }

  /// Writes a pair for each name that has none (all of them with overwrite), the folder mode
  /// 0700 and each secret file 0600, written to a temporary name and renamed. Returns the
  /// names it wrote.
  std::vector<std::string> make(const std::vector<std::string> &names, bool overwrite) const;

  /// The pair of `name`. Throws TransportError when the file is missing (saying how to make
  /// it), readable by others than its owner (saying how to fix it) or malformed.
  CurveKeyPair read_pair(const std::string &name) const;
  /// The public key of `name` (from NAME.key, or NAME.key_secret when only that is there).
  std::string read_public(const std::string &name) const;

private:
  std::filesystem::path folder_;
};

} // namespace fsi::proto
