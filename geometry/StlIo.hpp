#pragma once
// Reading and writing STL files (ASCII and binary). Reading merges vertices with identical
// coordinates so that the result is an indexed mesh whose closedness can be checked. An ASCII
// file may hold several `solid NAME ... endsolid` blocks: read_stl_regions keeps which block
// each triangle came from (blocks of the same name form one region).

#include "geometry/RegionSoup.hpp"
#include "geometry/TriangleSoup.hpp"

#include <string>

namespace fsi::geometry {

enum class StlFormat { ascii, binary };

/// Reads an ASCII or binary STL file (detected from its size and first bytes) and merges
/// duplicate vertices exactly. Throws MeshFileNotFoundError or MeshFileUnreadableError
/// (empty file, garbage, truncated data, no triangle).
TriangleSoup read_stl(const std::string &path);

/// Like read_stl, and keeps the regions: one per distinct `solid NAME` of an ASCII file (in
/// order of first appearance; a block without a name is the region ""), one unnamed region
/// for a binary file.
RegionSoup read_stl_regions(const std::string &path);

/// Writes the soup as STL. ASCII keeps 17 significant digits (exact round trip); binary
/// stores 32-bit floats. Facet normals are computed from the vertex order. Throws
/// std::runtime_error naming the path when the file cannot be written.
void write_stl(const std::string &path, const TriangleSoup &soup, StlFormat format);

/// Writes the soup as ASCII STL, one `solid NAME` block per region (in region order; binary
/// STL cannot hold names). Throws std::invalid_argument when region_of_triangle does not
/// match the triangles, std::runtime_error naming the path when the file cannot be written.
void write_stl_regions(const std::string &path, const RegionSoup &regions);

} // namespace fsi::geometry
