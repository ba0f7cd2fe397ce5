// Scenario files (TOML; docs/scenarios.md is the reference): the one reader and the writer.
// Model sections ([model], [plant]) are read and written through the table of model kinds
// (io/model_kinds.hpp).
#pragma once

#include <string>

#include "hinf/models/model.hpp"
#include "hinf/numerics/signal.hpp"
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
//
// Trust: a file is data. A model section whose kind loads or runs a program (kind = "casadi"
// loads the compiled library its model.json names; kind = "python" imports and calls Python
// code) is read only with allow_code; otherwise it is an InputError naming the key and how to
// allow it (hinf-sim and hinf-cpp --trust-code, trust_code=True in Python, HINF_TRUST_CODE=1).
//
// A model section whose kind is a program is loaded only after every other check of the file
// has passed (the sizes that the model sets are checked after it, as they must be).
Scenario parse_scenario_toml(const std::string& text, const std::string& source, bool allow_code = false);
// Every check that needs no model, with nothing loaded or run whatever the model's kind: the
// reader's keys, types and values, and Scenario::validate_settings (trust aside). The sizes a
// model sets (the length of q0, the inputs u1..um, the channels w1..wnw) are not checked.
// InputError naming the source, as parse_scenario_toml. parse_scenario_toml runs these checks
// first when a model section's kind is a program.
void check_scenario_toml(const std::string& text, const std::string& source);
// Reads and parses a scenario file; a file that cannot be read (missing, a directory) is an
// InputError naming the path.
Scenario load_scenario_toml(const std::string& path, bool allow_code = false);
// The environment's answer to "may files run code": HINF_TRUST_CODE = 1 yes, unset, empty or 0
// no, anything else an InputError. The front ends use it as the default of their --trust-code.
bool code_trusted_by_environment();
// The inverse of parse_scenario_toml: the scenario as a scenario file that reads back to an
// equal scenario (numbers written exactly). A model or signal that has no file form (a model
// or a signal implemented in Python) is an InputError naming it.
std::string scenario_toml(const Scenario& scenario);
// Whether a scenario document's [desired] or [path_change] gives waypoints, a path or plan
// options (the planner of the Python package replaces them by inputs), parsed with every guard of parse_scenario_toml
// (an InputError for what it refuses).
bool needs_planning_toml(const std::string& text, const std::string& source);
// The model of a document's [model] section, read as parse_scenario_toml reads it (the planner
// of the Python package needs the model before the desired inputs exist).
ModelPtr parse_model_toml(const std::string& text, const std::string& source, bool allow_code = false);

// A signal from a TOML document whose one key is `key` (a number or a signal table, as in a
// scenario), e.g. "kappa = { offset = 1.0 }".
Signal parse_signal_toml(const std::string& text, const std::string& key, const std::string& source);

}  // namespace hinf
