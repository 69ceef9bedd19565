#include "SelfLaunch.hpp"

#include "participant/FluidParticipant.hpp"

#include <spdlog/spdlog.h>

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace fsi::apps {

int run_self(int argc, char **argv, const std::vector<std::string> &extra) {
  std::vector<std::string> args = {std::filesystem::read_symlink("/proc/self/exe").string()};
  for (int i = 1; i < argc; ++i)
    args.emplace_back(argv[i]);
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<char *> pointers;
  for (auto &a : args)
    pointers.push_back(a.data());
  pointers.push_back(nullptr);
  spdlog::default_logger()->flush();
  const pid_t child = fork();
  if (child < 0)
    throw std::runtime_error(std::string("cannot start the precursor run: ") + std::strerror(errno));
  if (child == 0) {
    execv(pointers[0], pointers.data());
    _exit(127);
  }
  int status = 0;
  bool forwarded = false;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR)
      throw std::runtime_error(std::string("waiting for the precursor run: ") + std::strerror(errno));
    const int signal = participant::FluidParticipant::stop_signal();
    if (signal != 0 && !forwarded) {
      kill(child, signal);
      forwarded = true;
    }
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

namespace {

std::atomic<int> stop_signals_received{0};
std::atomic<int> first_stop_signal{0};

extern "C" void count_stop_signal(int signal) {
  int none = 0;
  first_stop_signal.compare_exchange_strong(none, signal);
  participant::FluidParticipant::stop_signal() = signal;
  ++stop_signals_received;
}

/// Whether `program` is an executable file in a folder of PATH.
bool on_path(const std::string &program) {
  const char *path = std::getenv("PATH");
  std::string folders = path ? path : "";
  std::size_t begin = 0;
  while (begin <= folders.size()) {
    const std::size_t end = std::min(folders.find(':', begin), folders.size());
    const std::string folder = folders.substr(begin, end - begin);
    if (!folder.empty() && ::access((folder + "/" + program).c_str(), X_OK) == 0)
      return true;
    begin = end + 1;
  }
  return false;
}

} // namespace

int rank_stop_signal(int user_signal) { return user_signal == SIGUSR2 ? SIGTERM : SIGINT; }

[[noreturn]] void run_mpirun(int n, int argc, char **argv) {
  if (!on_path("mpirun"))
    throw std::runtime_error("cannot start mpirun: not on PATH (install the Debian package openmpi-bin)");
  std::vector<std::string> args = {"mpirun", "-np", std::to_string(n), "--oversubscribe", "--stdin", "none",
                                   "-x", "WM_PROJECT_DIR", "-x", "FOAM_ETC"};
  if (geteuid() == 0)
    args.push_back("--allow-run-as-root");
  args.push_back(std::filesystem::read_symlink("/proc/self/exe").string());
  for (int i = 1; i < argc; ++i)
    args.emplace_back(argv[i]);
  args.emplace_back("--mpi-rank");
  std::vector<char *> pointers;
  for (auto &a : args)
    pointers.push_back(a.data());
  pointers.push_back(nullptr);
  spdlog::info("starting {} MPI ranks with mpirun", n);
  spdlog::default_logger()->flush();
  std::signal(SIGINT, count_stop_signal);
  std::signal(SIGTERM, count_stop_signal);
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child < 0)
    throw std::runtime_error(std::string("cannot start mpirun: ") + std::strerror(errno));
  if (child == 0) {
    // Its own process group: a terminal's Ctrl-C reaches this process only, not mpirun (which
    // would kill the ranks a second after passing them SIGTERM) nor the ranks. Should this
    // process die (a launcher's SIGKILL), mpirun gets SIGTERM and stops the ranks.
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent)
      _exit(128 + SIGTERM);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    execvp("mpirun", pointers.data());
    _exit(127);
  }
  setpgid(child, child);
  constexpr int poll_ms = 100;
  // Signals within this time of the first are the same stop: the launcher passes on a Ctrl-C
  // that the terminal delivered to this process too.
  constexpr int same_stop_ms = 500;
  int forwarded_ms = -1, counted = 0;
  bool stopped_at_once = false;
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child)
      break;
    if (done < 0 && errno != EINTR)
      throw std::runtime_error(std::string("waiting for mpirun: ") + std::strerror(errno));
    const int received = stop_signals_received.load();
    if (received > 0 && forwarded_ms < 0) {
      // mpirun passes SIGUSR1 and SIGUSR2 on to every rank and leaves them running: each finishes
      // its step and checkpoints it, as one process would on SIGINT or SIGTERM (rank_stop_signal).
      kill(child, first_stop_signal.load() == SIGTERM ? SIGUSR2 : SIGUSR1);
      forwarded_ms = 0;
    } else if (forwarded_ms >= 0 && !stopped_at_once) {
      forwarded_ms += poll_ms;
      if (forwarded_ms <= same_stop_ms) {
        counted = received;
      } else if (received > counted) {
        kill(child, SIGTERM); // a second stop: mpirun stops the ranks at once
        stopped_at_once = true;
      }
    }
    ::usleep(poll_ms * 1000);
  }
  spdlog::default_logger()->flush();
  std::exit(WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status));
}

} // namespace fsi::apps
