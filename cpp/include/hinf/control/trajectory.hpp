// The desired (feasible) trajectory of paper eq. (8):
//     dq_d/dt = f(t, q_d) + G(t, q_d) u_d(t),   q_d(t0) = q_d0,
// integrated forward once with Dormand-Prince 5(4) at tight tolerances (restarting at the points
// of table inputs, where u_d is not smooth) and kept as its dense output, so q_d(t), u_d(t) and the linearization along it (paper eq. 10, model.hpp)
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

struct TrajectoryOptions {
  double rtol = 1e-10;
  double atol = 1e-12;
  long max_steps = 2000000;
};

class Trajectory {
 public:
  Trajectory(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, double tf,
             const TrajectoryOptions& options = {});
  // A trajectory from a dense output integrated before (by the constructor above; e.g. read
  // back from a pickle): the same input checks, and `dense` must have n components and cover
  // [t0, tf].
  Trajectory(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, double tf, PiecewisePolynomial dense,
             StepStats stats);

  const Model& model() const { return *model_; }
  const ModelPtr& model_ptr() const { return model_; }
  int n() const { return model_->n(); }
  int m() const { return model_->m(); }
  double t0() const { return t0_; }
  double tf() const { return tf_; }
  const Vec& q_d0() const { return q_d0_; }
  const VectorSignal& u_d_signal() const { return u_d_; }

  void q_d(double t, double* out, std::size_t* cursor = nullptr) const;
  Vec q_d(double t) const;
  void u_d(double t, double* out) const { u_d_.eval(t, out); }
  Vec u_d(double t) const { return u_d_(t); }
  // A_e(t) = d/dq [f + G u_d] at q_d(t), B_e(t) = G(t, q_d(t)), D_e(t) = D(t, q_d(t)).
  Mat A_e(double t) const;
  Mat B_e(double t) const;
  Mat D_e(double t) const;
  // A_e(t) into A for the q_d = q_d(t) the caller already has.
  void A_e(double t, const ConstVecRef& q_d, MatRef A) const;

  const PiecewisePolynomial& dense() const { return dense_; }
  const StepStats& stats() const { return stats_; }

 private:
  // The checks of the constructors' arguments (not of the dense output).
  void check_arguments() const;
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
