// What every file of the bindings shares (private to the Python module): enum arguments given by
// name, the checks of values that come from Python, NumPy vectorization over times, and
// signals from Python values.
//
// Conventions of the bindings (mirroring the C++ API, cpp/include/hinf):
//   * the same names, argument order and defaults as C++ (defaults read from default-constructed
//     C++ structs);
//   * a C++ member function is a Python method (trajectory.n(), solution.gamma()); a data member
//     of a C++ struct is a property: read/write for option structs, read-only for results;
//   * enums are Python enums named by their name tables (core/enum_names.hpp: Method.bdf,
//     Law.hinf), and every argument or field of an enum type also takes the name as a str;
//   * C++ out-parameters become return values (Model.f(t, q) returns f; eigenvalue_bounds()
//     returns (min, max)).
// C++ InputError arrives as ValueError; numerical failures as hinf_cpp.HinfError subclasses
// (SolverError, ConjugatePointError, CouplingConditionError) with their data as attributes.
// Long calls release the GIL; Python callables and Python subclasses re-acquire it.
#pragma once

#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/typing.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string_view>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contracts.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/enum_names.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/interrupt.hpp"
#include "hinf/core/types.hpp"
#include "hinf/models/model.hpp"
#include "hinf/numerics/signal.hpp"

namespace py = pybind11;

// The enums with names (core/enum_names.hpp), declared here so that their casters below are the
// same in every file of the module; each is defined (with its names) in its layer's header.
namespace hinf {
enum class Method;                // numerics/solver_options.hpp
enum class NewtonSystems;         // numerics/solver_options.hpp
enum class Interpolation;         // numerics/signal.hpp
enum class RunStatus;             // control/simulation.hpp
enum class FilterLinearization;   // control/output_feedback.hpp
enum class CouplingPolicy;        // control/output_feedback.hpp
enum class GammaCondition;        // control/analysis.hpp
enum class StepStatus;            // control/online_controller.hpp
enum class MeasurementUse;        // control/online_controller.hpp
enum class Law;                   // scenario/scenario.hpp
enum class SampledDesign;         // scenario/scenario.hpp
enum class RunOutcome;            // scenario/study.hpp
enum class TerminalWeight;        // control/receding_horizon.hpp
}  // namespace hinf

// ---- enums from their names ----
// Wherever an enum is expected, its name (a str) is taken too: SolverOptions(method="erk"),
// scenario.law = "lqr". An unknown name is a ValueError listing the names (from_string). The
// stubs show the argument as "Method | str".
namespace pybind11::detail {

template <class E>
class named_enum_caster : public type_caster_base<E> {
 public:
  bool load(handle src, bool convert) {
    if (!isinstance<str>(src)) return type_caster_base<E>::load(src, convert);
    loaded_ = hinf::from_string<E>(src.cast<std::string>());
    this->value = &loaded_;
    return true;
  }

