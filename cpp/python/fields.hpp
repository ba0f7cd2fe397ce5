// The structs of the C++ API as Python classes, field by field (private to the Python module):
// Fields<T>::list names the data members of a struct once, in declaration order, and the
// properties of its Python class, the keyword constructor (defaults from T{}), __repr__, __eq__
// and pickling are all made from that list (bind_options, bind_result). Also the pickling
// helpers shared by several files of the bindings.
#pragma once

#include <cstddef>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "casters.hpp"
#include "hinf/control/analysis.hpp"
#include "hinf/control/backstepping.hpp"
#include "hinf/control/cascade.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/online_controller.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/control/online_receding_horizon.hpp"
#include "hinf/control/receding_horizon.hpp"
#include "hinf/control/sampled_loop.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/models/vehicles.hpp"
#include "hinf/numerics/piecewise_polynomial.hpp"
#include "hinf/numerics/signal.hpp"
#include "hinf/numerics/solver_options.hpp"
#include "hinf/scenario/scenario.hpp"
#include "hinf/scenario/study.hpp"

namespace hinf::python {

// Fields<T>::list names the data members of a C++ struct once, in declaration order. The
// properties of its Python class, the keyword constructor (defaults from T{}), __repr__,
// __eq__ and pickling are all made from that list; the documentation of each field is its
// contract, "<T>::<name>", or for a field declared on the line of another (double m, M;), the
// other's ("documented_by").
template <class T, class V>
struct Field {
  using Value = V;
  const char* name;
  V T::*member;
  const char* documented_by = nullptr;
};
template <class T, class V>
constexpr Field<T, V> field(const char* name, V T::*member, const char* documented_by = nullptr) {
  return {name, member, documented_by};
}

template <class T>
struct Fields {};  // specialized for every struct bound field by field

template <>
struct Fields<Harmonic> {
  static constexpr auto list =
      std::make_tuple(field("amplitude", &Harmonic::amplitude), field("omega", &Harmonic::omega),
                      field("phase", &Harmonic::phase), field("cosine", &Harmonic::cosine));
};
template <>
struct Fields<ShipParameters> {
  static constexpr auto list = std::make_tuple(
      field("m_u", &ShipParameters::m_u), field("m_v", &ShipParameters::m_v), field("m_r", &ShipParameters::m_r),
      field("d_u", &ShipParameters::d_u), field("d_v", &ShipParameters::d_v), field("d_r", &ShipParameters::d_r));
};
// The built-in vehicles' parameters (vehicles.hpp).
template <>
struct Fields<FossenVesselParameters> {
  static constexpr auto list =
      std::make_tuple(field("M", &FossenVesselParameters::M), field("D", &FossenVesselParameters::D));
};
template <>
struct Fields<HovercraftParameters> {
  static constexpr auto list =
      std::make_tuple(field("d", &HovercraftParameters::d), field("d_r", &HovercraftParameters::d_r));
};
template <>
struct Fields<PlanarVtolParameters> {
  static constexpr auto list =
      std::make_tuple(field("g", &PlanarVtolParameters::g), field("epsilon", &PlanarVtolParameters::epsilon));
};
template <>
struct Fields<AuvParameters> {
  static constexpr auto list = std::make_tuple(
      field("m11", &AuvParameters::m11), field("m22", &AuvParameters::m22), field("m33", &AuvParameters::m33),
      field("X_u", &AuvParameters::X_u), field("X_uu", &AuvParameters::X_uu), field("Y_v", &AuvParameters::Y_v),
      field("Y_vv", &AuvParameters::Y_vv), field("N_r", &AuvParameters::N_r), field("N_rr", &AuvParameters::N_rr));
};
template <>
struct Fields<BacksteppingGains> {
  static constexpr auto list = std::make_tuple(field("k", &BacksteppingGains::k), field("k1", &BacksteppingGains::k1),
                                               field("k2", &BacksteppingGains::k2), field("k3", &BacksteppingGains::k3));
};
template <>
struct Fields<CascadeGains> {
  static constexpr auto list =
      std::make_tuple(field("k", &CascadeGains::k), field("k1", &CascadeGains::k1), field("k2", &CascadeGains::k2));
};
template <>
struct Fields<ActuatorLimits> {
  static constexpr auto list = std::make_tuple(field("u_min", &ActuatorLimits::u_min),
                                               field("u_max", &ActuatorLimits::u_max),
                                               field("rate_max", &ActuatorLimits::rate_max));
};
template <>
struct Fields<OnlineFilter> {
  static constexpr auto list = std::make_tuple(field("N", &OnlineFilter::N), field("Sigma0", &OnlineFilter::Sigma0),
                                               field("Q", &OnlineFilter::Q), field("hold", &OnlineFilter::hold),
                                               field("update", &OnlineFilter::update));
};
template <>
struct Fields<OnlineOptions> {
  static constexpr auto list = std::make_tuple(
      field("filter", &OnlineOptions::filter), field("limits", &OnlineOptions::limits),
      field("max_age", &OnlineOptions::max_age),
      field("compensate_delay", &OnlineOptions::compensate_delay), field("history", &OnlineOptions::history));
};
template <>
struct Fields<SampledLoopOptions> {
  static constexpr auto list = std::make_tuple(field("delay", &SampledLoopOptions::delay),
                                               field("simulation", &SampledLoopOptions::simulation),
                                               field("measurement_every", &SampledLoopOptions::measurement_every),
                                               field("sigma", &SampledLoopOptions::sigma),
                                               field("noise", &SampledLoopOptions::noise));
};
template <>
struct Fields<StepReport> {
  static constexpr auto list =
      std::make_tuple(field("status", &StepReport::status), field("measurement", &StepReport::measurement),
                      field("saturated", &StepReport::saturated), field("rate_limited", &StepReport::rate_limited),
                      field("rho_sigma_z", &StepReport::rho_sigma_z),
                      field("coupling_violated", &StepReport::coupling_violated),
                      field("window_stale", &StepReport::window_stale));
};
template <>
struct Fields<PathChange> {
  static constexpr auto list = std::make_tuple(field("t", &PathChange::t), field("u_d", &PathChange::u_d));
};
template <>
struct Fields<DesiredStates> {
  static constexpr auto list = std::make_tuple(field("t", &DesiredStates::t), field("q", &DesiredStates::q),
                                               field("max_defect", &DesiredStates::max_defect));
};
template <>
struct Fields<RecedingHorizonOptions> {
  static constexpr auto list = std::make_tuple(field("window", &RecedingHorizonOptions::window),
                                               field("update", &RecedingHorizonOptions::update),
                                               field("terminal", &RecedingHorizonOptions::terminal));
};
template <>
struct Fields<HorizonWindow> {
  static constexpr auto list = std::make_tuple(
      field("index", &HorizonWindow::index), field("t_start", &HorizonWindow::t_start),
      field("t_use_end", &HorizonWindow::t_use_end), field("trajectory", &HorizonWindow::trajectory),
      field("design", &HorizonWindow::design));
};
template <>
struct Fields<RecedingHorizonReport> {
  static constexpr auto list = std::make_tuple(
      field("options", &RecedingHorizonReport::options), field("windows", &RecedingHorizonReport::windows),
      field("largest_window_bytes", &RecedingHorizonReport::largest_window_bytes),
      field("peak_bytes", &RecedingHorizonReport::peak_bytes), field("grde", &RecedingHorizonReport::grde),
      field("divergence_bound", &RecedingHorizonReport::divergence_bound));
};
template <>
struct Fields<RecedingOnlineStatus> {
  static constexpr auto list = std::make_tuple(
      field("window_in_use", &RecedingOnlineStatus::window_in_use),
      field("windows_solved", &RecedingOnlineStatus::windows_solved),
      field("windows_failed", &RecedingOnlineStatus::windows_failed),
      field("failed_t_start", &RecedingOnlineStatus::failed_t_start),
      field("last_failure", &RecedingOnlineStatus::last_failure),
      field("stale_steps", &RecedingOnlineStatus::stale_steps));
};
template <>
struct Fields<WindowGammaStar> {
  static constexpr auto list = std::make_tuple(
      field("gamma_star", &WindowGammaStar::gamma_star), field("window", &WindowGammaStar::window),
      field("t_start", &WindowGammaStar::t_start), field("windows", &WindowGammaStar::windows),
      field("converged", &WindowGammaStar::converged), field("result", &WindowGammaStar::result));
};
template <>
struct Fields<OnlineCounts> {
  static constexpr auto list = std::make_tuple(
      field("steps", &OnlineCounts::steps), field("used", &OnlineCounts::used),
      field("predicted", &OnlineCounts::predicted), field("refused", &OnlineCounts::refused),
      field("past_horizon", &OnlineCounts::past_horizon), field("lost", &OnlineCounts::lost), field("saturated", &OnlineCounts::saturated),
      field("rate_limited", &OnlineCounts::rate_limited), field("largest_command", &OnlineCounts::largest_command),
      field("coupling_violated", &OnlineCounts::coupling_violated),
      field("coupling_violation_t", &OnlineCounts::coupling_violation_t), field("largest_rho", &OnlineCounts::largest_rho));
};
template <>
struct Fields<SolverOptions> {
  static constexpr auto list = std::make_tuple(
      field("method", &SolverOptions::method), field("rtol", &SolverOptions::rtol), field("atol", &SolverOptions::atol),
      field("max_steps", &SolverOptions::max_steps), field("escape_norm", &SolverOptions::escape_norm),
      field("newton_systems", &SolverOptions::newton_systems));
};
template <>
struct Fields<SimulationOptions> {
  static constexpr auto list = std::make_tuple(field("output_dt", &SimulationOptions::output_dt),
                                               field("divergence_factor", &SimulationOptions::divergence_factor),
                                               field("solver", &SimulationOptions::solver));
};
template <>
struct Fields<TrajectoryOptions> {
  static constexpr auto list =
      std::make_tuple(field("rtol", &TrajectoryOptions::rtol), field("atol", &TrajectoryOptions::atol),
                      field("max_steps", &TrajectoryOptions::max_steps));
};
template <>
struct Fields<GammaStarOptions> {
  static constexpr auto list = std::make_tuple(
      field("lower", &GammaStarOptions::lower), field("upper", &GammaStarOptions::upper),
      field("rtol", &GammaStarOptions::rtol), field("max_evaluations", &GammaStarOptions::max_evaluations),
      field("threads", &GammaStarOptions::threads), field("solver", &GammaStarOptions::solver));
};
template <>
struct Fields<OutputFeedbackProblem> {
  static constexpr auto list = std::make_tuple(
      field("design", &OutputFeedbackProblem::design), field("sigma", &OutputFeedbackProblem::sigma),
      field("sample_period", &OutputFeedbackProblem::sample_period), field("noise", &OutputFeedbackProblem::noise),
      field("N", &OutputFeedbackProblem::N), field("Sigma0", &OutputFeedbackProblem::Sigma0),
      field("Q", &OutputFeedbackProblem::Q));
};
template <>
struct Fields<OutputFeedbackOptions> {
  static constexpr auto list =
      std::make_tuple(field("filter_A", &OutputFeedbackOptions::filter_A),
                      field("on_coupling_violation", &OutputFeedbackOptions::on_coupling_violation),
                      field("sigma_eigenvalues", &OutputFeedbackOptions::sigma_eigenvalues));
};
template <>
struct Fields<MeasurementSpec> {
  static constexpr auto list = std::make_tuple(
      field("sigma", &MeasurementSpec::sigma), field("sample_period", &MeasurementSpec::sample_period),
      field("seed", &MeasurementSpec::seed), field("N", &MeasurementSpec::N), field("Q0", &MeasurementSpec::Q0),
      field("eta", &MeasurementSpec::eta), field("filter_A", &MeasurementSpec::filter_A),
      field("on_coupling_violation", &MeasurementSpec::on_coupling_violation));
};
template <>
struct Fields<SamplingSpec> {
  static constexpr auto list = std::make_tuple(
      field("period", &SamplingSpec::period), field("design", &SamplingSpec::design),
      field("delay", &SamplingSpec::delay), field("compensate_delay", &SamplingSpec::compensate_delay),
      field("limits", &SamplingSpec::limits), field("max_age", &SamplingSpec::max_age),
      field("measurement_period", &SamplingSpec::measurement_period),
      field("measurement_update", &SamplingSpec::measurement_update));
};
template <>
struct Fields<StepStats> {
  static constexpr auto list =
      std::make_tuple(field("steps", &StepStats::steps), field("rejected", &StepStats::rejected),
                      field("rhs_evals", &StepStats::rhs_evals), field("jac_evals", &StepStats::jac_evals));
};
template <>
struct Fields<SolveStats> {
  static constexpr auto list = std::make_tuple(
      field("steps", &SolveStats::steps), field("rejected", &SolveStats::rejected),
      field("rhs_evals", &SolveStats::rhs_evals), field("jac_evals", &SolveStats::jac_evals),
      field("memory_bytes", &SolveStats::memory_bytes), field("method", &SolveStats::method));
};
template <>
struct Fields<Timing> {
  static constexpr auto list = std::make_tuple(field("design", &Timing::design), field("simulate", &Timing::simulate),
                                               field("analysis", &Timing::analysis), field("total", &Timing::total));
};
template <>
struct Fields<GammaTrial> {
  static constexpr auto list =
      std::make_tuple(field("gamma", &GammaTrial::gamma), field("passed", &GammaTrial::passed),
                      field("t_escape", &GammaTrial::t_escape), field("condition", &GammaTrial::condition),
                      field("rhs_evals", &GammaTrial::rhs_evals));
};
template <>
struct Fields<GammaStarResult> {
  static constexpr auto list = std::make_tuple(
      field("gamma_star", &GammaStarResult::gamma_star), field("lower", &GammaStarResult::lower),
      field("upper", &GammaStarResult::upper), field("t_escape_lower", &GammaStarResult::t_escape_lower),
      field("binding", &GammaStarResult::binding), field("converged", &GammaStarResult::converged),
      field("trials", &GammaStarResult::trials), field("rhs_evals", &GammaStarResult::rhs_evals));
};
template <>
struct Fields<Certificates> {
  static constexpr auto list = std::make_tuple(
      field("m", &Certificates::m), field("M", &Certificates::M, "m"), field("kappa_min", &Certificates::kappa_min),
      field("p_min", &Certificates::p_min), field("p_min_t", &Certificates::p_min_t, "p_min"),
      field("remainder_L", &Certificates::remainder_L), field("remainder_method", &Certificates::remainder_method),
      field("remainder_is_bound", &Certificates::remainder_is_bound), field("epsilon", &Certificates::epsilon),
      field("epsilon_t", &Certificates::epsilon_t, "epsilon"),
      field("attraction_radius", &Certificates::attraction_radius),
      field("decay_rate", &Certificates::decay_rate));
};
template <>
struct Fields<EstimatorSeries> {
  static constexpr auto list = std::make_tuple(
      field("q_hat", &EstimatorSeries::q_hat), field("y", &EstimatorSeries::y),
      field("sigma_min_eig", &EstimatorSeries::sigma_min_eig), field("sigma_max_eig", &EstimatorSeries::sigma_max_eig),
      field("rho_sigma_z", &EstimatorSeries::rho_sigma_z),
      field("coupling_violation_t", &EstimatorSeries::coupling_violation_t));
};
template <>
struct Fields<SimulationResult> {
  static constexpr auto list = std::make_tuple(
      field("t", &SimulationResult::t), field("q", &SimulationResult::q), field("q_d", &SimulationResult::q_d),
      field("u", &SimulationResult::u), field("u_d", &SimulationResult::u_d), field("w", &SimulationResult::w),
      field("estimator", &SimulationResult::estimator), field("status", &SimulationResult::status),
      field("status_message", &SimulationResult::status_message),
      field("heading_index", &SimulationResult::heading_index), field("integrator", &SimulationResult::integrator),
      field("stats", &SimulationResult::stats));
};
template <>
struct Fields<RunResult> {
  static constexpr auto list = std::make_tuple(
      field("scenario_name", &RunResult::scenario_name), field("law", &RunResult::law),
      field("output_feedback", &RunResult::output_feedback), field("gamma", &RunResult::gamma),
      field("trajectory", &RunResult::trajectory), field("plant", &RunResult::plant),
      field("solution", &RunResult::solution),
      field("Z0", &RunResult::Z0), field("Z_min_eig", &RunResult::Z_min_eig),
      field("Z_max_eig", &RunResult::Z_max_eig, "Z_min_eig"),
      field("gamma_star", &RunResult::gamma_star), field("simulation", &RunResult::simulation),
      field("sampling", &RunResult::sampling), field("online", &RunResult::online),
      field("receding_horizon", &RunResult::receding_horizon),
      field("metrics", &RunResult::metrics), field("timing", &RunResult::timing));
};
template <>
struct Fields<StudyOptions> {
  static constexpr auto list =
      std::make_tuple(field("threads", &StudyOptions::threads), field("share_designs", &StudyOptions::share_designs));
};
template <>
struct Fields<StudyRun> {
  static constexpr auto list = std::make_tuple(
      field("status", &StudyRun::status), field("reason", &StudyRun::reason), field("metrics", &StudyRun::metrics),
      field("gamma", &StudyRun::gamma), field("law", &StudyRun::law),
      field("output_feedback", &StudyRun::output_feedback), field("design_seconds", &StudyRun::design_seconds),
      field("simulate_seconds", &StudyRun::simulate_seconds), field("design", &StudyRun::design));
};

template <class T, class = void>
struct has_fields : std::false_type {};
template <class T>
struct has_fields<T, std::void_t<decltype(Fields<T>::list)>> : std::true_type {};

template <class T>
constexpr std::size_t field_count = std::tuple_size_v<std::decay_t<decltype(Fields<T>::list)>>;

template <class T, class F>
void for_each_field(F&& f) {
  std::apply([&](const auto&... each) { (f(each), ...); }, Fields<T>::list);
}

template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};
template <class T>
struct is_vector : std::false_type {};
template <class T>
struct is_vector<std::vector<T>> : std::true_type {};
template <class T>
struct is_shared_ptr : std::false_type {};
template <class T>
struct is_shared_ptr<std::shared_ptr<T>> : std::true_type {};

