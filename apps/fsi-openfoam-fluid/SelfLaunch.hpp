#pragma once
// The fluid process starting itself again: for the precursor run (a child it waits for,
// passing on a stop signal), and under mpirun for an MPI run (a child it waits for and exits
// with, so that the process id, the signals and the exit code stay those the launcher knows).

#include <string>
#include <vector>

namespace fsi::apps {

/// Runs this program again with its arguments and `extra`, and waits for it; a stop signal
/// received meanwhile (participant::FluidParticipant::stop_signal) is passed on. Returns its exit code.
int run_self(int argc, char **argv, const std::vector<std::string> &extra);

/// Runs mpirun with n ranks of this program (with --mpi-rank) on the prepared case, in a process
/// group of its own, and exits with its exit code. A first SIGINT or SIGTERM reaches the ranks as
/// SIGUSR1 or SIGUSR2, which mpirun passes on and leaves them running: they finish the step and
/// checkpoint it (mpirun itself, given SIGINT, would kill them a second after SIGTERM, within a
/// pump's step). A second signal stops mpirun at once. Throws std::runtime_error when mpirun
/// cannot start.
[[noreturn]] void run_mpirun(int n, int argc, char **argv);

/// On a rank: the stop signal SIGUSR1 or SIGUSR2 stands for (SIGINT, SIGTERM).
int rank_stop_signal(int user_signal);

} // namespace fsi::apps
