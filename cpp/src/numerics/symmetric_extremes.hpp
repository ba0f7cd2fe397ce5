// Private: the smallest and largest eigenvalue of a small symmetric matrix, several times
// cheaper than a full eigen-decomposition (it runs at every output time of a simulation).
//
// Householder tridiagonalization T = Q' A Q, then Laguerre's method on the characteristic
// polynomial g(x) = det(x I - T), started at the Gershgorin bounds: for a polynomial with
// only real roots, Laguerre's iteration started beyond the extreme root converges to it
// monotonically and cubically, multiple roots included. g'/g and (g'/g)' come from the
// LDL' recurrence of T - x I: q_1 = d_1 - x, q_i = d_i - x - e_{i-1}^2 / q_{i-1}.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace hinf::detail {

// Laguerre iteration from x0 beyond the extreme root (direction -1 from above for the largest
// root, +1 from below for the smallest).
template <class VecD, class VecE>
double laguerre_extreme_root(const VecD& d, const VecE& e, double x0, double scale) {
  const int n = static_cast<int>(d.size());
  const double tiny = std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon();
  double x = x0;
  for (int iteration = 0; iteration < 60; ++iteration) {
    // G = g'/g = sum q_i'/q_i, H = -dG/dx = sum_i (q_i'^2 - q_i'' q_i) / q_i^2.
    double G = 0.0, H = 0.0;
    double q_prev = 1.0, dq_prev = 0.0, ddq_prev = 0.0;
    for (int i = 0; i < n; ++i) {
      double q = d[i] - x, dq = -1.0, ddq = 0.0;
      if (i > 0) {
        const double e2 = e[i - 1] * e[i - 1];
        const double inv = 1.0 / q_prev;
        q -= e2 * inv;
        dq += e2 * dq_prev * inv * inv;
        ddq += e2 * (ddq_prev * inv * inv - 2.0 * dq_prev * dq_prev * inv * inv * inv);
      }
      if (std::abs(q) < tiny) q = std::copysign(tiny, q == 0.0 ? 1.0 : q);
      const double r = dq / q;
      G += r;
      H += r * r - ddq / q;
      q_prev = q;
      dq_prev = dq;
      ddq_prev = ddq;
    }
    // prod q_i = det(T - x I) = (-1)^n g(x), so g'/g = sum q_i'/q_i = G and -(g'/g)' = H.
    const double radicand = std::max(0.0, (n - 1) * (n * H - G * G));
    const double root = std::sqrt(radicand);
    const double denominator = G >= 0.0 ? G + root : G - root;
    if (denominator == 0.0 || !std::isfinite(denominator)) break;
    const double step = n / denominator;
    const double x_new = x - step;
    if (!std::isfinite(x_new)) break;
    const bool done = std::abs(x_new - x) <= 4.0 * std::numeric_limits<double>::epsilon() * (std::abs(x) + scale);
    x = x_new;
    if (done) break;
  }
  return x;
}

// Tridiagonal form (d, e) of A and the Gershgorin bounds of its spectrum.
template <class MatN>
struct TridiagonalForm {
  explicit TridiagonalForm(const MatN& A) : tri(A), n(static_cast<int>(A.rows())) {
    const auto d = tri.diagonal();
    const auto e = tri.subDiagonal();
    for (int i = 0; i < n; ++i) {
      const double radius = (i > 0 ? std::abs(e[i - 1]) : 0.0) + (i + 1 < n ? std::abs(e[i]) : 0.0);
      lo = std::min(lo, d[i] - radius);
      hi = std::max(hi, d[i] + radius);
      scale = std::max(scale, std::abs(d[i]) + radius);
    }
    // Start strictly outside the spectrum.
    margin = 1e-12 * std::max(scale, std::numeric_limits<double>::min());
  }
  double largest() const { return laguerre_extreme_root(tri.diagonal(), tri.subDiagonal(), hi + margin, scale); }
  double smallest() const { return laguerre_extreme_root(tri.diagonal(), tri.subDiagonal(), lo - margin, scale); }

  Eigen::Tridiagonalization<MatN> tri;
  int n;
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  double scale = 0.0, margin = 0.0;
};

// The extremes are computed on A / max |a_ij| and scaled back, so that entries beyond 1e154
// (whose squares overflow in the recurrence) are handled.
template <class MatN>
void symmetric_eigen_extremes(const MatN& A, double& lambda_min, double& lambda_max) {
  if (A.rows() == 1) {
    lambda_min = lambda_max = A(0, 0);
    return;
  }
  const double scale = A.cwiseAbs().maxCoeff();
  if (!(scale > 0.0) || !std::isfinite(scale)) {  // zero, or not finite: nothing to scale
    const TridiagonalForm<MatN> form(A);
    lambda_max = form.largest();
    lambda_min = form.smallest();
    return;
  }
  const TridiagonalForm<MatN> form(A / scale);
  lambda_max = scale * form.largest();
  lambda_min = scale * form.smallest();
}

template <class MatN>
double symmetric_eigen_max(const MatN& A) {
  double lo = 0.0, hi = 0.0;
  symmetric_eigen_extremes(A, lo, hi);
  return hi;
}

// The spectral radius of Sigma Z for symmetric positive semidefinite Sigma and Z: the largest
// eigenvalue of L' Sigma L with Z = L L' (or of L' Z L with Sigma = L L'). A factor that is
// semidefinite only (a solution that decayed to about zero) is replaced by its eigenvalues
// clamped at zero. sigma_work, z_work and product are workspaces of A's size.
template <class MatN>
double spectral_radius_of_product(const MatN& Sigma, const MatN& Z, MatN& factor, MatN& product) {
  Eigen::LLT<MatN> llt(Z);
  const MatN* other = &Sigma;
  if (llt.info() != Eigen::Success) {
    llt.compute(Sigma);
    other = &Z;
  }
  if (llt.info() == Eigen::Success) {
    factor = llt.matrixL();
  } else {
    const Eigen::SelfAdjointEigenSolver<MatN> eig(Sigma);
    factor = eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
    other = &Z;
  }
  product.noalias() = factor.transpose() * (*other) * factor;
  return std::max(0.0, symmetric_eigen_max(product));
}

}  // namespace hinf::detail
