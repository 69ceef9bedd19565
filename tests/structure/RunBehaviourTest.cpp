// Behaviour a user relies on, through the real executable: bad input gives one clear error,
// exit code 2 and no results; a diverging run stops with exit code 1, a message naming the
// step, the point and the likely cause, and the last good state on disk; `--check` validates
// without running; docs/case-reference.md holds the reference generated from the declarations.

#include "CaseFixture.hpp"
#include "structure_solver/MemoryBudget.hpp"
#include "case/SchemaDoc.hpp"
#include "structure_solver/output/ResultsReader.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace fsi::structure {
namespace {

using Outcome = testing::SolverOutcome;

Outcome run_solver(const std::string &arguments) { return testing::run_structure_solver(arguments); }

const char *valid_case = R"(run: {end_time_s: 0.01, time_step_s: 1.0e-4, output_interval_s: 0.005}
gravity_m_per_s2: [0, 0, -9.81]
structures:
  - name: sheet
    model: membrane
    size_m: [0.1, 0.05]
    n_points: [11, 6]
    material:
      mass_per_area_kg_per_m2: 0.08
    edges: {s1_min: clamped}
)";

std::string with(const std::string &from, const std::string &to) {
  std::string yaml = valid_case;
  const auto at = yaml.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return yaml.replace(at, from.size(), to);
}

void expect_bad_input(const std::string &yaml, const std::string &expected_message) {
  const auto dir = testing::make_case_dir(yaml);
  const Outcome out = run_solver(dir.string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find(expected_message), std::string::npos) << out.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "output" / "structure.h5")) << "a rejected case wrote results";
}

// A grid that cannot fit in memory: refused when the case is read (exit 2, the memory it needs),
// before the output folder exists, not by std::bad_alloc. 100000 x 100000 points need ~37 TiB.
TEST(RunBehaviour, AGridThatCannotFitInMemoryIsRefusedBeforeAnyOutput) {
  const auto dir = testing::make_case_dir(with("n_points: [11, 6]", "n_points: [100000, 100000]"));
  for (const std::string &arguments : {"--check " + dir.string(), dir.string()}) {
    const Outcome out = run_solver(arguments);
    EXPECT_EQ(out.exit_code, 2) << out.output;
    EXPECT_NE(out.output.find("its grid of 100000 x 100000 points (10000000000 points in all) needs about 37.3 TiB"),
              std::string::npos)
        << out.output;
    EXPECT_NE(out.output.find("available"), std::string::npos) << out.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "output")) << "the output folder was made";
  }
}

TEST(RunBehaviour, MemoryBudgetCountsEveryStructuresPoints) {
  const auto setup = testing::load_case(with("n_points: [11, 6]", "n_points: [101, 201]"));
  const std::uint64_t expected = MemoryBudget::base_bytes + MemoryBudget::bytes_per_point * 101 * 201;
  EXPECT_EQ(MemoryBudget::estimate_bytes(setup.structures), expected);
  EXPECT_NO_THROW(MemoryBudget::check_fits(setup.structures, expected));     // just fits
  EXPECT_THROW(MemoryBudget::check_fits(setup.structures, expected - 1), common::ConfigError);
  EXPECT_NO_THROW(MemoryBudget::check_fits(setup.structures, 0));            // unknown: no check
  EXPECT_GT(MemoryBudget::available_bytes(), 0u);                            // Linux has MemAvailable
}

TEST(RunBehaviour, UnknownKeyIsRejectedWithASuggestion) {
  expect_bad_input(with("mass_per_area_kg_per_m2", "mass_per_aera_kg_per_m2"),
                   "unknown key 'structures[0].material.mass_per_aera_kg_per_m2'. Did you mean 'mass_per_area_kg_per_m2'?");
}

TEST(RunBehaviour, UnknownModelListsTheValidModels) {
  expect_bad_input(with("model: membrane", "model: membrain"), "Did you mean 'membrane'? Valid models: membrane, filament");
}

TEST(RunBehaviour, NegativeDensityIsOutOfRange) {
  expect_bad_input(with("mass_per_area_kg_per_m2: 0.08", "mass_per_area_kg_per_m2: -0.08"),
                   "mass_per_area_kg_per_m2 = -0.08 is out of range: allowed > 0 kg/m^2");
}

TEST(RunBehaviour, ImpossibleTimeStepIsRejected) {
  expect_bad_input(with("time_step_s: 1.0e-4", "time_step_s: 0"), "time_step_s = 0 is out of range");
  expect_bad_input(with("end_time_s: 0.01", "end_time_s: 1.0e-6"), "end_time_s must be at least one time step");
}

TEST(RunBehaviour, AStopPlaneWithoutANormalIsRejected) {
  expect_bad_input(with("output_interval_s: 0.005}", "output_interval_s: 0.005,\n     stop_when_past: {point_m: [0.3, 0, 0], normal: [0, 0, 0]}}"),
                   "run.stop_when_past.normal");
}

