#include "hinf/scenario.hpp"

#include <chrono>
#include <cmath>

#include "hinf/checks.hpp"
#include "hinf/controller.hpp"
#include "hinf/errors.hpp"

namespace hinf {

Scenario Scenario::resolved() const {
  require(model != nullptr, "the scenario has no model");
  Scenario s = *this;
  const int n = model->n();
  if (s.Q.size() == 0) s.Q = Mat::Identity(n, n);
  if (s.Qf.size() == 0) s.Qf = Mat::Identity(n, n);
  if (s.disturbance.dim() == 0 && model->nw() > 0) s.disturbance = VectorSignal::zeros(model->nw());
  if (s.measurement) {
    MeasurementSpec& ms = *s.measurement;
    if (ms.Q0.size() == 0) ms.Q0 = 2.0 * Mat::Identity(n, n);
  }
  return s;
}

void Scenario::validate() const {
  require(model != nullptr, "the scenario has no model");
  const int n = model->n(), m = model->m(), nw = model->nw();
  check_horizon(t0, tf);
  check_size(desired_q0, n, "[desired] q0");
  require(desired_u.dim() == m, "[desired] needs ", m, " input signals (u1..u", m, "), got ",
          desired_u.dim());
  require(!std::isnan(gamma) && gamma > 0.0, "[controller] gamma must be > 0 (or inf), got ", gamma);
  check_symmetric_weight(Q, n, "Q", false);
  check_symmetric_weight(Qf, n, "Qf", true);
  require(disturbance.dim() == nw, "[disturbance] has ", disturbance.dim(), " channels, the model has ", nw);
  check_size(initial_q0, n, "[initial] q0");
  solver.validate();
  require(std::isfinite(output_dt) && output_dt > 0.0, "[output] dt must be > 0, got ", output_dt);
  for (double t : output_grid(t0, tf, output_dt)) {
    const double k = kappa(t);
    require(std::isfinite(k) && k > 0.0, "[controller] kappa must be > 0 on [t0, tf]: kappa(", t,
            ") = ", k);
  }
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RunResult run_scenario(const Scenario& scenario) {
  const auto start = std::chrono::steady_clock::now();
  const Scenario s = scenario.resolved();
  s.validate();
  if (s.measurement)
    throw InputError("[measurement] (output feedback, paper §4) is not supported by this build");

  RunResult result;
  result.scenario_name = s.name;
  result.gamma = s.gamma;
  result.trajectory = std::make_shared<const Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, s.tf);
  result.solution = solve_grde(result.trajectory, s.Q, s.Qf, s.gamma, s.solver);
  result.timing.design = seconds_since(start);

  const auto simulate_start = std::chrono::steady_clock::now();
  HinfStateFeedback controller(result.solution, s.kappa);
  result.controller = controller.name();
  result.simulation = simulate_state_feedback(*result.trajectory, controller, s.disturbance,
                                              s.initial_q0, s.output_dt, s.solver);
  result.timing.simulate = seconds_since(simulate_start);

  const auto analysis_start = std::chrono::steady_clock::now();
  result.Z0 = result.solution->Z(s.t0);
  const std::vector<double> grid(result.simulation.t.data(),
                                 result.simulation.t.data() + result.simulation.t.size());
  result.solution->eigenvalue_range(grid, result.Z_min_eig, result.Z_max_eig);
  result.metrics = compute_metrics(*s.model, result.simulation, s.Q);
  result.timing.analysis = seconds_since(analysis_start);
  result.timing.total = seconds_since(start);
  return result;
}

}  // namespace hinf
