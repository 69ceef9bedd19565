#include "LagrangianGrid.hpp"

#include <algorithm>
#include <stdexcept>

namespace fsi::structure {

LagrangianGrid::LagrangianGrid(int n1, int n2, double length_1_m, double length_2_m)
    : n1_(n1), n2_(n2), ds1_(length_1_m / (n1 - 1)), ds2_(n2 > 1 ? length_2_m / (n2 - 1) : 1.0) {
  if (n1 < 3 || n2 < 1 || n2 == 2)
    throw std::invalid_argument("a Lagrangian grid needs n1 >= 3 and n2 == 1 or n2 >= 3");
  if (!(length_1_m > 0.0) || (n2 > 1 && !(length_2_m > 0.0)))
    throw std::invalid_argument("a Lagrangian grid needs positive lengths");
}

double LagrangianGrid::min_spacing_m() const { return is_filament() ? ds1_ : std::min(ds1_, ds2_); }

double LagrangianGrid::point_measure(int i1, int i2) const {
  const double along_1 = end_weight(i1, n1_) * ds1_;
  return is_filament() ? along_1 : along_1 * end_weight(i2, n2_) * ds2_;
}

double LagrangianGrid::edge_measure_1(int i2) const {
  return is_filament() ? ds1_ : ds1_ * end_weight(i2, n2_) * ds2_;
}

double LagrangianGrid::edge_measure_2(int i1) const { return end_weight(i1, n1_) * ds1_ * ds2_; }

Eigen::VectorXd LagrangianGrid::point_measures() const {
  Eigen::VectorXd measures(n_points());
  for (int i1 = 0; i1 < n1_; ++i1)
    for (int i2 = 0; i2 < n2_; ++i2)
      measures[index(i1, i2)] = point_measure(i1, i2);
  return measures;
}

} // namespace fsi::structure
