"""Pickling: scenarios, models, options and results go to other processes and machines.

A Scenario travels as its scenario file (scenario_toml) plus solver.escape_norm; models,
signals, options and result structs by value; a Trajectory and a Riccati solution with their
dense output (the integrator's pieces), so nothing is recomputed. Every round trip must give
an equal object: the same code reads the same numbers, so the comparisons are exact."""

from __future__ import annotations

import math
import multiprocessing
import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import hinf_cpp as hc

SHIPPED = ["paper_fig1", "paper_fig2", "poor_heading_180", "poor_position_ahead"]


def round_trip(value):
    return pickle.loads(pickle.dumps(value))


# ---- enums, options and small structs: by value ----

def enum_members():
    return [member for enum in (hc.Method, hc.RunStatus, hc.Law, hc.FilterLinearization, hc.CouplingPolicy,
                                hc.GammaCondition) for member in enum.__members__.values()]


@pytest.mark.parametrize("member", enum_members(), ids=str)
def test_enums_pickle_and_compare_by_member(member):
    assert round_trip(member) == member and type(round_trip(member)) is type(member)
    assert type(member)(member.name) == member  # built from its name
    others = [m for m in type(member).__members__.values() if m != member]
    assert others and all(round_trip(member) != m for m in others)
    assert member != member.name  # a member is not its name (hashes differ)
    assert hash(round_trip(member)) == hash(member)


def changed_options():
    """One value of each option struct away from its defaults, and a second that differs from
    the first in one field."""
    return {
        "SolverOptions": (hc.SolverOptions("erk", 1e-9, 1e-11, 1234, 1e7), dict(escape_norm=1e8)),
        "SimulationOptions": (hc.SimulationOptions(0.05, 50.0, hc.SolverOptions("adams")), dict(output_dt=0.1)),
        "TrajectoryOptions": (hc.TrajectoryOptions(1e-9, 1e-11, 5000), dict(max_steps=6000)),
        "GammaStarOptions": (hc.GammaStarOptions(1.0, 3.0, 1e-6, 40, 1, hc.SolverOptions("erk")), dict(upper=4.0)),
        "OutputFeedbackOptions": (hc.OutputFeedbackOptions("desired", "flag"), dict(filter_A="estimate")),
        "MeasurementSpec": (hc.MeasurementSpec(0.3, 0.02, 2**63 + 5, 0.09 * np.eye(3), 3.0 * np.eye(6), 0.5,
                                               "desired", "flag"), dict(N=0.1 * np.eye(3))),
        "ShipParameters": (hc.ShipParameters(0.7, -1.5, 0.4, 1.1, 2.2, 0.9), dict(d_r=1.0)),
        "CascadeGains": (hc.CascadeGains(0.3, 2.5, 3.5), dict(k2=3.0)),
        "Harmonic": (hc.Harmonic(0.3, 0.2, 0.1, True), dict(cosine=False)),
    }


@pytest.mark.parametrize("name", list(changed_options()))
def test_option_structs_pickle_by_value(name):
    value, change = changed_options()[name]
    copy = round_trip(value)
    assert type(copy) is type(value) and copy == value and copy is not value
    assert value != getattr(hc, name)()  # the value differs from the defaults ...
    other = round_trip(value)
    for field, new in change.items():
        setattr(other, field, new)
    assert other != value  # ... and == sees a change of one field
    assert eval(repr(value), {**vars(hc), "array": np.array}) == value  # the repr builds it again


def test_nested_options_are_copied_not_shared():
    options = hc.GammaStarOptions(solver=hc.SolverOptions("erk"))
    copy = round_trip(options)
    copy.solver.rtol = 1e-6
    assert options.solver.rtol == 1e-8 and copy.solver.rtol == 1e-6


def test_output_feedback_problem_pickles_with_its_design(paper_solutions):
    noise = hc._core.standard_normal_samples(3, 4000, 3)
    problem = hc.OutputFeedbackProblem(paper_solutions["erk"], 0.5, 0.01, noise, 0.25 * np.eye(3), np.eye(6),
                                       np.eye(6))
    copy = round_trip(problem)
    for field in ("sigma", "sample_period", "noise", "N", "Sigma0", "Q"):
        assert np.array_equal(getattr(copy, field), getattr(problem, field)), field
    times = np.linspace(0.0, 40.0, 333)
    np.testing.assert_array_equal(copy.design.Z(times), problem.design.Z(times))


