#include "hinf/control/online_controller.hpp"

#include <algorithm>
#include <cmath>

#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/resources.hpp"

namespace hinf {

namespace {

// Classical Runge-Kutta steps of the prediction: at most this long (s), as the sampled
// linearization's (discrete_design.hpp).
constexpr double kMaxSubstep = SampledLinearization::kMaxSubstep;

void check_limit_vector(const Vec& v, int m, const char* name) {
  require(v.size() == 0 || v.size() == m, "the actuator limit ", name, " needs ", m, " numbers (one per input) or none, got ",
          v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i)
    require(!std::isnan(v[i]), "the actuator limit ", name, "[", i, "] is NaN");
}

}  // namespace

SampledLaw::SampledLaw(TrajectoryPtr trajectory, std::string kind, double gamma, double period, std::vector<Mat> K)
    : trajectory_(std::move(trajectory)), kind_(std::move(kind)), gamma_(gamma), period_(period), K_(std::move(K)) {
  require(trajectory_ != nullptr, "a sampled law needs its trajectory");
  require(!trajectory_->u_d_signal().is_function(),
          "the online controller needs u_d as signals (constants, harmonics or tables), not a function of t: a "
          "function may allocate and throw, which step() must not");
  const int N = sample_count(trajectory_->t0(), trajectory_->tf(), period_);
  require(static_cast<int>(K_.size()) == N, "a sampled law of ", N, " samples needs ", N, " gains, got ", K_.size());
  check_memory(8.0 * (N + 1.0) * trajectory_->n() * (2.0 * trajectory_->n() + 2.0 * trajectory_->m()),
               str_cat("a sampled law of ", N, " samples"), "choose a longer period (or a shorter horizon)");
  A_.reserve(static_cast<std::size_t>(N) + 1);
  B_.reserve(static_cast<std::size_t>(N) + 1);
  for (int k = 0; k <= N; ++k) {
    const double t = std::min(trajectory_->t0() + k * period_, trajectory_->tf());
    A_.push_back(trajectory_->A_e(t));
    B_.push_back(trajectory_->B_e(t));
  }
}

std::shared_ptr<const SampledLaw> SampledLaw::emulated(RiccatiSolutionPtr design, double period, const Signal& kappa) {
  require(design != nullptr, "the emulated law needs a design (a solution of the GRDE)");
  const Trajectory& trajectory = design->trajectory();
  const int N = sample_count(trajectory.t0(), trajectory.tf(), period);
  std::vector<Mat> K;
  K.reserve(static_cast<std::size_t>(N));
  for (int k = 0; k < N; ++k) {
    const double t = trajectory.t0() + k * period;
    const double kappa_k = kappa(t);
    require(std::isfinite(kappa_k) && kappa_k > 0.0, "the gain scaling kappa must be > 0, got ", kappa_k, " at t = ", t);
    K.push_back(kappa_k * design->gain(t));
  }
  return std::make_shared<const SampledLaw>(design->trajectory_ptr(), "emulated", design->gamma(), period, std::move(K));
}

std::shared_ptr<const SampledLaw> SampledLaw::digital(DiscreteDesignPtr design) {
  require(design != nullptr, "the digital law needs a discrete design");
  std::vector<Mat> K;
  K.reserve(static_cast<std::size_t>(design->steps()));
  for (int k = 0; k < design->steps(); ++k) K.push_back(design->gain(k));
  return std::make_shared<const SampledLaw>(design->sampled().trajectory_ptr(), "digital", design->gamma(),
                                            design->period(), std::move(K));
}

void ActuatorLimits::validate(int m) const {
  check_limit_vector(u_min, m, "u_min");
  check_limit_vector(u_max, m, "u_max");
  check_limit_vector(rate_max, m, "rate_max");
  if (u_min.size() > 0 && u_max.size() > 0)
    for (int i = 0; i < m; ++i)
      require(u_min[i] <= u_max[i], "the actuator limits need u_min <= u_max, got u_min[", i, "] = ", u_min[i],
              " > u_max[", i, "] = ", u_max[i]);
  for (Eigen::Index i = 0; i < rate_max.size(); ++i)
    require(rate_max[i] > 0.0, "the rate limit rate_max[", i, "] must be > 0 (+inf: none), got ", rate_max[i]);
}

void OnlineOptions::validate(int m) const {
  limits.validate(m);
  require(!std::isnan(max_age) && max_age > 0.0, "max_age must be > 0 s, got ", max_age);
  require(history >= 2 && history <= 1000000, "history must be in [2, 1e6] commands, got ", history);
}

OnlineController::OnlineController(SampledLawPtr law, const OnlineOptions& options)
    : law_(std::move(law)), options_(options) {
  require(law_ != nullptr, "an online controller needs a sampled law");
  const int n = law_->n(), m = law_->m();
  options_.validate(m);
  heading_ = law_->trajectory().model().heading_index();
  for (Vec* v : {&x_, &q_d_, &k1_, &k2_, &k3_, &k4_, &x_stage_}) v->setZero(n);
  for (Vec* v : {&u_held_, &u_, &u_ff_, &u_d_, &ue_}) v->setZero(m);
  A_t_.setZero(n, n);
  B_t_.setZero(n, m);
  history_t_.assign(static_cast<std::size_t>(options_.history), 0.0);
  history_u_.setZero(m, options_.history);
}

void OnlineController::reset(double t, const ConstVecRef& q, const ConstVecRef& u_held) {
  require(std::isfinite(t) && t >= law_->t0() && t < law_->t_end(), "reset at t = ", t, " outside the law's samples [",
          law_->t0(), ", ", law_->t_end(), ")");
  check_size(q, n(), "q");
  check_finite(q, "q");
  law_->trajectory().q_d(t, q_d_.data(), &q_cursor_);
  tracking_error(n(), heading_, q.data(), q_d_.data(), x_.data());
  if (u_held.size() == 0) {
    law_->trajectory().u_d(t, u_held_.data());
    const ActuatorLimits& limits = options_.limits;
    if (limits.u_min.size() > 0) u_held_ = u_held_.cwiseMax(limits.u_min);
    if (limits.u_max.size() > 0) u_held_ = u_held_.cwiseMin(limits.u_max);
  } else {
    check_size(u_held, m(), "u_held");
    check_finite(u_held, "u_held");
    u_held_ = u_held;
  }
  t_x_ = t_held_ = t_last_ = t_meas_last_ = t;
  history_start_ = history_size_ = 0;
  remember(t, u_held_);
  counts_ = OnlineCounts();
  reset_ = true;
}

void OnlineController::remember(double t, const Vec& u) noexcept {
  const int capacity = options_.history;
  if (history_size_ > 0) {
    const int newest = (history_start_ + history_size_ - 1) % capacity;
    if (history_t_[static_cast<std::size_t>(newest)] == t) {  // the same time again: replaces
      history_u_.col(newest) = u;
      return;
    }
  }
  int slot;
  if (history_size_ < capacity) {
    slot = (history_start_ + history_size_) % capacity;
    ++history_size_;
  } else {
    slot = history_start_;
    history_start_ = (history_start_ + 1) % capacity;
  }
  history_t_[static_cast<std::size_t>(slot)] = t;
  history_u_.col(slot) = u;
}

int OnlineController::entry_at(double t) const noexcept {
  const int capacity = options_.history;
  for (int i = history_size_ - 1; i > 0; --i) {
    const int slot = (history_start_ + i) % capacity;
    if (history_t_[static_cast<std::size_t>(slot)] <= t) return slot;
  }
  return history_start_;
}

void OnlineController::derivative(double t, const Vec& x, int entry, Vec& dx) noexcept {
  const SampledLaw& law = *law_;
  const double position = (t - law.t0()) / law.period();
  const int k = std::clamp(static_cast<int>(std::floor(position)), 0, law.steps() - 1);
  const double theta = std::clamp(position - k, 0.0, 1.0);
  A_t_ = (1.0 - theta) * law.A(k) + theta * law.A(k + 1);
  B_t_ = (1.0 - theta) * law.B(k) + theta * law.B(k + 1);
  law.trajectory().u_d(t, u_d_.data());
  ue_ = history_u_.col(entry) - u_d_;
  dx.noalias() = A_t_ * x;
  dx.noalias() += B_t_ * ue_;
}

void OnlineController::predict_to(double t) noexcept {
  const int capacity = options_.history;
  double s = t_x_;
  while (s < t) {
    // The command applied from s on, until the next one (or t).
    const int entry = entry_at(s);
    const int next = (entry - history_start_ + capacity) % capacity + 1;
    double end = t;
    if (next < history_size_) end = std::min(t, history_t_[static_cast<std::size_t>((history_start_ + next) % capacity)]);
    const int substeps = std::max(1, static_cast<int>(std::ceil((end - s) / kMaxSubstep - 1e-9)));
    const double h = (end - s) / substeps;
    for (int i = 0; i < substeps; ++i) {
      const double a = s + i * h, mid = a + 0.5 * h, b = i + 1 == substeps ? end : a + h;
      const double dt = b - a;
      derivative(a, x_, entry, k1_);
      x_stage_ = x_ + 0.5 * dt * k1_;
      derivative(mid, x_stage_, entry, k2_);
      x_stage_ = x_ + 0.5 * dt * k2_;
      derivative(mid, x_stage_, entry, k3_);
      x_stage_ = x_ + dt * k3_;
      derivative(b, x_stage_, entry, k4_);
      x_ += (dt / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
    }
    s = end;
  }
  t_x_ = std::max(t_x_, t);
}

StepReport OnlineController::step(double t_now, const double* q, double t_meas, double* u) noexcept {
  StepReport report;
  if (!reset_) return report;
  ++counts_.steps;
  const int n = this->n(), m = this->m();
  auto hold = [&](StepStatus status) {
    for (int i = 0; i < m; ++i) u[i] = u_held_[i];
    report.status = status;
    return report;
  };
  if (!std::isfinite(t_now) || t_now < t_last_) {
    ++counts_.refused;
    return hold(StepStatus::Refused);
  }
  if (t_now >= law_->t_end()) {
    ++counts_.past_horizon;
    return hold(StepStatus::PastHorizon);
  }

  // The measurement.
  MeasurementUse use = MeasurementUse::Used;
  if (q == nullptr) {
    use = MeasurementUse::Missing;
  } else {
    bool finite = std::isfinite(t_meas);
    for (int i = 0; i < n && finite; ++i) finite = std::isfinite(q[i]);
    if (!finite)
      use = MeasurementUse::NotFinite;
    else if (t_meas > t_now)
      use = MeasurementUse::Future;
    else if (t_meas <= t_meas_last_)
      use = MeasurementUse::Duplicate;
    else if (t_now - t_meas > options_.max_age || t_meas < history_t_[static_cast<std::size_t>(history_start_)])
      use = MeasurementUse::Stale;
  }
  report.measurement = use;
  report.status = StepStatus::Ok;

  // The law acts on the estimate at t_now; without delay compensation, on q_e(t_meas) as the
  // law at t_meas would (the command is one computed for t_meas, applied late).
  const SampledLaw& law = *law_;
  const bool late = use == MeasurementUse::Used && !options_.compensate_delay;
  const double t_law = late ? t_meas : t_now;
  const int k = std::clamp(static_cast<int>(std::floor((t_law - law.t0()) / law.period() + 1e-9)), 0, law.steps() - 1);
  law.trajectory().u_d(t_law, u_ff_.data());
  if (use == MeasurementUse::Used) {
    law.trajectory().q_d(t_meas, q_d_.data(), &q_cursor_);
    tracking_error(n, heading_, q, q_d_.data(), x_.data());
    t_x_ = t_meas;
    t_meas_last_ = t_meas;
    ++counts_.used;
  } else {
    ++counts_.predicted;
  }
  if (late) u_.noalias() = -law.gain(k) * x_;
  predict_to(t_now);
  if (!late) u_.noalias() = -law.gain(k) * x_;
  u_ += u_ff_;

  // The limits: the rate from the command held, then the bounds.
  const ActuatorLimits& limits = options_.limits;
  const double dt = t_now - t_held_;
  for (int i = 0; i < m; ++i) {
    double v = u_[i];
    if (limits.rate_max.size() > 0 && std::isfinite(limits.rate_max[i])) {
      const double step = limits.rate_max[i] * dt;
      const double limited = std::clamp(v, u_held_[i] - step, u_held_[i] + step);
      if (limited != v) report.rate_limited = true;
      v = limited;
    }
    const double lo = limits.u_min.size() > 0 ? limits.u_min[i] : -INFINITY;
    const double hi = limits.u_max.size() > 0 ? limits.u_max[i] : INFINITY;
    const double bounded = std::clamp(v, lo, hi);
    if (bounded != v) report.saturated = true;
    u_[i] = bounded;
    u[i] = bounded;
    counts_.largest_command = std::max(counts_.largest_command, std::abs(bounded));
  }
  counts_.saturated += report.saturated;
  counts_.rate_limited += report.rate_limited;
  u_held_ = u_;
  t_held_ = t_now;
  t_last_ = t_now;
  remember(t_now, u_);
  return report;
}

}  // namespace hinf
