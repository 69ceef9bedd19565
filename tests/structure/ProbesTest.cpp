// The `probes` list of a case: checked at load (file, line, key, value and what is allowed),
// echoed in the effective configuration, and written by the real fsi-structure into
// structure.h5 (/probes/<name>, aligned with /time_s) and probes.csv, which agree.

#include "CaseFixture.hpp"
#include "structure_solver/output/ResultsPaths.hpp"
#include "structure_solver/output/ResultsReader.hpp"

#include "common/ConfigEmitter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace fsi::structure {
namespace {

// A free sheet and a pinned chain, both falling or swinging under gravity.
const char *two_structures = R"(run: {end_time_s: 0.02, time_step_s: 1.0e-4, output_interval_s: 0.005}
gravity_m_per_s2: [0, 0, -9.81]
structures:
  - name: sheet
    model: membrane
    size_m: [0.1, 0.05]
    n_points: [11, 6]
    origin_m: [0, 0, 1]
  - name: chain
    model: filament
    length_m: 0.2
    n_points: 11
    tension_coefficient_n: 200
)";

const char *three_probes = R"(probes:
  - {name: centre, structure: sheet, at: centroid}
  - {name: free_edge, structure: sheet, at: edge_centre, edge: s1_max}
  - {name: tip, structure: chain, at: edge_centre, edge: end}
)";

std::string load_error(const std::string &probes_yaml) {
  try {
    testing::load_case(std::string(two_structures) + probes_yaml);
  } catch (const common::ConfigError &e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string &probes_yaml, const std::string &expected) {
  const std::string message = load_error(probes_yaml);
  EXPECT_NE(message.find(expected), std::string::npos) << "message: " << message;
  EXPECT_NE(message.find("case.yaml:"), std::string::npos) << "names the file: " << message;
}

std::vector<std::string> split(const std::string &line, char separator) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, separator))
    fields.push_back(field);
  return fields;
}

TEST(Probes, EveryKindLoadsAndIsEchoedWithItsOwnKeysOnly) {
  StructureSetup config = testing::load_case(std::string(two_structures) + three_probes +
                                         "  - {name: corner, structure: sheet, at: point, index: [10, 5]}\n"
                                         "  - {name: middle, structure: chain, at: point, index: [5]}\n");
  ASSERT_EQ(config.probes.size(), 5u);
  EXPECT_EQ(config.probes[1].at, ProbeLocation::edge_centre);
  EXPECT_EQ(config.probes[1].edge, "s1_max");
  EXPECT_EQ(config.probes[3].index, (std::vector<int>{10, 5}));
  const YAML::Node echoed = YAML::Load(config.case_yaml)["probes"];
  EXPECT_EQ(echoed[0]["at"].as<std::string>(), "centroid");
  EXPECT_FALSE(echoed[0]["edge"]);
  EXPECT_FALSE(echoed[0]["index"]);
  EXPECT_EQ(echoed[2]["edge"].as<std::string>(), "end");
  EXPECT_EQ(echoed[4]["index"].as<std::vector<int>>(), (std::vector<int>{5}));
}

TEST(Probes, AnUnknownStructureIsNamedWithTheStructuresOfTheCase) {
  expect_error("probes:\n  - {name: c, structure: shet, at: centroid}\n",
               "probes[0].structure = 'shet' is not a structure of this case. Did you mean 'sheet'? Structures: "
               "sheet, chain.");
}

TEST(Probes, EdgesAreThoseOfTheModel) {
  expect_error("probes:\n  - {name: e, structure: chain, at: edge_centre, edge: s1_max}\n",
               "probes[0].edge = 's1_max' is not an edge of filament 'chain'. Allowed: start, end.");
  expect_error("probes:\n  - {name: e, structure: sheet, at: edge_centre, edge: s1_mx}\n",
               "Did you mean 's1_max'? Allowed: s1_min, s1_max, s2_min, s2_max.");
  expect_error("probes:\n  - {name: e, structure: sheet, at: edge_centre}\n",
               "probes[0] has `at: edge_centre` but no `edge`");
  expect_error("probes:\n  - {name: e, structure: sheet, at: centroid, edge: s1_max}\n",
               "probes[0].edge is only read with `at: edge_centre`; this probe has `at: centroid`.");
}

TEST(Probes, PointIndicesMustLieOnTheGrid) {
  expect_error("probes:\n  - {name: p, structure: sheet, at: point, index: [11, 0]}\n",
               "probes[0].index = [11, 0] is outside the grid of 'sheet' ([11, 6] points)");
  expect_error("probes:\n  - {name: p, structure: chain, at: point, index: [1, 2]}\n",
               "probes[0].index = [1, 2] must hold one index [i] (a filament).");
  expect_error("probes:\n  - {name: p, structure: sheet, at: point, index: [3]}\n",
               "must hold two indices [i1, i2] (a membrane).");
  expect_error("probes:\n  - {name: p, structure: sheet, at: point}\n", "probes[0] has `at: point` but no `index`");
}

