// The matrix Riccati differential equations of the paper, solved along a desired trajectory.
//
// GRDE, paper eq. (13), solved BACKWARD from Z(tf) = Qf:
//     -dZ/dt = A_e' Z + Z A_e + Q - Z (B B' - gamma^-2 D D') Z.
// Sign convention: Z > 0 is the cost-to-go matrix, V(t, q_e) = q_e' Z(t) q_e; the
// state-feedback law (17)/(18) is u = u_d - kappa B' Z q_e. gamma = +inf gives LQR. Here
// A = A_e(t), B = B_e(t) and D = D_e(t), the linearization along the desired trajectory
// (model.hpp, trajectory.hpp).
//
// Filter Riccati equation, paper eq. (36), solved FORWARD from Sigma(t0) = (Q0 - eta I)^-1:
//     dSigma/dt = A Sigma + Sigma A' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D D',
// here with A = A_e(t) (the linearization along the desired path; the output-feedback
// simulation also offers A(q_hat(t)), see output_feedback.hpp).
//
// Both solutions are kept as the integrator's dense output (symmetric half, types.hpp), so
// they are available at any t in [t0, tf] with the integrator's accuracy. A finite escape
// (a conjugate point: gamma <= gamma*, eq. 14) raises ConjugatePointError with the
// estimated escape time. A solution is immutable once solved (no caches; lookups take
// caller-owned cursors): several threads may evaluate one at once (run_scenarios shares one
// between runs, study.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hinf/control/trajectory.hpp"
#include "hinf/numerics/piecewise_polynomial.hpp"
#include "hinf/numerics/signal.hpp"
#include "hinf/numerics/solver_options.hpp"
#include "hinf/numerics/sparse_matrix.hpp"

namespace hinf {

// The counts of a Riccati solve or a closed-loop run, and the size of what it stored.
struct SolveStats {
  long steps = 0;     // accepted steps
  long rejected = 0;  // rejected steps (error test failures)
  long rhs_evals = 0;  // right-hand-side evaluations
  long jac_evals = 0;  // Jacobians (dense) or Schur factorizations (Lyapunov Newton systems)
  std::size_t memory_bytes = 0;  // stored dense output
  std::string method;  // the integrator that solved it: "erk", "adams", "bdf (dense Newton)",
                       // "bdf (Lyapunov Newton)", or "erk, then bdf (...) from t = ..." for
                       // Method::Auto
};

// A Riccati solution that should be positive semidefinite counts as such while its smallest
// eigenvalue is above -kSemidefiniteTolerance times its largest: a solution that decays to about
// zero (no process noise, no weight) crosses zero by round-off and integration error only.
constexpr double kSemidefiniteTolerance = 1e-6;

// The storage of a block-diagonal symmetric n x n matrix: the packed triangles (types.hpp) of
// its diagonal blocks one after the other, sum k(k+1)/2 numbers for blocks of sizes k. A Riccati
// equation whose model and weights are uncoupled in groups of states (Model::uncoupled_blocks)
// keeps X block-diagonal; it is integrated and stored in this form. One block of size n is the
// plain packed storage.
struct PackedBlocks {
  std::vector<int> start, size, offset;  // block b: states start[b] .. start[b] + size[b] - 1,
                                         // its packed triangle at offset[b]
  int n = 0;    // the matrix's size
  int dim = 0;  // numbers stored

  // Blocks of the given sizes (each >= 1), in order.
  explicit PackedBlocks(const std::vector<int>& sizes = {});
  int count() const { return static_cast<int>(size.size()); }
  bool all_of_size(int k) const;
  // X (n x n; the blocks only are read) into the storage, and back (zero off the blocks).
  void pack(const Mat& X, double* stored) const;
  void unpack(const double* stored, Mat& X) const;
  // The whole packed X (n(n+1)/2 numbers, types.hpp) from the storage.
  void expand(const double* stored, double* packed) const;
};

// A symmetric-matrix-valued solution X(t) on [t0, tf] kept as dense output.
class SymmetricSolution {
 public:
  // X's dense output in the storage of `blocks` (empty: one block, the plain packed X).
  SymmetricSolution(TrajectoryPtr trajectory, double gamma, PiecewisePolynomial X, SolveStats stats,
                    std::vector<int> blocks = {});
  virtual ~SymmetricSolution() = default;

