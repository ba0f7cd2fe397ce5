"""Conjugate points and gamma* of random LTI systems against an independent reference.

For an LTI plant the GRDE (13) and the filter Riccati equation (36) are solved exactly by the
linear flow of their Hamiltonian matrices; _support.first_conjugate_point finds the first time
at which that flow's X becomes singular (a finite escape of Z = Y X^-1), with NumPy only,
watching the smallest eigenvalue of P = X'(Y + c X) on a fine grid and refining every local
minimum, so that a conjugate point where Z blows up and comes back within a short interval
(just below a tangential conjugate point) is not missed. The reference is checked here against
the scalar closed form (_support.scalar_escape_tau), against SciPy's integration of the Riccati
equation away from gamma*, and near gamma* against SciPy's integration of W = Z^-1.

Per random system (seeded: one master seed, each system its own seed, reported on failure):
* gamma_star at the default options is within 1e-6 of the reference: the reference finds a
  conjugate point at gamma_lib (1 - 1e-6) and none at gamma_lib (1 + 1e-6) (otherwise the
  reference gamma* is bisected to report the error);
* grde_escape_time is finite just below the reference gamma* (1 - 1e-5) and NaN just above
  (1 + 1e-5);
* the same for filter_escape_time at the reference threshold of the filter (36);
* D = 0: every gamma passes, gamma* = 0.
"""

from __future__ import annotations

import math
import pathlib

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import hinf_cpp as hc
from _support import (
    bracket_threshold,
    filter_conjugate_tau,
    grde_conjugate_tau,
    inverse_grde,
    inverse_grde_conjugate_point,
    scalar_escape_tau,
    threshold_by_bisection,
)

MASTER_SEED = 20261123
GRDE_SYSTEMS, FILTER_SYSTEMS, CHUNK = 200, 50, 10
GAMMA_RTOL = 1e-6   # gamma_star against the reference gamma*
ESCAPE_OFFSET = 1e-5  # grde_escape_time / filter_escape_time just below and just above
HORIZONS = (0.5, 1.0, 5.0, 20.0)
QF_KINDS = ("1e-8 I", "I", "10 I", "random SPD")
KINDS = ("stable", "unstable", "marginal")

_master = np.random.default_rng(MASTER_SEED)
GRDE_SEEDS = [int(s) for s in _master.integers(0, 2**63, size=GRDE_SYSTEMS)]
FILTER_SEEDS = [int(s) for s in _master.integers(0, 2**63, size=FILTER_SYSTEMS)]


# ---- the random systems ----

