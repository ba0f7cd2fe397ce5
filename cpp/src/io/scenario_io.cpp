#include "hinf/io/scenario_io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <system_error>
#include <toml++/toml.h>

#include "hinf/core/errors.hpp"
#include "hinf/models/generated_model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/models/vehicles.hpp"

namespace hinf {

namespace {

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

// Reads one TOML table; keys outside `known` are rejected up front. key_prefix names a
// nested table in messages ("u2.harmonics[0].").
class TableReader {
 public:
  TableReader(const toml::table& table, std::string where, std::string source,
              std::vector<std::string> known, std::string key_prefix = "")
      : table_(table), where_(std::move(where)), source_(std::move(source)), known_(std::move(known)),
        key_prefix_(std::move(key_prefix)) {
    // Unknown keys first: a misspelt key is the cause of any "is required" that follows.
    for (auto&& [k, v] : table_) {
      const std::string key(k.str());
      if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
        std::string list;
        for (const std::string& name : known_) list += (list.empty() ? "" : ", ") + name;
        throw InputError(str_cat(source_, ": ", where_, " unknown key '", key_prefix_, key,
                                 "' (known keys: ", list, ")"));
      }
    }
  }

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(str_cat(source_, ": ", where_, " ", key_prefix_, key, ": ", problem));
  }

  const toml::node* get(const std::string& key) {
    return table_.get(key);
  }
  bool has(const std::string& key) const { return table_.contains(key); }

  double number(const std::string& key) {
    const toml::node* node = get(key);
    if (node == nullptr) fail(key, "is required");
    return as_number(*node, key);
  }
  double number_or(const std::string& key, double fallback) {
    const toml::node* node = get(key);
    return node != nullptr ? as_number(*node, key) : fallback;
  }
  // Every number of a scenario is finite, except where inf has a meaning (gamma):
  // allow_infinite lets +-inf through (never nan).
  double as_number(const toml::node& node, const std::string& key, bool allow_infinite = false) const {
    double value = 0.0;
    if (const auto* i = node.as_integer()) value = static_cast<double>(i->get());
    else if (const auto* f = node.as_floating_point()) value = f->get();
    else fail(key, "expected a number, got " + type_name(node));
    if (std::isnan(value) || (std::isinf(value) && !allow_infinite))
      fail(key, str_cat("expected a finite number, got ", value));
    return value;
  }
  std::string string_or(const std::string& key, const std::string& fallback) {
    const toml::node* node = get(key);
    if (node == nullptr) return fallback;
    if (const auto* s = node->as_string()) return s->get();
    fail(key, "expected a string, got " + type_name(*node));
  }
  std::string string(const std::string& key) {
    if (!has(key)) fail(key, "is required");
    return string_or(key, "");
  }
  // A closed choice given by its name (enum_names.hpp).
  template <class E>
  E enum_or(const std::string& key, E fallback) {
    if (!has(key)) return fallback;
    const std::string name = string(key);
    try {
      return from_string<E>(name);
    } catch (const InputError& e) {
      fail(key, e.what());
    }
  }
  std::int64_t integer_or(const std::string& key, std::int64_t fallback) {
    const toml::node* node = get(key);
    if (node == nullptr) return fallback;
    if (const auto* i = node->as_integer()) return i->get();
    fail(key, "expected an integer, got " + type_name(*node));
  }
  bool boolean_or(const std::string& key, bool fallback) {
    const toml::node* node = get(key);
    if (node == nullptr) return fallback;
    if (const auto* b = node->as_boolean()) return b->get();
    fail(key, "expected true or false, got " + type_name(*node));
  }
  Vec vector(const std::string& key, int size) {
    const toml::node* node = get(key);
    if (node == nullptr) fail(key, "is required");
    return as_vector(*node, key, size);
  }
  Vec as_vector(const toml::node& node, const std::string& key, int size) const {
    const toml::array* array = node.as_array();
    const std::string expected = size >= 0 ? str_cat(size, " numbers") : "an array of numbers";
    if (array == nullptr) fail(key, str_cat("expected ", expected, ", got ", type_name(node)));
    if (array->empty()) fail(key, str_cat("expected ", expected, ", got an empty array"));
    if (size >= 0 && static_cast<int>(array->size()) != size)
      fail(key, str_cat("expected ", size, " numbers, got ", array->size()));
    Vec v(static_cast<Eigen::Index>(array->size()));
    for (std::size_t i = 0; i < array->size(); ++i)
      v[static_cast<Eigen::Index>(i)] = as_number(*array->get(i), str_cat(key, "[", i, "]"));
    return v;
  }
  // A number (that many times the identity) or a nested list (a full matrix).
  Mat matrix(const std::string& key, int rows, int cols, bool allow_scalar) {
    const toml::node* node = get(key);
    if (node == nullptr) fail(key, "is required");
    if (allow_scalar && (node->is_integer() || node->is_floating_point())) {
      require(rows == cols, "internal: scalar weight for a non-square matrix");
      return as_number(*node, key) * Mat::Identity(rows, cols);
    }
    const toml::array* array = node->as_array();
    const std::string expected = str_cat(allow_scalar ? "a number or " : "", "a ", rows, " x ",
                                         cols, " nested list");
    if (array == nullptr) fail(key, "expected " + expected + ", got " + type_name(*node));
    if (array->empty()) fail(key, "expected " + expected + ", got an empty array");
    if (static_cast<int>(array->size()) != rows)
      fail(key, str_cat("expected ", expected, ", got ", array->size(), " rows"));
    Mat M(rows, cols);
    for (int i = 0; i < rows; ++i) {
      const toml::node& row = *array->get(static_cast<std::size_t>(i));
      if (!row.is_array()) fail(key, str_cat("expected ", expected, ", row ", i, " is ", type_name(row)));
      M.row(i) = as_vector(row, str_cat(key, "[", i, "]"), cols).transpose();
    }
    return M;
  }
  Signal signal(const std::string& key) {
    const toml::node* node = get(key);
    if (node == nullptr) fail(key, "is required");
    return as_signal(*node, key);
  }
  Signal as_signal(const toml::node& node, const std::string& key) const {
    if (node.is_integer() || node.is_floating_point()) {
      try {
        return Signal(as_number(node, key));
      } catch (const InputError& e) {
        if (std::string(e.what()).rfind(source_, 0) == 0) throw;
        fail(key, e.what());
      }
    }
    const toml::table* table = node.as_table();
    if (table == nullptr)
      fail(key, "expected a signal { offset = ..., harmonics = [...] } or { table = {...} }, got " +
                    type_name(node));
    TableReader reader(*table, where_, source_, {"offset", "harmonics", "table"}, key_prefix_ + key + ".");
    if (reader.has("table")) {
      if (reader.has("offset") || reader.has("harmonics"))
        fail(key, "a tabulated signal cannot also have offset or harmonics");
      const toml::table* tab = reader.get("table")->as_table();
      if (tab == nullptr) fail(key + ".table", "expected a table { t = [...], value = [...] }");
      TableReader points(*tab, where_, source_, {"t", "value", "interpolation"}, key_prefix_ + key + ".table.");
      const Vec t = points.vector("t", -1);
      const Vec v = points.vector("value", -1);
      const Interpolation interpolation = points.enum_or("interpolation", Interpolation::Pchip);
      try {
        return Signal::table(std::vector<double>(t.data(), t.data() + t.size()),
                             std::vector<double>(v.data(), v.data() + v.size()), interpolation);
      } catch (const InputError& e) {
        fail(key, e.what());
      }
    }
    const double offset = reader.has("offset") ? reader.number("offset") : 0.0;
    std::vector<Harmonic> harmonics;
    if (const toml::node* list = reader.get("harmonics")) {
      const toml::array* array = list->as_array();
      if (array == nullptr) fail(key + ".harmonics", "expected an array of tables, got " + type_name(*list));
      for (std::size_t i = 0; i < array->size(); ++i) {
        const std::string hkey = str_cat(key, ".harmonics[", i, "]");
        const toml::table* ht = array->get(i)->as_table();
        if (ht == nullptr) fail(hkey, "expected a table, got " + type_name(*array->get(i)));
        TableReader h(*ht, where_, source_, {"amplitude", "omega", "frequency_hz", "phase", "shape"},
                      key_prefix_ + hkey + ".");
        Harmonic harmonic;
        harmonic.amplitude = h.number("amplitude");
        const bool has_omega = h.has("omega"), has_hz = h.has("frequency_hz");
        if (has_omega == has_hz) fail(hkey, "give exactly one of omega (rad/s) and frequency_hz (Hz)");
        harmonic.omega = has_omega ? h.number("omega")
                                   : 2.0 * M_PI * h.number("frequency_hz");
        harmonic.phase = h.has("phase") ? h.number("phase") : 0.0;
        const std::string shape = h.has("shape") ? h.string("shape") : "sin";
        if (shape != "sin" && shape != "cos")
          h.fail("shape", "expected \"sin\" or \"cos\", got \"" + shape + "\"");
        harmonic.cosine = shape == "cos";
        harmonics.push_back(harmonic);
      }
    }
    try {
      return Signal(offset, std::move(harmonics));
    } catch (const InputError& e) {
      fail(key, e.what());
    }
  }

