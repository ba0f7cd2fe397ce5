// gamma* (paper eq. 14), the first conjugate point of the GRDE (13), and the smallest gamma of
// the output-feedback design (paper §4: GRDE, filter Riccati equation (36), coupling
// rho(Sigma Z) < gamma^2), against independent truth (references.hpp):
//   * scalar LTI systems: the conjugate time is known in closed form, so gamma* for a horizon T
//     is the root of tau_c(gamma) = T (bisection here); the scalar filter (36) and the coupling
//     sigma(t) z(t) < gamma^2 have closed forms too;
//   * long horizons: the infinite-horizon full-information H-infinity level, from the game
//     Hamiltonian's eigenvalues and stable invariant subspace (bisection);
//   * the paper's ship: the inverse W = Z^-1, integrated backward by an RK4 of this file, whose
//     smallest eigenvalue crosses zero exactly at a conjugate point;
//   * the search itself: monotone, consistent trials, reproducible, the same answer with any
//     number of threads, bad options and brackets as InputErrors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hinf/control/analysis.hpp"
#include "hinf/control/backstepping.hpp"
#include "hinf/control/cascade.hpp"
#include "hinf/control/controller.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::GammaCondition;
using hinf::GammaStarOptions;
using hinf::GammaStarResult;
using hinf::Mat;
using hinf::Method;
using hinf::SolverOptions;
using hinf::Vec;
using hinf_ref::kInf;

const Method kMethods[] = {Method::Auto, Method::BDF, Method::Adams, Method::ERK};

Mat m11(double x) { return Mat::Constant(1, 1, x); }

SolverOptions solver(Method method) {
  SolverOptions o;
  o.method = method;
  return o;
}

// dq/dt = a q + b u + d w (and y = c q + noise when c is given) along q_d = 0, u_d = 0.
hinf::TrajectoryPtr scalar_trajectory(double a, double b, double d, double T, double c = NAN) {
  auto model = std::make_shared<const hinf::LinearModel>(m11(a), m11(b), m11(d), std::isnan(c) ? Mat() : m11(c));
  return std::make_shared<const hinf::Trajectory>(model, Vec::Zero(1), hinf::VectorSignal::zeros(1), 0.0, T);
}

hinf::TrajectoryPtr lti_trajectory(const Mat& A, const Mat& B, const Mat& D, double T) {
  auto model = std::make_shared<const hinf::LinearModel>(A, B, D);
  return std::make_shared<const hinf::Trajectory>(model, Vec::Zero(A.rows()),
                                                  hinf::VectorSignal::zeros(static_cast<int>(B.cols())), 0.0, T);
}

// ======================================================================= scalar closed forms

// (a, b, d, q, qf, T) of dq/dt = a q + b u + d w with Q = q, Qf = qf on [0, T]. Backward time
// tau = T - t: dz/dtau = 2 a z + q - s z^2, s = b^2 - d^2 / gamma^2.
struct ScalarCase {
  const char* label;
  double a, b, d, q, qf, T;
  double tau(double gamma) const { return hinf_ref::scalar_escape_tau(a, b * b - d * d / (gamma * gamma), q, qf); }
  // The gamma with tau_c(gamma) = T: tau_c increases with gamma (a larger gamma makes S larger
  // and z smaller), from 0 to inf below d / b. Checked monotone on a grid, then bisected.
  double gamma_star() const {
    const double top = b > 0.0 ? d / b * (1.0 - 1e-9) : 1e4;
    double lo = 1e-3, previous = -1.0;
    for (int k = 0; k <= 3000; ++k) {
      const double g = 1e-3 * std::pow(top / 1e-3, k / 3000.0);
      const double t = std::min(tau(g), 1e300);
      EXPECT_GE(t, previous * (1.0 - 1e-12)) << label << ": tau_c not monotone in gamma at " << g;
      previous = t;
      if (t <= T) lo = g;
    }
    EXPECT_LE(tau(1e-3), T) << label;
    EXPECT_GT(tau(top), T) << label;
    return hinf_ref::bisect_threshold([&](double g) { return tau(g) <= T; }, lo, top, 1e-15);
  }
};

const ScalarCase kScalarCases[] = {
    // s < 0 and a^2 + s q < 0 near gamma*: z grows like a tangent.
    {"oscillatory", 0.1, 0.5, 1.0, 1.0, 1.0, 5.0},
    // Unstable a, a^2 + s q > 0: the escape needs k = a - s qf > beta (tanh form).
    {"unstable, real exponent", 1.0, 1.0, 1.0, 1.0, 1.0, 3.0},
    // Stable a: below the infinite-horizon level 1/sqrt(3) the escape time grows without bound
    // as gamma -> 1/sqrt(3), so gamma*(40) is set by an escape only a long horizon sees.
    {"stable, long horizon", -1.0, 1.0, 1.0, 0.5, 0.2, 40.0},
    {"stable, short horizon", -0.5, 0.8, 1.5, 2.0, 0.5, 8.0},
    // b = 0: every gamma has an escape, tau_c -> inf as gamma -> inf; gamma* is large (~42).
    {"no control (b = 0)", 0.3, 0.0, 1.0, 1.0, 1.0, 10.0},
};

// The first zero of x of d/dtau [x; y] = [[-a, s], [q, a]] [x; y], x(0) = 1, y(0) = qf (the
// linear system behind z = y / x), by RK4 with step h and bisection on the last step.
double rk4_first_zero_of_x(double a, double s, double q, double qf, double h, double tau_max) {
  const auto rhs = [&](double, const hinf_ref::Vec& v) {
    hinf_ref::Vec d(2);
    d << -a * v[0] + s * v[1], q * v[0] + a * v[1];
    return d;
  };
  hinf_ref::Vec v(2);
  v << 1.0, qf;
  for (double tau = 0.0; tau < tau_max; tau += h) {
    const hinf_ref::Vec next = hinf_ref::rk4_step(rhs, tau, v, h);
    if (next[0] <= 0.0) {
      double lo = 0.0, hi = h;  // one RK4 step of length theta from v: x(theta) changes sign in (lo, hi]
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (hinf_ref::rk4_step(rhs, tau, v, mid)[0] > 0.0 ? lo : hi) = mid;
      }
      return tau + hi;
    }
    v = next;
  }
  return kInf;
}

TEST(GammaStarScalar, ClosedFormConjugateTimeAgainstRk4) {
  // The reference itself: the closed-form escape time against an RK4 integration of the linear
  // system at h = tau_c / 2000 (RK4 error ~ (h |M|)^4 ~ 1e-12 relative, far below 1e-8).
  for (const ScalarCase& c : kScalarCases) {
    const double g_star = c.gamma_star();
    EXPECT_NEAR(c.tau(g_star), c.T, 1e-9 * c.T) << c.label;
    for (double factor : {0.5, 0.9, 0.99}) {
      const double gamma = factor * g_star, s = c.b * c.b - c.d * c.d / (gamma * gamma);
      const double tau = c.tau(gamma);
      ASSERT_TRUE(std::isfinite(tau)) << c.label;
      const double rk4 = rk4_first_zero_of_x(c.a, s, c.q, c.qf, tau / 2000.0, 2.0 * tau);
      EXPECT_NEAR(rk4, tau, 1e-8 * tau) << c.label << " factor " << factor;
    }
  }
  // The stable long-horizon case: the level 1 / sqrt(b^2 + a^2 / q) (where a^2 + s q = 0) has
  // no escape at all, and gamma*(40) lies just below it.
  const ScalarCase& c = kScalarCases[2];
  const double level = 1.0 / std::sqrt(c.b * c.b + c.a * c.a / c.q);
  EXPECT_TRUE(std::isinf(c.tau(level * (1 + 1e-9))));
  const double g_star = c.gamma_star();
  EXPECT_LT(g_star, level);
  EXPECT_LT(level, 1.01 * g_star);
  const double tau_late = c.tau(0.5 * (g_star + level));
  EXPECT_GT(tau_late, c.T);
  EXPECT_LT(tau_late, kInf);
}

