#pragma once
// The precursor run of section 3.2: the flow with its rigid bodies alone (no structure, no
// coupler) for fluid.openfoam.precursor_time_s, whose last fields are the initial fields of the
// coupled run ("a precursor simulation without the rag but including the cylindrical pole was
// run to determine the initial pressure and velocity conditions"). OpenFOAM-free: this class
// knows where the precursor lives (<output>/precursor/openfoam), whether its result is still
// valid for the case (a fingerprint of everything the precursor's flow depends on) and how to
// hand its fields to the coupled run. fsi-openfoam-fluid --precursor runs it.

#include "OpenFoamConfig.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace fsi::fluid {

/// What the precursor needs of a case (filled by the executable, case/ModuleSetups.hpp).
struct PrecursorInputs {
  std::optional<OpenFoamConfig> openfoam; ///< fluid.openfoam (absent: no precursor)
  double coupled_time_step_s = 0.0;       ///< run.time_step_s
  std::string fluid_yaml;                 ///< the effective `fluid` section (YAML)
  std::string collisions_yaml;            ///< the effective `collisions.surfaces` (YAML, files by name; "" if none)
  std::vector<std::filesystem::path> surface_stl_files; ///< STL files of the collision surfaces
};

class Precursor {
public:
  Precursor(const PrecursorInputs &inputs, std::filesystem::path case_dir, std::filesystem::path output_dir);

  /// The case asks for one (fluid.openfoam.precursor_time_s > 0).
  bool wanted() const { return end_time_s_ > 0.0; }
  double end_time_s() const { return end_time_s_; }
  double time_step_s() const { return time_step_s_; }
  /// Its steps, summing to end_time_s(): its own dt, then (when the coupled run's dt is
  /// smaller) a geometric ramp down to it, at most 1.25 times per step, and `handover_steps` at
  /// the coupled dt, so that the state it hands over belongs to the coupled step. An abrupt
  /// change of dt makes PIMPLE start with a pressure transient, which the ramp reduces and the
  /// last steps absorb (measured on rag-behind-pole, 2e-3 to 1e-4 s: at once, the pole's drag
  /// jumps to 7.7 times its precursor value and is still 1.8 times it 20 steps later; with the
  /// ramp it peaks at 2.7 times and the coupled run starts at 1.14 times, relaxing on).
  std::vector<double> step_sizes() const;
  static constexpr int handover_steps = 100;
  /// The OpenFOAM case the precursor runs in.
  std::filesystem::path foam_case() const { return folder_ / "openfoam"; }
  std::filesystem::path folder() const { return folder_; }

  /// Hash (16 hex digits) of what the precursor's flow depends on: the fluid and collisions
  /// sections, its step sizes and end time, the files of the OpenFOAM case folder and
  /// the STL files of the collision surfaces. The structures, the coupling and run.end_time_s
  /// are not part of it: changing the rag reuses the precursor.
  const std::string &fingerprint() const { return fingerprint_; }
  /// A completed precursor with this fingerprint is on disk.
  bool is_current() const;
  /// Records a completed precursor (after its fields are written).
  void mark_complete() const;
  /// Forgets any earlier result (before a new precursor run starts): removes the folder's
  /// files, so that files hard-linked from elsewhere are left as they are.
  void invalidate() const;

  /// Copies every field of the precursor's last time into the coupled case's start time (0/),
  /// per processor folder when the fluid runs on n_ranks > 1 (the precursor used the same
  /// decomposition). Returns the number of files copied; throws when the precursor has none.
  std::size_t install_fields(const std::filesystem::path &coupled_case, int n_ranks) const;

  /// The time folder with the largest numeric name in an OpenFOAM case (or processor) folder.
  static std::filesystem::path latest_time_directory(const std::filesystem::path &folder);

private:
  std::filesystem::path stamp_file() const { return folder_ / "completed.fingerprint"; }
  std::string compute_fingerprint(const PrecursorInputs &inputs, const std::filesystem::path &case_dir) const;

  std::filesystem::path folder_;
  double end_time_s_ = 0.0;
  double time_step_s_ = 0.0;
  double coupled_time_step_s_ = 0.0;
  std::string fingerprint_;
};

} // namespace fsi::fluid
