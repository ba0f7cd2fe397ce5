// The Newton systems of BDF on a matrix Riccati equation solved as Lyapunov equations
// (cpp/src/numerics/lyapunov_newton.hpp) against the dense solve of the packed Jacobian, and full
// solves through them against tight references.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "hinf/control/riccati.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/models/model.hpp"
#include "control/riccati_kernel.hpp"
#include "numerics/lyapunov_newton.hpp"
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Mat;
using hinf::Vec;

Mat random_symmetric(hinf_ref::Rng& rng, int n) {
  const Mat G = hinf_ref::normal_matrix(rng, n, n);
  return 0.5 * (G + G.transpose());
}

TEST(LyapunovNewton, SolvesTheNewtonSystemOfTheDenseJacobian) {
  // (I - gamma J) E = B with J the packed Jacobian of dX/dt = s (M'X + XM + R - XSX) at X,
  // built by the dense kernel (riccati_kernel.hpp, itself checked against finite differences in
  // test_riccati), solved by LU: the two solutions agree to the round-off of the two solves,
  // cond(I - gamma J) eps times the solution's size with a margin of 100 (measured at most
  // 1.5 cond eps, printed).
  hinf_ref::Rng rng(20261124);
  for (int n : {1, 2, 3, 5, 8, 13}) {
    for (double sign : {-1.0, 1.0}) {
      const int p = hinf::packed_size(n);
      const Mat M = hinf_ref::normal_matrix(rng, n, n), S = random_symmetric(rng, n), X = random_symmetric(rng, n);
      const double gamma = rng.uniform(0.05, 0.25);
      Mat W(n, n), P(n, n), J(p, p);
      hinf::detail::riccati_jacobian(sign, M, S, X, W, P, J.data());
      const Mat system = Mat::Identity(p, p) - gamma * J;
      const Mat B = random_symmetric(rng, n);
      Vec b(p), dense(p), structured(p);
      hinf::pack_symmetric(B, b.data());
      dense = system.partialPivLu().solve(b);
      hinf::detail::LyapunovNewton newton(n);
      newton.factor(M - S * X);
      ASSERT_TRUE(newton.solve(gamma * sign, b.data(), structured.data()));
      Eigen::JacobiSVD<Mat> svd(system);
      const double cond = svd.singularValues()(0) / svd.singularValues()(p - 1);
      std::printf("[lyapunov newton] n = %2d, sign %+.0f: cond %.1e, difference %.1e cond eps |E|, "
                  "residual %.1e cond eps |B|\n",
                  n, sign, cond,
                  (structured - dense).cwiseAbs().maxCoeff() / (cond * hinf_test::kEps * dense.cwiseAbs().maxCoeff()),
                  (system * structured - b).cwiseAbs().maxCoeff() / (cond * hinf_test::kEps * b.cwiseAbs().maxCoeff()));
      EXPECT_LT((structured - dense).cwiseAbs().maxCoeff(),
                100.0 * cond * hinf_test::kEps * dense.cwiseAbs().maxCoeff())
          << "n = " << n << ", sign = " << sign << ", cond = " << cond;
      // The residual of the structured solution in the dense system.
      EXPECT_LT((system * structured - b).cwiseAbs().maxCoeff(), 100.0 * cond * hinf_test::kEps * b.cwiseAbs().maxCoeff());
      // x may alias b.
      Vec in_place = b;
      ASSERT_TRUE(newton.solve(gamma * sign, in_place.data(), in_place.data()));
      EXPECT_EQ(in_place, structured);
    }
  }
}

TEST(LyapunovNewton, SingularSystemIsReportedNotSolved) {
  // M_cl = diag(1, 2): (I - gamma J) is singular for gamma s (mu_i + mu_j) = 1, e.g. gamma s = 1/2.
  hinf::detail::LyapunovNewton newton(2);
  Mat M_cl(2, 2);
  M_cl << 1.0, 0.0, 0.0, 2.0;
  newton.factor(M_cl);
  Vec b = Vec::Ones(3), x(3);
  EXPECT_FALSE(newton.solve(0.5, b.data(), x.data()));
  EXPECT_TRUE(newton.solve(0.1, b.data(), x.data()));
}

// A random stable LTI system of n states (seeded), as a trajectory from q_d = 0.
hinf::TrajectoryPtr stable_lti(int n, unsigned seed, double horizon, double fast_mode = 0.0) {
  hinf_ref::Rng rng(seed);
  Mat A = hinf_ref::normal_matrix(rng, n, n) / std::sqrt(n);
  const double abscissa = A.eigenvalues().real().maxCoeff();
  A -= (abscissa + 0.5) * Mat::Identity(n, n);
  if (fast_mode > 0.0) A(0, 0) -= fast_mode;  // a mode much faster than the horizon: stiff
  const Mat B = hinf_ref::normal_matrix(rng, n, 2), D = hinf_ref::normal_matrix(rng, n, 2);
  auto model = std::make_shared<hinf::LinearModel>(A, B, D);
  return std::make_shared<const hinf::Trajectory>(model, Vec::Zero(n), hinf::VectorSignal::zeros(2), 0.0,
                                                  horizon);
}

