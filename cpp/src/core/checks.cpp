#include "hinf/core/checks.hpp"

#include <cmath>

#include "hinf/core/errors.hpp"

namespace hinf {

void check_dimension(long long value, int min, const std::string& name) {
  require(value >= min && value <= kMaxDimension, name, " must be in [", min, ", ", kMaxDimension,
          "], got ", value);
}

void check_finite(double value, const std::string& name) {
  require(std::isfinite(value), name, " must be finite, got ", value);
}

void check_finite(const ConstMatRef& M, const std::string& name) {
  for (Eigen::Index j = 0; j < M.cols(); ++j)
    for (Eigen::Index i = 0; i < M.rows(); ++i)
      require(std::isfinite(M(i, j)), name, " has a non-finite entry ", M(i, j), " at (", i, ", ",
              j, ")");
}

void check_shape(const ConstMatRef& M, int rows, int cols, const std::string& name) {
  require(M.rows() == rows && M.cols() == cols, "Incompatible dimensions of ", name,
          ": expected (", rows, ", ", cols, ") but found (", M.rows(), ", ", M.cols(), ")");
}

void check_size(const ConstVecRef& v, int size, const std::string& name) {
  require(v.size() == size, "Incompatible length of ", name, ": expected ", size, " but found ",
          v.size());
  check_finite(v, name);
}

void check_symmetric_weight(const ConstMatRef& M, int n, const std::string& name,
                            bool definite) {
  require(n >= 1, name, " must be at least 1 x 1, the problem has n = ", n);
  check_shape(M, n, n, name);
  check_finite(M, name);
  // Relative to the matrix's own size, so that a tiny weight (1e-12 I) is as valid as I.
  const double scale = M.cwiseAbs().maxCoeff();
  const double asym = (M - M.transpose()).cwiseAbs().maxCoeff();
  require(asym <= 1e-10 * scale, name, " must be symmetric: max |", name, " - ", name,
          "'| = ", asym, "; pass (M + M')/2 if the asymmetry is round-off");
  Eigen::SelfAdjointEigenSolver<Mat> eig(0.5 * (M + M.transpose()), Eigen::EigenvaluesOnly);
  const double lambda_min = eig.eigenvalues()(0);
  if (definite) {
    require(lambda_min > 1e-12 * scale, name,
            " must be positive definite: its smallest eigenvalue is ", lambda_min);
  } else {
    require(lambda_min >= -1e-12 * scale, name,
            " must be positive semidefinite: its smallest eigenvalue is ", lambda_min);
  }
}

void check_horizon(double t0, double tf) {
  check_finite(t0, "t0");
  check_finite(tf, "tf");
  require(tf > t0, "the horizon needs tf > t0, got t0 = ", t0, ", tf = ", tf);
}

}  // namespace hinf
