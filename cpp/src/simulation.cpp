#include "hinf/simulation.hpp"

#include <cmath>

#include "hinf/checks.hpp"
#include "hinf/cvode.hpp"
#include "hinf/dopri5.hpp"
#include "hinf/errors.hpp"
#include "hinf/sparse_matrix.hpp"

namespace hinf {

std::vector<double> output_grid(double t0, double tf, double dt) {
  check_horizon(t0, tf);
  require(std::isfinite(dt) && dt > 0.0, "the output step dt must be > 0, got ", dt);
  const double intervals = (tf - t0) / dt;
  require(intervals <= 1e8, "the output grid would have ", intervals, " points: use a larger dt");
  // A last interval shorter than 1e-6 dt is merged into the one before.
  const long count = std::max(1L, static_cast<long>(std::ceil(intervals - 1e-6)));
  std::vector<double> grid;
  grid.reserve(static_cast<std::size_t>(count + 1));
  for (long k = 0; k < count; ++k) grid.push_back(t0 + static_cast<double>(k) * dt);
  grid.push_back(tf);
  return grid;
}

namespace {

// Evaluates the dense-output polynomial of one Dormand-Prince step at theta.
void eval_dense(const double* c, int degree, int dim, double theta, double* out) {
  for (int i = 0; i < dim; ++i) out[i] = c[degree * dim + i];
  for (int j = degree - 1; j >= 0; --j)
    for (int i = 0; i < dim; ++i) out[i] = out[i] * theta + c[j * dim + i];
}

}  // namespace

SimulationResult simulate_state_feedback(const Trajectory& trajectory, Controller& controller,
                                         const Disturbance& disturbance, const Vec& q0,
                                         double output_dt, const SolverOptions& options) {
  const Model& model = trajectory.model();
  const int n = model.n(), m = model.m(), nw = model.nw();
  check_size(q0, n, "the initial state q0");
  require(controller.m() == m, "the controller gives ", controller.m(), " inputs, the model has ", m);
  require(disturbance.dim() == nw, "the disturbance has ", disturbance.dim(),
          " channels, the model '", model.name(), "' has ", nw);
  options.validate();
  const double t0 = trajectory.t0(), tf = trajectory.tf();
  const std::vector<double> grid = output_grid(t0, tf, output_dt);
  const long count = static_cast<long>(grid.size());

  const bool constant_BD = model.constant_input_matrices();
  Mat B = model.B(t0), D = model.D(t0);
  const SparseMatrix B_sparse(B), D_sparse(D);
  Vec u(m), w(nw);
  Mat J(n, n), dudq(m, n);
  auto rhs = [&](double t, const double* y, double* dydt) {
    Eigen::Map<const Vec> q(y, n);
    Eigen::Map<Vec> out(dydt, n);
    model.f(t, q, out);
    controller.control(t, q, u);
    disturbance.eval(t, y, w.data());
    if (constant_BD) {
      B_sparse.add_product(u.data(), dydt);
      D_sparse.add_product(w.data(), dydt);
    } else {
      out.noalias() += model.B(t) * u + model.D(t) * w;
    }
  };

  SimulationResult result;
  result.t = Eigen::Map<const Vec>(grid.data(), count);
  result.q.resize(count, n);
  result.q.row(0) = q0.transpose();
  Vec y = q0;

  result.integrator = options.method == Method::ERK ? "dormand-prince 5(4)" : "CVODE " + to_string(options.method);
  if (options.method == Method::ERK) {
    Dopri5 stepper(n, options.rtol, options.atol, options.max_steps);
    long next = 1;
    stepper.integrate(rhs, t0, tf, y.data(), [&](double t_start, double h, const double* c, const double*) {
      const double t_end = t_start + h;
      const double slack = 1e-12 * std::max(1.0, std::abs(t_end));
      while (next < count && grid[static_cast<std::size_t>(next)] <= t_end + slack) {
        const double theta = std::min(1.0, (grid[static_cast<std::size_t>(next)] - t_start) / h);
        eval_dense(c, 4, n, theta, result.q.row(next).data());
        ++next;
      }
    });
    result.stats.steps = stepper.stats().steps;
    result.stats.rejected = stepper.stats().rejected;
    result.stats.rhs_evals = stepper.stats().rhs_evals;
  } else {
    Cvode::Jacobian jacobian = nullptr;
    if (options.method == Method::BDF)
      jacobian = [&](double t, const double* yy, const double*, double* Jout) {
        Eigen::Map<const Vec> q(yy, n);
        if (!constant_BD) B = model.B(t);
        model.dfdq(t, q, J);
        controller.control_jacobian(t, q, dudq);
        Eigen::Map<Mat>(Jout, n, n) = J + B * dudq;
      };
    Cvode solver(n, options.method, options.rtol, options.atol, options.max_steps, rhs, jacobian);
    solver.reset(t0, y.data(), tf);
    for (long k = 1; k < count; ++k) {
      solver.advance(grid[static_cast<std::size_t>(k)], y.data());
      result.q.row(k) = y.transpose();
    }
    result.stats.steps = solver.num_steps();
    result.stats.rejected = solver.num_error_test_failures();
    result.stats.rhs_evals = solver.num_rhs_evals();
    result.stats.jac_evals = solver.num_jac_evals();
  }

  // Signals on the grid.
  result.q_d.resize(count, n);
  result.u.resize(count, m);
  result.u_d.resize(count, m);
  result.w.resize(count, nw);
  std::size_t cursor = 0;
  for (long k = 0; k < count; ++k) {
    const double t = grid[static_cast<std::size_t>(k)];
    trajectory.q_d(t, result.q_d.row(k).data(), &cursor);
    trajectory.u_d(t, result.u_d.row(k).data());
    controller.control(t, result.q.row(k).transpose(), result.u.row(k).transpose());
    disturbance.eval(t, result.q.row(k).data(), result.w.row(k).data());
  }
  return result;
}

}  // namespace hinf
