// The GRDE (paper eq. 13), solved backward by solve_grde, against independent truth:
//   * scalar LTI problems: closed-form solutions (derived below) for s > 0, s = 0, s < 0,
//     the algebraic fixed point, and the closed-form escape time of a conjugate point;
//   * matrix LTI problems: the exact solution Z = Y X^-1 of the linear Hamiltonian system
//     (matrix exponential), the GRDE residual with RiccatiSolution::dZdt, symmetry and
//     positive definiteness;
//   * the ship along the paper trajectory: the three methods agree, gain = B'Z, and the
//     fixed-size (n = 6) kernel agrees with the dynamic one through an equivalent 7-state model.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hinf/control/riccati.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/models/fleet.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"
#include "control/riccati_kernel.hpp"  // private (cpp/src): the packed right-hand side and Jacobian
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Mat;
using hinf::Method;
using hinf::SolverOptions;
using hinf::Vec;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const Method kMethods[] = {Method::BDF, Method::Adams, Method::ERK};

SolverOptions options_for(Method method, double rtol = 1e-10, double atol = 1e-12) {
  SolverOptions o;
  o.method = method;
  o.rtol = rtol;
  o.atol = atol;
  return o;
}

// q_d = 0, u_d = 0 for an LTI model: A_e(t) = A.
hinf::TrajectoryPtr lti_trajectory(const Mat& A, const Mat& B, const Mat& D, double t0, double tf) {
  auto model = std::make_shared<const hinf::LinearModel>(A, B, D);
  return std::make_shared<const hinf::Trajectory>(model, Vec::Zero(A.rows()),
                                                  hinf::VectorSignal::zeros(static_cast<int>(B.cols())),
                                                  t0, tf);
}

// ======================================================================= scalar closed form
//
// With tau = tf - t the scalar GRDE -dz/dt = 2 a z + q - s z^2, s = b^2 - d^2/gamma^2, reads
//     dz/dtau = -s z^2 + 2 a z + q,   z(0) = qf.
// s = 0:      z = (qf + q/(2a)) e^{2 a tau} - q/(2a)     (z = qf + q tau when a = 0).
// D = a^2 + s q > 0, lambda = sqrt(D): the roots of -s z^2 + 2 a z + q are z_pm = (a pm lambda)/s
//     and d/dtau ln((z - z_p)/(z - z_m)) = -s (z_p - z_m) = -2 lambda, so with
//     r = (qf - z_p)/(qf - z_m) e^{-2 lambda tau}:  z = (z_p - r z_m) / (1 - r);
//     it escapes where r = 1: tau_c = ln((qf - z_p)/(qf - z_m)) / (2 lambda) if that is > 0.
// D < 0 (only for s < 0): with y = z - a/s, dy/dtau = p y^2 + c, p = -s, c = D/s > 0, so
//     y = sqrt(c/p) tan(omega tau + atan(y0 sqrt(p/c))), omega = sqrt(-D), and it escapes at
//     tau_c = (pi/2 - atan(y0 sqrt(p/c))) / omega.
struct Scalar {
  double a, b, d, gamma, q, qf;
  double s() const { return b * b - (std::isinf(gamma) ? 0.0 : d * d / (gamma * gamma)); }
  double D() const { return a * a + s() * q; }

  double z(double tau) const {
    const double S = s();
    if (S == 0.0) {
      if (a == 0.0) return qf + q * tau;
      return (qf + q / (2 * a)) * std::exp(2 * a * tau) - q / (2 * a);
    }
    const double disc = D();
    if (disc > 0.0) {
      const double lambda = std::sqrt(disc);
      const double zp = (a + lambda) / S, zm = (a - lambda) / S;
      const double r = (qf - zp) / (qf - zm) * std::exp(-2 * lambda * tau);
      return (zp - r * zm) / (1 - r);
    }
    const double p = -S, c = disc / S, omega = std::sqrt(-disc);
    const double y0 = qf - a / S;
    return a / S + std::sqrt(c / p) * std::tan(omega * tau + std::atan(y0 * std::sqrt(p / c)));
  }

  // Escape time in tau (infinity when none).
  double tau_escape() const {
    const double S = s();
    if (S >= 0.0) return kInf;
    const double disc = D();
    if (disc > 0.0) {
      const double lambda = std::sqrt(disc);
      const double zp = (a + lambda) / S, zm = (a - lambda) / S;
      const double ratio = (qf - zp) / (qf - zm);
      const double tau = ratio > 0 ? std::log(ratio) / (2 * lambda) : -1.0;
      return tau > 0 ? tau : kInf;
    }
    const double p = -S, c = disc / S, omega = std::sqrt(-disc);
    return (M_PI / 2 - std::atan((qf - a / S) * std::sqrt(p / c))) / omega;
  }

  // Size of the terms of the closed forms above (qf, q / 2a, z_pm, a / s): the scale of their
  // round-off.
  double terms() const {
    const double S = s();
    double size = 1.0 + std::abs(qf) + (a != 0.0 ? std::abs(q / (2 * a)) : 0.0);
    if (S != 0.0) size += (std::abs(a) + std::sqrt(std::abs(D()))) / std::abs(S);
    return size;
  }

  // Positive root of 0 = 2 a z + q - s z^2 (s > 0): the fixed point of the GRDE.
  double algebraic() const { return (a + std::sqrt(D())) / s(); }

  hinf::TrajectoryPtr trajectory(double t0, double tf) const {
    return lti_trajectory(Mat::Constant(1, 1, a), Mat::Constant(1, 1, b), Mat::Constant(1, 1, d), t0, tf);
  }
};

// The closed form itself satisfies the ODE (central differences) -- guards the test's algebra.
void check_closed_form(const Scalar& c, double tau_max) {
  for (double tau = 0.05; tau < tau_max; tau += tau_max / 17) {
    const double h = 1e-5;
    const double dz = (c.z(tau + h) - c.z(tau - h)) / (2 * h);
    const double z = c.z(tau);
    const double rhs = -c.s() * z * z + 2 * c.a * z + c.q;
    ASSERT_NEAR(dz, rhs, 1e-6 * std::max(1.0, std::abs(rhs))) << "closed form wrong at tau = " << tau;
  }
  ASSERT_NEAR(c.z(0.0), c.qf, hinf_test::kRoundoff * c.terms());
}

struct ScalarCase {
  const char* label;
  Scalar c;
  double t0, tf;
};

const ScalarCase kScalarCases[] = {
    // s = 1 - 0.25/4 = 0.9375 > 0, unstable a.
    {"s>0 unstable a", {0.5, 1.0, 0.5, 2.0, 1.0, 3.0}, 0.0, 5.0},
    // s > 0, stable a, Qf below the fixed point, t0 != 0.
    {"s>0 stable a", {-1.0, 2.0, 1.0, 1.5, 0.3, 0.01}, 2.0, 6.0},
    // LQR limit gamma = inf: s = b^2.
    {"LQR gamma=inf", {1.0, 2.0, 1.0, kInf, 1.0, 0.1}, 0.0, 4.0},
    // s = 0.25 - 1/4 = 0 exactly: the equation is linear.
    {"s=0", {-0.5, 0.5, 1.0, 2.0, 2.0, 0.5}, 0.0, 5.0},
    // s = 0 and a = 0: z = qf + q tau.
    {"s=0 a=0", {0.0, 0.5, 1.0, 2.0, 2.0, 0.5}, 0.0, 3.0},
    // s = 0.25 - 1 = -0.75 < 0, D = 1 - 0.375 > 0, Qf = 1 below the upper root 2.39: no escape.
    {"s<0 no escape", {-1.0, 0.5, 1.0, 1.0, 0.5, 1.0}, 0.0, 6.0},
};

