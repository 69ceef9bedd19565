#pragma once
// Who takes part in a coupled run, as admission found them: the routing ids of the fluid and
// the structure participant, the structures' topology the structure announced, and the
// measure (area or length, SI) of every Lagrangian point of all structures, concatenated.

#include "proto/Protocol.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace fsi::coupler {

struct Roster {
  std::string fluid_id, structure_id;
  std::vector<proto::v2::StructureTopology> topology;
  Eigen::VectorXd measures; ///< one per Lagrangian point, in the order of `topology`

  Eigen::Index n_points() const { return measures.size(); }
};

} // namespace fsi::coupler
