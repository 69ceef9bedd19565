#pragma once
// One probe: a weighted mean of some points of one structure, of their positions and, with the
// same weights, of their velocities. The weights are either fixed (a centroid: each point's
// rest measure, so the mean is the centre of mass and its velocity the momentum over the mass;
// a single point: weight 1) or follow the points (an edge centre: the trapezoid rule along the
// edge as it is now, so the mean is the midpoint of the edge curve however unevenly its
// points are spaced).

#include "common/Types.hpp"

#include <string>
#include <vector>

namespace fsi::structure {

/// Position (m) and velocity (m/s) of a probe at one instant.
struct ProbeSample {
  Vec3 position_m = Vec3::Zero();
  Vec3 velocity_m_per_s = Vec3::Zero();
};

class Probe {
public:
  /// Mean of `points` with fixed `weights` (one per point, positive sum).
  static Probe weighted(std::string name, std::size_t structure_index, std::vector<int> points,
                        Eigen::VectorXd weights);
  /// Mean of `points`, given in order along a curve, weighted by the trapezoid rule along the
  /// curve through their current positions (equal weights if the curve has no length).
  static Probe along_curve(std::string name, std::size_t structure_index, std::vector<int> points);

  const std::string &name() const { return name_; }
  /// Which structure of the scene (index in the scene's order) the probe reads.
  std::size_t structure_index() const { return structure_index_; }
  /// The probe's value for the structure's current positions and velocities ([n_points, 3]).
  ProbeSample sample(const PointArray &x_m, const PointArray &v_m_per_s) const;

private:
  Probe(std::string name, std::size_t structure_index, std::vector<int> points, Eigen::VectorXd weights);
  Eigen::VectorXd trapezoid_weights(const PointArray &x_m) const;

  std::string name_;
  std::size_t structure_index_;
  std::vector<int> points_;
  Eigen::VectorXd weights_; ///< fixed weights; empty: trapezoid rule along the current curve
};

} // namespace fsi::structure
