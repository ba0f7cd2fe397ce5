// The controller on a vehicle: called once per sample with the latest measurement, it answers
// with the command to apply now and hold until the next call.
//
// Two objects, as a design and a context: a SampledLaw (the design tabulated on the controller's
// sample grid t_k = t0 + k T; immutable, shared by any number of vehicles and threads) and an
// OnlineController (one per vehicle: the estimate, the command held, the statistics). All the
// memory of step() is taken at construction: step() allocates nothing, takes no lock and never
// throws (errors are statuses).
//
// State feedback, step(t_now, q, t_meas, u): q is the full state measured at t_meas <= t_now. The
// controller keeps the estimate of the tracking error q_e = q - q_d (heading wrapped, angles.hpp)
// and the commands it applied. A measurement used resets the estimate to q - q_d(t_meas); with
// delay compensation the estimate is then predicted to t_now along the linearization
//     dq_e/dt = A_e(t) q_e + B_e(t) (u(t) - u_d(t)),
// with u(t) the commands actually applied (after limits), A_e and B_e interpolated linearly between
// the samples, classical Runge-Kutta steps of at most 5 ms, restarted where the command changed.
// A sample without a usable measurement (none, stale, a duplicate, ...) predicts the estimate
// from the last call in the same way. Then
//     u = u_d(t_now) - K_k q_e(t_now),   k the sample that holds t_now
// (without delay compensation, u_d(t_meas) - K q_e(t_meas) with the sample of t_meas),
// limited: first the rate, |u - u_held| <= rate_max (t_now - t_held) per channel, then the bounds
// u_min <= u <= u_max. The command returned is the one applied, and the one the prediction uses.
//
// Output feedback (OnlineOptions::filter with a weight N): the measurement is y = C q + noise
// (p numbers, C the model's), and the controller runs the estimator (35) and the filter (36) of
// output_feedback.hpp along the desired trajectory:
//     dq_hat/dt = A_e q_hat + B_e (u - u_d) + gamma^-2 D_e D_e' Z q_hat
//                 + [I - gamma^-2 Sigma Z]^-1 Sigma C' N^-1 (y_e - C q_hat),
//     dSigma/dt = A_e Sigma + Sigma A_e' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D_e D_e',
// with A_e, B_e, D_e and Z (the design's Z(t_k), or M_k of the digital design) interpolated
// linearly between samples: the estimator's drift is the linearization, A(q_hat) q_hat + alpha
// of (35) less its second-order remainder, so that a step needs nothing of the model but its
// tables. A measurement y taken at t_meas enters as the measured error y_e = y - C q_d(t_meas)
// (the heading's component, and the innovation's, wrapped), in one of two ways
// (OnlineFilter::update):
//   - sampled (the default): once, at t_meas, as the sampled-measurement form of (35)-(36):
//         Sigma+ = (Sigma^-1 + C' R^-1 C)^-1,   R = N / hold,
//         q_hat+ = q_hat + [I - gamma^-2 Sigma+ Z]^-1 Sigma+ C' R^-1 (y_e - C q_hat),
//     with R the noise covariance of one measurement (N is an intensity, hold the sensor's
//     period); between measurements the innovation terms are off. The command of the same step
//     sees the measurement. As hold -> 0 this is (35)-(36) with y held; at gamma = inf it is the
//     continuous-discrete Kalman filter.
//   - held: in the innovation terms of (35)-(36) from t_meas for `hold` seconds and until a newer
//     one is used (the error changes slowly where the vehicle's position does not, so holding it
//     costs little); the command of the same step does not see it yet.
//   - discrete (the digital law only): the central controller of discrete_output_feedback.hpp on
//     the law's samples t_k, with R = N / hold. A measurement of sample k (t_meas in
//     [t_k, t_{k+1})) enters the worst-case state x_w of that sample, and so every command of
//     it from then on, u = u_d(t_now) - F_k x_w, and the estimate of sample k + 1;
//     StepReport::rho_sigma_z is rho(Sigma_k M_k). The estimate is advanced sample by sample with the mean of the commands
//     applied over each sample (less u_d at its middle); a sample without a measurement predicts
//     (its Pi_k without C' R^-1 C). A measurement of a sample the estimate has passed is stale;
//     compensate_delay does not apply (the delay of one sample is the design's).
// Without a measurement the estimator runs open loop and Sigma grows. A measurement that arrives
// late (t_meas earlier than the last call) is used from its own time: the estimate is
// integrated again from the last measurement's time, where it is kept.
// Then u = u_d(t_now) - K_k q_hat(t_now) as above. The coupling condition rho(Sigma Z) < gamma^2
// is evaluated at every step (StepReport::rho_sigma_z); where it fails the estimator's gain is
// singular: the step is still computed, flagged, and counted.
#pragma once

