#include "structure_solver/collision/StructureContact.hpp"

#include "geometry/TriangleBvh.hpp"
#include "geometry/TrianglePoint.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::structure::collision {
namespace {

using Triangle = geometry::TriangleBvh::Triangle;

/// Pairs already at d_c up to round-off are not corrected again.
constexpr double kSettledTolerance_m = 1e-12;

Vec3 row(const PointArray &x, Eigen::Index i) { return x.row(i).transpose(); }

/// Barycentric coordinates of q, a point of triangle abc, clamped to the triangle.
Vec3 barycentric(const Vec3 &q, const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const Vec3 e1 = b - a, e2 = c - a, aq = q - a;
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double q1 = aq.dot(e1), q2 = aq.dot(e2);
  const double denominator = d11 * d22 - d12 * d12;
  if (!(denominator > 0.0))
    return Vec3::Constant(1.0 / 3.0);
  Vec3 w(0.0, (d22 * q1 - d12 * q2) / denominator, (d11 * q2 - d12 * q1) / denominator);
  w = w.cwiseMax(0.0);
  w[0] = std::max(0.0, 1.0 - w[1] - w[2]);
  return w / w.sum();
}

Vec3 unit_normal(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const Vec3 n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

} // namespace

StructureContact::StructureContact(std::vector<ContactBody> bodies, double threshold_m, double target_distance_m)
    : bodies_(std::move(bodies)), threshold_m_(threshold_m), target_distance_m_(target_distance_m) {
  if (!(threshold_m > 0.0) || !(target_distance_m >= threshold_m))
    throw std::invalid_argument("contact between structures needs 0 < threshold_m (" + std::to_string(threshold_m) +
                                ") <= target_distance_m (" + std::to_string(target_distance_m) + ").");
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const auto &body = bodies_[k];
    if (body.n1 < 1 || body.n2 < 1 || body.point_mass_kg.size() != Eigen::Index(body.n1) * body.n2 ||
        !(body.point_mass_kg.minCoeff() > 0.0))
      throw std::invalid_argument("contact between structures: structure " + std::to_string(k) + " has " +
                                  std::to_string(body.point_mass_kg.size()) + " point masses for a grid of " +
                                  std::to_string(body.n1) + " x " + std::to_string(body.n2) +
                                  " points; each must be positive.");
    auto &triangles = triangles_.emplace_back();
    if (body.n2 < 2)
      continue; // a filament: points only
    const auto index = [&](int i1, int i2) { return Eigen::Index(i1) * body.n2 + i2; };
    for (int i1 = 0; i1 + 1 < body.n1; ++i1)
      for (int i2 = 0; i2 + 1 < body.n2; ++i2) {
        triangles.push_back({index(i1, i2), index(i1 + 1, i2), index(i1 + 1, i2 + 1)});
        triangles.push_back({index(i1, i2), index(i1 + 1, i2 + 1), index(i1, i2 + 1)});
      }
  }
}

ContactStats StructureContact::correct(std::vector<PointArray> &positions_m, const std::vector<PointArray> &start_m,
                                       const std::vector<bool> &in_scene,
                                       const std::set<std::pair<std::size_t, std::size_t>> &apart) const {
  if (positions_m.size() != bodies_.size() || start_m.size() != bodies_.size() ||
      !(in_scene.empty() || in_scene.size() == bodies_.size()))
    throw std::invalid_argument("StructureContact::correct: " + std::to_string(positions_m.size()) + " and " +
                                std::to_string(start_m.size()) + " structures given (" +
                                std::to_string(in_scene.size()) + " flags), contact has " +
                                std::to_string(bodies_.size()) + ".");
  for (std::size_t k = 0; k < bodies_.size(); ++k)
    if (positions_m[k].rows() != bodies_[k].point_mass_kg.size() || start_m[k].rows() != positions_m[k].rows())
      throw std::invalid_argument("StructureContact::correct: structure " + std::to_string(k) + " has " +
                                  std::to_string(positions_m[k].rows()) + " points, its grid " +
                                  std::to_string(bodies_[k].point_mass_kg.size()) + ".");
  ContactStats stats;
  for (std::size_t a = 0; a < bodies_.size(); ++a)
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      if (a != b && !triangles_[b].empty() && (in_scene.empty() || (in_scene[a] && in_scene[b])) &&
          apart.count({std::min(a, b), std::max(a, b)}) == 0)
        correct_pair(a, b, positions_m, start_m, stats);
  return stats;
}

