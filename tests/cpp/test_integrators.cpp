// The integrators (Dormand-Prince 5(4), CVODE BDF/Adams) and the dense output they build,
// checked against exact solutions of linear ODEs: y' = -y, the harmonic oscillator
// y' = [y2, -y1], and a stiff 2x2 system with eigenvalues -1 and -1e4.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/core/interrupt.hpp"
#include "hinf/core/types.hpp"
#include "hinf/numerics/cvode.hpp"
#include "hinf/numerics/dopri5.hpp"
#include "hinf/numerics/piecewise_polynomial.hpp"
#include "hinf/numerics/stepper.hpp"
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Mat;
using hinf::Method;
using hinf::PiecewisePolynomial;
using hinf::Vec;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A linear test problem y' = A y with its exact flow y(t) = exp(A t) y(0), y(0) = y_init.
struct LinearProblem {
  std::string name;
  Mat A;
  Vec y_init;
  std::function<Vec(double)> exact;  // y(t)
  std::function<Mat(double)> flow;   // exp(A dt)

  void rhs(double, const double* y, double* dy) const {
    Eigen::Map<const Vec> yy(y, A.rows());
    Eigen::Map<Vec>(dy, A.rows()) = A * yy;
  }
  int dim() const { return static_cast<int>(A.rows()); }
};

LinearProblem decay() {
  LinearProblem p;
  p.name = "decay";
  p.A = Mat::Constant(1, 1, -1.0);
  p.y_init = Vec::Ones(1);
  p.exact = [](double t) { return Vec::Constant(1, std::exp(-t)); };
  p.flow = [](double dt) { return Mat::Constant(1, 1, std::exp(-dt)); };
  return p;
}

LinearProblem oscillator() {
  LinearProblem p;
  p.name = "oscillator";
  p.A = Mat::Zero(2, 2);
  p.A(0, 1) = 1.0;
  p.A(1, 0) = -1.0;
  p.y_init = Vec(2);
  p.y_init << 1.0, 0.0;
  p.exact = [](double t) {
    Vec y(2);
    y << std::cos(t), -std::sin(t);
    return y;
  };
  p.flow = [](double dt) {
    Mat F(2, 2);
    F << std::cos(dt), std::sin(dt), -std::sin(dt), std::cos(dt);
    return F;
  };
  return p;
}

// A = V diag(-1, -1e4) V^-1, V = [[1, 1], [1, 2]], V^-1 = [[2, -1], [-1, 1]]; y(0) = [1, 0]
// excites both modes: y(t) = V diag(e^-t, e^-1e4 t) V^-1 y(0).
LinearProblem stiff() {
  LinearProblem p;
  p.name = "stiff";
  Mat V(2, 2), Vi(2, 2);
  V << 1, 1, 1, 2;
  Vi << 2, -1, -1, 1;
  p.A = V * Vec(Eigen::Vector2d(-1.0, -1e4)).asDiagonal() * Vi;
  p.y_init = Vec(2);
  p.y_init << 1.0, 0.0;
  p.exact = [V, Vi](double t) {
    const Vec c = Vi * Vec(Eigen::Vector2d(1.0, 0.0));
    Vec modes(2);
    modes << c[0] * std::exp(-t), c[1] * std::exp(-1e4 * t);
    return Vec(V * modes);
  };
  return p;
}

double max_abs(const Vec& v) { return v.cwiseAbs().maxCoeff(); }

// ================================================================= PiecewisePolynomial

// A cubic per component, p_i(t) = sum_k a_ik t^k; the pieces below re-expand it about each
// piece's start in powers of theta, so every piece represents the same global polynomial.
struct GlobalCubic {
  double a[2][4] = {{1.0, -2.0, 0.5, 0.1}, {-0.3, 0.7, -0.05, 0.02}};
  double value(int i, double t) const { return a[i][0] + t * (a[i][1] + t * (a[i][2] + t * a[i][3])); }
  double slope(int i, double t) const { return a[i][1] + t * (2 * a[i][2] + t * 3 * a[i][3]); }
  // Sizes of the terms of value and slope at t: what their round-off is relative to.
  double value_terms(int i, double t) const {
    const double x = std::abs(t);
    return std::abs(a[i][0]) + x * (std::abs(a[i][1]) + x * (std::abs(a[i][2]) + x * std::abs(a[i][3])));
  }
  double slope_terms(int i, double t) const {
    const double x = std::abs(t);
    return std::abs(a[i][1]) + x * (2 * std::abs(a[i][2]) + x * 3 * std::abs(a[i][3]));
  }
  // Taylor coefficients about t_s, scaled by h^k: c_k = p^(k)(t_s) h^k / k!.
  std::vector<double> coeffs(double t_s, double h) const {
    std::vector<double> c(8);
    for (int i = 0; i < 2; ++i) {
      const double d0 = value(i, t_s), d1 = slope(i, t_s);
      const double d2 = 2 * a[i][2] + 6 * a[i][3] * t_s, d3 = 6 * a[i][3];
      c[0 * 2 + i] = d0;
      c[1 * 2 + i] = d1 * h;
      c[2 * 2 + i] = d2 * h * h / 2.0;
      c[3 * 2 + i] = d3 * h * h * h / 6.0;
    }
    return c;
  }
};

