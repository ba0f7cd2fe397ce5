// Python bindings of hinf_core: one block per type, argument names as in C++.
// C++ InputError arrives as ValueError; numerical failures as hinf_cpp.HinfError subclasses
// (SolverError, ConjugatePointError, CouplingConditionError) with their data as attributes.
// Long calls release the GIL; Python callables and Python subclasses re-acquire it.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <optional>

#include "hinf/analysis.hpp"
#include "hinf/checks.hpp"
#include "hinf/controller.hpp"
#include "hinf/errors.hpp"
#include "hinf/metrics.hpp"
#include "hinf/model.hpp"
#include "hinf/output_feedback.hpp"
#include "hinf/riccati.hpp"
#include "hinf/scenario.hpp"
#include "hinf/scenario_io.hpp"
#include "hinf/simulation.hpp"
#include "hinf/trajectory.hpp"

namespace py = pybind11;
using namespace hinf;

namespace {

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

// A Model implemented in Python: override n, m, nw, f(t, q), dfdq(t, q), B(t), D(t) (and
// optionally name, error_split, C, noise_channels, state_names, position_indices,
// heading_index, constant_input_matrices).
// Its structure (name, n, m, nw, state names, position and heading indices, noise channels,
// constant_input_matrices) is read once, on first use, validated (check_structure) and never
// asked again: everything downstream sizes its arrays by it. What f, dfdq, B, D, C and
// error_split return is checked against it at every call.
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

