// Metrics of a closed-loop run. metric_table() is their one definition (name, label, unit,
// definition): the results file, the bindings, the Python tables and docs/results.md all
// come from it. Integrals are trapezoid sums over the output grid; "position" is the model's
// position_indices() (x, y for the ship), "heading" its heading_index(); the heading error is
// wrapped to (-pi, pi] (angles.hpp); "last half" is the grid points with t >= (t0 + tf)/2.
// A metric that does not apply (no position, no heading, no disturbance, no output feedback)
// is NaN. A run that stopped early (status Diverged) reports only max_position_error, over
// the part it ran.
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
  double l2_gain = NAN;
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

constexpr std::size_t kMetricCount = 11;
// The metrics, in the order of the results file.
const std::array<MetricDefinition, kMetricCount>& metric_table();

// The metrics of a closed-loop run of `model` (whose position and heading indices they use),
// with Q (n x n, symmetric positive semidefinite) weighting q_e in the L2 gain.
// InputError when the run's series do not fit the model or Q is not such a weight.
Metrics compute_metrics(const Model& model, const SimulationResult& run, const Mat& Q);

// sqrt of the trapezoid integral of the squared row norms of series over times t.
double l2_norm(const Vec& t, const RowMat& series);

}  // namespace hinf