 private:
  const toml::table& table_;
  std::string where_, source_;
  std::vector<std::string> known_;
  std::string key_prefix_;
};

const toml::table* section(const toml::table& root, const std::string& name, const std::string& source,
                           bool required) {
  const toml::node* node = root.get(name);
  if (node == nullptr) {
    if (required) throw InputError(str_cat(source, ": missing required section [", name, "]"));
    return nullptr;
  }
  const toml::table* table = node->as_table();
  if (table == nullptr)
    throw InputError(str_cat(source, ": [", name, "] must be a table, got ", type_name(*node)));
  return table;
}

// `first`, then the keys of a table of (scenario-file key, parameter) (kShipParameterKeys, ...).
template <class Keys>
std::vector<std::string> key_names(const Keys& keys, std::vector<std::string> first = {}) {
  for (const auto& [key, member] : keys) first.push_back(key);
  return first;
}

// The keys of a model section ([model], [plant]) besides "kind", for each kind. A key of
// another kind is refused naming the kinds it belongs to; any other unknown key with the list
// of the kind's keys.
const std::vector<std::pair<std::string, std::vector<std::string>>>& model_kind_keys() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> kinds = {
      {"ship", key_names(kShipParameterKeys)},
      {"linear", {"A", "B", "D", "C"}},
      {"casadi", {"file", "parameters"}},
      {"python", {"callable"}},
      {"fossen_vessel", {"preset", "M", "D"}},
      {"hovercraft", key_names(kHovercraftParameterKeys)},
      {"pvtol", key_names(kPlanarVtolParameterKeys)},
      {"auv", key_names(kAuvParameterKeys, {"preset"})},
  };
  return kinds;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// A TableReader of a model section (`where`: "[model]" or "[plant]") for its kind (read first:
// it decides which keys are known).
TableReader model_reader(const toml::table& table, const std::string& source, const std::string& where,
                         std::string& kind) {
  const auto fail = [&source, &where](const std::string& key, const std::string& problem) {
    return InputError(str_cat(source, ": ", where, " ", key, ": ", problem));
  };
  const toml::node* node = table.get("kind");
  if (node == nullptr) throw fail("kind", "is required");
  if (node->as_string() == nullptr) throw fail("kind", "expected a string, got " + type_name(*node));
  kind = node->as_string()->get();
  const std::vector<std::string>* keys = nullptr;
  std::string kinds;
  for (const auto& [name, names] : model_kind_keys()) {
    if (name == kind) keys = &names;
    kinds += str_cat(kinds.empty() ? "" : ", ", "\"", name, "\"");
  }
  if (keys == nullptr) throw fail("kind", str_cat("unknown model kind \"", kind, "\": use one of ", kinds));
  for (auto&& [k, v] : table) {
    const std::string key(k.str());
    if (key == "kind" || contains(*keys, key)) continue;
    std::string owners;
    for (const auto& [name, names] : model_kind_keys())
      if (contains(names, key)) owners += str_cat(owners.empty() ? "" : " or ", "kind = \"", name, "\"");
    if (!owners.empty()) throw fail(key, str_cat("is a key of ", owners, ", not of kind = \"", kind, "\""));
  }
  std::vector<std::string> known{"kind"};
  known.insert(known.end(), keys->begin(), keys->end());
  return TableReader(table, where, source, known);
}

