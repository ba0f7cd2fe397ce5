// The receding-horizon design: the GRDE (13) solved over a window that moves with time, so that a
// mission of any length is designed with memory that depends on the window, not on the mission.
//
// Window j starts at t_j = t0 + j * update and covers [t_j, t_j + H] (H = window):
//   - its desired trajectory is eq. (8) integrated from q_d(t_j) of window j - 1 (q_d0 for
//     j = 0) with the same u_d: the windows chain into one desired trajectory, continuous at every
//     t_j, whose value differs from one integration over the whole mission by the integration
//     error only (trajectory.hpp);
//   - its design is the GRDE solved backward from Z(t_j + H) = the terminal weight, with its own
//     conjugate-point check (ConjugatePointError names the window). The terminal weight is Qf
//     (TerminalWeight::Qf), or the stabilizing solution of the stationary game ARE of the
//     linearization frozen at the window's end (TerminalWeight::Stationary, solve_game_are): the
//     cost-to-go of an infinite horizon beyond the window, so that the window's Z is that of a
//     longer horizon already at its start (for a slowly varying trajectory);
//   - the law of window j is used on [t_j, t_{j+1}): u = u_d - kappa B_e' Z_j (q - q_d), so the
//     Z in use is always at least H - update before its window's end, where the terminal weight
//     has decayed (the gain of a fixed-horizon design collapses towards B' Qf over its last
//     seconds; the receding horizon never reaches them).
// The gamma a receding-horizon run certifies is the largest gamma* over its windows: each window
// is a finite-horizon game of its own (receding_horizon_gamma_star).
//
// A desired trajectory given as states (a planner's nodes, for a vehicle open-loop unstable
// along its plan; trajectory.hpp): each window is the states form over its own interval, from its
// start (the node there, or the chained q_d) through the nodes inside it, each interval
// integrated from its node; beyond the last node the window integrates from it. The windows
// then chain without the open-loop drift of one integration. The nodes are kept whole (their
// memory grows with the mission: n + 1 numbers per node).
//
// A path changed under way (with_path_change): from the window that starts at t_join on, the
// windows' trajectories continue from the chained q_d(t_join) with other inputs (a new plan from
// that state); the windows before it keep the old inputs to their ends.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "hinf/control/analysis.hpp"
#include "hinf/control/disturbance.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/enum_names.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf {

// The weight Z(t_j + H) at the end of every window.
enum class TerminalWeight {
  Qf,         // the design's Qf
  Stationary  // the stabilizing solution of the stationary game ARE at the window's end
};
template <>
struct EnumNames<TerminalWeight> {
  static constexpr const char* what = "terminal";
  static constexpr std::array<std::pair<TerminalWeight, const char*>, 2> names{
      {{TerminalWeight::Qf, "qf"}, {TerminalWeight::Stationary, "stationary"}}};
};

// The window of the receding horizon (scenario table [receding_horizon]).
struct RecedingHorizonOptions {
  double window = 10.0;  // H (s): the length of every window's design, > 0
  double update = 1.0;   // s: a new window every this long, in (0, H]
  TerminalWeight terminal = TerminalWeight::Qf;  // the weight at every window's end
  // InputError naming the option.
  void validate() const;
};

// One window: its desired trajectory and its design on [t_start, t_start + H].
struct HorizonWindow {
  int index = 0;            // j
  double t_start = 0.0;     // t_j (s)
  double t_use_end = 0.0;   // t_{j+1} = t_j + update: the window's law is used on [t_j, t_{j+1})
  TrajectoryPtr trajectory;  // q_d, u_d and the linearization on [t_j, t_j + H]
  RiccatiSolutionPtr design;  // Z of the GRDE on [t_j, t_j + H], Z(t_j + H) = Qf
  // The bytes the window stores (the dense outputs of q_d and of Z).
  std::size_t memory_bytes() const;
};

