// The built-in vehicles (vehicles.hpp): analytic Jacobians against central differences, the
// right-hand sides against the textbook equations written out here, the structure (G, D, C,
// noise channels, indices), the parameter checks, and [model] of a scenario file for each kind.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/io/model_kinds.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/scenario/scenario.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/vehicles.hpp"
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Mat;
using hinf::Vec;

// A state with velocities in [-2, 2] and angles over more than a full turn; an input in [-2, 2].
Vec random_state(hinf_ref::Rng& rng) {
  Vec q(6);
  for (int i = 0; i < 6; ++i) q[i] = rng.uniform(-2.0, 2.0);
  return q;
}
Vec random_input(hinf_ref::Rng& rng) { return Vec{{rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)}}; }

// Column j: (g(q + h e_j) - g(q - h e_j)) / 2h.
Mat central_differences(const std::function<Vec(const Vec&)>& g, const Vec& q, double h) {
  Mat J(g(q).size(), q.size());
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    Vec plus = q, minus = q;
    plus[j] += h;
    minus[j] -= h;
    J.col(j) = (g(plus) - g(minus)) / (2.0 * h);
  }
  return J;
}

// Central differences with h = 1e-6 of a right-hand side g whose entries are at most `size` in
// magnitude near q: round-off of the two evaluations, a few ulps of `size` each, divided by 2h
// (at most 1e3 eps size / h, 2.2e-7 size), plus the truncation h^2/6 |g'''|. Every vehicle's g is
// a polynomial of degree <= 2 in the velocities times sines and cosines of one angle, with third
// derivatives below 100 (size bounded too) for states in [-2, 2] and the parameters used here:
// truncation < 2e-11. (For the AUV, |u| u has no third derivative at 0: across 0 the difference
// quotient is off by at most h X_uu / m11, 5e-7; the seeded states keep away from 0 by far more
// than h.)
constexpr double kStep = 1e-6;
double difference_tolerance(double size) { return 1e3 * hinf_test::kEps * (1.0 + size) / kStep + 2e-11; }

struct Vehicle {
  std::string label;
  std::shared_ptr<const hinf::Model> model;
};

hinf::FossenVesselParameters nondefault_vessel() {
  hinf::FossenVesselParameters p;
  // A general symmetric positive definite M (m12, m13 != 0) and a non-symmetric D.
  p.M << 2.0, 0.1, -0.2,  //
      0.1, 3.0, 0.4,  //
      -0.2, 0.4, 0.7;
  p.D << 0.5, 0.05, 0.0,  //
      -0.1, 0.8, 0.2,  //
      0.02, -0.05, 0.3;
  return p;
}

std::vector<Vehicle> vehicles() {
  return {
      {"fossen supply vessel", std::make_shared<hinf::FossenVessel>()},
      {"fossen general M", std::make_shared<hinf::FossenVessel>(nondefault_vessel())},
      {"hovercraft", std::make_shared<hinf::Hovercraft>()},
      {"hovercraft 0.7/0.3", std::make_shared<hinf::Hovercraft>(hinf::HovercraftParameters{0.7, 0.3})},
      {"pvtol", std::make_shared<hinf::PlanarVtol>()},
      {"pvtol g 9.81 eps -0.4", std::make_shared<hinf::PlanarVtol>(hinf::PlanarVtolParameters{9.81, -0.4})},
      {"auv sirene", std::make_shared<hinf::Auv>()},
      {"auv other", std::make_shared<hinf::Auv>(hinf::AuvParameters{10, 20, 3, 1, 2, 3, 4, 0.5, 0.25})},
  };
}

Vec drift(const hinf::Model& model, const Vec& q) {
  Vec out(6);
  model.f(0.0, q, out);
  return out;
}

TEST(Vehicles, DriftJacobianMatchesCentralDifferences) {
  for (const Vehicle& vehicle : vehicles()) {
    hinf_ref::Rng rng(2024);
    for (int trial = 0; trial < 40; ++trial) {
      const Vec q = random_state(rng);
      Mat J(6, 6);
      vehicle.model->dfdq(0.0, q, J);
      const auto f = [&](const Vec& x) { return drift(*vehicle.model, x); };
      const Mat J_fd = central_differences(f, q, kStep);
      const double size = drift(*vehicle.model, q).cwiseAbs().maxCoeff() + J.cwiseAbs().maxCoeff();
      EXPECT_LT((J - J_fd).cwiseAbs().maxCoeff(), difference_tolerance(size))
          << vehicle.label << " at q = " << q.transpose();
    }
  }
}

