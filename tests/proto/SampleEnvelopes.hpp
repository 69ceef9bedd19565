#pragma once
// One Envelope per body type, filled with values that would expose lossy handling: extreme and
// subnormal doubles, negative zero, the largest integers, UTF-8 text, nested repeated messages.

#include "proto/Protocol.hpp"

#include <vector>

namespace fsi::proto::test {

/// One Envelope per oneof body field of Envelope, in field-number order.
std::vector<Envelope> sample_envelopes();

/// True when a and b serialise to the same bytes (every double bit for bit).
bool same_bytes(const Envelope &a, const Envelope &b);

} // namespace fsi::proto::test
