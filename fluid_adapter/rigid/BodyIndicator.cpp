#include "fluid_adapter/rigid/BodyIndicator.hpp"

#include "fluid_adapter/rigid/ParallelFor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::fluid::rigid {
namespace {

/// Bounds are widened by this fraction of the body's size against round-off.
constexpr double kRoundOffFraction = 1e-9;

double largest(const Eigen::VectorXd &values) { return values.size() ? values.maxCoeff() : 0.0; }

} // namespace

BodyIndicator::BodyIndicator(const RigidBody &body, const PointArray &cell_centres_m,
                             IndicatorOptions options, const Eigen::VectorXd &cell_sizes_m)
    : body_(body), options_(options) {
  const Eigen::Index n_cells = cell_centres_m.rows();
  const bool fraction = options_.sampling == IndicatorOptions::Sampling::cell_fraction;
  const bool sized = needs_sizes();
  if (sized && cell_sizes_m.size() != n_cells)
    throw std::invalid_argument("body '" + body.name() + "': " + (fraction ? "cell_fraction" : "inside_smoothed") +
                                " sampling needs one cell size per cell (" + std::to_string(n_cells) + " cells, " +
                                std::to_string(cell_sizes_m.size()) + " sizes)");
  if (fraction && options_.samples_per_direction < 2)
    throw std::invalid_argument("body '" + body.name() + "': samples_per_direction must be >= 2");
  if (options_.sampling == IndicatorOptions::Sampling::inside_smoothed && !(options_.smoothing_depth_cells > 0.0))
    throw std::invalid_argument("body '" + body.name() + "': smoothing_depth_cells must be > 0");
  // A cut cell may have its centre outside the body but sub-points inside: widen by its half diagonal.
  const double margin_m = kRoundOffFraction * body.body_box_m().diagonal().norm() +
                          (fraction ? 0.5 * std::sqrt(3.0) * largest(cell_sizes_m) : 0.0);
  region_ = SweptRegion::of(body, margin_m);
  for (Eigen::Index c = 0; c < n_cells; ++c)
    if (region_.contains(cell_centres_m.row(c).transpose()))
      candidate_cells_.push_back(static_cast<std::int32_t>(c));
  const auto n_candidates = static_cast<Eigen::Index>(candidate_cells_.size());
  candidate_centres_m_.resize(n_candidates, 3);
  candidate_sizes_m_.resize(sized ? n_candidates : 0);
  for (Eigen::Index k = 0; k < n_candidates; ++k) {
    candidate_centres_m_.row(k) = cell_centres_m.row(candidate_cells_[static_cast<std::size_t>(k)]);
    if (sized)
      candidate_sizes_m_(k) = cell_sizes_m(candidate_cells_[static_cast<std::size_t>(k)]);
  }
  candidate_chi_ = Eigen::VectorXd::Zero(n_candidates);
  chi_ = Eigen::VectorXd::Zero(n_cells);
  velocity_m_per_s_ = PointArray::Zero(n_cells, 3);
}

void BodyIndicator::move_cells(const PointArray &cell_centres_m) {
  if (cell_centres_m.rows() != chi_.size())
    throw std::invalid_argument("body '" + body_.name() + "': the moved mesh has " +
                                std::to_string(cell_centres_m.rows()) + " cells, the indicator was built on " +
                                std::to_string(chi_.size()));
  for (Eigen::Index k = 0; k < candidate_centres_m_.rows(); ++k)
    candidate_centres_m_.row(k) = cell_centres_m.row(candidate_cells_[static_cast<std::size_t>(k)]);
}

double BodyIndicator::sharp_value(const Vec3 &centre_body_m) const {
  return body_.contains_body_point(centre_body_m) ? 1.0 : 0.0;
}