// ---- the built-in vehicles (vehicles.hpp) in [model] ----

// A vehicle from its parameters; a parameter the constructor refuses is reported as the
// section's (`where`).
template <class Vehicle, class Parameters>
ModelPtr make_vehicle(const Parameters& parameters, const std::string& source, const std::string& where) {
  try {
    return std::make_shared<Vehicle>(parameters);
  } catch (const InputError& e) {
    throw InputError(str_cat(source, ": ", where, " ", e.what()));
  }
}

// The numbers of a parameter struct read by their keys (kShipParameterKeys, ...); a key not
// given keeps the value in p.
template <class Parameters, std::size_t N>
void read_parameters(TableReader& r, const std::array<std::pair<const char*, double Parameters::*>, N>& keys,
                     Parameters& p) {
  for (const auto& [key, member] : keys) p.*member = r.number_or(key, p.*member);
}

// The preset named by the key "preset" (the default preset when absent); the only preset of a
// kind is its parameters' defaults.
void check_preset(TableReader& r, const std::string& kind, const std::string& preset) {
  const std::string name = r.string_or("preset", preset);
  if (name != preset)
    r.fail("preset", str_cat("unknown preset \"", name, "\" of kind = \"", kind, "\": the preset is \"", preset,
                             "\"; change single parameters by their keys"));
}

// kind = "fossen_vessel", "hovercraft", "pvtol" or "auv" (docs/scenarios.md); nullptr for
// another kind.
ModelPtr parse_vehicle_model(TableReader& r, const std::string& kind, const std::string& source,
                             const std::string& where) {
  if (kind == "fossen_vessel") {
    check_preset(r, kind, "supply_vessel");
    FossenVesselParameters p = FossenVesselParameters::supply_vessel();
    if (r.has("M")) p.M = r.matrix("M", 3, 3, false);
    if (r.has("D")) p.D = r.matrix("D", 3, 3, false);
    return make_vehicle<FossenVessel>(p, source, where);
  }
  if (kind == "hovercraft") {
    HovercraftParameters p;
    read_parameters(r, kHovercraftParameterKeys, p);
    return make_vehicle<Hovercraft>(p, source, where);
  }
  if (kind == "pvtol") {
    PlanarVtolParameters p;
    read_parameters(r, kPlanarVtolParameterKeys, p);
    return make_vehicle<PlanarVtol>(p, source, where);
  }
  if (kind == "auv") {
    check_preset(r, kind, "sirene");
    AuvParameters p = AuvParameters::sirene();
    read_parameters(r, kAuvParameterKeys, p);
    return make_vehicle<Auv>(p, source, where);
  }
  return nullptr;
}

// ---- end of the built-in vehicles ----

PythonModelHook& python_model_hook() {
  static PythonModelHook hook;
  return hook;
}

// The model of a model section: [model], or (where = "[plant]") the [plant] table that
// parse_plant merged with [model].
ModelPtr parse_model(const toml::table& table, const std::string& source, const std::string& where = "[model]") {
  std::string kind;
  TableReader r = model_reader(table, source, where, kind);
  if (kind == "python") {
    const std::string callable = r.string("callable");
    if (!python_model_hook())
      r.fail("kind", "\"python\" names a model made by Python code (" + callable +
                         "): run this scenario with hinf-cpp, or export the model as kind = \"casadi\" for hinf-sim");
    ModelPtr model = python_model_hook()(callable, source);
    if (model == nullptr) r.fail("callable", "'" + callable + "' made no model");
    return model;
  }
  if (kind == "casadi") {
    // The model's description (model.json, written by hinf_cpp.symbolic.SymbolicModel.export),
    // relative to the scenario file's folder.
    std::filesystem::path file = r.string("file");
    std::error_code ec;
    if (file.is_relative() && std::filesystem::is_regular_file(source, ec))
      file = std::filesystem::path(source).parent_path() / file;
    std::map<std::string, double> parameters;
    if (const toml::node* node = r.get("parameters")) {
      const toml::table* values = node->as_table();
      if (values == nullptr) r.fail("parameters", "expected a table of name = number, got " + type_name(*node));
      for (auto&& [key, value] : *values)
        parameters[std::string(key.str())] = r.as_number(value, str_cat("parameters.", key.str()));
    }
    try {
      return std::make_shared<GeneratedModel>(file.lexically_normal().string(), parameters);
    } catch (const InputError& e) {
      r.fail("file", e.what());
    }
  }
  if (kind == "ship") {
    ShipParameters p;
    read_parameters(r, kShipParameterKeys, p);
    return std::make_shared<ShipModel>(p);
  }
  if (kind == "linear") {
    // A, B and D set the model's dimensions: n = rows of A, m = columns of B, nw = columns of D.
    auto dimensions = [&r](const char* key, const char* shape) {
      const toml::node* node = r.get(key);
      if (node == nullptr) r.fail(key, str_cat("is required: an ", shape, " nested list"));
      const toml::array* rows = node->as_array();
      const toml::array* first = rows != nullptr && !rows->empty() ? rows->get(0)->as_array() : nullptr;
      std::string found;
      if (rows == nullptr) found = type_name(*node);
      else if (rows->empty()) found = "an empty array";
      else if (first == nullptr) found = "a first row that is " + type_name(*rows->get(0));
      else if (first->empty()) found = "an empty first row";
      if (!found.empty()) r.fail(key, str_cat("expected an ", shape, " nested list, got ", found));
      return std::make_pair(static_cast<int>(rows->size()), static_cast<int>(first->size()));
    };
    const int n = dimensions("A", "n x n").first;
    const Mat A = r.matrix("A", n, n, false);
    const Mat B = r.matrix("B", n, dimensions("B", "n x m").second, false);
    Mat D = Mat::Identity(n, n);
    if (r.has("D")) D = r.matrix("D", n, dimensions("D", "n x nw").second, false);
    Mat C;  // a measurement y = C q adds one noise channel per output (model.hpp)
    if (r.has("C")) C = r.matrix("C", dimensions("C", "p x n").first, n, false);
    return std::make_shared<LinearModel>(A, B, D, C);
  }
  return parse_vehicle_model(r, kind, source, where);  // model_kind_keys() has no other kind
}