# ---- signals and models ----

def test_signals_pickle_by_value():
    times = np.linspace(-2.0, 13.0, 301)
    harmonics = [hc.Harmonic(0.3, 0.2, 0.5), hc.Harmonic(1.0, 3.0, 0.0, True)]
    for signal in (hc.Signal(), hc.Signal(0.25), hc.Signal(0.1, harmonics),
                   hc.Signal.table([-2.0, 0.0, 5.5, 13.0], [1.0, -1.0, 2.5, 0.0])):
        copy = round_trip(signal)
        assert repr(copy) == repr(signal)
        np.testing.assert_array_equal(copy(times), signal(times))
    vector = hc.VectorSignal([1.0, hc.Signal(0.0, [hc.Harmonic(0.3, 0.2)])])
    np.testing.assert_array_equal(round_trip(vector)(times), vector(times))
    assert round_trip(hc.VectorSignal.zeros(3)).dim() == 3
    with pytest.raises(TypeError, match="cannot pickle a VectorSignal that is a function of t"):
        pickle.dumps(hc.VectorSignal(2, lambda t: np.zeros(2)))


def test_models_pickle_by_value():
    rng = np.random.default_rng(8)
    ship = hc.ShipModel(hc.ShipParameters(0.7, -1.5, 0.4, 1.1, 2.2, 0.9))
    A, B, D, C = rng.standard_normal((3, 3)), rng.standard_normal((3, 1)), rng.standard_normal((3, 2)), \
        rng.standard_normal((2, 3))
    for model in (ship, hc.ShipModel(), hc.LinearModel(A, B, D, C), hc.LinearModel(A, B, D)):
        copy = round_trip(model)
        assert type(copy) is type(model) and copy is not model
        assert (copy.name(), copy.n(), copy.m(), copy.nw(), copy.noise_channels(), copy.state_names()) == \
               (model.name(), model.n(), model.m(), model.nw(), model.noise_channels(), model.state_names())
        for _ in range(5):
            t, q = float(rng.uniform(0.0, 10.0)), rng.standard_normal(model.n())
            np.testing.assert_array_equal(copy.f(t, q), model.f(t, q))
            np.testing.assert_array_equal(copy.dfdq(t, q), model.dfdq(t, q))
            np.testing.assert_array_equal(copy.D(t, np.zeros(copy.n())), model.D(t, np.zeros(model.n())))
            np.testing.assert_array_equal(copy.G(t, np.zeros(copy.n())), model.G(t, np.zeros(model.n())))
    assert round_trip(ship).parameters() == ship.parameters()
    linear = hc.LinearModel(A, B, D, C)
    np.testing.assert_array_equal(round_trip(linear).measurement_C(), C)
    np.testing.assert_array_equal(round_trip(linear).process_D(), D)


class PythonScalar(hc.Model):
    def __init__(self):
        hc.Model.__init__(self)

    def name(self):
        return "python-scalar"

    def n(self):
        return 1

    def m(self):
        return 1

    def nw(self):
        return 1

    def f(self, t, q):
        return -q

    def dfdq(self, t, q):
        return -np.eye(1)

    def G(self, t, q):
        return np.eye(1)

    def D(self, t, q):
        return np.eye(1)


def test_a_model_implemented_in_python_does_not_pickle():
    with pytest.raises(TypeError, match="cannot pickle the model 'python-scalar': a model implemented in Python"):
        pickle.dumps(PythonScalar())
    trajectory = hc.Trajectory(PythonScalar(), [1.0], [0.0], 0.0, 1.0)
    with pytest.raises(TypeError, match="cannot pickle the model 'python-scalar'"):
        pickle.dumps(trajectory)


# ---- scenarios ----

