#include "structure_solver/output/StructureTopology.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace fsi::structure::output {
namespace {

bool is_valid_name(const std::string &name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) != 0 || c == '_' || c == '-' || c == '.';
  });
}

void fail(const StructureLayout &layout, const std::string &reason) {
  throw std::invalid_argument("structure '" + layout.name + "' (" + layout.model + ", grid " +
                              std::to_string(layout.n1) + " x " + std::to_string(layout.n2) +
                              "): " + reason);
}

std::vector<std::int64_t> quad_cells(std::int64_t n1, std::int64_t n2) {
  std::vector<std::int64_t> cells;
  cells.reserve(static_cast<std::size_t>(4 * (n1 - 1) * (n2 - 1)));
  for (std::int64_t i1 = 0; i1 + 1 < n1; ++i1) {
    for (std::int64_t i2 = 0; i2 + 1 < n2; ++i2) {
      const std::int64_t corner = i1 * n2 + i2;
      cells.insert(cells.end(), {corner, corner + n2, corner + n2 + 1, corner + 1});
    }
  }
  return cells;
}

std::vector<std::int64_t> segment_cells(std::int64_t n_points) {
  std::vector<std::int64_t> cells;
  cells.reserve(static_cast<std::size_t>(2 * (n_points - 1)));
  for (std::int64_t i = 0; i + 1 < n_points; ++i) {
    cells.insert(cells.end(), {i, i + 1});
  }
  return cells;
}

} // namespace

void check_layout(const StructureLayout &layout) {
  if (!is_valid_name(layout.name)) {
    fail(layout, "the name must be non-empty and use only letters, digits, '_', '-' or '.'");
  }
  if (layout.model != "membrane" && layout.model != "filament") {
    fail(layout, "unknown model; valid models are: membrane, filament");
  }
  if (layout.n1 < 2 || layout.n2 < 1) {
    fail(layout, "the grid needs n1 >= 2 and n2 >= 1 points");
  }
  if (layout.model == "filament" && layout.n2 != 1) {
    fail(layout, "a filament has n2 == 1");
  }
}

Connectivity connectivity_of(const StructureLayout &layout) {
  check_layout(layout);
  if (layout.n2 > 1) {
    return {quad_cells(layout.n1, layout.n2), 4};
  }
  return {segment_cells(layout.n1), 2};
}

std::string xdmf_topology_type(const Connectivity &connectivity) {
  return connectivity.nodes_per_cell == 4 ? "Quadrilateral" : "Polyline";
}

} // namespace fsi::structure::output
