#pragma once
// The time loop of the flow alone with its rigid bodies (no structure, no coupler), on every
// rank: the precursor of a coupled run (section 3.2, at Precursor::step_sizes), and a case
// without structures (a pump's single-phase performance, at run.time_step_s).

#include "FlowAloneCheckpoints.hpp"
#include "fluid_adapter/FoamFlow.hpp"
#include "fluid_adapter/OpenFoamFluidModel.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace fsi::apps {

struct FlowAloneSchedule {
  std::string label;                ///< what the log calls it ("precursor", "flow")
  std::filesystem::path folder;     ///< where forces.csv goes
  std::vector<double> step_sizes_s; ///< the time steps, in order
  /// The case's checkpoints (the flow alone; none for the precursor): sets written as due, and
  /// a restart's first step, after which the run resumes and its tables are continued.
  const FlowAloneCheckpoints *checkpoints = nullptr;
};

/// Steps through the schedule; progress with ETA and the rigid-body loads (folder/forces.csv:
/// per body the force of the fluid on it, N, and its torque about the body's box centre, N m;
/// folder/parts.csv: that torque split among the named parts of each body whose STL has
/// several `solid NAME` blocks, columns body<b>.<part>.t{x,y,z}_n_m, BodyPartLoads;
/// folder/parts_staircase.csv: the same columns, the share of each part's torque that the
/// pressure on its staircase's steps takes, OpenFoamFluidModel::last_step_part_staircase_loads)
/// and the split of each step's wall time (folder/timings.csv, s: penalization, fluid solve,
/// loads; the master's) from the master, a line per step; writes the fields at the end. A
/// restart keeps the tables' rows up to its first step and appends. Returns the exit code
/// (common::exit_code_interrupted when stopped by a signal, after a checkpoint when it has them).
int run_flow_alone(fluid::OpenFoamFluidModel &model, fluid::FoamFlow &flow, const FlowAloneSchedule &schedule);

/// n steps of dt to end_time_s (the last one shortened to land on it).
std::vector<double> uniform_steps(double time_step_s, double end_time_s);
/// A restart at step k (k >= 1) and time t_k: uniform_steps when its first k steps reach t_k
/// (to 1e-6 dt), so that the restart takes the uninterrupted run's steps; otherwise (a run that
/// ended on a shorter last step, asked for more) k steps that sum to t_k, then uniform_steps
/// from t_k: it goes on from its own time, not from k dt.
std::vector<double> resumed_steps(double time_step_s, double end_time_s, long resumed_step, double resumed_at_s);

} // namespace fsi::apps
