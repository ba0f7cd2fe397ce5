// In-process timings of the C++ core on a scenario, median over repeated runs:
//   hinf-bench SCENARIO.toml [--repeat N]
// Times the desired trajectory, the GRDE solve per method, the closed loop per method and the
// whole run_scenario, each the median (and min, max) of N runs in this process.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "hinf/control/controller.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/scenario/scenario.hpp"

using namespace hinf;

namespace {

// The scenario's closed-loop options with another integrator.
SimulationOptions with_solver(const Scenario& s, const SolverOptions& solver) {
  SimulationOptions options = s.simulation_options();
  options.solver = solver;
  return options;
}

struct Stats {
  double median, min, max;
};

Stats time_it(int repeat, const std::function<void()>& work) {
  std::vector<double> seconds;
  work();  // warm-up
  for (int i = 0; i < repeat; ++i) {
    const auto start = std::chrono::steady_clock::now();
    work();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return {seconds[seconds.size() / 2], seconds.front(), seconds.back()};
}

void report(const std::string& what, const Stats& s) {
  std::printf("%-46s %9.3f ms   [%.3f .. %.3f]\n", what.c_str(), s.median * 1e3, s.min * 1e3, s.max * 1e3);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: hinf-bench SCENARIO.toml [--repeat N]\n");
    return 2;
  }
  int repeat = 101;
  for (int i = 2; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--repeat") == 0) repeat = std::max(1, std::atoi(argv[i + 1]));
  try {
    const Scenario s = load_scenario_toml(argv[1]).resolved();
    s.validate();
    std::printf("scenario %s, median of %d runs\n", s.name.c_str(), repeat);
    TrajectoryPtr trajectory;
    report("desired trajectory", time_it(repeat, [&] {
             trajectory = std::make_shared<const Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, s.tf);
           }));
    for (Method method : {Method::ERK, Method::BDF, Method::Adams}) {
      SolverOptions options = s.solver;
      options.method = method;
      RiccatiSolutionPtr solution;
      report("GRDE solve, " + to_string(method), time_it(repeat, [&] {
               solution = solve_grde(trajectory, s.Q, s.Qf, s.gamma, options);
             }));
      std::printf("%-46s %9ld steps, %ld rhs, %.0f kB\n", "", solution->stats().steps,
                  solution->stats().rhs_evals, solution->stats().memory_bytes / 1e3);
      HinfStateFeedback controller(solution, s.kappa);
      report("state-feedback closed loop, " + to_string(method), time_it(repeat, [&] {
               simulate_state_feedback(*trajectory, controller, s.disturbance, s.initial_q0, with_solver(s, options));
             }));
      report("design + closed loop, " + to_string(method), time_it(repeat, [&] {
               auto tr = std::make_shared<const Trajectory>(s.model, s.desired_q0, s.desired_u, s.t0, s.tf);
               auto sol = solve_grde(tr, s.Q, s.Qf, s.gamma, options);
               HinfStateFeedback c(sol, s.kappa);
               simulate_state_feedback(*tr, c, s.disturbance, s.initial_q0, with_solver(s, options));
             }));
      Scenario variant = s;
      variant.solver.method = method;
      const int runs = method == Method::Adams && s.measurement ? std::max(1, repeat / 10) : repeat;
      report("run_scenario, " + to_string(method), time_it(runs, [&] { run_scenario(variant); }));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hinf-bench: error: %s\n", e.what());
    return 1;
  }
}
