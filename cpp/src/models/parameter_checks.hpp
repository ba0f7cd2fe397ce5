// What the built-in vehicles share (private to the models layer): the body-frame kinematics
// and its Jacobian, the measurement of position and heading, the process disturbance on the
// velocity rows, and the checks of their parameters.
#pragma once

#include <cmath>
#include <string>

#include "hinf/core/errors.hpp"
#include "hinf/core/types.hpp"

namespace hinf::detail {

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

inline void check_nonnegative(double value, const std::string& model, const char* name, const char* what) {
  require(std::isfinite(value) && value >= 0.0, model, ": the ", what, " ", name, " must be finite and >= 0, got ",
          value, "; set ", name, " >= 0 (0 for none)");
}

inline void check_positive(double value, const std::string& model, const char* name, const char* what) {
  require(std::isfinite(value) && value > 0.0, model, ": the ", what, " ", name, " must be finite and > 0, got ",
          value, "; give the ", what, " in its units (> 0)");
}

// The smallest eigenvalue of the symmetric part of a 3 x 3 matrix.
inline double smallest_symmetric_eigenvalue(const Mat& A) {
  Eigen::SelfAdjointEigenSolver<Mat> eig(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  return eig.eigenvalues()(0);
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

}  // namespace hinf::detail