TEST(GammaStarScalar, MatchesTheClosedFormForEveryMethod) {
  for (const ScalarCase& c : kScalarCases) {
    const double exact = c.gamma_star();
    const auto tr = scalar_trajectory(c.a, c.b, c.d, c.T);
    for (Method method : kMethods) {
      GammaStarOptions o;
      o.rtol = 1e-7;
      o.solver = solver(method);
      const GammaStarResult r = hinf::gamma_star(tr, m11(c.q), m11(c.qf), o);
      const std::string where = std::string(c.label) + " " + hinf::to_string(method);
      std::printf("[gamma* scalar] %-24s %-5s: %.10f exact %.10f rel. error %.1e, %zu trials\n", c.label,
                  hinf::to_string(method).c_str(), r.gamma_star, exact, std::abs(r.gamma_star - exact) / exact,
                  r.trials.size());
      ASSERT_TRUE(r.converged) << where;
      EXPECT_EQ(r.binding, GammaCondition::Grde) << where;
      // analysis.hpp: at rtol 1e-7 and the default solver options gamma* is good to 1e-6.
      EXPECT_LT(std::abs(r.gamma_star - exact) / exact, 1e-6) << where;
      EXPECT_EQ(r.gamma_star, r.upper) << where;
      EXPECT_LT(r.lower, r.upper) << where;
      EXPECT_LE(r.upper - r.lower, 1e-7 * r.upper) << where;
      // Where the lower end escapes, the closed form says (within 1e-6 of gamma* it may already
      // say "no escape": t0). The escape time of a scalar Riccati equation is found to ~1e-7 T
      // at the default tolerances (test_riccati); 1e-5 T leaves a margin of 100.
      EXPECT_GE(r.t_escape_lower, 0.0) << where;
      EXPECT_LE(r.t_escape_lower, c.T) << where;
      EXPECT_NEAR(r.t_escape_lower, std::max(0.0, c.T - c.tau(r.lower)), 1e-5 * c.T) << where;
      // Every trial away from gamma* agrees with the closed form: pass/fail and the escape time.
      for (const hinf::GammaTrial& t : r.trials) {
        const double tau = c.tau(t.gamma);
        const bool far = std::abs(t.gamma - exact) > 1e-5 * exact;
        if (far) {
          EXPECT_EQ(t.passed, tau > c.T) << where << " gamma " << t.gamma;
        }
        if (t.passed) {
          EXPECT_TRUE(std::isnan(t.t_escape)) << where;
          EXPECT_EQ(t.condition, GammaCondition::None) << where;
        } else {
          EXPECT_EQ(t.condition, GammaCondition::Grde) << where;
          if (far) {
            EXPECT_NEAR(t.t_escape, c.T - tau, 1e-5 * c.T) << where << " gamma " << t.gamma;
          }
        }
      }
    }
  }
}

TEST(GammaStarScalar, GrdeEscapeTimeMatchesTheClosedForm) {
  for (const ScalarCase& c : kScalarCases) {
    const double exact = c.gamma_star();
    const auto tr = scalar_trajectory(c.a, c.b, c.d, c.T);
    for (Method method : kMethods) {
      const std::string where = std::string(c.label) + " " + hinf::to_string(method);
      for (double factor : {0.5, 0.9, 0.999}) {
        const double gamma = factor * exact;
        const double t_escape = hinf::grde_escape_time(tr, m11(c.q), m11(c.qf), gamma, solver(method));
        EXPECT_NEAR(t_escape, c.T - c.tau(gamma), 1e-5 * c.T) << where << " factor " << factor;
      }
      try {
        hinf::solve_grde(tr, m11(c.q), m11(c.qf), 0.9 * exact, solver(method));
        ADD_FAILURE() << where << ": no ConjugatePointError at 0.9 gamma*";
      } catch (const hinf::ConjugatePointError& e) {
        EXPECT_EQ(e.gamma(), 0.9 * exact) << where;
        EXPECT_NEAR(e.t_escape(), c.T - c.tau(0.9 * exact), 1e-5 * c.T) << where;
      }
      EXPECT_TRUE(std::isnan(hinf::grde_escape_time(tr, m11(c.q), m11(c.qf), 1.001 * exact, solver(method))))
          << where;
    }
  }
}

// ======================================================================= the search itself

const ScalarCase& oscillatory() { return kScalarCases[0]; }

TEST(GammaStarSearch, ThreadsGiveBracketsAroundTheSameGammaAndRunsRepeat) {
  // Other numbers of threads evaluate other k-section points, so the brackets differ, but each
  // holds the exact gamma* (up to the search's accuracy, 1e-6) and they overlap. The same
  // options twice: the same computation, the same trials exactly.
  const ScalarCase& c = oscillatory();
  const double exact = c.gamma_star();
  const auto tr = scalar_trajectory(c.a, c.b, c.d, c.T);
  std::vector<GammaStarResult> results;
  for (int threads : {1, 2, 3, 4}) {
    GammaStarOptions o;
    o.threads = threads;
    o.rtol = 1e-7;
    const GammaStarResult r = hinf::gamma_star(tr, m11(c.q), m11(c.qf), o);
    ASSERT_TRUE(r.converged) << threads;
    EXPECT_LE(r.lower, exact * (1 + 1e-6)) << threads;
    EXPECT_GE(r.upper, exact * (1 - 1e-6)) << threads;
    for (const GammaStarResult& other : results)
      EXPECT_LT(std::max(other.lower, r.lower), std::min(other.upper, r.upper) * (1 + 2e-6)) << threads;
    const GammaStarResult again = hinf::gamma_star(tr, m11(c.q), m11(c.qf), o);
    ASSERT_EQ(again.trials.size(), r.trials.size()) << threads;
    for (std::size_t k = 0; k < r.trials.size(); ++k) {
      EXPECT_EQ(again.trials[k].gamma, r.trials[k].gamma) << threads << " trial " << k;
      EXPECT_EQ(again.trials[k].passed, r.trials[k].passed) << threads << " trial " << k;
    }
    EXPECT_EQ(again.gamma_star, r.gamma_star);
    EXPECT_EQ(again.lower, r.lower);
    results.push_back(r);
  }
}

