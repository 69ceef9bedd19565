#include "Scene.hpp"

#include "ModelFactory.hpp"

#include "geometry/BoxSurface.hpp"
#include "geometry/CylinderSurface.hpp"
#include "geometry/PlaneSurface.hpp"
#include "geometry/TriangleMeshSurface.hpp"
#include "motion/MotionFactory.hpp"

#include "checkpoint/CheckpointError.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <sstream>

namespace fsi::structure {

namespace {

std::unique_ptr<geometry::RigidSurface> make_surface(const geometry::SurfaceConfig &c) {
  using namespace geometry;
  if (c.plane)
    return std::make_unique<PlaneSurface>(c.plane->point_m, c.plane->normal);
  if (c.box)
    return std::make_unique<BoxSurface>(c.box->min_m, c.box->max_m);
  if (c.cylinder)
    return std::make_unique<CylinderSurface>(c.cylinder->axis_start_m, c.cylinder->axis_end_m, c.cylinder->radius_m);
  const auto side = c.mesh->fluid_side == FluidSide::inside ? TriangleMeshSurface::FluidSide::inside
                                                             : TriangleMeshSurface::FluidSide::outside;
  return std::make_unique<TriangleMeshSurface>(c.mesh->file.string(), side);
}

} // namespace

std::vector<participant::LifeSpec> life_specs(const std::vector<StructureConfig> &structures) {
  std::vector<participant::LifeSpec> specs;
  for (const auto &s : structures)
    specs.push_back({s.release_time_s, s.remove_when_past, s.tear_above_stretch_ratio});
  return specs;
}

Scene::Scene(const StructureSetup &config)
    : life_(life_specs(config.structures), config.run.time_step_s), time_step_s_(config.run.time_step_s) {
  for (const auto &entry : config.structures) {
    const BuildContext context{entry.name, config.gravity_m_per_s2, config.run.time_step_s};
    structures_.push_back(ModelFactory::builtin().build(entry.model, *entry.parameters, context));
    StructureModel &s = *structures_.back();
    if (entry.placement) { // the initial shape moved as a rigid body, its velocity turned with it
      const PointArray v = s.velocities_m_per_s() * entry.placement->rotation().transpose();
      s.restore_state(entry.placement->apply(s.positions_m(), s.point_measures()), v, 0.0);
    }
    spdlog::info("structure '{}': model {}, {} x {} points, spacing {:.4g} m{}", entry.name, entry.model,
                 s.grid_shape().first, s.grid_shape().second, s.lagrangian_spacing_m(),
                 entry.release_time_s > 0.0 ? fmt::format(", released at t = {:g} s", entry.release_time_s) : "");
    zero_loads_.push_back(PointArray::Zero(s.n_points(), 3));
  }
  if (config.collisions) {
    build_collisions(*config.collisions, config.gravity_m_per_s2.norm(), config.rigid_motions_from_coupler);
    for (std::size_t i = 0; i < structures_.size(); ++i) // declared on top of each other
      if (life_.in_scene(i))
        note_overlaps(i);
  } else
    spdlog::info("collisions: none (no rigid surfaces, no collision search)");
}

void Scene::build_collisions(const CollisionConfig &config, double gravity_m_per_s2, bool motions_from_coupler) {
  if (!config.surfaces.empty()) {
    collisions_ = std::make_unique<collision::CollisionSet>(config.threshold_m, config.target_distance_m);
    for (std::size_t i = 0; i < config.surfaces.size(); ++i) {
      const auto &surface = config.surfaces[i];
      std::shared_ptr<const motion::RigidMotion> motion = std::make_shared<const motion::StaticPose>();
      if (surface.motion && motions_from_coupler) {
        coupled_motions_.push_back(std::make_shared<motion::CoupledMotion>("surface" + std::to_string(i)));
        motion = coupled_motions_.back();
      } else if (surface.motion) {
        motion = motion::make_motion(*surface.motion, gravity_m_per_s2);
      }
      collisions_->add_surface(make_surface(surface), std::move(motion));
    }
    spdlog::info("collisions: {}", collisions_->describe());
  }
  spreads_.resize(structures_.size());
  if (config.spread_points > 0 && collisions_)
    for (std::size_t i = 0; i < structures_.size(); ++i) {
      const auto [n1, n2] = structures_[i]->grid_shape();
      spreads_[i] = std::make_unique<collision::CorrectionSpread>(n1, n2, config.spread_points);
      spdlog::info("collisions: structure '{}': each wall correction spread over its grid neighbours up to {} "
                   "points away", structures_[i]->name(), config.spread_points);
    }
  self_collisions_.resize(structures_.size());
  if (config.self_collision)
    for (std::size_t i = 0; i < structures_.size(); ++i)
      self_collisions_[i] = std::make_unique<collision::SelfCollision>(
          structures_[i]->positions_m(), config.threshold_m, config.target_distance_m);
  if (config.structure_contact && structures_.size() < 2)
    spdlog::warn("collisions.structure_contact: the case has one structure, nothing to touch");
  if (config.structure_contact && structures_.size() >= 2) {
    std::vector<collision::ContactBody> bodies;
    for (const auto &s : structures_) {
      const auto [n1, n2] = s->grid_shape();
      bodies.push_back({n1, n2, s->point_measures() * s->mass_per_measure()});
    }
    contact_ = std::make_unique<collision::StructureContact>(std::move(bodies), config.threshold_m,
                                                             config.target_distance_m);
    contact_start_.resize(structures_.size());
    contact_now_.resize(structures_.size());
    spdlog::info("collisions: contact between the {} structures (points against the other sheets' triangles)",
                 structures_.size());
  }
}

motion::CoupledMotion *Scene::coupled_motion(const std::string &name) const {
  for (const auto &motion : coupled_motions_)
    if (motion->name() == name)
      return motion.get();
  return nullptr;
}

void Scene::advance() { advance(zero_loads_); } // gravity only, no fluid

void Scene::advance(const std::vector<PointArray> &load_densities) {
  last_corrections_ = 0;
  last_iterations_ = 0;
  for (const std::size_t i : life_.release(time_s_)) { // from where it waited, on the scene's clock
    StructureModel &s = *structures_[i];
    s.restore_state(s.positions_m(), s.velocities_m_per_s(), time_s_);
    spdlog::info("structure '{}' released at t = {:g} s ({} in the scene)", s.name(), time_s_, life_.n_in_scene());
    note_overlaps(i);
  }
  if (contact_)
    for (std::size_t i = 0; i < structures_.size(); ++i)
      contact_start_[i] = structures_[i]->positions_m();
  for (std::size_t i = 0; i < structures_.size(); ++i)
    if (life_.in_scene(i))
      last_iterations_ += structures_[i]->advance(load_densities[i]); // Eq. (4)
  if (contact_) {
    correct_contacts();
    forget_parted_overlaps();
  }
  // The walls last, so that no point ends a step inside a rigid body.
  for (std::size_t i = 0; i < structures_.size(); ++i)
    if (life_.in_scene(i))
      correct_collisions(*structures_[i], i); // Eq. (11)
  time_s_ += time_step_s_;
}

std::vector<std::size_t> Scene::remove_past_planes() {
  std::vector<const PointArray *> positions;
  for (const auto &s : structures_)
    positions.push_back(&s->positions_m());
  const auto removed = life_.remove_past_planes(positions, time_s_);
  for (const std::size_t i : removed) {
    structures_[i]->retire();
    spdlog::info("structure '{}' removed at t = {:g} s: all its points are past its remove_when_past plane ({} "
                 "left in the scene)", structures_[i]->name(), time_s_, life_.n_in_scene());
  }
  return removed;
}

std::vector<std::size_t> Scene::tear_overstretched() {
  const std::vector<double> stretch = max_stretch_ratios();
  const auto torn = life_.tear_overstretched(stretch, time_s_);
  for (const std::size_t i : torn) {
    spdlog::warn("structure '{}' torn off the scene at t = {:g} s: stretch ratio {:.4g} above its "
                 "tear_above_stretch_ratio ({} left in the scene)", structures_[i]->name(), time_s_, stretch[i],
                 life_.n_in_scene());
    structures_[i]->retire();
  }
  return torn;
}

std::vector<double> Scene::max_stretch_ratios() const {
  // Also a structure's gone this step: the structure accepts a step (and tears) before it
  // sends it, and the coupler, which tears in the scene only, must see the same value.
  std::vector<double> stretch;
  for (std::size_t i = 0; i < structures_.size(); ++i)
    stretch.push_back(life_.tears(i) && life_.life(i) != participant::Life::waiting
                          ? structures_[i]->max_stretch_ratio()
                          : 1.0);
  return stretch;
}

std::vector<std::string> Scene::names() const {
  std::vector<std::string> out;
  for (const auto &s : structures_)
    out.push_back(s->name());
  return out;
}

void Scene::save_state(checkpoint::StateArchive &archive) const {
  archive.put_double("time_s", time_s_);
  for (const auto &s : structures_)
    s->save_state(archive, "structures/" + s->name() + "/");
  life_.save(archive, names());
  std::string pairs;
  for (const auto &[a, b] : overlapping_)
    pairs += (pairs.empty() ? "" : " ") + std::to_string(a) + "-" + std::to_string(b);
  archive.put_text("contact/overlapping", pairs);
}

void Scene::load_state(const checkpoint::StateArchive &archive) {
  time_s_ = archive.number("time_s");
  for (const auto &s : structures_)
    s->load_state(archive, "structures/" + s->name() + "/");
  life_.load(archive, names(), time_s_);
  overlapping_.clear();
  if (archive.has("contact/overlapping")) {
    std::istringstream pairs(archive.text("contact/overlapping"));
    std::size_t a = 0, b = 0;
    char dash = 0;
    while (pairs >> a >> dash >> b)
      if (dash == '-' && a < b && b < structures_.size())
        overlapping_.insert({a, b});
      else
        throw checkpoint::CheckpointError("contact/overlapping = '" + archive.text("contact/overlapping") +
                                          "': not pairs i-j of structures, i < j");
  }
  for (std::size_t i = 0; i < structures_.size(); ++i)
    if (life_.life(i) == Life::gone)
      structures_[i]->retire();
}

void Scene::restore_states(const std::vector<PointArray> &x_m, const std::vector<PointArray> &v_m_per_s,
                           double time_s) {
  for (std::size_t i = 0; i < structures_.size(); ++i)
    structures_[i]->restore_state(x_m[i], v_m_per_s[i], time_s);
  time_s_ = time_s;
}

void Scene::note_overlaps(std::size_t released) {
  if (!contact_)
    return;
  for (std::size_t i = 0; i < structures_.size(); ++i)
    contact_now_[i] = structures_[i]->positions_m();
  for (std::size_t j = 0; j < structures_.size(); ++j)
    if (j != released && life_.in_scene(j) && contact_->touching(released, j, contact_now_) &&
        overlapping_.insert({std::min(released, j), std::max(released, j)}).second)
      spdlog::info("structure '{}' enters the scene within d_c of '{}': the two pass through each other until "
                   "they part", structures_[released]->name(), structures_[j]->name());
}

void Scene::forget_parted_overlaps() {
  for (auto pair = overlapping_.begin(); pair != overlapping_.end();) {
    const auto [a, b] = *pair;
    const bool parted =
        !life_.in_scene(a) || !life_.in_scene(b) || !contact_->touching(a, b, contact_now_);
    pair = parted ? overlapping_.erase(pair) : std::next(pair);
  }
}

void Scene::correct_contacts() {
  for (std::size_t i = 0; i < structures_.size(); ++i)
    contact_now_[i] = structures_[i]->positions_m();
  const auto stats = contact_->correct(contact_now_, contact_start_, life_.in_scene_flags(), overlapping_);
  if (stats.n_contacts == 0)
    return;
  last_corrections_ += stats.n_contacts;
  for (std::size_t i = 0; i < structures_.size(); ++i)
    if (life_.in_scene(i))
      structures_[i]->correct_positions([&](PointArray &x) { x = contact_now_[i]; });
}

void Scene::correct_collisions(StructureModel &structure, std::size_t index) {
  const bool self = index < self_collisions_.size() && self_collisions_[index];
  if (!collisions_ && !self)
    return;
  structure.correct_positions([&](PointArray &x) {
    if (self)
      last_corrections_ += self_collisions_[index]->correct(x);
    if (!collisions_)
      return;
    const auto &spread = spreads_[index];
    if (spread)
      before_correction_ = x;
    const std::size_t corrected = collisions_->correct(x, structure.time_s()).n_points_corrected;
    last_corrections_ += corrected;
    // The spread moves the neighbours along their corrected points' wall normals; a neighbour
    // that it brings within d_c of another wall is corrected by Eq. 11 again.
    if (spread && corrected > 0 && spread->apply(before_correction_, x) > 0)
      collisions_->correct(x, structure.time_s());
  });
}

} // namespace fsi::structure
