#include "ProbeConfig.hpp"

#include "StructureConfig.hpp"
#include "common/DidYouMean.hpp"

#include <algorithm>
#include <cctype>

namespace fsi::structure {
namespace {

const char *location_name(ProbeLocation at) {
  switch (at) {
  case ProbeLocation::centroid:
    return "centroid";
  case ProbeLocation::edge_centre:
    return "edge_centre";
  case ProbeLocation::point:
    return "point";
  }
  return "?";
}

bool is_valid_name(const std::string &name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
}

std::string format_index(const std::vector<int> &index) {
  std::string text;
  for (const int i : index)
    text += (text.empty() ? "" : ", ") + std::to_string(i);
  return "[" + text + "]";
}

} // namespace

std::vector<std::string> ProbeConfig::edge_names(int n2) {
  if (n2 == 1)
    return {"start", "end"};
  return {"s1_min", "s1_max", "s2_min", "s2_max"};
}

void ProbeConfig::validate(const common::ConfigReader &v) const {
  if (at != ProbeLocation::edge_centre && v.has("edge"))
    v.fail_value("edge", std::string("is only read with `at: edge_centre`; this probe has `at: ") +
                             location_name(at) + "`.");
  if (at != ProbeLocation::point && v.has("index"))
    v.fail_value("index", std::string("is only read with `at: point`; this probe has `at: ") + location_name(at) +
                              "`.");
  v.finish(); // a misspelt key first: it explains a missing one
  if (!is_valid_name(name))
    v.fail_value("name", (name.empty() ? std::string("is missing") : "= '" + name + "' is not allowed") +
                             ": a probe needs a name of letters, digits, '_' and '-' (it names an HDF5 group "
                             "and CSV columns).");
  if (structure.empty())
    v.fail("needs `structure`: the name of the structure it follows.");
  if (at == ProbeLocation::edge_centre && edge.empty())
    v.fail("has `at: edge_centre` but no `edge` (s1_min, s1_max, s2_min, s2_max; a filament: start, end).");
  if (at == ProbeLocation::point && index.empty())
    v.fail("has `at: point` but no `index` ([i1, i2]; a filament: [i]).");
}

void ProbeConfig::check_against(const std::vector<StructureConfig> &structures, const common::ConfigReader &v) const {
  std::vector<std::string> names;
  for (const auto &s : structures)
    names.push_back(s.name);
  const auto found = std::find(names.begin(), names.end(), structure);
  if (found == names.end())
    v.fail_value("structure", "= '" + structure + "' is not a structure of this case." +
                                  common::did_you_mean(structure, names) + " Structures: " + common::join(names) +
                                  ".");
  const StructureConfig &target = structures[static_cast<std::size_t>(found - names.begin())];
  if (!target.parameters)
    return; // an invalid model was reported already
  const auto [n1, n2] = target.parameters->grid_shape();
  if (at == ProbeLocation::edge_centre)
    check_edge(n2, target.model + " '" + target.name + "'", v);
  if (at == ProbeLocation::point)
    check_index(n1, n2, v);
}

void ProbeConfig::check_edge(int n2, const std::string &structure_kind, const common::ConfigReader &v) const {
  const std::vector<std::string> valid = edge_names(n2);
  if (std::find(valid.begin(), valid.end(), edge) == valid.end())
    v.fail_value("edge", "= '" + edge + "' is not an edge of " + structure_kind + "." +
                             common::did_you_mean(edge, valid) + " Allowed: " + common::join(valid) + ".");
}

void ProbeConfig::check_index(int n1, int n2, const common::ConfigReader &v) const {
  const bool filament = n2 == 1;
  const std::string grid = filament ? "[" + std::to_string(n1) + "] points" : "[" + std::to_string(n1) + ", " +
                                                                                std::to_string(n2) + "] points";
  if (index.size() != (filament ? 1u : 2u))
    v.fail_value("index", "= " + format_index(index) + " must hold " +
                              (filament ? "one index [i] (a filament)" : "two indices [i1, i2] (a membrane)") + ".");
  const bool inside = index[0] < n1 && (filament || index[1] < n2);
  if (!inside)
    v.fail_value("index", "= " + format_index(index) + " is outside the grid of '" + structure + "' (" + grid +
                              "): indices run from 0 to n - 1.");
}

} // namespace fsi::structure
