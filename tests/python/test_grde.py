"""The GRDE (13), -dZ/dt = A'Z + ZA + Q - Z (BB' - gamma^-2 DD') Z, Z(tf) = Qf, solved
backward, through the Python API.

tests/cpp/test_riccati.cpp checks the numerics: closed forms and conjugate points for every
method, the algebraic fixed point, the exact Hamiltonian solution, the ship's three methods,
residual, gain and conjugate point. Here: what solve_grde returns to Python (one closed form,
the exception, the evaluations at arrays of times), and what the C++ tests do not check: the
dense output at rtol 1e-12 and dZ/dt against the closed form, the long-horizon limit against
SciPy's algebraic Riccati equation for every method, game and LQR, escape_norm, a long LQR
horizon, time-varying input matrices of a Python model, the methods' agreement on the paper's
run at the default tolerances."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import hinf_cpp as hc
from _support import (
    METHODS,
    ROUNDOFF,
    SHIP_B,
    game_are,
    hamiltonian_grde,
    hinf_norm_upper_bound,
    max_rel,
    random_stable_lti,
    scalar_escape_tau,
    scalar_grde_closed_form,
)

TIGHT = dict(rtol=1e-12, atol=1e-14)

# ---- scalar LTI GRDE vs its closed form ----

# (a, b, d, gamma, q, qf, t0, tf);  s = b^2 - d^2 / gamma^2.
SCALAR_CASES = {
    # s = 0.75 > 0, unstable open loop: z converges to the stable root.
    "s>0": (0.5, 1.0, 1.0, 2.0, 2.0, 0.5, 0.0, 5.0),
    # s = 1 - 4/4 = 0 exactly: the Lyapunov (linear) case, z = qf e^{2a tau} + q (e^{2a tau}-1)/(2a).
    "s=0": (-0.3, 1.0, 2.0, 2.0, 1.0, 2.0, 0.0, 5.0),
    # s = 0.36 - 1.44/2.25 = -0.28 < 0, a^2 + s q > 0, qf below the unstable root: no escape.
    "s<0": (-0.8, 0.6, 1.2, 1.5, 1.5, 1.0, 0.0, 4.0),
    # s = -1, a^2 + s q < 0: oscillatory (tan-like) solution, escape at tau = pi/(2 w) = 1.81;
    # the horizon (0.9) stops at half of it. t0 != 0.
    "s<0 oscillatory": (-0.5, 1.0, math.sqrt(2.0), 1.0, 1.0, 0.5, 1.0, 1.9),
    # gamma = inf: the LQR Riccati equation, t0 < 0.
    "lqr": (0.4, 0.8, 1.0, math.inf, 1.0, 3.0, -2.0, 3.0),
}


def scalar_trajectory(a, b, d, t0, tf):
    model = hc.LinearModel(np.array([[a]]), np.array([[b]]), np.array([[d]]))
    return hc.Trajectory(model, [0.0], [0.0], t0, tf)


def scalar_s(b, d, gamma):
    return b * b - (0.0 if math.isinf(gamma) else d * d / gamma**2)


@pytest.mark.parametrize("case", list(SCALAR_CASES))
def test_scalar_closed_form_against_scipy(case):
    """The closed form itself, once, against solve_ivp at rtol 1e-12."""
    a, b, d, gamma, q, qf, t0, tf = SCALAR_CASES[case]
    s = scalar_s(b, d, gamma)
    ref = solve_ivp(lambda tau, z: 2 * a * z + q - s * z * z, (0.0, tf - t0), [qf],
                    method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
    taus = np.linspace(0.0, tf - t0, 501)
    exact = scalar_grde_closed_form(a, s, q, qf, taus)
    np.testing.assert_allclose(ref.sol(taus)[0], exact, rtol=1e-10)
    if case == "s=0":
        assert s == 0.0
        linear = qf * np.exp(2 * a * taus) + q * (np.exp(2 * a * taus) - 1) / (2 * a)
        np.testing.assert_allclose(exact, linear, rtol=ROUNDOFF)  # two closed forms: round-off


def test_scalar_grde_matches_closed_form():
    """One closed form through the binding at the default options (every case and method:
    tests/cpp/test_riccati.cpp): the solution's getters, its dense output at an array of times,
    and a scalar time giving the same interpolant."""
    a, b, d, gamma, q, qf, t0, tf = SCALAR_CASES["s>0"]
    s = scalar_s(b, d, gamma)
    tr = scalar_trajectory(a, b, d, t0, tf)
    sol = hc.solve_grde(tr, np.array([[q]]), np.array([[qf]]), gamma)
    assert sol.gamma() == gamma and sol.t0() == t0 and sol.tf() == tf and sol.n() == 1
    steps = np.asarray(sol.dense().breakpoints())
    assert steps[0] == pytest.approx(t0) and steps[-1] == pytest.approx(tf)
    times = np.linspace(t0, tf, 2001)
    Z = sol.Z(times)
    assert Z.shape == (times.size, 1, 1)
    exact = scalar_grde_closed_form(a, s, q, qf, tf - times)
    # Default rtol 1e-8: measured max relative error 1.3e-8 (erk, which "auto" runs here) to
    # 5.8e-8 (bdf).
    error = np.max(np.abs(Z[:, 0, 0] - exact) / np.abs(exact))
    assert error < 1e-7, f"max relative error {error:.2e}"
    # Scalar and array evaluation: the same interpolant at the same time.
    assert sol.Z(float(times[777]))[0, 0] == Z[777, 0, 0]


@pytest.mark.parametrize("case", list(SCALAR_CASES))
def test_scalar_grde_converges_at_tight_tolerances(case, method):
    """At rtol 1e-12 the dense output is within 1e-9 of the closed form everywhere (an
    interpolant of low order, e.g. cubic Hermite between BDF steps, would not be), and dZ/dt is
    the right-hand side at it (tests/cpp/test_riccati.cpp stops at rtol 1e-10)."""
    a, b, d, gamma, q, qf, t0, tf = SCALAR_CASES[case]
    s = scalar_s(b, d, gamma)
    tr = scalar_trajectory(a, b, d, t0, tf)
    sol = hc.solve_grde(tr, np.array([[q]]), np.array([[qf]]), gamma,
                        hc.SolverOptions(method=method, **TIGHT))
    times = np.linspace(t0, tf, 2001)
    exact = scalar_grde_closed_form(a, s, q, qf, tf - times)
    error = np.max(np.abs(sol.Z(times)[:, 0, 0] - exact) / np.abs(exact))
    assert error < 1e-9, f"{case} {method}: max relative error {error:.2e}"
    # dZ/dt = -(2 a z + q - s z^2) away from the first (order-1, for CVODE) step at tf.
    inner = times[times < tf - 0.05 * (tf - t0)]
    z = scalar_grde_closed_form(a, s, q, qf, tf - inner)
    rate = -(2 * a * z + q - s * z * z)
    assert max_rel(sol.dZdt(inner)[:, 0, 0], rate) < 1e-6


# ---- conjugate points ----

# (a, b, d, gamma, q, qf, t0, tf) with s < 0 and an escape inside the horizon.
ESCAPE_CASE = (-0.2, 1.0, 2.0, 1.0, 0.5, 0.3, 2.0, 12.0)


def test_scalar_conjugate_point_raises_with_its_escape_time():
    """A conjugate point reaches Python as ConjugatePointError, a HinfError and a RuntimeError,
    with gamma, the escape time (the closed form's; every method and the ship:
    tests/cpp/test_riccati.cpp) and a message."""
    a, b, d, gamma, q, qf, t0, tf = ESCAPE_CASE
    tau_c = scalar_escape_tau(a, scalar_s(b, d, gamma), q, qf)
    assert 0.0 < tau_c < tf - t0
    tr = scalar_trajectory(a, b, d, t0, tf)
    with pytest.raises(hc.ConjugatePointError) as info:
        hc.solve_grde(tr, np.array([[q]]), np.array([[qf]]), gamma)
    error = info.value
    assert isinstance(error, hc.HinfError) and isinstance(error, RuntimeError)
    assert error.gamma == gamma
    # Default rtol 1e-8: measured |t_escape - exact| / horizon 7.5e-8 (bdf) to 2.1e-10 (erk).
    assert abs(error.t_escape - (tf - tau_c)) < 1e-5 * (tf - t0), (error.t_escape, tf - tau_c)
    assert "conjugate point" in str(error)


def scalar_lqr_exact(a, b, q, qf, tau):
    """Scalar GRDE with s = b^2 > 0 in a cancellation-free form: with the roots
    z+ = (a + beta)/s, z- = -q/(a + beta) of s z^2 - 2 a z - q (beta = sqrt(a^2 + s q)),
    w = (z - z+)/(z - z-) obeys dw/dtau = -2 beta w, so z = (z+ - w z-)/(1 - w)."""
    s = b * b
    beta = math.sqrt(a * a + s * q)
    z_plus, z_minus = (a + beta) / s, -q / (a + beta)
    w = (qf - z_plus) / (qf - z_minus) * math.exp(-2.0 * beta * tau)
    return (z_plus - w * z_minus) / (1.0 - w)


LQR_LARGE = (1.0, 1e-6, 1.0, 1.0, 0.0, 20.0)  # a, b, q, qf, t0, tf: a nearly uncontrollable unstable mode


def test_lqr_large_solution_with_a_raised_escape_norm(lti_trajectory, method):
    """gamma = inf (LQR): no conjugate point, but Z(t0) of the scalar GRDE with a = 1, b = 1e-6,
    q = qf = 1 is about 2e12 (= 2a/b^2), far above the default escape threshold. The problem
    solves correctly once escape_norm is raised above |Z| (Z grows by 12 orders of magnitude;
    measured max relative error: bdf 1.6e-6, adams and erk ~1e-7)."""
    a, b, q, qf, t0, tf = LQR_LARGE
    assert 1e12 < scalar_lqr_exact(a, b, q, qf, tf - t0) < 3e12
    # The reference agrees with the generic closed form where that one is well conditioned.
    assert scalar_lqr_exact(0.4, 0.8, 1.0, 3.0, 2.5) == pytest.approx(
        float(scalar_grde_closed_form(0.4, 0.64, 1.0, 3.0, 2.5)), rel=ROUNDOFF)  # two closed forms
    tr = lti_trajectory([[a]], [[b]], [[1.0]], t0, tf)
    sol = hc.solve_grde(tr, np.array([[q]]), np.array([[qf]]), math.inf,
                        hc.SolverOptions(method=method, escape_norm=1e20))
    times = np.linspace(t0, tf, 201)
    exact = np.array([scalar_lqr_exact(a, b, q, qf, tf - t) for t in times])
    assert np.max(np.abs(sol.Z(times)[:, 0, 0] / exact - 1.0)) < 1e-5


class PeriodicScalar(hc.Model):
    """dq/dt = a(t) q + b u + w with a(t) = 1 + 0.9 sin(5 t): time-varying, so that the solver
    keeps taking steps over a long horizon."""

    B_GAIN = 1e-6

    def __init__(self):
        hc.Model.__init__(self)

    def n(self):
        return 1

    def m(self):
        return 1

    def nw(self):
        return 1

    @staticmethod
    def a(t):
        return 1.0 + 0.9 * math.sin(5.0 * t)

    def f(self, t, q):
        return np.array([self.a(t) * q[0]])

    def dfdq(self, t, q):
        return np.array([[self.a(t)]])

    def G(self, t, q):
        return np.array([[self.B_GAIN]])

    def D(self, t, q):
        return np.array([[1.0]])


def test_lqr_large_solution_over_a_long_horizon(method):
    """Z (gamma = inf, no conjugate point possible) passes the escape threshold early and then
    stays about 1e12 for 190 s of a time-varying problem, thousands of steps after the W = Z^-1
    probe has shown that it does not escape. Regression: a step budget after the probe used to
    stop this solve with "gamma = inf is very close to the smallest admissible value". The
    reference integrates W = 1/Z, dW/dt = 2 a W + q W^2 - b^2, with SciPy."""
    T, b = 200.0, PeriodicScalar.B_GAIN
    tr = hc.Trajectory(PeriodicScalar(), [0.0], [0.0], 0.0, T)
    sol = hc.solve_grde(tr, np.eye(1), np.eye(1), math.inf, hc.SolverOptions(method=method))
    ref = solve_ivp(lambda t, w: [2.0 * PeriodicScalar.a(t) * w[0] + w[0] ** 2 - b * b], (T, 0.0), [1.0],
                    method="DOP853", rtol=1e-12, atol=1e-30, dense_output=True)
    times = np.linspace(0.0, 180.0, 37)
    Z_ref = 1.0 / ref.sol(times)[0]
    assert Z_ref.min() > 1e11
    assert np.max(np.abs(sol.Z(times)[:, 0, 0] / Z_ref - 1.0)) < 1e-5  # measured: bdf 1.2e-7
    assert sol.stats().steps > 3000


# ---- long horizons: the game algebraic Riccati equation ----

def random_game(seed: int, n: int):
    rng = np.random.default_rng(seed)
    m, nw = 1 + n % 2, 2
    A, B, D, Q = random_stable_lti(rng, n, m, nw)
    C = np.linalg.cholesky(Q).T
    gamma = hinf_norm_upper_bound(A, C, D, factor=3.0)
    return A, B, D, Q, gamma


@pytest.mark.parametrize("n,seed", [(3, 2024), (4, 7), (5, 31)])
@pytest.mark.parametrize("finite_gamma", [True, False], ids=["game", "lqr"])
def test_long_horizon_converges_to_the_are(lti_trajectory, method, n, seed, finite_gamma):
    A, B, D, Q, gamma = random_game(seed, n)
    if not finite_gamma:
        gamma = math.inf
    X = game_are(A, B, D, Q, gamma)
    S = B @ B.T - (0.0 if math.isinf(gamma) else D @ D.T / gamma**2)
    # X is the stabilizing solution; the convergence rate of Z(t) -> X is 2 |alpha|.
    assert np.max(np.abs(A.T @ X + X @ A + Q - X @ S @ X)) < 1e-10 * np.max(np.abs(X))
    alpha = np.max(np.linalg.eigvals(A - S @ X).real)
    assert alpha < 0 and np.min(np.linalg.eigvalsh(X)) > 0
    horizon = 25.0 / abs(alpha)  # transient e^{-50}
    tr = lti_trajectory(A, B, D, 0.0, horizon)
    sol = hc.solve_grde(tr, Q, np.eye(n), gamma, hc.SolverOptions(method=method))
    # Measured (n = 3..5, game and LQR): bdf <= 3.9e-10, adams <= 1.1e-9, erk <= 3.5e-9.
    assert max_rel(sol.Z(0.0), X) < 1e-6


@pytest.mark.parametrize("n,seed", [(2, 1), (4, 7)])
def test_matrix_grde_matches_the_hamiltonian_solution_at_a_tight_tolerance(lti_trajectory, method, n, seed):
    """Short horizon, any gamma without conjugate point: Z(t) = Y X^-1 with
    [X; Y](t) = expm(H (t - tf)) [I; Qf] exactly (SciPy expm), at rtol 1e-12 (at rtol 1e-10:
    tests/cpp/test_riccati.cpp)."""
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((n, n))  # not necessarily stable
    B = rng.standard_normal((n, 2))
    D = rng.standard_normal((n, 3))
    L = rng.standard_normal((n, n))
    Q = L @ L.T + 0.2 * np.eye(n)
    Qf = 2.0 * np.eye(n) + 0.1 * np.ones((n, n))
    gamma, t0, tf = 10.0, 0.0, 2.0
    S = B @ B.T - D @ D.T / gamma**2
    times = np.linspace(t0, tf, 241)
    exact = hamiltonian_grde(A, S, Q, Qf, tf, times)
    assert np.all(np.linalg.eigvalsh(exact) > 0)  # no conjugate point on [t0, tf]
    tr = lti_trajectory(A, B, D, t0, tf)
    tight = hc.solve_grde(tr, Q, Qf, gamma, hc.SolverOptions(method=method, **TIGHT))
    # Measured: <= 1.4e-11 for every method.
    assert max_rel(tight.Z(times), exact) < 1e-9


class TimeVaryingInputs(hc.Model):
    """dq/dt = A q + B(t) u + D(t) w with time-varying B and D (constant_input_matrices False)."""

    def __init__(self, A):
        hc.Model.__init__(self)
        self.A = np.asarray(A, dtype=float)

    def n(self):
        return 2

    def m(self):
        return 1

    def nw(self):
        return 1

    def f(self, t, q):
        return self.A @ q

    def dfdq(self, t, q):
        return self.A.copy()

    def G(self, t, q):
        return np.array([[0.0], [1.0 + 0.5 * math.sin(t)]])

    def D(self, t, q):
        return np.array([[0.3 * math.cos(2 * t)], [1.0]])

    def constant_input_matrices(self):
        return False


def test_time_varying_input_matrices_against_scipy():
    """A Python model's time-varying B(t), D(t) (constant_input_matrices() False from Python)
    reach the GRDE, at the default options (a closed form with time-varying B for every method:
    tests/cpp/test_riccati.cpp)."""
    model = TimeVaryingInputs([[0.0, 1.0], [-1.0, -0.3]])
    Q, Qf, gamma, t0, tf = np.diag([1.0, 0.5]), np.eye(2), 2.0, 0.0, 6.0
    tr = hc.Trajectory(model, np.zeros(2), [0.0], t0, tf)
    sol = hc.solve_grde(tr, Q, Qf, gamma)
    A = model.A

    def rhs(t, z):
        Z = z.reshape(2, 2)
        B, D = model.G(t, np.zeros(model.n())), model.D(t, np.zeros(model.n()))
        S = B @ B.T - D @ D.T / gamma**2
        return (-(A.T @ Z + Z @ A + Q - Z @ S @ Z)).ravel()

    ref = solve_ivp(rhs, (tf, t0), Qf.ravel(), method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
    times = np.linspace(t0, tf, 301)
    expected = ref.sol(times).T.reshape(-1, 2, 2)
    assert max_rel(sol.Z(times), expected) < 1e-6
    # gain(t) = B(t)' Z(t) with the time-varying B.
    gains = sol.gain(times)
    for k in range(0, times.size, 30):
        np.testing.assert_allclose(gains[k], model.G(times[k], np.zeros(model.n())).T @ expected[k], rtol=1e-6, atol=1e-9)


# ---- along the paper's trajectory ----

PAPER_TIMES = np.linspace(0.0, 40.0, 2001)


def test_paper_Z_symmetric_positive_definite(paper_solutions):
    """Z at an array of times, and eigenvalue_range of a list of times, on the paper's design
    at the default options (the GRDE residual and Z > 0 for every method:
    tests/cpp/test_riccati.cpp)."""
    sol = paper_solutions["auto"]
    Z = sol.Z(PAPER_TIMES)
    assert Z.shape == (PAPER_TIMES.size, 6, 6)
    # Symmetric by construction: the library integrates one triangle and mirrors it.
    np.testing.assert_array_equal(Z, np.transpose(Z, (0, 2, 1)))
    eig = np.linalg.eigvalsh(Z)
    assert eig.min() > 0.0
    # eigenvalue_range (paper eq. 22) equals NumPy's extreme eigenvalues over the same times, up
    # to the round-off of two eigenvalue algorithms (relative to |Z| ~ 21, also for the smallest).
    lo, hi = sol.eigenvalue_range(list(PAPER_TIMES))
    slack = ROUNDOFF * np.max(np.abs(eig))
    assert lo == pytest.approx(eig.min(), abs=slack)
    assert hi == pytest.approx(eig.max(), abs=slack)
    # Z(tf) = Qf = I from the first step's polynomial: round-off.
    np.testing.assert_allclose(sol.Z(40.0), np.eye(6), rtol=0, atol=ROUNDOFF)


def test_paper_methods_agree(paper_solutions):
    """At the default tolerances (rtol 1e-8; tests/cpp/test_riccati.cpp compares them at 1e-10)."""
    Z = {m: paper_solutions[m].Z(PAPER_TIMES) for m in METHODS}
    # Measured: bdf-erk 5.1e-8, adams-erk 2.0e-8 (relative to max |Z| ~ 20).
    assert max_rel(Z["bdf"], Z["erk"]) < 1e-6
    assert max_rel(Z["adams"], Z["erk"]) < 1e-6


def test_gain_is_B_transpose_Z(paper_solutions):
    """gain at an array of times and at one time (a dense B, and every method:
    tests/cpp/test_riccati.cpp)."""
    sol = paper_solutions["bdf"]
    K = sol.gain(PAPER_TIMES)
    assert K.shape == (PAPER_TIMES.size, 2, 6)
    # B has entries 0 and 1 only: every product and sum is exact, in C++ and in NumPy alike.
    np.testing.assert_allclose(K, SHIP_B.T @ sol.Z(PAPER_TIMES), rtol=0, atol=1e-14)
    np.testing.assert_allclose(sol.gain(1.5), SHIP_B.T @ sol.Z(1.5), rtol=0, atol=1e-14)


def test_numpy_scalar_times_are_numbers(paper_solutions, paper_trajectory):
    """Z(t), gain(t), q_d(t) document "a number" for one time: NumPy scalars (np.arange of
    integers gives np.int64) and 0-d arrays are numbers too."""
    sol = paper_solutions["erk"]
    expected = sol.Z(3.0)
    for t in (np.float64(3.0), np.int64(3), np.float32(3.0), np.array(3.0)):  # all exactly 3.0
        np.testing.assert_array_equal(sol.Z(t), expected)
        np.testing.assert_array_equal(paper_trajectory.q_d(t), paper_trajectory.q_d(3.0))
