// The certificates of paper §3 (eqs. 22-24, hinf::certify) and the attenuation guarantee of
// eq. (12), against independent truth:
//   * m, M (22) and p(t) = lambda_min(Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z) (23) from
//     Eigen's eigenvalues of matrices built here, on fine grids (the library refines its extremes
//     between samples: within 1e-8 of the grid's, on the safe side);
//   * the ship's remainder bound |f(q_d + e) - f(q_d) - A_e e| <= L |e|^2 against remainders
//     sampled with the ship written out by hand (references.hpp);
//   * the radius, attraction radius and decay rate of (24) from their formulas; closed loops
//     started on the certified ball decay at the certified rate;
//   * for an LTI plant (where the linearization is exact) the completed square
//         L_gamma = q_e(t0)' Z(t0) q_e(t0) - gamma^2 int |w - gamma^-2 D' Z q_e|^2 dt
//     (differentiate V = q_e' Z q_e along the closed loop with u = u_d - B' Z q_e), so from a zero
//     initial error L_gamma <= 0 and the L2 gain is <= gamma, and L_gamma = -gamma^2 int |v|^2
//     exactly for w = v + the worst case (16).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hinf/control/analysis.hpp"
#include "hinf/control/controller.hpp"
#include "hinf/control/disturbance.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"
#include "hinf/scenario/scenario.hpp"
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Certificates;
using hinf::Mat;
using hinf::Method;
using hinf::RowMat;
using hinf::SolverOptions;
using hinf::Vec;
using hinf_test::kEps;
using hinf_test::kRoundoff;

constexpr double kInf = std::numeric_limits<double>::infinity();

SolverOptions solver(Method method, double rtol = 1e-8, double atol = 1e-10) {
  SolverOptions o;
  o.method = method;
  o.rtol = rtol;
  o.atol = atol;
  return o;
}

// A uniform grid of `count` times plus the solver's steps and their midpoints.
std::vector<double> fine_times(const hinf::SymmetricSolution& sol, int count) {
  std::vector<double> times;
  for (int k = 0; k < count; ++k) times.push_back(sol.t0() + (sol.tf() - sol.t0()) * k / (count - 1));
  const std::vector<double> steps = sol.dense().breakpoints();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    times.push_back(steps[k]);
    if (k + 1 < steps.size()) times.push_back(0.5 * (steps[k] + steps[k + 1]));
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

// P(t) = Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z of eq. (23).
Mat P_matrix(const Mat& Z, const Mat& B, const Mat& D, const Mat& Q, double kappa, double gamma) {
  const Mat ZB = Z * B, ZD = Z * D;
  const Mat P = Q + (2.0 * kappa - 1.0) * ZB * ZB.transpose() + ZD * ZD.transpose() / (gamma * gamma);
  return 0.5 * (P + P.transpose());
}

double lambda_min(const Mat& S) { return Eigen::SelfAdjointEigenSolver<Mat>(S).eigenvalues()(0); }
double lambda_max(const Mat& S) {
  return Eigen::SelfAdjointEigenSolver<Mat>(S).eigenvalues()(S.rows() - 1);
}

// The ship's remainder bound, derived here: with e = (e_u, e_v, e_r, e_x, e_y, e_psi), r = f(q_d
// + e) - f(q_d) - A_e e has r_u = m_u e_v e_r, r_v = m_v e_u e_r, r_r = m_r e_u e_v, r_psi = 0 and
// r_xy = [R(psi_d + e_psi) - R(psi_d) - R'(psi_d) e_psi] (u_d, v_d) + [R(psi_d + e_psi) - R(psi_d)]
// (e_u, e_v), R the rotation; |e^{ib} - 1 - ib| <= b^2 / 2, |e^{ib} - 1| <= |b| and |e_i e_j| <=
// |e|^2 / 2 give |r| <= L |e|^2 for every e, L = 1/2 sqrt(m_u^2 + m_v^2 + m_r^2 + (|(u_d, v_d)| +
// 1)^2). The sampling test below checks that it is one.
double ship_L(const Vec& q_d) {
  const hinf_ref::ShipParams p;
  const double speed = std::hypot(q_d[0], q_d[1]);
  return 0.5 * std::sqrt(p.m_u * p.m_u + p.m_v * p.m_v + p.m_r * p.m_r + (speed + 1.0) * (speed + 1.0));
}

hinf::TrajectoryPtr paper_trajectory() {
  Vec q_d0 = Vec::Zero(6);
  q_d0[0] = 1.0;
  const hinf::VectorSignal u_d(std::vector<hinf::Signal>{
      hinf::Signal(1.0), hinf::Signal(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}})});
  return std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::ShipModel>(), q_d0, u_d, 0.0, 40.0);
}

