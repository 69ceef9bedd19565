#include "ImplicitStep.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

namespace fsi::coupler {

namespace {
Eigen::Map<const Eigen::VectorXd> as_vector(const PointArray &points) { return {points.data(), points.size()}; }
} // namespace

ImplicitStep::ImplicitStep(const ImplicitCouplingConfig &settings)
    : settings_(settings), accelerator_(make_accelerator(settings)) {}

void ImplicitStep::advance(long n, StepExchange &exchange) {
  first_force(n, exchange);
  auto &state = exchange.state();
  auto &coupled = exchange.coupled();
  const double t_next = static_cast<double>(n + 1) * exchange.time_step_s();
  const PointArray x_start = state.x_now_m, x_before = state.x_prev_m; // X^n, X^{n-1}: each iteration starts there
  accelerator_->begin_step();
  for (int k = 0;; ++k) {
    if (k > 0) { // back to the start of the step
      state.x_now_m = x_start;
      state.x_prev_m = x_before;
    }
    exchange.advance_fluid_and_structure(n, k > 0);           // under F_k; X^{n+1}_k
    exchange.interpolate_fluid_velocity(n, t_next, state.x_now_m); // U^{n+1}_k at X^{n+1}_k
    exchange.apply_coupling_law(evaluated_);                  // F~_k = H(F_k)
    iterations_ = k + 1;
    const bool converged = compare(coupled.force_density_n_per_measure, evaluated_.force_density_n_per_measure,
                                   state.x_now_m.rows());
    if ((converged && iterations_ >= settings_.min_iterations) || iterations_ >= settings_.max_iterations) {
      if (!converged)
        warn_unconverged(n);
      break;
    }
    accelerator_->next(as_vector(coupled.force_density_n_per_measure),
                       as_vector(evaluated_.force_density_n_per_measure), next_force_);
    coupled.force_density_n_per_measure = Eigen::Map<const PointArray>(next_force_.data(), state.x_now_m.rows(), 3);
  }
  accelerator_->end_step();
  exchange.law().accept(evaluated_); // the law's state moves on with the end-of-step evaluation
  guess_ = evaluated_.force_density_n_per_measure;
}

void ImplicitStep::first_force(long n, StepExchange &exchange) {
  if (!have_guess_) { // the first step of a run (or of a restart)
    exchange.interpolate_fluid_velocity(n, static_cast<double>(n) * exchange.time_step_s(), exchange.state().x_now_m);
    exchange.apply_coupling_law(exchange.coupled());
    have_guess_ = true;
  } else {
    exchange.coupled().force_density_n_per_measure = guess_;
  }
}

bool ImplicitStep::compare(const PointArray &f_k, const PointArray &f_tilde_k, Eigen::Index n_points) {
  const auto f = as_vector(f_k);
  const auto f_tilde = as_vector(f_tilde_k);
  const double scale = f_tilde.norm();
  residual_ = (f_tilde - f).norm() / (scale > 0.0 ? scale : 1.0);
  const double rms = (f_tilde - f).norm() / std::sqrt(static_cast<double>(std::max<Eigen::Index>(1, n_points)));
  return (f_tilde - f).norm() <= settings_.tolerance * scale || rms <= settings_.absolute_tolerance_n_per_measure;
}

void ImplicitStep::warn_unconverged(long n) {
  ++unconverged_steps_;
  if (unconverged_steps_ <= 10 || unconverged_steps_ % 1000 == 0)
    spdlog::warn("step {}: not converged after {} coupling iterations (residual {:.3g}, tolerance {:.3g}); "
                 "accepted ({} such steps so far)",
                 n, iterations_, residual_, settings_.tolerance, unconverged_steps_);
}

std::string ImplicitStep::progress_note(double mean_iterations) const {
  return fmt::format(", {:.2f} coupling iterations/step (residual {:.2g}, {} unconverged)", mean_iterations, residual_,
                     unconverged_steps_);
}

void ImplicitStep::save_state(checkpoint::StateArchive &archive) const {
  if (have_guess_)
    archive.put_points("implicit/guess_n_per_measure", guess_);
  accelerator_->save_state(archive);
}

void ImplicitStep::load_state(const checkpoint::StateArchive &archive, Eigen::Index n_points) {
  if (archive.has("implicit/guess_n_per_measure")) { // the next step's F_0
    guess_ = archive.points("implicit/guess_n_per_measure", n_points);
    have_guess_ = true;
  }
  accelerator_->load_state(archive, 3 * n_points); // IQN-ILS: the columns of the last steps
}

} // namespace fsi::coupler
