#include "hinf/models/fossen_vessel.hpp"

#include <cmath>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "models/vehicle_parts.hpp"

namespace hinf {

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
  const double lambda_M = detail::smallest_symmetric_eigenvalue(p_.M);
  require(lambda_M > 1e-12 * scale_M, "FossenVessel: the mass matrix M must be positive definite, its smallest",
          " eigenvalue is ", lambda_M, ": the masses and inertia (rigid body plus added mass) must be > 0 and",
          " larger than the couplings");
  const double lambda_D = detail::smallest_symmetric_eigenvalue(p_.D);
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
  detail::body_kinematics(q, out);
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
  detail::body_kinematics_jacobian(q, J);
}

Mat FossenVessel::G(double, const ConstVecRef&) const {
  Mat G = Mat::Zero(6, 2);
  G.block(0, 0, 3, 1) = M_inverse_.col(0);  // surge force
  G.block(0, 1, 3, 1) = M_inverse_.col(2);  // yaw moment (also accelerates sway through m23)
  return G;
}

Mat FossenVessel::D(double, const ConstVecRef&) const { return detail::disturbance_on_rows(0, M_inverse_); }

Mat FossenVessel::C(double) const { return detail::pick_rows(3, 4, 5); }

std::vector<std::pair<std::string, double>> FossenVessel::named_parameters() const {
  std::vector<std::pair<std::string, double>> named;
  append_matrix_parameters(named, "M", p_.M);
  append_matrix_parameters(named, "D", p_.D);
  return named;
}

}  // namespace hinf
