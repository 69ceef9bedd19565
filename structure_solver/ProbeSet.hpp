#pragma once
// The probes of a case (the `probes` list), built once against the structures of the scene
// and sampled at every saved step. Physics only: the results writer stores the samples.

#include "Probe.hpp"
#include "ProbeConfig.hpp"
#include "StructureModel.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fsi::structure {

/// What the probes need of one structure: its name, grid shape (n2 == 1: a filament) and the
/// measure (area or length) each point carries.
struct ProbedStructure {
  std::string name;
  int n1 = 0;
  int n2 = 1;
  Eigen::VectorXd point_measures;
};

class ProbeSet {
public:
  /// `configs` were validated against the case (ProbeConfig::check_against); throws
  /// std::invalid_argument when one names a structure, edge or point that is not there.
  ProbeSet(const std::vector<ProbeConfig> &configs, const std::vector<ProbedStructure> &structures);
  /// The probes of `configs` on the structures of a scene.
  static ProbeSet for_structures(const std::vector<ProbeConfig> &configs,
                                 const std::vector<std::unique_ptr<StructureModel>> &structures);

  bool empty() const { return probes_.empty(); }
  std::size_t size() const { return probes_.size(); }
  /// Probe names, in the order of the case file (and of sample()).
  std::vector<std::string> names() const;

  /// One sample per probe; `positions_m` and `velocities_m_per_s` hold one array per structure,
  /// in the order given at construction.
  std::vector<ProbeSample> sample(const std::vector<const PointArray *> &positions_m,
                                  const std::vector<const PointArray *> &velocities_m_per_s) const;
  /// One sample per probe, from the current state of the scene's structures.
  std::vector<ProbeSample> sample(const std::vector<std::unique_ptr<StructureModel>> &structures) const;

private:
  static Probe make_probe(const ProbeConfig &config, std::size_t structure_index, const ProbedStructure &structure);

  std::vector<Probe> probes_;
};

} // namespace fsi::structure
