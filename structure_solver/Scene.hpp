#pragma once
// A structure-only scene: the flexible structures of a case, the rigid surfaces they collide
// with, and one time step of the algorithm of section 2.3 without fluid:
// solve Eq. (4) for every structure, then correct positions for contact between structures
// and for collisions (Eq. 11).

#include "StructureModel.hpp"
#include "StructureSetup.hpp"
#include "structure_solver/collision/CollisionSet.hpp"
#include "structure_solver/collision/CorrectionSpread.hpp"
#include "structure_solver/collision/SelfCollision.hpp"
#include "structure_solver/collision/StructureContact.hpp"
#include "motion/CoupledMotion.hpp"

#include <memory>
#include <vector>

namespace fsi::structure {

class Scene {
public:
  explicit Scene(const StructureSetup &setup);

  /// One step for every structure (no fluid load): Eq. (4), then Eq. (11).
  void advance();
  /// One step under load densities, one N_i x 3 array per structure (e.g. -F_fsi, Eq. 3).
  void advance(const std::vector<PointArray> &load_densities);

  double time_s() const { return structures_.front()->time_s(); }
  const std::vector<std::unique_ptr<StructureModel>> &structures() const { return structures_; }
  bool has_collisions() const { return collisions_ != nullptr; }
  /// Points corrected by collisions in the last step (all structures).
  std::size_t last_corrections() const { return last_corrections_; }
  /// Linear-solver (CG) iterations of the last step, summed over structures (0: direct).
  int last_solver_iterations() const { return last_iterations_; }
  /// In a coupled run, the moving rigid surface named `name` (surface<i>, i its index in
  /// collisions.surfaces), whose pose the coupler sends; nullptr for another name.
  motion::CoupledMotion *coupled_motion(const std::string &name) const;
  std::size_t n_coupled_motions() const { return coupled_motions_.size(); }

private:
  void build_collisions(const CollisionConfig &config, double gravity_m_per_s2, bool motions_from_coupler);
  void correct_collisions(StructureModel &structure, std::size_t index);
  void correct_contacts();

  std::vector<std::unique_ptr<StructureModel>> structures_;
  std::unique_ptr<collision::CollisionSet> collisions_;
  std::vector<std::unique_ptr<collision::SelfCollision>> self_collisions_;
  std::unique_ptr<collision::StructureContact> contact_; ///< nullptr: structures pass through each other
  std::vector<PointArray> contact_start_, contact_now_;  ///< X^n and X^{n+1} of every structure
  /// Per structure, the spreading of the wall corrections over its grid (nullptr: none).
  std::vector<std::unique_ptr<collision::CorrectionSpread>> spreads_;
  PointArray before_correction_; ///< scratch of the spreading
  std::vector<PointArray> zero_loads_;
  std::vector<std::shared_ptr<motion::CoupledMotion>> coupled_motions_;
  std::size_t last_corrections_ = 0;
  int last_iterations_ = 0;
};

} // namespace fsi::structure
