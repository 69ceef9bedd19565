#pragma once
// The collision model of Sec. 2.5: rigid surfaces, each following its own prescribed motion,
// and the correction of Eq. 11 applied to the Lagrangian points of a sheet.

#include "motion/RigidMotion.hpp"
#include "common/Types.hpp"
#include "geometry/RigidSurface.hpp"

#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace fsi::structure::collision {

/// What one call of CollisionSet::correct() did.
struct CorrectionStats {
  std::size_t n_points_corrected = 0; ///< distinct points moved at least once
  std::size_t n_corrections = 0;      ///< point moves, summed over surfaces and passes
  std::size_t n_passes = 0;           ///< passes over all surfaces that were run
  /// Corrections that found a facing wall within d_t on the way out (a gap narrower than
  /// 2 d_t) and stopped midway instead of crossing into it.
  std::size_t n_pinched = 0;
  /// Most negative signed distance met by a corrected point (m); +infinity when none.
  double min_signed_distance_m = std::numeric_limits<double>::infinity();

  /// Deepest penetration into a solid (m): max(0, -min_signed_distance_m).
  double deepest_penetration_m() const;
};

class CollisionSet {
public:
  /// threshold_m is d_c, target_distance_m is d_t of Eq. 11; max_passes bounds the repeated
  /// passes that settle points near two surfaces (a corner). Throws std::invalid_argument
  /// unless 0 < threshold_m <= target_distance_m and max_passes >= 1.
  CollisionSet(double threshold_m, double target_distance_m, int max_passes = 4);

  /// Adds a surface that follows `motion` (body frame -> world). Prepares its culling data
  /// for the threshold. Throws std::invalid_argument for a null surface or motion.
  void add_surface(std::unique_ptr<geometry::RigidSurface> surface,
                   std::shared_ptr<const motion::RigidMotion> motion);

  /// Eq. 11: every point closer than d_c to a surface (or inside it) is moved along the wall
  /// normal to distance d_t. Surfaces are applied in turn and the pass repeated until no point
  /// moves (at most max_passes). In a gap narrower than 2 d_t (a rag pinched between a blade
  /// and a shroud lip, or in an impeller's side gap) no place is d_t from both walls: a move
  /// that would end within d_c of a wall facing it (normals more than 120 degrees apart)
  /// stops where the two distances are equal, so the point stays in the gap instead of being
  /// thrown from one wall into the other. Non-finite points are left alone. A pass over many points is
  /// split among OpenMP threads (OMP_NUM_THREADS); the result is the same bit for bit.
  CorrectionStats correct(PointArray &positions_m, double time_s) const;

  std::size_t n_surfaces() const { return bodies_.size(); }
  double threshold_m() const { return threshold_m_; }
  double target_distance_m() const { return target_distance_m_; }
  /// One line per surface, for the log.
  std::string describe() const;

private:
  struct Body {
    std::unique_ptr<geometry::RigidSurface> surface;
    std::shared_ptr<const motion::RigidMotion> motion;
  };

  /// The nearest wall of any surface to a point (world frame): signed distance and normal
  /// into the fluid; distance +infinity when no surface is within d_c.
  struct Clearance {
    double signed_distance_m;
    Vec3 normal_into_fluid;
  };
  Clearance nearest_wall(const Vec3 &world_m, const std::vector<Eigen::Isometry3d> &poses) const;

  /// Applies Eq. 11 for one surface (index `b`, poses of all at time_s) to the points listed
  /// in `active`; marks the points it moves in `moved` and `was_corrected`.
  void correct_against(std::size_t b, const std::vector<Eigen::Isometry3d> &poses, PointArray &positions_m,
                       const std::vector<Eigen::Index> &active, std::vector<char> &moved,
                       std::vector<char> &was_corrected, CorrectionStats &stats) const;

  double threshold_m_;
  double target_distance_m_;
  int max_passes_;
  std::vector<Body> bodies_;
};

} // namespace fsi::structure::collision
