#include "hinf/control/trajectory.hpp"

#include <algorithm>
#include <cmath>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

Trajectory::Trajectory(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, double tf,
                       const TrajectoryOptions& options)
    : model_(std::move(model)), q_d0_(std::move(q_d0)), u_d_(std::move(u_d)), t0_(t0), tf_(tf) {
  check_arguments();
  require(options.rtol > 0 && options.atol > 0 && options.max_steps > 0,
          "trajectory tolerances and max_steps must be > 0");
  dense_ = PiecewisePolynomial(model_->n());
  Vec y = q_d0_;
  integrate(t0, tf, y, options, stats_);
  dense_.finalize();
  check_declarations();
}

Trajectory::Trajectory(ModelPtr model, std::vector<double> t_nodes, const RowMat& q_nodes, VectorSignal u_d,
                       const TrajectoryOptions& options)
    : model_(std::move(model)), u_d_(std::move(u_d)), node_times_(std::move(t_nodes)) {
  require(model_ != nullptr, "Trajectory needs a model");
  const std::size_t count = node_times_.size();
  require(count >= 2, "a desired trajectory given as states needs at least two nodes, got ", count);
  for (std::size_t k = 0; k < count; ++k)
    require(std::isfinite(node_times_[k]), "the desired states' time ", k, " is not finite");
  // From k = 1: require() evaluates its message's arguments before it tests the condition.
  for (std::size_t k = 1; k < count; ++k)
    require(node_times_[k] > node_times_[k - 1], "the desired states' times must increase: t[", k, "] = ",
            node_times_[k], " follows t[", k - 1, "] = ", node_times_[k - 1]);
  check_structure(structure_of(*model_));
  require(q_nodes.rows() == static_cast<Eigen::Index>(count) && q_nodes.cols() == model_->n(),
          "the desired states need one row of ", model_->n(), " numbers per time (", count, " x ", model_->n(),
          "), got ", q_nodes.rows(), " x ", q_nodes.cols());
  require(q_nodes.allFinite(), "the desired states are not all finite");
  require(options.rtol > 0 && options.atol > 0 && options.max_steps > 0,
          "trajectory tolerances and max_steps must be > 0");
  t0_ = node_times_.front();
  tf_ = node_times_.back();
  q_d0_ = q_nodes.row(0).transpose();
  check_arguments();
  dense_ = PiecewisePolynomial(model_->n());
  defects_.reserve(count - 1);
  for (std::size_t k = 0; k + 1 < count; ++k) {
    Vec y = q_nodes.row(static_cast<Eigen::Index>(k)).transpose();
    integrate(node_times_[k], node_times_[k + 1], y, options, stats_);
    defects_.push_back((y - q_nodes.row(static_cast<Eigen::Index>(k + 1)).transpose()).cwiseAbs().maxCoeff());
  }
  dense_.finalize();
  check_declarations();
}

void Trajectory::integrate(double a, double b, Vec& y, const TrajectoryOptions& options, StepStats& stats) {
  const int n = model_->n();
  const int m = model_->m();
  const bool constant_G = model_->constant_input_matrices();
  Mat G = model_->G(a, y);
  Vec u(m), f(n);
  auto rhs = [&](double t, const double* yy, double* dydt) {
    Eigen::Map<const Vec> q(yy, n);
    Eigen::Map<Vec> out(dydt, n);
    model_->f(t, q, f);
    u_d_.eval(t, u.data());
    if (!constant_G) {
      G = model_->G(t, q);
      if (G.rows() != n || G.cols() != m)
        throw InputError(str_cat("G(t, q) of the model '", model_->name(), "' at t = ", t, " has shape (",
                                 G.rows(), ", ", G.cols(), "), expected (", n, ", ", m, ")"));
    }
    out.noalias() = f + G * u;
    if (!out.allFinite()) {
      check_finite_outputs(*model_, t, q);
      throw InputError(str_cat("the desired input u_d is not finite at t = ", t));
    }
  };
  // The step budget is the whole trajectory's: what the intervals before used counts.
  const long budget = options.max_steps - stats.steps - stats.rejected;
  require(budget > 0, "the desired trajectory needs more than max_steps = ", options.max_steps, " steps");
  Dopri5 stepper(n, options.rtol, options.atol, budget);
  try {
    // A table input is a polynomial between its points only: the integration stops at every
    // point inside the horizon, so that no step straddles a kink (a "linear" table's, say),
    // which the error estimate of a step would not see.
    for (double c : input_breakpoints(a, b)) {
      stepper.integrate(rhs, a, c, y.data(), [&](const DensePiece& piece) { dense_.append(piece); });
      a = c;
    }
  } catch (const SolverError& e) {
    throw SolverError(str_cat("the desired trajectory could not be integrated: ", e.what()), e.t(), e.flag());
  }
  stats += stepper.stats();
  stats.method = stepper.stats().method;
}

