#include "hinf/scenario/scenario.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include "hinf/control/controller.hpp"
#include "hinf/control/discrete_design.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/control/sampled_loop.hpp"
#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/models/ship.hpp"
#include "scenario/scenario_run.hpp"

namespace hinf {

int SamplingSpec::measurement_every() const {
  if (!(measurement_period > 0.0) || !(period > 0.0)) return 1;
  return std::max(1, static_cast<int>(std::lround(measurement_period / period)));
}

SimulationOptions Scenario::simulation_options() const {
  SimulationOptions options;
  options.output_dt = output_dt;
  options.divergence_factor = divergence_factor;
  options.solver = solver;
  return options;
}

Scenario Scenario::resolved() const {
  require(model != nullptr, "the scenario has no model");
  check_horizon(t0, tf);
  check_structure(structure_of(*model));  // before its sizes are used
  Scenario s = *this;
  const int n = model->n();
  check_size(desired_q0, n, "[desired] q0");
  validate_model(*model, t0, desired_q0);
  if (s.Q.size() == 0) s.Q = Mat::Identity(n, n);
  if (s.Qf.size() == 0) s.Qf = Mat::Identity(n, n);
  if (s.disturbance.dim() == 0 && model->nw() > 0) s.disturbance = VectorSignal::zeros(model->nw());
  if (s.measurement) {
    MeasurementSpec& ms = *s.measurement;
    if (ms.Q0.size() == 0) ms.Q0 = 2.0 * Mat::Identity(n, n);
    const int p = static_cast<int>(model->C(s.t0).rows());
    if (ms.N.size() == 0) {
      if (ms.sigma > 0.0) ms.N = ms.sigma * ms.sigma * Mat::Identity(p, p);  // else validate() reports it
    } else if (ms.N.rows() == 1 && ms.N.cols() == 1 && p != 1) {
      ms.N = ms.N(0, 0) * Mat::Identity(p, p);
    }
  }
  return s;
}

namespace {

// The rows of C(t) (measured outputs), or -1 for a model without a measurement.
long measured_outputs(const Model& model, double t) {
  try {
    return static_cast<long>(model.C(t).rows());
  } catch (const InputError&) {
    return -1;  // Model::C of a model without a measurement
  }
}

std::string list_text(const std::vector<int>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) text += str_cat(i > 0 ? ", " : "", values[i]);
  return text + "]";
}

}  // namespace

void check_plant(const Model& model, const Model& plant, double t0) {
  try {
    check_structure(structure_of(plant));
  } catch (const InputError& e) {
    throw InputError(str_cat("[plant] ", e.what()));
  }
  const auto same = [&](const char* what, const auto& a, const auto& b) {
    require(a == b, "[plant] the plant '", plant.name(), "' has ", what, " = ", b, ", the design model '",
            model.name(), "' has ", a, ": a plant must have the design model's structure (n, m, nw, measured"
            " outputs, noise channels, heading and position indices)");
  };
  same("n", model.n(), plant.n());
  same("m", model.m(), plant.m());
  same("nw", model.nw(), plant.nw());
  same("noise channels", list_text(model.noise_channels()), list_text(plant.noise_channels()));
  same("heading index", model.heading_index(), plant.heading_index());
  same("position indices", list_text(model.position_indices()), list_text(plant.position_indices()));
  same("measured outputs (rows of C; -1: none)", measured_outputs(model, t0), measured_outputs(plant, t0));
}

