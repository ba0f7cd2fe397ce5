"""The closed loop (paper eqs. 17/18): u = u_d - kappa B' Z (q - q_d), simulated on the ship.

tests/cpp/test_simulation.cpp checks the numerics: the zero-error run and the decay from the
paper's start for every method, the law with a time-varying kappa, a closed form of the closed
loop, the metrics against hand computations. Here: what simulate_state_feedback takes and
returns, the ship's closed loop with the paper's disturbance against SciPy (the C++ tests have
no such check), the Figure 1 run (its methods at the default tolerances, every metric, the
heading metrics too, from the series), controllers and disturbances written in Python."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import hinf_cpp as hc
from _support import (
    PAPER_Q0,
    PAPER_Q_D0,
    ROUNDOFF,
    SHIP_B,
    SHIP_D,
    max_rel,
    paper_disturbance,
    ship_drift,
    summation_rtol,
)

INITIAL_POSITION_ERROR = math.sqrt(2.0)  # 1 m behind and 1 m aside


def paper_disturbance_signals():
    """0.1 cos(2 pi 0.2 t) on w1..w3 (paper §5), as library Signals."""
    w = hc.Signal(0.0, [hc.Harmonic(0.1, 2.0 * math.pi * 0.2, 0.0, True)])
    return [w, w, w, 0.0, 0.0, 0.0]


def test_zero_error_stays_on_the_desired_trajectory(paper_trajectory, paper_solutions):
    """q0 = q_d0 and w = 0: u = u_d and q(t) = q_d(t) up to the integrator's accuracy, at the
    default options (every method: tests/cpp/test_simulation.cpp); the series' shapes and grid.
    Measured max |q - q_d|: bdf 3.9e-7, adams 2.3e-7, erk 1.9e-9."""
    controller = hc.HinfStateFeedback(paper_solutions["auto"])
    run = hc.simulate_state_feedback(paper_trajectory, controller, None, PAPER_Q_D0,
                                     hc.SimulationOptions(output_dt=0.01))
    assert run.t.shape == (4001,) and run.q.shape == (4001, 6) and run.u.shape == (4001, 2)
    # t0 + k dt (library) against NumPy's linspace: round-off of times up to 40.
    np.testing.assert_allclose(run.t, np.linspace(0.0, 40.0, 4001), rtol=0, atol=ROUNDOFF * 40.0)
    # The same interpolant at the same times: exactly equal.
    np.testing.assert_allclose(run.q_d, paper_trajectory.q_d(run.t), rtol=0, atol=0)
    assert np.max(np.abs(run.q - run.q_d)) < 1e-6
    assert np.max(np.abs(run.u - run.u_d)) < 1e-5
    np.testing.assert_array_equal(run.w, 0.0)
    np.testing.assert_array_equal(run.q_e(), run.q - run.q_d)  # the same subtraction


def test_closed_loop_matches_an_independent_integration(paper_trajectory, paper_solutions):
    """The simulator integrates f + B u + D w with the law (17): compare with SciPy on the
    docs/mathematics.md equations, the law written in NumPy from the solution's gain and the
    trajectory, and the paper's disturbance written in NumPy."""
    sol = paper_solutions["erk"]
    kappa = 0.75

    def law(t, q):
        return paper_trajectory.u_d(t) - kappa * sol.gain(t) @ (q - paper_trajectory.q_d(t))

    def rhs(t, q):
        return ship_drift(q) + SHIP_B @ law(t, q) + SHIP_D @ paper_disturbance(t)

    t_end = 20.0  # enough to cover the transient, keeps the Python integration short
    ref = solve_ivp(rhs, (0.0, t_end), PAPER_Q0, method="DOP853", rtol=1e-11, atol=1e-12,
                    dense_output=True)
    assert ref.success
    controller = hc.HinfStateFeedback(sol, kappa=hc.Signal(kappa))
    solver = hc.SolverOptions(method="erk", rtol=1e-10, atol=1e-12)
    run = hc.simulate_state_feedback(paper_trajectory, controller, paper_disturbance_signals(), PAPER_Q0,
                                     hc.SimulationOptions(output_dt=0.05, solver=solver))
    keep = run.t <= t_end
    np.testing.assert_allclose(run.q[keep], ref.sol(run.t[keep]).T, rtol=0, atol=1e-7)
    # The recorded u and w are the law and the disturbance at the recorded states (the law in
    # C++ and in NumPy: round-off of the size of its terms; w = 0.1 cos(.): round-off of 0.1).
    for k in np.flatnonzero(keep)[::20]:
        q_e = run.q[k] - paper_trajectory.q_d(run.t[k])
        terms = np.max(np.abs(paper_trajectory.u_d(run.t[k]))) + kappa * np.max(np.abs(sol.gain(run.t[k])) @ np.abs(q_e))
        np.testing.assert_allclose(run.u[k], law(run.t[k], run.q[k]), rtol=0, atol=ROUNDOFF * terms)
        np.testing.assert_allclose(run.w[k], paper_disturbance(run.t[k]), rtol=0, atol=ROUNDOFF * 0.1)


