// A main for the fuzz targets in builds without libFuzzer (g++): runs every file given, or every
// file in every folder given, through LLVMFuzzerTestOneInput once: the committed corpus and
// past crashers replayed as a regression test (F1 of docs/security.md).
//
//   --interrupt-every-ms N   a timer signal (SIGALRM, no SA_RESTART) every N ms during the replay,
//                            as libFuzzer's own timer sends: every system call it lands in fails
//                            with EINTR, which the code under test must repeat or report
//   --rounds R               replay everything R times

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <sys/time.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);

namespace {
void run_file(const std::filesystem::path &file) {
  std::ifstream in(file, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size());
}

volatile std::sig_atomic_t interruptions = 0;
void count_interruption(int) { interruptions = interruptions + 1; }

void interrupt_every(long ms) {
  struct sigaction action {};
  action.sa_handler = count_interruption;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0; // no SA_RESTART: interrupted calls fail with EINTR
  sigaction(SIGALRM, &action, nullptr);
  itimerval timer{};
  timer.it_interval.tv_sec = ms / 1000;
  timer.it_interval.tv_usec = (ms % 1000) * 1000;
  timer.it_value = timer.it_interval;
  setitimer(ITIMER_REAL, &timer, nullptr);
}
} // namespace

int main(int argc, char **argv) {
  long inputs = 0, rounds = 1;
  std::vector<const char *> paths;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--interrupt-every-ms") == 0 && i + 1 < argc)
      interrupt_every(std::atol(argv[++i]));
    else if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc)
      rounds = std::atol(argv[++i]);
    else
      paths.push_back(argv[i]);
  }
  for (long round = 0; round < rounds; ++round)
    for (const char *argument : paths) {
      const std::filesystem::path path(argument);
      if (std::filesystem::is_directory(path)) {
        for (const auto &entry : std::filesystem::recursive_directory_iterator(path))
          if (entry.is_regular_file()) {
            run_file(entry.path());
            ++inputs;
          }
      } else if (std::filesystem::is_regular_file(path)) {
        run_file(path);
        ++inputs;
      } else if (path.parent_path().filename() != "crashers") { // no crasher of this target yet: fine
        std::fprintf(stderr, "no such file or folder: %s\n", argument);
        return 2;
      }
    }
  std::printf("%ld inputs replayed without a crash", inputs);
  if (interruptions > 0)
    std::printf(", under %ld timer interruptions", static_cast<long>(interruptions));
  std::printf("\n");
  return inputs > 0 ? 0 : 1;
}