// Equal values: NaN equals NaN (a value compared with its copy or its pickle), arrays of the
// same shape and entries, structs field by field.
template <class V>
bool same(const V& a, const V& b) {
  if constexpr (std::is_floating_point_v<V>) {
    return a == b || (std::isnan(a) && std::isnan(b));
  } else if constexpr (std::is_base_of_v<Eigen::DenseBase<V>, V>) {
    return a.rows() == b.rows() && a.cols() == b.cols() &&
           (a.array() == b.array() || (a.array().isNaN() && b.array().isNaN())).all();
  } else if constexpr (is_optional<V>::value) {
    return a.has_value() == b.has_value() && (!a || same(*a, *b));
  } else if constexpr (is_vector<V>::value) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const auto& x, const auto& y) { return same(x, y); });
  } else if constexpr (std::is_same_v<V, VectorSignal>) {
    return a.same_signals(b);
  } else if constexpr (std::is_same_v<V, Metrics>) {
    for (const MetricDefinition& d : metric_table())
      if (!same(a.*(d.value), b.*(d.value))) return false;
    return true;
  } else if constexpr (has_fields<V>::value) {
    bool equal = true;
    for_each_field<V>([&](const auto& f) { equal = equal && same(a.*(f.member), b.*(f.member)); });
    return equal;
  } else {
    return a == b;
  }
}