// [plant]: a model section with the keys of [model]. Its kind defaults to [model]'s; with the
// same kind, a key not given is [model]'s (for kind = "casadi", each name of [plant.parameters]
// not given is [model.parameters]'), so only what differs need be written; with another kind,
// a key not given is that kind's default. Messages name [plant].
ModelPtr parse_plant(const toml::table& plant, const toml::table& model, const std::string& source) {
  const toml::node* kind = plant.get("kind");
  const bool same_kind = kind == nullptr || (kind->is_string() && model.get("kind")->is_string() &&
                                             kind->as_string()->get() == model.get("kind")->as_string()->get());
  if (!same_kind) return parse_model(plant, source, "[plant]");
  toml::table merged = model;
  for (auto&& [key, value] : plant) {
    toml::table* base_parameters = merged.get_as<toml::table>("parameters");
    if (key.str() == "parameters" && value.is_table() && base_parameters != nullptr) {
      for (auto&& [name, number] : *value.as_table()) base_parameters->insert_or_assign(name, number);
    } else {
      merged.insert_or_assign(key, value);
    }
  }
  return parse_model(merged, source, "[plant]");
}

std::string file_stem(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  const std::size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

// toml++ makes a table of each part of a dotted key (a.b.c = 1, [a.b.c]), and builds and frees
// them recursively: a key of some hundred thousand parts overflows the stack. Scenario keys
// have at most four parts; more than kMaxKeyParts are refused before parsing. (Arrays and
// inline tables are nested at most TOML_MAX_NESTED_VALUES deep: toml++ refuses more.)
constexpr int kMaxKeyParts = 16;

bool bare_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

// The index just past the TOML string that starts at text[i] (basic or literal, single- or
// multi-line), counting the line breaks inside it. An unterminated string ends at the end of
// its line (single-line) or of the text (multi-line); toml++ reports it.
std::size_t skip_string(const std::string& text, std::size_t i, long& line) {
  const char quote = text[i];
  const std::string triple(3, quote);
  const bool multiline = text.compare(i, 3, triple) == 0;
  i += multiline ? 3 : 1;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\\' && quote == '"') {
      if (i + 1 < text.size() && text[i + 1] == '\n') ++line;
      i += 2;
    } else if (multiline && text.compare(i, 3, triple) == 0) {
      i += 3;
      while (i < text.size() && text[i] == quote) ++i;  // up to two quotes may end the content
      return i;
    } else if (!multiline && c == quote) {
      return i + 1;
    } else if (c == '\n') {
      if (!multiline) return i;
      ++line;
      ++i;
    } else {
      ++i;
    }
  }
  return i;
}

// Refuses a run of more than kMaxKeyParts parts joined by dots (bare words or strings), outside
// strings and comments. Numbers and dates have at most two such parts ("1.5").
void check_key_parts(const std::string& text, const std::string& source) {
  long line = 1;
  int parts = 0;  // parts of the dotted run being read: "a.b.c" has 3
  bool after_dot = false;
  std::size_t i = 0, run_start = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (bare_key_char(c) || c == '"' || c == '\'') {
      if (!after_dot) run_start = i;
      if (bare_key_char(c)) {
        while (i < text.size() && bare_key_char(text[i])) ++i;
      } else {
        i = skip_string(text, i, line);
      }
      parts = after_dot ? parts + 1 : 1;
      after_dot = false;
      if (parts > kMaxKeyParts)
        throw InputError(str_cat(source, ":", line, ": invalid TOML: the key '", text.substr(run_start, 40),
                                 "...' has more than ", kMaxKeyParts,
                                 " dotted parts (tables nested too deeply for a scenario)"));
    } else if (c == ' ' || c == '\t') {
      ++i;
    } else if (c == '.' && parts > 0 && !after_dot) {
      after_dot = true;
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else {
      if (c == '\n') ++line;
      parts = 0;
      after_dot = false;
      ++i;
    }
  }
}

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// For messages: the key whose value holds the byte at `offset` ("[measurement] seed"), or ""
// when `offset` is not inside a value. The value of the last '=' before `offset` holds it
// unless a line break comes after that value's arrays and inline tables have all closed.
// Strings and comments are not told apart: this only names, it decides nothing.
std::string key_at(const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const std::size_t equals = offset == 0 ? std::string::npos : text.rfind('=', offset - 1);
  if (equals == std::string::npos) return "";
  int open = 0;
  for (std::size_t i = equals + 1; i < offset; ++i) {
    if (text[i] == '[' || text[i] == '{') ++open;
    if (text[i] == ']' || text[i] == '}') --open;
    if (text[i] == '\n' && open <= 0) return "";
  }
  // The key: from the start of its line, or of its place in an inline table, to the '='.
  const std::size_t before = equals == 0 ? std::string::npos : text.find_last_of("\n{,", equals - 1);
  const std::size_t key_start = before == std::string::npos ? 0 : before + 1;
  const std::string key = trim(text.substr(key_start, equals - key_start));
  if (key.empty()) return "";
  // The table: the last header line ("[name]" or "[[name]]") above the key.
  for (std::size_t end = key_start; end > 0;) {
    const std::size_t newline = text.rfind('\n', end - 1);
    const std::size_t start = newline == std::string::npos ? 0 : newline + 1;
    const std::string line = trim(text.substr(start, end - start));
    if (!line.empty() && line[0] == '[') {
      const std::size_t close = line.rfind(']');
      return (close == std::string::npos ? line : line.substr(0, close + 1)) + " " + key;
    }
    if (newline == std::string::npos) break;
    end = newline;
  }
  return "top level " + key;
}

