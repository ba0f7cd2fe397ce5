// A library of underactuated vehicles (docs/vehicles.md), each a Model with an analytic
// Jacobian, for tracking studies beyond the paper's ship (ship.hpp):
//
//   FossenVessel  3-DOF surface vessel in Fossen's matrix form (supply vessel preset)
//   Hovercraft    planar hovercraft in inertial coordinates (input matrix depends on the heading)
//   PlanarVtol    the planar VTOL aircraft of Hauser, Sastry and Meyer (input matrix depends on
//                 the roll angle)
//   Auv           AUV in the horizontal plane with quadratic drag (Sirene preset)
//
// State orders and units, fixed here once:
//   FossenVessel, Auv: q = [u, v, r, x, y, psi] (the ship's order): surge and sway speed in the
//       body frame, yaw rate, inertial position, heading. FossenVessel is in Fossen's
//       dimensionless bis units (length L, time sqrt(L / g), mass of the ship); Auv in SI
//       (m/s, rad/s, m, rad; inputs in N and N m).
//   Hovercraft: q = [x, y, psi, vx, vy, r]: inertial position (m), heading (rad), inertial
//       velocity (m/s), yaw rate (rad/s); inputs per unit mass (m/s^2) and inertia (rad/s^2).
//   PlanarVtol: q = [x, y, theta, x_dot, y_dot, theta_dot]: lateral and vertical position, roll
//       angle (rad), their rates; normalized units (gravity g, 1 by default).
//
// Common to all four: m = 2 inputs (one short of the 3 degrees of freedom); nw = 6: w1..w3 are
// process disturbances on the three velocity equations (forces and moment where the model has
// masses), w4..w6 the measurement-noise channels (D has zero columns there); the measurement is
// y = C q = [x, y, heading] (position and heading or roll angle), noise on w4..w6; the tracking
// error of the heading (roll) angle is wrapped. The error split is the Model default and there
// is no analytic remainder bound (NaN: certificates use their sampled estimate).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/model.hpp"

namespace hinf {

// ---------------------------------------------------------------------- FossenVessel
// Fossen's 3-DOF horizontal-plane model (T. I. Fossen, Handbook of Marine Craft Hydrodynamics
// and Motion Control, Wiley, 2011):
//     M nu_dot + C(nu) nu + D nu = B_tau tau + w,    eta_dot = R(psi) nu,
// nu = [u, v, r], eta = [x, y, psi], tau = [tau_u, tau_r] (surge force, yaw moment; no sway
// force: B_tau = [[1, 0], [0, 0], [0, 1]]), M symmetric positive definite (rigid body plus added
// mass), C(nu) its Coriolis-centripetal matrix in the skew-symmetric form
//     C(nu) = [[0, 0, -a2], [0, 0, a1], [a2, -a1, 0]],   [a1, a2, a3] = M nu,
// (for M = [[m11, 0, 0], [0, m22, m23], [0, m23, m33]]: a1 = m11 u, a2 = m22 v + m23 r), and
// linear damping D whose symmetric part is positive definite (D itself need not be symmetric).
// So f = [M^-1 (-C(nu) nu - D nu); R(psi) nu], G = [M^-1 B_tau; 0] (constant; the yaw moment
// also accelerates sway through m23), and the disturbance w1..w3 enters as forces: D_w =
// [M^-1; 0] on w1..w3.
struct FossenVesselParameters {
  // Defaults: the supply vessel (supply_vessel()).
  Mat M = supply_vessel_M();  // mass matrix, 3 x 3, symmetric positive definite
  Mat D = supply_vessel_D();  // linear damping, 3 x 3, (D + D') / 2 positive definite

  // The supply vessel of Fossen, Sagatun and Sorensen, "Identification of dynamically
  // positioned ships", Control Engineering Practice 4(3), 369-376, 1996, in bis units
  // (length L = 76.2 m, mass 6000 t):
  //   M = [[1.1274, 0, 0], [0, 1.8902, -0.0744], [0, -0.0744, 0.1278]],
  //   D = [[0.0358, 0, 0], [0, 0.1183, -0.0124], [0, -0.0041, 0.0308]].
  static FossenVesselParameters supply_vessel() { return {}; }
  static Mat supply_vessel_M();
  static Mat supply_vessel_D();
};

class FossenVessel final : public Model {
 public:
  // InputError unless M and D are finite 3 x 3 matrices, M symmetric positive definite and the
  // symmetric part of D positive definite.
  explicit FossenVessel(const FossenVesselParameters& parameters = {});
  const FossenVesselParameters& parameters() const { return p_; }
  // M[i][j] and D[i][j], the entries of [model] M and D.
  std::vector<std::pair<std::string, double>> named_parameters() const override;
  bool same_as(const Model& other) const override { return same_type_and_parameters(*this, other); }

