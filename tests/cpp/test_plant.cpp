// A plant that differs from the design model ([plant], Scenario::plant): a plant equal to the
// model gives the very numbers of a run without one (state and output feedback; constant and
// state-dependent input matrices); a ship with 30% more damping changes the closed loop and is
// still tracked; from a zero initial error without disturbance the loop leaves the trajectory
// only through the model error, to first order in it (half the error, half the deviation), and
// not at all with the model itself; [plant] in scenario files (defaults from [model], another
// kind of the same structure, the round trip, errors naming [plant]); the results file; runs of
// a study with other plants share one design.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hinf/control/trajectory.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/io/results.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/models/vehicles.hpp"
#include "hinf/scenario/scenario.hpp"
#include "hinf/scenario/study.hpp"

namespace {

using hinf::Mat;
using hinf::RowMat;
using hinf::Scenario;
using hinf::ShipParameters;
using hinf::Vec;

const std::string kSourceDir = HINF_SOURCE_DIR;

std::string read_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  std::string text;
  char chunk[4096];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0) text.append(chunk, got);
  std::fclose(file);
  return text;
}

std::string shipped(const std::string& stem) { return read_file(kSourceDir + "/scenarios/" + stem + ".toml"); }

Scenario parse(const std::string& text, double tf) {
  Scenario s = hinf::parse_scenario_toml(text, "test.toml");
  s.tf = tf;
  return s;
}

// The paper's ship with its damping scaled by `factor`.
hinf::ModelPtr damped_ship(double factor) {
  ShipParameters p;
  p.d_u *= factor;
  p.d_v *= factor;
  p.d_r *= factor;
  return std::make_shared<hinf::ShipModel>(p);
}

double max_abs(const RowMat& M) { return M.size() == 0 ? 0.0 : M.cwiseAbs().maxCoeff(); }

TEST(Plant, APlantEqualToTheModelGivesTheSameNumbers) {
  // [plant] written out with the model's own values: another object, the same numbers.
  for (const std::string stem : {"paper_fig1", "paper_fig2", "hovercraft_s_curve", "fossen_vessel_turn"}) {
    const std::string text = shipped(stem);
    const Scenario alone = parse(text, 6.0);
    Scenario with_plant = parse(text + "\n[plant]\n", 6.0);
    ASSERT_NE(with_plant.plant, nullptr) << stem;
    EXPECT_NE(with_plant.plant.get(), with_plant.model.get()) << stem;
    EXPECT_EQ(with_plant.plant->named_parameters(), with_plant.model->named_parameters()) << stem;
    const hinf::RunResult a = hinf::run_scenario(alone), b = hinf::run_scenario(with_plant);
    EXPECT_EQ(a.simulation.q, b.simulation.q) << stem;
    EXPECT_EQ(a.simulation.u, b.simulation.u) << stem;
    if (a.simulation.estimator) {
      EXPECT_EQ(a.simulation.estimator->q_hat, b.simulation.estimator->q_hat) << stem;
    }
    EXPECT_EQ(a.metrics.rms_position_error_last_half, b.metrics.rms_position_error_last_half) << stem;
    EXPECT_EQ(b.plant, with_plant.plant);
    EXPECT_EQ(a.plant, nullptr);
  }
}

// The largest position error |p - p_d| over the output times in [a, b].
double max_position_error(const hinf::SimulationResult& r, double a, double b) {
  const RowMat e = r.q_e();
  double largest = 0.0;
  for (Eigen::Index k = 0; k < r.t.size(); ++k)
    if (r.t[k] >= a && r.t[k] <= b) largest = std::max(largest, std::hypot(e(k, 3), e(k, 4)));
  return largest;
}

