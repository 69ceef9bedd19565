// The run status attribute, and what a user sees when the results cannot be written.

#include "OutputTestSupport.hpp"

#include "structure_solver/output/ResultsReader.hpp"

#include <fstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fsi::structure::output::testing {
namespace {

/// Runs `action`, expects an exception of type E whose message contains `needle`.
template <typename E, typename Action>
void expect_throw_mentioning(Action action, const std::string &needle) {
  try {
    action();
    ADD_FAILURE() << "no exception; expected one mentioning " << needle;
  } catch (const E &error) {
    EXPECT_NE(std::string(error.what()).find(needle), std::string::npos) << error.what();
  }
}

using ResultsStatus = ScratchFolderTest;

TEST_F(ResultsStatus, EachStatusSetIsReadBackFromTheFile) {
  ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
  write_sample_run(writer, 1);
  for (const std::string status :
       {"completed", "diverged: max stretch ratio 3.7 exceeds 3 at step 17", "interrupted"}) {
    writer.set_status(status);
    // set_status() flushed: a reader opened while the writer is still alive sees it.
    EXPECT_EQ(ResultsReader(h5_path()).string_attribute("/", "status"), status);
  }
}

TEST_F(ResultsStatus, StatusSurvivesClosingTheWriter) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 2);
    writer.set_status("completed");
  }
  const ResultsReader reader(h5_path());
  EXPECT_EQ(reader.string_attribute("/", "status"), "completed");
  EXPECT_EQ(reader.n_saved(), 2);
}

using ResultsErrors = ScratchFolderTest;

TEST_F(ResultsErrors, CreatingInAMissingFolderNamesTheFile) {
  const std::filesystem::path missing = folder_ / "no_such_folder" / "run.h5";
  expect_throw_mentioning<std::runtime_error>(
      [&] { ResultsWriter writer(missing, xdmf_path(), sample_metadata()); }, missing.string());
}

TEST_F(ResultsErrors, XdmfInAMissingFolderNamesTheIndex) {
  const std::filesystem::path missing = folder_ / "no_such_folder" / "run.xdmf";
  expect_throw_mentioning<std::runtime_error>(
      [&] { ResultsWriter writer(h5_path(), missing, sample_metadata()); }, missing.string());
}

TEST_F(ResultsErrors, CreatingUnderAPathThatIsAFileNamesTheFile) {
  const std::filesystem::path not_a_folder = folder_ / "plain_file";
  std::ofstream(not_a_folder) << "not a folder";
  const std::filesystem::path target = not_a_folder / "run.h5";
  expect_throw_mentioning<std::runtime_error>(
      [&] { ResultsWriter writer(target, xdmf_path(), sample_metadata()); }, target.string());
}

/// The message of what `action` throws, "" if it throws nothing, run as an ordinary user: in a
/// child process that gives up root (uid and gid of `nobody`, 65534) when the test runs as root,
/// which may write into read-only folders (CI and this project's machines run as root).
template <typename Action> std::string thrown_as_ordinary_user(Action action) {
  if (::geteuid() != 0) {
    try {
      action();
      return "";
    } catch (const std::exception &error) {
      return error.what();
    }
  }
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0)
    return "pipe failed";
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipe_fds[0]);
    std::string message = "cannot drop root";
    if (::setgid(65534) == 0 && ::setuid(65534) == 0) {
      try {
        action();
        message = "";
      } catch (const std::exception &error) {
        message = error.what();
      }
    }
    [[maybe_unused]] const auto written = ::write(pipe_fds[1], message.data(), message.size());
    ::_exit(0);
  }
  ::close(pipe_fds[1]);
  std::string message;
  char buffer[512];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;)
    message.append(buffer, static_cast<std::size_t>(n));
  ::close(pipe_fds[0]);
  ::waitpid(child, nullptr, 0);
  return message;
}