// The InputError that f throws, with its message; fails the test when f throws nothing else.
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const hinf::InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an InputError: " << e.what();
    return "";
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(GammaStarSearch, BadOptionsAreInputErrors) {
  struct Bad {
    const char* words;
    void (*set)(GammaStarOptions&);
  };
  const Bad cases[] = {
      {"empty or inverted", [](GammaStarOptions& o) { o.lower = 2.0, o.upper = 1.0; }},
      {"empty or inverted", [](GammaStarOptions& o) { o.lower = 1.5, o.upper = 1.5; }},
      {"empty or inverted", [](GammaStarOptions& o) { o.lower = 1.0; }},  // lower > 0 = upper
      {">= 0", [](GammaStarOptions& o) { o.lower = -1.0, o.upper = 2.0; }},
      {">= 0", [](GammaStarOptions& o) { o.upper = -2.0; }},
      {"finite", [](GammaStarOptions& o) { o.upper = kInf; }},
      {"finite", [](GammaStarOptions& o) { o.upper = NAN; }},
      {"rtol", [](GammaStarOptions& o) { o.rtol = 0.0; }},
      {"rtol", [](GammaStarOptions& o) { o.rtol = -1e-3; }},
      {"rtol", [](GammaStarOptions& o) { o.rtol = 1.0; }},
      {"rtol", [](GammaStarOptions& o) { o.rtol = NAN; }},
      {"max_evaluations", [](GammaStarOptions& o) { o.max_evaluations = 1; }},
      {"threads", [](GammaStarOptions& o) { o.threads = 0; }},
      {"rtol", [](GammaStarOptions& o) { o.solver.rtol = 0.5; }},  // the solver's options too
  };
  const ScalarCase& c = oscillatory();
  const auto tr = scalar_trajectory(c.a, c.b, c.d, c.T);
  const auto measured = scalar_trajectory(c.a, c.b, c.d, c.T, 1.0);
  for (const Bad& bad : cases) {
    GammaStarOptions o;
    bad.set(o);
    for (const std::string& message :
         {input_error([&] { o.validate(); }), input_error([&] { hinf::gamma_star(tr, m11(1.0), m11(1.0), o); }),
          input_error([&] {
            hinf::gamma_star_output_feedback(measured, m11(1.0), m11(1.0), m11(1.0), m11(1.0), o);
          })})
      EXPECT_NE(message.find(bad.words), std::string::npos) << "'" << bad.words << "' not in: " << message;
  }
  GammaStarOptions fine;
  EXPECT_NO_THROW(fine.validate());
}

TEST(GammaStarSearch, BracketEndsMustFailAndPass) {
  const ScalarCase& c = oscillatory();
  const double exact = c.gamma_star();  // 1.8488
  const auto tr = scalar_trajectory(c.a, c.b, c.d, c.T);
  auto with = [](double lower, double upper) {
    GammaStarOptions o;
    o.lower = lower;
    o.upper = upper;
    o.rtol = 1e-7;
    return o;
  };
  EXPECT_NE(input_error([&] { hinf::gamma_star(tr, m11(c.q), m11(c.qf), with(0.5, 1.5)); }).find("raise the upper end"),
            std::string::npos);
  EXPECT_NE(input_error([&] { hinf::gamma_star(tr, m11(c.q), m11(c.qf), with(0.0, 1.5)); }).find("raise the upper end"),
            std::string::npos);
  EXPECT_NE(input_error([&] { hinf::gamma_star(tr, m11(c.q), m11(c.qf), with(2.0, 3.0)); }).find("lower the lower end"),
            std::string::npos);
  // A valid bracket is used as given: its ends are the first two trials.
  GammaStarResult r = hinf::gamma_star(tr, m11(c.q), m11(c.qf), with(1.0, 3.0));
  ASSERT_GE(r.trials.size(), 2u);
  EXPECT_EQ(r.trials[0].gamma, 1.0);
  EXPECT_FALSE(r.trials[0].passed);
  EXPECT_EQ(r.trials[1].gamma, 3.0);
  EXPECT_TRUE(r.trials[1].passed);
  EXPECT_LT(std::abs(r.gamma_star - exact) / exact, 1e-6);
  // upper only (lower = 0 stands for "fails"): no evaluation at 0.
  r = hinf::gamma_star(tr, m11(c.q), m11(c.qf), with(0.0, 3.0));
  EXPECT_EQ(r.trials[0].gamma, 3.0);
  for (const hinf::GammaTrial& t : r.trials) EXPECT_GT(t.gamma, 0.0);
  EXPECT_LT(std::abs(r.gamma_star - exact) / exact, 1e-6);
}

TEST(GammaStarSearch, MaxEvaluationsReachedIsNotConvergedButStillABracket) {
  const ScalarCase& c = oscillatory();
  const double exact = c.gamma_star();
  GammaStarOptions o;
  o.rtol = 1e-9;
  o.max_evaluations = 6;
  const GammaStarResult r = hinf::gamma_star(scalar_trajectory(c.a, c.b, c.d, c.T), m11(c.q), m11(c.qf), o);
  EXPECT_FALSE(r.converged);
  EXPECT_LE(r.trials.size(), 6u);
  EXPECT_LT(r.lower, exact);
  EXPECT_LT(exact, r.upper);
  EXPECT_EQ(r.upper, r.gamma_star);
  EXPECT_GT(r.upper - r.lower, 1e-9 * r.upper);
}

TEST(GammaStarSearch, EveryGammaPassesWithoutDisturbance) {
  // D = 0: S = B B' whatever gamma, no conjugate point ever: gamma* = 0.
  Mat A(2, 2), B(2, 1);
  A << 0.5, 1.0, 0.0, -1.0;
  B << 0.0, 1.0;
  const GammaStarResult r = hinf::gamma_star(lti_trajectory(A, B, Mat::Zero(2, 1), 5.0), Mat::Identity(2, 2),
                                             Mat::Identity(2, 2));
  EXPECT_EQ(r.gamma_star, 0.0);
  EXPECT_EQ(r.lower, 0.0);
  EXPECT_TRUE(r.converged);
  for (const hinf::GammaTrial& t : r.trials) EXPECT_TRUE(t.passed);
}

// ======================================================================= long horizons

TEST(HinfLevelReference, ScalarClosedForms) {
  // Stable a: the Hamiltonian eigenvalues +-sqrt(a^2 + s q) reach the imaginary axis at
  // gamma = d / sqrt(b^2 + a^2 / q). Unstable a: the stabilizing root x = (a + sqrt(a^2 + s q))
  // / s goes through infinity at s = 0 (gamma = d / b) and comes back negative while the
  // Hamiltonian stays hyperbolic, so a test of the imaginary axis alone would give 0.894, not 2.
  // The reference bisects to 1e-13; its own tests move the level by ~1e-12 at most: 1e-10.
  double a = -1.0, b = 1.0, d = 1.0, q = 0.5;
  EXPECT_NEAR(hinf_ref::full_information_hinf_level(m11(a), m11(b), m11(d), m11(q)),
              d / std::sqrt(b * b + a * a / q), 1e-10);
  a = 0.5, b = 1.0, d = 2.0, q = 1.0;
  const double level = hinf_ref::full_information_hinf_level(m11(a), m11(b), m11(d), m11(q));
  EXPECT_NEAR(level, d / b, 1e-10 * d / b);
  const double s = b * b - d * d / (0.999 * level * 0.999 * level);
  const hinf_ref::AreSolution below = hinf_ref::stabilizing_are(m11(a), m11(s), m11(q));
  ASSERT_TRUE(below.ok);  // hyperbolic, stabilizing ...
  EXPECT_LT(below.X(0, 0), 0.0);  // ... but not >= 0
  EXPECT_LT(d / std::sqrt(b * b + a * a / q), 0.9 * level);
}

struct LongHorizonCase {
  const char* label;
  std::uint64_t seed;
  double abscissa, T;
  std::vector<Method> methods;
};

