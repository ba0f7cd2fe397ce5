// The online controller (control/online_controller.hpp):
//   * step() allocates nothing: a replaced global operator new counts the heap allocations of
//     100 000 steps through every path (measurements used, missing, stale, duplicate, limits);
//   * the prediction on a scalar LTI system against the closed form, with the command applied
//     (after the limits), not the law's;
//   * limits held exactly, every time case a status;
//   * closed loops of the paper's ship written here (a fixed-step RK4 of the plant with the command
//     held between samples, the controller called as a vehicle would): sampled at T = 0.01 s within
//     1% of the continuous loop's RMS tracking error, at 0.1 s within 5%; a one-sample computation
//     delay compensated within 10% of the undelayed loop, and at T = 0.5 s the prediction removes
//     more than half of what the delay costs;
//   * the library's sampled loop (control/sampled_loop.hpp) against the loop written here;
//   * output feedback: the filter's Sigma against the Kalman-Bucy closed form, a late measurement
//     against the same measurement on time, and the paper's Figure 2 sampled at T = 0.01 s and
//     0.1 s against the continuous loop with the same noise samples.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <vector>

#include "hinf/control/controller.hpp"
#include "hinf/control/discrete_design.hpp"
#include "hinf/control/analysis.hpp"
#include "hinf/control/discrete_output_feedback.hpp"
#include "hinf/control/online_controller.hpp"
#include "hinf/control/online_receding_horizon.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/sampled_loop.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"

// ---- heap allocation counter: every operator new of the process goes through here ----
// GCC inlines the replaced operators into library code and then warns that free() releases what
// operator new returned: here both are malloc and free.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
namespace {
// Only the thread that counts: the receding horizon's solver allocates on a thread of its own.
thread_local bool g_counting = false;
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  if (g_counting) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {

using hinf::MeasurementUse;
using hinf::StepStatus;
using hinf::Mat;
using hinf::Vec;
constexpr double kInf = std::numeric_limits<double>::infinity();

Mat m11(double x) { return Mat::Constant(1, 1, x); }

// dq/dt = a q + b u + d w along q_d = 0, u_d = 0 on [0, tf].
hinf::TrajectoryPtr scalar_trajectory(double a, double b, double tf) {
  auto model = std::make_shared<const hinf::LinearModel>(m11(a), m11(b), m11(1.0));
  return std::make_shared<const hinf::Trajectory>(model, Vec::Zero(1), hinf::VectorSignal::zeros(1), 0.0, tf);
}

hinf::SampledLawPtr scalar_law(double a, double b, double tf, double T) {
  return hinf::SampledLaw::emulated(hinf::solve_grde(scalar_trajectory(a, b, tf), m11(1.0), m11(1.0), 5.0), T);
}

// ---- the paper's run (docs/scenarios.md), Figure 1 ----
hinf::VectorSignal paper_u_d() {
  return hinf::VectorSignal(std::vector<hinf::Signal>{hinf::Signal(1.0),
                                                      hinf::Signal(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}})});
}
hinf::VectorSignal paper_w() {
  // The ship's w: three forces, then the three measurement-noise channels (zero here).
  const hinf::Signal w(0.0, {hinf::Harmonic{0.1, 2.0 * M_PI * 0.2, 0.0, true}}), zero(0.0);
  return hinf::VectorSignal(std::vector<hinf::Signal>{w, w, w, zero, zero, zero});
}
Vec paper_q0() {
  Vec q0(6);
  q0 << 1.0, 0.0, 0.0, -1.0, -1.0, M_PI / 4;
  return q0;
}

struct Paper {
  hinf::TrajectoryPtr trajectory;
  hinf::RiccatiSolutionPtr design;
  double continuous_rms;  // the continuous loop's RMS position error over [20, 40]
};

double rms_position_error_last_half(const std::vector<double>& t, const std::vector<Vec>& q,
                                    const hinf::Trajectory& trajectory) {
  // The ship's position is (x, y), states 3 and 4 (q = [u, v, r, x, y, psi]).
  const std::vector<int> position = trajectory.model().position_indices();
  double sum = 0.0;
  long count = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < 20.0 - 1e-9) continue;
    const Vec q_d = trajectory.q_d(t[i]);
    for (int j : position) sum += (q[i][j] - q_d[j]) * (q[i][j] - q_d[j]);
    ++count;
  }
  return std::sqrt(sum / count);
}

const Paper& paper() {
  static const Paper p = [] {
    Vec q_d0 = Vec::Zero(6);
    q_d0(0) = 1.0;
    Paper out;
    out.trajectory = std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::ShipModel>(), q_d0,
                                                              paper_u_d(), 0.0, 40.0);
    out.design = hinf::solve_grde(out.trajectory, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0);
    hinf::HinfStateFeedback law(out.design);
    hinf::SimulationOptions options;
    options.solver.rtol = 1e-9;
    options.solver.atol = 1e-11;
    const hinf::SimulationResult r =
        hinf::simulate_state_feedback(*out.trajectory, law, hinf::Disturbance(paper_w()), paper_q0(), options);
    std::vector<double> t(r.t.data(), r.t.data() + r.t.size());
    std::vector<Vec> q;
    for (Eigen::Index i = 0; i < r.q.rows(); ++i) q.push_back(r.q.row(i).transpose());
    out.continuous_rms = rms_position_error_last_half(t, q, *out.trajectory);
    return out;
  }();
  return p;
}

// The sampled loop as a vehicle runs it: at t_k = k T the state is measured; the command computed
// from it is applied from t_k + delay (delay = 0 or T) and held. The plant (the ship, with the
// paper's disturbance) is integrated here by classical RK4 with steps of 2.5 ms. Returns the RMS
// position error over [20, 40] on a 0.01 s grid, or +inf when |q - q_d| exceeds 100.
double sampled_loop_rms(const hinf::SampledLawPtr& law, double T, bool delayed, bool compensate) {
  const hinf::Trajectory& trajectory = *paper().trajectory;
  const hinf::Model& ship = trajectory.model();
  const hinf::VectorSignal w = paper_w();
  hinf::OnlineOptions options;
  options.compensate_delay = compensate;
  hinf::OnlineController controller(law, options);
  Vec q = paper_q0();
  controller.reset(0.0, q);
  Vec u = controller.held_command(), u_next(2), dq(6), k1(6), k2(6), k3(6), k4(6), wv(6);
  auto rhs = [&](double t, const Vec& x, Vec& out) {
    ship.f(t, x, out);
    w.eval(t, wv.data());
    out += ship.G(t, x) * u + ship.D(t, x) * wv;
  };
  const double h = 0.0025;
  const int per_sample = static_cast<int>(std::lround(T / h));
  const int samples = static_cast<int>(std::lround(40.0 / T));
  std::vector<double> times;
  std::vector<Vec> states;
  Vec measured = q;
  for (int k = 0; k < samples; ++k) {
    const double t_k = k * T;
    if (!delayed) {
      const hinf::StepReport r = controller.step(t_k, q.data(), t_k, u.data());
      if (r.status != StepStatus::Ok && !(k == 0 && r.measurement == MeasurementUse::Duplicate)) return NAN;
    } else if (k > 0) {
      // The measurement of t_{k-1}, computed for one sample, applied now.
      controller.step(t_k, measured.data(), t_k - T, u.data());
    }
    measured = q;
    for (int i = 0; i < per_sample; ++i) {
      const double t = t_k + i * h;
      if (i % static_cast<int>(std::lround(0.01 / h)) == 0) {
        times.push_back(t);
        states.push_back(q);
      }
      rhs(t, q, k1);
      rhs(t + 0.5 * h, q + 0.5 * h * k1, k2);
      rhs(t + 0.5 * h, q + 0.5 * h * k2, k3);
      rhs(t + h, q + h * k3, k4);
      q += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      if (!q.allFinite() || (q - trajectory.q_d(t + h)).norm() > 100.0) return kInf;
    }
  }
  times.push_back(40.0);
  states.push_back(q);
  return rms_position_error_last_half(times, states, trajectory);
}