// repr of a field's value: an enum by its name (which is also accepted as input).
template <class V>
std::string value_repr(const V& value) {
  if constexpr (std::is_enum_v<V>) return str_cat("'", to_string(value), "'");
  else return py::repr(py::cast(value, py::return_value_policy::copy)).template cast<std::string>();
}

// The contract of a field of T (its comment in the header), or nothing; `type` is T's name.
template <class F>
std::optional<std::string_view> field_contract(const std::string& type, const F& f) {
  return find_contract(str_cat(type, "::", f.documented_by ? f.documented_by : f.name));
}

// The name of V in a docstring's type: float, int, bool, str, a bound class or enum by its
// Python name, X or None, list of X.
template <class V>
std::string python_type_name() {
  if constexpr (std::is_same_v<V, bool>) {
    return "bool";
  } else if constexpr (std::is_floating_point_v<V>) {
    return "float";
  } else if constexpr (std::is_integral_v<V>) {
    return "int";
  } else if constexpr (std::is_same_v<V, std::string>) {
    return "str";
  } else if constexpr (is_optional<V>::value) {
    return python_type_name<typename V::value_type>() + " or None";
  } else if constexpr (is_vector<V>::value) {
    return "list of " + python_type_name<typename V::value_type>();
  } else if constexpr (is_shared_ptr<V>::value) {
    return python_type_name<std::remove_const_t<typename V::element_type>>();
  } else {
    const py::detail::type_info* info = py::detail::get_type_info(typeid(V));
    if (info == nullptr)
      throw std::logic_error(str_cat("a field's type (", typeid(V).name(), ") has no Python name: give it"));
    return py::handle(reinterpret_cast<PyObject*>(info->type)).attr("__name__").cast<std::string>();
  }
}

