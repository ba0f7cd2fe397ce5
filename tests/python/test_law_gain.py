"""A law's own attenuation (hinf_cpp.law_gain, law_escape_time, solve_law_riccati) through the
binding, and the comparison's ``induced_l2_gain``. The numerics (closed forms, the closed loop's
H-infinity norm over long horizons) are checked in C++ (tests/cpp/test_gamma_star.cpp, LawGain)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import hinf_cpp as hc
from hinf_cpp.analysis import compare

I6 = np.eye(6)


@pytest.fixture(scope="module")
def trajectory():
    u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]  # paper Fig. 1, 10 s
    return hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)


def test_kappa_is_the_laws_gain_scaling(trajectory):
    """kappa as a number or a Signal is the same law; kappa = 2 (K = 2 B'Z) is another law, with
    another gain."""
    law = hc.solve_grde(trajectory, I6, I6, 5.0)
    number = hc.law_gain(law, I6, I6, 2.0)
    signal = hc.law_gain(law, I6, I6, hc.Signal(2.0))
    assert number.gamma_star == signal.gamma_star  # the same computation
    assert abs(number.gamma_star - hc.law_gain(law, I6, I6).gamma_star) > 1e-3


def test_the_worst_case_riccati_solution_is_stored_above_the_gain(trajectory):
    lqr = hc.solve_grde(trajectory, I6, I6, math.inf)
    gain = hc.law_gain(lqr, I6, I6).gamma_star
    P = hc.solve_law_riccati(lqr, I6, I6, 1.05 * gain)
    assert np.allclose(P.value(10.0), I6, atol=1e-9)  # P(tf) = Qf
    # Above the gain P is larger than the Lyapunov solution at gamma = inf (the disturbance term
    # gamma^-2 P D D' P only adds), and the escape test agrees with the search.
    lyapunov = hc.solve_law_riccati(lqr, I6, I6, math.inf)
    assert np.linalg.eigvalsh(P.value(0.0) - lyapunov.value(0.0)).min() > 0.0
    assert math.isnan(hc.law_escape_time(lqr, I6, I6, 1.05 * gain))
    assert 0.0 <= hc.law_escape_time(lqr, I6, I6, 0.95 * gain) < 10.0
    with pytest.raises(hc.ConjugatePointError):
        hc.solve_law_riccati(lqr, I6, I6, 0.95 * gain)


@pytest.mark.parametrize("call, match", [
    (lambda law: hc.law_gain(law, I6, I6, -1.0), "kappa must be > 0"),
    (lambda law: hc.law_gain(law, np.eye(3), I6), "Q"),
    (lambda law: hc.law_escape_time(law, I6, I6, 0.0), "gamma must be > 0"),
])
def test_bad_input_is_a_value_error(trajectory, call, match):
    with pytest.raises(ValueError, match=match):
        call(hc.solve_grde(trajectory, I6, I6, 5.0))


def test_compare_reports_each_laws_own_attenuation():
    """hinf's gain lies between gamma* and its gamma (the game's value bounds every law from
    below; the law guarantees its gamma); lqr and the baselines (their controllers linearized)
    have one above gamma* too; output feedback has none."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    comparison = compare(scenario)
    gains = {run.key: run.metrics["induced_l2_gain"] for run in comparison.runs}
    star = hc.scenario_gamma_star(scenario).gamma_star
    assert star * (1 - 1e-6) <= gains["hinf"] < scenario.gamma
    for key in ("lqr", "cascade", "backstepping"):
        assert gains[key] >= star * (1 - 1e-6), key
    assert all(math.isnan(gains[key]) for key in gains if key.endswith("output-feedback"))


