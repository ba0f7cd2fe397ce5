#include "hinf/io/results.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hinf/control/metrics.hpp"

namespace hinf {

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
  if (r.sampling) {
    const SamplingSpec& sp = *r.sampling;
    j["sampling"] = {{"period", sp.period},
                     {"design", to_string(sp.design)},
                     {"delay", sp.delay},
                     {"compensate_delay", sp.compensate_delay},
                     {"measurement_period", sp.measurement_every() * sp.period},
                     {"measurement_update", to_string(sp.measurement_update)}};
  }
  if (r.receding_horizon) {
    // What the receding horizon solved and held (receding_horizon.hpp, RecedingHorizonReport).
    const RecedingHorizonReport& rh = *r.receding_horizon;
    j["receding_horizon"] = {{"window", rh.options.window},
                             {"update", rh.options.update},
                             {"windows", rh.windows},
                             {"largest_window_bytes", rh.largest_window_bytes},
                             {"peak_bytes", rh.peak_bytes},
                             {"grde_steps", rh.grde.steps}};
  }
  if (r.online) {
    // What the online controller's steps did (online_controller.hpp, OnlineCounts).
    const OnlineCounts& c = *r.online;
    j["online"] = {{"steps", c.steps},
                   {"measurements_used", c.used},
                   {"predicted", c.predicted},
                   {"refused", c.refused},
                   {"past_horizon", c.past_horizon},
                   {"lost", c.lost},
                   {"saturated", c.saturated},
                   {"rate_limited", c.rate_limited},
                   {"saturated_share", number(c.steps > 0 ? static_cast<double>(c.saturated) / c.steps : NAN)},
                   {"largest_command", number(c.largest_command)},
                   {"coupling_violated", c.coupling_violated},
                   {"largest_rho_over_gamma2", number(r.output_feedback ? c.largest_rho : NAN)}};
    if (r.output_feedback) j["coupling_violation_t"] = number(c.coupling_violation_t);
  }
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

}  // namespace hinf
