// The built-in vehicles' equations: the C code generated from their statements
// (python/hinf_cpp/models/builtin.py) and compiled into the library, cpp/src/models/generated
// (private to the models layer).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/generated_model.hpp"
#include "models/generated/generated_model.h"

namespace hinf::detail {

using NamedValues = std::vector<std::pair<std::string, double>>;

// The equations of a built-in vehicle with its parameters given by name: every parameter of the
// description exactly once (a mismatch between a class's keys and its statement is a defect of
// the library: std::logic_error). InputError for a parameter that is not finite.
std::shared_ptr<const GeneratedModel> compiled_in_model(const hinf_generated_model& description,
                                                        const NamedValues& parameters);

// The description's parameter defaults (its statement's), by name.
NamedValues compiled_in_defaults(const hinf_generated_model& description);

}  // namespace hinf::detail
