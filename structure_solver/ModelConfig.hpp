#pragma once
// Type-erased configuration of one structure model. Each model declares its keys in a
// `template <class V> void visit_keys(V&)` and derives from ModelConfigBase<Self>, which
// forwards the three configuration visitors (reader, emitter, documentation) to it. The model
// itself is built by the solver's ModelFactory under the model's registry name: a configuration
// links no solver code.

#include "SolverChoices.hpp"
#include "TensionSchemeRegistry.hpp"
#include "common/Types.hpp"
#include "common/ConfigDocWriter.hpp"
#include "common/ConfigEmitter.hpp"
#include "common/ConfigReader.hpp"
#include "motion/MotionConfig.hpp"

#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace fsi::structure {

class ModelConfig {
public:
  virtual ~ModelConfig() = default;
  virtual void visit(common::ConfigReader &v) = 0;
  virtual void visit(common::ConfigEmitter &v) = 0;
  virtual void visit(common::ConfigDocWriter &v) = 0;
  /// Grid shape (n1, n2) the model will have; n2 == 1 for filaments (probes check indices).
  virtual std::pair<int, int> grid_shape() const = 0;
};

template <class Derived> class ModelConfigBase : public ModelConfig {
public:
  void visit(common::ConfigReader &v) override { self().visit_keys(v); }
  void visit(common::ConfigEmitter &v) override { self().visit_keys(v); }
  void visit(common::ConfigDocWriter &v) override { self().visit_keys(v); }

private:
  Derived &self() { return static_cast<Derived &>(*this); }
};

/// Numerical settings shared by the sheet-like models.
struct SolverConfig {
  LinearSolver linear_solver = LinearSolver::automatic;
  TimeScheme time_scheme = TimeScheme::paper;
  std::string tension = "frozen"; ///< a TensionSchemeRegistry name
  double max_stretch_ratio = 1.5;
  double max_speed_m_per_s = 1000.0;

  template <class V> void visit(V &v) {
    v.choice("linear_solver", linear_solver,
             {{"auto", LinearSolver::automatic}, {"cg", LinearSolver::conjugate_gradient}, {"direct", LinearSolver::direct}},
             "Solver of Eq. (4): Jacobi-preconditioned CG (fast for small dt), sparse LDLT (any dt), or CG "
             "falling back to LDLT.");
    v.choice("time_scheme", time_scheme, {{"paper", TimeScheme::paper}, {"energy_conserving", TimeScheme::energy_conserving}},
             "'paper': Eq. (4) as printed (slightly dissipative); 'energy_conserving': elastic force on the mean "
             "of X^{n+1} and X^{n-1}.");
    v.choice("tension", tension, TensionSchemeRegistry::builtin().choices(),
             "'frozen': tension coefficients at X^n (Eq. 4 as printed; stable for about Delta s / Delta t >= "
             "sqrt(2 phi / rho_1)); 'stabilized': above Delta s / (1.5 c) the part of the stretching stiffness the "
             "explicit step cannot carry is taken implicitly (no stretching-wave limit; robust, but less accurate at "
             "large steps); 'linearized': the change of the tension linearised about X^n and taken implicitly with "
             "its direction (a 3n x 3n system: no stretching-wave limit, accurate at large steps; see "
             "docs/verification.md). Both with time_scheme paper.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (TensionSchemeRegistry::builtin().entry(tension).paper_time_scheme_only &&
          time_scheme != TimeScheme::paper)
        v.fail("tension: stabilized and linearized work with time_scheme: paper only.");
    v.number("max_stretch_ratio", max_stretch_ratio, common::Range{.min = 1.0, .min_exclusive = true, .unit = "1"},
             "Stop the run (diverged) when an edge stretches beyond this ratio of its rest length.");
    v.number("max_speed_m_per_s", max_speed_m_per_s, common::Range::positive("m/s"),
             "Stop the run (diverged) when a point moves faster than this: catches a runaway that hardly "
             "stretches the structure.");
  }
};

/// Initial state shared by the sheet-like models.
struct InitialStateConfig {
  Vec3 velocity_m_per_s = Vec3::Zero();
  double curvature_1_per_m = 0.0;
  bool curved_rest_state = false;

  template <class V> void visit(V &v) {
    v.vec3("velocity_m_per_s", velocity_m_per_s, "m/s", "Uniform initial velocity.");
    v.number("curvature_1_per_m", curvature_1_per_m, common::Range::any("1/m"),
             "Pre-curvature: lines along s1 start as circular arcs of this curvature (0: flat/straight).");
    v.flag("curved_rest_state", curved_rest_state,
           "Bending rest state is the initial (pre-curved) shape instead of flat (small-rotation approximation).");
  }
};

} // namespace fsi::structure

namespace fsi::structure {

/// Keys every sheet-like model shares, declared after the model's own keys.
struct SharedSheetKeys {
  std::optional<motion::MotionConfig> clamp_motion;
  InitialStateConfig initial;
  SolverConfig solver;

  template <class V> void visit_shared(V &v) {
    v.optional_section("clamp_motion", clamp_motion,
                       "Rigid motion followed by the pinned/clamped points (and applied to the initial shape).");
    v.section("initial", initial, "Initial state.");
    v.section("solver", solver, "Numerical settings.");
  }
};

} // namespace fsi::structure
