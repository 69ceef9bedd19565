#include "OpenFoamFluidModel.hpp"

#include "FoamCheckpoint.hpp"
#include "checkpoint/ArchiveFile.hpp"
#include "common/Durations.hpp"
#include "common/UserError.hpp"

#include "fluid_adapter/ibm/ClosestCellLinear.hpp"
#include "fluid_adapter/ibm/PeskinKernel.hpp"
#include "proto/BodyPose.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/TransportError.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace fsi::fluid {

OpenFoamFluidModel::OpenFoamFluidModel(const OpenFoamConfig &config, FoamFlow &flow,
                                       std::vector<std::unique_ptr<rigid::RigidBody>> rigid_bodies)
    : config_(config), flow_(flow), cells_(flow.cell_centres_m(), flow.cell_volumes_m3()),
      bodies_(std::move(rigid_bodies)) {
  if (flow_.n_ranks() > 1 && config_.interpolation == InterpolationChoice::closest_cell_linear)
    throw std::runtime_error("fluid.openfoam.interpolation: closest_cell_linear is not available with MPI yet; use "
                             "kernel");
  rigid::IndicatorOptions indicator_options;
  if (config_.body_indicator == BodyIndicatorChoice::inside_smoothed) {
    indicator_options.sampling = rigid::IndicatorOptions::Sampling::inside_smoothed;
    indicator_options.smoothing_depth_cells = config_.body_indicator_depth_cells;
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto &body = bodies_[b];
    // On a moving mesh a moving body turns with its cells (check_bodies_on_moving_mesh).
    indicator_options.cells_move_with_body = carries_cells(b);
    indicators_.push_back(
        std::make_unique<rigid::BodyIndicator>(*body, cells_.centres_m(), indicator_options, cells_.sizes_m()));
    spdlog::info("rigid body '{}': {} candidate cells of {} (swept region), indicator {}", body->name(),
                 indicators_.back()->candidate_cells().size(), cells_.n_cells(),
                 config_.body_indicator == BodyIndicatorChoice::sharp
                     ? std::string("sharp")
                     : fmt::format("inside_smoothed over {:g} cells", config_.body_indicator_depth_cells));
  }
  const bool wall_model = config_.immersed_wall_model == ImmersedWallModelChoice::spalding;
  if (!bodies_.empty() && (flow_.uses_wall_distance() || wall_model)) {
    // Section 2.6: immersed bodies are walls for Spalart-Allmaras. Beyond C_DES Delta from every
    // wall, DES runs in LES mode whatever the distance, so measure within twice that. The wall
    // model alone needs the distance of the free cells next to the bodies: within two cells.
    constexpr double c_des = 0.65;
    const double largest_cell = cells_.n_cells() > 0 ? cells_.sizes_m().maxCoeff() : 0.0;
    const double margin = (flow_.uses_wall_distance() ? 2.0 * c_des : 2.0) * largest_cell;
    std::vector<const rigid::RigidBody *> bodies;
    for (const auto &b : bodies_)
      bodies.push_back(b.get());
    wall_distance_ = std::make_unique<rigid::ImmersedWallDistance>(bodies, cells_.centres_m(), margin);
    if (flow_.uses_wall_distance())
      spdlog::info("turbulence: immersed bodies are walls (nuTilda = 0 inside, wall distance measured in {} cells "
                   "within {:.3g} m)",
                   wall_distance_->n_measured_cells(), margin);
    if (wall_model) {
      spdlog::info("immersed walls: their shear by Spalding's law on the faces between body and free cells "
                   "(immersed_wall_model: spalding)");
      flow_.use_immersed_wall_function(true);
    }
    if (config_.immersed_wall_turbulence != ImmersedWallTurbulenceChoice::none &&
        flow_.use_immersed_omega_wall_function(config_.immersed_wall_turbulence ==
                                               ImmersedWallTurbulenceChoice::omega_wall_function))
      spdlog::info("immersed walls: omega, its production and kOmegaSST's nu_t next to them as the wall functions "
                   "make them next to mesh walls (immersed_wall_turbulence: {})",
                   config_.immersed_wall_turbulence == ImmersedWallTurbulenceChoice::automatic ? "auto"
                                                                                                : "omega_wall_function");
  }
}

std::string OpenFoamFluidModel::describe() const {
  return flow_.describe() + ", immersed boundary: Peskin 4-point kernel (Eqs. 6-8), interpolation " +
         (config_.interpolation == InterpolationChoice::kernel ? "kernel" : "closest_cell_linear") +
         (config_.normalise_kernel ? ", normalised weights" : ", raw weights");
}

// ---- the master: requests of the coupler, broadcast to the other ranks ----------------------

void OpenFoamFluidModel::set_checkpoints(std::filesystem::path root, long restart_step) {
  checkpoints_root_ = std::move(root);
  restart_step_ = restart_step;
}

void OpenFoamFluidModel::warn_unless_checkpoints_exact() const {
  if (!flow_.writes_binary())
    spdlog::warn("checkpoints: {} writes its fields in ascii (system/controlDict: writeFormat ascii), so a restart "
                 "resumes from them rounded to writePrecision digits and differs from the uninterrupted run; "
                 "writeFormat binary makes it exact",
                 flow_.case_directory().string());
}