// ======================================================================= the paper's ship

// The paper's design (gamma = 5, Q = Qf = I) solved tightly (rtol 1e-10), so that V = q_e' Z q_e
// along the closed loops is accurate far below the slack of the decay checks; Z and P(t) on a
// grid of 40001 times plus the solver's steps and midpoints.
class PaperCertificates : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    trajectory_ = paper_trajectory();
    design_ = hinf::solve_grde(trajectory_, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0,
                               solver(Method::BDF, 1e-10, 1e-12));
    times_ = fine_times(*design_, 40001);
    Z_.clear();
    for (double t : times_) Z_.push_back(design_->Z(t));
  }
  static void TearDownTestSuite() {
    design_.reset();
    trajectory_.reset();
    Z_.clear();
    times_.clear();
  }
  // The grid's min of p(t), where, and the round-off allowance of two eigenvalue algorithms on
  // P (the library's and Eigen's): kRoundoff times its largest entry (~400 on the ship at
  // gamma = 5, where p itself is 1).
  static void p_on_grid(double kappa, double& p_min, double& where, double& slack) {
    const Mat B = hinf_ref::ship_B(), D = Mat(hinf_ref::ship_D_process());
    p_min = kInf;
    double largest = 0.0;
    for (std::size_t k = 0; k < times_.size(); ++k) {
      const Mat P = P_matrix(Z_[k], B, D, Mat::Identity(6, 6), kappa, 5.0);
      largest = std::max(largest, P.cwiseAbs().maxCoeff());
      const double p = lambda_min(P);
      if (p < p_min) p_min = p, where = times_[k];
    }
    slack = kRoundoff * largest;
  }
  static hinf::TrajectoryPtr trajectory_;
  static hinf::RiccatiSolutionPtr design_;
  static std::vector<double> times_;
  static std::vector<Mat> Z_;
};
hinf::TrajectoryPtr PaperCertificates::trajectory_;
hinf::RiccatiSolutionPtr PaperCertificates::design_;
std::vector<double> PaperCertificates::times_;
std::vector<Mat> PaperCertificates::Z_;

TEST_F(PaperCertificates, MAndMAreTheExtremeEigenvaluesOfZ) {
  // (22): Eigen's extreme eigenvalues of Z on the grid are inner bounds of the true extremes;
  // the certificate's m, M (refined between samples) are at most 1e-8 beyond them and not
  // inside them by more than the round-off of two eigenvalue algorithms (of |Z| ~ 20.8).
  const Certificates c = hinf::certify(*design_, hinf::Signal(1.0), Mat::Identity(6, 6));
  double lo = kInf, hi = -kInf;
  for (const Mat& Z : Z_) {
    lo = std::min(lo, lambda_min(Z));
    hi = std::max(hi, lambda_max(Z));
  }
  const double slack = kRoundoff * std::max(std::abs(lo), std::abs(hi));
  std::printf("[certificates] m = %.10f (grid %.10f), M = %.10f (grid %.10f)\n", c.m, lo, c.M, hi);
  EXPECT_GE(c.m, lo - 1e-8);
  EXPECT_LE(c.m, lo + slack);
  EXPECT_GE(c.M, hi - slack);
  EXPECT_LE(c.M, hi + 1e-8);
  double m = 0.0, M = 0.0;
  design_->eigenvalue_bounds(m, M);
  EXPECT_EQ(c.m, m);  // the same computation (certify calls it)
  EXPECT_EQ(c.M, M);
  // The values tests/python/test_certificates.py pins for the paper's design, to 3 digits:
  // orientation only (the grid above is the check).
  EXPECT_NEAR(c.m, 0.219, 1e-3);
  EXPECT_NEAR(c.M, 20.8, 0.05);
}

