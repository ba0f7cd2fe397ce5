"""The default method ("auto"): Dormand-Prince while the problem is not stiff, BDF once the
stiffness test fires, with the choice in the solve statistics. On the paper's run it stays
explicit; on a system with a mode 1e4 times faster than the horizon it switches to BDF; both
give Z of a tight reference to integration accuracy."""
import math

import numpy as np

import hinf_cpp as hc

EYE6 = np.eye(6)


def max_relative_difference(a, b, times):
    return max(np.max(np.abs(a.Z(t) - b.Z(t))) / max(1.0, np.max(np.abs(b.Z(t)))) for t in times)


def test_auto_stays_explicit_on_the_paper_run(paper_trajectory):
    automatic = hc.solve_grde(paper_trajectory, EYE6, EYE6, 5.0)
    assert hc.SolverOptions().method == hc.Method.auto
    assert automatic.stats().method == "erk"
    reference = hc.solve_grde(paper_trajectory, EYE6, EYE6, 5.0, hc.SolverOptions("bdf", 1e-12, 1e-14))
    # rtol 1e-8 on a solution of size ~5 integrated over 40 s: global errors ~1e-7 relative at
    # most; the reference's are 1e-4 of that.
    assert max_relative_difference(automatic, reference, np.linspace(0.0, 40.0, 161)) < 1e-6


def stiff_lti(n=12, horizon=5.0, factor=1e4, seed=3):
    rng = np.random.default_rng(seed)
    M = rng.standard_normal((n, n)) / math.sqrt(n)
    A = M - (np.max(np.linalg.eigvals(M).real) + 0.5) * np.eye(n)
    v = rng.standard_normal(n)
    v /= np.linalg.norm(v)
    A = A - (factor / horizon) * np.outer(v, v)  # one mode near -factor / horizon
    B = rng.standard_normal((n, 3))
    model = hc.LinearModel(A, B, rng.standard_normal((n, 1)))
    return hc.Trajectory(model, np.zeros(n), [0.0] * 3, 0.0, horizon)


def test_auto_switches_to_bdf_on_a_stiff_system():
    trajectory = stiff_lti()
    n = trajectory.n()
    automatic = hc.solve_grde(trajectory, np.eye(n), np.eye(n), math.inf)
    assert automatic.stats().method.startswith("erk, then bdf (Lyapunov Newton) from t = ")
    explicit = hc.solve_grde(trajectory, np.eye(n), np.eye(n), math.inf, hc.SolverOptions("erk"))
    # The explicit method is held to its stability limit by the fast mode: several times the
    # right-hand sides of the switched solve.
    assert explicit.stats().rhs_evals > 4 * automatic.stats().rhs_evals
    reference = hc.solve_grde(trajectory, np.eye(n), np.eye(n), math.inf, hc.SolverOptions("bdf", 1e-12, 1e-14))
    times = np.linspace(0.0, 5.0, 101)
    # Both at rtol 1e-8 on |Z| = O(1) over a stable backward solve: 1e-6 leaves a factor 10-100.
    assert max_relative_difference(automatic, reference, times) < 1e-6
    assert max_relative_difference(explicit, reference, times) < 1e-6
