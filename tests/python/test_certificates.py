"""The certificates of paper §3 (eqs. 22-24) and the attenuation guarantee of eq. (12) through
the Python API.

tests/cpp/test_certificates.cpp checks the numerics: m, M (22) and p(t) (23) against
eigenvalues on fine grids, the ship's remainder bound against sampled remainders, epsilon and
the rates of (24), closed loops from the certified ball, and the completed square of (12).
Here: what certify returns to Python, with closed forms (p = 1 for kappa >= 1/2 on the ship,
kappa's minimum, the remainder bound's derivation, the formulas of (24)) and one grid of NumPy
eigenvalues; a model written in Python (its remainder sampled); and the Python-only
gamma_sweep (sweep_gamma, cost_L_gamma, sweep_figure), checked against independent truth:

* for LTI plants (where the linearization is exact), the completed square
      L_gamma = q_e(t0)' Z(t0) q_e(t0) - gamma^2 || w - gamma^-2 D' Z q_e ||^2
  (differentiate V along the closed loop with u = -B' Z q_e), so L_gamma <= 0 and the L2 gain is
  <= gamma for every disturbance from a zero initial error, and L_gamma = -gamma^2 |v|^2
  exactly for w = v + the worst case (16).
"""

from __future__ import annotations

import json
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import hinf_cpp as hc
from _support import (
    PAPER_PARAMETERS,
    ROUNDOFF,
    SHIP_B,
    SHIP_D,
)
from hinf_cpp.analysis.gamma_sweep import cost_L_gamma, sweep_figure, sweep_gamma

EYE6 = np.eye(6)
BIN = pathlib.Path(sys.executable).parent
HINF_CPP = BIN / "hinf-cpp"
DATA = pathlib.Path(__file__).resolve().parents[1] / "data"


def fine_times(sol, count=40001):
    """A uniform grid plus the solver's steps and their midpoints."""
    steps = np.asarray(sol.dense().breakpoints())
    return np.unique(np.concatenate([np.linspace(sol.t0(), sol.tf(), count), steps, 0.5 * (steps[1:] + steps[:-1])]))


def p_matrices(Z, B, D, Q, kappa, gamma):
    """Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z for a stack of Z (NumPy)."""
    ZB, ZD = Z @ B, Z @ D
    kappa = np.broadcast_to(np.asarray(kappa, dtype=float), (Z.shape[0],))
    P = (Q + (2.0 * kappa - 1.0)[:, None, None] * (ZB @ np.transpose(ZB, (0, 2, 1)))
         + (ZD @ np.transpose(ZD, (0, 2, 1))) / gamma**2)
    return 0.5 * (P + np.transpose(P, (0, 2, 1)))


def p_of_t(Z, B, D, Q, kappa, gamma):
    """lambda_min(Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z) for a stack of Z (NumPy)."""
    return np.linalg.eigvalsh(p_matrices(Z, B, D, Q, kappa, gamma))[:, 0]


def p_roundoff(Z, B, D, Q, kappa, gamma):
    """Round-off allowance for p(t) computed by two eigenvalue algorithms (the library's and
    LAPACK's): an eigenvalue of a symmetric matrix moves by at most the norm of the rounding
    errors, ~ eps times the size of its entries; ROUNDOFF times the largest entry of P over
    the stack."""
    return ROUNDOFF * np.max(np.abs(p_matrices(Z, B, D, Q, kappa, gamma)))


def ship_L(q_d) -> np.ndarray:
    """The ship's remainder bound, derived here: with e = (e_u, e_v, e_r, e_x, e_y, e_psi),
    r = f(q_d + e) - f(q_d) - A_e e has r_u = m_u e_v e_r, r_v = m_v e_u e_r, r_r = m_r e_u e_v,
    r_psi = 0 and r_xy = [R(psi_d + e_psi) - R(psi_d) - R'(psi_d) e_psi](u_d, v_d)
    + [R(psi_d + e_psi) - R(psi_d)](e_u, e_v), R the rotation; |e^{ib} - 1 - ib| <= b^2/2,
    |e^{ib} - 1| <= |b| and |e_i e_j| <= |e|^2/2 give |r| <= L |e|^2 for EVERY e with
    L = 1/2 sqrt(m_u^2 + m_v^2 + m_r^2 + (|(u_d, v_d)| + 1)^2) (cpp/src/models/model.cpp documents
    the same bound; tests/cpp/test_certificates.cpp checks by sampling that it is one)."""
    p = PAPER_PARAMETERS
    speed = np.hypot(q_d[..., 0], q_d[..., 1])
    return 0.5 * np.sqrt(p["m_u"]**2 + p["m_v"]**2 + p["m_r"]**2 + (speed + 1.0)**2)


