#pragma once
// A structure-only scene: the flexible structures of a case, the rigid surfaces they collide
// with, and one time step of the algorithm of section 2.3 without fluid:
// solve Eq. (4) for every structure in the scene, then correct positions for contact between
// structures and for collisions (Eq. 11). Which structures are in the scene is their LifeCycle:
// a structure released later waits, one removed past its plane is gone.

#include "StructureModel.hpp"
#include "StructureSetup.hpp"
#include "structure_solver/collision/CollisionSet.hpp"
#include "structure_solver/collision/CorrectionSpread.hpp"
#include "structure_solver/collision/SelfCollision.hpp"
#include "structure_solver/collision/StructureContact.hpp"
#include "motion/CoupledMotion.hpp"
#include "participant/LifeCycle.hpp"

#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace fsi::structure {

using participant::Life;
using participant::LifeCycle;

/// The life of each structure as its configuration declares it.
std::vector<participant::LifeSpec> life_specs(const std::vector<StructureConfig> &structures);

class Scene {
public:
  explicit Scene(const StructureSetup &setup);

  /// One step for every structure in the scene (no fluid load): the releases due at the step's
  /// start, Eq. (4), then Eq. (11).
  void advance();
  /// One step under load densities, one N_i x 3 array per structure (e.g. -F_fsi, Eq. 3; the
  /// rows of structures not in the scene are not read).
  void advance(const std::vector<PointArray> &load_densities);
  /// After a step is accepted: the structures in the scene past their removal plane are gone
  /// (their solvers' memory freed). Returns them.
  std::vector<std::size_t> remove_past_planes();
  /// At an accepted step: the structures in the scene stretched beyond their
  /// tear_above_stretch_ratio, torn off (gone, their solvers freed), as the coupler does from
  /// max_stretch_ratios() (LifeCycle::tear_overstretched).
  std::vector<std::size_t> tear_overstretched();
  /// Per structure, its largest stretch ratio when it can tear and has been released (in the
  /// scene or gone); 1 otherwise (what the structure sends the coupler in
  /// AdvanceReply.max_stretch_ratio).
  std::vector<double> max_stretch_ratios() const;

  double time_s() const { return time_s_; }
  const LifeCycle &life() const { return life_; }
  /// The pairs released onto each other that have not parted yet (the smaller index first).
  const std::set<std::pair<std::size_t, std::size_t>> &overlapping() const { return overlapping_; }
  /// The scene's whole state (time, every structure's state, the life cycle), bit for bit: a
  /// checkpoint, or the start of a step an implicit coupling repeats.
  void save_state(checkpoint::StateArchive &archive) const;
  /// Takes what save_state() wrote; throws checkpoint::CheckpointError naming a missing entry.
  void load_state(const checkpoint::StateArchive &archive);
  /// Puts every structure back to (x, v) and the scene's clock to time_s (the last good state
  /// after a divergence); the life cycle stays.
  void restore_states(const std::vector<PointArray> &x_m, const std::vector<PointArray> &v_m_per_s, double time_s);
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
  /// A structure released onto one in the scene (within d_c of it) passes through it until they
  /// part: contact would otherwise push them d_t apart in one step, a jump no sheet survives.
  void note_overlaps(std::size_t released);
  void forget_parted_overlaps();
  std::vector<std::string> names() const;

  std::vector<std::unique_ptr<StructureModel>> structures_;
  LifeCycle life_;
  double time_s_ = 0.0;
  double time_step_s_;
  std::unique_ptr<collision::CollisionSet> collisions_;
  std::vector<std::unique_ptr<collision::SelfCollision>> self_collisions_;
  std::unique_ptr<collision::StructureContact> contact_; ///< nullptr: structures pass through each other
  std::vector<PointArray> contact_start_, contact_now_;  ///< X^n and X^{n+1} of every structure
  std::set<std::pair<std::size_t, std::size_t>> overlapping_; ///< released onto each other, not yet parted
  /// Per structure, the spreading of the wall corrections over its grid (nullptr: none).
  std::vector<std::unique_ptr<collision::CorrectionSpread>> spreads_;
  PointArray before_correction_; ///< scratch of the spreading
  std::vector<PointArray> zero_loads_;
  std::vector<std::shared_ptr<motion::CoupledMotion>> coupled_motions_;
  std::size_t last_corrections_ = 0;
  int last_iterations_ = 0;
};

} // namespace fsi::structure
