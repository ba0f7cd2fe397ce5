// One way to step for every ODE solve of hinf_cpp: the method chosen in SolverOptions
// (Dormand-Prince 5(4), CVODE BDF or Adams, or Auto: Dormand-Prince until the problem turns
// out stiff, then BDF) integrates dy/dt = rhs(t, y) and hands each accepted step to the caller
// as a DensePiece of its own dense output (dense_piece.hpp).
#pragma once

#include <functional>
#include <type_traits>

#include "hinf/core/interrupt.hpp"
#include "hinf/numerics/cvode.hpp"
#include "hinf/numerics/dopri5.hpp"
#include "hinf/numerics/solver_options.hpp"

namespace hinf {

namespace detail {

template <class Rhs, class OnStep>
StepStats integrate_cvode(Method method, const SolverOptions& options, int dim, Rhs& rhs,
                          const Cvode::Jacobian& jacobian, NewtonSystem* newton, double t0, double t1, double* y,
                          OnStep& on_step) {
  Cvode solver(dim, method, options.rtol, options.atol, options.max_steps,
               [&rhs](double t, const double* x, double* dx) { rhs(t, x, dx); },
               method == Method::BDF ? jacobian : Cvode::Jacobian(), newton);
  solver.reset(t0, y, t1);
  const double direction = t1 > t0 ? 1.0 : -1.0;
  for (double t = t0; (t1 - t) * direction > 0.0;) {
    t = solver.step(y);
    throw_if_interrupted();  // Ctrl-C ends every integration within one step
    if (on_step(solver.last_step_piece()) == StepAction::Stop) break;
  }
  StepStats stats;
  stats.steps = solver.num_steps();
  stats.rejected = solver.num_error_test_failures();
  stats.rhs_evals = solver.num_rhs_evals();
  stats.jac_evals = solver.num_jac_evals();
  stats.method = to_string(method);
  return stats;
}

}  // namespace detail

// Integrates from t0 to t1 (backward when t1 < t0) starting from y, with options.method,
// options.rtol, options.atol and options.max_steps (steps over the whole integration).
// After every accepted step on_step(piece) is called with y holding the state at the step's
// end; it returns StepAction::Stop to end the integration there, or StepAction::Continue.
// BDF solves its Newton systems with `newton` when given, else with the dense `jacobian`
// (d rhs / d y, column-major; may be empty: difference quotients). Throws SolverError.
// The returned stats say which method integrated (for Auto: where it switched).
template <class Rhs, class OnStep>
StepStats integrate(const SolverOptions& options, int dim, Rhs&& rhs, const Cvode::Jacobian& jacobian,
                    double t0, double t1, double* y, OnStep&& on_step, NewtonSystem* newton = nullptr) {
  if (options.method == Method::BDF || options.method == Method::Adams)
    return detail::integrate_cvode(options.method, options, dim, rhs, jacobian, newton, t0, t1, y, on_step);
  Dopri5 stepper(dim, options.rtol, options.atol, options.max_steps);
  bool stopped = false, stiff = false;
  double t_switch = t0;
  stepper.integrate(rhs, t0, t1, y, [&](const DensePiece& piece) {
    if (on_step(piece) == StepAction::Stop) {
      stopped = true;
      return StepAction::Stop;
    }
    t_switch = piece.t_end;
    // Auto: steps limited by stability cost more than an implicit method's.
    if (options.method == Method::Auto && stepper.stiff() && t_switch != t1) {
      stiff = true;
      return StepAction::Stop;
    }
    return StepAction::Continue;
  });
  StepStats stats = stepper.stats();
  stats.method = to_string(Method::ERK);
  if (stopped || !stiff) return stats;
  SolverOptions rest = options;
  rest.max_steps = std::max(1L, options.max_steps - stats.steps - stats.rejected);
  const StepStats implicit =
      detail::integrate_cvode(Method::BDF, rest, dim, rhs, jacobian, newton, t_switch, t1, y, on_step);
  stats += implicit;
  stats.method = str_cat("erk, then bdf from t = ", t_switch, " (stiffness detected)");
  return stats;
}

}  // namespace hinf