TEST(GammaStarLongHorizon, ApproachesTheInfiniteHorizonLevel) {
  // With Qf small, Z(t) grows monotonically backward, gamma*(T) increases with T and tends to
  // the infinite-horizon level of the game ARE (3 states, 1 input, 2 disturbances, Q > 0).
  // Measured (gamma*(T) - level) / level: -3.2e-4 and -1.7e-5 (stable; the gap closes like
  // 1/T^2), +3.7e-7 (unstable: there the level is where X1 becomes singular).
  const LongHorizonCase cases[] = {
      {"stable seed 1", 1, -0.5, 200.0, {Method::BDF}},
      {"stable seed 3", 3, -0.5, 200.0, {Method::ERK}},
      {"unstable seed 2", 2, 0.5, 40.0, {Method::BDF, Method::ERK}},
  };
  for (const LongHorizonCase& c : cases) {
    const hinf_ref::Lti s = hinf_ref::random_lti(c.seed, 3, 1, 2, c.abscissa);
    const double level = hinf_ref::full_information_hinf_level(s.A, s.B, s.D, s.Q);
    ASSERT_TRUE(std::isfinite(level) && level > 0.0) << c.label;
    // The reference's solution just above its level: an ARE solution (residual at round-off
    // times |X|^2 |S|), stabilizing and positive semidefinite.
    {
      const double gamma = 1.001 * level;
      const Mat S = s.B * s.B.transpose() - s.D * s.D.transpose() / (gamma * gamma);
      const hinf_ref::AreSolution are = hinf_ref::stabilizing_are(s.A, S, s.Q);
      ASSERT_TRUE(are.ok) << c.label;
      const Mat& X = are.X;
      const Mat residual = s.A.transpose() * X + X * s.A + s.Q - X * S * X;
      EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-9 * std::max(1.0, X.cwiseAbs().maxCoeff() * X.cwiseAbs().maxCoeff()))
          << c.label;
      EXPECT_LT(hinf_ref::spectral_abscissa(s.A - S * X), 0.0) << c.label;
    }
    const Mat Qf = 1e-3 * Mat::Identity(3, 3);
    for (Method method : c.methods) {
      GammaStarOptions o;
      o.rtol = 1e-6;
      o.solver = solver(method);
      const GammaStarResult longer = hinf::gamma_star(lti_trajectory(s.A, s.B, s.D, c.T), s.Q, Qf, o);
      const GammaStarResult shorter = hinf::gamma_star(lti_trajectory(s.A, s.B, s.D, c.T / 4), s.Q, Qf, o);
      std::printf("[gamma* long horizon] %-15s %-3s: level %.8f, gamma*(T) %.8f (%+.1e), gamma*(T/4) %.8f\n", c.label,
                  hinf::to_string(method).c_str(), level, longer.gamma_star, longer.gamma_star / level - 1.0,
                  shorter.gamma_star);
      ASSERT_TRUE(longer.converged && shorter.converged) << c.label;
      EXPECT_LT(std::abs(longer.gamma_star - level) / level, 1e-3) << c.label;
      // Finite horizons need no more than the infinite one, and a longer horizon no less than a
      // shorter one (up to the search's accuracy, 1e-6, on each side).
      EXPECT_LE(longer.gamma_star, level * (1 + 2e-6)) << c.label;
      EXPECT_LE(shorter.gamma_star, longer.gamma_star * (1 + 2e-6)) << c.label;
    }
  }
}

// ======================================================================= the paper's ship

hinf::TrajectoryPtr paper_trajectory() {
  Vec q_d0 = Vec::Zero(6);
  q_d0[0] = 1.0;
  const hinf::VectorSignal u_d(std::vector<hinf::Signal>{
      hinf::Signal(1.0), hinf::Signal(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}})});
  return std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::ShipModel>(), q_d0, u_d, 0.0, 40.0);
}

// min over [0, 40] of lambda_min(W), W = Z^-1 of the ship's GRDE (Q = Qf = I) at gamma:
//     dW/dt = A W + W A' + W Q W - S,  W(tf) = Qf^-1,  S = B B' - gamma^-2 D D',
// integrated backward by RK4 (h = 0.0025 s) with A = df/dq at q_d(t) (hand-written Jacobian).
// W is smooth through an escape of Z: Z exists on [t, tf] exactly while lambda_min(W) > 0
// there. Also returns the first time (going backward) where lambda_min(W) <= 0, or NaN.
std::pair<double, double> ship_inverse_riccati(const hinf::Trajectory& tr, double gamma) {
  const Mat B = hinf_ref::ship_B(), D = hinf_ref::ship_D_process();
  const Mat S = B * B.transpose() - D * D.transpose() / (gamma * gamma);
  const auto rhs = [&](double t, const hinf_ref::Vec& w) {
    const Mat W = Eigen::Map<const Mat>(w.data(), 6, 6);
    const Mat A = hinf_ref::ship_jacobian(tr.q_d(t));
    const Mat dW = A * W + W * A.transpose() + W * W - S;
    return hinf_ref::Vec(Eigen::Map<const hinf_ref::Vec>(dW.data(), 36));
  };
  hinf_ref::Vec w = Eigen::Map<const hinf_ref::Vec>(Mat(Mat::Identity(6, 6)).data(), 36);
  const int steps = 16000;
  const double h = -40.0 / steps;
  double lowest = 1.0, first_crossing = NAN;
  for (int k = 0; k < steps; ++k) {
    w = hinf_ref::rk4_step(rhs, 40.0 + k * h, w, h);
    Mat W = Eigen::Map<const Mat>(w.data(), 6, 6);
    const double lambda = Eigen::SelfAdjointEigenSolver<Mat>(0.5 * (W + W.transpose())).eigenvalues()(0);
    lowest = std::min(lowest, lambda);
    if (lambda <= 0.0 && std::isnan(first_crossing)) first_crossing = 40.0 + (k + 1) * h;
  }
  return {lowest, first_crossing};
}

class PaperGammaStar : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    trajectory_ = paper_trajectory();
    result_ = std::make_unique<GammaStarResult>(
        hinf::gamma_star(trajectory_, Mat::Identity(6, 6), Mat::Identity(6, 6), GammaStarOptions()));
  }
  static void TearDownTestSuite() {
    result_.reset();
    trajectory_.reset();
  }
  static hinf::TrajectoryPtr trajectory_;
  static std::unique_ptr<GammaStarResult> result_;
};
hinf::TrajectoryPtr PaperGammaStar::trajectory_;
std::unique_ptr<GammaStarResult> PaperGammaStar::result_;

TEST_F(PaperGammaStar, TrialsAreMonotoneAndConsistent) {
  const GammaStarResult& r = *result_;
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.binding, GammaCondition::Grde);
  EXPECT_EQ(r.gamma_star, r.upper);
  EXPECT_LE(r.upper - r.lower, 1e-7 * r.upper);
  double min_passed = kInf, max_failed = 0.0;
  for (const hinf::GammaTrial& t : r.trials) {
    if (t.passed) {
      min_passed = std::min(min_passed, t.gamma);
      EXPECT_TRUE(std::isnan(t.t_escape));
      EXPECT_EQ(t.condition, GammaCondition::None);
    } else {
      max_failed = std::max(max_failed, t.gamma);
      EXPECT_EQ(t.condition, GammaCondition::Grde);
      EXPECT_GE(t.t_escape, 0.0);
      EXPECT_LE(t.t_escape, 40.0);
      if (t.gamma == r.lower) {
        EXPECT_EQ(t.t_escape, r.t_escape_lower);
      }
    }
  }
  EXPECT_LT(max_failed, min_passed);  // monotone: every pass above every failure
  EXPECT_EQ(r.gamma_star, min_passed);
  EXPECT_EQ(r.lower, max_failed);
  EXPECT_LE(r.trials.size(), 200u);
  // The automatic bracket starts at 1 and doubles: 1 fails, 2 passes.
  ASSERT_GE(r.trials.size(), 2u);
  EXPECT_EQ(r.trials[0].gamma, 1.0);
  EXPECT_FALSE(r.trials[0].passed);
  EXPECT_EQ(r.trials[1].gamma, 2.0);
  EXPECT_TRUE(r.trials[1].passed);
}

