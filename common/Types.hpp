#pragma once
// Array types shared by every module. Positions, velocities and forces of Lagrangian points
// are stored as N x 3 row-major arrays, so the memory is x0 y0 z0 x1 y1 z1 ... (the layout of
// the HDF5 datasets [n_points, 3] and of packed Protobuf arrays).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fsi {

using PointArray = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Vec3 = Eigen::Vector3d;

} // namespace fsi
