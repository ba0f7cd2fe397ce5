// Independent reference computations for the C++ tests (the C++ counterpart of
// tests/python/_support.py). Nothing here calls the code under test: closed forms, a fixed-step
// RK4, the algebraic Riccati equations from the Hamiltonian's stable invariant subspace
// (Eigen's eigen-solvers), the infinite-horizon H-infinity level by bisection, and the ship of
// docs/mathematics.md written out by hand.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <cstdint>
#include <random>

namespace hinf_ref {

using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;

constexpr double kInf = std::numeric_limits<double>::infinity();

// ======================================================================= scalar Riccati

// Solution of dz/dtau = 2 a z + q - s z^2, z(0) = z0. The GRDE (13) backward in tau = tf - t is
// s = b^2 - d^2/gamma^2, q = Q, z0 = Qf; the filter equation (36) forward in tau = t - t0 is
// s = c^2/N - Q/gamma^2, q = d^2, z0 = Sigma0.
// With z = y / x and d/dtau [x; y] = M [x; y], M = [[-a, s], [q, a]], M^2 = (a^2 + s q) I, so
// exp(M tau) = c(tau) I + sg(tau) M with (beta^2 = a^2 + s q)
//     c = cosh(beta tau), sg = sinh(beta tau) / beta     (beta^2 > 0; divided by c: tanh form)
//     c = 1,              sg = tau                      (beta^2 = 0)
//     c = cos(w tau),     sg = sin(w tau) / w           (w^2 = -beta^2 > 0),
// and z = (c z0 + sg (q + a z0)) / (c + sg (s z0 - a)).
inline double scalar_riccati(double a, double s, double q, double z0, double tau) {
  const double beta2 = a * a + s * q;
  if (beta2 > 0.0) {
    const double beta = std::sqrt(beta2);
    const double th = std::tanh(beta * tau) / beta;
    return (z0 + th * (q + a * z0)) / (1.0 + th * (s * z0 - a));
  }
  double c = 1.0, sg = tau;
  if (beta2 < 0.0) {
    const double w = std::sqrt(-beta2);
    c = std::cos(w * tau);
    sg = std::sin(w * tau) / w;
  }
  return (c * z0 + sg * (q + a * z0)) / (c + sg * (s * z0 - a));
}

// The first tau > 0 where x = c - sg k (k = a - s z0) vanishes: the finite escape of z, or
// +inf when there is none.
inline double scalar_escape_tau(double a, double s, double q, double z0) {
  const double beta2 = a * a + s * q;
  const double k = a - s * z0;
  if (beta2 < 0.0) {
    const double w = std::sqrt(-beta2);
    return std::atan2(w, k) / w;  // cot(w tau) = k / w, first root in (0, pi / w)
  }
  if (beta2 == 0.0) return k > 0.0 ? 1.0 / k : kInf;
  const double beta = std::sqrt(beta2);
  return k > beta ? std::atanh(beta / k) / beta : kInf;  // tanh(beta tau) = beta / k
}

// The point where a monotone predicate changes: lo fails (bad(lo)), hi passes; bisection to
// hi - lo <= rtol hi. Returns hi.
inline double bisect_threshold(const std::function<bool(double)>& bad, double lo, double hi,
                               double rtol = 1e-14) {
  while (hi - lo > rtol * hi) {
    const double mid = 0.5 * (lo + hi);
    (bad(mid) ? lo : hi) = mid;
  }
  return hi;
}

// ======================================================================= RK4

// One classical Runge-Kutta step of dx/dt = rhs(t, x) (rhs returns dx/dt).
inline Vec rk4_step(const std::function<Vec(double, const Vec&)>& rhs, double t, const Vec& x, double h) {
  const Vec k1 = rhs(t, x);
  const Vec k2 = rhs(t + 0.5 * h, x + 0.5 * h * k1);
  const Vec k3 = rhs(t + 0.5 * h, x + 0.5 * h * k2);
  const Vec k4 = rhs(t + h, x + h * k3);
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// ======================================================================= algebraic Riccati

// The stabilizing solution of F'X + XF + R - X S X = 0 from the stable invariant subspace of
// H = [[F, -S], [-R, -F']] (eigenvectors [V1; V2] of its n eigenvalues with negative real part,
// X = V2 V1^-1). ok = false when H has an eigenvalue within imag_tol of the imaginary axis, or
// V1 is singular (condition number above cond_max). The filter ARE (36)
// A X + X A' - X S X + D D' = 0 is this with F = A', R = D D'.
struct AreSolution {
  bool ok = false;
  const char* why = "";
  Mat X;
};

inline AreSolution stabilizing_are(const Mat& F, const Mat& S, const Mat& R, double imag_tol = 1e-9,
                                   double cond_max = 1e12) {
  const Eigen::Index n = F.rows();
  Mat H(2 * n, 2 * n);
  H << F, -S, -R, -F.transpose();
  Eigen::EigenSolver<Mat> eig(H);
  AreSolution out;
  if (eig.info() != Eigen::Success) {
    out.why = "eigen-solver failed";
    return out;
  }
  const Eigen::VectorXcd lambda = eig.eigenvalues();
  const double scale = std::max(1.0, lambda.cwiseAbs().maxCoeff());
  Eigen::MatrixXcd V(2 * n, n);
  Eigen::Index k = 0;
  for (Eigen::Index i = 0; i < 2 * n; ++i) {
    if (std::abs(lambda[i].real()) <= imag_tol * scale) {
      out.why = "imaginary";
      return out;
    }
    if (lambda[i].real() < 0.0) {
      if (k == n) {
        out.why = "more than n stable eigenvalues";
        return out;
      }
      V.col(k++) = eig.eigenvectors().col(i);
    }
  }
  if (k != n) {
    out.why = "fewer than n stable eigenvalues";
    return out;
  }
  const Eigen::MatrixXcd V1 = V.topRows(n), V2 = V.bottomRows(n);
  Eigen::JacobiSVD<Eigen::MatrixXcd> svd(V1);
  const double cond = svd.singularValues()(0) / svd.singularValues()(n - 1);
  if (!(cond < cond_max)) {
    out.why = "singular";
    return out;
  }
  // X = V2 V1^-1, i.e. V1' X' = V2'.
  const Eigen::MatrixXcd Xc = V1.transpose().fullPivLu().solve(V2.transpose()).transpose();
  out.X = 0.5 * (Xc.real() + Xc.real().transpose());
  out.ok = true;
  return out;
}

// The game ARE A'X + XA + Q - X (BB' - gamma^-2 DD') X = 0: admissible when the stabilizing
// solution exists and is positive semidefinite.
inline bool game_are_admissible(const Mat& A, const Mat& B, const Mat& D, const Mat& Q, double gamma) {
  const Mat S = B * B.transpose() - D * D.transpose() / (gamma * gamma);
  const AreSolution are = stabilizing_are(A, S, Q);
  if (!are.ok) return false;
  const double lowest = Eigen::SelfAdjointEigenSolver<Mat>(are.X).eigenvalues()(0);
  return lowest >= -1e-10 * std::max(1.0, are.X.cwiseAbs().maxCoeff());
}

// The infinite-horizon full-information H-infinity level of dq/dt = A q + B u + D w with the
// cost |q|_Q^2 + |u|^2: the infimum of the gammas above which the game ARE is admissible. The
// search walks down from gamma_max by the factor `step` to the first inadmissible gamma (one
// admissible interval from the top, not just a sign change), then bisects.
inline double full_information_hinf_level(const Mat& A, const Mat& B, const Mat& D, const Mat& Q,
                                          double gamma_max = 1e3, double step = 1.01, double rtol = 1e-13) {
  double gamma = gamma_max;
  if (!game_are_admissible(A, B, D, Q, gamma)) return kInf;
  while (game_are_admissible(A, B, D, Q, gamma / step)) {
    gamma /= step;
    if (gamma < 1e-9) return 0.0;
  }
  return bisect_threshold([&](double g) { return !game_are_admissible(A, B, D, Q, g); }, gamma / step, gamma, rtol);
}

// ======================================================================= random LTI systems

struct Lti {
  Mat A, B, D, Q;
};

// Seeded random numbers that are the same with every standard library: std::mt19937_64 is
// specified bit for bit, std::normal_distribution and std::uniform_real_distribution are not.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1) from the top 53 bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // Standard normal by Box-Muller (1 - uniform() is in (0, 1]: the logarithm is finite).
  double normal() {
    const double r = std::sqrt(-2.0 * std::log(1.0 - uniform()));
    return r * std::cos(2.0 * M_PI * uniform());
  }
  // An integer in [0, n).
  int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }

