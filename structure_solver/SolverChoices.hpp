#pragma once
// The choices of the solver section of a sheet-like model (solver.linear_solver,
// solver.time_scheme): configuration-side names of how the step of Eq. (4) is solved.

namespace fsi::structure {

enum class LinearSolver { automatic, conjugate_gradient, direct };
enum class TimeScheme { paper, energy_conserving };

} // namespace fsi::structure
