// A restart continues a set of the same case: a changed or removed key refuses it and is named;
// a key a newer build added to a section the set's case had is accepted and reported; a new
// section (a structure added) refuses it; a manifest without keys can only say that it differs,
// and fingerprints that differ over the same keys are refused.

#include "checkpoint/ArchiveFile.hpp"
#include "checkpoint/CaseIdentity.hpp"
#include "checkpoint/CheckpointSet.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using fsi::checkpoint::CaseIdentity;

namespace {

const std::string then_keys = "run.time_step_s = 0.00025\n"
                              "fluid.openfoam.mpi_ranks = 1\n"
                              "fluid.openfoam.body_indicator = sharp\n"
                              "structures[0].name = rag\n";

bool contains(const std::string &text, const std::string &part) { return text.find(part) != std::string::npos; }

} // namespace

TEST(CaseIdentity, TheSameFingerprintIsAdmitted) {
  const auto verdict = CaseIdentity("a1", then_keys).admits(CaseIdentity("a1", then_keys));
  EXPECT_TRUE(verdict.accepted);
  EXPECT_TRUE(verdict.added_keys.empty());
}

TEST(CaseIdentity, AChangedOrRemovedKeyIsRefusedAndNamed) {
  const std::string now = "run.time_step_s = 0.0001\n"
                          "fluid.openfoam.mpi_ranks = 1\n"
                          "structures[0].name = rag\n";
  const auto verdict = CaseIdentity("b2", now).admits(CaseIdentity("a1", then_keys));
  EXPECT_FALSE(verdict.accepted);
  EXPECT_TRUE(contains(verdict.refusal, "run.time_step_s was 0.00025, is 0.0001 now")) << verdict.refusal;
  EXPECT_TRUE(contains(verdict.refusal, "fluid.openfoam.body_indicator was sharp, is not set now")) << verdict.refusal;
  EXPECT_TRUE(contains(verdict.refusal, "fingerprint a1, this case's is b2")) << verdict.refusal;
}

TEST(CaseIdentity, AKeyANewerBuildAddedToAnExistingSectionIsAdmittedAndReported) {
  const auto now = then_keys + "fluid.openfoam.immersed_wall_turbulence = auto\n";
  const auto verdict = CaseIdentity("b2", now).admits(CaseIdentity("a1", then_keys));
  EXPECT_TRUE(verdict.accepted) << verdict.refusal;
  ASSERT_EQ(verdict.added_keys.size(), 1u);
  EXPECT_EQ(verdict.added_keys[0], "fluid.openfoam.immersed_wall_turbulence = auto");
}

TEST(CaseIdentity, ANewSectionOrListEntryIsRefused) {
  const auto with_structure = then_keys + "structures[1].name = flag\n";
  const auto verdict = CaseIdentity("b2", with_structure).admits(CaseIdentity("a1", then_keys));
  EXPECT_FALSE(verdict.accepted);
  EXPECT_TRUE(contains(verdict.refusal, "structures[1].name is new (flag)")) << verdict.refusal;
  const auto with_section = then_keys + "coupling.law = iqn\n";
  EXPECT_FALSE(CaseIdentity("b2", with_section).admits(CaseIdentity("a1", then_keys)).accepted);
  // a new key added beside an accepted one does not carry it through
  const auto both = then_keys + "fluid.openfoam.new_key = 1\nprobes[0].name = p\n";
  const auto mixed = CaseIdentity("b2", both).admits(CaseIdentity("a1", then_keys));
  EXPECT_FALSE(mixed.accepted);
  EXPECT_TRUE(mixed.added_keys.empty());
}

TEST(CaseIdentity, FingerprintsThatDifferOverTheSameKeysAreRefused) {
  const auto verdict = CaseIdentity("b2", then_keys).admits(CaseIdentity("a1", then_keys));
  EXPECT_FALSE(verdict.accepted);
  EXPECT_TRUE(contains(verdict.refusal, "its keys agree with this case's, its fingerprint does not")) << verdict.refusal;
}

TEST(CaseIdentity, WithoutKeysOnlyTheFingerprintsAreCompared) {
  const auto verdict = CaseIdentity("b2", then_keys).admits(CaseIdentity("a1"));
  EXPECT_FALSE(verdict.accepted);
  EXPECT_TRUE(contains(verdict.refusal, "a change of the case other than run.end_time_s")) << verdict.refusal;
}

TEST(CaseIdentity, ACheckpointSetContinuedAcrossBuildsSaysWhichKeysItAdded) {
  const fs::path root = fs::temp_directory_path() / ("fsi_case_identity_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const fsi::checkpoint::CheckpointSet old_build(root, CaseIdentity("a1", then_keys), 2);
  const fs::path folder = old_build.begin(10);
  fsi::checkpoint::StateArchive part;
  part.put_integer("step", 10);
  old_build.complete(10, 0.01, {{"fluid.ckpt", fsi::checkpoint::write_archive(folder / "fluid.ckpt", part)}});

  std::vector<std::string> skipped;
  const fsi::checkpoint::CheckpointSet new_build(
      root, CaseIdentity("b2", then_keys + "fluid.openfoam.immersed_wall_turbulence = auto\n"), 2);
  const auto found = new_build.newest(skipped);
  ASSERT_TRUE(found);
  EXPECT_TRUE(skipped.empty());
  ASSERT_EQ(found->notes.size(), 1u);
  EXPECT_TRUE(contains(found->notes[0], "fluid.openfoam.immersed_wall_turbulence = auto")) << found->notes[0];

  const fsi::checkpoint::CheckpointSet other_case(root, CaseIdentity("c3", "run.time_step_s = 0.001\n"), 2);
  EXPECT_FALSE(other_case.newest(skipped));
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_TRUE(contains(skipped[0], "run.time_step_s was 0.00025, is 0.001 now")) << skipped[0];
  fs::remove_all(root);
}
