#include "hinf/control/discrete_output_feedback.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/resources.hpp"

namespace hinf {

DiscreteOutputFeedback::DiscreteOutputFeedback(DiscreteDesignPtr design, Mat C, Mat R, Mat Q, std::vector<Mat> Sigma,
                                               std::vector<double> rho)
    : design_(std::move(design)), C_(std::move(C)), R_(std::move(R)), Q_(std::move(Q)), Sigma_(std::move(Sigma)),
      rho_(std::move(rho)) {
  require(design_ != nullptr, "the digital output feedback needs its design");
  require(static_cast<int>(Sigma_.size()) == steps() + 1 && static_cast<int>(rho_.size()) == steps() + 1,
          "the digital output feedback of ", steps(), " samples needs ", steps() + 1, " matrices Sigma_k and ratios");
}

const Mat& DiscreteOutputFeedback::Sigma(int k) const {
  require(k >= 0 && k <= steps(), "Sigma_k is defined for k = 0 .. ", steps(), ", got k = ", k);
  return Sigma_[static_cast<std::size_t>(k)];
}

double DiscreteOutputFeedback::coupling(int k) const {
  require(k >= 0 && k <= steps(), "the coupling ratio is defined for k = 0 .. ", steps(), ", got k = ", k);
  return rho_[static_cast<std::size_t>(k)];
}

double DiscreteOutputFeedback::largest_coupling() const { return *std::max_element(rho_.begin(), rho_.end()); }

DiscreteOutputFeedbackPtr solve_discrete_output_feedback(const DiscreteDesignPtr& design, const Mat& C, const Mat& R,
                                                         const Mat& Sigma0, const Mat& Q) {
  require(design != nullptr, "the digital output feedback needs a discrete design (solve_discrete_game)");
  const int n = design->n(), N = design->steps();
  require(C.cols() == n && C.rows() >= 1 && C.allFinite(), "C must be a finite p x ", n, " matrix (p >= 1), got ",
          C.rows(), " x ", C.cols());
  const int p = static_cast<int>(C.rows());
  check_symmetric_weight(R, p, "R (the covariance of one measurement)", true);
  check_symmetric_weight(Sigma0, n, "Sigma0", true);
  check_symmetric_weight(Q, n, "Q", false);
  check_memory(8.0 * (N + 1.0) * n * n, str_cat("the digital output feedback of ", N, " samples"),
               "choose a longer period (or a shorter horizon)");
  const double gamma = design->gamma(), T = design->period();
  const double inv_gamma2 = std::isinf(gamma) ? 0.0 : 1.0 / (gamma * gamma);
  const Mat I = Mat::Identity(n, n);
  // C' R^-1 C - gamma^-2 T Q: what a measured sample adds to Sigma^-1.
  const Mat information = C.transpose() * R.llt().solve(C) - inv_gamma2 * T * Q;
  std::vector<Mat> Sigma;
  std::vector<double> rho;
  Sigma.reserve(static_cast<std::size_t>(N) + 1);
  rho.reserve(static_cast<std::size_t>(N) + 1);
  Sigma.push_back(0.5 * (Sigma0 + Sigma0.transpose()));
  for (int k = 0;; ++k) {
    const Mat& S = Sigma.back();
    const double t = design->time(k);
    // (c): rho(Sigma_k M_k) = the largest eigenvalue of L' M_k L, Sigma_k = L L'.
    Eigen::LLT<Mat> chol(S);
    if (chol.info() != Eigen::Success)
      throw ConjugatePointError(str_cat("the discrete H-infinity filter escapes at t = ", t, " (k = ", k,
                                        "): Sigma_k is no longer positive definite at gamma = ", gamma,
                                        "; increase gamma, or decrease Sigma0"),
                                t, gamma);
    const Mat L = chol.matrixL();
    const Mat LtML = L.transpose() * design->M(k) * L;
    const double r = Eigen::SelfAdjointEigenSolver<Mat>(0.5 * (LtML + LtML.transpose()), Eigen::EigenvaluesOnly)
                         .eigenvalues()
                         .maxCoeff();
    rho.push_back(r * inv_gamma2);
    if (!(r * inv_gamma2 < 1.0))
      throw CouplingConditionError(
          str_cat("the coupling condition of the digital output feedback fails at t = ", t, " (k = ", k,
                  "): rho(Sigma_k M_k) = ", r, " >= gamma^2 = ", gamma * gamma, "; increase gamma, or decrease Sigma0"),
          t, r, gamma);
    if (k == N) break;
    // (b): Pi_k^-1 = Sigma_k^-1 + C' R^-1 C - gamma^-2 T Q > 0.
    const Mat Pi_inverse = chol.solve(I) + information;
    Eigen::LLT<Mat> pi_chol(0.5 * (Pi_inverse + Pi_inverse.transpose()));
    if (pi_chol.info() != Eigen::Success)
      throw ConjugatePointError(str_cat("the discrete H-infinity filter does not exist at t = ", t, " (k = ", k,
                                        "): Sigma_k^-1 + C' R^-1 C - gamma^-2 T Q is not positive definite at gamma = ",
                                        gamma, "; increase gamma, or decrease Sigma0 or R"),
                                t, gamma);
    const Mat Pi = pi_chol.solve(I);
    const Mat& A = design->sampled().A(k);
    const Mat& D = design->sampled().D(k);
    Mat next = A * Pi * A.transpose() + D * D.transpose() / T;
    Sigma.push_back(0.5 * (next + next.transpose()));
  }
  return std::make_shared<const DiscreteOutputFeedback>(design, C, R, Q, std::move(Sigma), std::move(rho));
}

}  // namespace hinf
