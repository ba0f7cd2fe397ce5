#include "hinf/control/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

namespace {

constexpr double kPi = 3.14159265358979323846;

double trapezoid(const Vec& t, const Vec& values) {
  double sum = 0.0;
  for (Eigen::Index k = 1; k < t.size(); ++k)
    sum += 0.5 * (t[k] - t[k - 1]) * (values[k] + values[k - 1]);
  return sum;
}

// The largest finite-or-not magnitude, and the magnitudes divided by it: squares of values
// beyond 1e154 overflow, squares of the scaled ones do not.
double scale_of(const Vec& magnitudes) {
  const double largest = magnitudes.size() > 0 ? magnitudes.maxCoeff() : 0.0;
  return largest > 0.0 && std::isfinite(largest) ? largest : 1.0;
}

// sqrt(integral of magnitude^2) by the trapezoid rule.
double root_integral_of_squares(const Vec& t, const Vec& magnitudes) {
  const double scale = scale_of(magnitudes);
  return scale * std::sqrt(std::max(0.0, trapezoid(t, (magnitudes / scale).array().square().matrix())));
}

// sqrt of the plain mean of magnitude^2 over the grid points with t >= (t0 + tf) / 2.
double rms_over_last_half(const Vec& t, const Vec& magnitudes) {
  const double t_half = 0.5 * (t[0] + t[t.size() - 1]);
  const double scale = scale_of(magnitudes);
  double sum = 0.0;
  long used = 0;
  for (Eigen::Index k = 0; k < t.size(); ++k)
    if (t[k] >= t_half) {
      sum += (magnitudes[k] / scale) * (magnitudes[k] / scale);
      ++used;
    }
  return used > 0 ? scale * std::sqrt(sum / used) : NAN;
}

// The Euclidean norm of each row (without overflow).
Vec row_norms(const RowMat& series) {
  Vec norms(series.rows());
  for (Eigen::Index k = 0; k < series.rows(); ++k) norms[k] = series.row(k).stableNorm();
  return norms;
}

}  // namespace

const std::array<MetricDefinition, kMetricCount>& metric_table() {
  static const std::array<MetricDefinition, kMetricCount> table{{
      {"rms_position_error_last_half", "RMS position error, last half", "m",
       "sqrt(mean over the last half of |p - p_d|^2)", &Metrics::rms_position_error_last_half},
      {"max_position_error", "max position error", "m", "max over the grid of |p - p_d|",
       &Metrics::max_position_error},
      {"final_position_error", "final position error", "m", "|p - p_d| at tf", &Metrics::final_position_error},
      {"rms_heading_error_last_half", "RMS heading error, last half", "rad",
       "sqrt(mean over the last half of wrap(psi - psi_d)^2)", &Metrics::rms_heading_error_last_half},
      {"final_heading_error", "final heading error", "rad", "|wrap(psi - psi_d)| at tf",
       &Metrics::final_heading_error},
      {"heading_excursion", "largest heading error, followed through its wraps", "rad",
       "max over the grid of |e|, e = psi - psi_d followed continuously from wrap(e(t0)) (a full turn reads 2 pi)",
       &Metrics::heading_excursion},
      {"turned_around", "turned around", "-",
       "1 when |e| passes max(pi, |e(t0)|) + 0.1 (through +-pi) or |wrap(e)| > pi/2 on more than half of"
       " the last half (tracks backwards), else 0 (docs/baselines.md)",
       &Metrics::turned_around},
      {"control_l2", "control L2 norm", "input s^1/2", "sqrt(integral of |u|^2)", &Metrics::control_l2},
      {"control_error_l2", "control correction L2 norm", "input s^1/2", "sqrt(integral of |u - u_d|^2)",
       &Metrics::control_error_l2},
      {"disturbance_l2", "disturbance L2 norm", "w s^1/2",
       "sqrt(integral of |w|^2) over every applied channel (the noise channels when sigma > 0)",
       &Metrics::disturbance_l2},
      {"disturbance_gain", "L2 gain from the desired start", "-",
       "sqrt(tracking_cost) / disturbance_l2 for a run that starts on the desired trajectory (q_e(t0) = 0);"
       " NaN from any other start (see response_ratio)",
       &Metrics::disturbance_gain},
      {"response_ratio", "response / disturbance ratio (initial error included)", "-",
       "sqrt(tracking_cost) / disturbance_l2 from any start: includes the response to the initial error",
       &Metrics::response_ratio},
      {"tracking_cost", "tracking cost L (eq. 37)", "-",
       "|q_e(tf)|_Qf^2 + integral of |q - q_d|_Q^2 + |u - u_d|^2", &Metrics::tracking_cost},
      {"attenuation_margin", "attenuation margin (eq. 39)", "-",
       "1 - tracking_cost / (gamma^2 disturbance_l2^2 + the initial-error term): >= 0 when the H-infinity"
       " law's bound holds (hinf law only)",
       &Metrics::attenuation_margin},
      {"max_rho_sigma_z", "max rho(Sigma Z)", "-",
       "max over the grid of the spectral radius of Sigma Z (output feedback; below gamma^2)",
       &Metrics::max_rho_sigma_z},
      {"rms_estimation_error_last_half", "RMS estimation error, last half", "state",
       "sqrt(mean over the last half of |q_hat - (q - q_d)|^2) (output feedback)",
       &Metrics::rms_estimation_error_last_half},
  }};
  return table;
}