void Scenario::validate_settings() const {
  check_horizon(t0, tf);
  require(!std::isnan(gamma) && gamma > 0.0, "[controller] gamma must be > 0 (or inf), got ", gamma);
  simulation_options().validate();
  require(lost_track > 0.0, "[solver] lost_track must be > 0 m (inf: never), got ", lost_track);
  const auto [kappa_min, kappa_min_t] = kappa.minimum(t0, tf);
  require(std::isfinite(kappa_min) && kappa_min > 0.0, "[controller] kappa must be > 0 on [t0, tf]: kappa(",
          kappa_min_t, ") = ", kappa_min);
  check_output_grid(t0, tf, output_dt);  // dt, without allocating the grid
  if (law == Law::Cascade) {
    for (double g : {cascade.k, cascade.k1, cascade.k2})
      require(std::isfinite(g) && g > 0.0, "[controller] cascade gains k, k1, k2 must be > 0, got (", cascade.k,
              ", ", cascade.k1, ", ", cascade.k2, ")");
  }
  if (law == Law::Backstepping) {
    for (double g : {backstepping.k, backstepping.k1, backstepping.k2, backstepping.k3})
      require(std::isfinite(g) && g > 0.0, "[controller] backstepping gains k, k1, k2, k3 must be > 0, got (",
              backstepping.k, ", ", backstepping.k1, ", ", backstepping.k2, ", ", backstepping.k3, ")");
  }
  require(!worst_case || std::isfinite(gamma),
          "[disturbance] worst_case needs a finite gamma: the worst-case disturbance gamma^-2 D' Z q_e is 0 at inf");
  if (measurement) {
    const MeasurementSpec& ms = *measurement;
    require(std::isfinite(ms.sigma) && ms.sigma >= 0.0, "[measurement] sigma must be >= 0, got ", ms.sigma);
    require(std::isfinite(ms.sample_period) && ms.sample_period > 0.0,
            "[measurement] sample_period must be > 0, got ", ms.sample_period);
    require(std::isfinite(ms.eta) && ms.eta > 0.0, "[measurement] eta must be > 0 (paper §4), got ", ms.eta);
  }
  if (sampling) {
    const SamplingSpec& sp = *sampling;
    require(std::isfinite(sp.period) && sp.period > 0.0 && sp.period <= tf - t0,
            "[sampling] period must be > 0 s and at most the horizon tf - t0 = ", tf - t0, " s, got ", sp.period);
    require(std::isfinite(sp.delay) && sp.delay >= 0.0 && sp.delay <= sp.period * (1.0 + 1e-12),
            "[sampling] delay must be in [0, period] = [0, ", sp.period, "] s, got ", sp.delay);
    require(!std::isnan(sp.max_age) && sp.max_age > 0.0, "[sampling] max_age must be > 0 s, got ", sp.max_age);
    if (sp.measurement_period != 0.0) {
      require(std::isfinite(sp.measurement_period) && sp.measurement_period <= tf - t0,
              "[sampling] measurement_period must be at most the horizon tf - t0 = ", tf - t0, " s, got ",
              sp.measurement_period);
      const double ratio = sp.measurement_period / sp.period;
      require(std::isfinite(ratio) && ratio >= 1.0 - 1e-9 && std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio,
              "[sampling] measurement_period must be a whole multiple of period = ", sp.period, " s (the sensor"
              " is read at controller samples), got ", sp.measurement_period);
    }
    require(!is_baseline(law), "[sampling] runs the online controller of the H-infinity or LQR design; the ",
            to_string(law), " law has no sampled form: remove [sampling] or choose law = \"hinf\" or \"lqr\"");
    require(sp.measurement_update != MeasurementUpdate::Discrete || sp.design == SampledDesign::Digital,
            "[sampling] measurement_update = \"discrete\" is the digital design's own filter: set design = "
            "\"digital\", or choose measurement_update = \"sampled\" or \"held\"");
    require(sp.design == SampledDesign::Emulated || (kappa.is_constant() && kappa.offset() == 1.0),
            "[controller] kappa scales the continuous law's gain; the digital design ([sampling] design ="
            " \"digital\") has its own gains: remove kappa or use design = \"emulated\"");
  }
  if (desired_states) {
    const DesiredStates& ds = *desired_states;
    require(ds.t.size() >= 2, "[desired] states.t needs at least two times, got ", ds.t.size());
    require(ds.t.front() == t0 && ds.t.back() == tf, "[desired] states.t must run from [horizon] t0 = ", t0,
            " to tf = ", tf, ", got ", ds.t.front(), " .. ", ds.t.back());
    require(std::isfinite(ds.max_defect) && ds.max_defect > 0.0, "[desired] max_defect must be > 0, got ",
            ds.max_defect);
  }
  if (path_change) {
    require(receding_horizon.has_value(), "[path_change] changes the path of a receding-horizon run: add"
            " [receding_horizon] (one design over [t0, tf] has one desired trajectory)");
    require(std::isfinite(path_change->t) && path_change->t > t0 && path_change->t < tf,
            "[path_change] t must be inside the horizon (", t0, ", ", tf, ") s, got ", path_change->t);
  }
  if (receding_horizon) {
    try {
      receding_horizon->validate();
    } catch (const InputError& e) {
      throw InputError(str_cat("[receding_horizon] ", e.what()));
    }
    require(!is_baseline(law), "[receding_horizon] designs the H-infinity or LQR law over a moving window; the ",
            to_string(law), " law has no design: remove [receding_horizon] or choose law = \"hinf\" or \"lqr\"");
    require(!measurement || sampling, "[receding_horizon] with [measurement] runs through the online controller:"
            " add [sampling] (the continuous output-feedback loop has no receding-horizon form)");
    if (sampling) {
      require(sampling->design == SampledDesign::Emulated, "[receding_horizon] hands the windows' continuous designs"
              " to the online controller: [sampling] design = \"emulated\" (the digital design has no"
              " receding-horizon form yet)");
      const double ratio = receding_horizon->update / sampling->period;
      require(std::isfinite(ratio) && ratio >= 1.0 - 1e-9 && std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio,
              "[receding_horizon] update must be a whole multiple of [sampling] period = ", sampling->period,
              " s (a window's law starts at a sample), got ", receding_horizon->update);
    }
    require(!worst_case, "[disturbance] worst_case uses one design over [t0, tf]; with [receding_horizon] there is"
            " none: remove worst_case or [receding_horizon]");
  }
}