// The numpydoc section `title` of T's fields: "Parameters" for an option struct (its keyword
// constructor, each with its default), "Attributes" for a result. Each field is
// "name : type" and its contract, indented. `types` gives the type of the fields whose Python
// type says too little, {field name, type}: every array (its shape and unit), since only the
// struct knows them ("array_like, shape (p, p)").
using FieldTypes = std::initializer_list<std::pair<std::string_view, std::string_view>>;
template <class T>
std::string fields_section(const std::string& type, const char* title, FieldTypes types) {
  const T defaults{};
  const bool with_defaults = std::string_view(title) == "Parameters";
  std::string text = str_cat(title, "\n", std::string(std::string_view(title).size(), '-'));
  for_each_field<T>([&](const auto& f) {
    using V = typename std::decay_t<decltype(f)>::Value;
    std::string type_name;
    for (const auto& [name, given] : types)
      if (name == f.name) type_name = std::string(given);
    if (type_name.empty()) {
      if constexpr (std::is_base_of_v<Eigen::EigenBase<V>, V>)
        throw std::logic_error(str_cat(type, ".", f.name, " is an array: give its shape (fields_section)"));
      else
        type_name = python_type_name<V>();
    }
    if (with_defaults) {
      if constexpr (std::is_enum_v<V>) type_name += " or str";  // an enum is also taken by its name
      if constexpr (std::is_arithmetic_v<V> || std::is_enum_v<V> || std::is_same_v<V, std::string>)
        type_name += ", default " + value_repr(defaults.*(f.member));
      else
        type_name += ", optional";
    }
    text += str_cat("\n", f.name, " : ", type_name);
    if (const std::optional<std::string_view> about = field_contract(type, f))
      text += "\n" + indented(*about, 4);
  });
  return text;
}