double BodyIndicator::fraction_value(const Eigen::Isometry3d &world_to_body,
                                     const Vec3 &centre_body_m, double cell_size_m) const {
  const double half_diagonal_m = 0.5 * std::sqrt(3.0) * cell_size_m;
  if (body_.body_box_m().exteriorDistance(centre_body_m) >= half_diagonal_m)
    return 0.0;
  // Cut test: the centre and the 8 corners of the cell (world-aligned cube) on one side.
  const Eigen::Matrix3d half_edges = 0.5 * cell_size_m * world_to_body.linear();
  const bool centre_inside = body_.contains_body_point(centre_body_m);
  bool cut = false;
  for (int corner = 0; corner < 8 && !cut; ++corner) {
    const Vec3 signs(corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, corner & 4 ? 1.0 : -1.0);
    cut = body_.contains_body_point(centre_body_m + half_edges * signs) != centre_inside;
  }
  if (!cut)
    return centre_inside ? 1.0 : 0.0;
  // Sub-points on a world-aligned lattice, mapped with the rotation part of the pose.
  const int n = options_.samples_per_direction;
  int n_inside = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 lattice(2.0 * (i + 0.5) / n - 1.0, 2.0 * (j + 0.5) / n - 1.0, 2.0 * (k + 0.5) / n - 1.0);
        n_inside += body_.contains_body_point(centre_body_m + half_edges * lattice) ? 1 : 0;
      }
  return static_cast<double>(n_inside) / (n * n * n);
}

double BodyIndicator::smoothed_value(const Vec3 &centre_body_m, double cell_size_m) const {
  if (!body_.contains_body_point(centre_body_m))
    return 0.0;
  const double depth_m = options_.smoothing_depth_cells * cell_size_m;
  if (!body_.surface().may_be_within(centre_body_m, depth_m))
    return 1.0;
  const double d = std::abs(body_.surface().distance(centre_body_m).signed_distance_m);
  return std::min(1.0, d / depth_m);
}

void BodyIndicator::update(double time_s) {
  if (evaluated_ && body_.motion().is_static())
    return;
  const Eigen::Isometry3d world_to_body = body_.motion().pose_at(time_s).inverse();
  rigid_velocity_ = RigidVelocity::of(body_.motion(), time_s);
  if (evaluated_ && options_.cells_move_with_body) {
    follow_carried_cells(world_to_body);
    return;
  }
  using Sampling = IndicatorOptions::Sampling;
  parallel_for(candidate_cells_.size(), options_.n_threads, [&](std::size_t begin, std::size_t end) {
    for (auto k = static_cast<Eigen::Index>(begin); k < static_cast<Eigen::Index>(end); ++k) {
      const Vec3 centre_m = candidate_centres_m_.row(k).transpose();
      const Vec3 centre_body_m = world_to_body * centre_m;
      double value = 0.0;
      switch (options_.sampling) {
      case Sampling::sharp:
        value = sharp_value(centre_body_m);
        break;
      case Sampling::cell_fraction:
        value = fraction_value(world_to_body, centre_body_m, candidate_sizes_m_(k));
        break;
      case Sampling::inside_smoothed:
        value = smoothed_value(centre_body_m, candidate_sizes_m_(k));
        break;
      }
      candidate_chi_(k) = value;
      const auto cell = candidate_cells_[static_cast<std::size_t>(k)];
      chi_(cell) = value;
      velocity_m_per_s_.row(cell) = rigid_velocity_.at(centre_m).transpose();
    }
  });
  inside_cells_.clear();
  for (std::size_t k = 0; k < candidate_cells_.size(); ++k)
    if (candidate_chi_(static_cast<Eigen::Index>(k)) > 0.0)
      inside_cells_.push_back(candidate_cells_[k]);
  evaluated_ = true;
  if (options_.cells_move_with_body) {
    first_body_centres_m_.resize(candidate_centres_m_.rows(), 3);
    for (Eigen::Index k = 0; k < candidate_centres_m_.rows(); ++k)
      first_body_centres_m_.row(k) = (world_to_body * Vec3(candidate_centres_m_.row(k).transpose())).transpose();
  }
}

void BodyIndicator::follow_carried_cells(const Eigen::Isometry3d &world_to_body) {
  // chi stays; the velocities follow the cells, and the cells are checked against the body.
  double drift = 0.0;
  for (Eigen::Index k = 0; k < candidate_centres_m_.rows(); ++k) {
    const Vec3 centre_m = candidate_centres_m_.row(k).transpose();
    drift = std::max(drift, (world_to_body * centre_m - first_body_centres_m_.row(k).transpose()).norm());
    velocity_m_per_s_.row(candidate_cells_[static_cast<std::size_t>(k)]) = rigid_velocity_.at(centre_m).transpose();
  }
  carried_drift_m_ = drift;
}

} // namespace fsi::fluid::rigid