geometry::TriangleBvh StructureContact::tree_of(std::size_t b, const PointArray &xb) const {
  std::vector<Triangle> triangles;
  triangles.reserve(triangles_[b].size());
  for (const auto &f : triangles_[b])
    triangles.push_back({row(xb, f[0]), row(xb, f[1]), row(xb, f[2])});
  return geometry::TriangleBvh(triangles);
}

bool StructureContact::touching(std::size_t a, std::size_t b, const std::vector<PointArray> &positions_m) const {
  for (const auto &[p, t] : {std::pair{a, b}, std::pair{b, a}}) {
    if (triangles_[t].empty())
      continue;
    const geometry::TriangleBvh tree = tree_of(t, positions_m[t]);
    for (Eigen::Index i = 0; i < positions_m[p].rows(); ++i)
      if (tree.nearest_within(row(positions_m[p], i), threshold_m_).face >= 0)
        return true;
  }
  return false;
}

void StructureContact::correct_pair(std::size_t a, std::size_t b, std::vector<PointArray> &positions_m,
                                    const std::vector<PointArray> &start_m, ContactStats &stats) const {
  PointArray &xa = positions_m[a];
  PointArray &xb = positions_m[b];
  const auto &faces = triangles_[b];
  // The tree is built once per pair; the moves of b's points it makes are small against d_c, and
  // each candidate's distance is measured again on b's current positions.
  const geometry::TriangleBvh tree = tree_of(b, xb);
  const auto &mass_a = bodies_[a].point_mass_kg;
  const auto &mass_b = bodies_[b].point_mass_kg;
  for (Eigen::Index i = 0; i < xa.rows(); ++i) {
    const Vec3 p = row(xa, i);
    if (!p.allFinite())
      continue;
    const auto found = tree.nearest_within(p, threshold_m_);
    if (found.face < 0)
      continue;
    const auto &f = faces[static_cast<std::size_t>(found.face)];
    const Vec3 v0 = row(xb, f[0]), v1 = row(xb, f[1]), v2 = row(xb, f[2]);
    const auto closest = geometry::closest_point_on_triangle(p, v0, v1, v2);
    const Vec3 q = closest.point_m;
    const Vec3 w = barycentric(q, v0, v1, v2);
    const Vec3 normal = unit_normal(v0, v1, v2);
    // The side of the sheet the point was on at the start of the step.
    const Vec3 q_start = w[0] * row(start_m[b], f[0]) + w[1] * row(start_m[b], f[1]) + w[2] * row(start_m[b], f[2]);
    const Vec3 normal_start = unit_normal(row(start_m[b], f[0]), row(start_m[b], f[1]), row(start_m[b], f[2]));
    double side = (row(start_m[a], i) - q_start).dot(normal_start);
    if (side == 0.0)
      side = (p - q).dot(normal);
    const double sign = side < 0.0 ? -1.0 : 1.0;

    Vec3 direction;
    double gap_m;
    // Over the sheet (the closest point inside a triangle, or on an edge between two with the
    // point along the normal): the side from the start of the step. Beside its rim: straight away.
    const Vec3 offset = p - q;
    const bool over_sheet = normal.squaredNorm() > 0.0 &&
                            (closest.feature == geometry::TriangleFeature::face ||
                             std::abs(offset.dot(normal)) >= (1.0 - 1e-6) * offset.norm());
    if (over_sheet) {
      direction = sign * normal;
      gap_m = offset.dot(direction); // negative: crossed within the step
    } else {
      gap_m = offset.norm();
      direction = gap_m > 0.0 ? Vec3(offset / gap_m) : Vec3(sign * normal);
    }
    if (!(gap_m < threshold_m_ - kSettledTolerance_m) || direction.squaredNorm() == 0.0)
      continue;
    // Separate by delta = d_t - gap along `direction`: the point by alpha, the triangle's vertices
    // by c w_k (the contact point by c |w|^2), with m_p alpha + c m_q = 0 (m_q = sum w_k m_k).
    const double delta_m = target_distance_m_ - gap_m;
    const double m_p = mass_a[i];
    const double m_q = w[0] * mass_b[f[0]] + w[1] * mass_b[f[1]] + w[2] * mass_b[f[2]];
    const double alpha = delta_m / (1.0 + m_p / m_q * w.squaredNorm());
    const double c = -m_p * alpha / m_q;
    xa.row(i) += alpha * direction.transpose();
    for (int k = 0; k < 3; ++k)
      xb.row(f[static_cast<std::size_t>(k)]) += (c * w[k]) * direction.transpose();
    ++stats.n_contacts;
    if (gap_m < 0.0)
      ++stats.n_crossings;
  }
}

} // namespace fsi::structure::collision
