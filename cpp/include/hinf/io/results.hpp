// The results files of a run (docs/results.md): the results file (JSON) and the time series (CSV).
#pragma once

#include <string>

#include "hinf/scenario/scenario.hpp"

namespace hinf {

// The results file of scenarios.md (one JSON object, matrices as nested row-major lists,
// non-finite numbers as null).
std::string results_json(const RunResult& result, int indent = 2);
// The time series on the output grid, one row per time, with a header line: t, the states,
// the desired states (suffix _d), u1.., u1_d.., w1..; with output feedback also the estimated
// errors (suffix _e_hat), the measurements y1.., sigma_min_eig, sigma_max_eig, rho_sigma_z.
std::string results_csv(const RunResult& result);

}  // namespace hinf
