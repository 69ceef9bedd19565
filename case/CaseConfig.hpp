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

#include <filesystem>

namespace fsi::case_config {

struct CaseConfig {
  common::RunConfig run;
  Vec3 gravity_m_per_s2{0.0, 0.0, -9.81};
  std::optional<structure::CollisionConfig> collisions;
  std::vector<structure::StructureConfig> structures;
  std::vector<structure::ProbeConfig> probes;
  std::optional<FluidConfig> fluid;
  std::optional<coupler::CouplingConfig> coupling;

  template <class V> void visit(V &v) {
    v.section("run", run, "Time stepping and output.");
    v.vec3("gravity_m_per_s2", gravity_m_per_s2, "m/s^2", "Gravitational acceleration g.");
    v.optional_section("collisions", collisions, "Rigid surfaces and the collision model of Eq. (11).");
    v.list("structures", structures,
           "Flexible structures of the scene (at least one; none with fluid.openfoam: the flow alone with its "
           "rigid bodies, e.g. a pump's performance).");
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
  void validate_probes(const common::ConfigReader &v) const;
};

} // namespace fsi::case_config