TEST(PiecewisePolynomial, HandMadePiecesEvalAndDerivative) {
  PiecewisePolynomial pp(2);
  EXPECT_TRUE(pp.empty());
  // Piece 0 on [0, 1]: y = [1 + 2 th + 3 th^2, th - th^2], th = t.
  const double c0[] = {1.0, 0.0, 2.0, 1.0, 3.0, -1.0};
  // Piece 1 on [1, 3] (h = 2), degree 1: y = [6 - th, 4 th], th = (t - 1) / 2.
  const double c1[] = {6.0, 0.0, -1.0, 4.0};
  pp.append(hinf::DensePiece{0.0, 0.0 + 1.0, 2, pp.dim(), c0});
  pp.append(hinf::DensePiece{1.0, 1.0 + 2.0, 1, pp.dim(), c1});
  pp.finalize();
  EXPECT_EQ(pp.num_pieces(), 2u);
  EXPECT_EQ(pp.t_min(), 0.0);
  EXPECT_EQ(pp.t_max(), 3.0);
  EXPECT_EQ(pp.breakpoints(), (std::vector<double>{0.0, 1.0, 3.0}));
  // Horner's scheme in theta against the polynomials written out: round-off of the terms,
  // which are below 10 here.
  const double tol = hinf_test::kRoundoff * 10.0;
  double y[2], dy[2];
  for (double t : {0.0, 0.25, 0.5, 0.9}) {
    pp.eval(t, y);
    pp.eval_derivative(t, dy);
    EXPECT_NEAR(y[0], 1 + 2 * t + 3 * t * t, tol);
    EXPECT_NEAR(y[1], t - t * t, tol);
    EXPECT_NEAR(dy[0], 2 + 6 * t, tol);
    EXPECT_NEAR(dy[1], 1 - 2 * t, tol);
  }
  for (double t : {1.1, 2.0, 2.5, 3.0}) {
    const double th = (t - 1.0) / 2.0;
    pp.eval(t, y);
    pp.eval_derivative(t, dy);
    EXPECT_NEAR(y[0], 6 - th, tol);
    EXPECT_NEAR(y[1], 4 * th, tol);
    EXPECT_NEAR(dy[0], -0.5, tol);  // d/dt = (d/dth) / h
    EXPECT_NEAR(dy[1], 2.0, tol);
  }
}

TEST(PiecewisePolynomial, BackwardPiecesAreReorderedByFinalize) {
  // Integration from t = 3 down to 0: pieces [3 -> 1] (h = -2) then [1 -> 0] (h = -1).
  const GlobalCubic p;
  PiecewisePolynomial pp(2);
  const std::vector<double> a = p.coeffs(3.0, -2.0), b = p.coeffs(1.0, -1.0);
  pp.append(hinf::DensePiece{3.0, 3.0 + -2.0, 3, pp.dim(), a.data()});
  pp.append(hinf::DensePiece{1.0, 1.0 + -1.0, 3, pp.dim(), b.data()});
  pp.finalize();
  EXPECT_EQ(pp.t_min(), 0.0);
  EXPECT_EQ(pp.t_max(), 3.0);
  EXPECT_EQ(pp.breakpoints(), (std::vector<double>{0.0, 1.0, 3.0}));
  double y[2], dy[2];
  for (double t = 0.0; t <= 3.0; t += 0.125) {
    pp.eval(t, y);
    pp.eval_derivative(t, dy);
    // Pieces re-expanded about their starts against the global cubic: round-off of the terms.
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(y[i], p.value(i, t), hinf_test::kRoundoff * p.value_terms(i, t)) << "t = " << t;
      EXPECT_NEAR(dy[i], p.slope(i, t), hinf_test::kRoundoff * p.slope_terms(i, t)) << "t = " << t;
    }
  }
}

