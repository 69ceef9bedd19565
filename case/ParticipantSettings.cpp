#include "ParticipantSettings.hpp"

#include "ChannelSettings.hpp"

#include "proto/TransportError.hpp"

#include <chrono>

namespace fsi::case_config {

participant::SessionSettings participant_settings(const CaseConfig &config, const std::string &endpoint_override,
                                                  const std::filesystem::path &case_dir, proto::Role role) {
  participant::SessionSettings settings;
  settings.role = role;
  settings.options = channel_options(config, case_dir, role == proto::v2::ROLE_FLUID ? "fluid" : "structure");
  settings.coupler = proto::Endpoint::parse(endpoint_override.empty() ? config.coupling->endpoint : endpoint_override);
  try {
    settings.coupler.check_connectable();
  } catch (const proto::TransportError &e) {
    if (!endpoint_override.empty())
      throw;
    throw proto::TransportError(std::string(e.what()) +
                                " (coupling.endpoint of the case; port 0 means 'any free port', which only ./fsi run "
                                "can hand over: give --endpoint or a fixed port)");
  }
  settings.case_fingerprint = config.fingerprint();
  settings.handshake_timeout =
      std::chrono::milliseconds(static_cast<long long>(1e3 * config.coupling->handshake_timeout_s));
  return settings;
}

} // namespace fsi::case_config