// The numpydoc section `title` of members of the C++ class `type` bound one by one (not through
// Fields): `items` gives each member's name and Python type, the text is its contract.
inline std::string members_section(const std::string& type, const char* title, FieldTypes items) {
  std::string text = str_cat(title, "\n", std::string(std::string_view(title).size(), '-'));
  for (const auto& [name, type_name] : items)
    text += str_cat("\n", std::string(name), " : ", std::string(type_name), "\n",
                    indented(contract(str_cat(type, "::", std::string(name))), 4));
  return text;
}

// Properties for the fields: read/write for options, read-only for results. Enums are returned
// by value (a Python enum object must not alias the struct's memory); other members as views.
// Each property's docstring is the field's contract. The class's __match_args__ lists the
// field names, for code that goes through all of them.
template <class T, class... Options>
void def_fields(py::class_<T, Options...>& cls, bool writable) {
  const std::string type = py::str(cls.attr("__name__"));
  py::list names;  // __match_args__: the field names, in order (as a dataclass has them)
  for_each_field<T>([&](const auto& f) { names.append(f.name); });
  cls.attr("__match_args__") = py::tuple(names);
  for_each_field<T>([&](const auto& f) {
    using V = typename std::decay_t<decltype(f)>::Value;
    const auto member = f.member;
    const std::string about(field_contract(type, f).value_or(""));
    const py::doc doc(about.empty() ? nullptr : about.c_str());
    if constexpr (std::is_enum_v<V>) {
      const auto get = [member](const T& o) { return o.*member; };
      if (writable) cls.def_property(f.name, get, [member](T& o, V v) { o.*member = v; }, doc);
      else cls.def_property_readonly(f.name, get, doc);
    } else if (writable) {
      cls.def_readwrite(f.name, member, doc);
    } else {
      cls.def_readonly(f.name, member, doc);
    }
  });
}