TEST_F(PaperCertificates, PMinIsTheSmallestEigenvalueOfP) {
  // (23). For kappa >= 1/2, P = I + a positive semidefinite matrix of rank <= 3 (D D' and B B'
  // act on u, v, r only) in 6 dimensions, so p(t) = 1 = lambda_min(Q) exactly (Remark 1's bound,
  // attained); kappa = 1/4 makes it negative.
  for (double kappa : {1.0, 0.5, 2.0, 0.25}) {
    const Certificates c = hinf::certify(*design_, hinf::Signal(kappa), Mat::Identity(6, 6));
    double p_min = 0.0, where = 0.0, slack = 0.0;
    p_on_grid(kappa, p_min, where, slack);
    std::printf("[certificates] kappa %.2f: p_min %.10f (grid %.10f at t = %.3f), at t = %.3f\n", kappa, c.p_min, p_min,
                where, c.p_min_t);
    EXPECT_EQ(c.kappa_min, kappa);
    EXPECT_GE(c.p_min, p_min - 1e-8) << kappa;
    EXPECT_LE(c.p_min, p_min + slack) << kappa;
    EXPECT_GE(c.p_min_t, 0.0);
    EXPECT_LE(c.p_min_t, 40.0);
    const Mat P_at = P_matrix(design_->Z(c.p_min_t), hinf_ref::ship_B(), hinf_ref::ship_D_process(),
                              Mat::Identity(6, 6), kappa, 5.0);
    EXPECT_NEAR(lambda_min(P_at), c.p_min, slack) << kappa;
    if (kappa >= 0.5) {
      EXPECT_NEAR(c.p_min, 1.0, slack) << kappa;
      // The formula p_min / (2 M) of (24) here and in the library: round-off apart.
      EXPECT_NEAR(c.decay_rate, c.p_min / (2.0 * c.M), kRoundoff * c.decay_rate) << kappa;
    } else {
      EXPECT_LT(c.p_min, 0.0);
      EXPECT_EQ(c.epsilon, 0.0);
      EXPECT_EQ(c.attraction_radius, 0.0);
      EXPECT_EQ(c.decay_rate, 0.0);
    }
  }
}

TEST_F(PaperCertificates, ShipRemainderBoundIsABound) {
  // |f(q_d + e) - f(q_d) - A_e e| <= L |e|^2 (hand-written ship and Jacobian) at 6000 random
  // times, directions (dense and sparse) and radii 1e-4 .. 10 (the bound is global); L =
  // remainder_L, the largest L(t) of the run. The bound is not vacuous: the worst sampled
  // ratio is above half of it.
  const Certificates c = hinf::certify(*design_, hinf::Signal(1.0), Mat::Identity(6, 6));
  EXPECT_TRUE(c.remainder_is_bound);
  EXPECT_NE(c.remainder_method.find("analytic"), std::string::npos) << c.remainder_method;
  const double L = c.remainder_L;
  hinf_ref::Rng rng(2024);
  double worst = 0.0;
  for (int k = 0; k < 6000; ++k) {
    const double t = rng.uniform(0.0, 40.0);
    const Vec q_d = trajectory_->q_d(t);
    Vec e = Vec::Zero(6);
    if (k % 2) {
      for (int i = 0; i < 6; ++i) e[i] = rng.normal();
    } else {
      const int count = 2 + rng.below(2);
      for (int j = 0; j < count; ++j) e[rng.below(6)] = rng.normal();
    }
    if (e.norm() == 0.0) continue;
    const double radius = std::pow(10.0, rng.uniform(-4.0, 1.0));
    e *= radius / e.norm();
    const Vec f1 = hinf_ref::ship_drift(q_d + e), f0 = hinf_ref::ship_drift(q_d);
    const Vec Je = hinf_ref::ship_jacobian(q_d) * e;
    const double ratio = (f1 - f0 - Je).norm() / (radius * radius);
    // The difference of values of f ~ 1 carries round-off ~ eps |f| / radius^2 in the ratio.
    const double roundoff = 10.0 * kEps * (f1.norm() + f0.norm() + Je.norm()) / (radius * radius);
    EXPECT_LE(ratio, L * (1 + 1e-9) + roundoff) << "t = " << t << ", radius " << radius;
    worst = std::max(worst, ratio);
  }
  std::printf("[certificates] remainder: worst sampled |r| / |e|^2 = %.4f, L = %.4f\n", worst, L);
  EXPECT_GT(worst, 0.5 * L);
  // remainder_L is the largest L(t) over the run (the derivation above, on the grid).
  double largest = 0.0;
  for (double t : times_) largest = std::max(largest, ship_L(trajectory_->q_d(t)));
  EXPECT_NEAR(L, largest, 1e-9 * largest);
}