def test_kappa_scales_the_feedback(paper_trajectory, paper_solutions):
    """kappa given as a number reaches the law (a time-varying kappa and the law's Jacobian:
    tests/cpp/test_simulation.cpp)."""
    sol = paper_solutions["bdf"]
    kappa = 2.0
    run = hc.simulate_state_feedback(paper_trajectory, hc.HinfStateFeedback(sol, kappa), None, PAPER_Q0,
                                     hc.SimulationOptions(output_dt=0.5))
    K = sol.gain(run.t)
    expected = run.u_d - kappa * np.einsum("kij,kj->ki", K, run.q - run.q_d)
    # The law in C++ and in NumPy: round-off of the size of its terms.
    terms = np.max(np.abs(run.u_d)) + kappa * np.max(np.einsum("kij,kj->ki", np.abs(K), np.abs(run.q - run.q_d)))
    np.testing.assert_allclose(run.u, expected, rtol=0, atol=ROUNDOFF * terms)


# ---- the paper's Figure 1 ----

def position_error(run) -> np.ndarray:
    return np.hypot(run.q_e()[:, 3], run.q_e()[:, 4])


def test_paper_figure1_position_error_decays(paper_run):
    run = paper_run.simulation
    error = position_error(run)
    # hypot(-1, -1) against sqrt(2): both within an ulp.
    assert error[0] == pytest.approx(INITIAL_POSITION_ERROR, rel=ROUNDOFF)
    assert error[-1] < 0.1 * INITIAL_POSITION_ERROR
    # scenarios.md: a few centimetres after about 10 s; stays small over the last half.
    assert np.max(error[run.t >= 20.0]) < 0.2 * INITIAL_POSITION_ERROR
    assert np.max(error) == pytest.approx(INITIAL_POSITION_ERROR, rel=1e-12)
    assert paper_run.law == hc.Law.hinf and not paper_run.output_feedback and paper_run.gamma == 5.0
    assert paper_run.scenario_name == "paper-fig1"


def test_paper_figure1_methods_agree(paper_scenario_path, paper_run):
    """To 1e-6 at the default tolerances (tests/cpp/test_simulation.cpp allows 1e-5). Measured
    max |q_bdf - q_erk| 8.8e-8, |q_adams - q_erk| 2.8e-8."""
    runs = {"bdf": paper_run}
    for method in ("adams", "erk"):
        scenario = hc.load_scenario(paper_scenario_path)
        scenario.solver = hc.SolverOptions(method=method)
        runs[method] = hc.run_scenario(scenario)
    for method in ("bdf", "adams"):
        np.testing.assert_allclose(runs[method].simulation.q, runs["erk"].simulation.q, rtol=0, atol=1e-6)
        np.testing.assert_allclose(runs[method].simulation.u, runs["erk"].simulation.u, rtol=0, atol=1e-5)
        assert max_rel(runs[method].Z0, runs["erk"].Z0) < 1e-6


