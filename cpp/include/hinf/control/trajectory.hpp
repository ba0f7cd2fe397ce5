// The desired (feasible) trajectory of paper eq. (8):
//     dq_d/dt = f(t, q_d) + G(t, q_d) u_d(t),   q_d(t0) = q_d0,
// integrated forward once with Dormand-Prince 5(4) at tight tolerances (restarting at the points
// of table inputs, where u_d is not smooth) and kept as its dense output, so q_d(t), u_d(t) and
// the linearization along it (paper eq. 10, model.hpp)
//     A_e(t) = d/dq [f + G u_d](t, q_d(t)),  B_e(t) = G(t, q_d(t)),  D_e(t) = D(t, q_d(t))
// are available at any t in [t0, tf]. A Trajectory is immutable once made: its const functions
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
  // A trajectory from a dense output integrated before (by the constructor above; e.g. read
  // back from a pickle): the same input checks, and `dense` must have n components and cover
  // [t0, tf].
  Trajectory(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, double tf, PiecewisePolynomial dense,
             StepStats stats);

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

 private:
  // The checks of the constructors' arguments (not of the dense output).
  void check_arguments() const;
  void check_declarations() const;
  // The points of u_d's tables inside (t0, tf), and tf: where the integration restarts.
  std::vector<double> input_breakpoints(double t0, double tf) const;

  ModelPtr model_;
  Vec q_d0_;
  VectorSignal u_d_;
  double t0_, tf_;
  PiecewisePolynomial dense_;
  StepStats stats_;
};

using TrajectoryPtr = std::shared_ptr<const Trajectory>;

}  // namespace hinf
