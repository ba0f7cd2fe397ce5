// Metrics of a closed-loop run (scenarios.md, "The results file"). Integrals are trapezoid
// sums over the output grid; "position" is the model's position_indices() (x, y for the ship).
// A metric that does not apply (no position, no disturbance, no output feedback) is NaN. The
// heading error is wrapped to (-pi, pi] (angles.hpp). A run that stopped early (status
// Diverged) reports only max_position_error, over the part it ran.
#pragma once

#include "hinf/model.hpp"
#include "hinf/simulation.hpp"

namespace hinf {

struct Metrics {
  double rms_position_error_last_half = NAN;  // sqrt(mean over t >= (t0+tf)/2 of |p_e|^2)
  double max_position_error = NAN;            // max |p_e|
  double final_position_error = NAN;          // |p_e(tf)|
  double control_l2 = NAN;                    // sqrt(int |u|^2)
  double control_error_l2 = NAN;              // sqrt(int |u - u_d|^2)
  double disturbance_l2 = NAN;                // sqrt(int |w|^2), every applied channel
  double l2_gain = NAN;                       // sqrt(int |q_e|_Q^2 + |u_e|^2) / disturbance_l2
  double max_rho_sigma_z = NAN;               // output feedback: max rho(Sigma Z)
  double rms_estimation_error_last_half = NAN;  // output feedback: of |q_hat - q_e|
};

Metrics compute_metrics(const Model& model, const SimulationResult& run, const Mat& Q);

// sqrt of the trapezoid integral of the squared row norms of series over times t.
double l2_norm(const Vec& t, const RowMat& series);

}  // namespace hinf
