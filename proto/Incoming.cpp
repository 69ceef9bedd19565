#include "Incoming.hpp"

#include <stdexcept>
#include <utility>

namespace fsi::proto {

Incoming::Incoming(std::string peer, Message message) : peer_(std::move(peer)), content_(std::move(message)) {}

Incoming::Incoming(std::string peer, MalformedMessage malformed)
    : peer_(std::move(peer)), content_(std::move(malformed)) {}

const Message &Incoming::message() const {
  if (is_malformed()) {
    throw std::logic_error("Incoming::message() called on a malformed message from " +
                           printable(peer_) + "; check is_malformed() first");
  }
  return std::get<Message>(content_);
}

Message &Incoming::message() { return const_cast<Message &>(std::as_const(*this).message()); }

Message &Incoming::message_to_fill() {
  if (is_malformed()) {
    content_.emplace<Message>();
  }
  return std::get<Message>(content_);
}

const MalformedMessage &Incoming::malformed() const {
  if (!is_malformed()) {
    throw std::logic_error("Incoming::malformed() called on a valid Envelope from " +
                           printable(peer_));
  }
  return std::get<MalformedMessage>(content_);
}

} // namespace fsi::proto
