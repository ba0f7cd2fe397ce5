// Metrics of a closed-loop run. metric_table() is their one definition (name, label, unit,
// definition): the results file, the bindings, the Python tables and docs/results.md all
// come from it. Integrals are trapezoid sums over the output grid; "position" is the model's
// position_indices() (x, y for the ship), "heading" its heading_index(); the heading error is
// wrapped to (-pi, pi] (angles.hpp); "last half" is the grid points with t >= (t0 + tf)/2.
// The tracking cost is the paper's L of eq. (37) on the run's errors (epsilon = 0):
//     L = |q_e(tf)|_Qf^2 + integral of |q_e|_Q^2 + |u - u_d|^2 dt,
// and the attenuation margin compares it with the right side of the H-infinity law's bound
// (eq. 39 with M = 0, which holds for the linearized loop):
//     margin = 1 - L / (gamma^2 ||w||^2 + initial_term),
// initial_term = q_e(t0)' Z(t0) q_e(t0) with state feedback (the game's value), gamma^2
// q_e(t0)' Q0 q_e(t0) with output feedback (eq. 39; the estimate starts at 0, w includes the
// measurement noise channels); negative when the bound is exceeded.
// A metric that does not apply (no position, no heading, no disturbance, no output feedback,
// no bound) is NaN. A run that stopped early (status Diverged) reports only
// max_position_error and heading_excursion, over the part it ran.
#pragma once

#include <array>

#include "hinf/control/simulation.hpp"
#include "hinf/models/model.hpp"

namespace hinf {

// The metrics of one run, each defined by its row of metric_table().
struct Metrics {
  double rms_position_error_last_half = NAN;
  double max_position_error = NAN;
  double final_position_error = NAN;
  double rms_heading_error_last_half = NAN;
  double final_heading_error = NAN;
  double control_l2 = NAN;
  double control_error_l2 = NAN;
  double disturbance_l2 = NAN;
  double disturbance_gain = NAN;
  double response_ratio = NAN;
  double tracking_cost = NAN;
  double attenuation_margin = NAN;
  double heading_excursion = NAN;
  double turned_around = NAN;
  double max_rho_sigma_z = NAN;
  double rms_estimation_error_last_half = NAN;
};

// The definition of one metric: a row of metric_table().
struct MetricDefinition {
  const char* name;        // key in the results file and in Python's RunResult.metrics
  const char* label;       // for tables
  const char* unit;        // for the ship; "-" is dimensionless
  const char* definition;  // what is computed
  double Metrics::*value;  // where compute_metrics() puts it
};

constexpr std::size_t kMetricCount = 16;
// The metrics, in the order of the results file.
const std::array<MetricDefinition, kMetricCount>& metric_table();

// What the tracking cost and the attenuation margin weigh (see above).
struct CostWeights {
  Mat Q;                      // weight of q_e (n x n, symmetric positive semidefinite)
  Mat Qf;                     // weight of q_e(tf) (n x n); empty: no terminal term
  double gamma = INFINITY;    // the law's attenuation level; infinite: no margin
  double initial_term = NAN;  // the bound's initial-error term (see above); NaN: no margin
};

// Turned around (metric turned_around, the recovery study's verdict): the heading error e,
// followed through its wraps from wrap(e(t0)), passes max(pi, |e(t0)|) + kTurnMargin (it went
// through +-pi), or |wrap(e)| > pi/2 on more than kBackwardsFraction of the last half (it
// tracks the path backwards).
constexpr double kTurnMargin = 0.1;          // rad
constexpr double kBackwardsFraction = 0.5;

// The metrics of a closed-loop run of `model` (whose position and heading indices they use),
// with Q (n x n, symmetric positive semidefinite) weighting q_e in the costs and gains.
// InputError when the run's series do not fit the model or Q is not such a weight.
Metrics compute_metrics(const Model& model, const SimulationResult& run, const Mat& Q);
// The same with the terminal weight and the bound of the H-infinity law (CostWeights); Qf must
// be an n x n symmetric positive semidefinite weight when given, gamma > 0, initial_term >= 0.
Metrics compute_metrics(const Model& model, const SimulationResult& run, const CostWeights& weights);

// sqrt of the trapezoid integral of the squared row norms of series over times t.
double l2_norm(const Vec& t, const RowMat& series);

}  // namespace hinf
