// Python bindings of hinf_core, mirroring the C++ API (cpp/include/hinf/*.hpp):
//   * the same names, argument order and defaults as C++ (defaults read from default-constructed
//     C++ structs);
//   * a C++ member function is a Python method (trajectory.n(), solution.gamma()); a data member
//     of a C++ struct is a property: read/write for option structs, read-only for results;
//   * enums are Python enums named by their name tables (enum_names.hpp: Method.bdf, Law.hinf),
//     and every argument or field of an enum type also takes the name as a str;
//   * C++ out-parameters become return values (Model.f(t, q) returns f; eigenvalue_bounds()
//     returns (min, max)).
// C++ InputError arrives as ValueError; numerical failures as hinf_cpp.HinfError subclasses
// (SolverError, ConjugatePointError, CouplingConditionError) with their data as attributes.
// Long calls release the GIL; Python callables and Python subclasses re-acquire it.
// Scenarios, models, options and results pickle (see the pickling section).
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/typing.h>

#include <atomic>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>

#include "hinf/control/analysis.hpp"
#include "hinf/control/cascade.hpp"
#include "hinf/control/controller.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/enum_names.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/io/model_kinds.hpp"
#include "hinf/io/results.hpp"
#include "hinf/io/scenario_file.hpp"
#include "hinf/models/fleet.hpp"
#include "hinf/models/generated_model.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/models/vehicles.hpp"
#include "hinf/numerics/generated_function.hpp"
#include "hinf/numerics/numdiff.hpp"
#include "hinf/numerics/piecewise_polynomial.hpp"
#include "hinf/scenario/scenario.hpp"
#include "hinf/scenario/study.hpp"

namespace py = pybind11;

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
HINF_ENUM_CASTER(RunStatus);
HINF_ENUM_CASTER(Law);
HINF_ENUM_CASTER(FilterLinearization);
HINF_ENUM_CASTER(CouplingPolicy);
HINF_ENUM_CASTER(GammaCondition);
HINF_ENUM_CASTER(NewtonSystems);
HINF_ENUM_CASTER(Interpolation);
HINF_ENUM_CASTER(RunOutcome);
#undef HINF_ENUM_CASTER

}  // namespace pybind11::detail

using namespace hinf;

