#include "control/online_estimator.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "hinf/control/discrete_design.hpp"
#include "hinf/core/angles.hpp"
#include "numerics/size_dispatch.hpp"

namespace hinf::detail {

namespace {

template <int N>
class Estimator final : public OnlineEstimator {
 public:
  using MatN = Eigen::Matrix<double, N, N>;
  using VecN = Eigen::Matrix<double, N, 1>;
  using MatPN = Eigen::Matrix<double, Eigen::Dynamic, N>;  // p x n
  using MatNP = Eigen::Matrix<double, N, Eigen::Dynamic>;  // n x p

  Estimator(const SampledLaw& law, const OnlineFilter& filter, const Mat& C, int heading_row)
      : law_(&law), filter_(filter.enabled()), heading_row_(heading_row),
        inv_gamma2_(std::isinf(law.gamma()) ? 0.0 : 1.0 / (law.gamma() * law.gamma())),
        // Sized here, not assigned later: Eigen's sized constructors leave the status fields
        // unset, and a copy of them is undefined behaviour.
        lu_(law.n()), llt_(law.n()), eigen_(law.n()) {
    const int n = law.n(), m = law.m();
    if (filter_) {
      C_ = C;
      CtNinv_ = C.transpose() * filter.N.inverse();
      // R^-1 = hold N^-1: the information of one measurement of the sensor's period.
      const double hold = filter.hold > 0.0 ? filter.hold : law.period();
      CtRinv_ = hold * CtNinv_;
      CtRinvC_ = CtRinv_ * C;
      // gamma^-2 T Q: what the discrete filter takes from Sigma^-1 at each sample.
      TQ_ = inv_gamma2_ * law.period() * filter.Q;
      S_predict_ = inv_gamma2_ * filter.Q;
      S_innovate_ = S_predict_ - CtNinv_ * C_;
      innovation_.setZero(C.rows());
    }
    for (MatN* M : {&A_, &DDt_, &Z_, &NN_, &gain_lhs_, &L_, &Sigma_, &S1_, &S2_, &S3_, &S4_, &S_stage_}) M->setZero(n, n);
    for (VecN* v : {&x_, &k1_, &k2_, &k3_, &k4_, &x_stage_, &n_tmp_, &r_}) v->setZero(n);
    B_.setZero(n, m);
    u_d_.setZero(m);
    ue_.setZero(m);
  }

  void set_law(const SampledLaw& law) noexcept override {
    law_ = &law;
    interpolated_at_ = NAN;
  }

