#include "hinf/control/online_controller.hpp"

#include <algorithm>
#include <cmath>

#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/resources.hpp"
#include "control/online_estimator.hpp"

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

SampledLaw::SampledLaw(TrajectoryPtr trajectory, std::string kind, double gamma, double period, std::vector<Mat> K,
                       std::vector<Mat> Z, SampledLinearizationPtr sampled)
    : trajectory_(std::move(trajectory)), kind_(std::move(kind)), gamma_(gamma), period_(period), K_(std::move(K)),
      Z_(std::move(Z)), sampled_(std::move(sampled)) {
  require(trajectory_ != nullptr, "a sampled law needs its trajectory");
  require(!trajectory_->u_d_signal().is_function(),
          "the online controller needs u_d as signals (constants, harmonics or tables), not a function of t: a "
          "function may allocate and throw, which step() must not");
  require(kind_ == "emulated" || kind_ == "digital", "a sampled law is \"emulated\" or \"digital\", got \"", kind_,
          "\"");
  require(!std::isnan(gamma_) && gamma_ > 0.0, "a sampled law's gamma must be > 0 (or inf), got ", gamma_);
  const int N = sample_count(trajectory_->t0(), trajectory_->tf(), period_);
  require(static_cast<int>(K_.size()) == N && static_cast<int>(Z_.size()) == N + 1, "a sampled law of ", N,
          " samples needs ", N, " gains and ", N + 1, " matrices Z_k, got ", K_.size(), " and ", Z_.size());
  // Tables made elsewhere (a pickle, say) are checked as any input.
  const int n = trajectory_->n(), m = trajectory_->m();
  for (std::size_t k = 0; k < K_.size(); ++k)
    require(K_[k].rows() == m && K_[k].cols() == n && K_[k].allFinite(), "the gain K_", k, " must be a finite ", m,
            " x ", n, " matrix");
  for (std::size_t k = 0; k < Z_.size(); ++k)
    require(Z_[k].rows() == n && Z_[k].cols() == n && Z_[k].allFinite(), "Z_", k, " must be a finite ", n, " x ", n,
            " matrix");
  const Model& model = trajectory_->model();
  check_memory(8.0 * (N + 1.0) * model.n() * (3.0 * model.n() + 2.0 * model.m() + model.nw()),
               str_cat("a sampled law of ", N, " samples"), "choose a longer period (or a shorter horizon)");
  for (auto* table : {&A_, &B_, &DDt_}) table->reserve(static_cast<std::size_t>(N) + 1);
  Vec q_d(model.n());
  Mat D;
  for (int k = 0; k <= N; ++k) {
    const double t = std::min(trajectory_->t0() + k * period_, trajectory_->tf());
    A_.push_back(trajectory_->A_e(t));
    B_.push_back(trajectory_->B_e(t));
    trajectory_->q_d(t, q_d.data());
    D = model.D(t, q_d);
    DDt_.push_back(D * D.transpose());
  }
  if (kind_ == "digital") {
    if (sampled_ == nullptr) sampled_ = std::make_shared<const SampledLinearization>(trajectory_, period_);
    require(sampled_->trajectory_ptr() == trajectory_ && sampled_->period() == period_ && sampled_->steps() == N,
            "a digital law's sampled linearization must be of its own trajectory and period");
    discrete_DDt_.reserve(static_cast<std::size_t>(N));
    for (int k = 0; k < N; ++k) discrete_DDt_.push_back(sampled_->D(k) * sampled_->D(k).transpose() / period_);
  } else {
    sampled_ = nullptr;
  }
}

