#pragma once
// Shared pieces of the results-file tests: a scratch folder per test, the two structures used
// throughout (a 4 x 3 membrane and a 5-point filament) and exactly known per-step values.

#include "structure_solver/output/ResultsWriter.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace fsi::structure::output::testing {

/// A fresh folder under the system temp directory, removed after the test.
class ScratchFolderTest : public ::testing::Test {
protected:
  void SetUp() override {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ =
        std::filesystem::temp_directory_path() / ("fsi_output_" + std::to_string(::getpid()) + "_" +
                                                  info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  std::filesystem::path h5_path() const { return folder_ / "run.h5"; }
  std::filesystem::path xdmf_path() const { return folder_ / "run.xdmf"; }

  std::filesystem::path folder_;
};

inline StructureLayout sheet_layout() { return {"sheet", "membrane", 4, 3}; }
inline StructureLayout fiber_layout() { return {"fiber", "filament", 5, 1}; }

inline RunMetadata sample_metadata() {
  return {"structure:\n  model: membrane\n  n1: 4\n", "v0.1.0-test"};
}

/// Exactly representable values, different for every structure, step, point and component.
inline PointArray sample_points(int structure_index, int saved_index, int n_points, double offset) {
  PointArray points(n_points, 3);
  for (int p = 0; p < n_points; ++p) {
    for (int c = 0; c < 3; ++c) {
      points(p, c) = offset + 100.0 * structure_index + 10.0 * saved_index + p + 0.25 * c;
    }
  }
  return points;
}

inline double sample_time_s(int saved_index) { return 0.1 * (saved_index + 1); }
inline long sample_step(int saved_index) { return 10L * saved_index + 7; }
inline double sample_scalar(int structure_index, int saved_index, int which) {
  return 1.5 + structure_index + 0.5 * saved_index + 0.0625 * which;
}

/// The arrays of one saved step for both structures; keeps them alive for the StepRecord.
struct SampleStep {
  explicit SampleStep(int saved_index) {
    const int n_points[2] = {sheet_layout().n_points(), fiber_layout().n_points()};
    record.step = sample_step(saved_index);
    record.time_s = sample_time_s(saved_index);
    for (int s = 0; s < 2; ++s) {
      positions[s] = sample_points(s, saved_index, n_points[s], 0.0);
      velocities[s] = sample_points(s, saved_index, n_points[s], -0.5);
      record.structures.push_back({&positions[s], &velocities[s], sample_scalar(s, saved_index, 0),
                                   sample_scalar(s, saved_index, 1),
                                   sample_scalar(s, saved_index, 2),
                                   sample_scalar(s, saved_index, 3)});
    }
  }
  SampleStep(const SampleStep &) = delete;
  SampleStep &operator=(const SampleStep &) = delete;

  PointArray positions[2];
  PointArray velocities[2];
  StepRecord record;
};

/// Creates a writer with the sheet and the fiber and writes `n_steps` sample steps.
inline void write_sample_run(ResultsWriter &writer, int n_steps) {
  writer.add_structure(sheet_layout());
  writer.add_structure(fiber_layout());
  for (int k = 0; k < n_steps; ++k) {
    const SampleStep sample(k);
    writer.write_step(sample.record);
  }
}

} // namespace fsi::structure::output::testing
