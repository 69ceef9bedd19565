#include "fluid_adapter/rigid/BodyPartLoads.hpp"

#include <Eigen/Geometry>

#include <stdexcept>
#include <string>

namespace fsi::fluid::rigid {
namespace {

std::vector<geometry::TriangleBvh::Triangle> body_triangles(const RigidBody &body) {
  const auto &soup = body.soup();
  std::vector<geometry::TriangleBvh::Triangle> triangles(static_cast<std::size_t>(soup.triangles.rows()));
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      triangles[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)] =
          soup.vertices_m.row(soup.triangles(t, k)).transpose();
  return triangles;
}

} // namespace

BodyPartLoads::BodyPartLoads(const RigidBody &body) : body_(body), bvh_(body_triangles(body)) {}

std::vector<BodyLoad> BodyPartLoads::from_source_on_fluid(const BodyIndicator &indicator,
                                                          const PointArray &cell_centres_m,
                                                          const PointArray &force_on_fluid_n_per_m3,
                                                          const Eigen::VectorXd &cell_volumes_m3,
                                                          const Vec3 &torque_point_m, double time_s,
                                                          const PointArray &couple_on_fluid_n_per_m2) {
  if (&indicator.body() != &body_)
    throw std::invalid_argument("body parts of '" + body_.name() + "' asked for the cells of body '" +
                                indicator.body().name() + "'");
  // The totals check the sizes and name the body.
  (void)BodyLoads::from_source_on_fluid(indicator, cell_centres_m, force_on_fluid_n_per_m3, cell_volumes_m3,
                                        torque_point_m);
  const bool couples = couple_on_fluid_n_per_m2.rows() > 0;
  if (couples && couple_on_fluid_n_per_m2.rows() != cell_centres_m.rows())
    throw std::invalid_argument("body parts of '" + body_.name() + "': " +
                                std::to_string(couple_on_fluid_n_per_m2.rows()) + " couples for " +
                                std::to_string(cell_centres_m.rows()) + " cells");
  std::vector<BodyLoad> loads(body_.part_names().size());
  for (auto &load : loads)
    load.torque_point_m = torque_point_m;
  const Eigen::Isometry3d to_body = body_.motion().pose_at(time_s).inverse();
  const auto &part_of = body_.part_of_triangle();
  last_face_.resize(indicator.n_cells(), -1);
  std::int32_t previous = -1; // else the previous cell's: neighbouring indices are often neighbours
  for (const std::int32_t cell : indicator.inside_cells()) {
    const Vec3 centre_m = cell_centres_m.row(cell).transpose();
    std::int32_t &last = last_face_[static_cast<std::size_t>(cell)];
    const auto nearest = bvh_.nearest(to_body * centre_m, last >= 0 ? last : previous);
    last = previous = nearest.face;
    BodyLoad &load = loads[static_cast<std::size_t>(part_of[static_cast<std::size_t>(nearest.face)])];
    const Vec3 on_body_n = -cell_volumes_m3(cell) * force_on_fluid_n_per_m3.row(cell).transpose();
    load.force_n += on_body_n;
    load.torque_n_m += (centre_m - torque_point_m).cross(on_body_n);
    if (couples)
      load.torque_n_m -= cell_volumes_m3(cell) * couple_on_fluid_n_per_m2.row(cell).transpose();
  }
  return loads;
}

} // namespace fsi::fluid::rigid
