// A desired trajectory given as states and inputs (control/trajectory.hpp, second constructor):
//   * on an open-loop-unstable plant with a bounded exact trajectory (q_d = sin t on
//     dq/dt = a q + u, a = 2), the states at nodes give q_d within the integration tolerance of
//     the closed form over 20 s, where one integration from q_d0 drifts away by e^(a t) times its
//     error;
//   * a state that is not on the trajectory shows as the defect of its interval, and a scenario
//     refuses it naming [desired] max_defect;
//   * on the paper's (stable) path the states of one integration give back that integration;
//   * bad nodes are named;
//   * the receding horizon along states: its windows chain along the states (within the
//     integration tolerance of sin t over 200 s, where windows of the inputs alone drift), and
//     its loop tracks them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "hinf/control/receding_horizon.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/models/model.hpp"
#include "hinf/scenario/scenario.hpp"

namespace {

using hinf::Mat;
using hinf::RowMat;
using hinf::Vec;

constexpr double kA = 2.0;  // the plant's open-loop growth rate (1/s)

// dq/dt = a q + u + w, with u_d = cos t - a sin t: q_d = sin t exactly.
hinf::ModelPtr unstable_model() {
  return std::make_shared<const hinf::LinearModel>(Mat::Constant(1, 1, kA), Mat::Constant(1, 1, 1.0),
                                                   Mat::Constant(1, 1, 1.0));
}
hinf::VectorSignal sine_inputs() {
  return hinf::VectorSignal({hinf::Signal(0.0, {hinf::Harmonic{1.0, 1.0, 0.0, true}, hinf::Harmonic{-kA, 1.0, 0.0, false}})});
}

std::vector<double> nodes(double tf, double h) {
  std::vector<double> t;
  for (int k = 0; k * h <= tf + 1e-12; ++k) t.push_back(k * h);
  return t;
}

TEST(DesiredStates, UnstablePlantFollowsItsStatesWhereOneIntegrationDrifts) {
  const std::vector<double> t = nodes(20.0, 0.5);
  RowMat q(static_cast<Eigen::Index>(t.size()), 1);
  for (std::size_t k = 0; k < t.size(); ++k) q(static_cast<Eigen::Index>(k), 0) = std::sin(t[k]);
  const hinf::Trajectory given(unstable_model(), t, q, sine_inputs());
  EXPECT_EQ(given.defects().size(), t.size() - 1);
  EXPECT_DOUBLE_EQ(given.t0(), 0.0);
  EXPECT_DOUBLE_EQ(given.tf(), 20.0);
  double largest = 0.0;
  for (double s = 0.0; s <= 20.0; s += 0.01) largest = std::max(largest, std::abs(given.q_d(s)[0] - std::sin(s)));
  // Each interval of 0.5 s carries a local error of rtol 1e-10 / atol 1e-12 grown by at most
  // e^(a 0.5) = 2.7: far below 1e-8, where the whole-horizon integration grows by e^(a 20) = 2e17.
  EXPECT_LT(largest, 1e-8);
  EXPECT_LT(given.max_defect(), 1e-8);

  const hinf::Trajectory integrated(unstable_model(), Vec::Zero(1), sine_inputs(), 0.0, 20.0);
  EXPECT_GT(std::abs(integrated.q_d(20.0)[0] - std::sin(20.0)), 1e-3);

  // The design along the states: the linear plant's GRDE, a Riccati ODE with constant
  // coefficients whatever q_d is, and so the same on both trajectories (two integrations of one
  // equation at rtol 1e-8).
  const auto a = hinf::solve_grde(std::make_shared<const hinf::Trajectory>(given), Mat::Identity(1, 1),
                                  Mat::Identity(1, 1), 5.0);
  const auto b = hinf::solve_grde(std::make_shared<const hinf::Trajectory>(integrated), Mat::Identity(1, 1),
                                  Mat::Identity(1, 1), 5.0);
  EXPECT_NEAR(a->Z(0.0)(0, 0), b->Z(0.0)(0, 0), 1e-6 * b->Z(0.0)(0, 0));
}

TEST(DesiredStates, AStateOffTheTrajectoryIsItsIntervalsDefect) {
  const std::vector<double> t = nodes(4.0, 0.5);
  RowMat q(static_cast<Eigen::Index>(t.size()), 1);
  for (std::size_t k = 0; k < t.size(); ++k) q(static_cast<Eigen::Index>(k), 0) = std::sin(t[k]);
  q(5, 0) += 0.1;  // t = 2.5 s
  const hinf::Trajectory given(unstable_model(), t, q, sine_inputs());
  // The interval into node 5 misses it by 0.1 (to the integration's accuracy); the one out of
  // it starts from the displaced state and grows it by e^(a 0.5) = e.
  EXPECT_NEAR(given.defects()[4], 0.1, 1e-8);
  EXPECT_NEAR(given.defects()[5], 0.1 * std::exp(kA * 0.5), 1e-8);
  EXPECT_DOUBLE_EQ(given.max_defect_t(), 2.5);
  EXPECT_NEAR(given.max_defect(), 0.1 * std::exp(kA * 0.5), 1e-8);
}

TEST(DesiredStates, StatesOfOneIntegrationGiveItBack) {
  const hinf::Scenario s =
      hinf::load_scenario_toml(std::string(HINF_SOURCE_DIR) + "/scenarios/paper_fig1.toml").resolved();
  const hinf::Trajectory whole(s.model, s.desired_q0, s.desired_u, 0.0, 10.0);
  const std::vector<double> t = nodes(10.0, 1.0);
  RowMat q(static_cast<Eigen::Index>(t.size()), 6);
  for (std::size_t k = 0; k < t.size(); ++k) q.row(static_cast<Eigen::Index>(k)) = whole.q_d(t[k]).transpose();
  const hinf::Trajectory given(s.model, t, q, s.desired_u);
  double largest = 0.0;
  for (double tt = 0.0; tt <= 10.0; tt += 0.05)
    largest = std::max(largest, (given.q_d(tt) - whole.q_d(tt)).cwiseAbs().maxCoeff());
  // Two integrations at rtol 1e-10 / atol 1e-12 of a path of size ~10 m over 10 s.
  EXPECT_LT(largest, 1e-7);
  EXPECT_LT(given.max_defect(), 1e-7);
}

TEST(DesiredStates, ScenarioRefusesStatesThatAreNotATrajectory) {
  hinf::Scenario s =
      hinf::load_scenario_toml(std::string(HINF_SOURCE_DIR) + "/scenarios/paper_fig1.toml").resolved();
  s.tf = 4.0;
  const hinf::Trajectory whole(s.model, s.desired_q0, s.desired_u, 0.0, 4.0);
  hinf::DesiredStates states;
  states.t = nodes(4.0, 1.0);
  states.q.resize(5, 6);
  for (int k = 0; k < 5; ++k) states.q.row(k) = whole.q_d(k).transpose();
  s.desired_states = states;
  EXPECT_NO_THROW(hinf::run_scenario(s));
  s.desired_states->q(2, 3) += 0.5;  // x at t = 2 s half a metre off
  try {
    hinf::run_scenario(s);
    FAIL() << "a state half a metre off the trajectory was accepted";
  } catch (const hinf::InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("max_defect"), std::string::npos) << message;
    EXPECT_NE(message.find("[desired] states"), std::string::npos) << message;
  }
  s.desired_states->q(2, 3) -= 0.5;
  s.desired_states->q(0, 0) += 1.0;
  EXPECT_THROW(hinf::run_scenario(s), hinf::InputError);  // row 0 is not q0
}