// Loading the module must not import NumPy (it would cost every `hinf-cpp` command about 80 ms
// before any work; benchmarks/README.md): no default argument may be an array, or print one.
// pybind11 converts each default to a Python object and, without a description, prints its
// repr into the signature when a function is defined.

// A keyword argument defaulting to a struct's T{}, shown as "T()": its repr would print its
// arrays through NumPy.
template <class T>
py::arg_v default_struct_arg(const char* name) {
  static const std::string shown = python_type_name<T>() + "()";  // arg_v keeps the pointer
  return py::arg_v(name, T{}, shown.c_str());
}

// A field of a keyword constructor: an array is taken as an optional array, None (the default,
// shown as "...") keeping T{}'s value.
template <class V>
using FieldArgument = std::conditional_t<std::is_base_of_v<Eigen::EigenBase<V>, V>, std::optional<V>, V>;
template <class V>
void assign_field(V& field, V&& value) {
  field = std::move(value);
}
template <class V>
void assign_field(V& field, std::optional<V>&& value) {
  if (value) field = std::move(*value);
}

// The keyword argument of field I with its default from `defaults`; an array's default shows as
// "..." in the signature, an empty VectorSignal as the expression that makes one, a struct left
// at its own default as "T()".
template <class T, std::size_t I>
py::arg_v field_arg(const T& defaults) {
  const auto& f = std::get<I>(Fields<T>::list);
  using V = typename std::decay_t<decltype(f)>::Value;
  if constexpr (std::is_base_of_v<Eigen::EigenBase<V>, V>) {
    return py::arg_v(f.name, py::none(), "...");
  } else if constexpr (std::is_same_v<V, VectorSignal>) {
    return py::arg_v(f.name, defaults.*(f.member), "VectorSignal([])");
  } else if constexpr (has_fields<V>::value) {
    if (same(defaults.*(f.member), V{})) return default_struct_arg<V>(f.name);
    return py::arg(f.name) = defaults.*(f.member);
  } else {
    return py::arg(f.name) = defaults.*(f.member);
  }
}