  std::string name() const override { return "fossen_vessel"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  void f(double t, const ConstVecRef& q, VecRef out) const override;
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override;
  Mat G(double t, const ConstVecRef& q) const override;
  Mat D(double t, const ConstVecRef& q) const override;
  Mat C(double t) const override;
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  std::vector<std::string> state_names() const override { return {"u", "v", "r", "x", "y", "psi"}; }
  std::vector<int> position_indices() const override { return {3, 4}; }
  int heading_index() const override { return 5; }

 private:
  FossenVesselParameters p_;
  Mat M_inverse_;
};

// ------------------------------------------------------------------------ Hovercraft
// A planar hovercraft in inertial coordinates (the model of Aguiar, Cremean and Hespanha,
// "Position tracking for a nonlinear underactuated hovercraft: controller design and
// experimental results", IEEE CDC 2003; and of Fantoni, Lozano, Mazenc and Pettersen,
// "Stabilization of a nonlinear underactuated hovercraft", Int. J. Robust Nonlinear Control
// 10(8), 2000), with inputs per unit mass and inertia, u = [F, T]:
//     dvx/dt = F cos(psi) - d vx + w1,   dvy/dt = F sin(psi) - d vy + w2,   dr/dt = T - d_r r + w3,
//     dx/dt = vx,   dy/dt = vy,   dpsi/dt = r.
// No force across the body axis: the thrust acts along the heading. G depends on psi.
struct HovercraftParameters {
  double d = 0.2;    // translational damping per unit mass (1/s), >= 0
  double d_r = 0.5;  // rotational damping per unit inertia (1/s), >= 0
};
// The parameters by their scenario-file keys (the reader, the writer, named_parameters()).
inline constexpr std::array<std::pair<const char*, double HovercraftParameters::*>, 2> kHovercraftParameterKeys{
    {{"d", &HovercraftParameters::d}, {"d_r", &HovercraftParameters::d_r}}};

class Hovercraft final : public Model {
 public:
  // InputError unless d and d_r are finite and >= 0.
  explicit Hovercraft(const HovercraftParameters& parameters = {});
  const HovercraftParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kHovercraftParameterKeys);
  }
  bool same_as(const Model& other) const override { return same_type_and_parameters(*this, other); }

  std::string name() const override { return "hovercraft"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  void f(double t, const ConstVecRef& q, VecRef out) const override;
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override;
  Mat G(double t, const ConstVecRef& q) const override;
  Mat D(double t, const ConstVecRef& q) const override;
  bool constant_input_matrices() const override { return false; }
  bool state_dependent_inputs() const override { return true; }
  void dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const override;
  Mat C(double t) const override;
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  std::vector<std::string> state_names() const override { return {"x", "y", "psi", "vx", "vy", "r"}; }
  std::vector<int> position_indices() const override { return {0, 1}; }
  int heading_index() const override { return 2; }

 private:
  HovercraftParameters p_;
};

// ------------------------------------------------------------------------ PlanarVtol
// The planar vertical take-off and landing aircraft of Hauser, Sastry and Meyer, "Nonlinear
// control design for slightly non-minimum phase systems: application to V/STOL aircraft",
// Automatica 28(4), 665-679, 1992, in their normalized form, u = [u1, u2] (thrust, rolling
// moment):
//     x_ddot = -u1 sin(theta) + epsilon u2 cos(theta) + w1,
//     y_ddot =  u1 cos(theta) + epsilon u2 sin(theta) - g + w2,
//     theta_ddot = u2 + w3.
// Gravity is part of f; G depends on theta. epsilon couples the rolling moment into the lateral
// acceleration (the slightly non-minimum-phase effect).
struct PlanarVtolParameters {
  double g = 1.0;        // gravity (1: the normalized form), >= 0
  double epsilon = 0.1;  // coupling of the rolling moment into the translation, finite
};
// The parameters by their scenario-file keys (the reader, the writer, named_parameters()).
inline constexpr std::array<std::pair<const char*, double PlanarVtolParameters::*>, 2> kPlanarVtolParameterKeys{
    {{"g", &PlanarVtolParameters::g}, {"epsilon", &PlanarVtolParameters::epsilon}}};

class PlanarVtol final : public Model {
 public:
  // InputError unless g is finite and >= 0 and epsilon finite.
  explicit PlanarVtol(const PlanarVtolParameters& parameters = {});
  const PlanarVtolParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kPlanarVtolParameterKeys);
  }
  bool same_as(const Model& other) const override { return same_type_and_parameters(*this, other); }

  std::string name() const override { return "pvtol"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  void f(double t, const ConstVecRef& q, VecRef out) const override;
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override;
  Mat G(double t, const ConstVecRef& q) const override;
  Mat D(double t, const ConstVecRef& q) const override;
  bool constant_input_matrices() const override { return false; }
  bool state_dependent_inputs() const override { return true; }
  void dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const override;
  Mat C(double t) const override;
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  std::vector<std::string> state_names() const override {
    return {"x", "y", "theta", "x_dot", "y_dot", "theta_dot"};
  }
  std::vector<int> position_indices() const override { return {0, 1}; }
  int heading_index() const override { return 2; }

 private:
  PlanarVtolParameters p_;
};