TEST(Vehicles, InputJacobianMatchesCentralDifferences) {
  for (const Vehicle& vehicle : vehicles()) {
    const hinf::Model& model = *vehicle.model;
    hinf_ref::Rng rng(77);
    for (int trial = 0; trial < 40; ++trial) {
      const Vec q = random_state(rng), u = random_input(rng);
      Mat dGu(6, 6), A(6, 6);
      model.dGudq(0.0, q, u, dGu);
      const auto Gu = [&](const Vec& x) -> Vec { return model.G(0.0, x) * u; };
      // G u is sin/cos of one angle times |u| <= 2 (times |epsilon| <= 1): size 2.
      EXPECT_LT((dGu - central_differences(Gu, q, kStep)).cwiseAbs().maxCoeff(), difference_tolerance(2.0))
          << vehicle.label;
      // A_e's formula: d/dq [f + G u], the drift's and the input's parts together.
      hinf::linearize(model, 0.0, q, u, A);
      const auto rhs = [&](const Vec& x) -> Vec { return drift(model, x) + model.G(0.0, x) * u; };
      const double size = rhs(q).cwiseAbs().maxCoeff() + A.cwiseAbs().maxCoeff();
      EXPECT_LT((A - central_differences(rhs, q, kStep)).cwiseAbs().maxCoeff(), difference_tolerance(size))
          << vehicle.label;
      if (!model.state_dependent_inputs()) {
        EXPECT_EQ(dGu.cwiseAbs().maxCoeff(), 0.0) << vehicle.label;
      }
    }
  }
}

// Round-off of an evaluation of the same formula in another order: kRoundoff times its terms.
double roundoff(double terms) { return hinf_test::kRoundoff * (1.0 + terms); }

TEST(FossenVessel, RightHandSideSolvesTheMatrixEquations) {
  // M nu_dot + C(nu) nu + D nu = B_tau tau + w, with C(nu) of Fossen's 3-DOF form for
  // M = [[m11, 0, 0], [0, m22, m23], [0, m23, m33]], written out here; eta_dot = R(psi) nu.
  const hinf::FossenVessel vessel;
  const Mat M = vessel.parameters().M, D = vessel.parameters().D;
  EXPECT_EQ(M, hinf::FossenVesselParameters::supply_vessel_M());
  const double m11 = 1.1274, m22 = 1.8902, m23 = -0.0744;
  hinf_ref::Rng rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec q = random_state(rng), tau = random_input(rng);
    Vec w(6);
    for (int i = 0; i < 6; ++i) w[i] = rng.uniform(-1.0, 1.0);
    const Vec q_dot = drift(vessel, q) + vessel.G(0.0, q) * tau + vessel.D(0.0, q) * w;
    const double u = q[0], v = q[1], r = q[2], psi = q[5];
    Mat C(3, 3);
    C << 0.0, 0.0, -m22 * v - m23 * r,  //
        0.0, 0.0, m11 * u,  //
        m22 * v + m23 * r, -m11 * u, 0.0;
    const Vec nu = q.head(3);
    const Vec force = Vec{{tau[0], 0.0, tau[1]}} + w.head(3);
    const Vec residual = M * q_dot.head(3) + C * nu + D * nu - force;
    // nu_dot is M^-1 times forces of size |C nu| + |D nu| + 3 <= 8 + 1 + 3; M^-1 has entries up
    // to 8 (1 / m33): round-off of terms of 100, multiplied back by M (entries <= 2).
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), roundoff(200.0)) << q.transpose();
    EXPECT_NEAR(q_dot[3], u * std::cos(psi) - v * std::sin(psi), roundoff(4.0));
    EXPECT_NEAR(q_dot[4], u * std::sin(psi) + v * std::cos(psi), roundoff(4.0));
    EXPECT_EQ(q_dot[5], r);
  }
}

