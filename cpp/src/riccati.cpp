#include "hinf/riccati.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hinf/checks.hpp"
#include "hinf/cvode.hpp"
#include "hinf/dopri5.hpp"
#include "hinf/errors.hpp"
#include "extremum.hpp"
#include "riccati_kernel.hpp"
#include "symmetric_extremes.hpp"

namespace hinf {

namespace {

enum class RiccatiKind { Control, Filter };

// dX/dt = sign (M(t)' X + X M(t) + R(t) - X S(t) X) along a trajectory:
//   Control (GRDE 13):  sign = -1, M = A_e, R = Q,    S = B B' - gamma^-2 D D';
//   Filter  (eq. 36):   sign = +1, M = A_e', R = D D', S = C' N^-1 C - gamma^-2 Q.
// With inverted = true the problem is the one of W = X^-1, which passes smoothly through a
// finite escape of X (W becomes singular there):
//   dW/dt = -W (dX/dt) W = (-sign) (M'' W + W M' + (-S) - W (-R) W).
// N is the state dimension when known at compile time (fixed-size Eigen types), else Dynamic.
template <int N>
class RiccatiProblem {
 public:
  using MatN = Eigen::Matrix<double, N, N>;
  using VecN = Eigen::Matrix<double, N, 1>;

  RiccatiProblem(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, double gamma,
                 const Mat& N_inv, bool inverted = false)
      : trajectory_(trajectory), model_(trajectory.model()), kind_(kind), inverted_(inverted),
        n_(trajectory.n()), sign_((kind == RiccatiKind::Control ? -1.0 : 1.0) * (inverted ? -1.0 : 1.0)),
        inv_gamma2_(std::isinf(gamma) ? 0.0 : 1.0 / (gamma * gamma)),
        constant_(model_.constant_input_matrices()), Q_(Q), N_inv_(N_inv) {
    for (auto* M : {&M_, &R_, &S_, &X_, &T_, &G_}) M->resize(n_, n_);
    q_d_.resize(n_);
    if (constant_) set_matrices(trajectory.t0());
  }

  int n() const { return n_; }

  void rhs(double t, const double* x, double* dx) {
    linearize(t);
    unpack_symmetric(x, X_);
    detail::riccati_rhs(sign_, M_, R_, S_, X_, T_, G_, dx, diagonal_S_);
  }

  void jacobian(double t, const double* x, double* J) {
    linearize(t);
    unpack_symmetric(x, X_);
    detail::riccati_jacobian(sign_, M_, S_, X_, T_, G_, J);
  }

 private:
  void set_matrices(double t) {
    const Mat D = model_.D(t);
    MatN R(n_, n_), S(n_, n_);
    if (kind_ == RiccatiKind::Control) {
      const Mat B = model_.B(t);
      R = Q_;
      S = B * B.transpose();
      if (inv_gamma2_ > 0.0) S -= inv_gamma2_ * (D * D.transpose());
    } else {
      const Mat C = model_.C(t);
      R = D * D.transpose();
      S = C.transpose() * N_inv_ * C;
      if (inv_gamma2_ > 0.0) S -= inv_gamma2_ * Q_;
    }
    R_ = inverted_ ? MatN(-S) : R;
    S_ = inverted_ ? MatN(-R) : S;
    diagonal_S_ = detail::is_diagonal(S_);
  }

  void linearize(double t) {
    // Explicit Runge-Kutta stages and Newton iterations often come back to the same t.
    if (t == linearized_at_) return;
    linearized_at_ = t;
    trajectory_.q_d(t, q_d_.data(), &cursor_);
    model_.dfdq(t, q_d_, T_);
    // M = A_e (control) or A_e' (filter); the inverse problem uses M'.
    const bool transpose = (kind_ == RiccatiKind::Filter) != inverted_;
    if (transpose) M_ = T_.transpose();
    else M_ = T_;
    if (!constant_) set_matrices(t);
  }

