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

}  // namespace

void bind_numerics(py::module_& m) {
  // ---- enums ----
  bind_enum<Method>(m, "Method", "Integrator of every ODE solve (solver_options.hpp)");
  bind_enum<NewtonSystems>(m, "NewtonSystems", "How BDF solves the Newton systems of a Riccati equation (solver_options.hpp)");
  bind_enum<Interpolation>(m, "Interpolation", "How a table Signal is interpolated between its points (signal.hpp)");

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

  // ---- solver options ----
  bind_options<SolverOptions>(m, "SolverOptions", "Integrator and tolerances ([solver] of a scenario)");

  // ---- dense output ----
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

  bind_generated_function(m);
}

}  // namespace hinf::python
