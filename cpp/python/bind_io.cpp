// The Python bindings of the io layer (cpp/include/hinf/io): the scenario reader and writer (a
// Scenario pickles as its scenario file), the results files, and the hook through which the
// Python package makes the models of [model] kind = "python".
#include "casters.hpp"
#include "fields.hpp"
#include "hinf/io/model_kinds.hpp"
#include "hinf/io/results.hpp"
#include "hinf/io/scenario_file.hpp"

namespace hinf::python {

namespace {

// scenario_toml, or a TypeError saying why the scenario cannot be pickled.
std::string scenario_text(const Scenario& s) {
  try {
    std::string text = scenario_toml(s);
    // What cannot be read back is an error now, not on load. A pickle is a program anyway (its
    // reader runs what it says), so its model section may load code.
    parse_scenario_toml(text, "<pickle>", true);
    return text;
  } catch (const InputError& e) {
    cannot_pickle(str_cat("the scenario '", s.name, "'"), e.what());
  }
}

}  // namespace

void bind_io(py::module_& m) {
  // ---- scenario and results files (io/scenario_file.hpp, io/results.hpp) ----
  m.def("parse_scenario_toml", &parse_scenario_toml, py::arg("text"), py::arg("source"), py::arg("allow_code") = false,
        doc({"parse_scenario_toml"}).c_str());
  m.def("load_scenario_toml", &load_scenario_toml, py::arg("path"), py::arg("allow_code") = false,
        doc({"load_scenario_toml"}).c_str());
  m.def("code_trusted_by_environment", &code_trusted_by_environment, doc({"code_trusted_by_environment"}).c_str());
  m.def("needs_planning_toml", &needs_planning_toml, py::arg("text"), py::arg("source"),
        doc({"needs_planning_toml"}).c_str());
  m.def("check_scenario_toml", &check_scenario_toml, py::arg("text"), py::arg("source"),
        doc({"check_scenario_toml"}).c_str());
  m.def("parse_model_toml", &parse_model_toml, py::arg("text"), py::arg("source"), py::arg("allow_code") = false,
        doc({"parse_model_toml"}).c_str());
  m.def("scenario_toml", &scenario_toml, py::arg("scenario"), doc({"scenario_toml", "io/scenario_file.hpp"}, R"(
Parameters
----------
scenario : Scenario
    The scenario to write.

Returns
-------
str
    The scenario file (TOML; docs/scenarios.md).

Raises
------
ValueError
    A model or a signal implemented in Python (it has no file form), naming it.

Examples
--------
>>> from hinf_cpp.scenario import scenario_toml
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.gamma = 4.0
>>> text = scenario_toml(scenario)
>>> "gamma = 4.0" in text, scenario_toml(hc._core.parse_scenario_toml(text, "copy")) == text
(True, True))").c_str());
  m.def("parse_signal_toml", &parse_signal_toml, py::arg("text"), py::arg("key"), py::arg("source"),
        doc({"parse_signal_toml"}).c_str());
  m.def("results_json", &results_json, py::arg("result"), py::arg("indent") = 2, doc({"results_json"}).c_str());
  m.def("results_csv", &results_csv, py::arg("result"), doc({"results_csv"}).c_str());

  // [model] kind = "python" in scenario files: the Python package registers the function that
  // makes the model (hinf_cpp.scenario.documents.model_from_callable) when it is imported.
  m.def(
      "set_python_model_hook",
      [](const py::function& make_model) {
        // The function is held by a shared pointer whose deleter takes the GIL; the hook is
        // cleared when the interpreter exits (atexit), before Python objects are torn down.
        auto held = std::shared_ptr<py::function>(new py::function(make_model), [](py::function* f) {
          py::gil_scoped_acquire gil;
          delete f;
        });
        set_python_model_hook([held](const std::string& callable, const std::string& source) -> ModelPtr {
          py::gil_scoped_acquire gil;
          return (*held)(callable, source).cast<ModelPtr>();
        });
      },
      py::arg("make_model"),
      "Registers make_model(callable: str, source: str) -> Model, the maker of the models that a scenario file "
      "names with [model] kind = \"python\" (hinf_cpp.scenario registers it when imported)");
  py::module_::import("atexit").attr("register")(py::cpp_function([] { set_python_model_hook({}); }));

  // RunResult (bind_scenario.cpp) writes its results files.
  py::class_<RunResult> run_result = py::reinterpret_borrow<py::class_<RunResult>>(m.attr("RunResult"));
  run_result.def("to_json", &results_json, py::arg("indent") = 2, doc({"results_json"}).c_str())
      .def("to_csv", &results_csv, doc({"results_csv"}).c_str());

  // Scenario (bind_scenario.cpp) pickles as its scenario file.
  py::class_<Scenario> scenario = py::reinterpret_borrow<py::class_<Scenario>>(m.attr("Scenario"));
  scenario.def(py::pickle(
          [](const Scenario& s) { return py::make_tuple(scenario_text(s), s.solver.escape_norm); },
          [](const py::tuple& state) {
            check_state(state, 2, "Scenario");
            Scenario s = parse_scenario_toml(state[0].cast<std::string>(), "<pickle>", true);
            s.solver.escape_norm = state[1].cast<double>();
            return s;
          }));
}

}  // namespace hinf::python
