// Model sections of scenario files through the table of model kinds (io/model_kinds.hpp),
// for the scenario reader and writer (private to the io layer).
#pragma once

#include <string>
#include <toml++/toml.h>

#include "hinf/models/model.hpp"

namespace hinf::detail {

// The model of a model section by its kind: [model], or (where = "[plant]") the [plant] table
// merged with [model]. InputError naming the source, the section and the key for anything
// wrong: no or an unknown kind, a key of another kind or of none, a value the kind refuses, a
// kind that runs code (ModelKind::code_key) without allow_code.
ModelPtr read_model_section(const toml::table& table, const std::string& source, const std::string& where,
                            bool allow_code);

// The checks of read_model_section that need no model: nothing is loaded or run.
void check_model_section(const toml::table& table, const std::string& source, const std::string& where,
                         bool allow_code);
// Whether the section's kind loads or runs a program (ModelKind::code_key); false for a section
// whose kind is missing or unknown (read_model_section names that problem).
bool section_runs_code(const toml::table& table);

// The section of a model (kind and every parameter). InputError when no kind writes it (a
// model implemented in Python, a model of a program's own that registered no kind).
toml::table model_section(const Model& model);

}  // namespace hinf::detail
