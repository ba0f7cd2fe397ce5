// Private: where does a symmetric-matrix-valued polynomial stop being positive definite?
//
// W(theta) = sum_j c_j theta^j on [0, 1] (a DensePiece of packed symmetric matrices,
// types.hpp). A test of W at sample points alone can step over a short dip of the smallest
// eigenvalue below zero (a tangential conjugate point). This search cannot, for the polynomial:
// on [a, b], with L the linear interpolant of W between the ends,
//     lambda_min(W(theta)) >= min(lambda_min(W(a)), lambda_min(W(b))) - ||W - L||_2
//                          >= min(lambda_min(W(a)), lambda_min(W(b))) - K (b - a)^2 / 8,
// (lambda_min is concave, and the interpolation error of a C^2 function is bounded by
// (b - a)^2 / 8 times the largest second derivative) where
//     K = sum_{j >= 2} j (j - 1) ||c_j||_F >= max_theta ||W''(theta)||_2.
// So [a, b] is certified positive definite when W(a) - beta I and W(b) - beta I, beta =
// K (b - a)^2 / 8, both have a Cholesky factorization; otherwise the interval is halved, left
// half first, which finds the FIRST loss of definiteness.
#pragma once

#include <Eigen/Cholesky>
#include <cmath>
#include <vector>

#include "hinf/core/types.hpp"
#include "hinf/numerics/dense_piece.hpp"

namespace hinf::detail {

template <int N>
class DefinitenessSearch {
 public:
  using MatN = Eigen::Matrix<double, N, N>;

  explicit DefinitenessSearch(int n) : n_(n), W_(n, n), llt_(n), values_(static_cast<std::size_t>(packed_size(n))) {}

  // The first theta in (0, 1] at which W(theta) is not positive definite (to a resolution of
  // 2^-kMaxDepth), or NaN if W stays positive definite on the piece. W(0) is assumed positive
  // definite (the previous step's end). A non-finite value counts as a loss of definiteness.
  double first_loss(const DensePiece& piece) {
    piece_ = &piece;
    curvature_ = 0.0;
    for (int j = 2; j <= piece.degree; ++j)
      curvature_ += j * (j - 1) * packed_frobenius(piece.coeffs + static_cast<long>(j) * piece.dim);
    evaluations_ = 0;
    return search(0.0, 1.0, 0);
  }

  // Whether W(theta) - shift I is positive definite.
  bool definite_at(const DensePiece& piece, double theta, double shift = 0.0) {
    piece.eval(theta, values_.data());
    for (double v : values_)
      if (!std::isfinite(v)) return false;
    unpack_symmetric(values_.data(), W_);
    if (shift != 0.0) W_.diagonal().array() -= shift;
    llt_.compute(W_);
    return llt_.info() == Eigen::Success;
  }

 private:
  static constexpr int kMaxDepth = 40;
  static constexpr int kMaxEvaluations = 4096;

  double search(double a, double b, int depth) {
    const double shift = curvature_ * (b - a) * (b - a) / 8.0;
    evaluations_ += 2;
    if (definite_at(*piece_, a, shift) && definite_at(*piece_, b, shift)) return NAN;
    // At the resolution limit (or out of budget) only the end point decides: a dip narrower
    // than that, if any, is below what the dense output resolves.
    if (depth >= kMaxDepth || evaluations_ >= kMaxEvaluations) return definite_at(*piece_, b) ? NAN : b;
    const double mid = 0.5 * (a + b);
    const double left = search(a, mid, depth + 1);
    if (!std::isnan(left)) return left;
    return search(mid, b, depth + 1);
  }

  // Frobenius norm of the symmetric matrix stored packed at p.
  double packed_frobenius(const double* p) const {
    double sum = 0.0;
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i <= j; ++i) {
        const double v = p[packed_index(i, j)];
        sum += (i == j ? 1.0 : 2.0) * v * v;
      }
    return std::sqrt(sum);
  }

  int n_;
  const DensePiece* piece_ = nullptr;
  double curvature_ = 0.0;
  int evaluations_ = 0;
  MatN W_;
  Eigen::LLT<MatN> llt_;
  std::vector<double> values_;
};

}  // namespace hinf::detail
