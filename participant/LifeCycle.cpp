#include "LifeCycle.hpp"

#include "checkpoint/CheckpointError.hpp"
#include "proto/TransportError.hpp"

#include <cmath>
#include <limits>

namespace fsi::participant {

LifeSpec life_spec_of(const proto::v2::StructureTopology &topology) {
  LifeSpec spec;
  spec.release_time_s = topology.release_time_s();
  if (!(spec.release_time_s >= 0.0) || !std::isfinite(spec.release_time_s))
    throw proto::MalformedMessageError("structure '" + topology.name() + "': release_time_s = " +
                                       std::to_string(spec.release_time_s) + " is not a time >= 0");
  spec.tear_above_stretch_ratio = topology.tear_above_stretch_ratio();
  if (!std::isfinite(spec.tear_above_stretch_ratio) ||
      !(spec.tear_above_stretch_ratio == 0.0 || spec.tear_above_stretch_ratio > 1.0))
    throw proto::MalformedMessageError("structure '" + topology.name() + "': tear_above_stretch_ratio = " +
                                       std::to_string(spec.tear_above_stretch_ratio) +
                                       " is neither 0 (never torn) nor a ratio above 1");
  const auto &plane = topology.remove_when_past();
  if (plane.empty())
    return spec;
  if (plane.size() != 6)
    throw proto::MalformedMessageError("structure '" + topology.name() + "': remove_when_past has " +
                                       std::to_string(plane.size()) + " values, expected 6 (a point and a normal)");
  common::StopPlane p;
  p.point_m = Vec3(plane[0], plane[1], plane[2]);
  p.normal = Vec3(plane[3], plane[4], plane[5]);
  if (!p.point_m.allFinite() || !(p.normal.norm() > 0.0) || !p.normal.allFinite())
    throw proto::MalformedMessageError("structure '" + topology.name() + "': remove_when_past's point or normal is "
                                       "not finite, or the normal is zero");
  spec.remove_when_past = p;
  return spec;
}

const char *exit_reason_name(ExitReason reason) {
  switch (reason) {
  case ExitReason::past_plane:
    return "past_plane";
  case ExitReason::torn:
    return "torn";
  case ExitReason::none:
    break;
  }
  return "";
}

void write_life_spec(const LifeSpec &spec, proto::v2::StructureTopology &topology) {
  topology.set_release_time_s(spec.release_time_s);
  topology.set_tear_above_stretch_ratio(spec.tear_above_stretch_ratio);
  topology.clear_remove_when_past();
  if (const auto &plane = spec.remove_when_past)
    for (const Vec3 &v : {plane->point_m, plane->normal})
      for (int k = 0; k < 3; ++k)
        topology.add_remove_when_past(v[k]);
}

LifeCycle::LifeCycle(const std::vector<LifeSpec> &structures, double time_step_s) : time_step_s_(time_step_s) {
  for (const auto &s : structures) {
    release_s_.push_back(s.release_time_s);
    exit_s_.push_back(std::numeric_limits<double>::quiet_NaN());
    removal_.push_back(s.remove_when_past);
    tear_above_.push_back(s.tear_above_stretch_ratio);
    reason_.push_back(ExitReason::none);
    life_.push_back(due(life_.size(), 0.0) ? Life::in_scene : Life::waiting);
  }
}

std::vector<bool> LifeCycle::in_scene_flags() const {
  std::vector<bool> flags(life_.size());
  for (std::size_t i = 0; i < life_.size(); ++i)
    flags[i] = in_scene(i);
  return flags;
}

std::size_t LifeCycle::n_in_scene() const {
  std::size_t n = 0;
  for (const Life l : life_)
    n += l == Life::in_scene;
  return n;
}

std::vector<std::uint32_t> LifeCycle::idle() const {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < life_.size(); ++i)
    if (!in_scene(i))
      out.push_back(static_cast<std::uint32_t>(i));
  return out;
}