// ------------------------------------------------------------------------------- Auv
// An underactuated AUV in the horizontal plane with linear and quadratic drag (diagonal mass
// matrix; no sway thrust), u = [tau_u, tau_r] (N, N m):
//     m11 u_dot = m22 v r - X_u u - X_uu |u| u + tau_u + w1,
//     m22 v_dot = -m11 u r - Y_v v - Y_vv |v| v + w2,
//     m33 r_dot = (m11 - m22) u v - N_r r - N_rr |r| r + tau_r + w3,
//     x_dot = u cos(psi) - v sin(psi),   y_dot = u sin(psi) + v cos(psi),   psi_dot = r.
// |u| u is continuously differentiable (derivative 2 |u|), so the analytic Jacobian exists
// everywhere; its second derivative jumps at zero speed.
struct AuvParameters {
  // Defaults: the Sirene AUV (sirene()).
  double m11 = 215.0;  // kg, > 0 (mass plus added mass in surge)
  double m22 = 265.0;  // kg, > 0 (sway)
  double m33 = 80.0;   // kg m^2, > 0 (yaw)
  double X_u = 70.0;   // kg/s, >= 0
  double X_uu = 100.0; // kg/m, >= 0
  double Y_v = 100.0;  // kg/s, >= 0
  double Y_vv = 200.0; // kg/m, >= 0
  double N_r = 50.0;   // kg m^2/s, >= 0
  double N_rr = 100.0; // kg m^2, >= 0

  // The Sirene AUV as in Aguiar and Pascoal, "Dynamic positioning and way-point tracking of
  // underactuated AUVs in the presence of ocean currents", Int. J. Control 80(7), 1092-1108,
  // 2007 (the defaults above).
  static AuvParameters sirene() { return {}; }
};
// The parameters by their scenario-file keys (the reader, the writer, named_parameters()).
inline constexpr std::array<std::pair<const char*, double AuvParameters::*>, 9> kAuvParameterKeys{
    {{"m11", &AuvParameters::m11},
     {"m22", &AuvParameters::m22},
     {"m33", &AuvParameters::m33},
     {"X_u", &AuvParameters::X_u},
     {"X_uu", &AuvParameters::X_uu},
     {"Y_v", &AuvParameters::Y_v},
     {"Y_vv", &AuvParameters::Y_vv},
     {"N_r", &AuvParameters::N_r},
     {"N_rr", &AuvParameters::N_rr}}};

class Auv final : public Model {
 public:
  // InputError unless the masses are finite and > 0 and the drag coefficients finite and >= 0.
  explicit Auv(const AuvParameters& parameters = {});
  const AuvParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kAuvParameterKeys);
  }
  bool same_as(const Model& other) const override { return same_type_and_parameters(*this, other); }

  std::string name() const override { return "auv"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  void f(double t, const ConstVecRef& q, VecRef out) const override;
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override;
  Mat G(double t, const ConstVecRef& q) const override;
  Mat D(double t, const ConstVecRef& q) const override;
  Mat C(double t) const override;
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  std::vector<std::string> state_names() const override { return {"u", "v", "r", "x", "y", "psi"}; }
  std::vector<int> position_indices() const override { return {3, 4}; }
  int heading_index() const override { return 5; }

 private:
  AuvParameters p_;
};

}  // namespace hinf