void Scenario::validate() const {
  require(model != nullptr, "the scenario has no model");
  validate_settings();
  check_structure(structure_of(*model));
  const int n = model->n(), m = model->m(), nw = model->nw();
  check_size(desired_q0, n, "[desired] q0");
  validate_model(*model, t0, desired_q0);
  if (path_change)
    require(path_change->u_d.dim() == m, "[path_change] needs ", m, " input signals (u1..u", m, "), got ",
            path_change->u_d.dim());
  if (desired_states) {
    const RowMat& q = desired_states->q;
    require(q.rows() == static_cast<Eigen::Index>(desired_states->t.size()) && q.cols() == n,
            "[desired] states.q needs one row of ", n, " numbers per time of states.t (",
            desired_states->t.size(), " x ", n, "), got ", q.rows(), " x ", q.cols());
    require(q.allFinite(), "[desired] states.q is not all finite");
    require(q.row(0).transpose() == desired_q0, "[desired] states.q[0] must be q0 (the desired state at t0)");
  }
  if (plant) {
    check_plant(*model, *plant, t0);
    try {
      validate_model(*plant, t0, desired_q0);
    } catch (const InputError& e) {
      throw InputError(str_cat("[plant] ", e.what()));
    }
  }
  require(desired_u.dim() == m, "[desired] needs ", m, " input signals (u1..u", m, "), got ",
          desired_u.dim());
  check_symmetric_weight(Q, n, "Q", false);
  check_symmetric_weight(Qf, n, "Qf", true);
  require(disturbance.dim() == nw, "[disturbance] has ", disturbance.dim(), " channels, the model has ", nw);
  // The measurement-noise channels carry the noise of [measurement], nothing else.
  for (int c : model->noise_channels()) {
    const bool zero = disturbance.is_function()
                          ? disturbance(t0)[c] == 0.0 && disturbance(0.5 * (t0 + tf))[c] == 0.0
                          : disturbance.channels()[static_cast<std::size_t>(c)].is_constant() &&
                                disturbance.channels()[static_cast<std::size_t>(c)].offset() == 0.0;
    require(zero, "[disturbance] w", c + 1, " is a measurement-noise channel of the model '", model->name(),
            "': its noise is set in [measurement] (sigma), not as a disturbance");
  }
  check_size(initial_q0, n, "[initial] q0");
  if (is_baseline(law))
    require(dynamic_cast<const ShipModel*>(model.get()) != nullptr, "[controller] law = \"", to_string(law),
            "\" is written for the ship model; the model is '", model->name(), "': choose law = \"hinf\" or \"lqr\"");
  if (measurement) {
    const MeasurementSpec& ms = *measurement;
    const int p = static_cast<int>(model->C(t0).rows());
    require(ms.N.size() > 0, "[measurement] N must be given when sigma = 0 (the default N is sigma^2 I)");
    check_symmetric_weight(ms.N, p, "[measurement] N", true);
    check_symmetric_weight(ms.Q0, n, "[measurement] Q0", false);
    const Mat shifted = ms.Q0 - ms.eta * Mat::Identity(n, n);
    Eigen::SelfAdjointEigenSolver<Mat> eig(0.5 * (shifted + shifted.transpose()), Eigen::EigenvaluesOnly);
    require(eig.eigenvalues()(0) > 0.0,
            "[measurement] Q0 - eta I must be positive definite (Sigma(t0) = (Q0 - eta I)^-1): its smallest"
            " eigenvalue is ", eig.eigenvalues()(0), "; increase Q0 or decrease eta");
    require(static_cast<int>(model->noise_channels().size()) == p, "the model '", model->name(),
            "' has no noise channel for each of its ", p, " measured outputs");
  }
  if (sampling) {
    try {
      sampling->limits.validate(m);
    } catch (const InputError& e) {
      throw InputError(str_cat("[sampling] ", e.what()));
    }
  }
}

