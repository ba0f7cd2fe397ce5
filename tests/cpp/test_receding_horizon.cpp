// The receding-horizon design (control/receding_horizon.hpp):
//   * windows chain into one desired trajectory: q_d of the windows against one integration over
//     the whole horizon, within the two integrations' tolerances;
//   * a window's Z against the full-horizon design's Z at the same times where both are far from
//     their ends (the GRDE forgets its terminal weight backward in time);
//   * the paper's Figure 1 under the receding horizon: RMS position error over the last half within
//     2% of the full-horizon design for H = 5 s and 10 s (updated every second);
//   * the memory held depends on the window, not on the mission: 400 s and 4000 s of the paper's
//     path, equal within 10% and under 2 MB;
//   * the largest gamma* over the windows against gamma* of single windows, and errors;
//   * the stationary terminal weight: a short window's Z at its start against the long design's,
//     and Figure 1 with H = 2 s within 2% where the terminal weight Qf is not.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hinf/control/analysis.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/online_receding_horizon.hpp"
#include "hinf/control/sampled_loop.hpp"
#include "hinf/control/receding_horizon.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/scenario/scenario.hpp"

namespace {

using hinf::Mat;
using hinf::Vec;

hinf::Scenario fig1() {
  return hinf::load_scenario_toml(std::string(HINF_SOURCE_DIR) + "/scenarios/paper_fig1.toml").resolved();
}

hinf::RecedingHorizon horizon_of(const hinf::Scenario& s, double window, double update,
                                 hinf::TerminalWeight terminal = hinf::TerminalWeight::Qf, double gamma = 0.0) {
  hinf::RecedingHorizonOptions options;
  options.window = window;
  options.update = update;
  options.terminal = terminal;
  return hinf::RecedingHorizon(s.model, s.desired_q0, s.desired_u, s.t0, s.Q, s.Qf, gamma > 0.0 ? gamma : s.gamma,
                               options, s.solver);
}

TEST(RecedingHorizon, WindowsChainIntoTheDesiredTrajectory) {
  const hinf::Scenario s = fig1();
  const hinf::RecedingHorizon horizon = horizon_of(s, 5.0, 1.0);
  const hinf::Trajectory whole(s.model, s.desired_q0, s.desired_u, s.t0, 12.0);
  hinf::HorizonWindow w = horizon.first();
  double largest = 0.0;
  for (int j = 0; j < 8; ++j, w = horizon.next(w)) {
    EXPECT_EQ(w.index, j);
    EXPECT_DOUBLE_EQ(w.t_start, static_cast<double>(j));
    EXPECT_DOUBLE_EQ(w.trajectory->tf(), j + 5.0);
    for (double t = w.t_start; t <= w.t_start + 5.0; t += 0.25)
      largest = std::max(largest, (w.trajectory->q_d(t) - whole.q_d(t)).cwiseAbs().maxCoeff());
  }
  // Both integrations hold a local error of rtol 1e-10 / atol 1e-12 per step over a path of size
  // ~10 m: their global difference over 12 s stays far below 1e-7 m.
  EXPECT_LT(largest, 1e-7);
}

TEST(RecedingHorizon, WindowZMatchesTheLongDesignFarFromTheEnds) {
  const hinf::Scenario s = fig1();
  const hinf::RecedingHorizon horizon = horizon_of(s, 10.0, 1.0);
  const auto path = std::make_shared<const hinf::Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, 40.0);
  const hinf::HorizonWindow w = horizon.window(3, path->q_d(3.0));
  const auto whole = hinf::solve_grde(path, s.Q, s.Qf, s.gamma, s.solver);
  // At t_j and t_j + 1 the window's terminal weight lies 9-10 s ahead and the long design's 36 s:
  // the GRDE forgets Qf at the rate of its closed loop (|K| recovers within ~4 s of the end,
  // issue #22), so the two designs agree to well under a percent there, and not near the window's
  // end.
  for (double t : {3.0, 4.0}) {
    const double rel = (w.design->Z(t) - whole->Z(t)).norm() / whole->Z(t).norm();
    EXPECT_LT(rel, 1e-3) << "t = " << t;
  }
  const double near_end = (w.design->Z(12.9) - whole->Z(12.9)).norm() / whole->Z(12.9).norm();
  EXPECT_GT(near_end, 1e-2);
}

