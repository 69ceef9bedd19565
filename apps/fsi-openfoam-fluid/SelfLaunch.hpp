#pragma once
// The fluid process starting itself again: for the precursor run (a child it waits for,
// passing on a stop signal), and under mpirun for an MPI run (replacing itself, so that the
// process id, the signals and the exit code stay those the launcher knows).

#include <string>
#include <vector>

namespace fsi::apps {

/// Runs this program again with its arguments and `extra`, and waits for it; a stop signal
/// received meanwhile (participant::FluidParticipant::stop_signal) is passed on. Returns its exit code.
int run_self(int argc, char **argv, const std::vector<std::string> &extra);

/// Replaces this process by mpirun running n ranks of this program (with --mpi-rank) on the
/// prepared case. Throws std::runtime_error when mpirun cannot start.
[[noreturn]] void exec_mpirun(int n, int argc, char **argv);

} // namespace fsi::apps
