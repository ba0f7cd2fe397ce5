#include "hinf/numerics/cvode.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "hinf/core/errors.hpp"

namespace hinf {

struct CvodeCallbacks {
  static int rhs(realtype t, N_Vector y, N_Vector ydot, void* user_data) {
    auto* self = static_cast<Cvode*>(user_data);
    try {
      self->rhs_(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
      const double* f = N_VGetArrayPointer(ydot);
      for (int i = 0; i < self->dim_; ++i)
        if (!std::isfinite(f[i])) return 1;  // recoverable: CVODE retries with a smaller step
      return 0;
    } catch (...) {
      self->pending_ = std::current_exception();
      return -1;
    }
  }

  static int jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user_data,
                      N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Cvode*>(user_data);
    try {
      self->jacobian_(t, N_VGetArrayPointer(y), N_VGetArrayPointer(fy), SUNDenseMatrix_Data(J));
      return 0;
    } catch (...) {
      self->pending_ = std::current_exception();
      return -1;
    }
  }

  // The matrix-embedded linear solver around a NewtonSystem: CVODE (6.4) never calls its setup
  // and passes no matrix, so the solve refreshes the Jacobian itself, with CVODE's rules.
  static SUNLinearSolver_Type newton_type(SUNLinearSolver) { return SUNLINEARSOLVER_MATRIX_EMBEDDED; }

  static int newton_solve(SUNLinearSolver LS, SUNMatrix, N_Vector x, N_Vector b, realtype) {
    auto* self = static_cast<Cvode*>(LS->content);
    try {
      realtype t = 0.0, gamma = 0.0, rl1 = 0.0;
      N_Vector ypred = nullptr, yn = nullptr, fn = nullptr, zn1 = nullptr;
      void* user_data = nullptr;
      CVodeGetNonlinearSystemData(self->mem_, &t, &ypred, &yn, &fn, &gamma, &rl1, &zn1, &user_data);
      long steps = 0, convfails = 0;
      CVodeGetNumSteps(self->mem_, &steps);
      CVodeGetNumNonlinSolvConvFails(self->mem_, &convfails);
      if (!self->newton_current_ || steps >= self->newton_step_ + Cvode::kNewtonRefreshSteps ||
          convfails > self->newton_convfails_) {
        self->newton_->refresh(t, N_VGetArrayPointer(ypred));
        self->newton_current_ = true;
        self->newton_step_ = steps;
        self->newton_convfails_ = convfails;
        ++self->newton_refreshes_;
      }
      const bool ok = self->newton_->solve(gamma, N_VGetArrayPointer(b), N_VGetArrayPointer(x));
      return ok ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_REC;
    } catch (...) {
      self->pending_ = std::current_exception();
      return SUNLS_PACKAGE_FAIL_UNREC;
    }
  }

