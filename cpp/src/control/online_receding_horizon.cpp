#include "hinf/control/online_receding_horizon.hpp"

#include <chrono>
#include <cmath>
#include <utility>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

RecedingOnlineController::RecedingOnlineController(std::shared_ptr<const RecedingHorizon> horizon, double period,
                                                   const OnlineOptions& options, const Signal& kappa, bool background)
    : horizon_(std::move(horizon)), period_(period), options_(options), kappa_(kappa), background_(background) {
  require(horizon_ != nullptr, "the receding-horizon controller needs a RecedingHorizon");
  require(std::isfinite(period_) && period_ > 0.0, "the controller's period must be > 0 s, got ", period_);
  update_ = horizon_->options().update;
  t0_ = horizon_->t0();
  const double ratio = update_ / period_;
  require(ratio >= 1.0 - 1e-9 && std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio,
          "the receding horizon's update period (", update_, " s) must be a whole multiple of the controller's period ",
          period_, " s: a window's law starts at a sample");
  require(!horizon_->u_d_signal().is_function(),
          "the online controller needs u_d as signals (constants, harmonics or tables), not a function of t");
}

RecedingOnlineController::~RecedingOnlineController() { stop_thread(); }

const OnlineController& RecedingOnlineController::controller() const {
  require(controller_ != nullptr, "the receding-horizon controller has no online controller before reset()");
  return *controller_;
}

void RecedingOnlineController::stop_thread() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void RecedingOnlineController::reset(double t, const ConstVecRef& q, const ConstVecRef& u_held) {
  stop_thread();
  const RecedingHorizon& h = *horizon_;
  const int j = h.window_at(t);
  // The desired trajectory chained from q_d0 to the window of t.
  Vec q_start = h.q_d0();
  for (int i = 0; i < j; ++i) q_start = h.window_trajectory(i, q_start)->q_d(h.window_start(i + 1));
  const HorizonWindow window = h.window(j, q_start);
  auto controller = std::make_unique<OnlineController>(SampledLaw::emulated(window.design, period_, kappa_), options_);
  controller->reset(t, q, u_held);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    controller_ = std::move(controller);
    stop_ = false;
    next_window_ = j + 1;
    next_q_start_ = window.trajectory->q_d(h.window_start(j + 1));
    status_ = RecedingOnlineStatus();
    status_.window_in_use = j;
    status_.windows_solved = 1;
  }
  finished_.store(j);
  in_use_.store(j);
  stale_steps_.store(0);
  if (background_) thread_ = std::thread([this] { run_thread(); });
}

bool RecedingOnlineController::work_once() {
  OnlineController& controller = *controller_;
  switch (controller.successor_state()) {
    case OnlineController::Handover::Offered:
      return false;  // the next window waits for its first sample
    case OnlineController::Handover::Switched:
      controller.take_retired();  // freed here, not in step()
      return true;
    case OnlineController::Handover::Empty:
      break;
  }
  int j;
  Vec q_start;
  std::shared_ptr<const RecedingHorizon> horizon;  // as it is now: a path change may replace it
  {
    std::lock_guard<std::mutex> lock(mutex_);
    j = next_window_;
    q_start = next_q_start_;
    horizon = horizon_;
    solving_ = j;
  }
  const RecedingHorizon& h = *horizon;
  std::string failure;
  TrajectoryPtr trajectory;
  SampledLawPtr law;
  try {
    trajectory = h.window_trajectory(j, q_start);
    law = SampledLaw::emulated(solve_grde(trajectory, h.Q(), h.Qf(), h.gamma(), h.solver()), period_, kappa_);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++next_window_;
    solving_ = -1;
    if (trajectory) {
      next_q_start_ = trajectory->q_d(h.window_start(j + 1));
    } else {
      // Without a trajectory the chain cannot continue: the desired state of the next window is
      // unknown, so the windows stop here (the last good one serves to its end).
      stop_ = true;
    }
    if (law) {
      ++status_.windows_solved;
    } else {
      ++status_.windows_failed;
      status_.failed_t_start = h.window_start(j);
      status_.last_failure = str_cat("receding-horizon window ", j, " [", h.window_start(j), ", ",
                                     h.window_start(j) + h.options().window, "] s: ", failure);
    }
  }
  if (law) controller.set_successor(std::move(law));
  finished_.store(j);
  wake_.notify_all();
  return true;
}

void RecedingOnlineController::run_thread() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    lock.unlock();
    bool worked = true;
    std::string failure;
    try {
      worked = work_once();
    } catch (const std::exception& e) {
      // Nothing may leave the thread (that would end the program): the windows stop here, the
      // last good one serves to its end, and status() says why.
      failure = e.what();
    }
    lock.lock();
    if (!failure.empty()) {
      ++status_.windows_failed;
      status_.last_failure = "the receding horizon's solver stopped: " + failure;
      stop_ = true;
      wake_.notify_all();
      break;
    }
    // Waiting for the switch to the offered window: step() takes no lock, so the thread looks
    // again every millisecond instead of being woken.
    if (!worked) wake_.wait_for(lock, std::chrono::milliseconds(1), [this] { return stop_; });
  }
}

void RecedingOnlineController::synchronize(double t) {
  require(controller_ != nullptr, "synchronize() before reset()");
  require(std::isfinite(t) && t >= t0_, "synchronize at t = ", t, " before the horizon's t0 = ", t0_);
  // horizon_->window_at(t), without reading horizon_ (change_path may replace it meanwhile).
  const int j = static_cast<int>(std::floor((t - t0_) / update_ + 1e-9));
  if (!background_) {
    for (;;) {
      bool stopped;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        stopped = stop_;
      }
      if (finished_.load() >= j || stopped) return;
      if (!work_once()) return;  // the next window is offered and waits for its first sample
    }
  }
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.wait(lock, [&] { return finished_.load() >= j || stop_; });
}

StepReport RecedingOnlineController::step(double t_now, const double* measurement, double t_meas, double* u) noexcept {
  if (controller_ == nullptr) return StepReport();
  StepReport report = controller_->step(t_now, measurement, t_meas, u);
  const SampledLaw& law = controller_->law();
  const int j = static_cast<int>(std::lround((law.t0() - t0_) / update_));
  in_use_.store(j, std::memory_order_relaxed);
  // The law in use is older than its update period: the next window is late or failed.
  if (report.status == StepStatus::Ok && t_now >= law.t0() + update_ * (1.0 - 1e-9)) {
    report.window_stale = true;
    stale_steps_.fetch_add(1, std::memory_order_relaxed);
  }
  return report;
}

void RecedingOnlineController::change_path(double t_join, VectorSignal u_d) {
  std::lock_guard<std::mutex> lock(mutex_);
  require(controller_ != nullptr, "change_path() before reset()");
  require(!u_d.is_function(), "the online controller needs the new path's u_d as signals (constants, harmonics or"
          " tables), not a function of t");
  std::shared_ptr<const RecedingHorizon> changed = horizon_->with_path_change(t_join, std::move(u_d));
  const int j = horizon_->window_at(t_join);
  const int first_free = solving_ >= 0 ? solving_ + 1 : next_window_;
  require(j >= first_free, "the path change at t = ", t_join, " s joins window ", j, ", which is solved already: the"
          " first window free to change starts at ", horizon_->window_start(first_free), " s");
  horizon_ = std::move(changed);
}

RecedingOnlineStatus RecedingOnlineController::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  RecedingOnlineStatus s = status_;
  s.window_in_use = in_use_.load(std::memory_order_relaxed);
  s.stale_steps = stale_steps_.load(std::memory_order_relaxed);
  return s;
}

}  // namespace hinf