checkpoint::CheckpointPart OpenFoamFluidModel::write_checkpoint(long n_completed) {
  if (checkpoints_root_.empty())
    throw std::logic_error("OpenFoamFluidModel::write_checkpoint before set_checkpoints");
  // Every rank writes its fields (processor<k>/<time> with several ranks: writeNow is collective),
  // then the master copies them all into the set (the ranks share the case folder).
  message_.clear();
  broadcast(Command::write_now, message_);
  return checkpoint_on_every_rank(n_completed);
}

checkpoint::CheckpointPart OpenFoamFluidModel::checkpoint_on_every_rank(long n_completed) {
  if (checkpoints_root_.empty())
    throw std::logic_error("OpenFoamFluidModel::checkpoint_on_every_rank before set_checkpoints");
  write_fields_on_every_rank();
  if (flow_.rank() != 0)
    return {};
  const auto folder = checkpoint::CheckpointSet::folder_of(checkpoints_root_, n_completed);
  std::filesystem::create_directories(folder);
  return FoamCheckpoint::write(flow_.case_directory(), flow_.time_name(), flow_.n_ranks(), folder, n_completed);
}

void OpenFoamFluidModel::write_fields_on_every_rank() {
  flow_.write_now();
  // A barrier: the master copies every rank's folder only once each has written it.
  double written = 1.0;
  flow_.sum_over_ranks(&written, 1);
}

void OpenFoamFluidModel::resume(long step, const std::string &checksum) {
  const auto part = checkpoint::CheckpointSet::folder_of(checkpoints_root_, step) / FoamCheckpoint::part_name;
  if (step != restart_step_)
    throw std::runtime_error("the coupler resumes from the checkpoint of step " + std::to_string(step) +
                             ", this fluid started from " +
                             (restart_step_ > 0 ? "that of step " + std::to_string(restart_step_)
                                                : std::string("t = 0 (give it --restart)")) +
                             ": every process of a restart must find the same newest checkpoint");
  if (checkpoint::archive_checksum(part) != checksum)
    throw std::runtime_error(part.string() + ": checksum " + checkpoint::archive_checksum(part) +
                             ", the coupler's checkpoint says " + checksum);
}

void OpenFoamFluidModel::start(const participant::RunPlan &plan) {
  const Eigen::VectorXd measures = plan.point_measures();
  message_.assign(measures.data(), measures.data() + measures.size());
  broadcast(Command::start, message_);
  do_start(message_);
  spdlog::info("{}", describe());
}

void OpenFoamFluidModel::interpolate(double /*time_s: the flow's own*/, participant::PointsView x_m,
                                     participant::MutablePointsView u_m_per_s) {
  message_.assign(x_m.data(), x_m.data() + x_m.size());
  broadcast(Command::interpolate, message_);
  positions_ = x_m;
  PointArray u;
  do_interpolate(u);
  u_m_per_s = u;
}

void OpenFoamFluidModel::spread_at(participant::PointsView x_m) {
  message_.assign(x_m.data(), x_m.data() + x_m.size());
  broadcast(Command::spread_at, message_);
  positions_ = x_m;
  build_stencil();
}

void OpenFoamFluidModel::set_idle_points(const std::vector<bool> &idle) {
  message_.assign(idle.begin(), idle.end());
  broadcast(Command::set_idle, message_);
  idle_points_ = idle;
}

void OpenFoamFluidModel::save_step_start() {
  message_.clear();
  broadcast(Command::save_step, message_);
  flow_.save_step_start();
  rate_at_step_start_ = penalization_rate_;
}

void OpenFoamFluidModel::restore_step_start() {
  message_.clear();
  broadcast(Command::restore_step, message_);
  flow_.restore_step_start();
  penalization_rate_ = rate_at_step_start_; // a repeated step's cells switch against the step's start
}

void OpenFoamFluidModel::advance(const participant::FluidStep &step,
                                 participant::PointsView force_density_n_per_measure,
                                 std::vector<participant::BodyLoad> &loads_out) {
  // Payload for the other ranks: t, dt, the moving bodies' poses at t + dt, then F_fsi^n.
  message_.assign({step.time_s, step.dt_s});
  pack_rigid_poses(step.bodies, message_);
  const std::size_t poses_end = message_.size();
  message_.insert(message_.end(), force_density_n_per_measure.data(),
                  force_density_n_per_measure.data() + force_density_n_per_measure.size());
  broadcast(Command::advance, message_);
  unpack_rigid_poses(step.time_s + step.dt_s, message_.data() + 2, message_.data() + poses_end);
  force_density_ = force_density_n_per_measure;
  std::vector<rigid::BodyLoad> loads;
  do_advance(step.step + 1, step.time_s, step.dt_s, loads);
  for (std::size_t b = 0; b < loads.size(); ++b)
    loads_out.push_back({bodies_[b]->name(), loads[b].force_n, loads[b].torque_n_m});
}