// The byte offset of a 1-based line and column (toml++ counts columns in code points: on a line
// with non-ASCII text before the position the offset is a little early).
std::size_t offset_of(const std::string& text, long line, long column) {
  std::size_t offset = 0;
  for (long l = 1; l < line; ++l) {
    const std::size_t next = text.find('\n', offset);
    if (next == std::string::npos) return text.size();
    offset = next + 1;
  }
  return std::min(text.size(), offset + static_cast<std::size_t>(std::max(0L, column - 1)));
}

// Parses a TOML document (a leading UTF-8 byte-order mark is skipped). Syntax errors, nesting
// too deep and text that is not UTF-8 are an InputError naming the source, line and column and,
// for an error inside a value (such as an integer beyond 64 bits), the key.
toml::table parse_toml(const std::string& text, const std::string& source) {
  check_key_parts(text, source);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const long line = static_cast<long>(e.source().begin.line);
    const long column = static_cast<long>(e.source().begin.column);
    const std::string key = key_at(text, offset_of(text, line, column));
    throw InputError(str_cat(source, ":", line, ":", column, ": invalid TOML", key.empty() ? "" : " in " + key,
                             ": ", e.description()));
  }
}

}  // namespace

Scenario parse_scenario_toml(const std::string& text, const std::string& source) {
  const toml::table root = parse_toml(text, source);
  TableReader top(root, "top level", source,
                  {"name", "description", "model", "plant", "horizon", "desired", "controller",
                   "disturbance", "initial", "measurement", "solver", "output"});
  Scenario s;
  s.name = top.string_or("name", file_stem(source));
  s.description = top.string_or("description", "");

  const toml::table& model = *section(root, "model", source, true);
  s.model = parse_model(model, source);
  const int n = s.model->n(), m = s.model->m(), nw = s.model->nw();
  if (const toml::table* plant = section(root, "plant", source, false)) s.plant = parse_plant(*plant, model, source);

  {
    TableReader r(*section(root, "horizon", source, true), "[horizon]", source, {"t0", "tf"});
    s.t0 = r.number_or("t0", 0.0);
    s.tf = r.number("tf");
  }
  if (s.plant) {
    try {
      check_plant(*s.model, *s.plant, s.t0);
    } catch (const InputError& e) {
      throw InputError(str_cat(source, ": ", e.what()));
    }
  }
  {
    std::vector<std::string> known{"q0"};
    for (int i = 1; i <= m; ++i) known.push_back(str_cat("u", i));
    const toml::table& desired = *section(root, "desired", source, true);
    // Planning (docs/planning.md) is the Python package's: it replaces these keys by the planned
    // inputs before the scenario reaches this reader.
    for (const char* key : {"waypoints", "path", "plan"})
      if (desired.contains(key))
        throw InputError(str_cat(source, ": [desired] ", key, ": a desired trajectory planned from waypoints or a "
                                 "path needs the planner of the Python package (docs/planning.md): run this file "
                                 "with hinf-cpp run, or write the planned scenario with hinf-cpp plan FILE -o "
                                 "PLANNED.toml and run that"));
    TableReader r(desired, "[desired]", source, known);
    s.desired_q0 = r.vector("q0", n);
    std::vector<Signal> inputs;
    for (int i = 1; i <= m; ++i) inputs.push_back(r.signal(str_cat("u", i)));
    s.desired_u = VectorSignal(std::move(inputs));
  }
  {
    TableReader r(*section(root, "controller", source, true), "[controller]", source,
                  {"gamma", "Q", "Qf", "kappa", "law", "cascade"});
    const toml::node* gamma = r.get("gamma");
    if (gamma == nullptr) r.fail("gamma", "is required");
    s.gamma = r.as_number(*gamma, "gamma", true);  // inf: the LQR limit
    s.law = r.enum_or("law", s.law);
    if (const toml::node* node = r.get("cascade")) {
      const toml::table* table = node->as_table();
      if (table == nullptr) r.fail("cascade", "expected a table { k = ..., k1 = ..., k2 = ... }, got " + type_name(*node));
      TableReader g(*table, "[controller]", source, {"k", "k1", "k2"}, "cascade.");
      s.cascade.k = g.number_or("k", s.cascade.k);
      s.cascade.k1 = g.number_or("k1", s.cascade.k1);
      s.cascade.k2 = g.number_or("k2", s.cascade.k2);
    }
    if (r.has("Q")) s.Q = r.matrix("Q", n, n, true);
    if (r.has("Qf")) s.Qf = r.matrix("Qf", n, n, true);
    if (r.has("kappa")) s.kappa = r.signal("kappa");
  }
  {
    std::vector<Signal> channels(static_cast<std::size_t>(nw));
    if (const toml::table* table = section(root, "disturbance", source, false)) {
      std::vector<std::string> known;
      for (int i = 1; i <= nw; ++i) known.push_back(str_cat("w", i));
      known.push_back("worst_case");
      TableReader r(*table, "[disturbance]", source, known);
      // The noise channels carry the measurement noise of [measurement]: a signal there would
      // count in the disturbance's energy without moving the vehicle, and output feedback
      // would overwrite it with the noise.
      for (int channel : s.model->noise_channels()) {
        const std::string key = str_cat("w", channel + 1);
        if (r.has(key))
          r.fail(key, str_cat("is a measurement-noise channel of the ", s.model->name(),
                              " model, not a disturbance: the measurement noise is set through"
                              " [measurement] (sigma, sample_period, seed)"));
      }
      s.worst_case = r.boolean_or("worst_case", false);
      for (int i = 1; i <= nw; ++i)
        if (r.has(str_cat("w", i))) channels[static_cast<std::size_t>(i - 1)] = r.signal(str_cat("w", i));
    }
    s.disturbance = VectorSignal(std::move(channels));
  }
  {
    TableReader r(*section(root, "initial", source, true), "[initial]", source, {"q0"});
    s.initial_q0 = r.vector("q0", n);
  }
  if (const toml::table* table = section(root, "measurement", source, false)) {
    TableReader r(*table, "[measurement]", source,
                  {"sigma", "sample_period", "seed", "N", "Q0", "eta", "filter_A",
                   "on_coupling_violation"});
    MeasurementSpec ms;
    ms.sigma = r.number("sigma");
    ms.sample_period = r.number_or("sample_period", ms.sample_period);
    const std::int64_t seed = r.integer_or("seed", 0);
    if (seed < 0) r.fail("seed", str_cat("must be >= 0, got ", seed));
    ms.seed = static_cast<std::uint64_t>(seed);
    if (const toml::node* node = r.get("N")) {
      const toml::array* rows = node->as_array();
      if (rows == nullptr) {
        ms.N = Mat::Constant(1, 1, r.number("N"));  // scalar: expanded to N I by resolved()
      } else {
        // p x p for p measured outputs (validate() checks p against the model)
        if (rows->empty()) r.fail("N", "expected a number or a p x p nested list (p measured outputs), got an empty array");
        const int p = static_cast<int>(rows->size());
        ms.N = r.matrix("N", p, p, false);
      }
    }
    if (r.has("Q0")) ms.Q0 = r.matrix("Q0", n, n, true);
    ms.eta = r.number_or("eta", ms.eta);
    ms.filter_A = r.enum_or("filter_A", ms.filter_A);
    ms.on_coupling_violation = r.enum_or("on_coupling_violation", ms.on_coupling_violation);
    s.measurement = ms;
  }
  if (const toml::table* table = section(root, "solver", source, false)) {
    TableReader r(*table, "[solver]", source, {"method", "newton_systems", "rtol", "atol", "max_steps", "divergence_factor"});
    s.solver.method = r.enum_or("method", s.solver.method);
    s.solver.newton_systems = r.enum_or("newton_systems", s.solver.newton_systems);
    s.solver.rtol = r.number_or("rtol", s.solver.rtol);
    s.solver.atol = r.number_or("atol", s.solver.atol);
    s.solver.max_steps = static_cast<long>(r.integer_or("max_steps", s.solver.max_steps));
    s.divergence_factor = r.number_or("divergence_factor", s.divergence_factor);
    try {
      s.simulation_options().validate();
    } catch (const InputError& e) {
      throw InputError(str_cat(source, ": [solver] ", e.what()));
    }
  }
  if (const toml::table* table = section(root, "output", source, false)) {
    TableReader r(*table, "[output]", source, {"dt"});
    s.output_dt = r.number_or("dt", s.output_dt);
  }
  return s;
}

