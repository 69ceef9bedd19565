#pragma once
// One Envelope per body type, filled with values that would expose lossy handling: extreme and
// subnormal doubles, negative zero, the largest integers, UTF-8 text, nested repeated messages.

#include "proto/Message.hpp"
#include "proto/Protocol.hpp"

#include <vector>

namespace fsi::proto::test {

/// One message per oneof body field of Envelope, in field-number order, with their array frames
/// (30 values each). Built afresh at each call: sending a message gives its frames away.
std::vector<Message> sample_messages();

/// True when the headers serialise to the same bytes and the array frames are the same bytes
/// (every double bit for bit).
bool same_bytes(const Message &a, const Message &b);

} // namespace fsi::proto::test
