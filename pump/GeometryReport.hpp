#pragma once
// geometry.yaml: what the generator built, for people and for the flow setup: per part the
// volumes (triangulated and OCC's), triangle count, bounding box and each region's area; the
// blade's wrap and angles as designed and as built; the rotation; the design inputs.

#include <filesystem>

namespace fsi::pump {

struct PumpDesign;
struct PumpGeometry;

void write_geometry_report(const std::filesystem::path &file, const PumpDesign &design, const PumpGeometry &geometry);

} // namespace fsi::pump
