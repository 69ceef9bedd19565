#pragma once
// The documented range of a numeric configuration key, with its unit for messages and docs.

#include <limits>
#include <sstream>
#include <string>

namespace fsi::common {

struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  bool max_exclusive = false;
  std::string unit; ///< SI unit shown in docs and messages ("m", "N/m", "1" for ratios)

  static Range any(std::string unit) { return Range{.unit = std::move(unit)}; }
  static Range positive(std::string unit) {
    return Range{.min = 0.0, .min_exclusive = true, .unit = std::move(unit)};
  }
  static Range non_negative(std::string unit) { return Range{.min = 0.0, .unit = std::move(unit)}; }
  static Range between(double lo, double hi, std::string unit) {
    return Range{.min = lo, .max = hi, .unit = std::move(unit)};
  }
  static Range at_least(double lo, std::string unit) { return Range{.min = lo, .unit = std::move(unit)}; }

  bool contains(double v) const {
    const bool above = min_exclusive ? v > min : v >= min;
    const bool below = max_exclusive ? v < max : v <= max;
    return above && below;
  }

  /// "> 0", "[0.5, 10]", "any" ...
  std::string describe() const {
    std::ostringstream out;
    const bool has_min = min > -std::numeric_limits<double>::infinity();
    const bool has_max = max < std::numeric_limits<double>::infinity();
    if (has_min && has_max)
      out << (min_exclusive ? "(" : "[") << min << ", " << max << (max_exclusive ? ")" : "]");
    else if (has_min)
      out << (min_exclusive ? "> " : ">= ") << min;
    else if (has_max)
      out << (max_exclusive ? "< " : "<= ") << max;
    else
      out << "any";
    return out.str();
  }
};

} // namespace fsi::common