TEST_F(PaperCertificates, RadiusAttractionRadiusAndDecayRate) {
  // (24): epsilon = min_t p(t) / (4 M L(t)) (p from Eigen and L from the derivation above, on the
  // grid), the attraction radius epsilon sqrt(m / M) and the decay rate p_min / (2 M).
  const Certificates c = hinf::certify(*design_, hinf::Signal(1.0), Mat::Identity(6, 6));
  const Mat B = hinf_ref::ship_B(), D = hinf_ref::ship_D_process();
  double best = kInf, where = 0.0, largest_P = 0.0;
  for (std::size_t k = 0; k < times_.size(); ++k) {
    const Mat P = P_matrix(Z_[k], B, D, Mat::Identity(6, 6), 1.0, 5.0);
    largest_P = std::max(largest_P, P.cwiseAbs().maxCoeff());
    const double ratio = lambda_min(P) / (4.0 * c.M * ship_L(trajectory_->q_d(times_[k])));
    if (ratio < best) best = ratio, where = times_[k];
  }
  std::printf("[certificates] epsilon %.8f at t = %.3f (grid %.8f at %.3f), attraction radius %.3e, decay rate %.5f\n",
              c.epsilon, c.epsilon_t, best, where, c.attraction_radius, c.decay_rate);
  ASSERT_GT(c.epsilon, 0.0);
  // p (= 1 here) carries the round-off of two eigenvalue algorithms, relative kRoundoff |P|.
  const double slack = kRoundoff * largest_P + kRoundoff;
  EXPECT_GE(c.epsilon, best * (1 - 1e-8));
  EXPECT_LE(c.epsilon, best * (1 + slack));
  EXPECT_NEAR(c.epsilon_t, where, 0.01);
  EXPECT_NEAR(c.attraction_radius, c.epsilon * std::sqrt(c.m / c.M), kRoundoff * c.attraction_radius);
  EXPECT_NEAR(c.decay_rate, c.p_min / (2.0 * c.M), kRoundoff * c.decay_rate);
}