#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "hinf/control/discrete_design.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/core/enum_names.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf {

namespace detail {
class OnlineEstimator;  // the output-feedback arithmetic (private: cpp/src/control/online_estimator.hpp)
}

// The law u = u_d(t) - K_k q_e tabulated at t_k = t0 + k T, k = 0 .. steps() - 1, with the
// linearization A_e(t_k), B_e(t_k), D_e(t_k) D_e(t_k)' and the game's value matrix Z_k (k = 0 .. steps())
// for the prediction and the estimator. Immutable.
class SampledLaw {
 public:
  // The continuous design emulated: K_k = kappa(t_k) B_e(t_k)' Z(t_k), held over each sample of
  // `period` (s). InputError for a period that is not > 0 or longer than the horizon, kappa not
  // > 0 at a sample, or u_d given as a function of t (a function may allocate and throw in
  // step(): give u_d as signals: constants, harmonics or tables).
  static std::shared_ptr<const SampledLaw> emulated(RiccatiSolutionPtr design, double period,
                                                    const Signal& kappa = Signal(1.0));
  // The digital design: K_k = F_k of the discrete game (discrete_design.hpp), at its period.
  static std::shared_ptr<const SampledLaw> digital(DiscreteDesignPtr design);

  // The desired trajectory of the design.
  const Trajectory& trajectory() const { return *trajectory_; }
  const TrajectoryPtr& trajectory_ptr() const { return trajectory_; }
  // "emulated" or "digital".
  const std::string& kind() const { return kind_; }
  // The gamma of the design (+inf: LQR).
  double gamma() const { return gamma_; }
  // The period T (s).
  double period() const { return period_; }
  // The number of states n and of inputs m.
  int n() const { return trajectory_->n(); }
  int m() const { return trajectory_->m(); }
  // The number of samples N.
  int steps() const { return static_cast<int>(K_.size()); }
  // The law is defined on [t0, t_end), t_end = t0 + N T <= tf (s).
  double t0() const { return trajectory_->t0(); }
  double t_end() const { return t0() + steps() * period_; }
  // K_k (m x n), and A_e(t_k) (n x n), B_e(t_k) (n x m); unchecked indices.
  const Mat& gain(int k) const { return K_[static_cast<std::size_t>(k)]; }
  const Mat& A(int k) const { return A_[static_cast<std::size_t>(k)]; }
  const Mat& B(int k) const { return B_[static_cast<std::size_t>(k)]; }
  // D_e(t_k) D_e(t_k)' (n x n) and Z_k (n x n: Z(t_k) of the continuous design, M_k of the
  // digital one), k = 0 .. steps(); unchecked indices.
  const Mat& DDt(int k) const { return DDt_[static_cast<std::size_t>(k)]; }
  const Mat& Z(int k) const { return Z_[static_cast<std::size_t>(k)]; }
  // The digital law's sampled linearization (discrete_design.hpp: A_k, B_k, D_k of the
  // zero-order hold), null for the emulated law; and D_k D_k' / T (n x n), k = 0 .. steps() - 1,
  // unchecked index.
  const SampledLinearizationPtr& sampled() const { return sampled_; }
  const Mat& discrete_DDt(int k) const { return discrete_DDt_[static_cast<std::size_t>(k)]; }

  // The tables (K: steps() gains; Z: steps() + 1 matrices); use emulated() or digital(). A
  // digital law samples its trajectory again unless `sampled` (of the same trajectory and
  // period) is given.
  SampledLaw(TrajectoryPtr trajectory, std::string kind, double gamma, double period, std::vector<Mat> K,
             std::vector<Mat> Z, SampledLinearizationPtr sampled = nullptr);

 private:
  TrajectoryPtr trajectory_;
  std::string kind_;
  double gamma_, period_;
  std::vector<Mat> K_, A_, B_, DDt_, Z_;
  SampledLinearizationPtr sampled_;
  std::vector<Mat> discrete_DDt_;
};

using SampledLawPtr = std::shared_ptr<const SampledLaw>;

// The actuators' limits. Empty vectors: no limit of that kind.
struct ActuatorLimits {
  Vec u_min;     // lower bounds of the command (m numbers; -inf: free)
  Vec u_max;     // upper bounds of the command (m numbers; +inf: free)
  Vec rate_max;  // largest |du/dt| per channel (units of u per second; +inf: free), > 0
  // InputError unless each vector is empty or has m numbers, u_min <= u_max, no NaN, rate_max > 0.
  void validate(int m) const;
};

