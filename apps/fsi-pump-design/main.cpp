// fsi-pump-design: checks a pump design file and prints what the design rules expect of it:
// the duty at its design flow rate (specific speed, head, head and flow coefficients, power,
// torque) and the volute its constant-angular-momentum rule gives (outer radius of the spiral
// every 45 degrees, throat area), each against the plausibility bands of the design rules.
//   fsi-pump-design DESIGN.yaml
//   fsi-pump-design DESIGN.yaml --write DIR   also generate the geometry: DIR/impeller.stl,
//                                     DIR/casing.stl (multi-solid ASCII STL, named regions),
//                                     DIR/geometry.yaml (the report) and DIR/geometry.png
//   fsi-pump-design --schema          the design-file reference (docs/pump-design.md)
//   fsi-pump-design DESIGN.yaml --check-stl IMPELLER.stl CASING.stl [--unit-scale S] [--report FILE]
//                                     the generated STL files' checks (pump/GeometryChecks.hpp) as a
//                                     table, and as YAML in FILE
// Exit codes: 0 valid, 2 bad input (a failed geometry check included).

#include "pump/BladeInlet.hpp"
#include "pump/BladeOutlet.hpp"
#include "pump/ChannelLayout.hpp"
#include "pump/DutyEstimate.hpp"
#include "pump/GeometryChecks.hpp"
#include "pump/PhysicalConstants.hpp"
#include "pump/PumpDesign.hpp"
#include "pump/PumpGeometry.hpp"
#include "pump/VoluteSizing.hpp"
#include "common/ExitCodes.hpp"
#include "common/GuardedMain.hpp"
#include "common/Logging.hpp"
#include "common/UserError.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