// ---------------------------------------------------------------------------------------------

TEST(OnlineController, StepAllocatesNothing) {
  const auto law = hinf::SampledLaw::emulated(paper().design, 0.05);
  hinf::OnlineOptions options;
  options.limits.u_min = Vec::Constant(2, -1.5);
  options.limits.u_max = Vec::Constant(2, 1.5);
  options.limits.rate_max = Vec::Constant(2, 4.0);
  options.max_age = 0.2;
  hinf::OnlineController controller(law, options);
  controller.reset(0.0, paper_q0());
  Vec q = paper_q0(), u(2);
  const double dt = 39.9 / 100000;
  long saturated = 0, predicted = 0;
  g_allocations = 0;
  g_counting = true;
  for (int i = 1; i <= 100000; ++i) {
    const double t = i * dt;
    const double* measurement = i % 7 == 0 ? nullptr : q.data();            // missing
    const double t_meas = i % 11 == 0 ? t - 0.5 : (i % 13 == 0 ? t - dt : t);  // stale / duplicate
    const hinf::StepReport r = controller.step(t, measurement, t_meas, u.data());
    saturated += r.saturated;
    predicted += r.measurement != MeasurementUse::Used;
    q.tail(3) += 0.01 * Vec::Constant(3, std::sin(i * 0.001));  // x, y, psi
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in 100 000 steps";
  // Every path was taken (not a loop that never reached the law).
  EXPECT_EQ(controller.counts().steps, 100000);
  EXPECT_GT(saturated, 0);
  EXPECT_GT(predicted, 20000);
  EXPECT_GT(controller.counts().rate_limited, 0);
}

hinf::OnlineFilter paper_filter();  // the paper's Figure-2 filter (below)

// The receding horizon's controller: its windows are solved on another thread and handed over
// while the vehicle steps, for state and output feedback; the stepping thread allocates nothing
// through the switches (and frees nothing: the solver's thread takes the laws left behind).
TEST(OnlineController, RecedingHorizonStepAllocatesNothingThroughSwitches) {
  for (bool output_feedback : {false, true}) {
    SCOPED_TRACE(output_feedback ? "output feedback" : "state feedback");
    hinf::RecedingHorizonOptions rh;
    rh.window = 5.0;
    rh.update = 0.5;
    auto horizon = std::make_shared<const hinf::RecedingHorizon>(
        paper().trajectory->model_ptr(), paper().trajectory->q_d0(), paper().trajectory->u_d_signal(), 0.0,
        Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0, rh);
    hinf::OnlineOptions options;
    options.limits.rate_max = Vec::Constant(2, 4.0);
    if (output_feedback) options.filter = paper_filter();
    hinf::RecedingOnlineController controller(horizon, 0.05, options);
    controller.reset(0.0, paper_q0());
    Vec measurement = output_feedback ? Vec(paper_q0().tail(3)) : paper_q0(), u(2);
    long switches = 0;
    int in_use = 0;
    g_allocations = 0;
    for (int k = 0; k < 600; ++k) {  // 30 s: 59 switches
      const double t = 0.05 * k;
      controller.synchronize(t);  // outside the count: it waits for the solver's thread
      g_counting = true;
      controller.step(t, measurement.data(), t, u.data());
      g_counting = false;
      const int now = controller.status().window_in_use;
      switches += now != in_use;
      in_use = now;
    }
    EXPECT_EQ(g_allocations.load(), 0) << "heap allocations on the stepping thread";
    EXPECT_EQ(switches, 59);
    EXPECT_EQ(controller.controller().counts().lost, 0);
  }
}

TEST(OnlineController, PredictionUsesTheAppliedCommand) {
  // x' = a x + b u: from x0 with u held, x(t0 + dt) = e^{a dt} x0 + b (e^{a dt} - 1) / a u.
  const double a = 0.3, b = 2.0;
  hinf::OnlineOptions options;
  options.limits.u_max = m11(0.05).col(0);
  options.limits.u_min = m11(-0.05).col(0);
  hinf::OnlineController controller(scalar_law(a, b, 10.0, 0.1), options);
  controller.reset(0.0, m11(1.0).col(0), m11(0.02).col(0));
  double u = 0.0;
  // A measurement at 0.1 s: the law asks for about -K x, far beyond the bound: the command applied
  // is -0.05.
  double x1 = 0.8;
  hinf::StepReport r = controller.step(0.1, &x1, 0.1, &u);
  EXPECT_EQ(r.status, StepStatus::Ok);
  EXPECT_EQ(r.measurement, MeasurementUse::Used);
  EXPECT_TRUE(r.saturated);
  EXPECT_EQ(u, -0.05);
  // No measurement at 0.3 s: the estimate is predicted with the applied -0.05 over 0.2 s.
  r = controller.step(0.3, nullptr, NAN, &u);
  EXPECT_EQ(r.measurement, MeasurementUse::Missing);
  const double e = std::exp(a * 0.2), expected = e * x1 + b * (e - 1.0) / a * (-0.05);
  // RK4 steps of 5 ms on a scalar linear equation: error ~ (a h)^5 / 120 per step, far below the
  // bound; 1e-10 leaves room for round-off on any CPU.
  EXPECT_NEAR(controller.estimate()[0], expected, 1e-10);
  EXPECT_EQ(controller.estimate_time(), 0.3);
  const double applied_since_03 = u;
  // Delay compensation: a measurement of 0.35 s at 0.4 s is predicted over 0.05 s with the command
  // applied since 0.3 s.
  const double x2 = 0.5;
  r = controller.step(0.4, &x2, 0.35, &u);
  EXPECT_EQ(r.measurement, MeasurementUse::Used);
  EXPECT_EQ(controller.held_command()[0], u);
  const double e2 = std::exp(a * 0.05);
  EXPECT_NEAR(controller.estimate()[0], e2 * x2 + b * (e2 - 1.0) / a * applied_since_03, 1e-10);
}

TEST(OnlineController, LimitsHoldExactly) {
  hinf::OnlineOptions options;
  options.limits.u_min = (Vec(2) << -0.5, -0.2).finished();
  options.limits.u_max = (Vec(2) << 1.5, 0.2).finished();
  options.limits.rate_max = (Vec(2) << 2.0, kInf).finished();
  hinf::OnlineController controller(hinf::SampledLaw::emulated(paper().design, 0.05), options);
  Vec q = paper_q0();
  q(5) = 3.0;  // a large heading error: commands far beyond the limits
  controller.reset(0.0, q);
  Vec u(2), previous = controller.held_command();
  double t_previous = 0.0;
  bool saw_rate = false, saw_bound = false;
  for (int i = 1; i <= 200; ++i) {
    const double t = i * 0.05;
    const hinf::StepReport r = controller.step(t, q.data(), t, u.data());
    ASSERT_EQ(r.status, StepStatus::Ok);
    EXPECT_LE(std::abs(u(0) - previous(0)), 2.0 * (t - t_previous) * (1 + 1e-15));
    for (int j = 0; j < 2; ++j) {
      EXPECT_GE(u(j), options.limits.u_min(j));
      EXPECT_LE(u(j), options.limits.u_max(j));
    }
    saw_rate |= r.rate_limited;
    saw_bound |= r.saturated;
    EXPECT_EQ(u, controller.held_command());
    previous = u;
    t_previous = t;
    q(5) -= 0.01;
  }
  EXPECT_TRUE(saw_rate);
  EXPECT_TRUE(saw_bound);
  EXPECT_LE(controller.counts().largest_command, 1.5);
}

TEST(OnlineController, EveryTimeCaseIsAStatus) {
  hinf::OnlineOptions options;
  options.max_age = 0.25;
  hinf::OnlineController controller(scalar_law(-1.0, 1.0, 2.0, 0.1), options);
  double u = 123.0, x = 0.5;
  EXPECT_EQ(controller.step(0.0, &x, 0.0, &u).status, StepStatus::NotReset);
  EXPECT_EQ(u, 123.0);
  controller.reset(0.0, m11(1.0).col(0));
  const double held0 = controller.held_command()[0];
  auto step = [&](double t_now, const double* q, double t_meas) { return controller.step(t_now, q, t_meas, &u); };

  hinf::StepReport r = step(0.2, &x, 0.2);
  EXPECT_EQ(r.measurement, MeasurementUse::Used);
  const double held = u;
  EXPECT_NE(held, held0);
  // Backwards in time: refused, nothing changes, the command held is returned.
  r = step(0.1, &x, 0.1);
  EXPECT_EQ(r.status, StepStatus::Refused);
  EXPECT_EQ(u, held);
  EXPECT_EQ(controller.estimate_time(), 0.2);
  r = step(NAN, &x, 0.1);
  EXPECT_EQ(r.status, StepStatus::Refused);
  // The same measurement again: a duplicate, predicted.
  r = step(0.3, &x, 0.2);
  EXPECT_EQ(r.status, StepStatus::Ok);
  EXPECT_EQ(r.measurement, MeasurementUse::Duplicate);
  // Older than max_age: stale.
  r = step(0.7, &x, 0.4);
  EXPECT_EQ(r.measurement, MeasurementUse::Stale);
  // From the future, not finite, missing.
  EXPECT_EQ(step(0.8, &x, 0.9).measurement, MeasurementUse::Future);
  const double nan = NAN;
  EXPECT_EQ(step(0.9, &nan, 0.85).measurement, MeasurementUse::NotFinite);
  EXPECT_EQ(step(1.0, &x, NAN).measurement, MeasurementUse::NotFinite);
  EXPECT_EQ(step(1.1, nullptr, NAN).measurement, MeasurementUse::Missing);
  EXPECT_EQ(controller.estimate_time(), 1.1);
  // The design ends at t_end = 2: past it, the command held.
  const double last = u;
  r = step(2.0, &x, 2.0);
  EXPECT_EQ(r.status, StepStatus::PastHorizon);
  EXPECT_EQ(u, last);
  const hinf::OnlineCounts& c = controller.counts();
  EXPECT_EQ(c.steps, 10);  // the call before reset() is not counted
  EXPECT_EQ(c.used, 1);
  EXPECT_EQ(c.predicted, 6);
  EXPECT_EQ(c.refused, 2);
  EXPECT_EQ(c.past_horizon, 1);
}

TEST(OnlineController, BadSetUpIsAnInputError) {
  const auto law = scalar_law(-1.0, 1.0, 2.0, 0.1);
  auto with = [&](auto edit) {
    hinf::OnlineOptions o;
    edit(o);
    return o;
  };
  EXPECT_THROW(hinf::OnlineController(nullptr), hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& o) { o.limits.u_min = Vec::Zero(2); })), hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& o) {
                 o.limits.u_min = m11(1.0).col(0);
                 o.limits.u_max = m11(0.0).col(0);
               })),
               hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& o) { o.limits.rate_max = m11(0.0).col(0); })),
               hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& o) { o.limits.u_max = m11(NAN).col(0); })),
               hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& o) { o.max_age = 0.0; })), hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& o) { o.history = 1; })), hinf::InputError);
  hinf::OnlineController controller(law);
  EXPECT_THROW(controller.reset(2.0, m11(0.0).col(0)), hinf::InputError);  // t_end
  EXPECT_THROW(controller.reset(0.0, Vec::Zero(2)), hinf::InputError);
  EXPECT_THROW(controller.reset(0.0, m11(NAN).col(0)), hinf::InputError);
  EXPECT_THROW(hinf::SampledLaw::emulated(paper().design, 0.0), hinf::InputError);
  EXPECT_THROW(hinf::SampledLaw::emulated(paper().design, 0.1, hinf::Signal(-1.0)), hinf::InputError);
  // u_d as a function of t: refused (it could allocate and throw inside step()).
  auto model = std::make_shared<const hinf::LinearModel>(m11(-1.0), m11(1.0), m11(1.0));
  const hinf::VectorSignal function(1, [](double) { return Vec::Zero(1); });
  const auto trajectory = std::make_shared<const hinf::Trajectory>(model, Vec::Zero(1), function, 0.0, 1.0);
  EXPECT_THROW(hinf::SampledLaw::emulated(hinf::solve_grde(trajectory, m11(1.0), m11(1.0), kInf), 0.1),
               hinf::InputError);
}