  const Trajectory& trajectory_;
  const Model& model_;
  RiccatiKind kind_;
  bool inverted_;
  int n_;
  double sign_;
  double inv_gamma2_;
  bool constant_;
  bool diagonal_S_ = false;
  Mat Q_, N_inv_;
  std::size_t cursor_ = 0;
  double linearized_at_ = NAN;  // the t of M_ (and of R_, S_ for time-varying input matrices)
  VecN q_d_;
  MatN M_, R_, S_, X_, T_, G_;
};

double max_abs(const double* y, int p) {
  double value = 0.0;
  for (int i = 0; i < p; ++i) {
    const double a = std::abs(y[i]);
    if (!(a <= value)) value = a;  // propagates NaN
  }
  return value;
}

[[noreturn]] void throw_escape(RiccatiKind kind, double t_escape, double gamma, double t0,
                               double tf, const std::string& detail) {
  if (kind == RiccatiKind::Control)
    throw ConjugatePointError(
        str_cat("conjugate point: Z(t) of the GRDE (13) escapes to infinity at t = ", t_escape,
                " (integrating backward from tf = ", tf, " toward t0 = ", t0, "); gamma = ", gamma,
                " is at or below gamma* for this trajectory, horizon and weights. Increase gamma"
                " (gamma_star() gives the smallest admissible value)",
                detail),
        t_escape, gamma);
  throw ConjugatePointError(
      str_cat("the filter Riccati equation (36) escapes to infinity at t = ", t_escape,
              " (integrating forward from t0 = ", t0, " toward tf = ", tf, "); gamma = ", gamma,
              " is too small for this filter. Increase gamma or Q0 - eta I", detail),
      t_escape, gamma);
}

template <int N>
double smallest_eigenvalue(const double* packed, int n) {
  Eigen::Matrix<double, N, N> W(n, n);
  unpack_symmetric(packed, W);
  double lo = 0.0, hi = 0.0;
  detail::symmetric_eigen_extremes(W, lo, hi);
  return lo;
}

// Where, between t_start and t_end, does the solution X of the Riccati problem escape to
// infinity? Integrates W = X^-1 from W(t_start) = X_start^-1 (X_start large, positive
// definite) and returns the first time the smallest eigenvalue of W reaches zero, located by
// bisection on the dense output; NaN if W stays positive definite (X is large but finite).
template <int N>
double escape_time(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, double gamma,
                   const Mat& N_inv, const Mat& X_start, double t_start, double t_end,
                   const SolverOptions& options) {
  RiccatiProblem<N> inverse(trajectory, kind, Q, gamma, N_inv, /*inverted=*/true);
  const int n = inverse.n();
  const int p = packed_size(n);
  const Eigen::LLT<Mat> llt(X_start);
  if (llt.info() != Eigen::Success) return t_start;  // X already lost positive definiteness
  const Mat W0 = llt.solve(Mat::Identity(n, n));
  std::vector<double> w(static_cast<std::size_t>(p)), at(static_cast<std::size_t>(p));
  pack_symmetric(0.5 * (W0 + W0.transpose()), w.data());
  const double scale = max_abs(w.data(), p);
  Dopri5 stepper(p, options.rtol, std::min(options.atol, 1e-3 * options.rtol * scale), options.max_steps);
  auto rhs = [&inverse](double t, const double* y, double* dy) { inverse.rhs(t, y, dy); };
  struct Found {
    double t;
  };
  try {
    stepper.integrate(rhs, t_start, t_end, w.data(), [&](double ts, double h, const double* c, const double* y) {
      if (smallest_eigenvalue<N>(y, n) > 0.0) return;
      double lo = 0.0, hi = 1.0;  // lambda_min(W) > 0 at theta = lo, <= 0 at theta = hi
      for (int i = 0; i < 60 && (hi - lo) * std::abs(h) > 1e-14 * std::max(1.0, std::abs(ts)); ++i) {
        const double mid = 0.5 * (lo + hi);
        for (int k = 0; k < p; ++k) {
          double v = c[4 * p + k];
          for (int j = 3; j >= 0; --j) v = v * mid + c[j * p + k];
          at[static_cast<std::size_t>(k)] = v;
        }
        (smallest_eigenvalue<N>(at.data(), n) > 0.0 ? lo : hi) = mid;
      }
      throw Found{ts + hi * h};
    });
  } catch (const Found& found) {
    return found.t;
  } catch (const SolverError& e) {
    return e.t();  // W could not be continued: treat the failure point as the escape
  }
  return NAN;
}

// Integrates the Riccati problem from (t_start, X_start) to t_end with the chosen method and
// returns its dense output. When |X|_max passes escape_norm * max(1, |X_start|_max), the
// inverse W = X^-1 decides whether X really escapes (ConjugatePointError at the escape
// time) or is only large; in the latter case the integration goes on.
template <int N>
std::pair<PiecewisePolynomial, SolveStats> integrate_riccati(RiccatiProblem<N>& problem,
                                                             const Trajectory& trajectory, RiccatiKind kind,
                                                             const Mat& Q, const Mat& N_inv,
                                                             const Mat& X_start, double t_start,
                                                             double t_end, double gamma,
                                                             const SolverOptions& options, bool store) {
  const int n = static_cast<int>(X_start.rows());
  const int p = packed_size(n);
  std::vector<double> x(static_cast<std::size_t>(p));
  pack_symmetric(X_start, x.data());
  const double t0 = std::min(t_start, t_end), tf = std::max(t_start, t_end);
  const double direction = t_end > t_start ? 1.0 : -1.0;

  auto rhs = [&problem](double t, const double* y, double* dy) { problem.rhs(t, y, dy); };
  double limit = options.escape_norm * std::max(1.0, max_abs(x.data(), p));
  bool probed = false;
  // Thrown when the inverse has been followed to t_end without an escape and nothing is
  // stored: the question "does X escape?" is answered (no), the rest need not be integrated.
  struct NoEscape {};
  // Once the inverse has shown that X does not escape, X is followed through its peak. A
  // continuation that has taken far more steps than the whole solve before it AND whose pace
  // since the probe would need more than max_steps to reach t_end (the step size collapsing
  // under the huge X) is stopped as a failure instead of grinding on to max_steps; a large X
  // that is integrated at a normal pace (a long horizon) is not affected.
  long steps_taken = 0, steps_at_probe = 0, step_budget_after_probe = 0;
  double t_probe = t_start;
  auto check_escape = [&](double t, const double* y) {
    ++steps_taken;
    if (probed && steps_taken > step_budget_after_probe) {
      const double steps_since = static_cast<double>(steps_taken - steps_at_probe);
      const double pace = std::abs(t - t_probe) / steps_since;  // mean step since the probe
      const double projected = static_cast<double>(steps_taken) + std::abs(t_end - t) / std::max(pace, 1e-300);
      if (projected > static_cast<double>(options.max_steps))
        throw SolverError(str_cat(steps_taken - steps_at_probe, " steps in the peak of the solution near t = ", t,
                                  " (the step size collapsed: at this pace max_steps = ", options.max_steps,
                                  " would not reach t = ", t_end, ")"),
                          t, "TOO_MUCH_WORK");
    }
    const double largest = max_abs(y, p);
    if (largest <= limit) return;
    if (!std::isfinite(largest)) throw_escape(kind, t, gamma, t0, tf, " (the solution became non-finite)");
    Mat X(n, n);
    unpack_symmetric(y, X);
    const double t_escape = escape_time<N>(trajectory, kind, Q, gamma, N_inv, X, t, t_end, options);
    if (!std::isnan(t_escape)) throw_escape(kind, t_escape, gamma, t0, tf, "");
    if (!store) throw NoEscape{};
    limit = std::numeric_limits<double>::infinity();  // large but finite: carry on
    probed = true;
    steps_at_probe = steps_taken;
    t_probe = t;
    step_budget_after_probe = steps_taken + std::max(2000L, 20 * steps_taken);
  };
  // A failure while X is large may be an escape the threshold has not caught yet.
  const double initial_scale = std::max(1.0, max_abs(x.data(), p));
  auto on_failure = [&](const SolverError& e) {
    if (!probed && max_abs(x.data(), p) > 1e3 * initial_scale) {
      Mat X(n, n);
      unpack_symmetric(x.data(), X);
      const double t_escape = escape_time<N>(trajectory, kind, Q, gamma, N_inv, X, e.t(), t_end, options);
      if (!std::isnan(t_escape)) throw_escape(kind, t_escape, gamma, t0, tf, "");
      if (!store) throw NoEscape{};
      probed = true;
    }
    std::string cause = e.what();
    while (!cause.empty() && (cause.back() == '.' || cause.back() == ' ')) cause.pop_back();
    throw SolverError(str_cat(kind == RiccatiKind::Control ? "GRDE (13)" : "filter Riccati (36)", " solve failed: ",
                              cause,
                              !probed ? std::string()
                                      : str_cat(". The solution has no finite escape but grows too large to integrate"
                                                " near t = ", e.t(),
                                                std::isinf(gamma) ? " (gamma = inf): rescale the weights or the model"
                                                                  : str_cat(": gamma = ", gamma,
                                                                            " is very close to the smallest admissible"
                                                                            " value; increase it"))),
                      e.t(), e.flag());
  };
  PiecewisePolynomial dense(p);
  SolveStats stats;
  try {
  if (options.method == Method::ERK) {
    Dopri5 stepper(p, options.rtol, options.atol, options.max_steps);
    try {
      stepper.integrate(rhs, t_start, t_end, x.data(),
                        [&](double t_step, double h, const double* c, const double* y) {
                          if (store) dense.append(t_step, h, 4, c);
                          check_escape(t_step + h, y);
                        });
    } catch (const ConjugatePointError&) {
      throw;
    } catch (const SolverError& e) {
      on_failure(e);
    }
    stats.steps = stepper.stats().steps;
    stats.rejected = stepper.stats().rejected;
    stats.rhs_evals = stepper.stats().rhs_evals;
  } else {
    Cvode::Jacobian jacobian = nullptr;
    if (options.method == Method::BDF)
      jacobian = [&problem](double t, const double* y, const double*, double* J) {
        problem.jacobian(t, y, J);
      };
    Cvode solver(p, options.method, options.rtol, options.atol, options.max_steps, rhs, jacobian);
    solver.reset(t_start, x.data(), t_end);
    double t = t_start;
    while ((t_end - t) * direction > 0.0) {
      try {
        t = solver.step(x.data());
        if (store) solver.append_last_step(dense);
        check_escape(t, x.data());
      } catch (const SolverError& e) {
        on_failure(e);
      }
    }
    stats.steps = solver.num_steps();
    stats.rejected = solver.num_error_test_failures();
    stats.rhs_evals = solver.num_rhs_evals();
    stats.jac_evals = solver.num_jac_evals();
  }
  } catch (const NoEscape&) {
    return {PiecewisePolynomial(p), stats};
  }
  dense.finalize();
  stats.memory_bytes = dense.memory_bytes();
  return {std::move(dense), stats};
}

template <int N>
std::pair<PiecewisePolynomial, SolveStats> solve_kind(const Trajectory& trajectory, RiccatiKind kind,
                                                      const Mat& Q, double gamma, const Mat& N_inv,
                                                      const Mat& X_start, const SolverOptions& options,
                                                      bool store) {
  RiccatiProblem<N> problem(trajectory, kind, Q, gamma, N_inv);
  const double t0 = trajectory.t0(), tf = trajectory.tf();
  if (kind == RiccatiKind::Control)
    return integrate_riccati(problem, trajectory, kind, Q, N_inv, X_start, tf, t0, gamma, options, store);
  return integrate_riccati(problem, trajectory, kind, Q, N_inv, X_start, t0, tf, gamma, options, store);
}

// Solves (store = true: keeps the dense output) or only integrates (store = false: enough to
// find escapes) the Riccati problem of `kind` over the trajectory's horizon.
std::pair<PiecewisePolynomial, SolveStats> solve(const Trajectory& trajectory, RiccatiKind kind,
                                                 const Mat& Q, double gamma, const Mat& N_inv,
                                                 const Mat& X_start, const SolverOptions& options,
                                                 bool store = true) {
  if (trajectory.n() == 6) return solve_kind<6>(trajectory, kind, Q, gamma, N_inv, X_start, options, store);
  return solve_kind<Eigen::Dynamic>(trajectory, kind, Q, gamma, N_inv, X_start, options, store);
}

// Escape time of an integration without storage, NaN when there is none.
double escape_or_nan(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, double gamma,
                     const Mat& N_inv, const Mat& X_start, const SolverOptions& options) {
  try {
    solve(trajectory, kind, Q, gamma, N_inv, X_start, options, /*store=*/false);
  } catch (const ConjugatePointError& e) {
    return e.t_escape();
  }
  return NAN;
}

void check_gamma(double gamma) {
  require(!std::isnan(gamma) && gamma > 0.0, "gamma must be > 0 (or inf), got ", gamma);
}

Mat symmetrized(const Mat& M) { return 0.5 * (M + M.transpose()); }

template <int N>
void extremes_over(const PiecewisePolynomial& X, const std::vector<double>& times, double& lambda_min,
                   double& lambda_max) {
  const int n = static_cast<int>(std::lround((std::sqrt(8.0 * X.dim() + 1.0) - 1.0) / 2.0));
  std::vector<double> p(static_cast<std::size_t>(X.dim()));
  Eigen::Matrix<double, N, N> Xt(n, n);
  std::size_t cursor = 0;
  for (double t : times) {
    X.eval(t, p.data(), &cursor);
    unpack_symmetric(p.data(), Xt);
    double lo = 0.0, hi = 0.0;
    detail::symmetric_eigen_extremes(Xt, lo, hi);
    lambda_min = std::min(lambda_min, lo);
    lambda_max = std::max(lambda_max, hi);
  }
}

template <int N>
void extremes_at(const PiecewisePolynomial& X, double t, double& lo, double& hi) {
  const int n = static_cast<int>(std::lround((std::sqrt(8.0 * X.dim() + 1.0) - 1.0) / 2.0));
  double packed[136];
  std::vector<double> heap;
  double* p = packed;
  if (X.dim() > 136) {
    heap.resize(static_cast<std::size_t>(X.dim()));
    p = heap.data();
  }
  X.eval(t, p);
  Eigen::Matrix<double, N, N> Xt(n, n);
  unpack_symmetric(p, Xt);
  detail::symmetric_eigen_extremes(Xt, lo, hi);
}

template <int N>
void continuous_bounds(const PiecewisePolynomial& X, double& lambda_min, double& lambda_max) {
  const std::vector<double> times = detail::step_samples(X.breakpoints());
  auto smallest = [&X](double t) {
    double lo = 0.0, hi = 0.0;
    extremes_at<N>(X, t, lo, hi);
    return lo;
  };
  auto largest = [&X](double t) {
    double lo = 0.0, hi = 0.0;
    extremes_at<N>(X, t, lo, hi);
    return hi;
  };
  lambda_min = detail::extremum_over(times, smallest, 1.0).first;
  lambda_max = detail::extremum_over(times, largest, -1.0).first;
}

}  // namespace

void SymmetricSolution::eigenvalue_bounds(double& lambda_min, double& lambda_max) const {
  if (n_ == 6) continuous_bounds<6>(X_, lambda_min, lambda_max);
  else continuous_bounds<Eigen::Dynamic>(X_, lambda_min, lambda_max);
}

SymmetricSolution::SymmetricSolution(TrajectoryPtr trajectory, double gamma, PiecewisePolynomial X,
                                     SolveStats stats)
    : trajectory_(std::move(trajectory)), n_(trajectory_->n()), gamma_(gamma), X_(std::move(X)),
      stats_(stats) {}

Mat SymmetricSolution::value(double t) const {
  std::vector<double> p(static_cast<std::size_t>(packed_size(n_)));
  X_.eval(t, p.data());
  Mat out(n_, n_);
  unpack_symmetric(p.data(), out);
  return out;
}

Mat SymmetricSolution::derivative(double t) const {
  std::vector<double> p(static_cast<std::size_t>(packed_size(n_)));
  X_.eval_derivative(t, p.data());
  Mat out(n_, n_);
  unpack_symmetric(p.data(), out);
  return out;
}

void SymmetricSolution::packed(double t, double* out, std::size_t* cursor) const {
  X_.eval(t, out, cursor);
}

void SymmetricSolution::eigenvalue_range(const std::vector<double>& times, double& lambda_min,
                                         double& lambda_max) const {
  lambda_min = std::numeric_limits<double>::infinity();
  lambda_max = -std::numeric_limits<double>::infinity();
  if (n_ == 6) extremes_over<6>(X_, times, lambda_min, lambda_max);
  else extremes_over<Eigen::Dynamic>(X_, times, lambda_min, lambda_max);
}

RiccatiSolution::RiccatiSolution(TrajectoryPtr trajectory, double gamma, PiecewisePolynomial Z,
                                 SolveStats stats)
    : SymmetricSolution(std::move(trajectory), gamma, std::move(Z), stats), m_(trajectory_->m()) {
  const Model& model = trajectory_->model();
  constant_B_ = model.constant_input_matrices();
  if (constant_B_) B_ = SparseMatrix(model.B(trajectory_->t0()));
}

Mat RiccatiSolution::gain(double t) const {
  Mat K(m_, n_);
  gain(t, K.data());
  return K;
}

void RiccatiSolution::gain(double t, double* out, std::size_t* cursor) const {
  if (constant_B_) {
    // K(j, c) = sum_i B(i, j) Z(i, c), column-major m x n.
    double packed_stack[kMaxPackedOnStack];
    std::vector<double> heap;
    double* z = packed_stack;
    if (packed_size(n_) > kMaxPackedOnStack) {
      heap.resize(static_cast<std::size_t>(packed_size(n_)));
      z = heap.data();
    }
    X_.eval(t, z, cursor);
    for (int k = 0; k < m_ * n_; ++k) out[k] = 0.0;
    const int n = n_, m = m_;
    B_.for_each([&](int i, int j, double b) {
      for (int c = 0; c < n; ++c) out[j + c * m] += b * z[packed_index(i, c)];
    });
    return;
  }
  Eigen::Map<Mat>(out, m_, n_) = trajectory_->model().B(t).transpose() * Z(t);
}

namespace {

void check_grde_input(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, double gamma,
                      const SolverOptions& options) {
  require(trajectory != nullptr, "the GRDE needs a trajectory");
  const int n = trajectory->n();
  check_symmetric_weight(Q, n, "Q", false);
  check_symmetric_weight(Qf, n, "Qf", true);
  check_gamma(gamma);
  options.validate();
}

// The inverse of N, after the checks of the filter Riccati equation's input.
Mat check_filter_input(const TrajectoryPtr& trajectory, const Mat& N, const Mat& Q, double gamma,
                       const Mat& Sigma0, const SolverOptions& options) {
  require(trajectory != nullptr, "the filter Riccati equation needs a trajectory");
  const Model& model = trajectory->model();
  const int n = trajectory->n();
  const int p = static_cast<int>(model.C(trajectory->t0()).rows());
  check_symmetric_weight(N, p, "N", true);
  check_symmetric_weight(Q, n, "Q", false);
  check_symmetric_weight(Sigma0, n, "Sigma0", true);
  check_gamma(gamma);
  options.validate();
  return symmetrized(N).inverse();
}

}  // namespace

RiccatiSolutionPtr solve_grde(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                              double gamma, const SolverOptions& options) {
  check_grde_input(trajectory, Q, Qf, gamma, options);
  auto [dense, stats] = solve(*trajectory, RiccatiKind::Control, symmetrized(Q), gamma, Mat(),
                              symmetrized(Qf), options);
  return std::make_shared<const RiccatiSolution>(trajectory, gamma, std::move(dense), stats);
}


FilterRiccatiSolutionPtr solve_filter_riccati(const TrajectoryPtr& trajectory, const Mat& N,
                                              const Mat& Q, double gamma, const Mat& Sigma0,
                                              const SolverOptions& options) {
  const Mat N_inv = check_filter_input(trajectory, N, Q, gamma, Sigma0, options);
  auto [dense, stats] = solve(*trajectory, RiccatiKind::Filter, symmetrized(Q), gamma, N_inv,
                              symmetrized(Sigma0), options);
  return std::make_shared<const FilterRiccatiSolution>(trajectory, gamma, std::move(dense), stats);
}

double grde_escape_time(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, double gamma,
                        const SolverOptions& options) {
  check_grde_input(trajectory, Q, Qf, gamma, options);
  return escape_or_nan(*trajectory, RiccatiKind::Control, symmetrized(Q), gamma, Mat(), symmetrized(Qf),
                       options);
}

double filter_escape_time(const TrajectoryPtr& trajectory, const Mat& N, const Mat& Q, double gamma,
                          const Mat& Sigma0, const SolverOptions& options) {
  const Mat N_inv = check_filter_input(trajectory, N, Q, gamma, Sigma0, options);
  return escape_or_nan(*trajectory, RiccatiKind::Filter, symmetrized(Q), gamma, N_inv, symmetrized(Sigma0),
                       options);
}

}  // namespace hinf
