// The built-in vehicles written out by hand in C++, as the library had them before their
// equations became CasADi generated code (models/builtin_vehicle.hpp): the reference that
// bench_builtin_vehicles.cpp times the generated equations against. Not used by the library.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/models/vehicles.hpp"

namespace handwritten {

using hinf::ConstVecRef;
using hinf::Mat;
using hinf::MatRef;
using hinf::Vec;
using hinf::VecRef;

// The measurement of every vehicle: position and heading (or roll angle), y = q[indices].
inline Mat pick_rows(int x, int y, int heading) {
  Mat C = Mat::Zero(3, 6);
  C(0, x) = C(1, y) = C(2, heading) = 1.0;
  return C;
}

// Zero n x 6 with the identity (or `block`) on rows first..first+2 of w1..w3: the process
// disturbance; w4..w6 (measurement noise) have zero columns.
inline Mat disturbance_on_rows(int first, const Mat& block) {
  Mat D = Mat::Zero(6, 6);
  D.block(first, 0, 3, 3) = block;
  return D;
}

// Kinematics eta_dot = R(psi) nu of the body-frame vessels (FossenVessel, Auv), q = [u, v, r,
// x, y, psi]: rows 3..5 of f and of df/dq.
inline void body_kinematics(const ConstVecRef& q, VecRef f) {
  const double u = q[0], v = q[1], r = q[2], c = std::cos(q[5]), s = std::sin(q[5]);
  f[3] = u * c - v * s;
  f[4] = u * s + v * c;
  f[5] = r;
}

inline void body_kinematics_jacobian(const ConstVecRef& q, MatRef J) {
  const double u = q[0], v = q[1], c = std::cos(q[5]), s = std::sin(q[5]);
  J(3, 0) = c;
  J(3, 1) = -s;
  J(3, 5) = -u * s - v * c;
  J(4, 0) = s;
  J(4, 1) = c;
  J(4, 5) = u * c - v * s;
  J(5, 2) = 1.0;
}

class Ship final : public hinf::Model {
 public:
  explicit Ship(const hinf::ShipParameters& parameters = {}) : p_(parameters) {
  }
  std::string name() const override { return "ship"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  std::vector<std::string> state_names() const override { return {"u", "v", "r", "x", "y", "psi"}; }
  std::vector<int> position_indices() const override { return {3, 4}; }
  int heading_index() const override { return 5; }
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  void f(double, const ConstVecRef& q, VecRef out) const override {
    const double u = q[0], v = q[1], r = q[2];
    out[0] = p_.m_u * v * r - p_.d_u * u;
    out[1] = p_.m_v * u * r - p_.d_v * v;
    out[2] = p_.m_r * u * v - p_.d_r * r;
    body_kinematics(q, out);
  }
  void dfdq(double, const ConstVecRef& q, MatRef J) const override {
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
    body_kinematics_jacobian(q, J);
  }
  Mat G(double, const ConstVecRef&) const override {
    Mat B = Mat::Zero(6, 2);
    B(0, 0) = 1.0;
    B(2, 1) = 1.0;
    return B;
  }
  Mat D(double, const ConstVecRef&) const override {
    Mat D = Mat::Zero(6, 6);
    D(0, 0) = D(1, 1) = D(2, 2) = 1.0;
    return D;
  }
  void error_split(double, const ConstVecRef& q_d, const ConstVecRef&, const ConstVecRef& q_e, MatRef A,
                            VecRef alpha) const override {
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
  Mat C(double) const override {
    Mat C = Mat::Zero(3, 6);
    C(0, 3) = C(1, 4) = C(2, 5) = 1.0;
    return C;
  }
 private:
  hinf::ShipParameters p_;
};

class FossenVessel final : public hinf::Model {
 public:
  explicit FossenVessel(const hinf::FossenVesselParameters& parameters = {}) : p_(parameters) {
    M_inverse_ = p_.M.inverse();
  }
  std::string name() const override { return "fossen_vessel"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  std::vector<std::string> state_names() const override { return {"u", "v", "r", "x", "y", "psi"}; }
  std::vector<int> position_indices() const override { return {3, 4}; }
  int heading_index() const override { return 5; }
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  void f(double, const ConstVecRef& q, VecRef out) const override {
    const Eigen::Vector3d nu = q.head<3>();
    const Eigen::Vector3d a = p_.M * nu;
    const double u = nu[0], v = nu[1], r = nu[2];
    const Eigen::Vector3d coriolis(-a[1] * r, a[0] * r, a[1] * u - a[0] * v);
    out.head<3>() = -M_inverse_ * (coriolis + p_.D * nu);
    body_kinematics(q, out);
  }
  void dfdq(double, const ConstVecRef& q, MatRef J) const override {
    const Eigen::Vector3d nu = q.head<3>();
    const Eigen::Vector3d a = p_.M * nu;
    const double u = nu[0], v = nu[1], r = nu[2];
    Eigen::Matrix3d coriolis;
    coriolis.row(0) = -r * p_.M.row(1);
    coriolis.row(1) = r * p_.M.row(0);
    coriolis.row(2) = u * p_.M.row(1) - v * p_.M.row(0);
    coriolis(0, 2) -= a[1];
    coriolis(1, 2) += a[0];
    coriolis(2, 0) += a[1];
    coriolis(2, 1) -= a[0];
    J.setZero();
    J.topLeftCorner(3, 3) = -M_inverse_ * (coriolis + p_.D);
    body_kinematics_jacobian(q, J);
  }
  Mat G(double, const ConstVecRef&) const override {
    Mat G = Mat::Zero(6, 2);
    G.block(0, 0, 3, 1) = M_inverse_.col(0);  // surge force
    G.block(0, 1, 3, 1) = M_inverse_.col(2);  // yaw moment (also accelerates sway through m23)
    return G;
  }
  Mat D(double, const ConstVecRef&) const override { return disturbance_on_rows(0, M_inverse_); }
  Mat C(double) const override { return pick_rows(3, 4, 5); }
 private:
  hinf::FossenVesselParameters p_;
  Mat M_inverse_;
};

class Hovercraft final : public hinf::Model {
 public:
  explicit Hovercraft(const hinf::HovercraftParameters& parameters = {}) : p_(parameters) {
  }
  std::string name() const override { return "hovercraft"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  std::vector<std::string> state_names() const override { return {"x", "y", "psi", "vx", "vy", "r"}; }
  std::vector<int> position_indices() const override { return {0, 1}; }
  int heading_index() const override { return 2; }
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  bool constant_input_matrices() const override { return false; }
  bool state_dependent_inputs() const override { return true; }
  void f(double, const ConstVecRef& q, VecRef out) const override {
    out[0] = q[3];
    out[1] = q[4];
    out[2] = q[5];
    out[3] = -p_.d * q[3];
    out[4] = -p_.d * q[4];
    out[5] = -p_.d_r * q[5];
  }
  void dfdq(double, const ConstVecRef&, MatRef J) const override {
    J.setZero();
    J(0, 3) = J(1, 4) = J(2, 5) = 1.0;
    J(3, 3) = J(4, 4) = -p_.d;
    J(5, 5) = -p_.d_r;
  }
  Mat G(double, const ConstVecRef& q) const override {
    Mat G = Mat::Zero(6, 2);
    G(3, 0) = std::cos(q[2]);
    G(4, 0) = std::sin(q[2]);
    G(5, 1) = 1.0;
    return G;
  }
  void dGudq(double, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const override {
    out.setZero();
    out(3, 2) = -u[0] * std::sin(q[2]);
    out(4, 2) = u[0] * std::cos(q[2]);
  }
  Mat D(double, const ConstVecRef&) const override { return disturbance_on_rows(3, Mat::Identity(3, 3)); }
  Mat C(double) const override { return pick_rows(0, 1, 2); }
 private:
  hinf::HovercraftParameters p_;
};

class PlanarVtol final : public hinf::Model {
 public:
  explicit PlanarVtol(const hinf::PlanarVtolParameters& parameters = {}) : p_(parameters) {
  }
  std::string name() const override { return "pvtol"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  std::vector<std::string> state_names() const override { return {"x", "y", "theta", "x_dot", "y_dot", "theta_dot"}; }
  std::vector<int> position_indices() const override { return {0, 1}; }
  int heading_index() const override { return 2; }
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  bool constant_input_matrices() const override { return false; }
  bool state_dependent_inputs() const override { return true; }
  void f(double, const ConstVecRef& q, VecRef out) const override {
    out[0] = q[3];
    out[1] = q[4];
    out[2] = q[5];
    out[3] = 0.0;
    out[4] = -p_.g;
    out[5] = 0.0;
  }
  void dfdq(double, const ConstVecRef&, MatRef J) const override {
    J.setZero();
    J(0, 3) = J(1, 4) = J(2, 5) = 1.0;
  }
  Mat G(double, const ConstVecRef& q) const override {
    const double c = std::cos(q[2]), s = std::sin(q[2]);
    Mat G = Mat::Zero(6, 2);
    G(3, 0) = -s;
    G(3, 1) = p_.epsilon * c;
    G(4, 0) = c;
    G(4, 1) = p_.epsilon * s;
    G(5, 1) = 1.0;
    return G;
  }
  void dGudq(double, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const override {
    const double c = std::cos(q[2]), s = std::sin(q[2]);
    out.setZero();
    out(3, 2) = -u[0] * c - p_.epsilon * u[1] * s;
    out(4, 2) = -u[0] * s + p_.epsilon * u[1] * c;
  }
  Mat D(double, const ConstVecRef&) const override { return disturbance_on_rows(3, Mat::Identity(3, 3)); }
  Mat C(double) const override { return pick_rows(0, 1, 2); }
 private:
  hinf::PlanarVtolParameters p_;
};

class Auv final : public hinf::Model {
 public:
  explicit Auv(const hinf::AuvParameters& parameters = {}) : p_(parameters) {
  }
  std::string name() const override { return "auv"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  std::vector<std::string> state_names() const override { return {"u", "v", "r", "x", "y", "psi"}; }
  std::vector<int> position_indices() const override { return {3, 4}; }
  int heading_index() const override { return 5; }
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  void f(double, const ConstVecRef& q, VecRef out) const override {
    const double u = q[0], v = q[1], r = q[2];
    out[0] = (p_.m22 * v * r - p_.X_u * u - p_.X_uu * std::abs(u) * u) / p_.m11;
    out[1] = (-p_.m11 * u * r - p_.Y_v * v - p_.Y_vv * std::abs(v) * v) / p_.m22;
    out[2] = ((p_.m11 - p_.m22) * u * v - p_.N_r * r - p_.N_rr * std::abs(r) * r) / p_.m33;
    body_kinematics(q, out);
  }
  void dfdq(double, const ConstVecRef& q, MatRef J) const override {
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
    body_kinematics_jacobian(q, J);
  }
  Mat G(double, const ConstVecRef&) const override {
    Mat G = Mat::Zero(6, 2);
    G(0, 0) = 1.0 / p_.m11;
    G(2, 1) = 1.0 / p_.m33;
    return G;
  }
  Mat D(double, const ConstVecRef&) const override {
    return disturbance_on_rows(0, Mat(Eigen::Vector3d(1.0 / p_.m11, 1.0 / p_.m22, 1.0 / p_.m33).asDiagonal()));
  }
  Mat C(double) const override { return pick_rows(3, 4, 5); }
 private:
  hinf::AuvParameters p_;
};

}  // namespace handwritten