TEST(PiecewisePolynomial, CursorAndBinarySearchAgree) {
  const GlobalCubic p;
  hinf_ref::Rng rng(5);
  for (bool backward : {false, true}) {
    PiecewisePolynomial pp(2);
    std::vector<double> knots{0.0};
    while (knots.size() < 60) knots.push_back(knots.back() + rng.uniform(0.01, 0.3));
    if (!backward) {
      for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
        const double h = knots[k + 1] - knots[k];
        pp.append(hinf::DensePiece{knots[k], knots[k] + h, 3, pp.dim(), p.coeffs(knots[k], h).data()});
      }
    } else {
      for (std::size_t k = knots.size() - 1; k > 0; --k) {
        const double h = knots[k - 1] - knots[k];
        pp.append(hinf::DensePiece{knots[k], knots[k] + h, 3, pp.dim(), p.coeffs(knots[k], h).data()});
      }
    }
    pp.finalize();
    const double lo = knots.front(), hi = knots.back();
    EXPECT_EQ(pp.t_min(), lo);
    EXPECT_NEAR(pp.t_max(), hi, hinf_test::kRoundoff * hi);  // start + length of the last piece
    // Sweeps up, down, random jumps, and the knots themselves.
    std::vector<double> times;
    for (int k = 0; k <= 400; ++k) times.push_back(lo + (hi - lo) * k / 400.0);
    for (int k = 400; k >= 0; --k) times.push_back(lo + (hi - lo) * k / 400.0);
    for (int k = 0; k < 400; ++k) times.push_back(rng.uniform(lo, hi));
    times.insert(times.end(), knots.begin(), knots.end());
    std::size_t cursor = 0;
    double y_cursor[2], y_plain[2], dy_cursor[2];
    for (double t : times) {
      pp.eval(t, y_cursor, &cursor);
      ASSERT_LT(cursor, pp.num_pieces());
      pp.eval_derivative(t, dy_cursor, &cursor);
      pp.eval(t, y_plain);
      // At a knot the cursor and the binary search may pick the two neighbouring pieces:
      // equal values up to round-off of the terms (up to ~120 at the last knot, t = 8.6).
      for (int i = 0; i < 2; ++i) {
        const double tol = hinf_test::kRoundoff * p.value_terms(i, t);
        EXPECT_NEAR(y_cursor[i], y_plain[i], tol) << "t = " << t;
        EXPECT_NEAR(y_cursor[i], p.value(i, t), tol) << "t = " << t;
        EXPECT_NEAR(dy_cursor[i], p.slope(i, t), hinf_test::kRoundoff * p.slope_terms(i, t)) << "t = " << t;
      }
    }
    // A stale cursor (past the end) falls back to the binary search.
    cursor = 1000;
    pp.eval(0.5 * (lo + hi), y_cursor, &cursor);
    EXPECT_LT(cursor, pp.num_pieces());
    EXPECT_NEAR(y_cursor[0], p.value(0, 0.5 * (lo + hi)), hinf_test::kRoundoff * p.value_terms(0, 0.5 * (lo + hi)));
  }
}

TEST(PiecewisePolynomial, OutOfRangeThrows) {
  PiecewisePolynomial empty(1);
  double y[2];
  EXPECT_THROW(empty.eval(0.0, y), hinf::InputError);
  EXPECT_THROW(empty.t_min(), hinf::InputError);
  const GlobalCubic p;
  PiecewisePolynomial pp(2);
  pp.append(hinf::DensePiece{1.0, 1.0 + 0.5, 3, pp.dim(), p.coeffs(1.0, 0.5).data()});
  pp.append(hinf::DensePiece{1.5, 1.5 + 0.5, 3, pp.dim(), p.coeffs(1.5, 0.5).data()});
  pp.finalize();
  std::size_t cursor = 0;
  EXPECT_THROW(pp.eval(0.99, y), hinf::InputError);
  EXPECT_THROW(pp.eval(2.01, y, &cursor), hinf::InputError);
  EXPECT_THROW(pp.eval_derivative(-5.0, y), hinf::InputError);
  EXPECT_THROW(pp.eval(kNaN, y), hinf::InputError);
  EXPECT_NO_THROW(pp.eval(1.0, y));
  EXPECT_NO_THROW(pp.eval(2.0, y, &cursor));
}