TEST_F(PaperCertificates, ClosedLoopsFromTheCertifiedBallDecayAtTheCertifiedRate) {
  // No disturbance, u = u_d - kappa B' Z q_e, |q_e(t0)| = attraction_radius in random directions:
  // certified to stay in the epsilon-ball with V(t) <= V(t0) exp(-decay_rate (t - t0)), V =
  // q_e' Z q_e. Slack 1e-12 absolute on V(t0) ~ 1e-6 (the closed loop at rtol 1e-10: V to ~1e-14;
  // Z at rtol 1e-10).
  for (double kappa : {1.0, 0.5}) {
    const Certificates c = hinf::certify(*design_, hinf::Signal(kappa), Mat::Identity(6, 6));
    hinf::HinfStateFeedback law(design_, hinf::Signal(kappa));
    hinf::SimulationOptions options;
    options.output_dt = 0.05;
    options.solver = solver(Method::ERK, 1e-10, 1e-14);
    hinf_ref::Rng rng(1999);
    double slowest = kInf;
    for (int run_index = 0; run_index < 3; ++run_index) {
      Vec e(6);
      for (int i = 0; i < 6; ++i) e[i] = rng.normal();
      e *= c.attraction_radius / e.norm();
      const hinf::SimulationResult run = hinf::simulate_state_feedback(*trajectory_, law, hinf::VectorSignal::zeros(6),
                                                                       trajectory_->q_d0() + e, options);
      const RowMat q_e = run.q_e();
      std::vector<double> V(static_cast<std::size_t>(run.t.size()));
      for (Eigen::Index k = 0; k < run.t.size(); ++k) {
        const Vec x = q_e.row(k).transpose();
        V[static_cast<std::size_t>(k)] = x.dot(design_->Z(run.t[k]) * x);
        EXPECT_LE(x.norm(), c.epsilon) << kappa << " t = " << run.t[k];
        EXPECT_LE(V[static_cast<std::size_t>(k)], V[0] * std::exp(-c.decay_rate * run.t[k]) + 1e-12)
            << kappa << " t = " << run.t[k];
        if (k > 0) {
          EXPECT_LE(V[static_cast<std::size_t>(k)],
                    V[static_cast<std::size_t>(k - 1)] * std::exp(-c.decay_rate * (run.t[k] - run.t[k - 1])) + 1e-12);
        }
      }
      slowest = std::min(slowest, std::log(V[0] / V[std::size_t(run.t.size() / 4)]) / run.t[run.t.size() / 4]);
    }
    std::printf("[certificates] kappa %.1f: certified decay rate %.4f, slowest measured over 10 s %.4f\n", kappa,
                c.decay_rate, slowest);
  }
}

TEST(ScenarioCertificates, PaperFig1IsTheDesignOfItsFile) {
  // scenario_certificates solves the file's design with the file's [solver] (bdf, rtol 1e-8)
  // and certifies it: the same computation as here with those options, the same numbers.
  const hinf::Scenario scenario = hinf::load_scenario_toml(std::string(HINF_SOURCE_DIR) + "/scenarios/paper_fig1.toml");
  ASSERT_EQ(scenario.solver.method, Method::BDF);
  const Certificates from_file = hinf::scenario_certificates(scenario);
  const auto design =
      hinf::solve_grde(paper_trajectory(), Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0, scenario.solver);
  const Certificates here = hinf::certify(*design, hinf::Signal(1.0), Mat::Identity(6, 6));
  EXPECT_EQ(from_file.m, here.m);
  EXPECT_EQ(from_file.M, here.M);
  EXPECT_EQ(from_file.p_min, here.p_min);
  EXPECT_EQ(from_file.epsilon, here.epsilon);
  EXPECT_EQ(from_file.remainder_L, here.remainder_L);
}

// ======================================================================= other models

