#pragma once
// A synthetic pump in the frame of GeometryChecks, made of prisms whose measures are known:
// the impeller is the shroud ring (R_eye..R2, -t..0), the hub disc (0..R2, b2..b2 + t) and two
// radial blades between them (0.5 mm short of both discs); the casing is a disc of radius
// 0.16 m from z = -0.06 to 0.12 m, so its section at the cut-water angle 0 beyond r3 = 0.105 m
// is the rectangle (0.16 - 0.105) x 0.18 m = 99 cm^2 (a corner of the polygon lies on +x).

#include "geometry/MeshGenerators.hpp"
#include "geometry/RegionSoup.hpp"
#include "pump/GeometryChecks.hpp"

namespace fsi::pump::testing {

constexpr double r2 = 0.1, eye = 0.05, b2 = 0.05, t = 0.008, r3 = 0.105;
constexpr double casing_radius = 0.16, casing_bottom = -0.06, casing_top = 0.12;
constexpr int n_around = 128;

inline PumpGeometryFrame frame() {
  PumpGeometryFrame f;
  f.impeller_radius_m = r2;
  f.eye_radius_m = eye;
  f.outlet_width_m = b2;
  f.disc_thickness_m = t;
  f.volute_base_radius_m = r3;
  f.cut_water_angle_rad = 0.0;
  f.design_throat_area_m2 = 100e-4;
  return f;
}

/// The limits of the tests: a coarse free-passage grid (h = 4 mm) keeps them fast.
inline GeometryCheckLimits limits(double unit_scale = 1.0) {
  GeometryCheckLimits l;
  l.unit_scale = unit_scale;
  l.passage_spacing_m = 0.004;
  return l;
}

/// Every triangle in one region of the given name.
inline geometry::RegionSoup one_region(geometry::TriangleSoup soup, const std::string &name) {
  const auto n = static_cast<std::size_t>(soup.triangles.rows());
  return {std::move(soup), {name}, std::vector<int>(n, 0)};
}

inline geometry::RegionSoup impeller() {
  using geometry::append_soup;
  using geometry::make_box;
  using geometry::make_ring;
  geometry::TriangleSoup soup =
      append_soup(make_ring(Vec3(0, 0, -t), eye, r2, t, n_around), make_ring(Vec3(0, 0, b2), 0.0, r2, t, n_around));
  soup = append_soup(soup, make_box(Vec3(0.03, -0.004, 0.0005), Vec3(0.098, 0.004, b2 - 0.0005)));
  soup = append_soup(soup, make_box(Vec3(-0.098, -0.004, 0.0005), Vec3(-0.03, 0.004, b2 - 0.0005)));
  return one_region(soup, "hub");
}

inline geometry::RegionSoup casing(double radius = casing_radius, double bottom = casing_bottom) {
  return one_region(geometry::make_ring(Vec3(0, 0, bottom), 0.0, radius, casing_top - bottom, n_around), "volute_wall");
}

} // namespace fsi::pump::testing
