// The sampled-data closed loop, as on a vehicle: the plant integrated continuously,
//     dq/dt = f(t, q) + G(t, q) u + D(t, q) w(t),
// its full state measured at t_k = t0 + k T (T the law's period), the measurement handed to the
// online controller (online_controller.hpp) at t_k + delay, and the command it returns applied
// from then on and held. The loop calls exactly the code a vehicle runs: OnlineController::step.
// Between events (samples, commands, output times) the plant is integrated by Dormand-Prince
// 5(4) at the solver options' tolerances, restarted at each event (the command jumps there).
// The time series are those of simulate_state_feedback (simulation.hpp): u is the command
// applied; a run that leaves the neighbourhood of the desired trajectory stops as Diverged.
// Past the law's last sample (t_end <= tf) the controller answers PastHorizon and the last
// command stays held; controller.counts() tells.
// An output-feedback controller (OnlineController::output_feedback()) is handed the measurement
// y_k = C q(t_k) + sigma v_k instead (C the plant's, v_k row k of the noise: standard normal
// samples, one per sample and measured output, as noise_sample_count and
// standard_normal_samples of output_feedback.hpp give them for the law's period), and starts
// from the estimate q_hat(t0) = 0 (the state q_d(t0)), as the paper's estimator.
#pragma once

#include "hinf/control/disturbance.hpp"
#include "hinf/control/online_controller.hpp"
#include "hinf/control/online_receding_horizon.hpp"
#include "hinf/control/simulation.hpp"

namespace hinf {

// The choices of the sampled loop.
struct SampledLoopOptions {
  double delay = 0.0;             // s, in [0, T]: the command computed from the measurement of
                                  // t_k is applied from t_k + delay (T: one sample late)
  SimulationOptions simulation;   // output grid, divergence bound, tolerances (method: erk always)
  int measurement_every = 1;      // the sensor is read at every this many-th sample (k = 0, e,
                                  // 2e, ...); the other samples are steps without a measurement
  double sigma = 0.0;             // output feedback: the noise's standard deviation per sample
  RowMat noise;                   // output feedback: v, one row per sample, one column per output
                                  // (empty when sigma = 0)
  void validate(double period) const;  // InputError naming the option
};

// The loop of `plant` (null: the trajectory's model) under `controller` (reset here at t0 with
// q0), from q0 at t0 to the trajectory's tf. InputError for sizes that do not match (as
// simulate_state_feedback), a controller on another trajectory than `trajectory`, bad options;
// SolverError when the integration fails.
SimulationResult simulate_sampled(const Trajectory& trajectory, OnlineController& controller,
                                  const Disturbance& disturbance, const Vec& q0, const SampledLoopOptions& options = {},
                                  const Model* plant = nullptr);
// The same loop under the receding horizon's online controller (online_receding_horizon.hpp),
// synchronized before every step (the run does not depend on how fast its windows are solved).
// `trajectory` is the reference of the run's q_d series and divergence bound: the desired
// trajectory integrated over [t0, tf] from the horizon's q_d0 with its u_d (the windows chain into
// it within their integration error); InputError when it does not start as the horizon does.
SimulationResult simulate_sampled(const Trajectory& trajectory, RecedingOnlineController& controller,
                                  const Disturbance& disturbance, const Vec& q0, const SampledLoopOptions& options = {},
                                  const Model* plant = nullptr);

}  // namespace hinf
