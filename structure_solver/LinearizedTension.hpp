#pragma once
// solver.tension: linearized: the tension linearised about X^n, directionally: the full
// stretching and shearing stiffness (material part 2 phi m d d^T / ds^4 per edge, phi m v_r v_c^T
// per shear cell, the 3 x 3 blocks coupling the coordinates) is taken implicitly on
// X^{n+1} - X^n, one Newton step of the implicit tension: a 3n x 3n system, solved by LDLT. No
// stretching-wave limit, and no resistance to transverse motion that the stretching does not
// have. The 3n x 3n pattern is that of the n x n system of Eq. (4) with every scalar nonzero a
// full 3 x 3 block.

#include "ScalarStepSystem.hpp"
#include "StepSystem.hpp"

#include <Eigen/SparseCholesky>

#include <array>
#include <vector>

namespace fsi::structure {

class LinearizedTension final : public StepSystem {
public:
  explicit LinearizedTension(const StepSettings &settings);

  /// Always by LDLT of the 3n x 3n system; returns 0.
  int solve(const StepInputs &in, PointArray &x_next) override;
  const Eigen::SparseMatrix<double> &matrix() const override { return system_.matrix(); }
  bool using_direct_solver() const override { return system_.using_direct_solver(); }
  bool explicit_stretching() const override { return false; }

private:
  void build_block_pattern();
  void fill_material_blocks(const PointArray &x, double *values) const;

  ScalarStepSystem system_;
  Eigen::SparseMatrix<double> block_;           ///< 3n x 3n system of the linearized tension
  Eigen::SparseMatrix<double> material_;        ///< its material part dt^2 K(X^n), same pattern
  std::vector<std::array<int, 9>> block_slots_; ///< per scalar slot: its 3 x 3 block's slots
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> block_ldlt_;
  bool block_analysed_ = false;
};

} // namespace fsi::structure