// The windows of a receding-horizon design along the desired trajectory from q_d(t0) = q_d0 with
// the inputs u_d. Immutable: window() is a pure function of its arguments, so windows may be
// solved on any thread.
class RecedingHorizon {
 public:
  // The model, q_d0 and u_d as for a Trajectory (trajectory.hpp); Q (n x n) symmetric positive
  // semidefinite, Qf symmetric positive definite, gamma > 0 (may be +inf: LQR), as for
  // solve_grde. InputError for any of them, or for bad options.
  RecedingHorizon(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, Mat Q, Mat Qf, double gamma,
                  RecedingHorizonOptions options, SolverOptions solver = {}, TrajectoryOptions trajectory = {});
  // The desired trajectory given as states: q_d(t_k) = row k of q_nodes at the nodes t_nodes
  // (increasing, t0 = t_nodes[0], q_d0 = row 0), as for Trajectory's states form; the rest as
  // above. InputError for nodes that are not finite and increasing or rows of another shape.
  RecedingHorizon(ModelPtr model, std::vector<double> t_nodes, RowMat q_nodes, VectorSignal u_d, Mat Q, Mat Qf,
                  double gamma, RecedingHorizonOptions options, SolverOptions solver = {},
                  TrajectoryOptions trajectory = {});

  // The design model of every window.
  const Model& model() const { return *model_; }
  const ModelPtr& model_ptr() const { return model_; }
  // The model's number of states and of inputs.
  int n() const { return model_->n(); }
  int m() const { return model_->m(); }
  // The start of the mission (s).
  double t0() const { return t0_; }
  // The attenuation level of every window (+inf: LQR).
  double gamma() const { return gamma_; }
  // The weights Q and Qf, q_d0 and u_d as given.
  const Mat& Q() const { return Q_; }
  const Mat& Qf() const { return Qf_; }
  const Vec& q_d0() const { return q_d0_; }
  const VectorSignal& u_d_signal() const { return u_d_; }
  // The nodes of a desired trajectory given as states (s; empty otherwise).
  const std::vector<double>& node_times() const { return node_t_; }
  // The desired states at the nodes, one row per node (0 x 0 otherwise).
  const RowMat& node_states() const { return node_q_; }
  // The window and update period, and the integrator of every window's GRDE.
  const RecedingHorizonOptions& options() const { return options_; }
  const SolverOptions& solver() const { return solver_; }

  // The changed horizon: from the window that starts at t_join on, u_d is `u_d` (m channels),
  // the desired trajectory continuing from q_d(t_join). t_join must be a window start after t0
  // and after the last change (InputError otherwise). This horizon stays as it is.
  std::shared_ptr<const RecedingHorizon> with_path_change(double t_join, VectorSignal u_d) const;
  // The path changes so far: (t_join, u_d), in order.
  const std::vector<std::pair<double, VectorSignal>>& path_changes() const { return changes_; }
  // The desired inputs of window j: u_d, or those of the last change at or before t_j.
  const VectorSignal& window_inputs(int j) const;

  // t_j = t0 + j * update (s).
  double window_start(int j) const { return t0_ + j * options_.update; }
  // The window whose law is used at t >= t0: floor((t - t0) / update) (a t within 1e-9 of the
  // update period's multiple belongs to the later window).
  int window_at(double t) const;
  // Window j (>= 0) from the desired state q_d(t_j) = q_d_start (n). InputError for a bad j or
  // q_d_start; SolverError when the integration fails; ConjugatePointError (naming the window)
  // when the GRDE of the window has a conjugate point at gamma.
  HorizonWindow window(int j, const Vec& q_d_start) const;
  // The desired trajectory of window j alone (no design), as window() integrates it.
  TrajectoryPtr window_trajectory(int j, const Vec& q_d_start) const;
  // The weight Z(t_j + H) of window j whose desired trajectory is `window` (window_trajectory):
  // Qf, or the stationary game ARE's solution at the window's end (options().terminal).
  // InputError naming the window when the ARE has no stabilizing, positive definite solution.
  Mat terminal_weight(int j, const Trajectory& window) const;
  // q_d(t) of the chained windows (path changes included), t >= t0: the windows' trajectories
  // integrated from q_d0 up to the window that holds t.
  Vec desired_state(double t) const;
  // The desired trajectory of a run on [t0, tf] (tf > t0), the reference of its q_d series:
  // without path changes one integration from q_d0 (the states form of the nodes, for a
  // trajectory given as states); with them the chained q_d given as states
  // at the window starts (Trajectory's states form), each interval integrated with the inputs in
  // effect (a function of t, so not for the online controller, which takes the windows').
  TrajectoryPtr reference(double tf) const;
  // Window 0, from q_d0.
  HorizonWindow first() const { return window(0, q_d0_); }
  // The window after `previous`, from its q_d at the next t_j.
  HorizonWindow next(const HorizonWindow& previous) const;

