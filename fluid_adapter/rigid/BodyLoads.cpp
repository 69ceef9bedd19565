#include "fluid_adapter/rigid/BodyLoads.hpp"

#include <stdexcept>
#include <string>

namespace fsi::fluid::rigid {

BodyLoad BodyLoads::from_source_on_fluid(const BodyIndicator &indicator,
                                         const PointArray &cell_centres_m,
                                         const PointArray &force_on_fluid_n_per_m3,
                                         const Eigen::VectorXd &cell_volumes_m3,
                                         const Vec3 &torque_point_m) {
  const auto n_cells = static_cast<Eigen::Index>(indicator.n_cells());
  if (cell_centres_m.rows() != n_cells || force_on_fluid_n_per_m3.rows() != n_cells ||
      cell_volumes_m3.size() != n_cells)
    throw std::invalid_argument(
        "body '" + indicator.body().name() + "' loads: expected " + std::to_string(n_cells) +
        " cells, got " + std::to_string(cell_centres_m.rows()) + " centres, " +
        std::to_string(force_on_fluid_n_per_m3.rows()) + " force densities, " +
        std::to_string(cell_volumes_m3.size()) + " volumes");
  BodyLoad load;
  load.torque_point_m = torque_point_m;
  for (const std::int32_t cell : indicator.inside_cells()) {
    const Vec3 on_body_n = -cell_volumes_m3(cell) * force_on_fluid_n_per_m3.row(cell).transpose();
    load.force_n += on_body_n;
    load.torque_n_m += (Vec3(cell_centres_m.row(cell).transpose()) - torque_point_m).cross(on_body_n);
  }
  return load;
}

} // namespace fsi::fluid::rigid
