#pragma once
// Boundary conditions of a sheet's edges (or a filament's ends), as listed under Eq. (3):
//  - free:    d2X/ds_n^2 = 0, d3X/ds_n^3 = 0, sigma = gamma = 0 (natural conditions of the energy)
//  - pinned:  X prescribed, d2X/ds_n^2 = 0 (the paper's "fixed" condition)
//  - clamped: X prescribed, dX/ds_n prescribed (second-order ghost points)
// Prescribed values are the initial ones, moved by the structure's clamp motion if it has one.

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fsi::structure {

enum class EdgeCondition { free, pinned, clamped };

inline const std::vector<std::pair<std::string, EdgeCondition>> &edge_condition_names() {
  static const std::vector<std::pair<std::string, EdgeCondition>> names{
      {"free", EdgeCondition::free},
      {"pinned", EdgeCondition::pinned},
      {"clamped", EdgeCondition::clamped},
      {"fixed", EdgeCondition::pinned}}; // the paper's name for pinned
  return names;
}

/// Conditions on the four edges: s1 = 0, s1 = L1, s2 = 0, s2 = L2. A filament uses the first two.
struct EdgeConditions {
  EdgeCondition s1_min = EdgeCondition::free;
  EdgeCondition s1_max = EdgeCondition::free;
  EdgeCondition s2_min = EdgeCondition::free;
  EdgeCondition s2_max = EdgeCondition::free;

  bool any_prescribed() const {
    for (auto c : {s1_min, s1_max, s2_min, s2_max})
      if (c != EdgeCondition::free)
        return true;
    return false;
  }
};

} // namespace fsi::structure
