// Closed-loop simulation and metrics: the output grid, the desired trajectory against an
// independent RK4 integration, the closed loop on the desired trajectory (zero error stays
// zero), convergence from the paper's initial error, metrics against hand computations on
// synthetic runs, and the input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hinf/control/controller.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"
#include "tolerances.hpp"

namespace {

// The closed-loop options of a test: output step and integrator.
hinf::SimulationOptions sim(double output_dt, const hinf::SolverOptions& solver) {
  hinf::SimulationOptions options;
  options.output_dt = output_dt;
  options.solver = solver;
  return options;
}


using hinf::Mat;
using hinf::Method;
using hinf::RowMat;
using hinf::SolverOptions;
using hinf::Vec;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const Method kMethods[] = {Method::BDF, Method::Adams, Method::ERK};

// ======================================================================= output grid

TEST(OutputGrid, EndsExactlyAtTfWithTheRequestedSpacing) {
  struct Case {
    double t0, tf, dt;
    std::size_t count;
  };
  const Case cases[] = {
      {0.0, 1.0, 0.25, 5},      // exact multiple
      {0.0, 1.0, 0.3, 5},       // 0, .3, .6, .9, 1 (last interval 0.1)
      {2.0, 3.0, 0.1, 11},      // (tf - t0)/dt = 10.000000000000002 in floating point
      {0.0, 40.0, 0.01, 4001},  // the paper's grid
      {-1.0, 0.5, 0.7, 4},      // -1, -0.3, 0.4, 0.5
      {0.0, 1.0, 5.0, 2},       // dt longer than the horizon: just the ends
  };
  for (const Case& c : cases) {
    const std::vector<double> g = hinf::output_grid(c.t0, c.tf, c.dt);
    ASSERT_EQ(g.size(), c.count) << c.t0 << " " << c.tf << " " << c.dt;
    EXPECT_EQ(g.front(), c.t0);
    EXPECT_EQ(g.back(), c.tf) << "must end exactly at tf";
    for (std::size_t k = 1; k + 1 < g.size(); ++k) {
      EXPECT_NEAR(g[k] - g[k - 1], c.dt, 1e-12 * std::max(1.0, std::abs(g[k])));
      EXPECT_NEAR(g[k], c.t0 + static_cast<double>(k) * c.dt, 1e-12 * std::max(1.0, std::abs(g[k])));
    }
    // The last interval is (0, dt]: never a duplicate or near-duplicate of tf.
    const double last = g[g.size() - 1] - g[g.size() - 2];
    EXPECT_GT(last, 1e-6 * c.dt);
    EXPECT_LE(last, c.dt * (1 + 1e-9));
  }
  // The partial interval of {0, 1, 0.3}.
  const std::vector<double> g = hinf::output_grid(0.0, 1.0, 0.3);
  EXPECT_NEAR(g[3], 0.9, hinf_test::kRoundoff);  // 3 x 0.3 in floating point
  EXPECT_NEAR(g[4] - g[3], 0.1, hinf_test::kRoundoff);
}

TEST(OutputGrid, BadInputsThrow) {
  EXPECT_THROW(hinf::output_grid(0.0, 1.0, 0.0), hinf::InputError);
  EXPECT_THROW(hinf::output_grid(0.0, 1.0, -0.1), hinf::InputError);
  EXPECT_THROW(hinf::output_grid(0.0, 1.0, kNaN), hinf::InputError);
  EXPECT_THROW(hinf::output_grid(1.0, 1.0, 0.1), hinf::InputError);
  EXPECT_THROW(hinf::output_grid(2.0, 1.0, 0.1), hinf::InputError);
  EXPECT_THROW(hinf::output_grid(kNaN, 1.0, 0.1), hinf::InputError);
}

// ======================================================================= the paper's ship

hinf::VectorSignal paper_u_d() {
  return hinf::VectorSignal(std::vector<hinf::Signal>{
      hinf::Signal(1.0), hinf::Signal(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}})});
}

Vec paper_q_d0() {
  Vec q = Vec::Zero(6);
  q[0] = 1.0;
  return q;
}

// 0.1 cos(2 pi 0.2 t) on w1..w3, zero on w4..w6.
hinf::VectorSignal paper_disturbance() {
  const hinf::Signal w(0.0, {hinf::Harmonic{0.1, 2.0 * M_PI * 0.2, 0.0, true}});
  return hinf::VectorSignal(std::vector<hinf::Signal>{w, w, w, hinf::Signal(), hinf::Signal(), hinf::Signal()});
}

class PaperShip : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    trajectory_ = std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::ShipModel>(),
                                                           paper_q_d0(), paper_u_d(), 0.0, 40.0);
    solution_ = hinf::solve_grde(trajectory_, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0);
  }
  static void TearDownTestSuite() {
    solution_.reset();
    trajectory_.reset();
  }
  static SolverOptions options(Method method) {
    SolverOptions o;
    o.method = method;
    return o;
  }
  static hinf::TrajectoryPtr trajectory_;
  static hinf::RiccatiSolutionPtr solution_;
};
hinf::TrajectoryPtr PaperShip::trajectory_;
hinf::RiccatiSolutionPtr PaperShip::solution_;

