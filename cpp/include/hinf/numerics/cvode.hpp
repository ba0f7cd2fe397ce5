// RAII wrapper of SUNDIALS CVODE (6.4) for dy/dt = rhs(t, y), y in R^dim.
//
// BDF uses Newton iteration with a dense direct linear solver (and the user Jacobian when one
// is given); Adams uses fixed-point iteration. Exceptions thrown by rhs or jacobian are kept
// and rethrown after CVODE returns; CVODE's own failures become SolverError carrying the
// flag name and the time. CVODE integrates backward when the stop time is below t0.
// max_steps bounds the steps over the solver's whole life, across reset() and advance() calls
// (CVODE itself counts per call and per re-initialization).
#pragma once

#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "hinf/numerics/dense_piece.hpp"
#include "hinf/numerics/solver_options.hpp"

namespace hinf {

// A structured solver of BDF's Newton systems (I - gamma J) x = b, used instead of a dense
// Jacobian and LU factorization (the Riccati equations: Lyapunov equations in O(n^3)).
class NewtonSystem {
 public:
  virtual ~NewtonSystem() = default;
  // Makes the Jacobian at (t, y) the current one.
  virtual void refresh(double t, const double* y) = 0;
  // x = (I - gamma J)^-1 b with the current Jacobian (x and b may alias); false when the
  // system is singular (the step is then retried with another step size).
  virtual bool solve(double gamma, const double* b, double* x) = 0;
};

class Cvode {
 public:
  using Rhs = std::function<void(double t, const double* y, double* ydot)>;
  // J = d rhs / d y, dim x dim, column-major; f = rhs(t, y) is given for free.
  using Jacobian = std::function<void(double t, const double* y, const double* f, double* J)>;

  // BDF solves its Newton systems with `newton` when given (it must outlive the solver; its
  // Jacobian is refreshed at the predicted state every kNewtonRefreshSteps steps and after a
  // Newton convergence failure, CVODE's own rules for dense Jacobians), else with the dense
  // `jacobian` (or difference quotients when that is empty) and LU.
  Cvode(int dim, Method method, double rtol, double atol, long max_steps, Rhs rhs,
        Jacobian jacobian = nullptr, NewtonSystem* newton = nullptr);
  ~Cvode();
  Cvode(const Cvode&) = delete;
  Cvode& operator=(const Cvode&) = delete;

  // (Re)starts at (t0, y0); the solver never steps past t_stop.
  void reset(double t0, const double* y0, double t_stop);
  // Takes one internal step toward t_stop; returns the new time and stores y there.
  double step(double* y);
  // Integrates to tout (between the current time and t_stop), interpolating; returns tout.
  double advance(double tout, double* y);
  // The interpolating polynomial of the last step (CVODE's Nordsieck history, the method's own
  // order) as a piece from the step's start to its end; valid until the next call.
  const DensePiece& last_step_piece();

  // Counts over the solver's life (all resets).
  long num_steps() const;
  long num_rhs_evals() const;
  long num_jac_evals() const;  // dense Jacobians, or refreshes of the Newton system
  long num_error_test_failures() const;

  static constexpr long kNewtonRefreshSteps = 20;

 private:
  void release();
  void check(int flag, const char* call, double t);
  void rethrow_pending();
  long counter(int (*get)(void*, long*)) const;
  // Steps left in the max_steps budget; a SolverError when there are none.
  long remaining_steps();

  int dim_;
  long max_steps_;
  Method method_;
  std::string method_name_;
  Rhs rhs_;
  Jacobian jacobian_;
  NewtonSystem* newton_ = nullptr;
  bool newton_current_ = false;  // a Jacobian has been set up since the last reset
  long newton_step_ = 0, newton_convfails_ = 0, newton_refreshes_ = 0;
  void* context_ = nullptr;  // SUNContext
  void* mem_ = nullptr;      // CVODE memory
  void* y_ = nullptr;        // N_Vector
  void* dky_ = nullptr;      // N_Vector scratch for CVodeGetDky
  void* matrix_ = nullptr;   // SUNMatrix (BDF)
  void* linsol_ = nullptr;   // SUNLinearSolver (BDF)
  void* nonlin_ = nullptr;   // SUNNonlinearSolver (Adams)
  bool initialized_ = false;
  double t_stop_ = 0.0;
  double t_step_start_ = 0.0, t_current_ = 0.0;  // the last step, for last_step_piece()
  std::exception_ptr pending_;
  std::string last_message_;
  // Counters of the integrations before the last re-initialization (CVODE restarts its own).
  long steps_before_ = 0, rhs_evals_before_ = 0, jac_evals_before_ = 0, error_test_failures_before_ = 0;
  std::vector<double> taylor_, piece_coeffs_;
  std::vector<double> y_step_start_;  // y at t_step_start_, exactly as the step began
  long steps_since_restart_ = 0;  // steps since reset(): 1 while the last step is the first
  DensePiece piece_;

  friend struct CvodeCallbacks;
};

}  // namespace hinf