TEST_F(PaperGammaStar, ItsCostIsTheTrialsAndAFewSolvesEach) {
  // Each trial counts the right-hand sides its escape test evaluated; the result sums them.
  const GammaStarResult& r = *result_;
  long sum = 0;
  for (const hinf::GammaTrial& t : r.trials) {
    EXPECT_GT(t.rhs_evals, 0);
    sum += t.rhs_evals;
  }
  EXPECT_EQ(r.rhs_evals, sum);
  // Budget: a test near gamma* continues on W (escape_norm) instead of following Z into its
  // peak, so no trial costs much more than a whole solve at a safe gamma: 10 solves each.
  const auto safe = hinf::solve_grde(trajectory_, Mat::Identity(6, 6), Mat::Identity(6, 6), 2.0 * r.gamma_star);
  const long solve = safe->stats().rhs_evals;
  long largest = 0;
  for (const hinf::GammaTrial& t : r.trials) largest = std::max(largest, t.rhs_evals);
  std::printf("[gamma* cost] %zu trials, %ld right-hand sides (%.1f solves at 2 gamma*, the largest trial %.1f)\n",
              r.trials.size(), r.rhs_evals, static_cast<double>(r.rhs_evals) / solve,
              static_cast<double>(largest) / solve);
  EXPECT_LE(largest, 10 * solve);
}

TEST_F(PaperGammaStar, BracketAgainstTheInverseRiccatiEquation) {
  // The search's accuracy is 1e-6 (analysis.hpp). An RK4 of W = Z^-1 (h = 0.0025 s; halving h
  // changes lambda_min(W) by less than 1e-15, and the sampled minimum is converged): 1e-6 below
  // the bracket lambda_min(W) dips below zero (a conjugate point), near the library's escape
  // time; 1e-6 above it stays positive. Near gamma* lambda_min(W) moves by ~0.13 per unit of
  // relative change in gamma, so the margins are ~1e-7, far above the RK4 error.
  const GammaStarResult& r = *result_;
  const auto [low_min, low_cross] = ship_inverse_riccati(*trajectory_, r.lower * (1 - 1e-6));
  const auto [high_min, high_cross] = ship_inverse_riccati(*trajectory_, r.upper * (1 + 1e-6));
  std::printf("[gamma* ship] bracket [%.10f, %.10f], escape at %.4f; RK4 min lambda(W): %.2e below (crossing %.4f), "
              "%.2e above\n",
              r.lower, r.upper, r.t_escape_lower, low_min, low_cross, high_min);
  EXPECT_LT(low_min, 0.0);
  EXPECT_GT(high_min, 0.0);
  EXPECT_TRUE(std::isnan(high_cross));
  // Below gamma* the first zero of lambda_min(W) moves away from the near-escape like
  // sqrt(gamma* - gamma) (0.3 s at 1e-4, measured): ~0.03 s at 1e-6, plus the 0.0025 s grid.
  EXPECT_NEAR(low_cross, r.t_escape_lower, 0.1);
}

TEST_F(PaperGammaStar, DesignJustAboveAndJustBelow) {
  // At the upper end solve_grde succeeds and Z is large (gamma* is where Z stops being
  // bounded); at the lower end it raises ConjugatePointError at the search's escape time. The
  // search's trial is grde_escape_time with the same options, and solve_grde runs the same
  // integration and escape test (it also stores the dense output): the same computation on the
  // same input, equal.
  const GammaStarResult& r = *result_;
  const Mat I = Mat::Identity(6, 6);
  const auto sol = hinf::solve_grde(trajectory_, I, I, r.upper);
  double lo = 0.0, hi = 0.0;
  sol->eigenvalue_bounds(lo, hi);
  EXPECT_GT(lo, 0.0);
  EXPECT_GT(hi, 1e3);
  try {
    hinf::solve_grde(trajectory_, I, I, r.lower);
    ADD_FAILURE() << "no ConjugatePointError at the lower end";
  } catch (const hinf::ConjugatePointError& e) {
    EXPECT_EQ(e.gamma(), r.lower);
    EXPECT_EQ(e.t_escape(), r.t_escape_lower);
  }
  EXPECT_EQ(hinf::grde_escape_time(trajectory_, I, I, r.lower), r.t_escape_lower);
  EXPECT_TRUE(std::isnan(hinf::grde_escape_time(trajectory_, I, I, r.upper)));
}

TEST_F(PaperGammaStar, OtherMethodsAndThreadsGiveOverlappingBrackets) {
  const GammaStarResult& r = *result_;
  for (const auto& [method, threads] : {std::pair{Method::ERK, 1}, std::pair{Method::BDF, 3}}) {
    GammaStarOptions o;
    o.threads = threads;
    o.solver = solver(method);
    const GammaStarResult other = hinf::gamma_star(trajectory_, Mat::Identity(6, 6), Mat::Identity(6, 6), o);
    ASSERT_TRUE(other.converged);
    // Each bracket is within the search's accuracy (1e-6) of gamma*: they overlap within 2e-6.
    EXPECT_LT(std::max(other.lower, r.lower), std::min(other.upper, r.upper) * (1 + 2e-6))
        << hinf::to_string(method) << " threads " << threads;
  }
}

// ======================================================================= output feedback

// Closed-form thresholds of the scalar output-feedback design (Q = q, Qf = qf, C = c,
// Sigma0 = s0): the GRDE's gamma* (tau_c = T), the filter's (forward, dsigma/dt = 2 a sigma +
// d^2 - s_f sigma^2, s_f = c^2/N - q/gamma^2: the same closed forms), and the coupling's: the
// smallest gamma with max_t sigma(t) z(t) < gamma^2 (both closed forms on a grid refined near
// both ends; bisection).
struct ScalarOutputFeedback {
  double a, b, d, c, q, qf, N, s0, T;

