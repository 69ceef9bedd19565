#pragma once
// The case's `coupling` section: the coupling law (from CouplingLawRegistry, its keys at the
// same level), where the coupler listens, and the liveness limits of the run.

#include "CouplingLawRegistry.hpp"
#include "ImplicitCouplingConfig.hpp"
#include "common/DidYouMean.hpp"

#include <string>

namespace fsi::coupler {

struct CouplingConfig {
  enum class Security { none, curve };
  enum class Scheme { explicit_, implicit };

  std::string law = "penalty";
  std::unique_ptr<CouplingLawConfig> parameters = CouplingLawRegistry::builtin().make_config("penalty");
  Scheme scheme = Scheme::explicit_;
  ImplicitCouplingConfig implicit;
  std::string endpoint = "tcp://127.0.0.1:0";
  Security security = Security::none;
  std::string keys_dir = "keys";
  bool insecure_remote = false;
  double heartbeat_interval_s = 0.5;
  double timeout_s = 10.0;
  double step_timeout_s = 600.0;
  double handshake_timeout_s = 120.0;

  template <class V> void visit(V &v) {
    v.text("law", law, "Coupling law: " + common::join(CouplingLawRegistry::builtin().names()) +
                            " (its keys follow at the same level).");
    if constexpr (std::is_same_v<V, common::ConfigReader>) {
      try {
        parameters = CouplingLawRegistry::builtin().make_config(law);
      } catch (const common::ConfigError &e) {
        v.fail_value("law", std::string("= ") + e.what());
      }
    }
    if constexpr (!std::is_same_v<V, common::ConfigDocWriter>)
      parameters->visit(v);
    v.choice("scheme", scheme, {{"explicit", Scheme::explicit_}, {"implicit", Scheme::implicit}},
             "explicit: the law is evaluated once per step at its start (section 2.3). implicit: the step is "
             "advanced again with an updated force until the law evaluated at its end agrees (keys in implicit).");
    v.section("implicit", implicit, "Sub-iterations of implicit coupling (scheme: implicit).");
    if constexpr (std::is_same_v<V, common::ConfigReader>) {
      if (v.has("implicit") && scheme != Scheme::implicit)
        v.fail_value("implicit", "is given, but scheme is explicit: add scheme: implicit, or remove the section.");
      if (scheme == Scheme::implicit && !parameters->build()->allows_implicit())
        v.fail_value("scheme", "= implicit takes the law penalty or feedback; " + law +
                                   " advances its IB points with the velocity at the start of the step.");
    }
    v.text("endpoint", endpoint,
           "Where the coupler listens (tcp://HOST:PORT, ipc:///PATH). Port 0: any free port, handed to the "
           "participants by ./fsi run; give a fixed port to start the processes by hand on several machines.");
    v.choice("security", security, {{"none", Security::none}, {"curve", Security::curve}},
             "curve: every connection encrypted and authenticated with ZeroMQ CURVE; the coupler admits only "
             "the keys in keys_dir (make them with ./fsi keys CASE). none: plaintext, for one machine.");
    v.text("keys_dir", keys_dir,
           "With security: curve, the folder of the key files, relative to the case folder (docs/security.md).");
    v.flag("insecure_remote", insecure_remote,
           "Allow binding an address other machines can reach without CURVE: anyone who reaches it can join "
           "the run and read its data. Only for a network you trust entirely.");
    v.number("heartbeat_interval_s", heartbeat_interval_s, common::Range::positive("s"),
             "Interval between heartbeats of the coupler and the participants.");
    v.number("timeout_s", timeout_s, common::Range::positive("s"),
             "A process that sends no heartbeat for this long is dead: the run stops, naming it.");
    v.number("step_timeout_s", step_timeout_s, common::Range::positive("s"),
             "Longest wait for one reply of a live participant (a hung solver).");
    v.number("handshake_timeout_s", handshake_timeout_s, common::Range::positive("s"),
             "Longest wait for all participants to connect at the start.");
    if constexpr (std::is_same_v<V, common::ConfigReader>) {
      if (v.has("allow_remote"))
        v.fail_value("allow_remote", "was replaced: use security: curve (keys from ./fsi keys CASE) to let other "
                                     "machines in, or insecure_remote: true on a network you trust entirely.");
      if (keys_dir.empty())
        v.fail_value("keys_dir", "is empty; give a folder (default: keys).");
    }
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (timeout_s <= 2.0 * heartbeat_interval_s)
        v.fail_value("timeout_s", "must exceed twice heartbeat_interval_s.");
  }
};

} // namespace fsi::coupler
