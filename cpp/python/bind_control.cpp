// The Python bindings of the control layer (cpp/include/hinf/control): the desired trajectory,
// the Riccati equations, the laws (and controllers implemented in Python), disturbances, closed
// loops, output feedback, metrics, gamma* and the certificates.
#include "casters.hpp"
#include "fields.hpp"
#include "hinf/control/analysis.hpp"
#include "hinf/control/cascade.hpp"
#include "hinf/control/controller.hpp"
#include "hinf/control/disturbance.hpp"
#include "hinf/control/metrics.hpp"
#include "hinf/control/output_feedback.hpp"
#include "hinf/control/riccati.hpp"
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

}  // namespace

void bind_control(py::module_& m) {
  // ---- enums ----
  bind_enum<RunStatus>(m, "RunStatus", "How a closed-loop run ended (simulation.hpp)");
  bind_enum<FilterLinearization>(m, "FilterLinearization",
                                 "Which A the filter Riccati equation (36) uses (output_feedback.hpp)");
  bind_enum<CouplingPolicy>(m, "CouplingPolicy",
                            "What a violation of rho(Sigma Z) < gamma^2 does (output_feedback.hpp)");
  bind_enum<GammaCondition>(m, "GammaCondition", "The condition a gamma fails (analysis.hpp)");

  // ---- options ----
  bind_options<SimulationOptions>(m, "SimulationOptions",
                                  "How a closed loop is simulated ([output] dt and [solver] of a scenario)");
  bind_options<TrajectoryOptions>(m, "TrajectoryOptions", "Tolerances of the desired trajectory's integration");

  // ---- desired trajectory ----
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
}

}  // namespace hinf::python