RowMat scenario_noise(const Scenario& scenario) {
  require(scenario.measurement.has_value(), "the scenario has no [measurement]");
  require(scenario.model != nullptr, "the scenario has no model");
  const MeasurementSpec& ms = *scenario.measurement;
  const double period = scenario.sampling ? scenario.sampling->period : ms.sample_period;
  const long samples = noise_sample_count(scenario.t0, scenario.tf, period);
  const int p = static_cast<int>(scenario.model->C(scenario.t0).rows());
  return standard_normal_samples(ms.seed, samples, p);
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

namespace {

Mat initial_sigma(const Scenario& s) {
  const MeasurementSpec& ms = *s.measurement;
  const int n = s.model->n();
  const Mat Sigma0 = (ms.Q0 - ms.eta * Mat::Identity(n, n)).inverse();
  return 0.5 * (Sigma0 + Sigma0.transpose());
}

TrajectoryPtr trajectory_of(const Scenario& s) {
  if (!s.desired_states) return std::make_shared<const Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, s.tf);
  const DesiredStates& ds = *s.desired_states;
  auto trajectory = std::make_shared<const Trajectory>(s.model, ds.t, ds.q, s.desired_u);
  // Feasibility per interval: a defect beyond the tolerance means the states are not a trajectory
  // of the model under u_d.
  require(trajectory->max_defect() <= ds.max_defect, "[desired] states are not a trajectory of the model '",
          s.model->name(), "' under u_d: the interval from t = ", trajectory->max_defect_t(), " s ends ",
          trajectory->max_defect(), " from the next state, more than max_defect = ", ds.max_defect,
          " (plan again with a smaller interval or more substeps, or raise [desired] max_defect)");
  return trajectory;
}

// The law's gamma: the scenario's, or inf for the lqr law.
// The controller of a ship baseline (cascade, backstepping) along the trajectory.
std::unique_ptr<Controller> baseline_controller(const Scenario& s, const TrajectoryPtr& trajectory) {
  if (s.law == Law::Cascade) return std::make_unique<CascadeController>(trajectory, s.cascade);
  return std::make_unique<BacksteppingController>(trajectory, s.backstepping);
}

double design_gamma(const Scenario& s) {
  return s.law == Law::Lqr ? std::numeric_limits<double>::infinity() : s.gamma;
}

// Q, Qf and, for the H-infinity law of a fixed continuous-time design, the right side of its
// bound (metrics.hpp): q_e0' Z(t0) q_e0 with state feedback, gamma^2 q_e0' Q0 q_e0 with output
// feedback (eq. 39). Other laws, sampled loops and receding horizons have no such bound here.
CostWeights cost_weights(const Scenario& s, const RunResult& result) {
  CostWeights weights;
  weights.Q = s.Q;
  weights.Qf = s.Qf;
  const SimulationResult& run = result.simulation;
  if (s.law != Law::Hinf || !std::isfinite(s.gamma) || s.sampling || s.receding_horizon || !result.solution ||
      run.t.size() == 0)
    return weights;
  Vec q_e0(s.model->n());
  tracking_error(s.model->n(), s.model->heading_index(), run.q.row(0).data(), run.q_d.row(0).data(), q_e0.data());
  weights.gamma = s.gamma;
  if (s.measurement) {
    weights.initial_term = s.gamma * s.gamma * q_e0.dot(s.measurement->Q0 * q_e0);
  } else {
    weights.initial_term = q_e0.dot(result.solution->Z(s.t0) * q_e0);
  }
  weights.initial_term = std::max(0.0, weights.initial_term);
  return weights;
}

// A run that ran to tf but ended more than [solver] lost_track farther from the desired path
// than it started has lost the track: status LostTrack, with the distances in the message. (A
// slow law may end a short run a little farther than it started; one that runs away ends far.)
void judge_track(const Scenario& s, RunResult& result) {
  SimulationResult& run = result.simulation;
  const std::vector<int> position = s.model->position_indices();
  if (run.status != RunStatus::Completed || position.empty() || run.t.size() == 0) return;
  double start = 0.0;  // positions are not angles: plain differences
  for (int i : position) start += std::pow(run.q(0, i) - run.q_d(0, i), 2);
  start = std::sqrt(start);
  const double end = result.metrics.final_position_error;  // compute_metrics, on the same series
  if (!(end > start + s.lost_track)) return;
  run.status = RunStatus::LostTrack;
  run.status_message = str_cat("the run ended ", end, " m from the desired path at tf = ", run.t[run.t.size() - 1],
                               " s, more than [solver] lost_track = ", s.lost_track,
                               " m farther than it started (", start, " m)");
}

// The receding horizon of a resolved, validated scenario with [receding_horizon], its path
// change applied.
std::shared_ptr<const RecedingHorizon> receding_horizon_of(const Scenario& s) {
  std::shared_ptr<const RecedingHorizon> horizon;
  if (s.desired_states) {
    // The windows follow the states; the defects are checked over [t0, tf] as without windows.
    trajectory_of(s);
    horizon = std::make_shared<const RecedingHorizon>(s.model, s.desired_states->t, s.desired_states->q, s.desired_u,
                                                      s.Q, s.Qf, design_gamma(s), *s.receding_horizon, s.solver);
  } else {
    horizon = std::make_shared<const RecedingHorizon>(s.model, s.desired_q0, s.desired_u, s.t0, s.Q, s.Qf,
                                                      design_gamma(s), *s.receding_horizon, s.solver);
  }
  if (s.path_change) horizon = horizon->with_path_change(s.path_change->t, s.path_change->u_d);
  return horizon;
}

}  // namespace