TEST(Plant, ThirtyPercentMoreDampingChangesTheLoopAndIsStillTracked) {
  // The ship with 30% more damping driven by u_d alone (open loop) falls behind q_d steadily:
  // its surge speed settles at 1/1.3 of the desired one. Under the H-infinity law designed on
  // the nominal ship, state or output feedback, the position error instead settles at a bounded
  // offset, far below that drift, and does not grow.
  for (const std::string stem : {"paper_fig1", "paper_fig2"}) {
    Scenario s = parse(shipped(stem), 40.0);
    const hinf::RunResult nominal = hinf::run_scenario(s);
    s.plant = damped_ship(1.3);
    const hinf::RunResult damped = hinf::run_scenario(s);
    ASSERT_EQ(damped.simulation.status, hinf::RunStatus::Completed) << stem;
    const double change = max_abs(damped.simulation.q - nominal.simulation.q);
    const hinf::Trajectory open_loop(s.plant, s.desired_q0, s.desired_u, s.t0, s.tf);
    const Vec drift = open_loop.q_d(s.tf) - nominal.trajectory->q_d(s.tf);
    const double open_loop_error = std::hypot(drift[3], drift[4]);
    const double middle = max_position_error(damped.simulation, 15.0, 25.0);
    const double last = max_position_error(damped.simulation, 30.0, 40.0);
    std::printf("[plant] %s: 30%% more damping moves the states by up to %.4g; position error, final %.4g m "
                "(nominal %.4g m, open loop %.4g m), largest over [15, 25] %.4g m, over [30, 40] %.4g m\n",
                stem.c_str(), change, damped.metrics.final_position_error, nominal.metrics.final_position_error,
                open_loop_error, middle, last);
    EXPECT_GT(change, 1e-2) << stem;
    EXPECT_LT(damped.metrics.final_position_error, 0.15 * open_loop_error) << stem;
    EXPECT_LT(last, 1.2 * middle) << stem;
  }
}

TEST(Plant, FromZeroErrorTheLoopLeavesTheTrajectoryOnlyByTheModelError) {
  // q(t0) = q_d(t0) and no disturbance: with the design model the closed loop stays on q_d (up
  // to the integration error); with another plant q_d is not a solution of the plant and the
  // deviation is driven by the model error, to first order linearly in it.
  Scenario s = parse(shipped("paper_fig1"), 40.0);
  s.initial_q0 = s.desired_q0;
  s.disturbance = hinf::VectorSignal::zeros(6);
  const auto deviation = [&](double factor) {
    Scenario run = s;
    run.plant = damped_ship(factor);
    const hinf::RunResult r = hinf::run_scenario(run);
    EXPECT_EQ(r.simulation.status, hinf::RunStatus::Completed);
    return max_abs(r.simulation.q_e());
  };
  const double same = deviation(1.0), e15 = deviation(1.15), e30 = deviation(1.3);
  std::printf("[plant] deviation from q_d: plant = model %.3g, 15%% more damping %.4g, 30%% %.4g (ratio %.4f)\n",
              same, e15, e30, e30 / e15);
  // The closed loop is integrated at rtol 1e-8, atol 1e-10 with states up to |x| ~ 35 m.
  EXPECT_LT(same, 1e-6);
  EXPECT_GT(e15, 1e-3);
  // First order in the model error: twice the error, about twice the deviation (the second-order
  // part is some percent at 30%).
  EXPECT_NEAR(e30 / e15, 2.0, 0.15);
}

TEST(Plant, TheMeasurementIsThePlants) {
  // An LTI system measured through y = C q + sigma v; the plant's sensor has 1.5 times the gain
  // the design model assumes. The estimator works with the design's C, the measurement comes
  // from the plant: y(t_k) = 1.5 q_1(t_k) + sigma v_k on the output grid (T = dt, so sample k).
  const std::string lti = R"(
[model]
kind = "linear"
A = [[0.0, 1.0], [-1.0, -0.5]]
B = [[0.0], [1.0]]
D = [[0.0], [1.0]]
C = [[1.0, 0.0]]
[horizon]
tf = 5.0
[desired]
q0 = [0.0, 0.0]
u1 = 0.0
[controller]
gamma = 5.0
[initial]
q0 = [0.5, 0.0]
[measurement]
sigma = 0.1
seed = 3
)";
  const Scenario alone = hinf::parse_scenario_toml(lti, "lti.toml");
  const hinf::RunResult nominal = hinf::run_scenario(alone);
  const hinf::RunResult same = hinf::run_scenario(hinf::parse_scenario_toml(lti + "[plant]\n", "lti.toml"));
  EXPECT_EQ(same.simulation.q, nominal.simulation.q);
  EXPECT_EQ(same.simulation.estimator->y, nominal.simulation.estimator->y);
  const Scenario biased = hinf::parse_scenario_toml(lti + "[plant]\nC = [[1.5, 0.0]]\n", "lti.toml");
  const hinf::RunResult r = hinf::run_scenario(biased);
  ASSERT_EQ(r.simulation.status, hinf::RunStatus::Completed);
  EXPECT_GT(max_abs(r.simulation.q - nominal.simulation.q), 1e-3);
  const RowMat noise = hinf::scenario_noise(biased);
  const RowMat& y = r.simulation.estimator->y;
  ASSERT_EQ(y.rows(), r.simulation.q.rows());
  for (Eigen::Index k = 0; k < y.rows(); ++k)
    EXPECT_NEAR(y(k, 0), 1.5 * r.simulation.q(k, 0) + 0.1 * noise(std::min<Eigen::Index>(k, noise.rows() - 1), 0),
                1e-14)
        << k;
}

