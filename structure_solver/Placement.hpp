#pragma once
// Where a structure starts when it is not where its model's keys put it: its initial shape moved
// as a rigid body so that its centroid (the measure-weighted mean of its points) lies at
// `centre_m`, turned about that centroid by `turn_angle_deg` about `turn_axis`. A feed's rags
// (structure_solver/feed) are one declared kind placed at drawn centres and turns.

#include "common/ConfigReader.hpp"
#include "common/Types.hpp"

#include <Eigen/Geometry>

#include <type_traits>

namespace fsi::structure {

struct Placement {
  Vec3 centre_m = Vec3::Zero();
  Vec3 turn_axis{0.0, 0.0, 1.0};
  double turn_angle_deg = 0.0;

  template <class V> void visit(V &v) {
    v.vec3("centre_m", centre_m, "m", "Where the structure's centroid starts.");
    v.vec3("turn_axis", turn_axis, "1", "Axis of the turn about the centroid (any length but zero).");
    v.number("turn_angle_deg", turn_angle_deg, common::Range::any("deg"),
             "Angle of the turn, right-handed about turn_axis.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (!(turn_axis.norm() > 0.0))
        v.fail_value("turn_axis", "is zero: give the direction to turn about, e.g. [0, 0, 1].");
  }

  Eigen::Matrix3d rotation() const {
    return Eigen::AngleAxisd(turn_angle_deg * M_PI / 180.0, turn_axis.normalized()).toRotationMatrix();
  }

  /// `points_m` moved so that their `weights`-weighted centroid is at centre_m, turned about it.
  PointArray apply(const PointArray &points_m, const Eigen::VectorXd &weights) const {
    const Vec3 centroid = (points_m.transpose() * weights) / weights.sum();
    const Eigen::Matrix3d r = rotation();
    PointArray out(points_m.rows(), 3);
    for (Eigen::Index i = 0; i < points_m.rows(); ++i)
      out.row(i) = (r * (points_m.row(i).transpose() - centroid) + centre_m).transpose();
    return out;
  }
};

} // namespace fsi::structure
