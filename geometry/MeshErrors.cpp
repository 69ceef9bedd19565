#include "geometry/MeshErrors.hpp"

namespace fsi::geometry {

MeshError::MeshError(const std::string &source, const std::string &message)
    : common::UserError(message), source_(source) {}

MeshFileNotFoundError::MeshFileNotFoundError(const std::string &path)
    : MeshError(path, "collision mesh file '" + path +
                          "' does not exist; check the path in the case configuration.") {}

MeshFileUnreadableError::MeshFileUnreadableError(const std::string &path, const std::string &reason)
    : MeshError(path, "collision mesh file '" + path + "' cannot be used: " + reason +
                          "; export it again as ASCII or binary STL.") {}

MeshNotClosedError::MeshNotClosedError(const std::string &source, std::size_t n_border_edges)
    : MeshError(source, "collision mesh '" + source + "' is not closed: it has " +
                            std::to_string(n_border_edges) +
                            " border edge(s); close the holes (e.g. in MeshLab or with "
                            "CGAL hole filling) so the surface encloses a volume."),
      n_border_edges_(n_border_edges) {}

MeshDegenerateError::MeshDegenerateError(const std::string &source, const std::string &reason)
    : MeshError(source, "collision mesh '" + source + "' is degenerate: " + reason +
                            "; repair it (e.g. in MeshLab) so that every triangle has an "
                            "area and every closed part encloses a volume, then export it again.") {}

} // namespace fsi::geometry
