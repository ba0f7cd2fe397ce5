#include "hinf/scenario_io.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <sstream>

#include "hinf/errors.hpp"

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
  double as_number(const toml::node& node, const std::string& key) const {
    if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
    if (const auto* f = node.as_floating_point()) return f->get();
    fail(key, "expected a number, got " + type_name(node));
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
    if (array == nullptr) fail(key, "expected an array of numbers, got " + type_name(node));
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
      TableReader points(*tab, where_, source_, {"t", "value"}, key_prefix_ + key + ".table.");
      const Vec t = points.vector("t", -1);
      const Vec v = points.vector("value", -1);
      try {
        return Signal::table(std::vector<double>(t.data(), t.data() + t.size()),
                             std::vector<double>(v.data(), v.data() + v.size()));
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

ModelPtr parse_model(const toml::table& table, const std::string& source) {
  TableReader r(table, "[model]", source, {"kind", "m_u", "m_v", "m_r", "d_u", "d_v", "d_r", "A", "B", "D"});
  const std::string kind = r.string("kind");
  ModelPtr model;
  if (kind == "ship") {
    ShipParameters p;
    p.m_u = r.number_or("m_u", p.m_u);
    p.m_v = r.number_or("m_v", p.m_v);
    p.m_r = r.number_or("m_r", p.m_r);
    p.d_u = r.number_or("d_u", p.d_u);
    p.d_v = r.number_or("d_v", p.d_v);
    p.d_r = r.number_or("d_r", p.d_r);
    for (const char* key : {"A", "B", "D"})
      if (r.has(key)) r.fail(key, "is a key of kind = \"linear\", not of kind = \"ship\"");
    model = std::make_shared<ShipModel>(p);
  } else if (kind == "linear") {
    for (const char* key : {"m_u", "m_v", "m_r", "d_u", "d_v", "d_r"})
      if (r.has(key)) r.fail(key, "is a key of kind = \"ship\", not of kind = \"linear\"");
    const toml::node* a = r.get("A");
    if (a == nullptr || !a->is_array()) r.fail("A", "is required: an n x n nested list");
    const int n = static_cast<int>(a->as_array()->size());
    const Mat A = r.matrix("A", n, n, false);
    const toml::node* b = r.get("B");
    if (b == nullptr || !b->is_array() || b->as_array()->empty() || !b->as_array()->get(0)->is_array())
      r.fail("B", "is required: an n x m nested list");
    const Mat B = r.matrix("B", n, static_cast<int>(b->as_array()->get(0)->as_array()->size()), false);
    Mat D = Mat::Identity(n, n);
    if (const toml::node* d = r.get("D")) {
      if (!d->is_array() || d->as_array()->empty() || !d->as_array()->get(0)->is_array())
        r.fail("D", "expected an n x nw nested list");
      D = r.matrix("D", n, static_cast<int>(d->as_array()->get(0)->as_array()->size()), false);
    }
    model = std::make_shared<LinearModel>(A, B, D);
  } else {
    r.fail("kind", "unknown model kind \"" + kind + "\": use \"ship\" or \"linear\"");
  }
  return model;
}

std::string file_stem(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  const std::size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

}  // namespace

Scenario parse_scenario_toml(const std::string& text, const std::string& source) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(str_cat(source, ":", e.source().begin.line, ":", e.source().begin.column,
                             ": invalid TOML: ", e.description()));
  }
  TableReader top(root, "top level", source,
                  {"name", "description", "model", "horizon", "desired", "controller",
                   "disturbance", "initial", "measurement", "solver", "output"});
  Scenario s;
  s.name = top.string_or("name", file_stem(source));
  s.description = top.string_or("description", "");
  for (const char* name : {"model", "horizon", "desired", "controller", "disturbance", "initial",
                           "measurement", "solver", "output"})
    top.get(name);

  s.model = parse_model(*section(root, "model", source, true), source);
  const int n = s.model->n(), m = s.model->m(), nw = s.model->nw();

  {
    TableReader r(*section(root, "horizon", source, true), "[horizon]", source, {"t0", "tf"});
    s.t0 = r.number_or("t0", 0.0);
    s.tf = r.number("tf");
  }
  {
    std::vector<std::string> known{"q0"};
    for (int i = 1; i <= m; ++i) known.push_back(str_cat("u", i));
    TableReader r(*section(root, "desired", source, true), "[desired]", source, known);
    s.desired_q0 = r.vector("q0", n);
    std::vector<Signal> inputs;
    for (int i = 1; i <= m; ++i) inputs.push_back(r.signal(str_cat("u", i)));
    s.desired_u = VectorSignal(std::move(inputs));
  }
  {
    TableReader r(*section(root, "controller", source, true), "[controller]", source,
                  {"gamma", "Q", "Qf", "kappa", "law", "cascade"});
    s.gamma = r.number("gamma");
    s.law = r.string_or("law", s.law);
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
    if (r.has("N")) {
      const toml::node* node = table->get("N");
      const int p = node->is_array() ? static_cast<int>(node->as_array()->size()) : -1;
      if (p >= 0) ms.N = r.matrix("N", p, p, false);
      else ms.N = Mat::Constant(1, 1, r.number("N"));  // scalar: expanded to N I by resolved()
    }
    if (r.has("Q0")) ms.Q0 = r.matrix("Q0", n, n, true);
    ms.eta = r.number_or("eta", ms.eta);
    ms.filter_A = r.string_or("filter_A", ms.filter_A);
    ms.on_coupling_violation = r.string_or("on_coupling_violation", ms.on_coupling_violation);
    s.measurement = ms;
  }
  if (const toml::table* table = section(root, "solver", source, false)) {
    TableReader r(*table, "[solver]", source, {"method", "rtol", "atol", "max_steps"});
    const std::string method = r.string_or("method", "bdf");
    try {
      s.solver.method = method_from_string(method);
    } catch (const InputError& e) {
      r.fail("method", e.what());
    }
    s.solver.rtol = r.number_or("rtol", s.solver.rtol);
    s.solver.atol = r.number_or("atol", s.solver.atol);
    s.solver.max_steps = static_cast<long>(r.integer_or("max_steps", s.solver.max_steps));
  }
  if (const toml::table* table = section(root, "output", source, false)) {
    TableReader r(*table, "[output]", source, {"dt"});
    s.output_dt = r.number_or("dt", s.output_dt);
  }
  return s;
}