TEST(FossenVessel, KineticEnergyChangesByThePowerOfTheForces) {
  // For any symmetric M, C(nu) is skew-symmetric: d/dt (nu' M nu / 2) = nu' M nu_dot =
  // nu' (B_tau tau + w - D nu), the Coriolis forces doing no work. A general M and D.
  const hinf::FossenVessel vessel(nondefault_vessel());
  const Eigen::Matrix3d M = vessel.parameters().M, D = vessel.parameters().D;
  hinf_ref::Rng rng(6);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec q = random_state(rng), tau = random_input(rng);
    Vec w = Vec::Zero(6);
    for (int i = 0; i < 3; ++i) w[i] = rng.uniform(-1.0, 1.0);
    const Eigen::Vector3d nu = q.head<3>();
    const Eigen::Vector3d nu_dot = (drift(vessel, q) + vessel.G(0.0, q) * tau + vessel.D(0.0, q) * w).head<3>();
    const Eigen::Vector3d force(tau[0] + w[0], w[1], tau[1] + w[2]);
    const double power = nu.dot(force - D * nu);
    // Terms: |nu| <= 3.5, |M nu_dot| up to |C nu| + |D nu| + 3 ~ 30: products of about 100.
    EXPECT_NEAR(nu.dot(M * nu_dot), power, roundoff(100.0)) << q.transpose();
  }
}

TEST(FossenVessel, InputsAndDisturbancesAreForcesThroughTheInverseMass) {
  const hinf::FossenVessel vessel;
  const Mat M = hinf::FossenVesselParameters::supply_vessel_M();
  const Vec q = Vec::Zero(6);
  const Mat G = vessel.G(0.0, q), D = vessel.D(0.0, q);
  Mat B_tau = Mat::Zero(3, 2);
  B_tau(0, 0) = B_tau(2, 1) = 1.0;
  // M G = B_tau: the inverse and the product, round-off of M^-1's entries (<= 8) times M's.
  EXPECT_LT((M * G.topRows(3) - B_tau).cwiseAbs().maxCoeff(), roundoff(16.0));
  EXPECT_LT((M * D.topLeftCorner(3, 3) - Mat::Identity(3, 3)).cwiseAbs().maxCoeff(), roundoff(16.0));
  EXPECT_EQ(G.bottomRows(3).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(D.bottomRows(3).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(D.rightCols(3).cwiseAbs().maxCoeff(), 0.0);  // the noise channels
  // The yaw moment accelerates sway (m23 != 0): underactuated, but not decoupled.
  EXPECT_GT(std::abs(G(1, 1)), 0.1);
  EXPECT_TRUE(vessel.constant_input_matrices());
  EXPECT_FALSE(vessel.state_dependent_inputs());
}

TEST(Hovercraft, RightHandSideIsTheTextbookModel) {
  const hinf::HovercraftParameters p{0.7, 0.3};
  const hinf::Hovercraft hovercraft(p);
  hinf_ref::Rng rng(8);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec q = random_state(rng), u = random_input(rng);
    const Vec q_dot = drift(hovercraft, q) + hovercraft.G(0.0, q) * u;
    const double x_dot = q[3], y_dot = q[4], r = q[5], psi = q[2];
    Vec expected(6);
    expected << x_dot, y_dot, r, u[0] * std::cos(psi) - 0.7 * x_dot, u[0] * std::sin(psi) - 0.7 * y_dot,
        u[1] - 0.3 * r;
    EXPECT_LT((q_dot - expected).cwiseAbs().maxCoeff(), roundoff(4.0)) << q.transpose();
  }
}

TEST(PlanarVtol, RightHandSideIsTheEquationsOfHauserSastryMeyer) {
  const hinf::PlanarVtolParameters p{9.81, -0.4};
  const hinf::PlanarVtol vtol(p);
  hinf_ref::Rng rng(9);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec q = random_state(rng), u = random_input(rng);
    const Vec q_dot = drift(vtol, q) + vtol.G(0.0, q) * u;
    const double theta = q[2];
    Vec expected(6);
    expected << q[3], q[4], q[5], -u[0] * std::sin(theta) + (-0.4) * u[1] * std::cos(theta),
        u[0] * std::cos(theta) + (-0.4) * u[1] * std::sin(theta) - 9.81, u[1];
    EXPECT_LT((q_dot - expected).cwiseAbs().maxCoeff(), roundoff(12.0)) << q.transpose();
  }
  // Hover: u1 = g, u2 = 0 at theta = 0 is an equilibrium.
  const Vec hover = Vec::Zero(6);
  EXPECT_EQ((drift(vtol, hover) + vtol.G(0.0, hover) * Vec{{9.81, 0.0}}).cwiseAbs().maxCoeff(), 0.0);
}

