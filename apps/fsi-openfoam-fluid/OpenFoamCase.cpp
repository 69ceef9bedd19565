#include "OpenFoamCase.hpp"

#include "common/ConfigError.hpp"
#include "common/Fnv1a.hpp"

#include <spdlog/spdlog.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace fsi::apps {

namespace {

namespace fs = std::filesystem;

/// Runs an OpenFOAM utility on the case, its output in case/log.<tool>.
void run_tool(const std::string &tool, const fs::path &foam_case, const std::string &options = "") {
  const fs::path log = foam_case / ("log." + tool);
  const std::string command = tool + " -case '" + foam_case.string() + "'" + options + " > '" + log.string() + "' 2>&1";
  spdlog::info("meshing: {}", command);
  if (std::system(command.c_str()) != 0)
    throw std::runtime_error(tool + " failed: see " + log.string());
}

fs::path mesh_cache_root() {
  if (const char *dir = std::getenv("FSI_MESH_CACHE"); dir && *dir)
    return dir;
  if (const char *dir = std::getenv("XDG_CACHE_HOME"); dir && *dir)
    return fs::path(dir) / "fsi" / "meshes";
  if (const char *home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "fsi" / "meshes";
  return {};
}

/// The hash of what a snappyHexMesh mesh is made from.
std::string mesh_inputs_hash(const fs::path &foam_case) {
  common::Fnv1a hash;
  for (const char *dict :
       {"blockMeshDict", "snappyHexMeshDict", "surfaceFeatureExtractDict", "meshQualityDict", "createBafflesDict"})
    hash.add_file(foam_case / "system" / dict);
  std::vector<fs::path> surfaces;
  if (fs::is_directory(foam_case / "constant" / "triSurface"))
    for (const auto &entry : fs::directory_iterator(foam_case / "constant" / "triSurface"))
      if (entry.is_regular_file())
        surfaces.push_back(entry.path());
  std::sort(surfaces.begin(), surfaces.end());
  for (const auto &file : surfaces) {
    hash.add(file.filename().string());
    hash.add_file(file);
  }
  return hash.hex();
}

std::string read_text(const fs::path &file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Refuses a snappyHexMesh mesh that still has faces on the background block's patches: the box
/// of blockMeshDict does not enclose the surface, and the part outside (an outlet, often) is cut
/// off without any error from the mesher.
void check_not_clipped_by_the_background(const fs::path &foam_case, const fs::path &mesh) {
  const std::string block = read_text(foam_case / "system" / "blockMeshDict");
  std::set<std::string> background{"defaultFaces"};
  if (const auto at = block.find("boundary"); at != std::string::npos) {
    const std::regex entry(R"((\w+)\s*\{\s*type)");
    for (auto it = std::sregex_iterator(block.begin() + static_cast<std::ptrdiff_t>(at), block.end(), entry);
         it != std::sregex_iterator(); ++it)
      background.insert((*it)[1]);
  }
  const std::string boundary = read_text(mesh / "boundary");
  const std::regex patch(R"((\w+)\s*\{[^}]*?nFaces\s+(\d+)\s*;)");
  for (auto it = std::sregex_iterator(boundary.begin(), boundary.end(), patch); it != std::sregex_iterator(); ++it)
    if (background.count((*it)[1]) && std::stol((*it)[2]) > 0)
      throw std::runtime_error("snappyHexMesh: the mesh of " + foam_case.string() + " reaches the background box (" +
                               std::string((*it)[2]) + " faces on the block patch '" + std::string((*it)[1]) +
                               "'): the box of system/blockMeshDict does not enclose the surface, so the part "
                               "outside it is cut off. Enlarge the box, or regenerate the case's files from its "
                               "geometry (cases/centrifugal-pump: make_case.py).");
}

/// The patch names of a case's mesh (constant/polyMesh/boundary), in order.
std::vector<std::string> patch_names(const fs::path &foam_case) {
  const std::string boundary = read_text(foam_case / "constant" / "polyMesh" / "boundary");
  const std::regex patch(R"((\w+)\s*\{[^}]*?nFaces)");
  std::vector<std::string> names;
  for (auto it = std::sregex_iterator(boundary.begin(), boundary.end(), patch); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  return names;
}

/// mapFields' options onto foam_case from source: -consistent when both meshes have the same
/// patches; else a system/mapFieldsDict mapping the patches they share (a patch the source does
/// not have, e.g. the AMI pair of a rotor turning with its body, keeps this case's condition).
std::string map_fields_options(const fs::path &foam_case, const fs::path &source) {
  const auto ours = patch_names(foam_case), theirs = patch_names(source);
  if (std::set<std::string>(ours.begin(), ours.end()) == std::set<std::string>(theirs.begin(), theirs.end()))
    return " -consistent";
  std::string shared, kept, pairs;
  for (const auto &name : ours) {
    const bool in_source = std::find(theirs.begin(), theirs.end(), name) != theirs.end();
    (in_source ? shared : kept) += " " + name;
    if (in_source)
      pairs += " " + name + " " + name;
  }
  std::ofstream(foam_case / "system" / "mapFieldsDict")
      << "FoamFile { version 2.0; format ascii; class dictionary; object mapFieldsDict; }\n"
      << "// Written by fsi-openfoam-fluid: the warm start maps the patches shared with the source.\n"
      << "patchMap (" << pairs << " );\ncuttingPatches ( );\n";
  spdlog::info("warm start: the meshes' patches differ; mapped:{}; kept as this case has them:{}", shared,
               kept.empty() ? std::string(" none") : kept);
  return "";
}

/// blockMesh, snappyHexMesh and checkMesh, or the same mesh from the cache.
void snappy_mesh(const fs::path &foam_case) {
  const fs::path root = mesh_cache_root();
  const fs::path cached = root.empty() ? fs::path() : root / mesh_inputs_hash(foam_case);
  const fs::path mesh = foam_case / "constant" / "polyMesh";
  if (!cached.empty() && fs::exists(cached / "polyMesh" / "owner")) {
    fs::remove_all(mesh);
    fs::copy(cached / "polyMesh", mesh, fs::copy_options::recursive);
    check_not_clipped_by_the_background(foam_case, mesh);
    spdlog::info("meshing: the snappyHexMesh mesh of these inputs is cached: {}", cached.string());
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  run_tool("blockMesh", foam_case);
  if (fs::exists(foam_case / "system" / "surfaceFeatureExtractDict"))
    run_tool("surfaceFeatureExtract", foam_case);
  run_tool("snappyHexMesh", foam_case, " -overwrite");
  if (fs::exists(foam_case / "system" / "createBafflesDict")) {
    // A rotor behind an AMI (the turning penalized impeller): its faceZone becomes the cyclicAMI
    // pair, and each side gets its own points so that the rotor can turn (as the AMI tutorials).
    run_tool("createBaffles", foam_case, " -overwrite");
    run_tool("mergeOrSplitBaffles", foam_case, " -split -overwrite");
  }
  run_tool("checkMesh", foam_case, " -constant");
  check_not_clipped_by_the_background(foam_case, mesh);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  spdlog::info("meshing: snappyHexMesh done in {:.0f} s (checkMesh: {})", seconds,
               (foam_case / "log.checkMesh").string());
  if (cached.empty())
    return;
  // Into a private folder first, then renamed: runs meshing the same inputs at once (the points
  // of a pump curve) never see a half-written cache entry.
  std::error_code error;
  const fs::path partial = root / (cached.filename().string() + ".partial." + std::to_string(::getpid()));
  fs::create_directories(partial, error);
  fs::copy(mesh, partial / "polyMesh", fs::copy_options::recursive, error);
  if (!error)
    fs::rename(partial, cached, error);
  if (error) {
    fs::remove_all(partial, error);
    spdlog::debug("meshing: mesh not cached in {}", cached.string());
  }
}

} // namespace

std::filesystem::path prepare_openfoam_case(const std::filesystem::path &case_dir, const fluid::OpenFoamConfig &foam,
                                            const std::filesystem::path &out) {
  const fs::path source = case_dir / foam.case_directory, target = out / "openfoam";
  if (!fs::is_directory(source / "system") || !fs::is_directory(source / "constant"))
    throw common::ConfigError((source).string() + ": fluid.openfoam.case_directory must be an OpenFOAM case "
                                                  "(folders system/, constant/ and 0/).");
  fs::remove_all(target);
  fs::create_directories(target);
  fs::copy(source, target, fs::copy_options::recursive);
  if (foam.operating_point) {
    foam.operating_point->write(target);
    spdlog::info("operating point: inlet flow rate {} m^3/s ({})", foam.operating_point->flow_rate_m3_per_s,
                 (target / fluid::OperatingPoint::file_name).string());
  }
  if (!fs::exists(target / "constant" / "polyMesh" / "owner")) {
    if (!fs::exists(target / "system" / "blockMeshDict"))
      throw common::ConfigError(source.string() + ": no mesh (constant/polyMesh) and no system/blockMeshDict.");
    if (fs::exists(target / "system" / "snappyHexMeshDict"))
      snappy_mesh(target);
    else
      run_tool("blockMesh", target);
  }
  if (fs::exists(target / "system" / "topoSetDict")) {
    // Cell zones the case's fvOptions act on (a pump's front seal: python/fsi/front_seal.py),
    // added to the mesh made or taken from the cache (which stays without them).
    run_tool("topoSet", target);
    spdlog::info("meshing: cell zones of system/topoSetDict added ({})", (target / "log.topoSet").string());
  }
  return target;
}

double map_initial_fields(const std::filesystem::path &foam_case, const std::filesystem::path &source) {
  if (!fs::is_directory(source / "constant" / "polyMesh"))
    throw common::ConfigError(source.string() + ": fluid.openfoam.initial_fields_from must be an OpenFOAM case "
                                                "with its mesh (constant/polyMesh), e.g. an earlier run's "
                                                "<output>/openfoam.");
  // The latest time folder (a number > 0) holding U.
  double latest = 0.0;
  std::string latest_name;
  for (const auto &entry : fs::directory_iterator(source)) {
    const std::string name = entry.path().filename().string();
    char *end = nullptr;
    const double t = std::strtod(name.c_str(), &end);
    if (end != name.c_str() && *end == '\0' && t > latest && fs::exists(entry.path() / "U")) {
      latest = t;
      latest_name = name;
    }
  }
  if (latest_name.empty())
    throw common::ConfigError(source.string() + ": fluid.openfoam.initial_fields_from has no time folder after 0 "
                                                "with fields (U): run it first, to its end.");
  run_tool("mapFields", foam_case,
           map_fields_options(foam_case, source) + " -sourceTime " + latest_name + " '" + source.string() + "'");
  // The fields a run must not inherit: the forcing of the source run is recomputed each step.
  for (const char *stale : {"fsiAcceleration", "phi"})
    fs::remove(foam_case / "0" / stale);
  return latest;
}

void decompose(const std::filesystem::path &foam_case, int n) {
  std::ofstream(foam_case / "system" / "decomposeParDict")
      << "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
      << "numberOfSubdomains " << n << ";\nmethod hierarchical;\n"
      << "coeffs { n (" << n << " 1 1); order xyz; }\n";
  const std::string command = "decomposePar -force -case '" + foam_case.string() + "' > '" +
                              (foam_case / "log.decomposePar").string() + "' 2>&1";
  spdlog::info("decomposing for {} MPI ranks: {}", n, command);
  if (std::system(command.c_str()) != 0)
    throw std::runtime_error("decomposePar failed: see " + (foam_case / "log.decomposePar").string());
}

} // namespace fsi::apps
