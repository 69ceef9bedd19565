#pragma once
// User errors raised while loading a rigid-surface mesh. Each message is one actionable
// sentence that names the file (or the in-memory source) it is about.

#include "common/UserError.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace fsi::geometry {

/// Base of every mesh loading error; catch this to handle them all.
class MeshError : public common::UserError {
public:
  MeshError(const std::string &source, const std::string &message);
  /// The file path (or in-memory source name) the error is about.
  const std::string &source() const { return source_; }

private:
  std::string source_;
};

/// The STL file does not exist.
class MeshFileNotFoundError : public MeshError {
public:
  explicit MeshFileNotFoundError(const std::string &path);
};

/// The file exists but cannot be read as ASCII or binary STL, or holds no triangle.
class MeshFileUnreadableError : public MeshError {
public:
  MeshFileUnreadableError(const std::string &path, const std::string &reason);
};

/// The mesh has border edges (each used by an odd number of triangles): it encloses no volume.
class MeshNotClosedError : public MeshError {
public:
  MeshNotClosedError(const std::string &source, std::size_t n_border_edges);
  std::size_t n_border_edges() const { return n_border_edges_; }

private:
  std::size_t n_border_edges_;
};

/// Zero-area triangles, out-of-range indices or a mesh enclosing no volume.
class MeshDegenerateError : public MeshError {
public:
  MeshDegenerateError(const std::string &source, const std::string &reason);
};

} // namespace fsi::geometry