void OpenFoamFluidModel::pack_rigid_poses(const std::vector<participant::BodyPose> &poses,
                                          std::vector<double> &out) const {
  // Section 2.3: the coupler moved the rigid surfaces; Eqs. (9-10) penalize them at t + dt.
  std::size_t expected = 0;
  for (const auto &body : bodies_)
    expected += body->coupled_motion() != nullptr;
  if (poses.size() != expected)
    throw proto::MalformedMessageError("FluidAdvance carries " + std::to_string(poses.size()) +
                                       " rigid-body poses; this case has " + std::to_string(expected) +
                                       " moving bodies");
  out.push_back(static_cast<double>(expected));
  for (const participant::BodyPose &pose : poses) {
    std::size_t b = 0;
    while (b < bodies_.size() && !(bodies_[b]->name() == pose.name && bodies_[b]->coupled_motion()))
      ++b;
    if (b == bodies_.size())
      throw proto::MalformedMessageError("FluidAdvance carries the pose of '" + pose.name +
                                         "', which is not a moving body of this case");
    out.push_back(static_cast<double>(b));
    const Eigen::Matrix3d r = pose.pose.linear();
    out.insert(out.end(), r.data(), r.data() + 9);
    const Vec3 origin = pose.pose.translation();
    for (const Vec3 &v : {origin, pose.origin_velocity_m_per_s, pose.angular_velocity_rad_per_s})
      out.insert(out.end(), v.data(), v.data() + 3);
  }
}

const double *OpenFoamFluidModel::unpack_rigid_poses(double time_s, const double *begin, const double *end) {
  const auto n_poses = static_cast<std::size_t>(*begin++);
  for (std::size_t i = 0; i < n_poses && begin + 19 <= end; ++i, begin += 19) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::Map<const Eigen::Matrix3d>(begin + 1);
    pose.translation() = Eigen::Map<const Vec3>(begin + 10);
    bodies_[static_cast<std::size_t>(begin[0])]->coupled_motion()->set(time_s, pose, Eigen::Map<const Vec3>(begin + 13),
                                                                       Eigen::Map<const Vec3>(begin + 16));
  }
  return begin;
}

void OpenFoamFluidModel::finish(const participant::RunEnd &end) {
  const bool success = end.success();
  message_.assign({success ? 1.0 : 0.0});
  broadcast(Command::finish, message_);
  log_lagrangian_stats();
  flow_.write_now();
  spdlog::info("fluid fields written at t = {} s ({})", flow_.time_s(), success ? "completed" : "stopped");
}

void OpenFoamFluidModel::broadcast(Command command, std::vector<double> &payload) {
  if (flow_.n_ranks() == 1)
    return;
  payload.insert(payload.begin(), static_cast<double>(command));
  collective([&] { flow_.broadcast_from_master(payload); });
  payload.erase(payload.begin());
}

// ---- the other ranks -----------------------------------------------------------------------

void OpenFoamFluidModel::follow() {
  while (true) {
    message_.clear();
    flow_.broadcast_from_master(message_); // not timed: mostly the wait for the master's next request
    const auto command = static_cast<Command>(static_cast<int>(message_.at(0)));
    const double *payload = message_.data() + 1;
    const std::size_t n = message_.size() - 1;
    switch (command) {
    case Command::start:
      do_start(std::vector<double>(payload, payload + n));
      break;
    case Command::interpolate: {
      positions_ = Eigen::Map<const PointArray>(payload, static_cast<Eigen::Index>(n / 3), 3);
      PointArray u;
      do_interpolate(u);
      break;
    }
    case Command::save_step:
      flow_.save_step_start();
      rate_at_step_start_ = penalization_rate_;
      break;
    case Command::restore_step:
      flow_.restore_step_start();
      penalization_rate_ = rate_at_step_start_;
      break;
    case Command::spread_at:
      positions_ = Eigen::Map<const PointArray>(payload, static_cast<Eigen::Index>(n / 3), 3);
      build_stencil();
      break;
    case Command::set_idle:
      idle_points_.assign(n, false);
      for (std::size_t k = 0; k < n; ++k)
        idle_points_[k] = payload[k] != 0.0;
      break;
    case Command::advance: {
      const double *forces = unpack_rigid_poses(payload[0] + payload[1], payload + 2, payload + n);
      force_density_ = Eigen::Map<const PointArray>(forces, static_cast<Eigen::Index>((payload + n - forces) / 3), 3);
      std::vector<rigid::BodyLoad> loads;
      do_advance(-1, payload[0], payload[1], loads); // rank 0 names the step
      break;
    }
    case Command::write_now:
      write_fields_on_every_rank();
      break;
    case Command::finish:
      log_lagrangian_stats();
      flow_.write_now();
      return;
    }
  }
}

// ---- collective work (every rank) ----------------------------------------------------------

