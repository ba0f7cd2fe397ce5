// The L-stable SDIRK4 integrator (sdirk4.hpp) on its own, against exact solutions:
//   * order: the error of one step on a linear system falls like h^5, the global error of
//     fixed steps like h^4 (error ratios 32 and 16 when the step is halved);
//   * quadrature: exact for y' = cubic in t, not for a quartic (order exactly 4);
//   * L-stability: one step on y' = lambda y with h lambda -> -inf gives R(h lambda) = O(1 / (h
//     lambda)) -> 0, and the Prothero-Robinson problem with lambda = -1e6 is integrated in tens
//     of steps (an explicit method would need millions), with its fast transient damped;
//   * the max_steps budget over the stepper's whole life.
//
// The linear test system y' = A y, A = [[-1, 2], [-2, -1]] (eigenvalues -1 +- 2i), y0 = (1, 1/2):
// its dyadic entries make the stepper's finite-difference Jacobian exact (the increment is
// sqrt(eps) = 2^-26 when atol = rtol and |y| <= 1, and A (y + 2^-26 e_j) is computed exactly),
// so its simplified Newton iteration solves the linear stage equations to round-off and the
// measured errors are the method's own.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <cstdio>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/numerics/sdirk4.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Sdirk4;
using hinf::StepAction;
using hinf::StepStats;
using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;

Mat test_matrix() {
  Mat A(2, 2);
  A << -1.0, 2.0, -2.0, -1.0;
  return A;
}

Vec test_y0() {
  Vec y(2);
  y << 1.0, 0.5;
  return y;
}

auto linear_rhs(const Mat& A) {
  return [A](double, const double* y, double* dy) {
    Eigen::Map<Vec>(dy, A.rows()) = A * Eigen::Map<const Vec>(y, A.rows());
  };
}

// One step from (0, y0): the stepper's first step is 1e-3 of the interval it is given, and the
// callback stops it there. Returns the step size taken; y holds the end of the step.
double first_step(Sdirk4& stepper, const Mat& A, double h, Vec& y) {
  double taken = 0.0;
  stepper.integrate(linear_rhs(A), 0.0, 1000.0 * h, y.data(),
                    [&](double, double step, const double*, const double*, const double*, const double*) {
                      taken = step;
                      return StepAction::Stop;
                    });
  return taken;
}

TEST(Sdirk4, LocalErrorOfOneStepIsFifthOrder) {
  const Mat A = test_matrix();
  std::vector<double> errors, steps;
  double h = 0.2;
  for (int k = 0; k < 5; ++k, h /= 2) {
    Sdirk4 stepper(2, 1e-2, 1e-2, 100);
    Vec y = test_y0();
    const double taken = first_step(stepper, A, h, y);
    EXPECT_NEAR(taken, h, 1e-14 * h);  // the step asked for, accepted at once
    const Vec exact = Mat((A * taken).exp()) * test_y0();
    errors.push_back((y - exact).norm());
    steps.push_back(taken);
    std::printf("[sdirk4] one step h = %-7.4g error %.3e\n", taken, errors.back());
  }
  // The local error of an order-4 method is C h^5 + O(h^6): the ratio of the errors of h and h/2
  // tends to 2^5; from h = 0.05 on the O(h^6) term moves log2 of it by less than 0.3.
  for (std::size_t k = 3; k < errors.size(); ++k) {
    const double order = std::log(errors[k - 1] / errors[k]) / std::log(steps[k - 1] / steps[k]);
    EXPECT_GT(order, 4.7) << k;
    EXPECT_LT(order, 5.3) << k;
  }
  EXPECT_GT(errors.back(), 1e3 * hinf_test::kEps);  // far above round-off: the ratios mean something
}

// Integrates y' = A y over n_steps fixed steps of size h: a first call stopped after its first
// step (1e-3 of the interval it is given), then one call per step over [t, t + h]. With errors
// far below the tolerance the stepper proposes a larger step and lands on t + h in one step;
// the test checks that it did. Returns |y(T) - exp(A T) y0|.
double fixed_step_error(double h, int n_steps) {
  const Mat A = test_matrix();
  Sdirk4 stepper(2, 1e-2, 1e-2, 10 * n_steps);
  Vec y = test_y0();
  double t = first_step(stepper, A, h, y);
  EXPECT_NEAR(t, h, 1e-14 * h);
  for (int k = 1; k < n_steps; ++k) {
    const long before = stepper.stats().steps;
    stepper.integrate(linear_rhs(A), t, t + h, y.data(),
                      [](double, double, const double*, const double*, const double*, const double*) {});
    t += h;
    EXPECT_EQ(stepper.stats().steps - before, 1) << "h = " << h << ", step " << k;
  }
  EXPECT_EQ(stepper.stats().rejected, 0);
  return (y - Mat((A * t).exp()) * test_y0()).norm();
}

