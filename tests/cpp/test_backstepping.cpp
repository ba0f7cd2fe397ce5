// The backstepping baseline law of the ship (control/backstepping.hpp, BacksteppingController):
//   * the desired trajectory is a solution of its closed loop (its commands are exact there):
//     started on the paper's curved path, the run stays on it to the integration's accuracy;
//   * the law at a state computed by hand (a straight line, a lateral offset): the commanded
//     velocity, its course and the surge that makes it;
//   * from a start ahead of the desired point (the situation in which the paper, §1, says a
//     Godhavn-type law turns the ship around, its reference [3]) it turns the ship around
//     (heading excursion > pi/2), tracks the path again, and the H-infinity law does not turn;
//   * the constructor's checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "hinf/control/backstepping.hpp"
#include "hinf/control/controller.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"
#include "ship_runs.hpp"

namespace {

using hinf::BacksteppingController;
using hinf::BacksteppingGains;
using hinf::Mat;
using hinf::ShipParameters;
using hinf::Vec;
using hinf_test::constant_inputs;
using hinf_test::paper_u_d;
using hinf_test::ship_trajectory;
using hinf_test::state;
using hinf_test::tight;

TEST(BacksteppingLaw, TheDesiredTrajectoryIsAClosedLoopSolution) {
  // The paper's path (curved: r_d and v_d vary) from the desired start, no disturbance.
  const Vec q_d0 = state(1.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  const auto trajectory = ship_trajectory(ShipParameters{}, q_d0, paper_u_d(), 40.0);
  BacksteppingController law(trajectory);
  const hinf::SimulationResult run = hinf::simulate_state_feedback(*trajectory, law, hinf::VectorSignal::zeros(6), q_d0, tight(0.1));
  ASSERT_EQ(run.status, hinf::RunStatus::Completed);
  // The law's commands equal u_d on the trajectory: the run differs from q_d only by the two
  // integrations' errors (rtol 1e-11 over 40 s of a state of size ~40 m: ~1e-8).
  const Mat error = run.q - run.q_d;
  EXPECT_LT(error.cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((run.u - run.u_d).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(BacksteppingLaw, ALateralOffsetByHand) {
  // A straight line along x with u_d = (1, 0): q_d(t) = (1, 0, 0, t, 0, 0) exactly. At t = 2 the
  // ship is at (2, -1), heading 0, surge 1, no sway or yaw rate. With k = 0.5:
  //   v_c = (1, 0) - 0.5 (0, -1) = (1, 0.5),  dv_c/dt = 0 - 0.5 ((1, 0) - (1, 0)) = 0,
  //   u_c = |v_c| = sqrt(1.25) (v = 0), du_c/dt = 0, psi_c = atan2(0.5, 1), dpsi_c/dt = 0,
  //   z1 = -atan(0.5), r_c = k1 atan(0.5), z2 = -r_c,
  //   u1 = d_u u - k3 (u - u_c) = 1 - (1 - sqrt(1.25)),
  //   u2 = 0 (dr_d/dt = 0) + atan(0.5) + k2 k1 atan(0.5).
  const auto trajectory = ship_trajectory(ShipParameters{}, state(1.0, 0.0, 0.0, 0.0, 0.0, 0.0),
                                          constant_inputs(1.0, 0.0), 5.0);
  BacksteppingGains gains;
  gains.k = 0.5;
  gains.k1 = 1.5;
  gains.k2 = 2.5;
  gains.k3 = 0.7;
  BacksteppingController law(trajectory, gains);
  Vec u(2);
  law.control(2.0, state(1.0, 0.0, 0.0, 2.0, -1.0, 0.0), u);
  const double a = std::atan(0.5);
  // A few operations on numbers of size ~1 each: round-off (the trajectory's q_d is exact here:
  // its integrator steps a constant state).
  EXPECT_NEAR(u[0], 1.0 - 0.7 * (1.0 - std::sqrt(1.25)), 1e-9);
  EXPECT_NEAR(u[1], a + 2.5 * 1.5 * a, 1e-9);
}

TEST(BacksteppingLaw, TurnsAroundFromAStartAheadWhereTheHinfLawDoesNot) {
  // The paper's path over 40 s; the ship starts 8 m ahead of the desired start along the path,
  // with the desired heading and velocities. The commanded velocity (1, 0) - 0.5 (8, 0) points
  // backwards: the backstepping law turns the ship round (the behaviour the paper, §1, ascribes
  // to Godhavn's law) and then back onto the path; the H-infinity law (gamma = 5) slows down
  // and waits for the desired point without turning.
  const Vec q_d0 = state(1.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  const Vec q0 = state(1.0, 0.0, 0.0, 8.0, 0.0, 0.0);
  const auto trajectory = ship_trajectory(ShipParameters{}, q_d0, paper_u_d(), 40.0);
  const Mat I = Mat::Identity(6, 6);
  BacksteppingController backstepping(trajectory);
  const hinf::SimulationResult turned = hinf::simulate_state_feedback(*trajectory, backstepping, hinf::VectorSignal::zeros(6), q0, tight(0.05));
  const hinf::Metrics b = hinf::compute_metrics(trajectory->model(), turned, I);
  hinf::HinfStateFeedback hinf_law(hinf::solve_grde(trajectory, I, I, 5.0));
  const hinf::SimulationResult waited = hinf::simulate_state_feedback(*trajectory, hinf_law, hinf::VectorSignal::zeros(6), q0, tight(0.05));
  const hinf::Metrics h = hinf::compute_metrics(trajectory->model(), waited, I);
  std::printf("[turn around] backstepping: excursion %.3f rad, final error %.3g m; hinf: excursion %.3f rad, "
              "final error %.3g m\n",
              b.heading_excursion, b.final_position_error, h.heading_excursion, h.final_position_error);
  EXPECT_EQ(b.turned_around, 1.0);
  EXPECT_GT(b.heading_excursion, 2.5) << "at least half a turn (it makes a whole loop: 6.4 rad measured)";
  EXPECT_LT(b.final_position_error, 0.1) << "back on the path";
  EXPECT_EQ(h.turned_around, 0.0);
}

TEST(BacksteppingLaw, ConstructorChecks) {
  const auto trajectory = ship_trajectory(ShipParameters{}, state(1.0, 0.0, 0.0, 0.0, 0.0, 0.0), paper_u_d(), 5.0);
  for (double bad : {0.0, -1.0, static_cast<double>(NAN), static_cast<double>(INFINITY)}) {
    BacksteppingGains gains;
    gains.k3 = bad;
    EXPECT_THROW(BacksteppingController(trajectory, gains), hinf::InputError) << bad;
  }
  const auto linear = std::make_shared<const hinf::Trajectory>(
      std::make_shared<const hinf::LinearModel>(Mat::Identity(2, 2), Mat::Identity(2, 1), Mat::Identity(2, 2)),
      Vec::Zero(2), hinf::VectorSignal::zeros(1), 0.0, 1.0);
  try {
    BacksteppingController law(linear);
    FAIL() << "a linear model was accepted";
  } catch (const hinf::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ship model"), std::string::npos) << e.what();
  }
}

}  // namespace