Scenario load_scenario_toml(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(str_cat("cannot read scenario file '", path, "'"));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_scenario_toml(buffer.str(), path);
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

std::string results_json(const RunResult& r, int indent) {
  const Metrics& mt = r.metrics;
  nlohmann::json j;
  j["scenario"] = r.scenario_name;
  j["controller"] = r.controller;
  j["gamma"] = number(r.gamma);
  j["Z0"] = r.solution ? matrix_json(r.Z0) : nlohmann::json(nullptr);
  j["Z_min_eig"] = number(r.Z_min_eig);
  j["Z_max_eig"] = number(r.Z_max_eig);
  j["gamma_star"] = r.gamma_star ? number(*r.gamma_star) : nlohmann::json(nullptr);
  j["coupling_violation_t"] = number(r.simulation.coupling_violation_t);
  j["metrics"] = {
      {"rms_position_error_last_half", number(mt.rms_position_error_last_half)},
      {"max_position_error", number(mt.max_position_error)},
      {"final_position_error", number(mt.final_position_error)},
      {"control_l2", number(mt.control_l2)},
      {"control_error_l2", number(mt.control_error_l2)},
      {"disturbance_l2", number(mt.disturbance_l2)},
      {"l2_gain", number(mt.l2_gain)},
      {"max_rho_sigma_z", number(mt.max_rho_sigma_z)},
      {"rms_estimation_error_last_half", number(mt.rms_estimation_error_last_half)},
  };
  j["timing_s"] = {{"design", r.timing.design},
                   {"simulate", r.timing.simulate},
                   {"analysis", r.timing.analysis},
                   {"total", r.timing.total}};
  const SolveStats grde = r.solution ? r.solution->stats() : SolveStats{};
  j["solver"] = {{"grde_steps", grde.steps},
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
  const bool estimated = s.q_hat.rows() == s.t.size() && s.t.size() > 0;
  if (estimated) {
    for (const std::string& name : names) os << "," << name << "_e_hat";
    for (Eigen::Index i = 1; i <= s.y.cols(); ++i) os << ",y" << i;
    os << ",sigma_min_eig,sigma_max_eig,rho_sigma_z";
  }
  os << "\n";
  for (Eigen::Index k = 0; k < s.t.size(); ++k) {
    os << s.t[k];
    for (const RowMat* M : {&s.q, &s.q_d, &s.u, &s.u_d, &s.w})
      for (Eigen::Index i = 0; i < M->cols(); ++i) os << "," << (*M)(k, i);
    if (estimated) {
      for (Eigen::Index i = 0; i < s.q_hat.cols(); ++i) os << "," << s.q_hat(k, i);
      for (Eigen::Index i = 0; i < s.y.cols(); ++i) os << "," << s.y(k, i);
      os << "," << s.sigma_min_eig[k] << "," << s.sigma_max_eig[k] << "," << s.rho_sigma_z[k];
    }
    os << "\n";
  }
  return os.str();
}

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw InputError(str_cat("cannot write '", path, "'"));
  out << text;
  if (!out) throw InputError(str_cat("error writing '", path, "'"));
}

}  // namespace hinf
