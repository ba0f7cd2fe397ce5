// Imperfect measurements (paper §4): the H-infinity filter, the estimator and the
// output-feedback tracking law, simulated together with the nonlinear plant.
//
//   measurement (25):  y = C q + E w,  E w = sigma v_k on the model's noise channels, v_k a
//                      standard normal sample held on [t0 + k T, t0 + (k+1) T);
//   estimator (35):    dq_hat/dt = A(q_hat) q_hat + alpha(q_hat)
//                                  - (kappa B B' - gamma^-2 D D') Z q_hat
//                                  + [I - gamma^-2 Sigma Z]^-1 Sigma C' N^-1 (y_e - C q_hat),
//                      q_hat(t0) = 0, y_e = y - C q_d(t); q_hat estimates the error q_e;
//   filter (36):       dSigma/dt = A Sigma + Sigma A' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D D',
//                      Sigma(t0) = (Q0 - eta I)^-1, A = A(q_hat(t)) or A_e(t) (filter_A);
//   control (34):      u = u_d(t) - kappa B' Z(t) q_hat (the paper's law, kappa = 1), or any
//                      Controller evaluated at the estimated state q_d + q_hat (certainty
//                      equivalence, for the baselines); the estimator uses the control applied.
// The central controller needs I - gamma^-2 Sigma Z invertible: the coupling condition
// rho(Sigma Z) < gamma^2 is checked at every output time.
//
// The noise is piecewise constant, so the closed loop is integrated one hold interval at a
// time, and every interval is a restart. One-step methods restart at no cost, multistep
// methods restart at first order. Per SolverOptions::method:
//   erk    Dormand-Prince 5(4), its step size carried from interval to interval;
//   bdf    the same while the problem is not stiff; once Dormand-Prince's stiffness test fires,
//          the L-stable SDIRK4 (sdirk4.hpp) takes over, keeping its Jacobian across intervals;
//   adams  CVODE Adams restarted at every sample (correct but slow).
// SimulationResult::integrator says what was used.
#pragma once

#include <cstdint>

#include "hinf/riccati.hpp"
#include "hinf/controller.hpp"
#include "hinf/disturbance.hpp"
#include "hinf/signal.hpp"
#include "hinf/simulation.hpp"

namespace hinf {

// Number of noise samples held over `period` that cover [t0, tf] (the last may be partial).
long noise_sample_count(double t0, double tf, double period);
// count x channels standard normal samples from a seeded generator (mt19937_64 and the
// Marsaglia polar method): the same numbers for the same seed on every run.
RowMat standard_normal_samples(std::uint64_t seed, long count, int channels);

struct OutputFeedbackOptions {
  double sigma = 0.0;            // noise standard deviation: E w = sigma v on the noise channels
  double sample_period = 0.01;   // T (s)
  Mat N;                         // filter weight N = E E' (p x p, positive definite)
  Mat Sigma0;                    // Sigma(t0) = (Q0 - eta I)^-1 (n x n, positive definite)
  Mat Q;                         // weight of the performance index, in (36)
  bool filter_uses_estimate = true;    // filter_A = "estimate" (true) or "desired"
  bool stop_on_coupling_violation = true;  // false: continue and report the first violation
};

// Simulates the output-feedback closed loop: filter and estimator of the design `grde` (Z,
// gamma; its trajectory), control by `controller` at the estimated state q_d + q_hat.
// noise: standard normal samples, one row per hold interval (noise_sample_count rows) and one
// column per measured output. Fills q_hat, y, sigma_min_eig, sigma_max_eig, rho_sigma_z and
// coupling_violation_t of the result. Throws CouplingConditionError when rho(Sigma Z) >=
// gamma^2 at an output time (unless stop_on_coupling_violation is false).
SimulationResult simulate_output_feedback(const RiccatiSolution& grde, Controller& controller,
                                          const Disturbance& disturbance, const Vec& q0,
                                          const RowMat& noise, const OutputFeedbackOptions& options,
                                          double output_dt, const SolverOptions& solver);

}  // namespace hinf