def random_lti_system(seed: int, measured: bool = False, no_disturbance: bool = False) -> dict:
    """dq/dt = A q + B u + D w on [0, T]: n = 1..8; A stable, unstable or marginal (skew-
    symmetric, or shifted so that its rightmost eigenvalues lie on the imaginary axis); B and D
    with repeated columns (rank deficient) three times in ten; Q = I or a random positive
    semidefinite matrix of random rank; Qf from QF_KINDS; T from HORIZONS. measured: also a
    measurement C (p = 1..n rows), N > 0 and Sigma0 > 0. no_disturbance: D = 0."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 9))
    kind = KINDS[int(rng.integers(0, 3))]
    A = rng.standard_normal((n, n)) / math.sqrt(n)
    abscissa = np.max(np.linalg.eigvals(A).real)
    if kind == "stable":
        A -= (abscissa + rng.uniform(0.1, 1.0)) * np.eye(n)
    elif kind == "unstable":
        A -= (abscissa - rng.uniform(0.1, 1.0)) * np.eye(n)
    elif rng.random() < 0.5:
        A = 0.5 * (A - A.T)
    else:
        A -= abscissa * np.eye(n)
    m, nw = int(rng.integers(1, n + 1)), int(rng.integers(1, n + 1))
    B, D = rng.standard_normal((n, m)), rng.standard_normal((n, nw))
    if m > 1 and rng.random() < 0.3:
        B[:, -1] = B[:, 0]
    if nw > 1 and rng.random() < 0.3:
        D[:, -1] = D[:, 0]
    if no_disturbance:
        D = np.zeros((n, nw))
    if rng.random() < 0.5:
        Q = np.eye(n)
    else:
        L = rng.standard_normal((n, int(rng.integers(1, n + 1))))
        Q = L @ L.T / n
    qf = QF_KINDS[int(rng.integers(0, 4))]
    if qf == "random SPD":
        G = rng.standard_normal((n, n))
        Qf = G @ G.T / n + 0.1 * np.eye(n)
    else:
        Qf = {"1e-8 I": 1e-8, "I": 1.0, "10 I": 10.0}[qf] * np.eye(n)
    T = HORIZONS[int(rng.integers(0, 4))]
    system = dict(seed=seed, n=n, kind=kind, A=A, B=B, D=D, Q=Q, Qf=Qf, qf=qf, T=T,
                  rank_B=int(np.linalg.matrix_rank(B)), rank_D=int(np.linalg.matrix_rank(D)))
    if measured:
        p = int(rng.integers(1, n + 1))
        C = rng.standard_normal((p, n))
        K = rng.standard_normal((p, p))
        G = rng.standard_normal((n, n))
        system.update(C=C, N=K @ K.T / p + 0.1 * np.eye(p), Sigma0=G @ G.T / n + 0.1 * np.eye(n))
    return system


def grde_system(index: int) -> dict:
    """System `index` of the GRDE set; every 25th has D = 0."""
    return random_lti_system(GRDE_SEEDS[index], no_disturbance=index % 25 == 24)


def filter_system(index: int) -> dict:
    return random_lti_system(FILTER_SEEDS[index], measured=True)


def trajectory(system: dict) -> hc.Trajectory:
    """q_d = 0, u_d = 0 on [0, T]: A_e(t) = A."""
    C = system.get("C", np.zeros((0, 0)))  # LinearModel's default C: none
    model = hc.LinearModel(system["A"], system["B"], system["D"], C)
    return hc.Trajectory(model, np.zeros(system["n"]), [0.0] * system["B"].shape[1], 0.0, system["T"])


def describe(index: int, system: dict) -> str:
    return (f"system {index} (seed {system['seed']}): n = {system['n']}, {system['kind']} A, "
            f"rank B = {system['rank_B']}/{system['B'].shape[1]}, rank D = {system['rank_D']}/"
            f"{system['D'].shape[1]}, Qf = {system['qf']}, T = {system['T']}")


def test_the_random_systems_cover_the_cases():
    """The generated set has every size, kind of A, Qf and horizon, rank-deficient B and D, and
    systems without disturbance."""
    systems = [grde_system(i) for i in range(GRDE_SYSTEMS)]
    assert {s["n"] for s in systems} == set(range(1, 9))
    assert {s["kind"] for s in systems} == set(KINDS)
    assert {s["qf"] for s in systems} == set(QF_KINDS)
    assert {s["T"] for s in systems} == set(HORIZONS)
    assert sum(s["rank_B"] < s["B"].shape[1] for s in systems) >= 10
    assert sum(0 < s["rank_D"] < s["D"].shape[1] for s in systems) >= 10
    assert sum(s["rank_D"] == 0 for s in systems) == GRDE_SYSTEMS // 25
    assert sum(np.linalg.matrix_rank(s["Q"]) < s["n"] for s in systems) >= 10
    marginal = [s for s in systems if s["kind"] == "marginal"]
    assert all(abs(np.max(np.linalg.eigvals(s["A"]).real)) < 1e-12 for s in marginal)
    assert {filter_system(i)["n"] for i in range(FILTER_SYSTEMS)} >= {1, 8}


# ---- the reference, checked ----

def test_reference_matches_the_scalar_closed_form():
    """Scalar systems, where the first escape is known in closed form (_support.
    scalar_escape_tau for dz/dtau = 2 a z + r - s z^2, z(0) = z0): 200 seeded GRDEs
    (s = b^2 - d^2 / gamma^2, r = q, z0 = qf) and 200 seeded filters (s = c^2 / N - q / gamma^2,
    r = d^2, z0 = Sigma0), with and without an escape on [0, T]. Measured agreement of the
    escape times 6e-10 relative (brentq on the reference's scalar near a simple zero)."""
    rng = np.random.default_rng(MASTER_SEED + 1)
    M = lambda x: np.array([[x]])  # noqa: E731
    escapes = 0
    for case in range(400):
        a, gamma = rng.uniform(-2.0, 2.0), rng.uniform(0.3, 3.0)
        b, d = rng.uniform(0.0, 1.5), rng.uniform(0.0, 2.0)
        q = 0.0 if rng.random() < 0.2 else rng.uniform(0.0, 2.0)
        z0 = (1e-8, 1.0, 10.0, rng.uniform(0.0, 3.0))[int(rng.integers(0, 4))]
        T = HORIZONS[int(rng.integers(0, 4))]
        if case < 200:
            exact = scalar_escape_tau(a, b * b - d * d / gamma**2, q, z0)
            tau = grde_conjugate_tau(M(a), M(b), M(d), M(q), M(z0), gamma, T)
        else:
            c, N = b, rng.uniform(0.2, 2.0)
            exact = scalar_escape_tau(a, c * c / N - q / gamma**2, d * d, z0)
            tau = filter_conjugate_tau(M(a), M(c), M(d), M(N), M(q), M(z0), gamma, T)
        if exact <= T:
            escapes += 1
            assert tau is not None and abs(tau - exact) <= 1e-8 * exact, (case, tau, exact)
        else:
            assert tau is None or exact - T <= 1e-9 * T, (case, tau, exact)
    assert 80 <= escapes <= 320  # both outcomes are well represented


def riccati_blow_up_tau(system: dict, gamma: float) -> float | None:
    """The GRDE integrated by SciPy (DOP853, rtol 1e-11) in backward time until max |Z| reaches
    1e8 (event), or None: an escape tau_c shows as an event within ~|Z|-scale / 1e8 of it."""
    A, B, D, Q, Qf, T, n = (system[k] for k in ("A", "B", "D", "Q", "Qf", "T", "n"))
    S = B @ B.T - D @ D.T / gamma**2

    def rhs(tau, z):
        Z = z.reshape(n, n)
        return (A.T @ Z + Z @ A + Q - Z @ S @ Z).ravel()

    def big(tau, z):
        return np.max(np.abs(z)) - 1e8

    big.terminal = True
    sol = solve_ivp(rhs, (0.0, T), Qf.ravel(), method="DOP853", rtol=1e-11, atol=1e-12, events=big)
    assert sol.status in (0, 1), sol.message
    return float(sol.t_events[0][0]) if sol.t_events[0].size else None


# Systems of the set with n >= 2: unstable, stable and marginal A, every Qf and horizon.
SCIPY_CHECKED = [0, 1, 4, 6, 7, 10, 13, 18]


@pytest.mark.parametrize("index", SCIPY_CHECKED)
def test_reference_matches_scipy_away_from_gamma_star(index):
    """Matrix systems of the set at 0.8 and 1.25 times the reference gamma*: SciPy's
    integration of the Riccati equation blows up where the reference says (within 1e-6 T: the
    event at |Z| = 1e8 precedes the escape by ~1e-8 relative) and not at all above gamma*."""
    system = grde_system(index)
    A, B, D, Q, Qf, T = (system[k] for k in ("A", "B", "D", "Q", "Qf", "T"))
    assert system["rank_D"] > 0 and system["n"] > 1

    def escapes(gamma):
        return grde_conjugate_tau(A, B, D, Q, Qf, gamma, T) is not None

    star = threshold_by_bisection(escapes, *bracket_threshold(escapes, 1.0), rtol=1e-8)
    below = grde_conjugate_tau(A, B, D, Q, Qf, 0.8 * star, T)
    blow_up = riccati_blow_up_tau(system, 0.8 * star)
    assert below is not None and blow_up is not None and abs(blow_up - below) < 1e-6 * T, (below, blow_up)
    assert grde_conjugate_tau(A, B, D, Q, Qf, 1.25 * star, T) is None
    assert riccati_blow_up_tau(system, 1.25 * star) is None


# A system of the set whose gamma* is set by a near-tangential conjugate point in the interior
# of the horizon (n = 2, T = 5).
NEAR_TANGENTIAL_INDEX = 78


def test_reference_matches_the_inverse_riccati_near_gamma_star():
    """Near gamma* the conjugate point of this system is a short excursion of Z to infinity and
    back (a near-tangential one, which the library missed at its default tolerances): at
    gamma* (1 -+ 2e-7) SciPy's W = Z^-1 (DOP853, rtol 1e-12; _support.inverse_grde) has
    lambda_min(W) crossing zero below and staying positive above, exactly as the reference says,
    and the escape times agree (measured 1e-10)."""
    index = NEAR_TANGENTIAL_INDEX
    system = grde_system(index)
    A, B, D, Q, Qf, T = (system[k] for k in ("A", "B", "D", "Q", "Qf", "T"))

    def escapes(gamma):
        return grde_conjugate_tau(A, B, D, Q, Qf, gamma, T) is not None

    star = threshold_by_bisection(escapes, *bracket_threshold(escapes, 1.0), rtol=1e-10)
    for factor, escape in ((1 - 2e-7, True), (1 + 2e-7, False)):
        gamma = star * factor
        S = B @ B.T - D @ D.T / gamma**2
        W = inverse_grde(lambda t: A, S, Q, Qf, 0.0, T, rtol=1e-12)
        lowest, where, crossing = inverse_grde_conjugate_point(W, 0.0, T, samples=20001)
        tau = grde_conjugate_tau(A, B, D, Q, Qf, gamma, T)
        assert (crossing is not None) == escape and (tau is not None) == escape, (factor, lowest, crossing, tau)
        if escape:
            assert abs((T - tau) - crossing) < 1e-8 * T
        # The near-escape lies inside the horizon, not at its end t0 (where gamma* would be set
        # by an escape entering the horizon, not by a tangency).
        assert 0.01 * T < where < 0.99 * T


# ---- the library against the reference ----

def check_grde_system(index: int) -> list[str]:
    """The library's gamma_star and grde_escape_time on one system: a list of failures."""
    system = grde_system(index)
    A, B, D, Q, Qf, T = (system[k] for k in ("A", "B", "D", "Q", "Qf", "T"))
    tr = trajectory(system)
    failures = []

    def escapes(gamma):
        return grde_conjugate_tau(A, B, D, Q, Qf, gamma, T) is not None

    try:
        lib = hc.gamma_star(tr, Q, Qf).gamma_star
    except hc.HinfError as error:
        return [f"{describe(index, system)}: gamma_star raised {type(error).__name__}: {error}"]
    if system["rank_D"] == 0:
        # S = BB' >= 0 whatever gamma: no conjugate point ever, gamma* = 0.
        if lib != 0.0:
            failures.append(f"{describe(index, system)}: D = 0 but gamma_star = {lib!r}")
        if escapes(1.0):
            failures.append(f"{describe(index, system)}: the reference escapes with D = 0")
        if not math.isnan(hc.grde_escape_time(tr, Q, Qf, 1.0)):
            failures.append(f"{describe(index, system)}: D = 0 but grde_escape_time(gamma = 1) is finite")
        return failures
    below, above = lib * (1 - GAMMA_RTOL), lib * (1 + GAMMA_RTOL)
    if escapes(below) and not escapes(above):
        # The reference gamma* lies in (below, above]: the escape checks at the bracket's ends
        # moved by ESCAPE_OFFSET are at least ESCAPE_OFFSET from gamma* (at most 1.1 of it).
        low, high = below * (1 - ESCAPE_OFFSET), above * (1 + ESCAPE_OFFSET)
    else:
        reference = threshold_by_bisection(escapes, *bracket_threshold(escapes, lib), rtol=1e-9)
        failures.append(f"{describe(index, system)}: gamma_star = {lib:.10g}, reference gamma* = "
                        f"{reference:.10g} (relative error {(lib - reference) / reference:+.2e})")
        low, high = reference * (1 - ESCAPE_OFFSET), reference * (1 + ESCAPE_OFFSET)
    t_low = hc.grde_escape_time(tr, Q, Qf, low)
    if not 0.0 <= t_low <= T:  # NaN fails too
        tau = grde_conjugate_tau(A, B, D, Q, Qf, low, T)
        failures.append(f"{describe(index, system)}: grde_escape_time at gamma* (1 - 1e-5) = {low:.10g} is "
                        f"{t_low} (reference escape at t = {T - tau:.6g})")
    t_high = hc.grde_escape_time(tr, Q, Qf, high)
    if not math.isnan(t_high):
        failures.append(f"{describe(index, system)}: grde_escape_time at gamma* (1 + 1e-5) = {high:.10g} is "
                        f"{t_high}, the reference finds no conjugate point")
    return failures


@pytest.mark.parametrize("first", range(0, GRDE_SYSTEMS, CHUNK))
def test_gamma_star_and_escape_time_against_the_reference(first):
    failures = []
    for index in range(first, first + CHUNK):
        failures += check_grde_system(index)
    assert not failures, "\n".join(failures)


def check_filter_system(index: int) -> list[str]:
    """filter_escape_time around the reference threshold gamma_f of the filter (36)."""
    system = filter_system(index)
    A, C, D, N, Q, Sigma0, T = (system[k] for k in ("A", "C", "D", "N", "Q", "Sigma0", "T"))

    def escapes(gamma):
        return filter_conjugate_tau(A, C, D, N, Q, Sigma0, gamma, T) is not None

    threshold = threshold_by_bisection(escapes, *bracket_threshold(escapes, 1.0), rtol=1e-7)
    tr = trajectory(system)
    failures = []
    low, high = threshold * (1 - ESCAPE_OFFSET), threshold * (1 + ESCAPE_OFFSET)
    t_low = hc.filter_escape_time(tr, N, Q, low, Sigma0)
    if not 0.0 <= t_low <= T:
        tau = filter_conjugate_tau(A, C, D, N, Q, Sigma0, low, T)
        failures.append(f"{describe(index, system)}: filter threshold {threshold:.10g}; filter_escape_time at "
                        f"(1 - 1e-5) is {t_low} (reference escape at t = {tau:.6g})")
    t_high = hc.filter_escape_time(tr, N, Q, high, Sigma0)
    if not math.isnan(t_high):
        failures.append(f"{describe(index, system)}: filter threshold {threshold:.10g}; filter_escape_time at "
                        f"(1 + 1e-5) is {t_high}, the reference finds no escape")
    return failures


@pytest.mark.parametrize("first", range(0, FILTER_SYSTEMS, CHUNK))
def test_filter_escape_time_against_the_reference(first):
    failures = []
    for index in range(first, first + CHUNK):
        failures += check_filter_system(index)
    assert not failures, "\n".join(failures)


# SLICOT's SB10FD example system, its state-feedback part (tests/data/sb10fd_state_feedback.toml).
# Just above gamma* its Z has a peak of ~1e6 times its scale, which a solve that follows Z
# itself crosses in ~1e5 steps (and misplaced gamma* by 1.4e-7): the escape test continues on
# W = c (Z + c I)^-1 from escape_norm times the scale.
SB10FD = pathlib.Path(__file__).resolve().parents[1] / "data" / "sb10fd_state_feedback.toml"


def test_gamma_star_of_the_sb10fd_state_feedback_problem():
    sc = hc.load_scenario(SB10FD)
    A, B, D = sc.model.A(), sc.model.B(), sc.model.process_D()
    Q, Qf, T = sc.Q, sc.Qf, sc.tf
    tr = hc.Trajectory(sc.model, sc.desired_q0, sc.desired_u, sc.t0, sc.tf)
    result = hc.gamma_star(tr, Q, Qf)
    star = result.gamma_star
    # The Hamiltonian reference: a conjugate point 1e-6 below, none 1e-6 above (GAMMA_RTOL).
    assert grde_conjugate_tau(A, B, D, Q, Qf, star * (1 - GAMMA_RTOL), T) is not None, star
    assert grde_conjugate_tau(A, B, D, Q, Qf, star * (1 + GAMMA_RTOL), T) is None, star
    # A budget instead of a clock: each escape test of the search takes about as many steps as
    # one solve (no gamma needs 1e5 steps in the peak): max_steps 20 000 is ~40 times one solve.
    budget = hc.GammaStarOptions(solver=hc.SolverOptions(max_steps=20000))
    assert hc.gamma_star(tr, Q, Qf, budget).gamma_star == star
    # The search reports its cost: 34 trials of about one solve each (5451 solves' worth when
    # each test followed Z into its peak).
    solve = hc.solve_grde(tr, Q, Qf, 2.0 * star).stats().rhs_evals
    assert result.rhs_evals == sum(trial.rhs_evals for trial in result.trials)
    assert result.rhs_evals < 100 * solve, (result.rhs_evals, solve)
