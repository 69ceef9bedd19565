#pragma once
// The one gmsh session of a process (RAII: gmsh::initialize on construction, gmsh::finalize on
// destruction; quiet, General.Terminal = 0), and the guard that turns gmsh's errors, which it
// throws as bare values, into GeometryError naming the part being built. Include only from the
// .cpp files of fsi_pump_geometry: gmsh stays inside that library.

#include <stdexcept>
#include <string>
#include <utility>

namespace fsi::pump {

/// The CAD kernel or the mesher failed on a part (a design the booleans cannot handle).
class GeometryError : public std::runtime_error {
public:
  explicit GeometryError(const std::string &message) : std::runtime_error(message) {}
};

class GmshSession {
public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession &) = delete;
  GmshSession &operator=(const GmshSession &) = delete;

  /// Starts an empty model named `part` (the previous model is cleared).
  void new_model(const std::string &part);
};

/// The last error gmsh logged (empty when none).
std::string gmsh_last_error();

/// Runs one step of building `part`; anything gmsh throws becomes a GeometryError
/// "<part>: <step> failed: <gmsh's last error>".
template <class Step> auto gmsh_step(const std::string &part, const std::string &step, Step &&work) {
  try {
    return std::forward<Step>(work)();
  } catch (const GeometryError &) {
    throw;
  } catch (const std::exception &e) {
    throw GeometryError(part + ": " + step + " failed: " + e.what());
  } catch (...) {
    throw GeometryError(part + ": " + step + " failed: " + gmsh_last_error());
  }
}

} // namespace fsi::pump
