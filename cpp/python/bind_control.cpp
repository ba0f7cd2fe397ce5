// The Python bindings of the control layer (cpp/include/hinf/control): the desired trajectory,
// the Riccati equations, the laws (and controllers implemented in Python), disturbances, closed
// loops, output feedback, metrics, gamma* and the certificates.
#include <tuple>

#include "casters.hpp"
#include "fields.hpp"
#include "hinf/control/analysis.hpp"
#include "hinf/control/backstepping.hpp"
#include "hinf/control/cascade.hpp"
#include "hinf/control/controller.hpp"
#include "hinf/control/discrete_design.hpp"
#include "hinf/control/discrete_output_feedback.hpp"
#include "hinf/control/disturbance.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/online_controller.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/control/sampled_loop.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"

namespace hinf::python {

namespace {

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


// A Disturbance from a Disturbance or anything to_vector_signal takes.
Disturbance to_disturbance(const py::object& value, int dim) {
  if (py::isinstance<Disturbance>(value)) {
    Disturbance d = value.cast<Disturbance>();
    require(d.dim() == dim, "the disturbance has ", d.dim(), " channels, expected ", dim);
    return d;
  }
  return Disturbance(to_vector_signal(value, dim, "disturbance"));
}


// RiccatiSolution and FilterRiccatiSolution: (trajectory, gamma, dense output, stats, blocks).
template <class Solution, class... Options>
void def_solution_pickle(py::class_<Solution, Options...>& cls) {
  cls.def(py::pickle(
      [](const Solution& s) {
        return py::make_tuple<py::return_value_policy::copy>(s.trajectory_ptr(), s.gamma(), s.dense(), s.stats(),
                                                             s.blocks());
      },
      [](const py::tuple& state) {
        check_state(state, 5, "Riccati solution");
        auto trajectory = state[0].cast<TrajectoryPtr>();
        require(trajectory != nullptr, "a pickled Riccati solution needs its trajectory");
        // The constructor checks the blocks against n and the dense output's size.
        return std::make_shared<Solution>(std::move(trajectory), state[1].cast<double>(),
                                          state[2].cast<PiecewisePolynomial>(), state[3].cast<SolveStats>(),
                                          state[4].cast<std::vector<int>>());
      }));
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

// The first lines of the examples that need a desired trajectory, or a design along it: the
// ship on the path of paper Fig. 1, over 10 s; Z at gamma = 5 with Q = Qf = I. The text that
// follows begins with a newline.
#define HINF_TRAJECTORY_EXAMPLE \
  ">>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1\n" \
  ">>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)"
#define HINF_DESIGN_EXAMPLE \
  HINF_TRAJECTORY_EXAMPLE "\n>>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)"

// What a matrix function of t vectorized over times returns, for the docstrings.
constexpr const char* kSquareOfT = "Shape (n, n) for a number t, (k, n, n) for a 1-D array of k times.";

// X(t) of a symmetric solution, vectorized over t.
template <class Solution, class Member>
py::object matrix_of_t(const Solution& s, const py::object& t, Member member) {
  const int n = s.n();
  return vectorize(t, n, n, [&s, n, member](double tt, double* out) { Eigen::Map<Mat>(out, n, n) = (s.*member)(tt); });
}

// A_k, B_k or D_k of a sampled linearization, with k checked (the C++ accessors do not check).
Mat sampled_matrix(const SampledLinearization& s, int k, const Mat& (SampledLinearization::*member)(int) const) {
  require(k >= 0 && k < s.steps(), "the sampled matrices are defined for k = 0 .. ", s.steps() - 1, ", got k = ", k);
  return (s.*member)(k);
}

// A measurement from Python: a raw array, not through the Vec caster, which refuses NaN: a
// non-finite measurement is a status of step() (MeasurementUse.not_finite), as in C++.
using MeasurementArray = std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>>;

// step() of an online controller (OnlineController or RecedingOnlineController) from Python:
// the measurement's shape checked against `current`, the controller whose law is in use, and
// (u, report) returned; the GIL released during the step.
template <class Stepping>
std::tuple<Vec, StepReport> step_from_python(Stepping& controller, const OnlineController& current, double t_now,
                           const MeasurementArray& q, const std::optional<double>& t_meas) {
  const int size = current.measurement_size();
  if (q && (q->ndim() != 1 || q->shape(0) != size))
    throw InputError(str_cat("q must have shape (", size, ",) (",
                             current.output_feedback() ? "the measured outputs y = C q" : "the full state",
                             "), got an array of ", q->size(), " numbers in ", q->ndim(), " dimensions"));
  Vec u(current.m());
  StepReport report;
  {
    ComputationScope release;
    report = controller.step(t_now, q ? q->data() : nullptr, t_meas.value_or(t_now), u.data());
  }
  if (report.status == StepStatus::NotReset) throw InputError("step() before reset(): call reset(t0, q0) first");
  return {std::move(u), report};
}

// The digital design and the online controller (discrete_design.hpp, online_controller.hpp).
void bind_digital(py::module_& m) {
  py::class_<SampledLinearization, py::smart_holder>(m, "SampledLinearization",
      doc({"SampledLinearization", "SampledLinearization::SampledLinearization"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory.
period : float
    The sample period T (s), > 0 and at most the horizon.

Raises
------
ValueError
    A bad period.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> sampled = hc.SampledLinearization(trajectory, 0.1)
>>> sampled.steps(), sampled.A(0).shape, sampled.B(0).shape, sampled.D(0).shape
(100, (6, 6), (6, 2), (6, 6)))").c_str())
      .def(py::init([](TrajectoryPtr trajectory, double period) {
             ComputationScope release;
             return std::make_shared<SampledLinearization>(std::move(trajectory), period);
           }),
           py::arg("trajectory"), py::arg("period"))
      .def("period", &SampledLinearization::period, doc({"SampledLinearization::period"}).c_str())
      .def("steps", &SampledLinearization::steps, doc({"SampledLinearization::steps"}).c_str())
      .def("time", &SampledLinearization::time, py::arg("k"), doc({"SampledLinearization::time"}).c_str())
      .def("trajectory", &SampledLinearization::trajectory_ptr, doc({"SampledLinearization::trajectory"}).c_str())
      .def("A", [](const SampledLinearization& s, int k) { return sampled_matrix(s, k, &SampledLinearization::A); },
           py::arg("k"),
           doc({"SampledLinearization::A"}, "k : int\n    0 .. steps() - 1 (ValueError outside).").c_str())
      .def("B", [](const SampledLinearization& s, int k) { return sampled_matrix(s, k, &SampledLinearization::B); },
           py::arg("k"),
           doc({"SampledLinearization::A"}).c_str())
      .def("D", [](const SampledLinearization& s, int k) { return sampled_matrix(s, k, &SampledLinearization::D); },
           py::arg("k"),
           doc({"SampledLinearization::A"}).c_str());

  py::class_<DiscreteDesign, py::smart_holder>(m, "DiscreteDesign", doc({"DiscreteDesign"}, R"(Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0)
>>> design.steps(), design.M(0).shape, design.gain(0).shape
(100, (6, 6), (2, 6)))").c_str())
      .def("gamma", &DiscreteDesign::gamma, doc({"DiscreteDesign::gamma"}).c_str())
      .def("period", &DiscreteDesign::period, doc({"DiscreteDesign::period"}).c_str())
      .def("steps", &DiscreteDesign::steps, doc({"DiscreteDesign::steps"}).c_str())
      .def("time", &DiscreteDesign::time, py::arg("k"), doc({"DiscreteDesign::time"}).c_str())
      .def("sampled", &DiscreteDesign::sampled_ptr, doc({"DiscreteDesign::sampled"}).c_str())
      .def("M", &DiscreteDesign::M, py::arg("k"), doc({"DiscreteDesign::M"}).c_str())
      .def("gain", &DiscreteDesign::gain, py::arg("k"), doc({"DiscreteDesign::gain"}).c_str())
      .def("worst_case_gain", &DiscreteDesign::worst_case_gain, py::arg("k"),
           doc({"DiscreteDesign::worst_case_gain"}).c_str())
      .def("sample_index", &DiscreteDesign::sample_index, py::arg("t"), doc({"DiscreteDesign::sample_index"}).c_str());

  m.def("solve_discrete_game",
        [](const py::object& source, double period, const Mat& Q, const Mat& Qf, double gamma) {
          if (py::isinstance<SampledLinearization>(source)) {
            auto sampled = source.cast<SampledLinearizationPtr>();
            ComputationScope release;
            return solve_discrete_game(sampled, Q, Qf, gamma);
          }
          auto trajectory = source.cast<TrajectoryPtr>();
          ComputationScope release;
          return solve_discrete_game(trajectory, period, Q, Qf, gamma);
        },
        py::arg("trajectory"), py::arg("period"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"),
        doc({"solve_discrete_game", "control/discrete_design.hpp"}, R"(Parameters
----------
trajectory : Trajectory or SampledLinearization
    The desired trajectory, or its linearization sampled before (then `period` is its own and
    the argument is ignored; pass 0).
period : float
    The sample period T (s).
Q : array_like, shape (n, n)
    Weight of the tracking error, symmetric positive semidefinite (per second, as in the GRDE).
Qf : array_like, shape (n, n)
    M_N, symmetric positive definite.
gamma : float
    The attenuation level, > 0 (inf: the discrete LQR).

Returns
-------
DiscreteDesign

Raises
------
ValueError
    Bad weights, gamma or period.
ConjugatePointError
    gamma^2 T I - D_k' M_{k+1} D_k is not positive definite at some sample: gamma is below
    the discrete gamma* (its t_escape is that sample's time).

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0)
>>> K = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0).gain(0.0)    # the continuous law's
>>> float(round(np.linalg.norm(design.gain(0) - K) / np.linalg.norm(K), 3))   # first order in T
0.059)").c_str());

  py::class_<DiscreteOutputFeedback, py::smart_holder>(m, "DiscreteOutputFeedback",
                                                       doc({"DiscreteOutputFeedback"}, R"(Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0)
>>> C = np.hstack([np.zeros((3, 3)), np.eye(3)])
>>> feedback = hc.solve_discrete_output_feedback(design, C, 0.25 * np.eye(3), np.eye(6), np.eye(6))
>>> bool(feedback.largest_coupling() < 1.0)
True)").c_str())
      .def("design", &DiscreteOutputFeedback::design_ptr, doc({"DiscreteOutputFeedback::design"}).c_str())
      .def("C", &DiscreteOutputFeedback::C, doc({"DiscreteOutputFeedback::C"}).c_str())
      .def("R", &DiscreteOutputFeedback::R, doc({"DiscreteOutputFeedback::C"}).c_str())
      .def("Q", &DiscreteOutputFeedback::Q, doc({"DiscreteOutputFeedback::C"}).c_str())
      .def("steps", &DiscreteOutputFeedback::steps, doc({"DiscreteDesign::steps"}).c_str())
      .def("Sigma", &DiscreteOutputFeedback::Sigma, py::arg("k"), doc({"DiscreteOutputFeedback::Sigma"}).c_str())
      .def("coupling", &DiscreteOutputFeedback::coupling, py::arg("k"),
           doc({"DiscreteOutputFeedback::coupling"}).c_str())
      .def("largest_coupling", &DiscreteOutputFeedback::largest_coupling,
           doc({"DiscreteOutputFeedback::largest_coupling"}).c_str());

  m.def("solve_discrete_output_feedback",
        [](const DiscreteDesignPtr& design, const Mat& C, const Mat& R, const Mat& Sigma0, const Mat& Q) {
          ComputationScope release;
          return solve_discrete_output_feedback(design, C, R, Sigma0, Q);
        },
        py::arg("design"), py::arg("C"), py::arg("R"), py::arg("Sigma0"), py::arg("Q"),
        doc({"solve_discrete_output_feedback", "control/discrete_output_feedback.hpp"}, R"(Parameters
----------
design : DiscreteDesign
    The digital design (solve_discrete_game).
C : array_like, shape (p, n)
    The measurement matrix (the model's C).
R : array_like, shape (p, p)
    The covariance of one measurement (sigma^2 per sample), symmetric positive definite.
Sigma0 : array_like, shape (n, n)
    The initial uncertainty, symmetric positive definite.
Q : array_like, shape (n, n)
    The game's state weight (the one the design was solved with).

Returns
-------
DiscreteOutputFeedback

Raises
------
ValueError
    Bad shapes or weights.
ConjugatePointError
    The filter does not exist at some sample (its t_escape is that sample's time).
CouplingConditionError
    rho(Sigma_k M_k) >= gamma^2 at some sample (its t is the first such sample's time).

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> C = np.hstack([np.zeros((3, 3)), np.eye(3)])
>>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0)
>>> feedback = hc.solve_discrete_output_feedback(design, C, 0.25 * np.eye(3), np.eye(6), np.eye(6))
>>> round(feedback.largest_coupling(), 3)      # rho(Sigma_k M_k) / gamma^2 < 1 at every sample
0.835
>>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 1.5)
>>> try:
...     hc.solve_discrete_output_feedback(design, C, 0.25 * np.eye(3), np.eye(6), np.eye(6))
... except hc.CouplingConditionError as error:
...     print(error.t, error.rho > error.gamma ** 2)   # at t0: Sigma0 = I is too uncertain for 1.5
0.0 True)").c_str());

  m.def("discrete_conjugate_time",
        [](const SampledLinearization& sampled, const Mat& Q, const Mat& Qf, double gamma) {
          ComputationScope release;
          return discrete_conjugate_time(sampled, Q, Qf, gamma);
        },
        py::arg("sampled"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"), doc({"discrete_conjugate_time"}, R"(Parameters
----------
sampled : SampledLinearization
Q : array_like, shape (n, n)
    Weight of the tracking error, as for solve_discrete_game.
Qf : array_like, shape (n, n)
    M_N, as for solve_discrete_game.
gamma : float
    The attenuation level.

Returns
-------
float
    t_k (s), or nan.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> sampled = hc.SampledLinearization(trajectory, 0.1)
>>> hc.discrete_conjugate_time(sampled, np.eye(6), np.eye(6), 5.0), hc.discrete_conjugate_time(sampled, np.eye(6), np.eye(6), 1.0)
(nan, 7.6000000000000005))").c_str());

  m.def("gamma_star_discrete",
        [](const SampledLinearizationPtr& sampled, const Mat& Q, const Mat& Qf, const GammaStarOptions& options) {
          ComputationScope release;
          return gamma_star_discrete(sampled, Q, Qf, options);
        },
        py::arg("sampled"), py::arg("Q"), py::arg("Qf"), py::arg("options") = GammaStarOptions{},
        doc({"gamma_star_discrete"}, R"(Parameters
----------
sampled : SampledLinearization
    The linearization sampled at the controller's period.
Q : array_like, shape (n, n)
    Weight of the tracking error, as for solve_discrete_game.
Qf : array_like, shape (n, n)
    M_N, as for solve_discrete_game.
options : GammaStarOptions, optional
    The bracket, tolerance, evaluations and threads.

Returns
-------
GammaStarResult

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> sampled = hc.SampledLinearization(trajectory, 0.1)
>>> round(hc.gamma_star_discrete(sampled, np.eye(6), np.eye(6)).gamma_star, 4)
1.3992)").c_str());

  m.def("gamma_star_discrete_output_feedback",
        [](const SampledLinearizationPtr& sampled, const Mat& Q, const Mat& Qf, const Mat& C, const Mat& R,
           const Mat& Sigma0, const GammaStarOptions& options) {
          ComputationScope release;
          return gamma_star_discrete_output_feedback(sampled, Q, Qf, C, R, Sigma0, options);
        },
        py::arg("sampled"), py::arg("Q"), py::arg("Qf"), py::arg("C"), py::arg("R"), py::arg("Sigma0"),
        py::arg("options") = GammaStarOptions{}, doc({"gamma_star_discrete_output_feedback"}, R"(Parameters
----------
sampled : SampledLinearization
    The linearization sampled at the controller's period.
Q : array_like, shape (n, n)
    Weight of the tracking error, as for solve_discrete_game (and the filter's).
Qf : array_like, shape (n, n)
    M_N, as for solve_discrete_game.
C : array_like, shape (p, n)
    The measurement matrix.
R : array_like, shape (p, p)
    The covariance of one measurement.
Sigma0 : array_like, shape (n, n)
    The initial uncertainty.
options : GammaStarOptions, optional
    The bracket, tolerance, evaluations and threads.

Returns
-------
GammaStarResult

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> sampled = hc.SampledLinearization(trajectory, 0.1)
>>> C = np.hstack([np.zeros((3, 3)), np.eye(3)])
>>> result = hc.gamma_star_discrete_output_feedback(sampled, np.eye(6), np.eye(6), C, 0.25 * np.eye(3), np.eye(6))
>>> result.binding, bool(result.gamma_star > hc.gamma_star_discrete(sampled, np.eye(6), np.eye(6)).gamma_star)
(<GammaCondition.coupling: 3>, True))").c_str());

  py::class_<SampledLaw, py::smart_holder>(m, "SampledLaw", doc({"SampledLaw"}, R"(Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> law = hc.SampledLaw.emulated(design, 0.1)
>>> law.kind(), law.steps(), law.t_end()
('emulated', 100, 10.0))").c_str())
      .def_static("emulated",
                  [](RiccatiSolutionPtr design, double period, const py::object& kappa) {
                    const Signal k = to_signal(kappa, "kappa");
                    ComputationScope release;
                    return SampledLaw::emulated(std::move(design), period, k);
                  },
                  py::arg("design"), py::arg("period"), py::arg("kappa") = Signal(1.0),
                  doc({"SampledLaw::emulated"}, R"(Parameters
----------
design : RiccatiSolution
    The continuous design (solve_grde).
period : float
    The controller's period T (s).
kappa : Signal or float, default 1.0
    The gain scaling kappa(t), > 0.

Returns
-------
SampledLaw

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> hc.SampledLaw.emulated(design, 0.05).period()
0.05)").c_str())
      .def_static("digital", &SampledLaw::digital, py::arg("design"), doc({"SampledLaw::digital"}, R"(Parameters
----------
design : DiscreteDesign
    The digital design (solve_discrete_game).

Returns
-------
SampledLaw

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> law = hc.SampledLaw.digital(hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0))
>>> law.kind(), law.gamma()
('digital', 5.0))").c_str())
      .def("kind", &SampledLaw::kind, doc({"SampledLaw::kind"}).c_str())
      .def("gamma", &SampledLaw::gamma, doc({"SampledLaw::gamma"}).c_str())
      .def("period", &SampledLaw::period, doc({"SampledLaw::period"}).c_str())
      .def("n", &SampledLaw::n, doc({"SampledLaw::n"}).c_str())
      .def("m", &SampledLaw::m, doc({"SampledLaw::n"}).c_str())
      .def("steps", &SampledLaw::steps, doc({"SampledLaw::steps"}).c_str())
      .def("t0", &SampledLaw::t0, doc({"SampledLaw::t0"}).c_str())
      .def("t_end", &SampledLaw::t_end, doc({"SampledLaw::t0"}).c_str())
      .def("gain", [](const SampledLaw& law, int k) {
             require(k >= 0 && k < law.steps(), "the gain K_k is defined for k = 0 .. ", law.steps() - 1, ", got k = ", k);
             return law.gain(k);
           }, py::arg("k"), doc({"SampledLaw::gain"}).c_str())
      // Pickled as its trajectory and tables (K_k, Z_k); the linearization's tables are computed
      // again from the trajectory when it is read, as the factories compute them.
      .def(py::pickle(
          [](const SampledLaw& law) {
            py::list K, Z;
            for (int k = 0; k < law.steps(); ++k) K.append(law.gain(k));
            for (int k = 0; k <= law.steps(); ++k) Z.append(law.Z(k));
            return py::make_tuple(law.trajectory_ptr(), law.kind(), law.gamma(), law.period(), K, Z);
          },
          [](const py::tuple& state) {
            check_state(state, 6, "SampledLaw");
            return std::make_shared<const SampledLaw>(state[0].cast<TrajectoryPtr>(), state[1].cast<std::string>(),
                                                      state[2].cast<double>(), state[3].cast<double>(),
                                                      state[4].cast<std::vector<Mat>>(),
                                                      state[5].cast<std::vector<Mat>>());
          }));

  bind_options<ActuatorLimits>(m, "ActuatorLimits", {"ActuatorLimits"},
                               {{"u_min", "array_like, shape (m,) or (0,)"}, {"u_max", "array_like, shape (m,) or (0,)"},
                                {"rate_max", "array_like, shape (m,) or (0,)"}},
                               R"(Examples
--------
>>> limits = hc.ActuatorLimits(u_min=[-2.0, -1.0], u_max=[2.0, 1.0], rate_max=[4.0, np.inf])
>>> limits.u_max
array([2., 1.]))");
  bind_enum<MeasurementUpdate>(m, "MeasurementUpdate", R"(Examples
--------
>>> hc.OnlineFilter().update
<MeasurementUpdate.sampled: 1>)");
  bind_options<OnlineFilter>(m, "OnlineFilter", {"OnlineFilter"},
                             {{"N", "array_like, shape (p, p) or (0, 0)"}, {"Sigma0", "array_like, shape (n, n)"},
                              {"Q", "array_like, shape (n, n)"}},
                             R"(Examples
--------
>>> f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))   # paper Fig. 2
>>> f.hold
0.0)");
  bind_options<OnlineOptions>(m, "OnlineOptions", {"OnlineOptions"}, {}, R"(Examples
--------
>>> hc.OnlineOptions(max_age=0.2).compensate_delay
True)");
  bind_enum<StepStatus>(m, "StepStatus", R"(Examples
--------
>>> hc.StepStatus("refused")
<StepStatus.refused: 1>)");
  bind_enum<MeasurementUse>(m, "MeasurementUse", R"(Examples
--------
>>> hc.MeasurementUse("stale")
<MeasurementUse.stale: 2>)");
  bind_result<StepReport>(m, "StepReport", {"StepReport"}, {}, R"(Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
>>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
>>> controller.step(0.1, None)[1]
StepReport(status='ok', measurement='missing', saturated=False, rate_limited=False, rho_sigma_z=nan, coupling_violated=False, window_stale=False))", /*repr=*/true);
  bind_result<OnlineCounts>(m, "OnlineCounts", {"OnlineCounts"}, {}, R"(Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
>>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
>>> u, report = controller.step(0.1, None)
>>> controller.counts().steps, controller.counts().predicted
(1, 1))", /*repr=*/true);

  py::class_<OnlineController, py::smart_holder>(m, "OnlineController",
      doc({"OnlineController", "OnlineController::OnlineController"}, R"(Parameters
----------
law : SampledLaw
    The law (SampledLaw.emulated or SampledLaw.digital), shared by any number of controllers.
options : OnlineOptions, optional
    Actuator limits, the largest age of a measurement, delay compensation; a filter (its N
    given) makes it an output-feedback controller, whose step() takes the measurement y = C q.

Raises
------
ValueError
    Bad options (a filter whose shapes do not fit the model's measurement C).

Notes
-----
One object per vehicle: its calls change it, so two threads must not call one object at once.
With output feedback the estimator and the filter run along the desired trajectory's
linearization (docs/online.md).

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> limits = hc.ActuatorLimits(u_min=[-2.0, -2.0], u_max=[2.0, 2.0])
>>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1), hc.OnlineOptions(limits=limits))
>>> q0 = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
>>> controller.reset(0.0, q0)
>>> u, report = controller.step(0.1, q0, 0.1)
>>> u.round(3), report.status, report.saturated
(array([ 2.   , -1.941]), <StepStatus.ok: 0>, True))").c_str())
      .def(py::init<SampledLawPtr, const OnlineOptions&>(), py::arg("law"), default_struct_arg<OnlineOptions>("options"))
      .def("law", [](const OnlineController& c) { return &c.law(); }, py::return_value_policy::reference_internal,
           doc({"OnlineController::law"}).c_str())
      .def("options", &OnlineController::options, doc({"OnlineController::law"}).c_str())
      .def("n", &OnlineController::n, doc({"OnlineController::n"}).c_str())
      .def("m", &OnlineController::m, doc({"OnlineController::n"}).c_str())
      .def("output_feedback", &OnlineController::output_feedback, doc({"OnlineController::output_feedback"}).c_str())
      .def("measurement_size", &OnlineController::measurement_size,
           doc({"OnlineController::measurement_size"}).c_str())
      .def("reset",
           [](OnlineController& c, double t, const Vec& q, const std::optional<Vec>& u_held) {
             c.reset(t, q, u_held ? *u_held : Vec());
           },
           py::arg("t"), py::arg("q"), py::arg("u_held") = py::none(), doc({"OnlineController::reset"}, R"(Parameters
----------
t : float
    The time (s), in [t0, t_end).
q : array_like, shape (n,)
    The full state at t (output feedback: the initial estimate of the state).
u_held : array_like, shape (m,), optional
    The command held before t (default: u_d(t) within the limits).

Raises
------
ValueError
    A bad t, q or u_held.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
>>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
>>> controller.held_command()
array([1., 0.]))").c_str())
      .def("step",
           [](OnlineController& c, double t_now, const MeasurementArray& q, const std::optional<double>& t_meas) {
             return step_from_python(c, c, t_now, q, t_meas);
           },
           py::arg("t_now"), py::arg("q") = py::none(), py::arg("t_meas") = py::none(),
           doc({"OnlineController::step"}, R"(Parameters
----------
t_now : float
    The time of the command (s).
q : array_like, shape (n,) or (p,), optional
    The full state measured at t_meas (output feedback: the measurement y, p =
    measurement_size()); None: no measurement this sample.
t_meas : float, optional
    The time of the measurement (s), <= t_now; default t_now.

Returns
-------
u : numpy.ndarray, shape (m,)
    The command to apply now and hold.
report : StepReport
    The status, what became of the measurement, whether a limit was active.

Raises
------
ValueError
    q of another size than measurement_size(); step() before reset() (the C++ step() returns
    NotReset).

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
>>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
>>> u, report = controller.step(0.2, None)                      # no measurement: predicted
>>> report.measurement
<MeasurementUse.missing: 1>)").c_str())
      .def("replay",
           [](OnlineController& c, const Vec& t_now,
              const py::array_t<double, py::array::c_style | py::array::forcecast>& q, const std::optional<Vec>& t_meas) {
             const Eigen::Index k = t_now.size();
             const int size = c.measurement_size();
             if (q.ndim() != 2 || q.shape(0) != k || q.shape(1) != size)
               throw InputError(str_cat("q must have shape (", k, ", ", size, "): one measurement per time of t_now"));
             if (t_meas && t_meas->size() != k)
               throw InputError(str_cat("t_meas must have ", k, " times, one per time of t_now, got ", t_meas->size()));
             RowMat u(k, c.m());
             std::vector<StepReport> reports(static_cast<std::size_t>(k));
             const double* rows = q.data();
             {
               ComputationScope release;
               Vec command(c.m());
               for (Eigen::Index i = 0; i < k; ++i) {
                 reports[static_cast<std::size_t>(i)] =
                     c.step(t_now[i], rows + i * size, t_meas ? (*t_meas)[i] : t_now[i], command.data());
                 u.row(i) = command.transpose();
               }
             }
             if (k > 0 && reports.front().status == StepStatus::NotReset)
               throw InputError("replay() before reset(): call reset(t0, q0) first");
             return py::make_tuple(u, reports);
           },
           py::arg("t_now"), py::arg("q"), py::arg("t_meas") = py::none(),
           R"(The commands the controller would have sent for a log of measurements: step() for each row,
in order, in one call (the GIL released for the whole log).

Parameters
----------
t_now : array_like, shape (k,)
    The times of the commands (s).
q : array_like, shape (k, n) or (k, p)
    The measured states (output feedback: the measurements y), one row per time; a row with NaN
    is a non-finite measurement (the estimate is predicted).
t_meas : array_like, shape (k,), optional
    The times of the measurements (s); default t_now.

Returns
-------
u : numpy.ndarray, shape (k, m)
    The commands, as step() returns them one by one.
reports : list of StepReport

Raises
------
ValueError
    Shapes that do not match; replay() before reset().

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
>>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
>>> ts = np.array([0.1, 0.2, 0.3])
>>> log = np.tile([1.0, 0.0, 0.0, -1.0, -1.0, 0.0], (3, 1))
>>> u, reports = controller.replay(ts, log)
>>> u.shape, [r.measurement for r in reports][-1]
((3, 2), <MeasurementUse.used: 0>))")
      .def("estimate", &OnlineController::estimate, doc({"OnlineController::estimate"}).c_str())
      .def("estimate_time", &OnlineController::estimate_time, doc({"OnlineController::estimate"}).c_str())
      .def("sigma", &OnlineController::sigma, doc({"OnlineController::sigma"}, R"(Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
>>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1), hc.OnlineOptions(filter=f))
>>> controller.reset(0.0, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0])   # the estimate: on the path
>>> u, report = controller.step(0.1, [-1.0, -1.0, 0.8], 0.1)  # y = (x, y, psi)
>>> controller.sigma().shape, bool(report.rho_sigma_z < 25.0)
((6, 6), True))").c_str())
      .def("held_command", &OnlineController::held_command, doc({"OnlineController::estimate"}).c_str())
      .def("held_time", &OnlineController::held_time, doc({"OnlineController::estimate"}).c_str())
      .def("counts", &OnlineController::counts, doc({"OnlineController::counts"}).c_str());
}

// The sampled loop (sampled_loop.hpp); after simulate_state_feedback, whose conversions it uses.
void bind_sampled_loop(py::module_& m) {
  bind_options<SampledLoopOptions>(m, "SampledLoopOptions", {"SampledLoopOptions"},
                                   {{"noise", "array_like, shape (k, p) or (0, 0)"}}, R"(Examples
--------
>>> hc.SampledLoopOptions(delay=0.1).simulation.output_dt
0.01)");
  m.def("simulate_sampled",
        [](const Trajectory& trajectory, OnlineController& controller, const py::object& disturbance, const Vec& q0,
           const SampledLoopOptions& options, const std::optional<ModelPtr>& plant) {
          const Disturbance w = to_disturbance(disturbance, trajectory.model().nw());
          ComputationScope release;
          return simulate_sampled(trajectory, controller, w, q0, options, plant ? plant->get() : nullptr);
        },
        py::arg("trajectory"), py::arg("controller"), py::arg("disturbance"), py::arg("q0"),
        default_struct_arg<SampledLoopOptions>("options"), py::arg("plant") = py::none(),
        doc({"simulate_sampled", "control/sampled_loop.hpp"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory of the controller's law.
controller : OnlineController
    The controller, reset here at t0 with q0; its counts() tell afterwards what its steps did.
disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
    The disturbance on the model's nw channels, as for simulate_state_feedback.
q0 : array_like, shape (n,)
    The initial state q(t0).
options : SampledLoopOptions, optional
    The computation delay (s), the output grid, divergence factor and tolerances; for an
    output-feedback controller the noise's sigma and its samples (one row per sample).
plant : Model or None, optional
    The vehicle integrated, of the design model's structure; None: the trajectory's model.

Returns
-------
SimulationResult
    The series on the output grid (u: the command applied, piecewise constant).

Raises
------
ValueError
    Sizes that do not match, a controller of another trajectory, a delay outside [0, T].
SolverError
    The integration failed.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
>>> w = hc.Signal(0.0, [hc.Harmonic(0.1, 2 * np.pi * 0.2, cosine=True)])     # paper Fig. 1
>>> q0 = [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4]
>>> run = hc.simulate_sampled(trajectory, controller, [w, w, w, 0, 0, 0], q0, hc.SampledLoopOptions(delay=0.1))
>>> run.status, controller.counts().steps
(<RunStatus.completed: 0>, 100))").c_str());
}

// The receding horizon (receding_horizon.hpp).
void bind_receding_horizon(py::module_& m) {
  bind_enum<TerminalWeight>(m, "TerminalWeight", R"(Examples
--------
>>> hc.RecedingHorizonOptions(window=10.0, terminal="stationary").terminal
<TerminalWeight.stationary: 1>)");
  bind_options<RecedingHorizonOptions>(m, "RecedingHorizonOptions", {"RecedingHorizonOptions"}, {}, R"(Raises
------
ValueError
    From RecedingHorizon: a window that is not > 0, an update period outside (0, window].

Examples
--------
>>> hc.RecedingHorizonOptions(window=10.0, update=1.0)
RecedingHorizonOptions(window=10.0, update=1.0, terminal='qf'))");
  bind_result<HorizonWindow>(m, "HorizonWindow", {"HorizonWindow"}, {}, R"(Examples
--------
>>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
>>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
>>> window = horizon.next(horizon.first())
>>> window.index, window.t_start, window.t_use_end, window.trajectory.tf()
(1, 1.0, 2.0, 11.0))", /*repr=*/false)
      .def("memory_bytes", &HorizonWindow::memory_bytes, doc({"HorizonWindow::memory_bytes"}).c_str());
  bind_result<RecedingHorizonReport>(m, "RecedingHorizonReport", {"RecedingHorizonReport"}, {}, R"(Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
>>> report = hc.run_scenario(scenario).receding_horizon
>>> report.windows, bool(report.peak_bytes < 2**20)
(40, True))", /*repr=*/true);
  bind_result<WindowGammaStar>(m, "WindowGammaStar", {"WindowGammaStar"}, {}, R"(Examples
--------
>>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
>>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
...                              hc.RecedingHorizonOptions(window=5.0, update=5.0))
>>> worst = hc.receding_horizon_gamma_star(horizon, 20.0)
>>> worst.windows, worst.window >= 0, bool(worst.gamma_star < 5.0)
(4, True, True))", /*repr=*/false);

  py::class_<RecedingHorizon, py::smart_holder>(m, "RecedingHorizon",
      doc({"RecedingHorizon", "RecedingHorizon::RecedingHorizon", "control/receding_horizon.hpp"}, R"(Parameters
----------
model : Model
    The design model.
q_d0 : array_like, shape (n,)
    The desired initial state q_d(t0).
u_d : VectorSignal, callable, or list of Signal or float
    The desired inputs, m channels, as for Trajectory; defined for every t of the mission.
t0 : float
    The start of the mission (s).
Q : array_like, shape (n, n)
    Weight of the tracking error, symmetric positive semidefinite.
Qf : array_like, shape (n, n)
    Every window's terminal weight Z(t_j + H), symmetric positive definite.
gamma : float
    The attenuation level, > 0 (inf: LQR).
options : RecedingHorizonOptions
    The window H and the update period (s).
solver : SolverOptions, optional
    The integrator of every window's GRDE.
trajectory_options : TrajectoryOptions, optional
    Tolerances of every window's desired trajectory.

Raises
------
ValueError
    A bad model, q_d0, u_d, weight, gamma or option.

Examples
--------
>>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
>>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
>>> horizon.window_at(3.5), horizon.window_start(3)
(3, 3.0)
>>> first = horizon.first()
>>> first.design.Z(0.0).shape, first.trajectory.tf()
((6, 6), 10.0))").c_str())
      .def(py::init([](ModelPtr model, Vec q_d0, const py::object& u_d, double t0, Mat Q, Mat Qf, double gamma,
                       const RecedingHorizonOptions& options, const SolverOptions& solver,
                       const TrajectoryOptions& trajectory_options) {
             require(model != nullptr, "RecedingHorizon needs a model");
             VectorSignal inputs = to_vector_signal(u_d, model->m(), "u_d");
             return std::make_shared<RecedingHorizon>(std::move(model), std::move(q_d0), std::move(inputs), t0,
                                                      std::move(Q), std::move(Qf), gamma, options, solver,
                                                      trajectory_options);
           }),
           py::arg("model"), py::arg("q_d0"), py::arg("u_d"), py::arg("t0"), py::arg("Q"), py::arg("Qf"),
           py::arg("gamma"), py::arg("options"), py::arg("solver") = SolverOptions{},
           py::arg("trajectory_options") = TrajectoryOptions{})
      .def_static("from_states",
                  [](ModelPtr model, std::vector<double> t, const RowMat& q, const py::object& u_d, Mat Q, Mat Qf,
                     double gamma, const RecedingHorizonOptions& options, const SolverOptions& solver,
                     const TrajectoryOptions& trajectory_options) {
                    require(model != nullptr, "RecedingHorizon.from_states needs a model");
                    VectorSignal inputs = to_vector_signal(u_d, model->m(), "u_d");
                    return std::make_shared<RecedingHorizon>(std::move(model), std::move(t), q, std::move(inputs),
                                                             std::move(Q), std::move(Qf), gamma, options, solver,
                                                             trajectory_options);
                  },
                  py::arg("model"), py::arg("t"), py::arg("q"), py::arg("u_d"), py::arg("Q"), py::arg("Qf"),
                  py::arg("gamma"), py::arg("options"), py::arg("solver") = SolverOptions{},
                  py::arg("trajectory_options") = TrajectoryOptions{},
                  doc({"RecedingHorizon::RecedingHorizon"}, R"(The receding horizon along a desired trajectory given as states and inputs.

Parameters
----------
model : Model
    The design model.
t : array_like, shape (N + 1,)
    The nodes t_0 < ... < t_N (s); t_0 is the mission's start.
q : array_like, shape (N + 1, n)
    The desired states at the nodes (a planner's, e.g. ``Plan.t`` and ``Plan.q``).
u_d : VectorSignal, callable, or list of Signal or float
    The desired inputs, m channels, defined beyond the last node for the last windows.
Q, Qf, gamma, options, solver, trajectory_options
    As for the constructor.

Returns
-------
RecedingHorizon
    Every window the states form over its interval: from its start through the nodes inside it.

Raises
------
ValueError
    Nodes that are not finite and increasing, states of another shape, and as the constructor.

Examples
--------
>>> t = np.arange(0.0, 60.5, 0.5)                          # dq/dt = 2 q + u: unstable, q_d = sin t
>>> model = hc.LinearModel([[2.0]], [[1.0]], [[1.0]])
>>> u_d = [hc.Signal(0.0, [hc.Harmonic(1.0, 1.0, cosine=True), hc.Harmonic(-2.0, 1.0)])]
>>> horizon = hc.RecedingHorizon.from_states(model, t, np.sin(t)[:, None], u_d, [[1.0]], [[1.0]], 5.0,
...                                          hc.RecedingHorizonOptions(window=5.0))
>>> bool(abs(horizon.desired_state(40.3)[0] - np.sin(40.3)) < 1e-8)   # one integration: off by e^(2 t)
True)").c_str())
      .def("node_times", &RecedingHorizon::node_times, doc({"RecedingHorizon::node_times"}).c_str())
      .def("node_states", &RecedingHorizon::node_states, doc({"RecedingHorizon::node_states"}).c_str())
      .def("model", &RecedingHorizon::model_ptr, doc({"RecedingHorizon::model"}).c_str())
      .def("t0", &RecedingHorizon::t0, "The start of the mission (s).")
      .def("gamma", &RecedingHorizon::gamma, "The attenuation level of every window.")
      .def("options", &RecedingHorizon::options, "The window and update period.")
      .def("window_start", &RecedingHorizon::window_start, py::arg("j"), doc({"RecedingHorizon::window_start"}).c_str())
      .def("window_at", &RecedingHorizon::window_at, py::arg("t"), doc({"RecedingHorizon::window_at"}).c_str())
      .def("window", &RecedingHorizon::window, py::arg("j"), py::arg("q_d_start"), py::call_guard<ComputationScope>(),
           doc({"RecedingHorizon::window"}).c_str())
      .def("window_trajectory", &RecedingHorizon::window_trajectory, py::arg("j"), py::arg("q_d_start"),
           py::call_guard<ComputationScope>(), doc({"RecedingHorizon::window_trajectory"}).c_str())
      .def("first", &RecedingHorizon::first, py::call_guard<ComputationScope>(),
           doc({"RecedingHorizon::first"}).c_str())
      .def("next", &RecedingHorizon::next, py::arg("previous"), py::call_guard<ComputationScope>(),
           doc({"RecedingHorizon::next"}).c_str())
      .def("with_path_change",
           [](const RecedingHorizon& h, double t_join, const py::object& u_d) {
             return h.with_path_change(t_join, to_vector_signal(u_d, h.m(), "u_d"));
           },
           py::arg("t_join"), py::arg("u_d"), doc({"RecedingHorizon::with_path_change"}).c_str())
      .def("path_changes", &RecedingHorizon::path_changes, doc({"RecedingHorizon::path_changes"}).c_str())
      .def("window_inputs", &RecedingHorizon::window_inputs, py::arg("j"),
           doc({"RecedingHorizon::window_inputs"}).c_str())
      .def("terminal_weight", &RecedingHorizon::terminal_weight, py::arg("j"), py::arg("window"),
           doc({"RecedingHorizon::terminal_weight"}).c_str())
      .def("desired_state", &RecedingHorizon::desired_state, py::arg("t"), py::call_guard<ComputationScope>(),
           doc({"RecedingHorizon::desired_state"}).c_str())
      .def("reference", &RecedingHorizon::reference, py::arg("tf"), py::call_guard<ComputationScope>(),
           doc({"RecedingHorizon::reference"}).c_str());

  m.def("simulate_receding_horizon",
        [](const RecedingHorizon& horizon, const py::object& disturbance, const Vec& q0, double tf,
           const SimulationOptions& options, const std::optional<ModelPtr>& plant, const py::object& kappa) {
          const Disturbance w = to_disturbance(disturbance, horizon.model().nw());
          const Signal gain = to_signal(kappa, "kappa");
          RecedingHorizonReport report;
          SimulationResult run;
          {
            ComputationScope release;
            run = simulate_receding_horizon(horizon, w, q0, tf, options, plant ? plant->get() : nullptr, gain,
                                            &report);
          }
          return py::make_tuple(std::move(run), report);
        },
        py::arg("horizon"), py::arg("disturbance"), py::arg("q0"), py::arg("tf"),
        py::arg("options") = SimulationOptions{}, py::arg("plant") = py::none(), py::arg("kappa") = 1.0,
        doc({"simulate_receding_horizon", "control/receding_horizon.hpp"}, R"(Parameters
----------
horizon : RecedingHorizon
    The windows' design.
disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
    The disturbance on the model's nw channels, as for simulate_state_feedback.
q0 : array_like, shape (n,)
    The initial state q(t0).
tf : float
    The end of the mission (s), > t0: any length.
options : SimulationOptions, optional
    Output step (s), divergence factor and integrator.
plant : Model or None, optional
    The vehicle integrated, of the design model's structure; None: the design model.
kappa : Signal or float, optional
    The gain scaling kappa(t) > 0 of the law.

Returns
-------
tuple of (SimulationResult, RecedingHorizonReport)
    The series on the output grid, and what was solved and held.

Raises
------
ValueError
    Sizes that do not match, tf <= t0, bad options.
ConjugatePointError
    A window's GRDE has a conjugate point at gamma (the message names the window).
SolverError
    An integration failed.

Examples
--------
>>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
>>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
>>> run, report = hc.simulate_receding_horizon(horizon, None, [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4], 100.0)
>>> run.status, report.windows, bool(np.hypot(*run.q_e()[-1, 3:5]) < 0.01)
(<RunStatus.completed: 0>, 100, True))").c_str());
  bind_result<RecedingOnlineStatus>(m, "RecedingOnlineStatus", {"RecedingOnlineStatus"}, {}, R"(Examples
--------
>>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
>>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
>>> controller = hc.RecedingOnlineController(horizon, 0.05, background=False)   # no thread: synchronize solves
>>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
>>> status = controller.status()
>>> status.window_in_use, status.windows_solved, status.windows_failed
(0, 1, 0))", /*repr=*/true);

  py::class_<RecedingOnlineController, py::smart_holder>(m, "RecedingOnlineController",
      doc({"RecedingOnlineController", "RecedingOnlineController::RecedingOnlineController",
           "control/online_receding_horizon.hpp"}, R"(Parameters
----------
horizon : RecedingHorizon
    The windows' design.
period : float
    The controller's period T (s); the horizon's update period is a whole multiple of it.
options : OnlineOptions, optional
    As for OnlineController: limits, delay compensation, a filter for output feedback.
kappa : Signal or float, optional
    The gain scaling kappa(t) > 0.
background : bool, optional
    Solve the next window on a thread of its own (True); False: synchronize() solves it. A model
    implemented in Python is always solved by synchronize() (the thread would need the GIL).

Raises
------
ValueError
    A period that does not divide the update period, bad options, u_d given as a function.

Examples
--------
>>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
>>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
>>> controller = hc.RecedingOnlineController(horizon, 0.05)
>>> q = np.array([1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
>>> controller.reset(0.0, q)
>>> for k in range(41):                                         # two seconds at 20 Hz
...     controller.synchronize(0.05 * k)                        # a simulation waits for the solver
...     u, report = controller.step(0.05 * k, q)
>>> controller.status().window_in_use, report.window_stale
(2, False))").c_str())
      .def(py::init([](std::shared_ptr<const RecedingHorizon> horizon, double period, const OnlineOptions& options,
                       const py::object& kappa, bool background) {
             require(horizon != nullptr, "RecedingOnlineController needs a RecedingHorizon");
             // A model implemented in Python is solved on the calling thread: the solver's thread
             // would wait for the GIL, which Python holds when it deletes the controller (and the
             // destructor joins that thread).
             const bool thread = background && !implemented_in_python(&horizon->model());
             return std::make_shared<RecedingOnlineController>(std::move(horizon), period, options,
                                                               to_signal(kappa, "kappa"), thread);
           }),
           py::arg("horizon"), py::arg("period"), default_struct_arg<OnlineOptions>("options"), py::arg("kappa") = 1.0,
           py::arg("background") = true)
      .def("period", &RecedingOnlineController::period, "The controller's period T (s).")
      .def("options", &RecedingOnlineController::options, doc({"RecedingOnlineController::options"}).c_str())
      .def("controller", &RecedingOnlineController::controller, py::return_value_policy::reference_internal,
           doc({"RecedingOnlineController::controller"}).c_str())
      .def("reset",
           [](RecedingOnlineController& c, double t, const Vec& q, const std::optional<Vec>& u_held) {
             ComputationScope release;
             c.reset(t, q, u_held.value_or(Vec()));
           },
           py::arg("t"), py::arg("q"), py::arg("u_held") = py::none(), doc({"RecedingOnlineController::reset"}).c_str())
      .def("step",
           [](RecedingOnlineController& c, double t_now, const MeasurementArray& q,
              const std::optional<double>& t_meas) {
             if (c.status().window_in_use < 0) throw InputError("step() before reset(): call reset(t0, q0) first");
             return step_from_python(c, c.controller(), t_now, q, t_meas);
           },
           py::arg("t_now"), py::arg("q") = py::none(), py::arg("t_meas") = py::none(),
           doc({"RecedingOnlineController::step"}, "As OnlineController.step; raises ValueError before reset().")
               .c_str())
      .def("synchronize", &RecedingOnlineController::synchronize, py::arg("t"), py::call_guard<ComputationScope>(),
           doc({"RecedingOnlineController::synchronize"}).c_str())
      .def("status", &RecedingOnlineController::status, doc({"RecedingOnlineController::status"}).c_str())
      .def("change_path",
           [](RecedingOnlineController& c, double t_join, const py::object& u_d) {
             c.change_path(t_join, to_vector_signal(u_d, c.horizon().m(), "u_d"));
           },
           py::arg("t_join"), py::arg("u_d"), doc({"RecedingOnlineController::change_path"}).c_str());

  m.def("simulate_sampled_receding_horizon",
        [](const Trajectory& trajectory, RecedingOnlineController& controller, const py::object& disturbance,
           const Vec& q0, const SampledLoopOptions& options, const std::optional<ModelPtr>& plant) {
          const Disturbance w = to_disturbance(disturbance, trajectory.model().nw());
          ComputationScope release;
          return simulate_sampled(trajectory, controller, w, q0, options, plant ? plant->get() : nullptr);
        },
        py::arg("trajectory"), py::arg("controller"), py::arg("disturbance"), py::arg("q0"),
        default_struct_arg<SampledLoopOptions>("options"), py::arg("plant") = py::none(),
        doc({"simulate_sampled", "control/sampled_loop.hpp"}, R"(Parameters
----------
trajectory : Trajectory
    The reference: the desired trajectory over [t0, tf] from the horizon's q_d0 with its u_d
    (the run's q_d series and divergence bound; the windows chain into it);
    ``horizon.reference(tf)`` gives it, path changes included.
controller : RecedingOnlineController
    The controller, reset here at t0; synchronized before every step.
disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
    The disturbance on the model's nw channels, as for simulate_state_feedback.
q0 : array_like, shape (n,)
    The initial state q(t0).
options : SampledLoopOptions, optional
    The computation delay (s), the output grid, tolerances, and for output feedback the noise.
plant : Model or None, optional
    The vehicle integrated, of the design model's structure; None: the design model.

Returns
-------
SimulationResult
    The series on the output grid (u: the command applied, piecewise constant).

Raises
------
ValueError
    A reference that does not start as the horizon does, sizes that do not match.
SolverError
    The integration failed.

Examples
--------
>>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
>>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
>>> reference = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 30.0)
>>> controller = hc.RecedingOnlineController(horizon, 0.05)
>>> run = hc.simulate_sampled_receding_horizon(reference, controller, None, [1.0, 0.0, 0.0, -1.0, -1.0, 0.5])
>>> run.status, controller.status().window_in_use
(<RunStatus.completed: 0>, 29))").c_str());

  m.def("receding_horizon_gamma_star", &receding_horizon_gamma_star, py::arg("horizon"), py::arg("tf"),
        py::arg("options") = GammaStarOptions{}, py::call_guard<ComputationScope>(),
        doc({"receding_horizon_gamma_star", "control/receding_horizon.hpp"}, R"(Parameters
----------
horizon : RecedingHorizon
    The windows' design (its gamma is not used: each window's gamma* is searched).
tf : float
    The end of the mission (s): the windows that start before it are searched.
options : GammaStarOptions, optional
    The bisection of each window (its solver is replaced by the horizon's).

Returns
-------
WindowGammaStar
    The largest gamma* over the windows, the window where it occurs and its search.

Raises
------
ValueError
    tf <= t0, bad options.
SolverError
    An integration failed.

Examples
--------
>>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
>>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
...                              hc.RecedingHorizonOptions(window=5.0, update=5.0))
>>> hc.receding_horizon_gamma_star(horizon, 10.0).windows
2)").c_str());
}
}  // namespace

void bind_control(py::module_& m) {
  // ---- enums ----
  bind_enum<RunStatus>(m, "RunStatus", R"(Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.tf = 10.0
>>> hc.run_scenario(scenario).simulation.status
<RunStatus.completed: 0>)");
  bind_enum<FilterLinearization>(m, "FilterLinearization", R"(Examples
--------
>>> hc.OutputFeedbackOptions(filter_A="desired").filter_A
<FilterLinearization.desired: 1>)");
  bind_enum<CouplingPolicy>(m, "CouplingPolicy", R"(Examples
--------
>>> hc.OutputFeedbackOptions(on_coupling_violation="flag").on_coupling_violation
<CouplingPolicy.flag: 1>)");
  bind_enum<GammaCondition>(m, "GammaCondition", R"(Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
>>> scenario.tf = 10.0
>>> hc.scenario_gamma_star(scenario).binding              # state feedback: the GRDE
<GammaCondition.grde: 1>
>>> hc.scenario_gamma_star_output_feedback(scenario).binding
<GammaCondition.coupling: 3>)");

  // ---- options ----
  bind_options<SimulationOptions>(m, "SimulationOptions", {"SimulationOptions"}, {}, R"(Raises
------
ValueError
    An option out of its range, naming it.

Examples
--------
>>> options = hc.SimulationOptions(output_dt=0.05, solver=hc.SolverOptions(method="erk"))
>>> options.output_dt, options.solver.method
(0.05, <Method.erk: 3>))");
  bind_options<TrajectoryOptions>(m, "TrajectoryOptions", {"TrajectoryOptions"}, {}, R"(Examples
--------
>>> options = hc.TrajectoryOptions(rtol=1e-8, atol=1e-10)
>>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 10.0, options)
>>> round(float(trajectory.q_d(10.0)[3]), 6)                # x_d(10) = 10 m at 1 m/s
10.0)");

  // ---- desired trajectory ----
  py::class_<Trajectory, py::smart_holder>(m, "Trajectory", doc({"Trajectory", "control/trajectory.hpp"}, R"(Parameters
----------
model : Model
    The design model.
q_d0 : array_like, shape (n,)
    The desired initial state q_d(t0).
u_d : VectorSignal, callable, or list of Signal or float
    The desired inputs, m channels: a VectorSignal, a callable ``u_d(t) -> array_like, shape (m,)``
    (t in seconds), or one Signal or number per input.
t0 : float
    The start of the horizon (s).
tf : float
    The end of the horizon (s), > t0.
options : TrajectoryOptions, optional
    Tolerances of the integration.

Raises
------
ValueError
    A model that is not valid, q_d0 not of shape (n,) or not finite, u_d without m channels,
    tf <= t0, bad options.
SolverError
    The integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> trajectory.q_d(10.0).round(3)                            # [u, v, r, x, y, psi] at t = 10 s
array([ 0.981, -0.192,  0.191,  8.814,  3.236,  1.331])
>>> trajectory.A_e(np.array([0.0, 5.0])).shape, trajectory.B_e(0.0).shape
((2, 6, 6), (6, 2)))").c_str())
      .def(py::init([](ModelPtr model, Vec q_d0, const py::object& u_d, double t0, double tf,
                       const TrajectoryOptions& options) {
             require(model != nullptr, "Trajectory needs a model");
             VectorSignal inputs = to_vector_signal(u_d, model->m(), "u_d");
             ComputationScope release;
             return std::make_shared<Trajectory>(std::move(model), std::move(q_d0), std::move(inputs), t0, tf,
                                                 options);
           }),
           py::arg("model"), py::arg("q_d0"), py::arg("u_d"), py::arg("t0"), py::arg("tf"),
           py::arg("options") = TrajectoryOptions{})
      .def("model", &Trajectory::model_ptr, doc({"Trajectory::model"}).c_str())
      .def("n", &Trajectory::n, doc({"Trajectory::n"}).c_str())
      .def("m", &Trajectory::m, doc({"Trajectory::n"}).c_str())
      .def("t0", &Trajectory::t0, doc({"Trajectory::t0"}).c_str())
      .def("tf", &Trajectory::tf, doc({"Trajectory::t0"}).c_str())
      .def("q_d0", &Trajectory::q_d0, doc({"Trajectory::q_d0"}).c_str())
      .def("u_d_signal", &Trajectory::u_d_signal, doc({"Trajectory::q_d0"}).c_str())
      .def("q_d", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.n(), 0, [&tr](double tt, double* out) { tr.q_d(tt, out); });
      }, py::arg("t"),
         doc({"Trajectory::q_d"}, "Shape (n,) for a number t, (k, n) for a 1-D array of k times.").c_str())
      .def("u_d", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.m(), 0, [&tr](double tt, double* out) { tr.u_d(tt, out); });
      }, py::arg("t"),
         doc({"Trajectory::u_d"}, "Shape (m,) for a number t, (k, m) for a 1-D array of k times.").c_str())
      .def("A_e", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.n(), tr.n(), [&tr](double tt, double* out) {
          Eigen::Map<Mat>(out, tr.n(), tr.n()) = tr.A_e(tt);
        });
      }, py::arg("t"),
         doc({"Trajectory::A_e"}, kSquareOfT).c_str())
      .def("B_e", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.n(), tr.m(), [&tr](double tt, double* out) {
          Eigen::Map<Mat>(out, tr.n(), tr.m()) = tr.B_e(tt);
        });
      }, py::arg("t"),
         doc({"Trajectory::A_e"}, "Shape (n, m) for a number t, (k, n, m) for a 1-D array of k times.").c_str())
      .def("D_e", [](const Trajectory& tr, const py::object& t) {
        return vectorize(t, tr.n(), tr.model().nw(), [&tr](double tt, double* out) {
          Eigen::Map<Mat>(out, tr.n(), tr.model().nw()) = tr.D_e(tt);
        });
      }, py::arg("t"),
         doc({"Trajectory::A_e"}, "Shape (n, nw) for a number t, (k, n, nw) for a 1-D array of k times.").c_str())
      .def("dense", &Trajectory::dense, py::return_value_policy::reference_internal, doc({"Trajectory::dense"}).c_str())
      .def("stats", &Trajectory::stats, doc({"Trajectory::dense"}).c_str())
      .def_static("from_states",
                  [](ModelPtr model, std::vector<double> t, const RowMat& q, const py::object& u_d,
                     const TrajectoryOptions& options) {
                    require(model != nullptr, "Trajectory.from_states needs a model");
                    VectorSignal inputs = to_vector_signal(u_d, model->m(), "u_d");
                    ComputationScope release;
                    return std::make_shared<Trajectory>(std::move(model), std::move(t), q, std::move(inputs), options);
                  },
                  py::arg("model"), py::arg("t"), py::arg("q"), py::arg("u_d"), py::arg("options") = TrajectoryOptions{},
                  doc({"Trajectory::Trajectory"}, R"(The desired trajectory given as states and inputs.

Parameters
----------
model : Model
    The design model.
t : array_like, shape (N + 1,)
    The nodes t_0 < ... < t_N (s): the horizon [t_0, t_N].
q : array_like, shape (N + 1, n)
    The desired states at the nodes.
u_d : VectorSignal, callable, or list of Signal or float
    The desired inputs, m channels.
options : TrajectoryOptions, optional
    Tolerances of each interval's integration.

Returns
-------
Trajectory
    Each interval integrated from its node; defects() are the misses at the next nodes.

Raises
------
ValueError
    Nodes not increasing or not finite, q not of shape (N + 1, n), a bad model or u_d.
SolverError
    An interval's integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> t = np.linspace(0.0, 10.0, 11)
>>> again = hc.Trajectory.from_states(hc.ShipModel(), t, trajectory.q_d(t), u_d)
>>> len(again.defects()), bool(again.max_defect() < 1e-8)
(10, True))").c_str())
      .def("node_times", &Trajectory::node_times, doc({"Trajectory::node_times"}).c_str())
      .def("defects", &Trajectory::defects, doc({"Trajectory::node_times"}).c_str())
      .def("max_defect", &Trajectory::max_defect, doc({"Trajectory::max_defect"}).c_str())
      .def("max_defect_t", &Trajectory::max_defect_t, doc({"Trajectory::max_defect"}).c_str())
      .def(py::pickle(
          [](const Trajectory& tr) {
            return py::make_tuple<py::return_value_policy::copy>(tr.model_ptr(), tr.q_d0(), tr.u_d_signal(), tr.t0(),
                                                                 tr.tf(), tr.dense(), tr.stats(), tr.node_times(),
                                                                 tr.defects());
          },
          [](const py::tuple& state) {
            check_state(state, 9, "Trajectory");
            return std::make_shared<Trajectory>(state[0].cast<ModelPtr>(), state[1].cast<Vec>(),
                                                state[2].cast<VectorSignal>(), state[3].cast<double>(),
                                                state[4].cast<double>(), state[5].cast<PiecewisePolynomial>(),
                                                state[6].cast<StepStats>(), state[7].cast<std::vector<double>>(),
                                                state[8].cast<std::vector<double>>());
          }));

  // ---- Riccati equations ----
  bind_result<SolveStats>(m, "SolveStats", {"SolveStats"}, {}, R"(Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> stats = design.stats()
>>> stats.method, stats.steps > 0, stats.memory_bytes == design.dense().memory_bytes()
('erk', True, True))", /*repr=*/true);

  py::class_<SymmetricSolution, py::smart_holder>(m, "SymmetricSolution", doc({"SymmetricSolution"}, R"(
The base of RiccatiSolution (Z) and FilterRiccatiSolution (Sigma), made by the solvers.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> isinstance(design, hc.SymmetricSolution), design.n(), design.gamma()
(True, 6, 5.0)
>>> np.round(design.eigenvalue_bounds(), 3)                   # m and M of eq. (22)
array([ 0.219, 20.815]))").c_str())
      .def("trajectory", &SymmetricSolution::trajectory_ptr, doc({"SymmetricSolution::trajectory"}).c_str())
      .def("n", &SymmetricSolution::n, doc({"SymmetricSolution::n"}).c_str())
      .def("gamma", &SymmetricSolution::gamma, doc({"SymmetricSolution::gamma"}).c_str())
      .def("t0", &SymmetricSolution::t0, doc({"SymmetricSolution::t0"}).c_str())
      .def("tf", &SymmetricSolution::tf, doc({"SymmetricSolution::t0"}).c_str())
      .def("value", [](const SymmetricSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &SymmetricSolution::value);
      }, py::arg("t"),
         doc({"SymmetricSolution::value"}, kSquareOfT).c_str())
      .def("derivative", [](const SymmetricSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &SymmetricSolution::derivative);
      }, py::arg("t"),
         doc({"SymmetricSolution::derivative"}, kSquareOfT).c_str())
      .def("eigenvalue_range", &range<SymmetricSolution>, py::arg("times"),
           doc({"SymmetricSolution::eigenvalue_range"}, "Returns (smallest, largest); times (s): a non-empty list.")
               .c_str())
      .def("eigenvalue_bounds", &bounds<SymmetricSolution>,
           doc({"SymmetricSolution::eigenvalue_bounds"}, "Returns (m, M).").c_str())
      .def("dense", &SymmetricSolution::dense, py::return_value_policy::reference_internal,
           doc({"SymmetricSolution::dense"}).c_str())
      .def("stats", &SymmetricSolution::stats, doc({"SymmetricSolution::dense"}).c_str())
      .def("blocks", &SymmetricSolution::blocks, doc({"SymmetricSolution::blocks"}).c_str());

  py::class_<RiccatiSolution, SymmetricSolution, py::smart_holder> riccati(m, "RiccatiSolution",
      doc({"RiccatiSolution", "control/riccati.hpp"}, R"(
Made by solve_grde (and run_scenario); it pickles with its trajectory.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> design.Z(np.array([0.0, 5.0, 10.0])).shape                  # Z(t) at three times
(3, 6, 6)
>>> np.allclose(design.Z(10.0), np.eye(6)), design.gain(0.0).shape   # Z(tf) = Qf; K = B' Z
(True, (2, 6)))").c_str());
  riccati.def("m", &RiccatiSolution::m, doc({"RiccatiSolution::m"}).c_str())
      .def("Z", [](const RiccatiSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &RiccatiSolution::Z);
      }, py::arg("t"),
         doc({"RiccatiSolution::Z"}, kSquareOfT).c_str())
      .def("dZdt", [](const RiccatiSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &RiccatiSolution::dZdt);
      }, py::arg("t"),
         doc({"RiccatiSolution::Z"}, kSquareOfT).c_str())
      .def("gain", [](const RiccatiSolution& s, const py::object& t) {
        return vectorize(t, s.m(), s.n(), [&s](double tt, double* out) { s.gain(tt, out); });
      }, py::arg("t"),
         doc({"RiccatiSolution::gain"}, "Shape (m, n) for a number t, (k, m, n) for a 1-D array of k times.").c_str());
  def_solution_pickle(riccati);

  py::class_<FilterRiccatiSolution, SymmetricSolution, py::smart_holder> filter(m, "FilterRiccatiSolution",
      doc({"FilterRiccatiSolution"}, R"(
Made by solve_filter_riccati; it pickles with its trajectory.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> Sigma = hc.solve_filter_riccati(trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
>>> np.allclose(Sigma.Sigma(0.0), np.eye(6)), Sigma.Sigma(10.0).diagonal().round(3)
(True, array([0.431, 0.377, 0.384, 0.276, 0.298, 0.272])))").c_str());
  filter.def("Sigma", [](const FilterRiccatiSolution& s, const py::object& t) {
          return matrix_of_t(s, t, &FilterRiccatiSolution::Sigma);
        }, py::arg("t"),
           doc({"FilterRiccatiSolution::Sigma"}, kSquareOfT).c_str())
      .def("dSigma_dt", [](const FilterRiccatiSolution& s, const py::object& t) {
        return matrix_of_t(s, t, &FilterRiccatiSolution::dSigma_dt);
      }, py::arg("t"),
         doc({"FilterRiccatiSolution::Sigma"}, kSquareOfT).c_str());
  def_solution_pickle(filter);

  m.def("solve_grde", &solve_grde, py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"),
        py::arg("options") = SolverOptions{}, py::call_guard<ComputationScope>(),
            doc({"solve_grde", "control/riccati.hpp"}, R"(
Parameters
----------
trajectory : Trajectory
    The desired trajectory: the horizon [t0, tf] and A_e, B_e, D_e along it.
Q : array_like, shape (n, n)
    Weight of the tracking error q_e.
Qf : array_like, shape (n, n)
    Final value, Z(tf) = Qf.
gamma : float
    The attenuation level; ``np.inf`` gives LQR.
options : SolverOptions, optional
    Integrator and tolerances.

Returns
-------
RiccatiSolution
    Z(t) on [t0, tf].

Raises
------
ValueError
    Q or Qf of another shape, not symmetric or not (semi)definite; gamma <= 0 or NaN; bad options.
ConjugatePointError
    Z escapes to infinity at t_escape (s): gamma is at or below gamma*.
SolverError
    The integration failed.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> np.round(design.eigenvalue_bounds(), 3)                   # m I <= Z(t) <= M I
array([ 0.219, 20.815])
>>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), np.inf)
>>> bool(np.all(np.linalg.eigvalsh(design.Z(0.0) - lqr.Z(0.0)) >= 0))  # Z grows as gamma falls
True)").c_str());
  m.def("solve_game_are", &solve_game_are, py::arg("A"), py::arg("B"), py::arg("D"), py::arg("Q"), py::arg("gamma"),
        doc({"solve_game_are", "control/riccati.hpp"}, R"(Parameters
----------
A : array_like, shape (n, n)
    The state matrix.
B : array_like, shape (n, m)
    The input matrix.
D : array_like, shape (n, nw)
    The disturbance matrix.
Q : array_like, shape (n, n)
    Weight of the state, symmetric positive semidefinite.
gamma : float
    The attenuation level; ``np.inf`` gives the LQR equation.

Returns
-------
numpy.ndarray, shape (n, n)
    The stabilizing solution P.

Raises
------
ValueError
    Bad sizes or values, or no stabilizing solution (gamma at or below the stationary game's
    gamma*, or (A, B) not stabilizable).

Examples
--------
>>> P = hc.solve_game_are([[0.0, 1.0], [0.0, 0.0]], [[0.0], [1.0]], [[0.0], [1.0]], np.eye(2), np.inf)
>>> np.round(P, 6)                     # the double integrator's LQR: [[sqrt 3, 1], [1, sqrt 3]]
array([[1.732051, 1.      ],
       [1.      , 1.732051]])
>>> P = hc.solve_game_are([[1.0]], [[1.0]], [[1.0]], [[1.0]], 2.0)   # 2 P + 1 - 0.75 P^2 = 0
>>> round(float(P[0, 0]), 6), round((2 + 7 ** 0.5) / 1.5, 6)
(3.097168, 3.097168))").c_str());
  m.def("solve_filter_riccati", &solve_filter_riccati, py::arg("trajectory"), py::arg("N"), py::arg("Q"),
        py::arg("gamma"), py::arg("Sigma0"), py::arg("options") = SolverOptions{},
        py::call_guard<ComputationScope>(), doc({"solve_filter_riccati"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory: A = A_e(t) and D = D_e(t) along it; its model gives C (Model.C).
N : array_like, shape (p, p)
    The measurement noise weight N = E E' (p measured outputs, the rows of C).
Q : array_like, shape (n, n)
    The weight of the performance index (the GRDE's Q).
gamma : float
    The attenuation level; ``np.inf`` gives the Kalman-Bucy filter.
Sigma0 : array_like, shape (n, n)
    Sigma(t0), symmetric positive definite.
options : SolverOptions, optional
    Integrator and tolerances.

Returns
-------
FilterRiccatiSolution
    Sigma(t) on [t0, tf].

Raises
------
ValueError
    A model without a measurement; matrices of other shapes, not symmetric or not (semi)definite;
    gamma <= 0 or NaN; bad options.
ConjugatePointError
    Sigma escapes to infinity or loses positive definiteness at t_escape (s).
SolverError
    The integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> Sigma = hc.solve_filter_riccati(trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
>>> np.round(Sigma.eigenvalue_bounds(), 3)
array([0.101, 1.005]))").c_str());
  m.def("grde_escape_time", &grde_escape_time, py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"),
        py::arg("options") = SolverOptions{}, py::call_guard<ComputationScope>(), doc({"grde_escape_time"}, R"(
Parameters
----------
trajectory : Trajectory
    The desired trajectory.
Q : array_like, shape (n, n)
    Weight of the tracking error.
Qf : array_like, shape (n, n)
    Final value Z(tf).
gamma : float
    The attenuation level.
options : SolverOptions, optional
    Integrator and tolerances.

Returns
-------
float
    The escape time (s), or NaN when Z stays finite on [t0, tf].

Raises
------
ValueError
    As solve_grde.
SolverError
    The integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> hc.grde_escape_time(trajectory, np.eye(6), np.eye(6), 5.0)              # gamma > gamma*
nan
>>> round(hc.grde_escape_time(trajectory, np.eye(6), np.eye(6), 1.0), 2)     # gamma < gamma* = 1.33
7.56)").c_str());
  m.def("filter_escape_time", &filter_escape_time, py::arg("trajectory"), py::arg("N"), py::arg("Q"),
        py::arg("gamma"), py::arg("Sigma0"), py::arg("options") = SolverOptions{},
        py::call_guard<ComputationScope>(), doc({"filter_escape_time"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory (A = A_e(t); C of its model).
N : array_like, shape (p, p)
    The measurement noise weight.
Q : array_like, shape (n, n)
    The weight of the performance index.
gamma : float
    The attenuation level.
Sigma0 : array_like, shape (n, n)
    Sigma(t0).
options : SolverOptions, optional
    Integrator and tolerances.

Returns
-------
float
    The first time (s) Sigma escapes or loses positive definiteness, or NaN.

Raises
------
ValueError
    As solve_filter_riccati.
SolverError
    The integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> hc.filter_escape_time(trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
nan)").c_str());

  // ---- controllers and disturbances ----
  py::class_<Controller, PyController, py::smart_holder>(m, "Controller",
      doc({"Controller", "control/controller.hpp"}, R"(
Notes
-----
Subclass it in Python and implement m() and control(t, q) -> array_like of shape (m,) (q: the
actual state, shape (n,); t in seconds), and optionally name() and n(). It is called at every
stage of the integrator, holding the GIL.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> class OpenLoop(hc.Controller):
...     def m(self): return 2
...     def control(self, t, q): return trajectory.u_d(t)      # u = u_d(t): no feedback
>>> run = hc.simulate_state_feedback(trajectory, OpenLoop(), None, [1, 0, 0, 0, 0, 0])
>>> bool(np.abs(run.q - run.q_d).max() < 1e-6)               # from q_d(t0): stays on q_d
True)").c_str())
      .def(py::init<>())
      .def("name", &Controller::name, doc({"Controller::name"}).c_str())
      .def("n", &Controller::n, doc({"Controller::n"}).c_str())
      .def("m", &Controller::m, doc({"Controller::m"}).c_str())
      .def("control", [](Controller& c, double t, const Vec& q) {
        check_finite(t, "t");
        if (c.n() > 0) check_size(q, c.n(), "q");
        Vec u(c.m());
        c.control(t, q, u);
        return u;
      }, py::arg("t"), py::arg("q"), doc({"Controller::control"}, "Returns u, shape (m,).").c_str());

  py::class_<HinfStateFeedback, Controller, py::smart_holder>(m, "HinfStateFeedback",
      doc({"HinfStateFeedback", "HinfStateFeedback::HinfStateFeedback"}, R"(
Parameters
----------
solution : RiccatiSolution
    The design Z (solve_grde).
kappa : Signal or float, default 1.0
    The gain scaling kappa(t), > 0 (>= 1/2 for the certificates).

Raises
------
ValueError
    No solution; later, kappa(t) <= 0 where the law evaluates it.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> law = hc.HinfStateFeedback(design, kappa=1.0)
>>> q0 = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])      # 1 m behind, 1 m aside, 45 deg off
>>> law.name(), law.control(0.0, q0).round(3)
('hinf', array([ 2.035, -1.947])))").c_str())
      .def(py::init([](RiccatiSolutionPtr solution, const py::object& kappa) {
             return std::make_shared<HinfStateFeedback>(std::move(solution), to_signal(kappa, "kappa"));
           }),
           py::arg("solution"), py::arg("kappa") = Signal(1.0))
      .def("solution", &HinfStateFeedback::solution, py::return_value_policy::reference_internal,
           doc({"HinfStateFeedback::solution"}).c_str())
      .def("kappa", &HinfStateFeedback::kappa, doc({"HinfStateFeedback::solution"}).c_str())
      .def("checked_kappa", &HinfStateFeedback::checked_kappa, py::arg("t"),
           doc({"HinfStateFeedback::checked_kappa"}).c_str());

  bind_options<BacksteppingGains>(m, "BacksteppingGains", {"BacksteppingGains"}, {}, R"(Examples
--------
>>> hc.BacksteppingGains(k=0.3)
BacksteppingGains(k=0.3, k1=1.0, k2=2.0, k3=1.0))");

  py::class_<BacksteppingController, Controller, py::smart_holder>(m, "BacksteppingController",
      doc({"BacksteppingController", "BacksteppingController::BacksteppingController"}, R"(
Parameters
----------
trajectory : Trajectory
    A desired trajectory of a ShipModel.
gains : BacksteppingGains, optional
    k, k1, k2, k3 > 0.

Raises
------
ValueError
    A model other than the ship, or gains not > 0.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> law = hc.BacksteppingController(trajectory)
>>> run = hc.simulate_state_feedback(trajectory, law, None, [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
>>> law.name(), bool(np.hypot(*run.q_e()[-1, 3:5]) < np.hypot(1.0, 1.0))  # closer at 10 s
('backstepping', True))").c_str())
      .def(py::init<TrajectoryPtr, const BacksteppingGains&>(), py::arg("trajectory"),
           py::arg("gains") = BacksteppingGains{})
      .def("gains", &BacksteppingController::gains, doc({"BacksteppingController::gains"}).c_str());

  bind_options<CascadeGains>(m, "CascadeGains", {"CascadeGains"}, {}, R"(Examples
--------
>>> hc.CascadeGains(k=0.5)
CascadeGains(k=0.5, k1=2.0, k2=3.0))");

  py::class_<CascadeController, Controller, py::smart_holder>(m, "CascadeController",
      doc({"CascadeController", "CascadeController::CascadeController"}, R"(
Parameters
----------
trajectory : Trajectory
    A desired trajectory of a ShipModel.
gains : CascadeGains, optional
    k, k1, k2 > 0.

Raises
------
ValueError
    A model other than the ship, or gains not > 0.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> law = hc.CascadeController(trajectory, hc.CascadeGains(k=0.2))
>>> run = hc.simulate_state_feedback(trajectory, law, None, [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
>>> law.name(), round(float(np.hypot(*run.q_e()[-1, 3:5])), 2)  # position error at 10 s (m)
('cascade', 1.34))").c_str())
      .def(py::init<TrajectoryPtr, const CascadeGains&>(), py::arg("trajectory"), py::arg("gains") = CascadeGains{})
      .def("gains", &CascadeController::gains, doc({"CascadeController::gains"}).c_str());

  py::class_<Disturbance>(m, "Disturbance", doc({"Disturbance", "control/disturbance.hpp"}, R"(
Wherever a Disturbance is expected, a VectorSignal (or what one is made from) is taken too.

Parameters
----------
signals : VectorSignal
    w(t), the model's nw channels: ``Disturbance(signals)`` is the signals alone.
design : RiccatiSolution or SymmetricSolution
    ``Disturbance(signals, design)`` adds the worst-case disturbance gamma^-2 D_e' X q_e of this
    solution X at its finite gamma: a design Z (eq. 16), or a law's own P
    (solve_law_riccati).

Raises
------
ValueError
    signals without nw channels, no design, or a design at gamma = inf.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> w = hc.Disturbance(hc.VectorSignal([0.1, 0.1, 0.1, 0, 0, 0]), design)
>>> q0 = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
>>> w.worst_case(), w.eval(0.0, q0).round(4)                  # signals + gamma^-2 D' Z q_e
(True, array([0.0586, 0.1472, 0.1779, 0.    , 0.    , 0.    ])))").c_str())
      .def(py::init<VectorSignal>(), py::arg("signals"))
      .def(py::init<VectorSignal, std::shared_ptr<const SymmetricSolution>>(), py::arg("signals"), py::arg("design"))
      .def("dim", &Disturbance::dim, doc({"Disturbance::dim"}).c_str())
      .def("worst_case", &Disturbance::worst_case, doc({"Disturbance::worst_case"}).c_str())
      .def("design", &Disturbance::design, doc({"Disturbance::design"}).c_str())
      .def("signals", &Disturbance::signals, doc({"Disturbance::signals"}).c_str())
      .def("eval", [](const Disturbance& d, double t, const Vec& q) {
        check_finite(t, "t");
        if (d.design()) check_size(q, d.design()->n(), "q");
        Vec w(d.dim());
        d.eval(t, q.data(), w.data());
        return w;
      }, py::arg("t"), py::arg("q"),
         doc({"Disturbance::eval"}, "Returns w, shape (nw,); q is read by the worst case only.").c_str());
  py::implicitly_convertible<VectorSignal, Disturbance>();

  // ---- simulation ----
  bind_result<EstimatorSeries>(m, "EstimatorSeries", {"EstimatorSeries"},
                               {{"q_hat", "ndarray, shape (k, n)"}, {"y", "ndarray, shape (k, p)"},
                                {"sigma_min_eig", "ndarray, shape (k,)"}, {"sigma_max_eig", "ndarray, shape (k,)"},
                                {"rho_sigma_z", "ndarray, shape (k,)"}},
                               R"(Notes
-----
k is the number of output times, p the number of measured outputs.

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
>>> scenario.tf = 10.0
>>> estimator = hc.run_scenario(scenario).simulation.estimator
>>> estimator.q_hat.shape, estimator.y.shape, bool(estimator.rho_sigma_z.max() < 25.0)
((1001, 6), (1001, 3), True))", /*repr=*/false);

  bind_result<SimulationResult>(m, "SimulationResult", {"SimulationResult"},
                                {{"t", "ndarray, shape (k,)"}, {"q", "ndarray, shape (k, n)"},
                                 {"q_d", "ndarray, shape (k, n)"}, {"u", "ndarray, shape (k, m)"},
                                 {"u_d", "ndarray, shape (k, m)"}, {"w", "ndarray, shape (k, nw)"}},
                                R"(Notes
-----
k is the number of output times.

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.tf = 10.0
>>> run = hc.run_scenario(scenario).simulation
>>> run.t.shape, run.q.shape, run.u.shape, run.status
((1001,), (1001, 6), (1001, 2), <RunStatus.completed: 0>)
>>> round(float(np.hypot(*run.q_e()[0, 3:5])), 3)              # initial position error (m)
1.414)",
                                /*repr=*/false)
      .def_property_readonly("estimator", [](const SimulationResult& r) -> const EstimatorSeries* {
        return r.estimator ? &*r.estimator : nullptr;
      }, py::return_value_policy::reference_internal,
         doc({"SimulationResult::estimator"}, "None under state feedback.").c_str())
      .def("q_e", &SimulationResult::q_e, doc({"SimulationResult::q_e"}, "Shape (k, n).").c_str());

  m.def("output_grid", &output_grid, py::arg("t0"), py::arg("tf"), py::arg("dt"), doc({"output_grid"}).c_str());
  m.def("output_count", &output_count, py::arg("t0"), py::arg("tf"), py::arg("dt"), doc({"output_count"}).c_str());
  m.def("simulate_state_feedback",
        [](const Trajectory& trajectory, Controller& controller, const py::object& disturbance, const Vec& q0,
           const SimulationOptions& options, const std::optional<ModelPtr>& plant) {
          check_controller_fits(controller, trajectory.model());
          const Disturbance w = to_disturbance(disturbance, trajectory.model().nw());
          ComputationScope release;
          return simulate_state_feedback(trajectory, controller, w, q0, options, plant ? plant->get() : nullptr);
        },
        py::arg("trajectory"), py::arg("controller"), py::arg("disturbance"), py::arg("q0"),
        py::arg("options") = SimulationOptions{}, py::arg("plant") = py::none(),
        doc({"simulate_state_feedback", "control/simulation.hpp"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory (of the design model): q_d and the divergence bound.
controller : Controller
    The law, e.g. HinfStateFeedback, CascadeController, or a Python Controller.
disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
    The disturbance on the model's nw channels: a callable is ``w(t) -> array_like, shape (nw,)``
    (t in seconds); None is zero.
q0 : array_like, shape (n,)
    The initial state q(t0).
options : SimulationOptions, optional
    Output step (s), divergence factor and integrator.
plant : Model or None, optional
    The vehicle integrated, of the design model's structure; None: the trajectory's model.

Returns
-------
SimulationResult
    The series on the output grid; status diverged when the run stopped early.

Raises
------
ValueError
    q0 not of shape (n,) or not finite, a controller or disturbance of other sizes, a plant of
    another structure, bad options.
SolverError
    The integration failed.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> law = hc.HinfStateFeedback(design)
>>> w = hc.Signal(0.0, [hc.Harmonic(0.1, 2 * np.pi * 0.2, cosine=True)])     # paper Fig. 1
>>> q0 = [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4]                 # 1 m behind, 1 m aside, 45 deg off
>>> run = hc.simulate_state_feedback(trajectory, law, [w, w, w, 0, 0, 0], q0)
>>> error = np.hypot(run.q_e()[:, 3], run.q_e()[:, 4])       # position error (m)
>>> round(float(error[0]), 3), bool(error[-1] < 0.1)
(1.414, True))").c_str());

  bind_options<OutputFeedbackProblem>(m, "OutputFeedbackProblem", {"OutputFeedbackProblem"},
                                      {{"noise", "array_like, shape (k, p)"}, {"N", "array_like, shape (p, p)"},
                                       {"Sigma0", "array_like, shape (n, n)"}, {"Q", "array_like, shape (n, n)"}},
                                      R"(Notes
-----
k is noise_sample_count(t0, tf, sample_period), p the number of measured outputs (rows of the
model's C).

Raises
------
ValueError
    sigma < 0, sample_period <= 0, N or Sigma0 not symmetric positive definite, Q not
    symmetric positive semidefinite of Sigma0's size, noise not finite; the sizes against the
    design's model are checked by simulate_output_feedback.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> noise = hc.scenario_noise(hc.load_scenario(hc.scenario_path("paper_fig2")))[:1000]
>>> problem = hc.OutputFeedbackProblem(design, sigma=0.5, sample_period=0.01, noise=noise,
...                                    N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
>>> problem.noise.shape, problem.design.gamma()
((1000, 3), 5.0))", &check_problem);
  bind_options<OutputFeedbackOptions>(m, "OutputFeedbackOptions", {"OutputFeedbackOptions"}, {}, R"(Examples
--------
>>> hc.OutputFeedbackOptions(on_coupling_violation="flag", sigma_eigenvalues=False)
OutputFeedbackOptions(filter_A='estimate', on_coupling_violation='flag', sigma_eigenvalues=False))");

  m.def("noise_sample_count", &noise_sample_count, py::arg("t0"), py::arg("tf"), py::arg("period"),
        doc({"noise_sample_count"}).c_str());
  m.def("standard_normal_samples",
        [](std::uint64_t seed, long count, int channels) {
          // A few GB at most: an absurd count is an input error, not an attempt to allocate it.
          constexpr double kMaxNumbers = 1e9;
          require(count >= 0, "count must be >= 0, got ", count);
          check_dimension(channels, 0, "channels");
          require(static_cast<double>(count) * channels <= kMaxNumbers, "standard_normal_samples: count x channels = ",
                  count, " x ", channels, " is more than the ", kMaxNumbers, " numbers (8 GB) allowed");
          ComputationScope release;
          return standard_normal_samples(seed, count, channels);
        },
        py::arg("seed"), py::arg("count"), py::arg("channels"),
        doc({"standard_normal_samples"}, "At most 1e9 numbers (count x channels).").c_str());
  m.def("simulate_output_feedback",
        [](const OutputFeedbackProblem& problem, Controller& controller, const py::object& disturbance,
           const Vec& q0, const OutputFeedbackOptions& options, const SimulationOptions& simulation,
           const std::optional<ModelPtr>& plant) {
          require(problem.design != nullptr, "the output-feedback problem needs a design (a GRDE solution)");
          const Model& model = problem.design->trajectory().model();
          check_controller_fits(controller, model);
          const Disturbance w = to_disturbance(disturbance, model.nw());
          ComputationScope release;
          return simulate_output_feedback(problem, controller, w, q0, options, simulation,
                                          plant ? plant->get() : nullptr);
        },
        py::arg("problem"), py::arg("controller"), py::arg("disturbance"), py::arg("q0"),
        py::arg("options") = OutputFeedbackOptions{}, py::arg("simulation") = SimulationOptions{},
        py::arg("plant") = py::none(),
        doc({"simulate_output_feedback", "control/output_feedback.hpp"}, R"(Parameters
----------
problem : OutputFeedbackProblem
    The design (Z, gamma, trajectory), the noise samples and the filter's weights.
controller : Controller
    The law, applied at the estimated state q_d + q_hat (HinfStateFeedback of the design: eq. 34).
disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
    The disturbance on the model's nw channels, as for simulate_state_feedback (zero on the
    noise channels).
q0 : array_like, shape (n,)
    The initial state q(t0).
options : OutputFeedbackOptions, optional
    The filter's A and what a coupling violation does.
simulation : SimulationOptions, optional
    Output step (s), divergence factor and integrator.
plant : Model or None, optional
    The vehicle integrated, of the design model's structure; None: the design's model.

Returns
-------
SimulationResult
    The series on the output grid, with the estimator's series.

Raises
------
ValueError
    A problem without a design, or whose sizes do not fit the model; q0 not of shape (n,);
    a controller, disturbance or plant of other sizes; bad options.
CouplingConditionError
    rho(Sigma Z) >= gamma^2 (unless on_coupling_violation is "flag").
SolverError
    The integration failed.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> noise = hc._core.standard_normal_samples(1, hc._core.noise_sample_count(0.0, 10.0, 0.01), 3)
>>> problem = hc.OutputFeedbackProblem(design, sigma=0.5, sample_period=0.01, noise=noise,
...                                    N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
>>> run = hc.simulate_output_feedback(problem, hc.HinfStateFeedback(design), None,
...                                   [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
>>> run.estimator.q_hat.shape, round(float(run.estimator.rho_sigma_z.max()), 2)  # < gamma^2 = 25
((1001, 6), 20.81))").c_str());

  // ---- metrics (metrics.hpp: metric_table() is their one definition) ----
  py::class_<MetricDefinition>(m, "MetricDefinition", doc({"MetricDefinition"}, R"(Examples
--------
>>> definition = hc.metric_table()[0]
>>> definition.name, definition.unit, definition.definition
('rms_position_error_last_half', 'm', 'sqrt(mean over the last half of |p - p_d|^2)'))").c_str())
      .def_readonly("name", &MetricDefinition::name, doc({"MetricDefinition::name"}).c_str())
      .def_readonly("label", &MetricDefinition::label, doc({"MetricDefinition::label"}).c_str())
      .def_readonly("unit", &MetricDefinition::unit, doc({"MetricDefinition::unit"}).c_str())
      .def_readonly("definition", &MetricDefinition::definition, doc({"MetricDefinition::definition"}).c_str())
      .def("__repr__", [](const MetricDefinition& d) { return str_cat("MetricDefinition('", d.name, "')"); });
  m.def("metric_table", [] { return std::vector<MetricDefinition>(metric_table().begin(), metric_table().end()); },
        doc({"metric_table"}, R"(Returns
-------
list of MetricDefinition

Examples
--------
>>> [definition.name for definition in hc.metric_table()][:3]
['rms_position_error_last_half', 'max_position_error', 'final_position_error'])").c_str());

  std::string metric_attributes = "Attributes\n----------";
  for (const MetricDefinition& d : metric_table())
    metric_attributes +=
        str_cat("\n", d.name, " : float\n", indented(wrapped(str_cat(d.definition, " (unit: ", d.unit, ")"), 92), 4));
  py::class_<Metrics> metrics(m, "Metrics", doc({"Metrics", "control/metrics.hpp"}, metric_attributes + R"(

Examples
--------
>>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
>>> scenario.tf = 10.0
>>> metrics = hc.run_scenario(scenario).metrics
>>> round(metrics.max_position_error, 3), metrics.max_rho_sigma_z        # NaN: state feedback
(1.414, nan))").c_str());
  for (const MetricDefinition& d : metric_table()) {
    const auto member = d.value;
    metrics.def_property_readonly(d.name, [member](const Metrics& x) { return x.*member; },
                                  str_cat(d.definition, " (unit: ", d.unit, ")").c_str());
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
  m.def(
      "compute_metrics",
      [](const Model& model, const SimulationResult& run, const Mat& Q, const std::optional<Mat>& Qf, double gamma,
         double initial_term) {
        CostWeights weights;
        weights.Q = Q;
        if (Qf) weights.Qf = *Qf;
        weights.gamma = gamma;
        weights.initial_term = initial_term;
        return compute_metrics(model, run, weights);
      },
      py::arg("model"), py::arg("run"), py::arg("Q"), py::arg("Qf") = py::none(),
      py::arg("gamma") = std::numeric_limits<double>::infinity(), py::arg("initial_term") = NAN,
      doc({"compute_metrics"}, R"(
Parameters
----------
model : Model
    The model simulated (its position and heading indices).
run : SimulationResult
    The closed-loop run.
Q : array_like, shape (n, n)
    The weight of q_e in the tracking cost and the gains.
Qf : array_like, shape (n, n), optional
    The weight of q_e(tf) in the tracking cost; none: no terminal term.
gamma : float, default inf
    The H-infinity law's attenuation level, for attenuation_margin; inf: no margin.
initial_term : float, default nan
    The initial-error term of the law's bound (q_e0' Z(t0) q_e0 with state feedback); nan: no
    margin.

Returns
-------
Metrics

Raises
------
ValueError
    Series whose shapes do not fit the model, Q or Qf not symmetric positive semidefinite, gamma
    not > 0 or initial_term negative.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> run = hc.simulate_state_feedback(trajectory, hc.HinfStateFeedback(design), None,
...                               [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
>>> metrics = hc.compute_metrics(trajectory.model(), run, np.eye(6))
>>> round(metrics.max_position_error, 3), metrics.response_ratio         # no disturbance: no gain
(1.414, nan))").c_str());
  m.def("l2_norm", &l2_norm, py::arg("t"), py::arg("series"), doc({"l2_norm"}).c_str());

  // ---- gamma* and certificates (paper §3) ----
  bind_options<GammaStarOptions>(m, "GammaStarOptions", {"GammaStarOptions"}, {}, R"(Notes
-----
For a model implemented in Python the search evaluates one gamma at a time (its calls hold the
GIL).

Raises
------
ValueError
    An option out of its range, naming it.

Examples
--------
>>> options = hc.GammaStarOptions(lower=1.0, upper=2.0, rtol=1e-4)
>>> options.threads, options.solver.method
(2, <Method.auto: 0>))");
  bind_result<GammaTrial>(m, "GammaTrial", {"GammaTrial"}, {}, R"(Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> first = hc.gamma_star(trajectory, np.eye(6), np.eye(6)).trials[0]
>>> first.gamma, first.passed, first.condition, round(first.t_escape, 2)
(1.0, False, <GammaCondition.grde: 1>, 7.56))", /*repr=*/true);
  bind_result<GammaStarResult>(m, "GammaStarResult", {"GammaStarResult"}, {}, R"(Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> result = hc.gamma_star(trajectory, np.eye(6), np.eye(6))
>>> round(result.gamma_star, 4), result.binding, result.converged
(1.3346, <GammaCondition.grde: 1>, True))", /*repr=*/false)
      .def("__repr__", [](const GammaStarResult& r) {
        return str_cat("GammaStarResult(gamma_star=", r.gamma_star, ", bracket=[", r.lower, ", ", r.upper,
                       "], binding='", to_string(r.binding), "', t_escape_lower=", r.t_escape_lower,
                       ", evaluations=", r.trials.size(), ", rhs_evals=", r.rhs_evals, ")");
      });

  m.def("gamma_star",
        [](const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, const GammaStarOptions& options) {
          return gamma_star(trajectory, Q, Qf, serial_for_python_models(model_of(trajectory), options));
        },
        py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("options") = GammaStarOptions{},
        py::call_guard<ComputationScope>(), doc({"gamma_star", "control/analysis.hpp"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory (its horizon [t0, tf]).
Q : array_like, shape (n, n)
    Weight of the tracking error, symmetric positive semidefinite.
Qf : array_like, shape (n, n)
    Final value Z(tf), symmetric positive definite.
options : GammaStarOptions, optional
    The bracket, tolerance, evaluations, threads and solver options.

Returns
-------
GammaStarResult
    gamma*, the final bracket and every gamma tried.

Raises
------
ValueError
    Q or Qf not such weights, bad options.
SolverError
    An integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> result = hc.gamma_star(trajectory, np.eye(6), np.eye(6))
>>> round(result.gamma_star, 4), result.binding                  # below it, no design
(1.3346, <GammaCondition.grde: 1>))").c_str());
  m.def("law_gain",
        [](const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf, const Signal& kappa,
           const GammaStarOptions& options) {
          require(law != nullptr, "law_gain needs the law's design (a RiccatiSolution)");
          return law_gain(law, Q, Qf, kappa, serial_for_python_models(model_of(law->trajectory_ptr()), options));
        },
        py::arg("law"), py::arg("Q"), py::arg("Qf"), py::arg("kappa") = Signal(1.0),
        py::arg("options") = GammaStarOptions{}, py::call_guard<ComputationScope>(),
        doc({"law_gain", "control/analysis.hpp"}, R"(Parameters
----------
law : RiccatiSolution
    The law's design: Z of the GRDE at the law's gamma (the H-infinity law), or at gamma = inf
    (the LQR law). The law is u = u_d - kappa B_e' Z (q - q_d).
Q : array_like, shape (n, n)
    Weight of the tracking error in z, symmetric positive semidefinite.
Qf : array_like, shape (n, n)
    Weight of the final error, symmetric positive definite.
kappa : float or Signal, optional
    The law's gain scaling kappa(t) > 0 (default 1).
options : GammaStarOptions, optional
    The bracket, tolerance, evaluations, threads and solver options of the search.

Returns
-------
GammaStarResult
    The induced L2 gain of the law's linearized closed loop from w to z on [t0, tf] as
    gamma_star, with its bracket and every gamma tried.

Raises
------
ValueError
    Q or Qf not such weights, kappa not > 0, bad options.
SolverError
    An integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> hinf = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
>>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), float("inf"))
>>> gains = [hc.law_gain(law, np.eye(6), np.eye(6)).gamma_star for law in (hinf, lqr)]
>>> [round(gain, 3) for gain in gains]                       # each law's own attenuation
[2.071, 2.134])").c_str());
  m.def("law_escape_time", &law_escape_time, py::arg("law"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"),
        py::arg("kappa") = Signal(1.0), py::arg("options") = SolverOptions{}, py::call_guard<ComputationScope>(),
        doc({"law_escape_time"}, R"(Parameters
----------
law : RiccatiSolution
    The law's design (see law_gain).
Q : array_like, shape (n, n)
    The weight of the tracking error in z.
Qf : array_like, shape (n, n)
    The weight of the final error.
gamma : float
    The level tested.
kappa : float or Signal, optional
    The law's gain scaling (default 1).
options : SolverOptions, optional
    Integrator and tolerances.

Returns
-------
float
    The first escape of the law's closed-loop Riccati equation (backward from tf), or NaN when
    there is none: the law's induced L2 gain is below gamma.

Raises
------
ValueError
    As law_gain.
SolverError
    The integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), float("inf"))
>>> hc.law_escape_time(lqr, np.eye(6), np.eye(6), 2.2)             # above its gain 2.134
nan
>>> round(hc.law_escape_time(lqr, np.eye(6), np.eye(6), 2.0), 2)   # below: P escapes at t = 3.35
3.35)").c_str());
  m.def("solve_law_riccati", &solve_law_riccati, py::arg("law"), py::arg("Q"), py::arg("Qf"), py::arg("gamma"),
        py::arg("kappa") = Signal(1.0), py::arg("options") = SolverOptions{}, py::call_guard<ComputationScope>(),
        doc({"solve_law_riccati"}, R"(Parameters
----------
law : RiccatiSolution
    The law's design (see law_gain).
Q : array_like, shape (n, n)
    The weight of the tracking error in z.
Qf : array_like, shape (n, n)
    The weight of the final error.
gamma : float
    Above the law's gain (law_gain).
kappa : float or Signal, optional
    The law's gain scaling (default 1).
options : SolverOptions, optional
    Integrator and tolerances.

Returns
-------
SymmetricSolution
    P(t) of the law's closed-loop Riccati equation; the law's worst-case disturbance at gamma
    is w = gamma^-2 D_e' P (q - q_d).

Raises
------
ValueError
    As law_gain.
ConjugatePointError
    gamma is at or below the law's gain.
SolverError
    The integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), float("inf"))
>>> P = hc.solve_law_riccati(lqr, np.eye(6), np.eye(6), 2.2)
>>> bool(np.all(np.linalg.eigvalsh(P.value(0.0)) > 0))
True)").c_str());
  m.def("controller_gain",
        [](const TrajectoryPtr& trajectory, Controller& controller, const Mat& Q, const Mat& Qf,
           const GammaStarOptions& options) { return controller_gain(trajectory, controller, Q, Qf, options); },
        py::arg("trajectory"), py::arg("controller"), py::arg("Q"), py::arg("Qf"),
        py::arg("options") = GammaStarOptions{}, py::call_guard<ComputationScope>(),
        doc({"controller_gain", "control/analysis.hpp"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory the controller tracks (its model's n and m).
controller : Controller
    Any state-feedback controller: CascadeController, BacksteppingController, a law written in
    Python. It is linearized along the trajectory, K(t) = -du/dq at q_d(t), by its
    control_jacobian (central differences unless it has its own).
Q : array_like, shape (n, n)
    Weight of the tracking error in z, symmetric positive semidefinite.
Qf : array_like, shape (n, n)
    Weight of the final error, symmetric positive definite.
options : GammaStarOptions, optional
    The bracket, tolerance, evaluations and solver options of the search (one gamma at a time).

Returns
-------
GammaStarResult
    The induced L2 gain of the controller's linearized closed loop from w to z on [t0, tf] as
    gamma_star.

Raises
------
ValueError
    A controller of other sizes than the model, Q or Qf not such weights, bad options.
SolverError
    An integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> gains = [hc.controller_gain(trajectory, law, np.eye(6), np.eye(6)).gamma_star
...          for law in (hc.CascadeController(trajectory), hc.BacksteppingController(trajectory))]
>>> [round(gain, 2) for gain in gains]                       # the ship baselines' attenuation
[4.33, 2.57])").c_str());
  m.def("controller_escape_time", &controller_escape_time, py::arg("trajectory"), py::arg("controller"), py::arg("Q"),
        py::arg("Qf"), py::arg("gamma"), py::arg("options") = SolverOptions{}, py::call_guard<ComputationScope>(),
        doc({"controller_escape_time"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory the controller tracks.
controller : Controller
    The controller (see controller_gain).
Q : array_like, shape (n, n)
    The weight of the tracking error in z.
Qf : array_like, shape (n, n)
    The weight of the final error.
gamma : float
    The level tested.
options : SolverOptions, optional
    Integrator and tolerances.

Returns
-------
float
    The first escape of the controller's closed-loop Riccati equation (backward from tf), or
    NaN: its induced L2 gain is below gamma.

Raises
------
ValueError
    As controller_gain.
SolverError
    The integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> law = hc.BacksteppingController(trajectory)
>>> hc.controller_escape_time(trajectory, law, np.eye(6), np.eye(6), 10.0)
nan)").c_str());
  m.def("solve_controller_riccati", &solve_controller_riccati, py::arg("trajectory"), py::arg("controller"),
        py::arg("Q"), py::arg("Qf"), py::arg("gamma"), py::arg("options") = SolverOptions{},
        py::call_guard<ComputationScope>(),
        doc({"solve_controller_riccati"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory the controller tracks.
controller : Controller
    The controller (see controller_gain).
Q : array_like, shape (n, n)
    The weight of the tracking error in z.
Qf : array_like, shape (n, n)
    The weight of the final error.
gamma : float
    Above the controller's gain (controller_gain).
options : SolverOptions, optional
    Integrator and tolerances.

Returns
-------
SymmetricSolution
    P(t) of the controller's closed-loop Riccati equation; its worst-case disturbance at gamma
    is w = gamma^-2 D_e' P (q - q_d) (hc.Disturbance takes it).

Raises
------
ValueError
    As controller_gain.
ConjugatePointError
    gamma is at or below the controller's gain.
SolverError
    The integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> P = hc.solve_controller_riccati(trajectory, hc.BacksteppingController(trajectory), np.eye(6), np.eye(6), 10.0)
>>> bool(np.all(np.linalg.eigvalsh(P.value(0.0)) > 0))
True)").c_str());
  m.def("gamma_star_output_feedback",
        [](const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, const Mat& N, const Mat& Sigma0,
           const GammaStarOptions& options) {
          return gamma_star_output_feedback(trajectory, Q, Qf, N, Sigma0,
                                            serial_for_python_models(model_of(trajectory), options));
        },
        py::arg("trajectory"), py::arg("Q"), py::arg("Qf"), py::arg("N"), py::arg("Sigma0"),
        py::arg("options") = GammaStarOptions{}, py::call_guard<ComputationScope>(),
        doc({"gamma_star_output_feedback"}, R"(Parameters
----------
trajectory : Trajectory
    The desired trajectory (its model has a measurement, Model.C).
Q : array_like, shape (n, n)
    Weight of the tracking error.
Qf : array_like, shape (n, n)
    Final value Z(tf).
N : array_like, shape (p, p)
    The measurement noise weight, symmetric positive definite.
Sigma0 : array_like, shape (n, n)
    Sigma(t0), symmetric positive definite.
options : GammaStarOptions, optional
    The bracket, tolerance, evaluations, threads and solver options.

Returns
-------
GammaStarResult
    The smallest gamma; binding is the condition that limits it.

Raises
------
ValueError
    A model without a measurement, matrices that are not such weights, bad options.
SolverError
    An integration failed.

Examples
--------
)" HINF_TRAJECTORY_EXAMPLE R"(
>>> N, Sigma0 = 0.25 * np.eye(3), np.eye(6)                  # x, y, psi measured; Sigma(t0)
>>> result = hc.gamma_star_output_feedback(trajectory, np.eye(6), np.eye(6), N, Sigma0)
>>> round(result.gamma_star, 2), result.binding                  # the GRDE alone allows 1.33
(4.59, <GammaCondition.coupling: 3>))").c_str());
  m.def("max_rho_sigma_z",
        [](const RiccatiSolution& Z, const FilterRiccatiSolution& Sigma) {
          require(Z.n() == Sigma.n(), "max_rho_sigma_z: Z is ", Z.n(), " x ", Z.n(), " but Sigma is ", Sigma.n(), " x ",
                  Sigma.n(), ": pass the solutions of one design");
          ComputationScope release;
          return max_rho_sigma_z(Z, Sigma);
        },
        py::arg("Z"), py::arg("Sigma"), doc({"max_rho_sigma_z"}, R"(Parameters
----------
Z : RiccatiSolution
    The GRDE's solution.
Sigma : FilterRiccatiSolution
    The filter's solution along the same trajectory.

Returns
-------
tuple of float
    (the largest rho(Sigma(t) Z(t)), t in seconds).

Raises
------
ValueError
    Solutions of different sizes.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> Sigma = hc.solve_filter_riccati(trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
>>> rho, t = hc.max_rho_sigma_z(design, Sigma)
>>> round(rho, 2), t, rho < design.gamma() ** 2              # the coupling condition holds
(20.81, 0.0, True))").c_str());

  bind_result<Certificates>(m, "Certificates", {"Certificates"}, {}, R"(Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> certificates = hc.certify(design, 1.0, np.eye(6))
>>> round(certificates.m, 3), round(certificates.M, 3), round(certificates.p_min, 3)
(0.219, 20.815, 1.0))", /*repr=*/true);
  m.def("certify",
        [](const RiccatiSolution& Z, const py::object& kappa, const Mat& Q) {
          const Signal k = to_signal(kappa, "kappa");
          ComputationScope release;
          return certify(Z, k, Q);
        },
        py::arg("Z"), py::arg("kappa"), py::arg("Q"), doc({"certify"}, R"(Parameters
----------
Z : RiccatiSolution
    The design (solve_grde).
kappa : Signal or float
    The gain scaling kappa(t) of the law.
Q : array_like, shape (n, n)
    The GRDE's weight Q.

Returns
-------
Certificates

Raises
------
ValueError
    kappa not a Signal or a finite number; Q not a symmetric positive semidefinite (n, n) matrix.

Examples
--------
)" HINF_DESIGN_EXAMPLE R"(
>>> certificates = hc.certify(design, 1.0, np.eye(6))
>>> certificates.remainder_is_bound, certificates.decay_rate > 0      # the ship's analytic L
(True, True))").c_str());
  bind_digital(m);
  bind_sampled_loop(m);
  bind_receding_horizon(m);
}

#undef HINF_DESIGN_EXAMPLE
#undef HINF_TRAJECTORY_EXAMPLE

}  // namespace hinf::python