  double root(const std::function<double(double)>& tau_of) const {
    double lo = 0.0;
    for (int k = 0; k <= 3000; ++k) {
      const double g = 1e-3 * std::pow(1e6, k / 3000.0);
      if (tau_of(g) > T) {
        if (k == 0) return 0.0;
        return hinf_ref::bisect_threshold([&](double x) { return tau_of(x) <= T; }, lo, g, 1e-15);
      }
      lo = g;
    }
    return kInf;
  }
  double g_grde() const {
    return root([&](double g) { return hinf_ref::scalar_escape_tau(a, b * b - d * d / (g * g), q, qf); });
  }
  double g_filter() const {
    return root([&](double g) { return hinf_ref::scalar_escape_tau(a, c * c / N - q / (g * g), d * d, s0); });
  }
  // max_t sigma(t) z(t) over the times u, and where it is taken.
  std::pair<double, double> max_rho(double g, const std::vector<double>& u) const {
    double worst = 0.0, where = NAN;
    for (double t : u) {
      const double z = hinf_ref::scalar_riccati(a, b * b - d * d / (g * g), q, qf, T - t);
      const double sigma = hinf_ref::scalar_riccati(a, c * c / N - q / (g * g), d * d, s0, t);
      if (z * sigma > worst) worst = z * sigma, where = t;
    }
    return {worst, where};
  }
  bool coupling_ok(double g, const std::vector<double>& u) const { return max_rho(g, u).first < g * g; }
  // A grid of [0, T] refined near both ends.
  std::vector<double> times() const {
    std::vector<double> u;
    for (int k = 0; k <= 40000; ++k) u.push_back(T * k / 40000.0);
    for (int k = 0; k < 4000; ++k) {
      const double e = T * std::pow(10.0, -13.0 + 12.0 * k / 3999.0);
      u.push_back(e);
      u.push_back(T - e);
    }
    return u;
  }
  double g_coupling() const {
    const std::vector<double> u = times();
    double lo = std::max(g_grde(), g_filter()) * (1 + 1e-13), hi = 2.0 * lo;
    while (!coupling_ok(hi, u)) hi *= 2.0;
    if (coupling_ok(lo, u)) return lo;
    return hinf_ref::bisect_threshold([&](double g) { return !coupling_ok(g, u); }, lo, hi, 1e-14);
  }
  hinf::TrajectoryPtr trajectory() const { return scalar_trajectory(a, b, d, T, c); }
};

TEST(GammaStarOutputFeedback, ScalarCasesMatchTheClosedForms) {
  struct Case {
    const char* label;
    ScalarOutputFeedback p;
    double rtol;
    GammaCondition binding;
  };
  const Case cases[] = {
      // Sigma0 = 1: rho = sigma0 z(t0) at t0 exceeds gamma^2 up to 2.2975 (GRDE 1.8488).
      {"coupling at t0", {0.1, 0.5, 1.0, 1.0, 1.0, 1.0, 0.25, 1.0, 5.0}, 1e-7, GammaCondition::Coupling},
      // q = 4 > gamma^2 c^2 / N makes s_f < 0: the filter escapes below 1.3904 (GRDE 0.8727).
      // Yet the filter never binds: as gamma decreases to its threshold Sigma -> inf, so
      // rho(Sigma Z) -> inf and the coupling fails first (here from 1.3988).
      {"filter threshold above the GRDE's", {-1.0, 1.0, 1.0, 1.0, 4.0, 1.0, 1.0, 1.0, 5.0}, 1e-7,
       GammaCondition::Coupling},
      // The same with a tiny Qf and a small Sigma0, so that rho(Sigma Z) is small at both ends
      // (Z(tf) = 1e-9, Sigma(t0) = 1e-3): the coupling still binds, inside the horizon, where the
      // growing Sigma meets Z (t = 4.27).
      {"filter threshold, qf tiny", {-1.0, 1.0, 1.0, 1.0, 4.0, 1e-9, 1.0, 1e-3, 5.0}, 1e-7, GammaCondition::Coupling},
      // Tiny N and Sigma0: Sigma stays ~1e-6, and the coupling's window above the GRDE's gamma*
      // (closed forms: 2e-7 relative) is below the bracket's width 1e-5: the GRDE binds.
      {"tiny N and Sigma0", {0.1, 0.5, 1.0, 1.0, 1.0, 1.0, 2e-12, 2e-12, 5.0}, 1e-5, GammaCondition::Grde},
  };
  for (const Case& c : cases) {
    const ScalarOutputFeedback& p = c.p;
    const double g_grde = p.g_grde(), g_filter = p.g_filter(), g_coupling = p.g_coupling();
    const double expected = std::max({g_grde, g_filter, g_coupling});
    const auto tr = p.trajectory();
    GammaStarOptions o;
    o.rtol = c.rtol;
    const GammaStarResult r = hinf::gamma_star_output_feedback(tr, m11(p.q), m11(p.qf), m11(p.N), m11(p.s0), o);
    std::printf("[gamma* output feedback] %-34s grde %.6f filter %.6f coupling %.6f: library %.8f (%s at t = %.4f)\n",
                c.label, g_grde, g_filter, g_coupling, r.gamma_star, hinf::to_string(r.binding).c_str(),
                r.t_escape_lower);
    ASSERT_TRUE(r.converged) << c.label;
    EXPECT_EQ(r.binding, c.binding) << c.label;
    // The search's accuracy: 1e-6 (analysis.hpp) or its bracket, whichever is wider.
    EXPECT_LT(std::abs(r.gamma_star - expected) / expected, std::max(1e-6, 2 * c.rtol)) << c.label;
    if (c.binding == GammaCondition::Grde) {
      // The closed forms put the coupling's threshold less than the search's accuracy above
      // the GRDE's: no trial can see the difference, the lower end fails by the GRDE.
      EXPECT_LT(g_coupling - g_grde, 1e-6 * g_grde) << c.label;
      // The state-feedback search brackets the same threshold: the brackets overlap, each
      // within the search's accuracy (1e-6, or its bracket 2 rtol) of it.
      const GammaStarResult state = hinf::gamma_star(tr, m11(p.q), m11(p.qf), o);
      ASSERT_TRUE(state.converged) << c.label;
      EXPECT_LT(std::max(r.lower, state.lower), std::min(r.upper, state.upper) * (1 + 2 * std::max(1e-6, 2 * c.rtol)))
          << c.label;
      // The lower end escapes where the closed form says: just after t0, since tau_c(gamma*) =
      // T. Escape times of scalar Riccati equations are found to ~1e-7 T (test_riccati): 1e-5 T.
      EXPECT_GE(r.t_escape_lower, 0.0) << c.label;
      const double tau = hinf_ref::scalar_escape_tau(p.a, p.b * p.b - p.d * p.d / (r.lower * r.lower), p.q, p.qf);
      EXPECT_NEAR(r.t_escape_lower, std::max(0.0, p.T - tau), 1e-5 * p.T) << c.label;
      continue;
    }
    EXPECT_GT(g_coupling, std::max(g_grde, g_filter) * (1 + 10 * o.rtol)) << c.label;
    // The lower end fails where sigma(t) z(t) of the closed forms is largest: at t0 (an end of
    // the interval) or inside it, at a smooth maximum, whose place rho's accuracy (~1e-7
    // relative) fixes only to ~sqrt(1e-7) = 3e-4 of the time scale (1 s here), plus the
    // reference grid's T / 40000: 2e-3 T = 0.01 s, a factor of 20 (measured: 6e-5 s at most).
    const double t_max = p.max_rho(r.lower, p.times()).second;
    EXPECT_NEAR(r.t_escape_lower, t_max, 2e-3 * p.T) << c.label;
    if (g_filter > g_grde) {
      // Between the filter's and the coupling's thresholds the filter is bounded and positive,
      // but the coupling fails; below the filter's, (36) escapes where the closed form says.
      double gamma = 0.5 * (g_filter + g_coupling);
      const auto Z = hinf::solve_grde(tr, m11(p.q), m11(p.qf), gamma);
      const auto Sigma = hinf::solve_filter_riccati(tr, m11(p.N), m11(p.q), gamma, m11(p.s0));
      double lo = 0.0, hi = 0.0;
      Sigma->eigenvalue_bounds(lo, hi);
      EXPECT_GT(lo, 0.0) << c.label;
      EXPECT_GE(hinf::max_rho_sigma_z(*Z, *Sigma).first, gamma * gamma) << c.label;
      gamma = 0.99 * g_filter;
      const double tau = hinf_ref::scalar_escape_tau(p.a, p.c * p.c / p.N - p.q / (gamma * gamma), p.d * p.d, p.s0);
      try {
        hinf::solve_filter_riccati(tr, m11(p.N), m11(p.q), gamma, m11(p.s0));
        ADD_FAILURE() << c.label << ": the filter does not escape at 0.99 of its threshold";
      } catch (const hinf::ConjugatePointError& e) {
        EXPECT_NEAR(e.t_escape(), tau, 1e-5 * p.T) << c.label;
      }
      EXPECT_NEAR(hinf::filter_escape_time(tr, m11(p.N), m11(p.q), gamma, m11(p.s0)), tau, 1e-5 * p.T) << c.label;
    }
  }
}