TEST_F(PaperShip, DesiredTrajectoryMatchesIndependentRk4) {
  // Classical RK4 with h = 1e-3 (global error ~ 1e-12 here) on the ship's equations written
  // out in the test, with u_d = [1, 0.3 sin(0.2 t)].
  auto f = [](double t, const Eigen::Matrix<double, 6, 1>& q) {
    const double u = q[0], v = q[1], r = q[2], psi = q[5];
    Eigen::Matrix<double, 6, 1> d;
    d << 0.5 * v * r - u + 1.0, -2.0 * u * r - 2.0 * v, 0.5 * u * v - r + 0.3 * std::sin(0.2 * t),
        u * std::cos(psi) - v * std::sin(psi), u * std::sin(psi) + v * std::cos(psi), r;
    return d;
  };
  Eigen::Matrix<double, 6, 1> q = paper_q_d0();
  const double h = 1e-3;
  double max_err = 0.0;
  for (int k = 0; k < 40000; ++k) {
    const double t = k * h;
    const auto k1 = f(t, q), k2 = f(t + h / 2, q + h / 2 * k1), k3 = f(t + h / 2, q + h / 2 * k2),
               k4 = f(t + h, q + h * k3);
    q += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    if ((k + 1) % 250 == 0) {
      const double tn = (k + 1) * h;
      max_err = std::max(max_err, (trajectory_->q_d(tn) - Vec(q)).cwiseAbs().maxCoeff());
    }
  }
  std::printf("[trajectory] q_d vs RK4 (h = 1e-3): max abs difference %.2e\n", max_err);
  EXPECT_LT(max_err, 1e-8);
  // u_d and A_e are the documented functions of q_d(t).
  const Vec ud = trajectory_->u_d(7.0);
  EXPECT_EQ(ud[0], 1.0);
  EXPECT_NEAR(ud[1], 0.3 * std::sin(1.4), hinf_test::kRoundoff * 0.3);
  Mat J(6, 6);
  hinf::ShipModel().dfdq(7.0, trajectory_->q_d(7.0), J);
  EXPECT_EQ(trajectory_->A_e(7.0), J);  // the same code on the same q_d(7)
}

TEST_F(PaperShip, ZeroErrorAndZeroDisturbanceStaysOnTheDesiredTrajectory) {
  // Exactly, q = q_d and u = u_d; numerically the deviation is the integration error, which
  // is proportional to the tolerance (about 4e-7 at the default rtol 1e-8, over positions
  // of tens of metres): rtol 1e-9 leaves a wide margin below 1e-6.
  const std::vector<double> grid = hinf::output_grid(0.0, 40.0, 0.05);
  for (Method method : kMethods) {
    hinf::HinfStateFeedback controller(solution_);
    SolverOptions o = options(method);
    o.rtol = 1e-9;
    o.atol = 1e-11;
    const hinf::SimulationResult run = hinf::simulate_state_feedback(
        *trajectory_, controller, hinf::VectorSignal::zeros(6), paper_q_d0(), sim(0.05, o));
    ASSERT_EQ(run.t.size(), static_cast<Eigen::Index>(grid.size()));
    for (std::size_t k = 0; k < grid.size(); ++k) ASSERT_EQ(run.t[static_cast<Eigen::Index>(k)], grid[k]);
    ASSERT_EQ(run.q.rows(), run.t.size());
    ASSERT_EQ(run.q.cols(), 6);
    ASSERT_EQ(run.u.cols(), 2);
    ASSERT_EQ(run.w.cols(), 6);
    const double max_dev = (run.q - run.q_d).cwiseAbs().maxCoeff();
    const double max_du = (run.u - run.u_d).cwiseAbs().maxCoeff();
    std::printf("[closed loop] %-5s q0 = q_d0, w = 0: max |q - q_d| %.2e, max |u - u_d| %.2e\n",
                hinf::to_string(method).c_str(), max_dev, max_du);
    EXPECT_LT(max_dev, 1e-6) << hinf::to_string(method);
    EXPECT_LT(max_du, 1e-5) << hinf::to_string(method);
    EXPECT_EQ(run.w.cwiseAbs().maxCoeff(), 0.0);
    // The desired state on the grid is the trajectory's.
    EXPECT_EQ(Vec(run.q_d.row(200).transpose()), trajectory_->q_d(run.t[200]));
  }
}

