#include "numerics/lyapunov_newton.hpp"

#include <cmath>
#include <cstddef>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

// LAPACK (Fortran calling convention; the hidden lengths of character arguments are passed).
extern "C" {
void dgees_(const char* jobvs, const char* sort, int (*select)(const double*, const double*), const int* n,
            double* a, const int* lda, int* sdim, double* wr, double* wi, double* vs, const int* ldvs,
            double* work, const int* lwork, int* bwork, int* info, std::size_t jobvs_len, std::size_t sort_len);
}

namespace hinf::detail {

LyapunovNewton::LyapunovNewton(int n)
    : n_(n), U_(n, n), T_(n, n), A_(n, n), C_(n, n), work_(n, n), real_(static_cast<std::size_t>(n)),
      imag_(static_cast<std::size_t>(n)) {
  // The workspace size LAPACK asks for.
  int lwork = -1, sdim = 0, info = 0;
  double query = 0.0;
  dgees_("V", "N", nullptr, &n_, T_.data(), &n_, &sdim, real_.data(), imag_.data(), U_.data(), &n_, &query, &lwork,
         nullptr, &info, 1, 1);
  lapack_work_.resize(static_cast<std::size_t>(std::max(1.0, query)) + static_cast<std::size_t>(3 * n));
}

void LyapunovNewton::factor(const Mat& M_cl) {
  check_finite(M_cl, "the Riccati equation's closed-loop matrix M - S X");
  T_ = M_cl;
  const int lwork = static_cast<int>(lapack_work_.size());
  int sdim = 0, info = 0;
  dgees_("V", "N", nullptr, &n_, T_.data(), &n_, &sdim, real_.data(), imag_.data(), U_.data(), &n_,
         lapack_work_.data(), &lwork, nullptr, &info, 1, 1);
  if (info != 0)
    throw SolverError(str_cat("LAPACK dgees (the Schur form of the Riccati Jacobian) failed with info = ", info),
                      NAN, "LAPACK_DGEES");
  // The diagonal blocks of T: 2 x 2 where the subdiagonal is nonzero (a complex pair), else 1.
  blocks_.clear();
  for (int j = 0; j < n_;) {
    const int size = j + 1 < n_ && T_(j + 1, j) != 0.0 ? 2 : 1;
    blocks_.push_back({j, size});
    j += size;
  }
  ++factorizations_;
}

// Solves A' Y + Y A = C for symmetric Y (into C) with A upper quasi-triangular (the blocks of
// blocks_): column block by column block (Bartels-Stewart). For column block J, with the columns
// before it known, (A' (x) I + I (x) A_JJ') vec(Y_J) = C_J - Y_<J A_<J,J is lower block triangular
// in the row blocks I of A': each row block is a small Sylvester equation A_II' X + X A_JJ = R of
// at most 4 unknowns. The rows above J are known by symmetry, so only the rows from J on are
// solved. false if one of the small equations is singular.
bool LyapunovNewton::solve_quasi_triangular(const Mat& A, Mat& C) {
  for (const Block& J : blocks_) {
    const int j = J.start, s = J.size;
    auto Y_J = C.middleCols(j, s);
    for (int q = 0; q < s && j > 0; ++q) {
      // Y is symmetric: rows above the block are the solved columns' rows j + q ...
      Y_J.col(q).head(j) = C.row(j + q).head(j).transpose();
      // ... and only the rows from j on are unknown.
      Y_J.col(q).tail(n_ - j).noalias() -= C.block(j, 0, n_ - j, j) * A.col(j + q).head(j);
    }
    for (const Block& I : blocks_) {
      const int i = I.start, r = I.size;
      if (i < j) continue;
      // (A' Y_J)(i + p, q) over the rows already known: a column of A dotted with them.
      for (int q = 0; q < s && i > 0; ++q)
        for (int p = 0; p < r; ++p) Y_J(i + p, q) -= A.col(i + p).head(i).dot(Y_J.col(q).head(i));
      if (r == 1 && s == 1) {  // the usual case: a scalar equation
        const double diagonal = A(i, i) + A(j, j);
        if (diagonal == 0.0) return false;
        Y_J(i, 0) /= diagonal;
        continue;
      }
      // A_II' X + X A_JJ = R_IJ as (I_s (x) A_II' + A_JJ' (x) I_r) vec(X) = vec(R), at most 4 x 4.
      const int m = r * s;
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4> K = Eigen::Matrix4d::Zero().topLeftCorner(m, m);
      Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1> rhs(m);
      for (int q = 0; q < s; ++q)
        for (int p = 0; p < r; ++p) {
          for (int pp = 0; pp < r; ++pp) K(q * r + p, q * r + pp) += A(i + pp, i + p);  // (A_II')(p, pp)
          for (int qq = 0; qq < s; ++qq) K(q * r + p, qq * r + p) += A(j + qq, j + q);  // (A_JJ')(q, qq)
          rhs(q * r + p) = Y_J(i + p, q);
        }
      const auto lu = K.fullPivLu();
      if (!lu.isInvertible()) return false;
      const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1> x = lu.solve(rhs);
      for (int q = 0; q < s; ++q)
        for (int p = 0; p < r; ++p) Y_J(i + p, q) = x(q * r + p);
    }
  }
  return C.allFinite();
}

bool LyapunovNewton::solve(double gamma_s, const double* b, double* x) {
  // A_T = I/2 - gamma_s T keeps T's quasi-triangular canonical form.
  A_ = -gamma_s * T_;
  A_.diagonal().array() += 0.5;
  unpack_symmetric(b, work_);
  C_.noalias() = U_.transpose() * work_;
  work_.noalias() = C_ * U_;
  if (!solve_quasi_triangular(A_, work_)) return false;
  C_.noalias() = U_ * work_;
  work_.noalias() = C_ * U_.transpose();
  // The solution is symmetric up to round-off: pack the mean of the two triangles.
  int k = 0;
  for (int j = 0; j < n_; ++j)
    for (int i = 0; i <= j; ++i) x[k++] = 0.5 * (work_(i, j) + work_(j, i));
  return true;
}

}  // namespace hinf::detail