TEST(Probes, NamesAreUniqueAndUsableAsColumnsAndUnknownKeysAreRejected) {
  expect_error("probes:\n  - {name: a, structure: sheet}\n  - {name: a, structure: chain}\n",
               "probes[1].name = 'a' is used by two probes; probe names must be unique.");
  expect_error("probes:\n  - {name: a.b, structure: sheet}\n", "probes[0].name = 'a.b' is not allowed");
  expect_error("probes:\n  - {structure: sheet}\n", "probes[0].name is missing");
  expect_error("probes:\n  - {name: a, structure: sheet, at: centriod}\n",
               "probes[0].at 'centriod' is not one of: centroid, edge_centre, point. Did you mean 'centroid'?");
  expect_error("probes:\n  - {name: a, structur: sheet}\n",
               "unknown key 'probes[0].structur'. Did you mean 'structure'?");
}

TEST(Probes, TheRunWritesMatchingHdf5DatasetsAndCsv) {
  const auto dir = testing::make_case_dir(std::string(two_structures) + three_probes);
  const auto out = testing::run_structure_solver(dir.string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  output::ResultsReader results(dir / "output" / "structure.h5");
  const long n = results.n_saved();
  ASSERT_EQ(n, 5); // t = 0, 0.005, ..., 0.02
  EXPECT_EQ(results.probe_names(), (std::vector<std::string>{"centre", "free_edge", "tip"})); // alphabetical
  for (const std::string name : {"centre", "free_edge", "tip"}) {
    EXPECT_EQ(results.dataset_shape(output::paths::probe_dataset(name, "position_m")), (std::vector<hsize_t>{5, 3}));
    EXPECT_EQ(results.dataset_shape(output::paths::probe_dataset(name, "velocity_m_per_s")),
              (std::vector<hsize_t>{5, 3}));
    EXPECT_EQ(results.string_attribute(output::paths::probe_dataset(name, "position_m"), "units"), "m");
    EXPECT_EQ(results.string_attribute(output::paths::probe_dataset(name, "velocity_m_per_s"), "units"), "m/s");
  }

  std::ifstream csv(dir / "output" / "probes.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  std::string expected_header = "time_s";
  for (const std::string name : {"centre", "free_edge", "tip"})
    for (const char *column : {".x_m", ".y_m", ".z_m", ".u_m_per_s", ".v_m_per_s", ".w_m_per_s"})
      expected_header += "," + name + column;
  EXPECT_EQ(line, expected_header);

  const std::vector<double> time_s = results.time_s();
  const std::vector<std::string> order = {"centre", "free_edge", "tip"}; // case-file order
  long row = 0;
  for (; std::getline(csv, line); ++row) {
    const auto fields = split(line, ',');
    ASSERT_EQ(fields.size(), 1u + 6u * order.size()) << line;
    ASSERT_LT(row, n);
    EXPECT_NEAR(std::stod(fields[0]), time_s[static_cast<std::size_t>(row)], 1e-12);
    for (std::size_t p = 0; p < order.size(); ++p) {
      const PointArray x = results.probe_series(order[p], "position_m");
      const PointArray v = results.probe_series(order[p], "velocity_m_per_s");
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(std::stod(fields[1 + 6 * p + k]), x(row, k), 1e-13 * (1.0 + std::abs(x(row, k))));
        EXPECT_NEAR(std::stod(fields[4 + 6 * p + k]), v(row, k), 1e-13 * (1.0 + std::abs(v(row, k))));
      }
    }
  }
  EXPECT_EQ(row, n);

  // The free sheet falls as a rigid body: its centre of mass starts at (0.05, 0.025, 1) and
  // follows z = 1 - g t^2 / 2, w = -g t (to the time discretisation).
  const PointArray centre = results.probe_series("centre", "position_m");
  const PointArray centre_v = results.probe_series("centre", "velocity_m_per_s");
  EXPECT_NEAR(centre(0, 0), 0.05, 1e-12);
  EXPECT_NEAR(centre(0, 1), 0.025, 1e-12);
  const double t = time_s.back();
  EXPECT_NEAR(centre(n - 1, 2), 1.0 - 0.5 * 9.81 * t * t, 1e-5);
  EXPECT_NEAR(centre_v(n - 1, 2), -9.81 * t, 1e-3);
  // The chain hangs from the origin along -z: its tip starts 0.2 m below.
  const PointArray tip = results.probe_series("tip", "position_m");
  EXPECT_NEAR(tip(0, 2), -0.2, 1e-12);
}

TEST(Probes, WithoutProbesThereIsNoProbesGroupAndNoCsv) {
  const auto dir = testing::make_case_dir(two_structures);
  std::filesystem::create_directories(dir / "output");
  std::ofstream(dir / "output" / "probes.csv") << "time_s,old.x_m\n"; // left by an earlier run
  const auto out = testing::run_structure_solver(dir.string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  output::ResultsReader results(dir / "output" / "structure.h5");
  EXPECT_TRUE(results.probe_names().empty());
  EXPECT_FALSE(std::filesystem::exists(dir / "output" / "probes.csv"));
}

} // namespace
} // namespace fsi::structure
