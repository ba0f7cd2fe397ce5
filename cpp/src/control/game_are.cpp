// The stationary game Riccati equation (riccati.hpp: solve_game_are) by the matrix sign function
// of its Hamiltonian.
//
// H = [A, -S; -Q, -A'] with S = B B' - gamma^-2 D D'. When H has no eigenvalue on the imaginary
// axis, sign(H) = W splits R^2n into its stable (W = -I) and unstable (W = +I) invariant
// subspaces; the stabilizing solution P spans the stable one as [I; P], so (W + I) [I; P] = 0:
//     [W12; W22 + I] P = -[W11 + I; W21],
// an overdetermined, consistent system solved by QR. The sign is the limit of Newton's iteration
// Z <- (c Z + (c Z)^-1) / 2 from Z = H, with Byers' determinant scaling c = |det Z|^(-1/2n),
// which converges quadratically after a few steps (Byers 1987, Linear Algebra Appl. 85).
// Small n (the vehicles have n <= 48): dense LU and QR are what the job needs.
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>

#include "hinf/control/riccati.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

Mat solve_game_are(const Mat& A, const Mat& B, const Mat& D, const Mat& Q, double gamma) {
  const Eigen::Index n = A.rows();
  require(n > 0 && A.cols() == n, "the game ARE needs a square A, got ", A.rows(), " x ", A.cols());
  require(B.rows() == n && D.rows() == n, "the game ARE needs B and D with ", n, " rows (A's), got ", B.rows(),
          " and ", D.rows());
  check_symmetric_weight(Q, static_cast<int>(n), "Q", false);
  require(gamma > 0.0, "gamma must be > 0 (may be inf), got ", gamma);
  require(A.allFinite() && B.allFinite() && D.allFinite(), "the game ARE's A, B and D must be finite");

  Mat S = B * B.transpose();
  if (std::isfinite(gamma)) S -= (D * D.transpose()) / (gamma * gamma);
  const Eigen::Index N = 2 * n;
  Mat Z(N, N);
  Z << A, -S, -Q, -A.transpose();

  // Newton's iteration for the sign, with determinant scaling until it has nearly converged.
  constexpr int kMaxIterations = 100;
  bool scale = true, converged = false;
  for (int k = 0; k < kMaxIterations && !converged; ++k) {
    const Eigen::PartialPivLU<Mat> lu(Z);
    double log_det = 0.0;
    bool singular = false;
    for (Eigen::Index i = 0; i < N; ++i) {
      const double d = std::abs(lu.matrixLU()(i, i));
      if (!(d > 0.0) || !std::isfinite(d)) singular = true;
      else log_det += std::log(d);
    }
    if (singular) break;
    const double c = scale ? std::exp(-log_det / static_cast<double>(N)) : 1.0;
    Mat next = 0.5 * (c * Z + lu.inverse() / c);
    if (!next.allFinite()) break;
    const double change = (next - Z).lpNorm<1>(), size = next.lpNorm<1>();
    Z = std::move(next);
    if (change <= 1e-2 * size) scale = false;  // near the limit the scaling only slows it down
    converged = change <= 1e-13 * size;
  }
  const std::string advice =
      std::isfinite(gamma) ? " (gamma is at or below the stationary game's gamma*: raise gamma)"
                           : " ((A, B) is not stabilizable or (A, Q) has an unobservable mode on the imaginary axis)";
  require(converged, "the game ARE has no stabilizing solution: its Hamiltonian has eigenvalues on or near the"
          " imaginary axis", advice);

  Mat lhs(N, n), rhs(N, n);
  lhs << Z.topRightCorner(n, n), Z.bottomRightCorner(n, n) + Mat::Identity(n, n);
  rhs << Z.topLeftCorner(n, n) + Mat::Identity(n, n), Z.bottomLeftCorner(n, n);
  Mat P = lhs.colPivHouseholderQr().solve(-rhs);
  P = 0.5 * (P + P.transpose()).eval();
  require(P.allFinite(), "the game ARE has no stabilizing solution (the stable subspace is not a graph [I; P])",
          advice);

  // The answer checked: the residual relative to its terms, and a closed loop A - S P that is stable.
  const Mat residual = A.transpose() * P + P * A + Q - P * S * P;
  const double terms = Q.norm() + 2.0 * A.norm() * P.norm() + S.norm() * P.squaredNorm();
  require(residual.norm() <= 1e-8 * std::max(terms, std::numeric_limits<double>::min()),
          "the game ARE's solution is inaccurate (relative residual ", residual.norm() / terms, ")", advice);
  const Eigen::VectorXcd poles = (A - S * P).eigenvalues();
  require(poles.real().maxCoeff() < 0.0, "the game ARE has no stabilizing solution (closed-loop pole with real part ",
          poles.real().maxCoeff(), ")", advice);
  // Below the game's gamma* the stabilizing solution may exist but is indefinite: no cost-to-go.
  const double smallest = Eigen::SelfAdjointEigenSolver<Mat>(P, Eigen::EigenvaluesOnly).eigenvalues()(0);
  require(smallest >= -1e-9 * std::max(1.0, P.norm()), "the game ARE's stabilizing solution is indefinite (smallest"
          " eigenvalue ", smallest, ")", advice);
  return P;
}

}  // namespace hinf