TEST(GrdeScalar, MatchesClosedFormForEveryMethod) {
  hinf_ref::Rng rng(3);
  for (const ScalarCase& sc : kScalarCases) {
    check_closed_form(sc.c, sc.tf - sc.t0);
    ASSERT_TRUE(std::isinf(sc.c.tau_escape())) << sc.label;
    const auto trajectory = sc.c.trajectory(sc.t0, sc.tf);
    for (Method method : kMethods) {
      const auto sol = hinf::solve_grde(trajectory, Mat::Constant(1, 1, sc.c.q),
                                        Mat::Constant(1, 1, sc.c.qf), sc.c.gamma, options_for(method));
      EXPECT_EQ(sol->n(), 1);
      EXPECT_EQ(sol->gamma(), sc.c.gamma);
      // Many times: a uniform grid, random times (between steps), and the ends.
      std::vector<double> times;
      for (int k = 0; k <= 200; ++k) times.push_back(sc.t0 + (sc.tf - sc.t0) * k / 200.0);
      for (int k = 0; k < 300; ++k) times.push_back(rng.uniform(sc.t0, sc.tf));
      double max_rel = 0.0;
      for (double t : times) {
        const double exact = sc.c.z(sc.tf - t);
        const double z = sol->Z(t)(0, 0);
        max_rel = std::max(max_rel, std::abs(z - exact) / std::abs(exact));
      }
      std::printf("[grde scalar] %-14s %-5s: max rel. error %.2e over %zu times (%ld steps)\n",
                  sc.label, hinf::to_string(method).c_str(), max_rel, times.size(),
                  sol->stats().steps);
      EXPECT_LT(max_rel, 1e-7) << sc.label << " " << hinf::to_string(method);
      // Z(tf) = Qf: the first step's polynomial gives back its initial value, up to round-off.
      EXPECT_NEAR(sol->Z(sc.tf)(0, 0), sc.c.qf, hinf_test::kRoundoff * sc.c.qf) << "Z(tf) = Qf";
    }
  }
}

TEST(GrdeScalar, DefaultTolerances) {
  // The defaults (rtol 1e-8) on the first case: an independent sanity check of the defaults.
  const ScalarCase& sc = kScalarCases[0];
  const auto sol = hinf::solve_grde(sc.c.trajectory(sc.t0, sc.tf), Mat::Constant(1, 1, sc.c.q),
                                    Mat::Constant(1, 1, sc.c.qf), sc.c.gamma);
  double max_rel = 0.0;
  for (double t = sc.t0; t <= sc.tf; t += 0.01)
    max_rel = std::max(max_rel, std::abs(sol->Z(t)(0, 0) / sc.c.z(sc.tf - t) - 1.0));
  std::printf("[grde scalar] default options (bdf, rtol 1e-8): max rel. error %.2e\n", max_rel);
  EXPECT_LT(max_rel, 1e-6);
}

TEST(GrdeScalar, AlgebraicFixedPointStaysConstant) {
  for (const ScalarCase& sc : kScalarCases) {
    if (sc.c.s() <= 0.0) continue;
    const double z_bar = sc.c.algebraic();
    ASSERT_GT(z_bar, 0.0);
    const double terms = std::abs(2 * sc.c.a * z_bar) + std::abs(sc.c.q) + std::abs(sc.c.s()) * z_bar * z_bar;
    ASSERT_NEAR(2 * sc.c.a * z_bar + sc.c.q - sc.c.s() * z_bar * z_bar, 0.0, hinf_test::kRoundoff * terms);
    for (Method method : kMethods) {
      const auto sol = hinf::solve_grde(sc.c.trajectory(sc.t0, sc.tf), Mat::Constant(1, 1, sc.c.q),
                                        Mat::Constant(1, 1, z_bar), sc.c.gamma, options_for(method));
      double drift = 0.0;
      for (double t = sc.t0; t <= sc.tf; t += 0.0137)
        drift = std::max(drift, std::abs(sol->Z(t)(0, 0) - z_bar) / z_bar);
      EXPECT_LT(drift, 1e-10) << sc.label << " " << hinf::to_string(method);
      EXPECT_LT(std::abs(sol->dZdt(0.5 * (sc.t0 + sc.tf))(0, 0)), 1e-8);
    }
  }
}

TEST(GrdeScalar, LargeButFiniteIsNotAConjugatePoint) {
  // Z grows far beyond any escape threshold but stays finite: no conjugate point.
  const ScalarCase cases[] = {
      // s = 0, a = 1: z = (qf + q/2) e^{2 tau} - q/2 reaches 1.5 e^30 ~ 1.6e13 at t0.
      {"s=0 growth e^30", {1.0, 0.5, 1.0, 2.0, 1.0, 1.0}, 0.0, 15.0},
      // s = 1e-8 > 0 (LQR, b = 1e-4), a = 1: z saturates at the fixed point ~ 2a/s = 2e8.
      {"s=1e-8 saturating", {1.0, 1e-4, 0.0, kInf, 1.0, 1.0}, 0.0, 20.0},
  };
  for (const ScalarCase& sc : cases) {
    check_closed_form(sc.c, 1.0);
    ASSERT_TRUE(std::isinf(sc.c.tau_escape()));
    for (Method method : kMethods) {
      try {
        const auto sol = hinf::solve_grde(sc.c.trajectory(sc.t0, sc.tf), Mat::Constant(1, 1, sc.c.q),
                                          Mat::Constant(1, 1, sc.c.qf), sc.c.gamma, options_for(method));
        double max_rel = 0.0;
        for (double t = sc.t0; t <= sc.tf; t += 0.01)
          max_rel = std::max(max_rel, std::abs(sol->Z(t)(0, 0) / sc.c.z(sc.tf - t) - 1.0));
        std::printf("[grde large] %-18s %-5s: Z(t0) = %.3e (exact %.3e), max rel. error %.2e\n",
                    sc.label, hinf::to_string(method).c_str(), sol->Z(sc.t0)(0, 0),
                    sc.c.z(sc.tf - sc.t0), max_rel);
        EXPECT_LT(max_rel, 1e-7) << sc.label << " " << hinf::to_string(method);
      } catch (const hinf::ConjugatePointError& e) {
        ADD_FAILURE() << sc.label << " " << hinf::to_string(method)
                      << ": false conjugate point (the exact Z is finite): " << e.what();
      }
    }
  }
}