def test_paper_figure1_metrics_recomputed(paper_run):
    """Every metric of scenarios.md recomputed in NumPy from the returned time series."""
    run = paper_run.simulation
    t = run.t
    q_e, u_e = run.q - run.q_d, run.u - run.u_d
    Q = np.eye(6)
    pos2 = q_e[:, 3] ** 2 + q_e[:, 4] ** 2
    half = t >= 0.5 * (t[0] + t[-1])

    def l2(values):
        return math.sqrt(np.trapezoid(values, t))

    disturbance_l2 = l2(np.sum(run.w**2, axis=1))
    heading = np.pi - np.mod(np.pi - q_e[:, 5], 2.0 * np.pi)  # wrapped to (-pi, pi]
    expected = {
        "rms_position_error_last_half": math.sqrt(np.mean(pos2[half])),
        "max_position_error": math.sqrt(np.max(pos2)),
        "final_position_error": math.sqrt(pos2[-1]),
        "rms_heading_error_last_half": math.sqrt(np.mean(heading[half] ** 2)),
        "final_heading_error": abs(heading[-1]),
        "control_l2": l2(np.sum(run.u**2, axis=1)),
        "control_error_l2": l2(np.sum(u_e**2, axis=1)),
        "disturbance_l2": disturbance_l2,
    }
    # The cost of eq. (37) with the scenario's Qf = I, its ratio to ||w||, and the margin of the
    # bound L <= gamma^2 ||w||^2 + q_e0' Z(t0) q_e0 (gamma = 5).
    cost = np.trapezoid(np.einsum("ki,ij,kj->k", q_e, Q, q_e) + np.sum(u_e**2, axis=1), t) + q_e[-1] @ q_e[-1]
    expected["tracking_cost"] = cost
    expected["response_ratio"] = math.sqrt(cost) / disturbance_l2
    initial_term = q_e[0] @ paper_run.Z0 @ q_e[0]
    expected["attenuation_margin"] = 1.0 - cost / (25.0 * disturbance_l2**2 + initial_term)
    # The heading error followed through its wraps (it never wraps here: |e| < pi).
    expected["heading_excursion"] = np.max(np.abs(heading))
    metrics = paper_run.metrics
    # The library's C++ sums, means and maxima against NumPy's over the same 4001 samples:
    # summation round-off only.
    rtol = summation_rtol(t.size)
    for name, value in expected.items():
        assert getattr(metrics, name) == pytest.approx(value, rel=rtol), name
    # Output feedback metrics are absent (NaN) for state feedback; the start is off the path.
    assert math.isnan(metrics.max_rho_sigma_z)
    assert math.isnan(metrics.rms_estimation_error_last_half)
    assert math.isnan(metrics.disturbance_gain) and np.any(q_e[0] != 0.0)
    assert metrics.turned_around == 0.0 and metrics.attenuation_margin > 0.0
    # Every metric of the table is checked here.
    assert {d.name for d in hc.metric_table()} == set(expected) | {
        "max_rho_sigma_z", "rms_estimation_error_last_half", "disturbance_gain", "turned_around"}
    # Closed form: 3 channels of 0.1 cos(2 pi 0.2 t) over 8 whole periods: integral 3 * 0.01 * 20.
    assert metrics.disturbance_l2 == pytest.approx(math.sqrt(0.6), rel=1e-10)
    # The same numbers from compute_metrics on the same run: the same code, exactly (the margin's
    # initial term here is NumPy's product, not the library's: round-off).
    again = hc.compute_metrics(paper_run.trajectory.model(), run, Q, Qf=np.eye(6), gamma=5.0,
                               initial_term=float(initial_term))
    for d in hc.metric_table():
        if d.name == "attenuation_margin":
            assert again.attenuation_margin == pytest.approx(metrics.attenuation_margin, rel=1e-12)
        else:
            np.testing.assert_array_equal(getattr(again, d.name), getattr(metrics, d.name), err_msg=d.name)
    # Z(t) bounds over [t0, tf] (paper eq. 22): they enclose the extremes on the output grid
    # (up to the round-off of two eigenvalue algorithms, relative to |Z| ~ 21) and agree with
    # those on a ten times finer grid.
    eig = np.linalg.eigvalsh(paper_run.solution.Z(t))
    slack = ROUNDOFF * np.max(np.abs(eig))
    assert paper_run.Z_min_eig <= eig.min() + slack and paper_run.Z_max_eig >= eig.max() - slack
    fine = np.linalg.eigvalsh(paper_run.solution.Z(np.linspace(t[0], t[-1], 40001)))
    assert paper_run.Z_min_eig == pytest.approx(fine.min(), rel=1e-8)
    assert paper_run.Z_max_eig == pytest.approx(fine.max(), rel=1e-8)
    np.testing.assert_array_equal(paper_run.Z0, paper_run.solution.Z(0.0))  # the same evaluation


