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
  hinf_error.doc() = "Base class of the numerical failures of hinf_cpp.";
  py::register_exception_translator([](std::exception_ptr p) {
    auto raise = [](const py::object& type, const char* what, const py::dict& attributes) {
      py::object instance = type(what);
      for (auto item : attributes) py::setattr(instance, item.first, item.second);
      PyErr_SetObject(type.ptr(), instance.ptr());
    };
    try {
      if (p) std::rethrow_exception(p);
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

  m.def("wrap_angle", &wrap_angle, py::arg("angle"), "the angle wrapped to (-pi, pi]");
}

}  // namespace hinf::python