// The keyword constructor T(field1=T{}.field1, ...), followed by check(object).
template <class T, class Check, class... Options, std::size_t... I>
void def_field_init(py::class_<T, Options...>& cls, Check check, std::index_sequence<I...>) {
  using List = std::decay_t<decltype(Fields<T>::list)>;
  const T defaults{};
  cls.def(py::init([check](FieldArgument<typename std::tuple_element_t<I, List>::Value>... values) {
            T object;
            (assign_field(object.*(std::get<I>(Fields<T>::list).member), std::move(values)), ...);
            check(object);
            return object;
          }),
          field_arg<T, I>(defaults)...);
}
template <class T, class... Options, class Check>
void def_field_init(py::class_<T, Options...>& cls, Check check) {
  def_field_init(cls, check, std::make_index_sequence<field_count<T>>());
}

// __getstate__ / __setstate__ (by value, field by field), and unless told otherwise __eq__.
template <class T, class... Options>
void def_value_protocol(py::class_<T, Options...>& cls, bool equality = true) {
  const std::string type = py::str(cls.attr("__name__"));
  cls.def(py::pickle(
      [](const T& o) {
        py::list state;
        for_each_field<T>([&](const auto& f) { state.append(py::cast(o.*(f.member), py::return_value_policy::copy)); });
        return py::tuple(state);
      },
      [type](const py::tuple& state) {
        require(state.size() == field_count<T>, "a pickled ", type, " has ", field_count<T>, " fields, got ",
                state.size());
        T o;
        std::size_t i = 0;
        for_each_field<T>([&](const auto& f) {
          using V = typename std::decay_t<decltype(f)>::Value;
          o.*(f.member) = state[i++].template cast<V>();
        });
        return o;
      }));
  if (equality) cls.def("__eq__", [](const T& a, const T& b) { return same(a, b); }, py::is_operator());
}

