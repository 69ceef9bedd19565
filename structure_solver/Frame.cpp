#include "Frame.hpp"

#include <algorithm>
#include <stdexcept>

namespace fsi::structure {

Frame make_frame(const Vec3 &s1_direction, const Vec3 &s2_direction) {
  if (s1_direction.norm() == 0.0)
    throw std::invalid_argument("the s1 direction is the zero vector");
  const Vec3 e1 = s1_direction.normalized();
  Vec3 e2 = s2_direction - s2_direction.dot(e1) * e1;
  if (e2.norm() < 1e-9 * std::max(1.0, s2_direction.norm()))
    throw std::invalid_argument("the s2 direction is parallel to s1 (or zero)");
  e2.normalize();
  return {e1, e2, e1.cross(e2)};
}

} // namespace fsi::structure