std::shared_ptr<const SampledLaw> SampledLaw::emulated(RiccatiSolutionPtr design, double period, const Signal& kappa) {
  require(design != nullptr, "the emulated law needs a design (a solution of the GRDE)");
  const Trajectory& trajectory = design->trajectory();
  const int N = sample_count(trajectory.t0(), trajectory.tf(), period);
  std::vector<Mat> K, Z;
  K.reserve(static_cast<std::size_t>(N));
  Z.reserve(static_cast<std::size_t>(N) + 1);
  for (int k = 0; k <= N; ++k) {
    const double t = std::min(trajectory.t0() + k * period, trajectory.tf());
    Z.push_back(design->Z(t));
    if (k == N) break;
    const double kappa_k = kappa(t);
    require(std::isfinite(kappa_k) && kappa_k > 0.0, "the gain scaling kappa must be > 0, got ", kappa_k, " at t = ", t);
    K.push_back(kappa_k * design->gain(t));
  }
  return std::make_shared<const SampledLaw>(design->trajectory_ptr(), "emulated", design->gamma(), period, std::move(K),
                                            std::move(Z));
}

std::shared_ptr<const SampledLaw> SampledLaw::digital(DiscreteDesignPtr design) {
  require(design != nullptr, "the digital law needs a discrete design");
  std::vector<Mat> K, Z;
  K.reserve(static_cast<std::size_t>(design->steps()));
  Z.reserve(static_cast<std::size_t>(design->steps()) + 1);
  for (int k = 0; k < design->steps(); ++k) K.push_back(design->gain(k));
  for (int k = 0; k <= design->steps(); ++k) Z.push_back(design->M(k));
  return std::make_shared<const SampledLaw>(design->sampled().trajectory_ptr(), "digital", design->gamma(),
                                            design->period(), std::move(K), std::move(Z), design->sampled_ptr());
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

void OnlineFilter::validate(int n, int p) const {
  if (!enabled()) return;
  check_symmetric_weight(N, p, "the filter's N", true);
  check_symmetric_weight(Sigma0, n, "the filter's Sigma0", true);
  check_symmetric_weight(Q, n, "the filter's Q", false);
  require(std::isfinite(hold) && hold >= 0.0, "the filter's hold must be >= 0 s (0: the law's period), got ", hold);
}

void OnlineOptions::validate(int n, int m, int p) const {
  filter.validate(n, p);
  limits.validate(m);
  require(!std::isnan(max_age) && max_age > 0.0, "max_age must be > 0 s, got ", max_age);
  require(history >= 2 && history <= 1000000, "history must be in [2, 1e6] commands, got ", history);
}

OnlineController::OnlineController(SampledLawPtr law, const OnlineOptions& options)
    : law_(std::move(law)), options_(options) {
  require(law_ != nullptr, "an online controller needs a sampled law");
  const int n = law_->n(), m = law_->m();
  const Model& model = law_->trajectory().model();
  filter_ = options_.filter.enabled();
  if (filter_) {
    C_ = model.C(law_->t0());
    p_ = static_cast<int>(C_.rows());
  }
  options_.validate(n, m, p_);
  heading_ = model.heading_index();
  for (Vec* v : {&x_, &q_d_}) v->setZero(n);
  for (Vec* v : {&u_held_, &u_, &u_ff_, &u_entry_}) v->setZero(m);
  history_t_.assign(static_cast<std::size_t>(options_.history), 0.0);
  history_u_.setZero(m, options_.history);
  if (filter_) {
    hold_ = options_.filter.hold > 0.0 ? options_.filter.hold : law_->period();
    // The measurement of the heading: the row of C that is the heading's unit row, if any; its
    // innovation is an angle (as in the batch loop, output_feedback.cpp).
    for (int row = 0; heading_ >= 0 && row < p_; ++row)
      if (C_(row, heading_) == 1.0 && C_.row(row).squaredNorm() == 1.0) heading_row_ = row;
    for (Mat* M : {&Sigma_, &Sigma_anchor_}) M->setZero(n, n);
    x_anchor_.setZero(n);
    for (Vec* v : {&y_, &y_anchor_}) v->setZero(p_);
    discrete_ = options_.filter.update == MeasurementUpdate::Discrete;
    require(!discrete_ || law_->kind() == "digital",
            "the discrete measurement update is the digital design's own filter: it needs a digital law "
            "(SampledLaw::digital; in a scenario [sampling] design = \"digital\"), got an ", law_->kind(), " law");
    x_worst_.setZero(n);
    u_mean_.setZero(m);
  }
  estimator_ = detail::make_online_estimator(*law_, options_.filter, C_, heading_row_);
}

OnlineController::~OnlineController() = default;

OnlineController::OnlineController(OnlineController&&) noexcept = default;
OnlineController& OnlineController::operator=(OnlineController&&) noexcept = default;

void OnlineController::set_successor(SampledLawPtr next) {
  require(next != nullptr, "the successor of an online controller's law is null");
  require(successor_state() == Handover::Empty,
          "the online controller has a successor law pending (or one switched from, not taken back): wait for "
          "the switch and take_retired() first");
  const SampledLaw& law = *law_;
  require(law.kind() == "emulated" && next->kind() == "emulated",
          "a law is handed over between windows of the receding horizon: both must be emulated laws");
  require(next->trajectory().model_ptr() == law.trajectory().model_ptr(),
          "the successor law is of another model than the controller's");
  require(next->gamma() == law.gamma() && next->period() == law.period(), "the successor law has gamma = ",
          next->gamma(), " and period ", next->period(), " s, the controller's law ", law.gamma(), " and ",
          law.period(), " s");
  const double samples = (next->t0() - law.t0()) / law.period();
  require(samples >= 1.0 - 1e-9 && std::abs(samples - std::round(samples)) <= 1e-9 * std::max(1.0, samples),
          "the successor law starts at t = ", next->t0(), ", not at a later sample of the controller's law (t0 = ",
          law.t0(), ", period ", law.period(), " s)");
  handover_law_ = std::move(next);
  handover_.value.store(static_cast<int>(Handover::Offered), std::memory_order_release);
}

SampledLawPtr OnlineController::take_retired() {
  if (successor_state() != Handover::Switched) return nullptr;
  SampledLawPtr retired = std::move(handover_law_);
  handover_law_ = nullptr;
  handover_.value.store(static_cast<int>(Handover::Empty), std::memory_order_release);
  return retired;
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
  if (filter_) {
    // The state given is an estimate, not a measurement: a measurement at t itself is new.
    t_meas_last_ = -INFINITY;
    Sigma_ = options_.filter.Sigma0;
    have_y_ = have_y_anchor_ = false;
    x_anchor_ = x_;
    Sigma_anchor_ = Sigma_;
    k_est_ = std::clamp(static_cast<int>(std::floor((t - law_->t0()) / law_->period() + 1e-9)), 0,
                        law_->steps() - 1);
    pending_k_ = -1;
  }
  remember(t, u_held_);
  counts_ = OnlineCounts();
  reset_ = true;
  lost_ = false;
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

double OnlineController::command_end(int entry, double t) const noexcept {
  const int capacity = options_.history;
  const int next = (entry - history_start_ + capacity) % capacity + 1;
  if (next >= history_size_) return t;
  return std::min(t, history_t_[static_cast<std::size_t>((history_start_ + next) % capacity)]);
}

void OnlineController::predict_to(double t) noexcept {
  double s = t_x_;
  while (s < t) {
    // The command applied from s on, until the next one (or t); the measurement held, until it
    // is no longer.
    const int entry = entry_at(s);
    double end = command_end(entry, t);
    const bool innovate = filter_ && have_y_ && s < y_until_;
    if (innovate) end = std::min(end, y_until_);
    const int substeps = std::max(1, static_cast<int>(std::ceil((end - s) / kMaxSubstep - 1e-9)));
    u_entry_ = history_u_.col(entry);
    estimator_->integrate(s, end, substeps, u_entry_, y_, innovate, x_, Sigma_);
    s = end;
  }
  t_x_ = std::max(t_x_, t);
}

bool OnlineController::advance_to(int k) noexcept {
  const SampledLaw& law = *law_;
  const double T = law.period();
  for (; k_est_ < k; ++k_est_) {
    // The mean of the commands applied over [t_k, t_{k+1}), less u_d at the sample's middle.
    const double a = law.t0() + k_est_ * T, b = a + T;
    u_mean_.setZero();
    double s = a;
    while (s < b) {
      const int entry = entry_at(s);
      const double end = command_end(entry, b);
      u_mean_ += ((end - s) / T) * history_u_.col(entry);
      s = end;
    }
    law.trajectory().u_d(a + 0.5 * T, u_entry_.data());
    u_mean_ -= u_entry_;
    const bool measured = pending_k_ == k_est_;
    if (!estimator_->advance(k_est_, u_mean_, measured ? &y_ : nullptr, x_, Sigma_)) return false;
    if (measured) pending_k_ = -1;
  }
  t_x_ = law.t0() + k_est_ * T;
  return true;
}

bool OnlineController::discrete_command(double t_now, const double* measurement, double t_meas, MeasurementUse& use,
                                        StepReport& report) noexcept {
  const SampledLaw& law = *law_;
  auto sample_of = [&law](double t) {
    return std::clamp(static_cast<int>(std::floor((t - law.t0()) / law.period() + 1e-9)), 0, law.steps() - 1);
  };
  if (use == MeasurementUse::Used) {
    const int j = sample_of(t_meas);
    if (j < k_est_) {
      use = MeasurementUse::Stale;  // its sample is already in the estimate
    } else {
      if (!advance_to(j)) return false;
      law.trajectory().q_d(t_meas, q_d_.data(), &q_cursor_);
      for (int i = 0; i < p_; ++i) y_[i] = measurement[i];
      y_.noalias() -= C_ * q_d_;
      if (heading_row_ >= 0) y_[heading_row_] = wrap_angle(y_[heading_row_]);
      pending_k_ = j;
      t_meas_last_ = t_meas;
    }
  }
  report.measurement = use;
  if (use == MeasurementUse::Used)
    ++counts_.used;
  else
    ++counts_.predicted;
  const int k = sample_of(t_now);
  if (!advance_to(k)) return false;
  const double rho = estimator_->worst_case_state(k, x_, Sigma_, pending_k_ == k ? &y_ : nullptr, x_worst_);
  law.trajectory().u_d(t_now, u_ff_.data());
  u_.noalias() = -law.gain(k) * x_worst_;
  u_ += u_ff_;
  if (!u_.allFinite() || !Sigma_.allFinite()) return false;
  record_coupling(t_now, rho, report);
  return true;
}

StepReport OnlineController::step(double t_now, const double* measurement, double t_meas, double* u) noexcept {
  StepReport report;
  if (!reset_) return report;
  ++counts_.steps;
  const int n = this->n(), m = this->m(), size = measurement_size();
  auto hold = [&](StepStatus status) {
    for (int i = 0; i < m; ++i) u[i] = u_held_[i];
    report.status = status;
    return report;
  };
  if (lost_) {
    ++counts_.lost;
    return hold(StepStatus::Lost);
  }
  if (!std::isfinite(t_now) || t_now < t_last_) {
    ++counts_.refused;
    return hold(StepStatus::Refused);
  }
  // The receding horizon's successor law, from its first sample on: a swap of two pointers (the
  // law left stays in handover_law_ for take_retired).
  if (handover_.value.load(std::memory_order_acquire) == static_cast<int>(Handover::Offered) &&
      t_now >= handover_law_->t0() - 1e-9 * law_->period()) {
    law_.swap(handover_law_);
    estimator_->set_law(*law_);
    q_cursor_ = 0;
    handover_.value.store(static_cast<int>(Handover::Switched), std::memory_order_release);
  }
  if (t_now >= law_->t_end()) {
    ++counts_.past_horizon;
    return hold(StepStatus::PastHorizon);
  }

  // The measurement.
  MeasurementUse use = MeasurementUse::Used;
  const double oldest_command = history_t_[static_cast<std::size_t>(history_start_)];
  if (measurement == nullptr) {
    use = MeasurementUse::Missing;
  } else {
    bool finite = std::isfinite(t_meas);
    for (int i = 0; i < size && finite; ++i) finite = std::isfinite(measurement[i]);
    if (!finite)
      use = MeasurementUse::NotFinite;
    else if (t_meas > t_now)
      use = MeasurementUse::Future;
    else if (t_meas <= t_meas_last_)
      use = MeasurementUse::Duplicate;
    else if (t_now - t_meas > options_.max_age || t_meas < oldest_command ||
             (filter_ && t_meas < t_x_ && t_meas_last_ < oldest_command))
      use = MeasurementUse::Stale;
  }
  report.measurement = use;
  report.status = StepStatus::Ok;
  if (discrete_) {
    if (!discrete_command(t_now, measurement, t_meas, use, report)) {
      lost_ = true;
      ++counts_.lost;
      return hold(StepStatus::Lost);
    }
    return limit_and_hold(t_now, report, u);
  }

  // The law acts on the estimate at t_now; without delay compensation, on q_e(t_meas) as the
  // law at t_meas would (the command is one computed for t_meas, applied late).
  const SampledLaw& law = *law_;
  const bool late = use == MeasurementUse::Used && !options_.compensate_delay;
  const double t_law = late ? t_meas : t_now;
  const int k = std::clamp(static_cast<int>(std::floor((t_law - law.t0()) / law.period() + 1e-9)), 0, law.steps() - 1);
  law.trajectory().u_d(t_law, u_ff_.data());
  if (use == MeasurementUse::Used && !filter_) {
    law.trajectory().q_d(t_meas, q_d_.data(), &q_cursor_);
    tracking_error(n, heading_, measurement, q_d_.data(), x_.data());
    t_x_ = t_meas;
  } else if (use == MeasurementUse::Used) {
    // The estimator to t_meas with the measurement held before, from the last measurement's
    // estimate when t_meas is earlier than the estimate's time; then this measurement is held.
    if (t_meas < t_x_) {
      x_ = x_anchor_;
      Sigma_ = Sigma_anchor_;
      t_x_ = t_meas_last_;
      have_y_ = have_y_anchor_;
      y_ = y_anchor_;
      y_until_ = y_until_anchor_;
    }
    predict_to(t_meas);
    // The measured error y_e = y - C q_d(t_meas) is held: the error changes slowly where the
    // vehicle's position does not (a held position would lag the moving vehicle).
    law.trajectory().q_d(t_meas, q_d_.data(), &q_cursor_);
    for (int i = 0; i < p_; ++i) y_[i] = measurement[i];
    y_.noalias() -= C_ * q_d_;
    if (heading_row_ >= 0) y_[heading_row_] = wrap_angle(y_[heading_row_]);
    if (options_.filter.update == MeasurementUpdate::Sampled) {
      estimator_->update(t_meas, y_, x_, Sigma_);  // once, now: nothing is held
    } else {
      have_y_ = true;
      y_until_ = t_meas + hold_;
    }
    x_anchor_ = x_;
    Sigma_anchor_ = Sigma_;
    y_anchor_ = y_;
    have_y_anchor_ = have_y_;
    y_until_anchor_ = y_until_;
  }
  if (use == MeasurementUse::Used) {
    t_meas_last_ = t_meas;
    ++counts_.used;
  } else {
    ++counts_.predicted;
  }
  if (late) u_.noalias() = -law.gain(k) * x_;
  predict_to(t_now);
  if (!late) u_.noalias() = -law.gain(k) * x_;
  u_ += u_ff_;
  if (!u_.allFinite() || (filter_ && !Sigma_.allFinite())) {
    lost_ = true;
    ++counts_.lost;
    return hold(StepStatus::Lost);
  }
  if (filter_) record_coupling(t_now, estimator_->coupling(t_now, Sigma_), report);
  return limit_and_hold(t_now, report, u);
}
void OnlineController::record_coupling(double t_now, double rho, StepReport& report) noexcept {
  const double gamma2 = law_->gamma() * law_->gamma();
  report.rho_sigma_z = rho;
  report.coupling_violated = !(rho < gamma2);
  counts_.coupling_violated += report.coupling_violated;
  if (report.coupling_violated && std::isnan(counts_.coupling_violation_t)) counts_.coupling_violation_t = t_now;
  if (std::isfinite(gamma2)) counts_.largest_rho = std::max(counts_.largest_rho, rho / gamma2);
}

StepReport OnlineController::limit_and_hold(double t_now, StepReport report, double* u) noexcept {
  const int m = this->m();
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