// ================================================================= Dormand-Prince 5(4)

struct DopriRun {
  Vec y_end;
  double max_dense_error = 0.0;  // over interior thetas, absolute
  double max_c0_mismatch = 0.0;  // |c_0 - y(t_start)| (the dense output starts at the step's y)
  double max_sum_mismatch = 0.0; // |sum_j c_j - y_end| (and ends at the step's new y)
  long steps = 0;
};

DopriRun run_dopri(const LinearProblem& prob, double t0, double t1, double rtol, double atol) {
  const int n = prob.dim();
  hinf::Dopri5 stepper(n, rtol, atol, 100000);
  Vec y = prob.exact(t0);
  Vec y_prev = y;
  DopriRun run;
  double t_prev = t0;
  stepper.integrate(
      [&](double t, const double* yy, double* dy) { prob.rhs(t, yy, dy); }, t0, t1, y.data(),
      [&](const hinf::DensePiece& piece) {
        const double t_start = piece.t_start, h = piece.h();
        const double* c = piece.coeffs;
        const double* y_end = y.data();  // the stepper's state is at the end of the step
        EXPECT_EQ(piece.degree, 4);
        EXPECT_EQ(t_start, t_prev);
        EXPECT_TRUE(t1 > t0 ? h > 0 : h < 0);
        for (int i = 0; i < n; ++i) {
          run.max_c0_mismatch = std::max(run.max_c0_mismatch, std::abs(c[i] - y_prev[i]));
          const double sum = c[i] + c[n + i] + c[2 * n + i] + c[3 * n + i] + c[4 * n + i];
          run.max_sum_mismatch = std::max(run.max_sum_mismatch, std::abs(sum - y_end[i]));
        }
        for (double theta : {0.1, 0.3, 0.5, 0.77, 0.95}) {
          const Vec exact = prob.exact(t_start + theta * h);
          for (int i = 0; i < n; ++i) {
            double v = c[4 * n + i];
            for (int j = 3; j >= 0; --j) v = v * theta + c[j * n + i];
            run.max_dense_error = std::max(run.max_dense_error, std::abs(v - exact[i]));
          }
        }
        y_prev = Eigen::Map<const Vec>(y_end, n);
        t_prev = t_start + h;
        ++run.steps;
      });
  EXPECT_NEAR(t_prev, t1, hinf_test::kRoundoff * std::max(1.0, std::abs(t1)));  // sum of the steps
  run.y_end = y;
  return run;
}

// Ctrl-C (core/interrupt.hpp): every method stops after the step in progress, before the caller
// sees another piece, and a cleared request lets the same integration run to its end.
TEST(Interrupt, AnIntegrationStopsWithinOneStepAndRunsAgainOnceCleared) {
  for (const hinf::Method method : {hinf::Method::ERK, hinf::Method::BDF, hinf::Method::Adams, hinf::Method::Auto}) {
    hinf::SolverOptions options;
    options.method = method;
    const auto decay = [](double, const double* y, double* dy) { dy[0] = -y[0]; };
    long pieces = 0;
    const auto count = [&](const hinf::DensePiece&) {
      ++pieces;
      return hinf::StepAction::Continue;
    };
    double y = 1.0;
    hinf::request_interrupt();
    EXPECT_THROW(hinf::integrate(options, 1, decay, {}, 0.0, 10.0, &y, count), hinf::Interrupted)
        << hinf::to_string(method);
    EXPECT_EQ(pieces, 0) << hinf::to_string(method);
    EXPECT_TRUE(hinf::interrupt_requested());  // left set: every loop on the way out stops too
    hinf::clear_interrupt();
    y = 1.0;
    hinf::integrate(options, 1, decay, {}, 0.0, 10.0, &y, count);
    EXPECT_GT(pieces, 1) << hinf::to_string(method);
    EXPECT_NEAR(y, std::exp(-10.0), 1e-5) << hinf::to_string(method);  // the default tolerances
  }
}

