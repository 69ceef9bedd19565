#include "common/Allocator.hpp"

#include <malloc.h>

namespace fsi::common {
namespace {

// The same values as ALLOCATOR_TUNABLES in python/fsi/fsi_launch.py.
constexpr int mmap_threshold_bytes = 32 << 20; // glibc's largest on 64-bit; bigger blocks are mmapped
constexpr int trim_threshold_bytes = 256 << 20;

} // namespace

void keep_freed_memory() {
  mallopt(M_MMAP_THRESHOLD, mmap_threshold_bytes);
  mallopt(M_TRIM_THRESHOLD, trim_threshold_bytes);
}

} // namespace fsi::common
