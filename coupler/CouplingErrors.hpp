#pragma once
// Why a coupled run stops early. Each message is one sentence naming the participant and the
// step; the coupler tells the other participants, writes what it has and exits non-zero.
// The three classes are tiny and always caught together, so they share a file.

#include <stdexcept>
#include <string>

namespace fsi::coupler {

/// A participant died, hung, reported an error or broke the protocol (exit code 1).
class ParticipantFailed : public std::runtime_error {
public:
  ParticipantFailed(std::string participant, const std::string &message)
      : std::runtime_error(message), participant(std::move(participant)) {}
  std::string participant;
};

/// A participant does not belong to this run: other protocol version, other case (exit code 2).
class HandshakeRefused : public std::runtime_error {
public:
  explicit HandshakeRefused(const std::string &message) : std::runtime_error(message) {}
};

/// SIGINT or SIGTERM (exit code 130).
class StopRequested : public std::runtime_error {
public:
  explicit StopRequested(int signal)
      : std::runtime_error("interrupted by signal " + std::to_string(signal)), signal(signal) {}
  int signal;
};

} // namespace fsi::coupler
