#pragma once
// How a participant's session with the coupler ends other than by a Shutdown of success: the
// coupler refused or lost it, stopped the run because of someone else, or a stop signal ended
// it. The three classes are tiny and always caught together (Participant::run), so they share
// a file.

#include <stdexcept>
#include <string>

namespace fsi::participant {

/// The coupler refused the handshake, never answered it, or went silent during the run.
class CouplerLost : public std::runtime_error {
public:
  explicit CouplerLost(const std::string &message) : std::runtime_error(message) {}
};

/// The coupler stopped the run because of someone else (Shutdown with success = false, or an
/// ErrorReport); what() is its reason.
class RunStopped : public std::runtime_error {
public:
  explicit RunStopped(const std::string &message) : std::runtime_error(message) {}
};

/// A stop signal (SIGINT, SIGTERM) ended the run: the coupler ended it at a step boundary
/// (Shutdown.interrupted; `signal` 0 when this process received none), or this process
/// received one before the run started or while the coupler did not end the run within
/// SessionSettings::stop_grace.
class Interrupted : public std::runtime_error {
public:
  explicit Interrupted(int signal)
      : std::runtime_error("interrupted by signal " + std::to_string(signal)), signal(signal) {}
  Interrupted(int signal, const std::string &message, bool by_coupler)
      : std::runtime_error(message), signal(signal), by_coupler(by_coupler) {}
  int signal;
  /// The coupler ended the run (Shutdown.interrupted): it needs no ErrorReport.
  bool by_coupler = false;
};

} // namespace fsi::participant