  Mat B(double t) const override {
    const ModelStructure& s = structure();
    py::gil_scoped_acquire gil;
    return finite_matrix(call("B", t), s.n, s.m, "the Python model's B(t)", t);
  }
  Mat D(double t) const override {
    const ModelStructure& s = structure();
    py::gil_scoped_acquire gil;
    return finite_matrix(call("D", t), s.n, s.nw, "the Python model's D(t)", t);
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
    out = matrix_result(call("dfdq", t, Vec(q)), n, n, "the Python model's dfdq(t, q)", t);
  }
  void error_split(double t, const ConstVecRef& q_d, const ConstVecRef& q_e, MatRef A,
                   VecRef alpha) const override {
    const int n = structure().n;
    require_sized(q_d.size() == n && q_e.size() == n && A.rows() == n && A.cols() == n && alpha.size() == n,
                  "error_split(t, q_d, q_e)");
    py::gil_scoped_acquire gil;
    py::function override = py::get_override(static_cast<const Model*>(this), "error_split");
    if (!override) {
      py::gil_scoped_release release;
      Model::error_split(t, q_d, q_e, A, alpha);
      return;
    }
    const char* subject = "the Python model's error_split(t, q_d, q_e)";
    const py::object value = override(t, Vec(q_d), Vec(q_e));
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

std::string repr_options(const SolverOptions& o) {
  return str_cat("SolverOptions(method='", to_string(o.method), "', rtol=", o.rtol, ", atol=", o.atol,
                 ", max_steps=", o.max_steps, ", escape_norm=", o.escape_norm,
                 ", divergence_factor=", o.divergence_factor, ")");
}

py::dict metrics_dict(const Metrics& mt) {
  py::dict d;
  d["rms_position_error_last_half"] = mt.rms_position_error_last_half;
  d["max_position_error"] = mt.max_position_error;
  d["final_position_error"] = mt.final_position_error;
  d["control_l2"] = mt.control_l2;
  d["control_error_l2"] = mt.control_error_l2;
  d["disturbance_l2"] = mt.disturbance_l2;
  d["l2_gain"] = mt.l2_gain;
  d["max_rho_sigma_z"] = mt.max_rho_sigma_z;
  d["rms_estimation_error_last_half"] = mt.rms_estimation_error_last_half;
  return d;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "hinf_cpp core: H-infinity tracking control of nonlinear underactuated vehicles";
  m.attr("__version__") = HINF_VERSION;
  register_exceptions(m);

  // ---- signals ----
  py::class_<Harmonic>(m, "Harmonic", "a sin(omega t + phase) (or cos) term of a Signal")
      .def(py::init([](double amplitude, double omega, double phase, bool cosine) {
             return Harmonic{amplitude, omega, phase, cosine};
           }),
           py::arg("amplitude"), py::arg("omega"), py::arg("phase") = 0.0, py::arg("cosine") = false)
      .def_readwrite("amplitude", &Harmonic::amplitude)
      .def_readwrite("omega", &Harmonic::omega)
      .def_readwrite("phase", &Harmonic::phase)
      .def_readwrite("cosine", &Harmonic::cosine)
      .def("__repr__", [](const Harmonic& h) {
        return str_cat("Harmonic(amplitude=", h.amplitude, ", omega=", h.omega, ", phase=", h.phase,
                       ", cosine=", h.cosine ? "True" : "False", ")");
      });

  py::class_<Signal>(m, "Signal", "A scalar signal of absolute time: offset + harmonics, or a table")
      .def(py::init<>())
      .def(py::init<double>(), py::arg("constant"))
      .def(py::init<double, std::vector<Harmonic>>(), py::arg("offset"), py::arg("harmonics"))
      .def_static("table", &Signal::table, py::arg("t"), py::arg("values"))
      .def("__call__", [](const Signal& s, const py::object& t) {
        return vectorize(t, 0, 0, [&s](double tt, double* out) { out[0] = s(tt); });
      })
      .def_property_readonly("offset", &Signal::offset)
      .def_property_readonly("harmonics", &Signal::harmonics)
      .def_property_readonly("is_table", &Signal::is_table)
      .def_property_readonly("table_t", &Signal::table_t)
      .def_property_readonly("table_values", &Signal::table_values)
      .def("__repr__", [](const Signal& s) { return "Signal(" + s.describe() + ")"; });
  py::implicitly_convertible<double, Signal>();

  py::class_<VectorSignal>(m, "VectorSignal", "A vector signal: one Signal per channel, or a function of t")
      .def(py::init([](const py::sequence& channels) { return VectorSignal(to_signals(channels, "channels")); }),
           py::arg("channels"))
      .def(py::init([](int dim, const py::function& function) {
             return vector_signal_from_callable(function, dim, "function");
           }),
           py::arg("dim"), py::arg("function"), "function(t) must return an array of dim numbers")
      .def_static("zeros", &VectorSignal::zeros, py::arg("dim"))
      .def_property_readonly("dim", &VectorSignal::dim)
      .def_property_readonly("is_function", &VectorSignal::is_function)
      .def_property_readonly("channels", &VectorSignal::channels)
      .def("__call__", [](const VectorSignal& s, const py::object& t) {
        return vectorize(t, s.dim(), 0, [&s](double tt, double* out) { s.eval(tt, out); });
      });

  // ---- models ----
  py::class_<Model, PyModel, py::smart_holder>(m, "Model", R"doc(
Control-affine model dq/dt = f(t, q) + B(t) u + D(t) w (paper eq. 7).
Subclass it in Python and implement n(), m(), nw(), f(t, q), dfdq(t, q), B(t), D(t). Its structure
(n, m, nw, name, state_names, position_indices, heading_index, noise_channels,
constant_input_matrices) is read once, when the library first needs it, and validated; it must not
change afterwards. What f, dfdq, B, D, C and error_split return is checked at every call.)doc")
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
      .def("B", &Model::B, py::arg("t"))
      .def("D", &Model::D, py::arg("t"))
      .def("constant_input_matrices", &Model::constant_input_matrices)
      .def("error_split", [](const Model& model, double t, const Vec& q_d, const Vec& q_e) {
        check_size(q_d, model.n(), "q_d");
        check_size(q_e, model.n(), "q_e");
        Mat A(model.n(), model.n());
        Vec alpha(model.n());
        model.error_split(t, q_d, q_e, A, alpha);
        return py::make_tuple(A, alpha);
      }, py::arg("t"), py::arg("q_d"), py::arg("q_e"))
      .def("C", &Model::C, py::arg("t"), "measurement matrix of y = C q + E w (paper eq. 25)")
      .def("noise_channels", &Model::noise_channels, "the w channels that carry measurement noise")
      .def("state_names", &Model::state_names)
      .def("position_indices", &Model::position_indices)
      .def("heading_index", &Model::heading_index);

  py::class_<ShipParameters>(m, "ShipParameters")
      .def(py::init([](double m_u, double m_v, double m_r, double d_u, double d_v, double d_r) {
             return ShipParameters{m_u, m_v, m_r, d_u, d_v, d_r};
           }),
           py::arg("m_u") = 0.5, py::arg("m_v") = -2.0, py::arg("m_r") = 0.5, py::arg("d_u") = 1.0,
           py::arg("d_v") = 2.0, py::arg("d_r") = 1.0)
      .def_readwrite("m_u", &ShipParameters::m_u)
      .def_readwrite("m_v", &ShipParameters::m_v)
      .def_readwrite("m_r", &ShipParameters::m_r)
      .def_readwrite("d_u", &ShipParameters::d_u)
      .def_readwrite("d_v", &ShipParameters::d_v)
      .def_readwrite("d_r", &ShipParameters::d_r)
      .def("__repr__", [](const ShipParameters& p) {
        return str_cat("ShipParameters(m_u=", p.m_u, ", m_v=", p.m_v, ", m_r=", p.m_r, ", d_u=", p.d_u,
                       ", d_v=", p.d_v, ", d_r=", p.d_r, ")");
      });

  py::class_<ShipModel, Model, py::smart_holder>(m, "ShipModel", "The underactuated ship of paper eqs. (1)-(6)")
      .def(py::init<const ShipParameters&>(), py::arg("parameters") = ShipParameters{})
      .def_property_readonly("parameters", &ShipModel::parameters);

  py::class_<LinearModel, Model, py::smart_holder>(
      m, "LinearModel",
      "dq/dt = A q + B u + D w; with C (p x n), y = C q + noise on p extra w channels")
      .def(py::init([](Mat A, Mat B, Mat D, const std::optional<Mat>& C) {
             return std::make_shared<LinearModel>(std::move(A), std::move(B), std::move(D), C.value_or(Mat()));
           }),
           py::arg("A"), py::arg("B"), py::arg("D"), py::arg("C") = py::none())
      .def_property_readonly("A", &LinearModel::A);

  // ---- solver options ----
  py::class_<SolverOptions>(m, "SolverOptions", "Integrator and tolerances ([solver] of a scenario)")
      .def(py::init([](const std::string& method, double rtol, double atol, long max_steps, double escape_norm,
                       double divergence_factor) {
             SolverOptions o;
             o.method = from_string<Method>(method);
             o.rtol = rtol;
             o.atol = atol;
             o.max_steps = max_steps;
             o.escape_norm = escape_norm;
             o.divergence_factor = divergence_factor;
             o.validate();
             return o;
           }),
           py::arg("method") = "bdf", py::arg("rtol") = 1e-8, py::arg("atol") = 1e-10,
           py::arg("max_steps") = 500000, py::arg("escape_norm") = 1e6, py::arg("divergence_factor") = 1e3)
      .def_property("method", [](const SolverOptions& o) { return to_string(o.method); },
                    [](SolverOptions& o, const std::string& s) { o.method = from_string<Method>(s); })
      .def_readwrite("rtol", &SolverOptions::rtol)
      .def_readwrite("atol", &SolverOptions::atol)
      .def_readwrite("max_steps", &SolverOptions::max_steps)
      .def_readwrite("escape_norm", &SolverOptions::escape_norm)
      .def_readwrite("divergence_factor", &SolverOptions::divergence_factor)
      .def("validate", &SolverOptions::validate)
      .def("__repr__", &repr_options);

  // ---- trajectory ----
  py::class_<Trajectory, py::smart_holder>(m, "Trajectory", "Desired trajectory of paper eq. (8) with dense output")
      .def(py::init([](ModelPtr model, Vec q_d0, const py::object& u_d, double t0, double tf, double rtol,
                       double atol) {
             require(model != nullptr, "Trajectory needs a model");
             VectorSignal inputs = to_vector_signal(u_d, model->m(), "u_d");
             TrajectoryOptions options;
             options.rtol = rtol;
             options.atol = atol;
             py::gil_scoped_release release;
             return std::make_shared<Trajectory>(std::move(model), std::move(q_d0), std::move(inputs), t0,
                                                 tf, options);
           }),
           py::arg("model"), py::arg("q_d0"), py::arg("u_d"), py::arg("t0"), py::arg("tf"),
           py::arg("rtol") = 1e-10, py::arg("atol") = 1e-12,
           "u_d: a VectorSignal, a callable u_d(t) -> array, or a list of Signals/numbers")
      .def_property_readonly("model", &Trajectory::model_ptr)
      .def_property_readonly("t0", &Trajectory::t0)
      .def_property_readonly("tf", &Trajectory::tf)
      .def_property_readonly("n", &Trajectory::n)
      .def_property_readonly("m", &Trajectory::m)
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
      }, py::arg("t"))
      .def_property_readonly("num_steps", [](const Trajectory& tr) { return tr.stats().steps; });

