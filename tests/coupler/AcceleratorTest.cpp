// The accelerators of implicit coupling on a linear model problem with a known fixed point:
// H(x) = J x + b, x* = (I - J)^{-1} b. Each must converge in the number of iterations its
// theory gives:
// - constant: the error contracts by |1 - omega (1 - lambda)| per iteration (J = lambda I);
// - Aitken: exact at the second update when J = lambda I (omega_1 = 1 / (1 - lambda));
// - IQN-ILS: on a linear map of dimension m, at most m + 1 iterations (GMRES-like), even where
//   plain iteration diverges (spectral radius > 1), and with columns reused from the previous
//   step a new right-hand side converges in fewer, also after the columns went through a
//   checkpoint.

#include "coupler/AitkenRelaxation.hpp"
#include "coupler/ConstantRelaxation.hpp"
#include "coupler/IqnIlsAccelerator.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>

namespace fsi::coupler {
namespace {

struct Linear {
  Eigen::MatrixXd J;
  Eigen::VectorXd b;
  Eigen::VectorXd fixed_point() const {
    return (Eigen::MatrixXd::Identity(J.rows(), J.cols()) - J).colPivHouseholderQr().solve(b);
  }
};

/// Iterations until |H(x) - x| <= tol |H(x)| from x0 (the step's iterations as the coupler counts them).
int iterations_to_converge(Accelerator &acc, const Linear &h, Eigen::VectorXd x, double tol, int max = 200) {
  acc.begin_step();
  Eigen::VectorXd next;
  for (int k = 1; k <= max; ++k) {
    const Eigen::VectorXd x_tilde = h.J * x + h.b;
    if ((x_tilde - x).norm() <= tol * x_tilde.norm()) {
      acc.end_step();
      return k;
    }
    acc.next(x, x_tilde, next);
    x = next;
  }
  return max + 1;
}

TEST(ConstantRelaxation, ContractsAtTheRateItsEigenvalueGives) {
  // lambda = -20 (the drag law's a = 20 at 10x its explicit limit): plain iteration diverges,
  // omega = 0.05 contracts by |1 - 0.05 * 21| = 0.05 per iteration.
  const int m = 6;
  Linear h{-20.0 * Eigen::MatrixXd::Identity(m, m), Eigen::VectorXd::LinSpaced(m, 1.0, 2.0)};
  ConstantRelaxation acc(0.05);
  const double rate = std::abs(1.0 - 0.05 * 21.0);
  // |x_k - x*| = rate^k |x_0 - x*|; the relative residual (1 - lambda) |x_k - x*| / |x~_k| <= tol.
  const int k = iterations_to_converge(acc, h, Eigen::VectorXd::Zero(m), 1e-10);
  const Eigen::VectorXd x_star = h.fixed_point();
  const double expected = 1.0 + std::ceil(std::log(1e-10 * x_star.norm() / (21.0 * x_star.norm())) / std::log(rate));
  EXPECT_NEAR(k, expected, 1.0) << "rate " << rate;
  // Unrelaxed (omega = 1) it is plain fixed-point iteration: the error grows 20-fold each time.
  ConstantRelaxation plain(1.0);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m), next;
  for (int i = 0; i < 10; ++i) {
    plain.next(x, h.J * x + h.b, next);
    x = next;
  }
  EXPECT_GT((x - x_star).norm(), 1e10 * x_star.norm());
}

TEST(AitkenRelaxation, IsExactAtTheSecondUpdateForAMultipleOfTheIdentity) {
  const int m = 5;
  Linear h{-20.0 * Eigen::MatrixXd::Identity(m, m), Eigen::VectorXd::Constant(m, 3.0)};
  AitkenRelaxation acc(0.01);
  // x_0, x_1 = x_0 + 0.01 r_0, x_2 = x* (omega_1 = 1/21): H(x_2) = x_2 at the third evaluation.
  EXPECT_EQ(iterations_to_converge(acc, h, Eigen::VectorXd::Zero(m), 1e-12), 3);
  EXPECT_NEAR(acc.last_omega(), 1.0 / 21.0, 1e-12);
}

TEST(IqnIlsAccelerator, SolvesADivergentLinearMapInAtMostDimensionPlusOneIterations) {
  const int m = 8;
  std::srand(7);
  Eigen::MatrixXd J = Eigen::MatrixXd::Random(m, m) * 2.0; // spectral radius well above 1
  Linear h{J, Eigen::VectorXd::Random(m)};
  const Eigen::VectorXd x_star = h.fixed_point();
  ASSERT_GT(J.eigenvalues().cwiseAbs().maxCoeff(), 1.5);
  IqnIlsAccelerator acc(0.1, 0);
  // m secant pairs determine the inverse Jacobian on R^m: the (m + 2)-th evaluation converges
  // (one relaxation step, then m quasi-Newton steps).
  const int k = iterations_to_converge(acc, h, Eigen::VectorXd::Zero(m), 1e-9);
  EXPECT_LE(k, m + 2);
  // Its last iterate is the fixed point.
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m), next;
  IqnIlsAccelerator again(0.1, 0);
  again.begin_step();
  for (int i = 0; i < m + 1; ++i) {
    again.next(x, h.J * x + h.b, next);
    x = next;
  }
  EXPECT_LT((x - x_star).norm(), 1e-8 * x_star.norm());
}

