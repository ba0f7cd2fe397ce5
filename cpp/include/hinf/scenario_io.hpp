// Scenario files (TOML, shared/scenarios.md) and the results files (JSON, CSV).
#pragma once

#include <string>

#include "hinf/scenario.hpp"

namespace hinf {

// Parses a scenario; unknown keys and wrong types are an InputError naming the key.
// source names the text in messages (usually the file path); the scenario name defaults to
// the file's stem.
Scenario parse_scenario_toml(const std::string& text, const std::string& source);
Scenario load_scenario_toml(const std::string& path);

// The results file of scenarios.md (one JSON object, matrices as nested row-major lists,
// non-finite numbers as null).
std::string results_json(const RunResult& result, int indent = 2);
// The time series on the output grid, one row per time, with a header line: t, the states,
// the desired states (suffix _d), u1.., u1_d.., w1..; with output feedback also the estimated
// errors (suffix _e_hat), the measurements y1.., sigma_min_eig, sigma_max_eig, rho_sigma_z.
std::string results_csv(const RunResult& result);

void write_text_file(const std::string& path, const std::string& text);

}  // namespace hinf
