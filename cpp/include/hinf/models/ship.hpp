// The paper's underactuated ship: the model of paper eqs. (1)-(6), with its error split
// (26)-(31) and analytic remainder bound. The cascaded baseline law written for it is
// control/cascade.hpp.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/builtin_vehicle.hpp"
#include "hinf/models/model.hpp"

namespace hinf {

// The underactuated surface ship of paper eqs. (1)-(6) (docs/mathematics.md):
//   state q = [u, v, r, x, y, psi]: surge, sway (m/s), yaw rate (rad/s) in the body frame;
//             inertial position x, y (m) and heading psi (rad);
//   control [u1, u2]: surge force and yaw torque (per unit mass / inertia);
//   disturbance w = [w1..w6]: w1..w3 act on the u, v, r equations (D = diag(1,1,1,0,0,0));
//             w4..w6 are the measurement-noise channels of paper §4 (they enter through E).
//     du/dt   = m_u v r - d_u u + u1 + w1
//     dv/dt   = m_v u r - d_v v      + w2
//     dr/dt   = m_r u v - d_r r + u2 + w3
//     dx/dt   = u cos(psi) - v sin(psi)
//     dy/dt   = u sin(psi) + v cos(psi)
//     dpsi/dt = r
struct ShipParameters {
  double m_u = 0.5;   // coefficient of v r in du/dt (m_u v r), finite
  double m_v = -2.0;  // coefficient of u r in dv/dt (m_v u r), finite
  double m_r = 0.5;   // coefficient of u v in dr/dt (m_r u v), finite
  double d_u = 1.0;   // surge damping (1/s), finite
  double d_v = 2.0;   // sway damping (1/s), finite
  double d_r = 1.0;   // yaw damping (1/s), finite
};
// The parameters by their keys in a scenario file's [model] (and [plant]) section: the reader,
// the writer and ShipModel::named_parameters() go through this one list.
inline constexpr std::array<std::pair<const char*, double ShipParameters::*>, 6> kShipParameterKeys{
    {{"m_u", &ShipParameters::m_u},
     {"m_v", &ShipParameters::m_v},
     {"m_r", &ShipParameters::m_r},
     {"d_u", &ShipParameters::d_u},
     {"d_v", &ShipParameters::d_v},
     {"d_r", &ShipParameters::d_r}}};

// Its equations are generated from its statement (python/hinf_cpp/models/builtin.py, ship();
// models/builtin_vehicle.hpp), the error split (26)-(31) included.
class ShipModel final : public BuiltinVehicle {
 public:
  // InputError unless every parameter is finite.
  explicit ShipModel(const ShipParameters& parameters = {});
  // The parameters it was made with.
  const ShipParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kShipParameterKeys);
  }
  // Global bound (any radius): L = 1/2 sqrt(m_u^2 + m_v^2 + m_r^2 + (|(u_d, v_d)| + 1)^2); see
  // ship.cpp for the derivation.
  double remainder_bound(double t, const ConstVecRef& q_d, double radius) const override;

 private:
  ShipParameters p_;
};

}  // namespace hinf