Trajectory::Trajectory(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, double tf, PiecewisePolynomial dense,
                       StepStats stats, std::vector<double> node_times, std::vector<double> defects)
    : model_(std::move(model)), q_d0_(std::move(q_d0)), u_d_(std::move(u_d)), t0_(t0), tf_(tf),
      dense_(std::move(dense)), stats_(stats), node_times_(std::move(node_times)), defects_(std::move(defects)) {
  check_arguments();
  require(node_times_.empty() ? defects_.empty() : defects_.size() + 1 == node_times_.size(),
          "a trajectory given as states has one defect per interval between its nodes: got ", node_times_.size(),
          " nodes and ", defects_.size(), " defects");
  require(dense_.dim() == model_->n() && !dense_.empty(), "the dense output of a trajectory needs ", model_->n(),
          " components and at least one piece, got ", dense_.dim(), " components and ", dense_.num_pieces(),
          " pieces");
  require(dense_.t_min() <= t0 && dense_.t_max() >= tf, "the dense output covers [", dense_.t_min(), ", ",
          dense_.t_max(), "], not the horizon [", t0, ", ", tf, "]");
  check_declarations();
}

// What the model says about its input matrices, checked at the start, the middle and the end of
// the trajectory: a wrong declaration would freeze G at (t0, q_d0) or drop d(G u)/dq silently.
void Trajectory::check_declarations() const {
  const double t_mid = 0.5 * (t0_ + tf_);
  check_input_matrix_declarations(*model_, {t0_, t_mid, tf_}, {q_d0_, q_d(t_mid), q_d(tf_)});
}

std::vector<double> Trajectory::input_breakpoints(double t0, double tf) const {
  std::vector<double> points;
  if (!u_d_.is_function())
    for (const Signal& channel : u_d_.channels())
      if (channel.is_table())
        for (double t : channel.table_t())
          if (t > t0 && t < tf) points.push_back(t);
  points.push_back(tf);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

void Trajectory::check_arguments() const {
  require(model_ != nullptr, "Trajectory needs a model");
  check_horizon(t0_, tf_);
  check_structure(structure_of(*model_));  // before its sizes are used
  check_size(q_d0_, model_->n(), "the desired initial state q_d0");
  validate_model(*model_, t0_, q_d0_);
  require(u_d_.dim() == model_->m(), "the desired input u_d has ", u_d_.dim(), " channels, the model '",
          model_->name(), "' has ", model_->m(), " inputs");
}

double Trajectory::max_defect() const {
  return defects_.empty() ? 0.0 : *std::max_element(defects_.begin(), defects_.end());
}

double Trajectory::max_defect_t() const {
  if (defects_.empty()) return NAN;
  return node_times_[static_cast<std::size_t>(std::max_element(defects_.begin(), defects_.end()) - defects_.begin())];
}

void Trajectory::q_d(double t, double* out, std::size_t* cursor) const {
  dense_.eval(t, out, cursor);
}

Vec Trajectory::q_d(double t) const {
  Vec out(n());
  dense_.eval(t, out.data());
  return out;
}

Mat Trajectory::A_e(double t) const {
  Mat A(n(), n());
  A_e(t, q_d(t), A);
  return A;
}

void Trajectory::A_e(double t, const ConstVecRef& q_d, MatRef A) const {
  if (!model_->state_dependent_inputs()) {
    model_->dfdq(t, q_d, A);
    return;
  }
  linearize(*model_, t, q_d, u_d(t), A);
}

Mat Trajectory::B_e(double t) const { return model_->G(t, q_d(t)); }

Mat Trajectory::D_e(double t) const { return model_->D(t, q_d(t)); }

}  // namespace hinf