  // The desired trajectory it was solved along.
  const Trajectory& trajectory() const { return *trajectory_; }
  const TrajectoryPtr& trajectory_ptr() const { return trajectory_; }
  // The size of X: n x n, the trajectory's states.
  int n() const { return n_; }
  // The gamma of the equation (+inf: LQR, or the Kalman-Bucy filter).
  double gamma() const { return gamma_; }
  // The horizon [t0, tf] (s), the trajectory's.
  double t0() const { return trajectory_->t0(); }
  double tf() const { return trajectory_->tf(); }

  // X(t) (n x n, symmetric) from the dense output; t outside [t0, tf] is an InputError.
  Mat value(double t) const;
  // dX/dt at t (per second): the derivative of the dense output.
  Mat derivative(double t) const;
  // Packed symmetric half of X(t) (types.hpp).
  void packed(double t, double* out, std::size_t* cursor = nullptr) const;
  // Smallest and largest eigenvalue of X over the given times.
  void eigenvalue_range(const std::vector<double>& times, double& lambda_min, double& lambda_max) const;
  // m and M with m I <= X(t) <= M I on the whole interval (paper eq. 22): the extremes over
  // the ends and midpoints of the solver's steps, each refined by a golden-section search
  // over the neighbouring steps.
  void eigenvalue_bounds(double& lambda_min, double& lambda_max) const;

  // The dense output of X as stored (PackedBlocks of blocks(): the packed upper triangle,
  // n(n+1)/2 components, unless X was solved in uncoupled blocks) and the counts of its solve.
  const PiecewisePolynomial& dense() const { return X_; }
  const SolveStats& stats() const { return stats_; }
  // The sizes of the diagonal blocks X is stored in ({n}: the whole X).
  const std::vector<int>& blocks() const { return blocks_.size; }

 protected:
  TrajectoryPtr trajectory_;
  int n_;
  double gamma_;
  PiecewisePolynomial X_;
  SolveStats stats_;
  PackedBlocks blocks_;

 private:
  Mat unpacked(double t, bool derivative) const;
};

// Z(t) of the GRDE (13).
class RiccatiSolution final : public SymmetricSolution {
 public:
  RiccatiSolution(TrajectoryPtr trajectory, double gamma, PiecewisePolynomial Z, SolveStats stats,
                  std::vector<int> blocks = {});

  // The model's number of inputs (the rows of the gain).
  int m() const { return m_; }
  // Z(t) (n x n) and dZ/dt: value(t) and derivative(t).
  Mat Z(double t) const { return value(t); }
  Mat dZdt(double t) const { return derivative(t); }
  void Z_packed(double t, double* out, std::size_t* cursor = nullptr) const { packed(t, out, cursor); }
  // K(t) = B_e(t)' Z(t) (m x n), the gain of the state-feedback law (17), B_e(t) = G(t, q_d(t)).
  Mat gain(double t) const;
  void gain(double t, double* out, std::size_t* cursor = nullptr) const;  // column-major into out (m n)

