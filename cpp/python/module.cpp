// The Python extension hinf_cpp._core: the C++ API of hinf_core (cpp/include/hinf), bound layer
// by layer from the bottom, one file per layer (bind_<layer>.cpp), with the conventions and the
// helpers they share in casters.hpp and fields.hpp.
#include <csignal>

#include "casters.hpp"

namespace hinf::python {

namespace {

// Ctrl-C reaches a C++ computation that runs without the GIL: this handler, put before the one
// Python installed (kept in `python_handler`), requests an interrupt (core/interrupt.hpp) and
// then does what Python's would, which makes Python raise KeyboardInterrupt when the call
// returns. A SIGINT that Python ignores is not a request. Should Python code install another
// SIGINT handler later (signal.signal), that one replaces this chain: computations then finish
// before Python sees the signal, as before.
struct sigaction python_handler;

extern "C" void chained_sigint(int signal, siginfo_t* info, void* context) {
  if (!(python_handler.sa_flags & SA_SIGINFO) && python_handler.sa_handler == SIG_IGN) return;
  request_interrupt();
  if (python_handler.sa_flags & SA_SIGINFO) {
    python_handler.sa_sigaction(signal, info, context);
  } else if (python_handler.sa_handler == SIG_DFL) {
    sigaction(SIGINT, &python_handler, nullptr);
    raise(SIGINT);
  } else {
    python_handler.sa_handler(signal);
  }
}

void chain_sigint_handler() {
  struct sigaction chained {};
  chained.sa_sigaction = chained_sigint;
  chained.sa_flags = SA_SIGINFO;
  sigemptyset(&chained.sa_mask);
  if (sigaction(SIGINT, nullptr, &python_handler) == 0) sigaction(SIGINT, &chained, nullptr);
}

}  // namespace

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
  hinf::python::chain_sigint_handler();
}
