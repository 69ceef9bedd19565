#pragma once
// Wall distance to the immersed rigid surfaces, for the turbulence model (section 2.6: the
// immersed bodies are walls for Spalart-Allmaras, like the mesh's wall patches). Only cells
// within `margin_m` of a body's swept region are measured; the others keep the distance to
// the mesh's own walls. For DES/DDES that loses nothing as long as the margin exceeds the LES
// length C_DES Delta (beyond it d~ = C_DES Delta whatever d is); for RANS-SA give a margin that
// covers the region where the bodies matter.

#include "fluid_adapter/rigid/RigidBody.hpp"
#include "fluid_adapter/rigid/SweptRegion.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace fsi::fluid::rigid {

class ImmersedWallDistance {
public:
  ImmersedWallDistance(const std::vector<const RigidBody *> &bodies, const PointArray &cell_centres_m, double margin_m);

  /// Distances at time t (bodies at their poses): per cell, the distance (m) to the nearest
  /// immersed surface (inside a body too, never 0), +infinity for cells not measured.
  void update(double time_s);
  const Eigen::VectorXd &distance_m() const { return distance_m_; }
  std::size_t n_measured_cells() const;

private:
  struct Candidates {
    const RigidBody *body;
    std::vector<std::int32_t> cells;
  };
  std::vector<Candidates> candidates_;
  const PointArray &centres_m_;
  Eigen::VectorXd distance_m_;
};

} // namespace fsi::fluid::rigid