// RMS position error over the last half of the run (metrics.hpp).
double rms_last_half(const hinf::Scenario& s, const hinf::SimulationResult& run) {
  return hinf::compute_metrics(*s.model, run, s.Q).rms_position_error_last_half;
}

TEST(RecedingHorizon, Figure1WithinTwoPercentOfTheFullHorizon) {
  const hinf::Scenario s = fig1();
  const hinf::RunResult full = hinf::run_scenario(s);
  ASSERT_EQ(full.simulation.status, hinf::RunStatus::Completed);
  const double reference = full.metrics.rms_position_error_last_half;
  for (double window : {5.0, 10.0}) {
    const hinf::RecedingHorizon horizon = horizon_of(s, window, 1.0);
    hinf::RecedingHorizonReport report;
    const hinf::SimulationResult run = hinf::simulate_receding_horizon(
        horizon, hinf::Disturbance(s.disturbance), s.initial_q0, s.tf, s.simulation_options(), nullptr, s.kappa,
        &report);
    ASSERT_EQ(run.status, hinf::RunStatus::Completed);
    EXPECT_EQ(report.windows, 40);
    // One regular output grid: the update period is a multiple of dt.
    ASSERT_EQ(run.t.size(), full.simulation.t.size());
    EXPECT_NEAR(run.t[run.t.size() - 1], 40.0, 1e-12);
    const double rms = rms_last_half(s, run);
    EXPECT_NEAR(rms / reference, 1.0, 0.02) << "H = " << window << ": " << rms << " against " << reference;
  }
}

TEST(RecedingHorizon, StationaryTerminalWeightStandsForTheHorizonBeyond) {
  const hinf::Scenario s = fig1();
  const auto path = std::make_shared<const hinf::Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, 40.0);
  const auto whole = hinf::solve_grde(path, s.Q, s.Qf, s.gamma, s.solver);
  // A 2 s window at t = 10 s, against the 40 s design 30 s from its end. With Qf at its end the
  // window's Z at its start is still the terminal transient (measured 44% off); with the game
  // ARE of the frozen linearization it is within 1% (measured 0.8%: the path turns slowly, at
  // 0.2 rad/s).
  double off[2];
  int i = 0;
  for (hinf::TerminalWeight terminal : {hinf::TerminalWeight::Qf, hinf::TerminalWeight::Stationary}) {
    const hinf::HorizonWindow w = horizon_of(s, 2.0, 1.0, terminal).window(10, path->q_d(10.0));
    off[i++] = (w.design->Z(10.0) - whole->Z(10.0)).norm() / whole->Z(10.0).norm();
  }
  EXPECT_GT(off[0], 0.2);
  EXPECT_LT(off[1], 0.02);

  // Figure 1 with H = 2 s: within 2% of the full-horizon design with the stationary weight
  // (measured -0.1%), not with Qf (measured -10%).
  const double reference = hinf::run_scenario(s).metrics.rms_position_error_last_half;
  double ratio[2];
  i = 0;
  for (hinf::TerminalWeight terminal : {hinf::TerminalWeight::Qf, hinf::TerminalWeight::Stationary}) {
    const hinf::SimulationResult run =
        hinf::simulate_receding_horizon(horizon_of(s, 2.0, 1.0, terminal), hinf::Disturbance(s.disturbance),
                                        s.initial_q0, s.tf, s.simulation_options(), nullptr, s.kappa);
    ASSERT_EQ(run.status, hinf::RunStatus::Completed) << run.status_message;
    ratio[i++] = rms_last_half(s, run) / reference;
  }
  EXPECT_GT(std::abs(ratio[0] - 1.0), 0.05);
  EXPECT_NEAR(ratio[1], 1.0, 0.02);

  // Below the stationary game's gamma* (between 1.0 and 1.2 along this path) there is no
  // terminal weight: the error names the window and the other rule.
  try {
    horizon_of(s, 2.0, 1.0, hinf::TerminalWeight::Stationary, 1.0).first();
    ADD_FAILURE() << "gamma = 1 below the stationary game's gamma* was accepted";
  } catch (const hinf::InputError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("window 0"), std::string::npos) << text;
    EXPECT_NE(text.find("terminal = \"qf\""), std::string::npos) << text;
  }
}

