// run_scenario in two parts, the design and the closed loop, so that run_scenarios (study.cpp) can
// compute a design once and run every scenario that shares it (private to the library).
#pragma once

#include <cmath>
#include <cstddef>
#include <exception>
#include <optional>
#include <string>

#include "hinf/scenario/scenario.hpp"

namespace hinf::detail {

// The design of a scenario: the desired trajectory and the Riccati solution(s) of its law.
// Immutable once made, and safe to use from several threads at once (a Trajectory and a
// RiccatiSolution keep no state between const calls: lookups take caller-owned cursors).
struct ScenarioDesign {
  TrajectoryPtr trajectory;
  // Z of the law: at gamma (hinf, cascade) or at inf (lqr). Null when it does not exist:
  // solution_error is then the ConjugatePointError (the cascade law with state feedback runs
  // without it, as it does in run_scenario).
  RiccatiSolutionPtr solution;
  std::exception_ptr solution_error;
  // [disturbance] worst_case with the lqr law: the LQR law's own worst case at the scenario's
  // gamma, P of its closed-loop Riccati equation (solve_law_riccati; otherwise the worst case
  // uses `solution`, whose P is Z itself).
  std::shared_ptr<const SymmetricSolution> game;
  // [receding_horizon]: the windows' design (solved as the loop runs); trajectory is then its first
  // window's, and solution null.
  std::shared_ptr<const RecedingHorizon> horizon;
  // Anything else that failed (the trajectory, a SolverError of a Riccati solve, the game):
  // every run of the design fails with it.
  std::exception_ptr error;
  // m and M of paper eq. (22): the extreme eigenvalues of Z over [t0, tf] (RunResult::Z_min_eig,
  // Z_max_eig). Part of the design so that runs sharing it do not search them again (a few ms
  // for the ship, as long as a short closed loop); NaN without a solution.
  double Z_min_eig = NAN, Z_max_eig = NAN;
  double seconds = 0.0;  // wall-clock time of the design
};

// The design of a resolved, validated scenario. Never throws: failures are kept in the design.
ScenarioDesign design_scenario(const Scenario& s);

// The rest of run_scenario for a resolved, validated scenario and its design (which may come
// from another scenario with the same design_key): rethrows the design's failure where s needs
// what failed, then simulates the closed loop and computes the metrics. noise: explicit noise
// samples, or null for the seeded ones. Fills every field but timing.design and timing.total.
// sigma_eigenvalues: OutputFeedbackOptions::sigma_eigenvalues (run_scenarios, which keeps only the
// metrics, leaves that series out).
RunResult simulate_scenario(const Scenario& s, const ScenarioDesign& design, const RowMat* noise,
                            bool sigma_eigenvalues = true);

// Whether design_scenario gives two resolved, validated scenarios the same design: the design
// inputs are equal as values. They are the model (Model::same_as), t0, tf, desired q0 and u_d
// (a function of t equals nothing), Q, Qf, the [solver] options and the gamma of the law's
// design (inf for lqr), and with [disturbance] worst_case under the lqr law also the gamma of
// the game design. Everything else may differ (initial state, disturbance, kappa, cascade gains,
// measurement, output, divergence factor, plant).
bool same_design(const Scenario& a, const Scenario& b);
// A hash of the design inputs, equal for scenarios with the same design (same_design): for
// grouping many scenarios without comparing each pair.
std::size_t design_hash(const Scenario& s);

}  // namespace hinf::detail