 private:
  E loaded_{};
};

// The caster of each enum; its name in signatures says what it takes and what it gives.
#define HINF_ENUM_CASTER(E)                                                  \
  template <>                                                                \
  class type_caster<hinf::E> : public named_enum_caster<hinf::E> {           \
   public:                                                                   \
    static constexpr auto name = io_name(#E " | str", #E);                   \
  }
HINF_ENUM_CASTER(Method);
HINF_ENUM_CASTER(NewtonSystems);
HINF_ENUM_CASTER(Interpolation);
HINF_ENUM_CASTER(RunStatus);
HINF_ENUM_CASTER(FilterLinearization);
HINF_ENUM_CASTER(CouplingPolicy);
HINF_ENUM_CASTER(GammaCondition);
HINF_ENUM_CASTER(StepStatus);
HINF_ENUM_CASTER(MeasurementUse);
HINF_ENUM_CASTER(Law);
HINF_ENUM_CASTER(SampledDesign);
HINF_ENUM_CASTER(RunOutcome);
HINF_ENUM_CASTER(TerminalWeight);
#undef HINF_ENUM_CASTER

}  // namespace pybind11::detail

namespace hinf::python {

// The GIL released for a computation that Ctrl-C stops (core/interrupt.hpp; module.cpp chains
// the request to Python's SIGINT handler). A request left from a Ctrl-C that Python code has
// already handled (a KeyboardInterrupt caught, a notebook cell stopped) is cleared first: it
// must not stop this computation. Used as `ComputationScope scope;` or
// `py::call_guard<ComputationScope>()`.
class ComputationScope {
 private:
  struct ClearStaleRequest {
    ClearStaleRequest() { clear_interrupt(); }
  } clear_;  // before the release: members are made in this order
  py::gil_scoped_release release_;
};

// ---- docstrings ----
// A docstring is written once: the contract of a C++ declaration is its comment in the header
// (cpp/include/hinf, gathered by name into contracts.hpp by scripts/generate_contracts.py), and
// the binding adds only what Python has of its own, as numpydoc sections (Parameters with NumPy
// shapes, Returns, Raises, Examples).

// The contract of `key`, or nothing when no comment of the headers has that name: for what may
// lack one (a field of a struct, each of whose fields is looked up).
inline std::optional<std::string_view> find_contract(std::string_view key) {
  for (const auto& [name, text] : kContracts)
    if (name == key) return text;
  return std::nullopt;
}

// The contract of `key` ("solve_grde", "Trajectory::A_e", "control/riccati.hpp", ...). A key
// without one is a defect of the bindings: std::logic_error, which fails the import.
inline std::string_view contract(std::string_view key) {
  if (const std::optional<std::string_view> text = find_contract(key)) return *text;
  throw std::logic_error(str_cat("the bindings name the C++ contract '", std::string(key),
                                 "', which no comment of cpp/include/hinf has (scripts/generate_contracts.py)"));
}

// The docstring: the contracts of `keys` (paragraphs, in order), then `sections` (without a
// first newline: a raw string may begin on the line after its R"( ).
inline std::string doc(std::initializer_list<std::string_view> keys, std::string_view sections = {}) {
  if (!sections.empty() && sections.front() == '\n') sections.remove_prefix(1);
  std::string text;
  for (std::string_view key : keys) {
    if (!text.empty()) text += "\n\n";
    text += contract(key);
  }
  if (!sections.empty()) {
    if (!text.empty()) text += "\n\n";
    text += sections;
  }
  return text;
}

// `text` with every line but empty ones indented by `spaces`.
inline std::string indented(std::string_view text, int spaces) {
  const std::string margin(static_cast<std::size_t>(spaces), ' ');
  std::string out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = text.substr(start, end - start);
    if (!line.empty()) out += margin;
    out += line;
    if (end == text.size()) break;
    out += '\n';
    start = end + 1;
  }
  return out;
}

// `text`, one paragraph, broken at spaces into lines of at most `width` characters (a longer
// word stays whole).
inline std::string wrapped(std::string_view text, std::size_t width) {
  std::string out, line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + '\n';
      line.clear();
    }
    if (!line.empty()) line += ' ';
    line += word;
    start = end + 1;
  }
  return out + line;
}