bool needs_planning_toml(const std::string& text, const std::string& source) {
  const toml::table root = parse_toml(text, source);
  const toml::table* desired = root["desired"].as_table();
  if (desired == nullptr) return false;
  for (const char* key : {"waypoints", "path", "plan"})
    if (desired->contains(key)) return true;
  return false;
}

ModelPtr parse_model_toml(const std::string& text, const std::string& source) {
  const toml::table root = parse_toml(text, source);
  return parse_model(*section(root, "model", source, true), source);
}

Signal parse_signal_toml(const std::string& text, const std::string& key, const std::string& source) {
  const toml::table root = parse_toml(text, source);
  TableReader r(root, "signal", source, {key});
  return r.signal(key);
}

namespace {

std::string error_text(int error) { return std::generic_category().message(error); }

}  // namespace

Scenario load_scenario_toml(const std::string& path) {
  const std::string cannot = str_cat("cannot read scenario file '", path, "': ");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(cannot + "it is a directory");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw InputError(cannot + error_text(errno));
  std::string text;
  char chunk[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0) text.append(chunk, got);
  const int error = std::ferror(file) != 0 ? errno : 0;
  std::fclose(file);
  if (error != 0) throw InputError(cannot + error_text(error));
  return parse_scenario_toml(text, path);
}

namespace {

nlohmann::json number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json matrix_json(const Mat& M) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < M.cols(); ++j) row.push_back(number(M(i, j)));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

