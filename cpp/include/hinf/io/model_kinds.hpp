// The kinds of model of scenario files (docs/scenarios.md): the name that a model section
// ([model], [plant]) gives with kind = "...", the section's keys, how a section is read into a
// model and how a model is written back as a section. Each kind is registered once: the
// built-in ones in cpp/src/io/model_kinds.cpp (one line each), a program's own vehicle with
// register_model_kind. The scenario reader and writer and the [plant] section go through this
// one table, so a registered kind is read and written everywhere a model section is.
//
// Adding a vehicle to the library: its model in models/<vehicle>.{hpp,cpp} with a parameter
// struct and its table of keys (kShipParameterKeys is the pattern), and one line in the table
// of built-in kinds:
//     parameter_kind<Ship, ShipParameters>("ship", kShipParameterKeys),
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/core/types.hpp"
#include "hinf/models/model.hpp"

namespace hinf {

class SectionReader;
namespace detail {
class TableReader;  // cpp/src/io/toml_table.hpp
// The TOML reader behind a section (for the built-in kinds whose keys are more than numbers).
TableReader& table_of(const SectionReader& section);
}  // namespace detail

// The keys of one model section as a kind's reader sees them, read with the scenario reader's
// checks: a missing required key, a value of the wrong type or a non-finite number is an
// InputError naming the source (the file), the section and the key.
class SectionReader {
 public:
  SectionReader(detail::TableReader& table, std::string source, std::string where);

  // The scenario's source (its file path: relative file names are taken from its folder) and
  // the section ("[model]" or "[plant]").
  const std::string& source() const { return source_; }
  const std::string& where() const { return where_; }

  bool has(const std::string& key) const;
  double number_or(const std::string& key, double fallback) const;
  std::string string(const std::string& key) const;  // required
  std::string string_or(const std::string& key, const std::string& fallback) const;
  // A rows x cols nested list (required).
  Mat matrix(const std::string& key, int rows, int cols) const;
  // A table of name = number (required).
  std::map<std::string, double> numbers(const std::string& key) const;

  // InputError "<source>: <where> <key>: <problem>".
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
  // InputError "<source>: <where> <problem>", for a problem of the section as a whole (a
  // parameter that the model's constructor refuses).
  [[noreturn]] void fail_section(const std::string& problem) const;

 private:
  friend detail::TableReader& detail::table_of(const SectionReader& section);
  detail::TableReader* table_;
  std::string source_, where_;
};

// A value of a written model section: a number, a string, a matrix (written as a nested list of
// rows) or a table of numbers by name.
using SectionValue = std::variant<double, std::string, Mat, std::map<std::string, double>>;
// A model section as written, without "kind": its keys in order.
using Section = std::vector<std::pair<std::string, SectionValue>>;

struct ModelKind {
  std::string name;               // kind = "<name>"
  std::vector<std::string> keys;  // the section's keys besides "kind"; any other key is refused
                                  // (naming the kinds it belongs to, if any) before read is called
  // The model of a section of this kind (required).
  std::function<ModelPtr(const SectionReader& section)> read;
  // The section of a model of this kind, every parameter written out, or nullopt for a model
  // that is not of this kind. Empty: models of the kind have no file form (kind = "python").
  std::function<std::optional<Section>(const Model& model)> write;
  // The key that names a program the reader loads or runs (kind = "casadi": file, whose
  // model.json names a compiled library; kind = "python": callable), empty for a kind whose
  // models are data only. A section of such a kind is read only when the caller allows code
  // (parse_scenario_toml's allow_code); otherwise it is an InputError naming the key and how to
  // allow it, before anything is loaded.
  std::string code_key;
};

// Adds a kind to the table. InputError when the name is empty or taken, or read is empty.
// Safe to call from several threads; scenarios read afterwards know the kind.
void register_model_kind(ModelKind kind);
// The registered kinds' names in the order of registration (the built-in kinds first).
std::vector<std::string> model_kind_names();

// The kind of a vehicle that a struct of numbers describes, read and written through its table
// of (scenario-file key, member) that named_parameters() also uses (kShipParameterKeys, ...):
// a key not given keeps the value of `defaults`. With a preset name the section also takes the
// key preset = "<preset>" (the defaults are the preset). A parameter that Vehicle's constructor
// refuses (InputError) is reported as the section's.
template <class Vehicle, class Parameters, std::size_t N>
ModelKind parameter_kind(const std::string& name,
                         const std::array<std::pair<const char*, double Parameters::*>, N>& keys,
                         const Parameters& defaults = {}, const std::string& preset = "");

// [model] kind = "python", callable = "module:function" names a model made by Python code. The
// Python package installs the hook that makes it (hinf_cpp.scenario); without one (hinf-sim)
// such a scenario is an InputError that says to run it with hinf-cpp. The hook gets the
// callable's name and the scenario's source (for relative file paths).
using PythonModelHook = std::function<ModelPtr(const std::string& callable, const std::string& source)>;
void set_python_model_hook(PythonModelHook hook);

// ---- implementation ----

namespace detail {
// "preset" when a kind has a preset, then the keys of the table.
template <std::size_t N, class Parameters>
std::vector<std::string> parameter_key_names(const std::array<std::pair<const char*, double Parameters::*>, N>& keys,
                                             bool preset) {
  std::vector<std::string> names;
  if (preset) names.emplace_back("preset");
  for (const auto& [key, member] : keys) names.emplace_back(key);
  return names;
}
void check_preset(const SectionReader& section, const std::string& kind, const std::string& preset);
}  // namespace detail

template <class Vehicle, class Parameters, std::size_t N>
ModelKind parameter_kind(const std::string& name,
                         const std::array<std::pair<const char*, double Parameters::*>, N>& keys,
                         const Parameters& defaults, const std::string& preset) {
  ModelKind kind;
  kind.name = name;
  kind.keys = detail::parameter_key_names(keys, !preset.empty());
  kind.read = [name, keys, defaults, preset](const SectionReader& section) -> ModelPtr {
    if (!preset.empty()) detail::check_preset(section, name, preset);
    Parameters p = defaults;
    for (const auto& [key, member] : keys) p.*member = section.number_or(key, p.*member);
    try {
      return std::make_shared<Vehicle>(p);
    } catch (const InputError& e) {
      section.fail_section(e.what());
    }
  };
  kind.write = [](const Model& model) -> std::optional<Section> {
    if (dynamic_cast<const Vehicle*>(&model) == nullptr) return std::nullopt;
    Section section;
    for (const auto& [key, value] : model.named_parameters()) section.emplace_back(key, value);
    return section;
  };
  return kind;
}

}  // namespace hinf