  // ---- GRDE ----
  py::class_<SolveStats>(m, "SolveStats")
      .def_readonly("steps", &SolveStats::steps)
      .def_readonly("rejected", &SolveStats::rejected)
      .def_readonly("rhs_evals", &SolveStats::rhs_evals)
      .def_readonly("jac_evals", &SolveStats::jac_evals)
      .def_readonly("memory_bytes", &SolveStats::memory_bytes)
      .def("__repr__", [](const SolveStats& s) {
        return str_cat("SolveStats(steps=", s.steps, ", rejected=", s.rejected, ", rhs_evals=", s.rhs_evals,
                       ", jac_evals=", s.jac_evals, ", memory_bytes=", s.memory_bytes, ")");
      });

  py::class_<RiccatiSolution, py::smart_holder>(m, "RiccatiSolution", "Z(t) of the GRDE (13) on [t0, tf]")
      .def_property_readonly("trajectory", &RiccatiSolution::trajectory_ptr)
      .def_property_readonly("gamma", &RiccatiSolution::gamma)
      .def_property_readonly("t0", &RiccatiSolution::t0)
      .def_property_readonly("tf", &RiccatiSolution::tf)
      .def_property_readonly("n", &RiccatiSolution::n)
      .def_property_readonly("m", &RiccatiSolution::m)
      .def_property_readonly("stats", &RiccatiSolution::stats)
      .def("Z", [](const RiccatiSolution& s, const py::object& t) {
        return vectorize(t, s.n(), s.n(), [&s](double tt, double* out) {
          Eigen::Map<Mat>(out, s.n(), s.n()) = s.Z(tt);
        });
      }, py::arg("t"), "Z(t): (n, n) for a number, (len(t), n, n) for an array")
      .def("dZdt", [](const RiccatiSolution& s, const py::object& t) {
        return vectorize(t, s.n(), s.n(), [&s](double tt, double* out) {
          Eigen::Map<Mat>(out, s.n(), s.n()) = s.dZdt(tt);
        });
      }, py::arg("t"))
      .def("gain", [](const RiccatiSolution& s, const py::object& t) {
        return vectorize(t, s.m(), s.n(), [&s](double tt, double* out) { s.gain(tt, out); });
      }, py::arg("t"), "K(t) = B' Z(t): (m, n) for a number, (len(t), m, n) for an array")
      .def("step_times", [](const RiccatiSolution& s) { return s.dense().breakpoints(); })
      .def("eigenvalue_bounds", [](const RiccatiSolution& s) {
        double lo = 0, hi = 0;
        s.eigenvalue_bounds(lo, hi);
        return py::make_tuple(lo, hi);
      }, "(m, M) with m I <= Z(t) <= M I on [t0, tf] (paper eq. 22)")
      .def("eigenvalue_range", [](const RiccatiSolution& s, const std::vector<double>& times) {
        require(!times.empty(), "eigenvalue_range needs at least one time");
        double lo = 0, hi = 0;
        s.eigenvalue_range(times, lo, hi);
        return py::make_tuple(lo, hi);
      }, py::arg("times"));

