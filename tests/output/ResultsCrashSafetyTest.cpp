// The results file must stay readable when the simulation dies without closing it (killed,
// crashed): every step is flushed as it is written.

#include "OutputTestSupport.hpp"

#include "XdmfText.hpp"
#include "structure_solver/output/ResultsReader.hpp"

#include <sys/wait.h>
#include <unistd.h>

namespace fsi::structure::output::testing {
namespace {

/// In a child process: write `n_steps` sample steps, then die without running destructors.
void write_and_die_in_child(const std::filesystem::path &h5, const std::filesystem::path &xdmf,
                            int n_steps) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0) << "fork failed";
  if (child == 0) {
    try {
      ResultsWriter writer(h5, xdmf, sample_metadata());
      write_sample_run(writer, n_steps);
      ::_exit(0); // the writer is still open: no destructor, no H5Fclose
    } catch (...) {
      ::_exit(3);
    }
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0) << "the child could not write its steps";
}

using ResultsCrashSafety = ScratchFolderTest;

TEST_F(ResultsCrashSafety, FileWrittenByAProcessThatDiedWithoutClosingHoldsItsSteps) {
  write_and_die_in_child(h5_path(), xdmf_path(), 2);
  if (HasFatalFailure()) {
    return;
  }
  const ResultsReader reader(h5_path());
  ASSERT_EQ(reader.n_saved(), 2);
  EXPECT_EQ(reader.time_s(), std::vector<double>({sample_time_s(0), sample_time_s(1)}));
  EXPECT_EQ(reader.steps(), std::vector<std::int64_t>({sample_step(0), sample_step(1)}));
  EXPECT_EQ(reader.string_attribute("/", "status"), "running");
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(reader.position_m("sheet", k), sample_points(0, k, 12, 0.0));
    EXPECT_EQ(reader.velocity_m_per_s("fiber", k), sample_points(1, k, 5, -0.5));
  }
  EXPECT_EQ(reader.structure_series("fiber", "elastic_energy_j"),
            std::vector<double>({sample_scalar(1, 0, 2), sample_scalar(1, 1, 2)}));
}

TEST_F(ResultsCrashSafety, XdmfIndexOfAProcessThatDiedListsItsSteps) {
  write_and_die_in_child(h5_path(), xdmf_path(), 2);
  if (HasFatalFailure()) {
    return;
  }
  const XdmfText index(xdmf_path());
  EXPECT_EQ(index.time_values(), std::vector<double>({sample_time_s(0), sample_time_s(1)}));
  EXPECT_TRUE(index.is_complete());
}

/// Forked before any file is open, the child waits for the parent's go, then reads the file
/// the parent is still writing and exits 0 when it sees exactly `n_steps` correct steps.
/// The child also gives up (exit 4) when the parent closes the pipe without a go.
pid_t start_reader_child(const int go_pipe[2], const std::filesystem::path &h5, int n_steps) {
  const pid_t child = ::fork();
  if (child != 0) {
    return child;
  }
  ::close(go_pipe[1]);
  char go = 0;
  if (::read(go_pipe[0], &go, 1) != 1) {
    ::_exit(4);
  }
  try {
    const ResultsReader reader(h5);
    const bool ok =
        reader.n_saved() == n_steps && reader.time_s().back() == sample_time_s(n_steps - 1) &&
        reader.position_m("sheet", n_steps - 1) == sample_points(0, n_steps - 1, 12, 0.0);
    ::_exit(ok ? 0 : 1);
  } catch (...) {
    ::_exit(2);
  }
}

TEST_F(ResultsCrashSafety, AnotherProcessCanReadTheSavedStepsWhileTheRunGoesOn) {
  int go_pipe[2];
  ASSERT_EQ(::pipe(go_pipe), 0);
  const pid_t child = start_reader_child(go_pipe, h5_path(), 2);
  ::close(go_pipe[0]);
  ASSERT_GE(child, 0) << "fork failed";
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 2);
    EXPECT_EQ(::write(go_pipe[1], "g", 1), 1);
    ::close(go_pipe[1]);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child); // the writer is still open here
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: wrong values, 2: could not open or read the file";
  }
}

} // namespace
} // namespace fsi::structure::output::testing