namespace {

// An enum E as a Python enum whose members are the names of its table (enum_names.hpp), with
// a constructor from the name: Method("erk") is Method.erk. A member equals only itself (not its
// name: "erk" is taken as input, but Method.erk == "erk" is False, as hashes must agree).
template <class E>
void bind_enum(py::module_& m, const char* name, const char* doc) {
  py::enum_<E> cls(m, name, doc);
  for (const auto& [item, item_name] : EnumNames<E>::names) cls.value(item_name, item);
  cls.def(py::init([](const std::string& item_name) { return from_string<E>(item_name); }), py::arg("name"));
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
std::string describe(const py::handle& value) {
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
[[noreturn]] void wrong_value(const py::handle& value, const std::string& subject, const std::string& expected,
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
Vec vector_result(const py::handle& value, Eigen::Index size, const std::string& subject, double t) {
  const std::optional<Vec> v = try_cast<Vec>(value);
  if (!v) wrong_value(value, subject, str_cat("return an array of ", size, " numbers"), t);
  if (v->size() != size)
    throw InputError(str_cat(subject, " returned an array of length ", v->size(), " at t = ", t, ", expected ",
                             size, " numbers"));
  return *v;
}
Mat matrix_result(const py::handle& value, Eigen::Index rows, Eigen::Index cols, const std::string& subject,
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

// A Model implemented in Python: override n, m, nw, f(t, q), G(t, q), D(t, q) (and optionally
// dfdq(t, q), dGudq(t, q, u), name, error_split, C, noise_channels, state_names,
// position_indices, heading_index, constant_input_matrices, state_dependent_inputs).
// Its structure (name, n, m, nw, state names, position and heading indices, noise channels,
// constant_input_matrices, state_dependent_inputs) is read once, on first use, validated
// (check_structure) and never asked again: everything downstream sizes its arrays by it. What
// f, dfdq, G, D, C and error_split return is checked against it at every call.
//
// Without dfdq the Jacobian is numerical: the complex step Im f(q + i h e_j) / h (exact to
// round-off, h = 1e-20) when f computes with complex q and agrees, at the first call, with
// central differences; central differences otherwise (numerical_jacobian). Without dGudq a
// state-dependent G is differentiated by central differences.
class PyModel : public Model, public py::trampoline_self_life_support {
 public:
  std::string name() const override { return structure().name; }
  int n() const override { return structure().n; }
  int m() const override { return structure().m; }
  int nw() const override { return structure().nw; }
  bool constant_input_matrices() const override { return structure().constant_input_matrices; }
  std::vector<std::string> state_names() const override { return structure().state_names; }
  std::vector<int> position_indices() const override { return structure().position_indices; }
  int heading_index() const override { return structure().heading_index; }
  std::vector<int> noise_channels() const override { return structure().noise_channels; }

  bool state_dependent_inputs() const override { return structure().state_dependent_inputs; }

  std::vector<std::pair<std::string, double>> named_parameters() const override {
    py::gil_scoped_acquire gil;
    py::function override = py::get_override(static_cast<const Model*>(this), "named_parameters");
    if (!override) return {};
    const py::object value = override();
    const auto parameters = try_cast<std::vector<std::pair<std::string, double>>>(
        py::isinstance<py::dict>(value) ? py::object(py::list(value.attr("items")())) : value);
    if (!parameters) wrong_value(value, "the Python model's named_parameters()", "return a dict of str: float");
    return *parameters;
  }

  Mat G(double t, const ConstVecRef& q) const override {
    const ModelStructure& s = structure();
    require_sized(q.size() == s.n, "G(t, q)");
    py::gil_scoped_acquire gil;
    return finite_matrix(call("G", t, Vec(q)), s.n, s.m, "the Python model's G(t, q)", t);
  }
  Mat D(double t, const ConstVecRef& q) const override {
    const ModelStructure& s = structure();
    require_sized(q.size() == s.n, "D(t, q)");
    py::gil_scoped_acquire gil;
    return finite_matrix(call("D", t, Vec(q)), s.n, s.nw, "the Python model's D(t, q)", t);
  }
  Mat C(double t) const override {
    const ModelStructure& s = structure();
    py::gil_scoped_acquire gil;
    py::function override = py::get_override(static_cast<const Model*>(this), "C");
    if (!override) return Model::C(t);
    const py::object value = override(t);
    const std::optional<Mat> C = try_cast<Mat>(value);
    if (!C || C->rows() < 1 || C->rows() > kMaxDimension || C->cols() != s.n)
      wrong_value(value, "the Python model's C(t)", str_cat("return an array of shape (p, ", s.n, "), p >= 1"), t);
    check_finite(*C, "the Python model's C(t)");
    return *C;
  }

  void f(double t, const ConstVecRef& q, VecRef out) const override {
    const int n = structure().n;
    require_sized(q.size() == n && out.size() == n, "f(t, q)");
    py::gil_scoped_acquire gil;
    out = vector_result(call("f", t, Vec(q)), n, "the Python model's f(t, q)", t);
  }
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override {
    const int n = structure().n;
    require_sized(q.size() == n && out.rows() == n && out.cols() == n, "dfdq(t, q)");
    py::gil_scoped_acquire gil;
    if (py::get_override(static_cast<const Model*>(this), "dfdq")) {
      out = matrix_result(call("dfdq", t, Vec(q)), n, n, "the Python model's dfdq(t, q)", t);
      return;
    }
    out = numerical_dfdq(t, q);
  }
  void dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const override {
    const ModelStructure& s = structure();
    require_sized(q.size() == s.n && u.size() == s.m && out.rows() == s.n && out.cols() == s.n, "dGudq(t, q, u)");
    if (!s.state_dependent_inputs) {
      out.setZero();
      return;
    }
    py::gil_scoped_acquire gil;
    if (py::get_override(static_cast<const Model*>(this), "dGudq")) {
      out = matrix_result(call("dGudq", t, Vec(q), Vec(u)), s.n, s.n, "the Python model's dGudq(t, q, u)", t);
      return;
    }
    const Vec u_held = u;
    out = central_difference_jacobian(Vec(q), s.n, [&](const Vec& x) -> Vec {
      return finite_matrix(call("G", t, x), s.n, s.m, "the Python model's G(t, q)", t) * u_held;
    });
  }
  std::string jacobian_method() const override {
    const bool numerical_input_part = structure().state_dependent_inputs && !overrides("dGudq");
    std::string method = "analytic";
    if (!overrides("dfdq")) {
      switch (jacobian_choice_.load()) {
        case JacobianChoice::ComplexStep: method = "complex step"; break;
        case JacobianChoice::CentralDifferences: method = "central differences"; break;
        default: method = "numerical (complex step or central differences, chosen at the first Jacobian)";
      }
    }
    if (numerical_input_part && method != "central differences") method += "; d(G u)/dq by central differences";
    return method;
  }
  void error_split(double t, const ConstVecRef& q_d, const ConstVecRef& u_d, const ConstVecRef& q_e, MatRef A,
                   VecRef alpha) const override {
    const int n = structure().n;
    require_sized(q_d.size() == n && u_d.size() == structure().m && q_e.size() == n && A.rows() == n &&
                      A.cols() == n && alpha.size() == n,
                  "error_split(t, q_d, u_d, q_e)");
    py::gil_scoped_acquire gil;
    py::function override = py::get_override(static_cast<const Model*>(this), "error_split");
    if (!override) {
      py::gil_scoped_release release;
      Model::error_split(t, q_d, u_d, q_e, A, alpha);
      return;
    }
    const char* subject = "the Python model's error_split(t, q_d, u_d, q_e)";
    const py::object value = override(t, Vec(q_d), Vec(u_d), Vec(q_e));
    if (!py::isinstance<py::tuple>(value) || py::len(value) != 2)
      wrong_value(value, subject, str_cat("return a pair (A, alpha) of shapes (", n, ", ", n, ") and (", n, ",)"), t);
    const py::tuple pair = py::reinterpret_borrow<py::tuple>(value);
    A = matrix_result(pair[0], n, n, str_cat(subject, "[0] (A)"), t);
    alpha = vector_result(pair[1], n, str_cat(subject, "[1] (alpha)"), t);
  }

 private:
  const ModelStructure& structure() const {
    if (const ModelStructure* s = structure_.load(std::memory_order_acquire)) return *s;
    py::gil_scoped_acquire gil;
    if (const ModelStructure* s = structure_.load(std::memory_order_acquire)) return *s;
    auto read = std::make_unique<const ModelStructure>(read_structure());
    // The Python calls of read_structure() may have let another thread store its reading
    // first: the first one stored is the one used.
    if (const ModelStructure* s = structure_.load(std::memory_order_acquire)) return *s;
    structure_.store(read.get(), std::memory_order_release);
    return *(owned_ = std::move(read));
  }

  // With the GIL held.
  ModelStructure read_structure() const {
    ModelStructure s;
    s.name = read<std::string>("name", "return a str").value_or("python-model");
    s.n = required_int("n");
    s.m = required_int("m");
    s.nw = required_int("nw");
    check_dimensions(s);
    s.state_names = read<std::vector<std::string>>("state_names", "return a list of str")
                        .value_or(Model::numbered_state_names(s.n));
    s.position_indices = read<std::vector<int>>("position_indices", "return a list of int")
                             .value_or(Model::position_indices());
    s.heading_index = read<int>("heading_index", "return an int").value_or(Model::heading_index());
    s.noise_channels = read<std::vector<int>>("noise_channels", "return a list of int")
                           .value_or(Model::noise_channels());
    s.constant_input_matrices = read<bool>("constant_input_matrices", "return a bool")
                                    .value_or(Model::constant_input_matrices());
    s.state_dependent_inputs = read<bool>("state_dependent_inputs", "return a bool")
                                   .value_or(Model::state_dependent_inputs());
    check_structure(s);
    return s;
  }
  template <class T>
  std::optional<T> read(const char* method, const char* expected) const {
    return read_override<T>(static_cast<const Model*>(this), method, expected, "the Python model");
  }
  int required_int(const char* method) const {
    const std::optional<int> value = read<int>(method, "return an int");
    if (!value) throw InputError(str_cat("the Python model does not implement ", method, "()"));
    return *value;
  }

  bool overrides(const char* method) const {
    py::gil_scoped_acquire gil;
    return static_cast<bool>(py::get_override(static_cast<const Model*>(this), method));
  }

  // A C++ caller sizes its arrays by n: anything else is its error, reported before Python runs.
  void require_sized(bool fits, const char* method) const {
    if (!fits)
      throw InputError(str_cat("the Python model's ", method, " was called with arrays that do not fit n = ",
                               structure().n));
  }

  template <class... Args>
  py::object call(const char* method, Args&&... args) const {
    py::function override = py::get_override(static_cast<const Model*>(this), method);
    if (!override) throw InputError(str_cat("the Python model does not implement ", method, "()"));
    return override(std::forward<Args>(args)...);
  }
  static Mat finite_matrix(const py::handle& value, Eigen::Index rows, Eigen::Index cols, const char* subject,
                           double t) {
    Mat M = matrix_result(value, rows, cols, subject, t);
    if (!M.allFinite()) check_finite(M, str_cat(subject, " at t = ", t));
    return M;
  }

  // The numerical df/dq at (t, q), with the GIL held: the complex step if the model allows it
  // (decided at the first call, see the class comment), else central differences.
  Mat numerical_dfdq(double t, const ConstVecRef& q) const {
    const int n = structure().n;
    const Vec x = q;
    const auto real_f = [&](const Vec& point) -> Vec {
      return vector_result(call("f", t, point), n, "the Python model's f(t, q)", t);
    };
    JacobianChoice choice = jacobian_choice_.load();
    if (choice == JacobianChoice::CentralDifferences) return central_difference_jacobian(x, n, real_f);
    std::optional<Mat> complex_step;
    try {
      complex_step = complex_step_jacobian(x, n, [&](const Eigen::VectorXcd& point) -> Eigen::VectorXcd {
        const std::optional<Eigen::VectorXcd> out = try_cast<Eigen::VectorXcd>(call("f", t, point));
        if (!out || out->size() != n) throw InputError("f(t, q) did not return n complex numbers for a complex q");
        return *out;
      });
    } catch (const py::error_already_set&) {  // f does not take complex numbers
    } catch (const InputError&) {
    }
    if (choice == JacobianChoice::ComplexStep && complex_step) return *complex_step;
    // The first call: central differences are accurate to about eps^(2/3) of the scale; a
    // complex step within 1e-6 of the scale of them is taken to be right (a model whose f drops
    // the imaginary part, e.g. through abs() or a real array, fails this and gets central
    // differences).
    const Mat central = central_difference_jacobian(x, n, real_f);
    const double scale = 1.0 + central.cwiseAbs().maxCoeff() + real_f(x).cwiseAbs().maxCoeff();
    const bool agrees = complex_step && complex_step->allFinite() &&
                        (*complex_step - central).cwiseAbs().maxCoeff() <= 1e-6 * scale;
    jacobian_choice_.store(agrees ? JacobianChoice::ComplexStep : JacobianChoice::CentralDifferences);
    return agrees ? *complex_step : central;
  }

  enum class JacobianChoice { Undecided, ComplexStep, CentralDifferences };
  mutable std::atomic<JacobianChoice> jacobian_choice_{JacobianChoice::Undecided};
  mutable std::atomic<const ModelStructure*> structure_{nullptr};
  mutable std::unique_ptr<const ModelStructure> owned_;
};

// Every call into a model implemented in Python holds the GIL, so parallel gamma evaluations
// would only contend for it (each handover can wait for Python's switch interval): such
// models get one thread.
GammaStarOptions serial_for_python_models(const Model* model, GammaStarOptions options) {
  if (dynamic_cast<const PyModel*>(model) != nullptr) options.threads = 1;
  return options;
}
const Model* model_of(const TrajectoryPtr& trajectory) { return trajectory ? &trajectory->model() : nullptr; }

// A Controller implemented in Python: override m() and control(t, q) -> u, optionally name()
// and n() (the state size; without it n() reports 0, see controller.hpp).
class PyController : public Controller, public py::trampoline_self_life_support {
 public:
  std::string name() const override {
    py::gil_scoped_acquire gil;
    return read<std::string>("name", "return a str").value_or("python-controller");
  }
  int n() const override {
    py::gil_scoped_acquire gil;
    const std::optional<int> n = read<int>("n", "return an int");
    if (n) check_dimension(*n, 1, "the Python controller's n()");
    return n.value_or(0);
  }
  int m() const override {
    py::gil_scoped_acquire gil;
    const std::optional<int> m = read<int>("m", "return an int");
    if (!m) throw InputError("the Python controller does not implement m()");
    check_dimension(*m, 1, "the Python controller's m()");
    return *m;
  }
  void control(double t, const ConstVecRef& q, VecRef u) override {
    py::gil_scoped_acquire gil;
    py::function override = py::get_override(static_cast<const Controller*>(this), "control");
    if (!override) throw InputError("the Python controller does not implement control(t, q)");
    u = vector_result(override(t, Vec(q)), u.size(), "the Python controller's control(t, q)", t);
  }

 private:
  template <class T>
  std::optional<T> read(const char* method, const char* expected) const {
    return read_override<T>(static_cast<const Controller*>(this), method, expected, "the Python controller");
  }
};

// The controller fits a model of n states (a controller that does not say, n() = 0, is
// given q of the model's size and reads it as such).
void check_controller_fits(const Controller& controller, const Model& model) {
  const int n = controller.n();
  require(n == 0 || n == model.n(), "the controller '", controller.name(), "' takes q of ", n,
          " numbers, the model '", model.name(), "' has n = ", model.n(), " states");
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

// A scalar Signal from a Signal or a finite number; `what` names the argument in errors.
Signal to_signal(const py::handle& value, const std::string& what) {
  if (py::isinstance<Signal>(value)) return value.cast<Signal>();
  const std::optional<double> number = try_cast<double>(value);
  if (!number || !std::isfinite(*number)) wrong_value(value, what, "be a Signal or a finite number");
  return Signal(*number);
}

// One Signal per item of a sequence (what[0], what[1], ... in errors).
std::vector<Signal> to_signals(const py::handle& sequence, const std::string& what) {
  std::vector<Signal> channels;
  for (const py::handle item : sequence)
    channels.push_back(to_signal(item, str_cat(what, "[", channels.size(), "]")));
  return channels;
}

// A VectorSignal of `dim` channels from a Python callable f(t): what(t) in errors.
VectorSignal vector_signal_from_callable(py::function callable, int dim, const std::string& what) {
  const PythonFunction fn(std::move(callable));
  const std::string subject = what + "(t)";
  return VectorSignal(dim, [fn, dim, subject](double t) {
    py::gil_scoped_acquire gil;
    const py::object value = fn(t);
    const Vec v = vector_result(value, dim, subject, t);
    if (!v.allFinite())
      throw InputError(str_cat(subject, " returned a non-finite value at t = ", t, ": ", describe(value)));
    return v;
  });
}

// A VectorSignal of `dim` channels from a VectorSignal, a callable f(t) -> array, a list of
// Signals or numbers, or None (all zero).
VectorSignal to_vector_signal(const py::object& value, int dim, const std::string& what) {
  check_dimension(dim, 0, str_cat("the number of channels of ", what));
  if (value.is_none()) return VectorSignal::zeros(dim);
  if (py::isinstance<VectorSignal>(value)) {
    VectorSignal signal = value.cast<VectorSignal>();
    require(signal.dim() == dim, what, " has ", signal.dim(), " channels, expected ", dim);
    return signal;
  }
  if (PyCallable_Check(value.ptr()) && !py::isinstance<Signal>(value))
    return vector_signal_from_callable(value.cast<py::function>(), dim, what);
  if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
    std::vector<Signal> channels = to_signals(value, what);
    require(static_cast<int>(channels.size()) == dim, what, " has ", channels.size(), " channels, expected ", dim);
    return VectorSignal(std::move(channels));
  }
  wrong_value(value, what,
              str_cat("be a VectorSignal, a callable f(t) -> array, a list of ", dim, " Signals or numbers, or None"));
}

// A Disturbance from a Disturbance or anything to_vector_signal takes.
Disturbance to_disturbance(const py::object& value, int dim) {
  if (py::isinstance<Disturbance>(value)) {
    Disturbance d = value.cast<Disturbance>();
    require(d.dim() == dim, "the disturbance has ", d.dim(), " channels, expected ", dim);
    return d;
  }
  return Disturbance(to_vector_signal(value, dim, "disturbance"));
}

void register_exceptions(py::module_& m) {
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
}

// ---- structs, field by field ----
// Fields<T>::list names the data members of a C++ struct once, in declaration order. The
// properties of its Python class, the keyword constructor (defaults from T{}), __repr__,
// __eq__ and pickling are all made from that list.
template <class T, class V>
struct Field {
  using Value = V;
  const char* name;
  V T::*member;
};
template <class T, class V>
constexpr Field<T, V> field(const char* name, V T::*member) {
  return {name, member};
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
struct Fields<CascadeGains> {
  static constexpr auto list =
      std::make_tuple(field("k", &CascadeGains::k), field("k1", &CascadeGains::k1), field("k2", &CascadeGains::k2));
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
                      field("t_escape", &GammaTrial::t_escape), field("condition", &GammaTrial::condition));
};
template <>
struct Fields<GammaStarResult> {
  static constexpr auto list = std::make_tuple(
      field("gamma_star", &GammaStarResult::gamma_star), field("lower", &GammaStarResult::lower),
      field("upper", &GammaStarResult::upper), field("t_escape_lower", &GammaStarResult::t_escape_lower),
      field("binding", &GammaStarResult::binding), field("converged", &GammaStarResult::converged),
      field("trials", &GammaStarResult::trials));
};
template <>
struct Fields<Certificates> {
  static constexpr auto list = std::make_tuple(
      field("m", &Certificates::m), field("M", &Certificates::M), field("kappa_min", &Certificates::kappa_min),
      field("p_min", &Certificates::p_min), field("p_min_t", &Certificates::p_min_t),
      field("remainder_L", &Certificates::remainder_L), field("remainder_method", &Certificates::remainder_method),
      field("remainder_is_bound", &Certificates::remainder_is_bound), field("epsilon", &Certificates::epsilon),
      field("epsilon_t", &Certificates::epsilon_t), field("attraction_radius", &Certificates::attraction_radius),
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
      field("Z0", &RunResult::Z0), field("Z_min_eig", &RunResult::Z_min_eig), field("Z_max_eig", &RunResult::Z_max_eig),
      field("gamma_star", &RunResult::gamma_star), field("simulation", &RunResult::simulation),
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

// Properties for the fields: read/write for options, read-only for results. Enums are returned
// by value (a Python enum object must not alias the struct's memory); other members as views.
// The class's __match_args__ lists the field names, for code that goes through all of them.
template <class T, class... Options>
void def_fields(py::class_<T, Options...>& cls, bool writable) {
  py::list names;  // __match_args__: the field names, in order (as a dataclass has them)
  for_each_field<T>([&](const auto& f) { names.append(f.name); });
  cls.attr("__match_args__") = py::tuple(names);
  for_each_field<T>([&](const auto& f) {
    using V = typename std::decay_t<decltype(f)>::Value;
    const auto member = f.member;
    if constexpr (std::is_enum_v<V>) {
      const auto get = [member](const T& o) { return o.*member; };
      if (writable) cls.def_property(f.name, get, [member](T& o, V v) { o.*member = v; });
      else cls.def_property_readonly(f.name, get);
    } else if (writable) {
      cls.def_readwrite(f.name, member);
    } else {
      cls.def_readonly(f.name, member);
    }
  });
}

// The keyword constructor T(field1=T{}.field1, ...), followed by check(object).
template <class T, class Check, class... Options, std::size_t... I>
void def_field_init(py::class_<T, Options...>& cls, Check check, std::index_sequence<I...>) {
  using List = std::decay_t<decltype(Fields<T>::list)>;
  const T defaults{};
  cls.def(py::init([check](typename std::tuple_element_t<I, List>::Value... values) {
            T object;
            ((object.*(std::get<I>(Fields<T>::list).member) = std::move(values)), ...);
            check(object);
            return object;
          }),
          (py::arg(std::get<I>(Fields<T>::list).name) = defaults.*(std::get<I>(Fields<T>::list).member))...);
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

// An option struct: keyword constructor (then check), read/write fields, repr, pickle, ==.
template <class T, class Check>
py::class_<T> bind_options(py::module_& m, const char* name, const char* doc, Check check) {
  py::class_<T> cls(m, name, doc);
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
py::class_<T> bind_options(py::module_& m, const char* name, const char* doc) {
  return bind_options<T>(m, name, doc, [](const T& options) {
    if constexpr (has_validate<T>::value) options.validate();
  });
}

// A result struct: read-only fields, pickle, == (unless equality is false); small ones also a repr.
template <class T>
py::class_<T> bind_result(py::module_& m, const char* name, const char* doc, bool repr, bool equality = true) {
  py::class_<T> cls(m, name, doc);
  def_fields(cls, /*writable=*/false);
  if (repr) def_field_repr(cls);
  def_value_protocol(cls, equality);
  return cls;
}

// ---- pickling of the classes that are not plain structs ----

[[noreturn]] void cannot_pickle(const std::string& what, const std::string& why) {
  throw py::type_error(str_cat("cannot pickle ", what, ": ", why));
}

void check_state(const py::tuple& state, std::size_t size, const char* type) {
  require(state.size() == size, "a pickled ", type, " has ", size, " items, got ", state.size());
}

// ("harmonics", offset, harmonics) or ("table", table_t, table_values, interpolation).
py::tuple signal_state(const Signal& s) {
  if (s.is_table())
    return py::make_tuple<py::return_value_policy::copy>("table", s.table_t(), s.table_values(),
                                                         to_string(s.interpolation()));
  return py::make_tuple<py::return_value_policy::copy>("harmonics", s.offset(), s.harmonics());
}
Signal signal_from_state(const py::tuple& state) {
  require(state.size() > 0, "a pickled Signal has no items");
  if (state[0].cast<std::string>() == "table") {
    check_state(state, 4, "Signal table");
    return Signal::table(state[1].cast<std::vector<double>>(), state[2].cast<std::vector<double>>(),
                         from_string<Interpolation>(state[3].cast<std::string>()));
  }
  check_state(state, 3, "Signal");
  return Signal(state[1].cast<double>(), state[2].cast<std::vector<Harmonic>>());
}

// The pieces of a dense output as arrays: dim, t_start, t_end, degree, the coefficients in a row.
py::tuple dense_state(const PiecewisePolynomial& p) {
  const std::size_t count = p.num_pieces();
  Vec t_start(count), t_end(count);
  Eigen::VectorXi degree(count);
  std::vector<double> coefficients;
  for (std::size_t k = 0; k < count; ++k) {
    const DensePiece piece = p.piece(k);
    t_start[k] = piece.t_start;
    t_end[k] = piece.t_end;
    degree[k] = piece.degree;
    coefficients.insert(coefficients.end(), piece.coeffs, piece.coeffs + (piece.degree + 1) * piece.dim);
  }
  const Vec coefficient_row =
      Eigen::Map<const Vec>(coefficients.data(), static_cast<Eigen::Index>(coefficients.size()));
  return py::make_tuple(p.dim(), t_start, t_end, degree, coefficient_row);
}
PiecewisePolynomial dense_from_state(const py::tuple& state) {
  check_state(state, 5, "PiecewisePolynomial");
  const int dim = state[0].cast<int>();
  check_dimension(dim, 1, "the dimension of a pickled PiecewisePolynomial");
  const Vec t_start = state[1].cast<Vec>(), t_end = state[2].cast<Vec>(), coefficients = state[4].cast<Vec>();
  const Eigen::VectorXi degree = state[3].cast<Eigen::VectorXi>();
  require(t_end.size() == t_start.size() && degree.size() == t_start.size(),
          "a pickled PiecewisePolynomial needs as many step ends and degrees as pieces");
  PiecewisePolynomial p(dim);
  Eigen::Index used = 0;
  for (Eigen::Index k = 0; k < t_start.size(); ++k) {
    require(degree[k] >= 0 && used + (degree[k] + 1) * Eigen::Index{dim} <= coefficients.size(),
            "a pickled PiecewisePolynomial has too few coefficients for its pieces");
    p.append(DensePiece{t_start[k], t_end[k], degree[k], dim, coefficients.data() + used});
    used += (degree[k] + 1) * Eigen::Index{dim};
  }
  require(used == coefficients.size(), "a pickled PiecewisePolynomial has more coefficients than its pieces use");
  p.finalize();
  return p;
}

// RiccatiSolution and FilterRiccatiSolution: (trajectory, gamma, dense output, stats).
template <class Solution, class... Options>
void def_solution_pickle(py::class_<Solution, Options...>& cls) {
  cls.def(py::pickle(
      [](const Solution& s) {
        return py::make_tuple<py::return_value_policy::copy>(s.trajectory_ptr(), s.gamma(), s.dense(), s.stats());
      },
      [](const py::tuple& state) {
        check_state(state, 4, "Riccati solution");
        auto trajectory = state[0].cast<TrajectoryPtr>();
        require(trajectory != nullptr, "a pickled Riccati solution needs its trajectory");
        auto dense = state[2].cast<PiecewisePolynomial>();
        require(dense.dim() == packed_size(trajectory->n()), "a pickled Riccati solution of n = ", trajectory->n(),
                " needs ", packed_size(trajectory->n()), " components, got ", dense.dim());
        return std::make_shared<Solution>(std::move(trajectory), state[1].cast<double>(), std::move(dense),
                                          state[3].cast<SolveStats>());
      }));
}

// scenario_toml, or a TypeError saying why the scenario cannot be pickled.
std::string scenario_text(const Scenario& s) {
  try {
    std::string text = scenario_toml(s);
    parse_scenario_toml(text, "<pickle>");  // what cannot be read back is an error now, not on load
    return text;
  } catch (const InputError& e) {
    cannot_pickle(str_cat("the scenario '", s.name, "'"), e.what());
  }
}

std::string metrics_repr(const Metrics& metrics) {
  std::string text = "Metrics(";
  const char* separator = "";
  for (const MetricDefinition& d : metric_table()) {
    text += str_cat(separator, d.name, "=", value_repr(metrics.*(d.value)));
    separator = ", ";
  }
  return text + ")";
}

// Checks of an OutputFeedbackProblem that need no model (simulate_output_feedback checks the
// sizes against the design's model): a matrix left empty is checked there.
void check_problem(const OutputFeedbackProblem& p) {
  require(std::isfinite(p.sigma) && p.sigma >= 0.0, "sigma must be >= 0, got ", p.sigma);
  require(std::isfinite(p.sample_period) && p.sample_period > 0.0, "sample_period must be > 0, got ",
          p.sample_period);
  if (p.N.size() > 0) check_symmetric_weight(p.N, static_cast<int>(p.N.rows()), "N", true);
  if (p.Sigma0.size() > 0) check_symmetric_weight(p.Sigma0, static_cast<int>(p.Sigma0.rows()), "Sigma0", true);
  if (p.Q.size() > 0 && p.Sigma0.size() > 0)
    check_symmetric_weight(p.Q, static_cast<int>(p.Sigma0.rows()), "Q (the size of Sigma0)", false);
  if (p.noise.size() > 0) check_finite(p.noise, "noise");
}

// eigenvalue_bounds() and eigenvalue_range(times) as (min, max).
template <class Solution>
py::tuple bounds(const Solution& s) {
  double lo = 0, hi = 0;
  s.eigenvalue_bounds(lo, hi);
  return py::make_tuple(lo, hi);
}
template <class Solution>
py::tuple range(const Solution& s, const std::vector<double>& times) {
  require(!times.empty(), "eigenvalue_range needs at least one time");
  double lo = 0, hi = 0;
  s.eigenvalue_range(times, lo, hi);
  return py::make_tuple(lo, hi);
}

// X(t) of a symmetric solution, vectorized over t.
template <class Solution, class Member>
py::object matrix_of_t(const Solution& s, const py::object& t, Member member) {
  const int n = s.n();
  return vectorize(t, n, n, [&s, n, member](double tt, double* out) { Eigen::Map<Mat>(out, n, n) = (s.*member)(tt); });
}

// A built-in vehicle (vehicles.hpp): Vehicle(parameters), parameters(), pickled by value as
// its parameters (as ShipModel).
template <class Vehicle, class Parameters>
void bind_vehicle(py::module_& m, const char* name, const char* doc) {
  const std::string type = name;
  py::class_<Vehicle, Model, py::smart_holder>(m, name, doc)
      .def(py::init<const Parameters&>(), py::arg("parameters") = Parameters{})
      .def("parameters", &Vehicle::parameters)
      .def(py::pickle(
          [](const Vehicle& model) { return py::make_tuple<py::return_value_policy::copy>(model.parameters()); },
          [type](const py::tuple& state) {
            check_state(state, 1, type.c_str());
            return std::make_shared<Vehicle>(state[0].cast<Parameters>());
          }));
}

}  // namespace

// ---- CasADi generated code (generated_function.hpp) ----
// GeneratedFunction(path, name)(*inputs) -> list of arrays. An input is a number (a 1 x 1
// input), a 1-D array (a vector input) or a 2-D array of the input's shape; each output is a
// 2-D array of the output's shape (zeros where it is structurally zero). The evaluation
// releases the GIL (calls from several threads run at once).
static void bind_generated_function(py::module_& m) {
  using ColumnMajor = py::array_t<double, py::array::f_style | py::array::forcecast>;
  // Input i as a column-major float64 array (a copy unless it is one already), shape-checked.
  const auto input_array = [](const GeneratedFunction& f, int i, const py::handle& value) {
    const int rows = f.input_rows(i), cols = f.input_cols(i);
    const std::string subject = str_cat("input ", i, " (", f.input_name(i), ") of '", f.name(), "'");
    const std::string expected =
        str_cat("be an array of shape (", rows, ", ", cols, ")",
                rows * cols == 1 ? " or a number" : (rows == 1 || cols == 1) ? str_cat(" or of length ", rows * cols) : "");
    ColumnMajor array = ColumnMajor::ensure(value);
    if (!array) wrong_value(value, subject, expected);
    const bool fits = array.ndim() == 2 ? array.shape(0) == rows && array.shape(1) == cols
                      : array.ndim() == 1 ? (rows == 1 || cols == 1) && array.shape(0) == rows * cols
                                          : array.ndim() == 0 && rows * cols == 1;
    if (!fits) wrong_value(value, subject, expected);
    return array;
  };
  py::class_<GeneratedFunction, std::shared_ptr<GeneratedFunction>>(
      m, "GeneratedFunction",
      "A function of a shared library compiled from CasADi generated C code "
      "(hinf_cpp.codegen.compile_casadi_functions), evaluated in C++")
      .def(py::init<const std::string&, const std::string&>(), py::arg("path"), py::arg("name"))
      .def("name", &GeneratedFunction::name)
      .def("path", [](const GeneratedFunction& f) { return f.library()->path(); })
      .def("n_in", &GeneratedFunction::n_in)
      .def("n_out", &GeneratedFunction::n_out)
      .def("input_shape", [](const GeneratedFunction& f, int i) { return std::pair<int, int>(f.input_rows(i), f.input_cols(i)); },
           py::arg("i"))
      .def("output_shape", [](const GeneratedFunction& f, int i) { return std::pair<int, int>(f.output_rows(i), f.output_cols(i)); },
           py::arg("i"))
      .def("input_name", &GeneratedFunction::input_name, py::arg("i"))
      .def("output_name", &GeneratedFunction::output_name, py::arg("i"))
      .def("__call__",
           [input_array](const GeneratedFunction& f, const py::args& args) {
             if (static_cast<int>(args.size()) != f.n_in()) {
               std::string names;
               for (int i = 0; i < f.n_in(); ++i) names += (i ? ", " : "") + f.input_name(i);
               throw InputError(str_cat("'", f.name(), "' takes ", f.n_in(), " inputs (", names, "), got ", args.size()));
             }
             std::vector<ColumnMajor> inputs;
             std::vector<const double*> input_data;
             for (int i = 0; i < f.n_in(); ++i) {
               inputs.push_back(input_array(f, i, args[static_cast<std::size_t>(i)]));
               input_data.push_back(inputs.back().data());
             }
             std::vector<py::array_t<double, py::array::f_style>> outputs;
             std::vector<double*> output_data;
             for (int o = 0; o < f.n_out(); ++o) {
               outputs.emplace_back(std::vector<py::ssize_t>{f.output_rows(o), f.output_cols(o)});
               output_data.push_back(outputs.back().mutable_data());
             }
             {
               py::gil_scoped_release release;
               f.eval(input_data.data(), output_data.data());
             }
             return outputs;
           },
           "Evaluates in C++ (the GIL released): one input per argument (a number, a 1-D array for a vector, or an"
           " array of the input's shape); one 2-D array per output")
      .def("__repr__", [](const GeneratedFunction& f) {
        return str_cat("GeneratedFunction('", f.library()->path(), "', '", f.name(), "')");
      });
}

PYBIND11_MODULE(_core, m) {
  m.doc() = "hinf_cpp core: H-infinity tracking control of nonlinear underactuated vehicles";
  m.attr("__version__") = HINF_VERSION;
  register_exceptions(m);

  // ---- enums (enum_names.hpp) ----
  bind_enum<Method>(m, "Method", "Integrator of every ODE solve (solver_options.hpp)");
  bind_enum<RunStatus>(m, "RunStatus", "How a closed-loop run ended (simulation.hpp)");
  bind_enum<Law>(m, "Law", "The tracking law of a scenario (scenario.hpp)");
  bind_enum<FilterLinearization>(m, "FilterLinearization",
                                 "Which A the filter Riccati equation (36) uses (output_feedback.hpp)");
  bind_enum<CouplingPolicy>(m, "CouplingPolicy",
                            "What a violation of rho(Sigma Z) < gamma^2 does (output_feedback.hpp)");
  bind_enum<GammaCondition>(m, "GammaCondition", "The condition a gamma fails (analysis.hpp)");
  bind_enum<NewtonSystems>(m, "NewtonSystems", "How BDF solves the Newton systems of a Riccati equation (solver_options.hpp)");
  bind_enum<Interpolation>(m, "Interpolation", "How a table Signal is interpolated between its points (signal.hpp)");
  bind_enum<RunOutcome>(m, "RunOutcome", "How a run of a study ended (study.hpp)");

  // ---- signals ----
  bind_options<Harmonic>(m, "Harmonic", "a sin(omega t + phase) (or cos) term of a Signal");

  py::class_<Signal>(m, "Signal", "A scalar signal of absolute time: offset + harmonics, or a table")
      .def(py::init<>())
      .def(py::init<double>(), py::arg("constant"))
      .def(py::init<double, std::vector<Harmonic>>(), py::arg("offset"), py::arg("harmonics"))
      .def_static("table", [](std::vector<double> t, std::vector<double> values, Interpolation interpolation) {
            Signal signal = Signal::table(std::move(t), std::move(values), interpolation);
            const std::string warning = overshoot_warning(signal, "Signal.table");
            if (!warning.empty() && PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0)
              throw py::error_already_set();  // warnings turned into errors
            return signal;
          },
          py::arg("t"), py::arg("values"), py::arg("interpolation") = Interpolation::Pchip,
          "The table (t_i, v_i), interpolated by \"pchip\" (default, no overshoot), \"linear\", \"hold\" "
          "(the value of the last point at or before t) or \"cubic\" (natural spline; a UserWarning when it "
          "overshoots the values' range); at least two points, strictly increasing t")
      .def("__call__", [](const Signal& s, const py::object& t) {
        return vectorize(t, 0, 0, [&s](double tt, double* out) { out[0] = s(tt); });
      }, py::arg("t"))
      .def("minimum", &Signal::minimum, py::arg("t0"), py::arg("tf"),
           "(the smallest value on [t0, tf], where it is taken)")
      .def("is_table", &Signal::is_table)
      .def("is_constant", &Signal::is_constant)
      .def("offset", &Signal::offset)
      .def("harmonics", &Signal::harmonics)
      .def("table_t", &Signal::table_t)
      .def("table_values", &Signal::table_values)
      .def("interpolation", &Signal::interpolation)
      .def("overshoot", &Signal::overshoot,
           "(how far a table's interpolant leaves the range of its values, where); (0, t_first) inside it")
      .def("describe", &Signal::describe)
      .def("__repr__", [](const Signal& s) { return "Signal(" + s.describe() + ")"; })
      .def(py::pickle(&signal_state, &signal_from_state));
  py::implicitly_convertible<double, Signal>();
  m.def("overshoot_warning", &overshoot_warning, py::arg("signal"), py::arg("name"),
        "The warning for a table whose interpolant overshoots the range of its values, naming it `name`; '' otherwise");

  py::class_<VectorSignal>(m, "VectorSignal", "A vector signal: one Signal per channel, or a function of t")
      .def(py::init([](const py::sequence& channels) { return VectorSignal(to_signals(channels, "channels")); }),
           py::arg("channels"), "one Signal (or number) per channel")
      .def(py::init([](int dim, const py::function& function) {
             return vector_signal_from_callable(function, dim, "function");
           }),
           py::arg("dim"), py::arg("function"), "function(t) must return an array of dim numbers")
      .def_static("zeros", &VectorSignal::zeros, py::arg("dim"))
      .def("dim", &VectorSignal::dim)
      .def("is_function", &VectorSignal::is_function)
      .def("channels", &VectorSignal::channels)
      .def("__call__", [](const VectorSignal& s, const py::object& t) {
        return vectorize(t, s.dim(), 0, [&s](double tt, double* out) { s.eval(tt, out); });
      }, py::arg("t"))
      .def(py::pickle(
          [](const VectorSignal& s) {
            if (s.is_function())
              cannot_pickle("a VectorSignal that is a function of t", "only signals of channels pickle");
            return py::make_tuple<py::return_value_policy::copy>(s.dim(), s.channels());
          },
          [](const py::tuple& state) {
            check_state(state, 2, "VectorSignal");
            auto channels = state[1].cast<std::vector<Signal>>();
            return channels.empty() ? VectorSignal::zeros(state[0].cast<int>()) : VectorSignal(std::move(channels));
          }));

  // ---- models ----
  py::class_<Model, PyModel, py::smart_holder>(m, "Model", R"doc(
Control-affine model dq/dt = f(t, q) + G(t, q) u + D(t, q) w (paper eq. 7; model.hpp).
Subclass it in Python and implement n(), m(), nw(), f(t, q), G(t, q), D(t, q), and if you can
dfdq(t, q) (else a numerical Jacobian is used: the complex step when f accepts complex q, else
central differences; jacobian_method() says which). A G or D that depends on q needs
state_dependent_inputs() -> True and constant_input_matrices() -> False (dGudq(t, q, u) =
d/dq [G(t, q) u] is optional: central differences otherwise). Its structure (n, m, nw, name,
state_names, position_indices, heading_index, noise_channels, constant_input_matrices,
state_dependent_inputs) is read once, when the library first needs it, and validated; it must not
change afterwards. What f, dfdq, G, D, C and error_split return is checked at every call.
A model implemented in Python does not pickle.)doc")
      .def(py::init<>())
      .def("name", &Model::name)
      .def("n", &Model::n)
      .def("m", &Model::m)
      .def("nw", &Model::nw)
      .def("f", [](const Model& model, double t, const Vec& q) {
        check_size(q, model.n(), "q");
        Vec out(model.n());
        model.f(t, q, out);
        return out;
      }, py::arg("t"), py::arg("q"))
      .def("dfdq", [](const Model& model, double t, const Vec& q) {
        check_size(q, model.n(), "q");
        Mat out(model.n(), model.n());
        model.dfdq(t, q, out);
        return out;
      }, py::arg("t"), py::arg("q"))
      .def("G", [](const Model& model, double t, const Vec& q) {
        check_size(q, model.n(), "q");
        return model.G(t, q);
      }, py::arg("t"), py::arg("q"), "input matrix G(t, q) (n x m)")
      .def("D", [](const Model& model, double t, const Vec& q) {
        check_size(q, model.n(), "q");
        return model.D(t, q);
      }, py::arg("t"), py::arg("q"), "disturbance matrix D(t, q) (n x nw)")
      .def("dGudq", [](const Model& model, double t, const Vec& q, const Vec& u) {
        check_size(q, model.n(), "q");
        check_size(u, model.m(), "u");
        Mat out(model.n(), model.n());
        model.dGudq(t, q, u, out);
        return out;
      }, py::arg("t"), py::arg("q"), py::arg("u"), "d/dq [G(t, q) u] (n x n; zero when G does not depend on q)")
      .def("linearize", [](const Model& model, double t, const Vec& q, const Vec& u) {
        check_size(q, model.n(), "q");
        check_size(u, model.m(), "u");
        Mat out(model.n(), model.n());
        linearize(model, t, q, u, out);
        return out;
      }, py::arg("t"), py::arg("q"), py::arg("u"), "d/dq [f(t, q) + G(t, q) u] (A_e(t) at q_d(t), u_d(t))")
      .def("constant_input_matrices", &Model::constant_input_matrices)
      .def("state_dependent_inputs", &Model::state_dependent_inputs)
      .def("jacobian_method", &Model::jacobian_method,
           "how dfdq is obtained: analytic, automatic differentiation, complex step or central differences")
      .def("error_split", [](const Model& model, double t, const Vec& q_d, const Vec& u_d, const Vec& q_e) {
        check_size(q_d, model.n(), "q_d");
        check_size(u_d, model.m(), "u_d");
        check_size(q_e, model.n(), "q_e");
        Mat A(model.n(), model.n());
        Vec alpha(model.n());
        model.error_split(t, q_d, u_d, q_e, A, alpha);
        return py::make_tuple(A, alpha);
      }, py::arg("t"), py::arg("q_d"), py::arg("u_d"), py::arg("q_e"),
         "(A, alpha) of f_e = A(t, q_e) q_e + alpha (paper 26-31; f_e includes G(q) u_d - G(q_d) u_d)")
      .def("C", &Model::C, py::arg("t"), "measurement matrix of y = C q + E w (paper eq. 25)")
      .def("noise_channels", &Model::noise_channels, "the w channels that carry measurement noise")
      .def("remainder_bound", [](const Model& model, double t, const Vec& q_d, double radius) {
        check_size(q_d, model.n(), "q_d");
        return model.remainder_bound(t, q_d, radius);
      }, py::arg("t"), py::arg("q_d"), py::arg("radius"),
         "L with |f_e - A_e q_e| <= L |q_e|^2 for |q_e| <= radius, or NaN if the model has none")
      .def("state_names", &Model::state_names)
      .def("position_indices", &Model::position_indices)
      .def("heading_index", &Model::heading_index)
      .def("named_parameters",
           [](const Model& model) {
             py::typing::Dict<py::str, py::float_> parameters;
             for (const auto& [name, value] : model.named_parameters()) parameters[py::str(name)] = value;
             return parameters;
           },
           "the parameters by name, the keys of the model's scenario-file section ([model], [plant]); a matrix"
           " entry as NAME[i][j] (from 0); empty for a model without named parameters. A model implemented in"
           " Python may define it (returning a dict of numbers)")
      .def("__getstate__", [](const Model& model) -> py::tuple {
        cannot_pickle(str_cat("the model '", model.name(), "'"),
                      "a model implemented in Python does not pickle (ShipModel and LinearModel do)");
      });

  bind_options<ShipParameters>(m, "ShipParameters", "Parameters of the ship of paper eqs. (1)-(6)");

  py::class_<ShipModel, Model, py::smart_holder>(m, "ShipModel", "The underactuated ship of paper eqs. (1)-(6)")
      .def(py::init<const ShipParameters&>(), py::arg("parameters") = ShipParameters{})
      .def("parameters", &ShipModel::parameters)
      .def(py::pickle(
          [](const ShipModel& model) { return py::make_tuple<py::return_value_policy::copy>(model.parameters()); },
          [](const py::tuple& state) {
            check_state(state, 1, "ShipModel");
            return std::make_shared<ShipModel>(state[0].cast<ShipParameters>());
          }));

  py::class_<LinearModel, Model, py::smart_holder>(
      m, "LinearModel",
      "dq/dt = A q + B u + D w; with C (p x n), y = C q + noise on p extra w channels")
      .def(py::init<Mat, Mat, Mat, Mat>(), py::arg("A"), py::arg("B"), py::arg("D"), py::arg("C") = Mat())
      .def("A", &LinearModel::A)
      .def("B", &LinearModel::B)
      .def("process_D", &LinearModel::process_D, "D as given to the constructor (without the noise channels)")
      .def("measurement_C", &LinearModel::measurement_C, "C as given to the constructor (empty if none)")
      .def(py::pickle(
          [](const LinearModel& model) {
            return py::make_tuple(model.A(), model.B(), model.process_D(), model.measurement_C());
          },
          [](const py::tuple& state) {
            check_state(state, 4, "LinearModel");
            return std::make_shared<LinearModel>(state[0].cast<Mat>(), state[1].cast<Mat>(), state[2].cast<Mat>(),
                                                 state[3].cast<Mat>());
          }));

  py::class_<FleetModel, Model, py::smart_holder>(
      m, "FleetModel", "count independent copies of a model stacked block-diagonally (fleet.hpp)")
      .def(py::init<ModelPtr, int>(), py::arg("member"), py::arg("count"))
      .def("member", &FleetModel::member)
      .def("count", &FleetModel::count)
      .def(py::pickle(
          [](const FleetModel& model) { return py::make_tuple(model.member(), model.count()); },
          [](const py::tuple& state) {
            check_state(state, 2, "FleetModel");
            return std::make_shared<FleetModel>(state[0].cast<ModelPtr>(), state[1].cast<int>());
          }));

  // ---- the built-in vehicles (vehicles.hpp): parameters and models, pickled by value ----
  bind_options<FossenVesselParameters>(
      m, "FossenVesselParameters",
      "M (mass) and D (damping) of the 3-DOF vessel in Fossen's form; defaults: the supply vessel (bis units)")
      .def_static("supply_vessel", &FossenVesselParameters::supply_vessel,
                  "Fossen, Sagatun and Sorensen (1996), in bis units (the defaults)");
  bind_options<HovercraftParameters>(m, "HovercraftParameters",
                                     "Damping per unit mass (d) and inertia (d_r) of the planar hovercraft (1/s)");
  bind_options<PlanarVtolParameters>(m, "PlanarVtolParameters",
                                     "Gravity g and coupling epsilon of the planar VTOL (normalized units)");
  bind_options<AuvParameters>(m, "AuvParameters",
                              "Masses (kg, kg m^2) and drag coefficients of the AUV; defaults: the Sirene AUV")
      .def_static("sirene", &AuvParameters::sirene, "Aguiar and Pascoal (2007) (the defaults)");
  bind_vehicle<FossenVessel, FossenVesselParameters>(
      m, "FossenVessel", "3-DOF underactuated surface vessel M nu' + C(nu) nu + D nu = tau (vehicles.hpp)");
  bind_vehicle<Hovercraft, HovercraftParameters>(m, "Hovercraft",
                                                 "Planar hovercraft in inertial coordinates (vehicles.hpp)");
  bind_vehicle<PlanarVtol, PlanarVtolParameters>(
      m, "PlanarVtol", "Planar VTOL aircraft of Hauser, Sastry and Meyer (1992) (vehicles.hpp)");
  bind_vehicle<Auv, AuvParameters>(m, "Auv", "Underactuated AUV in the horizontal plane (vehicles.hpp)");

  py::class_<GeneratedModel, Model, py::smart_holder>(
      m, "GeneratedModel",
      "A model evaluated by CasADi-generated C code (generated_model.hpp; build it with "
      "hinf_cpp.symbolic.SymbolicModel)")
      .def(py::init<const std::string&, const std::map<std::string, double>&>(), py::arg("metadata_path"),
           py::arg("parameters") = std::map<std::string, double>{})
      .def("metadata_path", &GeneratedModel::metadata_path)
      .def("library_path", &GeneratedModel::library_path)
      .def("parameter_names", &GeneratedModel::parameter_names)
      .def("parameters", &GeneratedModel::parameters)
      .def(py::pickle(
          [](const GeneratedModel& model) { return py::make_tuple(model.metadata_path(), model.parameters()); },
          [](const py::tuple& state) {
            check_state(state, 2, "GeneratedModel");
            return std::make_shared<GeneratedModel>(state[0].cast<std::string>(),
                                                    state[1].cast<std::map<std::string, double>>());
          }));

  py::class_<ModelStructure>(m, "ModelStructure", "What a model says about itself (model.hpp)")
      .def(py::init<>())
      .def_readwrite("name", &ModelStructure::name)
      .def_readwrite("n", &ModelStructure::n)
      .def_readwrite("m", &ModelStructure::m)
      .def_readwrite("nw", &ModelStructure::nw)
      .def_readwrite("state_names", &ModelStructure::state_names)
      .def_readwrite("position_indices", &ModelStructure::position_indices)
      .def_readwrite("heading_index", &ModelStructure::heading_index)
      .def_readwrite("noise_channels", &ModelStructure::noise_channels)
      .def_readwrite("constant_input_matrices", &ModelStructure::constant_input_matrices)
      .def_readwrite("state_dependent_inputs", &ModelStructure::state_dependent_inputs);
  m.def("check_model_structure", &check_structure, py::arg("structure"),
        "ValueError naming the first fault of a model's structure (names per state, indices in range)");

  // ---- options ----
  bind_options<SolverOptions>(m, "SolverOptions", "Integrator and tolerances ([solver] of a scenario)");
  bind_options<SimulationOptions>(m, "SimulationOptions",
                                  "How a closed loop is simulated ([output] dt and [solver] of a scenario)");
  bind_options<TrajectoryOptions>(m, "TrajectoryOptions", "Tolerances of the desired trajectory's integration");

  // ---- dense output, trajectory ----
  py::class_<PiecewisePolynomial>(m, "PiecewisePolynomial", "Dense output of an ODE solve: one polynomial per step")
      .def("dim", &PiecewisePolynomial::dim)
      .def("num_pieces", &PiecewisePolynomial::num_pieces)
      .def("empty", &PiecewisePolynomial::empty)
      .def("t_min", &PiecewisePolynomial::t_min)
      .def("t_max", &PiecewisePolynomial::t_max)
      .def("eval", [](const PiecewisePolynomial& p, const py::object& t) {
        return vectorize(t, p.dim(), 0, [&p](double tt, double* out) { p.eval(tt, out); });
      }, py::arg("t"))
      .def("eval_derivative", [](const PiecewisePolynomial& p, const py::object& t) {
        return vectorize(t, p.dim(), 0, [&p](double tt, double* out) { p.eval_derivative(tt, out); });
      }, py::arg("t"))
      .def("breakpoints", &PiecewisePolynomial::breakpoints, "the ends of the pieces, increasing")
      .def("memory_bytes", &PiecewisePolynomial::memory_bytes)
      .def(py::pickle(&dense_state, &dense_from_state));

  bind_result<StepStats>(m, "StepStats", "Counts of an integration", /*repr=*/true);

  py::class_<Trajectory, py::smart_holder>(m, "Trajectory", "Desired trajectory of paper eq. (8) with dense output")
      .def(py::init([](ModelPtr model, Vec q_d0, const py::object& u_d, double t0, double tf,
                       const TrajectoryOptions& options) {
             require(model != nullptr, "Trajectory needs a model");
             VectorSignal inputs = to_vector_signal(u_d, model->m(), "u_d");
             py::gil_scoped_release release;
             return std::make_shared<Trajectory>(std::move(model), std::move(q_d0), std::move(inputs), t0, tf,
                                                 options);
           }),
           py::arg("model"), py::arg("q_d0"), py::arg("u_d"), py::arg("t0"), py::arg("tf"),
           py::arg("options") = TrajectoryOptions{},
           "u_d: a VectorSignal, a callable u_d(t) -> array, or a list of Signals/numbers")
      .def("model", &Trajectory::model_ptr)
      .def("n", &Trajectory::n)
      .def("m", &Trajectory::m)
      .def("t0", &Trajectory::t0)
      .def("tf", &Trajectory::tf)
      .def("q_d0", &Trajectory::q_d0)
      .def("u_d_signal", &Trajectory::u_d_signal)
      .def("q_d", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.n(), 0, [&tr](double tt, double* out) { tr.q_d(tt, out); });
      }, py::arg("t"))
      .def("u_d", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.m(), 0, [&tr](double tt, double* out) { tr.u_d(tt, out); });
      }, py::arg("t"))
      .def("A_e", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.n(), tr.n(), [&tr](double tt, double* out) {
          Eigen::Map<Mat>(out, tr.n(), tr.n()) = tr.A_e(tt);
        });
      }, py::arg("t"), "d/dq [f + G u_d] at q_d(t)")
      .def("B_e", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.n(), tr.m(), [&tr](double tt, double* out) {
          Eigen::Map<Mat>(out, tr.n(), tr.m()) = tr.B_e(tt);
        });
      }, py::arg("t"), "G(t, q_d(t))")
      .def("D_e", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.n(), tr.model().nw(), [&tr](double tt, double* out) {
          Eigen::Map<Mat>(out, tr.n(), tr.model().nw()) = tr.D_e(tt);
        });
      }, py::arg("t"), "D(t, q_d(t))")
      .def("dense", &Trajectory::dense, py::return_value_policy::reference_internal)
      .def("stats", &Trajectory::stats)
      .def(py::pickle(
          [](const Trajectory& tr) {
            return py::make_tuple<py::return_value_policy::copy>(tr.model_ptr(), tr.q_d0(), tr.u_d_signal(), tr.t0(),
                                                                 tr.tf(), tr.dense(), tr.stats());
          },
          [](const py::tuple& state) {
            check_state(state, 7, "Trajectory");
            return std::make_shared<Trajectory>(state[0].cast<ModelPtr>(), state[1].cast<Vec>(),
                                                state[2].cast<VectorSignal>(), state[3].cast<double>(),
                                                state[4].cast<double>(), state[5].cast<PiecewisePolynomial>(),
                                                state[6].cast<StepStats>());
          }));

  // ---- Riccati equations ----
  bind_result<SolveStats>(m, "SolveStats", "Counts and stored size of a Riccati solve", /*repr=*/true);

  py::class_<SymmetricSolution, py::smart_holder>(m, "SymmetricSolution",
                                                  "A symmetric-matrix-valued solution X(t) on [t0, tf] (dense output)")
      .def("trajectory", &SymmetricSolution::trajectory_ptr)
      .def("n", &SymmetricSolution::n)
      .def("gamma", &SymmetricSolution::gamma)
      .def("t0", &SymmetricSolution::t0)
      .def("tf", &SymmetricSolution::tf)
      .def("value", [](const SymmetricSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &SymmetricSolution::value);
      }, py::arg("t"), "X(t): (n, n) for a number, (len(t), n, n) for an array")
      .def("derivative", [](const SymmetricSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &SymmetricSolution::derivative);
      }, py::arg("t"))
      .def("eigenvalue_range", &range<SymmetricSolution>, py::arg("times"),
           "(smallest, largest) eigenvalue of X over the given times")
      .def("eigenvalue_bounds", &bounds<SymmetricSolution>,
           "(m, M) with m I <= X(t) <= M I on [t0, tf] (paper eq. 22)")
      .def("dense", &SymmetricSolution::dense, py::return_value_policy::reference_internal)
      .def("stats", &SymmetricSolution::stats);

  py::class_<RiccatiSolution, SymmetricSolution, py::smart_holder> riccati(m, "RiccatiSolution",
                                                                           "Z(t) of the GRDE (13) on [t0, tf]");
  riccati.def("m", &RiccatiSolution::m)
      .def("Z", [](const RiccatiSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &RiccatiSolution::Z);
      }, py::arg("t"), "Z(t): (n, n) for a number, (len(t), n, n) for an array")
      .def("dZdt", [](const RiccatiSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &RiccatiSolution::dZdt);
      }, py::arg("t"))
      .def("gain", [](const RiccatiSolution& s, const py::object& t) {
        return vectorize(t, s.m(), s.n(), [&s](double tt, double* out) { s.gain(tt, out); });
      }, py::arg("t"), "K(t) = B' Z(t): (m, n) for a number, (len(t), m, n) for an array");
  def_solution_pickle(riccati);

  py::class_<FilterRiccatiSolution, SymmetricSolution, py::smart_holder> filter(
      m, "FilterRiccatiSolution", "Sigma(t) of the filter Riccati equation (36), A = A_e(t)");
  filter.def("Sigma", [](const FilterRiccatiSolution& s, const py::object& t) {
          return matrix_of_t(s, t, &FilterRiccatiSolution::Sigma);
        }, py::arg("t"))
      .def("dSigma_dt", [](const FilterRiccatiSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &FilterRiccatiSolution::dSigma_dt);
      }, py::arg("t"));
  def_solution_pickle(filter);

  m.def("solve_grde", &solve_grde, py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"),
        py::arg("options") = SolverOptions{}, py::call_guard<py::gil_scoped_release>(),
        "Solve the GRDE (13) backward from Z(tf) = Qf; raises ConjugatePointError when gamma <= gamma*");
  m.def("solve_filter_riccati", &solve_filter_riccati, py::arg("trajectory"), py::arg("N"), py::arg("Q"),
        py::arg("gamma"), py::arg("Sigma0"), py::arg("options") = SolverOptions{},
        py::call_guard<py::gil_scoped_release>(),
        "Solve the filter Riccati equation (36) forward from Sigma(t0) = Sigma0 with A = A_e(t)");
  m.def("grde_escape_time", &grde_escape_time, py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"),
        py::arg("options") = SolverOptions{}, py::call_guard<py::gil_scoped_release>(),
        "Time of the first conjugate point of the GRDE on [t0, tf] (integrating backward), NaN if none");
  m.def("filter_escape_time", &filter_escape_time, py::arg("trajectory"), py::arg("N"), py::arg("Q"),
        py::arg("gamma"), py::arg("Sigma0"), py::arg("options") = SolverOptions{},
        py::call_guard<py::gil_scoped_release>(),
        "Time of the first escape of the filter Riccati equation (36) on [t0, tf], NaN if none");

  // ---- controllers and disturbances ----
  py::class_<Controller, PyController, py::smart_holder>(m, "Controller",
                                                         "Tracking controller u = control(t, q)")
      .def(py::init<>())
      .def("name", &Controller::name)
      .def("n", &Controller::n, "the state size (0: a Python controller that does not say)")
      .def("m", &Controller::m)
      .def("control", [](Controller& c, double t, const Vec& q) {
        check_finite(t, "t");
        if (c.n() > 0) check_size(q, c.n(), "q");
        Vec u(c.m());
        c.control(t, q, u);
        return u;
      }, py::arg("t"), py::arg("q"));

  py::class_<HinfStateFeedback, Controller, py::smart_holder>(m, "HinfStateFeedback",
                                                              "u = u_d - kappa B' Z (q - q_d), paper (17)/(18)")
      .def(py::init([](RiccatiSolutionPtr solution, const py::object& kappa) {
             return std::make_shared<HinfStateFeedback>(std::move(solution), to_signal(kappa, "kappa"));
           }),
           py::arg("solution"), py::arg("kappa") = Signal(1.0))
      .def("solution", &HinfStateFeedback::solution, py::return_value_policy::reference_internal)
      .def("kappa", &HinfStateFeedback::kappa)
      .def("checked_kappa", &HinfStateFeedback::checked_kappa, py::arg("t"), "kappa(t); a ValueError if not > 0");

  bind_options<CascadeGains>(m, "CascadeGains", "Gains k, k1, k2 > 0 of the cascade baseline");

  py::class_<CascadeController, Controller, py::smart_holder>(
      m, "CascadeController", "Cascaded tracking baseline for the ship (Lefeber, Pettersen, Nijmeijer type)")
      .def(py::init<TrajectoryPtr, const CascadeGains&>(), py::arg("trajectory"), py::arg("gains") = CascadeGains{})
      .def("gains", &CascadeController::gains);
  m.def("wrap_angle", &wrap_angle, py::arg("angle"), "the angle wrapped to (-pi, pi]");

  py::class_<Disturbance>(m, "Disturbance",
                          "w(t, q) = signals(t) [+ gamma^-2 D' Z q_e, the worst case of paper eq. (16)]")
      .def(py::init<VectorSignal>(), py::arg("signals"))
      .def(py::init<VectorSignal, RiccatiSolutionPtr>(), py::arg("signals"), py::arg("design"),
           "signals plus the worst-case disturbance of the design (a finite gamma)")
      .def("dim", &Disturbance::dim)
      .def("worst_case", &Disturbance::worst_case)
      .def("design", &Disturbance::design)
      .def("signals", &Disturbance::signals)
      .def("eval", [](const Disturbance& d, double t, const Vec& q) {
        check_finite(t, "t");
        if (d.design()) check_size(q, d.design()->n(), "q");
        Vec w(d.dim());
        d.eval(t, q.data(), w.data());
        return w;
      }, py::arg("t"), py::arg("q"), "w at time t for the actual state q (used by the worst case only)");
  py::implicitly_convertible<VectorSignal, Disturbance>();

  // ---- simulation ----
  bind_result<EstimatorSeries>(m, "EstimatorSeries", "The estimator's series of an output-feedback run (paper §4)",
                               /*repr=*/false);

  bind_result<SimulationResult>(m, "SimulationResult", "Time series on the output grid, one row per time",
                                /*repr=*/false)
      .def_property_readonly("estimator", [](const SimulationResult& r) -> const EstimatorSeries* {
        return r.estimator ? &*r.estimator : nullptr;
      }, py::return_value_policy::reference_internal, "the estimator's series (output feedback), else None")
      .def("q_e", &SimulationResult::q_e, "q - q_d, the heading component wrapped to (-pi, pi]");

  m.def("output_grid", &output_grid, py::arg("t0"), py::arg("tf"), py::arg("dt"));
  m.def("output_count", &output_count, py::arg("t0"), py::arg("tf"), py::arg("dt"));
  m.def("simulate_state_feedback",
        [](const Trajectory& trajectory, Controller& controller, const py::object& disturbance, const Vec& q0,
           const SimulationOptions& options, const std::optional<ModelPtr>& plant) {
          check_controller_fits(controller, trajectory.model());
          const Disturbance w = to_disturbance(disturbance, trajectory.model().nw());
          py::gil_scoped_release release;
          return simulate_state_feedback(trajectory, controller, w, q0, options, plant ? plant->get() : nullptr);
        },
        py::arg("trajectory"), py::arg("controller"), py::arg("disturbance"), py::arg("q0"),
        py::arg("options") = SimulationOptions{}, py::arg("plant") = py::none(),
        "Closed loop under state feedback (paper eq. 7); disturbance: a Disturbance, a VectorSignal, a callable"
        " w(t) -> array, a list of Signals/numbers, or None (zero); plant: the vehicle integrated (None: the"
        " trajectory's model)");

  bind_options<OutputFeedbackProblem>(m, "OutputFeedbackProblem",
                                      "The output-feedback problem: design, measurement noise, filter weights"
                                      " (paper §4); noise: standard normal samples, one row per hold interval",
                                      &check_problem);
  bind_options<OutputFeedbackOptions>(m, "OutputFeedbackOptions", "Choices of the output-feedback loop (paper §4)");

  m.def("noise_sample_count", &noise_sample_count, py::arg("t0"), py::arg("tf"), py::arg("period"));
  m.def("standard_normal_samples",
        [](std::uint64_t seed, long count, int channels) {
          // A few GB at most: an absurd count is an input error, not an attempt to allocate it.
          constexpr double kMaxNumbers = 1e9;
          require(count >= 0, "count must be >= 0, got ", count);
          check_dimension(channels, 0, "channels");
          require(static_cast<double>(count) * channels <= kMaxNumbers, "standard_normal_samples: count x channels = ",
                  count, " x ", channels, " is more than the ", kMaxNumbers, " numbers (8 GB) allowed");
          py::gil_scoped_release release;
          return standard_normal_samples(seed, count, channels);
        },
        py::arg("seed"), py::arg("count"), py::arg("channels"),
        "Seeded standard normal samples, one row per sample (mt19937_64, polar method)");
  m.def("simulate_output_feedback",
        [](const OutputFeedbackProblem& problem, Controller& controller, const py::object& disturbance,
           const Vec& q0, const OutputFeedbackOptions& options, const SimulationOptions& simulation,
           const std::optional<ModelPtr>& plant) {
          require(problem.design != nullptr, "the output-feedback problem needs a design (a GRDE solution)");
          const Model& model = problem.design->trajectory().model();
          check_controller_fits(controller, model);
          const Disturbance w = to_disturbance(disturbance, model.nw());
          py::gil_scoped_release release;
          return simulate_output_feedback(problem, controller, w, q0, options, simulation,
                                          plant ? plant->get() : nullptr);
        },
        py::arg("problem"), py::arg("controller"), py::arg("disturbance"), py::arg("q0"),
        py::arg("options") = OutputFeedbackOptions{}, py::arg("simulation") = SimulationOptions{},
        py::arg("plant") = py::none(),
        "Output-feedback closed loop (paper 34-36): filter and estimator of the problem's design, control by"
        " `controller` at the estimated state; disturbance as in simulate_state_feedback; plant: the vehicle"
        " integrated (None: the design's model)");

  // ---- metrics (metrics.hpp: metric_table() is their one definition) ----
  py::class_<MetricDefinition>(m, "MetricDefinition", "One metric of a run: name, label, unit, definition")
      .def_readonly("name", &MetricDefinition::name, "its key in the results file and Metrics' property")
      .def_readonly("label", &MetricDefinition::label)
      .def_readonly("unit", &MetricDefinition::unit)
      .def_readonly("definition", &MetricDefinition::definition)
      .def("__repr__", [](const MetricDefinition& d) { return str_cat("MetricDefinition('", d.name, "')"); });
  m.def("metric_table", [] { return std::vector<MetricDefinition>(metric_table().begin(), metric_table().end()); },
        "The metrics of a run, in the order of the results file");

  py::class_<Metrics> metrics(m, "Metrics", "Metrics of a closed-loop run (metric_table() defines each)");
  for (const MetricDefinition& d : metric_table()) {
    const auto member = d.value;
    metrics.def_property_readonly(d.name, [member](const Metrics& x) { return x.*member; }, d.definition);
  }
  metrics.def("__repr__", &metrics_repr)
      .def("__eq__", [](const Metrics& a, const Metrics& b) { return same(a, b); }, py::is_operator())
      .def(py::pickle(
          [](const Metrics& x) {
            py::list state;
            for (const MetricDefinition& d : metric_table()) state.append(x.*(d.value));
            return py::tuple(state);
          },
          [](const py::tuple& state) {
            check_state(state, kMetricCount, "Metrics");
            Metrics x;
            std::size_t i = 0;
            for (const MetricDefinition& d : metric_table()) x.*(d.value) = state[i++].cast<double>();
            return x;
          }));
  m.def("compute_metrics", &compute_metrics, py::arg("model"), py::arg("run"), py::arg("Q"));
  m.def("l2_norm", &l2_norm, py::arg("t"), py::arg("series"),
        "sqrt of the trapezoid integral of the squared row norms of series over times t");

  // ---- gamma* and certificates (paper §3) ----
  bind_options<GammaStarOptions>(m, "GammaStarOptions",
                                 "Options of the gamma* search. threads: gammas evaluated in parallel per round"
                                 " (one for a model implemented in Python, whose calls hold the GIL)");
  bind_result<GammaTrial>(m, "GammaTrial", "One gamma tried by the gamma* search", /*repr=*/true);
  bind_result<GammaStarResult>(m, "GammaStarResult", "gamma*, the final bracket and every gamma tried", /*repr=*/false)
      .def("__repr__", [](const GammaStarResult& r) {
        return str_cat("GammaStarResult(gamma_star=", r.gamma_star, ", bracket=[", r.lower, ", ", r.upper,
                       "], binding='", to_string(r.binding), "', t_escape_lower=", r.t_escape_lower,
                       ", evaluations=", r.trials.size(), ")");
      });

  m.def("gamma_star",
        [](const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, const GammaStarOptions& options) {
          return gamma_star(trajectory, Q, Qf, serial_for_python_models(model_of(trajectory), options));
        },
        py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("options") = GammaStarOptions{},
        py::call_guard<py::gil_scoped_release>(),
        "gamma* (paper eq. 14): the smallest gamma without a conjugate point of the GRDE on [t0, tf]");
  m.def("gamma_star_output_feedback",
        [](const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, const Mat& N, const Mat& Sigma0,
           const GammaStarOptions& options) {
          return gamma_star_output_feedback(trajectory, Q, Qf, N, Sigma0,
                                            serial_for_python_models(model_of(trajectory), options));
        },
        py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("N"), py::arg("Sigma0"),
        py::arg("options") = GammaStarOptions{}, py::call_guard<py::gil_scoped_release>(),
        "The smallest gamma for output feedback: GRDE, filter (36) with A_e and rho(Sigma Z) < gamma^2");
  m.def("max_rho_sigma_z",
        [](const RiccatiSolution& Z, const FilterRiccatiSolution& Sigma) {
          require(Z.n() == Sigma.n(), "max_rho_sigma_z: Z is ", Z.n(), " x ", Z.n(), " but Sigma is ", Sigma.n(), " x ",
                  Sigma.n(), ": pass the solutions of one design");
          py::gil_scoped_release release;
          return max_rho_sigma_z(Z, Sigma);
        },
        py::arg("Z"), py::arg("Sigma"), "(max over [t0, tf] of rho(Sigma Z), where)");

  bind_result<Certificates>(m, "Certificates", "The stability certificates of paper §3 (eqs. 22-24)", /*repr=*/true);
  m.def("certify",
        [](const RiccatiSolution& Z, const py::object& kappa, const Mat& Q) {
          const Signal k = to_signal(kappa, "kappa");
          py::gil_scoped_release release;
          return certify(Z, k, Q);
        },
        py::arg("Z"), py::arg("kappa"), py::arg("Q"),
        "The certificates of paper §3 for a design Z (its gamma), the gain scaling kappa(t) and the weight Q");

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
      .def("__copy__", [](const Scenario& s) { return Scenario(s); })
      .def(py::pickle(
          [](const Scenario& s) { return py::make_tuple(scenario_text(s), s.solver.escape_norm); },
          [](const py::tuple& state) {
            check_state(state, 2, "Scenario");
            Scenario s = parse_scenario_toml(state[0].cast<std::string>(), "<pickle>");
            s.solver.escape_norm = state[1].cast<double>();
            return s;
          }));

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
                             "Options of run_study. threads: worker threads (0: the hardware's; never more than"
                             " runs; one when a model or signal is implemented in Python); share_designs: compute each"
                             " distinct design (trajectory and Riccati solutions) once");
  bind_result<StudyRun>(m, "StudyRun",
                        "One row of run_study: status (its name: 'completed', 'diverged', 'conjugate_point',"
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
  m.def("run_study",
        [](const std::vector<Scenario>& scenarios, StudyOptions options,
           const std::optional<std::function<void(std::size_t, std::size_t)>>& progress) {
          // Every call into Python holds the GIL: runs of a model or signals implemented in
          // Python would only contend for it.
          for (const Scenario& s : scenarios)
            if (dynamic_cast<const PyModel*>(s.model.get()) != nullptr || s.desired_u.is_function() ||
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
          return run_study(scenarios, options, report);
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

  // ---- scenario and results files (io/scenario_file.hpp, io/results.hpp) ----
  m.def("parse_scenario_toml", &parse_scenario_toml, py::arg("text"), py::arg("source"),
        "The one scenario reader (the one hinf-sim uses): same checks, same messages");
  m.def("load_scenario_toml", &load_scenario_toml, py::arg("path"), "Reads a scenario file (parse_scenario_toml)");
  m.def("needs_planning_toml", &needs_planning_toml, py::arg("text"), py::arg("source"),
        "Whether a scenario document's [desired] gives waypoints, a path or plan options (parsed with every guard"
        " of the reader)");
  m.def("parse_model_toml", &parse_model_toml, py::arg("text"), py::arg("source"),
        "The model of a document's [model] section, read as parse_scenario_toml reads it");
  m.def("scenario_toml", &scenario_toml, py::arg("scenario"),
        "The scenario as a scenario file that reads back to an equal scenario");
  m.def("parse_signal_toml", &parse_signal_toml, py::arg("text"), py::arg("key"), py::arg("source"),
        "A Signal from a TOML document whose one key is `key` (as in a scenario)");
  m.def("results_json", &results_json, py::arg("result"), py::arg("indent") = 2,
        "The results file of scenarios.md (JSON; non-finite numbers as null)");
  m.def("results_csv", &results_csv, py::arg("result"), "The time series on the output grid (CSV, one row per time)");

  bind_generated_function(m);

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
}
