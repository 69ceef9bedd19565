#include "fluid_adapter/ibm/KernelStencil.hpp"

#include "fluid_adapter/ibm/PeskinKernel.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::fluid::ibm {
namespace {

void check_inputs(const PointArray &points_m, const Eigen::VectorXd &kernel_width_m, const std::vector<bool> &skip) {
  if (points_m.rows() != kernel_width_m.size() || !(skip.empty() || skip.size() == kernel_width_m.size()))
    throw std::invalid_argument("KernelStencil: " + std::to_string(points_m.rows()) + " points but " +
                                std::to_string(kernel_width_m.size()) + " kernel widths (and " +
                                std::to_string(skip.size()) + " skip flags)");
  if (!points_m.allFinite())
    throw std::invalid_argument("KernelStencil: a Lagrangian point is not finite");
  for (Eigen::Index k = 0; k < kernel_width_m.size(); ++k)
    if ((skip.empty() || !skip[static_cast<std::size_t>(k)]) &&
        !(std::isfinite(kernel_width_m[k]) && kernel_width_m[k] > 0.0))
      throw std::invalid_argument("KernelStencil: a kernel width is not positive and finite; "
                                  "take the widths from NearestCells merged over all ranks");
}

void check_rows(const char *what, Eigen::Index rows, Eigen::Index expected) {
  if (rows != expected)
    throw std::invalid_argument(std::string("KernelStencil: ") + what + " has " + std::to_string(rows) +
                                " rows, expected " + std::to_string(expected));
}

} // namespace

KernelStencil::KernelStencil(const CellIndex &index, const PointArray &points_m,
                             const Eigen::VectorXd &kernel_width_m)
    : mesh_(index.cells()) {
  rebuild(index, points_m, kernel_width_m);
}

void KernelStencil::rebuild(const CellIndex &index, const PointArray &points_m, const Eigen::VectorXd &kernel_width_m,
                            const std::vector<bool> &skip) {
  if (&index.cells() != &mesh_)
    throw std::invalid_argument("KernelStencil::rebuild: another mesh than the stencil's");
  check_inputs(points_m, kernel_width_m, skip);
  // clear() keeps the capacity: a stencil rebuilt every step reuses its arrays (tens of MB for
  // 10^4-10^5 points) instead of growing and page-faulting new ones.
  offsets_.clear();
  cells_of_pairs_.clear();
  weights_.clear();
  offsets_.reserve(static_cast<std::size_t>(points_m.rows()) + 1);
  offsets_.push_back(0);
  for (Eigen::Index k = 0; k < points_m.rows(); ++k) {
    if (skip.empty() || !skip[static_cast<std::size_t>(k)])
      add_point(index, points_m.row(k).transpose(), kernel_width_m[k], found_);
    offsets_.push_back(cells_of_pairs_.size());
  }
}

namespace {

/// phi along one axis for the cells of one point's support, remembered by the cells' centre
/// coordinate: on hexahedral meshes (blockMesh, snappyHexMesh) the up to 64 cells of a support
/// share about 4 coordinates per axis, so 12 evaluations replace 192. Same arguments, same
/// values: the weights are those of PeskinKernel::delta_per_m3 bit for bit.
class AxisPhi {
public:
  AxisPhi(double point_m, double inverse_width) : point_m_(point_m), inverse_width_(inverse_width) {}
  double operator()(double centre_m) {
    for (int i = 0; i < size_; ++i)
      if (centre_m_[i] == centre_m)
        return phi_[i];
    const double phi = PeskinKernel::phi((centre_m - point_m_) * inverse_width_);
    if (size_ < capacity) {
      centre_m_[size_] = centre_m;
      phi_[size_++] = phi;
    }
    return phi;
  }

private:
  static constexpr int capacity = 8;
  double point_m_, inverse_width_;
  double centre_m_[capacity] = {}, phi_[capacity] = {};
  int size_ = 0;
};

} // namespace

void KernelStencil::add_point(const CellIndex &index, const Vec3 &point_m, double width_m,
                              std::vector<CellId> &found) {
  index.cells_in_box(point_m, PeskinKernel::support_radius * width_m, found);
  const double inverse_width = 1.0 / width_m;
  AxisPhi phi_x(point_m.x(), inverse_width), phi_y(point_m.y(), inverse_width), phi_z(point_m.z(), inverse_width);
  for (const CellId cell : found) {
    // delta_per_m3(centre - point, width) * V, in the same order of operations.
    const Vec3 centre_m = mesh_.centre_m(cell);
    const double weight = phi_x(centre_m.x()) * phi_y(centre_m.y()) * phi_z(centre_m.z()) * inverse_width *
                          inverse_width * inverse_width * mesh_.volume_m3(cell);
    if (weight == 0.0)
      continue;
    cells_of_pairs_.push_back(cell);
    weights_.push_back(weight);
  }
}

Eigen::VectorXd KernelStencil::weight_sums() const {
  Eigen::VectorXd sums = Eigen::VectorXd::Zero(n_points());
  for (Eigen::Index k = 0; k < n_points(); ++k)
    for (std::size_t p = offsets_[k]; p < offsets_[k + 1]; ++p)
      sums[k] += weights_[p];
  return sums;
}

void KernelStencil::normalise_weights(const Eigen::VectorXd &total_weight_sums) {
  check_rows("total_weight_sums", total_weight_sums.size(), n_points());
  for (Eigen::Index k = 0; k < n_points(); ++k) {
    if (total_weight_sums[k] == 0.0)
      continue;
    for (std::size_t p = offsets_[k]; p < offsets_[k + 1]; ++p)
      weights_[p] /= total_weight_sums[k];
  }
}

PointArray KernelStencil::spread_point_forces(const PointArray &point_forces_n) const {
  check_rows("point_forces_n", point_forces_n.rows(), n_points());
  PointArray force_density_n_per_m3 = PointArray::Zero(mesh_.n_cells(), 3);
  for (Eigen::Index k = 0; k < n_points(); ++k)
    for (std::size_t p = offsets_[k]; p < offsets_[k + 1]; ++p) {
      const CellId cell = cells_of_pairs_[p];
      force_density_n_per_m3.row(cell) += (weights_[p] / mesh_.volume_m3(cell)) * point_forces_n.row(k);
    }
  return force_density_n_per_m3;
}

PointArray KernelStencil::spread(const PointArray &force_density_n_per_measure,
                                 const Eigen::VectorXd &point_measure) const {
  check_rows("point_measure", point_measure.size(), force_density_n_per_measure.rows());
  const PointArray point_forces_n = force_density_n_per_measure.array().colwise() * point_measure.array();
  return spread_point_forces(point_forces_n);
}

PointArray KernelStencil::interpolate(const PointArray &cell_velocity_m_per_s) const {
  check_rows("cell_velocity_m_per_s", cell_velocity_m_per_s.rows(), mesh_.n_cells());
  PointArray point_velocity_m_per_s = PointArray::Zero(n_points(), 3);
  for (Eigen::Index k = 0; k < n_points(); ++k)
    for (std::size_t p = offsets_[k]; p < offsets_[k + 1]; ++p)
      point_velocity_m_per_s.row(k) += weights_[p] * cell_velocity_m_per_s.row(cells_of_pairs_[p]);
  return point_velocity_m_per_s;
}

} // namespace fsi::fluid::ibm
