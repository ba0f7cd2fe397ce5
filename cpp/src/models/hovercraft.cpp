#include "hinf/models/hovercraft.hpp"

#include <cmath>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "models/vehicle_parts.hpp"

namespace hinf {

Hovercraft::Hovercraft(const HovercraftParameters& parameters) : p_(parameters) {
  detail::check_nonnegative(p_.d, "Hovercraft", "d", "translational damping");
  detail::check_nonnegative(p_.d_r, "Hovercraft", "d_r", "rotational damping");
}

void Hovercraft::f(double, const ConstVecRef& q, VecRef out) const {
  out[0] = q[3];
  out[1] = q[4];
  out[2] = q[5];
  out[3] = -p_.d * q[3];
  out[4] = -p_.d * q[4];
  out[5] = -p_.d_r * q[5];
}

void Hovercraft::dfdq(double, const ConstVecRef&, MatRef J) const {
  J.setZero();
  J(0, 3) = J(1, 4) = J(2, 5) = 1.0;
  J(3, 3) = J(4, 4) = -p_.d;
  J(5, 5) = -p_.d_r;
}

Mat Hovercraft::G(double, const ConstVecRef& q) const {
  Mat G = Mat::Zero(6, 2);
  G(3, 0) = std::cos(q[2]);
  G(4, 0) = std::sin(q[2]);
  G(5, 1) = 1.0;
  return G;
}

// G(q) u = [0, 0, 0, F cos(psi), F sin(psi), T]: only the psi column.
void Hovercraft::dGudq(double, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const {
  out.setZero();
  out(3, 2) = -u[0] * std::sin(q[2]);
  out(4, 2) = u[0] * std::cos(q[2]);
}

Mat Hovercraft::D(double, const ConstVecRef&) const { return detail::disturbance_on_rows(3, Mat::Identity(3, 3)); }

Mat Hovercraft::C(double) const { return detail::pick_rows(0, 1, 2); }

}  // namespace hinf
