"""Shared fixtures of the Python test suite.

The paper's run (docs/scenarios.md): the ship of docs/mathematics.md with the paper's parameters,
q_d0 = [1, 0, 0, 0, 0, 0], u_d(t) = [1, 0.3 sin(0.2 t)], t in [0, 40], gamma = 5,
Q = Qf = I. Everything a test compares against is computed independently in the test
(closed forms, SciPy, finite differences), never copied from the library's output.
"""

from __future__ import annotations

import numpy as np
import pytest

import hinf_cpp as hc
from _support import METHODS, PAPER_GAMMA, PAPER_Q_D0, PAPER_T0, PAPER_TF


@pytest.fixture(params=METHODS)
def method(request) -> str:
    """Each integrator of SolverOptions in turn."""
    return request.param


@pytest.fixture(scope="session")
def ship() -> hc.ShipModel:
    return hc.ShipModel(hc.ShipParameters())


@pytest.fixture(scope="session")
def paper_u_d() -> list:
    """u_d = [1, 0.3 sin(0.2 t)] as library Signals."""
    return [hc.Signal(1.0), hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]


@pytest.fixture(scope="session")
def paper_trajectory(ship, paper_u_d) -> hc.Trajectory:
    return hc.Trajectory(ship, PAPER_Q_D0, paper_u_d, PAPER_T0, PAPER_TF)


@pytest.fixture(scope="session")
def paper_solutions(paper_trajectory) -> dict:
    """GRDE solutions on the paper trajectory (gamma = 5, Q = Qf = I), one per method,
    at the default tolerances."""
    eye = np.eye(6)
    return {m: hc.solve_grde(paper_trajectory, eye, eye, PAPER_GAMMA, hc.SolverOptions(method=m))
            for m in METHODS}


@pytest.fixture(scope="session")
def paper_scenario_path():
    return hc.scenario_path("paper_fig1")


@pytest.fixture(scope="session")
def paper_run(paper_scenario_path) -> hc.RunResult:
    """run_scenario on the shipped paper_fig1.toml (read by the Python reader)."""
    return hc.run_scenario(hc.load_scenario(paper_scenario_path))


@pytest.fixture(scope="session")
def lti_trajectory():
    """Factory: an LTI trajectory (LinearModel, q_d0 = 0, u_d = 0, so q_d(t) = 0 and A_e = A)."""

    def make(A, B, D, t0: float = 0.0, tf: float = 1.0) -> hc.Trajectory:
        A = np.atleast_2d(np.asarray(A, dtype=float))
        B = np.atleast_2d(np.asarray(B, dtype=float))
        D = np.atleast_2d(np.asarray(D, dtype=float))
        model = hc.LinearModel(A, B, D)
        return hc.Trajectory(model, np.zeros(A.shape[0]), [0.0] * B.shape[1], t0, tf)

    return make