TEST(RunBehaviour, MissingMeshFileIsNamed) {
  expect_bad_input(std::string(valid_case) + "collisions:\n  surfaces:\n    - mesh: {file: impeller.stl}\n",
                   "impeller.stl': file not found");
}

TEST(RunBehaviour, NoStructureOnlyWithAnOpenFoamFluid) {
  // A scene without structures is the OpenFOAM flow alone with its rigid bodies (a pump's
  // performance): refused without an OpenFOAM fluid, and not a structure solver's job with one.
  const std::string none = "run: {end_time_s: 0.01, time_step_s: 1.0e-4, output_interval_s: 0.005}\nstructures: []\n";
  expect_bad_input(none, "must list at least one structure (none only with `fluid.openfoam`");
  const auto dir = testing::make_case_dir(none + "fluid:\n  openfoam: {case_directory: foam}\n");
  std::filesystem::create_directories(dir / "foam" / "system");
  const Outcome out = run_solver(dir.string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("has no structure: its flow runs alone (fsi-openfoam-fluid); run it with ./fsi run"),
            std::string::npos)
      << out.output;
}

TEST(RunBehaviour, MalformedYamlAndWrongTypesAreRejected) {
  expect_bad_input(with("n_points: [11, 6]", "n_points: [11, 6"), "not valid YAML");
  expect_bad_input(with("n_points: [11, 6]", "n_points: eleven"), "must be a list of two integers");
  expect_bad_input(with("{s1_min: clamped}", "{s1_min: glued}"), "'glued' is not one of: free, pinned, clamped, fixed");
}

TEST(RunBehaviour, CouplingSectionsAreCheckedLikeEveryOther) {
  const std::string flow = "fluid:\n  prescribed:\n    uniform: {velocity_m_per_s: [1, 0, 0]}\n";
  const std::string coupling = "coupling:\n  law: penalty\n  stiffness_n_per_m_per_measure: 1.0e5\n";
  expect_bad_input(std::string(valid_case) + coupling, "there is no `fluid` section");
  expect_bad_input(std::string(valid_case) + flow, "needs a `coupling` section");
  expect_bad_input(std::string(valid_case) + flow + "coupling: {law: penalti}\n",
                   "unknown coupling law 'penalti'. Did you mean 'penalty'? Valid laws: penalty");
  expect_bad_input(std::string(valid_case) + flow + "coupling: {stifness_n_per_m_per_measure: 1.0}\n",
                   "Did you mean 'stiffness_n_per_m_per_measure'?");
  expect_bad_input(std::string(valid_case) + "fluid:\n  prescribed:\n    uniform: {velocity_m_per_s: [1, 0, 0]}\n"
                                             "    quiescent: {}\n" + coupling,
                   "must hold exactly one of: quiescent, uniform, shear, rotation, table (found 2)");
  expect_bad_input(std::string(valid_case) + flow + "coupling: {heartbeat_interval_s: 1.0, timeout_s: 1.5}\n",
                   "must exceed twice heartbeat_interval_s");
}

TEST(RunBehaviour, CoupledParticipantWithPortZeroEndpointExplainsWhatToDo) {
  const auto dir = testing::make_case_dir(std::string(valid_case) +
                                          "fluid:\n  prescribed:\n    quiescent: {}\ncoupling: {law: penalty}\n");
  const Outcome out = run_solver("--coupled " + dir.string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("give --endpoint or a fixed port"), std::string::npos) << out.output;
}

TEST(RunBehaviour, APresetIsMergedOverTheCaseFile) {
  // presets/<name>.yaml overrides keys of case.yaml (maps key by key, list items by index).
  const auto dir = testing::make_case_dir(valid_case);
  std::filesystem::create_directories(dir / "presets");
  std::ofstream(dir / "presets" / "coarse.yaml") << "run: {time_step_s: 5.0e-4}\nstructures:\n  - n_points: [6, 4]\n";
  const Outcome plain = run_solver("--check " + dir.string());
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_NE(plain.output.find("100 steps"), std::string::npos) << plain.output;
  const Outcome coarse = run_solver("--check --resolution coarse " + dir.string());
  EXPECT_EQ(coarse.exit_code, 0) << coarse.output;
  EXPECT_NE(coarse.output.find("20 steps"), std::string::npos) << coarse.output;
  EXPECT_NE(coarse.output.find("6 x 4 points"), std::string::npos) << coarse.output;
  // size_m [0.1, 0.05] kept from case.yaml: spacing min(0.1 / 5, 0.05 / 3)
  EXPECT_NE(coarse.output.find("spacing 0.01667 m"), std::string::npos) << coarse.output;
  const Outcome unknown = run_solver("--check --resolution corse " + dir.string());
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("no preset 'corse'"), std::string::npos) << unknown.output;
  EXPECT_NE(unknown.output.find("Did you mean 'coarse'?"), std::string::npos) << unknown.output;
}

