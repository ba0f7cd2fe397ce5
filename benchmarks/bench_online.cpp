// The online controller's step() as a vehicle computer calls it, without Python:
//   hinf-bench-online [--steps N]
// The paper's Figure-1 design (ship, gamma = 5, [0, 40] s), its law emulated and its digital
// design at T = 0.05 s (20 Hz), with bounds and rate limits. Each call of step() is timed alone
// (steady_clock); printed: the median, the 99th percentile and the largest of N calls, for a
// measurement of the same instant (no prediction), one 20 ms old (predicted over 20 ms) and a
// missing sample (predicted over a whole period); beside them the straightforward alternative,
// the continuous law's HinfStateFeedback::control(t, q, u) (no limits, no prediction, no time
// checks), timed the same way; and the receding horizon's controller, its windows solved on the
// other thread while it steps.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "hinf/control/controller.hpp"
#include "hinf/control/discrete_design.hpp"
#include "hinf/control/online_controller.hpp"
#include "hinf/control/online_receding_horizon.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/models/ship.hpp"

using namespace hinf;

namespace {

struct Percentiles {
  double median, p99, max;  // s
};

Percentiles percentiles(std::vector<double> seconds) {
  std::sort(seconds.begin(), seconds.end());
  const auto at = [&](double q) { return seconds[static_cast<std::size_t>(q * (seconds.size() - 1))]; };
  return {at(0.5), at(0.99), seconds.back()};
}

// N calls of step(); `age` is how old the measurement is (s), or < 0 for none. Output feedback:
// the filter of the paper's Figure 2, and y = (x, y, psi); with age < 0 every fourth sample still
// has a measurement (without any, the H-infinity filter's Sigma escapes within seconds and the
// controller answers Lost).
void time_steps(const SampledLawPtr& law, bool output_feedback, MeasurementUpdate update, long steps, double age,
                std::vector<double>& seconds) {
  OnlineOptions options;
  if (output_feedback) {
    options.filter.N = 0.25 * Mat::Identity(3, 3);
    options.filter.Sigma0 = Mat::Identity(6, 6);
    options.filter.Q = Mat::Identity(6, 6);
    options.filter.update = update;
  }
  options.limits.u_min = Vec::Constant(2, -3.0);
  options.limits.u_max = Vec::Constant(2, 3.0);
  options.limits.rate_max = Vec::Constant(2, 20.0);
  OnlineController controller(law, options);
  Vec q0(6);
  q0 << 1.0, 0.0, 0.0, -1.0, -1.0, M_PI / 4;
  Vec q = q0, u(2);
  const double T = law->period();
  const long per_run = static_cast<long>(std::floor((law->t_end() - law->t0()) / T)) - 1;
  long k = 0;
  for (long i = 0; i < steps; ++i, ++k) {
    if (k % per_run == 0) {
      controller.reset(law->t0(), q0);
      k = 0;
    }
    const double t = law->t0() + (k + 1) * T;
    q(3) = q0(3) + 1e-3 * std::sin(0.01 * i);  // a measurement that changes
    const auto start = std::chrono::steady_clock::now();
    const bool missing = age < 0 && !(output_feedback && k % 4 == 0);
    controller.step(t, missing ? nullptr : (output_feedback ? q.data() + 3 : q.data()), t - std::max(age, 0.0),
                    u.data());
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}

// N calls of the receding horizon's step() (window 10 s, a new one every second, solved on the
// solver's thread while the steps run; 39 switches per 40 s run), measurement of the same instant.
// synchronize() before each call (not timed) keeps the windows on time as on a vehicle whose
// solves take less than the update period. With `background` the solve of the next window overlaps
// the timed calls (calls back to back: every call runs beside a solve, as a vehicle's would only
// while one is under way); without it synchronize() solves it between calls, so the timed calls
// differ from the fixed design's by the switches alone. The calls that switch windows (the first
// of every second: one in 20) go to `switching` too, the others to `others`.
void time_receding(const TrajectoryPtr& trajectory, bool output_feedback, bool background, long steps,
                   std::vector<double>& seconds, std::vector<double>& switching, std::vector<double>& others) {
  RecedingHorizonOptions rh;
  rh.window = 10.0;
  rh.update = 1.0;
  auto horizon = std::make_shared<const RecedingHorizon>(trajectory->model_ptr(), trajectory->q_d0(),
                                                         trajectory->u_d_signal(), 0.0, Mat::Identity(6, 6),
                                                         Mat::Identity(6, 6), 5.0, rh);
  OnlineOptions options;
  if (output_feedback) {
    options.filter.N = 0.25 * Mat::Identity(3, 3);
    options.filter.Sigma0 = Mat::Identity(6, 6);
    options.filter.Q = Mat::Identity(6, 6);
  }
  options.limits.u_min = Vec::Constant(2, -3.0);
  options.limits.u_max = Vec::Constant(2, 3.0);
  options.limits.rate_max = Vec::Constant(2, 20.0);
  RecedingOnlineController controller(horizon, 0.05, options, Signal(1.0), background);
  Vec q0(6);
  q0 << 1.0, 0.0, 0.0, -1.0, -1.0, M_PI / 4;
  Vec q = q0, u(2);
  const long per_run = 799;
  long k = 0;
  for (long i = 0; i < steps; ++i, ++k) {
    if (k % per_run == 0) {
      controller.reset(0.0, q0);
      k = 0;
    }
    const double t = (k + 1) * 0.05;
    q(3) = q0(3) + 1e-3 * std::sin(0.01 * i);
    controller.synchronize(t);
    const auto start = std::chrono::steady_clock::now();
    controller.step(t, output_feedback ? q.data() + 3 : q.data(), t, u.data());
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    ((k + 1) % 20 == 0 ? switching : others).push_back(seconds.back());
  }
}

// N calls paced 1 ms apart in wall time (sleep_until between them), as a vehicle's calls come with
// other work or idle time between them: the fixed design's controller, or the receding horizon's
// (H = 10 s, a new window every 20 calls, solved on the other thread well before its switch).
// State feedback, measurement of the instant, the limits of time_steps. The switching calls of the
// receding horizon go to `switching` too, the others to `others`.
void time_paced(const SampledLawPtr& law, bool receding, long steps, std::vector<double>& seconds,
                std::vector<double>& switching, std::vector<double>& others) {
  OnlineOptions options;
  options.limits.u_min = Vec::Constant(2, -3.0);
  options.limits.u_max = Vec::Constant(2, 3.0);
  options.limits.rate_max = Vec::Constant(2, 20.0);
  const Trajectory& trajectory = law->trajectory();
  RecedingHorizonOptions rh;
  rh.window = 10.0;
  rh.update = 1.0;
  auto horizon = std::make_shared<const RecedingHorizon>(trajectory.model_ptr(), trajectory.q_d0(),
                                                         trajectory.u_d_signal(), 0.0, Mat::Identity(6, 6),
                                                         Mat::Identity(6, 6), 5.0, rh);
  std::optional<RecedingOnlineController> moving;
  std::optional<OnlineController> fixed;
  if (receding)
    moving.emplace(horizon, 0.05, options);
  else
    fixed.emplace(law, options);
  Vec q0(6);
  q0 << 1.0, 0.0, 0.0, -1.0, -1.0, M_PI / 4;
  Vec q = q0, u(2);
  const long per_run = 799;
  auto next = std::chrono::steady_clock::now();
  for (long i = 0, k = 0; i < steps; ++i, ++k) {
    if (k % per_run == 0) {
      if (receding) moving->reset(0.0, q0);
      else fixed->reset(0.0, q0);
      k = 0;
    }
    const double t = (k + 1) * 0.05;
    q(3) = q0(3) + 1e-3 * std::sin(0.01 * i);
    if (receding) moving->synchronize(t);
    next += std::chrono::milliseconds(1);
    std::this_thread::sleep_until(next);
    const auto start = std::chrono::steady_clock::now();
    if (receding) moving->step(t, q.data(), t, u.data());
    else fixed->step(t, q.data(), t, u.data());
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (receding) ((k + 1) % 20 == 0 ? switching : others).push_back(seconds.back());
  }
}

// N calls of the continuous law's control(), on the same sample times and states.
void time_control(const RiccatiSolutionPtr& design, double T, long steps, std::vector<double>& seconds) {
  HinfStateFeedback law(design);
  Vec q0(6);
  q0 << 1.0, 0.0, 0.0, -1.0, -1.0, M_PI / 4;
  Vec q = q0, u(2);
  const long per_run = static_cast<long>(std::floor((design->tf() - design->t0()) / T)) - 1;
  for (long i = 0, k = 0; i < steps; ++i, k = (k + 1) % per_run) {
    const double t = design->t0() + (k + 1) * T;
    q(3) = q0(3) + 1e-3 * std::sin(0.01 * i);
    const auto start = std::chrono::steady_clock::now();
    law.control(t, q, u);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}

}  // namespace

int main(int argc, char** argv) {
  long steps = 100000;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--steps") == 0) steps = std::max(1000L, std::atol(argv[i + 1]));
  Vec q_d0 = Vec::Zero(6);
  q_d0(0) = 1.0;
  const VectorSignal u_d(std::vector<Signal>{Signal(1.0), Signal(0.0, {Harmonic{0.3, 0.2, 0.0, false}})});
  const auto trajectory = std::make_shared<const Trajectory>(std::make_shared<const ShipModel>(), q_d0, u_d, 0.0, 40.0);
  const double T = 0.05;
  const RiccatiSolutionPtr design = solve_grde(trajectory, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0);
  const SampledLawPtr laws[] = {
      SampledLaw::emulated(design, T),
      SampledLaw::digital(solve_discrete_game(trajectory, T, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0))};
  double load[3] = {NAN, NAN, NAN};
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = NAN;
    std::fclose(f);
  }
  std::printf("step() of the paper's ship (n = 6), T = %.2f s, %ld calls each; load average %.2f %.2f %.2f\n", T,
              steps, load[0], load[1], load[2]);
  std::printf("%-26s %-34s %10s %10s %10s\n", "law", "measurement", "median us", "p99 us", "max us");
  const std::pair<const char*, double> cases[] = {
      {"of the same instant", 0.0}, {"20 ms old (predicted 20 ms)", 0.02}, {"missing (predicted 50 ms)", -1.0}};
  // Rounds: every case runs steps / rounds calls per round, the cases one after the other, so a
  // change of the machine's load falls on all of them alike.
  const int rounds = 10;
  // State feedback with both laws, then output feedback: the emulated law with the sampled and
  // the held update, the digital law with its discrete one.
  struct Setting {
    const SampledLaw* law;
    bool output_feedback;
    MeasurementUpdate update;
  };
  const Setting settings[] = {{laws[0].get(), false, MeasurementUpdate::Sampled},
                              {laws[1].get(), false, MeasurementUpdate::Sampled},
                              {laws[0].get(), true, MeasurementUpdate::Sampled},
                              {laws[0].get(), true, MeasurementUpdate::Held},
                              {laws[1].get(), true, MeasurementUpdate::Discrete}};
  const auto law_of = [&laws](const SampledLaw* law) { return law == laws[0].get() ? laws[0] : laws[1]; };
  std::vector<std::vector<double>> seconds(3 * std::size(settings) + 5), switching(4), others(4);
  std::vector<double> paced_fixed, paced_receding, paced_switching, paced_others, unused;
  // The p99 of each round's paced calls: the fixed design (A), the receding horizon, the fixed
  // design again (B). B against A is the noise of the p99 itself (the same code twice).
  std::vector<double> p99_ratio_again, p99_ratio_receding;
  for (auto& s : seconds) s.reserve(static_cast<std::size_t>(steps));
  for (int round = 0; round < rounds; ++round) {
    int c = 0;
    for (const Setting& s : settings)
      for (const auto& [what, age] : cases)
        time_steps(law_of(s.law), s.output_feedback, s.update, steps / rounds, age, seconds[c++]);
    time_control(design, T, steps / rounds, seconds[c]);
    for (int i = 0; i < 4; ++i)
      time_receding(trajectory, i % 2 == 1, i < 2, steps / rounds, seconds[c + 1 + i], switching[i], others[i]);
    // Paced: a tenth of the calls for each of the three series (1 ms each in wall time).
    std::vector<double> a, r, b;
    time_paced(laws[0], false, steps / rounds / 10, a, unused, unused);
    time_paced(laws[0], true, steps / rounds / 10, r, paced_switching, paced_others);
    time_paced(laws[0], false, steps / rounds / 10, b, unused, unused);
    const double p99_a = percentiles(a).p99;
    p99_ratio_receding.push_back(percentiles(r).p99 / p99_a);
    p99_ratio_again.push_back(percentiles(b).p99 / p99_a);
    paced_fixed.insert(paced_fixed.end(), a.begin(), a.end());
    paced_fixed.insert(paced_fixed.end(), b.begin(), b.end());
    paced_receding.insert(paced_receding.end(), r.begin(), r.end());
  }
  int c = 0;
  for (const Setting& s : settings)
    for (const auto& [what, age] : cases) {
      const Percentiles p = percentiles(seconds[c++]);
      const std::string name =
          s.law->kind() + (s.output_feedback ? ", output, " + to_string(s.update) : std::string(", state"));
      const std::string label = s.output_feedback && age < 0 ? std::string("3 of 4 ") + what : std::string(what);
      std::printf("%-26s %-34s %10.3f %10.3f %10.3f\n", name.c_str(), label.c_str(), p.median * 1e6, p.p99 * 1e6,
                  p.max * 1e6);
    }
  const Percentiles p = percentiles(seconds[c]);
  std::printf("%-26s %-34s %10.3f %10.3f %10.3f\n", "control()", "HinfStateFeedback, of the instant", p.median * 1e6,
              p.p99 * 1e6, p.max * 1e6);
  for (int i = 0; i < 4; ++i)
    for (int part = 0; part < 3; ++part) {
      const Percentiles r = percentiles(part == 0 ? seconds[c + 1 + i] : part == 1 ? switching[i] : others[i]);
      const std::string label = std::string(i < 2 ? "solved beside" : "solved between") +
                                (part == 0 ? ", every call" : part == 1 ? ", switching calls" : ", other calls");
      std::printf("%-26s %-34s %10.3f %10.3f %10.3f\n", i % 2 == 0 ? "receding, state" : "receding, output, sampled",
                  label.c_str(), r.median * 1e6, r.p99 * 1e6, r.max * 1e6);
    }
  const std::pair<const char*, const std::vector<double>*> paced[] = {{"fixed design, every call", &paced_fixed},
                                                                       {"receding, every call", &paced_receding},
                                                                       {"receding, switching calls", &paced_switching},
                                                                       {"receding, other calls", &paced_others}};
  for (const auto& [label, values] : paced) {
    const Percentiles r = percentiles(*values);
    std::printf("%-26s %-34s %10.3f %10.3f %10.3f\n", "paced 1 ms, state", label, r.median * 1e6, r.p99 * 1e6,
                r.max * 1e6);
  }
  // Each round's p99 over the fixed design's first series (A): the median and range over rounds.
  std::printf("p99 of a round's paced calls over the fixed design's (A), median [min, max] of %d rounds:\n", rounds);
  for (const auto& [label, ratios] : {std::pair<const char*, std::vector<double>*>{"fixed design again (B)", &p99_ratio_again},
                                      {"receding horizon", &p99_ratio_receding}}) {
    std::sort(ratios->begin(), ratios->end());
    std::printf("  %-24s %.3f [%.3f, %.3f]\n", label, (*ratios)[ratios->size() / 2], ratios->front(), ratios->back());
  }
  return 0;
}
