#pragma once
// Which structures are in the scene (issue 33: rags fed in sequence into a running pump). A
// structure waits until its release time (structures[].release_time_s), is in the scene from
// the first step that starts at or after it, and is gone from the end of the first accepted step
// at which all its points are past its removal plane (structures[].remove_when_past), or at
// which it is stretched beyond its tear limit (structures[].tear_above_stretch_ratio): torn off. Only
// structures in the scene are advanced, touch each other and take part in the coupling; one
// that waits or is gone keeps its state where it was.
//
// Decisions are made on times and on accepted states only: a release at the start of a step
// from the scene's time, a removal when the step is accepted (after an implicit coupling's last
// iterate), so that a repeated step repeats them and a restart resumes them. The structure
// solver and the coupler each keep one, on the same accepted positions (bit for bit over the
// wire), and the coupler tells the fluid and the structure which structures are idle.

#include "checkpoint/StateArchive.hpp"
#include "common/RunConfig.hpp"
#include "common/Types.hpp"
#include "proto/Protocol.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fsi::participant {

enum class Life { waiting, in_scene, gone };
/// Why a structure is gone: past its removal plane, or torn (stretched beyond its tear limit).
enum class ExitReason { none, past_plane, torn };
const char *exit_reason_name(ExitReason reason); ///< "", "past_plane", "torn"

/// What decides one structure's life: its release time, its removal plane (none: it stays) and
/// the stretch ratio beyond which it is torn off the scene (0: never).
struct LifeSpec {
  double release_time_s = 0.0;
  std::optional<common::StopPlane> remove_when_past;
  double tear_above_stretch_ratio = 0.0;
};

/// The spec as the handshake carries it (StructureTopology.release_time_s, .remove_when_past);
/// throws proto::MalformedMessageError for a plane of other than 6 values or a zero normal.
LifeSpec life_spec_of(const proto::v2::StructureTopology &topology);
void write_life_spec(const LifeSpec &spec, proto::v2::StructureTopology &topology);

class LifeCycle {
public:
  /// From the structures' release times and removal planes; time_step_s rounds a release time
  /// to the step that starts nearest it.
  LifeCycle(const std::vector<LifeSpec> &structures, double time_step_s);

  std::size_t size() const { return life_.size(); }
  Life life(std::size_t i) const { return life_[i]; }
  bool in_scene(std::size_t i) const { return life_[i] == Life::in_scene; }
  /// Per structure, in_scene(i).
  std::vector<bool> in_scene_flags() const;
  std::size_t n_in_scene() const;
  /// The indices of the structures not in the scene (waiting or gone), ascending.
  std::vector<std::uint32_t> idle() const;
  /// The same, as it will be once the releases due at a step starting at time_s are made.
  std::vector<std::uint32_t> idle_after_release(double time_s) const;
  double release_time_s(std::size_t i) const { return release_s_[i]; }
  /// When it was removed (the end of the step that took it past its plane or tore it); NaN until then.
  double exit_time_s(std::size_t i) const { return exit_s_[i]; }
  ExitReason exit_reason(std::size_t i) const { return reason_[i]; }

  /// The structures that enter the scene at a step starting at time_s (waiting ones whose
  /// release time has come), now in the scene.
  std::vector<std::size_t> release(double time_s);
  /// The structures in the scene whose points (positions_m[i]) are all past their removal plane
  /// at the end of an accepted step ending at time_s, now gone.
  std::vector<std::size_t> remove_past_planes(const std::vector<const PointArray *> &positions_m, double time_s);
  /// The structures in the scene whose largest stretch ratio (max_stretch_ratio[i], at the end
  /// of an accepted step ending at time_s) is above their tear limit, now gone (torn).
  std::vector<std::size_t> tear_overstretched(const std::vector<double> &max_stretch_ratio, double time_s);
  /// Whether structure i is torn off rather than stopping the run when stretched too far.
  bool tears(std::size_t i) const { return tear_above_[i] > 0.0; }

  /// The states and exit times, for an exact restart and for a repeated step ("life/<name>/").
  void save(checkpoint::StateArchive &archive, const std::vector<std::string> &names) const;
  /// Takes what save() wrote; a checkpoint without it (written before structures had a life)
  /// means every structure whose release time has come by time_s is in the scene.
  void load(const checkpoint::StateArchive &archive, const std::vector<std::string> &names, double time_s);

private:
  bool due(std::size_t i, double time_s) const { return release_s_[i] <= time_s + 0.5 * time_step_s_; }

  double time_step_s_;
  std::vector<Life> life_;
  std::vector<double> release_s_, exit_s_, tear_above_;
  std::vector<ExitReason> reason_;
  std::vector<std::optional<common::StopPlane>> removal_;
};

} // namespace fsi::participant
