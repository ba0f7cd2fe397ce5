// A one-step, L-stable implicit Runge-Kutta integrator for stiff problems whose integration
// is restarted often (the sampled-noise closed loop of output_feedback.hpp): unlike BDF it
// has no history to rebuild after a restart, and it keeps its Jacobian, iteration matrix and
// step size across restarts.
//
// Method: the 5-stage, order-4, L-stable, stiffly accurate SDIRK of Hairer & Wanner
// ("Solving ODEs II", Table IV.6.5, gamma = 1/4) with its embedded order-3 solution. The
// error estimate is filtered by (I - h gamma J)^-1 (ibid. §IV.8) so that it stays meaningful
// for stiff components. Stage equations: simplified Newton with a finite-difference
// Jacobian, refreshed when the iteration fails. Dense output: cubic Hermite on each step.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

#include "hinf/core/errors.hpp"
#include "hinf/numerics/dopri5.hpp"

namespace hinf {

class Sdirk4 {
 public:
  Sdirk4(int dim, double rtol, double atol, long max_steps)
      : dim_(dim), rtol_(rtol), atol_(atol), max_steps_(max_steps) {
    for (auto* v : {&y0_, &f0_, &Y_, &G_, &dY_, &w_, &err_, &scratch_, &base_}) v->resize(dim);
    for (auto& k : k_) k.resize(dim);
    J_.resize(dim, dim);
  }

  const StepStats& stats() const { return stats_; }
  long factorizations() const { return factorizations_; }