  static void error_handler(int, const char* module, const char* function, char* msg,
                            void* user_data) {
    auto* self = static_cast<Cvode*>(user_data);
    self->last_message_ = str_cat(module, "/", function, ": ", msg);
  }
};

namespace {

std::string flag_name(long flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string result = name != nullptr ? name : "UNKNOWN";
  std::free(name);
  return result;
}

}  // namespace

Cvode::Cvode(int dim, Method method, double rtol, double atol, long max_steps, Rhs rhs,
             Jacobian jacobian, NewtonSystem* newton)
    : dim_(dim), max_steps_(max_steps), method_(method), method_name_(to_string(method)), rhs_(std::move(rhs)),
      jacobian_(std::move(jacobian)), newton_(method == Method::BDF ? newton : nullptr) {
  if (method != Method::BDF && method != Method::Adams)
    throw InputError("Cvode supports the methods \"bdf\" and \"adams\"");
  SUNContext ctx = nullptr;
  if (SUNContext_Create(nullptr, &ctx) != 0) throw SolverError("SUNContext_Create failed", 0.0, "");
  context_ = ctx;
  y_ = N_VNew_Serial(dim, ctx);
  dky_ = N_VNew_Serial(dim, ctx);
  mem_ = CVodeCreate(method == Method::BDF ? CV_BDF : CV_ADAMS, ctx);
  if (y_ == nullptr || dky_ == nullptr || mem_ == nullptr) {
    release();
    throw SolverError("CVODE: out of memory creating the solver", 0.0, "CV_MEM_FAIL");
  }
  N_VConst(0.0, static_cast<N_Vector>(y_));
  try {
    check(CVodeInit(mem_, CvodeCallbacks::rhs, 0.0, static_cast<N_Vector>(y_)), "CVodeInit", 0.0);
    check(CVodeSetErrHandlerFn(mem_, CvodeCallbacks::error_handler, this), "CVodeSetErrHandlerFn", 0.0);
    check(CVodeSetUserData(mem_, this), "CVodeSetUserData", 0.0);
    check(CVodeSStolerances(mem_, rtol, atol), "CVodeSStolerances", 0.0);
    check(CVodeSetMaxNumSteps(mem_, max_steps), "CVodeSetMaxNumSteps", 0.0);
    if (method == Method::BDF && newton_ != nullptr) {
      SUNLinearSolver ls = SUNLinSolNewEmpty(ctx);
      if (ls == nullptr) throw SolverError("CVODE: out of memory creating the linear solver", 0.0, "CV_MEM_FAIL");
      ls->content = this;
      ls->ops->gettype = CvodeCallbacks::newton_type;
      ls->ops->solve = CvodeCallbacks::newton_solve;
      linsol_ = ls;
      check(CVodeSetLinearSolver(mem_, ls, nullptr), "CVodeSetLinearSolver", 0.0);
    } else if (method == Method::BDF) {
      matrix_ = SUNDenseMatrix(dim, dim, ctx);
      linsol_ = SUNLinSol_Dense(static_cast<N_Vector>(y_), static_cast<SUNMatrix>(matrix_), ctx);
      check(CVodeSetLinearSolver(mem_, static_cast<SUNLinearSolver>(linsol_),
                                 static_cast<SUNMatrix>(matrix_)),
            "CVodeSetLinearSolver", 0.0);
      if (jacobian_) check(CVodeSetJacFn(mem_, CvodeCallbacks::jacobian), "CVodeSetJacFn", 0.0);
    } else {
      nonlin_ = SUNNonlinSol_FixedPoint(static_cast<N_Vector>(y_), 0, ctx);
      check(CVodeSetNonlinearSolver(mem_, static_cast<SUNNonlinearSolver>(nonlin_)),
            "CVodeSetNonlinearSolver", 0.0);
    }
  } catch (...) {
    release();
    throw;
  }
  taylor_.assign(static_cast<std::size_t>(13 * dim), 0.0);
  piece_coeffs_.assign(static_cast<std::size_t>(13 * dim), 0.0);
}

Cvode::~Cvode() { release(); }

void Cvode::release() {
  if (mem_ != nullptr) CVodeFree(&mem_);
  if (nonlin_ != nullptr) SUNNonlinSolFree(static_cast<SUNNonlinearSolver>(nonlin_));
  if (linsol_ != nullptr) {
    if (newton_ != nullptr) SUNLinSolFreeEmpty(static_cast<SUNLinearSolver>(linsol_));
    else SUNLinSolFree(static_cast<SUNLinearSolver>(linsol_));
  }
  if (matrix_ != nullptr) SUNMatDestroy(static_cast<SUNMatrix>(matrix_));
  if (dky_ != nullptr) N_VDestroy(static_cast<N_Vector>(dky_));
  if (y_ != nullptr) N_VDestroy(static_cast<N_Vector>(y_));
  if (context_ != nullptr) {
    SUNContext ctx = static_cast<SUNContext>(context_);
    SUNContext_Free(&ctx);
  }
  mem_ = nonlin_ = linsol_ = matrix_ = dky_ = y_ = context_ = nullptr;
}

void Cvode::check(int flag, const char* call, double t) {
  rethrow_pending();
  if (flag >= 0) return;
  const std::string name = flag_name(flag);
  throw SolverError(str_cat("CVODE ", method_name_, ": ", call, " failed at t = ", t, " with ",
                            name, last_message_.empty() ? "" : ": ", last_message_),
                    t, name);
}

void Cvode::rethrow_pending() {
  if (pending_) {
    std::exception_ptr error = pending_;
    pending_ = nullptr;
    std::rethrow_exception(error);
  }
}

void Cvode::reset(double t0, const double* y0, double t_stop) {
  if (initialized_) {
    steps_before_ = num_steps();
    rhs_evals_before_ = num_rhs_evals();
    jac_evals_before_ = num_jac_evals();
    error_test_failures_before_ = num_error_test_failures();
  }
  double* y = N_VGetArrayPointer(static_cast<N_Vector>(y_));
  for (int i = 0; i < dim_; ++i) y[i] = y0[i];
  check(CVodeReInit(mem_, t0, static_cast<N_Vector>(y_)), "CVodeReInit", t0);
  // The stop time is cleared once reached and after a re-init: set it every time.
  check(CVodeSetStopTime(mem_, t_stop), "CVodeSetStopTime", t0);
  t_stop_ = t_stop;
  t_current_ = t_step_start_ = t0;
  steps_since_restart_ = 0;
  newton_current_ = false;
  last_message_.clear();
  initialized_ = true;
}

long Cvode::remaining_steps() {
  const long left = max_steps_ - num_steps();
  if (left <= 0) {
    double t = 0.0;
    CVodeGetCurrentTime(mem_, &t);
    throw SolverError(str_cat("CVODE ", method_name_, ": more than max_steps = ", max_steps_,
                              " steps (stopped at t = ", t, "; CV_TOO_MUCH_WORK): the step size collapsed or"
                              " the problem needs a larger max_steps"),
                      t, "CV_TOO_MUCH_WORK");
  }
  return left;
}

double Cvode::step(double* y_out) {
  if (!initialized_) throw InputError("Cvode::step before reset");
  remaining_steps();
  double t = 0.0;
  const double* y_before = N_VGetArrayPointer(static_cast<N_Vector>(y_));
  y_step_start_.assign(y_before, y_before + dim_);
  const int flag = CVode(mem_, t_stop_, static_cast<N_Vector>(y_), &t, CV_ONE_STEP);
  check(flag, "CVode", t);
  ++steps_since_restart_;
  t_step_start_ = t_current_;
  t_current_ = t;
  const double* y = N_VGetArrayPointer(static_cast<N_Vector>(y_));
  for (int i = 0; i < dim_; ++i) y_out[i] = y[i];
  return t;
}

double Cvode::advance(double tout, double* y_out) {
  if (!initialized_) throw InputError("Cvode::advance before reset");
  // CVODE's own limit counts per call: give this call what is left of the whole budget.
  check(CVodeSetMaxNumSteps(mem_, remaining_steps()), "CVodeSetMaxNumSteps", tout);
  double t = 0.0;
  const int flag = CVode(mem_, tout, static_cast<N_Vector>(y_), &t, CV_NORMAL);
  check(flag, "CVode", t);
  const double* y = N_VGetArrayPointer(static_cast<N_Vector>(y_));
  for (int i = 0; i < dim_; ++i) y_out[i] = y[i];
  return t;
}

const DensePiece& Cvode::last_step_piece() {
  int order = 0;
  check(CVodeGetLastOrder(mem_, &order), "CVodeGetLastOrder", 0.0);
  // The step from the previous step's end to the current time, both exactly as CVODE has them.
  const double t_now = t_current_, h_last = t_current_ - t_step_start_;
  // Taylor form at the step's end t_n: y(t_n + s) = sum_k b_k (s / h)^k with b_k = y^(k)(t_n) h^k / k!
  // (h signed). With t = t_n - h + theta h, s / h = theta - 1, so the coefficients in theta are
  // d_j = sum_{k >= j} C(k, j) (-1)^(k - j) b_k.
  double scale = 1.0, factorial = 1.0;
  for (int k = 0; k <= order; ++k) {
    if (k > 0) {
      factorial *= k;
      scale *= h_last;
    }
    check(CVodeGetDky(mem_, t_now, k, static_cast<N_Vector>(dky_)), "CVodeGetDky", t_now);
    const double* d = N_VGetArrayPointer(static_cast<N_Vector>(dky_));
    for (int i = 0; i < dim_; ++i) taylor_[static_cast<std::size_t>(k * dim_ + i)] = d[i] * scale / factorial;
  }
  std::fill(piece_coeffs_.begin(), piece_coeffs_.begin() + static_cast<long>((order + 1) * dim_), 0.0);
  for (int k = 0; k <= order; ++k) {
    double binomial = 1.0;  // C(k, j), from j = 0
    for (int j = 0; j <= k; ++j) {
      const double factor = ((k - j) % 2 == 0 ? 1.0 : -1.0) * binomial;
      for (int i = 0; i < dim_; ++i)
        piece_coeffs_[static_cast<std::size_t>(j * dim_ + i)] += factor * taylor_[static_cast<std::size_t>(k * dim_ + i)];
      binomial = binomial * (k - j) / (j + 1);
    }
  }
  // CVODE's interpolant is the current step's polynomial: it ends at y(t_n) but passes the
  // step's start only to within the local error (0.26 off Z(tf) = Qf = 1.4e6 was seen). On the
  // first step after a (re)start the constant term is set to the initial value, so that the
  // solution at t0 is the initial value exactly (Z(tf) = Qf, Sigma(t0) = Sigma0); the piece
  // moves by that local error and its slope is kept (the first step can be 1e-11 long: a
  // correction of the slope would divide round-off by it).
  if (steps_since_restart_ == 1)
    for (int i = 0; i < dim_; ++i) piece_coeffs_[static_cast<std::size_t>(i)] = y_step_start_[static_cast<std::size_t>(i)];
  piece_ = DensePiece{t_step_start_, t_now, order, dim_, piece_coeffs_.data()};
  return piece_;
}

long Cvode::counter(int (*get)(void*, long*)) const {
  long value = 0;
  get(mem_, &value);
  return value;
}

long Cvode::num_steps() const { return steps_before_ + counter(CVodeGetNumSteps); }
long Cvode::num_rhs_evals() const { return rhs_evals_before_ + counter(CVodeGetNumRhsEvals); }
long Cvode::num_jac_evals() const {
  if (newton_ != nullptr) return newton_refreshes_;
  return jac_evals_before_ + (method_ == Method::BDF ? counter(CVodeGetNumJacEvals) : 0);
}
long Cvode::num_error_test_failures() const {
  return error_test_failures_before_ + counter(CVodeGetNumErrTestFails);
}

}  // namespace hinf