TEST(RecedingHorizon, DesiredStateChainsTheWindows) {
  const hinf::Scenario s = fig1();
  const auto changed = horizon_of(s, 5.0, 1.0).with_path_change(4.0, hinf::VectorSignal(std::vector<hinf::Signal>{
                                                                          hinf::Signal(1.0), hinf::Signal(-0.2)}));
  // Before the change: the one integration of the old inputs; after it: the new inputs from the
  // old path's state at 4 s (integrations at rtol 1e-10 over 10 s: within 1e-7).
  const hinf::Trajectory old_path(s.model, s.desired_q0, s.desired_u, 0.0, 4.0);
  EXPECT_LT((changed->desired_state(2.5) - old_path.q_d(2.5)).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_EQ(changed->desired_state(0.0), s.desired_q0);
  const hinf::Trajectory new_path(s.model, old_path.q_d(4.0), changed->window_inputs(4), 4.0, 10.0);
  EXPECT_LT((changed->desired_state(9.3) - new_path.q_d(9.3)).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_THROW(changed->desired_state(-1.0), hinf::InputError);
}

TEST(RecedingHorizon, MemoryDependsOnTheWindowNotTheMission) {
  hinf::Scenario s = fig1();
  const hinf::RecedingHorizon horizon = horizon_of(s, 10.0, 5.0);
  hinf::SimulationOptions options = s.simulation_options();
  options.output_dt = 1.0;
  options.solver = hinf::SolverOptions();  // the default (automatic) integrator: a long run at its cheapest
  std::size_t peak[2] = {0, 0};
  int i = 0;
  for (double tf : {400.0, 4000.0}) {
    hinf::RecedingHorizonReport report;
    const hinf::SimulationResult run = hinf::simulate_receding_horizon(
        horizon, hinf::Disturbance(s.disturbance), s.initial_q0, tf, options, nullptr, s.kappa, &report);
    ASSERT_EQ(run.status, hinf::RunStatus::Completed) << run.status_message;
    EXPECT_EQ(report.windows, static_cast<int>(tf / 5.0));
    peak[i++] = report.peak_bytes;
  }
  EXPECT_NEAR(static_cast<double>(peak[1]) / static_cast<double>(peak[0]), 1.0, 0.10);
  EXPECT_LT(peak[1], 2u << 20);
  // The full-horizon design of 400 s alone holds more than five times as much.
  const auto whole = std::make_shared<const hinf::Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, 400.0);
  const auto design = hinf::solve_grde(whole, s.Q, s.Qf, s.gamma, s.solver);
  EXPECT_GT(whole->dense().memory_bytes() + design->stats().memory_bytes, 5 * peak[0]);
}

TEST(RecedingHorizon, GammaStarIsTheLargestOverTheWindows) {
  const hinf::Scenario s = fig1();
  const hinf::RecedingHorizon horizon = horizon_of(s, 5.0, 5.0);
  hinf::GammaStarOptions options;
  options.rtol = 1e-6;
  const hinf::WindowGammaStar worst = hinf::receding_horizon_gamma_star(horizon, 20.0, options);
  EXPECT_EQ(worst.windows, 4);
  ASSERT_GE(worst.window, 0);
  EXPECT_TRUE(worst.converged);
  // Each window searched alone (an independent path through gamma_star): none above the largest,
  // the largest's own search equal to it (the same bisection on the same trajectory: exact).
  Vec q_start = s.desired_q0;
  for (int j = 0; j < 4; ++j) {
    const hinf::TrajectoryPtr trajectory = horizon.window_trajectory(j, q_start);
    hinf::GammaStarOptions search = options;
    search.solver = s.solver;
    const double g = hinf::gamma_star(trajectory, s.Q, s.Qf, search).gamma_star;
    EXPECT_LE(g, worst.gamma_star);
    if (j == worst.window) {
      EXPECT_EQ(g, worst.gamma_star);
    }
    q_start = trajectory->q_d(5.0 * (j + 1));
  }
  // A gamma below the largest window's gamma* fails in a window, which the error names.
  const hinf::RecedingHorizon low(s.model, s.desired_q0, s.desired_u, s.t0, s.Q, s.Qf, 0.95 * worst.gamma_star,
                                  horizon.options(), s.solver);
  try {
    hinf::HorizonWindow w = low.first();
    for (int j = 0; j < 4; ++j) w = low.next(w);
    FAIL() << "no window failed below the largest gamma*";
  } catch (const hinf::ConjugatePointError& e) {
    EXPECT_NE(std::string(e.what()).find("receding-horizon window"), std::string::npos) << e.what();
  }
}

TEST(RecedingHorizon, BadOptionsAreNamed) {
  const hinf::Scenario s = fig1();
  auto message = [&](double window, double update) {
    try {
      horizon_of(s, window, update);
    } catch (const hinf::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(0.0, 1.0).find("window"), std::string::npos);
  EXPECT_NE(message(5.0, 6.0).find("update"), std::string::npos);
  EXPECT_NE(message(5.0, NAN).find("update"), std::string::npos);
  const hinf::RecedingHorizon horizon = horizon_of(s, 5.0, 1.0);
  EXPECT_THROW(horizon.window(-1, s.desired_q0), hinf::InputError);
  EXPECT_THROW(horizon.window(0, Vec::Zero(3)), hinf::InputError);
  EXPECT_THROW(horizon.window_at(-1.0), hinf::InputError);
  EXPECT_EQ(horizon.window_at(2.9999999999999), 3);
  EXPECT_EQ(horizon.window_at(2.5), 2);
}

}  // namespace

// ---- the online controller over the receding horizon (online_receding_horizon.hpp) ----

namespace online {

std::shared_ptr<const hinf::RecedingHorizon> shared_horizon(const hinf::Scenario& s, double window, double update,
                                                            double gamma) {
  hinf::RecedingHorizonOptions options;
  options.window = window;
  options.update = update;
  return std::make_shared<const hinf::RecedingHorizon>(s.model, s.desired_q0, s.desired_u, s.t0, s.Q, s.Qf, gamma,
                                                       options, s.solver);
}

hinf::SampledLoopOptions loop_options(const hinf::Scenario& s) {
  hinf::SampledLoopOptions loop;
  loop.simulation = s.simulation_options();
  return loop;
}

TEST(RecedingOnline, Figure1SampledWithinTwoPercentAndIndependentOfTheThread) {
  const hinf::Scenario s = fig1();
  const double T = 0.02;
  const auto trajectory = std::make_shared<const hinf::Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, s.tf);
  const auto design = hinf::solve_grde(trajectory, s.Q, s.Qf, s.gamma, s.solver);
  hinf::OnlineController full(hinf::SampledLaw::emulated(design, T));
  const hinf::SimulationResult reference =
      hinf::simulate_sampled(*trajectory, full, hinf::Disturbance(s.disturbance), s.initial_q0, loop_options(s));
  const double rms_full = rms_last_half(s, reference);
  hinf::SimulationResult runs[2];
  for (int background = 0; background < 2; ++background) {
    hinf::RecedingOnlineController controller(shared_horizon(s, 10.0, 1.0, s.gamma), T, {}, hinf::Signal(1.0),
                                              background == 1);
    runs[background] = hinf::simulate_sampled(*trajectory, controller, hinf::Disturbance(s.disturbance),
                                              s.initial_q0, loop_options(s));
    const hinf::RecedingOnlineStatus status = controller.status();
    // 40 used; the thread may have solved the one after the last before the run ends.
    EXPECT_GE(status.windows_solved, 40);
    EXPECT_LE(status.windows_solved, background == 1 ? 41 : 40);
    EXPECT_EQ(status.windows_failed, 0);
    EXPECT_EQ(status.stale_steps, 0);
    EXPECT_EQ(status.window_in_use, 39);
  }
  // The same windows, handed over at the same samples: the same numbers whichever thread solved
  // them.
  EXPECT_TRUE(runs[0].q == runs[1].q);
  EXPECT_NEAR(rms_last_half(s, runs[0]) / rms_full, 1.0, 0.02);
}

TEST(RecedingOnline, Figure2OutputFeedbackWithinTwoPercent) {
  hinf::Scenario s = hinf::load_scenario_toml(std::string(HINF_SOURCE_DIR) + "/scenarios/paper_fig2_sampled.toml")
                         .resolved();
  const auto trajectory = std::make_shared<const hinf::Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, s.tf);
  const hinf::RowMat noise = hinf::scenario_noise(s);
  const hinf::SamplingSpec& sp = *s.sampling;
  hinf::OnlineOptions options;
  options.filter.N = s.measurement->N;
  options.filter.Sigma0 = (s.measurement->Q0 - s.measurement->eta * Mat::Identity(6, 6)).inverse();
  options.filter.Q = s.Q;
  hinf::SampledLoopOptions loop = loop_options(s);
  loop.sigma = s.measurement->sigma;
  loop.noise = noise;
  const auto design = hinf::solve_grde(trajectory, s.Q, s.Qf, s.gamma, s.solver);
  hinf::OnlineController full(hinf::SampledLaw::emulated(design, sp.period), options);
  const double rms_full = rms_last_half(
      s, hinf::simulate_sampled(*trajectory, full, hinf::Disturbance(s.disturbance), s.initial_q0, loop));
  for (double window : {5.0, 10.0}) {
    hinf::RecedingOnlineController controller(shared_horizon(s, window, 1.0, s.gamma), sp.period, options);
    const hinf::SimulationResult run =
        hinf::simulate_sampled(*trajectory, controller, hinf::Disturbance(s.disturbance), s.initial_q0, loop);
    ASSERT_EQ(run.status, hinf::RunStatus::Completed) << run.status_message;
    EXPECT_EQ(controller.controller().counts().lost, 0);
    // The filter's Sigma runs on across the windows (it is the estimator's, not the design's).
    EXPECT_NEAR(rms_last_half(s, run) / rms_full, 1.0, 0.02) << "H = " << window;
  }
}

