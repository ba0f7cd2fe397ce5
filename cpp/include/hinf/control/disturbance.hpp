// The disturbance w applied to the plant (all nw channels of the model):
//     w(t, q) = signals(t) [+ w*(t, q)],
// where w* = gamma^-2 D_e(t)' Z(t) (q - q_d(t)) is the worst-case disturbance of paper eq. (16)
// for a design Z at gamma (scenario key [disturbance] worst_case = true): the adversary of the
// game, feeding back the true error. Z may also be a law's closed-loop P at gamma
// (solve_law_riccati): then w* is that law's own worst case (for the H-infinity law at its gamma
// P = Z).
#pragma once

#include <memory>

#include "hinf/control/riccati.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf {

// The disturbance w(t, q) applied to a closed loop: signals, plus the worst-case disturbance of
// a design when one is given.
class Disturbance {
 public:
  Disturbance() = default;
  // The signals alone (implicit: a VectorSignal is a disturbance).
  Disturbance(VectorSignal signals);
  // signals + the worst-case disturbance of `design` (a GRDE solution Z or a law's P, at a finite
  // gamma).
  Disturbance(VectorSignal signals, std::shared_ptr<const SymmetricSolution> design);

  // The number of channels: the model's nw.
  int dim() const { return signals_.dim(); }
  // True when the worst-case disturbance of a design is added.
  bool worst_case() const { return design_ != nullptr; }
  // The design of the worst-case part (null without one); q in eval() has design()->n() numbers.
  const std::shared_ptr<const SymmetricSolution>& design() const { return design_; }
  // The signals w(t) without the worst-case part.
  const VectorSignal& signals() const { return signals_; }
  // w at time t for the actual state q (n numbers); writes dim() numbers. Safe to call from
  // several threads at once (it keeps no state between calls).
  void eval(double t, const double* q, double* w) const;

 private:
  VectorSignal signals_;
  std::shared_ptr<const SymmetricSolution> design_;
  Mat D_;  // D of the design's model, when constant
};

}  // namespace hinf
