// The digital output feedback: the discrete game of discrete_design.hpp with imperfect, sampled
// measurements, the command of sample k computed from y_0 .. y_k (the current-information
// pattern of Basar & Bernhard, "H-infinity optimal control and related minimax design problems",
// 2nd ed. 1995, ch. 6: a computer that measures at t_k and answers within the sample).
//
// The sampled error dynamics of discrete_design.hpp, measured:
//     x_{k+1} = A_k x_k + B_k u_k + D_k w_k,   y_k = C x_k + v_k,
// with the game's cost of discrete_design.hpp less gamma^2 (sum_k |v_k|^2_{R^-1} +
// |x_0|^2_{Sigma0^-1}): R is the covariance of one measurement (sigma^2 per sample, as on a
// datasheet), Sigma0 the initial uncertainty. In the variables that make the game's weights unit
// (u and w scaled by sqrt(T)), its filter Riccati difference equation runs forward from Sigma0:
//     Pi_k          = (Sigma_k^-1 + C' R^-1 C - gamma^-2 T Q)^-1,
//     Sigma_{k+1}   = A_k Pi_k A_k' + D_k D_k' / T,
// and the central controller acts on the worst-case state given y_0 .. y_k,
//     x_w           = x_hat_k + H_k (gamma^-2 M_k x_hat_k + C' R^-1 (y_k - C x_hat_k)),
//     H_k           = (Sigma_k^-1 + C' R^-1 C - gamma^-2 M_k)^-1,
//     u_k           = u_d(t_k) - F_k x_w,
//     x_hat_{k+1}   = A_k x_hat_k + B_k u_k + A_k Pi_k (gamma^-2 T Q x_hat_k + C' R^-1 (y_k - C x_hat_k)),
// with x_hat_0 the initial estimate (without y_k: x_w = (I - gamma^-2 Sigma_k M_k)^-1 x_hat_k and no
// C' R^-1 terms). It exists, and keeps the game's value below gamma^2, when for every k
//     (a) the state-feedback game exists (gamma^2 T I - D_k' M_{k+1} D_k > 0, discrete_design.hpp),
//     (b) Sigma_k^-1 + C' R^-1 C - gamma^-2 T Q > 0 (the filter exists),
//     (c) rho(Sigma_k M_k) < gamma^2 (the coupling condition).
// On a time-invariant plant the smallest gamma that keeps (a)-(c) is the optimal H-infinity norm of
// SLICOT's SB10DD (tests/python/test_discrete_output_feedback.py, to 1e-8), and the closed loop of
// the central controller has an H-infinity norm below gamma. As T -> 0 with R = N / T these become
// the continuous (36) and rho(Sigma Z) < gamma^2; at gamma = inf it is the discrete LQG controller
// (the Kalman filter and the discrete LQR).
#pragma once

#include <memory>
#include <vector>

#include "hinf/control/discrete_design.hpp"
#include "hinf/core/types.hpp"

namespace hinf {

// The filter Riccati solution along a digital design, with the coupling condition. Immutable;
// may be read from several threads.
class DiscreteOutputFeedback {
 public:
  DiscreteOutputFeedback(DiscreteDesignPtr design, Mat C, Mat R, Mat Q, std::vector<Mat> Sigma, std::vector<double> rho);

  // The state-feedback game it completes.
  const DiscreteDesign& design() const { return *design_; }
  const DiscreteDesignPtr& design_ptr() const { return design_; }
  // C (p x n), R (p x p), Q (n x n) as given.
  const Mat& C() const { return C_; }
  const Mat& R() const { return R_; }
  const Mat& Q() const { return Q_; }
  // Sigma_k (n x n), k = 0 .. steps(). InputError outside.
  const Mat& Sigma(int k) const;
  // rho(Sigma_k M_k) / gamma^2, k = 0 .. steps() (0 at gamma = inf): the coupling condition wants
  // < 1. InputError outside.
  double coupling(int k) const;
  // The largest coupling(k).
  double largest_coupling() const;
  int steps() const { return design_->steps(); }

 private:
  DiscreteDesignPtr design_;
  Mat C_, R_, Q_;
  std::vector<Mat> Sigma_;
  std::vector<double> rho_;
};

using DiscreteOutputFeedbackPtr = std::shared_ptr<const DiscreteOutputFeedback>;

// Solves the filter Riccati difference equation forward from Sigma0 along `design` and checks the
// coupling condition at every sample. C (p x n), R (p x p) symmetric positive definite, Sigma0
// (n x n) symmetric positive definite, Q (n x n) the game's state weight (the one `design` was
// solved with), symmetric positive semidefinite. InputError for bad input; ConjugatePointError
// when (b) fails at some k (its t_escape() is t_k: the filter escapes); CouplingConditionError
// when (c) fails (its t() is the first t_k, rho() is rho(Sigma_k M_k)). Both mean gamma is too
// small for this output feedback.
DiscreteOutputFeedbackPtr solve_discrete_output_feedback(const DiscreteDesignPtr& design, const Mat& C, const Mat& R,
                                                         const Mat& Sigma0, const Mat& Q);

}  // namespace hinf