 private:
  // The states form from q_a at t_a through the nodes strictly inside (t_a, t_b) to t_b, with u.
  TrajectoryPtr states_trajectory(double t_a, const Vec& q_a, double t_b, const VectorSignal& u) const;

  ModelPtr model_;
  Vec q_d0_;
  VectorSignal u_d_;
  double t0_;
  Mat Q_, Qf_;
  double gamma_;
  RecedingHorizonOptions options_;
  SolverOptions solver_;
  TrajectoryOptions trajectory_options_;
  std::vector<std::pair<double, VectorSignal>> changes_;
  std::vector<double> node_t_;  // a trajectory given as states: the nodes (empty: integrated from q_d0)
  RowMat node_q_;
};

// What a receding-horizon run solved and held.
struct RecedingHorizonReport {
  RecedingHorizonOptions options;      // the window and update period of the run
  int windows = 0;                     // windows solved
  std::size_t largest_window_bytes = 0;  // the largest window's stored dense outputs
  std::size_t peak_bytes = 0;          // the most held at once (the window in use and the next)
  SolveStats grde;                     // the windows' GRDE solves, summed (memory_bytes: the largest)
  double divergence_bound = NAN;       // the last divergence bound of the run (see simulate_receding_horizon)
};

// The state-feedback closed loop (simulation.hpp) under the receding-horizon law from q0 at t0 to
// tf (> t0; any length: the mission), the law kappa B_e' Z_j of window j on [t_j, t_{j+1}). The
// loop is integrated window by window, restarting at each t_j (the gain jumps there), and the
// windows are solved as it goes: at most two are held at once. The output grid restarts at each
// t_j (an update period that is a multiple of the output dt gives one regular grid). The
// divergence bound (simulation.hpp) takes the scale of the mission so far: max(1, |q_e(t0)|,
// max |q_d| over the windows used up to t). The series grow with tf / dt: choose dt for the
// mission. q_d in the results is the windows' chained desired trajectory. report (optional) says
// what was solved. Errors as simulate_state_feedback and RecedingHorizon::window.
SimulationResult simulate_receding_horizon(const RecedingHorizon& horizon, const Disturbance& disturbance,
                                           const Vec& q0, double tf, const SimulationOptions& options = {},
                                           const Model* plant = nullptr, const Signal& kappa = Signal(1.0),
                                           RecedingHorizonReport* report = nullptr);

// The largest gamma* (eq. 14) over the windows used on [t0, tf): the gamma a receding-horizon
// run certifies (each window is a game of its own with its terminal weight).
struct WindowGammaStar {
  double gamma_star = NAN;  // the largest window's gamma*
  int window = -1;          // the window where it occurs
  double t_start = NAN;     // its t_j (s)
  int windows = 0;          // windows evaluated
  bool converged = true;    // every window's bisection converged
  GammaStarResult result;   // that window's search
};
// Each window's gamma* (gamma_star, analysis.hpp, with the horizon's solver) from t0 to the last
// window that starts before tf, and the largest. The horizon's gamma is used only by the
// stationary terminal weight (the ARE at the design's gamma; the search keeps it fixed).
WindowGammaStar receding_horizon_gamma_star(const RecedingHorizon& horizon, double tf,
                                            const GammaStarOptions& options = {});

}  // namespace hinf