TEST(Plant, ScenarioFilesReadAndWriteIt) {
  const std::string fig1 = shipped("paper_fig1");
  // Only what differs: the rest is [model]'s.
  const Scenario s = hinf::parse_scenario_toml(fig1 + "\n[plant]\nd_u = 1.3\nd_r = 1.5\n", "a.toml");
  const auto* plant = dynamic_cast<const hinf::ShipModel*>(s.plant.get());
  ASSERT_NE(plant, nullptr);
  EXPECT_EQ(plant->parameters().d_u, 1.3);
  EXPECT_EQ(plant->parameters().d_r, 1.5);
  EXPECT_EQ(plant->parameters().d_v, 2.0);
  EXPECT_EQ(plant->parameters().m_v, -2.0);
  // Round trip: the plant written out in full, read back equal, written again the same.
  const std::string written = hinf::scenario_toml(s);
  EXPECT_NE(written.find("[plant]"), std::string::npos);
  const Scenario again = hinf::parse_scenario_toml(written, "b.toml");
  ASSERT_NE(again.plant, nullptr);
  EXPECT_EQ(again.plant->named_parameters(), s.plant->named_parameters());
  EXPECT_EQ(again.model->named_parameters(), s.model->named_parameters());
  EXPECT_EQ(hinf::scenario_toml(again), written);
  // Without [plant], none is written.
  EXPECT_EQ(hinf::scenario_toml(hinf::parse_scenario_toml(fig1, "c.toml")).find("[plant]"), std::string::npos);

  // Another kind of the same structure (n = 6, m = 2, nw = 6, noise on w4..w6, heading 5,
  // position 3 and 4): its own defaults.
  const Scenario vessel = hinf::parse_scenario_toml(fig1 + "\n[plant]\nkind = \"fossen_vessel\"\n", "d.toml");
  ASSERT_NE(dynamic_cast<const hinf::FossenVessel*>(vessel.plant.get()), nullptr);
  EXPECT_EQ(dynamic_cast<const hinf::FossenVessel*>(vessel.plant.get())->parameters().M,
            hinf::FossenVesselParameters::supply_vessel_M());
}

