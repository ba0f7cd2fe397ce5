#include "hinf/control/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/resources.hpp"
#include "hinf/numerics/sparse_matrix.hpp"
#include "hinf/numerics/stepper.hpp"
#include "control/run_series.hpp"

namespace hinf {

void SimulationOptions::validate() const {
  require(std::isfinite(output_dt) && output_dt > 0.0, "the output step dt must be > 0, got ", output_dt);
  require(std::isfinite(divergence_factor) && divergence_factor > 1.0,
          "divergence_factor must be a finite number > 1, got ", divergence_factor);
  solver.validate();
}

RowMat SimulationResult::q_e() const {
  RowMat errors(q.rows(), q.cols());
  for (Eigen::Index k = 0; k < q.rows(); ++k)
    tracking_error(static_cast<int>(q.cols()), heading_index, q.row(k).data(), q_d.row(k).data(), errors.row(k).data());
  return errors;
}

long output_count(double t0, double tf, double dt) {
  check_horizon(t0, tf);
  require(std::isfinite(dt) && dt > 0.0, "the output step dt must be > 0, got ", dt);
  const double intervals = (tf - t0) / dt;
  require(intervals <= 1e12, "the output grid would have ", intervals, " points: use a larger [output] dt");
  // A last interval shorter than 1e-6 dt is merged into the one before.
  return std::max(1L, static_cast<long>(std::ceil(intervals - 1e-6))) + 1;
}

long check_output_grid(double t0, double tf, double dt) {
  const long count = output_count(t0, tf, dt);
  check_memory(8.0 * static_cast<double>(count), str_cat("the output grid of ", count, " points"),
               "use a larger [output] dt");
  return count;
}

std::vector<double> output_grid(double t0, double tf, double dt) {
  const long count = check_output_grid(t0, tf, dt);
  std::vector<double> grid;
  grid.reserve(static_cast<std::size_t>(count));
  for (long k = 0; k + 1 < count; ++k) grid.push_back(t0 + static_cast<double>(k) * dt);
  grid.push_back(tf);
  return grid;
}

PathScale::PathScale(const Model& model)
    : is_position_(static_cast<std::size_t>(model.n()), 0),
      heading_(model.heading_index()),
      low_(Vec::Constant(model.n(), std::numeric_limits<double>::infinity())),
      high_(Vec::Constant(model.n(), -std::numeric_limits<double>::infinity())) {
  for (int i : model.position_indices()) is_position_[static_cast<std::size_t>(i)] = 1;
}

void PathScale::add(const Trajectory& trajectory, const std::vector<double>& grid) {
  Vec q_d(trajectory.n());
  std::size_t cursor = 0;
  for (double t : grid) {
    trajectory.q_d(t, q_d.data(), &cursor);
    low_ = low_.cwiseMin(q_d);
    high_ = high_.cwiseMax(q_d);
  }
}

double PathScale::scale() const {
  double scale = 0.0;
  for (Eigen::Index i = 0; i < low_.size(); ++i) {
    if (i == heading_ || !(low_[i] <= high_[i])) continue;  // the heading error is wrapped; no point yet
    const double extent = is_position_[static_cast<std::size_t>(i)] ? high_[i] - low_[i]
                                                                      : std::max(std::abs(low_[i]), std::abs(high_[i]));
    scale = std::max(scale, extent);
  }
  return scale;
}

double divergence_bound(const Trajectory& trajectory, const Vec& q0, const std::vector<double>& grid,
                        double divergence_factor) {
  const Model& model = trajectory.model();
  const int n = model.n();
  Vec q_d(n), q_e(n);
  trajectory.q_d(grid.front(), q_d.data());
  tracking_error(n, model.heading_index(), q0.data(), q_d.data(), q_e.data());
  PathScale path(model);
  path.add(trajectory, grid);
  return divergence_factor * std::max({1.0, q_e.cwiseAbs().maxCoeff(), path.scale()});
}

void check_plant_sizes(const Model& model, const Model& plant) {
  if (&plant == &model) return;
  require(plant.n() == model.n() && plant.m() == model.m() && plant.nw() == model.nw(), "the plant '", plant.name(),
          "' has (n, m, nw) = (", plant.n(), ", ", plant.m(), ", ", plant.nw(), "), the design model '", model.name(),
          "' has (", model.n(), ", ", model.m(), ", ", model.nw(), ")");
  require(plant.heading_index() == model.heading_index(), "the plant '", plant.name(), "' has heading index ",
          plant.heading_index(), ", the design model '", model.name(), "' has ", model.heading_index());
}

SimulationResult simulate_state_feedback(const Trajectory& trajectory, Controller& controller,
                                         const Disturbance& disturbance, const Vec& q0,
                                         const SimulationOptions& simulation, const Model* plant) {
  return detail::simulate_state_feedback(trajectory, controller, disturbance, q0, simulation, plant, NAN);
}

namespace detail {

SimulationResult simulate_state_feedback(const Trajectory& trajectory, Controller& controller,
                                         const Disturbance& disturbance, const Vec& q0,
                                         const SimulationOptions& simulation, const Model* plant, double given_bound) {
  // The design model (sizes, heading) and the vehicle integrated: the plant, or the design model.
  const Model& design_model = trajectory.model();
  const Model& model = plant != nullptr ? *plant : design_model;
  check_plant_sizes(design_model, model);
  const int n = model.n(), m = model.m(), nw = model.nw();
  check_size(q0, n, "the initial state q0");
  require(controller.m() == m, "the controller gives ", controller.m(), " inputs, the model has ", m);
  require(controller.n() == 0 || controller.n() == n, "the controller acts on states of ", controller.n(),
          " numbers, the model '", model.name(), "' has ", n);
  require(disturbance.dim() == nw, "the disturbance has ", disturbance.dim(),
          " channels, the model '", model.name(), "' has ", nw);
  simulation.validate();
  const SolverOptions& options = simulation.solver;
  const double t0 = trajectory.t0(), tf = trajectory.tf();
  const std::vector<double> grid = run_grid(trajectory, simulation.output_dt, nw);
  const long count = static_cast<long>(grid.size());
  // NaN: the run's own bound.
  const double bound = std::isnan(given_bound) ? divergence_bound(trajectory, q0, grid, simulation.divergence_factor)
                                               : given_bound;
  const int heading = model.heading_index();

  const bool constant_GD = model.constant_input_matrices();
  Mat G = model.G(t0, q0), D = model.D(t0, q0);
  const SparseMatrix G_sparse(G), D_sparse(D);
  Vec u(m), w(nw);
  Mat J(n, n), dudq(m, n);
  auto rhs = [&](double t, const double* y, double* dydt) {
    Eigen::Map<const Vec> q(y, n);
    Eigen::Map<Vec> out(dydt, n);
    model.f(t, q, out);
    controller.control(t, q, u);
    disturbance.eval(t, y, w.data());
    if (constant_GD) {
      G_sparse.add_product(u.data(), dydt);
      D_sparse.add_product(w.data(), dydt);
    } else {
      const Mat Gt = model.G(t, q), Dt = model.D(t, q);
      check_shape(Gt, n, m, str_cat("G(t, q) at t = ", t, " of the model '", model.name(), "'"));
      check_shape(Dt, n, nw, str_cat("D(t, q) at t = ", t, " of the model '", model.name(), "'"));
      out.noalias() += Gt * u + Dt * w;
    }
    if (!out.allFinite()) {
      // The model's own failure is reported as the model's (not as a step size that collapses).
      check_finite_outputs(model, t, q);
      throw SolverError(str_cat("the closed loop's right-hand side is not finite at t = ", t,
                                ": the model's f, G and D are finite there, the command u (", u.allFinite() ? "finite" : "not finite",
                                ") or the disturbance w (", w.allFinite() ? "finite" : "not finite", ") is not"),
                        t, "NOT_FINITE");
    }
  };
  // d/dq [f + G(q) u(q) + D(q) w] ~ df/dq + d(G u)/dq + G du/dq: the change of D(q) w with q is
  // left out (the Jacobian only steers the implicit methods' Newton iterations).
  auto jacobian = [&](double t, const double* yy, const double*, double* Jout) {
    Eigen::Map<const Vec> q(yy, n);
    if (!constant_GD) {
      G = model.G(t, q);
      check_shape(G, n, m, str_cat("G(t, q) at t = ", t, " of the model '", model.name(), "'"));
    }
    controller.control_jacobian(t, q, dudq);
    if (model.state_dependent_inputs()) {
      controller.control(t, q, u);
      linearize(model, t, q, u, J);
    } else {
      model.dfdq(t, q, J);
    }
    Eigen::Map<Mat>(Jout, n, n) = J + G * dudq;
  };

  SimulationResult result;
  result.heading_index = heading;
  result.q.resize(count, n);
  result.q.row(0) = q0.transpose();
  Vec y = q0;
  long next = 1;  // the next output time to record
  DivergenceCheck divergence(trajectory, heading, bound);
  const StepStats stats = integrate(options, n, rhs, jacobian, t0, tf, y.data(), [&](const DensePiece& piece) {
    const double slack = 1e-12 * std::max(1.0, std::abs(piece.t_end));
    while (next < count && grid[static_cast<std::size_t>(next)] <= piece.t_end + slack) {
      const double theta = piece.theta(grid[static_cast<std::size_t>(next)]);
      piece.eval(theta, result.q.row(next).data());
      ++next;
    }
    return divergence.within(piece.t_end, y.data(), "reduce the disturbance or the initial error, or raise [solver]"
                                                    " divergence_factor", result)
               ? StepAction::Continue
               : StepAction::Stop;
  });
  result.integrator = stats.method;
  result.stats.steps = stats.steps;
  result.stats.rejected = stats.rejected;
  result.stats.rhs_evals = stats.rhs_evals;
  result.stats.jac_evals = stats.jac_evals;

  // Signals on the recorded part of the grid.
  const long recorded = result.status == RunStatus::Completed ? count : next;
  record_reference_series(trajectory, disturbance, grid, recorded, result);
  result.u.resize(recorded, m);
  for (long k = 0; k < recorded; ++k)
    controller.control(result.t[k], result.q.row(k).transpose(), result.u.row(k).transpose());
  return result;
}

}  // namespace detail

std::vector<double> run_grid(const Trajectory& trajectory, double output_dt, int nw) {
  const long count = output_count(trajectory.t0(), trajectory.tf(), output_dt);
  check_memory(8.0 * static_cast<double>(count) * (1 + 2 * trajectory.n() + 2 * trajectory.m() + nw),
               str_cat("the time series on the output grid of ", count, " points"),
               "increase [output] dt (or shorten the horizon)");
  return output_grid(trajectory.t0(), trajectory.tf(), output_dt);
}

void record_reference_series(const Trajectory& trajectory, const Disturbance& disturbance,
                             const std::vector<double>& grid, long recorded, SimulationResult& result) {
  const int n = trajectory.n(), m = trajectory.m();
  result.t = Eigen::Map<const Vec>(grid.data(), recorded);
  result.q.conservativeResize(recorded, n);
  result.q_d.resize(recorded, n);
  result.u_d.resize(recorded, m);
  result.w.resize(recorded, disturbance.dim());
  std::size_t cursor = 0;
  for (long k = 0; k < recorded; ++k) {
    const double t = grid[static_cast<std::size_t>(k)];
    trajectory.q_d(t, result.q_d.row(k).data(), &cursor);
    trajectory.u_d(t, result.u_d.row(k).data());
    disturbance.eval(t, result.q.row(k).data(), result.w.row(k).data());
  }
}

DivergenceCheck::DivergenceCheck(const Trajectory& trajectory, int heading, double bound)
    : trajectory_(trajectory), heading_(heading), bound_(bound), q_d_(trajectory.n()), q_e_(trajectory.n()) {}

bool DivergenceCheck::within(double t, const double* y, const char* advice, SimulationResult& result) {
  trajectory_.q_d(t, q_d_.data(), &cursor_);
  tracking_error(static_cast<int>(q_d_.size()), heading_, y, q_d_.data(), q_e_.data());
  // A non-finite error (NaN compares false, and maxCoeff may skip it) is past every bound.
  const double error = q_e_.allFinite() ? q_e_.cwiseAbs().maxCoeff() : std::numeric_limits<double>::infinity();
  if (error <= bound_) return true;
  result.status = RunStatus::Diverged;
  result.status_message = str_cat("the tracking error |q - q_d|_inf = ", error, " exceeded the divergence bound ", bound_,
                                  " at t = ", t,
                                  ": the closed loop left the neighbourhood of the desired trajectory where the"
                                  " linearized design is meaningful (",
                                  advice, ")");
  return false;
}

}  // namespace hinf