TEST_F(PaperShip, InitialErrorDecays) {
  Vec q0 = paper_q_d0();
  q0[3] -= 1.0;
  q0[4] -= 1.0;
  q0[5] += M_PI / 4;
  std::vector<hinf::SimulationResult> runs;
  for (Method method : kMethods) {
    hinf::HinfStateFeedback controller(solution_);
    runs.push_back(hinf::simulate_state_feedback(*trajectory_, controller, paper_disturbance(), q0, sim(0.05, options(method))));
    const hinf::SimulationResult& run = runs.back();
    auto position_error = [&](Eigen::Index k) {
      return std::hypot(run.q(k, 3) - run.q_d(k, 3), run.q(k, 4) - run.q_d(k, 4));
    };
    const Eigen::Index last = run.t.size() - 1;
    EXPECT_NEAR(position_error(0), std::sqrt(2.0), hinf_test::kRoundoff);  // hypot(-1, -1)
    std::printf("[closed loop] %-5s from the paper's initial error: |p_e| = %.3f at t = 10, %.4f "
                "at tf\n",
                hinf::to_string(method).c_str(), position_error(200), position_error(last));
    EXPECT_LT(position_error(last), 0.1 * std::sqrt(2.0)) << hinf::to_string(method);
    // The applied disturbance is the paper's.
    EXPECT_NEAR(run.w(20, 0), 0.1 * std::cos(2 * M_PI * 0.2 * 1.0), hinf_test::kRoundoff * 0.1);
    EXPECT_EQ(run.w(20, 4), 0.0);
    // u = u_d - B'Z(t) (q - q_d) on the grid.
    const Eigen::Index k = 37;
    const Vec qe = (run.q.row(k) - run.q_d.row(k)).transpose();
    const Mat K = solution_->gain(run.t[k]);
    const Vec u_expected = run.u_d.row(k).transpose() - K * qe;
    // The law in the library and here: round-off of the size of its terms.
    const double terms = run.u_d.row(k).cwiseAbs().maxCoeff() + (K.cwiseAbs() * qe.cwiseAbs()).maxCoeff();
    EXPECT_LT((Vec(run.u.row(k).transpose()) - u_expected).cwiseAbs().maxCoeff(), hinf_test::kRoundoff * terms);
  }
  // The three integrators agree on the closed loop.
  for (std::size_t i = 1; i < runs.size(); ++i) {
    const double diff = (runs[i].q - runs[0].q).cwiseAbs().maxCoeff();
    std::printf("[closed loop] %s vs bdf: max |q difference| %.2e\n", hinf::to_string(kMethods[i]).c_str(), diff);
    EXPECT_LT(diff, 1e-5);
  }
}

TEST_F(PaperShip, KappaScalesTheGainAndTheJacobianIsExact) {
  // u = u_d - kappa(t) B'Z(t) (q - q_d), kappa(t) = 0.75 + 0.25 sin(t).
  const hinf::Signal kappa(0.75, {hinf::Harmonic{0.25, 1.0, 0.0, false}});
  hinf::HinfStateFeedback controller(solution_, kappa);
  EXPECT_EQ(controller.m(), 2);
  for (double t : {0.0, 3.3, 17.0, 39.9}) {
    Vec qt = trajectory_->q_d(t);
    qt[1] += 0.2;
    qt[3] -= 0.5;
    qt[5] += 0.3;
    Vec u(2);
    controller.control(t, qt, u);
    const Mat K = solution_->gain(t);
    const Vec q_e = qt - trajectory_->q_d(t);
    const Vec expected = trajectory_->u_d(t) - kappa(t) * K * q_e;
    // The law in the library and here: round-off of the size of its terms.
    const double terms = trajectory_->u_d(t).cwiseAbs().maxCoeff() + kappa(t) * (K.cwiseAbs() * q_e.cwiseAbs()).maxCoeff();
    EXPECT_LT((u - expected).cwiseAbs().maxCoeff(), hinf_test::kRoundoff * terms) << t;
    // du/dq = -kappa K: against central differences of control() (u is affine in q).
    Mat J(2, 6), J_fd(2, 6);
    controller.control_jacobian(t, qt, J);
    for (int j = 0; j < 6; ++j) {
      Vec qp = qt, qm = qt, up(2), um(2);
      qp[j] += 1e-4;
      qm[j] -= 1e-4;
      controller.control(t, qp, up);
      controller.control(t, qm, um);
      J_fd.col(j) = (up - um) / 2e-4;
    }
    EXPECT_LT((J - J_fd).cwiseAbs().maxCoeff(), 1e-9) << t;
    EXPECT_LT((J + kappa(t) * K).cwiseAbs().maxCoeff(), hinf_test::kRoundoff * kappa(t) * K.cwiseAbs().maxCoeff()) << t;
  }
}

// ======================================================================= time-varying B

// dq/dt = b(t) u (+ d w), b(t) = 1 + 0.5 sin t; B depends on t.
class TimeVaryingScalar final : public hinf::Model {
 public:
  std::string name() const override { return "tv-scalar"; }
  int n() const override { return 1; }
  int m() const override { return 1; }
  int nw() const override { return 1; }
  void f(double, const hinf::ConstVecRef&, hinf::VecRef out) const override { out[0] = 0.0; }
  void dfdq(double, const hinf::ConstVecRef&, hinf::MatRef J) const override { J(0, 0) = 0.0; }
  Mat G(double t, const hinf::ConstVecRef&) const override { return Mat::Constant(1, 1, 1.0 + 0.5 * std::sin(t)); }
  Mat D(double, const hinf::ConstVecRef&) const override { return Mat::Constant(1, 1, 0.6); }
  bool constant_input_matrices() const override { return false; }
};