TEST(Auv, RightHandSideIsTheQuadraticDragModel) {
  const hinf::AuvParameters p{10, 20, 3, 1, 2, 3, 4, 0.5, 0.25};
  const hinf::Auv auv(p);
  hinf_ref::Rng rng(10);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec q = random_state(rng), tau = random_input(rng);
    Vec w = Vec::Zero(6);
    for (int i = 0; i < 3; ++i) w[i] = rng.uniform(-1.0, 1.0);
    const Vec q_dot = drift(auv, q) + auv.G(0.0, q) * tau + auv.D(0.0, q) * w;
    const double u = q[0], v = q[1], r = q[2], psi = q[5];
    // m11 u_dot = m22 v r - X_u u - X_uu |u| u + tau_u + w1, and so on (masses 10, 20, 3).
    EXPECT_NEAR(10 * q_dot[0], 20 * v * r - 1 * u - 2 * std::abs(u) * u + tau[0] + w[0], roundoff(100.0));
    EXPECT_NEAR(20 * q_dot[1], -10 * u * r - 3 * v - 4 * std::abs(v) * v + w[1], roundoff(100.0));
    EXPECT_NEAR(3 * q_dot[2], (10 - 20) * u * v - 0.5 * r - 0.25 * std::abs(r) * r + tau[1] + w[2],
                roundoff(100.0));
    EXPECT_NEAR(q_dot[3], u * std::cos(psi) - v * std::sin(psi), roundoff(4.0));
    EXPECT_NEAR(q_dot[4], u * std::sin(psi) + v * std::cos(psi), roundoff(4.0));
    EXPECT_EQ(q_dot[5], r);
  }
  // The defaults are the Sirene AUV of Aguiar and Pascoal (2007).
  const hinf::AuvParameters sirene = hinf::AuvParameters::sirene();
  EXPECT_EQ(sirene.m11, 215.0);
  EXPECT_EQ(sirene.m22, 265.0);
  EXPECT_EQ(sirene.m33, 80.0);
  EXPECT_EQ(sirene.X_u, 70.0);
  EXPECT_EQ(sirene.X_uu, 100.0);
  EXPECT_EQ(sirene.Y_v, 100.0);
  EXPECT_EQ(sirene.Y_vv, 200.0);
  EXPECT_EQ(sirene.N_r, 50.0);
  EXPECT_EQ(sirene.N_rr, 100.0);
}

