// Checkpoint sets: a set counts only with its manifest and every part it lists intact; the
// newest good set of this case is found, newer bad ones are passed over with their reason; only
// `keep` complete sets stay.

#include "checkpoint/ArchiveFile.hpp"
#include "checkpoint/CheckpointError.hpp"
#include "checkpoint/CheckpointSet.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using fsi::checkpoint::CaseIdentity;
using fsi::checkpoint::CheckpointSet;
using fsi::checkpoint::StateArchive;

namespace {

/// <a folder of its own>/checkpoints, the folder removed with the test.
struct TempRoot {
  explicit TempRoot(const std::string &name)
      : folder(fs::temp_directory_path() / ("fsi_checkpoint_set_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(folder);
  }
  ~TempRoot() { fs::remove_all(folder); }
  fs::path checkpoints() const { return folder / "checkpoints"; }
  fs::path folder;
};

void write_set(const CheckpointSet &sets, long step, bool complete = true) {
  const fs::path folder = sets.begin(step);
  StateArchive part;
  part.put_integer("step", step);
  const std::string a = fsi::checkpoint::write_archive(folder / "structure.ckpt", part);
  const std::string b = fsi::checkpoint::write_archive(folder / "coupler.ckpt", part);
  if (complete)
    sets.complete(step, 1e-3 * static_cast<double>(step), {{"structure.ckpt", a}, {"coupler.ckpt", b}});
}

long newest_step(const CheckpointSet &sets, std::vector<std::string> &skipped) {
  const auto found = sets.newest(skipped);
  return found ? found->step : -1;
}

bool mentions(const std::vector<std::string> &messages, const std::string &text) {
  for (const auto &m : messages)
    if (m.find(text) != std::string::npos)
      return true;
  return false;
}

} // namespace

TEST(CheckpointSet, OnlyTheKeptCompleteSetsStayAndTheNewestIsFound) {
  const TempRoot tmp("keep");
  const CheckpointSet sets(tmp.checkpoints(), CaseIdentity("fp"), 2);
  for (long step : {10, 20, 30})
    write_set(sets, step);
  EXPECT_FALSE(fs::exists(sets.folder(10)));
  EXPECT_TRUE(fs::exists(sets.folder(20)));
  std::vector<std::string> skipped;
  const auto found = sets.newest(skipped);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->step, 30);
  EXPECT_DOUBLE_EQ(found->time_s, 0.03);
  EXPECT_EQ(found->checksum_of("coupler.ckpt"), fsi::checkpoint::archive_checksum(sets.folder(30) / "coupler.ckpt"));
  EXPECT_THROW(found->checksum_of("fluid.ckpt"), fsi::checkpoint::CheckpointError);
  EXPECT_TRUE(skipped.empty());
}

TEST(CheckpointSet, ASetWithoutItsManifestDoesNotCount) {
  const TempRoot tmp("incomplete");
  const CheckpointSet sets(tmp.checkpoints(), CaseIdentity("fp"), 3);
  write_set(sets, 10);
  write_set(sets, 20, false); // a process died before the set was complete
  std::vector<std::string> skipped;
  EXPECT_EQ(newest_step(sets, skipped), 10);
}

TEST(CheckpointSet, ABadNewestSetIsSkippedWithItsReasonAndThePreviousUsed) {
  const TempRoot tmp("bad");
  const auto root = tmp.checkpoints();
  const CheckpointSet sets(root, CaseIdentity("fp"), 3);
  write_set(sets, 10);
  write_set(sets, 20);
  const fs::path part = sets.folder(20) / "structure.ckpt";
  std::vector<std::string> skipped;

  fs::resize_file(part, fs::file_size(part) - 3); // truncated
  EXPECT_EQ(newest_step(sets, skipped), 10);
  EXPECT_TRUE(mentions(skipped, part.string() + ": truncated")) << skipped.front();

  write_set(sets, 20);
  StateArchive other; // a part of another checkpoint, intact on its own
  other.put_integer("step", 99);
  fsi::checkpoint::write_archive(part, other);
  skipped.clear();
  EXPECT_EQ(newest_step(sets, skipped), 10);
  EXPECT_TRUE(mentions(skipped, "the manifest says")) << skipped.front();

  write_set(sets, 20);
  fs::remove(sets.folder(20) / "coupler.ckpt");
  skipped.clear();
  EXPECT_EQ(newest_step(sets, skipped), 10);
  EXPECT_TRUE(mentions(skipped, "coupler.ckpt: missing")) << skipped.front();

  write_set(sets, 20); // the control: a good set 20 is used
  skipped.clear();
  EXPECT_EQ(newest_step(sets, skipped), 20);
  EXPECT_TRUE(skipped.empty());
}

TEST(CheckpointSet, ASetOfAnotherCaseIsSkipped) {
  const TempRoot tmp("other_case");
  const auto root = tmp.checkpoints();
  write_set(CheckpointSet(root, CaseIdentity("this-case"), 3), 10);
  write_set(CheckpointSet(root, CaseIdentity("another-case"), 3), 20);
  std::vector<std::string> skipped;
  EXPECT_EQ(newest_step(CheckpointSet(root, CaseIdentity("this-case"), 3), skipped), 10);
  EXPECT_TRUE(mentions(skipped, "written by another case (fingerprint another-case")) << skipped.front();
  skipped.clear();
  EXPECT_EQ(newest_step(CheckpointSet(root, CaseIdentity("a-third-case"), 3), skipped), -1);
  EXPECT_EQ(skipped.size(), 2u);
}
