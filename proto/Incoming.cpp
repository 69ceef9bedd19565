#include "Incoming.hpp"

#include <stdexcept>
#include <utility>

namespace fsi::proto {

Incoming::Incoming(std::string peer, Envelope envelope)
    : peer_(std::move(peer)), content_(std::move(envelope)) {}

Incoming::Incoming(std::string peer, MalformedMessage malformed)
    : peer_(std::move(peer)), content_(std::move(malformed)) {}

const Envelope &Incoming::envelope() const {
  if (is_malformed()) {
    throw std::logic_error("Incoming::envelope() called on a malformed message from " +
                           printable(peer_) + "; check is_malformed() first");
  }
  return std::get<Envelope>(content_);
}

Envelope &Incoming::envelope() { return const_cast<Envelope &>(std::as_const(*this).envelope()); }

Envelope &Incoming::envelope_to_fill() {
  if (is_malformed()) {
    content_.emplace<Envelope>();
  }
  return std::get<Envelope>(content_);
}

const MalformedMessage &Incoming::malformed() const {
  if (!is_malformed()) {
    throw std::logic_error("Incoming::malformed() called on a valid Envelope from " +
                           printable(peer_));
  }
  return std::get<MalformedMessage>(content_);
}

} // namespace fsi::proto