  py::class_<FilterRiccatiSolution, py::smart_holder>(m, "FilterRiccatiSolution",
                                                      "Sigma(t) of the filter Riccati equation (36), A = A_e(t)")
      .def_property_readonly("trajectory", &FilterRiccatiSolution::trajectory_ptr)
      .def_property_readonly("gamma", &FilterRiccatiSolution::gamma)
      .def_property_readonly("t0", &FilterRiccatiSolution::t0)
      .def_property_readonly("tf", &FilterRiccatiSolution::tf)
      .def_property_readonly("n", &FilterRiccatiSolution::n)
      .def_property_readonly("stats", &FilterRiccatiSolution::stats)
      .def("Sigma", [](const FilterRiccatiSolution& s, const py::object& t) {
        return vectorize(t, s.n(), s.n(), [&s](double tt, double* out) {
          Eigen::Map<Mat>(out, s.n(), s.n()) = s.Sigma(tt);
        });
      }, py::arg("t"))
      .def("dSigma_dt", [](const FilterRiccatiSolution& s, const py::object& t) {
        return vectorize(t, s.n(), s.n(), [&s](double tt, double* out) {
          Eigen::Map<Mat>(out, s.n(), s.n()) = s.dSigma_dt(tt);
        });
      }, py::arg("t"))
      .def("step_times", [](const FilterRiccatiSolution& s) { return s.dense().breakpoints(); })
      .def("eigenvalue_bounds", [](const FilterRiccatiSolution& s) {
        double lo = 0, hi = 0;
        s.eigenvalue_bounds(lo, hi);
        return py::make_tuple(lo, hi);
      }, "the extreme eigenvalues of Sigma(t) on [t0, tf]")
      .def("eigenvalue_range", [](const FilterRiccatiSolution& s, const std::vector<double>& times) {
        require(!times.empty(), "eigenvalue_range needs at least one time");
        double lo = 0, hi = 0;
        s.eigenvalue_range(times, lo, hi);
        return py::make_tuple(lo, hi);
      }, py::arg("times"));

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