TEST(Certificates, LinearModelWithTimeVaryingKappa) {
  // Full-rank B and Q = diag(1, 2, 3), where p(t) is not trivially lambda_min(Q), and kappa(t) =
  // 0.75 + 0.5 sin t (kappa_min = 1/4 at t = 3 pi / 2): p_min against Eigen on a fine grid; the
  // remainder of a LinearModel is 0, so epsilon and the attraction radius are infinite.
  hinf_ref::Rng rng(5);
  const Mat A = hinf_ref::normal_matrix(rng, 3, 3) - Mat::Identity(3, 3);
  const Mat B = hinf_ref::normal_matrix(rng, 3, 3), D = hinf_ref::normal_matrix(rng, 3, 2);
  const Mat Q = Vec(Eigen::Vector3d(1.0, 2.0, 3.0)).asDiagonal();
  auto model = std::make_shared<const hinf::LinearModel>(A, B, D);
  const auto tr = std::make_shared<const hinf::Trajectory>(model, Vec::Zero(3), hinf::VectorSignal::zeros(3), 0.0, 6.0);
  const auto sol = hinf::solve_grde(tr, Q, Mat::Identity(3, 3), 3.0);
  const std::vector<double> times = fine_times(*sol, 60001);
  std::vector<Mat> Z;
  double lo = kInf, hi = -kInf;
  for (double t : times) {
    Z.push_back(sol->Z(t));
    lo = std::min(lo, lambda_min(Z.back()));
    hi = std::max(hi, lambda_max(Z.back()));
  }
  const hinf::Signal varying(0.75, {hinf::Harmonic{0.5, 1.0, 0.0, false}});
  for (const hinf::Signal& kappa : {varying, hinf::Signal(1.0)}) {
    const Certificates c = hinf::certify(*sol, kappa, Q);
    double p_min = kInf, where = 0.0, largest = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const Mat P = P_matrix(Z[k], B, D, Q, kappa(times[k]), 3.0);
      largest = std::max(largest, P.cwiseAbs().maxCoeff());
      const double p = lambda_min(P);
      if (p < p_min) p_min = p, where = times[k];
    }
    const double slack = kRoundoff * largest;
    // min kappa on [0, 6]: 0.75 - 0.5 = 0.25 (closed form; refined to round-off in kappa).
    EXPECT_NEAR(c.kappa_min, kappa.is_constant() ? 1.0 : 0.25, kRoundoff);
    EXPECT_GE(c.p_min, p_min - 1e-8);
    EXPECT_LE(c.p_min, p_min + slack);
    EXPECT_NEAR(c.p_min_t, where, 1e-3);
    EXPECT_EQ(c.remainder_L, 0.0);
    EXPECT_TRUE(c.remainder_is_bound);
    EXPECT_EQ(c.epsilon, kInf);
    EXPECT_EQ(c.attraction_radius, kInf);
    EXPECT_NEAR(c.m, lo, 1e-8);
    EXPECT_NEAR(c.M, hi, 1e-8);
    EXPECT_NEAR(c.decay_rate, c.p_min / (2.0 * c.M), kRoundoff * std::abs(c.decay_rate));
  }
  EXPECT_GT(hinf::certify(*sol, hinf::Signal(1.0), Q).p_min, 1.0 + 0.1);  // strictly above lambda_min(Q)
}

// dq/dt = -q + q^2 + u + w: no remainder_bound (the default NaN), so the certificate samples
// |r| / |e|^2, which is exactly 1 (r = e^2).
class Quadratic final : public hinf::Model {
 public:
  std::string name() const override { return "quadratic"; }
  int n() const override { return 1; }
  int m() const override { return 1; }
  int nw() const override { return 1; }
  void f(double, const hinf::ConstVecRef& q, hinf::VecRef out) const override { out[0] = -q[0] + q[0] * q[0]; }
  void dfdq(double, const hinf::ConstVecRef& q, hinf::MatRef out) const override { out(0, 0) = -1.0 + 2.0 * q[0]; }
  Mat G(double, const hinf::ConstVecRef&) const override { return Mat::Ones(1, 1); }
  Mat D(double, const hinf::ConstVecRef&) const override { return Mat::Ones(1, 1); }
};