TEST(Dopri5, ForwardAndBackwardAgainstExactSolutions) {
  for (const LinearProblem& prob : {decay(), oscillator()}) {
    for (bool backward : {false, true}) {
      const double t0 = backward ? 10.0 : 0.0, t1 = backward ? 0.0 : 10.0;
      double previous_error = 0.0;
      for (double rtol : {1e-6, 1e-9}) {
        const DopriRun run = run_dopri(prob, t0, t1, rtol, rtol * 1e-2);
        const Vec exact = prob.exact(t1);
        const double error = max_abs(run.y_end - exact) / max_abs(exact);
        const double ratio = error / rtol;
        std::printf("[dopri5] %-10s %-8s rtol %.0e: end rel. error %.2e (%.2f rtol), dense max "
                    "abs error %.2e (%.2f rtol), %ld steps\n",
                    prob.name.c_str(), backward ? "backward" : "forward", rtol, error, ratio,
                    run.max_dense_error, run.max_dense_error / rtol, run.steps);
        // Global error a modest multiple of the (local) tolerance over ~10 time constants.
        EXPECT_LT(ratio, 50.0) << prob.name << (backward ? " backward" : " forward");
        // The dense output is as accurate as the steps (within the same multiple), relative
        // to the solution's scale (<= 1 forward; e^10 for the backward decay).
        const double scale = backward && prob.name == "decay" ? std::exp(10.0) : 1.0;
        EXPECT_LT(run.max_dense_error / scale, 50.0 * rtol);
        // c_0 is the step's initial y itself (a copy); the coefficients sum to the new y in
        // exact arithmetic, in floating point up to round-off of the solution's size.
        EXPECT_EQ(run.max_c0_mismatch, 0.0);
        EXPECT_LT(run.max_sum_mismatch, hinf_test::kRoundoff * scale);
        // Tightening the tolerance by 1000 must reduce the error substantially.
        if (previous_error > 0.0) {
          EXPECT_LT(error, previous_error / 50.0);
        }
        previous_error = error;
      }
    }
  }
}

TEST(Dopri5, StepSizeUnderflowIsASolverError) {
  // y' = y^2, y(0) = 1: y = 1 / (1 - t) escapes at t = 1.
  hinf::Dopri5 stepper(1, 1e-8, 1e-10, 1000000);
  double y = 1.0;
  try {
    stepper.integrate([](double, const double* yy, double* dy) { dy[0] = yy[0] * yy[0]; }, 0.0, 2.0,
                      &y, [](const hinf::DensePiece&) {});
    FAIL() << "no error although the solution escapes at t = 1";
  } catch (const hinf::SolverError& e) {
    EXPECT_NEAR(e.t(), 1.0, 1e-3) << e.what();
    EXPECT_FALSE(e.flag().empty());
  }
}

TEST(Dopri5, NonFiniteRhsIsASolverError) {
  hinf::Dopri5 stepper(1, 1e-8, 1e-10, 1000000);
  double y = 1.0;
  EXPECT_THROW(stepper.integrate(
                   [](double t, const double*, double* dy) { dy[0] = t > 0.5 ? kNaN : 1.0; }, 0.0,
                   1.0, &y, [](const hinf::DensePiece&) {}),
               hinf::SolverError);
}

TEST(Dopri5, TooManyStepsIsASolverError) {
  hinf::Dopri5 stepper(1, 1e-10, 1e-12, 20);
  double y = 0.0;
  try {
    stepper.integrate([](double t, const double*, double* dy) { dy[0] = std::cos(10.0 * t); }, 0.0,
                      100.0, &y, [](const hinf::DensePiece&) {});
    FAIL() << "20 steps cannot cover 160 periods at rtol 1e-10";
  } catch (const hinf::SolverError& e) {
    EXPECT_EQ(e.flag(), "TOO_MUCH_WORK");
    EXPECT_GT(e.t(), 0.0);
    EXPECT_LT(e.t(), 100.0);
  }
}

// ================================================================= CVODE

struct CvodeRun {
  Vec y_end;
  double t_end = 0.0;
  long steps = 0;
  long jac_calls = 0;
};

