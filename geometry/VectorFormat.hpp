#pragma once
// Formatting of vectors for describe() strings and error messages (internal helper).

#include "common/Types.hpp"

#include <sstream>
#include <string>

namespace fsi::geometry::detail {

/// "(x, y, z)" with 6 significant digits.
inline std::string format_vec3(const Vec3 &v) {
  std::ostringstream out;
  out.precision(6);
  out << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return out.str();
}

} // namespace fsi::geometry::detail
