#include "hinf/io/scenario_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <optional>
#include <vector>
#include <string>

#include "hinf/core/errors.hpp"
#include "hinf/io/files.hpp"
#include "io/model_sections.hpp"
#include "io/toml_table.hpp"

namespace hinf {

using detail::section;
using detail::TableReader;
using detail::type_name;

namespace {

const std::vector<std::string> kTopLevelKeys{"name",       "description", "model",   "plant",   "horizon",
                                             "desired",    "controller",  "disturbance", "initial", "measurement",
                                             "sampling",   "receding_horizon", "path_change", "solver", "output"};

// [plant]: a model section with the keys of [model]. Its kind defaults to [model]'s; with the
// same kind, a key not given is [model]'s (for kind = "casadi", each name of [plant.parameters]
// not given is [model.parameters]'), so only what differs need be written; with another kind,
// a key not given is that kind's default. The table the plant is read from.
toml::table plant_table(const toml::table& plant, const toml::table& model) {
  const toml::node* kind = plant.get("kind");
  const toml::node* model_kind = model.get("kind");
  const bool same_kind = kind == nullptr || (kind->is_string() && model_kind != nullptr && model_kind->is_string() &&
                                             kind->as_string()->get() == model_kind->as_string()->get());
  if (!same_kind) return plant;
  toml::table merged = model;
  for (auto&& [key, value] : plant) {
    toml::table* base_parameters = merged.get_as<toml::table>("parameters");
    if (key.str() == "parameters" && value.is_table() && base_parameters != nullptr) {
      for (auto&& [name, number] : *value.as_table()) base_parameters->insert_or_assign(name, number);
    } else {
      merged.insert_or_assign(key, value);
    }
  }
  return merged;
}

// The keys of a table that match a prefix and a channel number (u1, u2, ...): the channels a
// section gives when the model, and so the number of channels, is not known yet.
std::vector<std::string> numbered_keys(const toml::table& table, const std::string& prefix) {
  std::vector<std::string> keys;
  for (auto&& [k, v] : table) {
    const std::string key(k.str());
    if (key.size() > prefix.size() && key.compare(0, prefix.size(), prefix) == 0 && key[prefix.size()] != '0' &&
        key.find_first_not_of("0123456789", prefix.size()) == std::string::npos)
      keys.push_back(key);
  }
  return keys;
}

std::string file_stem(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  const std::size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

// Every section but [model] and [plant] into s, with the sizes of s.model, or (s.model null) with
// the sizes a model sets unchecked: the pass that runs before a model that is a program is loaded.
void read_sections(const toml::table& root, const std::string& source, Scenario& s) {
  const bool sized = s.model != nullptr;
  const int n = sized ? s.model->n() : -1, m = sized ? s.model->m() : -1, nw = sized ? s.model->nw() : -1;
  {
    TableReader r(*section(root, "horizon", source, true), "[horizon]", source, {"t0", "tf"});
    s.t0 = r.number_or("t0", 0.0);
    s.tf = r.number("tf");
  }
  if (s.plant && sized) {
    try {
      check_plant(*s.model, *s.plant, s.t0);
    } catch (const InputError& e) {
      throw InputError(str_cat(source, ": ", e.what()));
    }
  }
  {
    const toml::table& desired = *section(root, "desired", source, true);
    std::vector<std::string> known{"q0", "states", "max_defect"};
    if (sized) {
      for (int i = 1; i <= m; ++i) known.push_back(str_cat("u", i));
    } else {
      for (const std::string& key : numbered_keys(desired, "u")) known.push_back(key);
    }
    // Planning (docs/planning.md) is the Python package's: it replaces these keys by the planned
    // inputs before the scenario reaches this reader.
    for (const char* key : {"waypoints", "path", "plan"})
      if (desired.contains(key))
        throw InputError(str_cat(source, ": [desired] ", key, ": a desired trajectory planned from waypoints or a "
                                 "path needs the planner of the Python package (docs/planning.md): run this file "
                                 "with hinf-cpp run, or write the planned scenario with hinf-cpp plan FILE -o "
                                 "PLANNED.toml and run that"));
    TableReader r(desired, "[desired]", source, known);
    if (const toml::node* node = r.get("states")) {
      // states = { t = [...], q = [[...], ...] }: the desired trajectory at nodes (trajectory.hpp).
      const toml::table* table = node->as_table();
      if (table == nullptr) r.fail("states", "expected a table { t = [...], q = [[...], ...] }, got " + type_name(*node));
      TableReader states(*table, "[desired] states", source, {"t", "q"});
      DesiredStates ds;
      const toml::node* t = states.get("t");
      if (t == nullptr) states.fail("t", "is required");
      const Vec times = states.as_vector(*t, "t", -1);
      ds.t.assign(times.data(), times.data() + times.size());
      ds.q = states.matrix("q", static_cast<int>(ds.t.size()), n, false);
      ds.max_defect = r.number_or("max_defect", ds.max_defect);
      s.desired_states = std::move(ds);
    } else if (r.has("max_defect")) {
      r.fail("max_defect", "applies to [desired] states only");
    }
    s.desired_q0 = s.desired_states && !r.has("q0") ? Vec(s.desired_states->q.row(0).transpose()) : r.vector("q0", n);
    std::vector<Signal> inputs;
    for (std::size_t i = 3; i < known.size(); ++i) inputs.push_back(r.signal(known[i]));
    if (sized) s.desired_u = VectorSignal(std::move(inputs));
  }
  {
    TableReader r(*section(root, "controller", source, true), "[controller]", source,
                  {"gamma", "Q", "Qf", "kappa", "law", "cascade", "backstepping"});
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
    if (const toml::node* node = r.get("backstepping")) {
      const toml::table* table = node->as_table();
      if (table == nullptr)
        r.fail("backstepping", "expected a table { k = ..., k1 = ..., k2 = ..., k3 = ... }, got " + type_name(*node));
      TableReader g(*table, "[controller]", source, {"k", "k1", "k2", "k3"}, "backstepping.");
      s.backstepping.k = g.number_or("k", s.backstepping.k);
      s.backstepping.k1 = g.number_or("k1", s.backstepping.k1);
      s.backstepping.k2 = g.number_or("k2", s.backstepping.k2);
      s.backstepping.k3 = g.number_or("k3", s.backstepping.k3);
    }
    if (r.has("Q")) s.Q = r.matrix("Q", n, n, true);
    if (r.has("Qf")) s.Qf = r.matrix("Qf", n, n, true);
    if (r.has("kappa")) s.kappa = r.signal("kappa");
  }
  {
    std::vector<Signal> channels(static_cast<std::size_t>(std::max(nw, 0)));
    if (const toml::table* table = section(root, "disturbance", source, false)) {
      std::vector<std::string> known = sized ? std::vector<std::string>{} : numbered_keys(*table, "w");
      for (int i = 1; i <= nw; ++i) known.push_back(str_cat("w", i));
      known.push_back("worst_case");
      TableReader r(*table, "[disturbance]", source, known);
      if (!sized) {
        for (const std::string& key : known)
          if (key != "worst_case") r.signal(key);
      }
      // The noise channels carry the measurement noise of [measurement]: a signal there would
      // count in the disturbance's energy without moving the vehicle, and output feedback
      // would overwrite it with the noise.
      for (int channel : sized ? s.model->noise_channels() : std::vector<int>{}) {
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
  if (const toml::table* table = section(root, "sampling", source, false)) {
    TableReader r(*table, "[sampling]", source,
                  {"period", "design", "delay", "compensate_delay", "u_min", "u_max", "rate_max", "max_age",
                   "measurement_period", "measurement_update"});
    SamplingSpec sp;
    sp.period = r.number("period");
    sp.design = r.enum_or("design", sp.design);
    sp.delay = r.number_or("delay", sp.delay);
    sp.compensate_delay = r.boolean_or("compensate_delay", sp.compensate_delay);
    // Limits per input; inf (TOML's inf, -inf) leaves a channel free.
    if (r.has("u_min")) sp.limits.u_min = r.vector("u_min", m, true);
    if (r.has("u_max")) sp.limits.u_max = r.vector("u_max", m, true);
    if (r.has("rate_max")) sp.limits.rate_max = r.vector("rate_max", m, true);
    if (const toml::node* node = r.get("max_age")) sp.max_age = r.as_number(*node, "max_age", true);
    sp.measurement_period = r.number_or("measurement_period", sp.measurement_period);
    sp.measurement_update = r.enum_or("measurement_update", sp.measurement_update);
    s.sampling = sp;
  }
  if (const toml::table* table = section(root, "receding_horizon", source, false)) {
    TableReader r(*table, "[receding_horizon]", source, {"window", "update", "terminal"});
    RecedingHorizonOptions rh;
    rh.window = r.number("window");
    rh.update = r.number_or("update", rh.update);
    rh.terminal = r.enum_or("terminal", rh.terminal);
    s.receding_horizon = rh;
  }
  if (const toml::table* table = section(root, "path_change", source, false)) {
    std::vector<std::string> known{"t"};
    if (sized) {
      for (int i = 1; i <= m; ++i) known.push_back(str_cat("u", i));
    } else {
      for (const std::string& key : numbered_keys(*table, "u")) known.push_back(key);
    }
    for (const char* key : {"waypoints", "path", "plan"})
      if (table->contains(key))
        throw InputError(str_cat(source, ": [path_change] ", key, ": a new path planned from waypoints or a path "
                                 "needs the planner of the Python package (docs/planning.md): run this file with "
                                 "hinf-cpp run, or write the planned scenario with hinf-cpp plan FILE -o PLANNED.toml "
                                 "and run that"));
    TableReader r(*table, "[path_change]", source, known);
    PathChange change;
    change.t = r.number("t");
    std::vector<Signal> inputs;
    for (std::size_t i = 1; i < known.size(); ++i) inputs.push_back(r.signal(known[i]));
    if (sized) change.u_d = VectorSignal(std::move(inputs));
    s.path_change = std::move(change);
  }
  if (const toml::table* table = section(root, "solver", source, false)) {
    TableReader r(*table, "[solver]", source, {"method", "newton_systems", "rtol", "atol", "max_steps", "divergence_factor",
                                                        "lost_track"});
    s.solver.method = r.enum_or("method", s.solver.method);
    s.solver.newton_systems = r.enum_or("newton_systems", s.solver.newton_systems);
    s.solver.rtol = r.number_or("rtol", s.solver.rtol);
    s.solver.atol = r.number_or("atol", s.solver.atol);
    s.solver.max_steps = static_cast<long>(r.integer_or("max_steps", s.solver.max_steps));
    s.divergence_factor = r.number_or("divergence_factor", s.divergence_factor);
    s.lost_track = r.number_or("lost_track", s.lost_track);
    require(s.lost_track > 0.0, source, ": [solver] lost_track must be > 0 m (inf: never), got ", s.lost_track);
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
}

// Every section read and every setting checked without a model.
void check_unsized(const toml::table& root, const std::string& source) {
  Scenario unsized;
  read_sections(root, source, unsized);
  try {
    unsized.validate_settings();
  } catch (const InputError& e) {
    throw InputError(str_cat(source, ": ", e.what()));
  }
}

}  // namespace

Scenario parse_scenario_toml(const std::string& text, const std::string& source, bool allow_code) {
  const toml::table root = detail::parse_toml(text, source);
  TableReader top(root, "top level", source, kTopLevelKeys);
  Scenario s;
  s.name = top.string_or("name", file_stem(source));
  s.description = top.string_or("description", "");
  const toml::table& model = *section(root, "model", source, true);
  const toml::table* plant_given = section(root, "plant", source, false);
  const std::optional<toml::table> plant =
      plant_given == nullptr ? std::nullopt : std::optional<toml::table>(plant_table(*plant_given, model));
  // A model that is a program runs only after everything else in the file has been checked.
  if (detail::section_runs_code(model) || (plant && detail::section_runs_code(*plant))) {
    detail::check_model_section(model, source, "[model]", allow_code);
    if (plant) detail::check_model_section(*plant, source, "[plant]", allow_code);
    check_unsized(root, source);
  }
  s.model = detail::read_model_section(model, source, "[model]", allow_code);
  if (plant) s.plant = detail::read_model_section(*plant, source, "[plant]", allow_code);
  read_sections(root, source, s);
  return s;
}

void check_scenario_toml(const std::string& text, const std::string& source) {
  const toml::table root = detail::parse_toml(text, source);
  TableReader top(root, "top level", source, kTopLevelKeys);
  top.string_or("name", "");
  top.string_or("description", "");
  const toml::table& model = *section(root, "model", source, true);
  detail::check_model_section(model, source, "[model]", true);
  if (const toml::table* plant = section(root, "plant", source, false))
    detail::check_model_section(plant_table(*plant, model), source, "[plant]", true);
  check_unsized(root, source);
}

bool needs_planning_toml(const std::string& text, const std::string& source) {
  const toml::table root = detail::parse_toml(text, source);
  for (const char* name : {"desired", "path_change"}) {
    const toml::table* table = root[name].as_table();
    if (table == nullptr) continue;
    for (const char* key : {"waypoints", "path", "plan"})
      if (table->contains(key)) return true;
  }
  return false;
}

ModelPtr parse_model_toml(const std::string& text, const std::string& source, bool allow_code) {
  const toml::table root = detail::parse_toml(text, source);
  return detail::read_model_section(*section(root, "model", source, true), source, "[model]", allow_code);
}

Signal parse_signal_toml(const std::string& text, const std::string& key, const std::string& source) {
  const toml::table root = detail::parse_toml(text, source);
  TableReader r(root, "signal", source, {key});
  return r.signal(key);
}

Scenario load_scenario_toml(const std::string& path, bool allow_code) {
  return parse_scenario_toml(read_text_file(path, "scenario file"), path, allow_code);
}

bool code_trusted_by_environment() {
  const char* value = std::getenv("HINF_TRUST_CODE");
  const std::string text = value == nullptr ? "" : value;
  if (text.empty() || text == "0") return false;
  if (text == "1") return true;
  throw InputError(str_cat("HINF_TRUST_CODE = '", text, "': set it to 1 (files may run code) or 0 (they may not)"));
}

}  // namespace hinf
