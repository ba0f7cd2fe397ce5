// The built-in vehicles' generated equations against the same vehicles written out by hand
// (handwritten_vehicles.hpp), on each vehicle's shipped scenario:
//   hinf-bench-vehicles [--repeat N]          (built with the C++ targets; run from the repository)
// For each scenario, the design (desired trajectory and GRDE, the scenario's solver) and the whole
// run_scenario (design, closed loop, metrics) with the built-in model and with the hand-written
// one, interleaved (the order alternates every round), the median of N rounds each, and their
// ratio. The load average is printed before and after: compare ratios measured at a low load.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "handwritten_vehicles.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/models/vehicles.hpp"
#include "hinf/scenario/scenario.hpp"

using namespace hinf;

namespace {

double seconds(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::string load_average() {
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  file >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

// The hand-written twin of a built-in model, with its parameters.
ModelPtr handwritten_twin(const Model& model) {
  if (const auto* ship = dynamic_cast<const ShipModel*>(&model))
    return std::make_shared<handwritten::Ship>(ship->parameters());
  if (const auto* vessel = dynamic_cast<const FossenVessel*>(&model))
    return std::make_shared<handwritten::FossenVessel>(vessel->parameters());
  if (const auto* hovercraft = dynamic_cast<const Hovercraft*>(&model))
    return std::make_shared<handwritten::Hovercraft>(hovercraft->parameters());
  if (const auto* pvtol = dynamic_cast<const PlanarVtol*>(&model))
    return std::make_shared<handwritten::PlanarVtol>(pvtol->parameters());
  if (const auto* auv = dynamic_cast<const Auv*>(&model)) return std::make_shared<handwritten::Auv>(auv->parameters());
  throw InputError("not a built-in vehicle: " + model.name());
}

struct Pair {
  double generated, handwritten;
};

// Medians of `work` on the built-in and on the hand-written scenario, interleaved.
Pair interleaved(int repeat, const std::function<void(const Scenario&)>& work, const Scenario& generated,
                 const Scenario& handwritten) {
  std::vector<double> a, b;
  work(generated);  // warm-up
  work(handwritten);
  for (int round = 0; round < repeat; ++round) {
    if (round % 2 == 0) {
      a.push_back(seconds([&] { work(generated); }));
      b.push_back(seconds([&] { work(handwritten); }));
    } else {
      b.push_back(seconds([&] { work(handwritten); }));
      a.push_back(seconds([&] { work(generated); }));
    }
  }
  return {median(a), median(b)};
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 41;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--repeat") == 0) repeat = std::max(1, std::atoi(argv[i + 1]));
  try {
    std::printf("load average before: %s\n", load_average().c_str());
    std::printf("%-24s %-8s %12s %12s %8s\n", "scenario", "what", "generated", "hand-written", "ratio");
    const auto design = [](const Scenario& s) {
      const Scenario r = s.resolved();
      const auto trajectory = std::make_shared<const Trajectory>(r.model, r.desired_q0, r.desired_u, r.t0, r.tf);
      solve_grde(trajectory, r.Q, r.Qf, r.gamma, r.solver);
    };
    const auto whole_run = [](const Scenario& s) { run_scenario(s); };
    for (const char* name : {"paper_fig1", "paper_fig2", "fossen_vessel_turn", "hovercraft_s_curve", "pvtol_climb",
                             "auv_s_curve"}) {
      const Scenario generated = load_scenario_toml(std::string("scenarios/") + name + ".toml");
      Scenario handwritten = generated;
      handwritten.model = handwritten_twin(*generated.model);
      for (const auto& [what, work] : {std::pair<const char*, std::function<void(const Scenario&)>>{"design", design},
                                       {"run", whole_run}}) {
        const Pair p = interleaved(repeat, work, generated, handwritten);
        std::printf("%-24s %-8s %9.3f ms %9.3f ms %8.3f\n", name, what, p.generated * 1e3, p.handwritten * 1e3,
                    p.generated / p.handwritten);
      }
    }
    std::printf("load average after: %s (medians of %d interleaved rounds)\n", load_average().c_str(), repeat);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hinf-bench-vehicles: %s\n", e.what());
    return 1;
  }
  return 0;
}
