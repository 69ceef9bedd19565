// Rags that enter and leave a running scene (issue 33): release times, removal past a plane, the
// feed section expanded into structures, and the state a restart needs. Through the real parser
// (CaseFixture) and the real Scene.

#include "CaseFixture.hpp"

#include "common/ConfigError.hpp"
#include "structure_solver/feed/FeedSchedule.hpp"
#include "structure_solver/output/ResultsPaths.hpp"
#include "structure_solver/output/ResultsReader.hpp"

#include <gtest/gtest.h>

#include <malloc.h>

#include <cmath>
#include <fstream>

namespace fsi::structure {
namespace {

/// Two 4 cm rags falling freely (no fluid), dt = 1 ms; the second released at 10 ms, the first
/// removed once all its points are 5 cm below where it started.
const char *two_rags = R"(run: {end_time_s: 1, time_step_s: 1.0e-3, output_interval_s: 0.01}
gravity_m_per_s2: [0, 0, -9.81]
structures:
  - name: first
    model: membrane
    size_m: [0.04, 0.04]
    n_points: [5, 5]
    origin_m: [0, 0, 0]
    s1_direction: [1, 0, 0]
    s2_direction: [0, 1, 0]
    remove_when_past: {point_m: [0, 0, -0.05], normal: [0, 0, -1]}
  - name: second
    model: membrane
    size_m: [0.04, 0.04]
    n_points: [5, 5]
    origin_m: [0.1, 0, 0]
    s1_direction: [1, 0, 0]
    s2_direction: [0, 1, 0]
    release_time_s: 0.01
)";

TEST(Feed, ARagWaitsUntilItsReleaseAndThenFallsAsOneReleasedAtTheStart) {
  Scene scene(testing::load_case(two_rags));
  const auto &first = *scene.structures()[0], &second = *scene.structures()[1];
  const PointArray first_start = first.positions_m(), second_start = second.positions_m();
  EXPECT_FALSE(scene.life().in_scene(1));
  for (int k = 0; k < 10; ++k)
    scene.advance();
  EXPECT_EQ(second.positions_m(), second_start); // waited, bit for bit
  EXPECT_FALSE(scene.life().in_scene(1));
  const PointArray first_at_10 = first.positions_m() - first_start;
  for (int k = 0; k < 10; ++k)
    scene.advance();
  EXPECT_TRUE(scene.life().in_scene(1));
  // 10 steps after its release it has fallen as far as the first had 10 steps after the start:
  // Eq. (4)'s free fall, g dt^2 n (n + 1) / 2 = 0.540 mm at n = 10, to round-off.
  EXPECT_NEAR(second.time_s(), scene.time_s(), 1e-15);
  EXPECT_LT(((second.positions_m() - second_start) - first_at_10).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(first_at_10(0, 2), -9.81 * 1e-6 * 10 * 11 / 2, 1e-15);
}

TEST(Feed, ARagPastItsPlaneIsRemovedKeepsItsLastStateAndFreesItsSolver) {
  Scene scene(testing::load_case(two_rags));
  const auto &first = *scene.structures()[0], &second = *scene.structures()[1];
  // z = -0.05 m in free fall: t = sqrt(2 * 0.05 / 9.81) = 0.101 s, the end of step 102 or so.
  int removed_at = -1;
  for (int k = 1; k <= 200 && removed_at < 0; ++k) {
    scene.advance();
    if (!scene.remove_past_planes().empty())
      removed_at = k;
    else
      EXPECT_GT(first.positions_m().col(2).maxCoeff(), -0.05) << "step " << k;
  }
  ASSERT_GT(removed_at, 0);
  EXPECT_LT(first.positions_m().col(2).maxCoeff(), -0.05);
  EXPECT_NEAR(scene.life().exit_time_s(0), removed_at * 1e-3, 1e-12);
  EXPECT_NEAR(scene.life().exit_time_s(0), std::sqrt(2 * 0.05 / 9.81), 2e-3);
  EXPECT_TRUE(std::isnan(scene.life().exit_time_s(1)));
  EXPECT_TRUE(first.retired());
  EXPECT_THROW(scene.structures()[0]->advance(PointArray::Zero(25, 3)), std::logic_error);
  const PointArray left = first.positions_m(), second_then = second.positions_m();
  for (int k = 0; k < 5; ++k)
    scene.advance();
  EXPECT_EQ(first.positions_m(), left); // gone: stays where it left, never advanced
  EXPECT_LT(second.positions_m().col(2).maxCoeff(), second_then.col(2).minCoeff()); // the other goes on
  EXPECT_EQ(scene.life().n_in_scene(), 1u);
}

/// A 4 cm rag pinned along one edge and hanging under gravity (it stretches a little), torn off
/// above a stretch ratio of 1.00001; beside it a free one falling.
const char *hanging_and_falling = R"(run: {end_time_s: 1, time_step_s: 1.0e-3, output_interval_s: 0.01}
gravity_m_per_s2: [0, 0, -9.81]
structures:
  - name: hanging
    model: membrane
    size_m: [0.04, 0.04]
    n_points: [5, 5]
    origin_m: [0, 0, 0]
    s1_direction: [0, 0, -1]
    s2_direction: [0, 1, 0]
    edges: {s1_min: pinned}
    tear_above_stretch_ratio: 1.00001
    solver: {max_stretch_ratio: 1.000001}
  - name: falling
    model: membrane
    size_m: [0.04, 0.04]
    n_points: [5, 5]
    origin_m: [0.1, 0, 0]
    s1_direction: [1, 0, 0]
    s2_direction: [0, 1, 0]
)";

TEST(Feed, ARagStretchedBeyondItsTearLimitIsTornOffAndTheOthersGoOn) {
  Scene scene(testing::load_case(hanging_and_falling));
  const auto &hanging = *scene.structures()[0], &falling = *scene.structures()[1];
  int torn_at = -1;
  for (int k = 1; k <= 100 && torn_at < 0; ++k) {
    scene.advance();
    const double stretch = hanging.max_stretch_ratio();
    const auto ratios = scene.max_stretch_ratios();
    ASSERT_EQ(ratios.size(), 2u);
    EXPECT_EQ(ratios[0], stretch);  // what the coupler gets, bit for bit (also once it is torn)
    EXPECT_EQ(ratios[1], 1.0);      // the falling one cannot tear
    if (!scene.tear_overstretched().empty()) {
      torn_at = k;
      EXPECT_GT(stretch, 1.00001);
    } else {
      EXPECT_LE(stretch, 1.00001) << "step " << k;
    }
  }
  ASSERT_GT(torn_at, 0);
  EXPECT_EQ(scene.life().life(0), participant::Life::gone);
  EXPECT_EQ(scene.life().exit_reason(0), participant::ExitReason::torn);
  EXPECT_NEAR(scene.life().exit_time_s(0), torn_at * 1e-3, 1e-12);
  EXPECT_TRUE(hanging.retired());
  const PointArray left = hanging.positions_m(), falling_then = falling.positions_m();
  for (int k = 0; k < 5; ++k)
    scene.advance();
  EXPECT_EQ(hanging.positions_m(), left);
  EXPECT_LT(falling.positions_m().col(2).maxCoeff(), falling_then.col(2).minCoeff());
  // The reason survives a checkpoint.
  checkpoint::StateArchive archive;
  scene.save_state(archive);
  Scene resumed(testing::load_case(hanging_and_falling));
  resumed.load_state(archive);
  EXPECT_EQ(resumed.life().exit_reason(0), participant::ExitReason::torn);
  EXPECT_EQ(resumed.life().exit_time_s(0), scene.life().exit_time_s(0));
}

TEST(Feed, ATornRagNoLongerStopsTheRunAndItsReasonIsInTheResults) {
  // solver.max_stretch_ratio 1.000001 would stop the run as diverged; the tear limit takes its place.
  std::string yaml = hanging_and_falling;
  yaml.replace(yaml.find("end_time_s: 1,"), 14, "end_time_s: 0.1,");
  const auto dir = testing::make_case_dir(yaml);
  const auto out = testing::run_structure_solver(dir.string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_NE(out.output.find("structure 'hanging' torn off the scene"), std::string::npos) << out.output;
  output::ResultsReader results(dir / "output" / "structure.h5");
  EXPECT_EQ(results.string_attribute(output::paths::structure_group("hanging"), "exit_reason"), "torn");
  EXPECT_EQ(results.string_attribute(output::paths::structure_group("falling"), "exit_reason"), "");
}

TEST(Feed, ATearLimitOfOneOrLessIsRefused) {
  std::string yaml = hanging_and_falling;
  yaml.replace(yaml.find("tear_above_stretch_ratio: 1.00001"), 33, "tear_above_stretch_ratio: 0.9");
  try {
    testing::load_case(yaml);
    FAIL() << "accepted";
  } catch (const common::ConfigError &e) {
    EXPECT_NE(std::string(e.what()).find("tear_above_stretch_ratio"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0 (never torn) or a ratio above 1"), std::string::npos) << e.what();
  }
}

TEST(Feed, TheSceneStateSavedAndLoadedResumesReleasesAndRemovalsBitForBit) {
  Scene full(testing::load_case(two_rags)), resumed(testing::load_case(two_rags));
  checkpoint::StateArchive archive;
  double saved_at = 0.0;
  for (int k = 0; k < 105; ++k) { // past the first's removal, the second released
    full.advance();
    full.remove_past_planes();
    if (k == 4) { // before the release
      full.save_state(archive);
      saved_at = full.time_s();
    }
  }
  resumed.load_state(archive);
  EXPECT_EQ(resumed.time_s(), saved_at);
  for (int k = 5; k < 105; ++k) {
    resumed.advance();
    resumed.remove_past_planes();
  }
  EXPECT_EQ(resumed.time_s(), full.time_s());
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(resumed.structures()[i]->positions_m(), full.structures()[i]->positions_m()) << i;
    EXPECT_EQ(resumed.life().life(i), full.life().life(i)) << i;
  }
  EXPECT_EQ(resumed.life().exit_time_s(0), full.life().exit_time_s(0));
  // A checkpoint of a gone rag: loading it retires the rag again.
  checkpoint::StateArchive after;
  full.save_state(after);
  Scene again(testing::load_case(two_rags));
  again.load_state(after);
  EXPECT_TRUE(again.structures()[0]->retired());
  EXPECT_EQ(again.life().life(0), Life::gone);
}

TEST(Feed, APlacedRagHasItsCentroidAtTheCentreAndItsShapeTurned) {
  std::string yaml = two_rags;
  yaml += R"(    placement: {centre_m: [0.3, 0.2, 0.1], turn_axis: [0, 0, 2], turn_angle_deg: 90}
)";
  Scene scene(testing::load_case(yaml));
  const auto &s = *scene.structures()[1];
  const Vec3 centroid = s.positions_m().colwise().mean().transpose();
  EXPECT_LT((centroid - Vec3(0.3, 0.2, 0.1)).norm(), 1e-15);
  // s1 was +x; turned 90 deg about +z it is +y: points (0, 0) and (4, 0) differ by 4 cm along y.
  const Eigen::RowVector3d edge = s.positions_m().row(4 * 5) - s.positions_m().row(0);
  EXPECT_LT((edge - Eigen::RowVector3d(0, 0.04, 0)).norm(), 1e-15);
}

const char *feed_case = R"(run: {end_time_s: 0.1, time_step_s: 1.0e-3, output_interval_s: 0.01}
feed:
  rags: 5
  seed: 7
  spacing: poisson
  interval_s: 0.02
  first_release_s: 0.005
  region: {min_m: [-0.1, -0.1, 0.2], max_m: [0.1, 0.1, 0.3]}
  kinds:
    - name: wipe
      model: membrane
      size_m: [0.04, 0.02]
      n_points: [5, 3]
    - model: membrane
      size_m: [0.03, 0.03]
      n_points: [4, 4]
  remove_when_past: {point_m: [0, 0, -1], normal: [0, 0, -1]}
)";

TEST(Feed, TheFeedSectionBecomesOneStructurePerReleaseOfItsSchedule) {
  const auto dir = testing::make_case_dir(feed_case);
  const auto config = case_config::CaseConfig::load(dir);
  ASSERT_EQ(config.structures.size(), 5u);
  EXPECT_EQ(config.n_fed, 5u);
  const auto releases = feed::draw_releases(config.feed->plan());
  const char *names[] = {"wipe01", "rag02", "wipe03", "rag04", "wipe05"};
  for (std::size_t i = 0; i < 5; ++i) {
    const auto &s = config.structures[i];
    EXPECT_EQ(s.name, names[i]);
    EXPECT_EQ(s.release_time_s, releases[i].time_s) << i; // through YAML, bit for bit
    ASSERT_TRUE(s.placement && s.remove_when_past);
    EXPECT_EQ(s.placement->centre_m, releases[i].centre_m) << i;
    const Eigen::Matrix3d turn = releases[i].turn.toRotationMatrix();
    EXPECT_LT((s.placement->rotation() - turn).cwiseAbs().maxCoeff(), 1e-14) << i;
    EXPECT_EQ(s.remove_when_past->normal, Vec3(0, 0, -1));
  }
  EXPECT_GT(config.structures[1].release_time_s, 0.005);
  // The emitted configuration declares the feed, not its rags: read again, it is the same case.
  const auto again_dir = testing::make_case_dir(common::to_yaml(const_cast<case_config::CaseConfig &>(config)));
  const auto again = case_config::CaseConfig::load(again_dir);
  EXPECT_EQ(again.structures.size(), 5u);
  EXPECT_EQ(again.fingerprint(), config.fingerprint());
  // In the scene: each rag's centroid where the schedule put it, all waiting at the start.
  Scene scene(case_config::structure_setup(case_config::CaseConfig::load(dir)));
  for (std::size_t i = 0; i < 5; ++i) {
    const auto &s = *scene.structures()[i];
    const Vec3 centroid = (s.positions_m().transpose() * s.point_measures()) / s.point_measures().sum();
    EXPECT_LT((centroid - releases[i].centre_m).norm(), 1e-14) << i;
    EXPECT_FALSE(scene.life().in_scene(i));
  }
}

TEST(Feed, AKindThatSetsWhatTheFeedSetsIsRefusedByName) {
  std::string yaml = feed_case;
  yaml.replace(yaml.find("      n_points: [5, 3]"), 22, "      n_points: [5, 3]\n      release_time_s: 0.2");
  try {
    case_config::CaseConfig::load(testing::make_case_dir(yaml));
    FAIL() << "accepted";
  } catch (const common::ConfigError &e) {
    EXPECT_NE(std::string(e.what()).find("feed.kinds[0]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("release_time_s and placement are the feed's"), std::string::npos)
        << e.what();
  }
}

TEST(Feed, TheClogCriterionIsReadStrictlyAndEmittedAsGiven) {
  std::string yaml = feed_case;
  yaml += "  clog_criterion: {power_rise_fraction: 0.05, retained_rags: 3}\n";
  const auto config = case_config::CaseConfig::load(testing::make_case_dir(yaml));
  ASSERT_TRUE(config.feed->clog_criterion);
  const auto &c = *config.feed->clog_criterion;
  EXPECT_FALSE(c.head_drop_fraction);
  EXPECT_EQ(c.power_rise_fraction, 0.05);
  EXPECT_EQ(c.retained_rags, 3);
  EXPECT_EQ(c.held_revolutions, 3);
  const std::string emitted = common::to_yaml(const_cast<case_config::CaseConfig &>(config));
  EXPECT_NE(emitted.find("power_rise_fraction: 0.05"), std::string::npos) << emitted;
  EXPECT_EQ(emitted.find("head_drop_fraction"), std::string::npos) << emitted; // absent stays absent
  const auto refused = [&](const std::string &criterion, const std::string &words) {
    try {
      case_config::CaseConfig::load(testing::make_case_dir(std::string(feed_case) + "  clog_criterion: " + criterion + "\n"));
      ADD_FAILURE() << "accepted: " << criterion;
    } catch (const common::ConfigError &e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused("{held_revolutions: 2}", "feed.clog_criterion");
  refused("{held_revolutions: 2}", "has no condition");
  refused("{head_drop_fraction: 1.0}", "feed.clog_criterion.head_drop_fraction");
  refused("{retained_rags: 0}", "feed.clog_criterion.retained_rags");
  refused("{retained_rag: 2}", "retained_rag");
}

TEST(Feed, ADeclaredStructureNamedAsAFedRagIsRefused) {
  std::string yaml = feed_case;
  yaml += R"(structures:
  - {name: wipe03, model: membrane, size_m: [0.04, 0.02], n_points: [5, 3]}
)";
  try {
    case_config::CaseConfig::load(testing::make_case_dir(yaml));
    FAIL() << "accepted";
  } catch (const common::ConfigError &e) {
    EXPECT_NE(std::string(e.what()).find("two structures named 'wipe03'"), std::string::npos) << e.what();
  }
}


TEST(Feed, ARagReleasedOntoAnotherPassesThroughItInsteadOfBeingFlungApart) {
  // Two 4 cm rags in zero gravity, the second released at 10 ms 1 mm over the first (inside
  // d_c = 4 mm), drifting sideways at 0.5 m/s. Contact would move them 3 mm apart in one step
  // (a 60 % stretch of a 5 mm edge); instead they pass through each other until they have
  // parted, and then the pair is in contact again.
  const std::string yaml = R"(run: {end_time_s: 1, time_step_s: 1.0e-3, output_interval_s: 0.01}
gravity_m_per_s2: [0, 0, 0]
collisions: {structure_contact: true}
structures:
  - {name: first, model: membrane, size_m: [0.04, 0.04], n_points: [9, 9], origin_m: [0, 0, 0],
     s1_direction: [1, 0, 0], s2_direction: [0, 1, 0], material: &soft {mass_per_area_kg_per_m2: 0.1,
     coefficients: {tension_coefficient_n_per_m: 0.01, bending_rigidity_n_m: 1.0e-9}}}
  - {name: second, model: membrane, size_m: [0.04, 0.04], n_points: [9, 9], origin_m: [0.002, 0.002, 0.001],
     s1_direction: [1, 0, 0], s2_direction: [0, 1, 0], release_time_s: 0.01, material: *soft,
     initial: {velocity_m_per_s: [0.5, 0, 0]}}
)";
  Scene scene(testing::load_case(yaml));
  const auto &second = *scene.structures()[1];
  double largest_stretch = 0.0;
  for (int k = 0; k < 120; ++k) { // 0.5 m/s x 0.11 s = 55 mm: clear of the first by 11 mm
    scene.advance();
    largest_stretch = std::max(largest_stretch, second.max_stretch_ratio());
    if (k >= 10 && k < 90) {
      EXPECT_NEAR(second.positions_m().col(2).mean(), 0.001, 1e-12) << "step " << k; // passed through
      EXPECT_EQ(scene.overlapping().size(), 1u) << "step " << k;
    }
  }
  EXPECT_LT(largest_stretch, 1.0 + 1e-9);
  EXPECT_GT(second.positions_m().col(0).minCoeff(), 0.04 + 0.004);
  EXPECT_TRUE(scene.overlapping().empty()); // parted: in contact again
}


/// Resident memory of this process (bytes), after giving freed heap back to the system.
double resident_bytes() {
  malloc_trim(0);
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0, resident = 0.0;
  statm >> pages >> resident;
  return resident * 4096.0;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool under_address_sanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool under_address_sanitizer = true;
#else
constexpr bool under_address_sanitizer = false;
#endif
#else
constexpr bool under_address_sanitizer = false;
#endif

TEST(Feed, RemovedRagsGiveTheirSolversMemoryBack) {
  if (under_address_sanitizer) // its allocator keeps freed memory in quarantine
    GTEST_SKIP() << "resident memory is the sanitizer's, not the solver's";
  // Four 60 x 60 rags with the linearized tension (a 3n x 3n system each), three of them past
  // their removal plane from the start: after one step they are gone, and the memory their
  // solvers took (the rise from building the scene) falls back by at least half.
  std::string yaml = R"(run: {end_time_s: 1, time_step_s: 1.0e-4, output_interval_s: 0.01}
gravity_m_per_s2: [0, 0, 0]
structures:
)";
  for (int i = 0; i < 4; ++i)
    yaml += "  - {name: rag" + std::to_string(i) + ", model: membrane, size_m: [0.3, 0.3], n_points: [60, 60], "
            "origin_m: [0, 0, " + std::to_string(0.1 * i) + "], solver: {tension: linearized}" +
            (i > 0 ? ", remove_when_past: {point_m: [0, 0, 0.05], normal: [0, 0, 1]}" : "") + "}\n";
  const auto setup = testing::load_case(yaml);
  const double before = resident_bytes();
  Scene scene(setup);
  scene.advance();
  const double built = resident_bytes();
  EXPECT_EQ(scene.remove_past_planes().size(), 3u);
  const double after = resident_bytes();
  std::printf("resident memory: %.1f MB before the scene, %.1f MB with it, %.1f MB with three rags removed\n",
              before / 1e6, built / 1e6, after / 1e6);
  EXPECT_GT(built - before, 4e6); // the scene took something measurable
  EXPECT_LT(after - before, 0.5 * (built - before)) << "removed rags kept their memory";
  scene.advance(); // the one left goes on
  EXPECT_EQ(scene.life().n_in_scene(), 1u);
}

} // namespace
} // namespace fsi::structure