namespace detail {

ScenarioDesign design_scenario(const Scenario& s) {
  const auto start = std::chrono::steady_clock::now();
  ScenarioDesign design;
  try {
    if (s.receding_horizon) {
      // The windows are solved as the loop runs (simulate_receding_horizon): here only the first
      // window's trajectory, for the model and the results.
      design.horizon = receding_horizon_of(s);
      design.trajectory = design.horizon->window_trajectory(0, s.desired_q0);
      design.seconds = seconds_since(start);
      return design;
    }
    design.trajectory = trajectory_of(s);
    // The design of the law: Z at gamma (hinf, and the estimator of cascade) or at inf (lqr).
    try {
      design.solution = solve_grde(design.trajectory, s.Q, s.Qf, design_gamma(s), s.solver);
    } catch (const ConjugatePointError&) {
      design.solution_error = std::current_exception();
    }
    if (s.worst_case && s.law == Law::Lqr && design.solution)
      design.game = solve_law_riccati(design.solution, s.Q, s.Qf, s.gamma, s.kappa, s.solver);
    if (s.worst_case && is_baseline(s.law)) {
      // A baseline's own worst case, from its closed loop linearized along the trajectory.
      std::unique_ptr<Controller> law = baseline_controller(s, design.trajectory);
      design.game = solve_controller_riccati(design.trajectory, *law, s.Q, s.Qf, s.gamma, s.solver);
    }
    if (design.solution) design.solution->eigenvalue_bounds(design.Z_min_eig, design.Z_max_eig);
  } catch (...) {
    design.error = std::current_exception();
  }
  design.seconds = seconds_since(start);
  return design;
}

namespace {

// The gamma of the game design of [disturbance] worst_case with the lqr law or a baseline (the
// law's own closed loop), if there is one.
std::optional<double> game_gamma(const Scenario& s) {
  if (s.worst_case && (s.law == Law::Lqr || is_baseline(s.law))) return s.gamma;
  return std::nullopt;
}

// The LQR law's own worst case depends on its gain scaling kappa (K = kappa B'Z).
bool same_kappa(const Scenario& a, const Scenario& b) {
  return VectorSignal(std::vector<Signal>{a.kappa}).same_signals(VectorSignal(std::vector<Signal>{b.kappa}));
}

// The same law for a game: the LQR law's worst case depends on kappa, a baseline's on its gains.
bool same_game_law(const Scenario& a, const Scenario& b) {
  if (a.law != b.law) return false;
  if (a.law == Law::Lqr) return same_kappa(a, b);
  if (a.law == Law::Cascade)
    return a.cascade.k == b.cascade.k && a.cascade.k1 == b.cascade.k1 && a.cascade.k2 == b.cascade.k2;
  const BacksteppingGains &x = a.backstepping, &y = b.backstepping;
  return x.k == y.k && x.k1 == y.k1 && x.k2 == y.k2 && x.k3 == y.k3;
}

bool same_matrix(const Mat& a, const Mat& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && a == b;
}

bool same_states(const Scenario& a, const Scenario& b) {
  if (a.desired_states.has_value() != b.desired_states.has_value()) return false;
  if (!a.desired_states) return true;
  const DesiredStates &x = *a.desired_states, &y = *b.desired_states;
  return x.t == y.t && same_matrix(x.q, y.q) && x.max_defect == y.max_defect;
}

void combine(std::size_t& seed, double value) {
  seed ^= std::hash<double>{}(value) + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
}

}  // namespace

bool same_design(const Scenario& a, const Scenario& b) {
  return a.model->same_as(*b.model) && a.t0 == b.t0 && a.tf == b.tf && same_matrix(a.desired_q0, b.desired_q0) &&
         a.desired_u.same_signals(b.desired_u) && same_states(a, b) && design_gamma(a) == design_gamma(b) &&
         same_matrix(a.Q, b.Q) &&
         same_matrix(a.Qf, b.Qf) && a.solver == b.solver && game_gamma(a) == game_gamma(b) &&
         (!game_gamma(a) || same_game_law(a, b)) &&
         a.receding_horizon.has_value() == b.receding_horizon.has_value() &&
         (!a.receding_horizon || (a.receding_horizon->window == b.receding_horizon->window &&
                                  a.receding_horizon->update == b.receding_horizon->update &&
                                  a.receding_horizon->terminal == b.receding_horizon->terminal)) &&
         a.path_change.has_value() == b.path_change.has_value() &&
         (!a.path_change || (a.path_change->t == b.path_change->t && a.path_change->u_d.same_signals(b.path_change->u_d)));
}

std::size_t design_hash(const Scenario& s) {
  std::size_t seed = std::hash<std::string>{}(s.model->name());
  for (const auto& [name, value] : s.model->named_parameters()) combine(seed, value);
  for (double value : {s.t0, s.tf, design_gamma(s), s.solver.rtol, s.solver.atol}) combine(seed, value);
  if (s.receding_horizon)
    for (double value : {s.receding_horizon->window, s.receding_horizon->update}) combine(seed, value);
  for (Eigen::Index i = 0; i < s.desired_q0.size(); ++i) combine(seed, s.desired_q0[i]);
  if (s.desired_states)
    for (double t : s.desired_states->t) combine(seed, t);
  for (const Mat* M : {&s.Q, &s.Qf})
    for (Eigen::Index i = 0; i < M->size(); ++i) combine(seed, M->data()[i]);
  return seed;
}

namespace {

// The loop of [sampling]: the online controller of the law's design (emulated, or the discrete
// game at the period), with the filter of [measurement] when there is one.
SimulationResult simulate_sampled_scenario(const Scenario& s, const RunResult& result, const ScenarioDesign& design,
                                           const Disturbance& disturbance, const RowMat* noise, OnlineCounts& counts,
                                           std::optional<RecedingHorizonReport>& receding) {
  const SamplingSpec& sp = *s.sampling;
  OnlineOptions options;
  options.limits = sp.limits;
  options.max_age = sp.max_age;
  options.compensate_delay = sp.compensate_delay;
  SampledLoopOptions loop;
  loop.delay = sp.delay;
  loop.simulation = s.simulation_options();
  loop.measurement_every = sp.measurement_every();
  if (s.measurement) {
    const MeasurementSpec& ms = *s.measurement;
    options.filter.N = ms.N;
    options.filter.Sigma0 = initial_sigma(s);
    options.filter.Q = s.Q;
    options.filter.hold = sp.measurement_every() * sp.period;
    options.filter.update = sp.measurement_update;
    loop.sigma = ms.sigma;
    loop.noise = noise == nullptr ? scenario_noise(s) : *noise;
  }
  SimulationResult r;
  if (design.horizon) {
    // The windows on the solver's thread, handed over at their first samples; the desired
    // trajectory over [t0, tf], path changes included, is the run's reference (its q_d series
    // and divergence bound).
    RecedingOnlineController controller(design.horizon, sp.period, options, s.kappa);
    r = simulate_sampled(*design.horizon->reference(s.tf), controller, disturbance, s.initial_q0, loop, s.plant.get());
    counts = controller.controller().counts();
    const RecedingOnlineStatus status = controller.status();
    if (status.windows_failed > 0)
      throw ConjugatePointError(status.last_failure + " (the online controller kept the window before it)",
                                status.failed_t_start, design.horizon->gamma());
    RecedingHorizonReport& report = receding.emplace();
    report.options = design.horizon->options();
    report.windows = status.window_in_use + 1;  // used (one more may be solved ahead, by the thread's timing)
  } else {
    const SampledLawPtr law =
        sp.design == SampledDesign::Emulated
            ? SampledLaw::emulated(result.solution, sp.period, s.kappa)
            : SampledLaw::digital(solve_discrete_game(result.trajectory, sp.period, s.Q, s.Qf, design_gamma(s)));
    OnlineController controller(law, options);
    r = simulate_sampled(*result.trajectory, controller, disturbance, s.initial_q0, loop, s.plant.get());
    counts = controller.counts();
  }
  if (s.measurement && s.measurement->on_coupling_violation == CouplingPolicy::Error && counts.coupling_violated > 0) {
    const double gamma = design_gamma(s);
    throw CouplingConditionError(
        str_cat("coupling condition violated at t = ", counts.coupling_violation_t, " in the sampled loop: rho(Sigma Z)"
                " >= gamma^2 = ", gamma * gamma, " at ", counts.coupling_violated, " of ", counts.steps, " steps (paper"
                " §4: I - gamma^-2 Sigma Z must stay invertible). Increase gamma, or make Sigma(t0) = (Q0 - eta I)^-1"
                " smaller (larger Q0 - eta I); or ask to continue and only flag it"),
        counts.coupling_violation_t, counts.largest_rho * gamma * gamma, gamma);
  }
  return r;
}

}  // namespace

RunResult simulate_scenario(const Scenario& s, const ScenarioDesign& design, const RowMat* noise,
                            bool sigma_eigenvalues) {
  // The cascade law with state feedback does not use the law's design: there it is only
  // reported, and a gamma at or below gamma* leaves it out instead of failing the run.
  const bool design_needed = (!is_baseline(s.law) || s.measurement || s.worst_case) && !s.receding_horizon;
  if (design.error) std::rethrow_exception(design.error);
  if (!design.solution && design_needed) std::rethrow_exception(design.solution_error);

  RunResult result;
  result.scenario_name = s.name;
  result.law = s.law;
  result.output_feedback = s.measurement.has_value();
  result.gamma = design_gamma(s);
  result.trajectory = design.trajectory;
  result.plant = s.plant;
  result.solution = design.solution;
  // The law's own worst case: P of its closed loop at gamma (Z itself for hinf).
  const std::shared_ptr<const SymmetricSolution> game =
      design.game ? design.game : std::shared_ptr<const SymmetricSolution>(design.solution);

  const auto simulate_start = std::chrono::steady_clock::now();
  std::unique_ptr<Controller> controller;
  if (is_baseline(s.law)) controller = baseline_controller(s, result.trajectory);
  else if (result.solution) controller = std::make_unique<HinfStateFeedback>(result.solution, s.kappa);
  const Disturbance disturbance = s.worst_case ? Disturbance(s.disturbance, game) : Disturbance(s.disturbance);
  if (s.receding_horizon && !s.sampling) {
    result.simulation = simulate_receding_horizon(*design.horizon, disturbance, s.initial_q0, s.tf,
                                                  s.simulation_options(), s.plant.get(), s.kappa,
                                                  &result.receding_horizon.emplace());
  } else if (s.sampling) {
    result.sampling = s.sampling;
    result.simulation =
        simulate_sampled_scenario(s, result, design, disturbance, noise, result.online.emplace(), result.receding_horizon);
  } else if (s.measurement) {
    const MeasurementSpec& ms = *s.measurement;
    OutputFeedbackProblem problem;
    problem.design = result.solution;
    problem.sigma = ms.sigma;
    problem.sample_period = ms.sample_period;
    problem.noise = noise == nullptr ? scenario_noise(s) : *noise;
    problem.N = ms.N;
    problem.Sigma0 = initial_sigma(s);
    problem.Q = s.Q;
    OutputFeedbackOptions options;
    options.filter_A = ms.filter_A;
    options.on_coupling_violation = ms.on_coupling_violation;
    options.sigma_eigenvalues = sigma_eigenvalues;
    result.simulation = simulate_output_feedback(problem, *controller, disturbance, s.initial_q0, options,
                                                 s.simulation_options(), s.plant.get());
  } else {
    result.simulation = simulate_state_feedback(*result.trajectory, *controller, disturbance, s.initial_q0,
                                                s.simulation_options(), s.plant.get());
  }
  result.timing.simulate = seconds_since(simulate_start);

  const auto analysis_start = std::chrono::steady_clock::now();
  if (result.solution) result.Z0 = result.solution->Z(s.t0);
  result.Z_min_eig = design.Z_min_eig;
  result.Z_max_eig = design.Z_max_eig;
  result.metrics = compute_metrics(*s.model, result.simulation, cost_weights(s, result));
  judge_track(s, result);
  result.timing.analysis = seconds_since(analysis_start);
  return result;
}

}  // namespace detail