// Integrates prob from t0 to t1 one internal step at a time, appending every step's
// interpolant to dense (when given).
CvodeRun run_cvode(const LinearProblem& prob, Method method, bool user_jacobian, double t0,
                   double t1, double rtol, double atol, PiecewisePolynomial* dense) {
  const int n = prob.dim();
  CvodeRun run;
  hinf::Cvode::Jacobian jac = nullptr;
  if (user_jacobian)
    jac = [&](double, const double*, const double*, double* J) {
      ++run.jac_calls;
      Eigen::Map<Mat>(J, n, n) = prob.A;
    };
  hinf::Cvode solver(n, method, rtol, atol, 100000,
                     [&](double t, const double* y, double* dy) { prob.rhs(t, y, dy); }, jac);
  Vec y = prob.exact(t0);
  solver.reset(t0, y.data(), t1);
  double t = t0;
  for (int guard = 0; guard < 200000 && t != t1; ++guard) {
    t = solver.step(y.data());
    if (dense != nullptr) dense->append(solver.last_step_piece());
  }
  if (dense != nullptr) dense->finalize();
  run.y_end = y;
  run.t_end = t;
  run.steps = solver.num_steps();
  return run;
}

struct CvodeCase {
  Method method;
  bool jacobian;
  const char* label;
};
const CvodeCase kCvodeCases[] = {
    {Method::BDF, false, "bdf"}, {Method::BDF, true, "bdf+jac"}, {Method::Adams, false, "adams"}};

TEST(Cvode, EndPointAndDenseOutputAgainstExactSolutions) {
  // atol small enough that the relative tolerance governs everywhere (|y| >= e^-10 here), so
  // the errors can be compared with rtol alone.
  for (const LinearProblem& prob : {decay(), oscillator()}) {
    for (const CvodeCase& c : kCvodeCases) {
      for (bool backward : {false, true}) {
        double previous_error = 0.0;
        for (double rtol : {1e-7, 1e-10}) {
          const double atol = rtol * 1e-7;
          const double t0 = backward ? 10.0 : 0.0, t1 = backward ? 0.0 : 10.0;
          PiecewisePolynomial dense(prob.dim());
          const CvodeRun run = run_cvode(prob, c.method, c.jacobian, t0, t1, rtol, atol, &dense);
          EXPECT_EQ(run.t_end, t1) << "the last step must land on the stop time";
          const Vec exact_end = prob.exact(t1);
          const double end_error = max_abs(run.y_end - exact_end) / max_abs(exact_end);
          EXPECT_NEAR(dense.t_min(), 0.0, 1e-9);
          EXPECT_NEAR(dense.t_max(), 10.0, 1e-9);
          EXPECT_EQ(dense.num_pieces(), static_cast<std::size_t>(run.steps));
          // (a) Global: the dense output against the exact solution at arbitrary times.
          hinf_ref::Rng rng(11);
          std::vector<double> times{0.0, 10.0};
          for (int k = 0; k < 2000; ++k) times.push_back(rng.uniform(0.0, 10.0));
          double dense_error = 0.0;
          for (double t : times) {
            Vec y(prob.dim());
            dense.eval(t, y.data());
            const Vec exact = prob.exact(t);
            dense_error = std::max(dense_error, max_abs(y - exact) / max_abs(exact));
          }
          // (b) Local: inside each piece the interpolant must follow the exact flow,
          // y(t_a) = exp(A (t_a - t_b)) y(t_b), free of the error accumulated before the step.
          const std::vector<double> knots = dense.breakpoints();
          double local_error = 0.0;
          for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
            const double h = knots[k + 1] - knots[k];
            const double ta = knots[k] + 0.1 * h, tb = knots[k] + 0.9 * h;
            Vec ya(prob.dim()), yb(prob.dim());
            dense.eval(ta, ya.data());
            dense.eval(tb, yb.data());
            const Vec predicted = prob.flow(ta - tb) * yb;
            local_error = std::max(local_error, max_abs(ya - predicted) / max_abs(ya));
          }
          std::printf("[cvode] %-10s %-8s %-8s rtol %.0e: end rel. error %.2e (%.1f rtol), "
                      "dense max rel. error %.2e (%.1f rtol), within-step %.2e (%.2f rtol), "
                      "%ld steps\n",
                      prob.name.c_str(), c.label, backward ? "backward" : "forward", rtol,
                      end_error, end_error / rtol, dense_error, dense_error / rtol, local_error,
                      local_error / rtol, run.steps);
          // CVODE controls the local error; over ~10 time constants or 1.6 periods its
          // global error is tens to ~150 rtol (BDF at rtol 1e-10).
          EXPECT_LT(end_error, 400.0 * rtol) << prob.name << " " << c.label;
          EXPECT_LT(dense_error, 400.0 * rtol) << prob.name << " " << c.label;
          EXPECT_LT(local_error, 10.0 * rtol) << prob.name << " " << c.label;
          if (previous_error > 0.0) {
            EXPECT_LT(end_error, previous_error / 20.0) << "tolerance 1000x tighter";
          }
          previous_error = end_error;
          if (c.jacobian) {
            EXPECT_GT(run.jac_calls, 0) << "the user Jacobian was never called";
          }
        }
      }
    }
  }
}