  m.def("solve_grde", &solve_grde, py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"),
        py::arg("options") = SolverOptions{}, py::call_guard<py::gil_scoped_release>(),
        "Solve the GRDE (13) backward from Z(tf) = Qf; raises ConjugatePointError when gamma <= gamma*");

  // ---- controllers and simulation ----
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
      .def_property_readonly("kappa", &HinfStateFeedback::kappa);

  py::class_<CascadeGains>(m, "CascadeGains", "Gains k, k1, k2 > 0 of the cascade baseline")
      .def(py::init([](double k, double k1, double k2) { return CascadeGains{k, k1, k2}; }), py::arg("k") = 0.2,
           py::arg("k1") = 2.0, py::arg("k2") = 3.0)
      .def_readwrite("k", &CascadeGains::k)
      .def_readwrite("k1", &CascadeGains::k1)
      .def_readwrite("k2", &CascadeGains::k2)
      .def("__repr__", [](const CascadeGains& g) {
        return str_cat("CascadeGains(k=", g.k, ", k1=", g.k1, ", k2=", g.k2, ")");
      });

  py::class_<CascadeController, Controller, py::smart_holder>(
      m, "CascadeController", "Cascaded tracking baseline for the ship (Lefeber, Pettersen, Nijmeijer type)")
      .def(py::init<TrajectoryPtr, const CascadeGains&>(), py::arg("trajectory"), py::arg("gains") = CascadeGains{})
      .def_property_readonly("gains", &CascadeController::gains);
  m.def("wrap_angle", &wrap_angle, py::arg("angle"), "the angle wrapped to (-pi, pi]");

  py::class_<Disturbance>(m, "Disturbance",
                          "w(t, q) = signals(t) [+ gamma^-2 D' Z q_e, the worst case of paper eq. (16)]")
      .def(py::init([](const py::object& signals, int dim) {
             return Disturbance(to_vector_signal(signals, dim, "signals"));
           }),
           py::arg("signals"), py::arg("dim"))
      .def(py::init([](const py::object& signals, const RiccatiSolutionPtr& design) {
             require(design != nullptr, "the worst-case disturbance needs a design");
             return Disturbance(to_vector_signal(signals, design->trajectory().model().nw(), "signals"), design);
           }),
           py::arg("signals"), py::arg("worst_case_design"))
      .def_property_readonly("dim", &Disturbance::dim)
      .def_property_readonly("worst_case", &Disturbance::worst_case)
      .def("__call__", [](const Disturbance& d, double t, const Vec& q) {
        check_finite(t, "t");
        if (d.design()) check_size(q, d.design()->n(), "q");
        Vec w(d.dim());
        d.eval(t, q.data(), w.data());
        return w;
      }, py::arg("t"), py::arg("q"));

  py::class_<SimulationResult>(m, "SimulationResult", "Time series on the output grid, one row per time")
      .def_readonly("t", &SimulationResult::t)
      .def_readonly("q", &SimulationResult::q)
      .def_readonly("q_d", &SimulationResult::q_d)
      .def_readonly("u", &SimulationResult::u)
      .def_readonly("u_d", &SimulationResult::u_d)
      .def_readonly("w", &SimulationResult::w)
      .def_readonly("q_hat", &SimulationResult::q_hat)
      .def_readonly("y", &SimulationResult::y)
      .def_readonly("sigma_min_eig", &SimulationResult::sigma_min_eig)
      .def_readonly("sigma_max_eig", &SimulationResult::sigma_max_eig)
      .def_readonly("rho_sigma_z", &SimulationResult::rho_sigma_z)
      .def_readonly("coupling_violation_t", &SimulationResult::coupling_violation_t)
      .def_property_readonly("status", [](const SimulationResult& r) { return to_string(r.status); },
                             "\"completed\", or \"diverged\" (stopped early: the tracking error left the divergence bound)")
      .def_readonly("status_message", &SimulationResult::status_message)
      .def_readonly("integrator", &SimulationResult::integrator)
      .def_readonly("stats", &SimulationResult::stats)
      .def_property_readonly("q_e", &SimulationResult::q_e, "q - q_d, the heading component wrapped to (-pi, pi]");