// How a measurement enters the output-feedback estimator.
enum class MeasurementUpdate {
  Held,    // held in the innovation of (35)-(36) for `hold` seconds after its time (a continuous
           // measurement, as the batch loop's held noise)
  Sampled,  // once, at its time, as a jump of the estimate and Sigma (the sampled-measurement
            // form of (35)-(36), see the top of this file): the command of the same step sees it
  Discrete  // the digital law's own filter: the central controller of the discrete game with
            // one-step-delayed measurements (discrete_output_feedback.hpp), run on the law's
            // samples (see the top of this file); the digital law only
};
template <>
struct EnumNames<MeasurementUpdate> {
  static constexpr const char* what = "measurement update";
  static constexpr std::array<std::pair<MeasurementUpdate, const char*>, 3> names{
      {{MeasurementUpdate::Held, "held"},
       {MeasurementUpdate::Sampled, "sampled"},
       {MeasurementUpdate::Discrete, "discrete"}}};
};

// The filter of an output-feedback controller (see the top of this file). An empty N: state
// feedback (step() takes the full state).
struct OnlineFilter {
  Mat N;              // p x p, symmetric positive definite: the weight of the measurement noise
                      // in (36); for noise of standard deviation sigma per sample held over the
                      // sensor's period T_s, the continuous filter's intensity sigma^2 T_s
  Mat Sigma0;         // n x n, symmetric positive definite: Sigma at reset(), (Q0 - eta I)^-1
  Mat Q;              // n x n, symmetric positive semidefinite: the performance weight in (36)
  double hold = 0.0;  // s: the sensor's period; 0: the law's period. Held: how long a measurement
                      // stays in the innovation after its time; sampled: the noise covariance of
                      // one measurement is N / hold
  MeasurementUpdate update = MeasurementUpdate::Sampled;
  bool enabled() const { return N.size() > 0; }
  // InputError naming the matrix, for shapes (p measured outputs, n states) or values that do
  // not fit.
  void validate(int n, int p) const;
};

// The choices of an online controller.
struct OnlineOptions {
  OnlineFilter filter;           // output feedback (empty N: state feedback)
  ActuatorLimits limits;         // bounds and rate limits of the command
  double max_age = 1e300;        // s: a measurement older than this at t_now is stale (not used)
  bool compensate_delay = true;  // predict a measurement from t_meas to t_now (false: the command
                                 // is the law's at t_meas, u_d(t_meas) - K q_e(t_meas), as if
                                 // computed then and applied late)
  int history = 64;              // applied commands remembered (>= 2): a measurement older than
                                 // the oldest is stale
  void validate(int n, int m, int p) const;  // InputError naming the option (p: measured outputs)
};

// What step() did.
enum class StepStatus {
  Ok,           // a command was computed (see MeasurementUse for the measurement)
  Refused,      // t_now is not finite or earlier than the last call's: nothing changed, u is the
                // command held
  PastHorizon,  // t_now >= t_end, where the design ends: u is the command held; reset() with a
                // new design to continue
  NotReset,     // step() before reset(): u is left as it is
  Lost          // the estimate is not finite (output feedback: the filter's Sigma escaped, as the
                // H-infinity filter's does in a long enough time without measurements, or the
                // estimator's gain became singular at a coupling violation): u is the command held,
                // and every step answers Lost until reset()
};
template <>
struct EnumNames<StepStatus> {
  static constexpr const char* what = "step status";
  static constexpr std::array<std::pair<StepStatus, const char*>, 5> names{{{StepStatus::Ok, "ok"},
                                                                            {StepStatus::Refused, "refused"},
                                                                            {StepStatus::PastHorizon, "past_horizon"},
                                                                            {StepStatus::NotReset, "not_reset"},
                                                                            {StepStatus::Lost, "lost"}}};
};

// What became of the measurement given to step(). Anything but Used: the estimate was predicted.
enum class MeasurementUse {
  Used,       // used (and predicted to t_now with delay compensation)
  Missing,    // none given
  Stale,      // older than max_age at t_now, or than the commands remembered
  Duplicate,  // not newer than the last measurement used (the same one again, or out of order)
  Future,     // t_meas > t_now
  NotFinite   // t_meas or a component of q is NaN or infinite
};
template <>
struct EnumNames<MeasurementUse> {
  static constexpr const char* what = "measurement use";
  static constexpr std::array<std::pair<MeasurementUse, const char*>, 6> names{
      {{MeasurementUse::Used, "used"},
       {MeasurementUse::Missing, "missing"},
       {MeasurementUse::Stale, "stale"},
       {MeasurementUse::Duplicate, "duplicate"},
       {MeasurementUse::Future, "future"},
       {MeasurementUse::NotFinite, "not_finite"}}};
};