// dq/dt = -q + G u + D w with a flaw chosen by the test: a NaN in f or in df/dq after t = 1, a G
// that changes with t or with q while the model declares the default (constant, independent of q).
class FlawedScalar final : public hinf::Model {
 public:
  enum class Flaw { NanDrift, NanJacobian, GofT, GofQ };
  explicit FlawedScalar(Flaw flaw) : flaw_(flaw) {}
  std::string name() const override { return "flawed"; }
  int n() const override { return 1; }
  int m() const override { return 1; }
  int nw() const override { return 1; }
  void f(double t, const hinf::ConstVecRef& q, hinf::VecRef out) const override {
    out[0] = flaw_ == Flaw::NanDrift && t > 1.0 ? std::numeric_limits<double>::quiet_NaN() : -q[0];
  }
  void dfdq(double t, const hinf::ConstVecRef&, hinf::MatRef J) const override {
    // NaN on (1, 1.5) only: met inside the backward solve, not at its start tf = 2.
    J(0, 0) = flaw_ == Flaw::NanJacobian && t > 1.0 && t < 1.5 ? std::numeric_limits<double>::quiet_NaN() : -1.0;
  }
  Mat G(double t, const hinf::ConstVecRef& q) const override {
    if (flaw_ == Flaw::GofT) return Mat::Constant(1, 1, 1.0 + 0.5 * t);
    if (flaw_ == Flaw::GofQ) return Mat::Constant(1, 1, 1.0 + 0.5 * std::tanh(q[0]));
    return Mat::Constant(1, 1, 1.0);
  }
  Mat D(double, const hinf::ConstVecRef&) const override { return Mat::Constant(1, 1, 0.5); }

 private:
  Flaw flaw_;
};

std::shared_ptr<const hinf::Trajectory> flawed_trajectory(FlawedScalar::Flaw flaw) {
  return std::make_shared<const hinf::Trajectory>(std::make_shared<const FlawedScalar>(flaw), Vec::Constant(1, 1.0),
                                                  hinf::VectorSignal(std::vector<hinf::Signal>{hinf::Signal(0.5)}),
                                                  0.0, 2.0);
}

template <class Action>
std::string input_error_of(Action action) {
  try {
    action();
  } catch (const hinf::InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("another error: ") + e.what();
  }
  return "(no error)";
}

TEST(ModelChecks, ANonFiniteDriftIsTheModelsErrorWithItsTimeAndState) {
  // Before: the desired trajectory's integrator shrank its step on NaN until it gave up, blaming
  // the step size.
  const std::string what = input_error_of([] { flawed_trajectory(FlawedScalar::Flaw::NanDrift); });
  EXPECT_NE(what.find("the model 'flawed' returned a non-finite f(t, q) (nan at (0, 0)) at t = 1"), std::string::npos)
      << what;
  EXPECT_NE(what.find(", q = ["), std::string::npos) << what;
}

TEST(ModelChecks, ANonFiniteJacobianIsNotAConjugatePoint) {
  // Before: the GRDE backward from tf met the NaN at once and reported a conjugate point at tf.
  const auto trajectory = flawed_trajectory(FlawedScalar::Flaw::NanJacobian);
  const std::string what = input_error_of(
      [&] { hinf::solve_grde(trajectory, Mat::Identity(1, 1), Mat::Identity(1, 1), 10.0); });
  EXPECT_NE(what.find("the model 'flawed' returned a non-finite df/dq (t, q)"), std::string::npos) << what;
}

TEST(ModelChecks, ANonFinitePlantInTheClosedLoopIsTheModelsError) {
  // The design model is sound; the plant's drift becomes NaN after t = 1.
  const auto sound = std::make_shared<const hinf::Trajectory>(
      std::make_shared<const hinf::LinearModel>(Mat::Constant(1, 1, -1.0), Mat::Constant(1, 1, 1.0),
                                                Mat::Constant(1, 1, 0.5)),
      Vec::Constant(1, 1.0), hinf::VectorSignal(std::vector<hinf::Signal>{hinf::Signal(0.5)}), 0.0, 2.0);
  hinf::HinfStateFeedback controller(hinf::solve_grde(sound, Mat::Identity(1, 1), Mat::Identity(1, 1), 10.0));
  const FlawedScalar plant(FlawedScalar::Flaw::NanDrift);
  for (Method method : kMethods) {
    hinf::SimulationOptions options;
    options.solver.method = method;
    const std::string what = input_error_of([&] {
      hinf::simulate_state_feedback(*sound, controller, hinf::VectorSignal::zeros(1), Vec::Constant(1, 1.2), options,
                                    &plant);
    });
    EXPECT_NE(what.find("the model 'flawed' returned a non-finite f(t, q)"), std::string::npos)
        << hinf::to_string(method) << ": " << what;
  }
}

