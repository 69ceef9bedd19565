#pragma once
// The precursor's time loop (section 3.2): the flow with its rigid bodies alone, no structure,
// no coupler, on every rank, at the precursor's own step schedule (Precursor::step_sizes).

#include "FoamFlow.hpp"
#include "OpenFoamFluidModel.hpp"
#include "Precursor.hpp"

namespace fsi::fluid {

/// Steps to the precursor's end time; progress with ETA and the rigid-body loads
/// (precursor/forces.csv) from the master; writes the fields at the end. Returns the exit
/// code (common::exit_code_interrupted when stopped by a signal: the result is not kept).
int run_precursor_steps(OpenFoamFluidModel &model, FoamFlow &flow, const Precursor &precursor);

} // namespace fsi::fluid
