// Imperfect measurements (paper §4): the filter Riccati equation (36), the estimator (35) and
// the output-feedback law (34) in closed loop, the coupling condition rho(Sigma Z) < gamma^2, the
// switch of "auto" and "bdf" to SDIRK4 on a stiff loop, and the paper's Figure 2 run, against
// independent truth (references.hpp):
//   * the filter: scalar closed forms (and escape times), the exact solution of an LTI filter
//     from the matrix exponential of its Hamiltonian, the stabilizing solution of the filter ARE
//     (stable invariant subspace) as the long-horizon limit, Kalman-Bucy at gamma = inf;
//   * the closed loop: plant, estimator and filter integrated by an RK4 of this file from the
//     paper's equations with the same noise samples (only Z(t), q_d(t), u_d(t) come from the
//     library, tested elsewhere), at a tolerance derived from both accuracies;
//   * the coupling condition: rho = sigma z of two scalar closed forms crossing gamma^2.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hinf/control/analysis.hpp"
#include "hinf/control/controller.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"
#include "hinf/scenario/scenario.hpp"
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Mat;
using hinf::Method;
using hinf::RowMat;
using hinf::SolverOptions;
using hinf::Vec;
using hinf_test::kRoundoff;

const Method kMethods[] = {Method::Auto, Method::BDF, Method::Adams, Method::ERK};
constexpr double kInf = std::numeric_limits<double>::infinity();

Mat m11(double x) { return Mat::Constant(1, 1, x); }

SolverOptions solver(Method method, double rtol = 1e-8, double atol = 1e-10) {
  SolverOptions o;
  o.method = method;
  o.rtol = rtol;
  o.atol = atol;
  return o;
}

hinf::SimulationOptions simulation(double output_dt, const SolverOptions& s) {
  hinf::SimulationOptions o;
  o.output_dt = output_dt;
  o.solver = s;
  return o;
}

// An LTI model with measurements along q_d = 0, u_d = 0 (A_e(t) = A).
hinf::TrajectoryPtr lti_measured(const Mat& A, const Mat& B, const Mat& D, const Mat& C, double t0, double tf) {
  auto model = std::make_shared<const hinf::LinearModel>(A, B, D, C);
  return std::make_shared<const hinf::Trajectory>(model, Vec::Zero(A.rows()),
                                                  hinf::VectorSignal::zeros(static_cast<int>(B.cols())), t0, tf);
}

double max_rel(const Mat& a, const Mat& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

Mat symmetric(const Mat& M) { return 0.5 * (M + M.transpose()); }

// ======================================================================= the filter (36)

// dsigma/dtau = 2 a sigma + d^2 - s_f sigma^2, s_f = c^2/N - q/gamma^2 (tau = t - t0).
struct ScalarFilter {
  double a, b, d, c, N, q, gamma, sigma0;
  double s_f() const { return c * c / N - (std::isinf(gamma) ? 0.0 : q / (gamma * gamma)); }
  double sigma(double tau) const { return hinf_ref::scalar_riccati(a, s_f(), d * d, sigma0, tau); }
  double tau_escape() const { return hinf_ref::scalar_escape_tau(a, s_f(), d * d, sigma0); }
};

TEST(FilterRiccati, ScalarClosedFormsKalmanBucyAndEscape) {
  const double t0 = 2.0, tf = 12.0;
  // s_f > 0 (bounded, to the ARE root), s_f = c^2/N at gamma = inf (Kalman-Bucy), s_f < 0.
  const ScalarFilter bounded{0.3, 1.0, 1.0, 1.0, 0.5, 1.0, 2.0, 0.2};
  const ScalarFilter kalman{0.3, 1.0, 1.0, 1.0, 0.5, 1.0, kInf, 0.2};
  const ScalarFilter escaping{0.2, 1.0, 1.0, 0.5, 1.0, 1.0, 0.4, 1.0};
  ASSERT_GT(bounded.s_f(), 0.0);
  ASSERT_LT(escaping.s_f(), 0.0);
  const double tau_c = escaping.tau_escape();
  ASSERT_GT(tau_c, 0.0);
  ASSERT_LT(tau_c, tf - t0);
  for (Method method : kMethods) {
    const std::string where = hinf::to_string(method);
    for (const ScalarFilter* f : {&bounded, &kalman}) {
      const auto tr = lti_measured(m11(f->a), m11(f->b), m11(f->d), m11(f->c), t0, tf);
      const auto sol = hinf::solve_filter_riccati(tr, m11(f->N), m11(f->q), f->gamma, m11(f->sigma0), solver(method));
      EXPECT_EQ(sol->gamma(), f->gamma);
      double worst = 0.0;
      for (int k = 0; k <= 200; ++k) {
        const double t = t0 + (tf - t0) * k / 200;
        worst = std::max(worst, std::abs(sol->Sigma(t)(0, 0) - f->sigma(t - t0)) / f->sigma(t - t0));
      }
      // Default tolerances (rtol 1e-8): the solution to ~1e-7; 1e-6 leaves a margin of 10.
      EXPECT_LT(worst, 1e-6) << where << " gamma " << f->gamma;
      // Sigma(t0) = Sigma0 from the first step's polynomial: round-off.
      EXPECT_NEAR(sol->Sigma(t0)(0, 0), f->sigma0, kRoundoff * f->sigma0) << where;
      // No escape ahead.
      EXPECT_TRUE(std::isnan(hinf::filter_escape_time(tr, m11(f->N), m11(f->q), f->gamma, m11(f->sigma0),
                                                      solver(method))))
          << where;
    }
    // Kalman-Bucy tends to the positive root of 2 a s + d^2 - (c^2/N) s^2 = 0.
    const double root = (kalman.a + std::sqrt(kalman.a * kalman.a + kalman.s_f() * kalman.d * kalman.d)) / kalman.s_f();
    EXPECT_NEAR(kalman.sigma(1e3), root, 1e-12 * root);

    const auto tr = lti_measured(m11(escaping.a), m11(escaping.b), m11(escaping.d), m11(escaping.c), t0, tf);
    try {
      hinf::solve_filter_riccati(tr, m11(escaping.N), m11(escaping.q), escaping.gamma, m11(escaping.sigma0),
                                 solver(method));
      ADD_FAILURE() << where << ": no escape";
    } catch (const hinf::ConjugatePointError& e) {
      // The escape time of a scalar Riccati equation is found to ~1e-7 of the horizon.
      EXPECT_NEAR(e.t_escape(), t0 + tau_c, 1e-5 * (tf - t0)) << where;
      EXPECT_NE(std::string(e.what()).find("filter"), std::string::npos) << e.what();
    }
    EXPECT_NEAR(hinf::filter_escape_time(tr, m11(escaping.N), m11(escaping.q), escaping.gamma, m11(escaping.sigma0),
                                         solver(method)),
                t0 + tau_c, 1e-5 * (tf - t0))
        << where;
    // Before the escape, Sigma follows the closed form.
    const auto before = lti_measured(m11(escaping.a), m11(escaping.b), m11(escaping.d), m11(escaping.c), t0,
                                     t0 + 0.5 * tau_c);
    const auto sol = hinf::solve_filter_riccati(before, m11(escaping.N), m11(escaping.q), escaping.gamma,
                                                m11(escaping.sigma0), solver(method));
    for (int k = 0; k <= 100; ++k) {
      const double tau = 0.5 * tau_c * k / 100;
      EXPECT_NEAR(sol->Sigma(t0 + tau)(0, 0), escaping.sigma(tau), 1e-6 * escaping.sigma(tau)) << where;
    }
  }
}

// Exact Sigma(t) of the LTI filter dSigma/dt = A Sigma + Sigma A' - Sigma S Sigma + R: Sigma = Y X^-1
// with d[X; Y]/dt = [[-A', S], [R, A]] [X; Y] (X' = -A'X + S Y, Y' = R X + A Y give
// Sigma' = R + A Sigma + Sigma A' - Sigma S Sigma). Over a step of length tau from Sigma_start:
// [X; Y] = exp(H tau) [I; Sigma_start]. Chained over short steps (one exponential of H tau, with
// |H tau| small) rather than one exponential over the whole horizon, so that X stays well
// conditioned.
Mat filter_flow_step(const Mat& E, const Mat& Sigma_start) {
  const Eigen::Index n = Sigma_start.rows();
  Mat XY0(2 * n, n);
  XY0 << Mat::Identity(n, n), Sigma_start;
  const Mat XY = E * XY0;
  const Mat X = XY.topRows(n), Y = XY.bottomRows(n);
  return symmetric(X.transpose().fullPivLu().solve(Y.transpose()));  // (Y X^-1)' = X^-T Y'
}

Mat filter_hamiltonian(const Mat& A, const Mat& S, const Mat& R) {
  const Eigen::Index n = A.rows();
  Mat H(2 * n, 2 * n);
  H << -A.transpose(), S, R, A;
  return H;
}

TEST(FilterRiccati, MatchesTheHamiltonianSolution) {
  // Short horizon, random A, non-diagonal N and Sigma0, t0 != 0, gamma = 10 and inf (the exact
  // solution is checked positive definite below: no escape on the horizon).
  hinf_ref::Rng rng(36);
  const int n = 4, p = 2;
  const Mat A = hinf_ref::normal_matrix(rng, n, n), B = hinf_ref::normal_matrix(rng, n, 1),
            D = hinf_ref::normal_matrix(rng, n, 3), C = hinf_ref::normal_matrix(rng, p, n),
            L = hinf_ref::normal_matrix(rng, n, n);
  Mat N(2, 2);
  N << 0.5, 0.1, 0.1, 0.3;
  const Mat Q = L * L.transpose() / n + 0.1 * Mat::Identity(n, n);
  const Mat Sigma0 = 0.4 * Mat::Identity(n, n) + 0.05 * Mat::Ones(n, n);
  const double t0 = 1.5, tf = 3.5;
  const auto tr = lti_measured(A, B, D, C, t0, tf);
  for (double gamma : {10.0, kInf}) {
    const Mat S = C.transpose() * N.inverse() * C - (std::isinf(gamma) ? 0.0 : 1.0 / (gamma * gamma)) * Q;
    const Mat R = D * D.transpose();
    const Mat E = Mat((filter_hamiltonian(A, S, R) * ((tf - t0) / 120)).exp());
    std::vector<double> times{t0};
    std::vector<Mat> exact{Sigma0};
    for (int k = 1; k <= 120; ++k) {
      times.push_back(t0 + (tf - t0) * k / 120);
      exact.push_back(filter_flow_step(E, exact.back()));
      ASSERT_GT(Eigen::SelfAdjointEigenSolver<Mat>(exact.back()).eigenvalues()(0), 0.0);
    }
    // The chained reference against one exponential over the whole horizon (to the conditioning
    // of the latter's X, measured ~1e-9).
    EXPECT_LT(max_rel(filter_flow_step(Mat((filter_hamiltonian(A, S, R) * (tf - t0)).exp()), Sigma0), exact.back()),
              1e-7);
    for (Method method : kMethods) {
      const std::string where = hinf::to_string(method) + " gamma " + std::to_string(gamma);
      const auto sol = hinf::solve_filter_riccati(tr, N, Q, gamma, Sigma0, solver(method));
      const auto tight = hinf::solve_filter_riccati(tr, N, Q, gamma, Sigma0, solver(method, 1e-12, 1e-14));
      double err = 0.0, err_tight = 0.0, err_rate = 0.0;
      for (std::size_t k = 0; k < times.size(); ++k) {
        err = std::max(err, max_rel(sol->Sigma(times[k]), exact[k]));
        err_tight = std::max(err_tight, max_rel(tight->Sigma(times[k]), exact[k]));
        // dSigma/dt is the right-hand side at the exact solution (away from the first steps,
        // where the dense output's derivative is least accurate). The derivative of an
        // interpolant is an order less accurate than its value: measured up to 2.5e-7 (bdf,
        // whose first steps are of low order), 7e-8 (erk), 4e-8 (adams) at rtol 1e-12.
        if (times[k] > t0 + 0.05 * (tf - t0)) {
          const Mat& X = exact[k];
          const Mat rate = A * X + X * A.transpose() - X * S * X + R;
          err_rate = std::max(err_rate, max_rel(tight->dSigma_dt(times[k]), rate));
        }
      }
      std::printf("[filter vs exp(H t)] %-22s max rel. error %.2e (rtol 1e-8), %.2e (rtol 1e-12), rate %.2e\n",
                  where.c_str(), err, err_tight, err_rate);
      // Measured: <= 1.3e-7 at rtol 1e-8, <= 6e-11 at rtol 1e-12 (every method).
      EXPECT_LT(err, 5e-7) << where;
      EXPECT_LT(err_tight, 1e-9) << where;
      EXPECT_LT(err_rate, 1e-6) << where;
    }
  }
}

// A random filter problem: A stable (spectral abscissa -0.5) or shifted unstable by +1 with n
// measured rows (observable); N > 0; Q > 0; gamma three times the filter's own H-infinity level
// (the bisection of references.hpp on the dual ARE), or inf (Kalman-Bucy).
struct FilterProblem {
  Mat A, B, D, C, N, Q;
  double level = 0.0;
};

FilterProblem random_filter_problem(std::uint64_t seed, int n, bool unstable) {
  hinf_ref::Lti s = hinf_ref::random_lti(seed, n, 1, 2, -0.5);
  hinf_ref::Rng rng(seed + 1000);
  FilterProblem f;
  f.A = unstable ? Mat(s.A + Mat::Identity(n, n)) : s.A;
  f.B = s.B;
  f.D = s.D;
  f.Q = s.Q;
  const int p = unstable ? n : 1 + n % 2;
  f.C = hinf_ref::normal_matrix(rng, p, n);
  const Mat M = hinf_ref::normal_matrix(rng, p, p);
  f.N = M * M.transpose() + 0.5 * Mat::Identity(p, p);
  // The filter ARE A X + X A' - X (C'N^-1C - gamma^-2 Q) X + DD' = 0 is the game ARE of
  // (A', C' N^-1/2, Q^1/2) with weight DD'.
  const Mat N_inv_sqrt = Mat(f.N.llt().matrixL()).inverse().transpose();  // N^-1 = L^-T L^-1
  const Mat Q_sqrt = f.Q.llt().matrixL();
  f.level = hinf_ref::full_information_hinf_level(f.A.transpose(), f.C.transpose() * N_inv_sqrt, Q_sqrt,
                                                  f.D * f.D.transpose());
  return f;
}

TEST(FilterRiccati, LongHorizonConvergesToTheFilterAre) {
  struct Case {
    int n;
    std::uint64_t seed;
    bool unstable;
  };
  for (const Case& c : {Case{3, 11, false}, Case{4, 12, false}, Case{5, 13, false}, Case{3, 14, true}}) {
    const FilterProblem f = random_filter_problem(c.seed, c.n, c.unstable);
    ASSERT_TRUE(std::isfinite(f.level)) << c.seed;
    for (double gamma : {3.0 * std::max(f.level, 0.1), kInf}) {
      const Mat S = f.C.transpose() * f.N.inverse() * f.C - (std::isinf(gamma) ? 0.0 : 1.0 / (gamma * gamma)) * f.Q;
      const Mat R = f.D * f.D.transpose();
      const hinf_ref::AreSolution are = hinf_ref::stabilizing_are(f.A.transpose(), S, R);
      ASSERT_TRUE(are.ok) << c.seed << " " << are.why;
      const Mat& X = are.X;
      // The reference is an ARE solution (round-off of |X|^2 |S|), positive definite, stabilizing.
      const Mat residual = f.A * X + X * f.A.transpose() - X * S * X + R;
      EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-10 * std::max(1.0, X.squaredNorm() * S.norm())) << c.seed;
      EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat>(X).eigenvalues()(0), 0.0) << c.seed;
      const double alpha = hinf_ref::spectral_abscissa(f.A - X * S);
      ASSERT_LT(alpha, 0.0) << c.seed;
      // 25 time constants of the filter's error dynamics: the transient is below e^-50.
      const double tf = 25.0 / std::abs(alpha);
      const auto tr = lti_measured(f.A, f.B, f.D, f.C, 0.0, tf);
      const Mat Sigma0 = 0.5 * Mat::Identity(c.n, c.n);
      for (Method method : kMethods) {
        const auto sol = hinf::solve_filter_riccati(tr, f.N, f.Q, gamma, Sigma0, solver(method));
        const double err = max_rel(sol->Sigma(tf), X);
        std::printf("[filter ARE] n = %d seed %lu %-8s gamma %-8.4g %-5s: rel. error %.2e at tf = %.1f\n", c.n,
                    static_cast<unsigned long>(c.seed), c.unstable ? "unstable" : "stable", gamma,
                    hinf::to_string(method).c_str(), err, tf);
        // Measured: <= 2.1e-9 for every method.
        EXPECT_LT(err, 1e-6) << c.seed << " " << hinf::to_string(method);
        EXPECT_LT((sol->Sigma(0.0) - Sigma0).cwiseAbs().maxCoeff(), kRoundoff * 0.5);
      }
    }
  }
}