TEST(ModelChecks, InputMatricesThatChangeMustBeDeclared) {
  // Before: G was taken at (t0, q_d0) everywhere (G(t)), or its d(G u)/dq left out (G(q)),
  // silently.
  const std::string of_t = input_error_of([] { flawed_trajectory(FlawedScalar::Flaw::GofT); });
  EXPECT_NE(of_t.find("the model 'flawed' returns another G at t = 1, q = ["), std::string::npos) << of_t;
  EXPECT_NE(of_t.find("than at t = 0, q = [1]"), std::string::npos) << of_t;
  EXPECT_NE(of_t.find("override constant_input_matrices() to return false"), std::string::npos) << of_t;
  const std::string of_q = input_error_of([] { flawed_trajectory(FlawedScalar::Flaw::GofQ); });
  EXPECT_NE(of_q.find("override state_dependent_inputs() to return true"), std::string::npos) << of_q;
}

TEST(DesiredTrajectory, LinearTableInputAgainstTheClosedForm) {
  // dq/dt = -q + u(t) with u a "linear" table that zig-zags (slopes +-40 between points 0.05 s
  // apart, kinks at every point). On a piece where u = a + b s (s = t - t_k):
  //   q = a - b + b s + (q_k - a + b) exp(-s).
  // The integration restarts at the table's points, so it keeps its tolerance (rtol 1e-10,
  // atol 1e-12) across the kinks: 1e-9 allows 200 steps' worth of local errors (|q| <= 1).
  std::vector<double> t, v;
  for (int k = 0; k <= 200; ++k) {
    t.push_back(0.05 * k);
    v.push_back(k % 2 == 0 ? 1.0 : -1.0);
  }
  const hinf::Signal u = hinf::Signal::table(t, v, hinf::Interpolation::Linear);
  auto model = std::make_shared<const hinf::LinearModel>(Mat::Constant(1, 1, -1.0), Mat::Constant(1, 1, 1.0),
                                                         Mat::Identity(1, 1));
  const hinf::Trajectory trajectory(model, Vec::Constant(1, 0.5), hinf::VectorSignal({u}), 0.0, 10.0);
  double q_k = 0.5;
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const double a = v[k], b = (v[k + 1] - v[k]) / (t[k + 1] - t[k]);
    for (double s : {0.0, 0.013, 0.025, 0.041})
      EXPECT_NEAR(trajectory.q_d(t[k] + s)[0], a - b + b * s + (q_k - a + b) * std::exp(-s), 1e-9) << t[k] + s;
    const double h = t[k + 1] - t[k];
    q_k = a - b + b * h + (q_k - a + b) * std::exp(-h);
  }
  EXPECT_NEAR(trajectory.q_d(10.0)[0], q_k, 1e-9);
}

TEST(SimulationTimeVarying, ClosedLoopErrorHasTheClosedForm) {
  // gamma = inf, Q = 0, Qf = qf, q_d = 2 (u_d = 0, f = 0). Then w := 1/z obeys
  // dw/dt = -b^2, so w(t) = 1/qf + int_t^tf b^2, and the error e = q - q_d under
  // u = -kappa b z e obeys de/dt = -kappa b^2 z e, which makes e z^kappa constant:
  //     e(t) = e0 (w(t) / w(t0))^kappa.
  const double qf = 0.8, t0 = 0.0, tf = 6.0, e0 = 0.5;
  auto model = std::make_shared<const TimeVaryingScalar>();
  const auto trajectory = std::make_shared<const hinf::Trajectory>(
      model, Vec::Constant(1, 2.0), hinf::VectorSignal::zeros(1), t0, tf);
  const auto solution = hinf::solve_grde(trajectory, Mat::Zero(1, 1), Mat::Constant(1, 1, qf),
                                         std::numeric_limits<double>::infinity());
  auto w_of = [&](double t) {
    return 1.0 / qf + 1.125 * (tf - t) + std::cos(t) - std::cos(tf) -
           0.0625 * (std::sin(2 * tf) - std::sin(2 * t));
  };
  for (double kappa : {1.0, 0.7}) {
    for (Method method : kMethods) {
      hinf::HinfStateFeedback controller(solution, hinf::Signal(kappa));
      SolverOptions o;
      o.method = method;
      o.rtol = 1e-10;
      o.atol = 1e-12;
      const hinf::SimulationResult run = hinf::simulate_state_feedback(
          *trajectory, controller, hinf::VectorSignal::zeros(1), Vec::Constant(1, 2.0 + e0), sim(0.1, o));
      double max_err = 0.0, max_u_err = 0.0;
      for (Eigen::Index k = 0; k < run.t.size(); ++k) {
        const double t = run.t[k];
        const double e = e0 * std::pow(w_of(t) / w_of(t0), kappa);
        max_err = std::max(max_err, std::abs(run.q(k, 0) - 2.0 - e));
        max_u_err = std::max(max_u_err, std::abs(run.u(k, 0) + kappa * (1.0 + 0.5 * std::sin(t)) / w_of(t) * e));
      }
      std::printf("[closed loop] tv-B kappa %.1f %-5s: max |e - e_exact| %.2e, max |u - u_exact| %.2e\n",
                  kappa, hinf::to_string(method).c_str(), max_err, max_u_err);
      EXPECT_LT(max_err, 1e-7) << hinf::to_string(method);
      EXPECT_LT(max_u_err, 1e-7) << hinf::to_string(method);
    }
  }
}

