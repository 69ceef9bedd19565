#include "TestMeshes.hpp"

#include <cmath>
#include <random>

namespace fsi::fluid::ibm::testing {
namespace {

EulerianCells tensor_grid(int n, const std::vector<double> &faces_m) {
  const auto n_cells = static_cast<Eigen::Index>(n) * n * n;
  PointArray centres_m(n_cells, 3);
  Eigen::VectorXd volumes_m3(n_cells);
  Eigen::Index c = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k, ++c) {
        const int f[3] = {i, j, k};
        double volume = 1.0;
        for (int axis = 0; axis < 3; ++axis) {
          centres_m(c, axis) = 0.5 * (faces_m[f[axis]] + faces_m[f[axis] + 1]);
          volume *= faces_m[f[axis] + 1] - faces_m[f[axis]];
        }
        volumes_m3[c] = volume;
      }
  return EulerianCells(std::move(centres_m), std::move(volumes_m3));
}

std::vector<double> faces(int n, double length_m, double stretching) {
  const double two_pi = 2.0 * M_PI;
  std::vector<double> faces_m(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    faces_m[i] = length_m * (s + stretching * std::sin(two_pi * s) / two_pi);
  }
  return faces_m;
}

} // namespace

EulerianCells uniform_grid(int n, double length_m) { return tensor_grid(n, faces(n, length_m, 0.0)); }

EulerianCells stretched_grid(int n, double length_m, double stretching) {
  return tensor_grid(n, faces(n, length_m, stretching));
}

EulerianCells subset(const EulerianCells &cells, const std::vector<CellId> &keep) {
  PointArray centres_m(static_cast<Eigen::Index>(keep.size()), 3);
  Eigen::VectorXd volumes_m3(static_cast<Eigen::Index>(keep.size()));
  for (std::size_t i = 0; i < keep.size(); ++i) {
    centres_m.row(static_cast<Eigen::Index>(i)) = cells.centres_m().row(keep[i]);
    volumes_m3[static_cast<Eigen::Index>(i)] = cells.volume_m3(keep[i]);
  }
  return EulerianCells(std::move(centres_m), std::move(volumes_m3));
}

PointArray random_points(int n, double lo_m, double hi_m, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> uniform(lo_m, hi_m);
  PointArray points_m(n, 3);
  for (Eigen::Index k = 0; k < n; ++k)
    for (int axis = 0; axis < 3; ++axis)
      points_m(k, axis) = uniform(generator);
  return points_m;
}

} // namespace fsi::fluid::ibm::testing
