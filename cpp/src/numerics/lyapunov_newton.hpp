// Private: the Newton systems of an implicit method applied to a matrix Riccati equation,
// solved as Lyapunov equations in O(n^3) instead of O(n^6).
//
// For dX/dt = s (M'X + X M + R - X S X) (riccati_kernel.hpp) the Jacobian acts on a symmetric
// perturbation E as J E = s (M_cl' E + E M_cl), M_cl = M - S X. A Newton system of a BDF step,
// (I - gamma J) E = B, is therefore the Lyapunov equation
//     A' E + E A = B,   A = I/2 - gamma s M_cl.
// With the real Schur form M_cl = U T U' (LAPACK dgees, T quasi-upper-triangular in canonical
// form), A = U (I/2 - gamma s T) U' and the equation becomes
//     A_T' Y + Y A_T = U' B U,   E = U Y U',   A_T = I/2 - gamma s T,
// solved column block by column block (Bartels-Stewart, as LAPACK dtrsyl but with Eigen's
// vectorized block products instead of one call per element, several times faster here). The
// Schur form does not depend on gamma: it is computed when M_cl is refreshed and serves every
// gamma until the next refresh. Costs: the Schur form about 25 n^3 flops, a solve about 10 n^3
// (four n x n products and the quasi-triangular solve). The dense alternative factors a
// Jacobian of n(n+1)/2 unknowns: n^6 / 24.
#pragma once

#include <vector>

#include "hinf/core/types.hpp"

namespace hinf::detail {

class LyapunovNewton {
 public:
  explicit LyapunovNewton(int n);
  int n() const { return n_; }

  // The closed-loop matrix M_cl (n x n, column-major) of the current Jacobian; its Schur form
  // serves the solves until the next call. InputError if M_cl is not finite, SolverError if
  // LAPACK fails.
  void factor(const Mat& M_cl);
  // E = (I - gamma_s J)^-1 B for packed symmetric B (types.hpp), gamma_s = gamma * s; x and b
  // may alias. false if the Lyapunov equation is (numerically) singular: 1 = gamma_s (mu_i +
  // mu_j) for eigenvalues mu of M_cl (the step size should then change).
  bool solve(double gamma_s, const double* b, double* x);

  long factorizations() const { return factorizations_; }

 private:
  struct Block {
    int start, size;  // a diagonal block of the quasi-triangular Schur form: 1 x 1 or 2 x 2
  };
  bool solve_quasi_triangular(const Mat& A, Mat& C);

  int n_;
  Mat U_, T_, A_, C_, work_;
  std::vector<Block> blocks_;
  std::vector<double> lapack_work_, real_, imag_;
  long factorizations_ = 0;
};

}  // namespace hinf::detail