template <class Operation> void OpenFoamFluidModel::collective(const Operation &operation) {
  if (flow_.n_ranks() == 1) {
    operation();
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  operation();
  lagrangian_stats_.collectives_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void OpenFoamFluidModel::log_lagrangian_stats() {
  // Collective (every rank at its finish): the master logs every rank's figures. The other
  // ranks' broadcasts are not timed (they wait there for the master's next request).
  const int n_ranks = flow_.n_ranks();
  if (n_ranks == 1)
    return;
  const double steps = std::max<double>(1.0, static_cast<double>(lagrangian_stats_.interpolations));
  std::vector<double> figures(2 * static_cast<std::size_t>(n_ranks), 0.0);
  figures[2 * static_cast<std::size_t>(flow_.rank())] = 1e3 * lagrangian_stats_.collectives_s / steps;
  figures[2 * static_cast<std::size_t>(flow_.rank()) + 1] =
      lagrangian_stats_.points_seen == 0 ? 0.0
                                         : 100.0 * static_cast<double>(lagrangian_stats_.points_skipped) /
                                               static_cast<double>(lagrangian_stats_.points_seen);
  flow_.sum_over_ranks(figures.data(), figures.size());
  if (flow_.rank() != 0 || lagrangian_stats_.points_seen == 0)
    return;
  for (int r = 0; r < n_ranks; ++r)
    spdlog::info("MPI rank {} of {}: Lagrangian data (broadcasts from rank 0, reductions over the ranks, waits "
                 "included) {:.3f} ms a step over {} steps; nearest-cell searches skipped (no cell of this rank "
                 "within a kernel's reach) for {:.1f} % of the points",
                 r, n_ranks, figures[2 * static_cast<std::size_t>(r)], lagrangian_stats_.interpolations,
                 figures[2 * static_cast<std::size_t>(r) + 1]);
}

void OpenFoamFluidModel::do_start(const std::vector<double> &point_measures) {
  point_measures_ =
      Eigen::Map<const Eigen::VectorXd>(point_measures.data(), static_cast<Eigen::Index>(point_measures.size()));
}

void OpenFoamFluidModel::kernel_widths(Eigen::VectorXd &widths_m) {
  // Eq. (6): h is the size of the cell nearest to each point, over all ranks (lowest rank on
  // ties), so every rank spreads and interpolates with the same kernel.
  const Eigen::Index n = positions_.rows();
  if (skip_beyond_m_ < 0.0) {
    local_max_width_m_ = cells_.n_cells() > 0 ? cells_.sizes_m().maxCoeff() : 0.0;
    // A kernel reaches cell centres within support_radius h <= support_radius h_max of a point
    // along each axis, so within sqrt(3) support_radius h_max.
    double negative_max = -local_max_width_m_;
    collective([&] { flow_.min_over_ranks(&negative_max, 1); });
    skip_beyond_m_ = std::sqrt(3.0) * ibm::PeskinKernel::support_radius * -negative_max;
  }
  // A rank whose cell centres all lie farther than skip_beyond_m_ from a point skips its
  // nearest-cell query and reports the distance to its centres' box, a lower bound. If some
  // centre of another rank lies within skip_beyond_m_, that rank still wins the point. If
  // none does, no kernel of width <= h_max touches any cell: the point gets no pairs whatever
  // its width, exactly as with the true nearest cell, so only a positive width is needed.
  Eigen::VectorXd distance(n), local_width(n);
  std::size_t skipped = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!idle_points_.empty() && idle_points_[static_cast<std::size_t>(k)]) { // no query, no pairs
      distance[k] = 0.0;
      local_width[k] = 0.0;
      continue;
    }
    const auto nearest = index().nearest_within(positions_.row(k).transpose(), skip_beyond_m_);
    distance[k] = nearest.distance_m;
    local_width[k] = nearest.cell >= 0 ? cells_.size_m(nearest.cell) : local_max_width_m_;
    skipped += nearest.cell < 0 && cells_.n_cells() > 0;
  }
  lagrangian_stats_.points_skipped += skipped;
  lagrangian_stats_.points_seen += static_cast<std::size_t>(n);
  Eigen::VectorXd best = distance;
  collective([&] { flow_.min_over_ranks(best.data(), static_cast<std::size_t>(n)); });
  Eigen::VectorXd owner(n);
  for (Eigen::Index k = 0; k < n; ++k)
    owner[k] = distance[k] == best[k] ? flow_.rank() : std::numeric_limits<double>::infinity();
  collective([&] { flow_.min_over_ranks(owner.data(), static_cast<std::size_t>(n)); });
  widths_m.resize(n);
  for (Eigen::Index k = 0; k < n; ++k)
    widths_m[k] = owner[k] == flow_.rank() ? local_width[k] : 0.0;
  collective([&] { flow_.sum_over_ranks(widths_m.data(), static_cast<std::size_t>(n)); });
}

void OpenFoamFluidModel::do_interpolate(PointArray &u_m_per_s) {
  ++lagrangian_stats_.interpolations;
  build_stencil();
  flow_.cell_velocities(cell_velocity_);
  if (config_.interpolation == InterpolationChoice::kernel) {
    u_m_per_s = stencil_->interpolate(cell_velocity_); // this rank's part of the kernel sum
    collective([&] { flow_.sum_over_ranks(u_m_per_s.data(), static_cast<std::size_t>(u_m_per_s.size())); });
    return;
  }
  nearest_ = std::make_unique<ibm::NearestCells>(index(), positions_);
  ibm::CellGradientArray gradients;
  flow_.cell_velocity_gradients(gradients);
  u_m_per_s = ibm::ClosestCellLinear(cells_, *nearest_).interpolate(positions_, cell_velocity_, gradients);
}