TEST(Certificates, SampledRemainderForAModelWithoutABound) {
  const auto tr = std::make_shared<const hinf::Trajectory>(std::make_shared<const Quadratic>(), Vec::Constant(1, 0.3),
                                                           hinf::VectorSignal::zeros(1), 0.0, 3.0);
  const auto sol = hinf::solve_grde(tr, Mat::Identity(1, 1), Mat::Identity(1, 1), 2.0);
  const Certificates c = hinf::certify(*sol, hinf::Signal(1.0), Mat::Identity(1, 1));
  EXPECT_FALSE(c.remainder_is_bound);
  EXPECT_NE(c.remainder_method.find("not a bound"), std::string::npos) << c.remainder_method;
  // r = e^2 exactly; as a difference of values of f ~ 1 at radii >= 0.01 it carries round-off
  // of a few eps / 0.01^2 ~ 1e-11 relative.
  EXPECT_NEAR(c.remainder_L, 1.0, 1e-9);
  double p_min = kInf;
  for (double t : fine_times(*sol, 3001))
    p_min = std::min(p_min, lambda_min(P_matrix(sol->Z(t), Mat::Ones(1, 1), Mat::Ones(1, 1), Mat::Ones(1, 1), 1.0, 2.0)));
  EXPECT_NEAR(c.epsilon, p_min / (4.0 * c.M), 1e-8 * c.epsilon);
}

// ======================================================================= attenuation (eq. 12)

// A 2-state LTI plant (eigenvalues -0.15 +- 0.94i; gamma* = 1.70 on [0, 10] with these weights),
// where the linearized guarantee is exact. Harmonic disturbance v = (sin 1.3 t, 0.5 cos 0.4 t).
struct Attenuation {
  Mat A, B, D, Q, Qf;
  hinf::TrajectoryPtr trajectory;
  hinf::VectorSignal v;
  Attenuation() : A(2, 2), B(2, 1), D(2, 2), Q(2, 2), Qf(0.5 * Mat::Identity(2, 2)) {
    A << 0.2, 1.0, -1.0, -0.5;
    B << 0.0, 1.0;
    D << 1.0, 0.0, 0.3, 1.0;
    Q << 1.0, 0.2, 0.2, 2.0;
    trajectory = std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::LinearModel>(A, B, D),
                                                          Vec::Zero(2), hinf::VectorSignal::zeros(1), 0.0, 10.0);
    v = hinf::VectorSignal(std::vector<hinf::Signal>{hinf::Signal(0.0, {hinf::Harmonic{1.0, 1.3, 0.0, false}}),
                                                     hinf::Signal(0.0, {hinf::Harmonic{0.5, 0.4, 0.0, true}})});
  }
  // Closed form of int_0^T |v|^2 dt = int sin^2(1.3 t) + 0.25 cos^2(0.4 t) dt.
  static double energy(double T = 10.0) {
    return (T / 2 - std::sin(2.6 * T) / 5.2) + 0.25 * (T / 2 + std::sin(0.8 * T) / 1.6);
  }
};

// Trapezoid rule of samples f_k over times t_k.
double trapezoid(const Vec& t, const std::vector<double>& f) {
  double s = 0.0;
  for (Eigen::Index k = 1; k < t.size(); ++k)
    s += 0.5 * (t[k] - t[k - 1]) * (f[static_cast<std::size_t>(k)] + f[static_cast<std::size_t>(k - 1)]);
  return s;
}

