#include "ChannelSettings.hpp"

#include "proto/CurveKeyFolder.hpp"

#include <stdexcept>

namespace fsi::case_config {

std::vector<std::string> curve_key_names() { return {"coupler", "structure", "fluid"}; }

std::filesystem::path keys_folder(const CaseConfig &config, const std::filesystem::path &case_dir) {
  const std::filesystem::path dir(config.coupling->keys_dir);
  return dir.is_absolute() ? dir : case_dir / dir;
}

proto::ChannelOptions channel_options(const CaseConfig &config, const std::filesystem::path &case_dir,
                                      const std::string &process) {
  if (!config.coupling)
    throw std::logic_error("channel_options needs a case with a coupling section");
  proto::ChannelOptions options;
  std::int64_t points = 0;
  for (const auto &structure : config.structures) {
    const auto [n1, n2] = structure.parameters->grid_shape();
    points += static_cast<std::int64_t>(n1) * n2;
  }
  options.max_message_bytes = proto::ChannelOptions::message_limit_bytes(points);
  options.insecure_remote = config.coupling->insecure_remote;
  if (config.coupling->security == coupler::CouplingConfig::Security::curve) {
    const proto::CurveKeyFolder keys(keys_folder(config, case_dir));
    const proto::CurveKeyPair own = keys.read_pair(process);
    proto::CurveSettings curve;
    curve.public_key = own.public_key;
    curve.secret_key = own.secret_key;
    if (process == "coupler") {
      for (const auto &name : curve_key_names())
        if (name != "coupler")
          curve.admitted[name] = keys.read_public(name);
    } else {
      curve.server_public_key = keys.read_public("coupler");
    }
    options.curve = std::move(curve);
  }
  return options;
}

} // namespace fsi::case_config