double max_difference(const hinf::RiccatiSolution& a, const hinf::RiccatiSolution& b) {
  double worst = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const double t = a.t0() + (a.tf() - a.t0()) * k / 200.0;
    worst = std::max(worst, (a.Z(t) - b.Z(t)).cwiseAbs().maxCoeff());
  }
  return worst;
}

hinf::SolverOptions method(hinf::Method m, double rtol = 1e-8, double atol = 1e-10) {
  hinf::SolverOptions o;
  o.method = m;
  o.rtol = rtol;
  o.atol = atol;
  return o;
}

TEST(LyapunovNewton, FullSolvesAgreeWithATightReference) {
  // BDF with Lyapunov Newton systems (n > 8) and Auto against Dormand-Prince at rtol 1e-12:
  // Z is of order 1 (Z(tf) = I), BDF's global error at rtol 1e-8 is tens to a hundred rtol, at
  // most ~1e-6 here (measured 6e-9 for BDF, 4e-10 for Auto, printed), so 1e-5 absolute leaves
  // a margin of 10 over that bound.
  for (int n : {12, 24}) {
    const auto trajectory = stable_lti(n, 7 + n, 5.0);
    const Mat Q = Mat::Identity(n, n);
    const auto reference = hinf::solve_grde(trajectory, Q, Q, 8.0, method(hinf::Method::ERK, 1e-12, 1e-14));
    const auto bdf = hinf::solve_grde(trajectory, Q, Q, 8.0, method(hinf::Method::BDF));
    EXPECT_EQ(bdf->stats().method, "bdf (Lyapunov Newton)");
    EXPECT_GT(bdf->stats().jac_evals, 0);
    EXPECT_LT(max_difference(*bdf, *reference), 1e-5) << "n = " << n;
    const auto automatic = hinf::solve_grde(trajectory, Q, Q, 8.0, method(hinf::Method::Auto));
    std::printf("[lyapunov newton] n = %d: max difference of Z from the reference: bdf %.1e, auto %.1e\n", n,
                max_difference(*bdf, *reference), max_difference(*automatic, *reference));
    EXPECT_EQ(automatic->stats().method, "erk") << "not stiff: the explicit method";
    EXPECT_LT(max_difference(*automatic, *reference), 1e-5) << "n = " << n;
  }
}

TEST(LyapunovNewton, AutoSwitchesToTheImplicitMethodOnAStiffProblem) {
  // A mode 1e4 times faster than the horizon (rate -2e3 on a horizon of 5): Dormand-Prince's
  // steps are limited by stability, its stiffness test fires, BDF takes over.
  const int n = 12;
  const auto trajectory = stable_lti(n, 99, 5.0, 2000.0);
  const Mat Q = Mat::Identity(n, n);
  const auto automatic = hinf::solve_grde(trajectory, Q, Q, 8.0, method(hinf::Method::Auto));
  EXPECT_EQ(automatic->stats().method.rfind("erk, then bdf (Lyapunov Newton) from t = ", 0), 0u)
      << automatic->stats().method;
  const auto reference = hinf::solve_grde(trajectory, Q, Q, 8.0, method(hinf::Method::BDF, 1e-11, 1e-13));
  const auto explicit_only = hinf::solve_grde(trajectory, Q, Q, 8.0, method(hinf::Method::ERK));
  std::printf("[lyapunov newton] stiff n = 12: %s; max difference of Z %.1e; "
              "right-hand sides: erk %ld, auto %ld (%.1fx)\n",
              automatic->stats().method.c_str(), max_difference(*automatic, *reference),
              static_cast<long>(explicit_only->stats().rhs_evals),
              static_cast<long>(automatic->stats().rhs_evals),
              static_cast<double>(explicit_only->stats().rhs_evals) / automatic->stats().rhs_evals);
  // Auto at rtol 1e-8 against BDF at rtol 1e-11, Z of order 1: the same bound as above (measured
  // 1.8e-8).
  EXPECT_LT(max_difference(*automatic, *reference), 1e-5);
  // The explicit method needs far more right-hand-side evaluations (its steps are limited by
  // stability): that is what the switch saves (measured 8.6x; 4x asserted).
  EXPECT_GT(explicit_only->stats().rhs_evals, 4 * automatic->stats().rhs_evals);
}

}  // namespace
