// The discrete H-infinity filter, a-priori form (Simon, "Optimal state estimation", 2006, ch. 11;
// Shaked and Theodor, CDC 1992), for
//     x_{k+1} = F_k x_k + w_k,   y_k = H_k x_k + v_k,
// with Q the weight (covariance, for the Kalman limit) of w_k, R that of v_k (one measurement
// sample: sigma^2 per sample at the measurement period, as on a datasheet), S_bar_k = L' S_k L the
// weight of the estimation error and theta = gamma^-2:
//     K_k     = P_k [I - theta S_bar_k P_k + H' R^-1 H P_k]^-1 H' R^-1,
//     x_{k+1} = F x_k + F K_k (y_k - H x_k),
//     P_{k+1} = F P_k [I - theta S_bar_k P_k + H' R^-1 H P_k]^-1 F' + Q.
// The filter exists while P_k^-1 - theta S_bar_k + H' R^-1 H > 0. gamma = +inf (theta = 0) is the
// Kalman filter in its a-priori form (K_k = P_k H' (H P_k H' + R)^-1).
#pragma once

#include "hinf/core/types.hpp"

namespace hinf {

// One step of the recursion: the gain K_k (n x p) and P_{k+1} (n x n) from P_k. P_k symmetric
// positive definite (n x n), F (n x n), H (p x n), Q (n x n) symmetric positive semidefinite,
// R_inv = R^-1 (p x p) symmetric positive definite, S_bar (n x n) symmetric positive semidefinite,
// gamma > 0 (may be +inf). Returns false, leaving K and P_next unchanged, when the existence
// condition fails at this step. Checks nothing else: the caller checks its inputs once.
bool discrete_hinf_filter_step(const Mat& P, const Mat& F, const Mat& H, const Mat& Q, const Mat& R_inv,
                               const Mat& S_bar, double gamma, Mat& K, Mat& P_next);

}  // namespace hinf
