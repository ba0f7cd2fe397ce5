#include "hinf/control/discrete_filter.hpp"

#include <cmath>

namespace hinf {

bool discrete_hinf_filter_step(const Mat& P, const Mat& F, const Mat& H, const Mat& Q, const Mat& R_inv,
                               const Mat& S_bar, double gamma, Mat& K, Mat& P_next) {
  const Eigen::Index n = P.rows();
  const double theta = std::isinf(gamma) ? 0.0 : 1.0 / (gamma * gamma);
  const Mat HtRinv = H.transpose() * R_inv;
  // Existence: P^-1 - theta S_bar + H' R^-1 H > 0.
  Eigen::LLT<Mat> P_chol(P);
  if (P_chol.info() != Eigen::Success) return false;
  const Mat information = P_chol.solve(Mat::Identity(n, n)) - theta * S_bar + HtRinv * H;
  Eigen::LLT<Mat> information_chol(0.5 * (information + information.transpose()));
  if (information_chol.info() != Eigen::Success) return false;
  // P [I - theta S_bar P + H' R^-1 H P]^-1 = (P^-1 - theta S_bar + H' R^-1 H)^-1: symmetric.
  Mat PA = information_chol.solve(Mat::Identity(n, n));
  PA = 0.5 * (PA + PA.transpose()).eval();
  K = PA * HtRinv;
  P_next = F * PA * F.transpose() + Q;
  P_next = 0.5 * (P_next + P_next.transpose()).eval();
  return true;
}

}  // namespace hinf
