// The Python bindings of the scenario layer (cpp/include/hinf/scenario): scenarios and their
// runs, and batches of them (run_scenarios). A scenario pickles as its file (bind_io.cpp).
#include "casters.hpp"
#include "fields.hpp"
#include "hinf/scenario/scenario.hpp"
#include "hinf/scenario/study.hpp"

namespace hinf::python {

void bind_scenario(py::module_& m) {
  // ---- enums ----
  bind_enum<Law>(m, "Law", "The tracking law of a scenario (scenario.hpp)");
  bind_enum<RunOutcome>(m, "RunOutcome", "How a run of a study ended (study.hpp)");

  // ---- scenarios ----
  bind_options<MeasurementSpec>(m, "MeasurementSpec", "[measurement] of a scenario (paper §4)");

  py::class_<Scenario>(m, "Scenario", R"doc(Everything one run needs (docs/scenarios.md).
Pickles as its scenario file (scenario_toml) and solver.escape_norm, which the file does not hold;
a scenario whose model or signals are implemented in Python does not pickle (TypeError).)doc")
      .def(py::init<>())
      .def_readwrite("name", &Scenario::name)
      .def_readwrite("description", &Scenario::description)
      .def_readwrite("model", &Scenario::model)
      .def_property(
          "plant", [](const Scenario& s) { return s.plant ? std::optional<ModelPtr>(s.plant) : std::nullopt; },
          [](Scenario& s, const std::optional<ModelPtr>& plant) { s.plant = plant.value_or(nullptr); },
          "[plant]: the vehicle the closed loop integrates, or None (the design model)")
      .def_readwrite("t0", &Scenario::t0)
      .def_readwrite("tf", &Scenario::tf)
      .def_readwrite("desired_q0", &Scenario::desired_q0)
      .def_property("desired_u", [](const Scenario& s) { return s.desired_u; },
                    [](Scenario& s, const py::object& v) {
                      require(s.model != nullptr, "set Scenario.model before desired_u");
                      s.desired_u = to_vector_signal(v, s.model->m(), "desired_u");
                    })
      .def_readwrite("gamma", &Scenario::gamma)
      .def_readwrite("Q", &Scenario::Q)
      .def_readwrite("Qf", &Scenario::Qf)
      .def_property("kappa", [](const Scenario& s) { return s.kappa; },
                    [](Scenario& s, const py::object& v) { s.kappa = to_signal(v, "kappa"); })
      .def_property("law", [](const Scenario& s) { return s.law; }, [](Scenario& s, Law law) { s.law = law; })
      .def_readwrite("cascade", &Scenario::cascade)
      .def_property("disturbance", [](const Scenario& s) { return s.disturbance; },
                    [](Scenario& s, const py::object& v) {
                      require(s.model != nullptr, "set Scenario.model before disturbance");
                      s.disturbance = to_vector_signal(v, s.model->nw(), "disturbance");
                    })
      .def_readwrite("worst_case", &Scenario::worst_case)
      .def_readwrite("initial_q0", &Scenario::initial_q0)
      .def_readwrite("measurement", &Scenario::measurement)
      .def_readwrite("solver", &Scenario::solver)
      .def_readwrite("output_dt", &Scenario::output_dt)
      .def_readwrite("divergence_factor", &Scenario::divergence_factor)
      .def("resolved", &Scenario::resolved)
      .def("validate", &Scenario::validate)
      .def("simulation_options", &Scenario::simulation_options)
      .def("copy", [](const Scenario& s) { return Scenario(s); }, "an independent copy (signals and model shared)")
      .def("__copy__", [](const Scenario& s) { return Scenario(s); });

  bind_result<Timing>(m, "Timing", "Wall-clock seconds of a run", /*repr=*/true);

  bind_result<RunResult>(m, "RunResult",
                                           "Result of run_scenario (gamma_star may be set afterwards, as hinf-sim"
                                           " does, for the results file); == is not defined (its trajectory and"
                                           " design are shared objects)",
                                           /*repr=*/false, /*equality=*/false)
      .def_readwrite("gamma_star", &RunResult::gamma_star)
      .def_property_readonly(
          "plant", [](const RunResult& r) { return r.plant ? std::optional<ModelPtr>(r.plant) : std::nullopt; },
          "the scenario's [plant], the vehicle the closed loop integrated; None: the design model");

  m.def("run_scenario", &run_scenario, py::arg("scenario"), py::call_guard<py::gil_scoped_release>(), "Run a scenario");
  m.def("run_scenario_with_noise", &run_scenario_with_noise, py::arg("scenario"), py::arg("noise"),
        py::call_guard<py::gil_scoped_release>(),
        "Run a scenario with [measurement] on the given noise samples (one row per hold interval, one column per"
        " measured output) instead of the seeded ones, so that a run can be replayed exactly");
  // ---- studies (study.hpp) ----
  bind_options<StudyOptions>(m, "StudyOptions",
                             "Options of run_scenarios. threads: worker threads (0: the hardware's; never more than"
                             " runs; one when a model or signal is implemented in Python); share_designs: compute each"
                             " distinct design (trajectory and Riccati solutions) once");
  bind_result<StudyRun>(m, "StudyRun",
                        "One row of run_scenarios: status (its name: 'completed', 'diverged', 'conjugate_point',"
                        " 'coupling_violation', 'solver_failure', 'invalid_input', 'failed'; outcome is the"
                        " RunOutcome), reason (empty when completed), metrics (as RunResult.metrics; NaN when the"
                        " run failed), gamma, law, output_feedback, design_seconds, simulate_seconds, design (runs"
                        " with the same number shared one design; -1: none was made)",
                        /*repr=*/false)
      .def_property_readonly("status", [](const StudyRun& r) { return to_string(r.status); },
                             "how the run ended, by name (outcome: the RunOutcome)")
      .def_property_readonly("outcome", [](const StudyRun& r) { return r.status; }, "how the run ended")
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
          py::gil_scoped_release release;
          return run_scenarios(scenarios, options, report);
        },
        py::arg("scenarios"), py::arg("options") = StudyOptions{}, py::arg("progress") = py::none(),
        "Runs every scenario (in parallel, designs shared; study.hpp) and returns one StudyRun per scenario, in"
        " order: each row is what run_scenario gives for that scenario alone, and a run that fails is a row with"
        " its status and reason. progress(done, total), if given, is called on this thread about every 0.1 s"
        " and at the end; an exception it raises (or Ctrl-C) stops the study and is raised here");
  m.def("scenario_gamma_star",
        [](const Scenario& scenario, const GammaStarOptions& options) {
          return scenario_gamma_star(scenario, serial_for_python_models(scenario.model.get(), options));
        },
        py::arg("scenario"), py::arg("options") = GammaStarOptions{}, py::call_guard<py::gil_scoped_release>(),
        "gamma* of a scenario's state-feedback design");
  m.def("scenario_gamma_star_output_feedback",
        [](const Scenario& scenario, const GammaStarOptions& options) {
          return scenario_gamma_star_output_feedback(scenario, serial_for_python_models(scenario.model.get(), options));
        },
        py::arg("scenario"), py::arg("options") = GammaStarOptions{}, py::call_guard<py::gil_scoped_release>(),
        "The smallest gamma of a scenario's output-feedback design");
  m.def("scenario_certificates", &scenario_certificates, py::arg("scenario"),
        py::call_guard<py::gil_scoped_release>(), "The certificates of paper §3 for a scenario's design");
  m.def("scenario_warnings", &scenario_warnings, py::arg("scenario"),
        "What is legal in a scenario but probably not meant (a table whose interpolation overshoots its"
        " values), one message per finding naming the key");
  m.def("scenario_noise", &scenario_noise, py::arg("scenario"),
        "The seeded standard normal noise samples of a scenario with [measurement]");
}

}  // namespace hinf::python