TEST(Vehicles, StructureMeasurementAndNoiseChannels) {
  struct Expected {
    std::vector<int> position;
    int heading;
    std::vector<std::string> names;
    bool state_dependent;
  };
  const std::vector<Expected> expected = {
      {{3, 4}, 5, {"u", "v", "r", "x", "y", "psi"}, false},
      {{3, 4}, 5, {"u", "v", "r", "x", "y", "psi"}, false},
      {{0, 1}, 2, {"x", "y", "psi", "vx", "vy", "r"}, true},
      {{0, 1}, 2, {"x", "y", "psi", "vx", "vy", "r"}, true},
      {{0, 1}, 2, {"x", "y", "theta", "x_dot", "y_dot", "theta_dot"}, true},
      {{0, 1}, 2, {"x", "y", "theta", "x_dot", "y_dot", "theta_dot"}, true},
      {{3, 4}, 5, {"u", "v", "r", "x", "y", "psi"}, false},
      {{3, 4}, 5, {"u", "v", "r", "x", "y", "psi"}, false},
  };
  const std::vector<Vehicle> all = vehicles();
  ASSERT_EQ(all.size(), expected.size());
  hinf_ref::Rng rng(11);
  for (std::size_t k = 0; k < all.size(); ++k) {
    const hinf::Model& model = *all[k].model;
    const Expected& e = expected[k];
    const Vec q = random_state(rng);
    EXPECT_NO_THROW(hinf::validate_model(model, 0.0, q)) << all[k].label;
    EXPECT_EQ(model.position_indices(), e.position) << all[k].label;
    EXPECT_EQ(model.heading_index(), e.heading) << all[k].label;
    EXPECT_EQ(model.state_names(), e.names) << all[k].label;
    EXPECT_EQ(model.state_dependent_inputs(), e.state_dependent) << all[k].label;
    EXPECT_EQ(model.constant_input_matrices(), !e.state_dependent) << all[k].label;
    // The equations are CasADi generated code (models/builtin_vehicle.hpp): exact Jacobians.
    EXPECT_EQ(model.jacobian_method(), "automatic differentiation");
    EXPECT_TRUE(std::isnan(model.remainder_bound(0.0, q, 1.0)));
    // y = [x, y, heading]; the noise on w4..w6, whose columns of D are zero.
    Mat C_expected = Mat::Zero(3, 6);
    C_expected(0, e.position[0]) = C_expected(1, e.position[1]) = C_expected(2, e.heading) = 1.0;
    EXPECT_EQ(model.C(0.0), C_expected) << all[k].label;
    EXPECT_EQ(model.noise_channels(), (std::vector<int>{3, 4, 5})) << all[k].label;
    const Mat D = model.D(0.0, q);
    EXPECT_EQ(D.rightCols(3).cwiseAbs().maxCoeff(), 0.0) << all[k].label;
    // The process disturbance acts on the velocity equations only, one channel each.
    for (int channel = 0; channel < 3; ++channel)
      for (int row : e.position) EXPECT_EQ(D(row, channel), 0.0) << all[k].label;
    EXPECT_EQ(D(e.heading, 0), 0.0);
    // G: the control never enters the position and heading equations directly.
    const Mat G = model.G(0.0, q);
    for (int row : {e.position[0], e.position[1], e.heading})
      EXPECT_EQ(G.row(row).cwiseAbs().maxCoeff(), 0.0) << all[k].label;
    if (!e.state_dependent) {
      EXPECT_EQ(G, model.G(0.0, random_state(rng))) << all[k].label;
    }
  }
}

