"""Independent reference implementations used by the tests (NumPy/SciPy only).

Nothing here calls hinf_cpp: these are the "truth" the library is checked against.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import linalg

METHODS = ("bdf", "adams", "erk")

PAPER_Q_D0 = np.array([1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
PAPER_T0, PAPER_TF = 0.0, 40.0
PAPER_GAMMA = 5.0
# The actual start of Figure 1 (scenarios.md): 1 m behind, 1 m aside, 45 degree heading error.
PAPER_Q0 = PAPER_Q_D0 + np.array([0.0, 0.0, 0.0, -1.0, -1.0, math.pi / 4])

PAPER_PARAMETERS = dict(m_u=0.5, m_v=-2.0, m_r=0.5, d_u=1.0, d_v=2.0, d_r=1.0)


def paper_u_d(t: float) -> np.ndarray:
    """u_d(t) = [1, 0.3 sin(0.2 t)] of the paper's run."""
    return np.array([1.0, 0.3 * math.sin(0.2 * t)])


def paper_disturbance(t: float) -> np.ndarray:
    """w(t) of the paper: 0.1 cos(2 pi 0.2 t) on w1..w3, zero on w4..w6."""
    c = 0.1 * math.cos(2.0 * math.pi * 0.2 * t)
    return np.array([c, c, c, 0.0, 0.0, 0.0])


# ---- the ship, DESIGN.md "The model (paper eqs. 1-6, clean)" ----

def ship_drift(q, p=PAPER_PARAMETERS) -> np.ndarray:
    """f(q) of DESIGN.md: dq/dt = f(q) + B u + D w."""
    u, v, r, _, _, psi = q
    return np.array([
        p["m_u"] * v * r - p["d_u"] * u,
        p["m_v"] * u * r - p["d_v"] * v,
        p["m_r"] * u * v - p["d_r"] * r,
        u * math.cos(psi) - v * math.sin(psi),
        u * math.sin(psi) + v * math.cos(psi),
        r,
    ])


SHIP_B = np.array([[1.0, 0.0], [0.0, 0.0], [0.0, 1.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0]])
SHIP_D = np.diag([1.0, 1.0, 1.0, 0.0, 0.0, 0.0])


def central_jacobian(fun, x, h=1e-6) -> np.ndarray:
    """Central finite differences of fun at x, one column per component."""
    x = np.asarray(x, dtype=float)
    columns = []
    for j in range(x.size):
        step = h * max(1.0, abs(x[j]))
        xp, xm = x.copy(), x.copy()
        xp[j] += step
        xm[j] -= step
        columns.append((np.asarray(fun(xp)) - np.asarray(fun(xm))) / (2.0 * step))
    return np.column_stack(columns)


# ---- the scalar GRDE ----

def scalar_grde_closed_form(a, s, q, qf, tau):
    """Solution of dz/dtau = 2 a z + q - s z^2, z(0) = qf (tau = tf - t, backward time).

    With z = y / x and d/dtau [x; y] = M [x; y], M = [[-a, s], [q, a]], M^2 = (a^2 + s q) I,
    so exp(M tau) = c(tau) I + sg(tau) M with
        c = cosh(beta tau), sg = sinh(beta tau) / beta      (beta^2 = a^2 + s q > 0)
        c = 1,              sg = tau                       (beta^2 = 0)
        c = cos(w tau),     sg = sin(w tau) / w            (w^2 = -(a^2 + s q) > 0),
    and z = (c qf + sg (q + a qf)) / (c + sg (s qf - a)). For beta^2 > 0 numerator and
    denominator are divided by c (tanh form) to avoid overflow.
    """
    tau = np.asarray(tau, dtype=float)
    beta2 = a * a + s * q
    if beta2 > 0.0:
        beta = math.sqrt(beta2)
        th = np.tanh(beta * tau) / beta
        return (qf + th * (q + a * qf)) / (1.0 + th * (s * qf - a))
    if beta2 == 0.0:
        c, sg = np.ones_like(tau), tau
    else:
        w = math.sqrt(-beta2)
        c, sg = np.cos(w * tau), np.sin(w * tau) / w
    return (c * qf + sg * (q + a * qf)) / (c + sg * (s * qf - a))


