// Scenario files (TOML, docs/scenarios.md) and the results files (JSON, CSV; docs/results.md).
#pragma once

#include <functional>
#include <string>

#include "hinf/scenario/scenario.hpp"

namespace hinf {

// The one scenario reader: hinf-sim and the Python package (hinf_cpp.load_scenario,
// scenario_from_dict) both read scenarios through it, so they accept and reject the same files
// with the same messages.
//
// Parses a scenario (UTF-8 TOML; a leading byte-order mark is allowed). Everything wrong is an
// InputError naming the source, and the key where there is one: unknown keys, wrong types,
// integers beyond 64 bits, non-finite numbers (only gamma may be inf), empty arrays, noise
// channels of the model in [disturbance], keys nested too deeply, text that is not UTF-8.
// source names the text in messages (usually the file path); the scenario name defaults to
// the file's stem.
Scenario parse_scenario_toml(const std::string& text, const std::string& source);
// Reads and parses a scenario file; a file that cannot be read (missing, a directory) is an
// InputError naming the path.
Scenario load_scenario_toml(const std::string& path);
// The inverse of parse_scenario_toml: the scenario as a scenario file that reads back to an
// equal scenario (numbers written exactly). A model or signal that has no file form (a model
// or a signal implemented in Python) is an InputError naming it.
std::string scenario_toml(const Scenario& scenario);
// [model] kind = "python", callable = "module:function" names a model made by Python code
// (Python-only, docs/scenarios.md). The Python package installs the hook that makes it; without
// one (hinf-sim) such a scenario is an InputError that says to run it with hinf-cpp. The hook
// gets the callable's name and the scenario's source (for relative file paths).
using PythonModelHook = std::function<ModelPtr(const std::string& callable, const std::string& source)>;
void set_python_model_hook(PythonModelHook hook);

// Whether a scenario document's [desired] gives waypoints, a path or plan options (the planner
// of the Python package replaces them by inputs), parsed with every guard of parse_scenario_toml
// (an InputError for what it refuses).
bool needs_planning_toml(const std::string& text, const std::string& source);
// The model of a document's [model] section, read as parse_scenario_toml reads it (the planner
// of the Python package needs the model before the desired inputs exist).
ModelPtr parse_model_toml(const std::string& text, const std::string& source);

// A signal from a TOML document whose one key is `key` (a number or a signal table, as in a
// scenario), e.g. "kappa = { offset = 1.0 }".
Signal parse_signal_toml(const std::string& text, const std::string& key, const std::string& source);

// The results file of scenarios.md (one JSON object, matrices as nested row-major lists,
// non-finite numbers as null).
std::string results_json(const RunResult& result, int indent = 2);
// The time series on the output grid, one row per time, with a header line: t, the states,
// the desired states (suffix _d), u1.., u1_d.., w1..; with output feedback also the estimated
// errors (suffix _e_hat), the measurements y1.., sigma_min_eig, sigma_max_eig, rho_sigma_z.
std::string results_csv(const RunResult& result);

// Checks, before any computation, that an output file can be written at path: not empty,
// not a directory, and the nearest existing folder above it is a writable folder (missing
// folders are created by write_text_file). InputError naming the path otherwise.
void check_output_path(const std::string& path);
// Writes a file whole or not at all: a temporary file in the same folder, renamed over path
// once complete (an existing device or pipe, such as /dev/stdout, is written in place).
// Creates missing folders. InputError naming the path on any failure (a full disk included).
void write_text_file(const std::string& path, const std::string& text);

}  // namespace hinf
