#include "IqnIlsAccelerator.hpp"

namespace fsi::coupler {

void IqnIlsAccelerator::begin_step() {
  iteration_ = 0;
  steps_.emplace_back();
  while (static_cast<int>(steps_.size()) > reuse_steps_ + 1)
    steps_.pop_front();
}

void IqnIlsAccelerator::end_step() {
  if (reuse_steps_ == 0)
    steps_.clear();
}

namespace {
const std::string prefix = "implicit/iqn_ils/";
}

void IqnIlsAccelerator::save_state(checkpoint::StateArchive &archive) const {
  archive.put_integer(prefix + "n_steps", static_cast<std::int64_t>(steps_.size()));
  for (std::size_t s = 0; s < steps_.size(); ++s) {
    const std::string step = prefix + "steps/" + std::to_string(s) + "/";
    archive.put_integer(step + "n_columns", static_cast<std::int64_t>(steps_[s].first.size()));
    for (std::size_t i = 0; i < steps_[s].first.size(); ++i) {
      archive.put_vector(step + "v/" + std::to_string(i), steps_[s].first[i]);
      archive.put_vector(step + "w/" + std::to_string(i), steps_[s].second[i]);
    }
  }
}

void IqnIlsAccelerator::load_state(const checkpoint::StateArchive &archive, long size) {
  steps_.clear();
  if (!archive.has(prefix + "n_steps"))
    return; // a part written without the columns: the history starts afresh
  const auto n_steps = archive.integer(prefix + "n_steps");
  for (std::int64_t s = 0; s < n_steps; ++s) {
    const std::string step = prefix + "steps/" + std::to_string(s) + "/";
    auto &columns = steps_.emplace_back();
    const auto n = archive.integer(step + "n_columns");
    for (std::int64_t i = 0; i < n; ++i) {
      columns.first.push_back(archive.vector(step + "v/" + std::to_string(i), size));
      columns.second.push_back(archive.vector(step + "w/" + std::to_string(i), size));
    }
  }
}

long IqnIlsAccelerator::n_columns() const {
  long n = 0;
  for (const auto &step : steps_)
    n += static_cast<long>(step.first.size());
  return n;
}

void IqnIlsAccelerator::next(const Eigen::VectorXd &x, const Eigen::VectorXd &x_tilde, Eigen::VectorXd &out) {
  if (steps_.empty())
    begin_step();
  Eigen::VectorXd r = x_tilde - x;
  if (iteration_ > 0) {
    steps_.back().first.push_back(r - r_prev_);
    steps_.back().second.push_back(x_tilde - x_tilde_prev_);
  }
  r_prev_ = r;
  x_tilde_prev_ = x_tilde;
  ++iteration_;
  // Newest columns first; no more columns than rows.
  const long rows = x.size();
  const long m = std::min(n_columns(), rows);
  if (m == 0) {
    out = x + omega_ * r;
    return;
  }
  Eigen::MatrixXd V(rows, m), W(rows, m);
  long j = 0;
  for (auto step = steps_.rbegin(); step != steps_.rend() && j < m; ++step)
    for (std::size_t i = step->first.size(); i-- > 0 && j < m; ++j) {
      V.col(j) = step->first[i];
      W.col(j) = step->second[i];
    }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(V);
  qr.setThreshold(1e-12); // relative to the largest pivot: a column that adds nothing new is dropped
  const Eigen::VectorXd c = qr.solve(-r);
  out = x_tilde + W * c;
}

} // namespace fsi::coupler