  // Integrates from t0 to t1 (t1 > t0). on_step(t_start, h, y_start, f_start, y_end, f_end)
  // is called after each accepted step (for cubic Hermite output between the two ends); it may
  // return StepAction::Stop to end the integration there. max_steps bounds the step attempts
  // over the stepper's whole life (all integrate() calls).
  template <class Rhs, class OnStep>
  void integrate(Rhs&& rhs, double t0, double t1, double* y, OnStep&& on_step) {
    if (!(t1 > t0)) return;
    Eigen::Map<Eigen::VectorXd> ymap(y, dim_);
    double h_step = h_next_ > 0.0 ? h_next_ : 1e-3 * (t1 - t0);
    double t = t0;
    rhs(t, static_cast<const double*>(y), f0_.data());
    ++stats_.rhs_evals;
    if (!have_jacobian_) refresh_jacobian(rhs, t, y);
    for (;;) {
      if (stats_.steps + stats_.rejected >= max_steps_)
        throw SolverError(str_cat("SDIRK4: more than max_steps = ", max_steps_, " steps (stopped at t = ", t,
                                  " on the way to t = ", t1, "); raise max_steps or loosen rtol"),
                          t, "TOO_MUCH_WORK");
      if (h_step < 16.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t)))
        throw SolverError(str_cat("SDIRK4: step size underflow at t = ", t), t, "STEP_TOO_SMALL");
      double h = h_step;
      const bool last = t + 1.01 * h >= t1;
      if (last) h = t1 - t;
      y0_ = ymap;
      for (int i = 0; i < dim_; ++i) w_[i] = 1.0 / (atol_ + rtol_ * std::abs(y[i]));
      if (!stages(rhs, t, h)) {
        ++stats_.rejected;
        if (jacobian_fresh_) h_step = 0.5 * h;
        else refresh_jacobian(rhs, t, y0_.data());
        continue;
      }
      const double norm = error_norm(h);
      const double factor = std::clamp(0.9 * std::pow(std::max(norm, 1e-10), -0.25), 0.2, 5.0);
      if (norm > 1.0) {
        ++stats_.rejected;
        h_step = h * std::min(factor, 0.5);
        continue;
      }
      ++stats_.steps;
      ymap = Y_;
      const Eigen::VectorXd& f_end = k_[kStages - 1];  // stiffly accurate: the last stage is y_{n+1}
      bool stop = false;
      if constexpr (std::is_void_v<decltype(on_step(t, h, y, y, y, y))>)
        on_step(t, h, static_cast<const double*>(y0_.data()), static_cast<const double*>(f0_.data()),
                static_cast<const double*>(y), static_cast<const double*>(f_end.data()));
      else
        stop = on_step(t, h, static_cast<const double*>(y0_.data()), static_cast<const double*>(f0_.data()),
                       static_cast<const double*>(y), static_cast<const double*>(f_end.data())) == StepAction::Stop;
      t = last ? t1 : t + h;
      f0_ = f_end;
      // A new step size only when the change is worth a new factorization; a step shortened
      // to land on t1 keeps the natural step for the next call.
      const double proposed = h * factor;
      if ((proposed < h_step || proposed > 1.2 * h_step) && !(last && h < h_step && proposed >= h_step))
        h_step = proposed;
      if (last || stop) {
        h_next_ = h_step;
        return;
      }
    }
  }

 private:
  static constexpr int kStages = 5;
  static constexpr double kGamma = 0.25;
  // Butcher tableau (strictly lower part), nodes, and b - b^ (b^ the order-3 weights).
  static constexpr double kA[kStages][kStages] = {
      {0, 0, 0, 0, 0},
      {1.0 / 2, 0, 0, 0, 0},
      {17.0 / 50, -1.0 / 25, 0, 0, 0},
      {371.0 / 1360, -137.0 / 2720, 15.0 / 544, 0, 0},
      {25.0 / 24, -49.0 / 48, 125.0 / 16, -85.0 / 12, 0}};
  static constexpr double kC[kStages] = {1.0 / 4, 3.0 / 4, 11.0 / 20, 1.0 / 2, 1.0};
  static constexpr double kE[kStages] = {25.0 / 24 - 59.0 / 48, -49.0 / 48 + 17.0 / 96,
                                         125.0 / 16 - 225.0 / 32, 0.0, 1.0 / 4};

  template <class Rhs>
  void refresh_jacobian(Rhs& rhs, double t, const double* y) {
    scratch_ = Eigen::Map<const Eigen::VectorXd>(y, dim_);
    for (int j = 0; j < dim_; ++j) {
      const double yj = scratch_[j];
      const double delta = std::sqrt(std::numeric_limits<double>::epsilon()) *
                           std::max({std::abs(yj), atol_ / rtol_, 1e-8});
      scratch_[j] = yj + delta;
      rhs(t, static_cast<const double*>(scratch_.data()), dY_.data());
      J_.col(j) = (dY_ - f0_) / delta;
      scratch_[j] = yj;
    }
    stats_.rhs_evals += dim_;
    ++stats_.jac_evals;
    have_jacobian_ = true;
    jacobian_fresh_ = true;
    h_lu_ = -1.0;  // force a new factorization
  }

  // The iteration matrix I - h gamma J; an approximate one (h within 20%) is kept, as
  // simplified Newton and the error filter only need an approximation.
  void factorize(double h) {
    if (h_lu_ > 0.0 && h <= 1.2 * h_lu_ && h >= h_lu_ / 1.2) return;
    lu_.compute(Eigen::MatrixXd::Identity(dim_, dim_) - (h * kGamma) * J_);
    h_lu_ = h;
    ++factorizations_;
  }

  // Solves Y = base + h gamma f(t, Y) by simplified Newton, starting from Y = base + h gamma k
  // (k a derivative estimate); on success k = (Y - base) / (h gamma) = f(t, Y).
  template <class Rhs>
  bool solve_stage(Rhs& rhs, double t, double h, Eigen::VectorXd& k) {
    Y_ = base_ + (h * kGamma) * k;
    double previous = 0.0;
    for (int iteration = 0; iteration < 7; ++iteration) {
      rhs(t, static_cast<const double*>(Y_.data()), k.data());
      ++stats_.rhs_evals;
      G_ = base_ + (h * kGamma) * k - Y_;  // residual of Y = base + h gamma f(t, Y)
      dY_ = lu_.solve(G_);
      Y_ += dY_;
      const double norm = std::sqrt((dY_.cwiseProduct(w_)).squaredNorm() / dim_);
      if (!std::isfinite(norm)) return false;
      if (iteration > 0) {
        const double rate = norm / previous;
        if (rate > 0.9) return false;
        if (rate / (1.0 - rate) * norm < 0.03) break;
      } else if (norm < 1e-3) {
        break;
      }
      if (iteration == 6) return false;
      previous = norm;
    }
    k = (Y_ - base_) / (h * kGamma);
    return true;
  }

  // The stages from (t, y0_); false when the Newton iteration fails.
  template <class Rhs>
  bool stages(Rhs& rhs, double t, double h) {
    factorize(h);
    for (int i = 0; i < kStages; ++i) {
      base_ = y0_;
      for (int j = 0; j < i; ++j) base_ += (h * kA[i][j]) * k_[j];
      k_[i] = i == 0 ? f0_ : k_[i - 1];
      if (!solve_stage(rhs, t + kC[i] * h, h, k_[i])) return false;
    }
    Y_ = base_ + (h * kGamma) * k_[kStages - 1];
    jacobian_fresh_ = false;
    return true;
  }

  // Weighted RMS norm of the local error estimate, filtered by (I - h gamma J)^-1.
  double error_norm(double h) {
    err_.setZero();
    for (int i = 0; i < kStages; ++i) err_ += (h * kE[i]) * k_[i];
    err_ = lu_.solve(err_);
    double norm = 0.0;
    for (int i = 0; i < dim_; ++i) {
      const double wi = 1.0 / (atol_ + rtol_ * std::max(std::abs(y0_[i]), std::abs(Y_[i])));
      norm += (err_[i] * wi) * (err_[i] * wi);
    }
    norm = std::sqrt(norm / dim_);
    return std::isfinite(norm) ? norm : 1e10;
  }

  int dim_;
  double rtol_, atol_;
  long max_steps_;
  double h_next_ = 0.0, h_lu_ = -1.0;
  bool have_jacobian_ = false, jacobian_fresh_ = false;
  long factorizations_ = 0;
  StepStats stats_;
  std::array<Eigen::VectorXd, kStages> k_;
  Eigen::VectorXd y0_, f0_, Y_, G_, dY_, w_, err_, scratch_, base_;
  Eigen::MatrixXd J_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace hinf