// The message of the InputError thrown by make(), or "" when none is thrown.
std::string error_of(const std::function<void()>& make) {
  try {
    make();
  } catch (const hinf::InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Vehicles, BadParametersAreRefusedNamingThem) {
  // Fossen vessel: M symmetric positive definite, D dissipative, both finite 3 x 3.
  auto vessel = [](auto change) {
    return error_of([&] {
      hinf::FossenVesselParameters p;
      change(p);
      hinf::FossenVessel v(p);
    });
  };
  std::string message = vessel([](auto& p) { p.M(1, 2) = 0.1; });
  EXPECT_TRUE(contains(message, "mass matrix M must be symmetric") && contains(message, "m23 = m32")) << message;
  message = vessel([](auto& p) { p.M(2, 2) = -0.1; });
  EXPECT_TRUE(contains(message, "mass matrix M must be positive definite")) << message;
  message = vessel([](auto& p) { p.M(0, 0) = 0.0; });
  EXPECT_TRUE(contains(message, "mass matrix M must be positive definite")) << message;
  message = vessel([](auto& p) { p.D(1, 1) = -0.2; });
  EXPECT_TRUE(contains(message, "damping matrix D") && contains(message, "(D + D')/2")) << message;
  // A non-symmetric D with a positive definite symmetric part is fine (the preset is one)...
  EXPECT_EQ(vessel([](auto& p) { p.D(1, 2) = 0.1; }), "");
  // ... but a coupling that makes the symmetric part indefinite is not.
  message = vessel([](auto& p) { p.D(1, 2) = p.D(2, 1) = 0.5; });
  EXPECT_TRUE(contains(message, "damping matrix D")) << message;
  message = vessel([](auto& p) { p.M = Mat::Identity(2, 2); });
  EXPECT_TRUE(contains(message, "mass matrix M") && contains(message, "(3, 3)")) << message;
  message = vessel([](auto& p) { p.D(0, 0) = NAN; });
  EXPECT_TRUE(contains(message, "damping matrix D") && contains(message, "non-finite")) << message;

  message = error_of([] { hinf::Hovercraft h(hinf::HovercraftParameters{-0.1, 0.5}); });
  EXPECT_TRUE(contains(message, "Hovercraft") && contains(message, "damping d ") && contains(message, ">= 0"))
      << message;
  message = error_of([] { hinf::Hovercraft h(hinf::HovercraftParameters{0.1, INFINITY}); });
  EXPECT_TRUE(contains(message, "d_r")) << message;
  EXPECT_EQ(error_of([] { hinf::Hovercraft h(hinf::HovercraftParameters{0.0, 0.0}); }), "");  // undamped

  message = error_of([] { hinf::PlanarVtol v(hinf::PlanarVtolParameters{-1.0, 0.1}); });
  EXPECT_TRUE(contains(message, "PlanarVtol") && contains(message, "gravity g")) << message;
  message = error_of([] { hinf::PlanarVtol v(hinf::PlanarVtolParameters{1.0, NAN}); });
  EXPECT_TRUE(contains(message, "epsilon")) << message;

  for (const char* name : {"m11", "m22", "m33"}) {
    message = error_of([name] {
      hinf::AuvParameters p;
      (std::string(name) == "m11" ? p.m11 : std::string(name) == "m22" ? p.m22 : p.m33) = 0.0;
      hinf::Auv a(p);
    });
    EXPECT_TRUE(contains(message, std::string(name) + " must be finite and > 0")) << message;
  }
  message = error_of([] {
    hinf::AuvParameters p;
    p.Y_vv = -1.0;
    hinf::Auv a(p);
  });
  EXPECT_TRUE(contains(message, "Y_vv must be finite and >= 0")) << message;
}

// A scenario file around a [model] section (6 states, 2 inputs).
std::string scenario_with_model(const std::string& model) {
  return "[model]\n" + model + R"(
[horizon]
tf = 1.0
[desired]
q0 = [0.1, 0.0, 0.0, 0.0, 0.0, 0.0]
u1 = 0.5
u2 = 0.1
[controller]
gamma = 10.0
[initial]
q0 = [0.1, 0.0, 0.0, 0.1, 0.1, 0.1]
)";
}

std::string reader_error(const std::string& model) {
  return error_of([&] { hinf::parse_scenario_toml(scenario_with_model(model), "vehicle.toml"); });
}

TEST(VehicleScenarios, EveryKeyIsReadAndThePresetsAreTheDefaults) {
  const auto model = [](const std::string& text) {
    return hinf::parse_scenario_toml(scenario_with_model(text), "vehicle.toml").model;
  };
  const auto vessel = std::dynamic_pointer_cast<const hinf::FossenVessel>(model("kind = \"fossen_vessel\""));
  ASSERT_NE(vessel, nullptr);
  EXPECT_EQ(vessel->parameters().M, hinf::FossenVesselParameters::supply_vessel_M());
  EXPECT_EQ(vessel->parameters().D, hinf::FossenVesselParameters::supply_vessel_D());
  const auto other = std::dynamic_pointer_cast<const hinf::FossenVessel>(
      model("kind = \"fossen_vessel\"\nM = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.1], [0.0, 0.1, 1.0]]"));
  EXPECT_EQ(other->parameters().M(1, 2), 0.1);
  EXPECT_EQ(other->parameters().D, hinf::FossenVesselParameters::supply_vessel_D());  // D from the preset
  const auto hovercraft =
      std::dynamic_pointer_cast<const hinf::Hovercraft>(model("kind = \"hovercraft\"\nd = 0.7\nd_r = 0.3"));
  EXPECT_EQ(hovercraft->parameters().d, 0.7);
  EXPECT_EQ(hovercraft->parameters().d_r, 0.3);
  const auto vtol =
      std::dynamic_pointer_cast<const hinf::PlanarVtol>(model("kind = \"pvtol\"\ng = 9.81\nepsilon = 0.01"));
  EXPECT_EQ(vtol->parameters().g, 9.81);
  EXPECT_EQ(vtol->parameters().epsilon, 0.01);
  const auto auv = std::dynamic_pointer_cast<const hinf::Auv>(
      model("kind = \"auv\"\npreset = \"sirene\"\nm11 = 1.0\nm22 = 2.0\nm33 = 3.0\nX_u = 4.0\nX_uu = 5.0\n"
            "Y_v = 6.0\nY_vv = 7.0\nN_r = 8.0\nN_rr = 9.0"));
  const hinf::AuvParameters& p = auv->parameters();
  EXPECT_EQ(std::vector<double>({p.m11, p.m22, p.m33, p.X_u, p.X_uu, p.Y_v, p.Y_vv, p.N_r, p.N_rr}),
            std::vector<double>({1, 2, 3, 4, 5, 6, 7, 8, 9}));
  const auto sirene = std::dynamic_pointer_cast<const hinf::Auv>(model("kind = \"auv\""));
  EXPECT_EQ(sirene->parameters().m22, 265.0);
}