namespace {

std::string band(double value, double lo, double hi) {
  return value >= lo && value <= hi ? "within " + fmt::format("{:.4g}-{:.4g}", lo, hi)
                                    : "OUTSIDE " + fmt::format("{:.4g}-{:.4g}", lo, hi);
}

/// A single channel: its leading edge's inflow angle and a rotating-channel-jet estimate of the
/// swirl it leaves (c_u2 = u2 - w2 cos beta_2, w2 = Q / A2), to be checked by the flow solver.
void channel_report(const fsi::pump::PumpDesign &design, double duty_head_m) {
  const auto &op = design.operation;
  const auto &imp = design.impeller;
  const fsi::pump::ChannelLayout layout(design);
  const double q = op.design_flow_rate_m3_per_s, omega = op.rotation_rate_rad_per_s, deg = M_PI / 180.0;
  const double r_mean = 0.5 * (layout.boss_radius_m() + layout.eye_radius_m());
  const double eye_area = M_PI * (std::pow(layout.eye_radius_m(), 2) - std::pow(layout.boss_radius_m(), 2));
  const double c1m = q / eye_area, flow_angle = std::atan2(c1m, omega * r_mean) / deg;
  spdlog::info("single channel: leading edge from r = {:.4g} to {:.4g} m across the eye, {:.1f} deg along the wrap; "
               "inflow c1m = {:.3g} m/s at Q = {:.4g} m^3/s meets it at {:.1f} deg against its {:.4g} deg at r = "
               "{:.3g} m (no incidence at Q = {:.3g} m^3/s)",
               layout.boss_radius_m(), layout.eye_radius_m(), layout.leading_edge_phi_rad() / deg, c1m, q, flow_angle,
               imp.inlet_blade_angle_deg, r_mean,
               std::tan(imp.inlet_blade_angle_deg * deg) * omega * r_mean * eye_area);
  if (imp.single_channel->mouth_roof_height_m) {
    // The eye's water enters through the mouth's part of the eye at c_m = Q / that area and
    // keeps its relative speed along the channel where the roof's angle is atan(c_m / u).
    const double mouth_area = eye_area * layout.mouth_end_rad() / (2.0 * M_PI), roof = layout.mouth_roof_angle_deg();
    spdlog::info("  mouth: roof from {:.3g} m above the shroud plane at the back wall to the hub disc over {:.4g} deg, "
                 "at {:.1f} deg at r = {:.3g} m; the eye's water through the mouth ({:.3g} cm^2) meets it at that "
                 "angle at Q = {:.3g} m^3/s",
                 *imp.single_channel->mouth_roof_height_m, layout.mouth_end_rad() / deg, roof, r_mean,
                 1e4 * mouth_area, std::tan(roof * deg) * omega * r_mean * mouth_area);
  }
  const double u2 = omega * 0.5 * imp.outer_diameter_m, a2 = layout.exit_area_m2();
  const double w2 = q / a2, cu2 = u2 - w2 * std::cos(imp.outlet_blade_angle_deg * deg);
  spdlog::info("  exit area {:.4g} cm^2 (normal to the channel), w2 = {:.3g} m/s, c_u2 = u2 - w2 cos beta_2 = {:.3g} "
               "m/s: Euler head {:.3g} m (an estimate; the duty above needs H / eta_h = {:.3g} m); smallest section "
               "side {:.3g} m",
               1e4 * a2, w2, cu2, u2 * cu2 / fsi::pump::g_m_per_s2, duty_head_m / op.hydraulic_efficiency,
               layout.smallest_section_side_m());
  // A sphere rising through the eye into the mouth passes between the boss and the eye's rim, and
  // then through the channel's sections: neither bound can the generated free passage exceed.
  const double annulus = layout.eye_radius_m() - layout.boss_radius_m();
  spdlog::info("  free passage at most {:.3g} m: the eye's annulus from the boss to its rim ({:.3g} m) and the smallest "
               "section side (the geometry checks measure it with a sphere)",
               std::min(annulus, layout.smallest_section_side_m()), annulus);
}

int report(const fsi::pump::PumpDesign &design) {
  const auto &op = design.operation;
  const auto &imp = design.impeller;
  const auto duty =
      fsi::pump::estimate_duty_for_flow(op.rotation_rate_rad_per_s, imp.outer_diameter_m, op.design_flow_rate_m3_per_s);
  spdlog::info("duty at Q = {:.4g} m^3/s, omega = {:.4g} rad/s ({:.0f} rpm), D2 = {:.4g} m (Gülich's psi_opt):",
               op.design_flow_rate_m3_per_s, op.rotation_rate_rad_per_s, fsi::pump::rpm(op.rotation_rate_rad_per_s),
               imp.outer_diameter_m);
  spdlog::info("  specific speed n_q = {:.3g}; tip speed u2 = {:.4g} m/s", duty.specific_speed, duty.tip_speed_m_per_s);
  spdlog::info("  head H = {:.3g} m; psi = gH/u2^2 = {:.3g} ({}); phi = Q/(omega R2^3) = {:.3g}", duty.head_m,
               duty.head_coefficient, band(duty.head_coefficient, 0.3, 0.5), duty.flow_coefficient);
  spdlog::info("  hydraulic power {:.4g} W; shaft torque {:.3g} N m at eta = 0.8, {:.3g} N m at eta = 0.6",
               duty.hydraulic_power_w, duty.torque_n_m(0.8, op.rotation_rate_rad_per_s),
               duty.torque_n_m(0.6, op.rotation_rate_rad_per_s));
  const fsi::pump::VoluteSizing volute = fsi::pump::size_volute(design);
  std::string radii;
  for (int deg = 45; deg <= 360; deg += 45)
    radii += fmt::format("{}{:.4g}", radii.empty() ? "" : ", ", volute.outer_radius_m(deg * M_PI / 180.0));
  spdlog::info("volute (constant angular momentum, c_u2 r2 = {:.4g} m^2/s, {}): outer radius every 45 deg {} m",
               volute.angular_momentum_m2_per_s(),
               op.design_swirl_m2_per_s > 0.0 ? "operation.design_swirl_m2_per_s" : "the duty's head and eta_h", radii);
  const fsi::pump::ThroatBand throat = fsi::pump::throat_band(design);
  spdlog::info("  throat area {:.4g} cm^2 ({} cm^2 for this duty: throat velocity c3 = {:.3g}-{:.3g} sqrt(2 g H))",
               1e4 * volute.throat_area_m2(),
               band(1e4 * volute.throat_area_m2(), 1e4 * throat.min_area_m2, 1e4 * throat.max_area_m2),
               fsi::pump::ThroatBand::min_velocity_ratio, fsi::pump::ThroatBand::max_velocity_ratio);
  if (imp.single_channel) {
    channel_report(design, duty.head_m);
    return fsi::common::exit_code_success;
  }
  const auto inlet = fsi::pump::blade_inlet_at(design, op.design_flow_rate_m3_per_s);
  spdlog::info("blade inlet at Q = {:.4g} m^3/s: r1 = {:.4g} m, u1 = {:.3g} m/s, c1m = {:.3g} m/s (b1 = b2); flow angle "
               "beta_1 = {:.1f} deg against the blade's {:.4g} deg: incidence {:.1f} deg ({} deg)",
               op.design_flow_rate_m3_per_s, inlet.radius_m, inlet.blade_speed_m_per_s, inlet.meridional_m_per_s,
               inlet.flow_angle_deg, imp.inlet_blade_angle_deg, inlet.incidence_deg,
               band(inlet.incidence_deg, 0.0, 6.0));
  spdlog::info("  inlet throat {:.3g} cm^2, w1 = {:.3g} m/s = {:.2g} u1; no incidence at Q = {:.3g} m^3/s "
               "({:.2g} Q_design)",
               1e4 * inlet.throat_area_m2, inlet.throat_velocity_m_per_s,
               inlet.throat_velocity_m_per_s / inlet.blade_speed_m_per_s, inlet.shockless_flow_rate_m3_per_s,
               inlet.shockless_flow_rate_m3_per_s / op.design_flow_rate_m3_per_s);
  const auto outlet = fsi::pump::blade_outlet_at(design, op.design_flow_rate_m3_per_s);
  spdlog::info("blade outlet at Q = {:.4g} m^3/s: {} blade(s), Wiesner's slip factor {:.3g}, c2m = {:.3g} m/s, "
               "c_u2 = {:.3g} m/s: Euler head {:.3g} m, torque {:.3g} N m; the duty above needs H / eta_h = {:.3g} m "
               "({:.2g} times; Gülich's psi_opt is for 5-7 blades)",
               op.design_flow_rate_m3_per_s, imp.n_blades, outlet.slip_factor, outlet.meridional_m_per_s,
               outlet.swirl_m_per_s, outlet.euler_head_m, outlet.torque_n_m, duty.head_m / op.hydraulic_efficiency,
               duty.head_m / op.hydraulic_efficiency / outlet.euler_head_m);
  return fsi::common::exit_code_success;
}

/// --check-stl: every check of the two files, the table on stdout, the YAML in report_file.
int check_stl(const fsi::pump::PumpDesign &design, const std::vector<std::string> &files, double unit_scale,
              const std::string &report_file) {
  fsi::pump::GeometryCheckLimits limits;
  limits.unit_scale = unit_scale;
  const fsi::pump::GeometryChecks checks(fsi::pump::PumpGeometryFrame::from_design(design), limits);
  const fsi::pump::GeometryCheckReport report = checks.run(files.at(0), files.at(1));
  std::cout << report.table();
  if (!report_file.empty() && !(std::ofstream(report_file) << report.to_yaml()))
    throw fsi::common::UserError("cannot write the check report '" + report_file + "'; check that its folder exists.");
  if (const auto *failed = report.first_failure()) {
    spdlog::error("{}", failed->message);
    return fsi::common::exit_code_bad_input;
  }
  spdlog::info("{} and {}: every check passed", files[0], files[1]);
  return fsi::common::exit_code_success;
}

void log_part(const char *name, const fsi::pump::BuiltPart &part) {
  const auto &s = part.surface;
  std::string regions;
  for (std::size_t r = 0; r < s.region_names.size(); ++r) {
    const double area = s.region_area_m2(static_cast<int>(r));
    if (area > 0.0)
      regions += fmt::format("{}{} {:.5g}", regions.empty() ? "" : ", ", s.region_names[r], area);
  }
  spdlog::info("{}: {} triangles, volume {:.6g} m^3 (OCC {:.6g} m^3); region areas m^2: {}", name, s.triangles.size(),
               s.enclosed_volume_m3(), part.cad_volume_m3, regions);
}

int write_geometry(const fsi::pump::PumpDesign &design, const std::filesystem::path &dir) {
  const auto geometry = fsi::pump::PumpGeometry::build(design);
  geometry.write(dir, design);
  log_part("impeller", geometry.impeller);
  log_part("casing", geometry.casing);
  if (geometry.channel)
    spdlog::info("channel as built: {:.4g} m^3 inside D2; leading edge at {:.1f} deg; built in {:.1f} s",
                 geometry.channel->channel_volume_m3, geometry.channel->leading_edge_angle_deg, geometry.seconds);
  else
    spdlog::info("blade as built: wrap {:.3f} deg (on the mesh {:.2f} deg), beta1 {:.3f} deg, beta2 {:.3f} deg; "
                 "built in {:.1f} s",
                 geometry.blade.wrap_deg, geometry.blade.wrap_on_mesh_deg, geometry.blade.inlet_angle_deg,
                 geometry.blade.outlet_angle_deg, geometry.seconds);
  const std::string plot =
      std::string("/usr/bin/python3 ") + FSI_SOURCE_DIR + "/pump/plot_geometry.py '" + dir.string() + "'";
  if (std::system(plot.c_str()) != 0)
    spdlog::warn("the picture {}/geometry.png was not drawn ({} failed)", dir.string(), plot);
  spdlog::info("wrote {}/impeller.stl, casing.stl, geometry.yaml, geometry.png", dir.string());
  return fsi::common::exit_code_success;
}

} // namespace

