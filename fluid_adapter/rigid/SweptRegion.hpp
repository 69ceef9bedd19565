#pragma once
// The world region a rigid body can occupy over its whole motion, used once per fluid mesh to
// pick the candidate cells whose indicator can ever be non-zero:
//   * a static body: its world-frame bounding box;
//   * a rotation about a fixed axis (motion::AxisRotation, every prescribed motion of this
//     project): the solid of revolution bounded by the body's axial extent [a_min, a_max] and
//     radial extent [r_min, r_max] about the axis (an annulus, or a cylinder when the axis
//     crosses the body). Both extents are exact for the solid enclosed by the surface: the
//     axial coordinate is linear and the radius convex (extremes at vertices, except r_min,
//     taken as the 2D distance from the axis to each triangle projected on the normal plane);
//   * any other motion: unbounded (every cell is a candidate).
// Every bound is widened by margin_m (round-off, or the half-size of a cell when the
// indicator samples inside the cell).

#include "common/Types.hpp"
#include "fluid_adapter/rigid/RigidBody.hpp"

#include <Eigen/Geometry>

#include <string>

namespace fsi::fluid::rigid {

class SweptRegion {
public:
  enum class Kind { static_box, revolution, unbounded };

  static SweptRegion of(const RigidBody &body, double margin_m);

  bool contains(const Vec3 &point_world_m) const;
  Kind kind() const { return kind_; }
  /// One line for the log, e.g. "annulus about (0 0 1) r in [0.6, 1.4] m, a in [-0.3, 0.3] m".
  std::string describe() const;

private:
  Kind kind_ = Kind::unbounded;
  Eigen::AlignedBox3d box_m_;     ///< static_box
  Vec3 axis_point_m_ = Vec3::Zero(); ///< revolution
  Vec3 axis_direction_ = Vec3::UnitZ();
  double axial_min_m_ = 0.0, axial_max_m_ = 0.0;
  double radial_min_sq_m2_ = 0.0, radial_max_sq_m2_ = 0.0;
  double radial_min_m_ = 0.0, radial_max_m_ = 0.0;
};

} // namespace fsi::fluid::rigid
