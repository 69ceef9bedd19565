#pragma once
// A triangle soup whose triangles belong to named regions: the `solid NAME` blocks of a
// multi-solid ASCII STL (a pump's impeller: hub, shroud, blade sides...). Regions do not
// split the mesh: vertices shared by two regions are one vertex, so closedness and
// orientation are properties of the whole soup.

#include "geometry/TriangleSoup.hpp"

#include <string>
#include <vector>

namespace fsi::geometry {

struct RegionSoup {
  TriangleSoup soup;
  std::vector<std::string> region_names; ///< region r is named region_names[r] ("" unnamed)
  std::vector<int> region_of_triangle;   ///< one entry per row of soup.triangles

  /// Name of the region holding triangle t.
  const std::string &region_name_of(Eigen::Index t) const {
    return region_names[static_cast<std::size_t>(region_of_triangle[static_cast<std::size_t>(t)])];
  }
};

} // namespace fsi::geometry
