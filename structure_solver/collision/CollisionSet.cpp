#include "structure_solver/collision/CollisionSet.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include <omp.h>

namespace fsi::structure::collision {
namespace {

/// A point already at d_c (up to round-off, e.g. just corrected with d_t = d_c) is not
/// corrected again.
constexpr double kSettledTolerance_m = 1e-12;

/// Below this many points a pass runs on one thread: starting the team costs more than the
/// queries (a culled point costs a few ns, a near one about 0.3 us).
constexpr std::size_t kMinPointsForThreads = 2048;

} // namespace

double CorrectionStats::deepest_penetration_m() const {
  return std::max(0.0, -min_signed_distance_m);
}

CollisionSet::CollisionSet(double threshold_m, double target_distance_m, int max_passes)
    : threshold_m_(threshold_m), target_distance_m_(target_distance_m), max_passes_(max_passes) {
  if (!(threshold_m > 0.0) || !std::isfinite(threshold_m)) {
    throw std::invalid_argument("collision threshold_m = " + std::to_string(threshold_m) +
                                " must be positive (the paper uses two Eulerian cell widths).");
  }
  if (!(target_distance_m >= threshold_m) || !std::isfinite(target_distance_m)) {
    throw std::invalid_argument(
        "collision target_distance_m = " + std::to_string(target_distance_m) +
        " must be at least threshold_m = " + std::to_string(threshold_m) +
        ", or corrected points would be corrected again.");
  }
  if (max_passes < 1) {
    throw std::invalid_argument("collision max_passes = " + std::to_string(max_passes) +
                                " must be at least 1.");
  }
}

void CollisionSet::add_surface(std::unique_ptr<geometry::RigidSurface> surface,
                               std::shared_ptr<const motion::RigidMotion> motion) {
  if (!surface || !motion) {
    throw std::invalid_argument("CollisionSet::add_surface needs a surface and a motion.");
  }
  surface->prepare_culling(threshold_m_);
  bodies_.push_back({std::move(surface), std::move(motion)});
}

CorrectionStats CollisionSet::correct(PointArray &positions_m, double time_s) const {
  CorrectionStats stats;
  const auto n_points = static_cast<std::size_t>(positions_m.rows());
  if (bodies_.empty() || n_points == 0) {
    return stats;
  }
  // The first pass checks every point; later passes only the points moved in the pass
  // before (a point that did not move keeps the distances it was checked with).
  std::vector<Eigen::Index> active(n_points);
  for (std::size_t i = 0; i < n_points; ++i)
    active[i] = static_cast<Eigen::Index>(i);
  std::vector<char> was_corrected(n_points, 0), moved(n_points, 0);
  std::vector<Eigen::Isometry3d> poses;
  for (const Body &body : bodies_)
    poses.push_back(body.motion->pose_at(time_s));
  for (int pass = 0; pass < max_passes_ && !active.empty(); ++pass) {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      correct_against(b, poses, positions_m, active, moved, was_corrected, stats);
    }
    ++stats.n_passes;
    std::vector<Eigen::Index> next;
    for (Eigen::Index i : active) {
      if (moved[static_cast<std::size_t>(i)])
        next.push_back(i);
      moved[static_cast<std::size_t>(i)] = 0;
    }
    active = std::move(next);
  }
  stats.n_points_corrected =
      static_cast<std::size_t>(std::count(was_corrected.begin(), was_corrected.end(), 1));
  return stats;
}

CollisionSet::Clearance CollisionSet::nearest_wall(const Vec3 &world_m,
                                                   const std::vector<Eigen::Isometry3d> &poses) const {
  Clearance nearest{std::numeric_limits<double>::infinity(), Vec3::Zero()};
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Vec3 body_m = poses[b].inverse() * world_m;
    if (!bodies_[b].surface->may_be_within(body_m, threshold_m_))
      continue;
    const geometry::SurfaceDistance d = bodies_[b].surface->distance(body_m);
    if (d.signed_distance_m < nearest.signed_distance_m)
      nearest = {d.signed_distance_m, poses[b].linear() * d.normal_into_fluid};
  }
  return nearest;
}

