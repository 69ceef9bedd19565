#pragma once
// One entry of the case's `structures` list: a name, a model from the registry and that
// model's own keys at the same level, and the structure's life in the scene: when it is
// released, where it starts when placed, and the plane past which it is removed.

#include "ModelRegistry.hpp"
#include "Placement.hpp"
#include "common/DidYouMean.hpp"
#include "common/RunConfig.hpp"

#include <optional>

namespace fsi::structure {

struct StructureConfig {
  std::string name = "sheet";
  std::string model = "membrane";
  std::unique_ptr<ModelConfig> parameters;
  double release_time_s = 0.0;
  std::optional<Placement> placement;
  std::optional<common::StopPlane> remove_when_past;
  double tear_above_stretch_ratio = 0.0;

  template <class V> void visit(V &v) {
    v.text("name", name, "Unique name; the HDF5 group /structures/<name>.");
    v.text("model", model, "Structure model: " + common::join(ModelRegistry::builtin().names()) + ".");
    v.number("release_time_s", release_time_s, common::Range::non_negative("s"),
             "When the structure enters the scene (0: from the start). Before it, it is neither advanced nor "
             "coupled: it waits where it starts.");
    v.optional_section("placement", placement,
                       "Moves the initial shape as a rigid body: its centroid to centre_m, turned about it. Absent: "
                       "where the model's keys put it.");
    v.optional_section("remove_when_past", remove_when_past,
                       "Removes the structure from the scene at the first step where all its points are past this "
                       "plane (a rag leaving through a pump's discharge): from then on it is neither advanced nor "
                       "coupled, its solver's memory is freed, and structure.h5 keeps its history and exit time.");
    v.number("tear_above_stretch_ratio", tear_above_stretch_ratio, common::Range::non_negative("1"),
             "0: never torn. Above 1: the structure is torn off the scene, as one past remove_when_past leaves it, "
             "at the first accepted step where an edge is stretched beyond this ratio of its rest length (a rag "
             "caught between a turning impeller and its casing, which a real one would tear), and its stretch no "
             "longer stops the run (solver.max_stretch_ratio); exit_reason 'torn' in structure.h5.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (tear_above_stretch_ratio != 0.0 && !(tear_above_stretch_ratio > 1.0))
        v.fail_value("tear_above_stretch_ratio", "= " + std::to_string(tear_above_stretch_ratio) +
                                                     ": 0 (never torn) or a ratio above 1.");
    if constexpr (std::is_same_v<V, common::ConfigDocWriter>)
      return; // each model's keys are documented in their own table
    else {
      if constexpr (std::is_same_v<V, common::ConfigReader>) {
        try {
          parameters = ModelRegistry::builtin().make_config(model);
        } catch (const common::ConfigError &e) {
          v.fail_value("model", std::string("= ") + e.what());
        }
      }
      if (parameters)
        parameters->visit(v);
    }
  }
};

} // namespace fsi::structure
