#pragma once
// The typed configuration of a case (the folder's case.yaml), parsed once and strictly: the
// aggregate of the sections each module declares and owns (run: common; structures, probes,
// collisions: structure_solver; fluid: prescribed_flow and fluid_adapter; coupling: coupler).
// Only the executables and the tests include it: a physics module gets its own sections (see
// ModuleSetups.hpp), never the whole case.

#include "FluidConfig.hpp"
#include "checkpoint/CaseIdentity.hpp"
#include "common/RunConfig.hpp"
#include "coupler/CouplingConfig.hpp"
#include "structure_solver/CollisionConfig.hpp"
#include "structure_solver/ProbeConfig.hpp"
#include "structure_solver/StructureConfig.hpp"
#include "structure_solver/feed/FeedConfig.hpp"

#include <filesystem>

namespace fsi::case_config {

struct CaseConfig {
  common::RunConfig run;
  Vec3 gravity_m_per_s2{0.0, 0.0, -9.81};
  std::optional<structure::CollisionConfig> collisions;
  std::optional<structure::feed::FeedConfig> feed;
  /// The declared structures, then the feed's rags (the last n_fed, expanded at load).
  std::vector<structure::StructureConfig> structures;
  std::size_t n_fed = 0;
  std::vector<structure::ProbeConfig> probes;
  std::optional<FluidConfig> fluid;
  std::optional<coupler::CouplingConfig> coupling;

  template <class V> void visit(V &v) {
    v.section("run", run, "Time stepping and output.");
    v.vec3("gravity_m_per_s2", gravity_m_per_s2, "m/s^2", "Gravitational acceleration g.");
    v.optional_section("collisions", collisions, "Rigid surfaces and the collision model of Eq. (11).");
    v.optional_section("feed", feed,
                       "Rags released into the running scene in sequence (as pump test rigs feed them): their kinds "
                       "and schedule. They become structures of their own, named after their kind (rag01, rag02, "
                       "...). Optional.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (feed)
        expand_feed(v);
    // The emitted configuration declares the feed, not its rags: read again, it expands again.
    std::vector<structure::StructureConfig> fed;
    if constexpr (std::is_same_v<V, common::ConfigEmitter>)
      for (std::size_t i = structures.size() - n_fed; i < structures.size(); ++i)
        fed.push_back(std::move(structures[i]));
    if constexpr (std::is_same_v<V, common::ConfigEmitter>)
      structures.resize(structures.size() - n_fed);
    v.list("structures", structures,
           "Flexible structures of the scene (at least one, or a feed; none with fluid.openfoam: the flow alone "
           "with its rigid bodies, e.g. a pump's performance).");
    for (auto &s : fed)
      structures.push_back(std::move(s));
    v.list("probes", probes,
           "Places on the structures (centroid, edge centre, grid point) whose position and velocity are saved "
           "at every saved step: structure.h5 /probes/<name> and probes.csv. Optional.");
    v.optional_section("fluid", fluid,
                       "The fluid the structures move in. Absent: structure only (no coupler, no fluid process).");
    v.optional_section("coupling", coupling, "Fluid-structure coupling (section 2.3); required with `fluid`.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      validate(v);
  }

  /// Reads and validates `case_dir/case.yaml`, with `case_dir/presets/<preset>.yaml` merged
  /// over it when a preset is named (e.g. --resolution coarse), then the assignments
  /// ("a.b.c=VALUE", --set); throws common::ConfigError.
  static CaseConfig load(const std::filesystem::path &case_dir, const std::string &preset = "",
                         const std::vector<std::string> &assignments = {});
  /// The presets a case offers (file names in case_dir/presets without .yaml), sorted.
  static std::vector<std::string> presets(const std::filesystem::path &case_dir);

  /// Where the processes of a run write: `override_dir` when given (-o DIR), else
  /// case_dir / run.output_directory.
  std::filesystem::path output_directory(const std::filesystem::path &case_dir, const std::string &override_dir) const {
    return override_dir.empty() ? case_dir / run.output_directory : std::filesystem::path(override_dir);
  }

  /// True when the scene has a fluid and a structure: then a coupler and a fluid participant run too.
  bool is_coupled() const { return fluid.has_value() && !structures.empty(); }
  /// True when the scene is the OpenFOAM flow alone with its rigid bodies (no structure): only
  /// the fluid process runs (a pump's single-phase performance).
  bool is_flow_alone() const { return structures.empty() && fluid && fluid->openfoam; }
  /// Hash (16 hex digits) of the effective configuration without what may differ between
  /// the processes of one run (output folder, endpoint): participants must agree on it.
  std::string fingerprint() const;
  /// The fingerprint a checkpoint carries: the case's, without run.end_time_s and the
  /// checkpoint settings (a restart may run further, or checkpoint more often).
  std::string restart_fingerprint() const;
  /// What a checkpoint records of the case: the restart fingerprint and the keys it hashes
  /// (checkpoint::CaseIdentity), so that a refused restart can name the keys that changed.
  checkpoint::CaseIdentity restart_identity() const;

private:
  void validate(common::ConfigReader &v) const;
  /// Appends the feed's rags to the `structures` list of the YAML being read (before it is read):
  /// one entry per release of the feed's schedule, its kind's keys with a name, release time,
  /// placement and removal plane.
  void expand_feed(common::ConfigReader &v);
  void validate_probes(const common::ConfigReader &v) const;
};

} // namespace fsi::case_config
