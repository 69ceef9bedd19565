#pragma once
// Keys of implicit coupling (`coupling.scheme: implicit`, section `coupling.implicit`): the
// sub-iterations of a step and their acceleration (docs/coupling.md).

#include "common/ConfigDocWriter.hpp"
#include "common/ConfigEmitter.hpp"
#include "common/ConfigReader.hpp"

namespace fsi::coupler {

enum class Acceleration { constant, aitken, iqn_ils };

struct ImplicitCouplingConfig {
  Acceleration acceleration = Acceleration::iqn_ils;
  double relaxation = 0.5;
  double tolerance = 1e-3;
  double absolute_tolerance_n_per_measure = 1e-4;
  int min_iterations = 1;
  int max_iterations = 30;
  int reuse_steps = 8;

  template <class V> void visit(V &v) {
    v.choice("acceleration", acceleration,
             {{"constant", Acceleration::constant}, {"aitken", Acceleration::aitken}, {"iqn_ils", Acceleration::iqn_ils}},
             "How the next interface force of a step is chosen from the last ones: constant under-relaxation, "
             "Aitken's dynamic relaxation, or IQN-ILS (interface quasi-Newton with an inverse Jacobian from "
             "least squares, Anderson acceleration).");
    v.number("relaxation", relaxation, common::Range::between(0.0, 1.0, "1"),
             "Relaxation factor omega: every iteration (constant), the first of each step (aitken, iqn_ils). "
             "0 repeats the step with the same force (a check of the participants' in-step checkpoints).");
    v.number("tolerance", tolerance, common::Range::positive("1"),
             "A step has converged when |F~ - F| <= tolerance |F~| (2-norms over all points), F the force the "
             "step was advanced with and F~ the coupling law evaluated at its end.");
    v.number("absolute_tolerance_n_per_measure", absolute_tolerance_n_per_measure,
             common::Range::non_negative("N/m^2 (sheet), N/m (filament)"),
             "A step has also converged when the root mean square over the points of |F~ - F| is below this: "
             "the relative test cannot be met where the force itself vanishes (a structure moving with the flow).");
    v.integer("min_iterations", min_iterations, common::Range::at_least(1.0, "iterations"),
              "Iterations of every step at least.");
    v.integer("max_iterations", max_iterations, common::Range::at_least(1.0, "iterations"),
              "Iterations of a step at most; a step that has not converged then is accepted, counted and logged. "
              "1 is the explicit scheme, bit for bit.");
    v.integer("reuse_steps", reuse_steps, common::Range::at_least(0.0, "steps"),
              "iqn_ils: the previous steps whose iterations still inform the Jacobian.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (max_iterations < min_iterations)
        v.fail_value("max_iterations", "is below min_iterations (" + std::to_string(min_iterations) + ").");
  }
};

} // namespace fsi::coupler