TEST(RunBehaviour, MissingCaseFolderIsBadInput) {
  const Outcome out = run_solver("/nonexistent/case");
  EXPECT_EQ(out.exit_code, 2);
  EXPECT_NE(out.output.find("not a case folder"), std::string::npos) << out.output;
}

TEST(RunBehaviour, CheckValidatesWithoutRunning) {
  const auto dir = testing::make_case_dir(valid_case);
  const Outcome out = run_solver("--check " + dir.string());
  EXPECT_EQ(out.exit_code, 0) << out.output;
  EXPECT_NE(out.output.find("is valid"), std::string::npos) << out.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "output"));
}

TEST(RunBehaviour, CompletedRunWritesResultsAndEffectiveConfiguration) {
  const auto dir = testing::make_case_dir(valid_case);
  const Outcome out = run_solver(dir.string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  output::ResultsReader results(dir / "output" / "structure.h5");
  EXPECT_EQ(results.n_saved(), 3); // t = 0, 0.005, 0.01
  EXPECT_EQ(results.string_attribute("/", "status"), "completed");
  EXPECT_TRUE(std::filesystem::exists(dir / "output" / "structure.xdmf"));
  std::ifstream effective(dir / "output" / "config.effective.yaml");
  std::stringstream text;
  text << effective.rdbuf();
  EXPECT_NE(text.str().find("damping_kg_per_m2_s: 0"), std::string::npos) << "defaults must be echoed";
}

TEST(RunBehaviour, DivergenceStopsWithStepPointCauseAndLastGoodState) {
  // phi = 1e5 N/m with rho_1 = 0.08 kg/m^2: tension wave speed sqrt(2 phi / rho_1) = 1600 m/s,
  // far beyond Delta s / Delta t = 100 m/s: the semi-implicit tension step is unstable.
  const std::string yaml = with("mass_per_area_kg_per_m2: 0.08",
                                "mass_per_area_kg_per_m2: 0.08\n      coefficients: {tension_coefficient_n_per_m: 1.0e5}");
  const auto dir = testing::make_case_dir(yaml);
  const Outcome out = run_solver(dir.string());
  EXPECT_EQ(out.exit_code, 1) << out.output;
  EXPECT_NE(out.output.find("diverged at step"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("(i1, i2) = "), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("Likely cause: the time step is too large"), std::string::npos) << out.output;
  output::ResultsReader results(dir / "output" / "structure.h5");
  EXPECT_EQ(results.string_attribute("/", "status").rfind("diverged: step ", 0), 0u);
  const PointArray last = results.position_m("sheet", results.n_saved() - 1);
  EXPECT_TRUE(last.allFinite());
}

TEST(RunBehaviour, ARunawayThatDoesNotStretchIsStoppedByTheSpeedGuard) {
  // A rigid translation never stretches the sheet: the speed guard catches it (here a sheet
  // thrown at 50 m/s with a 20 m/s limit).
  const std::string yaml = with("edges: {s1_min: clamped}", "edges: {s1_min: free}\n    initial: {velocity_m_per_s: [50, 0, 0]}"
                                                            "\n    solver: {max_speed_m_per_s: 20}");
  const auto dir = testing::make_case_dir(yaml);
  const Outcome out = run_solver(dir.string());
  EXPECT_EQ(out.exit_code, 1) << out.output;
  EXPECT_NE(out.output.find("exceeds solver.max_speed_m_per_s = 20"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("Likely cause: a coupling too stiff"), std::string::npos) << out.output;
}

TEST(RunBehaviour, InterruptKeepsTheResultsSoFarAndSaysSo) {
  // 400k steps would take minutes; SIGINT after 1 s must stop it with exit code 130, the
  // steps so far in the file and status "interrupted".
  const auto dir = testing::make_case_dir(with("end_time_s: 0.01", "end_time_s: 40.0"));
  const Outcome out = testing::run_structure_solver(dir.string(), "timeout --preserve-status -s INT 1 ");
  EXPECT_EQ(out.exit_code, 130) << out.output;
  output::ResultsReader results(dir / "output" / "structure.h5");
  EXPECT_EQ(results.string_attribute("/", "status"), "interrupted");
  EXPECT_GE(results.n_saved(), 2);
  EXPECT_TRUE(results.position_m("sheet", results.n_saved() - 1).allFinite());
}

TEST(RunBehaviour, CaseReferenceDocHoldsTheGeneratedSchema) {
  std::ifstream doc(std::string(FSI_SOURCE_DIR) + "/docs/case-reference.md");
  std::stringstream text;
  text << doc.rdbuf();
  EXPECT_NE(text.str().find(case_config::case_schema_markdown()), std::string::npos)
      << "docs/case-reference.md is stale: regenerate it with scripts/update_case_reference.sh (after a build)";
}

} // namespace
} // namespace fsi::structure
