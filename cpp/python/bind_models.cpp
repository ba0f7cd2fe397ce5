// The Python bindings of the models layer (cpp/include/hinf/models): the Model interface (and
// models implemented in Python), the ship, LinearModel, fleets, the vehicles, generated models.
#include "casters.hpp"
#include "fields.hpp"
#include "hinf/models/fleet.hpp"
#include "hinf/models/generated_model.hpp"
#include "hinf/models/model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/models/vehicles.hpp"
#include "hinf/numerics/numdiff.hpp"

namespace hinf::python {

namespace {

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
      py::gil_scoped_release release;  // nested in a computation: no ComputationScope
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


// A built-in vehicle (vehicles.hpp): Vehicle(parameters), parameters(), pickled by value as
// its parameters (as ShipModel).
template <class Vehicle, class Parameters>
void bind_vehicle(py::module_& m, const char* name, const std::string& text) {
  const std::string type = name;
  py::class_<Vehicle, Model, py::smart_holder>(m, name, text.c_str())
      .def(py::init<const Parameters&>(), default_struct_arg<Parameters>("parameters"))
      .def("parameters", &Vehicle::parameters, doc({str_cat(type, "::parameters")}).c_str())
      .def(py::pickle(
          [](const Vehicle& model) { return py::make_tuple<py::return_value_policy::copy>(model.parameters()); },
          [type](const py::tuple& state) {
            check_state(state, 1, type.c_str());
            return std::make_shared<Vehicle>(state[0].cast<Parameters>());
          }));
}

}  // namespace

bool implemented_in_python(const Model* model) { return dynamic_cast<const PyModel*>(model) != nullptr; }

void bind_models(py::module_& m) {
  // ---- models ----
  py::class_<Model, PyModel, py::smart_holder>(m, "Model", doc({"Model", "models/model.hpp"}, R"(Notes
-----
Subclass it in Python and implement n(), m(), nw(), f(t, q), G(t, q), D(t, q), and if you can
dfdq(t, q) (else the Jacobian is numerical: the complex step when f accepts complex q, else
central differences; jacobian_method() says which). q arrives as a float64 array of shape (n,);
f returns shape (n,), dfdq (n, n), G (n, m), D (n, nw). A G or D that depends on q needs
state_dependent_inputs() -> True and constant_input_matrices() -> False (dGudq(t, q, u) is
optional: central differences otherwise). The other methods have defaults. The structure is
read once, when the library first needs it, and validated; what f, dfdq, G, D, C and
error_split return is checked at every call (ValueError naming the method). Each call holds the
GIL, so computations with a Python model run on one thread; such a model does not pickle.

Examples
--------
>>> class DoubleIntegrator(hc.Model):
...     def n(self): return 2
...     def m(self): return 1
...     def nw(self): return 1
...     def f(self, t, q): return np.array([q[1], 0.0])
...     def G(self, t, q): return np.array([[0.0], [1.0]])
...     def D(self, t, q): return np.array([[0.0], [1.0]])
>>> model = DoubleIntegrator()
>>> model.dfdq(0.0, np.array([0.0, 2.0]))                    # no dfdq: numerical
array([[0., 1.],
       [0., 0.]])
>>> model.jacobian_method(), model.state_names()
('complex step', ['q0', 'q1']))").c_str())
      .def(py::init<>())
      .def("name", &Model::name, doc({"Model::name"}).c_str())
      .def("n", &Model::n, doc({"Model::n"}).c_str())
      .def("m", &Model::m, doc({"Model::n"}).c_str())
      .def("nw", &Model::nw, doc({"Model::n"}).c_str())
      .def("f", [](const Model& model, double t, const Vec& q) {
        check_size(q, model.n(), "q");
        Vec out(model.n());
        model.f(t, q, out);
        return out;
      }, py::arg("t"), py::arg("q"), doc({"Model::f"}, "t in seconds, q of shape (n,); returns f, shape (n,).").c_str())
      .def("dfdq", [](const Model& model, double t, const Vec& q) {
        check_size(q, model.n(), "q");
        Mat out(model.n(), model.n());
        model.dfdq(t, q, out);
        return out;
      }, py::arg("t"), py::arg("q"),
         doc({"Model::f"}, "t in seconds, q of shape (n,); returns df/dq, shape (n, n).").c_str())
      .def("G", [](const Model& model, double t, const Vec& q) {
        check_size(q, model.n(), "q");
        return model.G(t, q);
      }, py::arg("t"), py::arg("q"),
         doc({"Model::G"}, "t in seconds, q of shape (n,); returns G, shape (n, m).").c_str())
      .def("D", [](const Model& model, double t, const Vec& q) {
        check_size(q, model.n(), "q");
        return model.D(t, q);
      }, py::arg("t"), py::arg("q"),
         doc({"Model::G"}, "t in seconds, q of shape (n,); returns D, shape (n, nw).").c_str())
      .def("dGudq", [](const Model& model, double t, const Vec& q, const Vec& u) {
        check_size(q, model.n(), "q");
        check_size(u, model.m(), "u");
        Mat out(model.n(), model.n());
        model.dGudq(t, q, u, out);
        return out;
      }, py::arg("t"), py::arg("q"), py::arg("u"),
         doc({"Model::dGudq"}, "q of shape (n,), u of shape (m,); returns shape (n, n).").c_str())
      .def("linearize", [](const Model& model, double t, const Vec& q, const Vec& u) {
        check_size(q, model.n(), "q");
        check_size(u, model.m(), "u");
        Mat out(model.n(), model.n());
        linearize(model, t, q, u, out);
        return out;
      }, py::arg("t"), py::arg("q"), py::arg("u"),
         doc({"linearize"}, "q of shape (n,), u of shape (m,); returns A, shape (n, n).").c_str())
      .def("constant_input_matrices", &Model::constant_input_matrices, doc({"Model::constant_input_matrices"}).c_str())
      .def("state_dependent_inputs", &Model::state_dependent_inputs, doc({"Model::state_dependent_inputs"}).c_str())
      .def("jacobian_method", &Model::jacobian_method, doc({"Model::jacobian_method"}).c_str())
      .def("error_split", [](const Model& model, double t, const Vec& q_d, const Vec& u_d, const Vec& q_e) {
        check_size(q_d, model.n(), "q_d");
        check_size(u_d, model.m(), "u_d");
        check_size(q_e, model.n(), "q_e");
        Mat A(model.n(), model.n());
        Vec alpha(model.n());
        model.error_split(t, q_d, u_d, q_e, A, alpha);
        return py::make_tuple(A, alpha);
      }, py::arg("t"), py::arg("q_d"), py::arg("u_d"), py::arg("q_e"),
         doc({"Model::error_split"},
             "q_d, q_e of shape (n,), u_d of shape (m,); returns (A, alpha) of shapes (n, n) and (n,).").c_str())
      .def("C", &Model::C, py::arg("t"), doc({"Model::C"}, "Returns C, shape (p, n).").c_str())
      .def("noise_channels", &Model::noise_channels,
         doc({"Model::C"}, "Returns the noise channels, indices into w.").c_str())
      .def("remainder_bound", [](const Model& model, double t, const Vec& q_d, double radius) {
        check_size(q_d, model.n(), "q_d");
        return model.remainder_bound(t, q_d, radius);
      }, py::arg("t"), py::arg("q_d"), py::arg("radius"), doc({"Model::remainder_bound"}).c_str())
      .def("state_names", &Model::state_names, doc({"Model::state_names"}).c_str())
      .def("position_indices", &Model::position_indices, doc({"Model::position_indices"}).c_str())
      .def("heading_index", &Model::heading_index, doc({"Model::heading_index"}).c_str())
      .def("named_parameters",
           [](const Model& model) {
             py::typing::Dict<py::str, py::float_> parameters;
             for (const auto& [name, value] : model.named_parameters()) parameters[py::str(name)] = value;
             return parameters;
           },
           doc({"Model::named_parameters"}, "Returns a dict name -> value; a model implemented in Python may define it "
                                            "(returning a dict of numbers).").c_str())
      .def("__getstate__", [](const Model& model) -> py::tuple {
        cannot_pickle(str_cat("the model '", model.name(), "'"),
                      "a model implemented in Python does not pickle (ShipModel and LinearModel do)");
      });

  bind_options<ShipParameters>(m, "ShipParameters", {"ShipParameters"}, {}, R"(Examples
--------
>>> hc.ShipParameters(d_u=1.5)
ShipParameters(m_u=0.5, m_v=-2.0, m_r=0.5, d_u=1.5, d_v=2.0, d_r=1.0))");

  py::class_<ShipModel, Model, py::smart_holder>(m, "ShipModel",
      doc({"models/ship.hpp", "ShipParameters", "ShipModel", "ShipModel::ShipModel"}, R"(
Parameters
----------
parameters : ShipParameters, optional
    The paper's parameters by default.

Raises
------
ValueError
    A parameter that is not finite.

Examples
--------
>>> ship = hc.ShipModel(hc.ShipParameters(d_u=1.5))
>>> ship.n(), ship.m(), ship.nw(), ship.state_names()
(6, 2, 6, ['u', 'v', 'r', 'x', 'y', 'psi'])
>>> ship.f(0.0, np.array([1.0, 0.0, 0.0, 0.0, 0.0, 0.0]))[[0, 3]]   # du/dt = -d_u u, dx/dt = u
array([-1.5,  1. ]))").c_str())
      .def(py::init<const ShipParameters&>(), py::arg("parameters") = ShipParameters{})
      .def("parameters", &ShipModel::parameters, doc({"ShipModel::parameters"}).c_str())
      .def(py::pickle(
          [](const ShipModel& model) { return py::make_tuple<py::return_value_policy::copy>(model.parameters()); },
          [](const py::tuple& state) {
            check_state(state, 1, "ShipModel");
            return std::make_shared<ShipModel>(state[0].cast<ShipParameters>());
          }));

  py::class_<LinearModel, Model, py::smart_holder>(m, "LinearModel", doc({"LinearModel"}, R"(Parameters
----------
A : array_like, shape (n, n)
    The state matrix.
B : array_like, shape (n, m)
    The input matrix.
D : array_like, shape (n, nw)
    The disturbance matrix.
C : array_like, shape (p, n), optional
    The measurement matrix; without it the model has no measurement.

Raises
------
ValueError
    Matrices whose shapes do not fit, or entries that are not finite.

Examples
--------
>>> model = hc.LinearModel(np.array([[0.0, 1.0], [0.0, 0.0]]), np.array([[0.0], [1.0]]), np.eye(2),
...                        C=np.array([[1.0, 0.0]]))
>>> model.n(), model.m(), model.nw(), model.noise_channels()      # w = [process (2), noise (1)]
(2, 1, 3, [2]))").c_str())
      .def(py::init([](Mat A, Mat B, Mat D, std::optional<Mat> C) {
             return LinearModel(std::move(A), std::move(B), std::move(D), C ? std::move(*C) : Mat());
           }),
           py::arg("A"), py::arg("B"), py::arg("D"), py::arg_v("C", py::none(), "None"))
      .def("A", &LinearModel::A, doc({"LinearModel::A"}).c_str())
      .def("B", &LinearModel::B, doc({"LinearModel::A"}).c_str())
      .def("process_D", &LinearModel::process_D, doc({"LinearModel::process_D"}).c_str())
      .def("measurement_C", &LinearModel::measurement_C, doc({"LinearModel::process_D"}).c_str())
      .def(py::pickle(
          [](const LinearModel& model) {
            return py::make_tuple(model.A(), model.B(), model.process_D(), model.measurement_C());
          },
          [](const py::tuple& state) {
            check_state(state, 4, "LinearModel");
            return std::make_shared<LinearModel>(state[0].cast<Mat>(), state[1].cast<Mat>(), state[2].cast<Mat>(),
                                                 state[3].cast<Mat>());
          }));

  py::class_<FleetModel, Model, py::smart_holder>(m, "FleetModel",
      doc({"models/fleet.hpp", "FleetModel::FleetModel"}, R"(
Parameters
----------
member : Model
    The model of one vehicle (n_1 states).
count : int
    The number of vehicles, >= 1.

Raises
------
ValueError
    No member, or count < 1 or too large.

Examples
--------
>>> fleet = hc.FleetModel(hc.ShipModel(), 3)
>>> fleet.n(), fleet.m(), fleet.state_names()[:4], fleet.heading_index()
(18, 6, ['u_1', 'v_1', 'r_1', 'x_1'], -1))").c_str())
      .def(py::init<ModelPtr, int>(), py::arg("member"), py::arg("count"))
      .def("member", &FleetModel::member, doc({"FleetModel::member"}).c_str())
      .def("count", &FleetModel::count, doc({"FleetModel::member"}).c_str())
      .def(py::pickle(
          [](const FleetModel& model) { return py::make_tuple(model.member(), model.count()); },
          [](const py::tuple& state) {
            check_state(state, 2, "FleetModel");
            return std::make_shared<FleetModel>(state[0].cast<ModelPtr>(), state[1].cast<int>());
          }));

  // ---- the built-in vehicles (vehicles.hpp): parameters and models, pickled by value ----
  bind_options<FossenVesselParameters>(m, "FossenVesselParameters", {"FossenVesselParameters"},
                                       {{"M", "array_like, shape (3, 3)"}, {"D", "array_like, shape (3, 3)"}},
                                       R"(Examples
--------
>>> vessel = hc.FossenVesselParameters.supply_vessel()
>>> float(vessel.M[1, 2]), vessel.D.shape
(-0.0744, (3, 3)))")
      .def_static("supply_vessel", &FossenVesselParameters::supply_vessel,
                  doc({"FossenVesselParameters::supply_vessel"}).c_str());
  bind_options<HovercraftParameters>(m, "HovercraftParameters", {"HovercraftParameters"}, {}, R"(Examples
--------
>>> hc.HovercraftParameters(d=0.1)
HovercraftParameters(d=0.1, d_r=0.5))");
  bind_options<PlanarVtolParameters>(m, "PlanarVtolParameters", {"PlanarVtolParameters"}, {}, R"(Examples
--------
>>> hc.PlanarVtolParameters(epsilon=0.0)
PlanarVtolParameters(g=1.0, epsilon=0.0))");
  bind_options<AuvParameters>(m, "AuvParameters", {"AuvParameters"}, {}, R"(Examples
--------
>>> sirene = hc.AuvParameters.sirene()
>>> sirene.m11, sirene == hc.AuvParameters()
(215.0, True))")
      .def_static("sirene", &AuvParameters::sirene, doc({"AuvParameters::sirene"}).c_str());
  bind_vehicle<FossenVessel, FossenVesselParameters>(
      m, "FossenVessel", doc({"models/fossen_vessel.hpp", "FossenVesselParameters", "FossenVessel::FossenVessel"}, R"(
Parameters
----------
parameters : FossenVesselParameters, optional
    M and D; the supply vessel by default.

Raises
------
ValueError
    M or D not finite 3 x 3, M not symmetric positive definite, or the symmetric part of D not.

Examples
--------
>>> vessel = hc.FossenVessel()
>>> vessel.name(), vessel.state_names(), vessel.m()
('fossen_vessel', ['u', 'v', 'r', 'x', 'y', 'psi'], 2))"));
  bind_vehicle<Hovercraft, HovercraftParameters>(
      m, "Hovercraft", doc({"models/hovercraft.hpp", "HovercraftParameters", "Hovercraft::Hovercraft"}, R"(Parameters
----------
parameters : HovercraftParameters, optional
    The damping d and d_r (1/s).

Raises
------
ValueError
    d or d_r not finite or negative.

Examples
--------
>>> hover = hc.Hovercraft()
>>> hover.state_names(), hover.state_dependent_inputs()
(['x', 'y', 'psi', 'vx', 'vy', 'r'], True)
>>> hover.G(0.0, np.array([0.0, 0.0, np.pi / 2, 0.0, 0.0, 0.0]))[3:5, 0].round(6)   # thrust along y
array([0., 1.]))"));
  bind_vehicle<PlanarVtol, PlanarVtolParameters>(
      m, "PlanarVtol", doc({"models/planar_vtol.hpp", "PlanarVtolParameters", "PlanarVtol::PlanarVtol"}, R"(Parameters
----------
parameters : PlanarVtolParameters, optional
    Gravity g and the coupling epsilon (normalized units).

Raises
------
ValueError
    g not finite or negative, or epsilon not finite.

Examples
--------
>>> vtol = hc.PlanarVtol()
>>> vtol.state_names()[:3], float(vtol.f(0.0, np.zeros(6))[4])   # y_ddot = -g without thrust
(['x', 'y', 'theta'], -1.0))"));
  bind_vehicle<Auv, AuvParameters>(m, "Auv", doc({"models/auv.hpp", "AuvParameters", "Auv::Auv"}, R"(Parameters
----------
parameters : AuvParameters, optional
    Masses and drag coefficients (SI); the Sirene AUV by default.

Raises
------
ValueError
    A mass not finite or not > 0, or a drag coefficient not finite or negative.

Examples
--------
>>> auv = hc.Auv()
>>> auv.named_parameters()["m11"], auv.state_names()[3:]
(215.0, ['x', 'y', 'psi']))"));

  py::class_<GeneratedModel, Model, py::smart_holder>(m, "GeneratedModel", doc({"models/generated_model.hpp"}, R"(
hinf_cpp.models.SymbolicModel writes model.json and its library (build(), compile()).

Parameters
----------
metadata_path : str
    The path of model.json.
parameters : dict of str to float, optional
    Parameter values by name; the others keep their defaults.

Raises
------
ValueError
    Naming the file: a missing file or not a model description, a missing function or one of
    other sizes than the description says, an invalid structure, an unknown or non-finite
    parameter.

Examples
--------
>>> import casadi as ca
>>> from hinf_cpp.models import SymbolicModel
>>> q, d = ca.SX.sym("q", 2), ca.SX.sym("d")
>>> cart = SymbolicModel("cart", state=q, inputs=1, f=ca.vertcat(q[1], -d * q[1]), G=[[0.0], [1.0]],
...                      D=[[0.0], [1.0]], parameters=d, parameter_values={"d": 0.5})
>>> built = cart.build(cache_dir="cache")                    # model.json and its library
>>> model = hc.GeneratedModel(str(built.metadata_path), {"d": 1.0})
>>> model.parameters(), model.f(0.0, np.array([0.0, 2.0]))
({'d': 1.0}, array([ 2., -2.])))").c_str())
      .def(py::init<const std::string&, const std::map<std::string, double>&>(), py::arg("metadata_path"),
           py::arg("parameters") = std::map<std::string, double>{})
      .def("metadata_path", &GeneratedModel::metadata_path, doc({"GeneratedModel::metadata_path"}).c_str())
      .def("library_path", &GeneratedModel::library_path, doc({"GeneratedModel::library_path"}).c_str())
      .def("parameter_names", &GeneratedModel::parameter_names, doc({"GeneratedModel::parameter_names"}).c_str())
      .def("parameters", &GeneratedModel::parameters, doc({"GeneratedModel::parameters"}).c_str())
      .def(py::pickle(
          [](const GeneratedModel& model) { return py::make_tuple(model.metadata_path(), model.parameters()); },
          [](const py::tuple& state) {
            check_state(state, 2, "GeneratedModel");
            return std::make_shared<GeneratedModel>(state[0].cast<std::string>(),
                                                    state[1].cast<std::map<std::string, double>>());
          }));

  py::class_<ModelStructure>(m, "ModelStructure", doc({"ModelStructure"}).c_str())
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
  m.def("check_model_structure", &check_structure, py::arg("structure"), doc({"check_structure"}).c_str());
}

}  // namespace hinf::python
