// run_scenarios (study.hpp): every row is run_scenario's result for that scenario alone, exactly
// (the same code on the same input), with one or two threads and with or without shared
// designs, for state and output feedback and the three laws; runs that share design inputs
// share one design and the others do not; failures of every kind are rows while the other runs
// complete; progress is called on the calling thread, ends with done == total, and an
// exception it throws stops the study.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "hinf/control/metrics.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/interrupt.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"
#include "hinf/scenario/scenario.hpp"
#include "hinf/scenario/study.hpp"

namespace {

using hinf::Law;
using hinf::Mat;
using hinf::RunOutcome;
using hinf::Scenario;
using hinf::StudyOptions;
using hinf::StudyRun;

const std::string kSourceDir = HINF_SOURCE_DIR;

// The shipped Figure 1 (state feedback) or Figure 2 (output feedback) scenario on a shorter
// horizon, to keep the tests fast.
Scenario paper(int figure, double tf = 8.0) {
  Scenario s = hinf::load_scenario_toml(kSourceDir + "/scenarios/paper_fig" + std::to_string(figure) + ".toml");
  s.tf = tf;
  return s;
}

Scenario with_law(Scenario s, Law law) {
  s.law = law;
  return s;
}

// Bitwise equality of every metric (NaN equals NaN).
void expect_same_metrics(const hinf::Metrics& a, const hinf::Metrics& b, const std::string& where) {
  for (const hinf::MetricDefinition& d : hinf::metric_table()) {
    const double x = a.*(d.value), y = b.*(d.value);
    EXPECT_EQ(std::memcmp(&x, &y, sizeof x), 0) << where << ": " << d.name << " " << x << " != " << y;
  }
}

bool all_nan(const hinf::Metrics& m) {
  for (const hinf::MetricDefinition& d : hinf::metric_table())
    if (!std::isnan(m.*(d.value))) return false;
  return true;
}

// Figure 1 and 2 with each law, and variants that share their designs (another initial state,
// another seed, another disturbance) or not (another gamma).
std::vector<Scenario> mixed_batch() {
  std::vector<Scenario> runs;
  for (int figure : {1, 2})
    for (Law law : {Law::Hinf, Law::Lqr, Law::Cascade}) runs.push_back(with_law(paper(figure), law));
  Scenario moved = paper(1);
  moved.initial_q0[3] = -2.0;
  runs.push_back(moved);
  Scenario reseeded = paper(2);
  reseeded.measurement->seed = 7;
  runs.push_back(reseeded);
  Scenario calm = paper(1);
  calm.disturbance = hinf::VectorSignal::zeros(6);
  calm.kappa = hinf::Signal(2.0);
  runs.push_back(calm);
  Scenario other_gamma = paper(1);
  other_gamma.gamma = 8.0;
  runs.push_back(other_gamma);
  Scenario lqr_other_gamma = with_law(paper(1), Law::Lqr);
  lqr_other_gamma.gamma = 3.0;  // the lqr design is at inf whatever gamma says
  runs.push_back(lqr_other_gamma);
  return runs;
}

// Ctrl-C stops a batch: Interrupted from the call, not rows of failed runs.
TEST(Study, AnInterruptStopsTheBatchInsteadOfFailingItsRuns) {
  const std::vector<Scenario> scenarios(4, paper(1));
  for (int threads : {1, 2}) {
    hinf::StudyOptions options;
    options.threads = threads;
    hinf::request_interrupt();
    EXPECT_THROW(hinf::run_scenarios(scenarios, options), hinf::Interrupted) << threads;
    hinf::clear_interrupt();
  }
  EXPECT_EQ(hinf::run_scenarios(scenarios).size(), 4u);
}

TEST(Study, RowsAreRunScenarioExactlyForAnyThreadsAndSharing) {
  const std::vector<Scenario> runs = mixed_batch();
  std::vector<hinf::RunResult> alone;
  for (const Scenario& s : runs) alone.push_back(hinf::run_scenario(s));
  for (int threads : {1, 2}) {
    for (bool share : {true, false}) {
      StudyOptions options;
      options.threads = threads;
      options.share_designs = share;
      const std::vector<StudyRun> rows = hinf::run_scenarios(runs, options);
      ASSERT_EQ(rows.size(), runs.size());
      for (std::size_t i = 0; i < runs.size(); ++i) {
        const std::string where = hinf::str_cat("run ", i, " threads ", threads, " share ", share);
        EXPECT_EQ(rows[i].status, RunOutcome::Completed) << where << ": " << rows[i].reason;
        EXPECT_TRUE(rows[i].reason.empty()) << where;
        EXPECT_EQ(rows[i].law, alone[i].law) << where;
        EXPECT_EQ(rows[i].output_feedback, alone[i].output_feedback) << where;
        EXPECT_EQ(rows[i].gamma, alone[i].gamma) << where;
        EXPECT_GT(rows[i].design_seconds, 0.0) << where;
        EXPECT_GT(rows[i].simulate_seconds, 0.0) << where;
        expect_same_metrics(rows[i].metrics, alone[i].metrics, where);
      }
    }
  }
}

TEST(Study, RunsWithEqualDesignInputsShareOneDesign) {
  const std::vector<Scenario> runs = mixed_batch();
  const std::vector<StudyRun> rows = hinf::run_scenarios(runs);
  // 0-2: Figure 1 hinf, lqr, cascade; 3-5: Figure 2 hinf, lqr, cascade; 6: Figure 1 from
  // another start; 7: Figure 2 with another seed; 8: Figure 1 without disturbance, kappa 2;
  // 9: Figure 1 at gamma 8; 10: Figure 1 lqr at "gamma" 3.
  const auto design = [&](std::size_t i) { return rows[i].design; };
  // The same model, horizon, desired trajectory, Q, Qf and solver in both figures: hinf and
  // cascade share the design at gamma = 5 and the lqr runs the one at inf.
  for (std::size_t i : {2, 3, 5, 6, 7, 8}) EXPECT_EQ(design(i), design(0)) << i;
  for (std::size_t i : {4, 10}) EXPECT_EQ(design(i), design(1)) << i;
  EXPECT_NE(design(1), design(0));
  EXPECT_NE(design(9), design(0));
  EXPECT_NE(design(9), design(1));
  for (const StudyRun& row : rows) EXPECT_GE(row.design, 0);
  // A shared design is timed once and reported in each of its runs.
  EXPECT_EQ(rows[6].design_seconds, rows[0].design_seconds);

  StudyOptions apart;
  apart.share_designs = false;
  const std::vector<StudyRun> own = hinf::run_scenarios(runs, apart);
  for (std::size_t i = 0; i < own.size(); ++i) EXPECT_EQ(own[i].design, static_cast<int>(i));
}

// The design inputs are compared as values, whatever the file form: a model without one (a
// model of the program's own, like one implemented in Python) shares its design with the runs
// of the same object and with no other; built-in models by their parameters; desired inputs by
// their definitions, a function of t with nothing.
class OwnShip final : public hinf::Model {
 public:
  std::string name() const override { return "own ship"; }
  int n() const override { return ship_.n(); }
  int m() const override { return ship_.m(); }
  int nw() const override { return ship_.nw(); }
  void f(double t, const hinf::ConstVecRef& q, hinf::VecRef out) const override { ship_.f(t, q, out); }
  void dfdq(double t, const hinf::ConstVecRef& q, hinf::MatRef out) const override { ship_.dfdq(t, q, out); }
  Mat G(double t, const hinf::ConstVecRef& q) const override { return ship_.G(t, q); }
  Mat D(double t, const hinf::ConstVecRef& q) const override { return ship_.D(t, q); }