@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_scenarios_pickle_as_their_file(name):
    scenario = hc.load_scenario(hc.scenario_path(name))
    scenario.solver.escape_norm = 1e8  # not in the file form: carried beside it
    copy = round_trip(scenario)
    assert hc._core.scenario_toml(copy) == hc._core.scenario_toml(scenario)
    assert copy.solver == scenario.solver and copy.name == scenario.name and copy.law == scenario.law
    assert (copy.measurement is None) == (scenario.measurement is None)
    if copy.measurement is not None:
        assert copy.measurement == scenario.measurement


def test_a_scenario_changed_in_python_pickles_with_its_changes():
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    scenario.law = "cascade"
    scenario.gamma = 4.25
    scenario.kappa = hc.Signal(1.0, [hc.Harmonic(0.25, 0.5)])
    scenario.divergence_factor = 50.0
    scenario.cascade = hc.CascadeGains(0.3, 2.5, 3.5)
    measurement = scenario.measurement
    measurement.filter_A = "desired"
    scenario.measurement = measurement
    copy = round_trip(scenario)
    assert (copy.law, copy.gamma, copy.divergence_factor, copy.cascade) == \
           (hc.Law.cascade, 4.25, 50.0, hc.CascadeGains(0.3, 2.5, 3.5))
    assert copy.measurement.filter_A == hc.FilterLinearization.desired
    times = np.linspace(0.0, 40.0, 101)
    np.testing.assert_array_equal(copy.kappa(times), scenario.kappa(times))


def test_a_scenario_with_python_parts_does_not_pickle():
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.disturbance = lambda t: np.zeros(6)
    with pytest.raises(TypeError, match="cannot pickle the scenario 'paper-fig1': .*function of t"):
        pickle.dumps(scenario)
    scenario = hc.Scenario()
    scenario.name = "mine"
    scenario.model = PythonScalar()
    with pytest.raises(TypeError, match="cannot pickle the scenario 'mine': the model 'python-scalar' has no "
                                        "scenario-file form"):
        pickle.dumps(scenario)
    with pytest.raises(TypeError, match="cannot pickle the scenario '': the scenario has no model"):
        pickle.dumps(hc.Scenario())


@pytest.mark.parametrize("name", ["paper_fig1", "paper_fig2"])
def test_a_pickled_scenario_runs_bit_for_bit_the_same(name):
    scenario = hc.load_scenario(hc.scenario_path(name))
    direct, pickled = hc.run_scenario(scenario), hc.run_scenario(round_trip(scenario))
    assert pickled.simulation == direct.simulation  # every series and field, exactly
    assert pickled.metrics == direct.metrics
    np.testing.assert_array_equal(pickled.Z0, direct.Z0)
    assert (pickled.Z_min_eig, pickled.Z_max_eig) == (direct.Z_min_eig, direct.Z_max_eig)


# ---- results ----

def assert_same_result(copy: hc.RunResult, result: hc.RunResult):
    """Everything a RunResult holds, compared exactly."""
    assert (copy.scenario_name, copy.law, copy.output_feedback, copy.gamma, copy.gamma_star) == \
           (result.scenario_name, result.law, result.output_feedback, result.gamma, result.gamma_star)
    assert copy.simulation == result.simulation and copy.metrics == result.metrics and copy.timing == result.timing
    assert (copy.simulation.estimator is None) == (result.simulation.estimator is None)
    np.testing.assert_array_equal(copy.Z0, result.Z0)
    np.testing.assert_array_equal([copy.Z_min_eig, copy.Z_max_eig], [result.Z_min_eig, result.Z_max_eig])
    assert hc._core.results_json(copy) == hc._core.results_json(result)
    assert hc._core.results_csv(copy) == hc._core.results_csv(result)
    # The dense outputs: the same pieces, so the same values at any t (steps' ends, midpoints,
    # arbitrary times), derivatives included.
    tr, tr0 = copy.trajectory, result.trajectory
    assert (tr.t0(), tr.tf(), tr.stats()) == (tr0.t0(), tr0.tf(), tr0.stats())
    np.testing.assert_array_equal(tr.dense().breakpoints(), tr0.dense().breakpoints())
    steps = np.asarray(tr0.dense().breakpoints())
    times = np.concatenate([steps, 0.5 * (steps[1:] + steps[:-1]),
                            np.random.default_rng(1).uniform(tr0.t0(), tr0.tf(), 200)])
    np.testing.assert_array_equal(tr.q_d(times), tr0.q_d(times))
    np.testing.assert_array_equal(tr.u_d(times), tr0.u_d(times))
    np.testing.assert_array_equal(tr.A_e(times[:50]), tr0.A_e(times[:50]))
    assert type(tr.model()) is type(tr0.model())
    if result.solution is None:
        assert copy.solution is None
        return
    Z, Z0 = copy.solution, result.solution
    assert Z.trajectory() is tr  # one shared trajectory, as before pickling
    assert (Z.gamma(), Z.n(), Z.m(), Z.stats()) == (Z0.gamma(), Z0.n(), Z0.m(), Z0.stats())
    steps = np.asarray(Z0.dense().breakpoints())
    np.testing.assert_array_equal(Z.dense().breakpoints(), steps)
    times = np.concatenate([steps, 0.5 * (steps[1:] + steps[:-1])])
    np.testing.assert_array_equal(Z.Z(times), Z0.Z(times))
    np.testing.assert_array_equal(Z.dZdt(times), Z0.dZdt(times))
    np.testing.assert_array_equal(Z.gain(times), Z0.gain(times))
    assert Z.eigenvalue_bounds() == Z0.eigenvalue_bounds()


