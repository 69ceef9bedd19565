#pragma once
// Configuration of the `membrane` model: a rectangular sheet (2D in 3D), Eq. (3) with both
// material coordinates. Units: rho_1 in kg/m^2, phi in N/m, zeta in N m.

#include "BoundaryConditions.hpp"
#include "CompressionResponse.hpp"
#include "ModelConfig.hpp"

namespace fsi::structure {

struct SheetCoefficients {
  double tension_coefficient_n_per_m = 100.0;
  double bending_rigidity_n_m = 1e-4;
  template <class V> void visit(V &v) {
    v.number("tension_coefficient_n_per_m", tension_coefficient_n_per_m, common::Range::positive("N/m"),
             "phi: sigma_ij = phi (T_ij - T0_ij) (stretching and shearing).");
    v.number("bending_rigidity_n_m", bending_rigidity_n_m, common::Range::non_negative("N m"),
             "zeta: constant bending rigidity (Kirchhoff plate D = zeta).");
  }
};

/// First-principles route of section 3.1: phi = E t, zeta = E t^3 / (12 (1 - nu^2)).
struct SheetElasticModuli {
  double youngs_modulus_pa = 1e6;
  double thickness_m = 1e-4;
  double poisson_ratio = 0.3;
  template <class V> void visit(V &v) {
    v.number("youngs_modulus_pa", youngs_modulus_pa, common::Range::positive("Pa"), "Young's modulus E.");
    v.number("thickness_m", thickness_m, common::Range::positive("m"), "Sheet thickness t.");
    v.number("poisson_ratio", poisson_ratio, common::Range{.min = -1.0, .max = 0.5, .min_exclusive = true, .unit = "1"},
             "Poisson's ratio nu.");
  }
};

struct SheetMaterial {
  double mass_per_area_kg_per_m2 = 0.08;
  double damping_kg_per_m2_s = 0.0;
  CompressionResponse compression = CompressionResponse::elastic;
  std::optional<SheetCoefficients> coefficients;
  std::optional<SheetElasticModuli> elastic_moduli;

  template <class V> void visit(V &v) {
    v.number("mass_per_area_kg_per_m2", mass_per_area_kg_per_m2, common::Range::positive("kg/m^2"),
             "rho_1 = rho_s - rho_f c: sheet mass per area minus displaced fluid.");
    v.number("damping_kg_per_m2_s", damping_kg_per_m2_s, common::Range::non_negative("kg/(m^2 s)"),
             "lambda: structural damping of Eq. (4).");
    v.choice("compression", compression, compression_response_names(),
             "Stretching tension in compression: 'elastic' pushes back (the paper), 'slack' carries none "
             "(cloth wrinkles instead; keeps stiff rags stable when the flow crumples them).");
    v.optional_section("coefficients", coefficients, "Give phi and zeta directly (default when neither is given).");
    v.optional_section("elastic_moduli", elastic_moduli, "Or derive phi and zeta from E, thickness and nu.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (coefficients && elastic_moduli)
        v.fail("gives both 'coefficients' and 'elastic_moduli'; keep one.");
  }
  double tension_coefficient() const;
  double bending_rigidity() const;
};

struct SheetEdges {
  EdgeConditions conditions;
  template <class V> void visit(V &v) {
    const auto &names = edge_condition_names();
    v.choice("s1_min", conditions.s1_min, names, "Edge s1 = 0.");
    v.choice("s1_max", conditions.s1_max, names, "Edge s1 = L1.");
    v.choice("s2_min", conditions.s2_min, names, "Edge s2 = 0.");
    v.choice("s2_max", conditions.s2_max, names, "Edge s2 = L2.");
  }
};

class MembraneConfig final : public ModelConfigBase<MembraneConfig>, public SharedSheetKeys {
public:
  Eigen::Vector2d size_m{0.1, 0.1};
  Eigen::Vector2i n_points{26, 26};
  Vec3 origin_m{0.0, 0.0, 0.0};
  Vec3 s1_direction{1.0, 0.0, 0.0};
  Vec3 s2_direction{0.0, 1.0, 0.0};
  SheetMaterial material;
  SheetEdges edges;

  template <class V> void visit_keys(V &v) {
    v.vec2("size_m", size_m, common::Range::positive("m"), "Sheet lengths [L1, L2] along s1 and s2.");
    v.int2("n_points", n_points, common::Range::at_least(3, "1"), "Lagrangian points [n1, n2] (spacing L/(n-1)).");
    v.vec3("origin_m", origin_m, "m", "Position of the corner s1 = s2 = 0.");
    v.vec3("s1_direction", s1_direction, "1", "Direction of s1 in space.");
    v.vec3("s2_direction", s2_direction, "1", "Direction of s2 (made orthogonal to s1).");
    v.section("material", material, "Mass, stiffness and damping.");
    v.section("edges", edges, "Boundary condition of each edge: free, pinned or clamped.");
    visit_shared(v);
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      validate(v);
  }

  std::pair<int, int> grid_shape() const override { return {n_points[0], n_points[1]}; }

private:
  void validate(common::ConfigReader &v) const;
};

} // namespace fsi::structure
