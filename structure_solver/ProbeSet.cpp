#include "ProbeSet.hpp"

#include <numeric>
#include <stdexcept>

namespace fsi::structure {
namespace {

/// Points of one edge (a sheet, index = i1 * n2 + i2) or one end (a filament), in order.
std::vector<int> edge_points(const std::string &edge, int n1, int n2) {
  std::vector<int> points;
  if (n2 == 1 && (edge == "start" || edge == "end"))
    return {edge == "start" ? 0 : n1 - 1};
  if (edge == "s1_min" || edge == "s1_max") {
    const int i1 = edge == "s1_min" ? 0 : n1 - 1;
    for (int i2 = 0; i2 < n2; ++i2)
      points.push_back(i1 * n2 + i2);
  } else if (edge == "s2_min" || edge == "s2_max") {
    const int i2 = edge == "s2_min" ? 0 : n2 - 1;
    for (int i1 = 0; i1 < n1; ++i1)
      points.push_back(i1 * n2 + i2);
  }
  if (points.empty() || n2 == 1)
    throw std::invalid_argument("no edge '" + edge + "' on a grid of " + std::to_string(n1) + " x " +
                                std::to_string(n2) + " points");
  return points;
}

int grid_point(const std::vector<int> &index, int n1, int n2) {
  const bool valid = index.size() == (n2 == 1 ? 1u : 2u) && index[0] >= 0 && index[0] < n1 &&
                     (n2 == 1 || (index[1] >= 0 && index[1] < n2));
  if (!valid)
    throw std::invalid_argument("probe index outside the grid of " + std::to_string(n1) + " x " +
                                std::to_string(n2) + " points");
  return n2 == 1 ? index[0] : index[0] * n2 + index[1];
}

} // namespace

ProbeSet::ProbeSet(const std::vector<ProbeConfig> &configs, const std::vector<ProbedStructure> &structures) {
  for (const ProbeConfig &config : configs) {
    std::size_t found = 0;
    while (found < structures.size() && structures[found].name != config.structure)
      ++found;
    if (found == structures.size())
      throw std::invalid_argument("probe '" + config.name + "': no structure '" + config.structure + "'");
    probes_.push_back(make_probe(config, found, structures[found]));
  }
}

ProbeSet ProbeSet::for_structures(const std::vector<ProbeConfig> &configs,
                                  const std::vector<std::unique_ptr<StructureModel>> &structures) {
  std::vector<ProbedStructure> probed;
  for (const auto &s : structures)
    probed.push_back({s->name(), s->grid_shape().first, s->grid_shape().second, s->point_measures()});
  return ProbeSet(configs, probed);
}

Probe ProbeSet::make_probe(const ProbeConfig &config, std::size_t structure_index, const ProbedStructure &structure) {
  const int n1 = structure.n1, n2 = structure.n2;
  switch (config.at) {
  case ProbeLocation::centroid: {
    std::vector<int> all(static_cast<std::size_t>(n1 * n2));
    std::iota(all.begin(), all.end(), 0);
    return Probe::weighted(config.name, structure_index, std::move(all), structure.point_measures);
  }
  case ProbeLocation::edge_centre:
    return Probe::along_curve(config.name, structure_index, edge_points(config.edge, n1, n2));
  case ProbeLocation::point:
    return Probe::weighted(config.name, structure_index, {grid_point(config.index, n1, n2)},
                           Eigen::VectorXd::Ones(1));
  }
  throw std::invalid_argument("probe '" + config.name + "': unknown location");
}

std::vector<std::string> ProbeSet::names() const {
  std::vector<std::string> names;
  for (const Probe &probe : probes_)
    names.push_back(probe.name());
  return names;
}

std::vector<ProbeSample> ProbeSet::sample(const std::vector<const PointArray *> &positions_m,
                                          const std::vector<const PointArray *> &velocities_m_per_s) const {
  std::vector<ProbeSample> samples;
  samples.reserve(probes_.size());
  for (const Probe &probe : probes_) {
    const std::size_t s = probe.structure_index();
    samples.push_back(probe.sample(*positions_m.at(s), *velocities_m_per_s.at(s)));
  }
  return samples;
}

std::vector<ProbeSample> ProbeSet::sample(const std::vector<std::unique_ptr<StructureModel>> &structures) const {
  std::vector<const PointArray *> x, v;
  for (const auto &s : structures) {
    x.push_back(&s->positions_m());
    v.push_back(&s->velocities_m_per_s());
  }
  return sample(x, v);
}

} // namespace fsi::structure
