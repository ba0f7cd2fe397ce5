// Input checks where C++ callers hand the library inconsistent sizes or a faulty model: a
// model subclass with bad structure (validate_model, used by Trajectory and compute_metrics),
// controllers given q or u of the wrong length, a run of another model, dense-output lookups
// at NaN, and dimensions that would allocate without bound. Each is an InputError naming the
// fault, never a read past an array.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hinf/control/cascade.hpp"
#include "hinf/control/controller.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/piecewise_polynomial.hpp"
#include "hinf/numerics/signal.hpp"

namespace {

using hinf::InputError;
using hinf::Mat;
using hinf::RowMat;
using hinf::Vec;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Runs `call` and returns the InputError's message ("" when nothing is thrown).
template <class Call>
std::string input_error(Call&& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// dq/dt = -q + B u + D w with 2 states, 1 input and 1 disturbance channel; each fault is a switch.
class FaultyModel : public hinf::Model {
 public:
  std::vector<int> positions = {0, 1};
  int heading = -1;
  std::vector<int> noise = {};
  int states = 2;
  int d_columns = 1;
  double b_wrong_after = std::numeric_limits<double>::infinity();  // B is 3 x 1 for t > this

  std::string name() const override { return "faulty"; }
  int n() const override { return states; }
  int m() const override { return 1; }
  int nw() const override { return 1; }
  void f(double, const hinf::ConstVecRef& q, hinf::VecRef out) const override { out = -q; }
  void dfdq(double, const hinf::ConstVecRef&, hinf::MatRef out) const override { out = -Mat::Identity(2, 2); }
  Mat G(double t, const hinf::ConstVecRef&) const override { return Mat::Ones(t > b_wrong_after ? 3 : 2, 1); }
  Mat D(double, const hinf::ConstVecRef&) const override { return Mat::Ones(2, d_columns); }
  bool constant_input_matrices() const override { return std::isinf(b_wrong_after); }
  std::vector<int> position_indices() const override { return positions; }
  int heading_index() const override { return heading; }
  std::vector<int> noise_channels() const override { return noise; }
};

std::shared_ptr<const hinf::Trajectory> trajectory_of(std::shared_ptr<const hinf::Model> model) {
  return std::make_shared<const hinf::Trajectory>(std::move(model), Vec::Ones(2),
                                                  hinf::VectorSignal::zeros(1), 0.0, 1.0);
}

TEST(ValidateModel, FaultyStructureIsAnInputErrorWhereTheModelEnters) {
  struct Case {
    std::string expected;
    void (*spoil)(FaultyModel&);
  };
  const Case cases[] = {
      {"position_indices() = [50, -7] holds 50, which is not a state index (0 to 1)",
       [](FaultyModel& m) { m.positions = {50, -7}; }},
      {"position_indices() = [1, 1] holds 1 twice", [](FaultyModel& m) { m.positions = {1, 1}; }},
      {"heading_index() must be -1 (no heading) or a state index (0 to 1), got -2",
       [](FaultyModel& m) { m.heading = -2; }},
      {"noise_channels() = [0, 1] holds 1, which is not a disturbance channel (0 to 0)",
       [](FaultyModel& m) { m.noise = {0, 1}; }},
      {"the number of states n() must be in [1, 10000], got 0", [](FaultyModel& m) { m.states = 0; }},
      {"Incompatible dimensions of D(t, q) of the model 'faulty': expected (2, 1) but found (2, 3)",
       [](FaultyModel& m) { m.d_columns = 3; }},
  };
  for (const Case& c : cases) {
    auto model = std::make_shared<FaultyModel>();
    c.spoil(*model);
    EXPECT_NE(input_error([&] { hinf::validate_model(*model, 0.0, Vec::Ones(2)); }).find(c.expected), std::string::npos)
        << c.expected;
    EXPECT_NE(input_error([&] { trajectory_of(model); }).find(c.expected), std::string::npos) << c.expected;
  }
}

TEST(ValidateModel, TimeVaryingBOfTheWrongShapeDuringTheTrajectory) {
  auto model = std::make_shared<FaultyModel>();
  model->b_wrong_after = 0.5;
  EXPECT_NE(input_error([&] { trajectory_of(model); }).find("has shape (3, 1), expected (2, 1)"),
            std::string::npos);
}

// A run of the 2-state model with output times 0, 0.5, 1 (every series zero).
hinf::SimulationResult zero_run(int n, int m, int nw) {
  hinf::SimulationResult r;
  r.t = Vec::LinSpaced(3, 0.0, 1.0);
  r.q = r.q_d = RowMat::Zero(3, n);
  r.u = r.u_d = RowMat::Zero(3, m);
  r.w = RowMat::Zero(3, nw);
  return r;
}

TEST(ComputeMetrics, FaultyModelOrARunOfAnotherModelIsAnInputError) {
  FaultyModel model;
  EXPECT_EQ(input_error([&] { hinf::compute_metrics(model, zero_run(2, 1, 1), Mat::Identity(2, 2)); }), "");
  model.positions = {50, -7};
  EXPECT_NE(input_error([&] { hinf::compute_metrics(model, zero_run(2, 1, 1), Mat::Identity(2, 2)); })
                .find("position_indices() = [50, -7]"),
            std::string::npos);
  const hinf::ShipModel ship;
  EXPECT_NE(input_error([&] { hinf::compute_metrics(ship, zero_run(2, 1, 1), Mat::Identity(6, 6)); })
                .find("run.q has shape (3, 2), expected (3, 6) for the model 'ship'"),
            std::string::npos);
  hinf::SimulationResult run = zero_run(6, 2, 6);
  run.estimator.emplace().q_hat = RowMat::Zero(3, 2);
  EXPECT_NE(input_error([&] { hinf::compute_metrics(ship, run, Mat::Identity(6, 6)); })
                .find("run.estimator.q_hat has shape (3, 2), expected (3, 6)"),
            std::string::npos);
  EXPECT_NE(input_error([&] { hinf::compute_metrics(ship, zero_run(6, 2, 6), Mat::Identity(2, 2)); })
                .find("Incompatible dimensions of Q: expected (6, 6) but found (2, 2)"),
            std::string::npos);
}

// ================================================================= controllers

struct ShipDesign {
  hinf::TrajectoryPtr trajectory;
  hinf::RiccatiSolutionPtr solution;
};

const ShipDesign& ship_design() {
  static const ShipDesign design = [] {
    Vec q_d0 = Vec::Zero(6);
    q_d0[0] = 1.0;
    auto trajectory = std::make_shared<const hinf::Trajectory>(
        std::make_shared<hinf::ShipModel>(), q_d0,
        hinf::VectorSignal(std::vector<hinf::Signal>{hinf::Signal(1.0), hinf::Signal(0.0)}), 0.0, 2.0);
    return ShipDesign{trajectory, hinf::solve_grde(trajectory, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0)};
  }();
  return design;
}

TEST(Controllers, StateAndInputOfTheWrongLengthAreInputErrors) {
  hinf::HinfStateFeedback hinf_law(ship_design().solution);
  hinf::CascadeController cascade(ship_design().trajectory);
  for (hinf::Controller* law : {static_cast<hinf::Controller*>(&hinf_law), static_cast<hinf::Controller*>(&cascade)}) {
    EXPECT_EQ(law->n(), 6);
    Vec q = Vec::Zero(6), u(2), short_q = Vec::Zero(1), long_u(3);
    EXPECT_EQ(input_error([&] { law->control(1.0, q, u); }), "");
    EXPECT_NE(input_error([&] { law->control(1.0, short_q, u); })
                  .find("takes q of 6 numbers and gives u of 2, got q of 1"),
              std::string::npos)
        << law->name();
    EXPECT_NE(input_error([&] { law->control(1.0, q, long_u); }).find("got q of 6 and u of 3"), std::string::npos)
        << law->name();
  }
  Mat dudq(2, 5);
  EXPECT_NE(input_error([&] { hinf_law.control_jacobian(1.0, Vec::Zero(6), dudq); }).find("needs 6 columns, got 5"),
            std::string::npos);
  EXPECT_NE(input_error([&] { cascade.control_jacobian(1.0, Vec::Zero(6), dudq); })
                .find("du/dq must be (2, 6), got (2, 5)"),
            std::string::npos);
}

TEST(Controllers, NaNTimeIsNotLookedUpInTheCursorPiece) {
  // The law keeps a cursor into Z's dense output; a NaN time used to be "inside" that piece.
  hinf::HinfStateFeedback law(ship_design().solution);
  Vec q = Vec::Zero(6), u(2);
  law.control(1.0, q, u);
  EXPECT_NE(input_error([&] { law.control(kNaN, q, u); }).find("is outside the solved interval"), std::string::npos);
}

TEST(PiecewisePolynomial, NaNWithACursorIsAnInputError) {
  hinf::PiecewisePolynomial p(1);
  const double c[] = {1.0, 2.0};  // y = 1 + 2 theta on [0, 1]
  p.append(hinf::DensePiece{0.0, 0.0 + 1.0, 1, p.dim(), c});
  p.finalize();
  std::size_t cursor = 0;
  double y = 0.0;
  p.eval(0.5, &y, &cursor);
  EXPECT_DOUBLE_EQ(y, 2.0);
  EXPECT_NE(input_error([&] { p.eval(kNaN, &y, &cursor); }).find("outside the solved interval"), std::string::npos);
  EXPECT_NE(input_error([&] { p.eval_derivative(kNaN, &y, &cursor); }).find("outside"), std::string::npos);
}

// ====================================================================== sizes

TEST(Dimensions, NegativeOrHugeDimensionsAreInputErrorsNotAllocations) {
  EXPECT_NE(input_error([] { hinf::VectorSignal::zeros(-1); }).find("must be in [0, 10000], got -1"),
            std::string::npos);
  EXPECT_NE(input_error([] { hinf::VectorSignal::zeros(1 << 30); }).find("got 1073741824"), std::string::npos);
  EXPECT_NE(input_error([] { hinf::VectorSignal(-2, [](double) { return Vec(); }); }).find("got -2"),
            std::string::npos);
  EXPECT_NE(input_error([] { hinf::check_symmetric_weight(Mat(), 0, "N", true); }).find("N must be at least 1 x 1"),
            std::string::npos);
}

}  // namespace
