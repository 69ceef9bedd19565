#pragma once
// The OpenFOAM case a fluid run works in: the case's fluid.openfoam.case_directory copied into
// the output folder and meshed when it has no mesh (blockMesh; then snappyHexMesh when the
// case has a system/snappyHexMeshDict, e.g. a pump casing); decomposed for MPI.

#include "fluid_adapter/OpenFoamConfig.hpp"

#include <filesystem>
#include <string>

namespace fsi::apps {

/// Copies case_dir/foam.case_directory to out/openfoam (replacing an earlier copy), writes its
/// operating point (constant/operatingPoint) when the case gives one, and meshes it when it has
/// no constant/polyMesh: blockMesh, then (with system/snappyHexMeshDict)
/// surfaceFeatureExtract when the case has its dictionary, snappyHexMesh -overwrite, (with
/// system/createBafflesDict: a rotor's faceZone made a cyclicAMI pair) createBaffles -overwrite
/// and mergeOrSplitBaffles -split -overwrite, and checkMesh. A snappyHexMesh mesh is kept in the mesh cache ($FSI_MESH_CACHE, default
/// ~/.cache/fsi/meshes) under a hash of the files it is made from (system/ dictionaries of the
/// meshing tools, constant/triSurface): the next run with the same inputs reuses it. Returns the
/// copy. Throws common::ConfigError for a folder that is not an OpenFOAM case,
/// std::runtime_error when a meshing tool fails (naming its log).
std::filesystem::path prepare_openfoam_case(const std::filesystem::path &case_dir, const fluid::OpenFoamConfig &foam,
                                            const std::filesystem::path &out);

/// A warm start: maps the latest fields of the OpenFOAM case `source` onto foam_case's mesh as
/// its initial fields (mapFields -consistent -sourceTime latestTime, log in
/// foam_case/log.mapFields). Returns the source time mapped (s). Throws common::ConfigError
/// when source is not an OpenFOAM case with a time folder after 0, std::runtime_error when
/// mapFields fails.
double map_initial_fields(const std::filesystem::path &foam_case, const std::filesystem::path &source);

/// decomposePar into n subdomains, cut along x (Debian's scotch is a stub).
void decompose(const std::filesystem::path &foam_case, int n);

} // namespace fsi::apps
