// Tracking controllers: u = control(t, q) for the actual state q.
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "hinf/control/riccati.hpp"
#include "hinf/core/angles.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf {

// A tracking law u = control(t, q) of the actual state q; the closed loops call it at every
// stage of the integrator.
class Controller {
 public:
  virtual ~Controller() = default;
  // The law's name ("hinf", "lqr", "cascade", ...), for results and messages.
  virtual std::string name() const = 0;
  // The state size: control() takes q of n() numbers. A controller implemented in Python may
  // leave n() out (it reads q as a NumPy array of whatever length it is given): it then
  // reports 0, and callers check q against their model instead.
  virtual int n() const = 0;
  // The number of inputs: control() writes u of m() numbers.
  virtual int m() const = 0;
  // u (m) at time t for the actual state q (n). Controllers may keep lookup cursors: use one
  // controller object per thread.
  virtual void control(double t, const ConstVecRef& q, VecRef u) = 0;
  // du/dq (m x n), for implicit integrators. The default uses central differences
  // (numerics/numdiff.hpp); analytic overrides are preferred.
  virtual void control_jacobian(double t, const ConstVecRef& q, MatRef dudq);

 protected:
  // The first check of every control(): q has n() numbers and u has m(), else InputError (a
  // C++ caller can hand over anything; two comparisons are free next to the law).
  void check_control_sizes(const ConstVecRef& q, Eigen::Index u_size) const {
    if (q.size() != n() || u_size != m())
      throw InputError(str_cat("the ", name(), " controller takes q of ", n(), " numbers and gives u of ", m(),
                               ", got q of ", q.size(), " and u of ", u_size));
  }
};

using ControllerPtr = std::shared_ptr<Controller>;

// The H-infinity state-feedback tracking law, paper eqs. (17)/(18):
//     u = u_d(t) - kappa(t) B_e(t)' Z(t) (q - q_d(t)),  B_e(t) = G(t, q_d(t)),
// with the heading component of q - q_d wrapped to (-pi, pi] (angles.hpp).
// kappa = 1 is the saddle-point (optimal) law (15); kappa >= 1/2 keeps the Lyapunov proof
// of local exponential stability (eq. 23). kappa must stay > 0.
class HinfStateFeedback final : public Controller {
 public:
  // The law of the design `solution` (Z of the GRDE along its trajectory) with the gain
  // scaling kappa(t) (checked > 0 where the law evaluates it). InputError without a solution.
  HinfStateFeedback(RiccatiSolutionPtr solution, Signal kappa = Signal(1.0));
  // "hinf", or "lqr" for a design at gamma = inf.
  std::string name() const override;
  int n() const override { return solution_->n(); }
  int m() const override { return solution_->m(); }
  void control(double t, const ConstVecRef& q, VecRef u) override;
  void control_jacobian(double t, const ConstVecRef& q, MatRef dudq) override;
  // The design Z and the gain scaling kappa(t) of the law.
  const RiccatiSolution& solution() const { return *solution_; }
  const Signal& kappa() const { return kappa_; }
  // kappa(t); an InputError if it is not > 0.
  double checked_kappa(double t) const;

 private:
  // q_d, u_d, K = B'Z and kappa at t, kept until t changes.
  void evaluate_at(double t);

  RiccatiSolutionPtr solution_;
  Signal kappa_;
  int heading_;
  std::size_t q_cursor_ = 0, k_cursor_ = 0;
  double evaluated_at_ = NAN, kappa_now_ = 0.0;
  Vec q_d_, q_e_, u_d_;
  Mat K_;
};

}  // namespace hinf
