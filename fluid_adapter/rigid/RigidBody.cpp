#include "fluid_adapter/rigid/RigidBody.hpp"

#include "geometry/StlIo.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace fsi::fluid::rigid {
namespace {

/// Voxel culling radius as a fraction of the body's bounding-box diagonal: voxels farther
/// than this from the surface are classified inside/outside once, so that most points skip
/// the exact test. Small enough for a fine voxel grid, large enough for short triangle lists.
constexpr double kCullingFraction = 4e-3;

} // namespace

RigidBody::RigidBody(std::string name, Soup soup, std::unique_ptr<Surface> surface,
                     std::shared_ptr<const motion::RigidMotion> motion)
    : name_(std::move(name)), soup_(std::move(soup)), surface_(std::move(surface)),
      motion_(std::move(motion)) {
  if (!motion_)
    throw std::invalid_argument("rigid body '" + name_ + "': no motion given (use StaticPose)");
  part_of_triangle_.assign(static_cast<std::size_t>(soup_.triangles.rows()), 0);
  for (Eigen::Index v = 0; v < soup_.vertices_m.rows(); ++v)
    body_box_m_.extend(Vec3(soup_.vertices_m.row(v).transpose()));
  surface_->prepare_culling(kCullingFraction * body_box_m_.diagonal().norm());
}

motion::CoupledMotion &RigidBody::take_poses_from_coupler() {
  if (motion_->is_static())
    throw std::logic_error("rigid body '" + name_ + "' is static: the coupler sends no pose for it");
  if (!coupled_motion_) {
    coupled_motion_ = std::make_shared<motion::CoupledMotion>(name_);
    declared_motion_ = motion_;
    motion_ = coupled_motion_;
  }
  return *coupled_motion_;
}

std::unique_ptr<RigidBody> RigidBody::from_stl(const std::string &name, const std::string &stl_path,
                                               std::shared_ptr<const motion::RigidMotion> motion) {
  geometry::RegionSoup regions = geometry::read_stl_regions(stl_path);
  auto surface = Surface::from_triangles(regions.soup.vertices_m, regions.soup.triangles,
                                         Surface::FluidSide::outside, stl_path);
  std::unique_ptr<RigidBody> body(new RigidBody(name, std::move(regions.soup), std::move(surface), std::move(motion)));
  body->part_names_ = std::move(regions.region_names);
  body->part_of_triangle_ = std::move(regions.region_of_triangle);
  return body;
}

std::unique_ptr<RigidBody> RigidBody::from_region_soup(const std::string &name, const geometry::RegionSoup &regions,
                                                       std::shared_ptr<const motion::RigidMotion> motion) {
  if (regions.region_of_triangle.size() != static_cast<std::size_t>(regions.soup.triangles.rows()))
    throw std::invalid_argument("rigid body '" + name + "': " + std::to_string(regions.region_of_triangle.size()) +
                                " region indices for " + std::to_string(regions.soup.triangles.rows()) + " triangles");
  for (const int r : regions.region_of_triangle)
    if (r < 0 || static_cast<std::size_t>(r) >= regions.region_names.size())
      throw std::invalid_argument("rigid body '" + name + "': region index " + std::to_string(r) + " of " +
                                  std::to_string(regions.region_names.size()) + " regions");
  auto body = from_soup(name, regions.soup, std::move(motion));
  body->part_names_ = regions.region_names;
  body->part_of_triangle_ = regions.region_of_triangle;
  return body;
}

std::unique_ptr<RigidBody> RigidBody::from_soup(const std::string &name, const Soup &soup,
                                                std::shared_ptr<const motion::RigidMotion> motion) {
  auto surface = Surface::from_triangles(soup.vertices_m, soup.triangles,
                                         Surface::FluidSide::outside, name);
  return std::unique_ptr<RigidBody>(new RigidBody(name, soup, std::move(surface), std::move(motion)));
}

} // namespace fsi::fluid::rigid
