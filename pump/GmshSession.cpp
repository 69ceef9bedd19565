#include "GmshSession.hpp"

#include <gmsh.h>

#include <atomic>

namespace fsi::pump {
namespace {
std::atomic<bool> session_open{false};
} // namespace

GmshSession::GmshSession() {
  if (session_open.exchange(true))
    throw std::logic_error("GmshSession: gmsh is already initialized in this process (one session at a time)");
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  // Keep the faces of the fused parts apart (no merging of faces on the same surface), so that
  // every face of a solid comes from one named part and can be classified.
  gmsh::option::setNumber("Geometry.OCCUnionUnify", 0);
}

GmshSession::~GmshSession() {
  gmsh::finalize();
  session_open = false;
}

void GmshSession::new_model(const std::string &part) {
  gmsh::clear();
  gmsh::model::add(part);
}

std::string gmsh_last_error() {
  std::string error;
  gmsh::logger::getLastError(error);
  return error.empty() ? "(gmsh gave no message)" : error;
}

} // namespace fsi::pump