TEST(FilterRiccati, TheAreIsAFixedPoint) {
  // Sigma0 = X keeps Sigma(t) = X to the integrator's tolerance.
  const FilterProblem f = random_filter_problem(12, 4, false);
  const double gamma = 3.0 * std::max(f.level, 0.1);
  const Mat S = f.C.transpose() * f.N.inverse() * f.C - f.Q / (gamma * gamma);
  const hinf_ref::AreSolution are = hinf_ref::stabilizing_are(f.A.transpose(), S, f.D * f.D.transpose());
  ASSERT_TRUE(are.ok);
  const auto sol = hinf::solve_filter_riccati(lti_measured(f.A, f.B, f.D, f.C, 0.0, 10.0), f.N, f.Q, gamma, are.X,
                                              solver(Method::ERK, 1e-10, 1e-12));
  for (int k = 0; k <= 200; ++k) EXPECT_LT(max_rel(sol->Sigma(10.0 * k / 200), are.X), 1e-8) << k;
}

TEST(FilterRiccati, ResidualAlongThePaperTrajectory) {
  // Time-varying A_e(t) (the hand-written Jacobian at q_d(t)): dSigma/dt - (A_e Sigma + Sigma A_e'
  // - Sigma (C'N^-1 C - Q / gamma^2) Sigma + D D') = 0 on a grid and at the step midpoints,
  // relative to the size of the terms. Dense output at the default tolerances (rtol 1e-8):
  // values to ~1e-8; the derivative of an interpolant is less accurate than its values, by up to
  // ~100 for BDF's low-order first steps (measured: bdf 1.3e-6, adams 5.5e-7, erk and auto
  // 6.3e-8): 1e-5, a factor of 8 above the worst.
  Vec q_d0 = Vec::Zero(6);
  q_d0[0] = 1.0;
  const hinf::VectorSignal u_d(std::vector<hinf::Signal>{
      hinf::Signal(1.0), hinf::Signal(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}})});
  const auto tr = std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::ShipModel>(), q_d0, u_d, 0.0, 40.0);
  const Mat I = Mat::Identity(6, 6), N = 0.25 * Mat::Identity(3, 3), C = hinf_ref::ship_C();
  const Mat S = C.transpose() * N.inverse() * C - I / 25.0;
  const Mat DDt = hinf_ref::ship_D_process() * hinf_ref::ship_D_process().transpose();
  for (Method method : kMethods) {
    const auto sol = hinf::solve_filter_riccati(tr, N, I, 5.0, I, solver(method));
    std::vector<double> times;
    for (int k = 0; k <= 800; ++k) times.push_back(40.0 * k / 800);
    // The dense output's pieces end at the integrator's own step ends, the first and last at
    // the ends of the horizon exactly (piecewise_polynomial.hpp).
    const std::vector<double> steps = sol->dense().breakpoints();
    EXPECT_EQ(steps.front(), 0.0);
    EXPECT_EQ(steps.back(), 40.0);
    for (std::size_t k = 0; k + 1 < steps.size(); ++k) times.push_back(0.5 * (steps[k] + steps[k + 1]));
    double worst = 0.0, lowest = kInf, lo_eig = kInf, hi_eig = -kInf, largest = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const double t = times[k];
      const Mat Sigma = sol->Sigma(t);
      EXPECT_EQ((Sigma - Sigma.transpose()).cwiseAbs().maxCoeff(), 0.0);  // one triangle, mirrored
      const Mat A = hinf_ref::ship_jacobian(tr->q_d(t));
      const Mat ASigma = A * Sigma, SSS = Sigma * S * Sigma;
      const Mat residual = sol->dSigma_dt(t) - (ASigma + ASigma.transpose() - SSS + DDt);
      const double scale = 2.0 * ASigma.cwiseAbs().maxCoeff() + SSS.cwiseAbs().maxCoeff() + 1.0;
      worst = std::max(worst, residual.cwiseAbs().maxCoeff() / scale);
      const Vec eig = Eigen::SelfAdjointEigenSolver<Mat>(Sigma).eigenvalues();
      lowest = std::min(lowest, eig[0]);
      if (k <= 800) {
        lo_eig = std::min(lo_eig, eig[0]);
        hi_eig = std::max(hi_eig, eig[5]);
        largest = std::max(largest, eig.cwiseAbs().maxCoeff());
      }
    }
    std::printf("[filter residual] %-5s: max relative residual %.2e along the paper trajectory\n",
                hinf::to_string(method).c_str(), worst);
    EXPECT_LT(worst, 1e-5) << hinf::to_string(method);
    EXPECT_GT(lowest, 0.0);
    EXPECT_LT((sol->Sigma(0.0) - I).cwiseAbs().maxCoeff(), kRoundoff);
    // The library's extreme eigenvalues over the grid against Eigen's: round-off of |Sigma|.
    double lo = 0.0, hi = 0.0;
    sol->eigenvalue_range(std::vector<double>(times.begin(), times.begin() + 801), lo, hi);
    EXPECT_NEAR(lo, lo_eig, kRoundoff * largest);
    EXPECT_NEAR(hi, hi_eig, kRoundoff * largest);
  }
}

// ======================================================================= the closed loop