TEST(Attenuation, CompletedSquareGainBelowGammaAndTheWorstCase) {
  const Attenuation p;
  hinf::SimulationOptions options;
  options.output_dt = 0.002;
  options.solver = solver(Method::ERK, 1e-11, 1e-13);
  for (double gamma : {2.2, 5.0}) {
    const auto design = hinf::solve_grde(p.trajectory, p.Q, p.Qf, gamma, solver(Method::ERK, 1e-12, 1e-14));
    hinf::HinfStateFeedback law(design);
    for (bool worst_case : {false, true}) {
      for (const Vec& q0 : {Vec(Vec::Zero(2)), Vec(Eigen::Vector2d(0.5, -0.5))}) {
        const hinf::Disturbance w = worst_case ? hinf::Disturbance(p.v, design) : hinf::Disturbance(p.v);
        const hinf::SimulationResult run = hinf::simulate_state_feedback(*p.trajectory, law, w, q0, options);
        // L_gamma of (12) and the completed square from the series (trapezoid rule).
        std::vector<double> x, ww, gap;
        for (Eigen::Index k = 0; k < run.t.size(); ++k) {
          const Vec q_e = (run.q.row(k) - run.q_d.row(k)).transpose();
          const Vec u_e = (run.u.row(k) - run.u_d.row(k)).transpose();
          const Vec wk = run.w.row(k).transpose();
          const Vec w_star = p.D.transpose() * design->Z(run.t[k]) * q_e / (gamma * gamma);
          x.push_back(q_e.dot(p.Q * q_e) + u_e.squaredNorm());
          ww.push_back(wk.squaredNorm());
          gap.push_back((wk - w_star).squaredNorm());
        }
        const Vec q_end = (run.q.row(run.t.size() - 1) - run.q_d.row(run.t.size() - 1)).transpose();
        const double cost = trapezoid(run.t, x) - gamma * gamma * trapezoid(run.t, ww) + q_end.dot(p.Qf * q_end);
        const double square = q0.dot(design->Z(0.0) * q0) - gamma * gamma * trapezoid(run.t, gap);
        const double scale = gamma * gamma * trapezoid(run.t, ww);
        std::printf("[attenuation] gamma %.1f %-10s |q_e(0)| %.2f: L_gamma %.6f, completed square %.6f (%.1e of the "
                    "terms)\n",
                    gamma, worst_case ? "worst case" : "harmonic", q0.norm(), cost, square, std::abs(cost - square) / scale);
        // The identity is exact for the continuous integrals; the trapezoid rule at dt = 0.002
        // errs by ~dt^2 / 12 |f''| relative (~1e-7 for these frequencies), the integration at
        // rtol 1e-11 far less: 1e-5 of the size of the terms.
        EXPECT_LT(std::abs(cost - square), 1e-5 * scale) << gamma << " " << worst_case;
        // The library's tracking cost, ratio and margin (its own trapezoid sums) against these:
        // summation round-off of 5001 terms.
        hinf::CostWeights weights;
        weights.Q = p.Q;
        weights.Qf = p.Qf;
        weights.gamma = gamma;
        weights.initial_term = q0.dot(design->Z(0.0) * q0);
        const hinf::Metrics metrics = hinf::compute_metrics(p.trajectory->model(), run, weights);
        const double L = trapezoid(run.t, x) + q_end.dot(p.Qf * q_end);
        const double gain = std::sqrt(L / trapezoid(run.t, ww));
        const double roundoff = 4.0 * static_cast<double>(run.t.size()) * kEps;
        EXPECT_NEAR(metrics.tracking_cost, L, roundoff * L);
        EXPECT_NEAR(metrics.response_ratio, gain, roundoff * gain);
        // The margin of the bound L <= gamma^2 ||w||^2 + q0' Z(0) q0 is -L_gamma + the completed
        // square's initial term, over that bound.
        const double bound = gamma * gamma * trapezoid(run.t, ww) + weights.initial_term;
        EXPECT_NEAR(metrics.attenuation_margin, 1.0 - L / bound, roundoff);
        if (q0.norm() == 0.0) {
          EXPECT_EQ(metrics.disturbance_gain, metrics.response_ratio) << "from the desired start";
          EXPECT_LE(cost, 0.0);
          EXPECT_LE(gain, gamma);
        } else {
          EXPECT_TRUE(std::isnan(metrics.disturbance_gain)) << "not from the desired start";
        }
        // The linear loop keeps the bound: the margin is >= 0 up to the trapezoid rule's error
        // (1e-5 of the terms, as above).
        EXPECT_GE(metrics.attenuation_margin, -1e-5);
        if (q0.norm() == 0.0) {
          if (worst_case) {
            // w = v + w*: L_gamma = -gamma^2 int |v|^2 (closed form), up to the trapezoid rule.
            // The worst case amplifies w (|w|^2 / |v|^2 is the amplification of the terms).
            const double amplification = trapezoid(run.t, ww) / Attenuation::energy();
            EXPECT_NEAR(cost, -gamma * gamma * Attenuation::energy(),
                        1e-6 * amplification * gamma * gamma * Attenuation::energy())
                << gamma;
          }
        }
      }
    }
  }
}

}  // namespace