void OpenFoamFluidModel::build_stencil() {
  Eigen::VectorXd widths;
  kernel_widths(widths);
  if (!stencil_)
    stencil_ = std::make_unique<ibm::KernelStencil>(index(), PointArray(0, 3), Eigen::VectorXd(0));
  stencil_->rebuild(index(), positions_, widths, idle_points_); // reuses last step's arrays
  if (config_.normalise_kernel) {
    Eigen::VectorXd sums = stencil_->weight_sums();
    collective([&] { flow_.sum_over_ranks(sums.data(), static_cast<std::size_t>(sums.size())); });
    stencil_->normalise_weights(sums);
  }
}

void OpenFoamFluidModel::do_advance(long step, double time_s, double dt_s, std::vector<rigid::BodyLoad> &loads) {
  // Eq. (8) at the points of this step's interpolation (X^n): N/m^2 x m^2 -> N/m^3 per cell,
  // then per unit density for OpenFOAM's kinematic momentum equation (Eq. 1: +f_fsi).
  acceleration_ = stencil_->spread(force_density_, point_measures_) / config_.density_kg_per_m3;
  flow_.set_fsi_acceleration(acceleration_);
  step_flow(step, time_s, dt_s, loads);
}

void OpenFoamFluidModel::step_flow(long step, double time_s, double dt_s, std::vector<rigid::BodyLoad> &loads) {
  using common::Clock;
  using common::seconds_since;
  const double t_next = time_s + dt_s;
  if (dt_s > checked_dt_s_ * (1.0 + 1e-9)) // a smaller step only lowers the viscous number
    check_time_step(dt_s);
  timings_ = {};
  auto start = Clock::now();
  flow_.start_step(dt_s); // a moving mesh moves to t_next: the bodies are penalized where its cells are then
  if (flow_.mesh_moves())
    follow_moving_mesh();
  timings_.fluid_solve_s = seconds_since(start);
  start = Clock::now();
  if (!bodies_.empty())
    penalize_rigid_bodies(t_next, dt_s);
  if (!bodies_.empty() && flow_.mesh_moves())
    check_bodies_on_moving_mesh(t_next);
  timings_.penalization_s = seconds_since(start);
  start = Clock::now();
  flow_.advance(dt_s);
  timings_.fluid_solve_s += seconds_since(start);
  if (const long cut_off = flow_.cut_off_cells(); cut_off > 0 && (++cut_off_steps_ == 1 || cut_off_steps_ % 1000 == 0))
    spdlog::info("t = {} s: {} free cell(s) cut off by the bodies and walls from every open boundary, their pressure "
                 "held (docs/model.md, interface_flux: body_normal); {} step(s) so far",
                 t_next, cut_off, cut_off_steps_);
  if (!bodies_.empty()) {
    double transpiration[2] = {0.0, 0.0};
    flow_.immersed_transpiration(transpiration[0], transpiration[1]);
    flow_.sum_over_ranks(transpiration, 2);
    switching_.transpiration_m3_per_s = transpiration[0];
    switching_.transpiration_power_w = config_.density_kg_per_m3 * transpiration[1];
  }
  if (bodies_.empty())
    return;
  start = Clock::now();
  flow_.penalization_acceleration(penalization_acceleration_);
  penalization_force_ = penalization_acceleration_ * config_.density_kg_per_m3; // N/m^3 on the fluid
  held_fluid_load_density();
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    loads.push_back(rigid_body_load(b, t_next));
  timings_.loads_s = seconds_since(start);
  // Every rank has the summed loads: all of them stop at the same step.
  if (const std::string problem = runaway_loads_.observe(step, t_next, body_names(), loads); !problem.empty())
    throw std::runtime_error(problem + "; this step's fields are written when the run stops");
}

void OpenFoamFluidModel::check_time_step(double dt_s) {
  // Collective: every rank computes the same answer, so all refuse together.
  const ViscousNumber d = flow_.max_viscous_number(dt_s);
  const PisoSettings piso = flow_.piso_settings();
  const double limit = PisoLimit::measured_limit(piso);
  spdlog::info("viscous number nu_eff dt sum 1/dx^2 at dt = {:.6g} s: at most {:.3g}, in the cell at ({:.4g}, {:.4g}, "
               "{:.4g}) m; PIMPLE with momentumPredictor {}, nCorrectors {}, nOuterCorrectors {}: {}",
               dt_s, d.value, d.where_m.x(), d.where_m.y(), d.where_m.z(), piso.momentum_predictor ? "yes" : "no",
               piso.correctors, piso.outer_correctors,
               std::isfinite(limit) ? fmt::format("stable below {:.3g} (measured)", limit) : "no known limit");
  if (const std::string refusal = PisoLimit::refusal(piso, d, dt_s); !refusal.empty()) {
    if (config_.viscous_limit == ViscousLimitChoice::refuse)
      throw common::UserError(refusal + " (fluid.openfoam.viscous_limit: warn runs it anyway)");
    spdlog::warn("{} (fluid.openfoam.viscous_limit: warn: running anyway)", refusal);
  }
  checked_dt_s_ = dt_s;
}