TEST(Cvode, AdvanceInterpolatesToRequestedTimes) {
  const LinearProblem prob = oscillator();
  for (const CvodeCase& c : kCvodeCases) {
    hinf::Cvode solver(2, c.method, 1e-9, 1e-11, 100000,
                       [&](double t, const double* y, double* dy) { prob.rhs(t, y, dy); });
    Vec y = prob.y_init;
    solver.reset(0.0, y.data(), 7.0);
    for (double t_out = 0.35; t_out <= 7.0 + 1e-12; t_out += 0.35) {
      const double t = solver.advance(std::min(t_out, 7.0), y.data());
      EXPECT_EQ(t, std::min(t_out, 7.0));
      EXPECT_LT(max_abs(y - prob.exact(t)), 1e-7) << c.label << " t = " << t;
    }
  }
}

TEST(Cvode, StiffProblemWithBdf) {
  const LinearProblem prob = stiff();
  const double rtol = 1e-8, atol = 1e-12;
  for (bool jacobian : {false, true}) {
    PiecewisePolynomial dense(2);
    const CvodeRun run = run_cvode(prob, Method::BDF, jacobian, 0.0, 5.0, rtol, atol, &dense);
    const Vec exact = prob.exact(5.0);
    const double end_error = max_abs(run.y_end - exact) / max_abs(exact);
    // Dense output after the fast transient (t >= 1e-3, where e^-1e4 t < e^-10).
    double dense_error = 0.0;
    for (double t = 1e-3; t <= 5.0; t += 0.01) {
      Vec y(2);
      dense.eval(t, y.data());
      const Vec ex = prob.exact(t);
      dense_error = std::max(dense_error, max_abs(y - ex) / max_abs(ex));
    }
    std::printf("[cvode] stiff bdf%s: end rel. error %.2e (%.1f rtol), dense rel. error %.2e, "
                "%ld steps, %ld user-Jacobian calls\n",
                jacobian ? "+jac" : "    ", end_error, end_error / rtol, dense_error, run.steps,
                run.jac_calls);
    EXPECT_LT(end_error, 100.0 * rtol);
    EXPECT_LT(dense_error, 100.0 * rtol);
    // An explicit method would need about 5 * 1e4 / 3 steps; BDF takes a few hundred.
    EXPECT_LT(run.steps, 2000);
    if (jacobian) {
      EXPECT_GT(run.jac_calls, 0);
    }
  }
}

TEST(Cvode, RejectsExplicitMethod) {
  EXPECT_THROW(hinf::Cvode(1, Method::ERK, 1e-8, 1e-10, 1000,
                           [](double, const double*, double* dy) { dy[0] = 0.0; }),
               hinf::InputError);
}

TEST(Cvode, ExceptionFromRhsPropagates) {
  for (const CvodeCase& c : kCvodeCases) {
    hinf::Cvode::Jacobian jac = nullptr;
    if (c.jacobian) jac = [](double, const double*, const double*, double* J) { J[0] = -1.0; };
    hinf::Cvode solver(1, c.method, 1e-8, 1e-10, 100000,
                       [](double t, const double* y, double* dy) {
                         if (t > 0.5) throw std::runtime_error("user rhs failed on purpose");
                         dy[0] = -y[0];
                       },
                       jac);
    double y = 1.0;
    solver.reset(0.0, &y, 2.0);
    try {
      solver.advance(2.0, &y);
      FAIL() << c.label << ": no exception";
    } catch (const hinf::HinfError& e) {
      FAIL() << c.label << ": the user's exception was replaced by " << e.what();
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "user rhs failed on purpose") << c.label;
    }
  }
}

TEST(Cvode, ExceptionFromJacobianPropagates) {
  hinf::Cvode solver(
      1, Method::BDF, 1e-8, 1e-10, 100000, [](double, const double* y, double* dy) { dy[0] = -y[0]; },
      [](double, const double*, const double*, double*) { throw std::out_of_range("jacobian"); });
  double y = 1.0;
  solver.reset(0.0, &y, 1.0);
  EXPECT_THROW(solver.advance(1.0, &y), std::out_of_range);
}