// An enum E as a Python enum whose members are the names of its table (enum_names.hpp), with
// a constructor from the name: Method("erk") is Method.erk. A member equals only itself (not its
// name: "erk" is taken as input, but Method.erk == "erk" is False, as hashes must agree).
// Its docstring: the contract of the enum (key `name`), the constructor's Parameters, an
// Attributes section with the contract of each member ("Method::bdf": the C++ enumerator's name
// lower-cased, the member's name without underscores), then `sections`.
template <class E>
void bind_enum(py::module_& m, const char* name, std::string_view sections) {
  std::string members = "Parameters\n----------\nvalue : int\n    The member's number, as its repr shows it.\n"
                        "name : str\n    The member's name, one of those below.\n\nAttributes\n----------";
  for (const auto& [item, item_name] : EnumNames<E>::names) {
    std::string key = str_cat(name, "::", item_name);
    key.erase(std::remove(key.begin(), key.end(), '_'), key.end());
    members += str_cat("\n", item_name, "\n", indented(contract(key), 4));
  }
  const std::string text = doc({name}, members + "\n\n" + std::string(sections));
  py::options options;
  options.disable_enum_members_docstring();  // the members are in the text, with their meaning
  py::enum_<E> cls(m, name, text.c_str());
  for (const auto& [item, item_name] : EnumNames<E>::names) cls.value(item_name, item);
  cls.def(py::init([](const std::string& item_name) { return from_string<E>(item_name); }), py::arg("name"),
          "The member of that name (ValueError listing the names for another).");
  // Replaces (not overloads) pybind11's ==, whose argument would go through the caster above.
  const auto same_member = [](E self, const py::object& other) {
    return py::isinstance<E>(other) && other.cast<E>() == self;
  };
  cls.attr("__eq__") = py::cpp_function(same_member, py::name("__eq__"), py::is_method(cls), py::arg("other"));
  const auto other_member = [same_member](E self, const py::object& other) { return !same_member(self, other); };
  cls.attr("__ne__") = py::cpp_function(other_member, py::name("__ne__"), py::is_method(cls), py::arg("other"));
}

// ---- values from Python ----
// What Python hands over (arguments, and what user callables return) is checked here before
// C++ reads it: a value of the wrong kind or size is an InputError (ValueError) naming the
// argument, never pybind11's "Unable to cast" and never a read past an array.

// "None", "float 1.5", "numpy.ndarray of shape (1,), dtype float64": a Python value, for messages.
inline std::string describe(const py::handle& value) {
  if (value.is_none()) return "None";
  const std::string type = Py_TYPE(value.ptr())->tp_name;
  if (py::hasattr(value, "shape") && py::hasattr(value, "dtype"))
    return str_cat(type, " of shape ", py::str(value.attr("shape")).cast<std::string>(), ", dtype ",
                   py::str(value.attr("dtype")).cast<std::string>());
  std::string text = py::repr(value).cast<std::string>();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return type + " " + text;
}

// "<subject> must <expected>, got <value>[ at t = <t>]".
[[noreturn]] inline void wrong_value(const py::handle& value, const std::string& subject, const std::string& expected,
                              std::optional<double> t = std::nullopt) {
  throw InputError(str_cat(subject, " must ", expected, ", got ", describe(value),
                           t ? str_cat(" at t = ", *t) : std::string()));
}

// value as T, or nothing when it is not one (pybind11's cast_error).
template <class T>
std::optional<T> try_cast(const py::handle& value) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    return std::nullopt;
  }
}

// What a user callable returned at t: a vector of `size` numbers, or a matrix rows x cols.
// Finite values are not required here: a model's f at an integrator's trial state may
// legitimately overflow, which the integrators treat as a step failure.
inline Vec vector_result(const py::handle& value, Eigen::Index size, const std::string& subject, double t) {
  const std::optional<Vec> v = try_cast<Vec>(value);
  if (!v) wrong_value(value, subject, str_cat("return an array of ", size, " numbers"), t);
  if (v->size() != size)
    throw InputError(str_cat(subject, " returned an array of length ", v->size(), " at t = ", t, ", expected ",
                             size, " numbers"));
  return *v;
}
inline Mat matrix_result(const py::handle& value, Eigen::Index rows, Eigen::Index cols, const std::string& subject,
                  double t) {
  const std::optional<Mat> M = try_cast<Mat>(value);
  if (!M) wrong_value(value, subject, str_cat("return an array of shape (", rows, ", ", cols, ")"), t);
  if (M->rows() != rows || M->cols() != cols)
    throw InputError(str_cat(subject, " returned an array of shape (", M->rows(), ", ", M->cols(), ") at t = ", t,
                             ", expected (", rows, ", ", cols, ")"));
  return *M;
}