@pytest.mark.parametrize("name", ["paper_fig1", "paper_fig2"])
def test_run_results_pickle(name):
    result = hc.run_scenario(hc.load_scenario(hc.scenario_path(name)))
    result.gamma_star = 1.33502
    assert_same_result(round_trip(result), result)
    # The parts on their own, too.
    assert round_trip(result.simulation) == result.simulation
    assert round_trip(result.metrics) == result.metrics


def test_a_run_without_design_pickles():
    """The cascade law with state feedback below gamma*: no design (solution None)."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.law = hc.Law.cascade
    scenario.gamma = 1.0
    result = hc.run_scenario(scenario)
    assert result.solution is None
    assert_same_result(round_trip(result), result)


def test_filter_riccati_solution_pickles(paper_trajectory):
    Sigma = hc.solve_filter_riccati(paper_trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
    copy = round_trip(Sigma)
    times = np.linspace(0.0, 40.0, 777)
    np.testing.assert_array_equal(copy.Sigma(times), Sigma.Sigma(times))
    assert copy.stats() == Sigma.stats() and copy.gamma() == Sigma.gamma()


def test_tampered_dense_output_is_a_value_error(paper_solutions):
    state = list(paper_solutions["erk"].dense().__getstate__())
    state[4] = state[4][:-1]  # one coefficient short
    broken = hc.PiecewisePolynomial.__new__(hc.PiecewisePolynomial)
    with pytest.raises(ValueError, match="too few coefficients"):
        broken.__setstate__(tuple(state))
    state = list(paper_solutions["erk"].__getstate__())
    state[2] = hc.PiecewisePolynomial.__new__(hc.PiecewisePolynomial)
    state[2].__setstate__((2, np.zeros(0), np.zeros(0), np.zeros(0, dtype=np.int32), np.zeros(0)))
    solution = hc.RiccatiSolution.__new__(hc.RiccatiSolution)
    with pytest.raises(ValueError, match="needs 21 components, got 2"):
        solution.__setstate__(tuple(state))


def run_in_another_process(scenario: hc.Scenario) -> hc.RunResult:
    return hc.run_scenario(scenario)


def test_a_scenario_runs_in_another_process_as_here():
    """What a study does: the scenario goes to a fresh interpreter (spawn: nothing inherited),
    the result comes back; the same code on the same numbers gives the same run."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    with ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
        remote = pool.submit(run_in_another_process, scenario).result(timeout=300)
    local = hc.run_scenario(scenario)
    assert remote.simulation == local.simulation and remote.metrics == local.metrics
    np.testing.assert_array_equal(remote.solution.Z(np.linspace(0.0, 40.0, 41)),
                                  local.solution.Z(np.linspace(0.0, 40.0, 41)))
    assert not math.isnan(remote.metrics.max_rho_sigma_z)
