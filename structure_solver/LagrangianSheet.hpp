#pragma once
// The discrete sheet/filament shared by the membrane and filament models: a LagrangianGrid,
// its ElasticTerms, the semi-implicit step of Eq. (4), prescribed (pinned/clamped) points
// that follow an optional rigid clamp motion, and the state (X^n, X^{n-1}, V^n).

#include "ElasticTerms.hpp"
#include "StepSettings.hpp"
#include "StepSystem.hpp"
#include "StructureModel.hpp"
#include "motion/RigidMotion.hpp"

#include <cmath>
#include <memory>

namespace fsi::structure {

struct SheetSetup {
  SheetSetup(std::string name_, std::string model_, LagrangianGrid grid_, PointArray shape_body)
      : name(std::move(name_)), model(std::move(model_)), grid(grid_), shape_body_m(std::move(shape_body)) {}

  std::string name;
  std::string model;
  LagrangianGrid grid;
  PointArray shape_body_m;              ///< initial shape; world = clamp pose(0) * body
  Vec3 initial_velocity_m_per_s = Vec3::Zero();
  EdgeConditions edges;
  std::shared_ptr<const motion::RigidMotion> clamp_motion; ///< null: prescribed points stay put
  double mass_per_measure = 0.0;        ///< rho_1 (kg/m^2) or linear density (kg/m)
  double tension_coefficient = 0.0;     ///< phi (N/m or N)
  double bending_rigidity = 0.0;        ///< zeta (N m or N m^2)
  double damping_per_measure = 0.0;     ///< lambda (kg/(m^2 s) or kg/(m s))
  bool curved_rest_state = false;
  CompressionResponse compression = CompressionResponse::elastic;
  Vec3 gravity_m_per_s2 = Vec3::Zero();
  double time_step_s = 1e-4;
  LinearSolver linear_solver = LinearSolver::automatic;
  TimeScheme time_scheme = TimeScheme::paper;
  std::string tension_scheme = "frozen"; ///< a TensionSchemeRegistry name
  double max_stretch_ratio = 1.5;
  double max_speed_m_per_s = 1000.0;
};

class LagrangianSheet final : public StructureModel {
public:
  explicit LagrangianSheet(SheetSetup setup);

  const std::string &name() const override { return setup_.name; }
  std::string model() const override { return setup_.model; }
  std::pair<int, int> grid_shape() const override { return {setup_.grid.n1(), setup_.grid.n2()}; }
  double time_s() const override { return time_s_; }
  const PointArray &positions_m() const override { return x_; }
  const PointArray &velocities_m_per_s() const override { return v_; }
  const Eigen::VectorXd &point_measures() const override { return measure_; }
  double lagrangian_spacing_m() const override { return setup_.grid.min_spacing_m(); }
  double mass_per_measure() const override { return setup_.mass_per_measure; }
  double tension_wave_speed_m_per_s() const override {
    return std::sqrt(2.0 * setup_.tension_coefficient / setup_.mass_per_measure);
  }
  bool explicit_stretching() const override { return explicit_stretching_; }

  int advance(const PointArray &load_density) override;
  void retire() override { system_.reset(); }
  bool retired() const override { return !system_; }
  void correct_positions(const std::function<void(PointArray &)> &correction) override;

  void restore_state(const PointArray &x_m, const PointArray &v_m_per_s, double time_s) override;
  void save_state(checkpoint::StateArchive &archive, const std::string &prefix) const override;
  void load_state(const checkpoint::StateArchive &archive, const std::string &prefix) override;
  StructureEnergy energy() const override;
  double max_stretch_ratio() const override { return terms_->max_stretch_ratio(x_); }
  double stretch_limit() const override { return setup_.max_stretch_ratio; }
  double speed_limit_m_per_s() const override { return setup_.max_speed_m_per_s; }
  int worst_point() const override;
  std::string describe_point(int index) const override;

  /// Replaces the state (tests: mode shapes as initial conditions). Velocity from the pair.
  void set_state(const PointArray &x_now, const PointArray &x_prev);
  const ElasticTerms &elastic_terms() const { return *terms_; }
  bool is_prescribed(int point) const { return prescribed_[static_cast<std::size_t>(point)]; }

private:
  std::vector<bool> prescribed_points() const;
  PointArray prescribed_positions(double time_s) const;
  Eigen::Matrix3d clamp_rotation(double time_s) const;
  void restore_prescribed(double time_s);

  SheetSetup setup_;
  Eigen::VectorXd measure_;
  std::vector<bool> prescribed_;
  bool has_prescribed_;
  std::unique_ptr<ElasticTerms> terms_;
  std::unique_ptr<StepSystem> system_; ///< nullptr once retired
  bool explicit_stretching_ = true;
  PointArray x_, x_prev_, v_, load_;
  double time_s_ = 0.0;
};

} // namespace fsi::structure