namespace {

// The TOML form of a signal: a number for a constant, a table otherwise.
void insert_signal(toml::table& table, const std::string& key, const Signal& signal) {
  if (signal.is_constant()) {
    table.insert(key, signal.offset());
    return;
  }
  toml::table spec;
  if (signal.is_table()) {
    toml::array t, value;
    for (double x : signal.table_t()) t.push_back(x);
    for (double x : signal.table_values()) value.push_back(x);
    spec.insert("table", toml::table{{"t", std::move(t)},
                                     {"value", std::move(value)},
                                     {"interpolation", to_string(signal.interpolation())}});
  } else {
    spec.insert("offset", signal.offset());
    toml::array harmonics;
    for (const Harmonic& h : signal.harmonics())
      harmonics.push_back(toml::table{{"amplitude", h.amplitude},
                                      {"omega", h.omega},
                                      {"phase", h.phase},
                                      {"shape", h.cosine ? "cos" : "sin"}});
    spec.insert("harmonics", std::move(harmonics));
  }
  table.insert(key, std::move(spec));
}

// Channels prefix1, prefix2, ...: every one (all_channels), or only the non-zero ones that are
// not in `excluded`.
void insert_vector_signal(toml::table& table, const std::string& prefix, const VectorSignal& signals,
                          const std::string& what, bool all_channels, const std::vector<int>& excluded = {}) {
  require(!signals.is_function(), what, " is a function of t (a Python callable, say): it cannot be written to a",
          " scenario file; give it as signals (constants, harmonics or tables)");
  for (int i = 0; i < signals.dim(); ++i) {
    const Signal& channel = signals.channels()[static_cast<std::size_t>(i)];
    const bool zero = channel.is_constant() && channel.offset() == 0.0;
    const bool is_excluded = std::find(excluded.begin(), excluded.end(), i) != excluded.end();
    if (all_channels || (!zero && !is_excluded)) insert_signal(table, str_cat(prefix, i + 1), channel);
  }
}

toml::array vector_toml(const Vec& v) {
  toml::array a;
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

toml::array matrix_toml(const Mat& M) {
  toml::array rows;
  for (Eigen::Index i = 0; i < M.rows(); ++i) rows.push_back(vector_toml(M.row(i).transpose()));
  return rows;
}

// ---- the built-in vehicles (vehicles.hpp) in [model] ----

// kind = `kind` and every named parameter (Model::named_parameters: the section's keys).
toml::table named_parameters_toml(const std::string& kind, const Model& model) {
  toml::table table{{"kind", kind}};
  for (const auto& [name, value] : model.named_parameters()) table.insert(name, value);
  return table;
}

// The [model] table of a built-in vehicle, every parameter written out; nullopt for another model.
std::optional<toml::table> vehicle_model_toml(const Model& model) {
  if (const auto* vessel = dynamic_cast<const FossenVessel*>(&model)) {
    const FossenVesselParameters& p = vessel->parameters();
    return toml::table{{"kind", "fossen_vessel"}, {"M", matrix_toml(p.M)}, {"D", matrix_toml(p.D)}};
  }
  if (dynamic_cast<const Hovercraft*>(&model) != nullptr) return named_parameters_toml("hovercraft", model);
  if (dynamic_cast<const PlanarVtol*>(&model) != nullptr) return named_parameters_toml("pvtol", model);
  if (dynamic_cast<const Auv*>(&model) != nullptr) return named_parameters_toml("auv", model);
  return std::nullopt;
}

// ---- end of the built-in vehicles ----

// The model section ([model], [plant]) of a model, every parameter written out.
toml::table model_toml(const Model& model) {
  if (dynamic_cast<const ShipModel*>(&model) != nullptr) return named_parameters_toml("ship", model);
  if (const auto* linear = dynamic_cast<const LinearModel*>(&model)) {
    toml::table table{{"kind", "linear"}, {"A", matrix_toml(linear->A())}, {"B", matrix_toml(linear->B())},
                      {"D", matrix_toml(linear->process_D())}};
    if (linear->measurement_C().size() > 0) table.insert("C", matrix_toml(linear->measurement_C()));
    return table;
  }
  if (std::optional<toml::table> vehicle = vehicle_model_toml(model)) return *vehicle;
  if (const auto* generated = dynamic_cast<const GeneratedModel*>(&model)) {
    toml::table parameters;
    for (const auto& [name, value] : generated->parameters()) parameters.insert(name, value);
    return toml::table{{"kind", "casadi"},
                       {"file", std::filesystem::absolute(generated->metadata_path()).lexically_normal().string()},
                       {"parameters", parameters}};
  }
  throw InputError(str_cat("the model '", model.name(), "' has no scenario-file form (only the built-in models",
                           " and kind = \"casadi\" have one; a model implemented in Python has none)"));
}

}  // namespace

void set_python_model_hook(PythonModelHook hook) { python_model_hook() = std::move(hook); }

std::string scenario_toml(const Scenario& s) {
  require(s.model != nullptr, "the scenario has no model");
  const Model& model = *s.model;
  toml::table root;
  root.insert("name", s.name);
  if (!s.description.empty()) root.insert("description", s.description);
  root.insert("model", model_toml(model));
  if (s.plant) root.insert("plant", model_toml(*s.plant));
  root.insert("horizon", toml::table{{"t0", s.t0}, {"tf", s.tf}});
  toml::table desired{{"q0", vector_toml(s.desired_q0)}};
  insert_vector_signal(desired, "u", s.desired_u, "[desired] u_d", /*all_channels=*/true);
  root.insert("desired", std::move(desired));
  toml::table controller{{"gamma", s.gamma}, {"law", to_string(s.law)}};
  if (s.Q.size() > 0) controller.insert("Q", matrix_toml(s.Q));
  if (s.Qf.size() > 0) controller.insert("Qf", matrix_toml(s.Qf));
  insert_signal(controller, "kappa", s.kappa);
  controller.insert("cascade", toml::table{{"k", s.cascade.k}, {"k1", s.cascade.k1}, {"k2", s.cascade.k2}});
  root.insert("controller", std::move(controller));
  toml::table disturbance{{"worst_case", s.worst_case}};
  insert_vector_signal(disturbance, "w", s.disturbance, "[disturbance]", /*all_channels=*/false,
                       model.noise_channels());
  root.insert("disturbance", std::move(disturbance));
  root.insert("initial", toml::table{{"q0", vector_toml(s.initial_q0)}});
  if (s.measurement) {
    const MeasurementSpec& ms = *s.measurement;
    require(ms.seed <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()),
            "[measurement] seed = ", ms.seed, " does not fit in a scenario file's 64-bit signed integer");
    toml::table measurement{{"sigma", ms.sigma},
                            {"sample_period", ms.sample_period},
                            {"seed", static_cast<std::int64_t>(ms.seed)},
                            {"eta", ms.eta},
                            {"filter_A", to_string(ms.filter_A)},
                            {"on_coupling_violation", to_string(ms.on_coupling_violation)}};
    if (ms.N.size() > 0) measurement.insert("N", matrix_toml(ms.N));
    if (ms.Q0.size() > 0) measurement.insert("Q0", matrix_toml(ms.Q0));
    root.insert("measurement", std::move(measurement));
  }
  root.insert("solver", toml::table{{"method", to_string(s.solver.method)},
                                    {"newton_systems", to_string(s.solver.newton_systems)},
                                    {"rtol", s.solver.rtol},
                                    {"atol", s.solver.atol},
                                    {"max_steps", static_cast<std::int64_t>(s.solver.max_steps)},
                                    {"divergence_factor", s.divergence_factor}});
  root.insert("output", toml::table{{"dt", s.output_dt}});
  std::ostringstream os;
  os << toml::toml_formatter(root, toml::toml_formatter::default_flags & ~toml::format_flags::allow_literal_strings);
  return os.str() + "\n";
}

