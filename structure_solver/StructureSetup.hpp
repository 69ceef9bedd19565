#pragma once
// What a structure run needs of a case: the structure solver's own sections (structures,
// probes, collisions), the shared `run` section and gravity, and the case's identity: its
// effective configuration (saved with the results) and its fingerprint (checked by the
// coupler). The executables fill it from case.yaml (case/ModuleSetups.hpp); the structure
// solver never sees the whole case.

#include "CollisionConfig.hpp"
#include "ProbeConfig.hpp"
#include "StructureConfig.hpp"
#include "checkpoint/CaseIdentity.hpp"
#include "common/RunConfig.hpp"
#include "common/Types.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fsi::structure {

struct StructureSetup {
  common::RunConfig run;
  Vec3 gravity_m_per_s2{0.0, 0.0, -9.81};
  std::optional<CollisionConfig> collisions;
  std::vector<StructureConfig> structures;
  std::vector<ProbeConfig> probes;
  std::string case_yaml;        ///< the effective configuration of the whole case (YAML)
  std::string case_fingerprint; ///< the case's fingerprint (16 hex digits), as the coupler has it
  checkpoint::CaseIdentity restart_identity{""}; ///< what its checkpoints carry (the case without the end time)
  /// Resume from the newest complete checkpoint of the results folder (--restart).
  bool restart = false;
  /// A coupled run: the moving rigid surfaces take the poses the coupler sends
  /// (motion::CoupledMotion) instead of evaluating their motions here.
  bool rigid_motions_from_coupler = false;
};

} // namespace fsi::structure
