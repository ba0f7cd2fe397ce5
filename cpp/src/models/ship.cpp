#include "hinf/models/ship.hpp"

#include <cmath>

#include "hinf/core/checks.hpp"
#include "models/compiled_in.hpp"

namespace hinf {

namespace {

const ShipParameters& checked(const ShipParameters& p) {
  for (const auto& [key, member] : kShipParameterKeys) check_finite(p.*member, key);
  return p;
}

}  // namespace

ShipModel::ShipModel(const ShipParameters& parameters)
    : BuiltinVehicle(detail::compiled_in_model(hinf_ship_model, named_parameters_of(checked(parameters),
                                                                                      kShipParameterKeys))),
      p_(parameters) {}

// The remainder r = f(q_d + e) - f(q_d) - A_e e of the ship, e = (e_u, e_v, e_r, e_x, e_y, e_psi):
//   r_u = m_u e_v e_r,  r_v = m_v e_u e_r,  r_r = m_r e_u e_v,  r_psi = 0,
//   r_xy = [R(psi_d + e_psi) - R(psi_d) - R'(psi_d) e_psi] (u_d, v_d) + [R(psi_d + e_psi) - R(psi_d)] (e_u, e_v)
// with R the rotation by psi. For rotations |R(a + b) - R(a) - R'(a) b| = |e^{ib} - 1 - ib| <= b^2/2
// and |R(a + b) - R(a)| <= |b|; and |e_i e_j| <= |e|^2 / 2. Hence, with s_d = |(u_d, v_d)|,
//   |r|^2 <= |e|^4 / 4 (m_u^2 + m_v^2 + m_r^2 + (s_d + 1)^2)   for every e (any radius).
double ShipModel::remainder_bound(double, const ConstVecRef& q_d, double) const {
  const double speed = std::hypot(q_d[0], q_d[1]);
  return 0.5 * std::sqrt(p_.m_u * p_.m_u + p_.m_v * p_.m_v + p_.m_r * p_.m_r + (speed + 1.0) * (speed + 1.0));
}

}  // namespace hinf
