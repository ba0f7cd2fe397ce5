// The online controller over a receding horizon (receding_horizon.hpp): the design of window j,
// emulated at the controller's period (SampledLaw::emulated), is the law from t_j on.
//
// Double buffering: while window j runs, the next window is solved on a thread of its own and
// handed over whole (OnlineController::set_successor); step() switches to it at its first sample
// by swapping two pointers. step() never waits for a solve, allocates nothing, takes no lock and
// never throws: the solver's thread allocates, and frees the laws left behind.
//
// A window that fails (its GRDE has a conjugate point at gamma, or an integration fails) is not
// handed over: the controller keeps the last good window, which serves until its own end t_j + H
// (StepReport::window_stale says so; past that end step() answers PastHorizon), status() names the
// failure, and the window after it is tried next. So does a window that is late (its solve took
// longer than the update period).
//
// With background = false nothing runs on another thread: synchronize(t) solves what is due.
// Simulations call synchronize(t) before every step in either mode, so that their results do not
// depend on how fast the windows are solved (simulate_sampled of sampled_loop.hpp).
#pragma once

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "hinf/control/online_controller.hpp"
#include "hinf/control/receding_horizon.hpp"

namespace hinf {

// What the receding horizon of an online controller has done since reset().
struct RecedingOnlineStatus {
  int window_in_use = -1;     // the index j of the window whose law step() uses
  int windows_solved = 0;     // windows solved and handed over (the first, at reset(), included)
  int windows_failed = 0;     // windows whose solve failed (not handed over)
  double failed_t_start = NAN;  // the t_j of the last window that failed (s)
  std::string last_failure;   // its error message; empty when none failed
  long stale_steps = 0;       // steps with StepReport::window_stale
};

// The online controller of one vehicle over a receding horizon (see the top of this file).
class RecedingOnlineController {
 public:
  // horizon: the windows' design; period: the controller's T (s), with update a whole multiple of
  // it; options as for OnlineController (a filter gives output feedback); kappa the gain scaling.
  // InputError for a null horizon, a period that does not divide the update period, or bad
  // options.
  RecedingOnlineController(std::shared_ptr<const RecedingHorizon> horizon, double period,
                           const OnlineOptions& options = {}, const Signal& kappa = Signal(1.0),
                           bool background = true);
  ~RecedingOnlineController();  // stops and joins the solver's thread
  RecedingOnlineController(const RecedingOnlineController&) = delete;
  RecedingOnlineController& operator=(const RecedingOnlineController&) = delete;

  const RecedingHorizon& horizon() const { return *horizon_; }
  double period() const { return period_; }
  // The options of every window's OnlineController.
  const OnlineOptions& options() const { return options_; }
  // The online controller that steps (its law is the window in use); InputError before reset().
  const OnlineController& controller() const;

  // Starts at t >= t0 from q (as OnlineController::reset): the windows' trajectories are chained
  // from q_d0 up to the window of t, which is solved here (blocking; ConjugatePointError when it
  // has no design at gamma), and the solver's thread starts on the next one. Stops a thread that
  // runs. May allocate and throw; step() does neither.
  void reset(double t, const ConstVecRef& q, const ConstVecRef& u_held = Vec());
  // One sample, as OnlineController::step; report.window_stale when the law in use is past its
  // update period. Never throws, never allocates, takes no lock.
  StepReport step(double t_now, const double* measurement, double t_meas, double* u) noexcept;
  // Blocks until every window that starts at or before t has been solved (handed over, or
  // failed). For simulations and tests, not for a vehicle's loop.
  void synchronize(double t);
  // What the horizon has done (takes a lock: not from the stepping thread in real time).
  RecedingOnlineStatus status() const;
  // A path changed under way (RecedingHorizon::with_path_change): the windows from the one that
  // starts at t_join on follow u_d (a new plan from the desired state there). t_join must be the
  // start of a window not yet solved: at least one update period after the window last handed
  // over, and not the one being solved (InputError otherwise, or before reset()). Takes the
  // solver's lock: from any thread but not in the stepping thread's real-time loop.
  void change_path(double t_join, VectorSignal u_d);

 private:
  // One unit of the solver's work: take back a law left behind, or solve and hand over the next
  // window. False when there is nothing to do now.
  bool work_once();
  void run_thread();
  void stop_thread();

  std::shared_ptr<const RecedingHorizon> horizon_;
  double period_;
  OnlineOptions options_;
  Signal kappa_;
  bool background_;
  std::unique_ptr<OnlineController> controller_;

  // The solver's side (guarded by mutex_): the next window to solve and its desired start.
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
  bool stop_ = false;
  int next_window_ = 0;
  int solving_ = -1;  // the window being solved outside the lock (-1: none)
  Vec next_q_start_;
  RecedingOnlineStatus status_;
  std::atomic<int> finished_{-1};  // the highest window index solved or failed
  // The stepping side.
  std::atomic<int> in_use_{-1};
  std::atomic<long> stale_steps_{0};
  double update_ = 0.0, t0_ = 0.0;  // the horizon's update period and t0, for step()
};

}  // namespace hinf