TEST_F(PaperShip, BadInputsThrow) {
  hinf::HinfStateFeedback controller(solution_);
  const hinf::VectorSignal w = hinf::VectorSignal::zeros(6);
  const SolverOptions ok;
  EXPECT_THROW(hinf::simulate_state_feedback(*trajectory_, controller, w, Vec::Zero(5), sim(0.1, ok)),
               hinf::InputError);
  EXPECT_THROW(hinf::simulate_state_feedback(*trajectory_, controller, w, Vec::Zero(7), sim(0.1, ok)),
               hinf::InputError);
  Vec nan_q0 = paper_q_d0();
  nan_q0[2] = kNaN;
  EXPECT_THROW(hinf::simulate_state_feedback(*trajectory_, controller, w, nan_q0, sim(0.1, ok)),
               hinf::InputError);
  EXPECT_THROW(hinf::simulate_state_feedback(*trajectory_, controller, hinf::VectorSignal::zeros(3),
                                             paper_q_d0(), sim(0.1, ok)),
               hinf::InputError);
  EXPECT_THROW(hinf::simulate_state_feedback(*trajectory_, controller, hinf::VectorSignal::zeros(7),
                                             paper_q_d0(), sim(0.1, ok)),
               hinf::InputError);
  for (double dt : {0.0, -0.01, kNaN})
    EXPECT_THROW(hinf::simulate_state_feedback(*trajectory_, controller, w, paper_q_d0(), sim(dt, ok)),
                 hinf::InputError)
        << "dt = " << dt;
  SolverOptions bad = ok;
  bad.rtol = 0.0;
  EXPECT_THROW(hinf::simulate_state_feedback(*trajectory_, controller, w, paper_q_d0(), sim(0.1, bad)),
               hinf::InputError);
}

// ======================================================================= metrics

// A synthetic run: every row of each series is given by the callers.
hinf::SimulationResult synthetic(const std::vector<double>& t, int n, int m, int nw) {
  hinf::SimulationResult r;
  r.t = Eigen::Map<const Vec>(t.data(), static_cast<Eigen::Index>(t.size()));
  const Eigen::Index N = r.t.size();
  r.q = RowMat::Zero(N, n);
  r.q_d = RowMat::Zero(N, n);
  r.u = RowMat::Zero(N, m);
  r.u_d = RowMat::Zero(N, m);
  r.w = RowMat::Zero(N, nw);
  return r;
}

