#include "RunPlan.hpp"

namespace fsi::participant {

Eigen::Index RunPlan::n_points() const {
  Eigen::Index n = 0;
  for (const auto &s : structures)
    n += s.n_points();
  return n;
}

Eigen::VectorXd RunPlan::point_measures() const {
  Eigen::VectorXd all(n_points());
  Eigen::Index at = 0;
  for (const auto &s : structures) {
    all.segment(at, s.point_measure.size()) = s.point_measure;
    at += s.point_measure.size();
  }
  return all;
}

std::string RunEnd::status() const {
  switch (kind) {
  case Kind::completed:
    return "completed";
  case Kind::interrupted:
    return "interrupted";
  case Kind::stopped:
    return "stopped: " + reason;
  case Kind::coupler_lost:
    return "coupler lost: " + reason;
  case Kind::failed:
    break;
  }
  return "failed: " + reason;
}

} // namespace fsi::participant