std::vector<std::string> OpenFoamFluidModel::body_names() const {
  std::vector<std::string> names;
  for (const auto &body : bodies_)
    names.push_back(body->name());
  return names;
}

std::vector<rigid::BodyLoad> OpenFoamFluidModel::advance_without_structure(long step, double time_s, double dt_s) {
  if (acceleration_.rows() != cells_.n_cells()) // no structure: no FSI source
    flow_.set_fsi_acceleration(acceleration_ = PointArray::Zero(cells_.n_cells(), 3));
  std::vector<rigid::BodyLoad> loads;
  step_flow(step, time_s, dt_s, loads);
  return loads;
}

const ibm::CellIndex &OpenFoamFluidModel::index() {
  if (!index_)
    index_ = std::make_unique<ibm::CellIndex>(cells_);
  return *index_;
}

void OpenFoamFluidModel::follow_moving_mesh() {
  index_.reset(); // borrows cells_: rebuilt at the next query, on the moved centres
  cells_ = ibm::EulerianCells(flow_.cell_centres_m(), flow_.cell_volumes_m3());
  for (auto &indicator : indicators_)
    indicator->move_cells(cells_.centres_m());
}

void OpenFoamFluidModel::check_bodies_on_moving_mesh(double time_s) {
  const std::size_t n = bodies_.size();
  static_inside_centres_m_.resize(n);
  // Per body, the largest distance (m): a static body's inside cell from where it was at the
  // first step; a carried body's cell from where it was in the body's frame.
  std::vector<double> moved(n, 0.0);
  std::vector<Vec3> where(n, Vec3::Zero());
  for (std::size_t b = 0; b < n; ++b) {
    if (!bodies_[b]->declared_motion().is_static()) {
      moved[b] = indicators_[b]->carried_drift_m();
      continue;
    }
    const auto &inside = indicators_[b]->inside_cells();
    PointArray &first = static_inside_centres_m_[b];
    if (first.rows() == 0 && !inside.empty()) {
      first.resize(static_cast<Eigen::Index>(inside.size()), 3);
      for (std::size_t i = 0; i < inside.size(); ++i)
        first.row(static_cast<Eigen::Index>(i)) = cells_.centres_m().row(inside[i]);
    }
    for (std::size_t i = 0; i < inside.size(); ++i) {
      const Vec3 now = cells_.centres_m().row(inside[i]).transpose();
      const double d = (now - first.row(static_cast<Eigen::Index>(i)).transpose()).norm();
      if (d > moved[b]) {
        moved[b] = d;
        where[b] = now;
      }
    }
  }
  std::vector<double> largest(n);
  for (std::size_t b = 0; b < n; ++b)
    largest[b] = -moved[b];
  flow_.min_over_ranks(largest.data(), n);
  for (std::size_t b = 0; b < n; ++b) {
    // Round-off: OpenFOAM turns the points, the cell centres follow (1e-16 relative).
    const double distance = -largest[b];
    if (distance <= 1e-9 * std::max(1.0, bodies_[b]->body_box_m().diagonal().norm()))
      continue;
    if (bodies_[b]->declared_motion().is_static())
      throw common::UserError(fmt::format(
          "rigid body '{}' is static but covers cells the mesh moves (a cell inside it{} moved by {:.3g} m by t = {} "
          "s): a body held still must lie in the mesh's fixed cells, outside the cell zone that "
          "constant/dynamicMeshDict turns",
          bodies_[b]->name(),
          flow_.n_ranks() == 1 ? fmt::format(", now at ({:.4g}, {:.4g}, {:.4g}) m,", where[b].x(), where[b].y(),
                                             where[b].z())
                               : std::string(),
          distance, time_s));
    const Vec3 omega = indicators_[b]->rigid_velocity().angular_velocity_rad_per_s;
    throw common::UserError(fmt::format(
        "rigid body '{}' and its cells moved apart on a moving mesh by t = {} s: a cell it covers is {:.3g} m from "
        "where it was in the body's frame. A moving body must turn with its cells: constant/dynamicMeshDict's "
        "solidBody motion must be the body's own rotation, here omega = ({:.10g}, {:.10g}, {:.10g}) rad/s (the same "
        "axis, origin and rate to round-off: write both with all their digits), and its cell zone must hold the "
        "whole region the body sweeps",
        bodies_[b]->name(), time_s, distance, omega.x(), omega.y(), omega.z()));
  }
}

bool OpenFoamFluidModel::carries_cells(std::size_t body) const {
  return flow_.mesh_moves() && !bodies_[body]->declared_motion().is_static();
}