TEST(Metrics, ConstantSignalsHaveExactIntegrals) {
  // Grid with a partial last interval: T = 2.5.
  hinf::SimulationResult r = synthetic({0.0, 1.0, 2.0, 2.5}, 6, 2, 6);
  Vec q_d(6), q_e(6), u(2), u_d(2), w(6);
  q_d << 1.0, 0.0, 0.0, 10.0, 20.0, 0.3;
  q_e << 1.0, 0.0, 2.0, 3.0, -4.0, 0.5;  // position error (3, -4): |p_e| = 5
  u << 2.0, -1.0;
  u_d << 1.0, 1.0;                        // u_e = (1, -2)
  w << 0.1, 0.2, 0.3, 0.0, 0.0, 0.0;      // |w|^2 = 0.14
  for (Eigen::Index k = 0; k < 4; ++k) {
    r.q_d.row(k) = q_d.transpose();
    r.q.row(k) = (q_d + q_e).transpose();
    r.u.row(k) = u.transpose();
    r.u_d.row(k) = u_d.transpose();
    r.w.row(k) = w.transpose();
  }
  Mat Q = Mat::Zero(6, 6);
  Q.diagonal() << 1, 2, 3, 4, 5, 6;
  // |q_e|_Q^2 = 1 + 0 + 3*4 + 4*9 + 5*16 + 6*0.25 = 130.5, |u_e|^2 = 5.
  const hinf::Metrics mt = hinf::compute_metrics(hinf::ShipModel(), r, Q);
  const double T = 2.5;
  // A handful of sums and roots of these numbers against the closed forms: round-off of the
  // values (<= 32).
  const double tol = hinf_test::kRoundoff * 32.0;
  EXPECT_NEAR(mt.rms_position_error_last_half, 5.0, tol);
  EXPECT_NEAR(mt.max_position_error, 5.0, tol);
  EXPECT_NEAR(mt.final_position_error, 5.0, tol);
  EXPECT_NEAR(mt.control_l2, std::sqrt(5.0 * T), tol);
  EXPECT_NEAR(mt.control_error_l2, std::sqrt(5.0 * T), tol);
  EXPECT_NEAR(mt.disturbance_l2, std::sqrt(0.14 * T), tol);
  EXPECT_NEAR(mt.response_ratio, std::sqrt((130.5 + 5.0) * T) / std::sqrt(0.14 * T), tol);
  EXPECT_NEAR(mt.tracking_cost, (130.5 + 5.0) * T, tol * 340.0);  // no Qf given: no terminal term
  EXPECT_TRUE(std::isnan(mt.disturbance_gain)) << "q_e(t0) != 0: not from the desired start";
  EXPECT_TRUE(std::isnan(mt.attenuation_margin)) << "no bound given";
  // A constant heading error of 0.5 rad: that is the largest, and it never turns around.
  EXPECT_EQ(mt.heading_excursion, 0.5);
  EXPECT_EQ(mt.turned_around, 0.0);

  // With Qf, gamma and the bound's initial term: L = (130.5 + 5) T + |q_e|_Qf^2, Qf = 2 I.
  hinf::CostWeights weights;
  weights.Q = Q;
  weights.Qf = 2.0 * Mat::Identity(6, 6);
  weights.gamma = 3.0;
  weights.initial_term = 7.0;
  const hinf::Metrics mb = hinf::compute_metrics(hinf::ShipModel(), r, weights);
  const double L = 135.5 * T + 2.0 * q_e.squaredNorm();
  EXPECT_NEAR(mb.tracking_cost, L, tol * L);
  EXPECT_NEAR(mb.response_ratio, std::sqrt(L / (0.14 * T)), tol * 40.0);
  EXPECT_NEAR(mb.attenuation_margin, 1.0 - L / (9.0 * 0.14 * T + 7.0), tol * 100.0);
  EXPECT_LT(mb.attenuation_margin, 0.0) << "this made-up run exceeds the bound";
  EXPECT_TRUE(std::isnan(mt.max_rho_sigma_z)) << "state feedback: no Sigma";
  EXPECT_TRUE(std::isnan(mt.rms_estimation_error_last_half));
  // The plain L2 norm.
  EXPECT_NEAR(hinf::l2_norm(r.t, r.u), std::sqrt(5.0 * T), tol);
}

TEST(Metrics, LastHalfMaxFinalTrapezoidAndOutputFeedbackByHand) {
  // t = 0..4; x_e = [0, 3, 1, 2, 0.5], y_e = 0; u_e = [0, 1, 2, 1, 0] on channel 1 only;
  // no disturbance.
  hinf::SimulationResult r = synthetic({0.0, 1.0, 2.0, 3.0, 4.0}, 6, 2, 6);
  const double xe[] = {0.0, 3.0, 1.0, 2.0, 0.5};
  const double ue[] = {0.0, 1.0, 2.0, 1.0, 0.0};
  hinf::EstimatorSeries& estimator = r.estimator.emplace();
  estimator.rho_sigma_z = Vec(5);
  estimator.rho_sigma_z << 0.1, 0.7, 0.3, 0.2, 0.4;
  estimator.q_hat = RowMat::Zero(5, 6);
  for (Eigen::Index k = 0; k < 5; ++k) {
    r.q(k, 3) = 5.0 + xe[k];
    r.q_d(k, 3) = 5.0;
    r.u(k, 0) = 1.0 + ue[k];
    r.u_d(k, 0) = 1.0;
    // Estimate: q_e + (k, 0, ..., 0, 1): |q_hat - q_e|^2 = k^2 + 1.
    estimator.q_hat.row(k) = (r.q.row(k) - r.q_d.row(k));
    estimator.q_hat(k, 0) += static_cast<double>(k);
    estimator.q_hat(k, 5) += 1.0;
  }
  const hinf::Metrics mt = hinf::compute_metrics(hinf::ShipModel(), r, Mat::Identity(6, 6));
  // Sums and roots of these small numbers against the closed forms: round-off of values <= 20.
  const double tol = hinf_test::kRoundoff * 20.0;
  // Last half: t >= 2, i.e. points 2, 3, 4.
  EXPECT_NEAR(mt.rms_position_error_last_half, std::sqrt((1.0 + 4.0 + 0.25) / 3.0), tol);
  // hypot(x, 0) = |x| exactly, and the largest / last of exact inputs.
  EXPECT_EQ(mt.max_position_error, 3.0);
  EXPECT_EQ(mt.final_position_error, 0.5);
  // Trapezoid of u_e^2 = [0, 1, 4, 1, 0]: (0+1)/2 + (1+4)/2 + (4+1)/2 + (1+0)/2 = 6.
  EXPECT_NEAR(mt.control_error_l2, std::sqrt(6.0), tol);
  // |u|^2 = [1, 4, 9, 4, 1]: 2.5 + 6.5 + 6.5 + 2.5 = 18.
  EXPECT_NEAR(mt.control_l2, std::sqrt(18.0), tol);
  EXPECT_EQ(mt.disturbance_l2, 0.0);
  EXPECT_TRUE(std::isnan(mt.response_ratio)) << "no disturbance: the gain is undefined";
  EXPECT_TRUE(std::isnan(mt.disturbance_gain)) << "no disturbance: the gain is undefined";
  EXPECT_EQ(mt.max_rho_sigma_z, 0.7);
  // Points 2, 3, 4: (4 + 1, 9 + 1, 16 + 1) -> sqrt(32 / 3).
  EXPECT_NEAR(mt.rms_estimation_error_last_half, std::sqrt(32.0 / 3.0), tol);
}