namespace {

RunResult run(const Scenario& scenario, const RowMat* noise) {
  const auto start = std::chrono::steady_clock::now();
  const Scenario s = scenario.resolved();
  s.validate();
  const detail::ScenarioDesign design = detail::design_scenario(s);
  RunResult result = detail::simulate_scenario(s, design, noise);
  result.timing.design = design.seconds;
  result.timing.total = seconds_since(start);
  return result;
}

}  // namespace

RunResult run_scenario(const Scenario& scenario) { return run(scenario, nullptr); }

std::vector<std::string> scenario_warnings(const Scenario& scenario) {
  std::vector<std::string> warnings;
  auto check = [&](const Signal& signal, const std::string& name) {
    const std::string warning = overshoot_warning(signal, name);
    if (!warning.empty()) warnings.push_back(warning);
  };
  auto check_channels = [&](const VectorSignal& signals, const std::string& prefix) {
    if (signals.is_function()) return;
    for (std::size_t i = 0; i < signals.channels().size(); ++i)
      check(signals.channels()[i], str_cat(prefix, i + 1));
  };
  check_channels(scenario.desired_u, "[desired] u");
  check(scenario.kappa, "[controller] kappa");
  check_channels(scenario.disturbance, "[disturbance] w");
  return warnings;
}