TEST(SampledLoop, ApproachesTheContinuousLoop) {
  const double continuous = paper().continuous_rms;
  ASSERT_GT(continuous, 0.01);
  for (auto [T, bound] : {std::pair{0.01, 0.01}, std::pair{0.1, 0.05}}) {
    const double emulated = sampled_loop_rms(hinf::SampledLaw::emulated(paper().design, T), T, false, true);
    const auto digital_law = hinf::SampledLaw::digital(
        hinf::solve_discrete_game(paper().trajectory, T, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0));
    const double digital = sampled_loop_rms(digital_law, T, false, true);
    std::printf("[sampled loop] T = %.2f s: RMS position error %.5f emulated, %.5f digital, %.5f continuous\n", T,
                emulated, digital, continuous);
    EXPECT_NEAR(emulated / continuous, 1.0, bound) << "emulated, T = " << T;
    EXPECT_NEAR(digital / continuous, 1.0, bound) << "digital, T = " << T;
  }
}

TEST(SampledLoop, ACompensatedDelayCostsLittle) {
  const double T = 0.1;
  const auto law = hinf::SampledLaw::emulated(paper().design, T);
  const double undelayed = sampled_loop_rms(law, T, false, true);
  const double compensated = sampled_loop_rms(law, T, true, true);
  const double uncompensated = sampled_loop_rms(law, T, true, false);
  std::printf("[sampled loop] T = 0.1 s: undelayed %.5f, one-sample delay compensated %.5f, uncompensated %.5f\n",
              undelayed, compensated, uncompensated);
  EXPECT_NEAR(compensated / undelayed, 1.0, 0.10);
  EXPECT_LT(compensated, uncompensated);
  // T = 0.5 s: the prediction over the delay removes most of what the delay costs (measured here:
  // 0.060 m undelayed, 0.082 compensated, 0.125 uncompensated; what remains is the disturbance
  // during the delay, which no prediction knows).
  const auto slow = hinf::SampledLaw::emulated(paper().design, 0.5);
  const double slow_undelayed = sampled_loop_rms(slow, 0.5, false, true);
  const double slow_compensated = sampled_loop_rms(slow, 0.5, true, true);
  const double slow_uncompensated = sampled_loop_rms(slow, 0.5, true, false);
  std::printf("[sampled loop] T = 0.5 s: undelayed %.5f, one-sample delay compensated %.5f, uncompensated %.5f\n",
              slow_undelayed, slow_compensated, slow_uncompensated);
  EXPECT_LT(slow_compensated - slow_undelayed, 0.5 * (slow_uncompensated - slow_undelayed));
  // T = 1 s: the compensated loop still converges (measured 0.126 m), the uncompensated one does
  // not (this file's loop overflows to inf; a scenario run gives 47 m: the ship is lost). At T = 0.5 s the uncompensated loop of this
  // computation-delay model still converges (0.125 m), where the first measurement had it
  // diverge.
  const auto slowest = hinf::SampledLaw::emulated(paper().design, 1.0);
  const double slowest_compensated = sampled_loop_rms(slowest, 1.0, true, true);
  const double slowest_uncompensated = sampled_loop_rms(slowest, 1.0, true, false);
  std::printf("[sampled loop] T = 1 s: one-sample delay compensated %.5f, uncompensated %.5f\n", slowest_compensated,
              slowest_uncompensated);
  EXPECT_LT(slowest_compensated, 0.2);
  EXPECT_FALSE(slowest_uncompensated < 10.0) << "inf or NaN: the loop blew up";
}

