#include "fluid_adapter/rigid/SweptRegion.hpp"

#include "motion/AxisRotation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fsi::fluid::rigid {
namespace {

using Vec2 = Eigen::Vector2d;

double cross2(const Vec2 &a, const Vec2 &b) { return a.x() * b.y() - a.y() * b.x(); }

/// Distance from the origin to the segment [a, b] in the plane.
double origin_to_segment(const Vec2 &a, const Vec2 &b) {
  const Vec2 ab = b - a;
  const double length_sq = ab.squaredNorm();
  const double s = length_sq > 0.0 ? std::clamp(-a.dot(ab) / length_sq, 0.0, 1.0) : 0.0;
  return (a + s * ab).norm();
}

/// Distance from the origin to the (possibly degenerate) triangle abc in the plane.
double origin_to_triangle(const Vec2 &a, const Vec2 &b, const Vec2 &c) {
  const double d_ab = cross2(a, b), d_bc = cross2(b, c), d_ca = cross2(c, a);
  const bool has_neg = d_ab < 0 || d_bc < 0 || d_ca < 0;
  const bool has_pos = d_ab > 0 || d_bc > 0 || d_ca > 0;
  if (!(has_neg && has_pos))
    return 0.0; // the origin is inside (or on) the projected triangle
  return std::min({origin_to_segment(a, b), origin_to_segment(b, c), origin_to_segment(c, a)});
}

} // namespace

SweptRegion SweptRegion::of(const RigidBody &body, double margin_m) {
  SweptRegion region;
  const PointArray &vertices = body.soup().vertices_m;
  if (body.declared_motion().is_static()) {
    region.kind_ = Kind::static_box;
    const Eigen::Isometry3d pose = body.declared_motion().pose_at(0.0);
    for (Eigen::Index v = 0; v < vertices.rows(); ++v)
      region.box_m_.extend(pose * Vec3(vertices.row(v).transpose()));
    region.box_m_.min().array() -= margin_m;
    region.box_m_.max().array() += margin_m;
    return region;
  }
  const auto *rotation = dynamic_cast<const motion::AxisRotation *>(&body.declared_motion());
  if (!rotation)
    return region; // unbounded
  region.kind_ = Kind::revolution;
  region.axis_point_m_ = rotation->axis_point_m();
  region.axis_direction_ = rotation->axis_direction().normalized();
  const Vec3 &n = region.axis_direction_;
  // Orthonormal basis (e1, e2) of the plane normal to the axis.
  const Vec3 e1 = n.unitOrthogonal();
  const Vec3 e2 = n.cross(e1);
  std::vector<Vec2> projected(static_cast<std::size_t>(vertices.rows()));
  double a_min = std::numeric_limits<double>::infinity(), a_max = -a_min, r_max = 0.0;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    const Vec3 d = Vec3(vertices.row(v).transpose()) - region.axis_point_m_;
    a_min = std::min(a_min, d.dot(n));
    a_max = std::max(a_max, d.dot(n));
    projected[static_cast<std::size_t>(v)] = Vec2(d.dot(e1), d.dot(e2));
    r_max = std::max(r_max, projected[static_cast<std::size_t>(v)].norm());
  }
  double r_min = std::numeric_limits<double>::infinity();
  const auto &triangles = body.soup().triangles;
  for (Eigen::Index t = 0; t < triangles.rows() && r_min > 0.0; ++t)
    r_min = std::min(r_min, origin_to_triangle(projected[static_cast<std::size_t>(triangles(t, 0))],
                                               projected[static_cast<std::size_t>(triangles(t, 1))],
                                               projected[static_cast<std::size_t>(triangles(t, 2))]));
  region.axial_min_m_ = a_min - margin_m;
  region.axial_max_m_ = a_max + margin_m;
  region.radial_min_m_ = std::max(0.0, r_min - margin_m);
  region.radial_max_m_ = r_max + margin_m;
  region.radial_min_sq_m2_ = region.radial_min_m_ * region.radial_min_m_;
  region.radial_max_sq_m2_ = region.radial_max_m_ * region.radial_max_m_;
  return region;
}

bool SweptRegion::contains(const Vec3 &point_world_m) const {
  switch (kind_) {
  case Kind::static_box:
    return box_m_.contains(point_world_m);
  case Kind::revolution: {
    const Vec3 d = point_world_m - axis_point_m_;
    const double axial_m = d.dot(axis_direction_);
    if (axial_m < axial_min_m_ || axial_m > axial_max_m_)
      return false;
    const double radial_sq_m2 = (d - axial_m * axis_direction_).squaredNorm();
    return radial_sq_m2 >= radial_min_sq_m2_ && radial_sq_m2 <= radial_max_sq_m2_;
  }
  case Kind::unbounded:
    break;
  }
  return true;
}

std::string SweptRegion::describe() const {
  std::ostringstream out;
  switch (kind_) {
  case Kind::static_box:
    out << "static box [" << box_m_.min().transpose() << "] - [" << box_m_.max().transpose()
        << "] m";
    break;
  case Kind::revolution:
    out << "solid of revolution about the axis through (" << axis_point_m_.transpose()
        << ") along (" << axis_direction_.transpose() << "): r in [" << radial_min_m_ << ", "
        << radial_max_m_ << "] m, axial in [" << axial_min_m_ << ", " << axial_max_m_ << "] m";
    break;
  case Kind::unbounded:
    out << "unbounded (motion of unknown kind: every cell is tested)";
    break;
  }
  return out.str();
}

} // namespace fsi::fluid::rigid
