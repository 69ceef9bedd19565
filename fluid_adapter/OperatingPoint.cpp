#include "OperatingPoint.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fsi::fluid {

std::string OperatingPoint::dictionary() const {
  return fmt::format(R"(/*--------------------------------*- C++ -*----------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      operatingPoint;
}}
// The imposed volume flow rate at the inlet (m^3/s), from fluid.openfoam.operating_point of the
// case (written by fsi-openfoam-fluid when it prepares the case).
flowRate        {};
)",
                     flow_rate_m3_per_s);
}

void OperatingPoint::write(const std::filesystem::path &foam_case) const {
  const auto path = foam_case / file_name;
  std::ofstream out(path);
  out << dictionary();
  if (!out)
    throw std::runtime_error("cannot write " + path.string());
}

bool OperatingPoint::required_by(const std::filesystem::path &foam_case) {
  std::ifstream in(foam_case / "0" / "U");
  if (!in)
    return false;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str().find("operatingPoint") != std::string::npos;
}

} // namespace fsi::fluid