// simulate_sampled (Dormand-Prince between events, tight tolerances) against the loop of this file
// (RK4 with 2.5 ms steps, local error ~1e-13): the same RMS to 1e-6 relative, with and without
// a one-sample delay, and the same counts of the controller.
TEST(SampledLoop, TheLibrarysLoopIsTheLoopWrittenHere) {
  const hinf::Trajectory& trajectory = *paper().trajectory;
  for (auto [T, delayed] : {std::pair{0.1, false}, std::pair{0.1, true}, std::pair{0.5, true}}) {
    const auto law = hinf::SampledLaw::emulated(paper().design, T);
    hinf::OnlineController controller(law);
    hinf::SampledLoopOptions options;
    options.delay = delayed ? T : 0.0;
    options.simulation.solver.rtol = 1e-10;
    options.simulation.solver.atol = 1e-12;
    const hinf::SimulationResult r =
        hinf::simulate_sampled(trajectory, controller, hinf::Disturbance(paper_w()), paper_q0(), options);
    ASSERT_EQ(r.status, hinf::RunStatus::Completed);
    std::vector<double> t(r.t.data(), r.t.data() + r.t.size());
    std::vector<Vec> q;
    for (Eigen::Index i = 0; i < r.q.rows(); ++i) q.push_back(r.q.row(i).transpose());
    const double library = rms_position_error_last_half(t, q, trajectory);
    const double here = sampled_loop_rms(law, T, delayed, true);
    EXPECT_NEAR(library / here, 1.0, 1e-6) << "T = " << T << (delayed ? ", one sample late" : "");
    // One step per sample (the first answered with the state of reset(): a duplicate; one sample
    // late, the last at t = 40, past the law's end).
    EXPECT_EQ(controller.counts().steps, std::lround(40.0 / T));
    EXPECT_EQ(controller.counts().past_horizon, delayed ? 1 : 0);
    // The command series is piecewise constant: it changes only at the application times.
    for (Eigen::Index i = 1; i < r.u.rows(); ++i) {
      const double since_sample = std::fmod(r.t[i] - options.delay + 1e-9, T);
      if (since_sample > 1e-6 && since_sample < T - 0.011) {
        EXPECT_EQ(r.u.row(i), r.u.row(i - 1)) << "t = " << r.t[i];
      }
    }
  }
}

TEST(SampledLoop, BadSetUpIsAnInputError) {
  const auto law = hinf::SampledLaw::emulated(paper().design, 0.1);
  hinf::OnlineController controller(law);
  hinf::SampledLoopOptions options;
  options.delay = 0.2;  // longer than T
  EXPECT_THROW(hinf::simulate_sampled(*paper().trajectory, controller, hinf::Disturbance(paper_w()), paper_q0(), options),
               hinf::InputError);
  options.delay = 0.0;
  EXPECT_THROW(hinf::simulate_sampled(*paper().trajectory, controller, hinf::Disturbance(paper_w()), Vec::Zero(5), options),
               hinf::InputError);
  // A law designed along another trajectory (same model, other horizon).
  const auto other = std::make_shared<const hinf::Trajectory>(paper().trajectory->model_ptr(),
                                                               paper().trajectory->q_d0(), paper_u_d(), 0.0, 20.0);
  EXPECT_THROW(hinf::simulate_sampled(*other, controller, hinf::Disturbance(paper_w()), paper_q0(), options),
               hinf::InputError);
}