// The closed loop of paper §4 written from its equations, for the RK4 reference:
//   plant       dq/dt = f(t, q) + B u + D w(t),  u = u_d - kappa B' Z q_hat,
//   measurement y = C q + sigma v_k on [t0 + k T, t0 + (k+1) T),
//   estimator   dq_hat/dt = f(t, q_d + q_hat) - f(t, q_d) - (kappa B B' - gamma^-2 D D') Z q_hat
//                           + [I - gamma^-2 Sigma Z]^-1 Sigma C' N^-1 nu,
//               nu = y - C q_d - C q_hat (its heading component wrapped, when one is measured),
//   filter      dSigma/dt = A Sigma + Sigma A' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D D',
// A = A_filter(t, q_d(t), q_hat) (the decomposition's A(q_hat), or A_e(t)). D holds the process
// columns only.
struct Loop {
  std::function<Vec(double, const Vec&)> f;
  Mat B, D, C;
  std::function<Vec(double)> w;
  std::function<Mat(double, const Vec&, const Vec&)> A_filter;
  int heading_row = -1;
  // true: the heading component of nu, noise included, is wrapped (the documented innovation);
  // false: only C (q - q_d - q_hat) is wrapped and sigma v added after.
  bool wrap_with_noise = true;
  hinf::RiccatiSolutionPtr design;
  double kappa = 1.0, sigma = 0.0, period = 0.0;
  Mat N, Q, Sigma0;
  RowMat noise;
};

struct LoopSeries {
  std::vector<double> t;
  std::vector<Vec> q, q_hat;
  std::vector<Mat> Sigma;
};

// RK4 with `per_output` steps per output interval dt, the hold intervals T = k dt integrated one
// at a time with their noise sample.
LoopSeries reference_loop(const Loop& L, const Vec& q0, double dt, int outputs_per_period, int per_output) {
  const hinf::Trajectory& tr = L.design->trajectory();
  const int n = tr.n();
  const double t0 = tr.t0(), g2 = std::isinf(L.design->gamma()) ? 0.0 : 1.0 / std::pow(L.design->gamma(), 2);
  const Mat N_inv = L.N.inverse();
  const Mat S_f = L.C.transpose() * N_inv * L.C - g2 * L.Q;
  const Mat DDt = L.D * L.D.transpose(), BBt = L.B * L.B.transpose();
  Vec v;
  const auto rhs = [&](double t, const Vec& x) {
    const Vec q = x.head(n), q_hat = x.segment(n, n);
    const Mat Sigma = Eigen::Map<const Mat>(x.data() + 2 * n, n, n);
    const Vec qd = tr.q_d(t);
    const Mat Z = L.design->Z(t);
    const Vec u = tr.u_d(t) - L.kappa * L.B.transpose() * Z * q_hat;
    Vec nu = L.C * (q - qd - q_hat);
    if (L.heading_row >= 0 && !L.wrap_with_noise) nu[L.heading_row] = hinf_ref::wrapped(nu[L.heading_row]);
    nu += L.sigma * v;
    if (L.heading_row >= 0 && L.wrap_with_noise) nu[L.heading_row] = hinf_ref::wrapped(nu[L.heading_row]);
    const Mat gain = (Mat::Identity(n, n) - g2 * Sigma * Z).partialPivLu().solve(Sigma * L.C.transpose() * N_inv);
    const Mat A = L.A_filter(t, qd, q_hat);
    const Mat dSigma = A * Sigma + Sigma * A.transpose() - Sigma * S_f * Sigma + DDt;
    Vec dx(2 * n + n * n);
    dx.head(n) = L.f(t, q) + L.B * u + L.D * L.w(t);
    dx.segment(n, n) = L.f(t, qd + q_hat) - L.f(t, qd) - (L.kappa * BBt - g2 * DDt) * Z * q_hat + gain * nu;
    dx.tail(n * n) = Eigen::Map<const Vec>(dSigma.data(), n * n);
    return dx;
  };
  Vec x(2 * n + n * n);
  x << q0, Vec::Zero(n), Eigen::Map<const Vec>(L.Sigma0.data(), n * n);
  LoopSeries out;
  auto record = [&](double t) {
    out.t.push_back(t);
    out.q.push_back(x.head(n));
    out.q_hat.push_back(x.segment(n, n));
    out.Sigma.push_back(Eigen::Map<const Mat>(x.data() + 2 * n, n, n));
  };
  record(t0);
  const double h = dt / per_output;
  for (Eigen::Index k = 0; k < L.noise.rows(); ++k) {
    v = L.noise.row(k).transpose();
    for (int j = 0; j < outputs_per_period; ++j) {
      const double start = t0 + k * L.period + j * dt;
      for (int i = 0; i < per_output; ++i) x = hinf_ref::rk4_step(rhs, start + i * h, x, h);
      record(start + dt);
    }
  }
  return out;
}

double max_abs_diff(const std::vector<Vec>& a, const std::vector<Vec>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, (a[k] - b[k]).cwiseAbs().maxCoeff());
  return worst;
}

double max_abs(const std::vector<Vec>& a) {
  double worst = 0.0;
  for (const Vec& x : a) worst = std::max(worst, x.cwiseAbs().maxCoeff());
  return worst;
}

// The library's run against the reference (RK4 with 2 s steps per output; its error is below the
// difference to the run with s steps, |x_s - x_2s| ~ 15 times the error of x_2s). Tolerance:
// the library's (20 x its rtol times the size of the solution: a global error of a few rtol per
// unit of time, with a margin) plus that difference.
void expect_matches_reference(const hinf::SimulationResult& run, const Loop& L, const Vec& q0, double dt,
                              int outputs_per_period, int per_output, double library_rtol, const std::string& label) {
  const LoopSeries ref = reference_loop(L, q0, dt, outputs_per_period, 2 * per_output);
  const LoopSeries coarse = reference_loop(L, q0, dt, outputs_per_period, per_output);
  ASSERT_TRUE(run.estimator.has_value());
  const hinf::EstimatorSeries& est = *run.estimator;
  ASSERT_EQ(static_cast<std::size_t>(run.t.size()), ref.t.size()) << label;
  const int n = static_cast<int>(q0.size());
  std::vector<Vec> lib_q, lib_q_hat;
  for (Eigen::Index k = 0; k < run.t.size(); ++k) {
    ASSERT_NEAR(run.t[k], ref.t[static_cast<std::size_t>(k)], 1e-12 * std::max(1.0, std::abs(run.t[k]))) << label;
    lib_q.push_back(run.q.row(k).transpose());
    lib_q_hat.push_back(est.q_hat.row(k).transpose());
  }
  const double scale = std::max({1.0, max_abs(ref.q), max_abs(ref.q_hat)});
  const double tol_q = 20.0 * library_rtol * scale + max_abs_diff(ref.q, coarse.q);
  const double tol_q_hat = 20.0 * library_rtol * scale + max_abs_diff(ref.q_hat, coarse.q_hat);
  const double err_q = max_abs_diff(lib_q, ref.q), err_q_hat = max_abs_diff(lib_q_hat, ref.q_hat);
  std::printf("[closed loop vs RK4] %-18s |q| error %.2e (tol %.2e), |q_hat| error %.2e (tol %.2e), max |q_hat| %.2f\n",
              label.c_str(), err_q, tol_q, err_q_hat, tol_q_hat, max_abs(ref.q_hat));
  EXPECT_LT(err_q, tol_q) << label;
  EXPECT_LT(err_q_hat, tol_q_hat) << label;
  // Sigma: its extreme eigenvalues and rho(Sigma Z) from Eigen's solvers on the reference Sigma.
  double sigma_scale = 0.0, sigma_diff = 0.0;
  for (std::size_t k = 0; k < ref.Sigma.size(); ++k) {
    sigma_scale = std::max(sigma_scale, ref.Sigma[k].cwiseAbs().maxCoeff());
    sigma_diff = std::max(sigma_diff, (ref.Sigma[k] - coarse.Sigma[k]).cwiseAbs().maxCoeff());
  }
  const double tol_sigma = n * (20.0 * library_rtol * sigma_scale + sigma_diff);
  for (std::size_t k = 0; k < ref.Sigma.size(); ++k) {
    const Eigen::Index i = static_cast<Eigen::Index>(k);
    const Mat Sigma = symmetric(ref.Sigma[k]);
    const Vec eig = Eigen::SelfAdjointEigenSolver<Mat>(Sigma).eigenvalues();
    EXPECT_NEAR(est.sigma_min_eig[i], eig[0], tol_sigma) << label << " t = " << ref.t[k];
    EXPECT_NEAR(est.sigma_max_eig[i], eig[n - 1], tol_sigma) << label << " t = " << ref.t[k];
    const double Z_norm = L.design->Z(ref.t[k]).norm();
    EXPECT_NEAR(est.rho_sigma_z[i], hinf_ref::spectral_radius(Sigma * L.design->Z(ref.t[k])), tol_sigma * Z_norm)
        << label << " t = " << ref.t[k];
  }
  // The recorded control is the law (34) at the recorded estimate, and y = C q + sigma v with the
  // sample held at that time (C++ expressions in another order: round-off of the terms).
  const hinf::Trajectory& tr = L.design->trajectory();
  for (Eigen::Index k = 0; k < run.t.size(); ++k) {
    const double t = run.t[k];
    const Vec q = run.q.row(k).transpose(), q_hat = est.q_hat.row(k).transpose();
    const Mat K = L.design->gain(t);
    const Vec u = run.u_d.row(k).transpose() - L.kappa * K * q_hat;
    const double u_terms = run.u_d.row(k).cwiseAbs().maxCoeff() +
                           L.kappa * (K.cwiseAbs() * q_hat.cwiseAbs()).maxCoeff();
    EXPECT_LE((run.u.row(k).transpose() - u).cwiseAbs().maxCoeff(), kRoundoff * u_terms) << label << " t = " << t;
    EXPECT_LT((run.u_d.row(k).transpose() - tr.u_d(t)).cwiseAbs().maxCoeff(), kRoundoff * std::max(1.0, u_terms));
    const long sample = std::min<long>(L.noise.rows() - 1, static_cast<long>(std::floor((t - tr.t0()) / L.period + 1e-9)));
    const Vec v = L.noise.row(sample).transpose();
    const Vec y = L.C * q + L.sigma * v;
    const double y_terms = (L.C.cwiseAbs() * q.cwiseAbs()).maxCoeff() + L.sigma * v.cwiseAbs().maxCoeff();
    EXPECT_LT((est.y.row(k).transpose() - y).cwiseAbs().maxCoeff(), kRoundoff * std::max(1.0, y_terms))
        << label << " t = " << t;
  }
}

