// Private: the right-hand side and Jacobian shared by every matrix Riccati equation here,
//     dX/dt = sign (M' X + X M + R - X S X),
// with X symmetric in packed storage (types.hpp). The GRDE (13) is sign = -1, M = A_e,
// R = Q, S = B B' - gamma^-2 D D'; the filter Riccati equation (36) is sign = +1, M = A',
// R = D D', S = C' N^-1 C - gamma^-2 Q.
#pragma once

#include "hinf/core/types.hpp"

namespace hinf::detail {

// Whether S is diagonal (then S X is a row scaling: the ship's S = B B' - gamma^-2 D D' is).
template <class MatN>
bool is_diagonal(const MatN& S) {
  for (Eigen::Index j = 0; j < S.cols(); ++j)
    for (Eigen::Index i = 0; i < S.rows(); ++i)
      if (i != j && S(i, j) != 0.0) return false;
  return true;
}

// M'X + XM + R - XSX = G + G' with G = X (M - S X / 2) + R / 2: two n x n products (one when
// S is diagonal: pass diagonal_S). T and G are workspaces of the size of X.
template <class MatN>
void riccati_rhs(double sign, const MatN& M, const MatN& R, const MatN& S, const MatN& X,
                 MatN& T, MatN& G, double* dX, bool diagonal_S = false) {
  if (diagonal_S) T.noalias() = S.diagonal().asDiagonal() * X;
  else T.noalias() = S * X;
  T = M - 0.5 * T;
  G.noalias() = X * T;
  G += 0.5 * R;
  const int n = static_cast<int>(X.rows());
  int k = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= j; ++i) dX[k++] = sign * (G(i, j) + G(j, i));
}

// d(dX/dt)/dX in packed coordinates (column-major, packed_size(n) squared). For the unit
// symmetric perturbation E of entry (i, j): d(dX/dt) = sign (E W + W' E), W = M - S X,
// that is sign (P + P') with P = E W.
template <class MatN>
void riccati_jacobian(double sign, const MatN& M, const MatN& S, const MatN& X, MatN& W,
                      MatN& P, double* J) {
  W.noalias() = S * X;
  W = M - W;
  const int n = static_cast<int>(X.rows());
  const int p = packed_size(n);
  P.setZero();
  int column = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= j; ++i, ++column) {
      P.row(i) = W.row(j);
      if (i != j) P.row(j) = W.row(i);
      double* Jc = J + static_cast<std::size_t>(column) * p;
      int row = 0;
      for (int l = 0; l < n; ++l)
        for (int k = 0; k <= l; ++k) Jc[row++] = sign * (P(k, l) + P(l, k));
      P.row(i).setZero();
      P.row(j).setZero();
    }
}

}  // namespace hinf::detail
