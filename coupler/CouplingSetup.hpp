#pragma once
// What the coupler needs of a case: its own `coupling` section, the shared `run` section, the
// scene's rigid surfaces (whose prescribed motions it evaluates, section 2.3: "update the
// position of internal immersed rigid surfaces"), gravity (the pendulum motion), the number of
// structures the structure participant must bring, and the case's identity (effective
// configuration, fingerprint). The executable fills it from case.yaml (case/ModuleSetups.hpp).

#include "CouplingConfig.hpp"
#include "checkpoint/CaseIdentity.hpp"
#include "common/RunConfig.hpp"
#include "common/Types.hpp"
#include "geometry/SurfaceConfig.hpp"
#include "proto/ChannelOptions.hpp"

#include <string>
#include <vector>

namespace fsi::coupler {

struct CouplingSetup {
  common::RunConfig run;
  CouplingConfig coupling;
  proto::ChannelOptions channel; ///< the message size limit and CURVE keys (case/ChannelSettings.hpp)
  std::vector<geometry::SurfaceConfig> rigid_surfaces; ///< collisions.surfaces, in case order
  Vec3 gravity_m_per_s2{0.0, 0.0, -9.81};
  std::size_t n_structures = 0;
  std::string case_yaml;        ///< the effective configuration of the whole case (YAML)
  std::string case_fingerprint; ///< what every participant's hello must carry
  checkpoint::CaseIdentity restart_identity{""}; ///< what its checkpoints carry (the case without the end time)
  bool restart = false;            ///< --restart: resume from the newest complete checkpoint
};

} // namespace fsi::coupler
