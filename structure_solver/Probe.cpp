#include "Probe.hpp"

#include <cassert>
#include <stdexcept>

namespace fsi::structure {

Probe::Probe(std::string name, std::size_t structure_index, std::vector<int> points, Eigen::VectorXd weights)
    : name_(std::move(name)), structure_index_(structure_index), points_(std::move(points)),
      weights_(std::move(weights)) {
  if (points_.empty())
    throw std::invalid_argument("probe '" + name_ + "' has no points");
}

Probe Probe::weighted(std::string name, std::size_t structure_index, std::vector<int> points,
                      Eigen::VectorXd weights) {
  if (static_cast<std::size_t>(weights.size()) != points.size() || !(weights.sum() > 0.0))
    throw std::invalid_argument("probe '" + name + "': needs one weight per point and a positive sum");
  return Probe(std::move(name), structure_index, std::move(points), std::move(weights));
}

Probe Probe::along_curve(std::string name, std::size_t structure_index, std::vector<int> points) {
  return Probe(std::move(name), structure_index, std::move(points), Eigen::VectorXd());
}

ProbeSample Probe::sample(const PointArray &x_m, const PointArray &v_m_per_s) const {
  const Eigen::VectorXd w = weights_.size() > 0 ? weights_ : trapezoid_weights(x_m);
  ProbeSample mean;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    assert(points_[k] < x_m.rows() && points_[k] < v_m_per_s.rows());
    mean.position_m += w[static_cast<Eigen::Index>(k)] * x_m.row(points_[k]).transpose();
    mean.velocity_m_per_s += w[static_cast<Eigen::Index>(k)] * v_m_per_s.row(points_[k]).transpose();
  }
  mean.position_m /= w.sum();
  mean.velocity_m_per_s /= w.sum();
  return mean;
}

/// w_k = (|X_k - X_{k-1}| + |X_{k+1} - X_k|) / 2 (one term at the ends): the trapezoid rule
/// for the integral along the curve, exact for a field linear along a straight edge.
Eigen::VectorXd Probe::trapezoid_weights(const PointArray &x_m) const {
  const auto n = static_cast<Eigen::Index>(points_.size());
  Eigen::VectorXd w = Eigen::VectorXd::Zero(n);
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    const double segment = (x_m.row(points_[k + 1]) - x_m.row(points_[k])).norm();
    w[k] += 0.5 * segment;
    w[k + 1] += 0.5 * segment;
  }
  if (!(w.sum() > 0.0))
    w.setOnes(); // one point, or all at one place
  return w;
}

} // namespace fsi::structure