TEST(GrdeScalar, ConjugatePointEscapeTime) {
  struct EscapeCase {
    const char* label;
    Scalar c;
    double t0, tf;
  };
  const EscapeCase cases[] = {
      // a = 0, s = 1 - 4 = -3, q = qf = 1: z = tan(sqrt(3) tau + pi/3)/sqrt(3),
      // tau_c = (pi/2 - pi/3)/sqrt(3) = pi/(6 sqrt(3)) = 0.3023.
      {"D<0 tan", {0.0, 1.0, 2.0, 1.0, 1.0, 1.0}, 0.0, 1.0},
      // s = -0.75, D = 0.625 > 0 but Qf = 4 above the upper root 2.39: escapes.
      {"D>0 above root", {-1.0, 0.5, 1.0, 1.0, 0.5, 4.0}, 0.0, 6.0},
      // A gamma just below the scalar gamma*: s = 1 - 4/gamma^2 < 0 with a = 0.2, horizon 10.
      {"near gamma*", {0.2, 1.0, 2.0, 1.8, 1.0, 1.0}, 0.0, 10.0},
  };
  EXPECT_NEAR(cases[0].c.tau_escape(), M_PI / (6 * std::sqrt(3.0)), hinf_test::kRoundoff);  // two closed forms
  for (const EscapeCase& ec : cases) {
    const double tau_c = ec.c.tau_escape();
    ASSERT_TRUE(std::isfinite(tau_c)) << ec.label;
    ASSERT_LT(tau_c, ec.tf - ec.t0) << ec.label << ": the escape must lie inside the horizon";
    check_closed_form(ec.c, 0.9 * tau_c);
    const double t_exact = ec.tf - tau_c;
    for (Method method : kMethods) {
      try {
        hinf::solve_grde(ec.c.trajectory(ec.t0, ec.tf), Mat::Constant(1, 1, ec.c.q),
                         Mat::Constant(1, 1, ec.c.qf), ec.c.gamma, options_for(method, 1e-8, 1e-10));
        ADD_FAILURE() << ec.label << " " << hinf::to_string(method) << ": no ConjugatePointError";
      } catch (const hinf::ConjugatePointError& e) {
        const double err = e.t_escape() - t_exact;
        std::printf("[grde escape] %-14s %-5s: t_escape %.10f, exact %.10f, error %.2e\n",
                    ec.label, hinf::to_string(method).c_str(), e.t_escape(), t_exact, err);
        // rtol = 1e-8: the escape time to within 1e-5 (relative to horizons of 1 to 10).
        EXPECT_NEAR(e.t_escape(), t_exact, 1e-5) << ec.label << " " << hinf::to_string(method);
        EXPECT_EQ(e.gamma(), ec.c.gamma);
      }
    }
  }
}

// ======================================================================= matrix LTI problems

// Exact Z(t) of the LTI GRDE: [X; Y](t) = exp(H (t - tf)) [I; Qf], H = [[A, -S], [-Q, -A']],
// Z = Y X^-1 (X' = A X - S Y, Y' = -Q X - A'Y give Z' = Z S Z - Z A - A'Z - Q).
Mat exact_lti_Z(const Mat& A, const Mat& S, const Mat& Q, const Mat& Qf, double t, double tf) {
  const Eigen::Index n = A.rows();
  Mat H(2 * n, 2 * n);
  H << A, -S, -Q, -A.transpose();
  Mat XY0(2 * n, n);
  XY0 << Mat::Identity(n, n), Qf;
  const Mat XY = Mat((H * (t - tf)).exp()) * XY0;
  const Mat X = XY.topRows(n), Y = XY.bottomRows(n);
  const Mat Z = X.transpose().fullPivLu().solve(Y.transpose());  // (Y X^-1)' = X^-T Y'
  return 0.5 * (Z + Z.transpose());
}

struct LtiCase {
  const char* label;
  Mat A, B, D, Q, Qf;
  double gamma, t0, tf;
  Mat S() const {
    Mat s = B * B.transpose();
    if (!std::isinf(gamma)) s -= D * D.transpose() / (gamma * gamma);
    return s;
  }
};

LtiCase lti3() {
  LtiCase c;
  c.label = "3x3";
  c.A.resize(3, 3);
  c.A << 0.2, 1.0, 0.0, -0.5, -0.3, 0.7, 0.1, 0.0, -1.2;
  c.B.resize(3, 2);
  c.B << 1.0, 0.0, 0.5, 0.0, 0.0, -2.0;  // non-unit entries: exercises K = B'Z
  c.D.resize(3, 2);
  c.D << 0.3, 0.0, 0.0, 1.0, 0.2, 0.4;
  c.Q.resize(3, 3);
  c.Q << 2.0, 0.3, 0.0, 0.3, 1.0, -0.2, 0.0, -0.2, 0.5;
  c.Qf.resize(3, 3);
  c.Qf << 1.0, 0.2, 0.1, 0.2, 2.0, 0.0, 0.1, 0.0, 0.7;
  c.gamma = 3.0;
  c.t0 = -1.0;
  c.tf = 4.0;
  return c;
}

LtiCase lti2_singular_Q() {
  LtiCase c;
  c.label = "2x2 Q>=0";
  c.A.resize(2, 2);
  c.A << 0.0, 1.0, -2.0, -0.1;
  c.B = Mat(2, 1);
  c.B << 0.0, 1.0;
  c.D = Mat::Identity(2, 2);
  c.Q = Mat::Zero(2, 2);
  c.Q(0, 0) = 1.0;  // positive semidefinite only
  c.Qf = 0.5 * Mat::Identity(2, 2);
  c.gamma = 4.0;
  c.t0 = 0.0;
  c.tf = 8.0;
  return c;
}

// A 6x6 LTI problem: solve_grde dispatches n == 6 to its fixed-size kernel.
LtiCase lti6() {
  LtiCase c;
  c.label = "6x6";
  hinf_ref::Rng rng(17);
  c.A = Mat::Zero(6, 6);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) c.A(i, j) = 0.4 * rng.uniform(-1.0, 1.0);
  c.A.diagonal().array() -= 0.3;
  c.B = Mat::Zero(6, 2);
  c.B(0, 0) = 1.0;
  c.B(2, 1) = 1.0;
  c.B(4, 0) = -0.7;
  c.D = Mat::Zero(6, 3);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 3; ++j) c.D(i, j) = 0.5 * rng.uniform(-1.0, 1.0);
  Mat L(6, 6);  // not Mat::Random: it draws from std::rand, another sequence on every C library
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) L(i, j) = rng.uniform(-1.0, 1.0);
  c.Q = 0.2 * L * L.transpose() + 0.1 * Mat::Identity(6, 6);
  c.Qf = Mat::Identity(6, 6);
  c.gamma = 5.0;
  c.t0 = 0.0;
  c.tf = 6.0;
  return c;
}