// The report of one step().
struct StepReport {
  StepStatus status = StepStatus::NotReset;               // what step() did
  MeasurementUse measurement = MeasurementUse::Missing;  // what became of the measurement
  bool saturated = false;     // a bound of u_min / u_max was active
  bool rate_limited = false;  // the rate limit was active
  double rho_sigma_z = NAN;   // output feedback: rho(Sigma Z) at t_now, against gamma^2 (NaN: state
                              // feedback)
  bool coupling_violated = false;  // output feedback: rho(Sigma Z) >= gamma^2 (the estimator's
                                   // gain is singular)
  bool window_stale = false;  // receding horizon (online_receding_horizon.hpp): the law in use is
                              // past its update period (the next window is late or failed)
};

// Counts since reset().
struct OnlineCounts {
  long steps = 0;         // calls of step() (any status)
  long used = 0;          // measurements used
  long predicted = 0;     // commands computed without a measurement (MeasurementUse other than Used)
  long refused = 0;       // StepStatus::Refused
  long past_horizon = 0;  // StepStatus::PastHorizon
  long lost = 0;          // StepStatus::Lost
  long saturated = 0;     // commands with a bound active
  long rate_limited = 0;  // commands with the rate limit active
  double largest_command = 0.0;  // max |u_i| over the commands computed
  long coupling_violated = 0;    // output feedback: steps with rho(Sigma Z) >= gamma^2
  double coupling_violation_t = NAN;  // output feedback: the t_now of the first such step
  double largest_rho = 0.0;      // output feedback: max rho(Sigma Z) / gamma^2 over the steps
};

// The controller of one vehicle, state or output feedback (see the top of this file).
class OnlineController {
 public:
  // InputError for a null law or bad options (a filter whose shapes do not fit the model's
  // measurement). Takes all the memory step() uses.
  OnlineController(SampledLawPtr law, const OnlineOptions& options = {});
  ~OnlineController();
  OnlineController(OnlineController&&) noexcept;
  OnlineController& operator=(OnlineController&&) noexcept;

  // The law and the options it was made with.
  const SampledLaw& law() const { return *law_; }
  const OnlineOptions& options() const { return options_; }
  // The number of states n (of q) and of inputs m (of u).
  int n() const { return law_->n(); }
  int m() const { return law_->m(); }
  // Output feedback (a filter in the options)?
  bool output_feedback() const { return filter_; }
  // The numbers step() takes: n (the state) or p (the measurement y = C q).
  int measurement_size() const { return filter_ ? p_ : n(); }

  // Starts at time t (in [t0, t_end)) from the state q (n; with output feedback the initial
  // estimate of the state, and Sigma = Sigma0): the estimate is q - q_d(t) and the command held is
  // u_held (m; empty: u_d(t) within the limits). InputError for a bad t, q or u_held (reset() may
  // allocate and throw; step() does neither).
  void reset(double t, const ConstVecRef& q, const ConstVecRef& u_held = Vec());

  // One sample: the measurement (measurement_size() numbers: q, or y with output feedback; null:
  // none) taken at t_meas, the command for t_now into u (m numbers). Never throws, never
  // allocates.
  StepReport step(double t_now, const double* measurement, double t_meas, double* u) noexcept;

  // The receding horizon (receding_horizon.hpp, online_receding_horizon.hpp): the law to use from
  // its first sample on, handed over whole. `next` must be an emulated law of the same model,
  // gamma and period whose t0 is a later sample of this controller's law (InputError otherwise,
  // or when a successor is still pending: see successor_state()). step() switches to it at its
  // first call with t_now >= next->t0(), without allocating or freeing: the law it leaves is kept
  // until take_retired(). The estimate, Sigma and the commands remembered carry over; a prediction
  // that reaches back before the new law's t0 uses its first sample's tables there. May be called
  // from another thread than step(): the handover is a release/acquire pair, no lock.
  void set_successor(SampledLawPtr next);
  // Where the handover stands: Empty (none offered), Offered (set_successor, not yet switched
  // to), Switched (step() switched; take_retired() makes it Empty again).
  enum class Handover { Empty = 0, Offered = 1, Switched = 2 };
  Handover successor_state() const noexcept { return static_cast<Handover>(handover_.value.load(std::memory_order_acquire)); }
  // After a switch: the law switched away from (and Empty again); null before one.
  SampledLawPtr take_retired();