void OpenFoamFluidModel::penalize_rigid_bodies(double time_s, double dt_s) {
  // Section 2.3, first bullet: the rigid surfaces move first. chi and u_rib at t^{n+1}, where
  // the implicit penalization enforces u = u_rib.
  const Eigen::Index n = cells_.n_cells();
  // The cells the bodies covered at the step's start. On a process's first step: a restart's
  // from its set (so that it steps as the run it continues), none on a new run's.
  Eigen::VectorXd covered_before = penalization_rate_;
  const bool first_step = covered_before.size() != n;
  const bool before_known = !first_step || (restart_step_ > 0 && flow_.penalization_rate_at_start().size() == n);
  if (first_step)
    covered_before = before_known ? flow_.penalization_rate_at_start() : Eigen::VectorXd::Zero(n);
  penalization_rate_.setZero(n);
  rigid_velocity_.setZero(n, 3);
  for (auto &indicator : indicators_) {
    indicator->update(time_s);
    for (const auto c : indicator->candidate_cells()) {
      const double chi = indicator->chi()[c];
      if (chi <= 0.0)
        continue;
      penalization_rate_[c] = std::min(1.0, penalization_rate_[c] + chi);
      rigid_velocity_.row(c) += chi * indicator->body_velocity_m_per_s().row(c);
    }
  }
  for (std::size_t b = 0; first_step && b < bodies_.size(); ++b) // the mesh carries them: covered before too
    if (carries_cells(b))
      for (const auto c : indicators_[b]->inside_cells())
        covered_before[c] = 1.0;
  if (wall_distance_) {
    wall_distance_->update(time_s);
    flow_.set_immersed_walls(wall_distance_->distance_m(), penalization_rate_);
  }
  double switching[3] = {0.0, 0.0, 0.0}; // cells on, cells off, energy destroyed (J)
  if (before_known) {
    PointArray u_now;
    flow_.cell_velocities(u_now); // u^n, before this step's penalization
    for (Eigen::Index c = 0; c < n; ++c) {
      const bool now = penalization_rate_[c] > 0.0, before = covered_before[c] > 0.0;
      if (now && !before) {
        switching[0] += 1.0;
        const Vec3 u_rib = rigid_velocity_.row(c).transpose() / penalization_rate_[c];
        switching[2] +=
            0.5 * config_.density_kg_per_m3 * cells_.volumes_m3()[c] * (u_now.row(c).transpose() - u_rib).squaredNorm();
      } else if (before && !now) {
        switching[1] += 1.0;
      }
    }
  }
  if (config_.interface_flux == InterfaceFlux::body_normal) {
    // The body velocity's component along the surface normal at each penalized cell (the
    // closest point's normal): the velocity of the flux through its faces with free cells.
    PointArray u_normal = PointArray::Zero(n, 3);
    for (auto &indicator : indicators_) {
      const auto &body = indicator->body();
      const Eigen::Isometry3d pose = body.motion().pose_at(time_s);
      const Eigen::Isometry3d to_body = pose.inverse();
      for (const auto c : indicator->inside_cells()) {
        const Vec3 x = cells_.centres_m().row(c).transpose();
        const Vec3 normal = pose.linear() * body.surface().distance(to_body * x).normal_into_fluid;
        const Vec3 u = indicator->body_velocity_m_per_s().row(c).transpose();
        u_normal.row(c) = (u.dot(normal) * normal).transpose();
      }
    }
    flow_.set_interface_velocity(u_normal);
  }
  // The cells inside a body at both ends of the step hold the body's own fluid (held_fluid_load_density).
  held_.setZero(n);
  for (Eigen::Index c = 0; c < n; ++c)
    held_[c] = penalization_rate_[c] > 0.0 && covered_before[c] > 0.0 ? 1.0 : 0.0;
  flow_.sum_over_ranks(switching, 3);
  switching_ = {switching[0], switching[1], switching[2] / dt_s};
  penalization_rate_ /= config_.penalization_time_s;
  flow_.set_penalization(penalization_rate_, rigid_velocity_);
}

void OpenFoamFluidModel::held_fluid_load_density() {
  // The fluid of a body cell obeys rho Du/Dt = f_on_fluid + (what crosses the cell's faces), so
  // the reaction -sum f V over a body's cells is the load across its surface less the rate of
  // change of the momentum of the fluid it holds. That fluid stands for the body's own solid:
  // its momentum is the body's inertia, not a load of the flow on it (the correction of Uhlmann
  // 2005 for the internal fluid, here with the discrete ddt of each held cell). In a body
  // turning steadily it is the centripetal acceleration, no torque; but implicit Euler on cells
  // turning with the body keeps cos(omega dt) of their swirl each step, and the penalization
  // restores it: left in, the load reports rho omega^3 dt / 2 int r^2 dV of torque that no
  // surface carries (docs/model.md, "The fluid a body holds"). Cells the body took or left in
  // this step keep their momentum change in the load: the swept fluid's exchange.
  body_load_density_ = penalization_force_;
  double power_w = 0.0; // of the held fluid's inertia, at the body's velocity
  if (held_.size() == body_load_density_.rows() && (held_.array() > 0.0).any()) {
    flow_.cell_accelerations(cell_acceleration_);
    for (Eigen::Index c = 0; c < held_.size(); ++c) {
      if (held_[c] <= 0.0)
        continue;
      const Eigen::RowVector3d inertia = config_.density_kg_per_m3 * cell_acceleration_.row(c); // N/m^3
      body_load_density_.row(c) -= inertia;
      const double chi = penalization_rate_[c] * config_.penalization_time_s;
      power_w += cells_.volumes_m3()[c] * inertia.dot(rigid_velocity_.row(c)) / chi;
    }
  }
  flow_.sum_over_ranks(&power_w, 1);
  switching_.held_fluid_power_w = power_w;
}