TEST(GrdeMatrix, MatchesHamiltonianSolutionAndResidual) {
  hinf_ref::Rng rng(8);
  for (const LtiCase& c : {lti3(), lti2_singular_Q(), lti6()}) {
    const auto trajectory = lti_trajectory(c.A, c.B, c.D, c.t0, c.tf);
    const Mat S = c.S();
    std::vector<double> times;
    for (int k = 0; k < 150; ++k) times.push_back(rng.uniform(c.t0, c.tf));
    times.push_back(c.t0);
    times.push_back(c.tf);
    std::vector<Mat> exact;
    for (double t : times) exact.push_back(exact_lti_Z(c.A, S, c.Q, c.Qf, t, c.tf));
    for (Method method : kMethods) {
      const auto sol = hinf::solve_grde(trajectory, c.Q, c.Qf, c.gamma, options_for(method));
      double max_rel = 0.0, max_residual = 0.0, min_eig = kInf, max_gain_err = 0.0, gain_terms = 0.0;
      for (std::size_t k = 0; k < times.size(); ++k) {
        const double t = times[k];
        const Mat Z = sol->Z(t);
        ASSERT_EQ(Z.rows(), c.A.rows());
        EXPECT_EQ((Z - Z.transpose()).cwiseAbs().maxCoeff(), 0.0);
        min_eig = std::min(min_eig, Eigen::SelfAdjointEigenSolver<Mat>(Z).eigenvalues()(0));
        max_rel = std::max(max_rel, (Z - exact[k]).norm() / exact[k].norm());
        const Mat R = sol->dZdt(t) + c.A.transpose() * Z + Z * c.A + c.Q - Z * S * Z;
        max_residual = std::max(max_residual, R.norm() / std::max(1.0, Z.norm() * Z.norm()));
        max_gain_err = std::max(max_gain_err, (sol->gain(t) - c.B.transpose() * Z).cwiseAbs().maxCoeff());
        gain_terms = std::max(gain_terms, (c.B.cwiseAbs().transpose() * Z.cwiseAbs()).maxCoeff());
      }
      std::printf("[grde lti] %-9s %-5s: max rel. error vs exp(H t) %.2e, max GRDE residual %.2e, "
                  "min eig(Z) %.3f, %ld steps\n",
                  c.label, hinf::to_string(method).c_str(), max_rel, max_residual, min_eig,
                  sol->stats().steps);
      // rtol 1e-10: a global error of tens to hundreds of rtol, below 1e-7 (measured at most
      // 3.7e-9, 2x2 BDF; 3.0e-10 on the 6x6 system).
      EXPECT_LT(max_rel, 1e-7) << c.label << " " << hinf::to_string(method);
      // The residual takes dZdt from the dense output: its error is about the local error
      // (~rtol |Z|) over the step (mean steps 0.01 to 0.04 here), ~1e-8; 1e-5 is loose
      // (measured at most 3.7e-9).
      EXPECT_LT(max_residual, 1e-5) << c.label << " " << hinf::to_string(method);
      // Qf > 0, Q >= 0 and no escape on the horizon: Z(t) > 0 (measured min eig >= 0.12).
      EXPECT_GT(min_eig, 0.0) << c.label;
      // The library's product B'Z and this one (another order of the sums): round-off of |B|'|Z|.
      EXPECT_LT(max_gain_err, hinf_test::kRoundoff * gain_terms) << c.label;
    }
  }
}

TEST(GrdeMatrix, LongHorizonApproachesTheAlgebraicRiccatiSolution) {
  // Far from tf, Z(t) of a stabilizable/detectable LTI problem tends to the stabilizing
  // solution of 0 = A'Z + ZA + Q - Z S Z, whose closed loop A - S Z is Hurwitz.
  const LtiCase c = lti3();
  const auto trajectory = lti_trajectory(c.A, c.B, c.D, 0.0, 30.0);
  const auto sol = hinf::solve_grde(trajectory, c.Q, c.Qf, c.gamma, options_for(Method::BDF, 1e-9, 1e-11));
  const Mat Z = sol->Z(0.0), S = c.S();
  const Mat are = c.A.transpose() * Z + Z * c.A + c.Q - Z * S * Z;
  EXPECT_LT(are.norm() / Z.norm(), 1e-7);
  const Eigen::VectorXcd eig = Mat(c.A - S * Z).eigenvalues();
  for (Eigen::Index i = 0; i < eig.size(); ++i) EXPECT_LT(eig[i].real(), 0.0);
}

// The stationary game ARE (solve_game_are) against the limit of the GRDE above (lti3, lti6 over
// 30 s, BDF at rtol 1e-9: Z(0) is the limit within ~1e-8 relative; it was checked against the
// ARE's residual there) and against closed forms.
TEST(GameAre, EqualsTheLongHorizonLimitOfTheGrde) {
  for (const LtiCase& c : {lti3(), lti6()}) {
    const auto trajectory = lti_trajectory(c.A, c.B, c.D, 0.0, 30.0);
    const Mat Z0 = hinf::solve_grde(trajectory, c.Q, c.Qf, c.gamma, options_for(Method::BDF, 1e-9, 1e-11))->Z(0.0);
    const Mat P = hinf::solve_game_are(c.A, c.B, c.D, c.Q, c.gamma);
    EXPECT_EQ((P - P.transpose()).cwiseAbs().maxCoeff(), 0.0) << c.label;
    // Two computations: the GRDE's global error ~1e-8 relative (above) and the sign iteration's
    // ~1e-13; 1e-6 is loose.
    EXPECT_LT((P - Z0).norm() / Z0.norm(), 1e-6) << c.label;
  }
}

TEST(GameAre, ClosedForms) {
  // Scalar: 2 a P + q - s P^2 = 0, s = b^2 - d^2 / gamma^2 > 0: P = (a + sqrt(a^2 + q s)) / s.
  for (double gamma : {kInf, 5.0, 2.0, 1.2}) {
    const double a = 1.0, b = 1.0, d = 1.0, q = 1.0, s = b * b - d * d / (gamma * gamma);
    const Mat P = hinf::solve_game_are(Mat::Constant(1, 1, a), Mat::Constant(1, 1, b), Mat::Constant(1, 1, d),
                                       Mat::Constant(1, 1, q), gamma);
    EXPECT_NEAR(P(0, 0), (a + std::sqrt(a * a + q * s)) / s, 1e-12 * P(0, 0)) << "gamma = " << gamma;
  }
  // The double integrator's LQR with Q = I, R = 1: P = [[sqrt 3, 1], [1, sqrt 3]].
  Mat A(2, 2), B(2, 1);
  A << 0.0, 1.0, 0.0, 0.0;
  B << 0.0, 1.0;
  const Mat P = hinf::solve_game_are(A, B, B, Mat::Identity(2, 2), kInf);
  Mat exact(2, 2);
  exact << std::sqrt(3.0), 1.0, 1.0, std::sqrt(3.0);
  EXPECT_LT((P - exact).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(GameAre, NoStabilizingSolutionIsNamed) {
  const Mat one = Mat::Constant(1, 1, 1.0);
  // Scalar, a = b = d = q = 1: s = 1 - gamma^-2. For gamma in (1/sqrt 2, 1) the stabilizing root
  // is negative (no cost-to-go); below 1/sqrt 2 the Hamiltonian's eigenvalues are imaginary.
  for (double gamma : {0.9, 0.5}) {
    try {
      hinf::solve_game_are(one, one, one, one, gamma);
      ADD_FAILURE() << "gamma = " << gamma << " below the game's gamma* = 1 was accepted";
    } catch (const hinf::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("raise gamma"), std::string::npos) << e.what();
    }
  }
  // (A, B) not stabilizable: an unstable mode the input does not reach.
  Mat A(2, 2), B(2, 1);
  A << 1.0, 0.0, 0.0, -1.0;
  B << 0.0, 1.0;
  EXPECT_THROW(hinf::solve_game_are(A, B, B, Mat::Identity(2, 2), kInf), hinf::InputError);
  EXPECT_THROW(hinf::solve_game_are(A, Mat::Zero(3, 1), B, Mat::Identity(2, 2), kInf), hinf::InputError);
  EXPECT_THROW(hinf::solve_game_are(A, B, B, Mat::Identity(2, 2), -1.0), hinf::InputError);
}

// ======================================================================= the ship

hinf::VectorSignal paper_u_d() {
  return hinf::VectorSignal(std::vector<hinf::Signal>{
      hinf::Signal(1.0), hinf::Signal(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}})});
}

