#include "LinearizedTension.hpp"

#include <algorithm>

namespace fsi::structure {

LinearizedTension::LinearizedTension(const StepSettings &settings) : system_(settings) { build_block_pattern(); }

void LinearizedTension::build_block_pattern() {
  // Every scalar nonzero (r, c) becomes a full 3 x 3 block (3r + i, 3c + j).
  const Eigen::SparseMatrix<double> &scalar = system_.matrix();
  std::vector<Eigen::Triplet<double>> entries;
  for (int col = 0; col < scalar.outerSize(); ++col)
    for (int k = scalar.outerIndexPtr()[col]; k < scalar.outerIndexPtr()[col + 1]; ++k)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          entries.emplace_back(3 * scalar.innerIndexPtr()[k] + i, 3 * col + j, 0.0);
  block_.resize(3 * scalar.rows(), 3 * scalar.cols());
  block_.setFromTriplets(entries.begin(), entries.end());
  block_.makeCompressed();
  material_ = block_;
  block_slots_.resize(static_cast<std::size_t>(scalar.nonZeros()));
  for (int col = 0; col < scalar.outerSize(); ++col)
    for (int k = scalar.outerIndexPtr()[col]; k < scalar.outerIndexPtr()[col + 1]; ++k) {
      const int row = scalar.innerIndexPtr()[k];
      for (int j = 0; j < 3; ++j) {
        const int bcol = 3 * col + j;
        const int *begin = block_.innerIndexPtr() + block_.outerIndexPtr()[bcol];
        const int *end = block_.innerIndexPtr() + block_.outerIndexPtr()[bcol + 1];
        for (int i = 0; i < 3; ++i)
          block_slots_[static_cast<std::size_t>(k)][3 * i + j] =
              static_cast<int>(std::lower_bound(begin, end, 3 * row + i) - block_.innerIndexPtr());
      }
    }
}

void LinearizedTension::fill_material_blocks(const PointArray &x, double *values) const {
  // Material part of the tension Hessian (the change of sigma with X), scale 1:
  //   edge:  2 phi m / ds^4 d d^T on (a,a), (b,b) and minus it on (a,b), (b,a) (zero for a
  //          slack edge in compression: its sigma does not change with X there);
  //   shear: phi m v_r v_c^T with v_r = dT_12 / dX_r = coef_a[r] b + coef_b[r] a.
  const StepSlots &s = system_.slots();
  const ElasticTerms &terms = system_.terms();
  const double phi = terms.tension_coefficient();
  const auto add = [&](int scalar_slot, const Eigen::Matrix3d &block) {
    const auto &slots = block_slots_[static_cast<std::size_t>(scalar_slot)];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        values[slots[3 * i + j]] += block(i, j);
  };
  for (std::size_t k = 0; k < s.tension.size(); ++k) {
    const auto &t = terms.tension()[k];
    const Vec3 d = (x.row(t.b) - x.row(t.a)).transpose();
    const Eigen::Matrix3d block = 2.0 * terms.tension_stiffness(t, x) * t.measure * t.inv_ds_squared * t.inv_ds_squared * d * d.transpose();
    add(s.tension[k][0], block), add(s.tension[k][1], -block), add(s.tension[k][2], -block);
    add(s.tension[k][3], block);
  }
  for (std::size_t k = 0; k < s.shear.size(); ++k) {
    const auto &t = terms.shear()[k];
    Vec3 a, b;
    t.tangents(x, a, b);
    std::array<Vec3, 4> v;
    for (int r = 0; r < 4; ++r)
      v[static_cast<std::size_t>(r)] = t.coef_a[r] * b + t.coef_b[r] * a;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        add(s.shear[k][4 * r + c], phi * t.measure * v[static_cast<std::size_t>(r)] *
                                       v[static_cast<std::size_t>(c)].transpose());
  }
}

int LinearizedTension::solve(const StepInputs &in, PointArray &x_next) {
  // [M + dt^2 (H_sigma(X^n) + K(X^n))] X^{n+1} = [paper's right-hand side] + dt^2 K(X^n) X^n:
  // the frozen-tension step plus the change of sigma, linearised about X^n.
  const double dt = in.dt_s;
  system_.fill_values(*in.x_now, dt);
  PointArray rhs;
  system_.assemble_rhs(in, rhs);
  Eigen::Map<Eigen::VectorXd> material(material_.valuePtr(), material_.nonZeros());
  material.setZero();
  fill_material_blocks(*in.x_now, material_.valuePtr());
  material *= dt * dt;
  Eigen::Map<Eigen::VectorXd> b(rhs.data(), rhs.size());
  const Eigen::Map<const Eigen::VectorXd> xn(in.x_now->data(), in.x_now->size());
  b += material_ * xn;
  Eigen::Map<Eigen::VectorXd>(block_.valuePtr(), block_.nonZeros()) = material;
  double *values = block_.valuePtr();
  const double *scalar = system_.matrix().valuePtr();
  for (std::size_t k = 0; k < block_slots_.size(); ++k)
    for (int i = 0; i < 3; ++i)
      values[block_slots_[k][4 * i]] += scalar[k]; // the diagonal of each block: 3i + i
  // Prescribed points: move their known values to the right-hand side, keep their rows.
  const PointArray &xp = *in.prescribed_next;
  const StepSlots &s = system_.slots();
  const std::vector<bool> &prescribed = system_.prescribed();
  for (const auto &[k, row, col] : s.free_row_prescribed_col) {
    const auto &slots = block_slots_[static_cast<std::size_t>(k)];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        b[3 * row + i] -= values[slots[3 * i + j]] * xp(col, j);
  }
  for (const int k : s.prescribed_off_diagonal)
    for (const int slot : block_slots_[static_cast<std::size_t>(k)])
      values[slot] = 0.0;
  for (std::size_t p = 0; p < prescribed.size(); ++p)
    if (prescribed[p]) {
      const auto &slots = block_slots_[static_cast<std::size_t>(s.diagonal[p])];
      for (int i = 0; i < 3; ++i) {
        b[3 * static_cast<Eigen::Index>(p) + i] = 0.0;
        for (int j = 0; j < 3; ++j)
          b[3 * static_cast<Eigen::Index>(p) + i] += values[slots[3 * i + j]] * xp(static_cast<Eigen::Index>(p), j);
      }
    }
  factorize(block_ldlt_, block_, block_analysed_, "the linearized-tension step");
  x_next.resize(in.x_now->rows(), 3);
  Eigen::Map<Eigen::VectorXd>(x_next.data(), x_next.size()) = block_ldlt_.solve(b);
  return 0;
}

} // namespace fsi::structure
