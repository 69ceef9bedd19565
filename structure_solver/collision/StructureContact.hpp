#pragma once
// Contact between different structures (rags of a feed piling up on a leading edge): the
// collision of Eq. 11 with another structure's surface as the wall. Each point of one structure
// closer than d_c to a triangle of another sheet is moved with that triangle apart to d_t along
// the triangle's normal, on the side the point was at the start of the step, so that a point
// that crossed the sheet within the step is put back (a sheet is thinner than a step's move).
// The move is shared in inverse proportion to the masses (the point's against the triangle's at
// the contact point, its vertices' interpolated), so the mass-weighted centre of the pair does
// not move; the triangle's vertices take their share by their barycentric weights.
//
// Points against triangles, not points against points: the sheets' spacing (1 cm) is larger
// than d_c (4 mm), so a point of one rag passes between the points of another without touching
// them (self-collision's point pairs have that limit inside one sheet). Edge against edge is not
// checked: two sheets crossing only along edges within one step pass (at a rag's speed relative
// to another, a few mm per step, they meet face to point first).

#include "common/Types.hpp"
#include "geometry/TriangleBvh.hpp"

#include <array>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace fsi::structure::collision {

/// One structure as contact sees it: its grid (n1 x n2 points, row-major; n2 == 1 for a
/// filament, which has no triangles and takes part with its points only) and each point's mass.
struct ContactBody {
  int n1 = 0, n2 = 0;
  Eigen::VectorXd point_mass_kg;
};

/// What one call of StructureContact::correct() did.
struct ContactStats {
  std::size_t n_contacts = 0;  ///< point-triangle pairs moved apart
  std::size_t n_crossings = 0; ///< of them, points that had crossed the sheet in the step
};

class StructureContact {
public:
  /// threshold_m is d_c, target_distance_m d_t (0 < d_c <= d_t). Throws std::invalid_argument
  /// otherwise, or for a body whose masses do not match its grid or are not positive.
  StructureContact(std::vector<ContactBody> bodies, double threshold_m, double target_distance_m);

  /// Moves the points of every pair of different structures apart (Gauss-Seidel, pair after
  /// pair, in the order of the bodies). positions_m: X^{n+1} of each body, corrected in place;
  /// start_m: X^n, which gives the side each point was on; in_scene: per body, whether it takes
  /// part (empty: all; a feed's rag before its release or after its removal does not). Throws
  /// std::invalid_argument when the counts differ from the bodies'.
  /// Pairs in `apart` (index pairs, the smaller first) are skipped: structures released onto each
  /// other pass through each other until they part (Scene).
  ContactStats correct(std::vector<PointArray> &positions_m, const std::vector<PointArray> &start_m,
                       const std::vector<bool> &in_scene = {},
                       const std::set<std::pair<std::size_t, std::size_t>> &apart = {}) const;
  /// True when a point of body a is within d_c of a triangle of body b, or one of b of a's.
  bool touching(std::size_t a, std::size_t b, const std::vector<PointArray> &positions_m) const;

  std::size_t n_bodies() const { return bodies_.size(); }

private:
  /// Points of body a against the triangles of body b.
  void correct_pair(std::size_t a, std::size_t b, std::vector<PointArray> &positions_m,
                    const std::vector<PointArray> &start_m, ContactStats &stats) const;

  /// b's triangles at positions_m[b] in a tree, for the nearest-triangle queries.
  geometry::TriangleBvh tree_of(std::size_t b, const PointArray &xb) const;

  std::vector<ContactBody> bodies_;
  /// Per body, its triangles as point-index triples (two per grid quad; none for a filament).
  std::vector<std::vector<std::array<Eigen::Index, 3>>> triangles_;
  double threshold_m_;
  double target_distance_m_;
};

} // namespace fsi::structure::collision