// ---- output feedback ----

// The paper's Figure 2 set-up (scenarios/paper_fig2.toml): x, y, psi measured, sigma = 0.5 per
// sample, N = sigma^2 I, Sigma0 = (Q0 - eta I)^-1 = I, Q = I.
hinf::OnlineFilter paper_filter() {
  hinf::OnlineFilter filter;
  filter.N = 0.25 * Mat::Identity(3, 3);
  filter.Sigma0 = Mat::Identity(6, 6);
  filter.Q = Mat::Identity(6, 6);
  return filter;
}

double rms_last_half(const hinf::SimulationResult& r, const hinf::Trajectory& trajectory) {
  std::vector<double> t(r.t.data(), r.t.data() + r.t.size());
  std::vector<Vec> q;
  for (Eigen::Index i = 0; i < r.q.rows(); ++i) q.push_back(r.q.row(i).transpose());
  return rms_position_error_last_half(t, q, trajectory);
}

TEST(OutputFeedback, StepAllocatesNothing) {
  for (auto update : {hinf::MeasurementUpdate::Sampled, hinf::MeasurementUpdate::Held,
                      hinf::MeasurementUpdate::Discrete}) {
  SCOPED_TRACE(hinf::to_string(update));
  const auto law = update == hinf::MeasurementUpdate::Discrete
                       ? hinf::SampledLaw::digital(hinf::solve_discrete_game(
                             paper().trajectory, 0.05, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0))
                       : hinf::SampledLaw::emulated(paper().design, 0.05);
  hinf::OnlineOptions options;
  options.filter = paper_filter();
  options.filter.update = update;
  options.limits.u_min = Vec::Constant(2, -1.5);
  options.limits.u_max = Vec::Constant(2, 1.5);
  options.limits.rate_max = Vec::Constant(2, 4.0);
  options.max_age = 0.2;
  hinf::OnlineController controller(law, options);
  ASSERT_TRUE(controller.output_feedback());
  ASSERT_EQ(controller.measurement_size(), 3);
  controller.reset(0.0, paper_q0());
  Vec y = paper_q0().tail(3), u(2);
  const double dt = 39.9 / 100000;
  long late = 0;
  g_allocations = 0;
  g_counting = true;
  for (int i = 1; i <= 100000; ++i) {
    const double t = i * dt;
    const double* measurement = i % 7 == 0 ? nullptr : y.data();  // missing
    // stale, one step late (used after the estimate passed it), or on time
    const double t_meas = i % 11 == 0 ? t - 0.5 : (i % 13 == 0 ? t - 0.6 * dt : t);
    if (i % 13 == 0) {
      // the step before predicted past t_meas: the late measurement is integrated from the last one's
      // estimate
      late += t_meas < controller.estimate_time();
    }
    controller.step(t, measurement, t_meas, u.data());
    y += 0.01 * Vec::Constant(3, std::sin(i * 0.001));
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in 100 000 output-feedback steps";
  EXPECT_EQ(controller.counts().steps, 100000);
  EXPECT_GT(controller.counts().saturated, 0);
  EXPECT_GT(controller.counts().predicted, 20000);
  if (update != hinf::MeasurementUpdate::Discrete) {
    EXPECT_GT(late, 500);  // discrete: the estimate is at t_k
  }
  EXPECT_GT(controller.counts().largest_rho, 0.0);
  EXPECT_EQ(controller.counts().lost, 0);
  }
}

TEST(OutputFeedback, TheFilterIsKalmanBucysAsGammaGoesToInfinity) {
  // gamma = inf: (36) is the Kalman-Bucy equation dSigma/dt = 2 a Sigma - Sigma^2 c^2 / N + d^2,
  // whose solution from Sigma0 is known in closed form; with a measurement at t0 and at every
  // sample, each held over the sample, the innovation terms never switch off. RK4 steps of
  // h <= 5 ms on rates of at most 2 Sigma0 / N = 16 / s (h lambda <= 0.08): relative error per
  // step ~(h lambda)^5 / 5! ~ 3e-8, below 1e-5 over the run.
  const double a = -0.5, d = 1.0, N = 0.25;
  auto model = std::make_shared<const hinf::LinearModel>(m11(a), m11(1.0), m11(d), m11(1.0));
  const auto trajectory = std::make_shared<const hinf::Trajectory>(model, Vec::Zero(1), hinf::VectorSignal::zeros(1),
                                                                    0.0, 5.0);
  const auto law = hinf::SampledLaw::emulated(hinf::solve_grde(trajectory, m11(1.0), m11(1.0), kInf), 0.05);
  hinf::OnlineOptions options;
  options.filter.N = m11(N);
  options.filter.Sigma0 = m11(2.0);
  options.filter.Q = m11(1.0);
  options.filter.update = hinf::MeasurementUpdate::Held;
  hinf::OnlineController controller(law, options);
  controller.reset(0.0, m11(0.0).col(0));
  // Riccati ODE s' = -(s - s1)(s - s2) / N with roots s1,2 = N (a +- sqrt(a^2 + d^2 / N)):
  // (s - s1) / (s - s2) = (s0 - s1) / (s0 - s2) exp(-(s1 - s2) t / N).
  const double root = std::sqrt(a * a + d * d / N), s1 = N * (a + root), s2 = N * (a - root), s0 = 2.0;
  double u = 0.0, y = 0.0;
  EXPECT_EQ(controller.step(0.0, &y, 0.0, &u).measurement, MeasurementUse::Used);
  for (int k = 1; k < 100; ++k) {
    const double t = 0.05 * k;
    controller.step(t, &y, t, &u);
    const double ratio = (s0 - s1) / (s0 - s2) * std::exp(-(s1 - s2) * t / N);
    const double exact = (s1 - ratio * s2) / (1.0 - ratio);
    EXPECT_NEAR(controller.sigma()(0, 0), exact, 1e-5 * exact) << "t = " << t;
  }
}

TEST(OutputFeedback, TheSampledUpdateIsTheContinuousDiscreteKalmanFilterAtGammaInfinity) {
  // gamma = inf, dx/dt = a x + d w, y_k = c x(t_k) + v_k with Var v_k = R = N / hold: between
  // measurements Sigma solves dSigma/dt = 2 a Sigma + d^2, Sigma(t) = (Sigma+ + d^2 / (2a))
  // e^{2a(t - t_k)} - d^2 / (2a); at a measurement Sigma+ = 1 / (1 / Sigma- + c^2 / R) and
  // x+ = x- + Sigma+ c / R (y - c x-), x- = e^{a T} x+ (u pinned at 0 by u_min = u_max = 0).
  // RK4 steps of h <= 5 ms on rates |2a| = 1 / s: ~1e-12 relative.
  const double a = -0.5, c = 2.0, d = 1.0, N = 0.25, T = 0.05;
  auto model = std::make_shared<const hinf::LinearModel>(m11(a), m11(1.0), m11(d), m11(c));
  const auto trajectory = std::make_shared<const hinf::Trajectory>(model, Vec::Zero(1), hinf::VectorSignal::zeros(1),
                                                                    0.0, 5.0);
  const auto law = hinf::SampledLaw::emulated(hinf::solve_grde(trajectory, m11(1.0), m11(1.0), kInf), T);
  hinf::OnlineOptions options;
  options.filter.N = m11(N);
  options.filter.Sigma0 = m11(2.0);
  options.filter.Q = m11(1.0);
  options.limits.u_min = Vec::Zero(1);
  options.limits.u_max = Vec::Zero(1);
  ASSERT_EQ(options.filter.update, hinf::MeasurementUpdate::Sampled) << "the default";
  hinf::OnlineController controller(law, options);
  controller.reset(0.0, m11(0.3).col(0));
  const double R = N / T;
  double sigma = 2.0, x = 0.3, u = 0.0;
  for (int k = 0; k < 99; ++k) {
    const double t = T * k;
    if (k > 0) {
      sigma = (sigma + d * d / (2 * a)) * std::exp(2 * a * T) - d * d / (2 * a);
      x *= std::exp(a * T);
    }
    const double y = std::sin(0.7 * k);
    const double posterior = 1.0 / (1.0 / sigma + c * c / R);
    x += posterior * c / R * (y - c * x);
    sigma = posterior;
    EXPECT_EQ(controller.step(t, &y, t, &u).measurement, MeasurementUse::Used);
    EXPECT_NEAR(controller.sigma()(0, 0), sigma, 1e-9 * sigma) << "t = " << t;
    EXPECT_NEAR(controller.estimate()[0], x, 1e-9) << "t = " << t;
  }
}

// The digital output feedback on a scalar plant dx/dt = a x + u + d w, y = c x + v (T = 0.1 s):
// solve_discrete_output_feedback's Sigma_k at gamma = inf converges to the a-priori Kalman
// Riccati equation's fixed point (a quadratic's root); at finite gamma the controller's online
// recursion (one sample per step, every sample measured) gives the same Sigma_k as the batch
// solution, and its command is -F_k x_w with x_w written out here (discrete_output_feedback.hpp).
TEST(DiscreteOutputFeedback, KalmanAtInfinityAndTheOnlineRecursionIsTheBatchOne) {
  const double a = -0.5, c = 2.0, d = 1.0, T = 0.1, R = 0.2;
  auto model = std::make_shared<const hinf::LinearModel>(m11(a), m11(1.0), m11(d), m11(c));
  const auto trajectory = std::make_shared<const hinf::Trajectory>(model, Vec::Zero(1), hinf::VectorSignal::zeros(1),
                                                                    0.0, 20.0);
  const auto lqg = hinf::solve_discrete_output_feedback(
      hinf::solve_discrete_game(trajectory, T, m11(1.0), m11(1.0), kInf), m11(c), m11(R), m11(3.0), m11(1.0));
  // Sigma = A^2 Sigma R / (R + c^2 Sigma) + q, q = D_d^2 / T, A = e^{aT}, D_d = (e^{aT} - 1) / a d.
  const double Ad = std::exp(a * T), Dd = (Ad - 1.0) / a * d, q = Dd * Dd / T;
  const double b = R * (1.0 - Ad * Ad) - q * c * c;
  const double fixed = (-b + std::sqrt(b * b + 4.0 * c * c * q * R)) / (2.0 * c * c);
  // A converged recursion against a closed form: round-off of a few ulps per step, compared at 1e-10.
  EXPECT_NEAR(lqg->Sigma(lqg->steps())(0, 0), fixed, 1e-10 * fixed);
  EXPECT_EQ(lqg->largest_coupling(), 0.0);

  const double gamma = 3.0;
  const auto design = hinf::solve_discrete_game(trajectory, T, m11(1.0), m11(1.0), gamma);
  const auto feedback = hinf::solve_discrete_output_feedback(design, m11(c), m11(R), m11(3.0), m11(1.0));
  hinf::OnlineOptions options;
  options.filter.N = m11(R * T);  // R = N / hold, hold = T
  options.filter.Sigma0 = m11(3.0);
  options.filter.Q = m11(1.0);
  options.filter.update = hinf::MeasurementUpdate::Discrete;
  hinf::OnlineController controller(hinf::SampledLaw::digital(design), options);
  controller.reset(0.0, m11(0.4).col(0));
  double x_hat = 0.4, u = 0.0;
  const double inv_g2 = 1.0 / (gamma * gamma), Bd = (Ad - 1.0) / a;
  for (int k = 0; k < 150; ++k) {
    const double t = k * T, y = 0.3 * std::cos(0.4 * k);
    const hinf::StepReport r = controller.step(t, &y, t, &u);
    ASSERT_EQ(r.status, StepStatus::Ok);
    const double sigma = feedback->Sigma(k)(0, 0), M = design->M(k)(0, 0);
    // Two codes of one recursion (fixed and dynamic sizes): round-off over 150 steps, at 1e-10.
    EXPECT_NEAR(controller.sigma()(0, 0), sigma, 1e-10 * sigma) << "k = " << k;
    EXPECT_NEAR(r.rho_sigma_z, sigma * M, 1e-10 * sigma * M) << "k = " << k;
    const double H = 1.0 / (1.0 / sigma + c * c / R - inv_g2 * M);
    const double x_w = x_hat + H * (inv_g2 * M * x_hat + c / R * (y - c * x_hat));
    const double expected = -design->gain(k)(0, 0) * x_w;
    EXPECT_NEAR(u, expected, 1e-10 * (1.0 + std::abs(expected))) << "k = " << k;
    const double Pi = 1.0 / (1.0 / sigma + c * c / R - inv_g2 * T);
    x_hat = Ad * x_hat + Bd * u + Ad * Pi * (inv_g2 * T * x_hat + c / R * (y - c * x_hat));
  }
}

// The digital output feedback's gamma* on the paper's Figure 2 set-up (Sigma0 = I, N = 0.25, y =
// x, y, psi) against the continuous design's (the filter Riccati ODE (36) and rho(Sigma Z), 4.59,
// bound by the coupling at t0): at T = 0.01 s with R = N / T within 1% (the discrete design is
// first order in T: M_k against Z(t_k) 0.25% there, discrete_design.hpp), and larger at T = 0.1 s.
TEST(DiscreteOutputFeedback, ItsGammaStarApproachesTheContinuousOne) {
  const auto trajectory = paper().trajectory;
  Mat C = Mat::Zero(3, 6);
  C.rightCols(3).setIdentity();
  const Mat I3 = Mat::Identity(3, 3), I6 = Mat::Identity(6, 6);
  hinf::GammaStarOptions options;
  options.rtol = 1e-6;
  const hinf::GammaStarResult continuous =
      hinf::gamma_star_output_feedback(trajectory, I6, I6, 0.25 * I3, I6, options);
  double previous = 0.0;
  for (double T : {0.01, 0.1}) {
    const auto sampled = std::make_shared<const hinf::SampledLinearization>(trajectory, T);
    const hinf::GammaStarResult digital =
        hinf::gamma_star_discrete_output_feedback(sampled, I6, I6, C, 0.25 / T * I3, I6, options);
    std::printf("[digital output feedback] T = %.2f s: gamma* %.5f (continuous %.5f), binding %s at t = %g\n", T,
                digital.gamma_star, continuous.gamma_star, hinf::to_string(digital.binding).c_str(),
                digital.t_escape_lower);
    EXPECT_EQ(digital.binding, hinf::GammaCondition::Coupling);
    if (T == 0.01) {
      EXPECT_NEAR(digital.gamma_star / continuous.gamma_star, 1.0, 0.01);
    }
    EXPECT_GT(digital.gamma_star, previous);
    previous = digital.gamma_star;
  }
}

TEST(DiscreteOutputFeedback, BelowItsGammaItSaysWhichConditionFailsAndWhere) {
  const auto trajectory = paper().trajectory;
  Mat C = Mat::Zero(3, 6);
  C.rightCols(3).setIdentity();
  const Mat R = 0.25 * Mat::Identity(3, 3), I6 = Mat::Identity(6, 6);
  const auto ok = hinf::solve_discrete_output_feedback(hinf::solve_discrete_game(trajectory, 0.1, I6, I6, 5.0), C, R,
                                                       I6, I6);
  EXPECT_LT(ok->largest_coupling(), 1.0);
  EXPECT_GT(ok->largest_coupling(), 0.0);
  try {
    hinf::solve_discrete_output_feedback(hinf::solve_discrete_game(trajectory, 0.1, I6, I6, 1.5), C, R, I6, I6);
    ADD_FAILURE() << "gamma = 1.5 passed";
  } catch (const hinf::CouplingConditionError& e) {
    EXPECT_NE(std::string(e.what()).find("rho(Sigma_k M_k)"), std::string::npos) << e.what();
    EXPECT_GE(e.rho(), 1.5 * 1.5);
  } catch (const hinf::ConjugatePointError& e) {
    EXPECT_NE(std::string(e.what()).find("filter"), std::string::npos) << e.what();
  }
  // Shapes and weights are checked.
  const auto design = hinf::solve_discrete_game(trajectory, 0.1, I6, I6, 5.0);
  EXPECT_THROW(hinf::solve_discrete_output_feedback(design, Mat::Zero(3, 5), R, I6, I6), hinf::InputError);
  EXPECT_THROW(hinf::solve_discrete_output_feedback(design, C, -R, I6, I6), hinf::InputError);
  EXPECT_THROW(hinf::solve_discrete_output_feedback(nullptr, C, R, I6, I6), hinf::InputError);
  // The online controller runs the discrete update only with the digital law.
  hinf::OnlineOptions options;
  options.filter = paper_filter();
  options.filter.update = hinf::MeasurementUpdate::Discrete;
  EXPECT_THROW(hinf::OnlineController(hinf::SampledLaw::emulated(paper().design, 0.1), options), hinf::InputError);
}

TEST(OutputFeedback, ALateMeasurementIsUsedFromItsOwnTime) {
  for (auto update : {hinf::MeasurementUpdate::Sampled, hinf::MeasurementUpdate::Held}) {
  SCOPED_TRACE(hinf::to_string(update));
  // Commands pinned at 0 (u_min = u_max = 0): the estimate depends only on the measurements, so a
  // measurement of t = 0.2 handed over at 0.25 after a step at 0.22 must give the estimate of the
  // same measurement handed over on time. The integration's substeps differ: RK4, ~1e-12.
  const auto law = hinf::SampledLaw::emulated(paper().design, 0.05);
  hinf::OnlineOptions options;
  options.filter = paper_filter();
  options.filter.update = update;
  options.limits.u_min = Vec::Zero(2);
  options.limits.u_max = Vec::Zero(2);
  hinf::OnlineController on_time(law, options), late(law, options);
  on_time.reset(0.0, paper_q0());
  late.reset(0.0, paper_q0());
  Vec y1(3), y2(3), u(2);
  y1 << -0.9, -1.1, 0.7;
  y2 << -0.8, -1.0, 0.6;
  on_time.step(0.1, y1.data(), 0.1, u.data());
  on_time.step(0.2, y2.data(), 0.2, u.data());
  on_time.step(0.25, nullptr, 0.0, u.data());
  late.step(0.1, y1.data(), 0.1, u.data());
  late.step(0.22, nullptr, 0.0, u.data());
  const hinf::StepReport r = late.step(0.25, y2.data(), 0.2, u.data());
  EXPECT_EQ(r.measurement, MeasurementUse::Used);
  EXPECT_LT((late.estimate() - on_time.estimate()).norm(), 1e-9);
  EXPECT_LT((late.sigma() - on_time.sigma()).norm(), 1e-9);
  // The estimate without the late measurement differs (the check above can fail).
  hinf::OnlineController without(law, options);
  without.reset(0.0, paper_q0());
  without.step(0.1, y1.data(), 0.1, u.data());
  without.step(0.25, nullptr, 0.0, u.data());
  EXPECT_GT((without.estimate() - on_time.estimate()).norm(), 1e-3);
  }
}

TEST(OutputFeedback, ALongOutageLosesTheEstimateAndSaysSo) {
  // Without measurements the H-infinity filter's Sigma grows by Sigma gamma^-2 Q Sigma and escapes
  // in finite time (here within 5 s): the controller says Lost and holds its last finite command
  // instead of sending NaN, until reset().
  const auto law = hinf::SampledLaw::emulated(paper().design, 0.05);
  hinf::OnlineOptions options;
  options.filter = paper_filter();
  hinf::OnlineController controller(law, options);
  controller.reset(0.0, paper_q0());
  Vec u(2), y = paper_q0().tail(3);
  bool violated = false;
  double t = 0.0;
  hinf::StepReport r;
  for (int k = 1; k <= 200 && r.status != StepStatus::Lost; ++k) {
    t = 0.05 * k;
    r = controller.step(t, nullptr, t, u.data());
    violated = violated || r.coupling_violated;
  }
  ASSERT_EQ(r.status, StepStatus::Lost) << "t = " << t;
  EXPECT_TRUE(violated) << "the coupling condition fails before the estimate is lost";
  EXPECT_TRUE(u.allFinite());
  EXPECT_EQ(u, controller.held_command());
  EXPECT_EQ(controller.step(t + 0.05, y.data(), t + 0.05, u.data()).status, StepStatus::Lost);
  EXPECT_EQ(controller.counts().lost, 2);
  controller.reset(t + 0.1, paper_q0());
  EXPECT_EQ(controller.step(t + 0.15, y.data(), t + 0.15, u.data()).status, StepStatus::Ok);
}

TEST(OutputFeedback, BadFilterIsAnInputError) {
  const auto law = hinf::SampledLaw::emulated(paper().design, 0.1);
  auto with = [&](auto edit) {
    hinf::OnlineOptions o;
    o.filter = paper_filter();
    edit(o.filter);
    return o;
  };
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& f) { f.N = Mat::Identity(2, 2); })), hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& f) { f.N = -Mat::Identity(3, 3); })), hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& f) { f.Sigma0 = Mat::Identity(5, 5); })), hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& f) { f.Q = Mat(); })), hinf::InputError);
  EXPECT_THROW(hinf::OnlineController(law, with([](auto& f) { f.hold = -1.0; })), hinf::InputError);
  // A model without a measurement.
  EXPECT_THROW(hinf::OnlineController(scalar_law(-1.0, 1.0, 2.0, 0.1), with([](auto&) {})), hinf::InputError);
  // Noise for a state-feedback controller.
  hinf::OnlineController state_feedback(law);
  hinf::SampledLoopOptions loop;
  loop.sigma = 0.5;
  EXPECT_THROW(hinf::simulate_sampled(*paper().trajectory, state_feedback, hinf::Disturbance(paper_w()), paper_q0(),
                                      loop),
               hinf::InputError);
}

