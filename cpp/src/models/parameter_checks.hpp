// The checks of the built-in vehicles' parameters (private to the models layer): each failure is
// an InputError naming the vehicle, the parameter and what it must be.
#pragma once

#include <cmath>
#include <string>

#include "hinf/core/errors.hpp"
#include "hinf/core/types.hpp"

namespace hinf::detail {

inline void check_nonnegative(double value, const std::string& model, const char* name, const char* what) {
  require(std::isfinite(value) && value >= 0.0, model, ": the ", what, " ", name, " must be finite and >= 0, got ",
          value, "; set ", name, " >= 0 (0 for none)");
}

inline void check_positive(double value, const std::string& model, const char* name, const char* what) {
  require(std::isfinite(value) && value > 0.0, model, ": the ", what, " ", name, " must be finite and > 0, got ",
          value, "; give the ", what, " in its units (> 0)");
}

// The smallest eigenvalue of the symmetric part of a square matrix.
inline double smallest_symmetric_eigenvalue(const Mat& A) {
  Eigen::SelfAdjointEigenSolver<Mat> eig(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  return eig.eigenvalues()(0);
}

}  // namespace hinf::detail