Vec paper_q_d0() {
  Vec q = Vec::Zero(6);
  q[0] = 1.0;
  return q;
}

hinf::TrajectoryPtr paper_trajectory() {
  return std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::ShipModel>(),
                                                  paper_q_d0(), paper_u_d(), 0.0, 40.0);
}

// The ship with a 7th state of zero dynamics that enters nothing (f_7 = 0, B and D rows
// zero). Its GRDE splits exactly: the 6x6 block is the ship's Z, the coupling column stays
// 0 (its equation is linear and homogeneous in it), and Z_77 = Qf_77 + Q_77 (tf - t).
class ShipPlusIdleState final : public hinf::Model {
 public:
  std::string name() const override { return "ship+idle"; }
  int n() const override { return 7; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  void f(double t, const hinf::ConstVecRef& q, hinf::VecRef out) const override {
    Vec f6(6);
    ship_.f(t, q.head(6), f6);
    out.head(6) = f6;
    out[6] = 0.0;
  }
  void dfdq(double t, const hinf::ConstVecRef& q, hinf::MatRef J) const override {
    Mat J6(6, 6);
    ship_.dfdq(t, q.head(6), J6);
    J.setZero();
    J.topLeftCorner(6, 6) = J6;
  }
  Mat G(double t, const hinf::ConstVecRef&) const override {
    Mat B7 = Mat::Zero(7, 2);
    B7.topRows(6) = ship_.G(t, Vec::Zero(6));
    return B7;
  }
  Mat D(double t, const hinf::ConstVecRef&) const override {
    Mat D7 = Mat::Zero(7, 6);
    D7.topRows(6) = ship_.D(t, Vec::Zero(6));
    return D7;
  }

 private:
  hinf::ShipModel ship_;
};

class ShipGrde : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    trajectory_ = paper_trajectory();
    for (Method method : kMethods)
      solutions_.push_back(hinf::solve_grde(trajectory_, Mat::Identity(6, 6), Mat::Identity(6, 6),
                                            5.0, options_for(method)));
  }
  static void TearDownTestSuite() {
    solutions_.clear();
    trajectory_.reset();
  }
  static std::vector<double> sample_times() {
    std::vector<double> times;
    hinf_ref::Rng rng(21);
    for (int k = 0; k < 300; ++k) times.push_back(rng.uniform(0.0, 40.0));
    for (int k = 0; k <= 80; ++k) times.push_back(0.5 * k);
    return times;
  }
  static hinf::TrajectoryPtr trajectory_;
  static std::vector<hinf::RiccatiSolutionPtr> solutions_;
};
hinf::TrajectoryPtr ShipGrde::trajectory_;
std::vector<hinf::RiccatiSolutionPtr> ShipGrde::solutions_;

TEST_F(ShipGrde, ThreeMethodsAgree) {
  const std::vector<double> times = sample_times();
  for (std::size_t i = 1; i < solutions_.size(); ++i) {
    double max_diff = 0.0;
    for (double t : times) {
      const Mat Z0 = solutions_[0]->Z(t);
      max_diff = std::max(max_diff, (solutions_[i]->Z(t) - Z0).cwiseAbs().maxCoeff() /
                                        Z0.cwiseAbs().maxCoeff());
    }
    std::printf("[grde ship] %s vs bdf (rtol 1e-10): max rel. difference of Z %.2e\n",
                hinf::to_string(kMethods[i]).c_str(), max_diff);
    EXPECT_LT(max_diff, 1e-6) << hinf::to_string(kMethods[i]);
  }
}

TEST_F(ShipGrde, SymmetricPositiveDefiniteAndSatisfiesTheGrde) {
  const hinf::ShipModel ship;
  const Mat B = ship.G(0.0, Vec::Zero(6)), D = ship.D(0.0, Vec::Zero(6));
  const Mat S = B * B.transpose() - D * D.transpose() / 25.0;
  const Mat Q = Mat::Identity(6, 6);
  for (const auto& sol : solutions_) {
    double max_residual = 0.0, min_eig = kInf;
    for (double t : sample_times()) {
      const Mat Z = sol->Z(t);
      min_eig = std::min(min_eig, Eigen::SelfAdjointEigenSolver<Mat>(Z).eigenvalues()(0));
      // A_e from the model's Jacobian at the stored desired state.
      Mat A(6, 6);
      ship.dfdq(t, trajectory_->q_d(t), A);
      const Mat R = sol->dZdt(t) + A.transpose() * Z + Z * A + Q - Z * S * Z;
      max_residual = std::max(max_residual, R.cwiseAbs().maxCoeff() / Z.squaredNorm());
    }
    EXPECT_GT(min_eig, 0.0);
    EXPECT_LT(max_residual, 1e-5) << sol->stats().steps << " steps";
    // Z(tf) = Qf = I from the first step's polynomial: round-off.
    EXPECT_TRUE(sol->Z(40.0).isApprox(Mat::Identity(6, 6), hinf_test::kRoundoff));
  }
}

TEST_F(ShipGrde, GainIsBTransposeZ) {
  const Mat B = hinf::ShipModel().G(0.0, Vec::Zero(6));
  for (const auto& sol : solutions_) {
    std::size_t cursor = 0;
    Mat K_cursor(2, 6);
    for (double t = 0.0; t <= 40.0; t += 0.173) {
      const Mat Z = sol->Z(t);
      const Mat K = sol->gain(t);
      ASSERT_EQ(K.rows(), 2);
      ASSERT_EQ(K.cols(), 6);
      // B has entries 0 and 1: every product and sum is exact, in the library and here.
      EXPECT_LT((K - B.transpose() * Z).cwiseAbs().maxCoeff(), 1e-14);
      // The ship's B = [e1, e3]: the gain rows are rows 0 and 2 of Z.
      EXPECT_EQ(K.row(0), Z.row(0));
      EXPECT_EQ(K.row(1), Z.row(2));
      sol->gain(t, K_cursor.data(), &cursor);
      // At a step boundary the cursor may pick the neighbouring piece: round-off of |Z|.
      EXPECT_LT((K_cursor - K).cwiseAbs().maxCoeff(), hinf_test::kRoundoff * Z.cwiseAbs().maxCoeff());
    }
  }
}

