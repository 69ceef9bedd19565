#pragma once
// Reading and writing STL files (ASCII and binary). Reading merges vertices with identical
// coordinates so that the result is an indexed mesh whose closedness can be checked.

#include "geometry/TriangleSoup.hpp"

#include <string>

namespace fsi::geometry {

enum class StlFormat { ascii, binary };

/// Reads an ASCII or binary STL file (detected from its size and first bytes) and merges
/// duplicate vertices exactly. Throws MeshFileNotFoundError or MeshFileUnreadableError
/// (empty file, garbage, truncated data, no triangle).
TriangleSoup read_stl(const std::string &path);

/// Writes the soup as STL. ASCII keeps 17 significant digits (exact round trip); binary
/// stores 32-bit floats. Facet normals are computed from the vertex order. Throws
/// std::runtime_error naming the path when the file cannot be written.
void write_stl(const std::string &path, const TriangleSoup &soup, StlFormat format);

} // namespace fsi::geometry
