#pragma once
// What the structures of a case will take in memory, so that a grid that cannot fit is refused
// when the case is checked (exit 2, naming the memory it needs) instead of ending in
// std::bad_alloc after the output folder was made. The figure per point is measured
// (docs/security.md): the peak resident memory of fsi-structure for square sheets of 10^4 to
// 1.6 x 10^5 points grows by 2.7-3.0 KiB a point over a base of about 20 MiB; the estimate
// rounds both up.

#include "StructureConfig.hpp"

#include <cstdint>
#include <vector>

namespace fsi::structure {

class MemoryBudget {
public:
  static constexpr std::uint64_t bytes_per_point = 4 * 1024;
  static constexpr std::uint64_t base_bytes = 64ull << 20;

  /// The memory the structures need, by the measured figure above.
  static std::uint64_t estimate_bytes(const std::vector<StructureConfig> &structures);
  /// The memory this machine can give a new process now (MemAvailable of /proc/meminfo), or 0
  /// when unknown.
  static std::uint64_t available_bytes();
  /// Throws common::ConfigError naming the largest structure, the memory needed and the memory
  /// available, when the estimate exceeds available (unknown: no check).
  static void check_fits(const std::vector<StructureConfig> &structures, std::uint64_t available);
};

} // namespace fsi::structure