// The paper's Figure 2 (output feedback, sigma = 0.5) sampled at T: the controller gets
// y_k = C q(t_k) + sigma v_k, the continuous loop y(t) = C q(t) + sigma v_k on [t_k, t_k + T),
// with the same noise samples v_k (a sensor at the controller's rate; at T = 0.01 s, the paper's).
// The continuous loop sees C q(t) between samples, the sampled one only at t_k, so at T = 0.1 s
// the difference depends on the noise: with the sampled measurement update, over the paper's
// seed and seven others, the RMS is 3.0% above the continuous loop's (+5.0% on the paper's seed
// alone, -3% to +7% per seed); with the held update 8.6% over seven of them (+11% on the paper's
// seed), because the command sees a measurement one sample later; the digital law with its own
// discrete update (R = N / T) 2.9% (+5.2% on the paper's seed). The test takes the RMS over the
// eight runs.
struct Figure2Runs {
  double continuous_ms = 0.0, sampled_ms = 0.0;  // sums of mean squares
  long coupling_violated = 0;
};

Figure2Runs figure2_runs(double T, hinf::MeasurementUpdate update, std::uint64_t seed) {
  const hinf::Trajectory& trajectory = *paper().trajectory;
  hinf::SimulationOptions tight;
  tight.solver.rtol = 1e-9;
  tight.solver.atol = 1e-11;
  const hinf::RowMat noise = hinf::standard_normal_samples(seed, hinf::noise_sample_count(0.0, 40.0, T), 3);
  hinf::OutputFeedbackProblem problem;
  problem.design = paper().design;
  problem.sigma = 0.5;
  problem.sample_period = T;
  problem.noise = noise;
  problem.N = paper_filter().N;
  problem.Sigma0 = paper_filter().Sigma0;
  problem.Q = paper_filter().Q;
  hinf::HinfStateFeedback law(paper().design);
  const double continuous = rms_last_half(
      hinf::simulate_output_feedback(problem, law, hinf::Disturbance(paper_w()), paper_q0(), {}, tight), trajectory);

  hinf::OnlineOptions options;
  options.filter = paper_filter();
  options.filter.update = update;
  hinf::OnlineController controller(
      update == hinf::MeasurementUpdate::Discrete
          ? hinf::SampledLaw::digital(hinf::solve_discrete_game(paper().trajectory, T, Mat::Identity(6, 6),
                                                                Mat::Identity(6, 6), 5.0))
          : hinf::SampledLaw::emulated(paper().design, T),
      options);
  hinf::SampledLoopOptions loop;
  loop.simulation = tight;
  loop.sigma = 0.5;
  loop.noise = noise;
  const hinf::SimulationResult r =
      hinf::simulate_sampled(trajectory, controller, hinf::Disturbance(paper_w()), paper_q0(), loop);
  EXPECT_EQ(r.status, hinf::RunStatus::Completed);
  const double sampled = rms_last_half(r, trajectory);
  std::printf("[output feedback] T = %.2f s, %s update, seed %llu: RMS position error %.5f sampled, %.5f continuous\n",
              T, hinf::to_string(update).c_str(), static_cast<unsigned long long>(seed), sampled, continuous);
  return {continuous * continuous, sampled * sampled, controller.counts().coupling_violated};
}

