#pragma once
// Spreading of the wall correction (Eq. 11) over a sheet's grid neighbours. Eq. 11 moves a point
// by up to d_t in one step while its neighbours stay, which strains the edges next to it by up to
// d_t / Delta s (40 % for d_t = 4 mm at 1 cm spacing). Spread over the points up to n away on the
// grid with weights falling linearly, the step in displacement between neighbours is about
// 1 / (n + 1) of the correction, and so is the strain it makes (the paper proposes spreading for
// self-collision, Sec. 2.5).

#include "common/Types.hpp"

namespace fsi::structure::collision {

class CorrectionSpread {
public:
  /// A grid of n1 x n2 points, row-major (index i1 n2 + i2); radius_points n >= 1. Throws
  /// std::invalid_argument otherwise.
  CorrectionSpread(int n1, int n2, int radius_points);

  /// before: the positions before the correction, after: after it (the corrected points moved,
  /// the others not). Each point the correction did not move gets the weighted mean of the
  /// moves of the corrected points within radius_points of it on the grid that it lies in
  /// front of (not behind the plane through the moved point across its move by more than twice
  /// the move's length: not on the other face of a nose the rag is folded round), weight
  /// w = 1 - d / (n + 1) at grid distance d = sqrt(di^2 + dj^2) (the sum of the weights at
  /// least 1: a point between two corrected ones takes their mean, not their sum). Returns the
  /// number of points moved by the spread. Throws std::invalid_argument when the point counts
  /// differ from the grid's.
  std::size_t apply(const PointArray &before, PointArray &after) const;

  int radius_points() const { return radius_; }

private:
  int n1_, n2_, radius_;
};

} // namespace fsi::structure::collision