def test_the_lqr_run_meets_its_own_worst_case():
    """[disturbance] worst_case with lqr adds gamma^-2 D' P q_e, P of the LQR law's closed loop
    at gamma (not the H-infinity design's Z): the recorded w at t0 against both."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.worst_case = True
    scenario.law = hc.Law.lqr
    scenario.gamma = 2.5  # above the LQR law's gain (2.2), where its worst case and hinf's differ
    result = hc.run_scenario(scenario)
    resolved = scenario.resolved()
    lqr = hc.solve_grde(result.trajectory, resolved.Q, resolved.Qf, math.inf, resolved.solver)
    t0, gamma = result.simulation.t[0], scenario.gamma
    q_e = result.simulation.q[0] - result.trajectory.q_d(t0)
    D = result.trajectory.D_e(t0)
    signals = hc.Disturbance(scenario.disturbance).eval(t0, result.simulation.q[0])
    P = hc.solve_law_riccati(lqr, resolved.Q, resolved.Qf, gamma, resolved.kappa, resolved.solver)
    Z = hc.solve_grde(result.trajectory, resolved.Q, resolved.Qf, gamma, resolved.solver)
    own = signals + D.T @ P.value(t0) @ q_e / gamma**2
    hinf = signals + D.T @ Z.Z(t0) @ q_e / gamma**2
    w0 = result.simulation.w[0]
    # The same P integrated twice by the same code with the scenario's solver: equal to round-off
    # (the sum in another order); the two worst cases differ by far more.
    assert np.allclose(w0, own, rtol=1e-9, atol=1e-12)
    assert np.abs(own - hinf).max() > 1e-3
    comparison = compare(scenario, "hinf,lqr", worst_case=True)
    assert "lqr law's own worst case" in comparison["lqr"].disturbance["description"]
    assert "eq. 16" in comparison["hinf"].disturbance["description"]


def test_lqr_below_its_gain_has_no_worst_case():
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.worst_case, scenario.law, scenario.gamma = True, hc.Law.lqr, 1.5  # the LQR law's gain is 2.2
    with pytest.raises(hc.ConjugatePointError, match="closed-loop Riccati equation of the law"):
        hc.run_scenario(scenario)


class PythonBackstepping(hc.Controller):
    """The backstepping law seen through a controller written in Python: the binding's
    controller_gain takes any hc.Controller (its Jacobian by central differences)."""

    def __init__(self, trajectory):
        hc.Controller.__init__(self)
        self.law = hc.BacksteppingController(trajectory)

    def name(self):
        return "python-backstepping"

    def n(self):
        return 6

    def m(self):
        return 2

    def control(self, t, q):
        return self.law.control(t, q)


class OneInput(PythonBackstepping):
    def m(self):
        return 1


def test_a_baseline_run_meets_its_own_worst_case():
    """[disturbance] worst_case with backstepping adds gamma^-2 D' P q_e, P of its own closed
    loop linearized along the trajectory (solve_controller_riccati), not the design's Z; and the
    gain of the same law written in Python is the C++ controller's."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.tf, scenario.worst_case, scenario.law, scenario.gamma = 10.0, True, hc.Law.backstepping, 5.0
    result = hc.run_scenario(scenario)
    resolved = scenario.resolved()
    t0, gamma = result.simulation.t[0], scenario.gamma
    law = hc.BacksteppingController(result.trajectory, resolved.backstepping)
    P = hc.solve_controller_riccati(result.trajectory, law, resolved.Q, resolved.Qf, gamma, resolved.solver)
    q_e = result.simulation.q[0] - result.trajectory.q_d(t0)
    signals = hc.Disturbance(scenario.disturbance).eval(t0, result.simulation.q[0])
    own = signals + result.trajectory.D_e(t0).T @ P.value(t0) @ q_e / gamma**2
    # The same P by the same code with the scenario's solver: round-off.
    assert np.allclose(result.simulation.w[0], own, rtol=1e-9, atol=1e-12)
    gain = hc.controller_gain(result.trajectory, law, resolved.Q, resolved.Qf).gamma_star
    in_python = hc.controller_gain(result.trajectory, PythonBackstepping(result.trajectory), resolved.Q,
                                   resolved.Qf).gamma_star
    assert in_python == pytest.approx(gain, rel=1e-9)  # the same Jacobians, through Python
    assert gain < gamma
    with pytest.raises(ValueError, match="controller takes q of 6 numbers and gives u of 1; the model 'ship'"):
        hc.controller_gain(result.trajectory, OneInput(result.trajectory), resolved.Q, resolved.Qf)