TEST(OutputFeedback, Figure2SampledApproachesTheContinuousLoop) {
  // T = 0.01 s, the paper's seed: within 1%, each update (discrete: the digital law's own).
  for (auto update : {hinf::MeasurementUpdate::Sampled, hinf::MeasurementUpdate::Held,
                      hinf::MeasurementUpdate::Discrete}) {
    const Figure2Runs run = figure2_runs(0.01, update, 20000601);
    ASSERT_GT(run.continuous_ms, 1e-4);
    EXPECT_NEAR(std::sqrt(run.sampled_ms / run.continuous_ms), 1.0, 0.01) << hinf::to_string(update);
    EXPECT_EQ(run.coupling_violated, 0);
  }
  // T = 0.1 s: the RMS over eight noise seeds within 5%: the sampled update (the default) of the
  // emulated law, and the digital law's discrete update.
  for (auto update : {hinf::MeasurementUpdate::Sampled, hinf::MeasurementUpdate::Discrete}) {
    Figure2Runs total;
    for (std::uint64_t seed : {20000601ull, 1ull, 2ull, 3ull, 4ull, 5ull, 6ull, 7ull}) {
      const Figure2Runs run = figure2_runs(0.1, update, seed);
      total.continuous_ms += run.continuous_ms;
      total.sampled_ms += run.sampled_ms;
      total.coupling_violated += run.coupling_violated;
    }
    const double ratio = std::sqrt(total.sampled_ms / total.continuous_ms);
    std::printf("[output feedback] T = 0.10 s, %s update: RMS over 8 seeds %.4f of the continuous loop's\n",
                hinf::to_string(update).c_str(), ratio);
    EXPECT_NEAR(ratio, 1.0, 0.05) << hinf::to_string(update);
    EXPECT_EQ(total.coupling_violated, 0);
  }
}

}  // namespace
