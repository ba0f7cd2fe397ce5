// The ship model: analytic Jacobian and error decomposition against independent truth. The
// numerical Jacobians (numerics/numdiff.hpp) against a closed form.
#include <gtest/gtest.h>

#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/numdiff.hpp"
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Mat;
using hinf::Vec;

Vec random_state(hinf_ref::Rng& rng) {
  Vec q(6);
  for (int i = 0; i < 6; ++i) q[i] = rng.uniform(-2.0, 2.0);
  q[5] *= 3.0;  // headings over more than a full turn
  return q;
}

TEST(ShipModel, JacobianMatchesCentralDifferences) {
  const hinf::ShipModel ship;
  hinf_ref::Rng rng(12345);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec q = random_state(rng);
    Mat J(6, 6), J_fd(6, 6);
    ship.dfdq(0.0, q, J);
    for (int j = 0; j < 6; ++j) {
      const double h = 1e-6;
      Vec qp = q, qm = q, fp(6), fm(6);
      qp[j] += h;
      qm[j] -= h;
      ship.f(0.0, qp, fp);
      ship.f(0.0, qm, fm);
      J_fd.col(j) = (fp - fm) / (2 * h);
    }
    // Central differences with h = 1e-6: truncation h^2 |f'''| / 6 < 1e-12 (f is quadratic in
    // u, v, r; |d^3 f / dpsi^3| <= |u| + |v| <= 4), round-off a few ulps of |f| <= 12 over 2 h,
    // ~2e-9 (measured 6.7e-10): 1e-8.
    EXPECT_LT((J - J_fd).cwiseAbs().maxCoeff(), 1e-8) << "at q = " << q.transpose();
  }
}

TEST(ShipModel, DriftIsThePaperEquations) {
  // Equations (1)-(6) written out independently, non-default parameters.
  hinf::ShipParameters p{0.7, -1.3, 0.4, 1.1, 2.5, 0.9};
  const hinf::ShipModel ship(p);
  hinf_ref::Rng rng(7);
  const Vec q = random_state(rng);
  const double u = q[0], v = q[1], r = q[2], psi = q[5];
  Vec expected(6);
  expected << 0.7 * v * r - 1.1 * u, -1.3 * u * r - 2.5 * v, 0.4 * u * v - 0.9 * r,
      u * std::cos(psi) - v * std::sin(psi), u * std::sin(psi) + v * std::cos(psi), r;
  Vec f(6);
  ship.f(0.0, q, f);
  // The library's expressions against these: round-off of the terms (products of two states,
  // |q| <= 6, and a parameter <= 2.5).
  const double terms = 2.5 * (1.0 + q.cwiseAbs().maxCoeff()) * (1.0 + q.cwiseAbs().maxCoeff());
  EXPECT_LT((f - expected).cwiseAbs().maxCoeff(), hinf_test::kRoundoff * terms);
  const Mat B = ship.G(0.0, Vec::Zero(6)), D = ship.D(0.0, Vec::Zero(6));
  EXPECT_EQ(B.rows(), 6);
  EXPECT_EQ(B.cols(), 2);
  EXPECT_EQ(B(0, 0), 1.0);
  EXPECT_EQ(B(2, 1), 1.0);
  EXPECT_EQ(B.sum(), 2.0);
  EXPECT_EQ(D.diagonal().head(3).sum(), 3.0);
  EXPECT_EQ(D.sum(), 3.0);
}