// __repr__: Type(field=value, ...), text that builds an equal object.
template <class T, class... Options>
void def_field_repr(py::class_<T, Options...>& cls) {
  const std::string type = py::str(cls.attr("__name__"));
  cls.def("__repr__", [type](const T& o) {
    std::string text = type + "(";
    const char* separator = "";
    for_each_field<T>([&](const auto& f) {
      text += str_cat(separator, f.name, "=", value_repr(o.*(f.member)));
      separator = ", ";
    });
    return text + ")";
  });
}

// The docstring of a struct bound field by field: the contracts of `keys`, the section of its
// fields (fields_section), then `sections`.
template <class T>
std::string struct_doc(const char* name, std::initializer_list<std::string_view> keys, const char* title,
                       FieldTypes types, std::string_view sections) {
  if (!sections.empty() && sections.front() == '\n') sections.remove_prefix(1);
  return doc(keys, fields_section<T>(name, title, types) + "\n\n" + std::string(sections));
}

// An option struct: keyword constructor (then check), read/write fields, repr, pickle, ==. Its
// docstring: the contracts of `keys`, its fields as the constructor's Parameters, `sections`.
template <class T, class Check>
py::class_<T> bind_options(py::module_& m, const char* name, std::initializer_list<std::string_view> keys,
                           FieldTypes types, std::string_view sections, Check check) {
  py::class_<T> cls(m, name, struct_doc<T>(name, keys, "Parameters", types, sections).c_str());
  def_field_init(cls, check);
  def_fields(cls, /*writable=*/true);
  def_field_repr(cls);
  def_value_protocol(cls);
  return cls;
}
template <class T, class = void>
struct has_validate : std::false_type {};
template <class T>
struct has_validate<T, std::void_t<decltype(std::declval<const T&>().validate())>> : std::true_type {};

// ... checked by T::validate() where T has one.
template <class T>
py::class_<T> bind_options(py::module_& m, const char* name, std::initializer_list<std::string_view> keys,
                           FieldTypes types, std::string_view sections) {
  return bind_options<T>(m, name, keys, types, sections, [](const T& options) {
    if constexpr (has_validate<T>::value) options.validate();
  });
}

// A result struct: read-only fields, pickle, == (unless equality is false); small ones also a
// repr. Its docstring: the contracts of `keys`, its fields as Attributes, `sections`.
template <class T>
py::class_<T> bind_result(py::module_& m, const char* name, std::initializer_list<std::string_view> keys,
                          FieldTypes types, std::string_view sections, bool repr, bool equality = true) {
  py::class_<T> cls(m, name, struct_doc<T>(name, keys, "Attributes", types, sections).c_str());
  def_fields(cls, /*writable=*/false);
  if (repr) def_field_repr(cls);
  def_value_protocol(cls, equality);
  return cls;
}

// ---- pickling of the classes that are not plain structs ----

[[noreturn]] inline void cannot_pickle(const std::string& what, const std::string& why) {
  throw py::type_error(str_cat("cannot pickle ", what, ": ", why));
}

inline void check_state(const py::tuple& state, std::size_t size, const char* type) {
  require(state.size() == size, "a pickled ", type, " has ", size, " items, got ", state.size());
}

// Every call into a model implemented in Python holds the GIL, so parallel gamma evaluations
// would only contend for it (each handover can wait for Python's switch interval): such
// models get one thread.
inline GammaStarOptions serial_for_python_models(const Model* model, GammaStarOptions options) {
  if (implemented_in_python(model)) options.threads = 1;
  return options;
}

// The pieces of a dense output as arrays, and back (bind_numerics.cpp): PiecewisePolynomial and
// what holds one (Trajectory, the Riccati solutions) pickle through them.
py::tuple dense_state(const PiecewisePolynomial& p);
PiecewisePolynomial dense_from_state(const py::tuple& state);

}  // namespace hinf::python