 private:
  std::mt19937_64 engine_;
};

inline Mat normal_matrix(Rng& rng, Eigen::Index rows, Eigen::Index cols) {
  Mat M(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) M(i, j) = rng.normal();
  return M;
}

inline double spectral_abscissa(const Mat& A) { return A.eigenvalues().real().maxCoeff(); }

// A (spectral abscissa `abscissa`), B (n x m), D (n x nw) with standard normal entries from the
// seed; Q = L L' / n + 0.1 I > 0.
inline Lti random_lti(std::uint64_t seed, int n, int m, int nw, double abscissa) {
  Rng rng(seed);
  Lti s;
  s.A = normal_matrix(rng, n, n);
  s.A.diagonal().array() += abscissa - spectral_abscissa(s.A);
  s.B = normal_matrix(rng, n, m);
  s.D = normal_matrix(rng, n, nw);
  const Mat L = normal_matrix(rng, n, n);
  s.Q = L * L.transpose() / n + 0.1 * Mat::Identity(n, n);
  s.Q = 0.5 * (s.Q + s.Q.transpose());
  return s;
}

// ======================================================================= the ship (docs/mathematics.md)

struct ShipParams {
  double m_u = 0.5, m_v = -2.0, m_r = 0.5, d_u = 1.0, d_v = 2.0, d_r = 1.0;
};