TEST(DesiredStates, BadNodesAreNamed) {
  RowMat q = RowMat::Zero(3, 1);
  auto message = [&](std::vector<double> t, const RowMat& states) {
    try {
      hinf::Trajectory(unstable_model(), std::move(t), states, sine_inputs());
    } catch (const hinf::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({0.0, 1.0, 1.0}, q).find("increase"), std::string::npos);
  EXPECT_NE(message({0.0, NAN, 2.0}, q).find("not finite"), std::string::npos);
  EXPECT_NE(message({0.0, 1.0}, q).find("one row"), std::string::npos);
  EXPECT_NE(message({0.0}, RowMat::Zero(1, 1)).find("two nodes"), std::string::npos);
}

TEST(DesiredStates, RecedingHorizonFollowsTheStatesOverALongMission) {
  // Nodes every 0.5 s to 212 s: the windows of a run to 200 s (H = 10 s, update 1 s) reach 210 s.
  const std::vector<double> t = nodes(212.0, 0.5);
  RowMat q(static_cast<Eigen::Index>(t.size()), 1);
  for (std::size_t k = 0; k < t.size(); ++k) q(static_cast<Eigen::Index>(k), 0) = std::sin(t[k]);
  hinf::RecedingHorizonOptions options;
  options.window = 10.0;
  options.update = 1.0;
  const Mat one = Mat::Identity(1, 1);
  const hinf::RecedingHorizon on_states(unstable_model(), t, q, sine_inputs(), one, one, 5.0, options);
  // The chained windows against the closed form: each window is the states form over its
  // interval (local errors of rtol 1e-10 grown by at most e^(a 0.5)), so 1e-8 holds at any t ...
  double largest = 0.0;
  for (double s : {0.0, 3.7, 57.25, 123.9, 199.5}) largest = std::max(largest, std::abs(on_states.desired_state(s)[0] - std::sin(s)));
  EXPECT_LT(largest, 1e-8);
  // ... where windows that integrate the inputs from the chained state drift as one integration.
  const hinf::RecedingHorizon on_inputs(unstable_model(), Vec::Zero(1), sine_inputs(), 0.0, one, one, 5.0, options);
  EXPECT_GT(std::abs(on_inputs.desired_state(20.0)[0] - std::sin(20.0)), 1e-3);
  // The reference of a run and the loop: the vehicle started 0.5 off ends on sin t.
  const hinf::TrajectoryPtr reference = on_states.reference(200.0);
  EXPECT_LT(std::abs(reference->q_d(199.5)[0] - std::sin(199.5)), 1e-8);
  hinf::SimulationOptions run_options;
  run_options.output_dt = 0.5;
  const hinf::SimulationResult run = hinf::simulate_receding_horizon(
      on_states, hinf::Disturbance(hinf::VectorSignal::zeros(1)), Vec::Constant(1, 0.5), 200.0, run_options);
  ASSERT_EQ(run.status, hinf::RunStatus::Completed) << run.status_message;
  const Eigen::Index last = run.t.size() - 1;
  EXPECT_NEAR(run.q_d(last, 0), std::sin(200.0), 1e-8);
  // The closed loop contracts the initial 0.5 at a rate of at least 1/s (a - B'Z with Z ~ 2a): gone by 200 s.
  EXPECT_LT(std::abs(run.q(last, 0) - std::sin(200.0)), 1e-6);
  // Bad nodes are named.
  EXPECT_THROW(hinf::RecedingHorizon(unstable_model(), {0.0, 0.0}, RowMat::Zero(2, 1), sine_inputs(), one, one, 5.0,
                                     options),
               hinf::InputError);
  EXPECT_THROW(hinf::RecedingHorizon(unstable_model(), {0.0, 1.0}, RowMat::Zero(3, 1), sine_inputs(), one, one, 5.0,
                                     options),
               hinf::InputError);
}

}  // namespace
