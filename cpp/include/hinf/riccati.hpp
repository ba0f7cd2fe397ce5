// The generalized Riccati differential equation (GRDE) of paper eq. (13), solved backward:
//
//     -dZ/dt = A_e' Z + Z A_e + Q - Z (B B' - gamma^-2 D D') Z,    Z(tf) = Qf,
//
// with A_e(t) the linearization along the desired trajectory (paper eq. 10). Sign
// convention: Z > 0 is the cost-to-go matrix, V(t, q_e) = q_e' Z(t) q_e; the state-feedback
// law (17)/(18) is u = u_d - kappa B' Z q_e. gamma = +inf gives the LQR Riccati equation.
//
// Z(t) is kept as the integrator's dense output (symmetric half, see types.hpp), so Z(t) and
// the gain K(t) = B(t)' Z(t) are available at any t in [t0, tf] with the integrator's
// accuracy. A finite escape of Z (a conjugate point: gamma <= gamma*, eq. 14) raises
// ConjugatePointError with the estimated escape time.
#pragma once

#include <memory>
#include <tuple>
#include <vector>

#include "hinf/piecewise_polynomial.hpp"
#include "hinf/solver_options.hpp"
#include "hinf/trajectory.hpp"

namespace hinf {

struct SolveStats {
  long steps = 0;
  long rejected = 0;  // rejected steps (error test failures)
  long rhs_evals = 0;
  long jac_evals = 0;
  std::size_t memory_bytes = 0;  // stored dense output
};

class RiccatiSolution {
 public:
  RiccatiSolution(TrajectoryPtr trajectory, double gamma, PiecewisePolynomial Z, SolveStats stats);

  const Trajectory& trajectory() const { return *trajectory_; }
  const TrajectoryPtr& trajectory_ptr() const { return trajectory_; }
  int n() const { return n_; }
  int m() const { return m_; }
  double gamma() const { return gamma_; }
  double t0() const { return trajectory_->t0(); }
  double tf() const { return trajectory_->tf(); }

  Mat Z(double t) const;
  Mat dZdt(double t) const;
  // Packed symmetric half of Z(t) (types.hpp).
  void Z_packed(double t, double* out, std::size_t* cursor = nullptr) const;
  // K(t) = B(t)' Z(t) (m x n), the gain of the state-feedback law (17).
  Mat gain(double t) const;
  // K(t) column-major into out (m * n numbers).
  void gain(double t, double* out, std::size_t* cursor = nullptr) const;
  // Smallest and largest eigenvalue of Z at each time (paper eq. 22).
  void eigenvalue_range(const std::vector<double>& times, double& lambda_min, double& lambda_max) const;

  const PiecewisePolynomial& dense() const { return Z_; }
  const SolveStats& stats() const { return stats_; }

 private:
  static constexpr int kMaxPackedOnStack = 136;  // n <= 16 without heap use
  TrajectoryPtr trajectory_;
  int n_, m_;
  double gamma_;
  PiecewisePolynomial Z_;
  // Constant B as (row, column, value) triplets of its nonzeros: K = B' Z costs one
  // multiply-add per nonzero and column of Z, computed from the packed Z.
  bool constant_B_ = false;
  std::vector<std::tuple<int, int, double>> B_nonzeros_;
  SolveStats stats_;
};

using RiccatiSolutionPtr = std::shared_ptr<const RiccatiSolution>;

// Solves the GRDE (13) backward from Z(tf) = Qf over the trajectory's horizon.
// Q (n x n) symmetric positive semidefinite, Qf symmetric positive definite, gamma > 0
// (may be +inf). Throws InputError, SolverError or ConjugatePointError.
RiccatiSolutionPtr solve_grde(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                              double gamma, const SolverOptions& options = {});

}  // namespace hinf