double l2_norm(const Vec& t, const RowMat& series) { return root_integral_of_squares(t, row_norms(series)); }

Metrics compute_metrics(const Model& model, const SimulationResult& run, const Mat& Q) {
  CostWeights weights;
  weights.Q = Q;
  return compute_metrics(model, run, weights);
}

Metrics compute_metrics(const Model& model, const SimulationResult& run, const CostWeights& weights) {
  const Mat& Q = weights.Q;
  // The run must be one of this model: its columns are indexed by the model's states.
  if (run.t.size() > 0 && run.q.rows() > 0 && run.q.cols() == model.n())
    validate_model(model, run.t[0], run.q.row(0).transpose());
  else
    check_structure(structure_of(model));
  const auto check_series = [&](const RowMat& series, int columns, const char* name) {
    require(series.rows() == run.t.size() && series.cols() == columns, "compute_metrics: run.", name, " has shape (",
            series.rows(), ", ", series.cols(), "), expected (", run.t.size(), ", ", columns,
            ") for the model '", model.name(), "': pass the model the run was simulated with");
  };
  check_series(run.q, model.n(), "q");
  check_series(run.q_d, model.n(), "q_d");
  check_series(run.u, model.m(), "u");
  check_series(run.u_d, model.m(), "u_d");
  check_series(run.w, model.nw(), "w");
  if (run.estimator) check_series(run.estimator->q_hat, model.n(), "estimator.q_hat");
  check_symmetric_weight(Q, model.n(), "Q", false);
  if (weights.Qf.size() > 0) check_symmetric_weight(weights.Qf, model.n(), "Qf", false);
  require(weights.gamma > 0.0, "compute_metrics: gamma must be > 0 (infinite: no margin), got ", weights.gamma);
  require(std::isnan(weights.initial_term) || (weights.initial_term >= 0.0 && std::isfinite(weights.initial_term)),
          "compute_metrics: initial_term must be a finite number >= 0 (NaN: no margin), got ", weights.initial_term);
  Metrics metrics;
  const Eigen::Index count = run.t.size();
  if (count == 0) return metrics;
  const int heading = model.heading_index();
  const RowMat q_e = run.q_e();
  const RowMat u_e = run.u - run.u_d;

  const std::vector<int> position = model.position_indices();
  const bool completed = run.status != RunStatus::Diverged;  // integrated to tf (LostTrack too)
  if (!position.empty()) {
    RowMat position_error(count, static_cast<Eigen::Index>(position.size()));
    for (std::size_t c = 0; c < position.size(); ++c) position_error.col(static_cast<Eigen::Index>(c)) = q_e.col(position[c]);
    const Vec error = row_norms(position_error);
    metrics.max_position_error = error.maxCoeff();
    if (completed) {
      metrics.rms_position_error_last_half = rms_over_last_half(run.t, error);
      metrics.final_position_error = error[count - 1];
    }
  }
  if (heading >= 0) {
    // The heading error followed continuously from its wrapped start: each step adds its wrapped
    // increment, so a full turn reads 2 pi (the wrapped error alone would read 0).
    double followed = q_e(0, heading), largest = std::abs(followed);
    for (Eigen::Index k = 1; k < count; ++k) {
      followed += wrap_angle(q_e(k, heading) - q_e(k - 1, heading));
      largest = std::max(largest, std::abs(followed));
    }
    metrics.heading_excursion = std::isfinite(followed) ? largest : std::numeric_limits<double>::infinity();
    if (completed) {
      // Turned around: through +-pi, or pointing backwards for most of the last half.
      const bool through = metrics.heading_excursion > std::max(kPi, std::abs(q_e(0, heading))) + kTurnMargin;
      const double t_half = 0.5 * (run.t[0] + run.t[count - 1]);
      long last = 0, backwards = 0;
      for (Eigen::Index k = 0; k < count; ++k)
        if (run.t[k] >= t_half) {
          ++last;
          if (std::abs(q_e(k, heading)) > 0.5 * kPi) ++backwards;
        }
      const bool backwards_tracking = last > 0 && static_cast<double>(backwards) > kBackwardsFraction * last;
      metrics.turned_around = through || backwards_tracking ? 1.0 : 0.0;
    }
  }
  // A run that stopped early has no last half, no final error and no integral over [t0, tf].
  if (!completed) return metrics;
  if (heading >= 0) {
    metrics.rms_heading_error_last_half = rms_over_last_half(run.t, q_e.col(heading).cwiseAbs());
    metrics.final_heading_error = std::abs(q_e(count - 1, heading));
  }
  metrics.control_l2 = l2_norm(run.t, run.u);
  metrics.control_error_l2 = l2_norm(run.t, u_e);
  metrics.disturbance_l2 = l2_norm(run.t, run.w);
  // |(Q^1/2 q_e, u_e)| at each output time, computed on the values scaled by their largest.
  Vec performance(count);
  for (Eigen::Index k = 0; k < count; ++k) {
    const double scale = std::max({q_e.row(k).cwiseAbs().maxCoeff(), u_e.row(k).cwiseAbs().maxCoeff(),
                                   std::numeric_limits<double>::min()});
    const Vec e = q_e.row(k).transpose() / scale;
    performance[k] = scale * std::sqrt(std::max(0.0, e.dot(Q * e) + (u_e.row(k) / scale).squaredNorm()));
  }
  const double output_l2 = root_integral_of_squares(run.t, performance);
  double terminal = 0.0;
  if (weights.Qf.size() > 0) {
    const Vec e_f = q_e.row(count - 1).transpose();
    const double scale = std::max(e_f.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
    terminal = scale * scale * std::max(0.0, (e_f / scale).dot(weights.Qf * (e_f / scale)));
  }
  metrics.tracking_cost = output_l2 * output_l2 + terminal;
  if (metrics.disturbance_l2 > 0.0) {
    metrics.response_ratio = std::sqrt(metrics.tracking_cost) / metrics.disturbance_l2;
    if (q_e.row(0).cwiseAbs().maxCoeff() == 0.0) metrics.disturbance_gain = metrics.response_ratio;
  }
  if (std::isfinite(weights.gamma) && !std::isnan(weights.initial_term)) {
    const double bound =
        weights.gamma * weights.gamma * metrics.disturbance_l2 * metrics.disturbance_l2 + weights.initial_term;
    if (bound > 0.0) metrics.attenuation_margin = 1.0 - metrics.tracking_cost / bound;
  }

  if (run.estimator) {
    metrics.max_rho_sigma_z = run.estimator->rho_sigma_z.maxCoeff();
    RowMat estimation_error = run.estimator->q_hat - q_e;
    if (heading >= 0)
      for (Eigen::Index k = 0; k < count; ++k) estimation_error(k, heading) = wrap_angle(estimation_error(k, heading));
    metrics.rms_estimation_error_last_half = rms_over_last_half(run.t, row_norms(estimation_error));
  }
  return metrics;
}

}  // namespace hinf
