#include "ImmersedWallDistance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::fluid::rigid {

namespace {
constexpr double min_distance_m = 1e-9; // a cell centre exactly on the surface
} // namespace

ImmersedWallDistance::ImmersedWallDistance(const std::vector<const RigidBody *> &bodies,
                                           const PointArray &cell_centres_m, double margin_m)
    : centres_m_(cell_centres_m),
      distance_m_(Eigen::VectorXd::Constant(cell_centres_m.rows(), std::numeric_limits<double>::infinity())) {
  for (const RigidBody *body : bodies) {
    const SweptRegion region = SweptRegion::of(*body, margin_m);
    Candidates c{body, {}};
    for (Eigen::Index i = 0; i < cell_centres_m.rows(); ++i)
      if (region.contains(cell_centres_m.row(i).transpose()))
        c.cells.push_back(static_cast<std::int32_t>(i));
    candidates_.push_back(std::move(c));
  }
}

std::size_t ImmersedWallDistance::n_measured_cells() const {
  std::size_t n = 0;
  for (const auto &c : candidates_)
    n += c.cells.size();
  return n;
}

void ImmersedWallDistance::update(double time_s) {
  for (const auto &c : candidates_)
    for (const auto cell : c.cells)
      distance_m_[cell] = std::numeric_limits<double>::infinity();
  for (const auto &c : candidates_) {
    const Eigen::Isometry3d world_to_body = c.body->motion().pose_at(time_s).inverse();
    for (const auto cell : c.cells) {
      const Vec3 x_body = world_to_body * Vec3(centres_m_.row(cell).transpose());
      // Inside a body the distance to its surface (not 0): the Spalart-Allmaras models divide
      // by (kappa d)^2 before the solver zeroes nuTilda there.
      const double d = std::max(std::abs(c.body->surface().distance(x_body).signed_distance_m), min_distance_m);
      distance_m_[cell] = std::min(distance_m_[cell], d);
    }
  }
}

} // namespace fsi::fluid::rigid
