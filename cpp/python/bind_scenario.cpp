// The Python bindings of the scenario layer (cpp/include/hinf/scenario): scenarios and their
// runs, and batches of them (run_scenarios). A scenario pickles as its file (bind_io.cpp).
#include "casters.hpp"
#include "fields.hpp"
#include "hinf/scenario/scenario.hpp"
#include "hinf/scenario/study.hpp"

namespace hinf::python {

// The first lines of the examples that run a paper scenario over 10 s. The text that follows
// begins with a newline.
#define HINF_SCENARIO_EXAMPLE(name)                                      \
  ">>> scenario = hc.load_scenario(hc.scenario_path(\"" name "\"))\n" \
  ">>> scenario.tf = 10.0"

void bind_scenario(py::module_& m) {
  // ---- enums ----
  bind_enum<Law>(m, "Law", R"(Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> scenario.law = "lqr"
>>> result = hc.run_scenario(scenario)
>>> result.law, result.gamma
(<Law.lqr: 1>, inf))");
  bind_enum<RunOutcome>(m, "RunOutcome", R"(Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> low = scenario.copy()
>>> low.gamma = 1.2                                          # below gamma*
>>> [run.outcome for run in hc.run_scenarios([scenario, low])]
[<RunOutcome.completed: 0>, <RunOutcome.conjugate_point: 3>])");

  // ---- scenarios ----
  bind_options<MeasurementSpec>(m, "MeasurementSpec", {"MeasurementSpec"},
                                {{"N", "array_like, shape (p, p) or (1, 1)"},
                                 {"Q0", "array_like, shape (n, n) or (1, 1)"}},
                                R"(Notes
-----
p is the number of measured outputs (rows of the model's C); a 1 x 1 N or Q0 is that many times
the identity. The values are checked with the scenario (Scenario.validate()).

Examples
--------
>>> measurement = hc.load_scenario(hc.scenario_path("paper_fig2")).measurement
>>> measurement.sigma, measurement.sample_period, measurement.filter_A
(0.5, 0.01, <FilterLinearization.estimate: 0>))");

  bind_options<DesiredStates>(m, "DesiredStates", {"DesiredStates"}, {{"q", "array_like, shape (N + 1, n)"}},
                              R"(Notes
-----
The values are checked with the scenario (Scenario.validate()) and when its trajectory is made;
docs/scenarios.md has [desired] states.

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.tf = 2.0
>>> t = [0.0, 1.0, 2.0]
>>> trajectory = hc.Trajectory(scenario.model, scenario.desired_q0, scenario.desired_u, 0.0, 2.0)
>>> scenario.desired_states = hc.DesiredStates(t=t, q=trajectory.q_d(np.array(t)))
>>> result = hc.run_scenario(scenario)
>>> len(result.trajectory.node_times()), bool(result.trajectory.max_defect() < 1e-8)
(3, True))");

  bind_options<PathChange>(m, "PathChange", {"PathChange"}, {}, R"(Notes
-----
Checked with the scenario (Scenario.validate()); docs/scenarios.md has [path_change].

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
>>> scenario.path_change = hc.PathChange(t=20.0, u_d=hc.VectorSignal([hc.Signal(1.0), hc.Signal(-0.2)]))
>>> result = hc.run_scenario(scenario)
>>> bool(np.hypot(*result.simulation.q_e()[-1, 3:5]) < 0.1)      # on the new path at tf
True)");

  bind_enum<SampledDesign>(m, "SampledDesign", R"(Examples
--------
>>> hc.SamplingSpec(period=0.05, design="digital").design
<SampledDesign.digital: 1>)");
  bind_options<SamplingSpec>(m, "SamplingSpec", {"SamplingSpec"}, {}, R"(Notes
-----
The values are checked with the scenario (Scenario.validate()); docs/scenarios.md has the
[sampling] table.

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.sampling = hc.SamplingSpec(period=0.1, delay=0.02)
>>> scenario.tf = 10.0
>>> result = hc.run_scenario(scenario)
>>> result.online.steps, result.online.saturated
(100, 0))");

  const std::string scenario_fields = members_section(
      "Scenario", "Attributes",
      {{"name", "str"}, {"description", "str"}, {"model", "Model"}, {"plant", "Model or None"},
       {"t0", "float"}, {"tf", "float"}, {"desired_q0", "ndarray, shape (n,)"},
       {"desired_u", "VectorSignal (set: also a callable or a list of Signal or float)"},
       {"desired_states", "DesiredStates or None"}, {"path_change", "PathChange or None"}, {"gamma", "float"},
       {"Q", "ndarray, shape (n, n)"}, {"Qf", "ndarray, shape (n, n)"}, {"kappa", "Signal (set: also a float)"},
       {"law", "Law (set: also its name)"}, {"cascade", "CascadeGains"},
       {"backstepping", "BacksteppingGains"},
       {"disturbance", "VectorSignal (set: also a callable, a list of Signal or float, or None)"},
       {"worst_case", "bool"}, {"initial_q0", "ndarray, shape (n,)"}, {"measurement", "MeasurementSpec or None"},
       {"sampling", "SamplingSpec or None"}, {"receding_horizon", "RecedingHorizonOptions or None"},
       {"solver", "SolverOptions"}, {"output_dt", "float"}, {"divergence_factor", "float"},
       {"lost_track", "float"}});
  const auto member = [](const char* name) { return std::string(contract(str_cat("Scenario::", name))); };
  py::class_<Scenario>(m, "Scenario", doc({"Scenario", "scenario/scenario.hpp"}, scenario_fields + R"(

Notes
-----
``Scenario()`` is empty: hc.load_scenario and hc.scenario_from_dict make complete ones. Set model
before desired_u and disturbance (their number of channels is the model's). A scenario pickles as
its scenario file (hinf_cpp.scenario.scenario_toml) and solver.escape_norm, which the file does
not hold; one whose model or signals are implemented in Python does not pickle (TypeError).

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.name, scenario.gamma, scenario.model.name(), scenario.measurement is None
('paper-fig1', 5.0, 'ship', True)
>>> scenario.tf = 10.0                                      # a shorter horizon (s)
>>> round(hc.run_scenario(scenario).metrics.final_position_error, 3)
0.084)").c_str())
      .def(py::init<>())
      .def_readwrite("name", &Scenario::name, member("name").c_str())
      .def_readwrite("description", &Scenario::description, member("description").c_str())
      .def_readwrite("model", &Scenario::model, member("model").c_str())
      .def_property(
          "plant", [](const Scenario& s) { return s.plant ? std::optional<ModelPtr>(s.plant) : std::nullopt; },
          [](Scenario& s, const std::optional<ModelPtr>& plant) { s.plant = plant.value_or(nullptr); },
          member("plant").c_str())
      .def_readwrite("t0", &Scenario::t0, member("t0").c_str())
      .def_readwrite("tf", &Scenario::tf, member("tf").c_str())
      .def_readwrite("desired_q0", &Scenario::desired_q0, member("desired_q0").c_str())
      .def_property("desired_u", [](const Scenario& s) { return s.desired_u; },
                    [](Scenario& s, const py::object& v) {
                      require(s.model != nullptr, "set Scenario.model before desired_u");
                      s.desired_u = to_vector_signal(v, s.model->m(), "desired_u");
                    }, member("desired_u").c_str())
      .def_readwrite("desired_states", &Scenario::desired_states, member("desired_states").c_str())
      .def_readwrite("path_change", &Scenario::path_change, member("path_change").c_str())
      .def_readwrite("gamma", &Scenario::gamma, member("gamma").c_str())
      .def_readwrite("Q", &Scenario::Q, member("Q").c_str())
      .def_readwrite("Qf", &Scenario::Qf, member("Qf").c_str())
      .def_property("kappa", [](const Scenario& s) { return s.kappa; },
                    [](Scenario& s, const py::object& v) { s.kappa = to_signal(v, "kappa"); }, member("kappa").c_str())
      .def_property("law", [](const Scenario& s) { return s.law; }, [](Scenario& s, Law law) { s.law = law; },
                    member("law").c_str())
      .def_readwrite("cascade", &Scenario::cascade, member("cascade").c_str())
      .def_readwrite("backstepping", &Scenario::backstepping, member("backstepping").c_str())
      .def_property("disturbance", [](const Scenario& s) { return s.disturbance; },
                    [](Scenario& s, const py::object& v) {
                      require(s.model != nullptr, "set Scenario.model before disturbance");
                      s.disturbance = to_vector_signal(v, s.model->nw(), "disturbance");
                    }, member("disturbance").c_str())
      .def_readwrite("worst_case", &Scenario::worst_case, member("worst_case").c_str())
      .def_readwrite("initial_q0", &Scenario::initial_q0, member("initial_q0").c_str())
      .def_readwrite("measurement", &Scenario::measurement, member("measurement").c_str())
      .def_readwrite("sampling", &Scenario::sampling, member("sampling").c_str())
      .def_readwrite("receding_horizon", &Scenario::receding_horizon, member("receding_horizon").c_str())
      .def_readwrite("solver", &Scenario::solver, member("solver").c_str())
      .def_readwrite("output_dt", &Scenario::output_dt, member("output_dt").c_str())
      .def_readwrite("divergence_factor", &Scenario::divergence_factor, member("divergence_factor").c_str())
      .def_readwrite("lost_track", &Scenario::lost_track, member("lost_track").c_str())
      .def("resolved", &Scenario::resolved, doc({"Scenario::resolved"}).c_str())
      .def("validate", &Scenario::validate, doc({"Scenario::validate"}, "An InputError is a ValueError.").c_str())
      .def("simulation_options", &Scenario::simulation_options, doc({"Scenario::simulation_options"}).c_str())
      .def("copy", [](const Scenario& s) { return Scenario(s); },
           "An independent copy: its fields can be set without changing this one (the model and the signals, "
           "which are immutable, are shared).")
      .def("__copy__", [](const Scenario& s) { return Scenario(s); });

  bind_result<Timing>(m, "Timing", {"Timing"}, {}, R"(Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> timing = hc.run_scenario(scenario).timing
>>> timing.total >= timing.design + timing.simulate
True)", /*repr=*/true);

  bind_result<RunResult>(m, "RunResult", {"RunResult"},
                         {{"Z0", "ndarray, shape (n, n)"}, {"plant", "Model or None"},
                          {"solution", "RiccatiSolution or None"}, {"sampling", "SamplingSpec or None"},
                          {"online", "OnlineCounts or None"},
                          {"receding_horizon", "RecedingHorizonReport or None"}},
                         R"(Notes
-----
gamma_star may be set (a float or None), as for the results file; the other attributes are
read-only. == is not defined (the trajectory and the design are shared objects). It pickles with
its trajectory and design.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> result = hc.run_scenario(scenario)
>>> result.law, result.gamma, result.output_feedback, result.Z0.shape
(<Law.hinf: 0>, 5.0, False, (6, 6))
>>> round(result.metrics.final_position_error, 3), result.simulation.q.shape
(0.084, (1001, 6)))",
                         /*repr=*/false, /*equality=*/false)
      .def_readwrite("gamma_star", &RunResult::gamma_star, doc({"RunResult::gamma_star"}).c_str())
      .def_property_readonly(
          "plant", [](const RunResult& r) { return r.plant ? std::optional<ModelPtr>(r.plant) : std::nullopt; },
          doc({"RunResult::plant"}).c_str());

  m.def("run_scenario", &run_scenario, py::arg("scenario"), py::call_guard<ComputationScope>(),
        doc({"run_scenario"}, R"(Parameters
----------
scenario : Scenario
    The scenario (hc.load_scenario, hc.scenario_from_dict).

Returns
-------
RunResult
    The design, the closed loop's series and its metrics.

Raises
------
ValueError
    An invalid scenario, naming the key.
ConjugatePointError
    gamma <= gamma* for the law's design.
CouplingConditionError
    With [measurement], rho(Sigma Z) >= gamma^2 (unless on_coupling_violation = "flag").
SolverError
    An integration failed.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> result = hc.run_scenario(scenario)
>>> result.simulation.status, round(result.metrics.max_position_error, 3)   # the initial error (m)
(<RunStatus.completed: 0>, 1.414))").c_str());
  m.def("run_scenario_with_noise", &run_scenario_with_noise, py::arg("scenario"), py::arg("noise"),
        py::call_guard<ComputationScope>(), doc({"run_scenario_with_noise"}, R"(Parameters
----------
scenario : Scenario
    A scenario with [measurement].
noise : array_like, shape (k, p)
    Standard normal samples, k = noise_sample_count(t0, tf, sample_period) hold intervals, p
    measured outputs; scaled by sigma in the loop.

Returns
-------
RunResult

Raises
------
ValueError
    An invalid scenario, one without [measurement], or noise of another shape.
ConjugatePointError, CouplingConditionError, SolverError
    As run_scenario.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig2") R"(
>>> noise = hc.scenario_noise(scenario)                      # the seeded samples
>>> replay = hc.run_scenario_with_noise(scenario, noise)
>>> np.array_equal(replay.simulation.q, hc.run_scenario(scenario).simulation.q)
True
>>> quiet = hc.run_scenario_with_noise(scenario, np.zeros_like(noise))   # no measurement noise
>>> quiet.metrics.rms_estimation_error_last_half < replay.metrics.rms_estimation_error_last_half
True)").c_str());
  // ---- studies (study.hpp) ----
  bind_options<StudyOptions>(m, "StudyOptions", {"StudyOptions"}, {}, R"(Notes
-----
run_scenarios uses one thread when a model or a signal is implemented in Python.

Raises
------
ValueError
    threads < 0.

Examples
--------
>>> hc.StudyOptions(threads=2, share_designs=False)
StudyOptions(threads=2, share_designs=False))");
  bind_result<StudyRun>(m, "StudyRun", {"StudyRun"}, {{"status", "str"}}, R"(Notes
-----
status is the name of the outcome ('completed', 'diverged', 'conjugate_point', 'coupling_violation',
'solver_failure', 'invalid_input', 'failed'); the property outcome is the RunOutcome.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> low = scenario.copy()
>>> low.gamma = 1.2                                          # below gamma*
>>> done, failed = hc.run_scenarios([scenario, low])
>>> done.status, round(done.metrics.max_position_error, 3), failed.status, failed.reason[:15]
('completed', 1.414, 'conjugate_point', 'conjugate point'))",
                        /*repr=*/false)
      .def_property_readonly("status", [](const StudyRun& r) { return to_string(r.status); },
                             doc({"StudyRun::status"}, "By name (outcome: the RunOutcome).").c_str())
      .def_property_readonly("outcome", [](const StudyRun& r) { return r.status; }, doc({"StudyRun::status"}).c_str())
      .def("__repr__", [](const StudyRun& r) {
        return str_cat("StudyRun(status='", to_string(r.status), "', law='", to_string(r.law),
                       "', output_feedback=", r.output_feedback ? "True" : "False", ", gamma=", r.gamma,
                       ", design=", r.design, r.reason.empty() ? "" : ", reason=" + py::repr(py::str(r.reason)).cast<std::string>(),
                       ")");
      });
  m.def("run_scenarios",
        [](const std::vector<Scenario>& scenarios, StudyOptions options,
           const std::optional<std::function<void(std::size_t, std::size_t)>>& progress) {
          // Every call into Python holds the GIL: runs of a model or signals implemented in
          // Python would only contend for it.
          for (const Scenario& s : scenarios)
            if (implemented_in_python(s.model.get()) || s.desired_u.is_function() ||
                s.disturbance.is_function())
              options.threads = 1;
          // Called on this thread while the workers run: Ctrl-C (a pending KeyboardInterrupt) and
          // an exception of the callable stop the study.
          const auto report = [&progress](std::size_t done, std::size_t total) {
            py::gil_scoped_acquire gil;
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            if (progress) (*progress)(done, total);
          };
          ComputationScope release;
          return run_scenarios(scenarios, options, report);
        },
        py::arg("scenarios"), py::arg("options") = StudyOptions{}, py::arg("progress") = py::none(),
        doc({"run_scenarios", "scenario/study.hpp"}, R"(Parameters
----------
scenarios : list of Scenario
    The runs.
options : StudyOptions, optional
    Worker threads (one when a model or signal is implemented in Python) and design sharing.
progress : callable or None, optional
    ``progress(done, total)``, called on this thread about every 0.1 s and once at the end.

Returns
-------
list of StudyRun
    One row per scenario, in order.

Raises
------
ValueError
    Invalid options.
Exception
    What progress raises (KeyboardInterrupt for Ctrl-C) stops the study and is raised here.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> gammas = [2.0, 5.0, 10.0]
>>> runs = []
>>> for gamma in gammas:
...     run = scenario.copy()
...     run.gamma = gamma
...     runs.append(run)
>>> rows = hc.run_scenarios(runs, hc.StudyOptions(threads=2))
>>> [row.status for row in rows], [row.design for row in rows]   # three designs
(['completed', 'completed', 'completed'], [0, 1, 2]))").c_str());
  m.def("scenario_gamma_star",
        [](const Scenario& scenario, const GammaStarOptions& options) {
          return scenario_gamma_star(scenario, serial_for_python_models(scenario.model.get(), options));
        },
        py::arg("scenario"), py::arg("options") = GammaStarOptions{}, py::call_guard<ComputationScope>(),
        doc({"scenario_gamma_star"}, R"(Parameters
----------
scenario : Scenario
    The scenario (its model, horizon, desired trajectory, Q, Qf and [solver]).
options : GammaStarOptions, optional
    The bracket, tolerance, evaluations and threads; its solver is replaced by the scenario's.

Returns
-------
GammaStarResult

Raises
------
ValueError
    An invalid scenario or options.
SolverError
    An integration failed.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> round(hc.scenario_gamma_star(scenario).gamma_star, 3)
1.335)").c_str());
  m.def("scenario_gamma_star_output_feedback",
        [](const Scenario& scenario, const GammaStarOptions& options) {
          return scenario_gamma_star_output_feedback(scenario, serial_for_python_models(scenario.model.get(), options));
        },
        py::arg("scenario"), py::arg("options") = GammaStarOptions{}, py::call_guard<ComputationScope>(),
        doc({"scenario_gamma_star_output_feedback"}, R"(Parameters
----------
scenario : Scenario
    A scenario with [measurement] (N, Q0, eta give the filter's weights).
options : GammaStarOptions, optional
    The bracket, tolerance, evaluations and threads; its solver is replaced by the scenario's.

Returns
-------
GammaStarResult
    binding names the condition that limits gamma.

Raises
------
ValueError
    An invalid scenario or options, or no [measurement].
SolverError
    An integration failed.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig2") R"(
>>> result = hc.scenario_gamma_star_output_feedback(scenario)
>>> round(result.gamma_star, 2), result.binding
(4.59, <GammaCondition.coupling: 3>))").c_str());
  m.def("scenario_receding_horizon", &scenario_receding_horizon, py::arg("scenario"),
        py::call_guard<ComputationScope>(), doc({"scenario_receding_horizon"}, R"(Parameters
----------
scenario : Scenario
    A scenario with [receding_horizon].

Returns
-------
RecedingHorizon
    The windows a run of the scenario solves, along its [desired] trajectory (from inputs, or
    from states and inputs) with its [path_change] applied.

Raises
------
ValueError
    A scenario without [receding_horizon], or an invalid scenario.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
>>> horizon = hc.scenario_receding_horizon(scenario)
>>> horizon.window_at(20.5), horizon.window_start(21)
(20, 21.0))").c_str());
  m.def("scenario_certificates", &scenario_certificates, py::arg("scenario"),
        py::call_guard<ComputationScope>(), doc({"scenario_certificates"}, R"(Parameters
----------
scenario : Scenario
    The scenario (its gamma, Q, Qf, kappa, model and desired trajectory).

Returns
-------
Certificates

Raises
------
ValueError
    An invalid scenario.
ConjugatePointError
    gamma <= gamma*: there is no design.
SolverError
    An integration failed.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig1") R"(
>>> certificates = hc.scenario_certificates(scenario)
>>> round(certificates.M, 2), certificates.kappa_min, certificates.remainder_is_bound
(20.81, 1.0, True))").c_str());
  m.def("scenario_warnings", &scenario_warnings, py::arg("scenario"), doc({"scenario_warnings"}).c_str());
  m.def("scenario_noise", &scenario_noise, py::arg("scenario"), doc({"scenario_noise"}, R"(Parameters
----------
scenario : Scenario
    A scenario with [measurement] (its seed, sample period and horizon).

Returns
-------
ndarray, shape (k, p)
    k = noise_sample_count(t0, tf, sample_period) hold intervals, p measured outputs.

Raises
------
ValueError
    A scenario without a model or without [measurement], or an invalid horizon or sample period.

Examples
--------
)" HINF_SCENARIO_EXAMPLE("paper_fig2") R"(
>>> noise = hc.scenario_noise(scenario)
>>> noise.shape, np.array_equal(noise, hc.scenario_noise(scenario))     # 10 s / 0.01 s, seeded
((1000, 3), True))").c_str());
}

#undef HINF_SCENARIO_EXAMPLE

}  // namespace hinf::python
