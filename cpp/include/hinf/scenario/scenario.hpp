// A scenario: everything one run needs (docs/scenarios.md is the reference of its TOML form).
// Both front ends (the Python package and the hinf-sim executable) build a Scenario and call
// run_scenario(), so they give the same numbers.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "hinf/control/analysis.hpp"
#include "hinf/control/backstepping.hpp"
#include "hinf/control/cascade.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/online_controller.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/control/receding_horizon.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/numerics/signal.hpp"
#include "hinf/numerics/solver_options.hpp"

namespace hinf {

// [measurement]: imperfect, noisy measurements (paper §4).
struct MeasurementSpec {
  double sigma = 0.0;           // std of the noise on each measured output
  double sample_period = 0.01;  // noise held constant over each period (s)
  std::uint64_t seed = 0;       // seed of the noise samples (scenario_noise)
  Mat N;                        // filter weight N = E E' (empty: sigma^2 I)
  Mat Q0;                       // Sigma(t0) = (Q0 - eta I)^-1 (empty: 2 I)
  double eta = 1.0;             // > 0, with Q0 - eta I positive definite
  FilterLinearization filter_A = FilterLinearization::Estimate;  // the A of the filter (36)
  CouplingPolicy on_coupling_violation = CouplingPolicy::Error;   // what a violation does
};

// [desired] states: the desired trajectory given as states and inputs (trajectory.hpp), e.g. a
// plan of an open-loop-unstable vehicle.
struct DesiredStates {
  std::vector<double> t;  // the nodes t_0 = t0 < ... < t_N = tf (s)
  RowMat q;               // the desired states at the nodes, (N + 1) x n; row 0 is [desired] q0
  double max_defect = 1e-6;  // the largest defect d_k of an interval allowed (the states' units, > 0)
};

// [path_change]: the path changed under way, with [receding_horizon] (receding_horizon.hpp): from
// the window that starts at t on, the desired trajectory continues from q_d(t) with the inputs u_d.
struct PathChange {
  double t = 0.0;     // s: a window's start after t0
  VectorSignal u_d;   // the new desired inputs, m channels
};

// Which design a sampled loop runs ([sampling] design).
enum class SampledDesign {
  Emulated,  // the continuous design held over each sample (SampledLaw::emulated)
  Digital    // the discrete game at the period (SampledLaw::digital, solve_discrete_game)
};
template <>
struct EnumNames<SampledDesign> {
  static constexpr const char* what = "design";
  static constexpr std::array<std::pair<SampledDesign, const char*>, 2> names{
      {{SampledDesign::Emulated, "emulated"}, {SampledDesign::Digital, "digital"}}};
};

// [sampling]: the closed loop as on a vehicle (sampled_loop.hpp): the online controller called
// every `period`, its command held, with a computation delay and actuator limits.
struct SamplingSpec {
  double period = 0.0;                            // s: the controller's period T, > 0
  SampledDesign design = SampledDesign::Emulated;  // the law it runs
  double delay = 0.0;                             // s, in [0, T]: the command is applied this late
  bool compensate_delay = true;                   // predict the measurement over the delay
  ActuatorLimits limits;                          // u_min, u_max, rate_max (empty: none)
  double max_age = INFINITY;                      // s: an older measurement is stale
  double measurement_period = 0.0;                // s: the sensor's period, a multiple of T (0: T)
  MeasurementUpdate measurement_update = MeasurementUpdate::Sampled;  // how the output-feedback
                                                  // estimator takes a measurement (online_controller.hpp)
  // The sensor's period in samples of T (>= 1).
  int measurement_every() const;
};

// The tracking law of a scenario ([controller] law).
enum class Law {
  Hinf,    // the paper's H-infinity law (17)/(18), and (34) with measurements
  Lqr,     // the same design at gamma = inf; with [measurement] also the Kalman-Bucy filter
  Cascade,      // the cascaded ship baseline (control/cascade.hpp); with [measurement] on the H-infinity estimate
  Backstepping  // the backstepping ship baseline (control/backstepping.hpp); likewise
};
template <>
struct EnumNames<Law> {
  static constexpr const char* what = "law";
  static constexpr std::array<std::pair<Law, const char*>, 4> names{{{Law::Hinf, "hinf"},
                                                                     {Law::Lqr, "lqr"},
                                                                     {Law::Cascade, "cascade"},
                                                                     {Law::Backstepping, "backstepping"}}};
};
// True for the ship baselines (cascade, backstepping): laws without a Riccati design of their own.
inline bool is_baseline(Law law) { return law == Law::Cascade || law == Law::Backstepping; }

// A scenario: the model, the horizon, the desired trajectory, the law and its design, the
// disturbance, the initial state, the measurement (output feedback) and the solver. Fields left
// empty take the defaults that resolved() fills in.
struct Scenario {
  std::string name;           // for results and messages (a file's stem by default)
  std::string description;    // free text
  ModelPtr model;             // the design model: desired trajectory, GRDE, controller, estimator
  ModelPtr plant;             // [plant]: the vehicle the closed loop integrates (its f, G, D),
                              // when it differs from the design model; null: the design model.
                              // Same structure as the model (check_plant).
  double t0 = 0.0;            // [horizon] t0 (s)
  double tf = 0.0;            // [horizon] tf (s), > t0
  Vec desired_q0;             // q_d(t0)
  VectorSignal desired_u;     // u_d(t), m channels
  std::optional<DesiredStates> desired_states;  // [desired] states: q_d given at nodes, each
                              // interval integrated from its node; none: q_d integrated from q0
  double gamma = 0.0;         // > 0, may be +inf (LQR)
  Mat Q;                      // empty: identity
  Mat Qf;                     // empty: identity
  Signal kappa = Signal(1.0);  // gain scaling kappa(t) of the law (17)/(18), > 0
  Law law = Law::Hinf;        // the tracking law
  CascadeGains cascade;       // the gains of the cascade law
  BacksteppingGains backstepping;  // the gains of the backstepping law
  VectorSignal disturbance;   // w(t), nw channels (dim 0: all zero)
  bool worst_case = false;    // adds the worst-case disturbance gamma^-2 D' Z q_e of paper
                              // eq. (16) (Z of the H-infinity design at gamma, whatever the
                              // law) to the disturbance signals
  Vec initial_q0;             // q(t0)
  std::optional<MeasurementSpec> measurement;  // imperfect measurements; none: state feedback
  std::optional<SamplingSpec> sampling;        // a sampled loop through the online controller;
                                               // none: the continuous loop
  std::optional<PathChange> path_change;  // [path_change]: a new path from t on (with
                                          // [receding_horizon] in the continuous loop)
  std::optional<RecedingHorizonOptions> receding_horizon;  // [receding_horizon]: the law designed
                                               // over a moving window (receding_horizon.hpp), state
                                               // feedback in the continuous loop; none: one design
                                               // over [t0, tf]
  SolverOptions solver;             // every integration: the Riccati equations and the closed loop
  double output_dt = 0.01;          // [output] dt
  double divergence_factor = 10.0;  // [solver] divergence_factor (simulation.hpp)
  double lost_track = 1.0;          // [solver] lost_track (m, > 0, may be inf): a run that ends
                                    // more than this farther from the desired path than it
                                    // started has status LostTrack (models with a position only)