TEST(GammaStarOutputFeedback, PaperShipIsBoundByTheCouplingAtT0) {
  // N = 0.25 I3, Sigma(t0) = I: rho(Sigma Z) at t0 is lambda_max(Z(t0)), which exceeds gamma^2
  // up to the result: the coupling binds, at t0. Checked 1e-4 below and above with the GRDE
  // and filter solutions and Eigen's eigenvalues of Sigma(t) Z(t) on a grid.
  const auto tr = paper_trajectory();
  const Mat I = Mat::Identity(6, 6), N = 0.25 * Mat::Identity(3, 3);
  const GammaStarResult r = hinf::gamma_star_output_feedback(tr, I, I, N, I);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.binding, GammaCondition::Coupling);
  EXPECT_EQ(r.t_escape_lower, 0.0);
  EXPECT_GT(r.gamma_star, 3.0 * 1.3);  // far above the state-feedback gamma* (1.335)
  for (const auto& [factor, violated] : {std::pair{1 - 1e-4, true}, std::pair{1 + 1e-4, false}}) {
    const double gamma = r.gamma_star * factor;
    const auto Z = hinf::solve_grde(tr, I, I, gamma);
    const auto Sigma = hinf::solve_filter_riccati(tr, N, I, gamma, I);
    double worst = 0.0, where = NAN;
    for (int k = 0; k <= 4000; ++k) {
      const double t = 40.0 * k / 4000;
      const double rho = hinf_ref::spectral_radius(Sigma->Sigma(t) * Z->Z(t));
      if (rho > worst) worst = rho, where = t;
    }
    EXPECT_EQ(worst >= gamma * gamma, violated) << factor;
    EXPECT_EQ(where, 0.0) << factor;
    // At t0 Sigma = I: rho = lambda_max(Z(t0)) (two eigenvalue algorithms: round-off).
    EXPECT_NEAR(Eigen::SelfAdjointEigenSolver<Mat>(Z->Z(0.0)).eigenvalues()(5), worst, hinf_test::kRoundoff * worst);
    // The library's maximum is refined between samples: at least the grid's, and at t0 here.
    const auto [lib_rho, lib_t] = hinf::max_rho_sigma_z(*Z, *Sigma);
    EXPECT_GE(lib_rho, worst * (1 - hinf_test::kRoundoff));
    EXPECT_LE(lib_rho, worst * (1 + 1e-9));
    EXPECT_EQ(lib_t, 0.0);
  }
}

}  // namespace

// ======================================================================= a law's own induced gain

namespace law_gain_tests {

// The scalar LQR law on dq/dt = a q + b u + d w designed with Qf = the stationary LQR solution
// p = (a + sqrt(a^2 + b^2 q)) / b^2, so that Z(t) = p on the whole horizon and K = kappa b p.
// Its closed loop dx/dt = (a - b K) x + d w with z'z = q x^2 + K^2 x^2 has the closed-loop
// Riccati equation dp/dtau = 2 a_cl p + (q + K^2) + (d^2 / gamma^2) p^2 in backward time: the
// scalar form of scalar_escape_tau with s = -d^2 / gamma^2.
struct ScalarLaw {
  double a = 0.3, b = 1.0, d = 1.0, q = 1.0, pf = 1.0, T = 10.0, kappa = 1.0;
  double p() const { return (a + std::sqrt(a * a + b * b * q)) / (b * b); }
  double K() const { return kappa * b * p(); }
  double tau(double gamma) const { return hinf_ref::scalar_escape_tau(a - b * K(), -d * d / (gamma * gamma), q + K() * K(), pf); }
  // The gain: tau(gamma) = T (tau grows with gamma, from small gammas that escape at once).
  double gain() const {
    return hinf_ref::bisect_threshold([&](double g) { return tau(g) <= T; }, 1e-3, 1e3, 1e-15);
  }
  hinf::RiccatiSolutionPtr law() const {
    return hinf::solve_grde(scalar_trajectory(a, b, d, T), m11(q), m11(p()), kInf);
  }
};

TEST(LawGain, ScalarEscapeTimeAndGainMatchTheClosedForm) {
  for (double kappa : {1.0, 2.0}) {
    ScalarLaw c;
    c.kappa = kappa;
    const auto law = c.law();
    // The design is the stationary solution: Z stays at p to the solver's accuracy.
    for (double t : {0.0, 5.0, 10.0}) ASSERT_NEAR(law->Z(t)(0, 0), c.p(), 1e-7 * c.p());
    const double exact = c.gain();
    const hinf::Signal k(kappa);
    for (double factor : {0.5, 0.9, 0.999}) {
      const double gamma = factor * exact;
      EXPECT_NEAR(hinf::law_escape_time(law, m11(c.q), m11(c.pf), gamma, k), c.T - c.tau(gamma), 1e-5 * c.T)
          << "kappa " << kappa << " factor " << factor;
    }
    EXPECT_TRUE(std::isnan(hinf::law_escape_time(law, m11(c.q), m11(c.pf), 1.001 * exact, k))) << kappa;
    GammaStarOptions o;
    o.rtol = 1e-8;
    const GammaStarResult gain = hinf::law_gain(law, m11(c.q), m11(c.pf), k, o);
    ASSERT_TRUE(gain.converged);
    // The search's bracket (1e-8) and Z's error (1e-7 relative, through K) bound the difference.
    EXPECT_NEAR(gain.gamma_star, exact, 1e-6 * exact) << "kappa " << kappa;
    // The stored P at 1.01 times the gain: finite, at its end Qf.
    const auto P = hinf::solve_law_riccati(law, m11(c.q), m11(c.pf), 1.01 * exact, k);
    EXPECT_NEAR(P->value(c.T)(0, 0), c.pf, 1e-9);
    EXPECT_THROW(hinf::solve_law_riccati(law, m11(c.q), m11(c.pf), 0.99 * exact, k), hinf::ConjugatePointError);
  }
}

TEST(LawGain, LongHorizonApproachesTheClosedLoopsHinfNorm) {
  // A static LQR law (Qf = its ARE solution X, so K = B'X all along) on random stable and
  // unstable 3-state systems: over a long horizon its finite-horizon gain tends, from below, to
  // the H-infinity norm of the closed loop (A - BK, D, [Q^1/2; K]), here the level of the game
  // ARE with no control (the bounded-real lemma) from the Hamiltonian's eigenvalues. The gap
  // closes like 1/T^2: measured -3.1e-4 and -2.2e-4 at T = 200, -2.0e-5 and -1.4e-5 at T = 800.
  for (const auto& [seed, abscissa] : {std::pair<int, double>{1, -0.5}, {2, 0.5}}) {
    const hinf_ref::Lti s = hinf_ref::random_lti(seed, 3, 1, 2, abscissa);
    const hinf_ref::AreSolution lqr = hinf_ref::stabilizing_are(s.A, s.B * s.B.transpose(), s.Q);
    ASSERT_TRUE(lqr.ok) << seed;
    const Mat K = s.B.transpose() * lqr.X;
    const double norm = hinf_ref::full_information_hinf_level(s.A - s.B * K, Mat::Zero(3, 1), s.D,
                                                              s.Q + K.transpose() * K);
    ASSERT_TRUE(std::isfinite(norm) && norm > 0.0) << seed;
    const auto law = hinf::solve_grde(lti_trajectory(s.A, s.B, s.D, 800.0), s.Q, lqr.X, kInf);
    GammaStarOptions o;
    o.rtol = 1e-7;
    const GammaStarResult gain = hinf::law_gain(law, s.Q, lqr.X, hinf::Signal(1.0), o);
    std::printf("[law gain long horizon] seed %d: closed-loop norm %.8f, gain on [0, 800] %.8f (%+.1e)\n", seed, norm,
                gain.gamma_star, gain.gamma_star / norm - 1.0);
    EXPECT_LT(std::abs(gain.gamma_star - norm) / norm, 1e-4) << seed;
    EXPECT_LE(gain.gamma_star, norm * (1 + 2e-7)) << seed;
  }
}

TEST(LawGain, TheHinfLawsGainLiesBetweenGammaStarAndItsGamma) {
  // The game's gamma* bounds every state-feedback law's gain from below; the H-infinity law at
  // gamma guarantees its own gain below gamma (paper eq. 15 with kappa = 1).
  const auto trajectory = paper_trajectory();
  const Mat I = Mat::Identity(6, 6);
  const double star = hinf::gamma_star(trajectory, I, I).gamma_star;
  for (double gamma : {1.5, 5.0}) {
    const double gain = hinf::law_gain(hinf::solve_grde(trajectory, I, I, gamma), I, I).gamma_star;
    EXPECT_GE(gain, star * (1 - 2e-6)) << gamma;  // both searches to rtol 1e-7, the escapes to 1e-6
    EXPECT_LT(gain, gamma) << gamma;
  }
  const double lqr = hinf::law_gain(hinf::solve_grde(trajectory, I, I, kInf), I, I).gamma_star;
  EXPECT_GE(lqr, star * (1 - 2e-6));
}

TEST(LawGain, TheHinfLawsClosedLoopSolutionAtItsGammaIsItsDesign) {
  // With K = B'Z, A_cl = A - BB'Z and R = Q + ZBB'Z, the closed-loop equation at the design's
  // gamma becomes the GRDE (13) itself: P = Z (eq. 16 is the law's own worst case). Two
  // integrations of different equations, each to rtol 1e-8: agreement to 1e-6 relative.
  const auto trajectory = paper_trajectory();
  const Mat I = Mat::Identity(6, 6);
  const auto Z = hinf::solve_grde(trajectory, I, I, 5.0);
  const auto P = hinf::solve_law_riccati(Z, I, I, 5.0);
  for (double t : {0.0, 7.3, 20.0, 39.0}) {
    const Mat z = Z->Z(t), p = P->value(t);
    EXPECT_LT((p - z).norm(), 1e-6 * z.norm()) << "t = " << t;
  }
  // Another kappa is another law: P differs.
  const auto P2 = hinf::solve_law_riccati(Z, I, I, 5.0, hinf::Signal(2.0));
  EXPECT_GT((P2->value(0.0) - Z->Z(0.0)).norm(), 1e-3 * Z->Z(0.0).norm());
}

// The H-infinity law seen only through control(): its Jacobian comes from the default central
// differences, not from the design's K = kappa B'Z.
class ControlOnly final : public hinf::Controller {
 public:
  explicit ControlOnly(hinf::RiccatiSolutionPtr design) : law_(std::move(design)) {}
  std::string name() const override { return "control-only"; }
  int n() const override { return law_.n(); }
  int m() const override { return law_.m(); }
  void control(double t, const hinf::ConstVecRef& q, hinf::VecRef u) override { law_.control(t, q, u); }