 private:
  hinf::ShipModel ship_;
};

TEST(Study, DesignInputsAreComparedAsValues) {
  const auto own = std::make_shared<const OwnShip>();
  const auto with_model = [](hinf::ModelPtr model) {
    Scenario s = paper(1);
    s.model = std::move(model);
    return s;
  };
  hinf::ShipParameters heavier;
  heavier.d_u = 1.5;
  Scenario by_function = paper(1);
  by_function.desired_u = hinf::VectorSignal(2, [](double t) {
    hinf::Vec u(2);
    u << 1.0, 0.3 * std::sin(0.2 * t);
    return u;
  });
  Scenario moved = with_model(own);
  moved.initial_q0[3] = -2.0;
  const std::vector<Scenario> runs = {
      with_model(own), moved, with_model(std::make_shared<const OwnShip>()),  // 0-2: own models
      paper(1), with_model(std::make_shared<const hinf::ShipModel>()),         // 3-4: equal ships
      with_model(std::make_shared<const hinf::ShipModel>(heavier)),            // 5: another d_u
      by_function, by_function};                                              // 6-7: u_d a function
  const std::vector<StudyRun> rows = hinf::run_scenarios(runs);
  for (const StudyRun& row : rows) EXPECT_EQ(row.status, RunOutcome::Completed) << row.reason;
  EXPECT_EQ(rows[1].design, rows[0].design);
  EXPECT_NE(rows[2].design, rows[0].design);
  EXPECT_EQ(rows[4].design, rows[3].design);
  EXPECT_NE(rows[3].design, rows[0].design);
  EXPECT_NE(rows[5].design, rows[3].design);
  EXPECT_NE(rows[6].design, rows[3].design);
  EXPECT_NE(rows[7].design, rows[6].design);
}

TEST(Study, FailuresAreRowsAndTheOtherRunsComplete) {
  std::vector<Scenario> runs;
  runs.push_back(paper(1));                 // 0: completes
  Scenario below = paper(1);                // 1: gamma below gamma* (1.335): conjugate point
  below.gamma = 1.0;
  runs.push_back(below);
  // 2: the cascade law with state feedback needs no design: it runs without one, next to 1
  // whose design it shares.
  runs.push_back(with_law(below, Law::Cascade));
  Scenario coupled = paper(2);              // 3: Sigma(t0) = I and gamma = 2.5: rho(Sigma Z) >= gamma^2
  coupled.gamma = 2.5;
  runs.push_back(coupled);
  Scenario invalid = paper(1);              // 4: gamma < 0
  invalid.gamma = -1.0;
  runs.push_back(invalid);
  Scenario storm = paper(1);                // 5: a disturbance of 1e6 drives it past the bound
  storm.disturbance = hinf::VectorSignal({hinf::Signal(1e6), hinf::Signal(), hinf::Signal(), hinf::Signal(),
                                          hinf::Signal(), hinf::Signal()});
  runs.push_back(storm);
  runs.push_back(paper(2));                 // 6: completes
  Scenario solver = paper(1);               // 7: too few steps for the closed loop
  solver.solver.max_steps = 3;
  runs.push_back(solver);

  for (int threads : {1, 2}) {
    StudyOptions options;
    options.threads = threads;
    const std::vector<StudyRun> rows = hinf::run_scenarios(runs, options);
    const std::string where = hinf::str_cat("threads ", threads);
    ASSERT_EQ(rows.size(), runs.size());
    EXPECT_EQ(rows[0].status, RunOutcome::Completed) << where;
    expect_same_metrics(rows[0].metrics, hinf::run_scenario(runs[0]).metrics, where);
    EXPECT_EQ(rows[6].status, RunOutcome::Completed) << where;
    expect_same_metrics(rows[6].metrics, hinf::run_scenario(runs[6]).metrics, where);

    EXPECT_EQ(rows[1].status, RunOutcome::ConjugatePoint) << where << ": " << rows[1].reason;
    EXPECT_THROW(hinf::run_scenario(runs[1]), hinf::ConjugatePointError);
    EXPECT_TRUE(all_nan(rows[1].metrics)) << where;

    EXPECT_EQ(rows[2].status, RunOutcome::Completed) << where << ": " << rows[2].reason;
    EXPECT_EQ(rows[2].design, rows[1].design) << where;
    expect_same_metrics(rows[2].metrics, hinf::run_scenario(runs[2]).metrics, where);

    EXPECT_EQ(rows[3].status, RunOutcome::CouplingViolation) << where << ": " << rows[3].reason;
    EXPECT_NE(rows[3].reason.find("coupling condition violated"), std::string::npos) << rows[3].reason;
    EXPECT_TRUE(all_nan(rows[3].metrics)) << where;

    EXPECT_EQ(rows[4].status, RunOutcome::InvalidInput) << where;
    EXPECT_NE(rows[4].reason.find("gamma must be > 0"), std::string::npos) << rows[4].reason;
    EXPECT_EQ(rows[4].design, -1) << where;
    EXPECT_EQ(rows[4].gamma, -1.0) << where;
    EXPECT_TRUE(all_nan(rows[4].metrics)) << where;

    EXPECT_EQ(rows[5].status, RunOutcome::Diverged) << where;
    EXPECT_NE(rows[5].reason.find("divergence bound"), std::string::npos) << rows[5].reason;
    EXPECT_EQ(rows[5].design, rows[0].design) << where;
    const hinf::RunResult storm_alone = hinf::run_scenario(runs[5]);
    EXPECT_EQ(rows[5].reason, storm_alone.simulation.status_message);
    expect_same_metrics(rows[5].metrics, storm_alone.metrics, where);
    EXPECT_TRUE(std::isfinite(rows[5].metrics.max_position_error)) << where;

    EXPECT_EQ(rows[7].status, RunOutcome::SolverFailure) << where << ": " << rows[7].reason;
    EXPECT_FALSE(rows[7].reason.empty());
  }
}

TEST(Study, ProgressIsCalledOnTheCallingThreadAndEndsWithTheTotal) {
  std::vector<Scenario> runs(6, paper(1, 4.0));
  for (std::size_t i = 0; i < runs.size(); ++i) runs[i].initial_q0[4] = -1.0 - 0.1 * static_cast<double>(i);
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  bool elsewhere = false;
  StudyOptions options;
  options.threads = 2;
  hinf::run_scenarios(runs, options, [&](std::size_t done, std::size_t total) {
    elsewhere = elsewhere || std::this_thread::get_id() != caller;
    calls.emplace_back(done, total);
  });
  EXPECT_FALSE(elsewhere);
  ASSERT_FALSE(calls.empty());
  EXPECT_EQ(calls.back(), std::make_pair(runs.size(), runs.size()));
  for (std::size_t k = 1; k < calls.size(); ++k) EXPECT_GT(calls[k].first, calls[k - 1].first);

  // An empty study: one call, (0, 0).
  calls.clear();
  EXPECT_TRUE(hinf::run_scenarios({}, options, [&](std::size_t d, std::size_t t) { calls.emplace_back(d, t); }).empty());
  EXPECT_EQ(calls, (std::vector<std::pair<std::size_t, std::size_t>>{{0, 0}}));
}

// The paper's ship, recording the y of every state at which f is called at t = 0: a closed
// loop starting at y = y0 calls f(0, q0) first, so the distinct nonzero y recorded are the runs
// that started (the desired trajectory starts at y = 0). It has no scenario-file form, so every
// run makes its own design.
class StartRecordingShip final : public hinf::Model {
 public:
  std::string name() const override { return "start-recording ship"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  void f(double t, const hinf::ConstVecRef& q, hinf::VecRef out) const override {
    if (t == 0.0 && q[4] != 0.0) {
      std::lock_guard<std::mutex> lock(mutex_);
      starts_.insert(q[4]);
    }
    ship_.f(t, q, out);
  }
  void dfdq(double t, const hinf::ConstVecRef& q, hinf::MatRef out) const override { ship_.dfdq(t, q, out); }
  Mat G(double t, const hinf::ConstVecRef& q) const override { return ship_.G(t, q); }
  Mat D(double t, const hinf::ConstVecRef& q) const override { return ship_.D(t, q); }
  void error_split(double t, const hinf::ConstVecRef& q_d, const hinf::ConstVecRef& u_d, const hinf::ConstVecRef& q_e,
                   hinf::MatRef A, hinf::VecRef alpha) const override {
    ship_.error_split(t, q_d, u_d, q_e, A, alpha);
  }
  Mat C(double t) const override { return ship_.C(t); }
  std::vector<int> noise_channels() const override { return ship_.noise_channels(); }
  std::vector<int> position_indices() const override { return ship_.position_indices(); }
  int heading_index() const override { return ship_.heading_index(); }
  std::size_t started() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return starts_.size();
  }

