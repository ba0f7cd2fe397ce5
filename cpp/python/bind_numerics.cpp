// The Python bindings of the numerics layer (cpp/include/hinf/numerics): signals, solver
// options, dense output and CasADi generated code.
#include "casters.hpp"
#include "fields.hpp"
#include "hinf/numerics/generated_function.hpp"
#include "hinf/numerics/piecewise_polynomial.hpp"
#include "hinf/numerics/signal.hpp"
#include "hinf/numerics/solver_options.hpp"

namespace hinf::python {

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

namespace {

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

// ---- CasADi generated code (generated_function.hpp) ----
// GeneratedFunction(path, name)(*inputs) -> list of arrays. An input is a number (a 1 x 1
// input), a 1-D array (a vector input) or a 2-D array of the input's shape; each output is a
// 2-D array of the output's shape (zeros where it is structurally zero). The evaluation
// releases the GIL (calls from several threads run at once).
void bind_generated_function(py::module_& m) {
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
               ComputationScope release;
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

}  // namespace

// What a vector function of t vectorized over times returns, for the docstrings.
constexpr const char* kVectorOfT = "Shape (dim,) for a number t, (k, dim) for a 1-D array of k times.";

void bind_numerics(py::module_& m) {
  // ---- enums ----
  bind_enum<Method>(m, "Method", R"(Examples
--------
>>> hc.SolverOptions(method="erk").method
<Method.erk: 3>
>>> list(hc.Method.__members__), hc.Method("bdf") == hc.Method.bdf
(['auto', 'bdf', 'adams', 'erk'], True))");
  bind_enum<NewtonSystems>(m, "NewtonSystems", R"(Examples
--------
>>> hc.SolverOptions(method="bdf", newton_systems="lyapunov").newton_systems
<NewtonSystems.lyapunov: 2>)");
  bind_enum<Interpolation>(m, "Interpolation", R"(Examples
--------
>>> step = hc.Signal.table([0.0, 1.0, 2.0], [0.0, 1.0, 0.0], "linear")
>>> step.interpolation(), step(0.5)
(<Interpolation.linear: 1>, 0.5))");

  // ---- signals ----
  bind_options<Harmonic>(m, "Harmonic", {"Harmonic"}, {}, R"(Examples
--------
>>> term = hc.Harmonic(amplitude=0.3, omega=0.2)
>>> term
Harmonic(amplitude=0.3, omega=0.2, phase=0.0, cosine=False)
>>> round(hc.Signal(0.0, [term])(np.pi / 0.4), 6)         # 0.3 sin(pi / 2)
0.3)");

  py::class_<Signal>(m, "Signal", doc({"Signal"}, R"(Wherever a Signal is expected, a number is taken too (a constant).

Parameters
----------
constant : float
    ``Signal(constant)``: the constant signal. ``Signal()`` is zero.
offset : float
    ``Signal(offset, harmonics)``: offset + the sum of the harmonics, in the signal's unit.
harmonics : list of Harmonic
    The terms added to `offset`.

Raises
------
ValueError
    A constant, offset or harmonic that is not finite.

See Also
--------
Signal.table : a signal interpolated between points.

Examples
--------
>>> u2 = hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])
>>> u2(np.array([0.0, 2.5])).round(4)                       # 0.3 sin(0.2 t)
array([0.    , 0.1438])
>>> u2.describe(), hc.Signal(1.0).is_constant()
('0 + 0.3 sin(0.2 t + 0)', True))").c_str())
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
          doc({"Signal::table"}, R"(Parameters
----------
t : array_like, shape (k,)
    The times t_i (s), k >= 2, finite and strictly increasing.
values : array_like, shape (k,)
    The values v_i, finite.
interpolation : Interpolation or str, default "pchip"
    "pchip", "linear", "hold" or "cubic".

Returns
-------
Signal

Raises
------
ValueError
    Fewer than two points, times not strictly increasing, a value not finite, lengths that differ.

Warns
-----
UserWarning
    When the "cubic" interpolant overshoots the range of the values (see overshoot()).

Examples
--------
>>> ramp = hc.Signal.table([0.0, 10.0, 20.0], [0.0, 1.0, 1.0])
>>> ramp(np.array([5.0, 15.0])), ramp.is_table()
(array([0.5, 1. ]), True))").c_str())
      .def("__call__", [](const Signal& s, const py::object& t) {
        return vectorize(t, 0, 0, [&s](double tt, double* out) { out[0] = s(tt); });
      }, py::arg("t"),
         "The value at t (s): a float for a number, an array of shape (k,) for a 1-D array of k times. A table "
         "outside [t_first, t_last] is a ValueError.")
      .def("minimum", &Signal::minimum, py::arg("t0"), py::arg("tf"),
           doc({"Signal::minimum"}, "Returns (value, t), t in seconds.").c_str())
      .def("is_table", &Signal::is_table, doc({"Signal::is_table"}).c_str())
      .def("is_constant", &Signal::is_constant, doc({"Signal::is_constant"}).c_str())
      .def("offset", &Signal::offset, doc({"Signal::offset"}).c_str())
      .def("harmonics", &Signal::harmonics, doc({"Signal::harmonics"}).c_str())
      .def("table_t", &Signal::table_t, doc({"Signal::table_t"}).c_str())
      .def("table_values", &Signal::table_values, doc({"Signal::table_values"}).c_str())
      .def("interpolation", &Signal::interpolation, doc({"Signal::interpolation"}).c_str())
      .def("overshoot", &Signal::overshoot, doc({"Signal::overshoot"}, "Returns (amount, t), t in seconds.").c_str())
      .def("describe", &Signal::describe, doc({"Signal::describe"}).c_str())
      .def("__repr__", [](const Signal& s) { return "Signal(" + s.describe() + ")"; })
      .def(py::pickle(&signal_state, &signal_from_state));
  py::implicitly_convertible<double, Signal>();
  m.def("overshoot_warning", &overshoot_warning, py::arg("signal"), py::arg("name"),
        doc({"overshoot_warning"}).c_str());