TEST(OutputFeedbackLoop, LinearPlantMatchesAnIndependentRk4) {
  // A LinearModel with C (p = 2 noise channels appended to D) under output feedback, with a
  // disturbance on its own channel; gamma = inf is the LQR law with the Kalman-Bucy filter.
  hinf_ref::Rng rng(9);
  const int n = 3;
  Mat A = hinf_ref::normal_matrix(rng, n, n);
  A.diagonal().array() += 0.5 - hinf_ref::spectral_abscissa(A);  // unstable: spectral abscissa 0.5
  const Mat B = hinf_ref::normal_matrix(rng, n, 1), D = hinf_ref::normal_matrix(rng, n, 2),
            C = hinf_ref::normal_matrix(rng, 2, n);
  Mat N(2, 2);
  N << 0.2, 0.05, 0.05, 0.1;
  const double t0 = 0.5, tf = 4.5, T = 0.2, dt = 0.1, sigma = 0.3;
  auto model = std::make_shared<const hinf::LinearModel>(A, B, D, C);
  const hinf::VectorSignal u_d(std::vector<hinf::Signal>{hinf::Signal(0.3, {hinf::Harmonic{0.5, 1.1, 0.0, false}})});
  Vec q_d0(3), q0(3);
  q_d0 << 0.2, -0.1, 0.4;
  q0 << 1.0, -0.5, 0.3;
  const auto tr = std::make_shared<const hinf::Trajectory>(model, q_d0, u_d, t0, tf);
  const hinf::Signal w1(0.0, {hinf::Harmonic{0.4, 2.0, 0.0, false}});
  const hinf::VectorSignal w(std::vector<hinf::Signal>{w1, hinf::Signal(), hinf::Signal(), hinf::Signal()});
  const RowMat noise = hinf::standard_normal_samples(17, hinf::noise_sample_count(t0, tf, T), 2);
  std::printf("[closed loop] linear plant: spectral abscissa of A %.3f\n", hinf_ref::spectral_abscissa(A));
  for (double gamma : {5.0, kInf}) {
    const auto design = hinf::solve_grde(tr, Mat::Identity(n, n), Mat::Identity(n, n), gamma,
                                         solver(Method::ERK, 1e-12, 1e-14));
    hinf::OutputFeedbackProblem problem;
    problem.design = design;
    problem.sigma = sigma;
    problem.sample_period = T;
    problem.noise = noise;
    problem.N = N;
    problem.Sigma0 = 0.5 * Mat::Identity(n, n);
    problem.Q = Mat::Identity(n, n);
    hinf::HinfStateFeedback law(design);
    const double rtol = 1e-11;
    const hinf::SimulationResult run = hinf::simulate_output_feedback(problem, law, w, q0, {},
                                                                      simulation(dt, solver(Method::ERK, rtol, 1e-13)));
    EXPECT_EQ(run.status, hinf::RunStatus::Completed);
    Loop L;
    L.f = [A](double, const Vec& q) { return Vec(A * q); };
    L.B = B;
    L.D = D;
    L.C = C;
    L.w = [](double t) { return Vec(Eigen::Vector2d(0.4 * std::sin(2.0 * t), 0.0)); };
    L.A_filter = [A](double, const Vec&, const Vec&) { return A; };
    L.design = design;
    L.sigma = sigma;
    L.period = T;
    L.N = N;
    L.Q = problem.Q;
    L.Sigma0 = problem.Sigma0;
    L.noise = noise;
    expect_matches_reference(run, L, q0, dt, 2, 50, rtol, std::isinf(gamma) ? "linear, LQG" : "linear, gamma 5");
    // The noise channels of w (the last two of four) hold the samples: copies; w2 is zero and
    // w1 the disturbance.
    const hinf::EstimatorSeries& est = *run.estimator;
    for (Eigen::Index k = 0; k < run.t.size(); ++k) {
      const long sample = std::min<long>(noise.rows() - 1, static_cast<long>(std::floor((run.t[k] - t0) / T + 1e-9)));
      EXPECT_EQ(run.w(k, 2), noise(sample, 0));
      EXPECT_EQ(run.w(k, 3), noise(sample, 1));
      EXPECT_EQ(run.w(k, 1), 0.0);
      EXPECT_NEAR(run.w(k, 0), 0.4 * std::sin(2.0 * run.t[k]), kRoundoff * 0.4);
      EXPECT_TRUE(std::isfinite(est.rho_sigma_z[k]));
    }
    EXPECT_TRUE(std::isnan(est.coupling_violation_t));
  }
}

hinf::VectorSignal paper_u_d() {
  return hinf::VectorSignal(std::vector<hinf::Signal>{
      hinf::Signal(1.0), hinf::Signal(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}})});
}

Vec paper_q_d0() {
  Vec q = Vec::Zero(6);
  q[0] = 1.0;
  return q;
}

// The actual start of Figure 1: 1 m behind, 1 m aside, 45 degrees heading error.
Vec paper_q0() {
  Vec q = paper_q_d0();
  q[3] = -1.0;
  q[4] = -1.0;
  q[5] = M_PI / 4;
  return q;
}

// 0.1 cos(2 pi 0.2 t) on w1..w3, zero on w4..w6 (the noise channels).
hinf::VectorSignal paper_disturbance() {
  const hinf::Signal w(0.0, {hinf::Harmonic{0.1, 2.0 * M_PI * 0.2, 0.0, true}});
  return hinf::VectorSignal(std::vector<hinf::Signal>{w, w, w, hinf::Signal(), hinf::Signal(), hinf::Signal()});
}

Vec paper_disturbance_process(double t) { return Vec::Constant(3, 0.1 * std::cos(2.0 * M_PI * 0.2 * t)); }

hinf::TrajectoryPtr ship_trajectory(double tf, const hinf::VectorSignal& u_d = paper_u_d(), const Vec& q_d0 = paper_q_d0()) {
  return std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::ShipModel>(), q_d0, u_d, 0.0, tf);
}

Loop ship_loop(const hinf::RiccatiSolutionPtr& design, bool estimate_A) {
  Loop L;
  L.f = [](double, const Vec& q) { return hinf_ref::ship_drift(q); };
  L.B = hinf_ref::ship_B();
  L.D = hinf_ref::ship_D_process();
  L.C = hinf_ref::ship_C();
  L.w = paper_disturbance_process;
  if (estimate_A)
    L.A_filter = [](double, const Vec& q_d, const Vec& q_hat) { return hinf_ref::ship_split_A(q_d, q_hat); };
  else
    L.A_filter = [](double, const Vec& q_d, const Vec&) { return hinf_ref::ship_jacobian(q_d); };
  L.heading_row = 2;
  L.design = design;
  return L;
}

TEST(OutputFeedbackLoop, ShipMatchesAnIndependentRk4) {
  // The ship (hand-written drift, and the decomposition's A(q_hat) for filter_A = estimate),
  // kappa = 0.75, non-diagonal N and Sigma0, noise held over 0.25 s, horizon 6 s.
  const double tf = 6.0, T = 0.25, dt = 0.05, gamma = 5.0;
  const auto tr = ship_trajectory(tf);
  const Mat I = Mat::Identity(6, 6);
  const auto design = hinf::solve_grde(tr, I, I, gamma, solver(Method::ERK, 1e-12, 1e-14));
  Mat N(3, 3);
  N << 0.25, 0.02, 0.0, 0.02, 0.3, 0.0, 0.0, 0.0, 0.2;
  hinf::OutputFeedbackProblem problem;
  problem.design = design;
  problem.sigma = 0.5;
  problem.sample_period = T;
  problem.noise = hinf::standard_normal_samples(3, hinf::noise_sample_count(0.0, tf, T), 3);
  problem.N = N;
  problem.Sigma0 = 0.8 * I + 0.1 * Mat::Ones(6, 6);
  problem.Q = I;
  hinf::HinfStateFeedback law(design, hinf::Signal(0.75));
  for (hinf::FilterLinearization filter_A : {hinf::FilterLinearization::Estimate, hinf::FilterLinearization::Desired}) {
    hinf::OutputFeedbackOptions options;
    options.filter_A = filter_A;
    const double rtol = 1e-11;
    const hinf::SimulationResult run = hinf::simulate_output_feedback(
        problem, law, paper_disturbance(), paper_q0(), options, simulation(dt, solver(Method::ERK, rtol, 1e-13)));
    Loop L = ship_loop(design, filter_A == hinf::FilterLinearization::Estimate);
    L.kappa = 0.75;
    L.sigma = problem.sigma;
    L.period = T;
    L.N = N;
    L.Q = I;
    L.Sigma0 = problem.Sigma0;
    L.noise = problem.noise;
    ASSERT_GT(run.estimator->q_hat.cwiseAbs().maxCoeff(), 0.5);  // the estimator is doing something
    expect_matches_reference(run, L, paper_q0(), dt, 5, 20, rtol, "ship, " + hinf::to_string(filter_A));
  }
}

hinf::OutputFeedbackProblem paper_problem(const hinf::RiccatiSolutionPtr& design, double sigma, std::uint64_t seed) {
  const hinf::Trajectory& tr = design->trajectory();
  hinf::OutputFeedbackProblem problem;
  problem.design = design;
  problem.sigma = sigma;
  problem.sample_period = 0.01;
  problem.noise = hinf::standard_normal_samples(seed, hinf::noise_sample_count(tr.t0(), tr.tf(), 0.01), 3);
  problem.N = 0.25 * Mat::Identity(3, 3);
  problem.Sigma0 = Mat::Identity(6, 6);
  problem.Q = Mat::Identity(6, 6);
  return problem;
}

