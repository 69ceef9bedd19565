#include "OpenFoamCase.hpp"

#include "common/ConfigError.hpp"

#include <spdlog/spdlog.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace fsi::fluid {

std::filesystem::path prepare_openfoam_case(const std::filesystem::path &case_dir, const std::string &template_dir,
                                            const std::filesystem::path &out) {
  namespace fs = std::filesystem;
  const fs::path source = case_dir / template_dir, target = out / "openfoam";
  if (!fs::is_directory(source / "system") || !fs::is_directory(source / "constant"))
    throw common::ConfigError((source).string() + ": fluid.openfoam.case_directory must be an OpenFOAM case "
                                                       "(folders system/, constant/ and 0/).");
  fs::remove_all(target);
  fs::create_directories(target);
  fs::copy(source, target, fs::copy_options::recursive);
  if (!fs::exists(target / "constant" / "polyMesh" / "owner")) {
    if (!fs::exists(target / "system" / "blockMeshDict"))
      throw common::ConfigError(source.string() + ": no mesh (constant/polyMesh) and no system/blockMeshDict.");
    const std::string command = "blockMesh -case '" + target.string() + "' > '" + (target / "log.blockMesh").string() +
                                "' 2>&1";
    spdlog::info("meshing: {}", command);
    if (std::system(command.c_str()) != 0)
      throw std::runtime_error("blockMesh failed: see " + (target / "log.blockMesh").string());
  }
  return target;
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

} // namespace fsi::fluid
