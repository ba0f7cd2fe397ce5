// hinf-sim: runs a scenario file without Python and writes the results file.
//
//   hinf-sim SCENARIO.toml [--json OUT.json] [--csv OUT.csv] [--gamma-star] [--trust-code]
//   hinf-sim --version
//
// --trust-code (or HINF_TRUST_CODE=1) lets the scenario load the compiled library of a
// [model] kind = "casadi": a scenario file is data and runs no code without it.
// --gamma-star also computes gamma* (paper eq. 14) of the state-feedback design and puts it in
// the results file.
// Exit status: 0 success, 2 bad input or usage (unusable output paths and runs too large for
// the memory included), 3 numerical failure (solver, conjugate point, coupling condition), 130
// interrupted (Ctrl-C; "hinf-sim: interrupted"), 1 anything else (a bug). Errors are one line on stderr. Output paths are checked before the
// run; each file is written whole or not at all.
#include <cmath>
#include <iostream>
#include <new>
#include <optional>
#include <string>

#include "hinf/core/errors.hpp"
#include "hinf/core/interrupt.hpp"
#include "hinf/io/files.hpp"
#include "hinf/io/results.hpp"
#include "hinf/io/scenario_file.hpp"

namespace {

const char* kUsage = "usage: hinf-sim SCENARIO.toml [--json OUT.json] [--csv OUT.csv] [--gamma-star] [--trust-code]";
// The same words as hinf-cpp's.
const char* kOutOfMemory =
    "not enough memory for this run: shorten the horizon, use a larger [output] dt or shorter tables";

int fail(int status, const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n') c = ' ';
  std::cerr << "hinf-sim: error: " << line << "\n";
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenario_path;
  std::optional<std::string> json_path, csv_path;
  bool with_gamma_star = false;
  bool trust_code = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* option) -> std::optional<std::string> {
      if (i + 1 >= argc) throw hinf::InputError(std::string(option) + " needs a file name");
      return std::string(argv[++i]);
    };
    try {
      if (arg == "-h" || arg == "--help") {
        std::cout << kUsage << "\n       hinf-sim --version\n";
        return 0;
      } else if (arg == "--version") {
        // HINF_VERSION: the VERSION file, defined by cpp/CMakeLists.txt.
        std::cout << "hinf-sim " << HINF_VERSION << "\n";
        return 0;
      } else if (arg == "--json") {
        json_path = value("--json");
      } else if (arg == "--csv") {
        csv_path = value("--csv");
      } else if (arg == "--gamma-star") {
        with_gamma_star = true;
      } else if (arg == "--trust-code") {
        trust_code = true;
      } else if (!arg.empty() && arg[0] == '-') {
        return fail(2, "unknown option '" + arg + "'; " + kUsage);
      } else if (scenario_path.empty()) {
        scenario_path = arg;
      } else {
        return fail(2, "more than one scenario file given; " + std::string(kUsage));
      }
    } catch (const hinf::InputError& e) {
      return fail(2, e.what());
    }
  }
  if (scenario_path.empty()) return fail(2, std::string("no scenario file given; ") + kUsage);

  hinf::install_interrupt_handler();
  try {
    for (const std::optional<std::string>& path : {json_path, csv_path})
      if (path) hinf::check_output_path(*path);
    const hinf::Scenario scenario =
        hinf::load_scenario_toml(scenario_path, trust_code || hinf::code_trusted_by_environment());
    hinf::RunResult result = hinf::run_scenario(scenario);
    if (with_gamma_star) result.gamma_star = hinf::scenario_gamma_star(scenario).gamma_star;
    if (json_path) hinf::write_text_file(*json_path, hinf::results_json(result) + "\n");
    if (csv_path) hinf::write_text_file(*csv_path, hinf::results_csv(result));
    const hinf::Metrics& m = result.metrics;
    std::cout << "scenario " << result.scenario_name << ": gamma = " << result.gamma
              << ", final position error = " << m.final_position_error
              << ", RMS position error (last half) = " << m.rms_position_error_last_half;
    // The disturbance's gain exists for a run from the desired start only (metrics.hpp).
    if (!std::isnan(m.disturbance_gain)) std::cout << ", L2 gain from the desired start = " << m.disturbance_gain;
    std::cout << ", response/disturbance ratio = " << m.response_ratio;
    if (result.gamma_star) std::cout << ", gamma* = " << *result.gamma_star;
    if (result.online)
      std::cout << ", sampled every " << result.sampling->period << " s: " << result.online->steps << " steps, "
                << result.online->saturated << " saturated, largest |u| = " << result.online->largest_command;
    std::cout << " (total " << result.timing.total * 1e3 << " ms)\n";
    // Warnings after a success only: a failure is one line on stderr with nothing before it.
    for (const std::string& warning : hinf::scenario_warnings(scenario))
      std::cerr << "hinf-sim: warning: " << scenario_path << ": " << warning << "\n";
    if (result.simulation.status != hinf::RunStatus::Completed)
      std::cerr << "hinf-sim: warning: the run " << hinf::to_string(result.simulation.status) << ": "
                << result.simulation.status_message << "\n";
    return 0;
  } catch (const hinf::Interrupted&) {
    std::cerr << "hinf-sim: interrupted\n";
    return 130;  // 128 + SIGINT, as a shell reports a process that SIGINT ended
  } catch (const hinf::InputError& e) {
    return fail(2, e.what());
  } catch (const hinf::HinfError& e) {
    return fail(3, e.what());
  } catch (const std::bad_alloc&) {
    return fail(2, kOutOfMemory);
  } catch (const std::exception& e) {
    return fail(1, std::string("internal error: ") + e.what());
  }
}