TEST_F(ShipGrde, FixedSizeKernelAgreesWithDynamicKernel) {
  // The 7-state model goes through the dynamic kernel (n != 6).
  auto model7 = std::make_shared<const ShipPlusIdleState>();
  Vec q7 = Vec::Zero(7);
  q7.head(6) = paper_q_d0();
  q7[6] = 0.3;
  const auto trajectory7 =
      std::make_shared<const hinf::Trajectory>(model7, q7, paper_u_d(), 0.0, 40.0);
  Mat Q7 = Mat::Identity(7, 7), Qf7 = Mat::Identity(7, 7);
  Q7(6, 6) = 0.25;
  Qf7(6, 6) = 2.0;
  for (std::size_t i = 0; i < solutions_.size(); ++i) {
    const Method method = kMethods[i];
    const auto sol7 = hinf::solve_grde(trajectory7, Q7, Qf7, 5.0, options_for(method));
    double block = 0.0, coupling = 0.0, idle = 0.0;
    for (double t : sample_times()) {
      const Mat Z7 = sol7->Z(t), Z6 = solutions_[i]->Z(t);
      block = std::max(block, (Z7.topLeftCorner(6, 6) - Z6).cwiseAbs().maxCoeff() /
                                  Z6.cwiseAbs().maxCoeff());
      coupling = std::max(coupling, Z7.col(6).head(6).cwiseAbs().maxCoeff());
      idle = std::max(idle, std::abs(Z7(6, 6) - (2.0 + 0.25 * (40.0 - t))));
    }
    std::printf("[grde ship] %-5s n=6 kernel vs n=7 dynamic kernel: 6x6 block rel. diff %.2e, "
                "coupling %.1e, idle-state error %.1e\n",
                hinf::to_string(method).c_str(), block, coupling, idle);
    EXPECT_LT(block, 1e-6);
    // The idle state's coupling entries start at 0 and every term of their derivative has a
    // factor 0: they stay 0 (no round-off allowance needed).
    EXPECT_LT(coupling, 1e-12);
    EXPECT_LT(idle, 1e-8);
  }
}

TEST(GrdeShip, SmallGammaHitsAConjugatePoint) {
  // gamma = 0.3 makes S = BB' - DD'/gamma^2 strongly negative: S_vv = -1/0.09 = -11.1 on the
  // unactuated sway. With Z(tf) = I the sway entry grows like dz/dtau ~ 11.1 z^2 + O(z), a
  // scalar escape after about 1/11.1 = 0.09 s of backward time: a conjugate point just below tf.
  try {
    hinf::solve_grde(paper_trajectory(), Mat::Identity(6, 6), Mat::Identity(6, 6), 0.3);
    FAIL() << "no conjugate point at gamma = 0.3";
  } catch (const hinf::ConjugatePointError& e) {
    EXPECT_GT(e.t_escape(), 39.0);
    EXPECT_LT(e.t_escape(), 40.0);
  }
}

TEST(GrdeShip, ConjugatePointMatchesTheHamiltonianDeterminant) {
  // Independent conjugate-point time (docs/mathematics.md): integrate the linear Hamiltonian system
  // d[X; Y]/dt = [[A, -S], [-Q, -A']] [X; Y] backward from X(tf) = I, Y(tf) = Qf with a
  // classical RK4 (h = 1e-3) and find where det X first reaches 0; Z = Y X^-1 escapes there.
  const auto trajectory = paper_trajectory();
  const hinf::ShipModel ship;
  const double gamma = 1.0, tf = 40.0, h = 1e-3;
  const Mat B = ship.G(0.0, Vec::Zero(6)), D = ship.D(0.0, Vec::Zero(6));
  const Mat S = B * B.transpose() - D * D.transpose() / (gamma * gamma);
  const Mat Q = Mat::Identity(6, 6);
  auto rhs = [&](double t, const Mat& XY) {
    Mat A(6, 6);
    ship.dfdq(t, trajectory->q_d(t), A);
    Mat d(12, 6);
    d.topRows(6) = A * XY.topRows(6) - S * XY.bottomRows(6);
    d.bottomRows(6) = -Q * XY.topRows(6) - A.transpose() * XY.bottomRows(6);
    return d;
  };
  Mat XY(12, 6);
  XY << Mat::Identity(6, 6), Mat::Identity(6, 6);
  double t = tf, det_prev = 1.0, t_escape = NAN;
  while (t > 0.0) {
    const Mat k1 = rhs(t, XY), k2 = rhs(t - h / 2, XY - h / 2 * k1),
              k3 = rhs(t - h / 2, XY - h / 2 * k2), k4 = rhs(t - h, XY - h * k3);
    XY -= h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    t -= h;
    const double det = XY.topRows(6).determinant();
    if (det <= 0.0) {
      t_escape = t + h * det / (det - det_prev);  // linear interpolation of det X
      break;
    }
    det_prev = det;
  }
  ASSERT_TRUE(std::isfinite(t_escape)) << "gamma = 1 should be below gamma* on this horizon";
  for (Method method : kMethods) {
    try {
      hinf::solve_grde(trajectory, Q, Q, gamma, options_for(method, 1e-8, 1e-10));
      ADD_FAILURE() << hinf::to_string(method) << ": no conjugate point at gamma = 1";
    } catch (const hinf::ConjugatePointError& e) {
      std::printf("[grde ship] gamma = 1 %-5s: t_escape %.6f, Hamiltonian det X = 0 at %.6f "
                  "(difference %.1e)\n",
                  hinf::to_string(method).c_str(), e.t_escape(), t_escape, e.t_escape() - t_escape);
      EXPECT_NEAR(e.t_escape(), t_escape, 1e-5) << hinf::to_string(method);
    }
  }
}

// ======================================================================= time-varying B

// dq/dt = b(t) u + d w with b(t) = 1 + 0.5 sin t (B depends on t: the solver must rebuild
// S = B B' - gamma^-2 D D' at every time). With a = 0 and q = 0 the GRDE is
// dz/dtau = -s(t) z^2, so 1/z(t) = 1/qf + int_t^tf s, s = b^2 - d^2/gamma^2, and
//   int_t^tf b^2 = 1.125 (tf - t) + cos t - cos tf - 0.0625 (sin 2 tf - sin 2 t).
class TimeVaryingScalar final : public hinf::Model {
 public:
  explicit TimeVaryingScalar(double d) : d_(d) {}
  std::string name() const override { return "tv-scalar"; }
  int n() const override { return 1; }
  int m() const override { return 1; }
  int nw() const override { return 1; }
  void f(double, const hinf::ConstVecRef&, hinf::VecRef out) const override { out[0] = 0.0; }
  void dfdq(double, const hinf::ConstVecRef&, hinf::MatRef J) const override { J(0, 0) = 0.0; }
  Mat G(double t, const hinf::ConstVecRef&) const override { return Mat::Constant(1, 1, 1.0 + 0.5 * std::sin(t)); }
  Mat D(double, const hinf::ConstVecRef&) const override { return Mat::Constant(1, 1, d_); }
  bool constant_input_matrices() const override { return false; }

 private:
  double d_;
};

double integral_b2(double t, double tf) {
  return 1.125 * (tf - t) + std::cos(t) - std::cos(tf) - 0.0625 * (std::sin(2 * tf) - std::sin(2 * t));
}