# ==== the paper's ship at gamma = 5, Q = Qf = I ====

@pytest.fixture(scope="module")
def paper_design(paper_trajectory):
    """The paper's design solved tightly (rtol 1e-10), as in tests/cpp/test_certificates.cpp."""
    return hc.solve_grde(paper_trajectory, EYE6, EYE6, 5.0,
                         hc.SolverOptions(method="bdf", rtol=1e-10, atol=1e-12))


def test_m_and_M_are_the_eigenvalue_bounds_of_Z(paper_solutions):
    """(22) with kappa given as a number: m and M are the solution's eigenvalue bounds (against
    NumPy's eigenvalues on a grid: the linear model below, and the ship in
    tests/cpp/test_certificates.cpp)."""
    sol = paper_solutions["auto"]
    c = hc.certify(sol, 1.0, EYE6)
    assert c.kappa_min == 1.0
    assert (c.m, c.M) == sol.eigenvalue_bounds()  # the same computation (certify calls it)
    assert 0.0 < c.m < 1.0 < c.M  # Z(tf) = Qf = I lies between them
    # An independent implementation's values, orientation only.
    assert c.m == pytest.approx(0.219, abs=1e-3) and c.M == pytest.approx(20.8, abs=0.05)


@pytest.mark.parametrize("kappa", [1.0, 0.25])
def test_p_min_is_the_smallest_eigenvalue_of_P(paper_design, kappa):
    """(23) on the ship, kappa given as a Signal (p(t) against eigenvalues on a grid for
    kappa = 1, 1/2, 2, 1/4: tests/cpp/test_certificates.cpp). For kappa >= 1/2, P = I + a
    positive semidefinite matrix of rank <= 3 (D D' and B B' act on u, v, r only) in 6
    dimensions, so p(t) = 1 = lambda_min(Q) exactly (Remark 1's bound, attained); kappa = 1/4
    makes it negative (measured -7.15), and the certificate empty."""
    c = hc.certify(paper_design, hc.Signal(kappa), EYE6)
    assert c.kappa_min == kappa
    assert 0.0 <= c.p_min_t <= 40.0
    at = p_of_t(paper_design.Z(np.array([c.p_min_t])), SHIP_B, SHIP_D, EYE6, kappa, 5.0)[0]
    # p is the smallest eigenvalue of P, whose entries are at most 1 + (|2 kappa - 1| + 1/25) M^2
    # (B and D have unit columns, |Z| <= M): two eigenvalue algorithms differ by round-off of that.
    slack = ROUNDOFF * (1.0 + (abs(2.0 * kappa - 1.0) + 1.0 / 25.0) * c.M**2)
    assert at == pytest.approx(c.p_min, abs=slack)
    if kappa >= 0.5:
        assert c.p_min == pytest.approx(1.0, abs=slack)
        assert c.decay_rate == pytest.approx(c.p_min / (2.0 * c.M), rel=ROUNDOFF)
    else:
        assert c.p_min < 0.0
        assert c.epsilon == 0.0 and c.attraction_radius == 0.0 and c.decay_rate == 0.0