TEST(RecedingOnline, AFailedWindowKeepsTheLastGoodOneAndSaysSo) {
  hinf::Scenario s = fig1();
  // A turn to starboard after 20 s: its window needs a larger gamma than the ones before it (each
  // window has a gamma* of its own, searched here; the test needs the largest after the first).
  s.desired_u = hinf::VectorSignal(std::vector<hinf::Signal>{
      hinf::Signal(1.0), hinf::Signal::table({0.0, 20.0, 25.0, 60.0}, {0.3, 0.3, -0.5, -0.5}, hinf::Interpolation::Linear)});
  const auto probe = shared_horizon(s, 10.0, 5.0, s.gamma);
  std::vector<double> stars;
  Vec q_start = s.desired_q0;
  for (int j = 0; j < 6; ++j) {
    const hinf::TrajectoryPtr trajectory = probe->window_trajectory(j, q_start);
    hinf::GammaStarOptions search;
    search.solver = s.solver;
    search.rtol = 1e-5;
    stars.push_back(hinf::gamma_star(trajectory, s.Q, s.Qf, search).gamma_star);
    q_start = trajectory->q_d(5.0 * (j + 1));
  }
  int worst = 0;
  for (int j = 1; j < 6; ++j)
    if (stars[static_cast<std::size_t>(j)] > stars[static_cast<std::size_t>(worst)]) worst = j;
  ASSERT_GT(worst, 0) << "the first window has the largest gamma*: no later window can fail alone";
  double below = 0.0;  // the largest gamma* of the windows before the worst
  for (int j = 0; j < worst; ++j) below = std::max(below, stars[static_cast<std::size_t>(j)]);
  // Apart by far more than the bisections' tolerance (1e-5 relative).
  ASSERT_GT(stars[static_cast<std::size_t>(worst)] - below, 1e-3);
  const double gamma = 0.5 * (below + stars[static_cast<std::size_t>(worst)]);
  // Without the thread, so that no window after the run's end is tried (its failure would be the
  // last one reported).
  hinf::RecedingOnlineController controller(shared_horizon(s, 10.0, 5.0, gamma), 0.05, {}, hinf::Signal(1.0), false);
  controller.reset(0.0, s.initial_q0);
  const double t_fail = 5.0 * worst;
  Vec u(2);
  bool stale_seen = false;
  for (int k = 0; 0.05 * k < t_fail + 5.0 - 1e-9; ++k) {
    const double t = 0.05 * k;
    controller.synchronize(t);
    const hinf::StepReport report = controller.step(t, nullptr, t, u.data());
    ASSERT_EQ(report.status, hinf::StepStatus::Ok) << "t = " << t;
    EXPECT_EQ(report.window_stale, t >= t_fail - 1e-9) << "t = " << t;
    stale_seen = stale_seen || report.window_stale;
  }
  EXPECT_TRUE(stale_seen);
  const hinf::RecedingOnlineStatus status = controller.status();
  EXPECT_GE(status.windows_failed, 1);
  EXPECT_DOUBLE_EQ(status.failed_t_start, t_fail);
  EXPECT_EQ(status.window_in_use, worst - 1);  // the last good window serves to its end
  EXPECT_NE(status.last_failure.find("receding-horizon window"), std::string::npos) << status.last_failure;
}