GammaStarResult scenario_gamma_star(const Scenario& scenario, GammaStarOptions options) {
  const Scenario s = scenario.resolved();
  s.validate();
  options.solver = s.solver;
  return gamma_star(trajectory_of(s), s.Q, s.Qf, options);
}

GammaStarResult scenario_gamma_star_output_feedback(const Scenario& scenario, GammaStarOptions options) {
  const Scenario s = scenario.resolved();
  s.validate();
  require(s.measurement.has_value(), "the output-feedback gamma* needs a scenario with [measurement]");
  options.solver = s.solver;
  return gamma_star_output_feedback(trajectory_of(s), s.Q, s.Qf, s.measurement->N, initial_sigma(s), options);
}

std::shared_ptr<const RecedingHorizon> scenario_receding_horizon(const Scenario& scenario) {
  require(scenario.receding_horizon.has_value(),
          "the scenario has no [receding_horizon]: give one (window, update) to run it over moving windows");
  const Scenario s = scenario.resolved();
  s.validate();
  return receding_horizon_of(s);
}

Certificates scenario_certificates(const Scenario& scenario) {
  const Scenario s = scenario.resolved();
  s.validate();
  const RiccatiSolutionPtr Z = solve_grde(trajectory_of(s), s.Q, s.Qf, s.gamma, s.solver);
  return certify(*Z, s.kappa, s.Q);
}

RunResult run_scenario_with_noise(const Scenario& scenario, const RowMat& noise) {
  require(scenario.measurement.has_value(),
          "explicit noise needs a scenario with [measurement] (imperfect measurements)");
  return run(scenario, &noise);
}

}  // namespace hinf
