#pragma once
// Configuration of the `filament` model: a 1D filament in 3D, Eq. (3) with one material
// coordinate. Units: linear density kg/m, tension coefficient N, bending rigidity N m^2
// (Euler-Bernoulli EI). Stiff tension makes it nearly inextensible.

#include "BoundaryConditions.hpp"
#include "Frame.hpp"
#include "ModelConfig.hpp"

namespace fsi::structure {

struct FilamentEnds {
  EdgeCondition start = EdgeCondition::pinned;
  EdgeCondition end = EdgeCondition::free;
  template <class V> void visit(V &v) {
    const auto &names = edge_condition_names();
    v.choice("start", start, names, "Condition at s = 0.");
    v.choice("end", end, names, "Condition at s = L.");
  }
};

class FilamentConfig final : public ModelConfigBase<FilamentConfig>, public SharedSheetKeys {
public:
  double length_m = 1.0;
  int n_points = 41;
  Vec3 origin_m{0.0, 0.0, 0.0};
  Vec3 direction{0.0, 0.0, -1.0};
  Vec3 bend_direction{1.0, 0.0, 0.0};
  double linear_density_kg_per_m = 0.1;
  double tension_coefficient_n = 1e3;
  double bending_rigidity_n_m2 = 1e-6;
  double damping_kg_per_m_s = 0.0;
  FilamentEnds ends;

  template <class V> void visit_keys(V &v) {
    v.number("length_m", length_m, common::Range::positive("m"), "Filament length L.");
    v.integer("n_points", n_points, common::Range::at_least(3, "1"), "Lagrangian points (spacing L/(n-1)).");
    v.vec3("origin_m", origin_m, "m", "Position of s = 0.");
    v.vec3("direction", direction, "1", "Direction of the filament (s axis).");
    v.vec3("bend_direction", bend_direction, "1",
           "Direction toward which a pre-curved filament bends (made orthogonal to 'direction').");
    v.number("linear_density_kg_per_m", linear_density_kg_per_m, common::Range::positive("kg/m"),
             "Mass per length (minus displaced fluid).");
    v.number("tension_coefficient_n", tension_coefficient_n, common::Range::positive("N"),
             "phi: sigma = phi (|X_s|^2 - 1); large values make the filament nearly inextensible.");
    v.number("bending_rigidity_n_m2", bending_rigidity_n_m2, common::Range::non_negative("N m^2"),
             "zeta: bending rigidity (Euler-Bernoulli EI).");
    v.number("damping_kg_per_m_s", damping_kg_per_m_s, common::Range::non_negative("kg/(m s)"),
             "lambda: structural damping of Eq. (4).");
    v.section("ends", ends, "Boundary condition of each end: free, pinned or clamped.");
    visit_shared(v);
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      validate(v);
  }

  std::pair<int, int> grid_shape() const override { return {n_points, 1}; }
  /// The frame the filament is laid out in: e1 along `direction`, the normal e1 x e2 toward
  /// bend_direction (any perpendicular for a straight filament). Throws std::invalid_argument
  /// when the directions are degenerate (refused when the case is read).
  Frame frame() const;

private:
  void validate(common::ConfigReader &v) const;
};

} // namespace fsi::structure