TEST(VehicleScenarios, BadModelSectionsNameTheKey) {
  std::string message = reader_error("kind = \"fossen_vessel\"\npreset = \"tanker\"");
  EXPECT_TRUE(contains(message, "vehicle.toml: [model] preset: unknown preset \"tanker\"") &&
              contains(message, "\"supply_vessel\""))
      << message;
  message = reader_error("kind = \"auv\"\npreset = \"supply_vessel\"");
  EXPECT_TRUE(contains(message, "[model] preset") && contains(message, "\"sirene\"")) << message;
  // A key of another kind says whose it is; an unknown key lists the kind's keys.
  message = reader_error("kind = \"hovercraft\"\nm_u = 1.0");
  EXPECT_TRUE(contains(message, "[model] m_u: is a key of kind = \"ship\", not of kind = \"hovercraft\""))
      << message;
  message = reader_error("kind = \"pvtol\"\nD = [[1.0]]");
  EXPECT_TRUE(contains(message, "kind = \"linear\" or kind = \"fossen_vessel\"")) << message;
  message = reader_error("kind = \"pvtol\"\ngravity = 9.81");
  EXPECT_TRUE(contains(message, "unknown key 'gravity'") && contains(message, "known keys: kind, g, epsilon"))
      << message;
  message = reader_error("kind = \"submarine\"");
  EXPECT_TRUE(contains(message, "[model] kind: unknown model kind \"submarine\"") &&
              contains(message, "\"fossen_vessel\", \"hovercraft\", \"pvtol\", \"auv\""))
      << message;
  // Shapes and values: the reader's messages, and the model's checks under [model].
  message = reader_error("kind = \"fossen_vessel\"\nM = [[1.0, 0.0], [0.0, 1.0]]");
  EXPECT_TRUE(contains(message, "[model] M: expected a 3 x 3 nested list")) << message;
  message = reader_error("kind = \"fossen_vessel\"\nM = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.5], [0.0, 0.0, 1.0]]");
  EXPECT_TRUE(contains(message, "vehicle.toml: [model] FossenVessel: the mass matrix M must be symmetric"))
      << message;
  message = reader_error("kind = \"auv\"\nm33 = -80.0");
  EXPECT_TRUE(contains(message, "vehicle.toml: [model] Auv: the yaw inertia m33 must be finite and > 0"))
      << message;
  message = reader_error("kind = \"hovercraft\"\nd = nan");
  EXPECT_TRUE(contains(message, "[model] d: expected a finite number")) << message;
}

// ---- a vehicle of one's own: one file (this block) and one registration line ----

// A unicycle whose speed has linear drag, q = [x, y, psi, v], u = [thrust, yaw rate]:
//     dx/dt = v cos(psi),  dy/dt = v sin(psi),  dpsi/dt = u2,  dv/dt = -d v + u1 + w1.
struct UnicycleParameters {
  double d = 0.5;  // drag (1/s), > 0
};
inline constexpr std::array<std::pair<const char*, double UnicycleParameters::*>, 1> kUnicycleParameterKeys{
    {{"d", &UnicycleParameters::d}}};

