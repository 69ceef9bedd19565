#pragma once
// A minimal static-partition parallel loop on std::thread (TBB is not a dependency of this
// project): [0, n) is cut into one contiguous chunk per thread. Worth it only for loops of
// tens of thousands of cheap iterations; below min_per_thread everything runs on the caller.

#include <cstddef>
#include <functional>

namespace fsi::fluid::rigid {

/// Calls body(begin, end) on disjoint chunks covering [0, n), on up to n_threads threads
/// (0: the hardware concurrency). Exceptions from a chunk are rethrown on the caller.
void parallel_for(std::size_t n, std::size_t n_threads,
                  const std::function<void(std::size_t begin, std::size_t end)> &body,
                  std::size_t min_per_thread = 4096);

} // namespace fsi::fluid::rigid
