// Closed-loop simulation of the nonlinear model under a tracking controller (paper eq. 7):
//     dq/dt = f(t, q) + G(t, q) u + D(t, q) w(t),   u = controller(t, q),   q(t0) = q0,
// integrated with the chosen method; the time series are sampled on the output grid. f, G and
// D are the plant's: the design model's, or another model of the same structure (a plant with
// other parameters, for robustness studies), while the desired trajectory and the controller
// stay those of the design model.
//
// A closed loop that leaves the neighbourhood of the desired trajectory where the linearized
// design means anything stops early with status Diverged: when the tracking error |q_e|_inf
// (heading wrapped, angles.hpp) exceeds
//     divergence_bound = divergence_factor * max(1, |q_e(t0)|_inf, path scale),
// the path scale being the largest extent of the desired path on the output grid: the spread
// (max - min) of each position component, and the largest |q_d_i| of each other component but
// the heading (speeds and rates: a speed's scale is its size). On the paper's ship over 40 s
// that is the path's 40 m, so the default factor 10 stops a run 400 m or 400 m/s off, where a
// ship has physically left its path. Its time series then end at the last output time before.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "hinf/control/controller.hpp"
#include "hinf/control/disturbance.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/enum_names.hpp"
#include "hinf/numerics/signal.hpp"
#include "hinf/numerics/solver_options.hpp"

namespace hinf {

// How a closed loop is simulated (scenario keys [output] dt and [solver]).
struct SimulationOptions {
  double output_dt = 0.01;         // step of the output grid (s)
  double divergence_factor = 10.0;  // stop as diverged beyond this times the path's scale (> 1)
  SolverOptions solver;            // the integrator of the closed loop

  void validate() const;  // InputError naming the option and its admissible range
};

// t0, t0 + dt, t0 + 2 dt, ..., ending exactly at tf: the last interval may be shorter, or up
// to 1e-6 dt longer (rather than leave a sliver of an interval).
std::vector<double> output_grid(double t0, double tf, double dt);
// The number of points of output_grid(t0, tf, dt), without building it.
long output_count(double t0, double tf, double dt);
// output_count, and an InputError when the grid would not fit in memory (resources.hpp): the
// checks of output_grid without building it (Scenario::validate).
long check_output_grid(double t0, double tf, double dt);

// How a closed-loop run ended.
enum class RunStatus {
  Completed,  // integrated over the whole horizon
  Diverged,   // stopped when the tracking error exceeded the divergence bound (see above):
              // divergence_factor times the path's scale
  LostTrack   // integrated over the whole horizon, but it ended more than the scenario's
              // lost_track farther from the desired path than it started (scenario.hpp)
};
template <>
struct EnumNames<RunStatus> {
  static constexpr const char* what = "run status";
  static constexpr std::array<std::pair<RunStatus, const char*>, 3> names{
      {{RunStatus::Completed, "completed"}, {RunStatus::Diverged, "diverged"}, {RunStatus::LostTrack, "lost_track"}}};
};

// The estimator's series of an output-feedback run (paper §4), on the same output grid.
struct EstimatorSeries {
  RowMat q_hat;         // estimate of the error q_e (n)
  RowMat y;             // measurement y (p)
  Vec sigma_min_eig;    // smallest eigenvalue of the filter Riccati solution Sigma(t)
  Vec sigma_max_eig;    // largest eigenvalue of Sigma(t)
  Vec rho_sigma_z;      // spectral radius of Sigma(t) Z(t)
  double coupling_violation_t = NAN;  // first output time with rho(Sigma Z) >= gamma^2, if any
};

// Time series on the output grid, one row per time.
struct SimulationResult {
  Vec t;       // output times (s), from t0
  RowMat q;    // actual state (n)
  RowMat q_d;  // desired state (n)
  RowMat u;    // applied control (m)
  RowMat u_d;  // desired control (m)
  RowMat w;    // applied disturbance (nw), noise channels included for output feedback
  std::optional<EstimatorSeries> estimator;  // output feedback only
  RunStatus status = RunStatus::Completed;  // how the run ended
  std::string status_message;  // why the run stopped early or lost the track; empty when completed
  int heading_index = -1;      // the model's heading component (angles.hpp), -1 if none
  std::string integrator;      // how the closed loop was integrated
  SolveStats stats;            // the counts of the closed loop's integration

  // The tracking errors q - q_d, one row per output time, the heading component wrapped to
  // (-pi, pi].
  RowMat q_e() const;
};

// The path scale of divergence_bound (see above), gathered over output grids of one or more
// trajectories of the same model (the windows of a receding horizon).
class PathScale {
 public:
  explicit PathScale(const Model& model);
  // Takes in q_d on the times of `grid`.
  void add(const Trajectory& trajectory, const std::vector<double>& grid);
  // The largest spread of a position component and |q_d_i| of another but the heading so far.
  double scale() const;

 private:
  std::vector<char> is_position_;
  int heading_;
  Vec low_, high_;
};

// The divergence bound of the run from q0 along the trajectory (see above).
double divergence_bound(const Trajectory& trajectory, const Vec& q0, const std::vector<double>& grid,
                        double divergence_factor);

// InputError unless the plant has the design model's n, m, nw and heading index (nothing to
// check when they are the same object). Scenario files check more (check_plant, scenario.hpp).
void check_plant_sizes(const Model& model, const Model& plant);

// The closed loop of `plant` (null: the trajectory's model) under `controller`: the plant's f,
// G and D are integrated; the trajectory (of the design model) gives q_d and the divergence
// bound. A plant other than the design model is the model error of a robustness study.
SimulationResult simulate_state_feedback(const Trajectory& trajectory, Controller& controller,
                                         const Disturbance& disturbance, const Vec& q0,
                                         const SimulationOptions& options = {}, const Model* plant = nullptr);

}  // namespace hinf