// A Python callable kept by C++ objects (signals) that may be destroyed without the GIL held:
// the last copy lets go of it with the GIL.
class PythonFunction {
 public:
  explicit PythonFunction(py::function fn)
      : fn_(new py::function(std::move(fn)), [](py::function* f) {
          py::gil_scoped_acquire gil;
          delete f;
        }) {}
  // Call with the GIL held.
  template <class... Args>
  py::object operator()(Args&&... args) const {
    return (*fn_)(std::forward<Args>(args)...);
  }

 private:
  std::shared_ptr<py::function> fn_;
};

// method() of a Python subclass (self: its C++ base) as T, or nothing when the class does not
// define it; `who` ("the Python model") names it in errors. With the GIL held.
template <class T, class Base>
std::optional<T> read_override(const Base* self, const char* method, const char* expected, const char* who) {
  py::function override = py::get_override(self, method);
  if (!override) return std::nullopt;
  const py::object value = override();
  std::optional<T> result = try_cast<T>(value);
  if (!result) wrong_value(value, str_cat(who, "'s ", method, "()"), expected);
  return result;
}

// f(t) for a scalar t (any number, NumPy scalars and 0-d arrays included) gives one value;
// for a 1-D array of times, the values stacked on axis 0. rows = 0 means a scalar value,
// cols = 0 a vector of `rows`, otherwise a rows x cols matrix (fn writes column-major).
template <class Fn>
py::object vectorize(const py::object& t, int rows, int cols, Fn&& fn) {
  const py::array_t<double, py::array::c_style | py::array::forcecast> times(t);
  if (times.ndim() > 1) throw InputError("times must be a number or a 1-D array");
  const double* tp = times.data();
  for (py::ssize_t k = 0; k < times.size(); ++k)
    if (!std::isfinite(tp[k]))
      throw InputError(str_cat("times must be finite numbers, got ", tp[k],
                               times.ndim() == 0 ? std::string() : str_cat(" at index ", k)));
  const int r = std::max(rows, 1), c = std::max(cols, 1);
  const py::ssize_t block = r * c;
  std::vector<double> colmajor(static_cast<std::size_t>(block));
  if (times.ndim() == 0) {
    fn(*tp, colmajor.data());
    if (rows == 0) return py::float_(colmajor[0]);
    if (cols == 0) return py::cast(Eigen::Map<Vec>(colmajor.data(), rows).eval());
    return py::cast(Eigen::Map<Mat>(colmajor.data(), rows, cols).eval());
  }
  const py::ssize_t count = times.shape(0);
  std::vector<py::ssize_t> shape{count};
  if (rows > 0) shape.push_back(rows);
  if (cols > 0) shape.push_back(cols);
  py::array_t<double> out(shape);
  double* op = out.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t k = 0; k < count; ++k) {
      fn(tp[k], colmajor.data());
      // Column-major (Eigen) to row-major (NumPy).
      for (int i = 0; i < r; ++i)
        for (int j = 0; j < c; ++j) op[k * block + i * c + j] = colmajor[static_cast<std::size_t>(i + j * r)];
    }
  }
  return std::move(out);
}

// ---- signals from Python values (bind_numerics.cpp) ----

// A scalar Signal from a Signal or a finite number; `what` names the argument in errors.
Signal to_signal(const py::handle& value, const std::string& what);
// One Signal per item of a sequence (what[0], what[1], ... in errors).
std::vector<Signal> to_signals(const py::handle& sequence, const std::string& what);
// A VectorSignal of `dim` channels from a Python callable f(t): what(t) in errors.
VectorSignal vector_signal_from_callable(py::function callable, int dim, const std::string& what);
// A VectorSignal of `dim` channels from a VectorSignal, a callable f(t) -> array, a list of
// Signals or numbers, or None (all zero).
VectorSignal to_vector_signal(const py::object& value, int dim, const std::string& what);

// Whether a model is implemented in Python (bind_models.cpp): each of its calls holds the GIL,
// so computations that would run it on several threads at once run it on one.
bool implemented_in_python(const Model* model);

}  // namespace hinf::python
