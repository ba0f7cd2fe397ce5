// Dormand-Prince 5(4) explicit Runge-Kutta integrator with its 4th-order continuous extension
// (Hairer, Norsett & Wanner, "Solving ODEs I", §II.5-II.6; same coefficients as DOPRI5).
//
// Integrates dy/dt = rhs(t, y, dydt) from t0 to t1 (t1 < t0 integrates backward). After each
// accepted step, on_step(piece) receives the step's dense output as a DensePiece of degree 4
// (dense_piece.hpp); y then holds the state at the end of the step. on_step may return
// StepAction::Stop to end the integration there (or return nothing to continue).
// Errors: SolverError on step-size underflow, non-finite values or too many steps.
// max_steps bounds the step attempts (accepted and rejected) over the stepper's whole life, so
// a loop of many integrate() calls cannot exceed it either.
// A Dopri5 keeps its workspace and its last step size, so consecutive integrate() calls (e.g.
// one per hold interval of a sampled noise) restart cheaply. It also runs Hairer's stiffness
// test (h lambda estimated from the last two stages, both at t + h): stiff() turns true after
// 15 accepted steps in a row with h |lambda| > 3.25, i.e. steps limited by stability.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/core/interrupt.hpp"
#include "hinf/numerics/dense_piece.hpp"

namespace hinf {

// The counts of one integration (the desired trajectory's, Trajectory::stats()).
struct StepStats {
  long steps = 0;      // accepted steps
  long rejected = 0;   // rejected step attempts
  long rhs_evals = 0;  // right-hand-side evaluations
  long jac_evals = 0;  // Jacobian evaluations (implicit methods)
  std::string method;  // what integrated: "erk", "bdf", "adams", "erk, then bdf from t = ..."

  StepStats& operator+=(const StepStats& more) {
    steps += more.steps;
    rejected += more.rejected;
    rhs_evals += more.rhs_evals;
    jac_evals += more.jac_evals;
    return *this;
  }
};

class Dopri5 {
 public:
  Dopri5(int dim, double rtol, double atol, long max_steps)
      : dim_(dim), rtol_(rtol), atol_(atol), max_steps_(max_steps) {
    const std::size_t n = static_cast<std::size_t>(dim);
    for (auto* v : {&k1_, &k2_, &k3_, &k4_, &k5_, &k6_, &k7_, &ytmp_, &ynew_}) v->assign(n, 0.0);
    dense_.assign(5 * n, 0.0);
  }

  int dim() const { return dim_; }
  const StepStats& stats() const { return stats_; }
  bool stiff() const { return stiff_; }

  template <class Rhs, class OnStep>
  void integrate(Rhs&& rhs, double t0, double t1, double* y, OnStep&& on_step) {
    if (t1 == t0) return;
    const double dir = t1 > t0 ? 1.0 : -1.0;
    const double h_cap = std::abs(t1 - t0);
    double* k1 = k1_.data();
    rhs(t0, y, k1);
    ++stats_.rhs_evals;
    double h = h_next_ > 0.0 ? std::min(h_next_, h_cap) : initial_step(rhs, t0, y, dir, h_cap);
    double t = t0;
    bool last_rejected = false;
    for (;;) {
      if (stats_.steps + stats_.rejected >= max_steps_)
        throw SolverError(str_cat("Dormand-Prince: more than max_steps = ", max_steps_,
                                  " steps (stopped at t = ", t, " on the way to t = ", t1,
                                  "); raise max_steps or loosen rtol"),
                          t, "TOO_MUCH_WORK");
      if (h < kMinStepFactor * std::max(1.0, std::abs(t)))
        throw SolverError(str_cat("Dormand-Prince: step size underflow at t = ", t,
                                  " (the solution may be escaping to infinity)"),
                          t, "STEP_TOO_SMALL");
      bool last = false;
      if ((t + 1.01 * dir * h - t1) * dir >= 0.0) {
        h = std::abs(t1 - t);
        last = true;
      }
      const double hs = dir * h;
      const double err = attempt(rhs, t, hs, y);
      if (err <= 1.0) {
        // Accepted: dense output, then advance.
        build_dense(hs, y);
        const double t_start = t;
        t = last ? t1 : t + hs;
        std::copy(ynew_.begin(), ynew_.end(), y);
        std::swap(k1_, k7_);  // FSAL: f(t_new, y_new) is k1 of the next step
        k1 = k1_.data();
        ++stats_.steps;
        update_stiffness(hs);
        const DensePiece piece{t_start, t, 4, dim_, dense_.data()};
        throw_if_interrupted();  // Ctrl-C ends every integration within one step
        bool stop = false;
        if constexpr (std::is_void_v<decltype(on_step(piece))>) on_step(piece);
        else stop = on_step(piece) == StepAction::Stop;
        double fac = std::pow(std::max(err, 1e-16), kExpo1) / facold_beta_;
        fac = std::clamp(fac / kSafe, 1.0 / kFacMax, 1.0 / kFacMin);
        double h_new = h / fac;
        if (last_rejected) h_new = std::min(h_new, h);
        facold_beta_ = std::pow(std::max(err, 1e-4), kBeta);  // Lund stabilization (PI control)
        last_rejected = false;
        h_next_ = h_new;
        if (last || stop) return;
        h = std::min(h_new, h_cap);
      } else {
        ++stats_.rejected;
        last_rejected = true;
        const double fac = std::isfinite(err)
                               ? std::min(1.0 / kFacMin, std::pow(err, kExpo1) / kSafe)
                               : 1.0 / kFacMin;
        h /= fac;
      }
    }
  }

