#include "hinf/models/auv.hpp"

#include <cmath>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "models/vehicle_parts.hpp"

namespace hinf {

Auv::Auv(const AuvParameters& parameters) : p_(parameters) {
  detail::check_positive(p_.m11, "Auv", "m11", "surge mass");
  detail::check_positive(p_.m22, "Auv", "m22", "sway mass");
  detail::check_positive(p_.m33, "Auv", "m33", "yaw inertia");
  detail::check_nonnegative(p_.X_u, "Auv", "X_u", "linear surge drag");
  detail::check_nonnegative(p_.X_uu, "Auv", "X_uu", "quadratic surge drag");
  detail::check_nonnegative(p_.Y_v, "Auv", "Y_v", "linear sway drag");
  detail::check_nonnegative(p_.Y_vv, "Auv", "Y_vv", "quadratic sway drag");
  detail::check_nonnegative(p_.N_r, "Auv", "N_r", "linear yaw drag");
  detail::check_nonnegative(p_.N_rr, "Auv", "N_rr", "quadratic yaw drag");
}

void Auv::f(double, const ConstVecRef& q, VecRef out) const {
  const double u = q[0], v = q[1], r = q[2];
  out[0] = (p_.m22 * v * r - p_.X_u * u - p_.X_uu * std::abs(u) * u) / p_.m11;
  out[1] = (-p_.m11 * u * r - p_.Y_v * v - p_.Y_vv * std::abs(v) * v) / p_.m22;
  out[2] = ((p_.m11 - p_.m22) * u * v - p_.N_r * r - p_.N_rr * std::abs(r) * r) / p_.m33;
  detail::body_kinematics(q, out);
}

void Auv::dfdq(double, const ConstVecRef& q, MatRef J) const {
  const double u = q[0], v = q[1], r = q[2];
  J.setZero();
  J(0, 0) = -(p_.X_u + 2.0 * p_.X_uu * std::abs(u)) / p_.m11;
  J(0, 1) = p_.m22 * r / p_.m11;
  J(0, 2) = p_.m22 * v / p_.m11;
  J(1, 0) = -p_.m11 * r / p_.m22;
  J(1, 1) = -(p_.Y_v + 2.0 * p_.Y_vv * std::abs(v)) / p_.m22;
  J(1, 2) = -p_.m11 * u / p_.m22;
  J(2, 0) = (p_.m11 - p_.m22) * v / p_.m33;
  J(2, 1) = (p_.m11 - p_.m22) * u / p_.m33;
  J(2, 2) = -(p_.N_r + 2.0 * p_.N_rr * std::abs(r)) / p_.m33;
  detail::body_kinematics_jacobian(q, J);
}

Mat Auv::G(double, const ConstVecRef&) const {
  Mat G = Mat::Zero(6, 2);
  G(0, 0) = 1.0 / p_.m11;
  G(2, 1) = 1.0 / p_.m33;
  return G;
}

Mat Auv::D(double, const ConstVecRef&) const {
  return detail::disturbance_on_rows(0, Mat(Eigen::Vector3d(1.0 / p_.m11, 1.0 / p_.m22, 1.0 / p_.m33).asDiagonal()));
}

Mat Auv::C(double) const { return detail::pick_rows(3, 4, 5); }

}  // namespace hinf
