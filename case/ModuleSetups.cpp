#include "ModuleSetups.hpp"

#include "ChannelSettings.hpp"
#include "common/ConfigEmitter.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <stdexcept>

namespace fsi::case_config {

std::string effective_yaml(const CaseConfig &config) {
  // The emitter only reads; visit() is non-const because the reader shares it.
  return common::to_yaml(const_cast<CaseConfig &>(config));
}

structure::StructureSetup structure_setup(CaseConfig config) {
  structure::StructureSetup setup;
  setup.case_yaml = effective_yaml(config);
  setup.case_fingerprint = config.fingerprint();
  setup.restart_identity = config.restart_identity();
  setup.run = config.run;
  setup.gravity_m_per_s2 = config.gravity_m_per_s2;
  setup.collisions = std::move(config.collisions);
  setup.structures = std::move(config.structures);
  setup.probes = std::move(config.probes);
  return setup;
}

coupler::CouplingSetup coupling_setup(CaseConfig config, const std::filesystem::path &case_dir) {
  if (!config.coupling)
    throw std::logic_error("coupling_setup needs a case with a coupling section");
  coupler::CouplingSetup setup;
  setup.channel = channel_options(config, case_dir, "coupler");
  setup.case_yaml = effective_yaml(config);
  setup.case_fingerprint = config.fingerprint();
  setup.restart_identity = config.restart_identity();
  setup.run = config.run;
  setup.coupling = std::move(*config.coupling);
  if (config.collisions)
    setup.rigid_surfaces = config.collisions->surfaces;
  setup.gravity_m_per_s2 = config.gravity_m_per_s2;
  setup.n_structures = config.structures.size();
  return setup;
}

fluid::PrecursorInputs precursor_inputs(const CaseConfig &config) {
  fluid::PrecursorInputs inputs;
  inputs.coupled_time_step_s = config.run.time_step_s;
  if (!config.fluid || !config.fluid->openfoam)
    return inputs;
  inputs.openfoam = *config.fluid->openfoam;
  const YAML::Node node = YAML::Load(effective_yaml(config));
  inputs.fluid_yaml = YAML::Dump(node["fluid"]);
  if (node["collisions"] && node["collisions"]["surfaces"]) {
    // The rigid surfaces alone (the penalized bodies and their motion; the collision distances and
    // self-collision are the structure's), their STL files by name only: the contents are hashed
    // on their own, and a copy of the case elsewhere (a pump-curve point, a rag-ensemble member)
    // keeps its precursor valid.
    YAML::Node surfaces = YAML::Clone(node["collisions"]["surfaces"]);
    for (YAML::Node surface : surfaces)
      if (surface["mesh"] && surface["mesh"]["file"])
        surface["mesh"]["file"] = std::filesystem::path(surface["mesh"]["file"].as<std::string>()).filename().string();
    inputs.collisions_yaml = YAML::Dump(surfaces);
  }
  if (config.collisions)
    for (const auto &surface : config.collisions->surfaces)
      if (surface.mesh)
        inputs.surface_stl_files.push_back(surface.mesh->file);
  return inputs;
}

} // namespace fsi::case_config