def test_linear_model_certificates_with_time_varying_kappa(lti_trajectory):
    """A plant with full-rank B and Q = diag(1, 2, 3), where p(t) is not trivially lambda_min(Q),
    and kappa(t) = 0.75 + 0.5 sin t (kappa_min = 1/4): p_min from NumPy on a fine grid; the
    remainder of a LinearModel is 0, so epsilon and the attraction radius are infinite. The one
    check of m, M and p_min against a grid from Python (the ship's: tests/cpp/test_certificates.cpp)."""
    rng = np.random.default_rng(5)
    A, B, D = rng.standard_normal((3, 3)) - np.eye(3), rng.standard_normal((3, 3)), rng.standard_normal((3, 2))
    Q = np.diag([1.0, 2.0, 3.0])
    tr = lti_trajectory(A, B, D, 0.0, 6.0)
    sol = hc.solve_grde(tr, Q, np.eye(3), 3.0)
    times = fine_times(sol, 60001)
    Z = sol.Z(times)
    for kappa, kappa_t in ((hc.Signal(0.75, [hc.Harmonic(amplitude=0.5, omega=1.0)]), 0.75 + 0.5 * np.sin(times)),
                           (hc.Signal(1.0), 1.0)):
        c = hc.certify(sol, kappa, Q)
        p = p_of_t(Z, B, D, Q, kappa_t, 3.0)
        slack = p_roundoff(Z, B, D, Q, kappa_t, 3.0)  # two eigenvalue algorithms
        # min kappa(t) on [0, 6]: 0.75 - 0.5 = 0.25 at t = 3 pi / 2 (closed form; the library
        # refines its minimum between samples, to round-off in kappa).
        assert c.kappa_min == pytest.approx(0.25 if isinstance(kappa_t, np.ndarray) else 1.0, abs=ROUNDOFF)
        assert p.min() - 1e-8 <= c.p_min <= p.min() + slack
        assert c.p_min_t == pytest.approx(times[np.argmin(p)], abs=1e-3)
        assert c.remainder_L == 0.0 and c.remainder_is_bound
        assert c.epsilon == math.inf and c.attraction_radius == math.inf
        eig = np.linalg.eigvalsh(Z)
        assert c.m == pytest.approx(eig[:, 0].min(), abs=1e-8) and c.M == pytest.approx(eig[:, -1].max(), abs=1e-8)
        # The formula p_min / (2 M) of (24) evaluated here and in the library: round-off apart.
        assert c.decay_rate == pytest.approx(c.p_min / (2.0 * c.M), rel=ROUNDOFF)
    assert hc.certify(sol, hc.Signal(1.0), Q).p_min > np.linalg.eigvalsh(Q)[0] + 0.1  # strictly above Q's


def test_ship_remainder_bound_is_the_derivation(paper_design, paper_trajectory):
    """remainder_L is the largest L(t) over the run of the derivation in ship_L, on a fine grid
    (that L |e|^2 bounds remainders sampled at 6000 random times, directions and radii:
    tests/cpp/test_certificates.cpp)."""
    c = hc.certify(paper_design, 1.0, EYE6)
    assert c.remainder_is_bound and "analytic" in c.remainder_method
    times = fine_times(paper_design)
    assert ship_L(paper_trajectory.q_d(times)).max() == pytest.approx(c.remainder_L, rel=1e-9)


def test_epsilon_attraction_radius_and_decay_rate(paper_design):
    """(24): epsilon = min_t p(t) / (4 M L(t)) with p = 1 here (kappa = 1), so epsilon =
    1 / (4 M max L(t)) (measured 0.0082336; its place and the minimum over a grid:
    tests/cpp/test_certificates.cpp), the attraction radius epsilon sqrt(m / M), the decay rate
    p_min / (2 M), and scenario_certificates of paper_fig1.toml."""
    c = hc.certify(paper_design, 1.0, EYE6)
    # With p = 1 at every time, the smallest ratio is at the largest L(t), remainder_L: equal up
    # to the round-off of p (|P| <= 1 + 1.04 M^2, see above) and of the quotient.
    expected = 1.0 / (4.0 * c.M * c.remainder_L)
    assert c.epsilon == pytest.approx(expected, rel=ROUNDOFF * (1.0 + 1.04 * c.M**2) + ROUNDOFF)
    assert 0.0 <= c.epsilon_t <= 40.0
    # The formulas of (24) evaluated here and in the library: round-off apart.
    assert c.attraction_radius == pytest.approx(c.epsilon * math.sqrt(c.m / c.M), rel=ROUNDOFF)
    assert c.decay_rate == pytest.approx(c.p_min / (2.0 * c.M), rel=ROUNDOFF)
    assert hc.scenario_certificates(hc.load_scenario(hc.scenario_path("paper_fig1"))).epsilon == pytest.approx(
        c.epsilon, rel=1e-6)


