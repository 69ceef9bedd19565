#pragma once
// The OpenFOAM case a fluid run works in: the case's fluid.openfoam.case_directory copied into
// the output folder and meshed with blockMesh when it has no mesh; decomposed for MPI.

#include <filesystem>
#include <string>

namespace fsi::fluid {

/// Copies case_dir/template_dir to out/openfoam (replacing an earlier copy) and runs blockMesh
/// there when it has no mesh; returns the copy. Throws common::ConfigError for a folder that
/// is not an OpenFOAM case, std::runtime_error when blockMesh fails (naming its log).
std::filesystem::path prepare_openfoam_case(const std::filesystem::path &case_dir, const std::string &template_dir,
                                            const std::filesystem::path &out);

/// decomposePar into n subdomains, cut along x (Debian's scotch is a stub).
void decompose(const std::filesystem::path &foam_case, int n);

} // namespace fsi::fluid
