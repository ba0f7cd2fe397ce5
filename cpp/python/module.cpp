// The Python extension hinf_cpp._core: the C++ API of hinf_core (cpp/include/hinf), bound layer
// by layer from the bottom, one file per layer (bind_<layer>.cpp), with the conventions and the
// helpers they share in casters.hpp and fields.hpp.
#include "casters.hpp"

namespace hinf::python {

void bind_core(py::module_& m);
void bind_numerics(py::module_& m);
void bind_models(py::module_& m);
void bind_control(py::module_& m);
void bind_scenario(py::module_& m);
void bind_io(py::module_& m);

}  // namespace hinf::python

PYBIND11_MODULE(_core, m) {
  m.doc() = "hinf_cpp core: H-infinity tracking control of nonlinear underactuated vehicles";
  m.attr("__version__") = HINF_VERSION;
  // In layer order: a type is registered before any signature names it.
  hinf::python::bind_core(m);
  hinf::python::bind_numerics(m);
  hinf::python::bind_models(m);
  hinf::python::bind_control(m);
  hinf::python::bind_scenario(m);
  hinf::python::bind_io(m);
}
