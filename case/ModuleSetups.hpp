#pragma once
// From the whole case to what each module needs of it: the executables load case.yaml once
// (CaseConfig) and hand each physics module only its own sections, plus the case's identity
// (effective configuration and fingerprint). This is the one place that knows both.

#include "CaseConfig.hpp"
#include "coupler/CouplingSetup.hpp"
#include "fluid_adapter/Precursor.hpp"
#include "structure_solver/StructureSetup.hpp"

namespace fsi::case_config {

/// The effective configuration of the case (defaults included) as YAML.
std::string effective_yaml(const CaseConfig &config);

/// The structure solver's sections (consumes the structures, probes and collisions).
structure::StructureSetup structure_setup(CaseConfig config);

/// The coupler's sections; the case must have a `coupling` section.
coupler::CouplingSetup coupling_setup(CaseConfig config, const std::filesystem::path &case_dir);

/// The precursor's inputs (no openfoam section: none wanted).
fluid::PrecursorInputs precursor_inputs(const CaseConfig &config);

} // namespace fsi::case_config
