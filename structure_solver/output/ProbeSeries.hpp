#pragma once
// The group `/probes/<name>` of the results file: the position (m) and velocity (m/s) of one
// probe, one [3] row per saved step, aligned with /time_s.

#include "hdf5/ExtendableDataset.hpp"
#include "hdf5/H5Handle.hpp"
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
  hdf5::ExtendableDataset vector_series(const char *dataset, const char *units) const;

  std::string name_;
  hdf5::H5Handle group_;
  hdf5::ExtendableDataset position_m_;
  hdf5::ExtendableDataset velocity_m_per_s_;
};

} // namespace fsi::structure::output
