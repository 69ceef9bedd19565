// common::keep_freed_memory: a block of a few megabytes allocated, written and freed every time
// step must come back from the heap, not from the kernel (page faults), as the solvers'
// per-step fields and frames do.

#include "common/Allocator.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

/// Minor page faults of `steps` time steps that each allocate and write `blocks` blocks of
/// `bytes`, then free them all (a solver's temporary fields): glibc's defaults trim the freed
/// heap top once it exceeds twice the largest block, and the next step faults it in again.
long faults_of_steps(int blocks, std::size_t bytes, int steps) {
  const long before = minor_faults();
  std::vector<char *> held(static_cast<std::size_t>(blocks));
  for (int s = 0; s < steps; ++s) {
    for (auto &block : held) {
      block = static_cast<char *>(std::malloc(bytes));
      if (block == nullptr)
        return -1;
      std::memset(block, s + 1, bytes);
    }
    volatile char sink = held.back()[bytes / 2];
    (void)sink;
    for (auto *block : held)
      std::free(block);
  }
  return minor_faults() - before;
}

TEST(Allocator, FreedBlocksOfMegabytesAreReusedWithoutPageFaults) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer has its own allocator, which glibc's settings do not reach";
#endif
  fsi::common::keep_freed_memory();
  constexpr int blocks = 8;
  constexpr std::size_t bytes = 4u << 20; // 8 x 1024 pages of 4 KiB a step
  const long first = faults_of_steps(blocks, bytes, 1); // fresh memory: every page faults once
  const long next = faults_of_steps(blocks, bytes, 20);
  std::printf("page faults: first step %ld, next 20 steps %ld\n", first, next);
  ASSERT_GT(first, 4000); // the measurement sees the faults of fresh memory
  EXPECT_LT(next, first / 10);
}

} // namespace
