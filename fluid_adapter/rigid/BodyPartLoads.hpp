#pragma once
// The loads of BodyLoads split among the parts of the body's surface (the `solid NAME` blocks
// of its STL: a pump impeller's hub, shroud, blade sides, eye): each penalized cell's load goes
// wholly to the part of the surface triangle closest to its centre (in the body frame), so the
// parts' loads sum to the body's. It says which part of a body takes the load (the torque of an
// impeller's discs against its vane's), not a surface integral per part: the penalization
// force lives in the body's cells next to the surface, and a cell near an edge between two
// parts counts for the nearer one.

#include "common/Types.hpp"
#include "fluid_adapter/rigid/BodyIndicator.hpp"
#include "fluid_adapter/rigid/BodyLoads.hpp"
#include "geometry/TriangleBvh.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace fsi::fluid::rigid {

class BodyPartLoads {
public:
  /// `body` is borrowed and must outlive this.
  explicit BodyPartLoads(const RigidBody &body);

  const std::vector<std::string> &part_names() const { return body_.part_names(); }

  /// One load per part (in part_names() order) over the indicator's inside cells, the body
  /// placed by its motion at `time_s`; arguments as BodyLoads::from_source_on_fluid's (which
  /// throws on a size mismatch, as this does). `couple_on_fluid_n_per_m2` (optional, empty
  /// for none): per cell a torque density on the fluid (N m / m^3) beside the force's, whose
  /// reaction the cell's part also takes.
  std::vector<BodyLoad> from_source_on_fluid(const BodyIndicator &indicator, const PointArray &cell_centres_m,
                                             const PointArray &force_on_fluid_n_per_m3,
                                             const Eigen::VectorXd &cell_volumes_m3, const Vec3 &torque_point_m,
                                             double time_s, const PointArray &couple_on_fluid_n_per_m2 = {});

private:
  const RigidBody &body_;
  geometry::TriangleBvh bvh_; ///< the body-frame triangles
  /// Per cell, its closest triangle at the last call (-1: none yet): a moving body has moved
  /// a fraction of a cell since, so it bounds the next search tightly.
  std::vector<std::int32_t> last_face_;
};

} // namespace fsi::fluid::rigid
