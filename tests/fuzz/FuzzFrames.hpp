#pragma once
// The fuzz targets' input format for one ZeroMQ message: frames, each a 32-bit little-endian
// length and that many bytes; a length beyond the input takes the rest. Seeds are real
// messages written this way (make_fuzz_seeds.cpp), so the fuzzer starts from valid Envelopes.

#include <zmq.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

namespace fsi::fuzz {

inline std::vector<zmq::message_t> split_frames(const std::uint8_t *data, std::size_t size, std::size_t max_frames = 16) {
  std::vector<zmq::message_t> frames;
  std::size_t at = 0;
  while (at < size && frames.size() < max_frames) {
    std::uint32_t length = 0;
    const std::size_t header = std::min<std::size_t>(4, size - at);
    std::memcpy(&length, data + at, header);
    at += header;
    const std::size_t take = std::min<std::size_t>(length, size - at);
    frames.emplace_back(data + at, take);
    at += take;
  }
  return frames;
}

inline void append_frame(std::vector<std::uint8_t> &out, const void *bytes, std::size_t size) {
  const auto length = static_cast<std::uint32_t>(size);
  const auto *l = reinterpret_cast<const std::uint8_t *>(&length);
  out.insert(out.end(), l, l + 4);
  const auto *b = static_cast<const std::uint8_t *>(bytes);
  out.insert(out.end(), b, b + size);
}

} // namespace fsi::fuzz
