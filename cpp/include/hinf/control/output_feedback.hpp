// Imperfect measurements (paper §4): the H-infinity filter, the estimator and the
// output-feedback tracking law, simulated together with the nonlinear plant.
//
//   measurement (25):  y = C q + E w,  E w = sigma v_k on the model's noise channels, v_k a
//                      standard normal sample held on [t0 + k T, t0 + (k+1) T);
//   estimator (35):    dq_hat/dt = A(q_hat) q_hat + alpha(q_hat)
//                                  + G(t, q_d + q_hat) (u - u_d) + gamma^-2 D D' Z q_hat
//                                  + [I - gamma^-2 Sigma Z]^-1 Sigma C' N^-1 (y_e - C q_hat),
//                      q_hat(t0) = 0, y_e = y - C q_d(t); q_hat estimates the error q_e;
//                      A, alpha: the model's error_split; B = B_e(t), D = D_e(t) (model.hpp);
//                      with the paper's law and constant G = B the input terms are
//                      -(kappa B B' - gamma^-2 D D') Z q_hat, as in the paper;
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
//   auto, bdf  the same while the problem is not stiff; once Dormand-Prince's stiffness test
//          fires, the L-stable SDIRK4 (sdirk4.hpp) takes over, keeping its Jacobian across
//          intervals (a multistep BDF would restart at first order at every sample);
//   adams  CVODE Adams restarted at every sample (correct but slow).
// SimulationResult::integrator says what was used. The measured heading (and the heading
// innovation) is an angle, wrapped to (-pi, pi] (angles.hpp).
#pragma once

#include <cstdint>

#include "hinf/control/controller.hpp"
#include "hinf/control/disturbance.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/core/enum_names.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf {

// Number of noise samples held over `period` that cover [t0, tf] (the last may be partial).
long noise_sample_count(double t0, double tf, double period);
// count x channels standard normal samples from a seeded generator (mt19937_64 and the
// Marsaglia polar method): the same numbers for the same seed on every run.
RowMat standard_normal_samples(std::uint64_t seed, long count, int channels);

// Which A the filter Riccati equation (36) uses (scenario key [measurement] filter_A).
enum class FilterLinearization {
  Estimate,  // A(q_hat(t)): the decomposition (26)-(31) at the current estimate
  Desired    // A_e(t): the linearization along the desired trajectory
};
template <>
struct EnumNames<FilterLinearization> {
  static constexpr const char* what = "filter_A";
  static constexpr std::array<std::pair<FilterLinearization, const char*>, 2> names{
      {{FilterLinearization::Estimate, "estimate"}, {FilterLinearization::Desired, "desired"}}};
};

// What a violation of the coupling condition rho(Sigma Z) < gamma^2 does (scenario key
// [measurement] on_coupling_violation).
enum class CouplingPolicy {
  Error,  // a CouplingConditionError at the first output time with a violation
  Flag    // continue, and report the first violation's time in the estimator series
};
template <>
struct EnumNames<CouplingPolicy> {
  static constexpr const char* what = "on_coupling_violation";
  static constexpr std::array<std::pair<CouplingPolicy, const char*>, 2> names{
      {{CouplingPolicy::Error, "error"}, {CouplingPolicy::Flag, "flag"}}};
};

// The output-feedback problem: the design, the measurement noise and the filter's weights.
struct OutputFeedbackProblem {
  RiccatiSolutionPtr design;    // Z of the GRDE (13): its gamma and trajectory
  double sigma = 0.0;           // noise standard deviation: E w = sigma v on the noise channels
  double sample_period = 0.01;  // T (s): v is held over [t0 + k T, t0 + (k+1) T)
  RowMat noise;                 // v: standard normal samples, one row per hold interval
                                // (noise_sample_count rows), one column per measured output
  Mat N;                        // filter weight N = E E' (p x p, positive definite)
  Mat Sigma0;                   // Sigma(t0) = (Q0 - eta I)^-1 (n x n, positive definite)
  Mat Q;                        // weight of the performance index, in (36)
};

// The choices of the output-feedback loop.
struct OutputFeedbackOptions {
  FilterLinearization filter_A = FilterLinearization::Estimate;  // the A of the filter (36)
  CouplingPolicy on_coupling_violation = CouplingPolicy::Error;   // what a violation does
  bool sigma_eigenvalues = true;  // the series EstimatorSeries::sigma_min_eig and sigma_max_eig
                                  // (false: NaN). Every other output, the metrics and the check
                                  // that Sigma stays positive semidefinite are the same either
                                  // way; run_scenarios, which keeps only the metrics, turns it
                                  // off (a third of a Figure 2 run's time goes to eigenvalues on
                                  // the output grid).
};

// Simulates the output-feedback closed loop: filter and estimator of the problem's design
// (Z, gamma; its trajectory), control by `controller` at the estimated state q_d + q_hat.
// The result carries the estimator series. Throws CouplingConditionError when
// rho(Sigma Z) >= gamma^2 at an output time (unless options.on_coupling_violation is Flag), or
// when the integration stops between output times at the estimator gain's pole, where
// rho(Sigma Z) reaches gamma^2 (to 1e-3; with Flag this is a SolverError naming the violation).
// The measured heading (the row of C that picks the model's heading) and its innovation are
// angles, wrapped to (-pi, pi].
// The vehicle integrated is `plant` (null: the design's model), with y = C q of the plant; the
// estimator, the filter and the control stay those of the design (its model and trajectory).
SimulationResult simulate_output_feedback(const OutputFeedbackProblem& problem, Controller& controller,
                                          const Disturbance& disturbance, const Vec& q0,
                                          const OutputFeedbackOptions& options = {},
                                          const SimulationOptions& simulation = {}, const Model* plant = nullptr);

}  // namespace hinf