TEST(Cvode, NanRhsEndsInSolverError) {
  for (const CvodeCase& c : kCvodeCases) {
    for (double t_bad : {-1.0, 0.5}) {  // NaN from the start, or from t = 0.5 on
      hinf::Cvode solver(1, c.method, 1e-8, 1e-10, 100000,
                         [t_bad](double t, const double* y, double* dy) {
                           dy[0] = t > t_bad ? kNaN : -y[0];
                         });
      double y = 1.0;
      solver.reset(0.0, &y, 2.0);
      try {
        solver.advance(2.0, &y);
        FAIL() << c.label << ": NaN right-hand side accepted";
      } catch (const hinf::SolverError& e) {
        EXPECT_FALSE(e.flag().empty());
        EXPECT_LE(e.t(), std::max(t_bad, 0.0) + 1e-6) << c.label << ": " << e.what();
      }
    }
  }
}

TEST(Cvode, TooManyStepsIsASolverError) {
  hinf::Cvode solver(1, Method::Adams, 1e-10, 1e-12, 10,
                     [](double t, const double*, double* dy) { dy[0] = std::cos(10.0 * t); });
  double y = 0.0;
  solver.reset(0.0, &y, 100.0);
  EXPECT_THROW(solver.advance(100.0, &y), hinf::SolverError);
}

// CVODE counts max_steps per CVode() call; in one-step mode every call is one step, so the
// wrapper must count across calls or a collapsing step size loops without end.
TEST(Cvode, TooManyStepsIsASolverErrorInOneStepMode) {
  hinf::Cvode solver(1, Method::Adams, 1e-10, 1e-12, 10,
                     [](double t, const double*, double* dy) { dy[0] = std::cos(10.0 * t); });
  double y = 0.0;
  solver.reset(0.0, &y, 100.0);
  int calls = 0;
  try {
    while (calls < 1000) {
      solver.step(&y);
      ++calls;
    }
    FAIL() << "1000 steps taken with max_steps = 10";
  } catch (const hinf::SolverError& e) {
    EXPECT_EQ(calls, 10);
    EXPECT_EQ(e.flag(), "CV_TOO_MUCH_WORK");
  }
  // The budget spans restarts: a loop that resets the solver (one restart per noise sample,
  // say) cannot exceed max_steps either.
  solver.reset(0.0, &y, 100.0);
  EXPECT_THROW(solver.step(&y), hinf::SolverError);
}

TEST(Cvode, MaxStepsBoundsAdvanceAcrossOutputTimes) {
  // CVODE's own limit counts per CVode() call: 100 output times would allow 100 x max_steps.
  hinf::Cvode solver(1, Method::Adams, 1e-10, 1e-12, 50,
                     [](double t, const double*, double* dy) { dy[0] = std::cos(10.0 * t); });
  double y = 0.0;
  solver.reset(0.0, &y, 100.0);
  int outputs = 0;
  try {
    for (; outputs < 100; ++outputs) solver.advance(outputs + 1.0, &y);
    FAIL() << "100 s of a 10 rad/s oscillation at rtol 1e-10 in 50 steps";
  } catch (const hinf::SolverError& e) {
    EXPECT_EQ(e.flag(), "CV_TOO_MUCH_WORK") << e.what();
    EXPECT_LE(solver.num_steps(), 50);
  }
  EXPECT_LT(outputs, 100);
}

TEST(Dopri5, MaxStepsBoundsTheStepperOverAllCalls) {
  // Many short integrate() calls (one per hold interval) share one budget.
  hinf::Dopri5 stepper(1, 1e-10, 1e-12, 200);
  double y = 0.0;
  int calls = 0;
  try {
    for (; calls < 1000; ++calls)
      stepper.integrate([](double t, const double*, double* dy) { dy[0] = std::cos(10.0 * t); }, calls * 0.1,
                        (calls + 1) * 0.1, &y, [](const hinf::DensePiece&) {});
    FAIL() << "1000 intervals within 200 steps";
  } catch (const hinf::SolverError& e) {
    EXPECT_EQ(e.flag(), "TOO_MUCH_WORK");
  }
  EXPECT_LE(stepper.stats().steps + stepper.stats().rejected, 200);
  EXPECT_LT(calls, 1000);
}

}  // namespace
