// A 3-DOF surface vessel in Fossen's matrix form (the supply vessel preset).
// State order, units and what the built-in vehicles share: models/vehicles.hpp.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/builtin_vehicle.hpp"
#include "hinf/models/model.hpp"

namespace hinf {

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

// Its equations are generated from its statement (python/hinf_cpp/models/builtin.py,
// fossen_vessel(); models/builtin_vehicle.hpp), with M^-1 computed once here.
class FossenVessel final : public BuiltinVehicle {
 public:
  // InputError unless M and D are finite 3 x 3 matrices, M symmetric positive definite and the
  // symmetric part of D positive definite.
  explicit FossenVessel(const FossenVesselParameters& parameters = {});
  // The parameters it was made with.
  const FossenVesselParameters& parameters() const { return p_; }
  // M[i][j] and D[i][j], the entries of [model] M and D.
  std::vector<std::pair<std::string, double>> named_parameters() const override;

 private:
  FossenVesselParameters p_;
};

}  // namespace hinf
