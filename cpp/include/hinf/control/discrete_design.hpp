// The digital design: the H-infinity tracking design for a computer that measures every T seconds
// and holds its command until the next sample (zero-order hold). Basar & Bernhard, "H-infinity
// optimal control and related minimax design problems", 2nd ed. 1995, ch. 3 (the discrete-time
// game with perfect state measurements).
//
// Sampling the error dynamics along the desired trajectory (trajectory.hpp)
//     dq_e/dt = A_e(t) q_e + B_e(t) u_e + D_e(t) w,   u_e and w held over [t_k, t_k + T),
// with t_k = t0 + k T, k = 0 .. N-1, gives exactly the linear recursion
//     x_{k+1} = A_k x_k + B_k u_k + D_k w_k,
//     A_k = Phi(t_{k+1}, t_k),  B_k = int_{t_k}^{t_{k+1}} Phi(t_{k+1}, s) B_e(s) ds,  D_k alike,
// Phi the transition matrix of A_e. The game's cost, the sampled counterpart of the GRDE's (it
// converges to it as T -> 0: weights T Q, T I and gamma^2 T),
//     |x_N|^2_Qf + sum_{k<N} ( T |x_k|^2_Q + T |u_k|^2 - gamma^2 T |w_k|^2 ),
// has the game Riccati difference equation, solved backward from M_N = Qf:
//     Lambda_k = I + (B_k B_k' - gamma^-2 D_k D_k') M_{k+1} / T,
//     M_k = T Q + A_k' M_{k+1} Lambda_k^-1 A_k.
// A saddle point exists if and only if (the discrete conjugate point condition)
//     gamma^2 T I - D_k' M_{k+1} D_k > 0   for every k;
// the smallest gamma that keeps it is the discrete gamma*_d (gamma_star_discrete, analysis.hpp),
// which tends to the continuous gamma* as T -> 0. The law and the worst-case disturbance are
//     u_k = u_d(t_k) - F_k q_e(t_k),   F_k = B_k' M_{k+1} Lambda_k^-1 A_k / T,
//     w_k = gamma^-2 D_k' M_{k+1} Lambda_k^-1 A_k q_e(t_k) / T.
// N is the number of whole samples in [t0, tf]: the design ends at t_N = t0 + N T <= tf (a
// remainder of the horizon shorter than T is not designed for). gamma = +inf is the discrete LQR.
#pragma once

#include <memory>
#include <vector>

#include "hinf/control/trajectory.hpp"
#include "hinf/core/types.hpp"

namespace hinf {

// The number of whole samples of `period` in [t0, tf] (a horizon that is a multiple of the period
// up to round-off counts as one): floor((tf - t0) / period). InputError for a period that is not
// finite and > 0, longer than the horizon, or of more than 1e8 samples.
int sample_count(double t0, double tf, double period);

// The linearization along the desired trajectory sampled at period T with the inputs held: A_k,
// B_k, D_k for k = 0 .. steps() - 1 (see above). Immutable; may be read from several threads.
class SampledLinearization {
 public:
  // Integrates the variational equations over each sample with classical Runge-Kutta steps of at
  // most kMaxSubstep (at least two per sample): their error, O(h^4), is far below the O(T)
  // difference between the sampled and the continuous design. InputError for a period that is
  // not finite and > 0, or longer than the horizon.
  SampledLinearization(TrajectoryPtr trajectory, double period);

  static constexpr double kMaxSubstep = 0.005;  // s

  // The desired trajectory it samples.
  const Trajectory& trajectory() const { return *trajectory_; }
  const TrajectoryPtr& trajectory_ptr() const { return trajectory_; }
  // The period T (s).
  double period() const { return period_; }
  // The number of samples N.
  int steps() const { return static_cast<int>(A_.size()); }
  // t_k = t0 + k T (s), k = 0 .. N.
  double time(int k) const { return trajectory_->t0() + k * period_; }
  // A_k (n x n), B_k (n x m), D_k (n x nw), k = 0 .. steps() - 1 (unchecked index).
  const Mat& A(int k) const { return A_[static_cast<std::size_t>(k)]; }
  const Mat& B(int k) const { return B_[static_cast<std::size_t>(k)]; }
  const Mat& D(int k) const { return D_[static_cast<std::size_t>(k)]; }

 private:
  TrajectoryPtr trajectory_;
  double period_;
  std::vector<Mat> A_, B_, D_;
};

using SampledLinearizationPtr = std::shared_ptr<const SampledLinearization>;

// The solution of the game Riccati difference equation: M_k and the gains F_k of the law.
// Immutable; may be read from several threads.
class DiscreteDesign {
 public:
  DiscreteDesign(SampledLinearizationPtr sampled, double gamma, std::vector<Mat> M, std::vector<Mat> F,
                 std::vector<Mat> W);

  // The sampled linearization it was solved on, and its trajectory.
  const SampledLinearization& sampled() const { return *sampled_; }
  const SampledLinearizationPtr& sampled_ptr() const { return sampled_; }
  const Trajectory& trajectory() const { return sampled_->trajectory(); }
  // The gamma of the game (+inf: the discrete LQR).
  double gamma() const { return gamma_; }
  // The period T (s).
  double period() const { return sampled_->period(); }
  // The number of samples N.
  int steps() const { return sampled_->steps(); }
  // t_k = t0 + k T (s), k = 0 .. N.
  double time(int k) const { return sampled_->time(k); }
  // The number of states n and of inputs m.
  int n() const { return trajectory().n(); }
  int m() const { return trajectory().m(); }
  // M_k (n x n, symmetric), k = 0 .. steps(); M_steps = Qf. InputError outside.
  const Mat& M(int k) const;
  // F_k (m x n): u_k = u_d(t_k) - F_k q_e(t_k), k = 0 .. steps() - 1. InputError outside.
  const Mat& gain(int k) const;
  // The worst-case disturbance's gain (nw x n): w_k = W_k q_e(t_k); zero for gamma = inf.
  const Mat& worst_case_gain(int k) const;
  // The sample that holds t: floor((t - t0) / T), within 1e-9 T of a sample time that sample;
  // InputError for t outside [t0, t_N).
  int sample_index(double t) const;

 private:
  SampledLinearizationPtr sampled_;
  double gamma_;
  std::vector<Mat> M_, F_, W_;
};

using DiscreteDesignPtr = std::shared_ptr<const DiscreteDesign>;

// Solves the game Riccati difference equation backward from M_N = Qf. Q (n x n) symmetric
// positive semidefinite, Qf symmetric positive definite, gamma > 0 (may be +inf). InputError for
// bad input; ConjugatePointError when gamma^2 T I - D_k' M_{k+1} D_k is not positive definite at
// some k (its t_escape() is t_k, the latest such sample: gamma is below gamma*_d).
DiscreteDesignPtr solve_discrete_game(const SampledLinearizationPtr& sampled, const Mat& Q, const Mat& Qf,
                                      double gamma);
// The same, sampling the trajectory at `period` first.
DiscreteDesignPtr solve_discrete_game(const TrajectoryPtr& trajectory, double period, const Mat& Q, const Mat& Qf,
                                      double gamma);

// The latest sample time t_k at which the existence condition fails (the recursion stops there),
// or NaN when it holds for every k: the pass/fail test of the discrete gamma*. Nothing is
// stored; the same input checks as solve_discrete_game.
double discrete_conjugate_time(const SampledLinearization& sampled, const Mat& Q, const Mat& Qf, double gamma);

}  // namespace hinf
