// Tracking controllers: u = control(t, q) for the actual state q.
#pragma once

#include <memory>
#include <string>

#include "hinf/riccati.hpp"
#include "hinf/signal.hpp"

namespace hinf {

class Controller {
 public:
  virtual ~Controller() = default;
  virtual std::string name() const = 0;
  virtual int m() const = 0;
  // u (m) at time t for the actual state q (n). Controllers may keep lookup cursors: use one
  // controller object per thread.
  virtual void control(double t, const ConstVecRef& q, VecRef u) = 0;
  // du/dq (m x n), for implicit integrators. The default uses central differences;
  // analytic overrides are preferred.
  virtual void control_jacobian(double t, const ConstVecRef& q, MatRef dudq);
};

using ControllerPtr = std::shared_ptr<Controller>;

// The H-infinity state-feedback tracking law, paper eqs. (17)/(18):
//     u = u_d(t) - kappa(t) B(t)' Z(t) (q - q_d(t)).
// kappa = 1 is the saddle-point (optimal) law (15); kappa >= 1/2 keeps the Lyapunov proof
// of local exponential stability (eq. 23). kappa must stay > 0.
class HinfStateFeedback final : public Controller {
 public:
  HinfStateFeedback(RiccatiSolutionPtr solution, Signal kappa = Signal(1.0));
  std::string name() const override;
  int m() const override { return solution_->m(); }
  void control(double t, const ConstVecRef& q, VecRef u) override;
  void control_jacobian(double t, const ConstVecRef& q, MatRef dudq) override;
  const RiccatiSolution& solution() const { return *solution_; }
  const Signal& kappa() const { return kappa_; }

 private:
  double checked_kappa(double t) const;

  RiccatiSolutionPtr solution_;
  Signal kappa_;
  std::size_t q_cursor_ = 0, k_cursor_ = 0;
  Vec q_e_;
  Mat K_;
};

}  // namespace hinf