TEST(Sdirk4, GlobalErrorOfFixedStepsIsFourthOrder) {
  std::vector<double> errors;
  for (int n_steps : {16, 32, 64, 128}) {
    errors.push_back(fixed_step_error(2.0 / n_steps, n_steps));
    std::printf("[sdirk4] %3d fixed steps over [0, 2]: error %.3e\n", n_steps, errors.back());
  }
  // Global error C h^4 + O(h^5): ratio -> 2^4 when h is halved.
  for (std::size_t k = 2; k < errors.size(); ++k) {
    const double order = std::log2(errors[k - 1] / errors[k]);
    EXPECT_GT(order, 3.7) << k;
    EXPECT_LT(order, 4.3) << k;
  }
  EXPECT_GT(errors.back(), 1e3 * hinf_test::kEps);
}

// One step of y' = p t^(p-1) from (0, 0): the weights of the method integrate t^(p-1).
double quadrature_step(int power, double h, double& taken) {
  Sdirk4 stepper(1, 1e-2, 1e-2, 100);
  Vec y = Vec::Zero(1);
  stepper.integrate([power](double t, const double*, double* dy) { dy[0] = power * std::pow(t, power - 1); }, 0.0,
                    1000.0 * h, y.data(),
                    [&](double, double step, const double*, const double*, const double*, const double*) {
                      taken = step;
                      return StepAction::Stop;
                    });
  return y[0];
}

TEST(Sdirk4, ExactForCubicQuadratureNotForQuartic) {
  for (double h : {0.5, 0.25, 0.1}) {
    double taken = 0.0;
    // y' = 4 t^3: y = t^4, integrated exactly by an order-4 method (round-off of h^4).
    const double cubic = quadrature_step(4, h, taken);
    EXPECT_NEAR(cubic, std::pow(taken, 4), 100.0 * hinf_test::kEps * std::pow(taken, 4)) << h;
  }
  // y' = 5 t^4: error c h^5 exactly (no higher terms), c != 0: the quadrature order is 4, not 5.
  double h1 = 0.0, h2 = 0.0;
  const double e1 = quadrature_step(5, 0.4, h1) - std::pow(h1, 5);
  const double e2 = quadrature_step(5, 0.2, h2) - std::pow(h2, 5);
  EXPECT_GT(std::abs(e1), 1e-4 * std::pow(h1, 5));
  // c from both steps: equal up to the round-off of y ~ h^5 relative to the error (~1e-2 h^5).
  EXPECT_NEAR(e1 / std::pow(h1, 5), e2 / std::pow(h2, 5), 1e4 * hinf_test::kEps);
}

TEST(Sdirk4, LStableOneStepDampsInfiniteStiffness) {
  // One step of y' = lambda y from y = 1 gives R(z), z = h lambda. L-stability: R(z) -> 0 as
  // z -> -inf, here like 1/z (an A-stable method that is not L-stable, such as the trapezoidal
  // rule, has |R(-inf)| = 1). z R(z) must then be the same constant at z = -1e5 and -1e7 (the
  // next term is O(1/z^2), 1e-5 relative; the stage round-off ~ |h lambda| eps / |R| stays below 1%).
  std::vector<double> zR;
  for (double lambda : {-1e8, -1e10}) {
    Sdirk4 stepper(1, 1e-2, 1e-2, 100);
    Vec y = Vec::Ones(1);
    double taken = 0.0;
    stepper.integrate([lambda](double, const double* x, double* dy) { dy[0] = lambda * x[0]; }, 0.0, 1.0, y.data(),
                      [&](double, double step, const double*, const double*, const double*, const double*) {
                        taken = step;
                        return StepAction::Stop;
                      });
    const double z = lambda * taken;
    std::printf("[sdirk4] z = %.3g: R(z) = %.6e, z R(z) = %.6f\n", z, y[0], z * y[0]);
    EXPECT_LT(std::abs(y[0]), 100.0 / std::abs(z)) << z;
    zR.push_back(z * y[0]);
  }
  EXPECT_NEAR(zR[0], zR[1], 0.02 * std::abs(zR[1]));
}

