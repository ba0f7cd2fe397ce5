#include "hinf/models/ship.hpp"

#include <cmath>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "models/vehicle_parts.hpp"

namespace hinf {

ShipModel::ShipModel(const ShipParameters& parameters) : p_(parameters) {
  check_finite(p_.m_u, "m_u");
  check_finite(p_.m_v, "m_v");
  check_finite(p_.m_r, "m_r");
  check_finite(p_.d_u, "d_u");
  check_finite(p_.d_v, "d_v");
  check_finite(p_.d_r, "d_r");
}

void ShipModel::f(double, const ConstVecRef& q, VecRef out) const {
  const double u = q[0], v = q[1], r = q[2];
  out[0] = p_.m_u * v * r - p_.d_u * u;
  out[1] = p_.m_v * u * r - p_.d_v * v;
  out[2] = p_.m_r * u * v - p_.d_r * r;
  detail::body_kinematics(q, out);
}

void ShipModel::dfdq(double, const ConstVecRef& q, MatRef J) const {
  const double u = q[0], v = q[1], r = q[2];
  J.setZero();
  J(0, 0) = -p_.d_u;
  J(0, 1) = p_.m_u * r;
  J(0, 2) = p_.m_u * v;
  J(1, 0) = p_.m_v * r;
  J(1, 1) = -p_.d_v;
  J(1, 2) = p_.m_v * u;
  J(2, 0) = p_.m_r * v;
  J(2, 1) = p_.m_r * u;
  J(2, 2) = -p_.d_r;
  detail::body_kinematics_jacobian(q, J);
}

Mat ShipModel::G(double, const ConstVecRef&) const {
  Mat B = Mat::Zero(6, 2);
  B(0, 0) = 1.0;
  B(2, 1) = 1.0;
  return B;
}

Mat ShipModel::D(double, const ConstVecRef&) const {
  Mat D = Mat::Zero(6, 6);
  D(0, 0) = D(1, 1) = D(2, 2) = 1.0;
  return D;
}

// docs/mathematics.md, "Imperfect measurements": q1 = [u, v, x, y] (indices 0, 1, 3, 4) and
// q2 = [r, psi] (indices 2, 5), all errors; psi = psi_d + psi_e, r = r_d + r_e.
void ShipModel::error_split(double, const ConstVecRef& q_d, const ConstVecRef&, const ConstVecRef& q_e, MatRef A,
                            VecRef alpha) const {
  const double ud = q_d[0], vd = q_d[1], rd = q_d[2], psid = q_d[5];
  const double ue = q_e[0], ve = q_e[1], re = q_e[2], psie = q_e[5];
  const double psi = psid + psie;
  const double c = std::cos(psi), s = std::sin(psi), cd = std::cos(psid), sd = std::sin(psid);

  // alpha1(q2) and alpha2(q1) of the decomposition (docs/mathematics.md).
  const double alpha1_u = p_.m_u * vd * re;
  const double alpha1_v = p_.m_v * ud * re;
  const double alpha1_x = ud * (c - cd) - vd * (s - sd);
  const double alpha1_y = ud * (s - sd) + vd * (c - cd);
  const double alpha2_r = p_.m_r * (ue * vd + ud * ve + ue * ve);
  // A12 = d alpha1 / d q2 at q2 = 0, A21 = d alpha2 / d q1 at q1 = 0.
  const double A12_u_r = p_.m_u * vd, A12_v_r = p_.m_v * ud;
  const double A12_x_psi = -ud * sd - vd * cd, A12_y_psi = ud * cd - vd * sd;
  const double A21_r_u = p_.m_r * vd, A21_r_v = p_.m_r * ud;

  A.setZero();
  // Rows of q1: A11(q2) on (u, v, x, y), A12 on (r, psi).
  A(0, 0) = -p_.d_u;
  A(0, 1) = p_.m_u * (rd + re);
  A(0, 2) = A12_u_r;
  A(1, 0) = p_.m_v * (rd + re);
  A(1, 1) = -p_.d_v;
  A(1, 2) = A12_v_r;
  A(3, 0) = c;
  A(3, 1) = -s;
  A(3, 5) = A12_x_psi;
  A(4, 0) = s;
  A(4, 1) = c;
  A(4, 5) = A12_y_psi;
  // Rows of q2: A21 on (u, v, x, y), A22 = [[-d_r, 0], [1, 0]] on (r, psi).
  A(2, 0) = A21_r_u;
  A(2, 1) = A21_r_v;
  A(2, 2) = -p_.d_r;
  A(5, 2) = 1.0;

  alpha[0] = alpha1_u - A12_u_r * re;
  alpha[1] = alpha1_v - A12_v_r * re;
  alpha[3] = alpha1_x - A12_x_psi * psie;
  alpha[4] = alpha1_y - A12_y_psi * psie;
  alpha[2] = alpha2_r - (A21_r_u * ue + A21_r_v * ve);
  alpha[5] = 0.0;
}

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

Mat ShipModel::C(double) const {
  Mat C = Mat::Zero(3, 6);
  C(0, 3) = C(1, 4) = C(2, 5) = 1.0;
  return C;
}

std::vector<std::string> ShipModel::state_names() const {
  return {"u", "v", "r", "x", "y", "psi"};
}

}  // namespace hinf
