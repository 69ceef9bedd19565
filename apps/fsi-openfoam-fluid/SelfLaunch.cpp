#include "SelfLaunch.hpp"

#include "participant/FluidParticipant.hpp"

#include <spdlog/spdlog.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
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

[[noreturn]] void exec_mpirun(int n, int argc, char **argv) {
  std::vector<std::string> args = {"mpirun", "-np", std::to_string(n), "--oversubscribe", "-x", "WM_PROJECT_DIR",
                                   "-x", "FOAM_ETC"};
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
  execvp("mpirun", pointers.data());
  throw std::runtime_error(std::string("cannot start mpirun: ") + std::strerror(errno) +
                           " (install the Debian package openmpi-bin)");
}

} // namespace fsi::apps
