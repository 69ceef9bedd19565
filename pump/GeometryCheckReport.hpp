#pragma once
// What the geometry checks of a generated pump found (GeometryChecks): one line per check,
// pass or fail with an actionable message naming the file, and the measured numbers (units
// in the names). Written as a table for the terminal and as YAML next to the results.

#include "common/Types.hpp"

#include <limits>
#include <string>
#include <vector>

namespace fsi::pump {

enum class CheckStatus { pass, fail, skipped };

struct CheckResult {
  std::string name; ///< e.g. "impeller closed"
  CheckStatus status = CheckStatus::skipped;
  std::string value;   ///< what was measured, e.g. "0 open edges", "96.4 cm^2"
  std::string message; ///< for a failure: what is wrong, in which file, and what to do
};

struct GeometryCheckReport {
  static constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

  std::string impeller_file, casing_file;
  double unit_scale = 1.0; ///< metres per file unit
  std::vector<CheckResult> checks;

  double impeller_volume_m3 = unknown;
  double casing_volume_m3 = unknown;
  double min_clearance_m = unknown;       ///< between the impeller's and the casing's surfaces
  Vec3 closest_point_m = Vec3::Zero();    ///< the impeller vertex where they are closest
  double throat_area_m2 = unknown;        ///< the casing's section at the cut-water angle, beyond r3
  double design_throat_area_m2 = unknown; ///< the constant-angular-momentum rule's (VoluteSizing)
  double throat_band_min_m2 = unknown, throat_band_max_m2 = unknown;
  double free_passage_m = unknown; ///< largest sphere through the impeller's channel
  double free_passage_error_m = unknown;
  Vec3 bottleneck_m = Vec3::Zero(); ///< where that sphere gets stuck

  /// Adds a check line and returns it.
  CheckResult &add(const std::string &name, CheckStatus status, const std::string &value,
                   const std::string &message = "");
  bool passed() const;
  /// The first failed check, or nullptr.
  const CheckResult *first_failure() const;
  /// The checks as an aligned text table (name, status, value), failures' messages below.
  std::string table() const;
  std::string to_yaml() const;
};

std::string status_name(CheckStatus status);

} // namespace fsi::pump
