#include "common/Allocator.hpp"

#include <malloc.h>

namespace fsi::common {
namespace {

constexpr int mmap_threshold_bytes = 32 << 20; // glibc's largest on 64-bit; bigger blocks are mmapped
constexpr int trim_threshold_bytes = 256 << 20;

} // namespace

void keep_freed_memory() {
  mallopt(M_MMAP_THRESHOLD, mmap_threshold_bytes);
  mallopt(M_TRIM_THRESHOLD, trim_threshold_bytes);
}

const char *allocator_tunables() {
  return "glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=268435456";
}

} // namespace fsi::common
