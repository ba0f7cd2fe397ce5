#include "hinf/io/scenario_file.hpp"

#include <cstdint>
#include <limits>
#include <string>

#include "hinf/core/errors.hpp"
#include "io/model_sections.hpp"
#include "io/toml_table.hpp"

namespace hinf {

using detail::insert_signal;
using detail::matrix_toml;
using detail::vector_toml;

namespace {

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

}  // namespace

std::string scenario_toml(const Scenario& s) {
  require(s.model != nullptr, "the scenario has no model");
  const Model& model = *s.model;
  toml::table root;
  root.insert("name", s.name);
  if (!s.description.empty()) root.insert("description", s.description);
  root.insert("model", detail::model_section(model));
  if (s.plant) root.insert("plant", detail::model_section(*s.plant));
  root.insert("horizon", toml::table{{"t0", s.t0}, {"tf", s.tf}});
  toml::table desired{{"q0", vector_toml(s.desired_q0)}};
  if (s.desired_states) {
    toml::array t;
    for (double value : s.desired_states->t) t.push_back(value);
    desired.insert("states", toml::table{{"t", std::move(t)}, {"q", matrix_toml(s.desired_states->q)}});
    desired.insert("max_defect", s.desired_states->max_defect);
  }
  insert_vector_signal(desired, "u", s.desired_u, "[desired] u_d", /*all_channels=*/true);
  root.insert("desired", std::move(desired));
  toml::table controller{{"gamma", s.gamma}, {"law", to_string(s.law)}};
  if (s.Q.size() > 0) controller.insert("Q", matrix_toml(s.Q));
  if (s.Qf.size() > 0) controller.insert("Qf", matrix_toml(s.Qf));
  insert_signal(controller, "kappa", s.kappa);
  controller.insert("cascade", toml::table{{"k", s.cascade.k}, {"k1", s.cascade.k1}, {"k2", s.cascade.k2}});
  controller.insert("backstepping", toml::table{{"k", s.backstepping.k},
                                                {"k1", s.backstepping.k1},
                                                {"k2", s.backstepping.k2},
                                                {"k3", s.backstepping.k3}});
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
  if (s.sampling) {
    const SamplingSpec& sp = *s.sampling;
    toml::table sampling{{"period", sp.period},
                         {"design", to_string(sp.design)},
                         {"delay", sp.delay},
                         {"compensate_delay", sp.compensate_delay},
                         {"max_age", sp.max_age},
                         {"measurement_period", sp.measurement_period},
                         {"measurement_update", to_string(sp.measurement_update)}};
    if (sp.limits.u_min.size() > 0) sampling.insert("u_min", vector_toml(sp.limits.u_min));
    if (sp.limits.u_max.size() > 0) sampling.insert("u_max", vector_toml(sp.limits.u_max));
    if (sp.limits.rate_max.size() > 0) sampling.insert("rate_max", vector_toml(sp.limits.rate_max));
    root.insert("sampling", std::move(sampling));
  }
  if (s.path_change) {
    toml::table change{{"t", s.path_change->t}};
    insert_vector_signal(change, "u", s.path_change->u_d, "[path_change] u_d", /*all_channels=*/true);
    root.insert("path_change", std::move(change));
  }
  if (s.receding_horizon)
    root.insert("receding_horizon",
                toml::table{{"window", s.receding_horizon->window},
                            {"update", s.receding_horizon->update},
                            {"terminal", to_string(s.receding_horizon->terminal)}});
  root.insert("solver", toml::table{{"method", to_string(s.solver.method)},
                                    {"newton_systems", to_string(s.solver.newton_systems)},
                                    {"rtol", s.solver.rtol},
                                    {"atol", s.solver.atol},
                                    {"max_steps", static_cast<std::int64_t>(s.solver.max_steps)},
                                    {"divergence_factor", s.divergence_factor},
                                    {"lost_track", s.lost_track}});
  root.insert("output", toml::table{{"dt", s.output_dt}});
  return detail::toml_text(root);
}

}  // namespace hinf
