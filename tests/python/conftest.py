"""Shared fixtures of the Python test suite.

The paper's run (docs/scenarios.md): the ship of docs/mathematics.md with the paper's parameters,
q_d0 = [1, 0, 0, 0, 0, 0], u_d(t) = [1, 0.3 sin(0.2 t)], t in [0, 40], gamma = 5,
Q = Qf = I. Everything a test compares against is computed independently in the test
(closed forms, SciPy, finite differences), never copied from the library's output.
"""

from __future__ import annotations

import os
import pathlib
import sys

import numpy as np
import pytest

import hinf_cpp as hc
from _support import METHODS, PAPER_GAMMA, PAPER_Q_D0, PAPER_T0, PAPER_TF

# scripts/run_sanitized_tests.sh runs the suite with the sanitized build staged in a virtual
# environment (this variable names it) and the ASan runtime preloaded.
SANITIZER_STAGE = os.environ.get("HINF_SANITIZER_STAGE")


def pytest_sessionstart(session):
    """Under the sanitizer step, stops the run unless this process and the programs the tests
    start (next to sys.executable) are the sanitized build: a run of the plain build would pass
    and prove nothing."""
    if not SANITIZER_STAGE:
        return
    stage = pathlib.Path(SANITIZER_STAGE).resolve()
    bin_dir = pathlib.Path(sys.executable).parent
    maps = pathlib.Path("/proc/self/maps").read_text()
    checks = {
        "hinf_cpp": pathlib.Path(hc.__file__),
        "hinf_cpp._core": pathlib.Path(hc._core.__file__),
        "hinf-sim": bin_dir / "hinf-sim",
        "hinf-cpp": bin_dir / "hinf-cpp",
    }
    wrong = [f"{name} is {path}" for name, path in checks.items()
             if not (path.exists() and path.resolve().is_relative_to(stage))]
    if "/libasan.so" not in maps:
        wrong.append("the ASan runtime is not loaded")
    if wrong:
        pytest.exit(f"not the sanitized build in {stage}: {'; '.join(wrong)}", returncode=1)


# Tests that cannot run under AddressSanitizer. ASan reserves about 20 TB of address space for
# its shadow memory when a process starts, so a process started under an address-space limit
# (RLIMIT_AS) dies before main ("ReserveShadowMemoryRange failed"). ASan also handles SIGSEGV
# itself: a process that gets one writes a report and aborts (SIGABRT), so a test that crashes
# a child on purpose sees another signal and leaves a report that fails the step.
SANITIZER_SKIPS = {
    "tests/python/test_cli_errors.py::test_out_of_memory_is_exit_status_2":
        "runs hinf-sim and hinf-cpp under RLIMIT_AS, which ASan cannot start under",
    "tests/python/test_run_limits.py::test_gamma_star_with_more_threads_than_the_machine_or_the_system_allows":
        "runs a Python child under RLIMIT_AS, which ASan cannot start under",
    "tests/python/test_properties.py::test_run_property_reports_a_crash_with_its_input":
        "sends SIGSEGV to a Python child on purpose, which ASan turns into a report and SIGABRT",
}


# Tests marked "ipopt" run the trajectory planner's optimizer: CasADi loads its IPOPT plugin with
# dlopen(RTLD_DEEPBIND), which the ASan runtime refuses (it aborts the process with a report;
# google/sanitizers issue 611). The planner's own code is Python; what it calls in the library
# (Trajectory, run_scenario) is exercised under the sanitizers by the other tests.
IPOPT_SKIP = "CasADi loads IPOPT with dlopen(RTLD_DEEPBIND), which the ASan runtime refuses"


# Tests that run once per CI, in the plain stage (scripts/run_tests.sh runs both stages): those
# marked "slow" (long runs of code the other tests also cover) and "text" (they check documents,
# stubs, generated sources and include lines, not what the library computes).
ONCE_SKIPS = {
    "slow": "a slow test, run once, in the plain stage",
    "text": "checks text, not the library; run once, in the plain stage",
}


def pytest_collection_modifyitems(config, items):
    if not SANITIZER_STAGE:
        return
    for item in items:
        reason = SANITIZER_SKIPS.get(item.nodeid) or (IPOPT_SKIP if item.get_closest_marker("ipopt") else None)
        reason = reason or next((why for marker, why in ONCE_SKIPS.items() if item.get_closest_marker(marker)), None)
        if reason:
            item.add_marker(pytest.mark.skip(reason=f"under the sanitizers: {reason}"))


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
