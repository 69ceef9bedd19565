#pragma once
// FNV-1a, 64 bit: a content hash stable across builds and machines (unlike std::hash), for
// fingerprints (of a case, of a precursor's inputs, of a mesh's inputs). Not cryptographic.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fsi::common {

class Fnv1a {
public:
  /// The bytes of `text`, as they are.
  void add_bytes(const std::string &text) {
    for (const unsigned char c : text)
      hash_ = (hash_ ^ c) * 1099511628211ull;
  }
  /// `size` raw bytes at `data` (a binary file's body).
  void add_raw(const void *data, std::size_t size) {
    const auto *bytes = static_cast<const unsigned char *>(data);
    for (std::size_t i = 0; i < size; ++i)
      hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
  }
  /// `text` and a separator: "ab" + "c" hashes differently from "a" + "bc".
  void add(const std::string &text) {
    add_bytes(text);
    hash_ = (hash_ ^ 0xffu) * 1099511628211ull;
  }
  /// A file's contents (as add()); a missing file adds nothing but the separator.
  void add_file(const std::filesystem::path &file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream contents;
    contents << in.rdbuf();
    add(contents.str());
  }
  std::uint64_t value() const { return hash_; }
  /// 16 hex digits.
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
    return text;
  }

private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

} // namespace fsi::common
