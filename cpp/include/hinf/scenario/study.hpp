// Studies: many scenarios run as one batch (a Monte Carlo over noise seeds, initial states,
// disturbances or plants; a sweep over gamma or weights), in parallel, one row per run.
//
//   run_scenarios(scenarios, options, progress) -> one StudyRun per scenario, in the order given.
// (The Python package's hinf_cpp.studies.run_study runs a study file on top of it.)
//
// Independence. Every row is what run_scenario gives for that scenario alone, bit for bit,
// whatever the number of threads and whether designs are shared: each run is computed by one
// thread with the code of run_scenario (its design part and its closed-loop part), nothing
// mutable is shared between runs, and every row is written only by the thread of its run, at
// its index.
//
// Failures. No run stops the study: a run whose design or closed loop fails is a row with the
// failure's RunOutcome and message (ConjugatePointError, CouplingConditionError, SolverError,
// InputError, any other std::exception); a closed loop that stops as diverged is a row with
// outcome Diverged and the run's status message.
//
// Design sharing (StudyOptions::share_designs). Runs whose design inputs are equal share one
// desired trajectory and one set of Riccati solutions, computed once. The design inputs are the
// model (its kind and parameters), t0, tf, desired q0 and u_d, Q, Qf, the [solver] options and
// the gamma of the law's design (the scenario's gamma for hinf and cascade, inf for lqr; with
// [disturbance] worst_case and the lqr law also the scenario's gamma, for the game design).
// Everything else differs freely between runs that share a design: the initial state, the
// disturbance, the plant ([plant]), kappa, the cascade gains, [measurement] (seed, sigma, N,
// Q0, eta: the filter Riccati equation is integrated with each closed loop), [output], the
// divergence factor.
// The inputs are compared as values: models by Model::same_as (a built-in model by its type
// and parameters; a model implemented in Python only with itself, the same object), signals by
// their definitions (a function of t, such as a Python callable, equals no other signal).
// Distinct designs used by several runs are computed first, in parallel; a design used by a
// single run is computed by that run's thread, and a shared design is released once its last
// run is done.
//
// Threads. Runs (and designs) are spread over min(threads, number of runs) worker threads.
// Trajectories, Riccati solutions, models, signals and disturbances are only read by the runs
// (their const evaluations keep no state: lookups take caller-owned cursors); controllers,
// which keep cursors, are made per run. A model implemented in Python holds the GIL in each
// call, so its runs do not overlap (the Python binding gives such a study one thread).
//
// Progress. progress(done, total) is called on the calling thread only: it waits while the
// workers run and calls progress about every 0.1 s when the number of finished runs changed,
// and once at the end with done == total. An exception thrown by progress stops the study:
// the workers take no new run, finish the ones they are in, are joined, and the exception is
// rethrown to the caller of run_scenarios.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "hinf/control/metrics.hpp"
#include "hinf/core/enum_names.hpp"
#include "hinf/scenario/scenario.hpp"

namespace hinf {

// How a run of a study ended.
enum class RunOutcome {
  Completed,          // the closed loop ran over the whole horizon
  Diverged,           // the closed loop stopped at the divergence bound (simulation.hpp)
  LostTrack,          // it ran to tf but ended off the path (Scenario::lost_track)
  ConjugatePoint,     // no design: the GRDE escapes at this gamma (gamma <= gamma*)
  CouplingViolation,  // output feedback: rho(Sigma Z) < gamma^2 failed
  SolverFailure,      // an integrator failed (SolverError)
  InvalidInput,       // the scenario is invalid (Scenario::validate, or an InputError later)
  Failed              // any other exception
};
template <>
struct EnumNames<RunOutcome> {
  static constexpr const char* what = "run outcome";
  static constexpr std::array<std::pair<RunOutcome, const char*>, 8> names{
      {{RunOutcome::Completed, "completed"},
       {RunOutcome::Diverged, "diverged"},
       {RunOutcome::LostTrack, "lost_track"},
       {RunOutcome::ConjugatePoint, "conjugate_point"},
       {RunOutcome::CouplingViolation, "coupling_violation"},
       {RunOutcome::SolverFailure, "solver_failure"},
       {RunOutcome::InvalidInput, "invalid_input"},
       {RunOutcome::Failed, "failed"}}};
};

// One row of a study.
struct StudyRun {
  RunOutcome status = RunOutcome::Failed;  // how the run ended
  std::string reason;     // empty when completed; else the error message or the status message
  Metrics metrics;        // all NaN when the run failed before its closed loop ended; a diverged
                          // run has what compute_metrics gives for the part it ran
  double gamma = NAN;     // of the law's design (inf for lqr), as RunResult::gamma
  Law law = Law::Hinf;            // the scenario's law
  bool output_feedback = false;   // true with [measurement]
  double design_seconds = 0.0;    // wall-clock time of the design the run used (a shared design's
                                  // time is given in each of its runs)
  double simulate_seconds = 0.0;  // closed loop and metrics
  int design = -1;  // which of the study's designs the run used: runs with the same number shared
                    // one; -1 when the run failed before a design was made (invalid input)
};

// Options of run_scenarios.
struct StudyOptions {
  int threads = 0;            // worker threads (>= 0); 0: the hardware's threads; never more than runs
  bool share_designs = true;  // compute each distinct design once: runs with equal design
                              // inputs share it (see above)

  void validate() const;  // InputError unless threads >= 0
};

// Runs every scenario, in parallel, and returns one StudyRun per scenario, in the order given:
// each row is what run_scenario gives for that scenario alone. InputError only for invalid
// options; whatever a run raises is its row's outcome and reason.
std::vector<StudyRun> run_scenarios(const std::vector<Scenario>& scenarios, const StudyOptions& options = {},
                                const std::function<void(std::size_t done, std::size_t total)>& progress = {});
// The name of run_scenarios in 0.1, deprecated: removed in 0.3.
[[deprecated("run_study is renamed run_scenarios (hinf_cpp 0.2)")]] inline std::vector<StudyRun> run_study(
    const std::vector<Scenario>& scenarios, const StudyOptions& options = {},
    const std::function<void(std::size_t done, std::size_t total)>& progress = {}) {
  return run_scenarios(scenarios, options, progress);
}

}  // namespace hinf