TEST(GrdeTimeVarying, ClosedFormWithTimeVaryingB) {
  const double d = 0.6, gamma = 2.0, qf = 0.8, t0 = 0.0, tf = 6.0;
  auto model = std::make_shared<const TimeVaryingScalar>(d);
  const auto trajectory = std::make_shared<const hinf::Trajectory>(
      model, Vec::Zero(1), hinf::VectorSignal::zeros(1), t0, tf);
  for (Method method : kMethods) {
    const auto sol = hinf::solve_grde(trajectory, Mat::Zero(1, 1), Mat::Constant(1, 1, qf), gamma,
                                      options_for(method));
    double max_rel = 0.0, max_gain = 0.0;
    for (double t = t0; t <= tf; t += 0.0173) {
      const double exact = 1.0 / (1.0 / qf + integral_b2(t, tf) - d * d / (gamma * gamma) * (tf - t));
      max_rel = std::max(max_rel, std::abs(sol->Z(t)(0, 0) / exact - 1.0));
      // K(t) = B(t)' Z(t) with the time-varying B.
      max_gain = std::max(max_gain, std::abs(sol->gain(t)(0, 0) - (1.0 + 0.5 * std::sin(t)) * sol->Z(t)(0, 0)));
    }
    std::printf("[grde tv-B] %-5s: max rel. error %.2e\n", hinf::to_string(method).c_str(), max_rel);
    EXPECT_LT(max_rel, 1e-7) << hinf::to_string(method);
    // One product of the same two doubles (B(t) from the model, Z(t)) in the library and here.
    EXPECT_LT(max_gain, 1e-14) << hinf::to_string(method);
  }
}

// ======================================================================= the private kernel

// dX/dt = sign (M'X + XM + R - XSX) in packed storage: the right-hand side against the
// formula, and the Jacobian against central differences (exact for a quadratic up to
// round-off).
template <class MatN>
void check_kernel(int n, double sign, hinf_ref::Rng& rng) {
  auto u = [&rng]() { return rng.uniform(-1.0, 1.0); };
  MatN M(n, n), R(n, n), S(n, n), X(n, n), T(n, n), G(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = u();
  auto sym = [&](MatN& A) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) A(i, j) = A(j, i) = u();
  };
  sym(R);
  sym(S);
  sym(X);
  const int p = hinf::packed_size(n);
  std::vector<double> x(p), f(p), fp(p), fm(p), J(static_cast<std::size_t>(p) * p), expected(p);
  hinf::pack_symmetric(X, x.data());
  hinf::detail::riccati_rhs(sign, M, R, S, X, T, G, f.data());
  const Mat F = sign * (Mat(M).transpose() * Mat(X) + Mat(X) * Mat(M) + Mat(R) - Mat(X) * Mat(S) * Mat(X));
  hinf::pack_symmetric(F, expected.data());
  // The kernel against the formula: round-off of the terms (entries in [-1, 1]: |M'X|, |XM|
  // <= n, |R| <= 1, |XSX| <= n^2).
  const double terms = n * n + 2.0 * n + 1.0;
  for (int k = 0; k < p; ++k) EXPECT_NEAR(f[k], expected[k], hinf_test::kRoundoff * terms) << "rhs, packed entry " << k;
  hinf::detail::riccati_jacobian(sign, M, S, X, T, G, J.data());
  const double h = 1e-3;
  for (int c = 0; c < p; ++c) {
    std::vector<double> xp = x, xm = x;
    xp[c] += h;
    xm[c] -= h;
    MatN Xp(n, n), Xm(n, n);
    hinf::unpack_symmetric(xp.data(), Xp);
    hinf::unpack_symmetric(xm.data(), Xm);
    hinf::detail::riccati_rhs(sign, M, R, S, Xp, T, G, fp.data());
    hinf::detail::riccati_rhs(sign, M, R, S, Xm, T, G, fm.data());
    // Central differences are exact for the quadratic right-hand side; their round-off is
    // ~ eps |f| / h ~ 2e-16 x 49 / 1e-3 ~ 1e-11.
    for (int r = 0; r < p; ++r)
      EXPECT_NEAR(J[static_cast<std::size_t>(c) * p + r], (fp[r] - fm[r]) / (2 * h), 1e-10)
          << "n = " << n << ", sign " << sign << ", J(" << r << ", " << c << ")";
  }
}

TEST(RiccatiKernel, RhsAndJacobianMatchFormulaAndFiniteDifferences) {
  hinf_ref::Rng rng(4);
  for (double sign : {-1.0, 1.0}) {
    check_kernel<Mat>(1, sign, rng);
    check_kernel<Mat>(3, sign, rng);
    check_kernel<Eigen::Matrix<double, 6, 6>>(6, sign, rng);
  }
}

// ======================================================================= bad inputs

TEST(GrdeInputs, BadInputsThrowInputError) {
  const auto trajectory = paper_trajectory();
  const Mat I = Mat::Identity(6, 6);
  auto solve = [&](const Mat& Q, const Mat& Qf, double gamma, const SolverOptions& o) {
    return hinf::solve_grde(trajectory, Q, Qf, gamma, o);
  };
  const SolverOptions ok;
  // Shapes.
  EXPECT_THROW(solve(Mat::Identity(5, 5), I, 5.0, ok), hinf::InputError);
  EXPECT_THROW(solve(I, Mat::Identity(6, 5), 5.0, ok), hinf::InputError);
  EXPECT_THROW(solve(Mat(), I, 5.0, ok), hinf::InputError);
  // Non-symmetric, indefinite, singular.
  Mat asym = I;
  asym(0, 1) = 0.1;
  EXPECT_THROW(solve(asym, I, 5.0, ok), hinf::InputError);
  EXPECT_THROW(solve(I, asym, 5.0, ok), hinf::InputError);
  Mat indefinite = I;
  indefinite(3, 3) = -0.5;
  EXPECT_THROW(solve(indefinite, I, 5.0, ok), hinf::InputError);
  Mat singular = I;
  singular(4, 4) = 0.0;
  EXPECT_THROW(solve(I, singular, 5.0, ok), hinf::InputError);
  EXPECT_NO_THROW(solve(singular, I, 5.0, ok)) << "Q need only be positive semidefinite";
  // NaN.
  Mat nan = I;
  nan(2, 2) = kNaN;
  EXPECT_THROW(solve(nan, I, 5.0, ok), hinf::InputError);
  EXPECT_THROW(solve(I, nan, 5.0, ok), hinf::InputError);
  // gamma.
  EXPECT_THROW(solve(I, I, 0.0, ok), hinf::InputError);
  EXPECT_THROW(solve(I, I, -5.0, ok), hinf::InputError);
  EXPECT_THROW(solve(I, I, kNaN, ok), hinf::InputError);
  EXPECT_THROW(solve(I, I, -kInf, ok), hinf::InputError);
  // Solver options.
  SolverOptions bad = ok;
  bad.rtol = 0.0;
  EXPECT_THROW(solve(I, I, 5.0, bad), hinf::InputError);
  bad.rtol = -1e-8;
  EXPECT_THROW(solve(I, I, 5.0, bad), hinf::InputError);
  bad.rtol = kNaN;
  EXPECT_THROW(solve(I, I, 5.0, bad), hinf::InputError);
  bad = ok;
  bad.atol = 0.0;
  EXPECT_THROW(solve(I, I, 5.0, bad), hinf::InputError);
  bad = ok;
  bad.max_steps = 0;
  EXPECT_THROW(solve(I, I, 5.0, bad), hinf::InputError);
  EXPECT_THROW(hinf::solve_grde(nullptr, I, I, 5.0), hinf::InputError);
}

}  // namespace