class PythonHinfLaw(hc.Controller):
    """u = u_d(t) - K(t) (q - q_d(t)) written in Python from the solution and the trajectory."""

    def __init__(self, solution, trajectory):
        hc.Controller.__init__(self)
        self.solution, self.trajectory = solution, trajectory

    def m(self):
        return 2

    def control(self, t, q):
        return self.trajectory.u_d(t) - self.solution.gain(t) @ (q - self.trajectory.q_d(t))


def test_python_controller_matches_hinf_state_feedback(paper_trajectory, paper_solutions, method):
    """The Python law and HinfStateFeedback are two computations of the same u (NumPy against
    Eigen, and bdf's Newton Jacobian is a finite difference for the Python controller): their
    round-off differences steer the adaptive step sizes apart, so the runs agree to the
    integrator's accuracy, not to round-off (adams at rtol 1e-8: 2.8e-9 apart with another
    CPU's BLAS kernels). Both run at rtol 1e-11 to keep that small. Measured max |q
    difference| at rtol 1e-11 over builds and BLAS kernels: bdf <= 3e-10, adams 5e-11, erk 6e-14."""
    rtol, atol = 1e-11, 1e-13
    options = hc.SolverOptions(method=method, rtol=rtol, atol=atol)
    sol = paper_solutions[method]
    w = paper_disturbance_signals()
    builtin = hc.simulate_state_feedback(paper_trajectory, hc.HinfStateFeedback(sol), w, PAPER_Q0,
                                         hc.SimulationOptions(output_dt=0.01, solver=options))
    python = hc.simulate_state_feedback(paper_trajectory, PythonHinfLaw(sol, paper_trajectory), w,
                                        PAPER_Q0, hc.SimulationOptions(output_dt=0.01, solver=options))
    # Each run is within a few (rtol |q| + atol) of the exact closed loop (a contracting one):
    # 10 x that for the difference of two runs, |q| up to 22 m. u = u_d - K q_e moves by at most
    # the row sums of |K| times the difference of q.
    tolerance_q = 10.0 * (rtol * np.max(np.abs(builtin.q)) + atol)
    tolerance_u = np.max(np.sum(np.abs(sol.gain(builtin.t)), axis=2)) * tolerance_q
    np.testing.assert_allclose(python.q, builtin.q, rtol=0, atol=tolerance_q)
    np.testing.assert_allclose(python.u, builtin.u, rtol=0, atol=tolerance_u)
    np.testing.assert_array_equal(python.w, builtin.w)  # the same Signals at the same times


def test_disturbance_as_a_callable(paper_trajectory, paper_solutions):
    """A callable disturbance w(t) gives the same run as the equivalent Signals. The callable
    (Python's math.cos) and the Signal (C++) are two computations of w: where their round-off
    differs, the step sizes differ too and the runs agree to the integrator's accuracy, so
    both run at rtol 1e-11 (measured: identical on this build, both use the C library's cos)."""
    sol = paper_solutions["erk"]
    rtol, atol = 1e-11, 1e-13
    options = hc.SolverOptions(method="erk", rtol=rtol, atol=atol)
    a = hc.simulate_state_feedback(paper_trajectory, hc.HinfStateFeedback(sol), paper_disturbance_signals(),
                                   PAPER_Q0, hc.SimulationOptions(output_dt=0.1, solver=options))
    b = hc.simulate_state_feedback(paper_trajectory, hc.HinfStateFeedback(sol), paper_disturbance,
                                   PAPER_Q0, hc.SimulationOptions(output_dt=0.1, solver=options))
    # Two runs, each within a few (rtol |q| + atol) of the exact closed loop: 10 x that.
    np.testing.assert_allclose(b.q, a.q, rtol=0, atol=10.0 * (rtol * np.max(np.abs(a.q)) + atol))


def test_python_controller_exception_propagates(paper_trajectory, method):
    class Failing(hc.Controller):
        def __init__(self):
            hc.Controller.__init__(self)

        def m(self):
            return 2

        def control(self, t, q):
            if t > 1.0:
                raise LookupError("controller failed")
            return np.array([1.0, 0.0])

    with pytest.raises(LookupError, match="controller failed"):
        hc.simulate_state_feedback(paper_trajectory, Failing(), None, PAPER_Q_D0,
                                   hc.SimulationOptions(output_dt=0.1, solver=hc.SolverOptions(method=method)))
