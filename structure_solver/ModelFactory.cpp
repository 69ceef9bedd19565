#include "ModelFactory.hpp"

#include "FilamentConfig.hpp"
#include "InitialShape.hpp"
#include "LagrangianSheet.hpp"
#include "MembraneConfig.hpp"
#include "motion/MotionFactory.hpp"

namespace fsi::structure {

namespace {

/// Copies the shared settings (initial state, solver, clamp motion, gravity, time step).
void fill_shared_setup(SheetSetup &setup, const SharedSheetKeys &keys, const BuildContext &context) {
  const auto &[clamp_motion, initial, solver] = keys;
  setup.initial_velocity_m_per_s = initial.velocity_m_per_s;
  setup.curved_rest_state = initial.curved_rest_state;
  if (clamp_motion)
    setup.clamp_motion = motion::make_motion(*clamp_motion, context.gravity_m_per_s2.norm());
  setup.gravity_m_per_s2 = context.gravity_m_per_s2;
  setup.time_step_s = context.time_step_s;
  setup.linear_solver = solver.linear_solver;
  setup.time_scheme = solver.time_scheme;
  setup.tension_scheme = solver.tension;
  setup.max_stretch_ratio = solver.max_stretch_ratio;
  setup.max_speed_m_per_s = solver.max_speed_m_per_s;
}

std::unique_ptr<StructureModel> build_membrane(const MembraneConfig &c, const BuildContext &context) {
  LagrangianGrid grid(c.n_points[0], c.n_points[1], c.size_m[0], c.size_m[1]);
  const Frame frame = make_frame(c.s1_direction, c.s2_direction);
  SheetSetup setup{context.name, "membrane", grid, initial_shape(grid, c.origin_m, frame, c.initial.curvature_1_per_m)};
  fill_shared_setup(setup, c, context);
  setup.edges = c.edges.conditions;
  setup.mass_per_measure = c.material.mass_per_area_kg_per_m2;
  setup.tension_coefficient = c.material.tension_coefficient();
  setup.bending_rigidity = c.material.bending_rigidity();
  setup.damping_per_measure = c.material.damping_kg_per_m2_s;
  setup.compression = c.material.compression;
  return std::make_unique<LagrangianSheet>(std::move(setup));
}

std::unique_ptr<StructureModel> build_filament(const FilamentConfig &c, const BuildContext &context) {
  LagrangianGrid grid(c.n_points, 1, c.length_m, 0.0);
  SheetSetup setup{context.name, "filament", grid, initial_shape(grid, c.origin_m, c.frame(), c.initial.curvature_1_per_m)};
  fill_shared_setup(setup, c, context);
  setup.edges.s1_min = c.ends.start;
  setup.edges.s1_max = c.ends.end;
  setup.mass_per_measure = c.linear_density_kg_per_m;
  setup.tension_coefficient = c.tension_coefficient_n;
  setup.bending_rigidity = c.bending_rigidity_n_m2;
  setup.damping_per_measure = c.damping_kg_per_m_s;
  return std::make_unique<LagrangianSheet>(std::move(setup));
}

/// A builder of the model whose configuration class is Config (the one ModelRegistry makes
/// under the same name, so the cast holds).
template <class Config>
std::function<std::unique_ptr<StructureModel>(const ModelConfig &, const BuildContext &)>
builder(std::unique_ptr<StructureModel> (*build)(const Config &, const BuildContext &)) {
  return [build](const ModelConfig &config, const BuildContext &context) {
    return build(dynamic_cast<const Config &>(config), context);
  };
}

} // namespace

const ModelFactory &ModelFactory::builtin() {
  static const ModelFactory factory = [] {
    ModelFactory f;
    f.add({"membrane", builder(&build_membrane)});
    f.add({"filament", builder(&build_filament)});
    return f;
  }();
  return factory;
}

} // namespace fsi::structure
