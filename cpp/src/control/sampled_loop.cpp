#include "hinf/control/sampled_loop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hinf/control/output_feedback.hpp"
#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/resources.hpp"
#include "hinf/numerics/dopri5.hpp"
#include "control/run_series.hpp"

namespace hinf {

void SampledLoopOptions::validate(double period) const {
  require(std::isfinite(delay) && delay >= 0.0 && delay <= period * (1.0 + 1e-12),
          "the computation delay must be in [0, T] = [0, ", period, "] s, got ", delay);
  require(std::isfinite(sigma) && sigma >= 0.0, "the noise's standard deviation sigma must be >= 0, got ", sigma);
  require(measurement_every >= 1, "measurement_every must be >= 1 (a measurement every that many samples), got ",
          measurement_every);
  simulation.validate();
}

namespace {

// The loop of simulate_sampled for a Controller: OnlineController, or RecedingOnlineController
// (synchronized before each step, so that the run does not depend on how fast its windows are
// solved). `online` is the OnlineController that steps (after reset: its law).
struct Plain {
  OnlineController& c;
  const OnlineController& online() const { return c; }
  void reset(double t, const Vec& q) { c.reset(t, q); }
  void step(double t, const double* y, double t_meas, double* u) { c.step(t, y, t_meas, u); }
};
struct Receding {
  RecedingOnlineController& c;
  const OnlineController& online() const { return c.controller(); }
  void reset(double t, const Vec& q) { c.reset(t, q); }
  void step(double t, const double* y, double t_meas, double* u) {
    c.synchronize(t);
    c.step(t, y, t_meas, u);
  }
};

template <class Controller>
SimulationResult run_sampled(const Trajectory& trajectory, Controller controller_of, double T, bool output_feedback, int p,
                             const Disturbance& disturbance, const Vec& q0, const SampledLoopOptions& options,
                             const Model* plant) {
  const Model& design_model = trajectory.model();
  const Model& model = plant != nullptr ? *plant : design_model;
  check_plant_sizes(design_model, model);
  const int n = model.n(), m = model.m(), nw = model.nw();
  check_size(q0, n, "the initial state q0");
  check_finite(q0, "the initial state q0");
  require(disturbance.dim() == nw, "the disturbance has ", disturbance.dim(), " channels, the model '", model.name(),
          "' has ", nw);
  options.validate(T);
  const double t0 = trajectory.t0(), tf = trajectory.tf();
  Mat C;
  if (output_feedback) {
    C = model.C(t0);
    require(C.rows() == p && C.cols() == n, "the plant '", model.name(), "' measures C of shape (", C.rows(), ", ",
            C.cols(), "), the controller's filter expects (", p, ", ", n, ")");
    const long samples = noise_sample_count(t0, tf, T);
    if (options.sigma > 0.0 || options.noise.size() > 0)
      require(options.noise.rows() == samples && options.noise.cols() == p, "the noise must have ", samples,
              " rows (one per sample of ", T, " s) and ", p, " columns (one per measured output), got (",
              options.noise.rows(), ", ", options.noise.cols(), ")");
    check_finite(options.noise, "noise");
  } else {
    require(options.sigma == 0.0 && options.noise.size() == 0,
            "measurement noise needs an output-feedback controller (a filter in its options): a state-feedback"
            " controller measures the state itself");
  }
  const SimulationOptions& simulation = options.simulation;
  const std::vector<double> grid = run_grid(trajectory, simulation.output_dt, nw);
  const long count = static_cast<long>(grid.size());
  const double bound = divergence_bound(trajectory, q0, grid, simulation.divergence_factor);
  const int heading = model.heading_index();

  controller_of.reset(t0, output_feedback ? trajectory.q_d0() : q0);
  Vec u = controller_of.online().held_command(), w(nw);
  auto rhs = [&](double t, const double* y, double* dydt) {
    Eigen::Map<const Vec> q(y, n);
    Eigen::Map<Vec> out(dydt, n);
    model.f(t, q, out);
    disturbance.eval(t, y, w.data());
    out.noalias() += model.G(t, q) * u + model.D(t, q) * w;
  };
  Dopri5 stepper(n, simulation.solver.rtol, simulation.solver.atol, simulation.solver.max_steps);

  SimulationResult result;
  result.heading_index = heading;
  result.q.resize(count, n);
  result.u.resize(count, m);
  Vec y = q0, measured(output_feedback ? p : n);
  double t = t0, measured_at = t0, apply_at = t0;
  bool pending = false, pending_measured = false;
  long sample = 0, next_out = 0;
  DivergenceCheck divergence(trajectory, heading, bound);
  const auto due = [](double event, double now) { return event <= now + 1e-12 * std::max(1.0, std::abs(now)); };
  const auto sample_time = [&](long k) { return t0 + static_cast<double>(k) * T; };
  for (;;) {
    // The events at t, in the order a vehicle sees them: a command computed earlier is applied,
    // then the state is measured (and, without delay, answered at once), then the outputs.
    if (pending && due(apply_at, t)) {
      controller_of.step(apply_at, pending_measured ? measured.data() : nullptr, measured_at, u.data());
      pending = false;
    }
    if (sample_time(sample) < tf && due(sample_time(sample), t)) {
      const bool measuring = sample % options.measurement_every == 0;
      if (!measuring) {
        // no measurement at this sample: the step predicts
      } else if (output_feedback) {
        measured.noalias() = C * y;
        if (options.sigma > 0.0) measured += options.sigma * options.noise.row(sample).transpose();
      } else {
        measured = y;
      }
      measured_at = sample_time(sample);
      ++sample;
      if (options.delay == 0.0) {
        controller_of.step(measured_at, measuring ? measured.data() : nullptr, measured_at, u.data());
      } else {
        pending = true;
        pending_measured = measuring;
        apply_at = measured_at + options.delay;
      }
    }
    while (next_out < count && due(grid[static_cast<std::size_t>(next_out)], t)) {
      result.q.row(next_out) = y.transpose();
      result.u.row(next_out) = u.transpose();
      ++next_out;
    }
    if (next_out == count) break;
    double t_next = grid[static_cast<std::size_t>(next_out)];
    if (sample_time(sample) < tf) t_next = std::min(t_next, sample_time(sample));
    if (pending) t_next = std::min(t_next, apply_at);
    stepper.integrate(rhs, t, t_next, y.data(), [&](const DensePiece& piece) {
      return divergence.within(piece.t_end, y.data(),
                               "a shorter period, delay compensation, a smaller disturbance or initial error, or a"
                               " larger divergence_factor",
                               result)
                 ? StepAction::Continue
                 : StepAction::Stop;
    });
    if (result.status == RunStatus::Diverged) break;
    t = t_next;
  }
  const StepStats& stats = stepper.stats();
  result.integrator = str_cat("erk (Dormand-Prince, restarted at every event), sampled at T = ", T, " s");
  result.stats.steps = stats.steps;
  result.stats.rejected = stats.rejected;
  result.stats.rhs_evals = stats.rhs_evals;
  result.stats.method = "erk";

  record_reference_series(trajectory, disturbance, grid, next_out, result);
  result.u.conservativeResize(next_out, m);
  return result;
}

}  // namespace

SimulationResult simulate_sampled(const Trajectory& trajectory, OnlineController& controller,
                                  const Disturbance& disturbance, const Vec& q0, const SampledLoopOptions& options,
                                  const Model* plant) {
  require(&controller.law().trajectory() == &trajectory,
          "the controller's law was designed along another trajectory than the one given");
  return run_sampled(trajectory, Plain{controller}, controller.law().period(), controller.output_feedback(),
                     controller.measurement_size(), disturbance, q0, options, plant);
}

SimulationResult simulate_sampled(const Trajectory& trajectory, RecedingOnlineController& controller,
                                  const Disturbance& disturbance, const Vec& q0, const SampledLoopOptions& options,
                                  const Model* plant) {
  const RecedingHorizon& horizon = controller.horizon();
  // With path changes the reference's inputs are a function of t (RecedingHorizon::reference),
  // which compares equal to nothing.
  require(trajectory.model().same_as(horizon.model()) && trajectory.t0() == horizon.t0() &&
              trajectory.q_d0() == horizon.q_d0() &&
              (!horizon.path_changes().empty() || trajectory.u_d_signal().same_signals(horizon.u_d_signal())),
          "the reference trajectory must start where the receding horizon's does: its model, t0, q_d0 and u_d"
          " (RecedingHorizon.reference gives it)");
  const bool output_feedback = controller.options().filter.enabled();
  const int p = output_feedback ? static_cast<int>(horizon.model().C(horizon.t0()).rows()) : horizon.n();
  return run_sampled(trajectory, Receding{controller}, controller.period(), output_feedback, p, disturbance, q0,
                     options, plant);
}

}  // namespace hinf