// f(q) of dq/dt = f(q) + B u + D w, q = [u, v, r, x, y, psi].
inline Vec ship_drift(const Vec& q, const ShipParams& p = {}) {
  const double u = q[0], v = q[1], r = q[2], psi = q[5];
  Vec f(6);
  f << p.m_u * v * r - p.d_u * u, p.m_v * u * r - p.d_v * v, p.m_r * u * v - p.d_r * r,
      u * std::cos(psi) - v * std::sin(psi), u * std::sin(psi) + v * std::cos(psi), r;
  return f;
}

// df/dq, differentiated by hand.
inline Mat ship_jacobian(const Vec& q, const ShipParams& p = {}) {
  const double u = q[0], v = q[1], r = q[2], psi = q[5];
  const double c = std::cos(psi), s = std::sin(psi);
  Mat J(6, 6);
  J << -p.d_u, p.m_u * r, p.m_u * v, 0, 0, 0,  //
      p.m_v * r, -p.d_v, p.m_v * u, 0, 0, 0,    //
      p.m_r * v, p.m_r * u, -p.d_r, 0, 0, 0,    //
      c, -s, 0, 0, 0, -u * s - v * c,           //
      s, c, 0, 0, 0, u * c - v * s,             //
      0, 0, 1, 0, 0, 0;
  return J;
}

// A(q_e) of the decomposition (26)-(31) of docs/mathematics.md: q1 = [u, v, x, y] (indices 0, 1, 3, 4),
// q2 = [r, psi] (indices 2, 5); A11(q2), A12 = d alpha1/d q2 at 0, A21 = d alpha2/d q1 at 0,
// A22 = [[-d_r, 0], [1, 0]].
inline Mat ship_split_A(const Vec& q_d, const Vec& q_e, const ShipParams& p = {}) {
  const double ud = q_d[0], vd = q_d[1], rd = q_d[2], psid = q_d[5];
  const double re = q_e[2], psi = psid + q_e[5];
  const double c = std::cos(psi), s = std::sin(psi), cd = std::cos(psid), sd = std::sin(psid);
  Mat A = Mat::Zero(6, 6);
  // A11 on (u, v, x, y) x (u, v, x, y)
  A(0, 0) = -p.d_u;
  A(0, 1) = p.m_u * (rd + re);
  A(1, 0) = p.m_v * (rd + re);
  A(1, 1) = -p.d_v;
  A(3, 0) = c;
  A(3, 1) = -s;
  A(4, 0) = s;
  A(4, 1) = c;
  // A12 on (u, v, x, y) x (r, psi)
  A(0, 2) = p.m_u * vd;
  A(1, 2) = p.m_v * ud;
  A(3, 5) = -ud * sd - vd * cd;
  A(4, 5) = ud * cd - vd * sd;
  // A21 on (r, psi) x (u, v, x, y)
  A(2, 0) = p.m_r * vd;
  A(2, 1) = p.m_r * ud;
  // A22
  A(2, 2) = -p.d_r;
  A(5, 2) = 1.0;
  return A;
}

inline Mat ship_B() {
  Mat B = Mat::Zero(6, 2);
  B(0, 0) = 1.0;
  B(2, 1) = 1.0;
  return B;
}

// The process-disturbance part of D (w1..w3 on u, v, r).
inline Mat ship_D_process() {
  Mat D = Mat::Zero(6, 3);
  D(0, 0) = D(1, 1) = D(2, 2) = 1.0;
  return D;
}

inline Mat ship_C() {
  Mat C = Mat::Zero(3, 6);
  C(0, 3) = C(1, 4) = C(2, 5) = 1.0;
  return C;
}

// An angle in (-pi, pi] by atan2 (independent of the library's wrap_angle).
inline double wrapped(double angle) {
  const double w = std::atan2(std::sin(angle), std::cos(angle));
  return w == -M_PI ? M_PI : w;
}

// Spectral radius of a (non-symmetric) product, from Eigen's general eigen-solver.
inline double spectral_radius(const Mat& M) { return M.eigenvalues().cwiseAbs().maxCoeff(); }

}  // namespace hinf_ref