rigid::BodyLoad OpenFoamFluidModel::rigid_body_load(std::size_t b, double time_s) {
  const auto &body = *bodies_[b];
  // Torque about the body's centre (the centre of its bounding box, carried by its motion).
  const Vec3 centre = body.motion().pose_at(time_s) * body.body_box_m().center();
  rigid::BodyLoad load = rigid::BodyLoads::from_source_on_fluid(*indicators_[b], cells_.centres_m(),
                                                                body_load_density_, cells_.volumes_m3(), centre);
  double sums[6] = {load.force_n.x(),    load.force_n.y(),    load.force_n.z(),
                    load.torque_n_m.x(), load.torque_n_m.y(), load.torque_n_m.z()};
  flow_.sum_over_ranks(sums, 6); // each rank has the part of the body in its cells
  load.force_n = Vec3(sums[0], sums[1], sums[2]);
  load.torque_n_m = Vec3(sums[3], sums[4], sums[5]);
  if (b < part_splitters_.size() && part_splitters_[b]) {
    auto &parts = part_loads_[b];
    // The pressure inside the body pushes its cells against each other: taken off each cell (the
    // total is unchanged), the closest part gets only what crosses the body's surface.
    flow_.interior_pressure_acceleration(interior_pressure_, interior_couple_);
    across_surface_ = body_load_density_ - config_.density_kg_per_m3 * interior_pressure_;
    interior_couple_ *= -config_.density_kg_per_m3; // the couple of the removed forces, taken off too
    parts = part_splitters_[b]->from_source_on_fluid(*indicators_[b], cells_.centres_m(), across_surface_,
                                                    cells_.volumes_m3(), centre, time_s, interior_couple_);
    sum_over_ranks(parts);
    part_staircase_loads_[b] = staircase_loads(b, time_s, centre);
  }
  return load;
}

std::vector<rigid::BodyLoad> OpenFoamFluidModel::staircase_loads(std::size_t b, double time_s, const Vec3 &centre) {
  const auto &body = *bodies_[b];
  flow_.interface_pressure_faces(interface_faces_);
  const Eigen::Index n = cells_.centres_m().rows();
  staircase_.setZero(n, 3);
  staircase_couple_.setZero(n, 3);
  in_body_.assign(static_cast<std::size_t>(n), 0);
  for (const auto c : indicators_[b]->inside_cells())
    in_body_[static_cast<std::size_t>(c)] = 1;
  const Eigen::Isometry3d pose = body.motion().pose_at(time_s);
  const Eigen::Isometry3d to_body = pose.inverse();
  const double rho = config_.density_kg_per_m3;
  for (const auto &face : interface_faces_) {
    if (!in_body_[static_cast<std::size_t>(face.body_cell)])
      continue;
    // The surface normal at the face centre's closest point: each face is projected on the
    // surface it lies on (a cell at an edge has faces on two).
    const Vec3 normal = pose.linear() * body.surface().distance(to_body * face.centre_m).normal_into_fluid;
    const Vec3 &f = face.pressure_m4_per_s2;
    const Vec3 off = f - f.dot(normal) * normal;
    const double volume = cells_.volumes_m3()[face.body_cell];
    const Vec3 arm = face.centre_m - cells_.centres_m().row(face.body_cell).transpose();
    // On the fluid (the reaction of the body's), per unit volume, with the torque of moving it
    // from the face to the cell centre.
    staircase_.row(face.body_cell) -= (rho / volume * off).transpose();
    staircase_couple_.row(face.body_cell) -= (rho / volume * arm.cross(off)).transpose();
  }
  auto parts = part_splitters_[b]->from_source_on_fluid(*indicators_[b], cells_.centres_m(), staircase_,
                                                        cells_.volumes_m3(), centre, time_s, staircase_couple_);
  sum_over_ranks(parts);
  return parts;
}

void OpenFoamFluidModel::sum_over_ranks(std::vector<rigid::BodyLoad> &parts) const {
  std::vector<double> sums; // each rank has the part of the body in its cells
  for (const auto &part : parts)
    for (int k = 0; k < 3; ++k) {
      sums.push_back(part.force_n(k));
      sums.push_back(part.torque_n_m(k));
    }
  flow_.sum_over_ranks(sums.data(), sums.size());
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (int k = 0; k < 3; ++k) {
      parts[p].force_n(k) = sums[6 * p + 2 * static_cast<std::size_t>(k)];
      parts[p].torque_n_m(k) = sums[6 * p + 2 * static_cast<std::size_t>(k) + 1];
    }
}

void OpenFoamFluidModel::split_loads_by_part() {
  part_splitters_.clear();
  part_loads_.assign(bodies_.size(), {});
  part_staircase_loads_.assign(bodies_.size(), {});
  for (const auto &body : bodies_)
    part_splitters_.push_back(body->part_names().size() >= 2 ? std::make_unique<rigid::BodyPartLoads>(*body)
                                                             : nullptr);
}

const std::vector<std::string> &OpenFoamFluidModel::part_names(std::size_t body) const {
  static const std::vector<std::string> none;
  return body < part_splitters_.size() && part_splitters_[body] ? part_splitters_[body]->part_names() : none;
}

} // namespace fsi::fluid