 private:
  static constexpr double kBeta = 0.04;
  static constexpr double kExpo1 = 0.2 - kBeta * 0.75;
  static constexpr double kSafe = 0.9;
  static constexpr double kFacMin = 0.2;   // smallest step ratio
  static constexpr double kFacMax = 10.0;  // largest step ratio
  // Smallest step: kMinStepFactor * max(1, |t|) (a few units in the last place of t).
  static constexpr double kMinStepFactor = 16.0 * std::numeric_limits<double>::epsilon();

  double weight(double a, double b) const { return atol_ + rtol_ * std::max(std::abs(a), std::abs(b)); }

  template <class Rhs>
  double initial_step(Rhs& rhs, double t0, const double* y, double dir, double h_cap) {
    const double* f0 = k1_.data();
    double dnf = 0.0, dny = 0.0;
    for (int i = 0; i < dim_; ++i) {
      const double sk = atol_ + rtol_ * std::abs(y[i]);
      dnf += (f0[i] / sk) * (f0[i] / sk);
      dny += (y[i] / sk) * (y[i] / sk);
    }
    dnf = std::sqrt(dnf / dim_);
    dny = std::sqrt(dny / dim_);
    double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : 0.01 * dny / dnf;
    h = std::min(h, h_cap);
    for (int i = 0; i < dim_; ++i) ytmp_[i] = y[i] + dir * h * f0[i];
    rhs(t0 + dir * h, static_cast<const double*>(ytmp_.data()), k2_.data());
    ++stats_.rhs_evals;
    double der2 = 0.0;
    for (int i = 0; i < dim_; ++i) {
      const double sk = atol_ + rtol_ * std::abs(y[i]);
      der2 += ((k2_[i] - f0[i]) / sk) * ((k2_[i] - f0[i]) / sk);
    }
    der2 = std::sqrt(der2 / dim_) / h;
    const double der12 = std::max(std::abs(der2), dnf);
    const double h1 = der12 <= 1e-15 ? std::max(1e-6, h * 1e-3) : std::pow(0.01 / der12, 0.2);
    // Not below 1000 times the smallest step the loop accepts: a solution tiny against its
    // derivative (X = 1e-15 + (1 - t)) gives a guess below it, which would be refused as an
    // underflow though the problem is benign; a step too large is rejected and shrunk.
    const double h_floor = 1e3 * kMinStepFactor * std::max(1.0, std::abs(t0));
    return std::min(std::max(std::min(100.0 * h, h1), h_floor), h_cap);
  }

