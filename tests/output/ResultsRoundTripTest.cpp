// Writes three steps of a 4 x 3 membrane and a 5-point filament and reads every value back.

#include "OutputTestSupport.hpp"

#include "structure_solver/output/ResultsReader.hpp"

#include <cstdint>
#include <vector>

namespace fsi::structure::output::testing {
namespace {

class ResultsRoundTrip : public ScratchFolderTest {
protected:
  void SetUp() override {
    ScratchFolderTest::SetUp();
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, n_steps);
  }
  static constexpr int n_steps = 3;
};

TEST_F(ResultsRoundTrip, TimesAndStepsAreReadBackExactly) {
  const ResultsReader reader(h5_path());
  ASSERT_EQ(reader.n_saved(), n_steps);
  const std::vector<double> times = reader.time_s();
  const std::vector<std::int64_t> steps = reader.steps();
  ASSERT_EQ(times.size(), 3u);
  ASSERT_EQ(steps.size(), 3u);
  for (int k = 0; k < n_steps; ++k) {
    EXPECT_EQ(times[k], sample_time_s(k));
    EXPECT_EQ(steps[k], sample_step(k));
  }
}

TEST_F(ResultsRoundTrip, DatasetShapesFollowTheLayout) {
  const ResultsReader reader(h5_path());
  using Shape = std::vector<hsize_t>;
  EXPECT_EQ(reader.dataset_shape("/time_s"), Shape({3}));
  EXPECT_EQ(reader.dataset_shape("/step"), Shape({3}));
  EXPECT_EQ(reader.dataset_shape("/structures/sheet/position_m"), Shape({3, 12, 3}));
  EXPECT_EQ(reader.dataset_shape("/structures/sheet/velocity_m_per_s"), Shape({3, 12, 3}));
  EXPECT_EQ(reader.dataset_shape("/structures/fiber/position_m"), Shape({3, 5, 3}));
  EXPECT_EQ(reader.dataset_shape("/structures/fiber/kinetic_energy_j"), Shape({3}));
  EXPECT_EQ(reader.dataset_shape("/structures/sheet/connectivity"), Shape({6, 4}));
  EXPECT_EQ(reader.dataset_shape("/structures/fiber/connectivity"), Shape({4, 2}));
}

TEST_F(ResultsRoundTrip, PositionsAndVelocitiesAreReadBackExactly) {
  const ResultsReader reader(h5_path());
  const std::string names[2] = {"sheet", "fiber"};
  const int n_points[2] = {12, 5};
  for (int s = 0; s < 2; ++s) {
    for (int k = 0; k < n_steps; ++k) {
      EXPECT_EQ(reader.position_m(names[s], k), sample_points(s, k, n_points[s], 0.0))
          << names[s] << " step " << k;
      EXPECT_EQ(reader.velocity_m_per_s(names[s], k), sample_points(s, k, n_points[s], -0.5))
          << names[s] << " step " << k;
    }
  }
}

TEST_F(ResultsRoundTrip, StretchAndEnergiesAreReadBackExactly) {
  const ResultsReader reader(h5_path());
  const std::string names[2] = {"sheet", "fiber"};
  const std::string series[4] = {"max_stretch_ratio", "kinetic_energy_j", "elastic_energy_j",
                                 "potential_energy_j"};
  for (int s = 0; s < 2; ++s) {
    for (int which = 0; which < 4; ++which) {
      const std::vector<double> values = reader.structure_series(names[s], series[which]);
      ASSERT_EQ(values.size(), 3u);
      for (int k = 0; k < n_steps; ++k) {
        EXPECT_EQ(values[k], sample_scalar(s, k, which)) << names[s] << " " << series[which];
      }
    }
  }
}

TEST_F(ResultsRoundTrip, RootAttributesDescribeTheRun) {
  const ResultsReader reader(h5_path());
  EXPECT_EQ(reader.string_attribute("/", "units"), "SI");
  EXPECT_EQ(reader.string_attribute("/", "config_yaml"), sample_metadata().config_yaml);
  EXPECT_EQ(reader.string_attribute("/", "code_version"), "v0.1.0-test");
  EXPECT_EQ(reader.string_attribute("/", "status"), "running");
  const std::string created = reader.string_attribute("/", "created_utc");
  ASSERT_EQ(created.size(), 20u) << created; // 2024-01-31T12:00:00Z
  EXPECT_EQ(created[4], '-');
  EXPECT_EQ(created[10], 'T');
  EXPECT_EQ(created.back(), 'Z');
}

TEST_F(ResultsRoundTrip, StructureGroupsCarryModelGridShapeAndPointOrder) {
  const ResultsReader reader(h5_path());
  EXPECT_EQ(reader.structure_names(), std::vector<std::string>({"fiber", "sheet"}));
  EXPECT_EQ(reader.string_attribute("/structures/sheet", "model"), "membrane");
  EXPECT_EQ(reader.string_attribute("/structures/fiber", "model"), "filament");
  EXPECT_EQ(reader.int_attribute("/structures/sheet", "grid_shape"),
            std::vector<std::int64_t>({4, 3}));
  EXPECT_EQ(reader.int_attribute("/structures/fiber", "grid_shape"),
            std::vector<std::int64_t>({5, 1}));
  EXPECT_EQ(reader.string_attribute("/structures/sheet", "point_order"),
            "row-major over (s1, s2): index = i1 * n2 + i2");
  const StructureLayout sheet = reader.layout("sheet");
  EXPECT_EQ(sheet.model, "membrane");
  EXPECT_EQ(sheet.n1, 4);
  EXPECT_EQ(sheet.n2, 3);
}

TEST_F(ResultsRoundTrip, EveryDatasetHasItsUnits) {
  const ResultsReader reader(h5_path());
  EXPECT_EQ(reader.string_attribute("/time_s", "units"), "s");
  EXPECT_EQ(reader.string_attribute("/step", "units"), "1");
  for (const std::string name : {"sheet", "fiber"}) {
    const std::string group = "/structures/" + name + "/";
    EXPECT_EQ(reader.string_attribute(group + "position_m", "units"), "m");
    EXPECT_EQ(reader.string_attribute(group + "velocity_m_per_s", "units"), "m/s");
    EXPECT_EQ(reader.string_attribute(group + "max_stretch_ratio", "units"), "1");
    EXPECT_EQ(reader.string_attribute(group + "kinetic_energy_j", "units"), "J");
    EXPECT_EQ(reader.string_attribute(group + "elastic_energy_j", "units"), "J");
    EXPECT_EQ(reader.string_attribute(group + "potential_energy_j", "units"), "J");
    EXPECT_EQ(reader.string_attribute(group + "connectivity", "units"), "1");
  }
}

TEST_F(ResultsRoundTrip, MembraneConnectivityIsSixCounterClockwiseQuadsOverRowMajorPoints) {
  const Connectivity cells = ResultsReader(h5_path()).connectivity("sheet");
  ASSERT_EQ(cells.nodes_per_cell, 4);
  // Points i1 * 3 + i2 of the 4 x 3 grid; quad (i1, i2) = (i1,i2) (i1+1,i2) (i1+1,i2+1) (i1,i2+1).
  const std::vector<std::int64_t> expected = {0, 3, 4, 1, 1, 4, 5,  2, 3, 6,  7,  4,
                                              4, 7, 8, 5, 6, 9, 10, 7, 7, 10, 11, 8};
  EXPECT_EQ(cells.node_indices, expected);
}

TEST_F(ResultsRoundTrip, FilamentConnectivityIsConsecutiveSegments) {
  const Connectivity cells = ResultsReader(h5_path()).connectivity("fiber");
  ASSERT_EQ(cells.nodes_per_cell, 2);
  EXPECT_EQ(cells.node_indices, std::vector<std::int64_t>({0, 1, 1, 2, 2, 3, 3, 4}));
}

TEST_F(ResultsRoundTrip, ReadingAStepBeyondTheSavedOnesThrows) {
  const ResultsReader reader(h5_path());
  EXPECT_THROW(reader.position_m("sheet", 3), std::out_of_range);
  EXPECT_THROW(reader.position_m("sheet", -1), std::out_of_range);
}

TEST_F(ResultsRoundTrip, AskingForAnUnknownStructureListsTheKnownOnes) {
  const ResultsReader reader(h5_path());
  try {
    reader.position_m("shet", 0);
    FAIL() << "no exception for an unknown structure";
  } catch (const std::out_of_range &error) {
    EXPECT_NE(std::string(error.what()).find("no structure 'shet'; the file has: fiber, sheet"),
              std::string::npos)
        << error.what();
  }
}

} // namespace
} // namespace fsi::structure::output::testing
