#include "hinf/models/vehicles.hpp"

#include <cmath>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

namespace {

// The measurement of every vehicle: position and heading (or roll angle), y = q[indices].
Mat pick_rows(int x, int y, int heading) {
  Mat C = Mat::Zero(3, 6);
  C(0, x) = C(1, y) = C(2, heading) = 1.0;
  return C;
}

// Zero n x 6 with the identity (or `block`) on rows first..first+2 of w1..w3: the process
// disturbance; w4..w6 (measurement noise) have zero columns.
Mat disturbance_on_rows(int first, const Mat& block) {
  Mat D = Mat::Zero(6, 6);
  D.block(first, 0, 3, 3) = block;
  return D;
}

void check_nonnegative(double value, const std::string& model, const char* name, const char* what) {
  require(std::isfinite(value) && value >= 0.0, model, ": the ", what, " ", name, " must be finite and >= 0, got ",
          value, "; set ", name, " >= 0 (0 for none)");
}

void check_positive(double value, const std::string& model, const char* name, const char* what) {
  require(std::isfinite(value) && value > 0.0, model, ": the ", what, " ", name, " must be finite and > 0, got ",
          value, "; give the ", what, " in its units (> 0)");
}

// The smallest eigenvalue of the symmetric part of a 3 x 3 matrix.
double smallest_symmetric_eigenvalue(const Mat& A) {
  Eigen::SelfAdjointEigenSolver<Mat> eig(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  return eig.eigenvalues()(0);
}

// Kinematics eta_dot = R(psi) nu of the body-frame vessels (FossenVessel, Auv), q = [u, v, r,
// x, y, psi]: rows 3..5 of f and of df/dq.
void body_kinematics(const ConstVecRef& q, VecRef f) {
  const double u = q[0], v = q[1], r = q[2], c = std::cos(q[5]), s = std::sin(q[5]);
  f[3] = u * c - v * s;
  f[4] = u * s + v * c;
  f[5] = r;
}

void body_kinematics_jacobian(const ConstVecRef& q, MatRef J) {
  const double u = q[0], v = q[1], c = std::cos(q[5]), s = std::sin(q[5]);
  J(3, 0) = c;
  J(3, 1) = -s;
  J(3, 5) = -u * s - v * c;
  J(4, 0) = s;
  J(4, 1) = c;
  J(4, 5) = u * c - v * s;
  J(5, 2) = 1.0;
}

}  // namespace

// ---------------------------------------------------------------------- FossenVessel

Mat FossenVesselParameters::supply_vessel_M() {
  Mat M(3, 3);
  M << 1.1274, 0.0, 0.0,  //
      0.0, 1.8902, -0.0744,  //
      0.0, -0.0744, 0.1278;
  return M;
}

Mat FossenVesselParameters::supply_vessel_D() {
  Mat D(3, 3);
  D << 0.0358, 0.0, 0.0,  //
      0.0, 0.1183, -0.0124,  //
      0.0, -0.0041, 0.0308;
  return D;
}

FossenVessel::FossenVessel(const FossenVesselParameters& parameters) : p_(parameters) {
  check_shape(p_.M, 3, 3, "the FossenVessel mass matrix M");
  check_finite(p_.M, "the FossenVessel mass matrix M");
  check_shape(p_.D, 3, 3, "the FossenVessel damping matrix D");
  check_finite(p_.D, "the FossenVessel damping matrix D");
  const double scale_M = p_.M.cwiseAbs().maxCoeff();
  const double asymmetry = (p_.M - p_.M.transpose()).cwiseAbs().maxCoeff();
  require(asymmetry <= 1e-10 * scale_M, "FossenVessel: the mass matrix M must be symmetric (max |M - M'| = ",
          asymmetry, "): give the same value to M[i][j] and M[j][i] (m23 = m32 for a vessel at rest)");
  const double lambda_M = smallest_symmetric_eigenvalue(p_.M);
  require(lambda_M > 1e-12 * scale_M, "FossenVessel: the mass matrix M must be positive definite, its smallest",
          " eigenvalue is ", lambda_M, ": the masses and inertia (rigid body plus added mass) must be > 0 and",
          " larger than the couplings");
  const double lambda_D = smallest_symmetric_eigenvalue(p_.D);
  require(lambda_D > 1e-12 * p_.D.cwiseAbs().maxCoeff(), "FossenVessel: the damping matrix D must dissipate energy:",
          " its symmetric part (D + D')/2 must be positive definite, its smallest eigenvalue is ", lambda_D,
          "; make the diagonal damping > 0 and larger than the couplings");
  M_inverse_ = p_.M.inverse();
}

// nu_dot = M^-1 (-C(nu) nu - D nu) with C(nu) nu = [-a2 r, a1 r, a2 u - a1 v], a = M nu.
void FossenVessel::f(double, const ConstVecRef& q, VecRef out) const {
  const Eigen::Vector3d nu = q.head<3>();
  const Eigen::Vector3d a = p_.M * nu;
  const double u = nu[0], v = nu[1], r = nu[2];
  const Eigen::Vector3d coriolis(-a[1] * r, a[0] * r, a[1] * u - a[0] * v);
  out.head<3>() = -M_inverse_ * (coriolis + p_.D * nu);
  body_kinematics(q, out);
}

// d(C(nu) nu)/dnu, row by row (M_i the i-th row of M, e_i the unit row vectors):
//   -r M_2 - a2 e_r,   r M_1 + a1 e_r,   u M_2 + a2 e_u - v M_1 - a1 e_v.
void FossenVessel::dfdq(double, const ConstVecRef& q, MatRef J) const {
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

Mat FossenVessel::G(double, const ConstVecRef&) const {
  Mat G = Mat::Zero(6, 2);
  G.block(0, 0, 3, 1) = M_inverse_.col(0);  // surge force
  G.block(0, 1, 3, 1) = M_inverse_.col(2);  // yaw moment (also accelerates sway through m23)
  return G;
}

Mat FossenVessel::D(double, const ConstVecRef&) const { return disturbance_on_rows(0, M_inverse_); }

Mat FossenVessel::C(double) const { return pick_rows(3, 4, 5); }

std::vector<std::pair<std::string, double>> FossenVessel::named_parameters() const {
  std::vector<std::pair<std::string, double>> named;
  append_matrix_parameters(named, "M", p_.M);
  append_matrix_parameters(named, "D", p_.D);
  return named;
}

// ------------------------------------------------------------------------ Hovercraft

Hovercraft::Hovercraft(const HovercraftParameters& parameters) : p_(parameters) {
  check_nonnegative(p_.d, "Hovercraft", "d", "translational damping");
  check_nonnegative(p_.d_r, "Hovercraft", "d_r", "rotational damping");
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

Mat Hovercraft::D(double, const ConstVecRef&) const { return disturbance_on_rows(3, Mat::Identity(3, 3)); }

Mat Hovercraft::C(double) const { return pick_rows(0, 1, 2); }

// ------------------------------------------------------------------------ PlanarVtol

PlanarVtol::PlanarVtol(const PlanarVtolParameters& parameters) : p_(parameters) {
  check_nonnegative(p_.g, "PlanarVtol", "g", "gravity");
  require(std::isfinite(p_.epsilon), "PlanarVtol: the coupling coefficient epsilon must be finite, got ",
          p_.epsilon, "; give a small number (0 for no coupling)");
}

void PlanarVtol::f(double, const ConstVecRef& q, VecRef out) const {
  out[0] = q[3];
  out[1] = q[4];
  out[2] = q[5];
  out[3] = 0.0;
  out[4] = -p_.g;
  out[5] = 0.0;
}

void PlanarVtol::dfdq(double, const ConstVecRef&, MatRef J) const {
  J.setZero();
  J(0, 3) = J(1, 4) = J(2, 5) = 1.0;
}

Mat PlanarVtol::G(double, const ConstVecRef& q) const {
  const double c = std::cos(q[2]), s = std::sin(q[2]);
  Mat G = Mat::Zero(6, 2);
  G(3, 0) = -s;
  G(3, 1) = p_.epsilon * c;
  G(4, 0) = c;
  G(4, 1) = p_.epsilon * s;
  G(5, 1) = 1.0;
  return G;
}

// G(q) u = [0, 0, 0, -u1 s + eps u2 c, u1 c + eps u2 s, u2]: only the theta column.
void PlanarVtol::dGudq(double, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const {
  const double c = std::cos(q[2]), s = std::sin(q[2]);
  out.setZero();
  out(3, 2) = -u[0] * c - p_.epsilon * u[1] * s;
  out(4, 2) = -u[0] * s + p_.epsilon * u[1] * c;
}

Mat PlanarVtol::D(double, const ConstVecRef&) const { return disturbance_on_rows(3, Mat::Identity(3, 3)); }

Mat PlanarVtol::C(double) const { return pick_rows(0, 1, 2); }

// ------------------------------------------------------------------------------- Auv

Auv::Auv(const AuvParameters& parameters) : p_(parameters) {
  check_positive(p_.m11, "Auv", "m11", "surge mass");
  check_positive(p_.m22, "Auv", "m22", "sway mass");
  check_positive(p_.m33, "Auv", "m33", "yaw inertia");
  check_nonnegative(p_.X_u, "Auv", "X_u", "linear surge drag");
  check_nonnegative(p_.X_uu, "Auv", "X_uu", "quadratic surge drag");
  check_nonnegative(p_.Y_v, "Auv", "Y_v", "linear sway drag");
  check_nonnegative(p_.Y_vv, "Auv", "Y_vv", "quadratic sway drag");
  check_nonnegative(p_.N_r, "Auv", "N_r", "linear yaw drag");
  check_nonnegative(p_.N_rr, "Auv", "N_rr", "quadratic yaw drag");
}

void Auv::f(double, const ConstVecRef& q, VecRef out) const {
  const double u = q[0], v = q[1], r = q[2];
  out[0] = (p_.m22 * v * r - p_.X_u * u - p_.X_uu * std::abs(u) * u) / p_.m11;
  out[1] = (-p_.m11 * u * r - p_.Y_v * v - p_.Y_vv * std::abs(v) * v) / p_.m22;
  out[2] = ((p_.m11 - p_.m22) * u * v - p_.N_r * r - p_.N_rr * std::abs(r) * r) / p_.m33;
  body_kinematics(q, out);
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
  body_kinematics_jacobian(q, J);
}

Mat Auv::G(double, const ConstVecRef&) const {
  Mat G = Mat::Zero(6, 2);
  G(0, 0) = 1.0 / p_.m11;
  G(2, 1) = 1.0 / p_.m33;
  return G;
}

Mat Auv::D(double, const ConstVecRef&) const {
  return disturbance_on_rows(0, Mat(Eigen::Vector3d(1.0 / p_.m11, 1.0 / p_.m22, 1.0 / p_.m33).asDiagonal()));
}

Mat Auv::C(double) const { return pick_rows(3, 4, 5); }

}  // namespace hinf