// ======================================================================= uncoupled blocks
//
// A GRDE whose model and weights are block-diagonal is solved block by block (riccati.cpp,
// BlockLayout). Checked against independent solves of each block alone: the split must give
// the same Z and the same conjugate points.

TEST(UncoupledBlocks, MergeFollowsEveryCoupling) {
  using hinf::Coupling;
  const std::vector<int> singles(5, 1);
  Mat M = Mat::Zero(5, 5);
  EXPECT_EQ(hinf::merge_coupled_blocks(singles, M, Coupling::Entries), singles);
  M(3, 1) = 0.5;  // joins states 1..3 (a group is consecutive)
  EXPECT_EQ(hinf::merge_coupled_blocks(singles, M, Coupling::Entries), (std::vector<int>{1, 3, 1}));
  Mat B = Mat::Zero(5, 2);
  B(0, 0) = B(1, 0) = 1.0;  // an input on states 0 and 1 joins them
  B(4, 1) = 1.0;            // one on state 4 alone joins nothing
  EXPECT_EQ(hinf::merge_coupled_blocks(singles, B, Coupling::Columns), (std::vector<int>{2, 1, 1, 1}));
  EXPECT_EQ(hinf::merge_coupled_blocks({2, 3}, B, Coupling::Columns), (std::vector<int>{2, 3}));
  EXPECT_THROW(hinf::merge_coupled_blocks({2, 2}, B, Coupling::Columns), hinf::InputError);
}

TEST(UncoupledBlocks, LinearModelSplitsIntoItsBlocksAndEachBlockIsItsOwnGrde) {
  // Two random stable systems (3 and 4 states) side by side; the diagonal of Q and Qf only.
  hinf_ref::Rng rng(7);
  auto random = [&rng](int rows, int cols) {
    Mat M(rows, cols);
    for (int j = 0; j < cols; ++j)
      for (int i = 0; i < rows; ++i) M(i, j) = rng.uniform(-1.0, 1.0);
    return M;
  };
  const int sizes[] = {3, 4};
  std::vector<Mat> A, B, D;
  for (int k : sizes) {
    A.push_back(random(k, k) - 1.5 * Mat::Identity(k, k));
    B.push_back(random(k, 1));
    D.push_back(random(k, 2));
  }
  Mat A7 = Mat::Zero(7, 7), B7 = Mat::Zero(7, 2), D7 = Mat::Zero(7, 4);
  A7.topLeftCorner(3, 3) = A[0];
  A7.bottomRightCorner(4, 4) = A[1];
  B7.block(0, 0, 3, 1) = B[0];
  B7.block(3, 1, 4, 1) = B[1];
  D7.block(0, 0, 3, 2) = D[0];
  D7.block(3, 2, 4, 2) = D[1];
  EXPECT_EQ(hinf::LinearModel(A7, B7, D7).uncoupled_blocks(), (std::vector<int>{3, 4}));
  const Mat Q = Mat(Vec::LinSpaced(7, 0.5, 2.0).asDiagonal()), Qf = Mat(Vec::LinSpaced(7, 1.0, 3.0).asDiagonal());
  const double gamma = 2.0;
  for (Method method : {Method::Auto, Method::ERK, Method::BDF}) {
    const auto whole = hinf::solve_grde(lti_trajectory(A7, B7, D7, 0.0, 10.0), Q, Qf, gamma, options_for(method));
    EXPECT_NE(whole->stats().method.find("in 2 uncoupled blocks"), std::string::npos) << whole->stats().method;
    double worst = 0.0, coupling = 0.0;
    for (int b = 0, s = 0; b < 2; s += sizes[b], ++b) {
      const int k = sizes[b];
      const Mat Qb = Q.block(s, s, k, k), Qfb = Qf.block(s, s, k, k);
      const auto alone =
          hinf::solve_grde(lti_trajectory(A[b], B[b], D[b], 0.0, 10.0), Qb, Qfb, gamma, options_for(method));
      for (int i = 0; i <= 40; ++i) {
        const double t = 0.25 * i;
        const Mat Z = whole->Z(t);
        worst = std::max(worst, (Z.block(s, s, k, k) - alone->Z(t)).cwiseAbs().maxCoeff());
        coupling = std::max(coupling, Z.topRightCorner(3, 4).cwiseAbs().maxCoeff());
      }
    }
    std::printf("[grde blocks] %-4s split LTI vs blocks alone: %.1e, coupling %.1e\n",
                hinf::to_string(method).c_str(), worst, coupling);
    // Two solves at rtol 1e-10 of |Z| ~ 1, each with a global error of a few 1e-10 (the split
    // error norm counts each block's share of the state): 1e-7 leaves a wide margin.
    EXPECT_LT(worst, 1e-7);
    EXPECT_EQ(coupling, 0.0);  // never computed: exactly zero
  }
  // A coupling in Q joins the blocks: one dense solve.
  Mat Q_coupled = Q;
  Q_coupled(0, 6) = Q_coupled(6, 0) = 0.1;
  const auto joined = hinf::solve_grde(lti_trajectory(A7, B7, D7, 0.0, 10.0), Q_coupled, Qf, gamma);
  EXPECT_EQ(joined->stats().method.find("uncoupled"), std::string::npos) << joined->stats().method;
}

TEST(UncoupledBlocks, FleetHasTheShipsConjugatePoint) {
  // Two ships: the fleet's Z escapes where the ship's does (one block escaping is enough).
  const auto ship = std::make_shared<const hinf::ShipModel>();
  const auto fleet = std::make_shared<const hinf::FleetModel>(ship, 2);
  Vec q2(12);
  q2 << paper_q_d0(), paper_q_d0();
  const hinf::Signal surge(1.0), yaw(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}});
  const std::vector<hinf::Signal> u2{surge, yaw, surge, yaw};
  const auto trajectory2 = std::make_shared<const hinf::Trajectory>(fleet, q2, hinf::VectorSignal(u2), 0.0, 40.0);
  for (double gamma : {1.0, 1.3}) {
    const double alone =
        hinf::grde_escape_time(paper_trajectory(), Mat::Identity(6, 6), Mat::Identity(6, 6), gamma);
    const double both = hinf::grde_escape_time(trajectory2, Mat::Identity(12, 12), Mat::Identity(12, 12), gamma);
    std::printf("[grde blocks] gamma %.2f: escape of the ship %.9f, of the fleet of 2 %.9f\n", gamma, alone, both);
    ASSERT_FALSE(std::isnan(alone));
    // The same escape located by two integrations at rtol 1e-8 (W's error near the escape).
    EXPECT_NEAR(both, alone, 1e-5);
  }
  EXPECT_TRUE(std::isnan(hinf::grde_escape_time(trajectory2, Mat::Identity(12, 12), Mat::Identity(12, 12), 5.0)));
}