  m.def("simulate_state_feedback",
        [](const Trajectory& trajectory, Controller& controller, const py::object& disturbance,
           const Vec& q0, double output_dt, const SolverOptions& options) {
          check_controller_fits(controller, trajectory.model());
          const Disturbance w = to_disturbance(disturbance, trajectory.model().nw());
          py::gil_scoped_release release;
          return simulate_state_feedback(trajectory, controller, w, q0, output_dt, options);
        },
        py::arg("trajectory"), py::arg("controller"), py::arg("disturbance"), py::arg("q0"),
        py::arg("output_dt") = 0.01, py::arg("options") = SolverOptions{});
  py::class_<OutputFeedbackOptions>(m, "OutputFeedbackOptions", "Set-up of the output-feedback loop (paper §4)")
      .def(py::init([](double sigma, double sample_period, Mat N, Mat Sigma0, Mat Q, const std::string& filter_A,
                       bool stop_on_coupling_violation) {
             OutputFeedbackOptions o;
             o.sigma = sigma;
             o.sample_period = sample_period;
             o.N = std::move(N);
             o.Sigma0 = std::move(Sigma0);
             o.Q = std::move(Q);
             require(filter_A == "estimate" || filter_A == "desired",
                     "filter_A must be \"estimate\" or \"desired\", got \"", filter_A, "\"");
             // What can be checked without the model (simulate_output_feedback checks the sizes).
             require(std::isfinite(sigma) && sigma >= 0.0, "sigma must be >= 0, got ", sigma);
             require(std::isfinite(sample_period) && sample_period > 0.0, "sample_period must be > 0, got ",
                     sample_period);
             check_symmetric_weight(o.N, static_cast<int>(o.N.rows()), "N", true);
             check_symmetric_weight(o.Sigma0, static_cast<int>(o.Sigma0.rows()), "Sigma0", true);
             check_symmetric_weight(o.Q, static_cast<int>(o.Sigma0.rows()), "Q (the size of Sigma0)", false);
             o.filter_uses_estimate = filter_A == "estimate";
             o.stop_on_coupling_violation = stop_on_coupling_violation;
             return o;
           }),
           py::arg("sigma"), py::arg("sample_period"), py::arg("N"), py::arg("Sigma0"), py::arg("Q"),
           py::arg("filter_A") = "estimate", py::arg("stop_on_coupling_violation") = true)
      .def_readwrite("sigma", &OutputFeedbackOptions::sigma)
      .def_readwrite("sample_period", &OutputFeedbackOptions::sample_period)
      .def_readwrite("N", &OutputFeedbackOptions::N)
      .def_readwrite("Sigma0", &OutputFeedbackOptions::Sigma0)
      .def_readwrite("Q", &OutputFeedbackOptions::Q)
      .def_property("filter_A",
                    [](const OutputFeedbackOptions& o) { return o.filter_uses_estimate ? "estimate" : "desired"; },
                    [](OutputFeedbackOptions& o, const std::string& v) {
                      require(v == "estimate" || v == "desired", "filter_A must be \"estimate\" or \"desired\"");
                      o.filter_uses_estimate = v == "estimate";
                    })
      .def_readwrite("stop_on_coupling_violation", &OutputFeedbackOptions::stop_on_coupling_violation);

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
        [](const RiccatiSolutionPtr& grde, const py::object& controller, const py::object& disturbance,
           const Vec& q0, const RowMat& noise, const OutputFeedbackOptions& options, double output_dt,
           const SolverOptions& solver) {
          require(grde != nullptr, "simulate_output_feedback needs a GRDE solution");
          const Disturbance w = to_disturbance(disturbance, grde->trajectory().model().nw());
          // A Controller, or kappa (a Signal or a number) for the H-infinity law (34).
          std::shared_ptr<Controller> law;
          if (py::isinstance<Controller>(controller)) law = controller.cast<std::shared_ptr<Controller>>();
          else law = std::make_shared<HinfStateFeedback>(grde,
                                                         to_signal(controller, "controller (a Controller, or kappa)"));
          check_controller_fits(*law, grde->trajectory().model());
          py::gil_scoped_release release;
          return simulate_output_feedback(*grde, *law, w, q0, noise, options, output_dt, solver);
        },
        py::arg("grde"), py::arg("controller"), py::arg("disturbance"), py::arg("q0"), py::arg("noise"),
        py::arg("options"), py::arg("output_dt") = 0.01, py::arg("solver") = SolverOptions{},
        "Output-feedback closed loop (paper 34-36): filter and estimator of grde, control by `controller` (a"
        " Controller, or kappa for the H-infinity law) at the estimate; noise: standard normal samples, one"
        " row per hold interval");
  m.def("output_grid", &output_grid, py::arg("t0"), py::arg("tf"), py::arg("dt"));
  m.def("compute_metrics", [](const Model& model, const SimulationResult& run, const Mat& Q) {
    return metrics_dict(compute_metrics(model, run, Q));
  }, py::arg("model"), py::arg("run"), py::arg("Q"));

  // ---- gamma* and certificates (paper §3) ----
  py::class_<GammaStarOptions>(m, "GammaStarOptions",
                                "Options of the gamma* search. threads: gammas evaluated in parallel per round"
                                " (one for a model implemented in Python, whose calls hold the GIL)")
      .def(py::init([](double lower, double upper, double rtol, int max_evaluations, int threads,
                       const SolverOptions& solver) {
             GammaStarOptions o;
             o.lower = lower;
             o.upper = upper;
             o.rtol = rtol;
             o.max_evaluations = max_evaluations;
             o.threads = threads;
             o.solver = solver;
             o.validate();
             return o;
           }),
           py::arg("lower") = 0.0, py::arg("upper") = 0.0, py::arg("rtol") = 1e-7, py::arg("max_evaluations") = 200,
           py::arg("threads") = 2, py::arg("solver") = SolverOptions{})
      .def_readwrite("lower", &GammaStarOptions::lower)
      .def_readwrite("upper", &GammaStarOptions::upper)
      .def_readwrite("rtol", &GammaStarOptions::rtol)
      .def_readwrite("max_evaluations", &GammaStarOptions::max_evaluations)
      .def_readwrite("threads", &GammaStarOptions::threads)
      .def_readwrite("solver", &GammaStarOptions::solver)
      .def("__repr__", [](const GammaStarOptions& o) {
        return str_cat("GammaStarOptions(lower=", o.lower, ", upper=", o.upper, ", rtol=", o.rtol,
                       ", max_evaluations=", o.max_evaluations, ", threads=", o.threads, ")");
      });

  py::class_<GammaTrial>(m, "GammaTrial", "One gamma tried by the gamma* search")
      .def_readonly("gamma", &GammaTrial::gamma)
      .def_readonly("passed", &GammaTrial::passed)
      .def_readonly("t_escape", &GammaTrial::t_escape)
      .def_readonly("condition", &GammaTrial::condition)
      .def("__repr__", [](const GammaTrial& t) {
        return str_cat("GammaTrial(gamma=", t.gamma, ", passed=", t.passed ? "True" : "False",
                       t.passed ? "" : str_cat(", condition='", t.condition, "', t=", t.t_escape), ")");
      });

  py::class_<GammaStarResult>(m, "GammaStarResult", "gamma*, the final bracket and every gamma tried")
      .def_readonly("gamma_star", &GammaStarResult::gamma_star)
      .def_readonly("lower", &GammaStarResult::lower)
      .def_readonly("upper", &GammaStarResult::upper)
      .def_readonly("t_escape_lower", &GammaStarResult::t_escape_lower)
      .def_readonly("binding", &GammaStarResult::binding)
      .def_readonly("converged", &GammaStarResult::converged)
      .def_readonly("trials", &GammaStarResult::trials)
      .def("__repr__", [](const GammaStarResult& r) {
        return str_cat("GammaStarResult(gamma_star=", r.gamma_star, ", bracket=[", r.lower, ", ", r.upper,
                       "], binding='", r.binding, "', t_escape_lower=", r.t_escape_lower, ", evaluations=",
                       r.trials.size(), ")");
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

  py::class_<Certificates>(m, "Certificates", "The stability certificates of paper §3 (eqs. 22-24)")
      .def_readonly("m", &Certificates::m)
      .def_readonly("M", &Certificates::M)
      .def_readonly("kappa_min", &Certificates::kappa_min)
      .def_readonly("p_min", &Certificates::p_min)
      .def_readonly("p_min_t", &Certificates::p_min_t)
      .def_readonly("remainder_L", &Certificates::remainder_L)
      .def_readonly("remainder_method", &Certificates::remainder_method)
      .def_readonly("remainder_is_bound", &Certificates::remainder_is_bound)
      .def_readonly("epsilon", &Certificates::epsilon)
      .def_readonly("epsilon_t", &Certificates::epsilon_t)
      .def_readonly("attraction_radius", &Certificates::attraction_radius)
      .def_readonly("decay_rate", &Certificates::decay_rate);
  m.def("certify",
        [](const RiccatiSolution& solution, const Mat& Q, const py::object& kappa) {
          const Signal k = to_signal(kappa, "kappa");
          py::gil_scoped_release release;
          return certify(solution, k, Q);
        },
        py::arg("solution"), py::arg("Q"), py::arg("kappa") = Signal(1.0),
        "The certificates of paper §3 for a design Z (its gamma), the weight Q and kappa(t)");

  // ---- scenarios ----
  py::class_<MeasurementSpec>(m, "MeasurementSpec", "[measurement] of a scenario (paper §4)")
      .def(py::init<>())
      .def_readwrite("sigma", &MeasurementSpec::sigma)
      .def_readwrite("sample_period", &MeasurementSpec::sample_period)
      .def_readwrite("seed", &MeasurementSpec::seed)
      .def_readwrite("N", &MeasurementSpec::N)
      .def_readwrite("Q0", &MeasurementSpec::Q0)
      .def_readwrite("eta", &MeasurementSpec::eta)
      .def_readwrite("filter_A", &MeasurementSpec::filter_A)
      .def_readwrite("on_coupling_violation", &MeasurementSpec::on_coupling_violation);

  py::class_<Scenario>(m, "Scenario", "Everything one run needs (shared/scenarios.md)")
      .def(py::init<>())
      .def_readwrite("name", &Scenario::name)
      .def_readwrite("description", &Scenario::description)
      .def_readwrite("model", &Scenario::model)
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
      .def_readwrite("law", &Scenario::law)
      .def_readwrite("cascade", &Scenario::cascade)
      .def_readwrite("worst_case", &Scenario::worst_case)
      .def_property("disturbance", [](const Scenario& s) { return s.disturbance; },
                    [](Scenario& s, const py::object& v) {
                      require(s.model != nullptr, "set Scenario.model before disturbance");
                      s.disturbance = to_vector_signal(v, s.model->nw(), "disturbance");
                    })
      .def_readwrite("initial_q0", &Scenario::initial_q0)
      .def_readwrite("measurement", &Scenario::measurement)
      .def_readwrite("solver", &Scenario::solver)
      .def_readwrite("output_dt", &Scenario::output_dt)
      .def("resolved", &Scenario::resolved)
      .def("validate", &Scenario::validate)
      .def("copy", [](const Scenario& s) { return Scenario(s); }, "an independent copy (signals and model shared)")
      .def("__copy__", [](const Scenario& s) { return Scenario(s); });

  py::class_<Timing>(m, "Timing")
      .def_readonly("design", &Timing::design)
      .def_readonly("simulate", &Timing::simulate)
      .def_readonly("analysis", &Timing::analysis)
      .def_readonly("total", &Timing::total);

  py::class_<RunResult>(m, "RunResult", "Result of run_scenario")
      .def_readonly("scenario_name", &RunResult::scenario_name)
      .def_readonly("controller", &RunResult::controller)
      .def_readonly("gamma", &RunResult::gamma)
      .def_readonly("trajectory", &RunResult::trajectory)
      .def_readonly("solution", &RunResult::solution)
      .def_readonly("Z0", &RunResult::Z0)
      .def_readonly("Z_min_eig", &RunResult::Z_min_eig)
      .def_readonly("Z_max_eig", &RunResult::Z_max_eig)
      .def_readwrite("gamma_star", &RunResult::gamma_star)
      .def_readonly("simulation", &RunResult::simulation)
      .def_readonly("timing", &RunResult::timing)
      .def_property_readonly("metrics", [](const RunResult& r) { return metrics_dict(r.metrics); })
      .def("to_json", &results_json, py::arg("indent") = 2)
      .def("to_csv", &results_csv);

  m.def("run_scenario",
        [](const Scenario& scenario, const std::optional<RowMat>& noise) {
          py::gil_scoped_release release;
          return noise ? run_scenario_with_noise(scenario, *noise) : run_scenario(scenario);
        },
        py::arg("scenario"), py::arg("noise") = py::none(),
        "Run a scenario; with [measurement], noise (standard normal samples, one row per hold interval)"
        " replaces the seeded noise so that a run can be replayed exactly");
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
  m.def("scenario_noise", &scenario_noise, py::arg("scenario"),
        "The seeded standard normal noise samples of a scenario with [measurement]");
  m.def("parse_scenario_toml", &parse_scenario_toml, py::arg("text"), py::arg("source"),
        "The C++ scenario parser (the one hinf-sim uses)");
  // The one scenario reader (scenario_io.cpp) for the Python package: files and signals.
  m.def("load_scenario_toml", &load_scenario_toml, py::arg("path"),
        "Reads a scenario file with the reader of hinf-sim (same checks, same messages)");
  m.def("parse_signal_toml", &parse_signal_toml, py::arg("text"), py::arg("key"), py::arg("source"),
        "A Signal from a TOML document whose one key is `key` (as in a scenario)");
}