TEST(Plant, ErrorsNameThePlantSection) {
  const std::string fig1 = shipped("paper_fig1");
  const auto message = [&](const std::string& plant) {
    try {
      hinf::parse_scenario_toml(fig1 + "\n[plant]\n" + plant, "bad.toml");
    } catch (const hinf::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto expect_message = [&](const std::string& plant, const std::string& expected) {
    const std::string text = message(plant);
    EXPECT_NE(text.find("bad.toml: [plant]"), std::string::npos) << text;
    EXPECT_NE(text.find(expected), std::string::npos) << plant << " -> " << text;
  };
  expect_message("kind = \"linear\"\nA = [[0.0, 1.0], [0.0, 0.0]]\nB = [[0.0], [1.0]]\n",
                 "has n = 2, the design model 'ship' has 6");
  expect_message("kind = \"hovercraft\"\n", "heading index = 2, the design model 'ship' has 5");
  expect_message("d_x = 1.0\n", "unknown key 'd_x'");
  expect_message("d_u = \"much\"\n", "d_u: expected a number, got a string");
  expect_message("M = [[1.0]]\n", "M: is a key of kind = \"fossen_vessel\", not of kind = \"ship\"");
  expect_message("kind = \"fossen_vessel\"\nM = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]]\n", "M");
  expect_message("kind = \"boat\"\n", "unknown model kind \"boat\"");

  // Scenario::validate checks a plant set in code.
  Scenario s = hinf::parse_scenario_toml(fig1, "ok.toml");
  s.plant = std::make_shared<hinf::Hovercraft>();
  try {
    s.resolved().validate();
    ADD_FAILURE() << "no error";
  } catch (const hinf::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[plant] the plant 'hovercraft' has heading index = 2"), std::string::npos)
        << e.what();
  }
}

TEST(Plant, TheResultsFileRecordsModelAndPlant) {
  Scenario s = parse(shipped("paper_fig1"), 2.0);
  const nlohmann::json plain = nlohmann::json::parse(hinf::results_json(hinf::run_scenario(s)));
  EXPECT_EQ(plain["model"]["name"], "ship");
  EXPECT_EQ(plain["model"]["parameters"]["d_u"], 1.0);
  EXPECT_EQ(plain["model"]["parameters"]["m_v"], -2.0);
  EXPECT_EQ(plain["model"]["parameters"].size(), 6u);
  EXPECT_FALSE(plain.contains("plant"));
  s.plant = damped_ship(1.3);
  const nlohmann::json j = nlohmann::json::parse(hinf::results_json(hinf::run_scenario(s)));
  EXPECT_EQ(j["model"]["parameters"]["d_u"], 1.0);
  EXPECT_EQ(j["plant"]["name"], "ship");
  EXPECT_EQ(j["plant"]["parameters"]["d_u"], 1.3);
  EXPECT_EQ(j["plant"]["parameters"]["m_u"], 0.5);
}

TEST(Plant, NamedParametersAreTheScenarioKeys) {
  const auto names = [](const hinf::Model& model) {
    std::vector<std::string> out;
    for (const auto& [name, value] : model.named_parameters()) out.push_back(name);
    return out;
  };
  EXPECT_EQ(names(hinf::ShipModel()), (std::vector<std::string>{"m_u", "m_v", "m_r", "d_u", "d_v", "d_r"}));
  EXPECT_EQ(names(hinf::Hovercraft()), (std::vector<std::string>{"d", "d_r"}));
  EXPECT_EQ(names(hinf::PlanarVtol()), (std::vector<std::string>{"g", "epsilon"}));
  EXPECT_EQ(names(hinf::Auv()),
            (std::vector<std::string>{"m11", "m22", "m33", "X_u", "X_uu", "Y_v", "Y_vv", "N_r", "N_rr"}));
  const auto vessel = hinf::FossenVessel().named_parameters();
  ASSERT_EQ(vessel.size(), 18u);
  EXPECT_EQ(vessel[5].first, "M[1][2]");
  EXPECT_EQ(vessel[5].second, -0.0744);
  EXPECT_EQ(vessel[9 + 7].first, "D[2][1]");
  EXPECT_EQ(vessel[9 + 7].second, -0.0041);
  const hinf::LinearModel linear(Mat::Identity(2, 2), Mat::Ones(2, 1), Mat::Identity(2, 2), Mat::Ones(1, 2));
  EXPECT_EQ(names(linear), (std::vector<std::string>{"A[0][0]", "A[0][1]", "A[1][0]", "A[1][1]", "B[0][0]",
                                                     "B[1][0]", "D[0][0]", "D[0][1]", "D[1][0]", "D[1][1]",
                                                     "C[0][0]", "C[0][1]"}));
  // Each value is the one its key sets: written with the keys, read back the same.
  hinf::AuvParameters p;
  p.Y_vv = 123.0;
  EXPECT_EQ(hinf::Auv(p).named_parameters()[6], (std::pair<std::string, double>{"Y_vv", 123.0}));
}

TEST(Plant, StudyRunsWithOtherPlantsShareOneDesign) {
  std::vector<Scenario> runs;
  for (double factor : {0.8, 1.0, 1.2, 1.4}) {
    Scenario s = parse(shipped(factor == 1.0 ? "paper_fig2" : "paper_fig1"), 6.0);
    s.plant = damped_ship(factor);
    runs.push_back(s);
  }
  const std::vector<hinf::StudyRun> rows = hinf::run_scenarios(runs);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_EQ(rows[i].status, hinf::RunOutcome::Completed) << rows[i].reason;
    EXPECT_EQ(rows[i].design, rows[0].design) << i;
    const hinf::Metrics alone = hinf::run_scenario(runs[i]).metrics;
    EXPECT_EQ(rows[i].metrics.rms_position_error_last_half, alone.rms_position_error_last_half) << i;
    EXPECT_EQ(rows[i].metrics.control_l2, alone.control_l2) << i;
  }
}

}  // namespace