TEST(Metrics, ModelWithoutPositionGivesNaNPositionMetrics) {
  const hinf::LinearModel model(Mat::Identity(2, 2), Mat::Identity(2, 1), Mat::Identity(2, 2));
  hinf::SimulationResult r = synthetic({0.0, 0.5, 1.0}, 2, 1, 2);
  r.u.setConstant(2.0);
  r.w.setConstant(1.0);
  const hinf::Metrics mt = hinf::compute_metrics(model, r, Mat::Identity(2, 2));
  EXPECT_TRUE(std::isnan(mt.rms_position_error_last_half));
  EXPECT_TRUE(std::isnan(mt.max_position_error));
  EXPECT_TRUE(std::isnan(mt.final_position_error));
  EXPECT_NEAR(mt.control_l2, 2.0, hinf_test::kRoundoff * 2.0);
  EXPECT_NEAR(mt.disturbance_l2, std::sqrt(2.0), hinf_test::kRoundoff * 2.0);
  // u_e = 2 (u_d = 0), q_e = 0: from the desired start, so both ratios.
  EXPECT_NEAR(mt.response_ratio, std::sqrt(4.0) / std::sqrt(2.0), hinf_test::kRoundoff * 2.0);
  EXPECT_EQ(mt.disturbance_gain, mt.response_ratio);
  EXPECT_TRUE(std::isnan(mt.heading_excursion)) << "no heading";
  EXPECT_TRUE(std::isnan(mt.turned_around)) << "no heading";
}

TEST(Metrics, HeadingExcursionFollowsTheErrorThroughWraps) {
  // The heading error turns steadily through more than a full turn and back a little:
  // e = 0, 1, 2, 3, 4, 5, 6.5, 6 rad; its wrapped samples jump by -2 pi past pi, the followed
  // error does not. The largest |e| is 6.5 > max(pi, 0) + 0.1: turned around (through +-pi).
  const std::vector<double> times{0, 1, 2, 3, 4, 5, 6, 7};
  const double e[] = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.5, 6.0};
  hinf::SimulationResult r = synthetic(times, 6, 2, 6);
  for (Eigen::Index k = 0; k < 8; ++k) {
    r.q_d(k, 5) = 0.1 * static_cast<double>(k);  // the desired heading (psi, index 5) turns too
    r.q(k, 5) = r.q_d(k, 5) + e[k];
  }
  const hinf::Metrics mt = hinf::compute_metrics(hinf::ShipModel(), r, Mat::Identity(6, 6));
  // Sums of eight wrapped increments, each exact to round-off of values <= 2 pi.
  EXPECT_NEAR(mt.heading_excursion, 6.5, hinf_test::kRoundoff * 64.0);
  EXPECT_EQ(mt.turned_around, 1.0);
  // An error bounded by 1.5 rad neither passes pi nor points backwards (|e| < pi/2).
  for (Eigen::Index k = 0; k < 8; ++k) r.q(k, 5) = r.q_d(k, 5) + 1.5 * std::sin(static_cast<double>(k));
  const hinf::Metrics small = hinf::compute_metrics(hinf::ShipModel(), r, Mat::Identity(6, 6));
  EXPECT_NEAR(small.heading_excursion, 1.5 * std::abs(std::sin(5.0)), hinf_test::kRoundoff * 8.0);  // at k = 5
  EXPECT_EQ(small.turned_around, 0.0);
  // Pointing backwards (|e| = 2 > pi/2) on the whole last half without passing pi: tracks
  // the path backwards, turned around; the same on half the last half or less is not.
  for (Eigen::Index k = 0; k < 8; ++k) r.q(k, 5) = r.q_d(k, 5) + 2.0;
  const hinf::Metrics backwards = hinf::compute_metrics(hinf::ShipModel(), r, Mat::Identity(6, 6));
  EXPECT_NEAR(backwards.heading_excursion, 2.0, hinf_test::kRoundoff * 8.0);
  EXPECT_EQ(backwards.turned_around, 1.0);
  // Last half: t >= 3.5, points 4..7; backwards on 4 and 5 only: half, not more.
  for (Eigen::Index k = 0; k < 8; ++k) r.q(k, 5) = r.q_d(k, 5) + (k == 4 || k == 5 ? 2.0 : 1.0);
  EXPECT_EQ(hinf::compute_metrics(hinf::ShipModel(), r, Mat::Identity(6, 6)).turned_around, 0.0);
}

}  // namespace