 private:
  hinf::ShipModel ship_;
  mutable std::mutex mutex_;
  mutable std::set<double> starts_;
};

TEST(Study, AnExceptionFromProgressStopsTheStudy) {
  // 80 output-feedback runs of the whole horizon (some 50 ms each) on two threads. progress
  // throws at its first call after a run has finished: the workers finish the runs they are in
  // and take no other, so far fewer runs than 80 ever start.
  const auto model = std::make_shared<const StartRecordingShip>();
  std::vector<Scenario> runs(80, paper(2, 40.0));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    runs[i].model = model;
    runs[i].initial_q0[4] = -1.0 - 0.001 * static_cast<double>(i);
  }
  StudyOptions options;
  options.threads = 2;
  std::size_t done_at_throw = 0;
  EXPECT_THROW(hinf::run_scenarios(runs, options,
                               [&](std::size_t done, std::size_t) {
                                 if (done == 0) return;
                                 done_at_throw = done;
                                 throw std::runtime_error("interrupted");
                               }),
               std::runtime_error);
  std::printf("[study] progress threw at done = %zu; %zu of %zu runs started\n", done_at_throw, model->started(),
              runs.size());
  EXPECT_GE(done_at_throw, 1u);
  EXPECT_LT(model->started(), runs.size() / 2);
}

TEST(Study, OptionsAreChecked) {
  StudyOptions options;
  options.threads = -1;
  EXPECT_THROW(hinf::run_scenarios({paper(1)}, options), hinf::InputError);
  // More threads than runs: as many as runs.
  options.threads = 64;
  const std::vector<StudyRun> rows = hinf::run_scenarios({paper(1, 2.0)}, options);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].status, RunOutcome::Completed);
}

TEST(Study, OutcomeNames) {
  EXPECT_EQ(hinf::to_string(RunOutcome::SolverFailure), "solver_failure");
  EXPECT_EQ(hinf::to_string(RunOutcome::ConjugatePoint), "conjugate_point");
  EXPECT_EQ(hinf::from_string<RunOutcome>("coupling_violation"), RunOutcome::CouplingViolation);
  EXPECT_THROW(hinf::from_string<RunOutcome>("ok"), hinf::InputError);
}

}  // namespace
