// The generated pump geometry (coarse mesh sizes, same CAD): both solids closed and outward as
// the project's STL reader sees them, their volumes against independent estimates, the
// impeller inside the casing, the inlet and outlet discs' areas, the blade as built.

#include "pump/ChannelLayout.hpp"
#include "pump/PumpGeometry.hpp"

#include "geometry/StlIo.hpp"
#include "geometry/TriangleMeshSurface.hpp"
#include "geometry/TriangleSoupChecks.hpp"
#include "tests/support/TempPath.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

namespace fsi::pump {
namespace {

struct Built {
  PumpDesign design;
  PumpGeometry geometry;
  std::filesystem::path dir;
};

/// The designs built: the single blade (the default), two blades, and the single blade with an
/// inlet sump (cases/rag-in-pump).
enum class Variant { single_blade, two_blades, single_blade_with_sump, single_channel };

std::string variant_name(Variant v) {
  switch (v) {
  case Variant::single_blade: return "SingleBlade";
  case Variant::two_blades: return "TwoBlades";
  case Variant::single_channel: return "SingleChannel";
  default: return "SingleBladeWithSump";
  }
}

void PrintTo(Variant v, std::ostream *os) { *os << variant_name(v); } // gtest's name of the parameter

const Built &built(Variant variant) {
  static std::map<Variant, Built> cache;
  auto found = cache.find(variant);
  if (found == cache.end()) {
    Built b;
    if (variant == Variant::single_channel) { // the shipped design, with the wear-ring neck
      b.design = PumpDesign::load(std::string(FSI_SOURCE_DIR) + "/pump/designs/single-channel.yaml");
      b.design.impeller.single_channel->neck_length_m = 0.02;
      b.design.inlet.suction_pipe_diameter_m = 0.14;
    }
    b.design.impeller.n_blades = variant == Variant::two_blades ? 2 : 1;
    if (variant == Variant::single_blade_with_sump) {
      b.design.inlet.sump_diameter_m = 0.2;
      b.design.inlet.sump_height_m = 0.12;
    }
    b.geometry = PumpGeometry::build(b.design, GeometryOptions::coarse());
    b.dir = fsi::test_support::temp_path("fsi-pump-geometry-", "-" + std::to_string(static_cast<int>(variant)));
    b.geometry.write(b.dir, b.design);
    found = cache.emplace(variant, std::move(b)).first;
  }
  return found->second;
}

double signed_volume(const geometry::TriangleSoup &soup) {
  double six = 0.0;
  for (int t = 0; t < soup.triangles.rows(); ++t) {
    const Vec3 a = soup.vertices_m.row(soup.triangles(t, 0)), b = soup.vertices_m.row(soup.triangles(t, 1)),
               c = soup.vertices_m.row(soup.triangles(t, 2));
    six += a.cross(b).dot(c);
  }
  return six / 6.0;
}

/// Discs, boss and blades (section area x channel height), the blade section from the camber
/// length: t int dr / sin(beta) plus the nose's half disc.
double estimated_impeller_volume(const PumpDesign &d) {
  const auto &i = d.impeller;
  const double r2 = 0.5 * i.outer_diameter_m, t = i.blade_thickness_m, b2 = i.outlet_width_m;
  const BladeCamber camber = d.blade_camber();
  double length = 0.0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    const double r = camber.inlet_radius_m() + (k + 0.5) * (r2 - camber.inlet_radius_m()) / n;
    length += (r2 - camber.inlet_radius_m()) / n / std::sin(camber.beta_rad(r));
  }
  const double blade = (t * length + M_PI * t * t / 8.0) * b2;
  const double hub = M_PI * r2 * r2 * t;
  const double shroud = M_PI * (r2 * r2 - 0.25 * i.eye_diameter_m * i.eye_diameter_m) * t;
  const double boss = M_PI * 0.25 * i.hub_diameter_m * i.hub_diameter_m * (1.0 + PumpDesign::hub_nose_depth) * b2;
  return hub + shroud + boss + i.n_blades * blade;
}

/// The channel inside D2 between the discs from its sections (each clipped to the block, the
/// integral of r dr dz dphi), the vane the block less it, the discs, the neck and the noses.
double estimated_channel_volume(const ChannelLayout &layout, double b2) {
  const double r2 = layout.outer_radius_m();
  const int n = 20000;
  double volume = 0.0;
  for (int k = 0; k < n; ++k) {
    const ChannelSection s = layout.section((k + 0.5) * layout.exit_phi_rad() / n);
    const double inner = std::min(s.inner_radius_m, r2), outer = std::min(s.outer_radius_m, r2);
    const double height = std::min(s.top_z_m, b2) - std::max(s.floor_z_m, 0.0);
    volume += 0.5 * (outer * outer - inner * inner) * height * layout.exit_phi_rad() / n;
  }
  return volume;
}

double estimated_channel_impeller_volume(const PumpDesign &d) {
  const auto &i = d.impeller;
  const auto &sc = *i.single_channel;
  const ChannelLayout layout(d);
  const double r2 = 0.5 * i.outer_diameter_m, t = sc.disc_thickness_m, b2 = i.outlet_width_m;
  const double r_eye = 0.5 * i.eye_diameter_m, r_boss = 0.5 * i.hub_diameter_m, nose = i.leading_edge_radius_m;
  const double neck_outer = 0.5 * d.inlet.suction_pipe_diameter_m - sc.wear_ring_clearance_m;
  const double vane = M_PI * r2 * r2 * b2 - estimated_channel_volume(layout, b2);
  const double discs = M_PI * r2 * r2 * t + M_PI * (r2 * r2 - r_eye * r_eye) * t;
  const double neck = M_PI * (neck_outer * neck_outer - r_eye * r_eye) * sc.neck_length_m;
  // below the shroud plane: the boss nose's cap and the leading edge's half cylinder
  const double radius = 0.98 * r_boss, depth = radius - 0.2 * r_boss;
  const double cap = M_PI * depth * depth * (3.0 * radius - depth) / 3.0;
  const double edge = 0.5 * M_PI * nose * nose * (r_eye - r_boss);
  return vane + discs + neck + cap + edge;
}

void BothSolidsAreClosedOutwardAndNamedByRegion(const Built &b) {
  for (const char *file : {"impeller.stl", "casing.stl"}) {
    const auto soup = geometry::read_stl((b.dir / file).string());
    EXPECT_NO_THROW(geometry::check_triangle_soup(soup, file));
    EXPECT_GT(signed_volume(soup), 0.0) << file;
  }
  b.geometry.impeller.surface.check_closed_and_outward("impeller");
  b.geometry.casing.surface.check_closed_and_outward("casing");
  for (const BuiltPart *part : {&b.geometry.impeller, &b.geometry.casing}) {
    for (std::size_t r = 0; r < part->surface.region_names.size(); ++r) {
      if (part->surface.region_names[r] != "blade_tip") { // the open impeller's only
        EXPECT_GT(part->surface.region_area_m2(static_cast<int>(r)), 0.0) << part->surface.region_names[r];
      }
    }
  }
  for (const BuiltPart *part : {&b.geometry.impeller, &b.geometry.casing})
    for (const int region : part->surface.triangle_regions)
      ASSERT_GE(region, 0);
}

void VolumesMatchIndependentEstimates(const Built &b) {
  const double impeller = b.geometry.impeller.surface.enclosed_volume_m3();
  if (b.design.impeller.single_channel) {
    EXPECT_NEAR(impeller, estimated_channel_impeller_volume(b.design), 0.03 * impeller);
    const double channel = b.geometry.channel->channel_volume_m3;
    EXPECT_NEAR(channel, estimated_channel_volume(ChannelLayout(b.design), b.design.impeller.outlet_width_m),
                0.03 * channel);
  } else {
    EXPECT_NEAR(impeller, estimated_impeller_volume(b.design), 0.03 * impeller);
  }
  EXPECT_NEAR(impeller, b.geometry.impeller.cad_volume_m3, 0.01 * impeller);
  const double casing = b.geometry.casing.surface.enclosed_volume_m3();
  EXPECT_NEAR(casing, b.geometry.casing.cad_volume_m3, 0.01 * casing);
}

void TheImpellerSitsInsideTheCasing(const Built &b) {
  const geometry::TriangleMeshSurface casing((b.dir / "casing.stl").string(),
                                             geometry::TriangleMeshSurface::FluidSide::inside);
  int outside = 0;
  for (const Vec3 &p : b.geometry.impeller.surface.vertices_m)
    outside += !casing.is_inside_mesh(p);
  EXPECT_EQ(outside, 0);
}

void InletAndOutletDiscsHaveTheirDesignAreas(const Built &b) {
  const RegionSurface &casing = b.geometry.casing.surface;
  const double inlet = M_PI * std::pow(b.design.inlet.inlet_diameter_m(), 2) / 4.0;
  const double outlet = M_PI * std::pow(b.design.volute.discharge_diameter_m, 2) / 4.0;
  EXPECT_NEAR(casing.region_area_m2(casing.region_index("inlet")), inlet, 0.01 * inlet);
  EXPECT_NEAR(casing.region_area_m2(casing.region_index("outlet")), outlet, 0.01 * outlet);
}

/// The pipe's wall, and with a sump its wall and the annulus of its roof around the pipe.
void TheSuctionWallIsThePipeAndTheSump(const Built &b) {
  const InletDesign &in = b.design.inlet;
  double expected = M_PI * in.suction_pipe_diameter_m * in.suction_pipe_length_m;
  if (in.has_sump())
    expected += M_PI * in.sump_diameter_m * in.sump_height_m +
                M_PI / 4.0 * (std::pow(in.sump_diameter_m, 2) - std::pow(in.suction_pipe_diameter_m, 2));
  const RegionSurface &casing = b.geometry.casing.surface;
  EXPECT_NEAR(casing.region_area_m2(casing.region_index("suction_wall")), expected, 0.02 * expected);
}

/// The casing as the collision model sees it (fluid inside, culled at the collision threshold):
/// every point of the water in the suction pipe, the sump and the eye, across the plane where
/// the pipe opens into the chamber, is on the fluid side at its true distance from the walls.
void TheWaterAtThePipesMouthIsFluidForTheCollisions(const Built &b) {
  geometry::TriangleMeshSurface casing((b.dir / "casing.stl").string(), geometry::TriangleMeshSurface::FluidSide::inside);
  casing.prepare_culling(0.004);
  const InletDesign &in = b.design.inlet;
  const double z_low = b.design.chamber_floor_z_m();
  const double pipe_r = 0.5 * in.suction_pipe_diameter_m;
  int wrong = 0, checked = 0;
  for (double z = z_low - 0.03; z <= z_low + 0.005; z += 0.00037)
    for (double r = 0.0; r < pipe_r - 0.005; r += 0.0023)
      for (double phi = 0.0; phi < 2 * M_PI; phi += 0.41) {
        const Vec3 p(r * std::cos(phi), r * std::sin(phi), z);
        const double d = casing.distance(p).signed_distance_m;
        ++checked;
        if (!(d > 0.0)) {
          if (++wrong <= 5)
            ADD_FAILURE() << "point (" << p.transpose() << ") m: signed distance " << d << " m";
        }
      }
  EXPECT_EQ(wrong, 0) << "of " << checked;
}

void TheBladeIsBuiltWithItsDesignWrapAndAngles(const Built &b) {
  if (b.design.impeller.single_channel)
    return;
  EXPECT_NEAR(b.geometry.blade.wrap_deg, b.design.impeller.wrap_angle_deg, 1.0);
  EXPECT_NEAR(b.geometry.blade.wrap_on_mesh_deg, b.design.impeller.wrap_angle_deg, 1.0);
  EXPECT_NEAR(b.geometry.blade.inlet_angle_deg, b.design.impeller.inlet_blade_angle_deg, 0.5);
  EXPECT_NEAR(b.geometry.blade.outlet_angle_deg, b.design.impeller.outlet_blade_angle_deg, 0.5);
}

/// Blades: the leading edge is the axial nose and the blades' flat bottom edge in the eye (they
/// reach below the shroud plane), the edge a rising rag meets crosswise. Its area facing the
/// inflow is at least the blade thickness times the eye's radius less the blade's inlet radius
/// (the bottom runs along the camber, longer than that), all within the eye; what `eye` keeps
/// facing the inflow is the boss's bottom, pi r_boss^2.
void TheBladesBottomInTheEyeIsTheirLeadingEdge(const Built &b) {
  if (b.design.impeller.single_channel || !b.design.impeller.closed)
    return;
  const RegionSurface &impeller = b.geometry.impeller.surface;
  const int edge = impeller.region_index("blade_leading_edge"), eye = impeller.region_index("eye");
  const double r_eye = 0.5 * b.design.impeller.eye_diameter_m, r_boss = 0.5 * b.design.impeller.hub_diameter_m;
  const double r1 = 0.5 * b.design.impeller.blade_inlet_diameter_m;
  double edge_facing = 0.0, eye_facing = 0.0;
  for (std::size_t t = 0; t < impeller.triangles.size(); ++t) {
    const auto &tri = impeller.triangles[t];
    const Vec3 &a = impeller.vertices_m[tri[0]], &p1 = impeller.vertices_m[tri[1]], &p2 = impeller.vertices_m[tri[2]];
    const Vec3 n = 0.5 * (p1 - a).cross(p2 - a);
    if (!(-n[2] > 0.99 * n.norm()))
      continue; // not facing the inflow (-z)
    if (impeller.triangle_regions[t] == edge) {
      edge_facing += n.norm();
      for (const int v : tri)
        EXPECT_LE(std::hypot(impeller.vertices_m[v][0], impeller.vertices_m[v][1]), r_eye + 1e-6);
    } else if (impeller.triangle_regions[t] == eye) {
      eye_facing += n.norm();
    }
  }
  EXPECT_GT(edge_facing, b.design.impeller.n_blades * b.design.impeller.blade_thickness_m * (r_eye - r1));
  EXPECT_NEAR(eye_facing, M_PI * r_boss * r_boss, 0.03 * M_PI * r_boss * r_boss);
}

/// A single channel's leading edge: its round nose runs across the eye from the boss to the
/// shroud's rim in the shroud plane, every vertex within the nose's radius of its axis (most on
/// it; the end cap at the rim, in the channel, inside), and it
/// meets the axial inflow crosswise (its area facing the inflow about its length times its
/// diameter).
void TheLeadingEdgeCrossesTheInflow(const Built &b) {
  if (!b.design.impeller.single_channel)
    return;
  const RegionSurface &impeller = b.geometry.impeller.surface;
  const int edge = impeller.region_index("blade_leading_edge");
  const double angle = b.geometry.channel->leading_edge_angle_deg * M_PI / 180.0;
  const Vec3 axis(std::cos(angle), std::sin(angle), 0.0);
  const double radius = b.design.impeller.leading_edge_radius_m;
  double lo = 1e300, hi = 0.0, facing = 0.0, on_radius = 0.0, count = 0.0;
  for (std::size_t t = 0; t < impeller.triangles.size(); ++t) {
    if (impeller.triangle_regions[t] != edge)
      continue;
    const auto &tri = impeller.triangles[t];
    const Vec3 &a = impeller.vertices_m[tri[0]], &p1 = impeller.vertices_m[tri[1]], &p2 = impeller.vertices_m[tri[2]];
    facing += std::max(0.0, -0.5 * (p1 - a).cross(p2 - a)[2]); // area x (n . -e_z) where it faces the inflow
    for (const int v : tri) {
      const Vec3 &p = impeller.vertices_m[v];
      const double along = p.dot(axis);
      const double distance = (p - along * axis).norm();
      EXPECT_LE(distance, radius + 2e-4);
      on_radius += std::abs(distance - radius) < 2e-4;
      ++count;
      lo = std::min(lo, along);
      hi = std::max(hi, along);
    }
  }
  const double r_boss = 0.5 * b.design.impeller.hub_diameter_m, r_eye = 0.5 * b.design.impeller.eye_diameter_m;
  EXPECT_GT(on_radius, 0.8 * count);
  EXPECT_LT(lo, r_boss + radius);
  EXPECT_GT(hi, r_eye - 1e-3);
  EXPECT_GT(facing, 0.8 * 2.0 * radius * (r_eye - r_boss - radius));
}

void TheCutWaterHasItsRoundNose(const Built &b) {
  const RegionSurface &casing = b.geometry.casing.surface;
  const int nose = casing.region_index("cut_water");
  const double radius = b.design.volute.cut_water_nose_radius_m;
  for (std::size_t t = 0; t < casing.triangles.size(); ++t)
    if (casing.triangle_regions[t] == nose)
      for (const int v : casing.triangles[t]) {
        const Vec3 &p = casing.vertices_m[v];
        EXPECT_NEAR(std::hypot(p[0] - b.geometry.nose_centre_xy_m[0], p[1] - b.geometry.nose_centre_xy_m[1]), radius,
                    1e-6);
      }
}

// One test per design: ctest runs each test in its own process, and the build is the cost.
class GeneratedPump : public testing::TestWithParam<Variant> {};

TEST_P(GeneratedPump, IsClosedOutwardInsideTheCasingAndAsDesigned) {
  const Built &b = built(GetParam());
  {
    SCOPED_TRACE("BothSolidsAreClosedOutwardAndNamedByRegion");
    BothSolidsAreClosedOutwardAndNamedByRegion(b);
  }
  {
    SCOPED_TRACE("VolumesMatchIndependentEstimates");
    VolumesMatchIndependentEstimates(b);
  }
  {
    SCOPED_TRACE("TheImpellerSitsInsideTheCasing");
    TheImpellerSitsInsideTheCasing(b);
  }
  {
    SCOPED_TRACE("InletAndOutletDiscsHaveTheirDesignAreas");
    InletAndOutletDiscsHaveTheirDesignAreas(b);
  }
  {
    SCOPED_TRACE("TheWaterAtThePipesMouthIsFluidForTheCollisions");
    TheWaterAtThePipesMouthIsFluidForTheCollisions(b);
  }
  {
    SCOPED_TRACE("TheBladesBottomInTheEyeIsTheirLeadingEdge");
    TheBladesBottomInTheEyeIsTheirLeadingEdge(b);
  }
  {
    SCOPED_TRACE("TheSuctionWallIsThePipeAndTheSump");
    TheSuctionWallIsThePipeAndTheSump(b);
  }
  {
    SCOPED_TRACE("TheBladeIsBuiltWithItsDesignWrapAndAngles");
    TheBladeIsBuiltWithItsDesignWrapAndAngles(b);
  }
  {
    SCOPED_TRACE("TheLeadingEdgeCrossesTheInflow");
    TheLeadingEdgeCrossesTheInflow(b);
  }
  {
    SCOPED_TRACE("TheCutWaterHasItsRoundNose");
    TheCutWaterHasItsRoundNose(b);
  }
}

INSTANTIATE_TEST_SUITE_P(Designs, GeneratedPump,
                         testing::Values(Variant::single_blade, Variant::two_blades, Variant::single_blade_with_sump,
                                         Variant::single_channel),
                         [](const testing::TestParamInfo<Variant> &info) { return variant_name(info.param); });

} // namespace
} // namespace fsi::pump