void CollisionSet::correct_against(std::size_t b, const std::vector<Eigen::Isometry3d> &poses,
                                   PointArray &positions_m, const std::vector<Eigen::Index> &active,
                                   std::vector<char> &moved, std::vector<char> &was_corrected,
                                   CorrectionStats &stats) const {
  const Body &body = bodies_[b];
  const Eigen::Isometry3d world_to_body = poses[b].inverse();
  const Eigen::Matrix3d rotation = poses[b].linear();
  const double trigger_m = threshold_m_ - kSettledTolerance_m;
  // Each point is corrected on its own (its own row, its own flags), so the points are split
  // among threads; the counts and the minimum are reduced exactly, and the result does not
  // depend on the number of threads.
  const auto n_active = static_cast<std::ptrdiff_t>(active.size());
  std::size_t n_corrections = 0, n_pinched = 0;
  double min_signed_distance_m = stats.min_signed_distance_m;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : n_corrections, n_pinched) \
    reduction(min : min_signed_distance_m) if (active.size() >= kMinPointsForThreads)
  for (std::ptrdiff_t k = 0; k < n_active; ++k) {
    const Eigen::Index i = active[static_cast<std::size_t>(k)];
    const Vec3 world_m = positions_m.row(i).transpose();
    if (!world_m.allFinite())
      continue;
    const Vec3 body_m = world_to_body * world_m;
    if (!body.surface->may_be_within(body_m, threshold_m_))
      continue;
    const geometry::SurfaceDistance d = body.surface->distance(body_m);
    if (!(d.signed_distance_m < trigger_m))
      continue;
    // Eq. 11: X_c = X + n_w (d_t - eps_c), with n_w rotated from the body to the world.
    const Vec3 normal = rotation * d.normal_into_fluid;
    const double full_m = target_distance_m_ - d.signed_distance_m;
    double move_m = full_m;
    // A facing wall B within d_c of the end of the move: the gap is narrower than 2 d_t.
    // Along the move s, the distance to this wall grows as eps_c + s and the distance to B
    // falls as eps_B + c (full - s), c = -n_B . n_w; stop where the two are equal.
    const Clearance end = nearest_wall(world_m + full_m * normal, poses);
    const double facing = -end.normal_into_fluid.dot(normal);
    if (end.signed_distance_m < trigger_m && facing > 0.5) {
      move_m = (end.signed_distance_m + facing * full_m - d.signed_distance_m) / (1.0 + facing);
      move_m = std::clamp(move_m, -std::max(d.signed_distance_m, 0.0), full_m);
      ++n_pinched;
    }
    positions_m.row(i) += move_m * normal.transpose();
    min_signed_distance_m = std::min(min_signed_distance_m, d.signed_distance_m);
    was_corrected[static_cast<std::size_t>(i)] = 1;
    if (std::abs(move_m) > kSettledTolerance_m)
      moved[static_cast<std::size_t>(i)] = 1;
    ++n_corrections;
  }
  stats.n_corrections += n_corrections;
  stats.n_pinched += n_pinched;
  stats.min_signed_distance_m = min_signed_distance_m;
}

std::string CollisionSet::describe() const {
  std::string text = "collision: d_c = " + std::to_string(threshold_m_) +
                     " m, d_t = " + std::to_string(target_distance_m_) + " m, " +
                     std::to_string(bodies_.size()) + " surface(s), passes of " +
                     std::to_string(kMinPointsForThreads) + "+ points on " +
                     std::to_string(omp_get_max_threads()) + " thread(s) (OMP_NUM_THREADS)";
  for (const Body &body : bodies_) {
    text +=
        "\n  " + body.surface->describe() + (body.motion->is_static() ? " (static)" : " (moving)");
  }
  return text;
}

} // namespace fsi::structure::collision
