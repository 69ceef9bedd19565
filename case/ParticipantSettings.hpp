#pragma once
// How a participant process (structure, fluid) of a case joins its coupler.

#include "CaseConfig.hpp"
#include "participant/SessionSettings.hpp"

#include <filesystem>
#include <string>

namespace fsi::case_config {

/// The coupler endpoint (endpoint_override, else coupling.endpoint), the case fingerprint, the
/// handshake timeout and the channel options (ChannelSettings.hpp) of participant `role` of a
/// coupled case. Throws proto::TransportError for an endpoint that cannot be connected to (for
/// one from the case file the message says what to do about port 0), or a missing key.
participant::SessionSettings participant_settings(const CaseConfig &config, const std::string &endpoint_override,
                                                  const std::filesystem::path &case_dir, proto::Role role);

} // namespace fsi::case_config