 private:
  int m_;
  // Constant B as its nonzeros: K = B' Z costs one multiply-add per nonzero and column of Z,
  // computed from the packed Z.
  bool constant_B_ = false;
  SparseMatrix B_;
};

// Sigma(t) of the filter Riccati equation (36) with A = A_e(t).
class FilterRiccatiSolution final : public SymmetricSolution {
 public:
  using SymmetricSolution::SymmetricSolution;
  // Sigma(t) (n x n) and dSigma/dt: value(t) and derivative(t).
  Mat Sigma(double t) const { return value(t); }
  Mat dSigma_dt(double t) const { return derivative(t); }
};

using RiccatiSolutionPtr = std::shared_ptr<const RiccatiSolution>;
using FilterRiccatiSolutionPtr = std::shared_ptr<const FilterRiccatiSolution>;

// Solves the GRDE (13) backward from Z(tf) = Qf over the trajectory's horizon.
// Q (n x n) symmetric positive semidefinite, Qf symmetric positive definite, gamma > 0
// (may be +inf). Throws InputError, SolverError or ConjugatePointError.
RiccatiSolutionPtr solve_grde(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                              double gamma, const SolverOptions& options = {});

// The stabilizing solution P of the stationary game Riccati equation, the GRDE (13) with its
// derivative zero at constant A, B, D (n x n, n x m, n x nw):
//     A' P + P A + Q - P (B B' - gamma^-2 D D') P = 0,   A - (B B' - gamma^-2 D D') P stable.
// Q (n x n) symmetric positive semidefinite, gamma > 0 (may be +inf: the LQR equation).
// InputError for bad sizes or values, or when there is no stabilizing, positive semidefinite
// solution (gamma at or below the stationary game's gamma*, or (A, B) not stabilizable).
Mat solve_game_are(const Mat& A, const Mat& B, const Mat& D, const Mat& Q, double gamma);

// Solves the filter Riccati equation (36) forward from Sigma(t0) = Sigma0, with the model's
// measurement matrix C (Model::C), N (p x p) positive definite, Q (n x n) positive
// semidefinite, gamma > 0 (may be +inf: the Kalman-Bucy filter), A = A_e(t).
FilterRiccatiSolutionPtr solve_filter_riccati(const TrajectoryPtr& trajectory, const Mat& N,
                                              const Mat& Q, double gamma, const Mat& Sigma0,
                                              const SolverOptions& options = {});

// The first finite escape of Z (integrating the GRDE backward from tf): a conjugate point
// on [t0, tf] (paper eq. 14), or NaN when there is none. Nothing is stored; the same input
// checks as solve_grde. The escape is located on the inverse W = Z^-1, which is smooth
// there, so no escape between solver steps is missed.
double grde_escape_time(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, double gamma,
                        const SolverOptions& options = {});
// An escape test's answer with its work: the first escape time (NaN: none) and the right-hand
// sides of the Riccati equations it evaluated (the continuation on W included).
struct EscapeTest {
  double t_escape = NAN;
  long rhs_evals = 0;
};
// grde_escape_time with its work (gamma_star reports the cost of its search from it).
EscapeTest grde_escape_test(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, double gamma,
                            const SolverOptions& options = {});
// The same for the filter Riccati equation (36) (forward from Sigma0, A = A_e(t)).
double filter_escape_time(const TrajectoryPtr& trajectory, const Mat& N, const Mat& Q, double gamma,
                          const Mat& Sigma0, const SolverOptions& options = {});

// The closed loop of a state-feedback law: u = u_d - kappa(t) K(t) (q - q_d), K = B_e' Z(t) of
// `law` (a design at any gamma: the H-infinity law at its own gamma, the LQR law at gamma = inf),
// linearized along the design's trajectory, with x = q - q_d and the weighted error z,
//     dx/dt = (A_e - B_e K) x + D_e w,   z'z = x'Q x + |K x|^2 (kappa folded into K),
// plus x(tf)' Qf x(tf) at the end. From x(t0) = 0 its induced L2 gain over [t0, tf],
// sup_w (|z|^2 + x(tf)'Qf x(tf)) / |w|^2, is below gamma exactly when
//     -dP/dt = A_cl' P + P A_cl + Q + K'K + gamma^-2 P D_e D_e' P,   P(tf) = Qf,
// has no conjugate point on [t0, tf]. The first escape of P (backward from tf), or NaN;
// nothing is stored. Q symmetric positive semidefinite, Qf positive definite, gamma > 0, kappa > 0.
double law_escape_time(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf, double gamma,
                       const Signal& kappa = Signal(1.0), const SolverOptions& options = {});
// law_escape_time with its work.
EscapeTest law_escape_test(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf, double gamma,
                           const Signal& kappa = Signal(1.0), const SolverOptions& options = {});
// P of that equation at gamma, stored: the law's worst-case disturbance is w = gamma^-2 D_e' P x.
// ConjugatePointError when gamma is at or below the law's gain.
std::shared_ptr<const SymmetricSolution> solve_law_riccati(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf,
                                                           double gamma, const Signal& kappa = Signal(1.0),
                                                           const SolverOptions& options = {});

class Controller;  // controller.hpp
// The same two for any state-feedback controller of the trajectory's model (the ship
// baselines, a law written in Python), linearized along the trajectory: K(t) = -du/dq at
// (t, q_d(t)) from controller.control_jacobian (central differences unless it has its own).
// Calls the controller from this thread only. InputError for a controller of other sizes.
double controller_escape_time(const TrajectoryPtr& trajectory, Controller& controller, const Mat& Q, const Mat& Qf,
                              double gamma, const SolverOptions& options = {});
// controller_escape_time with its work.
EscapeTest controller_escape_test(const TrajectoryPtr& trajectory, Controller& controller, const Mat& Q,
                                  const Mat& Qf, double gamma, const SolverOptions& options = {});
// P at gamma for that controller, stored (its worst case is w = gamma^-2 D_e' P x).
std::shared_ptr<const SymmetricSolution> solve_controller_riccati(const TrajectoryPtr& trajectory,
                                                                  Controller& controller, const Mat& Q, const Mat& Qf,
                                                                  double gamma, const SolverOptions& options = {});

}  // namespace hinf