def test_sampled_remainder_for_a_model_without_a_bound():
    """A model written in Python, without remainder_bound: the certificate samples |r| / |e|^2
    and says it is not a bound. For f(q) = -q + q^2 the remainder is exactly e^2, so the
    sampled L is exactly 1 (and epsilon = min p / (4 M): tests/cpp/test_certificates.cpp)."""

    class Quadratic(hc.Model):
        def __init__(self):
            hc.Model.__init__(self)

        def name(self):
            return "quadratic"

        def n(self):
            return 1

        def m(self):
            return 1

        def nw(self):
            return 1

        def f(self, t, q):
            return np.array([-q[0] + q[0] ** 2])

        def dfdq(self, t, q):
            return np.array([[-1.0 + 2.0 * q[0]]])

        def G(self, t, q):
            return np.array([[1.0]])

        def D(self, t, q):
            return np.array([[1.0]])

    tr = hc.Trajectory(Quadratic(), [0.3], [0.0], 0.0, 3.0)
    sol = hc.solve_grde(tr, np.eye(1), np.eye(1), 2.0)
    c = hc.certify(sol, 1.0, np.eye(1))
    assert not c.remainder_is_bound and "not a bound" in c.remainder_method
    # r = e^2 exactly; computed as a difference of values of f ~ 1 at radii >= 0.01 it carries
    # round-off of a few eps / 0.01^2 ~ 1e-11 relative.
    assert c.remainder_L == pytest.approx(1.0, rel=1e-9)
    assert 0.0 < c.epsilon < math.inf


# ==== attenuation against gamma (paper eq. 12) on an LTI plant ====

# The closed loop under the worst case (16) just above gamma* amplifies integration errors
# (the feedback gamma^-2 D' Z q_e is large): at the default bdf rtol 1e-8 the max |w| is off by
# 2e-5 relative and L_gamma by 5e-4 .. 2.3e-3 depending on the build's round-off. Runs that
# compare L_gamma with its exact value there use this tight explicit solver (w then within
# 1e-9, L_gamma within its quadrature error).
TIGHT_SOLVER = {"method": "erk", "rtol": 1e-11, "atol": 1e-13}


def lti_scenario(disturbance=None, worst_case=False, dt=0.002, q0=(0.0, 0.0), solver=None):
    """A 2-state LTI plant, unstable open loop (eigenvalues -0.15 +- 0.96i shifted by 0.2):
    the linearized guarantee is exact."""
    spec = {
        "name": "lti-attenuation",
        "model": {"kind": "linear", "A": [[0.2, 1.0], [-1.0, -0.5]], "B": [[0.0], [1.0]],
                  "D": [[1.0, 0.0], [0.3, 1.0]]},
        "horizon": {"t0": 0.0, "tf": 10.0},
        "desired": {"q0": [0.0, 0.0], "u1": {"offset": 0.0}},
        "controller": {"gamma": 5.0, "Q": [[1.0, 0.2], [0.2, 2.0]], "Qf": 0.5},
        "disturbance": disturbance if disturbance is not None else {
            "w1": {"harmonics": [{"amplitude": 1.0, "omega": 1.3}]},
            "w2": {"harmonics": [{"amplitude": 0.5, "omega": 0.4, "shape": "cos"}]}},
        "initial": {"q0": list(q0)},
        "output": {"dt": dt},
        # The worst case near gamma* amplifies w some 13 times: a linear plant has no physical
        # scale to stop it at, so the divergence bound is far out.
        "solver": {"divergence_factor": 1e3, **(solver or {})},
    }
    if worst_case:
        spec["disturbance"] = dict(spec["disturbance"], worst_case=True)
    return hc.scenario_from_dict(spec)


def harmonic_energy(T=10.0) -> float:
    """Closed form of int_0^T (sin^2(1.3 t) + 0.25 cos^2(0.4 t)) dt (the signals above)."""
    return (T / 2 - math.sin(2.6 * T) / 5.2) + 0.25 * (T / 2 + math.sin(0.8 * T) / 1.6)


