#pragma once
// The exit codes of every executable (fsi-structure, fsi-coupler, fsi-prescribed-flow,
// fsi-openfoam-fluid), which the launcher and the scripts rely on.

namespace fsi::common {

/// The run completed (or the command did what was asked: --help, --check, --plan).
inline constexpr int exit_code_success = 0;
/// The run stopped: the simulation diverged, a peer failed or was lost, a solver failed.
inline constexpr int exit_code_run_failed = 1;
/// Invalid input: case file, command line, geometry, an endpoint that cannot be used.
inline constexpr int exit_code_bad_input = 2;
/// Stopped by SIGINT or SIGTERM (128 + SIGINT, the shell's convention), results kept.
inline constexpr int exit_code_interrupted = 130;

} // namespace fsi::common