  // A copy with the defaults filled in (Q = Qf = I, zero disturbance, N = sigma^2 I (a 1 x 1
  // N is that many times I), Q0 = 2 I).
  Scenario resolved() const;
  // Throws InputError naming the first problem found. Call on a resolved scenario.
  void validate() const;
  // The checks of validate() that need no model (the horizon, gamma, kappa, the solver and output
  // settings, the scalars of [measurement] and [sampling]): what the reader checks before it loads
  // a model that is a program.
  void validate_settings() const;
  // output_dt, divergence_factor and solver, for the closed loop.
  SimulationOptions simulation_options() const;
};

// InputError unless `plant` can stand in for `model` in a closed loop: the same n, m, nw, noise
// channels, heading index and position indices, and as many measured outputs (rows of C(t0)),
// or no measurement when the model has none. Messages name [plant].
void check_plant(const Model& model, const Model& plant, double t0);

// The wall-clock time of a run's parts (s).
struct Timing {
  double design = 0.0;    // desired trajectory, GRDE, eigenvalue bounds of Z
  double simulate = 0.0;  // closed loop
  double analysis = 0.0;  // metrics
  double total = 0.0;     // the whole run_scenario, checks included
};

// What run_scenario gives: the design, the closed loop and its metrics.
struct RunResult {
  std::string scenario_name;    // the scenario's name
  Law law = Law::Hinf;          // the scenario's law
  bool output_feedback = false;  // true with [measurement]
  double gamma = 0.0;           // of the law's design: the scenario's gamma, inf for lqr
  TrajectoryPtr trajectory;   // its model is the design model; with [receding_horizon] the first
                              // window's desired trajectory (the run's q_d is simulation.q_d)
  ModelPtr plant;             // the scenario's plant; null when the closed loop integrated the design model
  RiccatiSolutionPtr solution;  // the law's design; null for the cascade law with state feedback
                                // when no design exists at gamma (gamma <= gamma*), and with
                                // [receding_horizon] (the windows are not kept)
  Mat Z0;                       // Z(t0) (n x n); empty without a design
  double Z_min_eig = NAN, Z_max_eig = NAN;  // m and M of paper eq. (22) over [t0, tf]
  std::optional<double> gamma_star;  // not computed by run_scenario; set by the caller for
                                     // the results file (scenario_gamma_star)
  SimulationResult simulation;  // the closed loop's time series
  std::optional<SamplingSpec> sampling;  // the scenario's [sampling]
  std::optional<OnlineCounts> online;    // with [sampling]: what the online controller's steps did
  std::optional<RecedingHorizonReport> receding_horizon;  // with [receding_horizon]: what was solved
  Metrics metrics;              // of the closed loop (metrics.hpp)
  Timing timing;                // the wall-clock time of its parts
};

// One run: resolves and validates the scenario (InputError naming the key), designs the law
// (the desired trajectory, Z of the GRDE at the law's gamma), simulates the closed loop (state
// feedback, or output feedback with [measurement], its noise from the seed), and computes the
// metrics. ConjugatePointError when the design needs Z and gamma <= gamma*;
// CouplingConditionError and SolverError as the closed loops raise them.
RunResult run_scenario(const Scenario& scenario);

// What is legal but probably not meant, one message per finding, naming the key: a table
// whose interpolation overshoots the range of its values ([desired] u1, [disturbance] w2,
// [controller] kappa). The front ends print them (hinf-sim) or warn (Python).
std::vector<std::string> scenario_warnings(const Scenario& scenario);

// gamma* (eq. 14) of the scenario's state-feedback design (trajectory, Q, Qf, horizon; also
// for a scenario with [measurement]). options.solver is replaced by the scenario's [solver].
GammaStarResult scenario_gamma_star(const Scenario& scenario, GammaStarOptions options = {});
// The smallest gamma of the scenario's output-feedback design (needs [measurement]).
GammaStarResult scenario_gamma_star_output_feedback(const Scenario& scenario, GammaStarOptions options = {});
// The receding horizon a run of the scenario follows: its [receding_horizon] over its [desired]
// trajectory (inputs, or states and inputs), its [path_change] applied. InputError without
// [receding_horizon] or for an invalid scenario.
std::shared_ptr<const RecedingHorizon> scenario_receding_horizon(const Scenario& scenario);
// The certificates of paper §3 for the scenario's design (gamma, Q, Qf, kappa).
Certificates scenario_certificates(const Scenario& scenario);

// The standard normal noise samples of a scenario with [measurement] (from its seed): one row
// per hold interval of [measurement] sample_period, or with [sampling] one per sample of its
// period (a measurement's noise is that of its sample).
RowMat scenario_noise(const Scenario& scenario);
// As run_scenario, with explicit noise samples (one row per hold interval, one column per
// measured output; see output_feedback.hpp) instead of the seeded ones.
RunResult run_scenario_with_noise(const Scenario& scenario, const RowMat& noise);

}  // namespace hinf