def random_disturbance(seed: int):
    """Tabulated random signals (spline through 41 seeded Gaussian values) on w1, w2."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0.0, 10.0, 41).tolist()
    return {f"w{i}": {"table": {"t": t, "value": rng.standard_normal(41).tolist()}} for i in (1, 2)}


def numpy_cost_and_gain(run, Q, Qf, gamma):
    """L_gamma of (12) and the L2 gain on the output grid (trapezoid rule), from the series."""
    sim = run.simulation
    q_e, u_e, w = sim.q - sim.q_d, sim.u - sim.u_d, sim.w
    x = np.einsum("ki,ij,kj->k", q_e, Q, q_e) + np.sum(u_e**2, axis=1)
    ww = np.sum(w**2, axis=1)
    cost = np.trapezoid(x - gamma**2 * ww, sim.t) + q_e[-1] @ Qf @ q_e[-1]
    return cost, math.sqrt(np.trapezoid(x, sim.t) / np.trapezoid(ww, sim.t))


LTI_Q, LTI_QF = np.array([[1.0, 0.2], [0.2, 2.0]]), 0.5 * np.eye(2)
LTI_D = np.array([[1.0, 0.0], [0.3, 1.0]])


@pytest.fixture(scope="module")
def sweeps():
    """sweep_gamma (6 gammas, from the desired state) for three disturbances: the harmonic
    signals, a seeded random one, and the harmonic signals plus the worst case (16) (run with
    TIGHT_SOLVER)."""
    return {
        "harmonic": sweep_gamma(lti_scenario(), count=6),
        "random": sweep_gamma(lti_scenario(random_disturbance(11)), count=6),
        "worst case": sweep_gamma(lti_scenario(worst_case=True, solver=TIGHT_SOLVER), count=6),
    }


def test_sweep_gammas_are_above_gamma_star(sweeps):
    star = hc.scenario_gamma_star(lti_scenario()).gamma_star
    for sweep in sweeps.values():
        assert sweep.gamma_star == star and sweep.gamma_star_output_feedback is None
        assert sweep.zero_initial_error
        assert np.all(sweep.gammas > star)
        # np.geomspace keeps its end points exactly; the same products are formed here.
        assert sweep.gammas[0] == pytest.approx(star * (1 + 1e-3), rel=1e-12)
        assert sweep.gammas[-1] == pytest.approx(max(4 * 5.0, 10 * star), rel=1e-12)
        ratios = sweep.gammas[1:] / sweep.gammas[:-1]
        # geometric: exp of equally spaced logarithms, each rounded (a few ulps)
        np.testing.assert_allclose(ratios, ratios[0], rtol=ROUNDOFF)
    # Every gamma of the sweep designs without a conjugate point.
    tr = hc.Trajectory(hc.LinearModel(np.array([[0.2, 1.0], [-1.0, -0.5]]), np.array([[0.0], [1.0]]), LTI_D),
                       np.zeros(2), [0.0], 0.0, 10.0)
    for gamma in sweeps["harmonic"].gammas:
        assert math.isnan(hc.grde_escape_time(tr, LTI_Q, LTI_QF, gamma))


@pytest.mark.parametrize("name", ["harmonic", "random", "worst case"])
def test_sweep_gain_below_gamma_and_cost_nonpositive(sweeps, name):
    """From a zero initial error the completed square gives L_gamma = -gamma^2 |w - w*|^2 <= 0,
    hence sqrt(int |q_e|_Q^2 + |u_e|^2) <= gamma |w|: the measured gain is below gamma at every
    gamma, for every disturbance. With the worst case added the bound is nearly attained at
    the lowest gamma (measured gain / gamma 0.997)."""
    sweep = sweeps[name]
    assert np.all(sweep.response_ratio <= sweep.gammas)
    assert np.all(sweep.cost <= 0.0)
    if name == "worst case":
        assert sweep.response_ratio[0] > 0.95 * sweep.gammas[0]
        # L_gamma = -gamma^2 int |v|^2 exactly (v the harmonic signals), up to the trapezoid
        # rule at dt = 0.002 (measured 5e-8 .. 1.3e-7 relative; the solver's error, rtol 1e-11,
        # is far below). At the lowest gamma the worst case amplifies w (|w|^2 / |v|^2 ~ 170)
        # and L_gamma is the small difference of terms that much larger: the same relative
        # quadrature error of the terms, 1e-6, is 170 x 1e-6 ~ 2e-4 of L_gamma (measured 7e-6).
        expected = -sweep.gammas**2 * harmonic_energy()
        np.testing.assert_allclose(sweep.cost[1:], expected[1:], rtol=1e-6)
        np.testing.assert_allclose(sweep.cost[0], expected[0], rtol=2e-4)


@pytest.mark.parametrize("worst_case", [False, True])
def test_cost_L_gamma_against_numpy(worst_case):
    """cost_L_gamma equals a NumPy trapezoid of the time series of a run from a nonzero initial
    error (so every term counts), at gamma = 2.2 (gamma* = 1.70). (L_gamma against the completed
    square and the library's l2_gain against the series: tests/cpp/test_certificates.cpp.)"""
    scenario = lti_scenario(worst_case=worst_case, q0=(0.5, -0.5))
    scenario.gamma = 2.2
    run = hc.run_scenario(scenario)
    cost, _ = numpy_cost_and_gain(run, LTI_Q, LTI_QF, 2.2)
    # The same NumPy expression on the same arrays (1e-12 allows for another order of sums).
    assert cost_L_gamma(run, LTI_Q, LTI_QF) == pytest.approx(cost, rel=1e-12, abs=1e-12)


def test_sweep_figure_and_bad_arguments(sweeps, tmp_path):
    fig = sweep_figure(sweeps["worst case"])
    path = tmp_path / "sweep.png"
    fig.savefig(path)
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000
    axes = fig.get_axes()
    assert len(axes) == 2
    np.testing.assert_allclose(axes[0].lines[0].get_xdata(), sweeps["worst case"].gammas)
    np.testing.assert_allclose(axes[0].lines[0].get_ydata(), sweeps["worst case"].response_ratio)
    with pytest.raises(ValueError, match="count"):
        sweep_gamma(lti_scenario(), count=1)
    with pytest.raises(ValueError, match="upper"):
        sweep_gamma(lti_scenario(), count=3, upper=1.0)


# ==== the command line ====

pytestmark_cli = pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")


def cli(*args) -> subprocess.CompletedProcess:
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=120)


