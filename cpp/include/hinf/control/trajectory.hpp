// The desired (feasible) trajectory of paper eq. (8):
//     dq_d/dt = f(t, q_d) + G(t, q_d) u_d(t),   q_d(t0) = q_d0,
// integrated forward once with Dormand-Prince 5(4) at tight tolerances (restarting at the points
// of table inputs, where u_d is not smooth) and kept as its dense output, so q_d(t), u_d(t) and
// the linearization along it (paper eq. 10, model.hpp)
//     A_e(t) = d/dq [f + G u_d](t, q_d(t)),  B_e(t) = G(t, q_d(t)),  D_e(t) = D(t, q_d(t))
// are available at any t in [t0, tf]. A desired trajectory may also be given as states and inputs
// (a plan's nodes): each interval between nodes is then integrated from its node, so that an
// open-loop-unstable vehicle's growth acts over one interval only (second constructor).
// A Trajectory is immutable once made: its const functions
// keep no state (lookups take caller-owned cursors), so one trajectory may be read from several
// threads at once (run_scenarios shares one between runs, study.hpp).
#pragma once

#include <memory>
#include <vector>

#include "hinf/models/model.hpp"
#include "hinf/numerics/dopri5.hpp"
#include "hinf/numerics/piecewise_polynomial.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf {

// Tolerances of the desired trajectory's integration (Dormand-Prince 5(4)). Tight by default:
// the trajectory is integrated once, and every design along it inherits its error.
struct TrajectoryOptions {
  double rtol = 1e-10;       // relative tolerance, > 0
  double atol = 1e-12;       // absolute tolerance, > 0
  long max_steps = 2000000;  // step attempts over [t0, tf], > 0; exceeding it is a SolverError
};

// The desired trajectory q_d(t), u_d(t) on [t0, tf] and the linearization A_e, B_e, D_e along it.
class Trajectory {
 public:
  // Integrates eq. (8) forward from q_d(t0) = q_d0 (n numbers) with the inputs u_d (m
  // channels) over [t0, tf] (s), t0 < tf. InputError for a bad model (check_structure,
  // validate_model at (t0, q_d0)), q_d0 of another size or not finite, u_d with another number
  // of channels, a bad horizon or options; SolverError when the integration fails.
  Trajectory(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, double tf,
             const TrajectoryOptions& options = {});
  // The desired trajectory given as states and inputs: q_d(t_k) = row k of q_nodes ((N + 1) x n)
  // at the nodes t_0 < t_1 < ... < t_N (t0 = t_0, tf = t_N), and on each interval [t_k, t_{k+1}]
  // eq. (8) integrated from row k with u_d. The end of interval k misses node k + 1 by its defect
  // d_k = |q(t_{k+1}-) - q_{k+1}|_inf, and q_d jumps by d_k there: small wherever the nodes are
  // a trajectory of the model (a planner's, say), also for an open-loop-unstable vehicle, along
  // which one integration over [t0, tf] from q_d0 would drift away. InputError as the
  // constructor above, and for nodes that are not finite and increasing (N >= 1) or q_nodes of
  // another shape or not finite; SolverError when an interval's integration fails.
  Trajectory(ModelPtr model, std::vector<double> t_nodes, const RowMat& q_nodes, VectorSignal u_d,
             const TrajectoryOptions& options = {});
  // A trajectory from a dense output integrated before (by a constructor above; e.g. read back
  // from a pickle): the same input checks, and `dense` must have n components and cover
  // [t0, tf]; the nodes and defects of a trajectory given as states, if it was one.
  Trajectory(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, double tf, PiecewisePolynomial dense,
             StepStats stats, std::vector<double> node_times = {}, std::vector<double> defects = {});

  // The model integrated: the design model of everything built on this trajectory.
  const Model& model() const { return *model_; }
  const ModelPtr& model_ptr() const { return model_; }
  // The model's number of states and of inputs.
  int n() const { return model_->n(); }
  int m() const { return model_->m(); }
  // The horizon [t0, tf] (s).
  double t0() const { return t0_; }
  double tf() const { return tf_; }
  // The desired initial state q_d(t0) and the desired inputs u_d, as given.
  const Vec& q_d0() const { return q_d0_; }
  const VectorSignal& u_d_signal() const { return u_d_; }

  // The desired state q_d(t) (n) from the dense output; t outside [t0, tf] is an InputError.
  void q_d(double t, double* out, std::size_t* cursor = nullptr) const;
  Vec q_d(double t) const;
  // The desired input u_d(t) (m): the signal, at any t.
  void u_d(double t, double* out) const { u_d_.eval(t, out); }
  Vec u_d(double t) const { return u_d_(t); }
  // A_e(t) = d/dq [f + G u_d] at q_d(t), B_e(t) = G(t, q_d(t)), D_e(t) = D(t, q_d(t)).
  Mat A_e(double t) const;
  Mat B_e(double t) const;
  Mat D_e(double t) const;
  void A_e(double t, const ConstVecRef& q_d, MatRef A) const;  // into A, for the q_d(t) the caller has

  // The dense output of q_d (n components) and the counts of its integration.
  const PiecewisePolynomial& dense() const { return dense_; }
  const StepStats& stats() const { return stats_; }
  // A trajectory given as states: its nodes t_0 .. t_N (s) and the defect d_k of each interval
  // (N numbers, in the states' units); both empty for a trajectory integrated from q_d0 alone.
  const std::vector<double>& node_times() const { return node_times_; }
  const std::vector<double>& defects() const { return defects_; }
  // The largest defect (0 without nodes) and the start of its interval (NaN without nodes).
  double max_defect() const;
  double max_defect_t() const;

 private:
  // The checks of the constructors' arguments (not of the dense output).
  void check_arguments() const;
  void check_declarations() const;
  // The points of u_d's tables inside (t0, tf), and tf: where the integration restarts.
  std::vector<double> input_breakpoints(double t0, double tf) const;
  // Eq. (8) integrated from y at a to b (restarting at u_d's table points), appending to dense_.
  void integrate(double a, double b, Vec& y, const TrajectoryOptions& options, StepStats& stats);

  ModelPtr model_;
  Vec q_d0_;
  VectorSignal u_d_;
  double t0_, tf_;
  PiecewisePolynomial dense_;
  StepStats stats_;
  std::vector<double> node_times_, defects_;
};

using TrajectoryPtr = std::shared_ptr<const Trajectory>;

}  // namespace hinf