  // One Dormand-Prince step of size hs from (t, y); ynew_ and k7_ hold the result.
  // Returns the scaled error norm (<= 1: accept).
  template <class Rhs>
  double attempt(Rhs& rhs, double t, double hs, const double* y) {
    constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
    constexpr double a21 = 1.0 / 5;
    constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
    constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
    constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                     a54 = -212.0 / 729;
    constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                     a64 = 49.0 / 176, a65 = -5103.0 / 18656;
    constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192,
                     a75 = -2187.0 / 6784, a76 = 11.0 / 84;
    constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                     e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
    const int n = dim_;
    const double *k1 = k1_.data();
    double *k2 = k2_.data(), *k3 = k3_.data(), *k4 = k4_.data(), *k5 = k5_.data(),
           *k6 = k6_.data(), *k7 = k7_.data(), *yt = ytmp_.data(), *yn = ynew_.data();
    for (int i = 0; i < n; ++i) yt[i] = y[i] + hs * a21 * k1[i];
    rhs(t + c2 * hs, static_cast<const double*>(yt), k2);
    for (int i = 0; i < n; ++i) yt[i] = y[i] + hs * (a31 * k1[i] + a32 * k2[i]);
    rhs(t + c3 * hs, static_cast<const double*>(yt), k3);
    for (int i = 0; i < n; ++i) yt[i] = y[i] + hs * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
    rhs(t + c4 * hs, static_cast<const double*>(yt), k4);
    for (int i = 0; i < n; ++i)
      yt[i] = y[i] + hs * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
    rhs(t + c5 * hs, static_cast<const double*>(yt), k5);
    for (int i = 0; i < n; ++i)
      yt[i] = y[i] + hs * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
    rhs(t + hs, static_cast<const double*>(yt), k6);
    for (int i = 0; i < n; ++i)
      yn[i] = y[i] + hs * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
    rhs(t + hs, static_cast<const double*>(yn), k7);
    stats_.rhs_evals += 6;
    double err = 0.0;
    for (int i = 0; i < n; ++i) {
      const double e =
          hs * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
      const double r = e / weight(y[i], yn[i]);
      err += r * r;
    }
    err = std::sqrt(err / n);
    return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
  }

  // Hairer's test on the accepted step (k1_ now holds f(t + h, y_new), k6_ the 6th stage at
  // t + h from ytmp_, ynew_ was copied to y: compare with the stage-6 argument).
  void update_stiffness(double hs) {
    double num = 0.0, den = 0.0;
    for (int i = 0; i < dim_; ++i) {
      num += (k1_[i] - k6_[i]) * (k1_[i] - k6_[i]);
      den += (ynew_[i] - ytmp_[i]) * (ynew_[i] - ytmp_[i]);
    }
    if (den > 0.0 && std::abs(hs) * std::sqrt(num / den) > 3.25) {
      nonstiff_steps_ = 0;
      if (++stiff_steps_ >= 15) stiff_ = true;
    } else if (++nonstiff_steps_ >= 6) {
      stiff_steps_ = 0;
    }
  }

  // Dense output of the accepted step as monomial coefficients in theta.
  void build_dense(double hs, const double* y) {
    constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                     d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                     d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
    const int n = dim_;
    double *c0 = dense_.data(), *c1 = c0 + n, *c2 = c1 + n, *c3 = c2 + n, *c4 = c3 + n;
    for (int i = 0; i < n; ++i) {
      const double ydiff = ynew_[i] - y[i];
      const double bspl = hs * k1_[i] - ydiff;
      const double r4 = ydiff - hs * k7_[i] - bspl;
      const double r5 = hs * (d1 * k1_[i] + d3 * k3_[i] + d4 * k4_[i] + d5 * k5_[i] +
                              d6 * k6_[i] + d7 * k7_[i]);
      c0[i] = y[i];
      c1[i] = ydiff + bspl;
      c2[i] = -bspl + r4 + r5;
      c3[i] = -r4 - 2.0 * r5;
      c4[i] = r5;
    }
  }

  int dim_;
  double rtol_, atol_;
  long max_steps_;
  double h_next_ = 0.0;  // magnitude of the next step; 0 lets integrate() choose one
  double facold_beta_ = 0.69183097091893657;  // (1e-4)^beta
  int stiff_steps_ = 0, nonstiff_steps_ = 0;
  bool stiff_ = false;
  StepStats stats_;
  std::vector<double> k1_, k2_, k3_, k4_, k5_, k6_, k7_, ytmp_, ynew_, dense_;
};

}  // namespace hinf