std::vector<std::uint32_t> LifeCycle::idle_after_release(double time_s) const {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < life_.size(); ++i)
    if (!(in_scene(i) || (life_[i] == Life::waiting && due(i, time_s))))
      out.push_back(static_cast<std::uint32_t>(i));
  return out;
}

std::vector<std::size_t> LifeCycle::release(double time_s) {
  std::vector<std::size_t> released;
  for (std::size_t i = 0; i < life_.size(); ++i)
    if (life_[i] == Life::waiting && due(i, time_s)) {
      life_[i] = Life::in_scene;
      released.push_back(i);
    }
  return released;
}

std::vector<std::size_t> LifeCycle::remove_past_planes(const std::vector<const PointArray *> &positions_m,
                                                       double time_s) {
  std::vector<std::size_t> removed;
  for (std::size_t i = 0; i < life_.size(); ++i)
    if (life_[i] == Life::in_scene && removal_[i] && removal_[i]->all_past(*positions_m[i])) {
      life_[i] = Life::gone;
      exit_s_[i] = time_s;
      reason_[i] = ExitReason::past_plane;
      removed.push_back(i);
    }
  return removed;
}

std::vector<std::size_t> LifeCycle::tear_overstretched(const std::vector<double> &max_stretch_ratio, double time_s) {
  std::vector<std::size_t> torn;
  for (std::size_t i = 0; i < life_.size() && i < max_stretch_ratio.size(); ++i)
    if (life_[i] == Life::in_scene && tears(i) && !(max_stretch_ratio[i] <= tear_above_[i])) {
      life_[i] = Life::gone;
      exit_s_[i] = time_s;
      reason_[i] = ExitReason::torn;
      torn.push_back(i);
    }
  return torn;
}

void LifeCycle::save(checkpoint::StateArchive &archive, const std::vector<std::string> &names) const {
  for (std::size_t i = 0; i < life_.size(); ++i) {
    archive.put_integer("life/" + names[i] + "/state", static_cast<std::int64_t>(life_[i]));
    archive.put_double("life/" + names[i] + "/exit_time_s", exit_s_[i]);
    archive.put_integer("life/" + names[i] + "/exit_reason", static_cast<std::int64_t>(reason_[i]));
  }
}

void LifeCycle::load(const checkpoint::StateArchive &archive, const std::vector<std::string> &names, double time_s) {
  for (std::size_t i = 0; i < life_.size(); ++i) {
    const std::string key = "life/" + names[i] + "/state";
    if (!archive.has(key)) {
      life_[i] = due(i, time_s) ? Life::in_scene : Life::waiting;
      exit_s_[i] = std::numeric_limits<double>::quiet_NaN();
      reason_[i] = ExitReason::none;
      continue;
    }
    const std::int64_t state = archive.integer(key);
    if (state < 0 || state > static_cast<std::int64_t>(Life::gone))
      throw checkpoint::CheckpointError(key + " = " + std::to_string(state) + ": not a life state (0 waiting, 1 in "
                                        "the scene, 2 gone)");
    life_[i] = static_cast<Life>(state);
    exit_s_[i] = archive.number("life/" + names[i] + "/exit_time_s");
    // A checkpoint from before structures could tear: a gone one went past its plane.
    const std::string reason_key = "life/" + names[i] + "/exit_reason";
    const std::int64_t reason = archive.has(reason_key) ? archive.integer(reason_key)
                                                        : static_cast<std::int64_t>(life_[i] == Life::gone
                                                                                        ? ExitReason::past_plane
                                                                                        : ExitReason::none);
    if (reason < 0 || reason > static_cast<std::int64_t>(ExitReason::torn))
      throw checkpoint::CheckpointError(reason_key + " = " + std::to_string(reason) + ": not an exit reason (0 none, "
                                        "1 past its plane, 2 torn)");
    reason_[i] = static_cast<ExitReason>(reason);
  }
}

} // namespace fsi::participant