 private:
  hinf::HinfStateFeedback law_;
};

TEST(LawGain, AControllersLinearizationGivesTheDesignsGain) {
  // The same law two ways: its design's K(t) = B'Z(t), and -du/dq of its control() by central
  // differences along q_d (truncation and round-off ~1e-9 of K). Escape times and gains agree
  // to the searches' tolerance (rtol 1e-7 of gamma, escapes to 1e-6).
  const auto trajectory = paper_trajectory();
  const Mat I = Mat::Identity(6, 6);
  const auto design = hinf::solve_grde(trajectory, I, I, 5.0);
  ControlOnly controller(design);
  const double by_design = hinf::law_gain(design, I, I).gamma_star;
  const double by_controller = hinf::controller_gain(trajectory, controller, I, I).gamma_star;
  std::printf("[law gain] design %.9f, controller %.9f\n", by_design, by_controller);
  EXPECT_NEAR(by_controller, by_design, 2e-6 * by_design);
  const double gamma = 0.99 * by_design;  // below the gain: both escape, at the same time
  const double t_design = hinf::law_escape_time(design, I, I, gamma);
  const double t_controller = hinf::controller_escape_time(trajectory, controller, I, I, gamma);
  ASSERT_FALSE(std::isnan(t_design));
  EXPECT_NEAR(t_controller, t_design, 1e-5 * 40.0);
}

TEST(LawGain, TheShipBaselinesHaveAGainAboveGammaStar) {
  // No state-feedback law does better than the game's gamma*: the cascade and backstepping
  // laws, linearized along the paper's path, have gains above it (finite: their linearized
  // loops have no conjugate point at large gamma).
  const auto trajectory = paper_trajectory();
  const Mat I = Mat::Identity(6, 6);
  const double star = hinf::gamma_star(trajectory, I, I).gamma_star;
  hinf::CascadeController cascade(trajectory);
  hinf::BacksteppingController backstepping(trajectory);
  for (hinf::Controller* law : std::vector<hinf::Controller*>{&cascade, &backstepping}) {
    const GammaStarResult gain = hinf::controller_gain(trajectory, *law, I, I);
    std::printf("[law gain] %s: %.6f (gamma* %.6f)\n", law->name().c_str(), gain.gamma_star, star);
    EXPECT_TRUE(gain.converged) << law->name();
    EXPECT_GE(gain.gamma_star, star * (1 - 2e-6)) << law->name();
    EXPECT_TRUE(std::isfinite(gain.gamma_star)) << law->name();
  }
}

TEST(LawGain, BadInputIsAnInputError) {
  {
    // A controller whose sizes are not the model's.
    const auto trajectory = paper_trajectory();
    ScalarLaw c;
    ControlOnly scalar(c.law());
    EXPECT_THROW(hinf::controller_gain(trajectory, scalar, Mat::Identity(6, 6), Mat::Identity(6, 6)), hinf::InputError);
  }
  ScalarLaw c;
  const auto law = c.law();
  EXPECT_THROW(hinf::law_escape_time(nullptr, m11(1.0), m11(1.0), 2.0), hinf::InputError);
  EXPECT_THROW(hinf::law_escape_time(law, m11(1.0), m11(1.0), 2.0, hinf::Signal(0.0)), hinf::InputError);
  EXPECT_THROW(hinf::law_escape_time(law, m11(1.0), m11(1.0), -1.0), hinf::InputError);
  EXPECT_THROW(hinf::law_gain(law, Mat::Identity(2, 2), m11(1.0)), hinf::InputError);
}

}  // namespace law_gain_tests
