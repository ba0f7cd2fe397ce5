// TOML documents for the io layer (private): the reader of one table with its checks and
// messages (TableReader), parsing with the guards of the scenario reader, and the TOML form of
// vectors, matrices and signals.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "hinf/core/enum_names.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/types.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf::detail {

inline std::string type_name(const toml::node& node) {
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
      fail(key, str_cat(allow_infinite ? "expected a number (inf allowed), got " : "expected a finite number, got ",
                        value));
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
  Vec vector(const std::string& key, int size, bool allow_infinite = false) {
    const toml::node* node = get(key);
    if (node == nullptr) fail(key, "is required");
    return as_vector(*node, key, size, allow_infinite);
  }
  Vec as_vector(const toml::node& node, const std::string& key, int size, bool allow_infinite = false) const {
    const toml::array* array = node.as_array();
    const std::string expected = size >= 0 ? str_cat(size, " numbers") : "an array of numbers";
    if (array == nullptr) fail(key, str_cat("expected ", expected, ", got ", type_name(node)));
    if (array->empty()) fail(key, str_cat("expected ", expected, ", got an empty array"));
    if (size >= 0 && static_cast<int>(array->size()) != size)
      fail(key, str_cat("expected ", size, " numbers, got ", array->size()));
    Vec v(static_cast<Eigen::Index>(array->size()));
    for (std::size_t i = 0; i < array->size(); ++i)
      v[static_cast<Eigen::Index>(i)] = as_number(*array->get(i), str_cat(key, "[", i, "]"), allow_infinite);
    return v;
  }
  // A number (that many times the identity) or a nested list (a full matrix).
  Mat matrix(const std::string& key, int rows, int cols, bool allow_scalar) {
    const toml::node* node = get(key);
    if (node == nullptr) fail(key, "is required");
    // rows = cols = -1: a square matrix of any size (its size is checked once the model is known).
    if (allow_scalar && (node->is_integer() || node->is_floating_point())) {
      require(rows == cols, "internal: scalar weight for a non-square matrix");
      return as_number(*node, key) * Mat::Identity(std::max(rows, 1), std::max(cols, 1));
    }
    const toml::array* array = node->as_array();
    const std::string expected = str_cat(allow_scalar ? "a number or " : "", rows < 0 ? std::string("a square") :
                                         str_cat("a ", rows, " x ", cols), " nested list");
    if (array == nullptr) fail(key, "expected " + expected + ", got " + type_name(*node));
    if (array->empty()) fail(key, "expected " + expected + ", got an empty array");
    if (rows < 0) rows = cols = static_cast<int>(array->size());
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

inline const toml::table* section(const toml::table& root, const std::string& name, const std::string& source,
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

// Parses a TOML document (a leading UTF-8 byte-order mark is skipped). Syntax errors, nesting
// too deep and text that is not UTF-8 are an InputError naming the source, line and column and,
// for an error inside a value (such as an integer beyond 64 bits), the key.
toml::table parse_toml(const std::string& text, const std::string& source);

// The TOML form of a vector, a matrix (a list of rows) and a signal (a number for a constant, a
// table otherwise, inserted at `key`).
toml::array vector_toml(const Vec& v);
toml::array matrix_toml(const Mat& M);
void insert_signal(toml::table& table, const std::string& key, const Signal& signal);

// The text of a document, strings in basic (double) quotes.
std::string toml_text(const toml::table& root);

}  // namespace hinf::detail