TEST(RecedingOnline, ErrorsAreNamed) {
  const hinf::Scenario s = fig1();
  EXPECT_THROW(hinf::RecedingOnlineController(nullptr, 0.05), hinf::InputError);
  EXPECT_THROW(hinf::RecedingOnlineController(shared_horizon(s, 10.0, 1.0, s.gamma), 0.3), hinf::InputError);
  EXPECT_THROW(hinf::RecedingOnlineController(shared_horizon(s, 10.0, 1.0, s.gamma), -1.0), hinf::InputError);
  hinf::RecedingOnlineController controller(shared_horizon(s, 10.0, 1.0, s.gamma), 0.05);
  EXPECT_THROW(controller.synchronize(0.0), hinf::InputError);  // before reset
  EXPECT_THROW(controller.reset(0.0, Vec::Zero(3)), hinf::InputError);
}

}  // namespace online

// ---- a path changed under way ----

namespace path_change {

hinf::VectorSignal turn(double rate) {
  return hinf::VectorSignal(std::vector<hinf::Signal>{hinf::Signal(1.0), hinf::Signal(rate)});
}

TEST(PathChange, TheVehicleJoinsTheNewPath) {
  const hinf::Scenario s = fig1();
  const hinf::RecedingHorizon horizon = horizon_of(s, 10.0, 1.0);
  const auto changed = horizon.with_path_change(20.0, turn(-0.2));
  hinf::RecedingHorizonReport report;
  const hinf::SimulationResult run = hinf::simulate_receding_horizon(
      *changed, hinf::Disturbance(s.disturbance), s.initial_q0, s.tf, s.simulation_options(), nullptr, s.kappa,
      &report);
  ASSERT_EQ(run.status, hinf::RunStatus::Completed) << run.status_message;
  // The new path: from q_d(20) of the old one, turning at -0.2 rad/s (an independent integration
  // from the state the old path has at 20 s).
  const hinf::Trajectory old_path(s.model, s.desired_q0, s.desired_u, 0.0, 20.0);
  const hinf::Trajectory new_path(s.model, old_path.q_d(20.0), turn(-0.2), 20.0, 40.0);
  const Eigen::Index last = run.t.size() - 1;
  // q_d of the run is the new path (two integrations at rtol 1e-10 over 40 s)...
  EXPECT_LT((run.q_d.row(last).transpose() - new_path.q_d(40.0)).cwiseAbs().maxCoeff(), 1e-6);
  // ... more than a metre away from the old one ...
  const hinf::Trajectory unchanged(s.model, s.desired_q0, s.desired_u, 0.0, 40.0);
  EXPECT_GT((new_path.q_d(40.0) - unchanged.q_d(40.0)).head(5).tail(2).norm(), 1.0);
  // ... and the vehicle is on it: the paper's run ends within 0.04 m of its path; a join 20 s
  // before the end leaves it as close (the disturbance, not the join, sets the final error).
  const double final_error = run.q_e().row(last).segment(3, 2).norm();
  EXPECT_LT(final_error, 0.1);
}

TEST(PathChange, WindowsUseTheInputsOfTheirStart) {
  const hinf::Scenario s = fig1();
  const hinf::RecedingHorizon horizon = horizon_of(s, 10.0, 1.0);
  const auto changed = horizon.with_path_change(20.0, turn(-0.2))->with_path_change(30.0, turn(0.1));
  EXPECT_TRUE(changed->window_inputs(19).same_signals(s.desired_u));
  EXPECT_TRUE(changed->window_inputs(20).same_signals(turn(-0.2)));
  EXPECT_TRUE(changed->window_inputs(29).same_signals(turn(-0.2)));
  EXPECT_TRUE(changed->window_inputs(35).same_signals(turn(0.1)));
  EXPECT_TRUE(horizon.path_changes().empty());  // the horizon changed is a copy
  EXPECT_THROW(horizon.with_path_change(20.5, turn(0.0)), hinf::InputError);   // not a window start
  EXPECT_THROW(horizon.with_path_change(0.0, turn(0.0)), hinf::InputError);    // at t0
  EXPECT_THROW(changed->with_path_change(25.0, turn(0.0)), hinf::InputError);  // before the last change
  EXPECT_THROW(horizon.with_path_change(25.0, hinf::VectorSignal::zeros(3)), hinf::InputError);
}

TEST(PathChange, OnlineControllerTakesItAheadOfTheWindow) {
  const hinf::Scenario s = fig1();
  hinf::RecedingOnlineController controller(online::shared_horizon(s, 10.0, 1.0, s.gamma), 0.05);
  controller.reset(0.0, s.initial_q0);
  Vec u(2), q = s.initial_q0;
  for (int k = 0; k <= 300; ++k) {  // to 15 s
    controller.synchronize(0.05 * k);
    controller.step(0.05 * k, q.data(), 0.05 * k, u.data());
  }
  // Window 16 solved (synchronize waits for it) and offered: too late to change it.
  controller.synchronize(16.0);
  EXPECT_THROW(controller.change_path(16.0, turn(-0.2)), hinf::InputError);
  controller.change_path(20.0, turn(-0.2));
  for (int k = 301; k <= 420; ++k) {  // to 21 s
    controller.synchronize(0.05 * k);
    controller.step(0.05 * k, q.data(), 0.05 * k, u.data());
  }
  EXPECT_EQ(controller.status().window_in_use, 21);
  EXPECT_TRUE(controller.controller().law().trajectory().u_d_signal().same_signals(turn(-0.2)));
}

}  // namespace path_change
