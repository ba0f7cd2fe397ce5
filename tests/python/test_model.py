"""Models: the ship against docs/mathematics.md and finite differences, the error split (26)-(31),
Python-subclassed models, and the desired trajectory against independent integrations.

tests/cpp/test_model.cpp and test_simulation.cpp check the ship with its default parameters
(the Jacobian against central differences, the exact error split, the desired trajectory
against an RK4); here: one evaluation through the binding, the other parameters (where
m_u != m_r and d_u != d_r, so a mix-up of parameters shows), the decomposition of the design,
models written in Python, and trajectories from Python."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import hinf_cpp as hc
from _support import (
    PAPER_PARAMETERS,
    PAPER_Q_D0,
    ROUNDOFF,
    SHIP_B,
    SHIP_D,
    central_jacobian,
    expm_many,
    paper_u_d,
    ship_drift,
)

OTHER_PARAMETERS = dict(m_u=0.7, m_v=-1.3, m_r=0.4, d_u=1.1, d_v=2.5, d_r=0.9)


def random_ship_state(rng: np.random.Generator) -> np.ndarray:
    q = rng.uniform(-2.0, 2.0, size=6)
    q[5] *= 4.0  # headings over more than a full turn
    return q


@pytest.fixture(params=[PAPER_PARAMETERS, OTHER_PARAMETERS], ids=["paper", "other"])
def ship_and_parameters(request):
    return hc.ShipModel(hc.ShipParameters(**request.param)), request.param


# ---- the ship ----

def test_ship_drift_is_the_design_equations(ship_and_parameters):
    """One state per parameter set: the parameters and the state reach f (the equations at
    other states: tests/cpp/test_model.cpp)."""
    model, p = ship_and_parameters
    rng = np.random.default_rng(11)
    q = random_ship_state(rng)
    # C++ against NumPy: round-off of the terms, products of two states (|q| <= 8) and a
    # parameter (<= 2.5).
    terms = 2.5 * (1.0 + np.max(np.abs(q))) ** 2
    np.testing.assert_allclose(model.f(7.5, q), ship_drift(q, p), rtol=0, atol=ROUNDOFF * terms)
    assert (model.n(), model.m(), model.nw()) == (6, 2, 6)
    # B = [e1, e3]; D = diag(1, 1, 1, 0, 0, 0) (w4..w6 are measurement-noise channels).
    np.testing.assert_array_equal(model.G(0.0, np.zeros(model.n())), SHIP_B)  # constant 0/1 matrices: exact
    np.testing.assert_array_equal(model.D(3.0, np.zeros(model.n())), SHIP_D)
    assert model.state_names() == ["u", "v", "r", "x", "y", "psi"]
    assert list(model.position_indices()) == [3, 4]
    assert model.heading_index() == 5


def test_ship_parameters_roundtrip():
    p = hc.ShipParameters(**OTHER_PARAMETERS)
    model = hc.ShipModel(p)
    for key, value in OTHER_PARAMETERS.items():
        assert getattr(model.parameters(), key) == value
    with pytest.raises(ValueError, match="m_v"):
        hc.ShipModel(hc.ShipParameters(m_v=float("nan")))


def test_ship_jacobian_matches_central_differences():
    """The other parameters (the default ones: tests/cpp/test_model.cpp)."""
    model = hc.ShipModel(hc.ShipParameters(**OTHER_PARAMETERS))
    rng = np.random.default_rng(20240601)
    for _ in range(40):
        q = random_ship_state(rng)
        t = rng.uniform(0.0, 40.0)
        J = model.dfdq(t, q)
        J_fd = central_jacobian(lambda x: model.f(t, x), q, h=1e-6)
        # Truncation ~h^2 |f'''| ~ 1e-11, round-off ~eps |f| / h ~ 1e-9.
        np.testing.assert_allclose(J, J_fd, rtol=0, atol=1e-8)


# ---- the error split, paper eqs. (26)-(31) ----

def check_error_split(model: hc.Model, rng: np.random.Generator, trials: int = 40):
    """A(q_e) q_e + alpha(q_e) = f(q_d + q_e) - f(q_d) to round-off, A(0) = A_e, alpha(0) = 0.
    Both sides are different computations of the same numbers: they are compared at ROUNDOFF
    times the size of the terms (f at the two states, A q_e and alpha), not of the result."""
    n = model.n()
    for _ in range(trials):
        t = rng.uniform(0.0, 40.0)
        q_d = rng.uniform(-2.0, 2.0, size=n)
        q_e = rng.uniform(-2.0, 2.0, size=n)
        if n == 6:
            q_d[5] *= 4.0
            q_e[5] *= 4.0
        A, alpha = model.error_split(t, q_d, np.zeros(model.m()), q_e)
        f_actual, f_desired = model.f(t, q_d + q_e), model.f(t, q_d)
        f_e = f_actual - f_desired
        scale = (1.0 + np.max(np.abs(A)) * np.max(np.abs(q_e)) * n + np.max(np.abs(alpha))
                 + np.max(np.abs(f_actual)) + np.max(np.abs(f_desired)))
        np.testing.assert_allclose(A @ q_e + alpha, f_e, rtol=0, atol=ROUNDOFF * scale)
        A0, alpha0 = model.error_split(t, q_d, np.zeros(model.m()), np.zeros(n))
        J = model.dfdq(t, q_d)
        np.testing.assert_allclose(A0, J, rtol=0, atol=ROUNDOFF * (1.0 + np.max(np.abs(J))))
        np.testing.assert_allclose(alpha0, 0.0, rtol=0, atol=ROUNDOFF * (1.0 + np.max(np.abs(f_desired))))


def test_ship_error_split_identities():
    """The other parameters (the default ones: tests/cpp/test_model.cpp)."""
    check_error_split(hc.ShipModel(hc.ShipParameters(**OTHER_PARAMETERS)), np.random.default_rng(99))


def design_split(q_d, q_e, p):
    """The decomposition of docs/mathematics.md ("Imperfect measurements") written out in NumPy:
    q1 = [u, v, x, y], q2 = [r, psi]; A12 = d alpha1/d q2 and A21 = d alpha2/d q1 at 0 by
    finite differences; returns (A, alpha) in the state order [u, v, r, x, y, psi]."""
    ud, vd, rd, psid = q_d[0], q_d[1], q_d[2], q_d[5]
    i1, i2 = [0, 1, 3, 4], [2, 5]

    def A11(q2):
        re, pe = q2
        psi = psid + pe
        return np.array([[-p["d_u"], p["m_u"] * (rd + re), 0, 0],
                         [p["m_v"] * (rd + re), -p["d_v"], 0, 0],
                         [math.cos(psi), -math.sin(psi), 0, 0],
                         [math.sin(psi), math.cos(psi), 0, 0]])

    def alpha1(q2):
        re, pe = q2
        psi = psid + pe
        c, s, cd, sd = math.cos(psi), math.sin(psi), math.cos(psid), math.sin(psid)
        return np.array([p["m_u"] * vd * re,
                         p["m_v"] * ud * re,
                         ud * (c - cd) - vd * (s - sd),
                         ud * (s - sd) + vd * (c - cd)])

    def alpha2(q1):
        ue, ve = q1[0], q1[1]
        return np.array([p["m_r"] * (ue * vd + ud * ve + ue * ve), 0.0])

    A22 = np.array([[-p["d_r"], 0.0], [1.0, 0.0]])
    A12 = central_jacobian(alpha1, np.zeros(2), h=1e-5)
    A21 = central_jacobian(alpha2, np.zeros(4), h=1e-5)
    q1, q2 = q_e[i1], q_e[i2]
    A = np.zeros((6, 6))
    A[np.ix_(i1, i1)] = A11(q2)
    A[np.ix_(i1, i2)] = A12
    A[np.ix_(i2, i1)] = A21
    A[np.ix_(i2, i2)] = A22
    alpha = np.zeros(6)
    alpha[i1] = alpha1(q2) - A12 @ q2
    alpha[i2] = alpha2(q1) - A21 @ q1
    return A, alpha


def test_ship_error_split_is_the_design_decomposition(ship_and_parameters):
    model, p = ship_and_parameters
    rng = np.random.default_rng(5)
    for _ in range(20):
        q_d, q_e = random_ship_state(rng), random_ship_state(rng)
        A, alpha = model.error_split(1.0, q_d, np.zeros(model.m()), q_e)
        A_ref, alpha_ref = design_split(q_d, q_e, p)
        # A12, A21 by finite differences (alpha1 is trigonometric in psi_e): ~1e-10.
        np.testing.assert_allclose(A, A_ref, rtol=0, atol=1e-8)
        np.testing.assert_allclose(alpha, alpha_ref, rtol=0, atol=1e-7)


# ---- models written in Python ----

class PyPendulumCart(hc.Model):
    """A nonlinear, time-varying 3-state model implemented in Python (default error split)."""

    def __init__(self):
        hc.Model.__init__(self)

    def n(self):
        return 3

    def m(self):
        return 1

    def nw(self):
        return 2

    def f(self, t, q):
        x, y, z = q
        return np.array([y, -math.sin(x) - 0.1 * y + 0.2 * math.cos(t) * z, -z + x * y])

    def dfdq(self, t, q):
        x, y, z = q
        return np.array([[0.0, 1.0, 0.0],
                         [-math.cos(x), -0.1, 0.2 * math.cos(t)],
                         [y, x, -1.0]])

    def G(self, t, q):
        return np.array([[0.0], [1.0], [0.0]])

    def D(self, t, q):
        return np.array([[1.0, 0.0], [0.0, 0.0], [0.0, 1.0]])


class PyLinear(hc.Model):
    """dq/dt = A q + B u + D w implemented in Python."""

    def __init__(self, A, B, D):
        hc.Model.__init__(self)
        self.A, self.Bm, self.Dm = np.asarray(A), np.asarray(B), np.asarray(D)

    def n(self):
        return self.A.shape[0]

    def m(self):
        return self.Bm.shape[1]

    def nw(self):
        return self.Dm.shape[1]

    def f(self, t, q):
        return self.A @ q

    def dfdq(self, t, q):
        return self.A.copy()

    def G(self, t, q):
        return self.Bm

    def D(self, t, q):
        return self.Dm


def test_python_model_jacobian_and_default_error_split():
    model = PyPendulumCart()
    rng = np.random.default_rng(3)
    for _ in range(10):
        q, t = rng.uniform(-2, 2, size=3), rng.uniform(0, 10)
        # The Python model's own Jacobian is right (so the split identity below means something).
        np.testing.assert_allclose(model.dfdq(t, q), central_jacobian(lambda x: model.f(t, x), q),
                                   rtol=0, atol=1e-8)
    check_error_split(model, np.random.default_rng(4))


@pytest.mark.parametrize("n", [3, 6])
def test_python_linear_model_gives_the_same_grde_as_linear_model(n, method):
    rng = np.random.default_rng(100 + n)
    A = rng.standard_normal((n, n)) - 1.5 * np.eye(n)
    B = rng.standard_normal((n, 2))
    D = rng.standard_normal((n, 2))
    L = rng.standard_normal((n, n))
    Q = L @ L.T + 0.1 * np.eye(n)
    Qf = np.eye(n) * 0.5
    u_d = [hc.Signal(0.2, [hc.Harmonic(0.5, 1.3)]), hc.Signal(-0.1)]
    q_d0 = rng.standard_normal(n)
    options = hc.SolverOptions(method=method)
    rtol, atol = 1e-12, 1e-14  # of the desired trajectory's integration
    solutions = []
    for model in (hc.LinearModel(A, B, D), PyLinear(A, B, D)):
        tr = hc.Trajectory(model, q_d0, u_d, 0.5, 4.0, hc.TrajectoryOptions(rtol=rtol, atol=atol))
        solutions.append((tr, hc.solve_grde(tr, Q, Qf, 10.0, options)))
    times = np.linspace(0.5, 4.0, 301)
    (tr1, s1), (tr2, s2) = solutions
    # f = A q in NumPy (Python model) and in Eigen: round-off apart, which can steer the
    # adaptive steps apart, so the two desired trajectories agree to the integrator's accuracy:
    # 10 x (rtol |q_d| + atol) (measured 4e-14 with |q_d| up to 26).
    q_d = tr1.q_d(times)
    np.testing.assert_allclose(tr2.q_d(times), q_d, rtol=0, atol=10.0 * (rtol * np.max(np.abs(q_d)) + atol))
    # The GRDE of a linear model does not depend on q_d, and its inputs A_e = A, B, D, Q, Qf
    # are the same doubles for both models: the same computation, equal (measured: bit for bit).
    np.testing.assert_allclose(s2.Z(times), s1.Z(times), rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(s2.gain(times), s1.gain(times), rtol=1e-12, atol=1e-14)


# ---- the desired trajectory (paper eq. 8) ----

def test_paper_trajectory_at_arrays_of_times(paper_trajectory):
    """q_d, u_d and A_e at an array of times (q_d against an RK4 and A_e against the Jacobian:
    tests/cpp/test_simulation.cpp): their shapes, u_d the paper's, A_e the model's Jacobian at
    q_d, and a scalar time giving the same interpolant."""
    times = np.linspace(0.0, 40.0, 1601)
    q_d, A_e = paper_trajectory.q_d(times), paper_trajectory.A_e(times)
    assert q_d.shape == (times.size, 6) and A_e.shape == (times.size, 6, 6)
    # 0.3 sin(0.2 t) in C++ and in Python: round-off of 0.3.
    np.testing.assert_allclose(paper_trajectory.u_d(times),
                               np.array([paper_u_d(t) for t in times]), rtol=0, atol=ROUNDOFF * 0.3)
    # The same code on the same q_d(t): equal.
    np.testing.assert_array_equal(A_e[400], paper_trajectory.model().dfdq(times[400], q_d[400]))
    # Scalar-time and array-time evaluation agree (the same interpolant at the same time).
    np.testing.assert_array_equal(paper_trajectory.q_d(13.25), paper_trajectory.q_d(np.array([13.25]))[0])


def test_lti_trajectory_matches_the_matrix_exponential():
    """dq/dt = A q + B u with constant u: q(t) = e^{A(t-t0)} q0 + A^-1 (e^{A(t-t0)} - I) B u."""
    A = np.array([[-0.3, 1.0], [-1.0, -0.2]])
    B = np.array([[0.0], [1.0]])
    q0 = np.array([1.0, -0.5])
    u = 0.7
    t0, tf = 2.0, 12.0
    tr = hc.Trajectory(hc.LinearModel(A, B, np.eye(2)), q0, [u], t0, tf)
    times = np.linspace(t0, tf, 401)
    E = expm_many(A, times - t0)
    expected = E @ q0 + np.linalg.solve(A, ((E - np.eye(2)) @ B[:, 0] * u).T).T
    # The trajectory's integrator at its default rtol 1e-10, atol 1e-12, |q| ~ 1 over 10 time
    # units: 1e-10 absolute (measured ~1e-11).
    np.testing.assert_allclose(tr.q_d(times), expected, rtol=0, atol=1e-10)
    np.testing.assert_array_equal(tr.A_e(5.0), A)  # the model's own matrix, returned as given
    with pytest.raises(ValueError, match="outside"):
        tr.q_d(tf + 1.0)


def test_trajectory_uses_absolute_time(ship):
    """Signals are functions of absolute time: a horizon starting at t0 = 3 follows
    u_d(t) = [1, 0.3 sin(0.2 t)] from t = 3, not from 0."""
    q_d0 = np.array([1.0, 0.1, -0.05, 2.0, -1.0, 0.4])
    u_d = [hc.Signal(1.0), hc.Signal(0.0, [hc.Harmonic(0.3, 0.2)])]
    tr = hc.Trajectory(ship, q_d0, u_d, 3.0, 10.0)
    ref = solve_ivp(lambda t, q: ship_drift(q) + SHIP_B @ paper_u_d(t), (3.0, 10.0), q_d0,
                    method="DOP853", rtol=1e-13, atol=1e-13, dense_output=True)
    times = np.linspace(3.0, 10.0, 141)
    np.testing.assert_allclose(tr.q_d(times), ref.sol(times).T, rtol=0, atol=1e-9)
    assert (tr.t0(), tr.tf(), tr.n(), tr.m()) == (3.0, 10.0, 6, 2)


class Failing(hc.Model):
    """A 2-state model whose f or dfdq raises a Python exception after some time."""

    def __init__(self, where):
        hc.Model.__init__(self)
        self.where = where

    def n(self):
        return 2

    def m(self):
        return 1

    def nw(self):
        return 1

    def f(self, t, q):
        if self.where == "f" and t > 0.5:
            raise ZeroDivisionError("f failed")
        return np.array([q[1], -q[0]])

    def dfdq(self, t, q):
        if self.where == "dfdq" and t < 0.5:
            raise KeyError("dfdq failed")
        return np.array([[0.0, 1.0], [-1.0, 0.0]])

    def G(self, t, q):
        return np.array([[0.0], [1.0]])

    def D(self, t, q):
        return np.array([[1.0], [0.0]])


def test_python_exceptions_propagate(method):
    """An exception raised in a Python callback reaches the caller unchanged (type and text),
    from the trajectory integration and from inside each GRDE integrator."""
    with pytest.raises(ZeroDivisionError, match="f failed"):
        hc.Trajectory(Failing("f"), [1.0, 0.0], [0.0], 0.0, 1.0)
    tr = hc.Trajectory(Failing("dfdq"), [1.0, 0.0], [0.0], 0.0, 1.0)
    with pytest.raises(KeyError, match="dfdq failed"):
        hc.solve_grde(tr, np.eye(2), np.eye(2), 5.0, hc.SolverOptions(method=method))
    with pytest.raises(ZeroDivisionError):
        hc.Trajectory(hc.ShipModel(), PAPER_Q_D0, lambda t: 1 / 0, 0.0, 1.0)