  py::class_<VectorSignal>(m, "VectorSignal", doc({"VectorSignal"}, R"(
Wherever a VectorSignal is expected, a list of Signals or numbers, or a callable f(t), is taken
too. A function of t implemented in Python holds the GIL at each call, and does not pickle.

Parameters
----------
channels : list of Signal or float
    ``VectorSignal(channels)``: one Signal (or number) per channel.
dim : int
    ``VectorSignal(dim, function)``: the number of channels, >= 0.
function : callable
    ``function(t) -> array_like, shape (dim,)``, t in seconds; its values must be finite.

Raises
------
ValueError
    A channel that is not a Signal or a finite number; dim out of range; later, a function that
    returns the wrong length or a non-finite value (naming t).

Examples
--------
>>> w = hc.VectorSignal([hc.Signal(0.1), 0.0])
>>> w.dim(), w(2.0)
(2, array([0.1, 0. ]))
>>> hc.VectorSignal(2, lambda t: [t, 2 * t])(np.array([0.0, 1.0]))
array([[0., 0.],
       [1., 2.]]))").c_str())
      .def(py::init([](const py::sequence& channels) { return VectorSignal(to_signals(channels, "channels")); }),
           py::arg("channels"))
      .def(py::init([](int dim, const py::function& function) {
             return vector_signal_from_callable(function, dim, "function");
           }),
           py::arg("dim"), py::arg("function"))
      .def_static("zeros", &VectorSignal::zeros, py::arg("dim"), doc({"VectorSignal::zeros"}).c_str())
      .def("dim", &VectorSignal::dim, doc({"VectorSignal::dim"}).c_str())
      .def("is_function", &VectorSignal::is_function, doc({"VectorSignal::is_function"}).c_str())
      .def("channels", &VectorSignal::channels, doc({"VectorSignal::channels"}).c_str())
      .def("__call__", [](const VectorSignal& s, const py::object& t) {
        return vectorize(t, s.dim(), 0, [&s](double tt, double* out) { s.eval(tt, out); });
      }, py::arg("t"),
         "The values at t (s): shape (dim,) for a number, (k, dim) for a 1-D array of k times.")
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

  // ---- solver options ----
  bind_options<SolverOptions>(m, "SolverOptions", {"SolverOptions"}, {},
                              R"(Raises
------
ValueError
    An option out of its range, naming it.

Examples
--------
>>> options = hc.SolverOptions(method="erk", rtol=1e-6, atol=1e-8)
>>> options.method, options.max_steps
(<Method.erk: 3>, 500000)
>>> try:
...     hc.SolverOptions(atol=0.0)
... except ValueError as error:
...     print(error)
solver atol must be in (0, 1e-3] (about rtol / 100 for solutions of order 1), got 0)");

  // ---- dense output ----
  py::class_<PiecewisePolynomial>(m, "PiecewisePolynomial",
                                  doc({"numerics/piecewise_polynomial.hpp"}, R"(
Made by the solvers (Trajectory.dense(), RiccatiSolution.dense()); it pickles.

Examples
--------
>>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 10.0)
>>> dense = trajectory.dense()                               # q_d: surge 1 m/s along x
>>> dense.dim(), dense.t_min(), dense.t_max()
(6, 0.0, 10.0)
>>> dense.eval(5.0).round(6)
array([1., 0., 0., 5., 0., 0.]))").c_str())
      .def("dim", &PiecewisePolynomial::dim, doc({"PiecewisePolynomial::dim"}).c_str())
      .def("num_pieces", &PiecewisePolynomial::num_pieces, doc({"PiecewisePolynomial::num_pieces"}).c_str())
      .def("empty", &PiecewisePolynomial::empty, doc({"PiecewisePolynomial::empty"}).c_str())
      .def("t_min", &PiecewisePolynomial::t_min, doc({"PiecewisePolynomial::t_min"}).c_str())
      .def("t_max", &PiecewisePolynomial::t_max, doc({"PiecewisePolynomial::t_min"}).c_str())
      .def("eval", [](const PiecewisePolynomial& p, const py::object& t) {
        return vectorize(t, p.dim(), 0, [&p](double tt, double* out) { p.eval(tt, out); });
      }, py::arg("t"),
         doc({"PiecewisePolynomial::eval"}, kVectorOfT).c_str())
      .def("eval_derivative", [](const PiecewisePolynomial& p, const py::object& t) {
        return vectorize(t, p.dim(), 0, [&p](double tt, double* out) { p.eval_derivative(tt, out); });
      }, py::arg("t"),
         doc({"PiecewisePolynomial::eval_derivative"}, kVectorOfT).c_str())
      .def("breakpoints", &PiecewisePolynomial::breakpoints, doc({"PiecewisePolynomial::breakpoints"}).c_str())
      .def("memory_bytes", &PiecewisePolynomial::memory_bytes, doc({"PiecewisePolynomial::memory_bytes"}).c_str())
      .def(py::pickle(&dense_state, &dense_from_state));

  bind_result<StepStats>(m, "StepStats", {"StepStats"}, {}, R"(Examples
--------
>>> stats = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 10.0).stats()
>>> stats.steps > 0, stats.jac_evals                         # Dormand-Prince: no Jacobian
(True, 0))", /*repr=*/true);

  bind_generated_function(m);
}

}  // namespace hinf::python
