#pragma once
// The group `/probes/<name>` of the results file: the position (m) and velocity (m/s) of one
// probe, one [3] row per saved step, aligned with /time_s.

#include "structure_solver/output/ExtendableDataset.hpp"
#include "structure_solver/output/H5Handle.hpp"
#include "structure_solver/output/ResultsRecords.hpp"

#include <string>

namespace fsi::structure::output {

class ProbeSeries {
public:
  /// Creates the group `name` under `probes_group_id` with two empty [0, 3] datasets.
  ProbeSeries(hid_t probes_group_id, const std::string &name);

  /// Appends one row to both datasets.
  void append(const ProbeState &state);

  const std::string &name() const { return name_; }

private:
  ExtendableDataset vector_series(const char *dataset, const char *units) const;

  std::string name_;
  H5Handle group_;
  ExtendableDataset position_m_;
  ExtendableDataset velocity_m_per_s_;
};

} // namespace fsi::structure::output
