#pragma once
// The transport settings of a case's processes: the message size limit from the size of its
// structures, and, with coupling.security: curve, the keys each process needs from
// coupling.keys_dir (docs/security.md).

#include "CaseConfig.hpp"
#include "proto/ChannelOptions.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace fsi::case_config {

/// The key names of a coupled run: the coupler and one per participant role.
std::vector<std::string> curve_key_names();

/// The folder of the case's CURVE keys: coupling.keys_dir against the case folder.
std::filesystem::path keys_folder(const CaseConfig &config, const std::filesystem::path &case_dir);

/// The channel options of `process` ("coupler", "structure" or "fluid") for a coupled case.
/// Throws proto::TransportError when a key it needs is missing or unsafe.
proto::ChannelOptions channel_options(const CaseConfig &config, const std::filesystem::path &case_dir,
                                      const std::string &process);

} // namespace fsi::case_config
