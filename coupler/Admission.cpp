#include "Admission.hpp"

#include "CouplingErrors.hpp"
#include "common/Durations.hpp"
#include "checkpoint/CheckpointError.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace fsi::coupler {

using common::Clock;
using common::seconds_since;
using common::to_ms;

Admission::Admission(ParticipantTable &participants, const proto::CouplerChannel &channel, const CouplingSetup &setup)
    : participants_(participants), channel_(channel), setup_(setup) {}

Roster Admission::admit() {
  Roster roster;
  const auto deadline = std::chrono::steady_clock::now() + to_ms(setup_.coupling.handshake_timeout_s);
  while (roster.fluid_id.empty() || roster.structure_id.empty()) {
    const bool structure_missing = roster.structure_id.empty();
    const std::string missing = structure_missing ? (roster.fluid_id.empty() ? "structure and fluid" : "structure")
                                                  : "fluid";
    proto::Incoming *incoming = nullptr;
    try {
      incoming = &participants_.next(deadline, missing, "Hello", 0);
    } catch (const ParticipantFailed &e) {
      if (!e.participant.empty() && participants_.knows(e.participant))
        throw;
      throw nobody_joined(missing, structure_missing);
    }
    if (incoming->envelope().has_hello())
      accept_hello(*incoming, roster);
    else
      participants_.answer_error(incoming->peer(), "the run has not started: wait for Welcome", 0);
  }
  participants_.close_admission();
  return roster;
}

ParticipantFailed Admission::nobody_joined(const std::string &missing, bool structure_missing) const {
  const long dropped = channel_.dropped_unauthenticated();
  return ParticipantFailed(
      missing, "no " + missing + " participant joined within coupling.handshake_timeout_s = " +
                   std::to_string(setup_.coupling.handshake_timeout_s) + " s at " + channel_.endpoint().str() +
                   "; start it with ./fsi run --participant " + (structure_missing ? "structure" : "fluid") +
                   " CASE_DIR" +
                   (dropped > 0 ? " (" + std::to_string(dropped) +
                                      " messages were dropped as not authenticated: check that each host has the keys "
                                      "of this case, docs/security.md)"
                                : std::string()));
}

void Admission::accept_hello(const proto::Incoming &incoming, Roster &roster) {
  const auto &hello = incoming.envelope().hello();
  const std::string &peer = incoming.peer();
  if (hello.protocol_version() != proto::current_protocol_version)
    refuse(peer, "participant " + peer + " speaks protocol version " + std::to_string(hello.protocol_version()) +
                     ", this coupler version " + std::to_string(proto::current_protocol_version) +
                     ": build all processes of a run from the same version");
  if (hello.case_fingerprint() != setup_.case_fingerprint)
    refuse(peer, "participant " + peer + " was started with another case (fingerprint " + hello.case_fingerprint() +
                     ", the coupler's is " + setup_.case_fingerprint +
                     "): give every process the same case folder (copy it to every machine)");
  const bool is_fluid = hello.role() == proto::v2::ROLE_FLUID;
  if (!is_fluid && hello.role() != proto::v2::ROLE_STRUCTURE)
    refuse(peer, "participant " + peer + " has role " + std::string(proto::role_name(hello.role())) +
                     "; a coupled run takes one fluid and one structure participant");
  std::string &slot = is_fluid ? roster.fluid_id : roster.structure_id;
  if (!slot.empty())
    refuse(peer, "participant " + peer + " is a second " + std::string(proto::role_name(hello.role())) +
                     " participant; " + slot + " has joined already");
  if (!is_fluid)
    read_structures(peer, hello, roster);
  slot = peer;
  participants_.add(peer);
  spdlog::info("participant {} joined (role {}, protocol {})", peer, proto::role_name(hello.role()),
               hello.protocol_version());
}

void Admission::read_structures(const std::string &peer, const proto::v2::Hello &hello, Roster &roster) {
  if (hello.structures_size() != static_cast<int>(setup_.n_structures))
    refuse(peer, "participant " + peer + " announced " + std::to_string(hello.structures_size()) +
                     " structures; the case has " + std::to_string(setup_.n_structures));
  roster.topology.assign(hello.structures().begin(), hello.structures().end());
  Eigen::Index n = 0;
  for (const auto &s : roster.topology) {
    const std::uint64_t points = std::uint64_t{s.n1()} * s.n2(); // 64 bits: 2^16 x 2^16 must not wrap to 0
    if (static_cast<std::uint64_t>(s.point_measure_size()) != points)
      refuse(peer, "participant " + peer + ": structure '" + proto::printable(s.name()) + "' has " +
                       std::to_string(s.point_measure_size()) + " point measures for " + std::to_string(points) +
                       " points");
    n += static_cast<Eigen::Index>(points);
  }
  roster.measures.resize(n);
  Eigen::Index at = 0;
  for (const auto &s : roster.topology)
    for (const double m : s.point_measure())
      roster.measures[at++] = m;
}

void Admission::refuse(const std::string &peer, const std::string &message) {
  participants_.answer_error(peer, message, 0);
  throw HandshakeRefused(message);
}

void Admission::welcome(const Roster &roster, const WelcomeTerms &terms) {
  send_welcome(roster.structure_id, terms, nullptr, "structure.ckpt");
  send_welcome(roster.fluid_id, terms, &roster, "fluid.ckpt");
  spdlog::info("participants joined: {} and {}", roster.structure_id, roster.fluid_id);
}

void Admission::send_welcome(const std::string &id, const WelcomeTerms &terms, const Roster *with_structures,
                             const std::string &part) {
  proto::Message envelope(proto::make_envelope(proto::v2::ROLE_COUPLER, 0));
  auto *w = envelope.envelope().mutable_welcome();
  if (terms.restart && *terms.restart) {
    const auto &set = **terms.restart;
    w->set_first_step(static_cast<std::uint64_t>(set.step));
    try {
      w->set_checkpoint_checksum(set.checksum_of(part));
    } catch (const checkpoint::CheckpointError &e) {
      refuse(id, std::string("--restart: ") + e.what());
    }
  }
  w->set_time_step_s(terms.time_step_s);
  w->set_n_steps(static_cast<std::uint64_t>(terms.n_steps));
  w->set_heartbeat_interval_s(setup_.coupling.heartbeat_interval_s);
  w->set_timeout_s(setup_.coupling.timeout_s);
  w->set_implicit_coupling(terms.implicit_coupling);
  if (with_structures)
    for (const auto &s : with_structures->topology)
      *w->add_structures() = s;
  participants_.send(id, envelope, 0);
}

} // namespace fsi::coupler
