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

bool implemented_in_python(const Model* model) { return dynamic_cast<const PyModel*>(model) != nullptr; }

void bind_models(py::module_& m) {
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
}

}  // namespace hinf::python