// A(q) q + alpha(q) = f_e(q) exactly and A(0) = A_e, for the ship's own split and for the
// generic fallback of the Model base class.
template <class M>
void check_split(const M& model, const hinf::Model& as_base) {
  hinf_ref::Rng rng(99);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec q_d = random_state(rng), q_e = random_state(rng);
    Mat A(6, 6), A0(6, 6), A_e(6, 6);
    Vec alpha(6), alpha0(6), f_act(6), f_des(6);
    as_base.error_split(0.3, q_d, Vec::Zero(2), q_e, A, alpha);
    model.f(0.3, q_d + q_e, f_act);
    model.f(0.3, q_d, f_des);
    const Vec f_e = f_act - f_des;
    // Two computations of f_e: round-off of the size of their terms, not of the result.
    const double terms = 1.0 + 6.0 * A.cwiseAbs().maxCoeff() * q_e.cwiseAbs().maxCoeff() +
                         alpha.cwiseAbs().maxCoeff() + f_act.cwiseAbs().maxCoeff() + f_des.cwiseAbs().maxCoeff();
    EXPECT_LT((A * q_e + alpha - f_e).cwiseAbs().maxCoeff(), hinf_test::kRoundoff * terms);
    as_base.error_split(0.3, q_d, Vec::Zero(2), Vec::Zero(6), A0, alpha0);
    model.dfdq(0.3, q_d, A_e);
    // The split at 0 and the Jacobian are different code for the same matrix: round-off.
    EXPECT_LT((A0 - A_e).cwiseAbs().maxCoeff(), hinf_test::kRoundoff * (1.0 + A_e.cwiseAbs().maxCoeff()));
    // alpha(0) is built of products with 0 and differences x - x: exactly zero.
    EXPECT_EQ(alpha0.cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(ShipModel, ErrorSplitIsExact) {
  const hinf::ShipModel ship;
  check_split(ship, ship);
}

TEST(LinearModel, RejectsWrongShapes) {
  EXPECT_THROW(hinf::LinearModel(Mat::Zero(2, 3), Mat::Zero(2, 1), Mat::Zero(2, 1)),
               hinf::InputError);
  EXPECT_THROW(hinf::LinearModel(Mat::Zero(2, 2), Mat::Zero(3, 1), Mat::Zero(2, 1)),
               hinf::InputError);
  Mat A = Mat::Zero(2, 2);
  A(0, 1) = NAN;
  EXPECT_THROW(hinf::LinearModel(A, Mat::Zero(2, 1), Mat::Zero(2, 1)), hinf::InputError);
}

// F(x) = [sin(x0) exp(x1), x0 x1^2 / 3, cos(x0 - x2)] at x with entries up to 5: J in closed form.
template <class V>
V numdiff_probe(const V& x) {
  using std::cos, std::exp, std::sin;
  V F(3);
  F << sin(x[0]) * exp(x[1]), x[0] * x[1] * x[1] / 3.0, cos(x[0] - x[2]);
  return F;
}

Mat numdiff_probe_jacobian(const Vec& x) {
  Mat J = Mat::Zero(3, 3);
  J(0, 0) = std::cos(x[0]) * std::exp(x[1]);
  J(0, 1) = std::sin(x[0]) * std::exp(x[1]);
  J(1, 0) = x[1] * x[1] / 3.0;
  J(1, 1) = 2.0 * x[0] * x[1] / 3.0;
  J(2, 0) = -std::sin(x[0] - x[2]);
  J(2, 2) = std::sin(x[0] - x[2]);
  return J;
}

TEST(NumericalJacobians, AgainstTheClosedForm) {
  hinf_ref::Rng rng(2024);
  for (int trial = 0; trial < 20; ++trial) {
    Vec x(3);
    for (int i = 0; i < 3; ++i) x[i] = rng.uniform(-5.0, 5.0);
    const Mat J = numdiff_probe_jacobian(x);
    const double scale = 1.0 + numdiff_probe(x).cwiseAbs().maxCoeff() + J.cwiseAbs().maxCoeff();
    // Central differences: steps h <= eps^(1/3) 5 = 3e-5; truncation h^2 / 6 |F'''| with |F'''|
    // within the scale here (the exp factor is in it): 1.5e-10 scale; round-off eps / h |F|
    // <= 4e-11 scale (measured worst over 2000 points: 7.8e-11 scale). 1e-8 leaves 50 times that.
    const Mat central = hinf::central_difference_jacobian(x, 3, [](const Vec& y) { return numdiff_probe(y); });
    EXPECT_LT((central - J).cwiseAbs().maxCoeff(), 1e-8 * scale) << "x = " << x.transpose();
    // The complex step takes no difference: round-off of the formula only.
    const Mat complex = hinf::complex_step_jacobian(x, 3, [](const Eigen::VectorXcd& y) { return numdiff_probe(y); });
    EXPECT_LT((complex - J).cwiseAbs().maxCoeff(), hinf_test::kRoundoff * scale) << "x = " << x.transpose();
  }
  // A function of the wrong size is named, not read past.
  EXPECT_THROW(hinf::central_difference_jacobian(Vec::Zero(2), 3, [](const Vec&) { return Vec(Vec::Zero(2)); }),
               hinf::InputError);
  EXPECT_THROW(hinf::complex_step_jacobian(Vec::Zero(2), 3,
                                           [](const Eigen::VectorXcd&) { return Eigen::VectorXcd(Eigen::VectorXcd::Zero(1)); }),
               hinf::InputError);
}

}  // namespace