std::string results_json(const RunResult& r, int indent) {
  const Metrics& mt = r.metrics;
  nlohmann::json j;
  j["scenario"] = r.scenario_name;
  const auto parameters_json = [](const Model& model) {
    nlohmann::json parameters = nlohmann::json::object();
    for (const auto& [name, value] : model.named_parameters()) parameters[name] = number(value);
    return parameters;
  };
  j["model"] = {{"name", r.trajectory ? r.trajectory->model().name() : std::string()},
                {"jacobian", r.trajectory ? r.trajectory->model().jacobian_method() : std::string()},
                {"parameters", r.trajectory ? parameters_json(r.trajectory->model()) : nlohmann::json::object()}};
  if (r.plant) j["plant"] = {{"name", r.plant->name()}, {"parameters", parameters_json(*r.plant)}};
  j["controller"] = to_string(r.law) + (r.output_feedback ? "-output-feedback" : "");
  j["gamma"] = number(r.gamma);
  j["Z0"] = r.solution ? matrix_json(r.Z0) : nlohmann::json(nullptr);
  j["Z_min_eig"] = number(r.Z_min_eig);
  j["Z_max_eig"] = number(r.Z_max_eig);
  j["gamma_star"] = r.gamma_star ? number(*r.gamma_star) : nlohmann::json(nullptr);
  j["coupling_violation_t"] =
      number(r.simulation.estimator ? r.simulation.estimator->coupling_violation_t : NAN);
  j["status"] = to_string(r.simulation.status);
  j["status_message"] = r.simulation.status_message;
  j["metrics"] = nlohmann::json::object();
  for (const MetricDefinition& metric : metric_table()) j["metrics"][metric.name] = number(mt.*metric.value);

  j["timing_s"] = {{"design", r.timing.design},
                   {"simulate", r.timing.simulate},
                   {"analysis", r.timing.analysis},
                   {"total", r.timing.total}};
  const SolveStats grde = r.solution ? r.solution->stats() : SolveStats{};
  j["solver"] = {{"grde_method", grde.method},
                 {"grde_steps", grde.steps},
                 {"grde_rhs_evals", grde.rhs_evals},
                 {"grde_memory_bytes", grde.memory_bytes},
                 {"simulation_steps", r.simulation.stats.steps},
                 {"simulation_rhs_evals", r.simulation.stats.rhs_evals},
                 {"simulation_integrator", r.simulation.integrator}};
  return j.dump(indent);
}

std::string results_csv(const RunResult& r) {
  const SimulationResult& s = r.simulation;
  const Model& model = r.trajectory->model();
  const std::vector<std::string> names = model.state_names();
  std::ostringstream os;
  os.precision(17);
  os << "t";
  for (const std::string& name : names) os << "," << name;
  for (const std::string& name : names) os << "," << name << "_d";
  for (int i = 1; i <= model.m(); ++i) os << ",u" << i;
  for (int i = 1; i <= model.m(); ++i) os << ",u" << i << "_d";
  for (int i = 1; i <= model.nw(); ++i) os << ",w" << i;
  const EstimatorSeries* e = s.estimator ? &*s.estimator : nullptr;
  if (e != nullptr) {
    for (const std::string& name : names) os << "," << name << "_e_hat";
    for (Eigen::Index i = 1; i <= e->y.cols(); ++i) os << ",y" << i;
    os << ",sigma_min_eig,sigma_max_eig,rho_sigma_z";
  }
  os << "\n";
  for (Eigen::Index k = 0; k < s.t.size(); ++k) {
    os << s.t[k];
    for (const RowMat* M : {&s.q, &s.q_d, &s.u, &s.u_d, &s.w})
      for (Eigen::Index i = 0; i < M->cols(); ++i) os << "," << (*M)(k, i);
    if (e != nullptr) {
      for (Eigen::Index i = 0; i < e->q_hat.cols(); ++i) os << "," << e->q_hat(k, i);
      for (Eigen::Index i = 0; i < e->y.cols(); ++i) os << "," << e->y(k, i);
      os << "," << e->sigma_min_eig[k] << "," << e->sigma_max_eig[k] << "," << e->rho_sigma_z[k];
    }
    os << "\n";
  }
  return os.str();
}

void check_output_path(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError("an output file name is empty");
  const std::string cannot = str_cat("cannot write '", path, "': ");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(cannot + "it is a directory");
  // The nearest existing folder above: missing folders below it are created when writing.
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  while (!fs::exists(folder, ec)) {
    const fs::path up = folder.has_relative_path() ? folder.parent_path() : folder;
    const fs::path next = up.empty() ? fs::path(".") : up;
    if (next == folder) break;  // "/" or "." (a working directory that was removed)
    folder = next;
  }
  if (!fs::is_directory(folder, ec)) throw InputError(str_cat(cannot, "'", folder.string(), "' is not a directory"));
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(str_cat(cannot, "'", folder.string(), "': ", error_text(errno)));
}

namespace {

// Writes all of text to the open file descriptor; false (errno set) on failure.
bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void write_text_file(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  check_output_path(path);
  const std::string cannot = str_cat("cannot write '", path, "': ");
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    // A device or a pipe (/dev/stdout, /dev/null): written in place, it cannot be replaced.
    const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) throw InputError(cannot + error_text(errno));
    const bool written = write_all(fd, text);
    const int error = errno;
    if (::close(fd) != 0 && written) throw InputError(cannot + error_text(errno));
    if (!written) throw InputError(cannot + error_text(error));
    return;
  }
  // A temporary file next to the target, renamed over it once complete: a failed write (a
  // full disk) leaves the previous file, or none, never a truncated one.
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  fs::create_directories(folder, ec);
  if (ec) throw InputError(str_cat(cannot, "cannot create the folder '", folder.string(), "': ", ec.message()));
  static std::atomic<unsigned> counter{0};
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    temporary = (folder / str_cat(".", target.filename().string(), ".", ::getpid(), ".", counter++, ".tmp")).string();
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);  // mode less the umask
    if (fd < 0 && (errno != EEXIST || attempt > 100)) throw InputError(cannot + error_text(errno));
  }
  bool ok = write_all(fd, text) && ::fsync(fd) == 0;
  int error = errno;
  if (::close(fd) != 0 && ok) {
    ok = false;
    error = errno;
  }
  if (ok && std::rename(temporary.c_str(), path.c_str()) != 0) {
    ok = false;
    error = errno;
  }
  if (!ok) {
    ::unlink(temporary.c_str());
    throw InputError(cannot + error_text(error));
  }
}

}  // namespace hinf
