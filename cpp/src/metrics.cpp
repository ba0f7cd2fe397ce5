#include "hinf/metrics.hpp"

#include <cmath>

#include "hinf/angles.hpp"
#include "hinf/checks.hpp"
#include "hinf/errors.hpp"

namespace hinf {

namespace {

double trapezoid(const Vec& t, const Vec& values) {
  double sum = 0.0;
  for (Eigen::Index k = 1; k < t.size(); ++k)
    sum += 0.5 * (t[k] - t[k - 1]) * (values[k] + values[k - 1]);
  return sum;
}

// sqrt of the plain mean of squared[k] over the grid points with t >= (t0 + tf) / 2.
double rms_over_last_half(const Vec& t, const Vec& squared) {
  const double t_half = 0.5 * (t[0] + t[t.size() - 1]);
  double sum = 0.0;
  long used = 0;
  for (Eigen::Index k = 0; k < t.size(); ++k)
    if (t[k] >= t_half) {
      sum += squared[k];
      ++used;
    }
  return used > 0 ? std::sqrt(sum / used) : NAN;
}

}  // namespace

double l2_norm(const Vec& t, const RowMat& series) {
  return std::sqrt(trapezoid(t, series.rowwise().squaredNorm()));
}

Metrics compute_metrics(const Model& model, const SimulationResult& run, const Mat& Q) {
  // The run must be one of this model: its columns are indexed by the model's states.
  validate_model(model, run.t.size() > 0 ? run.t[0] : 0.0);
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
  if (run.q_hat.size() > 0) check_series(run.q_hat, model.n(), "q_hat");
  check_symmetric_weight(Q, model.n(), "Q", false);
  Metrics metrics;
  const Eigen::Index count = run.t.size();
  if (count == 0) return metrics;
  const int heading = model.heading_index();
  const RowMat q_e = run.q_e();
  const RowMat u_e = run.u - run.u_d;

  const std::vector<int> position = model.position_indices();
  if (!position.empty()) {
    Vec error(count);
    for (Eigen::Index k = 0; k < count; ++k) {
      double s = 0.0;
      for (int i : position) s += q_e(k, i) * q_e(k, i);
      error[k] = std::sqrt(s);
    }
    metrics.max_position_error = error.maxCoeff();
    // A run that stopped early has no last half and no final error.
    if (run.status != RunStatus::Completed) return metrics;
    metrics.rms_position_error_last_half = rms_over_last_half(run.t, error.array().square().matrix());
    metrics.final_position_error = error[count - 1];
  }
  if (run.status != RunStatus::Completed) return metrics;
  metrics.control_l2 = l2_norm(run.t, run.u);
  metrics.control_error_l2 = l2_norm(run.t, u_e);
  metrics.disturbance_l2 = l2_norm(run.t, run.w);
  Vec performance(count);
  for (Eigen::Index k = 0; k < count; ++k) {
    const Vec e = q_e.row(k).transpose();
    performance[k] = e.dot(Q * e) + u_e.row(k).squaredNorm();
  }
  const double output_l2 = std::sqrt(std::max(0.0, trapezoid(run.t, performance)));
  metrics.l2_gain = metrics.disturbance_l2 > 0.0 ? output_l2 / metrics.disturbance_l2 : NAN;

  if (run.rho_sigma_z.size() > 0) metrics.max_rho_sigma_z = run.rho_sigma_z.maxCoeff();
  if (run.q_hat.rows() == count) {
    RowMat estimation_error = run.q_hat - q_e;
    if (heading >= 0)
      for (Eigen::Index k = 0; k < count; ++k) estimation_error(k, heading) = wrap_angle(estimation_error(k, heading));
    const Vec squared = estimation_error.rowwise().squaredNorm();
    metrics.rms_estimation_error_last_half = rms_over_last_half(run.t, squared);
  }
  return metrics;
}

}  // namespace hinf