  void integrate(double s, double end, int substeps, const Vec& u, const Vec& y_e, bool innovate, Vec& x,
                 Mat& Sigma) noexcept override {
    x_ = x;
    if (filter_) Sigma_ = Sigma;
    const double h = (end - s) / substeps;
    for (int i = 0; i < substeps; ++i) {
      const double a = s + i * h, mid = a + 0.5 * h, b = i + 1 == substeps ? end : a + h;
      const double dt = b - a;
      derivative(a, x_, Sigma_, u, y_e, innovate, k1_, S1_);
      x_stage_ = x_ + 0.5 * dt * k1_;
      if (filter_) S_stage_ = Sigma_ + 0.5 * dt * S1_;
      derivative(mid, x_stage_, S_stage_, u, y_e, innovate, k2_, S2_);
      x_stage_ = x_ + 0.5 * dt * k2_;
      if (filter_) S_stage_ = Sigma_ + 0.5 * dt * S2_;
      derivative(mid, x_stage_, S_stage_, u, y_e, innovate, k3_, S3_);
      x_stage_ = x_ + dt * k3_;
      if (filter_) S_stage_ = Sigma_ + dt * S3_;
      derivative(b, x_stage_, S_stage_, u, y_e, innovate, k4_, S4_);
      x_ += (dt / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
      if (!filter_) continue;
      Sigma_ += (dt / 6.0) * (S1_ + 2.0 * S2_ + 2.0 * S3_ + S4_);
      S_stage_ = Sigma_.transpose();  // keeps Sigma symmetric against round-off
      Sigma_ = 0.5 * (Sigma_ + S_stage_);
    }
    x = x_;
    if (filter_) Sigma = Sigma_;
  }

  void update(double t, const Vec& y_e, Vec& x, Mat& Sigma) noexcept override {
    interpolate(t);
    Sigma_ = Sigma;
    llt_.compute(Sigma_);
    if (llt_.info() != Eigen::Success) {
      x.setConstant(NAN);
      return;
    }
    // Sigma+ = (Sigma^-1 + C' R^-1 C)^-1, through the information matrix.
    S1_.setIdentity();
    S2_ = llt_.solve(S1_);
    S2_ += CtRinvC_;
    llt_.compute(S2_);
    if (llt_.info() != Eigen::Success) {
      x.setConstant(NAN);
      return;
    }
    Sigma_ = llt_.solve(S1_);
    S3_ = Sigma_.transpose();
    Sigma_ = 0.5 * (Sigma_ + S3_);
    x_ = x;
    innovation_gain(Sigma_, x_, y_e, CtRinv_);
    x_ += n_tmp_;
    x = x_;
    Sigma = Sigma_;
  }

  bool advance(int k, const Vec& u_e, const Vec* y_e, Vec& x, Mat& Sigma) noexcept override {
    const SampledLinearization& sampled = *law_->sampled();
    interpolated_at_ = NAN;  // A_ and Z_ are overwritten below
    Sigma_ = Sigma;
    llt_.compute(Sigma_);
    if (llt_.info() != Eigen::Success) return false;
    // Pi^-1 = Sigma^-1 (+ C' R^-1 C) - gamma^-2 T Q
    S1_.setIdentity();
    S2_ = llt_.solve(S1_);
    S2_ -= TQ_;
    if (y_e != nullptr) S2_ += CtRinvC_;
    llt_.compute(S2_);
    if (llt_.info() != Eigen::Success) return false;
    S3_ = llt_.solve(S1_);  // Pi
    // x+ = A x + B u_e + A Pi (gamma^-2 T Q x + C' R^-1 (y_e - C x))
    x_ = x;
    n_tmp_.noalias() = TQ_ * x_;
    if (y_e != nullptr) {
      innovation_ = *y_e;
      innovation_.noalias() -= C_ * x_;
      if (heading_row_ >= 0) innovation_[heading_row_] = wrap_angle(innovation_[heading_row_]);
      n_tmp_.noalias() += CtRinv_ * innovation_;
    }
    r_.noalias() = S3_ * n_tmp_;
    n_tmp_ = x_ + r_;
    A_ = sampled.A(k);
    x_.noalias() = A_ * n_tmp_;
    x_.noalias() += sampled.B(k) * u_e;
    // Sigma+ = A Pi A' + D D' / T
    NN_.noalias() = A_ * S3_;
    S4_.noalias() = NN_ * A_.transpose();
    S4_ += law_->discrete_DDt(k);
    S2_ = S4_.transpose();
    Sigma_ = 0.5 * (S4_ + S2_);
    x = x_;
    Sigma = Sigma_;
    return true;
  }

  double worst_case_state(int k, const Vec& x, const Mat& Sigma, const Vec* y_e, Vec& out) noexcept override {
    interpolated_at_ = NAN;  // Z_ is overwritten below
    Z_ = law_->Z(k);
    Sigma_ = Sigma;
    const double r = rho(Sigma_);  // leaves the Cholesky factor of Sigma in llt_
    if (!std::isfinite(r)) {
      out.setConstant(NAN);
      return INFINITY;
    }
    // H^-1 = Sigma^-1 (+ C' R^-1 C) - gamma^-2 M_k
    S1_.setIdentity();
    S2_ = llt_.solve(S1_);
    S2_.noalias() -= inv_gamma2_ * Z_;
    x_ = x;
    n_tmp_.noalias() = inv_gamma2_ * (Z_ * x_);
    if (y_e != nullptr) {
      S2_ += CtRinvC_;
      innovation_ = *y_e;
      innovation_.noalias() -= C_ * x_;
      if (heading_row_ >= 0) innovation_[heading_row_] = wrap_angle(innovation_[heading_row_]);
      n_tmp_.noalias() += CtRinv_ * innovation_;
    }
    llt_.compute(S2_);
    if (llt_.info() != Eigen::Success) {
      out.setConstant(NAN);
      return r;
    }
    r_ = llt_.solve(n_tmp_);
    x_ += r_;
    out = x_;
    return r;
  }

  double coupling(double t, const Mat& Sigma) noexcept override {
    interpolate(t);
    Sigma_ = Sigma;
    return rho(Sigma_);
  }

 private:
  // rho(Sigma Z_) = the largest eigenvalue of L' Z_ L, Sigma = L L' (+inf when Sigma is not
  // positive definite).
  double rho(const MatN& Sigma) noexcept {
    llt_.compute(Sigma);
    if (llt_.info() != Eigen::Success) return INFINITY;
    L_ = llt_.matrixL();
    NN_.noalias() = Z_ * L_;
    gain_lhs_.noalias() = L_.transpose() * NN_;
    eigen_.compute(gain_lhs_, Eigen::EigenvaluesOnly);
    return eigen_.eigenvalues()[eigen_.eigenvalues().size() - 1];
  }

  // A_e, B_e (and with the filter D_e D_e' and Z) interpolated linearly between the samples around
  // t; nothing when they are already those of t (RK4 asks twice for the midpoint, and for each
  // step's end).
  void interpolate(double t) noexcept {
    if (t == interpolated_at_) return;
    interpolated_at_ = t;
    const double position = (t - law_->t0()) / law_->period();
    const int k = std::clamp(static_cast<int>(std::floor(position)), 0, law_->steps() - 1);
    const double theta = std::clamp(position - k, 0.0, 1.0);
    A_ = (1.0 - theta) * law_->A(k) + theta * law_->A(k + 1);
    B_ = (1.0 - theta) * law_->B(k) + theta * law_->B(k + 1);
    if (!filter_) return;
    DDt_ = (1.0 - theta) * law_->DDt(k) + theta * law_->DDt(k + 1);
    Z_ = (1.0 - theta) * law_->Z(k) + theta * law_->Z(k + 1);
  }

  // The prediction of the error (state feedback), or (35) and (36) (output feedback), at t (see
  // online_controller.hpp).
  void derivative(double t, const VecN& x, const MatN& Sigma, const Vec& u, const Vec& y_e, bool innovate, VecN& dx,
                  MatN& dSigma) noexcept {
    interpolate(t);
    law_->trajectory().u_d(t, u_d_.data());
    ue_ = u - u_d_;
    dx.noalias() = A_ * x;
    dx.noalias() += B_ * ue_;
    if (!filter_) return;
    // + gamma^-2 D_e D_e' Z q_hat (the worst-case disturbance the design assumes)
    n_tmp_.noalias() = Z_ * x;
    dx.noalias() += inv_gamma2_ * (DDt_ * n_tmp_);
    // dSigma = A Sigma + Sigma A' + D D' + Sigma (gamma^-2 Q - C' N^-1 C) Sigma
    NN_.noalias() = A_ * Sigma;
    dSigma = NN_ + NN_.transpose() + DDt_;
    NN_.noalias() = (innovate ? S_innovate_ : S_predict_) * Sigma;
    dSigma.noalias() += Sigma * NN_;
    if (!innovate) return;
    innovation_gain(Sigma, x, y_e, CtNinv_);
    dx += n_tmp_;
  }

  // [I - gamma^-2 Sigma Z]^-1 Sigma CtW (y_e - C x) into n_tmp_, the heading's innovation wrapped
  // (CtW: C' N^-1 for the held update's rate, C' R^-1 for the sampled update's jump).
  void innovation_gain(const MatN& Sigma, const VecN& x, const Vec& y_e, const MatNP& CtW) noexcept {
    innovation_ = y_e;
    innovation_.noalias() -= C_ * x;
    if (heading_row_ >= 0) innovation_[heading_row_] = wrap_angle(innovation_[heading_row_]);
    n_tmp_.noalias() = CtW * innovation_;
    r_.noalias() = Sigma * n_tmp_;
    gain_lhs_.setIdentity();
    gain_lhs_.noalias() -= inv_gamma2_ * (Sigma * Z_);
    lu_.compute(gain_lhs_);
    n_tmp_ = lu_.solve(r_);
  }

  const SampledLaw* law_;  // the law's tables (replaced by set_law)
  bool filter_;  // output feedback
  int heading_row_;
  double inv_gamma2_;
  double interpolated_at_ = NAN;
  MatPN C_;
  MatNP CtNinv_, CtRinv_;
  MatN CtRinvC_, TQ_;
  MatN S_predict_, S_innovate_;  // gamma^-2 Q and gamma^-2 Q - C' N^-1 C
  MatN A_, DDt_, Z_, NN_, gain_lhs_, L_, Sigma_, S1_, S2_, S3_, S4_, S_stage_;
  Mat B_;
  VecN x_, k1_, k2_, k3_, k4_, x_stage_, n_tmp_, r_;
  Vec u_d_, ue_, innovation_;
  Eigen::PartialPivLU<MatN> lu_;
  Eigen::LLT<MatN> llt_;
  Eigen::SelfAdjointEigenSolver<MatN> eigen_;
};

}  // namespace

std::unique_ptr<OnlineEstimator> make_online_estimator(const SampledLaw& law, const OnlineFilter& filter, const Mat& C,
                                                       int heading_row) {
  return with_state_size(law.n(), [&](auto size) -> std::unique_ptr<OnlineEstimator> {
    return std::make_unique<Estimator<decltype(size)::value>>(law, filter, C, heading_row);
  });
}

}  // namespace hinf::detail