@pytestmark_cli
def test_cli_certify(tmp_path, paper_solutions):
    out = tmp_path / "cert.json"
    done = cli(HINF_CPP, "certify", hc.scenario_path("paper_fig1"), "--json", out)
    assert done.returncode == 0, done.stderr
    data = json.loads(out.read_text())
    c = hc.certify(paper_solutions["bdf"], 1.0, EYE6)  # the file's design: bdf, rtol 1e-8
    # The same computation on the same input (the file states the fixture's design), written
    # to JSON and read back: equal up to the printed digits.
    for key in ("m", "M", "kappa_min", "p_min", "remainder_L", "epsilon", "attraction_radius", "decay_rate"):
        assert data[key] == pytest.approx(getattr(c, key), rel=1e-12), key
    assert data["scenario"] == "paper-fig1" and data["gamma"] == 5.0 and data["remainder_is_bound"] is True
    for words in ("m = 0.21", "M = 20.8", f"epsilon = {c.epsilon:.6g}", f"{c.attraction_radius:.6g}",
                  f"exp(-{c.decay_rate:.6g} (t - t0))"):
        assert words in done.stdout, words


@pytestmark_cli
def test_cli_sweep_gamma(tmp_path):
    path = tmp_path / "lti.toml"
    path.write_text((DATA / "lti_sweep.toml").read_text())
    plot, out = tmp_path / "sweep.png", tmp_path / "sweep.json"
    done = cli(HINF_CPP, "sweep-gamma", path, "--count", "3", "--plot", plot, "--json", out)
    assert done.returncode == 0, done.stderr
    data = json.loads(out.read_text())
    sweep = sweep_gamma(hc.load_scenario(path), count=3)
    # The same search and runs on the same file in another process: equal up to the JSON digits.
    assert data["gamma_star"] == sweep.gamma_star
    np.testing.assert_allclose(data["gamma"], sweep.gammas, rtol=1e-15)
    np.testing.assert_allclose(data["response_ratio"], sweep.response_ratio, rtol=1e-12)
    np.testing.assert_allclose(data["cost_L_gamma"], sweep.cost, rtol=1e-12)
    assert all(g <= gamma for g, gamma in zip(data["response_ratio"], data["gamma"]))
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert f"gamma* = {sweep.gamma_star:.6g}" in done.stdout
