// The state archive on disk: what goes in comes back bit for bit, and a file that is not what
// was written (truncated, longer, a flipped bit, another format) is refused with its name.

#include "checkpoint/ArchiveFile.hpp"
#include "checkpoint/CheckpointError.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace fs = std::filesystem;
using fsi::checkpoint::CheckpointError;
using fsi::checkpoint::StateArchive;

namespace {

/// A folder of its own for one test, removed with it.
struct TempFolder {
  explicit TempFolder(const std::string &name)
      : path(fs::temp_directory_path() / ("fsi_checkpoint_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempFolder() { fs::remove_all(path); }
  fs::path path;
};

std::string bytes_of(const fs::path &file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path &file, const std::string &bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

StateArchive sample() {
  StateArchive a;
  fsi::PointArray x(3, 3);
  x << 0.1, -0.0, 1e-310, // -0 and a subnormal keep their bits
      std::nextafter(1.0, 2.0), -1e300, 3.0, 1.0 / 3.0, 2.0 / 3.0, std::numeric_limits<double>::quiet_NaN();
  a.put_points("structures/rag/x_m", x);
  a.put_double("time_s", 0.1 + 0.2);
  a.put_integer("step", 1250);
  a.put_text("note", std::string("a text with a \0 inside", 22));
  return a;
}

} // namespace

TEST(ArchiveFile, WhatIsWrittenIsReadBackBitForBit) {
  const TempFolder dir("roundtrip");
  const fs::path file = dir.path / "a.ckpt";
  const StateArchive in = sample();
  fsi::checkpoint::write_archive(file, in);
  EXPECT_FALSE(fs::exists(file.string() + ".tmp")); // renamed into place
  const StateArchive out = fsi::checkpoint::read_archive(file);
  const fsi::PointArray a = in.points("structures/rag/x_m"), b = out.points("structures/rag/x_m", 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_TRUE(same_bits(a(i, j), b(i, j))) << i << "," << j;
  EXPECT_TRUE(same_bits(out.number("time_s"), 0.1 + 0.2));
  EXPECT_EQ(out.integer("step"), 1250);
  EXPECT_EQ(out.text("note"), in.text("note"));
}

TEST(ArchiveFile, AMissingEntryOrAnotherSizeIsNamed) {
  const TempFolder dir("entries");
  const fs::path file = dir.path / "a.ckpt";
  fsi::checkpoint::write_archive(file, sample());
  const StateArchive out = fsi::checkpoint::read_archive(file);
  try {
    out.points("structures/rag/x_previous_m");
    FAIL() << "a missing entry was read";
  } catch (const CheckpointError &e) {
    EXPECT_NE(std::string(e.what()).find("has no entry 'structures/rag/x_previous_m'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  EXPECT_THROW(out.points("structures/rag/x_m", 4), CheckpointError);
  EXPECT_THROW(out.integer("time_s"), CheckpointError);
}

TEST(ArchiveFile, ATruncatedLongerOrFlippedFileIsRefused) {
  const TempFolder dir("faults");
  const fs::path file = dir.path / "a.ckpt";
  fsi::checkpoint::write_archive(file, sample());
  const std::string good = bytes_of(file);
  const auto refused_with = [&](const std::string &bytes, const std::string &expected) {
    write_bytes(file, bytes);
    try {
      fsi::checkpoint::read_archive(file);
      ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const CheckpointError &e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
  };
  refused_with(good.substr(0, good.size() - 1), "truncated");
  refused_with(good.substr(0, good.size() / 2), "truncated");
  refused_with(good.substr(0, 10), "truncated");
  refused_with(good + "x", "longer than its header says");
  for (const std::size_t at : {good.size() / 2, good.size() - 9, std::size_t(60)}) {
    std::string flipped = good;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    refused_with(flipped, "checksum mismatch");
  }
  std::string other = good;
  other[0] = 'X';
  refused_with(other, "not a state archive");
  write_bytes(file, good); // the control: the good bytes still read
  EXPECT_NO_THROW(fsi::checkpoint::read_archive(file));
}