class Unicycle final : public hinf::Model {
 public:
  explicit Unicycle(const UnicycleParameters& p = {}) : p_(p) {
    hinf::require(p_.d > 0.0, "Unicycle: the drag d must be > 0, got ", p_.d);
  }
  std::string name() const override { return "unicycle"; }
  int n() const override { return 4; }
  int m() const override { return 2; }
  int nw() const override { return 1; }
  void f(double, const hinf::ConstVecRef& q, hinf::VecRef out) const override {
    out << q[3] * std::cos(q[2]), q[3] * std::sin(q[2]), 0.0, -p_.d * q[3];
  }
  void dfdq(double, const hinf::ConstVecRef& q, hinf::MatRef J) const override {
    J.setZero();
    J(0, 2) = -q[3] * std::sin(q[2]);
    J(0, 3) = std::cos(q[2]);
    J(1, 2) = q[3] * std::cos(q[2]);
    J(1, 3) = std::sin(q[2]);
    J(3, 3) = -p_.d;
  }
  Mat G(double, const hinf::ConstVecRef&) const override {
    Mat G = Mat::Zero(4, 2);
    G(3, 0) = G(2, 1) = 1.0;
    return G;
  }
  Mat D(double, const hinf::ConstVecRef&) const override {
    Mat D = Mat::Zero(4, 1);
    D(3, 0) = 1.0;
    return D;
  }
  std::vector<std::string> state_names() const override { return {"x", "y", "psi", "v"}; }
  std::vector<int> position_indices() const override { return {0, 1}; }
  int heading_index() const override { return 2; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return hinf::named_parameters_of(p_, kUnicycleParameterKeys);
  }
  bool same_as(const hinf::Model& other) const override { return hinf::same_type_and_parameters(*this, other); }

 private:
  UnicycleParameters p_;
};

TEST(VehicleScenarios, AVehicleOfOnesOwnIsOneFileAndOneRegistrationLine) {
  hinf::register_model_kind(hinf::parameter_kind<Unicycle, UnicycleParameters>("unicycle", kUnicycleParameterKeys));

  // Along a circle of radius 10 at speed 1 (thrust d v = 0.5 holds v = 1; yaw rate 0.1), from
  // half a metre aside with a heading error.
  const std::string text = R"(
[model]
kind = "unicycle"
d = 0.5
[horizon]
tf = 30.0
[desired]
q0 = [0.0, 0.0, 0.0, 1.0]
u1 = 0.5
u2 = 0.1
[controller]
gamma = 10.0
[initial]
q0 = [0.0, 0.5, 0.3, 1.0]
)";
  const hinf::Scenario scenario = hinf::parse_scenario_toml(text, "unicycle.toml");
  ASSERT_NE(dynamic_cast<const Unicycle*>(scenario.model.get()), nullptr);
  const hinf::RunResult result = hinf::run_scenario(scenario);
  EXPECT_EQ(result.simulation.status, hinf::RunStatus::Completed);
  EXPECT_LT(result.metrics.final_position_error, 0.05 * 0.5);  // the 0.5 m offset decays
  // Written back as its kind, with its parameter; read back to the same model.
  const std::string written = hinf::scenario_toml(scenario);
  EXPECT_TRUE(contains(written, "kind = \"unicycle\"") && contains(written, "d = 0.5")) << written;
  EXPECT_TRUE(hinf::parse_scenario_toml(written, "written.toml").model->same_as(*scenario.model));
  // The kind is in the table: its key is named as its own, its checks reach the file.
  EXPECT_TRUE(contains(reader_error("kind = \"ship\"\nd = 0.5"), "is a key of kind = \"hovercraft\" or kind = \"unicycle\""));
  EXPECT_TRUE(contains(reader_error("kind = \"unicycle\"\nd = -1.0"), "[model] Unicycle: the drag d must be > 0"));
  // A name is registered once.
  EXPECT_THROW(hinf::register_model_kind(hinf::parameter_kind<Unicycle, UnicycleParameters>("unicycle", kUnicycleParameterKeys)),
               hinf::InputError);
}

}  // namespace