int main(int argc, char **argv) {
  CLI::App app{"fsi-pump-design: check a pump design file and print what the design rules expect of it"};
  std::string file;
  bool schema = false;
  app.add_option("design", file, "Pump design file (YAML)");
  std::string write_dir;
  app.add_option("--write", write_dir, "Generate the geometry into DIR: impeller.stl, casing.stl, geometry.yaml")
      ->type_name("DIR");
  app.add_flag("--schema", schema, "Print the design-file reference (Markdown) and exit");
  std::vector<std::string> stl_files;
  double unit_scale = 1.0;
  std::string check_report;
  app.add_option("--check-stl", stl_files, "Check the generated IMPELLER.stl and CASING.stl against the design")
      ->expected(2);
  app.add_option("--unit-scale", unit_scale, "Metres per STL unit (0.001 for millimetres)")->check(CLI::PositiveNumber);
  app.add_option("--report", check_report, "Write the --check-stl report as YAML to this file");
  CLI11_PARSE(app, argc, argv);
  if (schema) {
    std::cout << fsi::pump::PumpDesign::schema_markdown();
    return fsi::common::exit_code_success;
  }
  if (file.empty()) {
    std::cerr << "fsi-pump-design: missing DESIGN (a pump design file, e.g. pump/designs/single-blade.yaml); see "
                 "--help\n";
    return fsi::common::exit_code_bad_input;
  }
  fsi::common::setup_logging("pump", false);
  if (!stl_files.empty())
    return fsi::common::guarded_main("pump geometry check", [&] {
      return check_stl(fsi::pump::PumpDesign::load(file), stl_files, unit_scale, check_report);
    });
  return fsi::common::guarded_main("pump design", [&] {
    const auto design = fsi::pump::PumpDesign::load(file);
    if (const int code = report(design); write_dir.empty() || code != fsi::common::exit_code_success)
      return code;
    if (const int code = write_geometry(design, write_dir); code != fsi::common::exit_code_success)
      return code;
    // The generated files pass the same checks as a user's own (geometry_checks.yaml).
    const std::filesystem::path dir(write_dir);
    return check_stl(design, {(dir / "impeller.stl").string(), (dir / "casing.stl").string()}, 1.0,
                     (dir / "geometry_checks.yaml").string());
  });
}
