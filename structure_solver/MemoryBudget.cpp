#include "MemoryBudget.hpp"

#include "common/ConfigError.hpp"

#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

namespace fsi::structure {

namespace {

std::uint64_t points_of(const StructureConfig &structure) {
  const auto [n1, n2] = structure.parameters->grid_shape();
  return static_cast<std::uint64_t>(n1) * static_cast<std::uint64_t>(n2);
}

std::string bytes_text(std::uint64_t bytes) {
  std::ostringstream out;
  const double gib = static_cast<double>(bytes) / (1ull << 30);
  if (gib >= 1024.0)
    out << std::setprecision(3) << gib / 1024.0 << " TiB";
  else if (gib >= 1.0)
    out << std::setprecision(3) << gib << " GiB";
  else
    out << std::setprecision(3) << static_cast<double>(bytes) / (1ull << 20) << " MiB";
  return out.str();
}

} // namespace

std::uint64_t MemoryBudget::estimate_bytes(const std::vector<StructureConfig> &structures) {
  std::uint64_t points = 0;
  for (const auto &s : structures)
    points += points_of(s);
  return base_bytes + bytes_per_point * points;
}

std::uint64_t MemoryBudget::available_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:")
      return kib * 1024;
  return 0;
}

void MemoryBudget::check_fits(const std::vector<StructureConfig> &structures, std::uint64_t available) {
  const std::uint64_t needed = estimate_bytes(structures);
  if (available == 0 || needed <= available)
    return;
  std::size_t largest = 0;
  for (std::size_t i = 1; i < structures.size(); ++i)
    if (points_of(structures[i]) > points_of(structures[largest]))
      largest = i;
  const auto [n1, n2] = structures[largest].parameters->grid_shape();
  throw common::ConfigError(
      "structures[" + std::to_string(largest) + "] '" + structures[largest].name + "': its grid of " +
      std::to_string(n1) + " x " + std::to_string(n2) + " points (" +
      std::to_string((needed - base_bytes) / bytes_per_point) + " points in all) needs about " + bytes_text(needed) +
      " of memory (" + std::to_string(bytes_per_point / 1024) + " KiB a point), and this machine has " +
      bytes_text(available) + " available; use fewer points (a coarser n_points) or a machine with more memory.");
}

} // namespace fsi::structure
