#include "FeedbackCouplingLaw.hpp"

#include <stdexcept>

namespace fsi::coupler {

FeedbackCouplingLaw::FeedbackCouplingLaw(double alpha_n_per_m_per_measure, double beta_n_s_per_m_per_measure)
    : alpha_(alpha_n_per_m_per_measure), beta_(beta_n_s_per_m_per_measure) {
  if (!(alpha_ >= 0.0) || !(beta_ >= 0.0) || !(alpha_ + beta_ > 0.0))
    throw std::invalid_argument("the feedback gains alpha and beta must be >= 0, one of them positive");
}

void FeedbackCouplingLaw::compute_force(const CouplingInputs &in, CouplingOutputs &out) {
  if (integral_.rows() != in.x_now_m->rows())
    throw std::logic_error("coupling law 'feedback': start() was not called with the structure points");
  // W^n = U_ib^n - V^n, with V^n = (X^n - X^{n-1}) / dt; I^n = I^{n-1} + W^n dt.
  const double dt = in.dt_s;
  out.force_density_n_per_measure = *in.u_ib_now_m_per_s - (*in.x_now_m - *in.x_prev_m) / dt; // W^n
  next_ = integral_ + dt * out.force_density_n_per_measure;
  out.force_density_n_per_measure = -(alpha_ * next_ + beta_ * out.force_density_n_per_measure);
}

void FeedbackCouplingLaw::accept(const CouplingOutputs &) { integral_.swap(next_); }

void FeedbackCouplingLaw::save_state(checkpoint::StateArchive &archive) const {
  archive.put_points("law/integral_m", integral_);
}

void FeedbackCouplingLaw::load_state(const checkpoint::StateArchive &archive, long n_points) {
  integral_ = archive.points("law/integral_m", n_points);
}

} // namespace fsi::coupler