TEST(Sdirk4, ProtheroRobinsonStiffProblem) {
  // y' = lambda (y - cos t) - sin t, lambda = -1e6: y = cos t + (y0 - 1) e^(lambda t). From
  // y0 = 2 the fast transient dies within 1e-5 s. An explicit method would need |h lambda| < ~3,
  // i.e. ~3e6 steps over [0, 10]; the L-stable method follows the slow solution with steps set
  // by accuracy alone.
  const double lambda = -1e6, rtol = 1e-6, atol = 1e-8;
  Sdirk4 stepper(1, rtol, atol, 20000);
  Vec y = Vec::Constant(1, 2.0);
  double worst = 0.0;
  stepper.integrate([lambda](double t, const double* x, double* dy) { dy[0] = lambda * (x[0] - std::cos(t)) - std::sin(t); },
                    0.0, 10.0, y.data(),
                    [&](double t, double h, const double*, const double*, const double* y1, const double*) {
                      const double t1 = t + h;
                      const double exact = std::cos(t1) + std::exp(lambda * t1);
                      worst = std::max(worst, std::abs(y1[0] - exact));
                    });
  const StepStats& s = stepper.stats();
  std::printf("[sdirk4] Prothero-Robinson: %ld steps, %ld rejected, %ld Jacobians, max error %.2e\n", s.steps,
              s.rejected, s.jac_evals, worst);
  EXPECT_LT(s.steps + s.rejected, 3000);
  // Global error of a tolerance-controlled run: a few tolerances times |y| <= 2; 50 x allows for
  // the accumulation over the run.
  EXPECT_LT(worst, 50.0 * (rtol * 2.0 + atol));
  EXPECT_NEAR(y[0], std::cos(10.0), 50.0 * (rtol + atol));
}

TEST(Sdirk4, MaxStepsBoundsTheStepperOverAllCalls) {
  auto decay = [](double, const double* x, double* dy) { dy[0] = -x[0]; };
  auto nothing = [](double, double, const double*, const double*, const double*, const double*) {};
  {
    Sdirk4 stepper(1, 1e-10, 1e-12, 12);
    Vec y(1);
    y[0] = 1.0;
    try {
      stepper.integrate(decay, 0.0, 10.0, y.data(), nothing);
      FAIL() << "12 steps cannot reach t = 10 at rtol 1e-10";
    } catch (const hinf::SolverError& e) {
      EXPECT_EQ(e.flag(), "TOO_MUCH_WORK");
      EXPECT_GT(e.t(), 0.0);
      EXPECT_LT(e.t(), 10.0);
    }
    EXPECT_EQ(stepper.stats().steps + stepper.stats().rejected, 12);
  }
  {
    // The budget is for the stepper's life: two calls that each fit in it exhaust it together.
    // A probe counts the attempts of a fresh stepper over [0, 1]; the budget is two more, fewer
    // than the next unit interval needs (its steps are ~ (rtol)^(1/4) long).
    Sdirk4 probe(1, 1e-8, 1e-10, 100000);
    Vec y(1);
    y[0] = 1.0;
    probe.integrate(decay, 0.0, 1.0, y.data(), nothing);
    const long first = probe.stats().steps + probe.stats().rejected;
    probe.integrate(decay, 1.0, 2.0, y.data(), nothing);
    ASSERT_GT(probe.stats().steps + probe.stats().rejected - first, 2);

    const long budget = first + 2;
    Sdirk4 stepper(1, 1e-8, 1e-10, budget);
    y[0] = 1.0;
    stepper.integrate(decay, 0.0, 1.0, y.data(), nothing);  // fits
    // rtol 1e-8 over one time constant: a global error of a few 1e-8; 1e-6 is a factor of 30.
    EXPECT_NEAR(y[0], std::exp(-1.0), 1e-6);
    try {
      stepper.integrate(decay, 1.0, 2.0, y.data(), nothing);
      FAIL() << "the second call should exhaust max_steps = " << budget;
    } catch (const hinf::SolverError& e) {
      EXPECT_EQ(e.flag(), "TOO_MUCH_WORK");
      EXPECT_GT(e.t(), 1.0);
      EXPECT_LT(e.t(), 2.0);
    }
    EXPECT_EQ(stepper.stats().steps + stepper.stats().rejected, budget);
  }
}

}  // namespace
