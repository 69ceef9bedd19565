#pragma once
// What the immersed-boundary maths needs of the Eulerian (finite-volume) mesh: the cell
// centres and volumes of the cells this process holds. OpenFOAM fills it from mesh.C() and
// mesh.V(); on a decomposed case each rank describes only its own cells. The local mesh size
// of a cell, used as the kernel width h of Eq. 6, is cbrt(volume).

#include "common/Types.hpp"

#include <cstdint>

namespace fsi::fluid::ibm {

/// Index of a cell in EulerianCells (OpenFOAM's 32-bit label).
using CellId = std::int32_t;

class EulerianCells {
public:
  /// centres_m: n x 3 (m); volumes_m3: n (m^3). Throws std::invalid_argument when the sizes
  /// differ, a value is not finite, a volume is not positive or there are more cells than
  /// CellId can count. An empty set (a rank without cells) is allowed.
  EulerianCells(PointArray centres_m, Eigen::VectorXd volumes_m3);

  CellId n_cells() const { return static_cast<CellId>(volumes_m3_.size()); }
  const PointArray &centres_m() const { return centres_m_; }
  const Eigen::VectorXd &volumes_m3() const { return volumes_m3_; }
  /// cbrt(volume) of every cell (m): the local Eulerian mesh size h.
  const Eigen::VectorXd &sizes_m() const { return sizes_m_; }

  Vec3 centre_m(CellId cell) const { return centres_m_.row(cell).transpose(); }
  double volume_m3(CellId cell) const { return volumes_m3_[cell]; }
  double size_m(CellId cell) const { return sizes_m_[cell]; }

private:
  void check() const;

  PointArray centres_m_;
  Eigen::VectorXd volumes_m3_;
  Eigen::VectorXd sizes_m_;
};

} // namespace fsi::fluid::ibm
