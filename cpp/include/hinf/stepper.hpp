// One way to step for every ODE solve of hinf_cpp: the method chosen in SolverOptions
// (Dormand-Prince 5(4), CVODE BDF or CVODE Adams) integrates dy/dt = rhs(t, y) and hands each
// accepted step to the caller as a DensePiece of its own dense output (dense_piece.hpp).
#pragma once

#include <functional>
#include <type_traits>

#include "hinf/cvode.hpp"
#include "hinf/dopri5.hpp"
#include "hinf/solver_options.hpp"

namespace hinf {

// Integrates from t0 to t1 (backward when t1 < t0) starting from y, with options.method,
// options.rtol, options.atol and options.max_steps (steps over the whole integration).
// After every accepted step on_step(piece) is called with y holding the state at the step's
// end; it returns StepAction::Stop to end the integration there, or StepAction::Continue.
// jacobian (d rhs / d y, column-major; may be empty) is used by BDF. Throws SolverError.
template <class Rhs, class OnStep>
StepStats integrate(const SolverOptions& options, int dim, Rhs&& rhs, const Cvode::Jacobian& jacobian,
                    double t0, double t1, double* y, OnStep&& on_step) {
  StepStats stats;
  if (options.method == Method::ERK) {
    Dopri5 stepper(dim, options.rtol, options.atol, options.max_steps);
    stepper.integrate(rhs, t0, t1, y, [&](const DensePiece& piece) { return on_step(piece); });
    return stepper.stats();
  }
  Cvode solver(dim, options.method, options.rtol, options.atol, options.max_steps,
               [&rhs](double t, const double* x, double* dx) { rhs(t, x, dx); },
               options.method == Method::BDF ? jacobian : Cvode::Jacobian());
  solver.reset(t0, y, t1);
  const double direction = t1 > t0 ? 1.0 : -1.0;
  for (double t = t0; (t1 - t) * direction > 0.0;) {
    t = solver.step(y);
    if (on_step(solver.last_step_piece()) == StepAction::Stop) break;
  }
  stats.steps = solver.num_steps();
  stats.rejected = solver.num_error_test_failures();
  stats.rhs_evals = solver.num_rhs_evals();
  stats.jac_evals = solver.num_jac_evals();
  return stats;
}

}  // namespace hinf