TEST(OutputFeedbackLoop, WithoutNoiseTheEstimateIsExact) {
  // sigma = 0: the noise channels of w stay zero and y = C q exactly, whatever the samples hold.
  // From q0 = q_d0 with no disturbance the estimate stays 0 and the ship on the desired path
  // (to integration accuracy); from the paper's start the estimation error decays to the
  // integration's noise floor.
  const auto tr = ship_trajectory(20.0);
  const Mat I = Mat::Identity(6, 6);
  for (Method method : {Method::ERK, Method::BDF}) {
    const auto design = hinf::solve_grde(tr, I, I, 5.0, solver(method));
    const hinf::OutputFeedbackProblem problem = paper_problem(design, 0.0, 5);
    hinf::HinfStateFeedback law(design);
    const hinf::VectorSignal none = hinf::VectorSignal::zeros(6);
    const hinf::SimulationResult still =
        hinf::simulate_output_feedback(problem, law, none, paper_q_d0(), {}, simulation(0.01, solver(method)));
    const hinf::EstimatorSeries& e = *still.estimator;
    ASSERT_EQ(still.t.size(), 2001);
    // The exact solution is q_hat = 0, q = q_d: the runs stay there to 1e-8 (measured ~1e-12).
    EXPECT_LT(e.q_hat.cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((still.q - still.q_d).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((still.u - still.u_d).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_TRUE((e.q_hat.row(0).array() == 0.0).all());
    EXPECT_TRUE((still.w.array() == 0.0).all());            // no disturbance, and no noise at sigma = 0
    EXPECT_TRUE((e.y.array() == still.q.rightCols(3).array()).all());  // C selects: y = C q exactly

    for (hinf::FilterLinearization filter_A :
         {hinf::FilterLinearization::Estimate, hinf::FilterLinearization::Desired}) {
      hinf::OutputFeedbackOptions options;
      options.filter_A = filter_A;
      const hinf::SimulationResult run =
          hinf::simulate_output_feedback(problem, law, none, paper_q0(), options, simulation(0.01, solver(method)));
      const RowMat q_e = run.q_e();
      const RowMat error = run.estimator->q_hat - q_e;
      const double first = error.row(0).norm();
      EXPECT_NEAR(first, (paper_q0() - paper_q_d0()).norm(), kRoundoff);
      double late = 0.0;
      for (Eigen::Index k = 0; k < run.t.size(); ++k)
        if (run.t[k] >= 15.0) late = std::max(late, error.row(k).norm());
      std::printf("[no noise] %-3s %-8s: estimation error %.3f at t0, %.2e at tf, max %.2e after 15 s\n",
                  hinf::to_string(method).c_str(), hinf::to_string(filter_A).c_str(), first,
                  error.row(run.t.size() - 1).norm(), late);
      // The observer's error decays exponentially (measured: 1.8e-7 of the start at 20 s, at
      // most 4.7e-6 after 15 s); the bounds leave a factor of 20 or more.
      EXPECT_LT(error.row(run.t.size() - 1).norm(), 1e-5 * first) << hinf::to_string(method);
      EXPECT_LT(late, 1e-4 * first) << hinf::to_string(method);
      EXPECT_TRUE((run.w.array() == 0.0).all());
    }
  }
}

TEST(OutputFeedbackLoop, NoiseIsHeldOverEachPeriodAndOneSampleActsFromItsPeriodOn) {
  // T = 0.03 s with output every 0.01 s: the noise channels w4..w6 at t_k = k dt hold sample
  // floor(k / 3) (copies). Replacing the sample of [1.5, 1.53) leaves the run unchanged before
  // 1.5 s (the same computation: bit for bit) and changes it after.
  const double tf = 3.0, T = 0.03;
  const auto tr = ship_trajectory(tf);
  const Mat I = Mat::Identity(6, 6);
  const auto design = hinf::solve_grde(tr, I, I, 5.0);
  hinf::OutputFeedbackProblem problem = paper_problem(design, 0.5, 99);
  problem.sample_period = T;
  problem.noise = hinf::standard_normal_samples(99, hinf::noise_sample_count(0.0, tf, T), 3);
  ASSERT_EQ(problem.noise.rows(), 100);
  hinf::HinfStateFeedback law(design);
  const hinf::SimulationResult base =
      hinf::simulate_output_feedback(problem, law, paper_disturbance(), paper_q0(), {}, simulation(0.01, solver(Method::ERK)));
  for (Eigen::Index k = 0; k < base.t.size(); ++k)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(base.w(k, 3 + j), problem.noise(std::min<Eigen::Index>(k / 3, 99), j)) << k;
  hinf::OutputFeedbackProblem changed = problem;
  changed.noise.row(50) += Eigen::RowVector3d(3.0, -2.0, 1.0);
  const hinf::SimulationResult other =
      hinf::simulate_output_feedback(changed, law, paper_disturbance(), paper_q0(), {}, simulation(0.01, solver(Method::ERK)));
  const Eigen::Index k150 = 150;  // t = 1.5
  ASSERT_NEAR(base.t[k150], 1.5, 1e-12);
  for (Eigen::Index k = 0; k <= k150; ++k) {
    EXPECT_TRUE((other.q.row(k).array() == base.q.row(k).array()).all()) << k;
    EXPECT_TRUE((other.estimator->q_hat.row(k).array() == base.estimator->q_hat.row(k).array()).all()) << k;
  }
  for (Eigen::Index k = 0; k < k150; ++k) EXPECT_TRUE((other.estimator->y.row(k).array() == base.estimator->y.row(k).array()).all()) << k;
  // y at 1.5 s already holds the new sample: sigma times the change (round-off of |y|).
  const Vec dy = (other.estimator->y.row(k150) - base.estimator->y.row(k150)).transpose();
  EXPECT_LT((dy - 0.5 * Vec(Eigen::Vector3d(3.0, -2.0, 1.0))).cwiseAbs().maxCoeff(),
            kRoundoff * (1.0 + base.estimator->y.row(k150).cwiseAbs().maxCoeff()));
  EXPECT_GT((other.estimator->q_hat.row(k150 + 1) - base.estimator->q_hat.row(k150 + 1)).cwiseAbs().maxCoeff(), 1e-4);
  EXPECT_GT((other.q.row(k150 + 5) - base.q.row(k150 + 5)).cwiseAbs().maxCoeff(), 1e-6);
}

// OutputFeedbackOptions::sigma_eigenvalues = false (what run_scenarios uses) leaves out only the
// series sigma_min_eig and sigma_max_eig: every other output is the same computation, bit for
// bit; and the series it keeps says Sigma stayed positive definite, which the check without the
// series (a Cholesky factor) must agree with.
TEST(OutputFeedbackLoop, WithoutTheSigmaEigenvalueSeriesEverythingElseIsTheSame) {
  const double tf = 3.0;
  const auto tr = ship_trajectory(tf);
  const Mat I = Mat::Identity(6, 6);
  const auto design = hinf::solve_grde(tr, I, I, 5.0);
  const hinf::OutputFeedbackProblem problem = paper_problem(design, 0.5, 7);
  hinf::HinfStateFeedback law(design);
  hinf::OutputFeedbackOptions without;
  without.sigma_eigenvalues = false;
  const hinf::SimulationResult full =
      hinf::simulate_output_feedback(problem, law, paper_disturbance(), paper_q0(), {}, simulation(0.01, solver(Method::ERK)));
  const hinf::SimulationResult lean = hinf::simulate_output_feedback(problem, law, paper_disturbance(), paper_q0(),
                                                                     without, simulation(0.01, solver(Method::ERK)));
  ASSERT_EQ(full.t.size(), lean.t.size());
  EXPECT_TRUE((full.q.array() == lean.q.array()).all());
  EXPECT_TRUE((full.u.array() == lean.u.array()).all());
  EXPECT_TRUE((full.estimator->q_hat.array() == lean.estimator->q_hat.array()).all());
  EXPECT_TRUE((full.estimator->y.array() == lean.estimator->y.array()).all());
  EXPECT_TRUE((full.estimator->rho_sigma_z.array() == lean.estimator->rho_sigma_z.array()).all());
  EXPECT_TRUE(lean.estimator->sigma_min_eig.array().isNaN().all());
  EXPECT_TRUE(lean.estimator->sigma_max_eig.array().isNaN().all());
  EXPECT_GT(full.estimator->sigma_min_eig.minCoeff(), 0.0);
  const hinf::Metrics a = hinf::compute_metrics(tr->model(), full, I), b = hinf::compute_metrics(tr->model(), lean, I);
  for (const hinf::MetricDefinition& metric : hinf::metric_table()) {
    const double x = a.*metric.value, y = b.*metric.value;
    EXPECT_TRUE(x == y || (std::isnan(x) && std::isnan(y))) << metric.name;
  }
}

// Regression: the heading of C (q - q_d - q_hat) was wrapped before sigma v was added, so the
// innovation's heading left (-pi, pi] (here pi + 0.25) and the estimator turned its heading the
// long way round (+0.137 after 0.01 s against -0.117).
TEST(OutputFeedbackLoop, HeadingInnovationIsWrappedWithItsNoise) {
  // output_feedback.hpp and docs/mathematics.md: the heading innovation y_e - C q_hat is an
  // angle, wrapped to (-pi, pi]. Start with a heading error of pi - 0.05 and a first noise
  // sample of +0.6 on the heading (sigma = 0.5): the innovation's heading is pi + 0.25, i.e.
  // -pi + 0.25 as an angle, so the estimator must first turn its heading estimate negative.
  // The reference RK4 wraps the innovation, noise included; 0.2 s of the loop.
  const double tf = 0.2, T = 0.01, dt = 0.01;
  const auto tr = ship_trajectory(tf);
  const Mat I = Mat::Identity(6, 6);
  const auto design = hinf::solve_grde(tr, I, I, 5.0, solver(Method::ERK, 1e-12, 1e-14));
  hinf::OutputFeedbackProblem problem = paper_problem(design, 0.5, 1);
  problem.noise.setZero();
  problem.noise(0, 2) = 0.6;
  hinf::HinfStateFeedback law(design);
  Vec q0 = paper_q_d0();
  q0[5] = M_PI - 0.05;
  const hinf::VectorSignal none = hinf::VectorSignal::zeros(6);
  const double rtol = 1e-11;
  hinf::OutputFeedbackOptions options;
  options.filter_A = hinf::FilterLinearization::Desired;
  const hinf::SimulationResult run =
      hinf::simulate_output_feedback(problem, law, none, q0, options, simulation(dt, solver(Method::ERK, rtol, 1e-13)));
  Loop L = ship_loop(design, false);
  L.w = [](double) { return Vec(Vec::Zero(3)); };
  L.sigma = problem.sigma;
  L.period = T;
  L.N = problem.N;
  L.Q = I;
  L.Sigma0 = problem.Sigma0;
  L.noise = problem.noise;
  const LoopSeries ref = reference_loop(L, q0, dt, 1, 20);
  L.wrap_with_noise = false;
  const LoopSeries noise_outside = reference_loop(L, q0, dt, 1, 20);
  std::printf("[heading innovation] q_hat_psi at t = %.2f: library %+.4f, reference (wrapped with the noise) %+.4f, "
              "reference wrapped before the noise is added %+.4f\n",
              run.t[1], run.estimator->q_hat(1, 5), ref.q_hat[1][5], noise_outside.q_hat[1][5]);
  EXPECT_LT(ref.q_hat[1][5], 0.0);  // the reference turns the estimate the short way round
  // Library (rtol 1e-11) and RK4 (20 steps per 0.01 s, error ~1e-10): 1e-6 is generous.
  EXPECT_NEAR(run.estimator->q_hat(1, 5), ref.q_hat[1][5], 1e-6);
  EXPECT_NEAR(run.estimator->q_hat(run.t.size() - 1, 5), ref.q_hat.back()[5], 1e-6);
}

// Regression: the recorded measurement y = C q + sigma v kept the heading unwrapped (y_psi
// reached 8.2 rad here).
TEST(OutputFeedbackLoop, MeasuredHeadingIsWrapped) {
  // output_feedback.hpp: "The measured heading ... is an angle, wrapped to (-pi, pi]". A ship
  // turning at u2_d = 1 (r_d -> 2/3 rad/s) passes psi = pi within 6 s; its recorded measurement of the
  // heading must stay in (-pi, pi] and equal psi + sigma v as an angle.
  const double tf = 10.0;
  const hinf::VectorSignal u_d(std::vector<hinf::Signal>{hinf::Signal(1.0), hinf::Signal(1.0)});
  const auto tr = ship_trajectory(tf, u_d);
  const Mat I = Mat::Identity(6, 6);
  const auto design = hinf::solve_grde(tr, I, I, 5.0);
  const hinf::OutputFeedbackProblem problem = paper_problem(design, 0.5, 2);
  hinf::HinfStateFeedback law(design);
  const hinf::SimulationResult run =
      hinf::simulate_output_feedback(problem, law, paper_disturbance(), paper_q_d0(), {}, simulation(0.01, solver(Method::ERK)));
  ASSERT_GT(run.q_d(run.t.size() - 1, 5), 1.5 * M_PI);
  double lowest = kInf, highest = -kInf, worst = 0.0;
  for (Eigen::Index k = 0; k < run.t.size(); ++k) {
    const double y = run.estimator->y(k, 2);
    lowest = std::min(lowest, y);
    highest = std::max(highest, y);
    const double v = problem.noise(std::min<long>(problem.noise.rows() - 1, static_cast<long>(std::floor(run.t[k] / 0.01 + 1e-9))), 2);
    const double gap = std::abs(hinf_ref::wrapped(y - run.q(k, 5) - 0.5 * v));
    worst = std::max(worst, gap);
  }
  std::printf("[measured heading] range of y_psi over the run: [%.3f, %.3f]\n", lowest, highest);
  EXPECT_GT(lowest, -M_PI);
  EXPECT_LE(highest, M_PI);
  EXPECT_LT(worst, 1e-12);  // y_psi = psi + sigma v, as angles
}

// ======================================================================= the coupling condition

// Scalar LTI (a, b, d, c, q, qf, gamma, N, Sigma0) on [0, 5]: Z(t) -> 2 (stable root of
// 0.75 z^2 - z - 1 = 0), Sigma(t) -> 2.42, so Sigma Z rises from 1 through gamma^2 = 4 and falls
// back below it near tf (Z(tf) = 1).
struct ScalarCoupling {
  double a = 0.5, b = 1.0, d = 1.0, c = 1.0, q = 1.0, qf = 1.0, gamma = 2.0, N = 1.2, s0 = 0.5;
  double t0 = 0.0, tf = 5.0, dt = 0.01;
  double rho(double t) const {
    const double z = hinf_ref::scalar_riccati(a, b * b - d * d / (gamma * gamma), q, qf, tf - t);
    const double sigma = hinf_ref::scalar_riccati(a, c * c / N - q / (gamma * gamma), d * d, s0, t - t0);
    return z * sigma;
  }
};

TEST(CouplingCondition, ScalarViolationRaisesOrIsFlagged) {
  const ScalarCoupling s;
  // The closed forms: the first crossing of gamma^2 (bisection) and the first output time after.
  int first = -1;
  for (int k = 0; k <= 500 && first < 0; ++k)
    if (s.rho(k * s.dt) >= s.gamma * s.gamma) first = k;
  ASSERT_GT(first, 0);
  const double t_first = first * s.dt;
  const double t_cross = hinf_ref::bisect_threshold([&](double t) { return s.rho(t) < s.gamma * s.gamma; },
                                                    (first - 1) * s.dt, t_first, 1e-15);
  // No tie at the grid point: rho there is clearly above gamma^2, and the one before below.
  ASSERT_GT(s.rho(t_first) - s.gamma * s.gamma, 1e-4);
  ASSERT_GT(s.gamma * s.gamma - s.rho(t_first - s.dt), 1e-4);
  std::printf("[coupling] rho = sigma z crosses gamma^2 = 4 at t = %.6f; first output time after: %.2f\n", t_cross,
              t_first);
  auto model = std::make_shared<const hinf::LinearModel>(m11(s.a), m11(s.b), m11(s.d), m11(s.c));
  const auto tr = std::make_shared<const hinf::Trajectory>(model, Vec::Zero(1), hinf::VectorSignal::zeros(1), s.t0, s.tf);
  const auto design = hinf::solve_grde(tr, m11(s.q), m11(s.qf), s.gamma);
  hinf::OutputFeedbackProblem problem;
  problem.design = design;
  problem.sigma = 0.0;
  problem.sample_period = s.dt;
  problem.noise = RowMat::Zero(hinf::noise_sample_count(s.t0, s.tf, s.dt), 1);
  problem.N = m11(s.N);
  problem.Sigma0 = m11(s.s0);
  problem.Q = m11(s.q);
  hinf::HinfStateFeedback law(design);
  const hinf::VectorSignal none = hinf::VectorSignal::zeros(2);
  for (Method method : kMethods) {
    const std::string where = hinf::to_string(method);
    try {
      hinf::simulate_output_feedback(problem, law, none, Vec::Zero(1), {}, simulation(s.dt, solver(method)));
      ADD_FAILURE() << where << ": no CouplingConditionError";
    } catch (const hinf::CouplingConditionError& e) {
      EXPECT_NEAR(e.t(), t_first, 1e-12) << where;
      EXPECT_EQ(e.gamma(), s.gamma) << where;
      EXPECT_GE(e.rho(), s.gamma * s.gamma) << where;
      // Sigma and Z to ~1e-8 (default tolerances): rho to 1e-6 relative with a margin.
      EXPECT_NEAR(e.rho(), s.rho(t_first), 1e-6 * s.rho(t_first)) << where;
      const std::string message = e.what();
      for (const char* words : {"coupling", "rho(Sigma Z)", "Increase gamma", "Q0 - eta I"})
        EXPECT_NE(message.find(words), std::string::npos) << words << " not in: " << message;
    }
    // Flag: the run (zero state, so the singular gain multiplies a zero innovation) completes,
    // reports the first violation, and rho_sigma_z is the closed form along the whole run: it
    // rises above gamma^2 and falls below it again.
    hinf::OutputFeedbackOptions flag;
    flag.on_coupling_violation = hinf::CouplingPolicy::Flag;
    const hinf::SimulationResult run =
        hinf::simulate_output_feedback(problem, law, none, Vec::Zero(1), flag, simulation(s.dt, solver(method)));
    const hinf::EstimatorSeries& e = *run.estimator;
    EXPECT_EQ(run.status, hinf::RunStatus::Completed) << where;
    EXPECT_NEAR(e.coupling_violation_t, t_first, 1e-12) << where;
    ASSERT_EQ(run.t.size(), 501) << where;
    Eigen::Index first_above = -1;
    for (Eigen::Index k = 0; k < run.t.size(); ++k) {
      EXPECT_NEAR(e.rho_sigma_z[k], s.rho(run.t[k]), 1e-6 * s.rho(run.t[k])) << where << " t = " << run.t[k];
      if (first_above < 0 && e.rho_sigma_z[k] >= s.gamma * s.gamma) first_above = k;
    }
    EXPECT_EQ(run.t[first_above], e.coupling_violation_t) << where;
    EXPECT_LT(e.rho_sigma_z[run.t.size() - 1], s.gamma * s.gamma) << where;  // the first time is reported
    EXPECT_TRUE((e.q_hat.array() == 0.0).all()) << where;
  }
}

TEST(CouplingCondition, ShipViolationIsReportedWhereRhoCrossesGammaSquared) {
  // The ship with a small Sigma(t0) = 0.01 I and filter_A = "desired": the Sigma of the closed
  // loop obeys the equation solve_filter_riccati solves, so rho(Sigma Z) of the two solutions
  // (Eigen's eigenvalues of the product) says where the condition fails: first at t_cross
  // (bisection on the dense outputs), between the output times t_first - dt and t_first. At
  // t_cross the estimator gain [I - gamma^-2 Sigma Z]^-1 has a pole. Whether the loop's
  // integrator steps over it (the check at the output time t_first then finds the violation) or
  // stops at it (between output times) depends on the method and its step sizes, so both are
  // accepted, for every method; either way the run must report the coupling condition (not an
  // integration failure), with the rho of the reference at the reported time.
  const auto tr = ship_trajectory(40.0);
  const Mat I = Mat::Identity(6, 6), N = 0.25 * Mat::Identity(3, 3);
  const double dt = 0.01;
  for (double gamma : {2.5, 2.0}) {
    const auto design = hinf::solve_grde(tr, I, I, gamma);
    const auto filter = hinf::solve_filter_riccati(tr, N, I, gamma, 0.01 * I);
    const auto rho = [&](double t) { return hinf_ref::spectral_radius(filter->Sigma(t) * design->Z(t)); };
    int first = -1;
    for (int k = 0; k <= 300 && first < 0; ++k)
      if (rho(dt * k) >= gamma * gamma) first = k;
    ASSERT_GT(first, 0) << gamma;
    const double t_first = dt * first, rho_first = rho(t_first);
    const double t_cross = hinf_ref::bisect_threshold([&](double t) { return rho(t) < gamma * gamma; },
                                                      dt * (first - 1), t_first, 1e-12);
    hinf::OutputFeedbackProblem problem = paper_problem(design, 0.5, 20000601);
    problem.Sigma0 = 0.01 * I;
    hinf::HinfStateFeedback law(design);
    hinf::OutputFeedbackOptions options;
    options.filter_A = hinf::FilterLinearization::Desired;
    for (Method method : {Method::Auto, Method::ERK, Method::Adams}) {
      const std::string where = hinf::str_cat("gamma ", gamma, " ", hinf::to_string(method));
      try {
        hinf::simulate_output_feedback(problem, law, paper_disturbance(), paper_q0(), options,
                                       simulation(dt, solver(method)));
        ADD_FAILURE() << where << ": no CouplingConditionError";
      } catch (const hinf::CouplingConditionError& e) {
        const bool at_output_time = std::abs(e.t() - t_first) <= 1e-12;
        std::printf("[coupling ship] %-11s: rho crosses gamma^2 at %.6f (first output time after: %.2f, rho %.5f); "
                    "error at t = %.6f (%s), rho %.5f\n",
                    where.c_str(), t_cross, t_first, rho_first, e.t(),
                    at_output_time ? "output time" : "between output times", e.rho());
        EXPECT_EQ(e.gamma(), gamma) << where;
        // Sigma and Z of the loop and of the reference solves, all at rtol 1e-8: rho to ~1e-7
        // relative; 1e-6 leaves a factor of 10.
        EXPECT_NEAR(e.rho(), rho(e.t()), 1e-6 * rho(e.t())) << where;
        if (at_output_time) {
          EXPECT_GE(e.rho(), gamma * gamma) << where;
        } else {
          // Stopped by the pole: not before the last output time that passed, not after t_first,
          // and with rho at gamma^2 (the library calls a stop with rho within 1e-3 of it the
          // coupling's).
          EXPECT_GT(e.t(), t_first - dt) << where;
          EXPECT_LT(e.t(), t_first) << where;
          EXPECT_GE(e.rho(), (1.0 - 1e-3) * gamma * gamma) << where;
        }
      }
    }
  }
}

// ======================================================================= stiff loops: bdf -> SDIRK4

struct StiffProblem {
  hinf::RiccatiSolutionPtr design;
  hinf::OutputFeedbackProblem problem;
  hinf::VectorSignal w;
  Vec q0;
  Mat A, B, D, C;
};

// A LinearModel with C and a fast stable mode (eigenvalue -5000) driving the slow ones.
StiffProblem stiff_problem(double tf) {
  StiffProblem s;
  s.A.resize(3, 3);
  s.A << -5000.0, 0.0, 0.0, 1.0, -0.5, 1.0, 200.0, -1.0, -0.2;
  s.B.resize(3, 1);
  s.B << 1.0, 0.0, 1.0;
  s.D.resize(3, 2);
  s.D << 1.0, 0.0, 0.0, 1.0, 0.0, 0.5;
  s.C.resize(2, 3);
  s.C << 0.0, 1.0, 0.0, 1.0, 0.0, 1.0;
  auto model = std::make_shared<const hinf::LinearModel>(s.A, s.B, s.D, s.C);
  const hinf::VectorSignal u_d(std::vector<hinf::Signal>{hinf::Signal(0.0, {hinf::Harmonic{1.0, 2.0, 0.0, false}})});
  const auto tr = std::make_shared<const hinf::Trajectory>(model, Vec::Zero(3), u_d, 0.0, tf);
  s.design = hinf::solve_grde(tr, Mat::Identity(3, 3), Mat::Identity(3, 3), 5.0, solver(Method::BDF, 1e-12, 1e-14));
  s.problem.design = s.design;
  s.problem.sigma = 0.1;
  s.problem.sample_period = 0.01;
  s.problem.noise = hinf::standard_normal_samples(7, hinf::noise_sample_count(0.0, tf, 0.01), 2);
  s.problem.N = 0.01 * Mat::Identity(2, 2);
  s.problem.Sigma0 = Mat::Identity(3, 3);
  s.problem.Q = Mat::Identity(3, 3);
  s.w = hinf::VectorSignal(std::vector<hinf::Signal>{hinf::Signal(0.0, {hinf::Harmonic{0.5, 3.0, 0.0, false}}),
                                                     hinf::Signal(), hinf::Signal(), hinf::Signal()});
  s.q0.resize(3);
  s.q0 << 0.3, -0.5, 0.2;
  return s;
}

TEST(StiffLoop, BdfAndAutoSwitchToSdirk4AndAgreeWithErk) {
  const StiffProblem s = stiff_problem(2.0);
  hinf::HinfStateFeedback law(s.design);
  const hinf::SimulationResult bdf =
      hinf::simulate_output_feedback(s.problem, law, s.w, s.q0, {}, simulation(0.01, solver(Method::BDF)));
  // output_feedback.hpp: for the sampled loop "auto" and "bdf" step the same way (Dormand-Prince,
  // then SDIRK4 once stiff): the same code on the same input, the same run bit for bit.
  const hinf::SimulationResult automatic =
      hinf::simulate_output_feedback(s.problem, law, s.w, s.q0, {}, simulation(0.01, solver(Method::Auto)));
  EXPECT_EQ(automatic.integrator, bdf.integrator);
  EXPECT_TRUE(automatic.q.cwiseEqual(bdf.q).all());
  EXPECT_TRUE(automatic.estimator->q_hat.cwiseEqual(bdf.estimator->q_hat).all());
  EXPECT_TRUE(automatic.estimator->rho_sigma_z.cwiseEqual(bdf.estimator->rho_sigma_z).all());
  const hinf::SimulationResult erk =
      hinf::simulate_output_feedback(s.problem, law, s.w, s.q0, {}, simulation(0.01, solver(Method::ERK, 1e-10, 1e-12)));
  std::printf("[stiff loop] bdf: \"%s\", %ld steps; erk: \"%s\", %ld steps\n", bdf.integrator.c_str(), bdf.stats.steps,
              erk.integrator.c_str(), erk.stats.steps);
  EXPECT_NE(bdf.integrator.find("SDIRK4"), std::string::npos);
  EXPECT_NE(bdf.integrator.find("stiff"), std::string::npos);
  EXPECT_EQ(erk.integrator.find("SDIRK4"), std::string::npos);
  EXPECT_GE(bdf.stats.jac_evals, 1);
  EXPECT_LT(bdf.stats.steps, erk.stats.steps);
  const double scale = std::max(1.0, erk.q.cwiseAbs().maxCoeff());
  EXPECT_GT(erk.q.cwiseAbs().maxCoeff(), 0.5);
  // bdf at rtol 1e-8 and erk at 1e-10, each within a few tolerances per unit of time of the
  // exact solution (2 s): 100 x (1e-8 + 1e-10) x the scale, a safety factor of 10 or more
  // (measured 5e-9 and 9e-9 against 1e-6).
  const double tol = 100.0 * (1e-8 + 1e-10) * scale;
  const double dq = (bdf.q - erk.q).cwiseAbs().maxCoeff();
  const double dq_hat = (bdf.estimator->q_hat - erk.estimator->q_hat).cwiseAbs().maxCoeff();
  std::printf("[stiff loop] bdf vs erk: max |dq| %.2e, max |dq_hat| %.2e (bound %.2e)\n", dq, dq_hat, tol);
  EXPECT_LT(dq, tol);
  EXPECT_LT(dq_hat, tol);
  EXPECT_LT((bdf.u - erk.u).cwiseAbs().maxCoeff(), tol * std::max(1.0, s.design->gain(0.0).norm()));
  EXPECT_LT(max_rel(bdf.estimator->sigma_min_eig, erk.estimator->sigma_min_eig), 1e-6);
  EXPECT_LT(max_rel(bdf.estimator->sigma_max_eig, erk.estimator->sigma_max_eig), 1e-6);
  EXPECT_LT(max_rel(bdf.estimator->rho_sigma_z, erk.estimator->rho_sigma_z), 1e-6);
}

TEST(StiffLoop, SdirkRunMatchesAnIndependentRk4) {
  // The stiff loop against the RK4 of this file with 400 steps per 0.01 s (|h lambda| = 0.125)
  // up to 0.6 s, past the switch to SDIRK4.
  const double tf = 0.6;
  const StiffProblem s = stiff_problem(tf);
  hinf::HinfStateFeedback law(s.design);
  const hinf::SimulationResult run =
      hinf::simulate_output_feedback(s.problem, law, s.w, s.q0, {}, simulation(0.01, solver(Method::BDF)));
  ASSERT_NE(run.integrator.find("SDIRK4"), std::string::npos) << run.integrator;
  Loop L;
  const Mat A = s.A;
  L.f = [A](double, const Vec& q) { return Vec(A * q); };
  L.B = s.B;
  L.D = s.D;
  L.C = s.C;
  L.w = [](double t) { return Vec(Eigen::Vector2d(0.5 * std::sin(3.0 * t), 0.0)); };
  L.A_filter = [A](double, const Vec&, const Vec&) { return A; };
  L.design = s.design;
  L.sigma = s.problem.sigma;
  L.period = 0.01;
  L.N = s.problem.N;
  L.Q = s.problem.Q;
  L.Sigma0 = s.problem.Sigma0;
  L.noise = s.problem.noise;
  expect_matches_reference(run, L, s.q0, 0.01, 1, 200, 1e-8, "stiff, bdf/SDIRK4");
}

// ======================================================================= bad inputs

TEST(OutputFeedbackInputs, BadProblemsAreInputErrors) {
  const auto tr = ship_trajectory(2.0);
  const Mat I = Mat::Identity(6, 6);
  const auto design = hinf::solve_grde(tr, I, I, 5.0);
  const hinf::OutputFeedbackProblem good = paper_problem(design, 0.5, 1);
  ASSERT_EQ(good.noise.rows(), 200);
  hinf::HinfStateFeedback law(design);
  struct Bad {
    const char* label;
    std::function<void(hinf::OutputFeedbackProblem&, Vec&, hinf::VectorSignal&)> change;
    std::vector<const char*> words;
  };
  const std::vector<Bad> cases = {
      {"noise 199 rows", [](auto& p, auto&, auto&) { p.noise = RowMat::Zero(199, 3); }, {"noise", "200 rows"}},
      {"noise 201 rows", [](auto& p, auto&, auto&) { p.noise = RowMat::Zero(201, 3); }, {"noise", "200 rows"}},
      {"noise 2 columns", [](auto& p, auto&, auto&) { p.noise = RowMat::Zero(200, 2); }, {"noise", "3 columns"}},
      {"NaN in noise", [](auto& p, auto&, auto&) { p.noise(100, 1) = NAN; }, {"noise"}},
      {"q0 5 states", [](auto&, auto& q0, auto&) { q0 = Vec::Zero(5); }, {"q0"}},
      {"q0 NaN", [](auto&, auto& q0, auto&) { q0[3] = NAN; }, {"q0"}},
      {"sigma < 0", [](auto& p, auto&, auto&) { p.sigma = -0.1; }, {"sigma"}},
      {"sigma NaN", [](auto& p, auto&, auto&) { p.sigma = NAN; }, {"sigma"}},
      {"period 0", [](auto& p, auto&, auto&) { p.sample_period = 0.0; }, {"period"}},
      {"N 2x2", [](auto& p, auto&, auto&) { p.N = Mat::Identity(2, 2); }, {"N"}},
      {"N singular", [](auto& p, auto&, auto&) { p.N(1, 1) = 0.0; }, {"N", "positive definite"}},
      {"Sigma0 negative", [](auto& p, auto&, auto&) { p.Sigma0 = -Mat::Identity(6, 6); }, {"Sigma0", "positive definite"}},
      {"Sigma0 5x5", [](auto& p, auto&, auto&) { p.Sigma0 = Mat::Identity(5, 5); }, {"Sigma0"}},
      {"Q negative", [](auto& p, auto&, auto&) { p.Q = -Mat::Identity(6, 6); }, {"Q", "semidefinite"}},
      {"no design", [](auto& p, auto&, auto&) { p.design = nullptr; }, {"design"}},
      {"disturbance 3 channels", [](auto&, auto&, auto& w) { w = hinf::VectorSignal::zeros(3); }, {"disturbance"}},
  };
  for (const Bad& bad : cases) {
    hinf::OutputFeedbackProblem p = good;
    Vec q0 = paper_q0();
    hinf::VectorSignal w = paper_disturbance();
    bad.change(p, q0, w);
    try {
      hinf::simulate_output_feedback(p, law, w, q0);
      ADD_FAILURE() << bad.label << ": accepted";
    } catch (const hinf::InputError& e) {
      for (const char* word : bad.words)
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << bad.label << ": " << word << " not in " << e.what();
    }
  }
  // A model without C cannot be filtered or simulated with measurements.
  auto plain = std::make_shared<const hinf::LinearModel>(-Mat::Identity(2, 2), Mat::Ones(2, 1), Mat::Identity(2, 2));
  const auto plain_tr = std::make_shared<const hinf::Trajectory>(plain, Vec::Zero(2), hinf::VectorSignal::zeros(1), 0.0, 1.0);
  const auto plain_design = hinf::solve_grde(plain_tr, Mat::Identity(2, 2), Mat::Identity(2, 2), 5.0);
  EXPECT_THROW(hinf::solve_filter_riccati(plain_tr, m11(1.0), Mat::Identity(2, 2), 5.0, Mat::Identity(2, 2)),
               hinf::InputError);
  hinf::OutputFeedbackProblem p;
  p.design = plain_design;
  p.sigma = 0.1;
  p.noise = RowMat::Zero(100, 1);
  p.N = m11(1.0);
  p.Sigma0 = Mat::Identity(2, 2);
  p.Q = Mat::Identity(2, 2);
  hinf::HinfStateFeedback plain_law(plain_design);
  EXPECT_THROW(hinf::simulate_output_feedback(p, plain_law, hinf::VectorSignal::zeros(2), Vec::Zero(2)), hinf::InputError);
}

// ======================================================================= the paper's Figure 2

std::string paper_fig2_path() { return std::string(HINF_SOURCE_DIR) + "/scenarios/paper_fig2.toml"; }

class PaperFigure2 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scenario_ = std::make_unique<hinf::Scenario>(hinf::load_scenario_toml(paper_fig2_path()));
    run_ = std::make_unique<hinf::RunResult>(hinf::run_scenario(*scenario_));
  }
  static void TearDownTestSuite() {
    run_.reset();
    scenario_.reset();
  }
  static std::unique_ptr<hinf::Scenario> scenario_;
  static std::unique_ptr<hinf::RunResult> run_;
};
std::unique_ptr<hinf::Scenario> PaperFigure2::scenario_;
std::unique_ptr<hinf::RunResult> PaperFigure2::run_;

TEST_F(PaperFigure2, TracksEstimatesAndKeepsTheCouplingCondition) {
  const hinf::RunResult& r = *run_;
  const hinf::SimulationResult& run = r.simulation;
  ASSERT_TRUE(r.output_feedback);
  ASSERT_TRUE(run.estimator.has_value());
  const hinf::EstimatorSeries& e = *run.estimator;
  EXPECT_EQ(run.status, hinf::RunStatus::Completed);
  ASSERT_EQ(run.t.size(), 4001);
  const RowMat q_e = run.q_e();
  std::vector<double> position(static_cast<std::size_t>(run.t.size()));
  for (Eigen::Index k = 0; k < run.t.size(); ++k) position[static_cast<std::size_t>(k)] = std::hypot(q_e(k, 3), q_e(k, 4));
  // The start of Figure 1: 1 m behind and 1 m aside, sqrt(2) m off.
  EXPECT_NEAR(position.front(), std::sqrt(2.0), kRoundoff);
  double late_max = 0.0;
  for (Eigen::Index k = 0; k < run.t.size(); ++k)
    if (run.t[k] >= 20.0) late_max = std::max(late_max, position[static_cast<std::size_t>(k)]);
  std::printf("[paper fig. 2] position error: %.3f m at t0, %.3f m at tf, max %.3f m over the last half\n",
              position.front(), position.back(), late_max);
  EXPECT_LT(position.back(), 0.2 * std::sqrt(2.0));
  EXPECT_LT(late_max, 0.3 * std::sqrt(2.0));
  // The coupling condition holds throughout: rho(Sigma Z) < gamma^2 = 25, Sigma > 0.
  EXPECT_TRUE(std::isnan(e.coupling_violation_t));
  EXPECT_LT(e.rho_sigma_z.maxCoeff(), 25.0);
  EXPECT_GT(e.sigma_min_eig.minCoeff(), 0.0);
  // Sigma(t0) = (Q0 - eta I)^-1 = (2 I - I)^-1 = I, q_hat(t0) = 0.
  EXPECT_NEAR(e.sigma_min_eig[0], 1.0, kRoundoff);
  EXPECT_NEAR(e.sigma_max_eig[0], 1.0, kRoundoff);
  EXPECT_TRUE((e.q_hat.row(0).array() == 0.0).all());
  // The estimation error shrinks from |q_e(t0)| = 1.62, and over the last half the estimate of
  // the position beats the raw measurement (sigma = 0.5 on x and y).
  double est2 = 0.0, meas2 = 0.0, all2 = 0.0;
  int count = 0;
  for (Eigen::Index k = 0; k < run.t.size(); ++k) {
    if (run.t[k] < 20.0) continue;
    est2 += std::pow(e.q_hat(k, 3) - q_e(k, 3), 2) + std::pow(e.q_hat(k, 4) - q_e(k, 4), 2);
    meas2 += std::pow(e.y(k, 0) - run.q(k, 3), 2) + std::pow(e.y(k, 1) - run.q(k, 4), 2);
    all2 += (e.q_hat.row(k) - q_e.row(k)).squaredNorm();
    ++count;
  }
  const double estimate_rms = std::sqrt(est2 / count), measurement_rms = std::sqrt(meas2 / count);
  const double first = (e.q_hat.row(0) - q_e.row(0)).norm();
  std::printf("[paper fig. 2] estimation error %.3f at t0, RMS %.3f over the last half; position: estimate %.3f, "
              "measurement %.3f m RMS\n",
              first, std::sqrt(all2 / count), estimate_rms, measurement_rms);
  EXPECT_LT(std::sqrt(all2 / count), 0.25 * first);
  // The measurement error is sigma v: RMS 0.5 sqrt(2) up to the sampling error of its 2 x 2001
  // squared standard normals (the RMS has relative standard deviation 1 / sqrt(2 x 4002) =
  // 0.011: 5 sigma is 0.056).
  EXPECT_NEAR(measurement_rms, 0.5 * std::sqrt(2.0), 0.056 * 0.5 * std::sqrt(2.0));
  EXPECT_LT(estimate_rms, 0.5 * measurement_rms);
  // The metrics of the run, from the series (scenarios.md definitions): the largest recorded rho,
  // the RMS estimation error over the last half (C++ sums in another order: round-off of 2000
  // terms).
  EXPECT_EQ(r.metrics.max_rho_sigma_z, e.rho_sigma_z.maxCoeff());
  EXPECT_NEAR(r.metrics.rms_estimation_error_last_half, std::sqrt(all2 / count),
              4.0 * count * hinf_test::kEps * std::sqrt(all2 / count));
}

TEST_F(PaperFigure2, SameSeedSameRunBitForBitAnotherSeedAnotherRun) {
  const hinf::RunResult again = hinf::run_scenario(hinf::load_scenario_toml(paper_fig2_path()));
  const hinf::SimulationResult &a = again.simulation, &b = run_->simulation;
  for (const auto& [x, y] : {std::pair{&a.q, &b.q}, std::pair{&a.u, &b.u}, std::pair{&a.w, &b.w},
                            std::pair{&a.estimator->q_hat, &b.estimator->q_hat}, std::pair{&a.estimator->y, &b.estimator->y}})
    EXPECT_TRUE((*x).cwiseEqual(*y).all());
  EXPECT_TRUE(a.estimator->rho_sigma_z.cwiseEqual(b.estimator->rho_sigma_z).all());
  // The scenario's noise is the seeded standard normal sequence, one row per 0.01 s, and
  // passing it explicitly replays the run exactly.
  const RowMat noise = hinf::scenario_noise(*scenario_);
  EXPECT_TRUE(noise.cwiseEqual(hinf::standard_normal_samples(20000601, 4000, 3)).all());
  const hinf::RunResult replay = hinf::run_scenario_with_noise(*scenario_, noise);
  EXPECT_TRUE(replay.simulation.q.cwiseEqual(b.q).all());
  EXPECT_TRUE(replay.simulation.estimator->q_hat.cwiseEqual(b.estimator->q_hat).all());
  // Another seed: the same start, other measurements, another run.
  hinf::Scenario other = *scenario_;
  other.measurement->seed = 20000602;
  const hinf::RunResult c = hinf::run_scenario(other);
  EXPECT_TRUE(c.simulation.q.row(0).cwiseEqual(b.q.row(0)).all());
  EXPECT_GT((c.simulation.q - b.q).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT((c.simulation.estimator->y - b.estimator->y).cwiseAbs().maxCoeff(), 0.5);
  // Figure 1's scenario has no measurements: no noise to draw.
  EXPECT_THROW(hinf::scenario_noise(hinf::load_scenario_toml(std::string(HINF_SOURCE_DIR) + "/scenarios/paper_fig1.toml")),
               hinf::InputError);
}

TEST_F(PaperFigure2, RunScenarioIsTheApiRun) {
  // run_scenario on paper_fig2.toml is solve_grde and simulate_output_feedback with the file's
  // [solver] (bdf, rtol 1e-8) and [output] dt, Sigma0 = (Q0 - eta I)^-1 = (2 I - I)^-1 = I,
  // N = sigma^2 I = 0.25 I, Q = I, the seeded noise and the file's signals: the same computation
  // on the same numbers, equal.
  const auto tr = ship_trajectory(40.0);
  const Mat I = Mat::Identity(6, 6);
  ASSERT_EQ(scenario_->solver.method, Method::BDF);
  const auto design = hinf::solve_grde(tr, I, I, 5.0, scenario_->solver);
  const hinf::OutputFeedbackProblem problem = paper_problem(design, 0.5, 20000601);
  hinf::HinfStateFeedback law(design, hinf::Signal(1.0));
  const hinf::SimulationResult api = hinf::simulate_output_feedback(problem, law, paper_disturbance(), paper_q0(), {},
                                                                    scenario_->simulation_options());
  const hinf::SimulationResult& file = run_->simulation;
  EXPECT_EQ(api.integrator, file.integrator);
  ASSERT_EQ(api.t.size(), file.t.size());
  EXPECT_TRUE(api.t.cwiseEqual(file.t).all());
  EXPECT_TRUE(api.q.cwiseEqual(file.q).all());
  EXPECT_TRUE(api.u.cwiseEqual(file.u).all());
  EXPECT_TRUE(api.w.cwiseEqual(file.w).all());
  EXPECT_TRUE(api.estimator->q_hat.cwiseEqual(file.estimator->q_hat).all());
  EXPECT_TRUE(api.estimator->y.cwiseEqual(file.estimator->y).all());
  EXPECT_TRUE(api.estimator->rho_sigma_z.cwiseEqual(file.estimator->rho_sigma_z).all());
  EXPECT_TRUE(api.estimator->sigma_min_eig.cwiseEqual(file.estimator->sigma_min_eig).all());
  EXPECT_TRUE(api.estimator->sigma_max_eig.cwiseEqual(file.estimator->sigma_max_eig).all());
}

TEST_F(PaperFigure2, MethodsAgree) {
  // The file's method is bdf: CVODE BDF for the GRDE, and for the sampled loop (plant,
  // estimator and filter) Dormand-Prince, which stays (the loop is not stiff: no switch to
  // SDIRK4). auto, erk and adams (for the GRDE and the loop) give the same run to their
  // accuracy. At rtol 1e-8 each run is within ~10 rtol of the exact one per unit of the
  // solution's size (|q| <= ~40 m over 40 s), so two runs differ by at most ~20 rtol x the
  // scale; the bound is 100 rtol x the scale (a safety factor of 5; measured: 2.3e-8 auto and
  // erk, 1.8e-7 adams, against 4e-5).
  const hinf::SimulationResult& bdf = run_->simulation;
  EXPECT_NE(bdf.integrator.find("dormand-prince"), std::string::npos) << bdf.integrator;
  EXPECT_EQ(bdf.integrator.find("SDIRK4"), std::string::npos) << bdf.integrator;
  const double scale = std::max(1.0, bdf.q.cwiseAbs().maxCoeff());
  for (Method method : {Method::Auto, Method::ERK, Method::Adams}) {
    hinf::Scenario s = *scenario_;
    s.solver.method = method;
    const hinf::SimulationResult other = hinf::run_scenario(s).simulation;
    if (method == Method::Adams) {
      EXPECT_NE(other.integrator.find("Adams"), std::string::npos) << other.integrator;
    }
    const double dq = (other.q - bdf.q).cwiseAbs().maxCoeff();
    const double dq_hat = (other.estimator->q_hat - bdf.estimator->q_hat).cwiseAbs().maxCoeff();
    const double drho = max_rel(other.estimator->rho_sigma_z, bdf.estimator->rho_sigma_z);
    std::printf("[paper fig. 2] %-5s vs bdf: max |dq| %.2e, max |dq_hat| %.2e, rho(Sigma Z) %.2e relative\n",
                hinf::to_string(method).c_str(), dq, dq_hat, drho);
    EXPECT_LT(dq, 100.0 * s.solver.rtol * scale) << hinf::to_string(method);
    EXPECT_LT(dq_hat, 100.0 * s.solver.rtol * scale) << hinf::to_string(method);
    // rho(Sigma Z) is O(1) to O(25): relative, with the same factor.
    EXPECT_LT(drho, 100.0 * s.solver.rtol) << hinf::to_string(method);
  }
}

}  // namespace