TEST(IqnIlsAccelerator, ColumnsReusedFromThePreviousStepsSpeedUpTheNextOne) {
  const int m = 8;
  std::srand(11);
  Linear h{Eigen::MatrixXd::Random(m, m) * 2.0, Eigen::VectorXd::Random(m)};
  IqnIlsAccelerator fresh(0.1, 0), reusing(0.1, 4);
  iterations_to_converge(fresh, h, Eigen::VectorXd::Zero(m), 1e-9);
  iterations_to_converge(reusing, h, Eigen::VectorXd::Zero(m), 1e-9);
  Linear next_step{h.J, Eigen::VectorXd::Random(m)}; // same Jacobian, the next step's right-hand side
  const int without = iterations_to_converge(fresh, next_step, Eigen::VectorXd::Zero(m), 1e-9);
  const int with = iterations_to_converge(reusing, next_step, Eigen::VectorXd::Zero(m), 1e-9);
  std::printf("IQN-ILS on the next step: %d iterations without reuse, %d with\n", without, with);
  EXPECT_LE(with, 3);
  EXPECT_GT(without, with);
}

TEST(IqnIlsAccelerator, ItsColumnsSavedAndLoadedContinueBitForBit) {
  // A restart: the columns of the last steps go through the checkpoint archive; the next step
  // then takes the same iterates as without the restart, and as few as with reuse.
  const int m = 8;
  std::srand(12);
  Linear h{Eigen::MatrixXd::Random(m, m) * 2.0, Eigen::VectorXd::Random(m)};
  IqnIlsAccelerator running(0.1, 4), resumed(0.1, 4), afresh(0.1, 4);
  iterations_to_converge(running, h, Eigen::VectorXd::Zero(m), 1e-9);
  checkpoint::StateArchive archive;
  running.save_state(archive);
  resumed.load_state(archive, m);
  afresh.load_state(checkpoint::StateArchive(), m); // a part without columns
  EXPECT_EQ(resumed.n_columns(), running.n_columns());
  Linear next_step{h.J, Eigen::VectorXd::Random(m)};
  const int n_running = iterations_to_converge(running, next_step, Eigen::VectorXd::Zero(m), 1e-9);
  const int n_resumed = iterations_to_converge(resumed, next_step, Eigen::VectorXd::Zero(m), 1e-9);
  const int n_afresh = iterations_to_converge(afresh, next_step, Eigen::VectorXd::Zero(m), 1e-9);
  EXPECT_EQ(n_resumed, n_running);
  EXPECT_GT(n_afresh, n_resumed);
  Eigen::VectorXd a, b;
  const Eigen::VectorXd x = Eigen::VectorXd::Random(m), x_tilde = next_step.J * x + next_step.b;
  running.begin_step();
  resumed.begin_step();
  running.next(x, x_tilde, a);
  resumed.next(x, x_tilde, b);
  EXPECT_TRUE((a.array() == b.array()).all());
  EXPECT_THROW(IqnIlsAccelerator(0.1, 4).load_state(archive, m + 1), std::exception); // another size
}

} // namespace
} // namespace fsi::coupler