TEST_F(ResultsErrors, CreatingInAReadOnlyFolderNamesTheFile) {
  const std::filesystem::path locked = folder_ / "locked";
  std::filesystem::create_directories(locked);
  ::chmod(folder_.c_str(), 0755); // an ordinary user may enter the scratch folder, not write in locked/
  ::chmod(locked.c_str(), 0555);
  const std::string message = thrown_as_ordinary_user(
      [&] { ResultsWriter writer(locked / "run.h5", locked / "run.xdmf", sample_metadata()); });
  EXPECT_NE(message.find((locked / "run.h5").string()), std::string::npos) << "thrown: '" << message << "'";
  ::chmod(locked.c_str(), 0700);
}

TEST_F(ResultsErrors, MismatchedStepIsRejectedAndWritesNothing) {
  ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
  write_sample_run(writer, 1);
  SampleStep wrong(1);
  wrong.positions[0] = sample_points(0, 1, 7, 0.0); // sheet has 12 points
  expect_throw_mentioning<std::invalid_argument>([&] { writer.write_step(wrong.record); },
                                                 "structure 'sheet': position_m has 7 points");
  wrong.record.structures.pop_back();
  expect_throw_mentioning<std::invalid_argument>([&] { writer.write_step(wrong.record); },
                                                 h5_path().string());
  EXPECT_EQ(writer.n_saved(), 1);
  const SampleStep right(1);
  writer.write_step(right.record); // the writer is still usable
  EXPECT_EQ(ResultsReader(h5_path()).n_saved(), 2);
}

TEST_F(ResultsErrors, AfterAFailedWriteFurtherStepsAreRefusedNamingTheFile) {
  const std::filesystem::path index_folder = folder_ / "index";
  std::filesystem::create_directories(index_folder);
  ResultsWriter writer(h5_path(), index_folder / "run.xdmf", sample_metadata());
  write_sample_run(writer, 1);
  std::filesystem::remove_all(index_folder); // the XDMF index can no longer be written
  const SampleStep second(1);
  expect_throw_mentioning<std::runtime_error>([&] { writer.write_step(second.record); },
                                              (index_folder / "run.xdmf").string());
  const SampleStep third(2);
  expect_throw_mentioning<std::runtime_error>([&] { writer.write_step(third.record); },
                                              "unusable after an earlier error");
  expect_throw_mentioning<std::runtime_error>([&] { writer.write_step(third.record); },
                                              h5_path().string());
  writer.set_status("diverged: output folder vanished"); // the status can still be recorded
  EXPECT_EQ(ResultsReader(h5_path()).string_attribute("/", "status"),
            "diverged: output folder vanished");
}

TEST_F(ResultsErrors, StructuresCannotBeAddedAfterTheFirstStep) {
  ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
  write_sample_run(writer, 1);
  expect_throw_mentioning<std::logic_error>(
      [&] {
        writer.add_structure({"late", "filament", 3, 1});
      },
      "'late'");
}

TEST_F(ResultsErrors, DuplicateStructureNamesAreRejected) {
  ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
  writer.add_structure(sheet_layout());
  expect_throw_mentioning<std::invalid_argument>([&] { writer.add_structure(sheet_layout()); },
                                                 "'sheet' added twice");
}

TEST_F(ResultsErrors, OpeningAMissingFileForReadingNamesIt) {
  const std::filesystem::path missing = folder_ / "missing.h5";
  expect_throw_mentioning<std::runtime_error>([&] { ResultsReader reader(missing); },
                                              missing.string());
}

TEST_F(ResultsErrors, NoHdf5ObjectStaysOpenAfterWritersAndReadersAreGone) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 2);
    const ResultsReader reader(h5_path());
    EXPECT_EQ(reader.position_m("fiber", 1), sample_points(1, 1, 5, 0.0));
  }
  EXPECT_THROW(ResultsWriter(folder_ / "missing" / "run.h5", xdmf_path(), sample_metadata()),
               std::runtime_error);
  EXPECT_THROW(ResultsWriter(h5_path(), folder_ / "missing" / "run.xdmf", sample_metadata()),
               std::runtime_error);
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

} // namespace
} // namespace fsi::structure::output::testing