  // The estimate of q_e at estimate_time() (n), the command held since held_time() (m).
  const Vec& estimate() const { return x_; }
  double estimate_time() const { return t_x_; }
  // The filter's Sigma at estimate_time() (n x n; empty for state feedback).
  const Mat& sigma() const { return Sigma_; }
  const Vec& held_command() const { return u_held_; }
  double held_time() const { return t_held_; }
  // The counts since reset().
  const OnlineCounts& counts() const { return counts_; }

 private:
  // The estimate (x_, and Sigma_ with output feedback) predicted from t_x_ to t along the
  // linearization with the applied commands (and the measurement held, while it is).
  void predict_to(double t) noexcept;
  // The history entry whose command is applied at t (the latest entry with time <= t).
  int entry_at(double t) const noexcept;
  // Until when the command of that entry is applied: the next entry's time, at most t.
  double command_end(int entry, double t) const noexcept;
  void remember(double t, const Vec& u) noexcept;
  // MeasurementUpdate::Discrete: the estimate advanced from sample k_est_ to k, each sample with
  // the mean command applied over it and the measurement pending for it, if any. False when the
  // filter failed (the estimate is then lost).
  bool advance_to(int k) noexcept;
  // MeasurementUpdate::Discrete: the measurement taken in (use may become Stale), the estimate
  // advanced to t_now's sample and the command before the limits into u_. False when the
  // estimate is lost.
  bool discrete_command(double t_now, const double* measurement, double t_meas, MeasurementUse& use,
                        StepReport& report) noexcept;
  // The coupling condition's rho of this step into the report and the counts.
  void record_coupling(double t_now, double rho, StepReport& report) noexcept;
  // The limits on u_ (the rate from the command held, then the bounds), the command applied
  // into u and remembered.
  StepReport limit_and_hold(double t_now, StepReport report, double* u) noexcept;

  SampledLawPtr law_;
  // The handover of set_successor: the successor while Offered, the law left while Switched.
  SampledLawPtr handover_law_;
  struct HandoverFlag {  // an atomic that moves with the controller (moved only when no thread steps it)
    std::atomic<int> value{0};
    HandoverFlag() = default;
    HandoverFlag(HandoverFlag&& other) noexcept : value(other.value.load()) {}
    HandoverFlag& operator=(HandoverFlag&& other) noexcept {
      value.store(other.value.load());
      return *this;
    }
  } handover_;
  OnlineOptions options_;
  int heading_;
  bool reset_ = false;
  bool lost_ = false;  // the estimate is not finite: every step answers Lost until reset()
  double t_last_ = 0.0;       // the last call's t_now
  double t_meas_last_ = 0.0;  // the last measurement used
  double t_x_ = 0.0, t_held_ = 0.0;
  Vec x_, u_held_, u_, u_ff_, q_d_;
  Vec u_entry_;  // a command of the history, for the prediction
  // The applied commands: a ring of options_.history entries (time, command), oldest first from
  // history_start_.
  std::vector<double> history_t_;
  Mat history_u_;  // m x history
  int history_start_ = 0, history_size_ = 0;
  std::size_t q_cursor_ = 0;
  OnlineCounts counts_;
  std::unique_ptr<detail::OnlineEstimator> estimator_;  // the arithmetic between calls (private)

  // Output feedback.
  bool filter_ = false;
  int p_ = 0, heading_row_ = -1;  // measured outputs; the row of C that measures the heading
  double hold_ = 0.0;
  Mat C_, Sigma_;
  Vec y_;                     // the measured error y - C q_d(t_meas) held
  bool have_y_ = false;       // a measurement is held in the innovation ...
  double y_until_ = 0.0;      // ... until this time
  // The estimate at the last measurement used (its time t_meas_last_), and the measurement then,
  // for a later measurement with an earlier time.
  Vec x_anchor_, y_anchor_;
  Mat Sigma_anchor_;
  bool have_y_anchor_ = false;
  double y_until_anchor_ = 0.0;
  // MeasurementUpdate::Discrete: the estimate is x_hat_{k_est_} (and Sigma_{k_est_}); the
  // measured error y_e of sample pending_k_ waits for the step to pending_k_ + 1 (-1: none).
  bool discrete_ = false;
  int k_est_ = 0, pending_k_ = -1;
  Vec x_worst_, u_mean_;
};

}  // namespace hinf
