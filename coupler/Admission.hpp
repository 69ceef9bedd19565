#pragma once
// Admission to a coupled run: the coupler waits for one fluid and one structure participant,
// checks each Hello (protocol version, case fingerprint, role, the structures announced) and
// returns who joined (the Roster); then it welcomes both with the run's terms. A participant
// that does not belong to the run is answered with the reason and the run refused.

#include "CouplingErrors.hpp"
#include "CouplingSetup.hpp"
#include "ParticipantTable.hpp"
#include "Roster.hpp"
#include "checkpoint/CheckpointSet.hpp"
#include "proto/CouplerChannel.hpp"

#include <optional>
#include <string>

namespace fsi::coupler {

/// What Welcome tells both participants.
struct WelcomeTerms {
  long n_steps = 0;
  double time_step_s = 0.0;
  bool implicit_coupling = false;
  /// A restart: the checkpoint set every participant resumes from (its part's checksum).
  const std::optional<checkpoint::CheckpointSet::Found> *restart = nullptr;
};

class Admission {
public:
  Admission(ParticipantTable &participants, const proto::CouplerChannel &channel, const CouplingSetup &setup);

  /// Waits (coupling.handshake_timeout_s) until a fluid and a structure have joined; closes the
  /// admission. Throws HandshakeRefused (a participant of another run) or ParticipantFailed
  /// (none joined in time, naming the missing role and how to start it).
  Roster admit();
  /// Welcome to the structure, then the fluid (which also gets the structures' topology).
  void welcome(const Roster &roster, const WelcomeTerms &terms);

private:
  void accept_hello(const proto::Incoming &incoming, Roster &roster);
  /// The structures a structure participant announced, and their point measures.
  void read_structures(const std::string &peer, const proto::v2::Hello &hello, Roster &roster);
  void send_welcome(const std::string &id, const WelcomeTerms &terms, const Roster *with_structures,
                    const std::string &part);
  [[noreturn]] void refuse(const std::string &peer, const std::string &message);
  /// The error when `missing` has not joined in time.
  ParticipantFailed nobody_joined(const std::string &missing, bool structure_missing) const;

  ParticipantTable &participants_;
  const proto::CouplerChannel &channel_;
  const CouplingSetup &setup_;
};

} // namespace fsi::coupler
