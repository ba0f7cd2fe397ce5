// The Python bindings of the core layer (cpp/include/hinf/core): the exceptions and angles.
#include "casters.hpp"
#include "fields.hpp"
#include "hinf/core/angles.hpp"
#include "hinf/core/errors.hpp"

namespace hinf::python {

void bind_core(py::module_& m) {
  // Exceptions (core/errors.hpp): InputError is ValueError; the numerical failures derive from HinfError.
  static py::exception<HinfError> hinf_error(m, "HinfError", PyExc_RuntimeError);
  static py::exception<SolverError> solver_error(m, "SolverError", hinf_error.ptr());
  static py::exception<ConjugatePointError> conjugate_error(m, "ConjugatePointError", hinf_error.ptr());
  static py::exception<CouplingConditionError> coupling_error(m, "CouplingConditionError",
                                                              hinf_error.ptr());
  hinf_error.doc() = doc({"core/errors.hpp"}, R"(Examples
--------
A bad input is a ValueError; a numerical failure is a HinfError subclass:

>>> issubclass(hc.SolverError, hc.HinfError), issubclass(hc.HinfError, RuntimeError)
(True, True)
>>> try:
...     hc.SolverOptions(rtol=2.0)
... except ValueError as error:
...     print(error)
solver rtol must be in [1e-14, 1e-3], got 2)");
  solver_error.doc() = doc({}, R"(An integrator failed: the step size became too small, too many steps, non-finite values.

Attributes
----------
t : float
    The time (s) at which it failed.
flag : str
    The integrator's reason (CVODE's flag name, or the project's integrators' own).

Examples
--------
>>> model = hc.LinearModel(np.array([[1.0]]), np.array([[1.0]]), np.array([[1.0]]))
>>> trajectory = hc.Trajectory(model, [1.0], [0.0], 0.0, 50.0)
>>> try:
...     hc.solve_grde(trajectory, np.eye(1), np.eye(1), 5.0, hc.SolverOptions(method="erk", max_steps=3))
... except hc.SolverError as error:
...     print(type(error).__name__, error.flag)
SolverError ...)");
  conjugate_error.doc() = doc({}, R"(The GRDE (paper eq. 13) escaped to infinity: gamma is at or below gamma* (eq. 14) for this
trajectory and horizon. Raise gamma (hc.gamma_star finds the smallest one that passes).

Attributes
----------
t_escape : float
    The estimated time (s) at which Z(t) escapes, integrating backward from tf.
gamma : float
    The gamma that failed.

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.gamma = 1.2                              # below gamma* = 1.335
>>> try:
...     hc.run_scenario(scenario)
... except hc.ConjugatePointError as error:
...     print(error.gamma, round(error.t_escape, 1))
1.2 ...)");
  coupling_error.doc() = doc({}, R"(The output-feedback coupling condition rho(Sigma Z) < gamma^2 (paper §4) failed.

Attributes
----------
t : float
    The time (s) of the first violation.
rho : float
    rho(Sigma(t) Z(t)) there.
gamma : float
    The design's gamma.

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
>>> scenario.gamma = 4.0                              # coupling-bound below 4.59
>>> try:
...     hc.run_scenario(scenario)
... except hc.CouplingConditionError as error:
...     print(error.t, error.rho > error.gamma ** 2)
0.0 True)");
  py::register_exception_translator([](std::exception_ptr p) {
    auto raise = [](const py::object& type, const char* what, const py::dict& attributes) {
      py::object instance = type(what);
      for (auto item : attributes) py::setattr(instance, item.first, item.second);
      PyErr_SetObject(type.ptr(), instance.ptr());
    };
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Interrupted&) {
      clear_interrupt();  // the request is answered: Python's KeyboardInterrupt carries it on
      // Python's own handler of the SIGINT is pending too: run it now (it raises the
      // KeyboardInterrupt and is then done), so that a second one does not follow this one.
      // Without a pending signal (a request from code, or not the main thread) raise it here.
      if (PyErr_CheckSignals() == 0) PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const ConjugatePointError& e) {
      py::dict a;
      a["t_escape"] = e.t_escape();
      a["gamma"] = e.gamma();
      raise(conjugate_error, e.what(), a);
    } catch (const CouplingConditionError& e) {
      py::dict a;
      a["t"] = e.t();
      a["rho"] = e.rho();
      a["gamma"] = e.gamma();
      raise(coupling_error, e.what(), a);
    } catch (const SolverError& e) {
      py::dict a;
      a["t"] = e.t();
      a["flag"] = e.flag();
      raise(solver_error, e.what(), a);
    } catch (const HinfError& e) {
      raise(hinf_error, e.what(), py::dict());
    }
  });

  // ---- Ctrl-C (core/interrupt.hpp; module.cpp chains the request to Python's SIGINT) ----
  m.def("request_interrupt", &request_interrupt, doc({"request_interrupt", "core/interrupt.hpp"},
                                                     "A computation that it stops raises KeyboardInterrupt.")
                                                     .c_str());
  m.def("clear_interrupt", &clear_interrupt, doc({"clear_interrupt"}).c_str());
  m.def("interrupt_requested", &interrupt_requested, doc({"interrupt_requested"}).c_str());

  m.def("wrap_angle", &wrap_angle, py::arg("angle"), doc({"wrap_angle", "core/angles.hpp"}, R"(Parameters
----------
angle : float
    An angle (rad).

Returns
-------
float
    The angle wrapped to (-pi, pi].

Examples
--------
>>> import math
>>> hc.wrap_angle(3 * math.pi / 2), hc.wrap_angle(-math.pi) == math.pi
(-1.5707963267948966, True)
)").c_str());
}

}  // namespace hinf::python
