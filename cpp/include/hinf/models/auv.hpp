// An AUV in the horizontal plane with quadratic drag (the Sirene preset).
// State order, units and what the built-in vehicles share: models/vehicles.hpp.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/builtin_vehicle.hpp"
#include "hinf/models/model.hpp"

namespace hinf {

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
  // 2007 (the defaults of the fields).
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

// Its equations are generated from its statement (python/hinf_cpp/models/builtin.py, auv();
// models/builtin_vehicle.hpp).
class Auv final : public BuiltinVehicle {
 public:
  // InputError unless the masses are finite and > 0 and the drag coefficients finite and >= 0.
  explicit Auv(const AuvParameters& parameters = {});
  // The parameters it was made with.
  const AuvParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kAuvParameterKeys);
  }

 private:
  AuvParameters p_;
};

}  // namespace hinf