def scalar_escape_tau(a, s, q, qf) -> float:
    """Backward time tau_c > 0 at which x(tau) = c + sg (s qf - a) first vanishes
    (the finite escape of z), or inf when it never does."""
    beta2 = a * a + s * q
    k = a - s * qf  # x = c - sg k
    if beta2 < 0.0:
        w = math.sqrt(-beta2)
        # cos(w tau) = (k / w) sin(w tau): first root of cot(w tau) = k / w in (0, pi / w).
        return math.atan2(w, k) / w
    if beta2 == 0.0:
        return 1.0 / k if k > 0.0 else math.inf
    beta = math.sqrt(beta2)
    # cosh = (k / beta) sinh  <=>  tanh(beta tau) = beta / k, solvable when k > beta.
    return math.atanh(beta / k) / beta if k > beta else math.inf


# ---- LTI systems ----

def random_stable_lti(rng: np.random.Generator, n: int, m: int, nw: int, margin: float = 0.5):
    """A random A with spectral abscissa -margin, random B (n x m), D (n x nw), Q > 0."""
    M = rng.standard_normal((n, n))
    A = M - (np.max(np.linalg.eigvals(M).real) + margin) * np.eye(n)
    B = rng.standard_normal((n, m))
    D = rng.standard_normal((n, nw))
    L = rng.standard_normal((n, n))
    Q = L @ L.T / n + 0.1 * np.eye(n)
    return A, B, D, 0.5 * (Q + Q.T)


def hinf_norm_upper_bound(A, C, D, factor: float = 3.0) -> float:
    """factor times the peak gain of C (jw I - A)^-1 D over a frequency sweep, checked to be
    above the true H-infinity norm: the Hamiltonian [[A, DD'/g^2], [-C'C, -A']] has no
    eigenvalue on the imaginary axis iff ||C (sI - A)^-1 D||_inf < g (A stable)."""
    n = A.shape[0]
    peak = 0.0
    for w in np.concatenate([[0.0], np.logspace(-3, 3, 3000)]):
        G = C @ np.linalg.solve(1j * w * np.eye(n) - A, D)
        peak = max(peak, np.linalg.svd(G, compute_uv=False)[0])
    gamma = factor * peak
    H = np.block([[A, D @ D.T / gamma**2], [-C.T @ C, -A.T]])
    eig = np.linalg.eigvals(H)
    assert np.min(np.abs(eig.real)) > 1e-6, "sweep missed the H-infinity peak"
    return gamma


def game_are(A, B, D, Q, gamma):
    """Stabilizing solution of A'X + XA + Q - X (BB' - gamma^-2 DD') X = 0 from SciPy,
    as the ARE with G = [B D], R = diag(I, -gamma^2 I); gamma = inf gives the LQR ARE."""
    m, nw = B.shape[1], D.shape[1]
    if math.isinf(gamma):
        X = linalg.solve_continuous_are(A, B, Q, np.eye(m))
    else:
        R = np.diag([1.0] * m + [-gamma**2] * nw)
        X = linalg.solve_continuous_are(A, np.hstack([B, D]), Q, R)
    return 0.5 * (X + X.T)


def expm_many(M, taus):
    """expm(M tau) for many tau, from one eigendecomposition of M (NumPy), cross-checked
    against scipy.linalg.expm at the largest |tau|. (SciPy's own expm is ~2 ms per call on
    these machines because of BLAS threading, too slow to call hundreds of times.)"""
    taus = np.asarray(taus, dtype=float)
    lam, V = np.linalg.eig(M)
    Vinv = np.linalg.inv(V)
    E = np.einsum("ij,kj,jl->kil", V, np.exp(np.multiply.outer(taus, lam)), Vinv)
    assert np.max(np.abs(E.imag)) < 1e-10 * max(1.0, np.max(np.abs(E.real)))
    E = E.real
    k = int(np.argmax(np.abs(taus)))
    check = linalg.expm(M * taus[k])
    assert np.max(np.abs(E[k] - check)) < 1e-11 * max(1.0, np.max(np.abs(check)))
    return E


def hamiltonian_grde(A, S, Q, Qf, tf, times):
    """Exact Z(t) of the LTI GRDE: [X; Y](t) = expm(H (t - tf)) [I; Qf],
    H = [[A, -S], [-Q, -A']], Z = Y X^-1."""
    n = A.shape[0]
    H = np.block([[A, -S], [-Q, -A.T]])
    XY = expm_many(H, np.asarray(times) - tf) @ np.vstack([np.eye(n), Qf])
    X, Y = XY[:, :n], XY[:, n:]
    return np.transpose(np.linalg.solve(np.transpose(X, (0, 2, 1)), np.transpose(Y, (0, 2, 1))), (0, 2, 1))


def max_rel(a, b) -> float:
    """max |a - b| / max |b| (one relative error over all entries)."""
    a, b = np.asarray(a), np.asarray(b)
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))
