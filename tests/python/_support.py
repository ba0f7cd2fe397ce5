"""Independent reference implementations used by the tests (NumPy/SciPy only), and shared
comparison helpers.

Nothing here calls hinf_cpp: these are the "truth" the library is checked against.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import linalg

METHODS = ("auto", "bdf", "adams", "erk")

# ---- tolerances for comparisons that involve no integrator ----
#
# Two DIFFERENT evaluations of one exact formula (C++ against NumPy, another summation order,
# another eigenvalue algorithm, with or without fused multiply-add, another BLAS kernel) each
# differ from the exact value by a few units in the last place (ulps) of the size of the terms
# per operation: tens of ulps for the short computations compared in these tests (matrices of
# order <= 8, a few dozen operations). They are compared at ROUNDOFF times the size of the
# terms: a factor of ten or more above that on any IEEE machine, and still about 1e10 below
# the effect of any mistake in a formula.
EPS = float(np.finfo(float).eps)  # 2.2e-16, one ulp of 1.0
ROUNDOFF = 1000.0 * EPS  # 2.2e-13


def summation_rtol(count: int) -> float:
    """Relative tolerance for two evaluations of a sum (or trapezoid rule) of `count`
    nonnegative terms in different orders (C++ loop against NumPy's pairwise np.sum): each is
    within (count - 1) eps of the exact sum (Higham, Accuracy and Stability of Numerical
    Algorithms, 2nd ed., eq. 4.4); 4 count eps covers both and a ratio or square root of such
    sums."""
    return 4.0 * count * EPS

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


# ---- the ship, docs/mathematics.md "The model (paper eqs. 1-6, clean)" ----

def ship_drift(q, p=PAPER_PARAMETERS) -> np.ndarray:
    """f(q) of docs/mathematics.md: dq/dt = f(q) + B u + D w."""
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


def numbers_close(a, b, path="$"):
    """Same structure, same strings, numbers within 1e-9 relative (timing_s excluded). For the
    two programs, which run the same library code on the same file: equal up to the printed
    digits, not a round-off allowance between different computations."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and set(a) == set(b), path
        for key in a:
            if key != "timing_s":
                numbers_close(a[key], b[key], f"{path}.{key}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            numbers_close(x, y, f"{path}[{i}]")
    elif isinstance(a, (int, float)) and not isinstance(a, bool):
        assert isinstance(b, (int, float)) and not isinstance(b, bool), path
        assert b == pytest.approx(a, rel=1e-9, abs=1e-300), path
    else:
        assert a == b, path


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


# ---- imperfect measurements (paper §4) ----

# The ship measures x, y, psi (docs/mathematics.md "Imperfect measurements"): C = [0 I3].
SHIP_C = np.hstack([np.zeros((3, 3)), np.eye(3)])


def ship_jacobian(q, p=PAPER_PARAMETERS) -> np.ndarray:
    """df/dq of ship_drift, written out by hand."""
    u, v, r, _, _, psi = q
    c, s = math.cos(psi), math.sin(psi)
    return np.array([
        [-p["d_u"], p["m_u"] * r, p["m_u"] * v, 0.0, 0.0, 0.0],
        [p["m_v"] * r, -p["d_v"], p["m_v"] * u, 0.0, 0.0, 0.0],
        [p["m_r"] * v, p["m_r"] * u, -p["d_r"], 0.0, 0.0, 0.0],
        [c, -s, 0.0, 0.0, 0.0, -u * s - v * c],
        [s, c, 0.0, 0.0, 0.0, u * c - v * s],
        [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
    ])


def ship_error_split(q_d, q_e, p=PAPER_PARAMETERS):
    """(A(q_e), alpha(q_e)) of docs/mathematics.md (paper eqs. 26-31) with A12 = d alpha1/d q2 and
    A21 = d alpha2/d q1 at 0 differentiated by hand; state order [u, v, r, x, y, psi],
    q1 = [u, v, x, y] (indices 0, 1, 3, 4), q2 = [r, psi] (indices 2, 5)."""
    ud, vd, rd, psid = q_d[0], q_d[1], q_d[2], q_d[5]
    ue, ve, re, pe = q_e[0], q_e[1], q_e[2], q_e[5]
    psi = psid + pe
    c, s, cd, sd = math.cos(psi), math.sin(psi), math.cos(psid), math.sin(psid)
    i1, i2 = [0, 1, 3, 4], [2, 5]
    A11 = np.array([[-p["d_u"], p["m_u"] * (rd + re), 0, 0],
                    [p["m_v"] * (rd + re), -p["d_v"], 0, 0],
                    [c, -s, 0, 0],
                    [s, c, 0, 0]])
    alpha1 = np.array([p["m_u"] * vd * re,
                       p["m_v"] * ud * re,
                       ud * (c - cd) - vd * (s - sd),
                       ud * (s - sd) + vd * (c - cd)])
    A12 = np.array([[p["m_u"] * vd, 0.0],
                    [p["m_v"] * ud, 0.0],
                    [0.0, -ud * sd - vd * cd],
                    [0.0, ud * cd - vd * sd]])
    A21 = np.array([[p["m_r"] * vd, p["m_r"] * ud, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]])
    A22 = np.array([[-p["d_r"], 0.0], [1.0, 0.0]])
    alpha2 = np.array([p["m_r"] * (ue * vd + ud * ve + ue * ve), 0.0])
    q1, q2 = np.asarray(q_e)[i1], np.asarray(q_e)[i2]
    A = np.zeros((6, 6))
    A[np.ix_(i1, i1)] = A11
    A[np.ix_(i1, i2)] = A12
    A[np.ix_(i2, i1)] = A21
    A[np.ix_(i2, i2)] = A22
    alpha = np.zeros(6)
    alpha[i1] = alpha1 - A12 @ q2
    alpha[i2] = alpha2 - A21 @ q1
    return A, alpha


def filter_are(A, C, D, N, Q, gamma):
    """Stabilizing solution X of the filter algebraic Riccati equation
        A X + X A' - X (C' N^-1 C - gamma^-2 Q) X + D D' = 0
    from SciPy, as the dual (control-form) ARE a'X + X a - X b r^-1 b' X + q = 0 with
    a = A', q = D D' and, writing Q = L'L, b = [C' L'], r = diag(N, -gamma^2 I), so that
    b r^-1 b' = C' N^-1 C - gamma^-2 L'L. gamma = inf: the Kalman-Bucy ARE (b = C', r = N)."""
    n = A.shape[0]
    if math.isinf(gamma):
        X = linalg.solve_continuous_are(A.T, C.T, D @ D.T, N)
    else:
        w, V = np.linalg.eigh(0.5 * (Q + Q.T))
        L = (V * np.sqrt(np.clip(w, 0.0, None))).T  # Q = L' L
        p = C.shape[0]
        R = np.zeros((p + n, p + n))
        R[:p, :p] = N
        R[p:, p:] = -gamma**2 * np.eye(n)
        X = linalg.solve_continuous_are(A.T, np.hstack([C.T, L.T]), D @ D.T, R)
    return 0.5 * (X + X.T)


def filter_hamiltonian(A, S, R, Sigma0, t0, times):
    """Exact Sigma(t) of the LTI forward Riccati equation dSigma/dt = A Sigma + Sigma A'
    - Sigma S Sigma + R, Sigma(t0) = Sigma0: with Sigma = Y X^-1,
    d[X; Y]/dt = [[-A', S], [R, A]] [X; Y], X(t0) = I, Y(t0) = Sigma0."""
    n = A.shape[0]
    H = np.block([[-A.T, S], [R, A]])
    XY = expm_many(H, np.asarray(times) - t0) @ np.vstack([np.eye(n), Sigma0])
    X, Y = XY[:, :n], XY[:, n:]
    return np.transpose(np.linalg.solve(np.transpose(X, (0, 2, 1)), np.transpose(Y, (0, 2, 1))), (0, 2, 1))


def spectral_radius_of_products(Sigma, Z) -> np.ndarray:
    """rho(Sigma_k Z_k) for stacks of matrices, from the eigenvalues of the (non-symmetric)
    product."""
    return np.max(np.abs(np.linalg.eigvals(np.asarray(Sigma) @ np.asarray(Z))), axis=-1)


def output_feedback_reference(t0, tf, q0, times, *, f, B, D, C, A_filter, q_d, u_d, Z, w,
                              kappa, gamma, N, Q, Sigma0, sigma, noise, period,
                              rtol=1e-11, atol=1e-12):
    """The closed loop of paper §4 integrated with SciPy (DOP853), one hold interval at a time:
        plant       dq/dt = f(t, q) + B u + D w(t),  u = u_d - kappa B' Z q_hat,
        measurement y = C q + sigma v_k on [t0 + k T, t0 + (k+1) T),
        estimator   dq_hat/dt = f(t, q_d + q_hat) - f(t, q_d) - (kappa B B' - gamma^-2 D D') Z q_hat
                                + [I - gamma^-2 Sigma Z]^-1 Sigma C' N^-1 (y - C q_d - C q_hat),
        filter      dSigma/dt = A Sigma + Sigma A' - Sigma (C'N^-1C - gamma^-2 Q) Sigma + D D',
    with A = A_filter(t, q_d(t), q_hat) and A(q) q + alpha(q) = f_e(q) used in the estimator.
    f, B, D, C are NumPy (f(t, q) the drift, B, D, C constant matrices); q_d, u_d, Z are callables
    of t. Returns (q, q_hat, Sigma) at `times` (which must lie in [t0, tf])."""
    n = len(q0)
    g2 = 0.0 if math.isinf(gamma) else 1.0 / gamma**2
    N_inv = np.linalg.inv(N)
    S_f = C.T @ N_inv @ C - g2 * Q
    DDt = D @ D.T
    BBt = B @ B.T

    def rhs(t, x, v):
        q, q_hat, Sigma = x[:n], x[n:2 * n], x[2 * n:].reshape(n, n)
        qd, Zt = q_d(t), Z(t)
        u = u_d(t) - kappa * B.T @ Zt @ q_hat
        dq = f(t, q) + B @ u + D @ w(t)
        y = C @ q + sigma * v
        gain = np.linalg.solve(np.eye(n) - g2 * Sigma @ Zt, Sigma @ C.T @ N_inv)
        dq_hat = (f(t, qd + q_hat) - f(t, qd) - (kappa * BBt - g2 * DDt) @ Zt @ q_hat
                  + gain @ (y - C @ qd - C @ q_hat))
        A = A_filter(t, qd, q_hat)
        dSigma = A @ Sigma + Sigma @ A.T - Sigma @ S_f @ Sigma + DDt
        return np.concatenate([dq, dq_hat, dSigma.ravel()])

    from scipy.integrate import solve_ivp

    times = np.asarray(times, dtype=float)
    out = np.empty((times.size, 2 * n + n * n))
    x = np.concatenate([np.asarray(q0, dtype=float), np.zeros(n), np.asarray(Sigma0, dtype=float).ravel()])
    k = 0
    while True:
        ta = t0 + k * period
        if ta >= tf - 1e-12 * max(1.0, abs(tf)):
            break
        tb = min(tf, t0 + (k + 1) * period)
        sol = solve_ivp(rhs, (ta, tb), x, method="DOP853", rtol=rtol, atol=atol, dense_output=True,
                        args=(noise[k],))
        assert sol.success, sol.message
        inside = (times >= ta) & (times <= tb)
        if np.any(inside):
            out[inside] = sol.sol(times[inside]).T
        x = sol.y[:, -1]
        k += 1
    return out[:, :n], out[:, n:2 * n], out[:, 2 * n:].reshape(-1, n, n)


# ---- the infinite-horizon full-information H-infinity level (gamma* of T -> infinity) ----

def game_hamiltonian(A, B, D, Q, gamma) -> np.ndarray:
    """H(gamma) = [[A, -S], [-Q, -A']], S = BB' - gamma^-2 DD', of the game ARE
    A'X + XA + Q - X S X = 0 (X = X2 X1^-1 for an n-dimensional invariant subspace [X1; X2])."""
    S = B @ B.T - D @ D.T / gamma**2
    return np.block([[A, -S], [-Q, -A.T]])


def stabilizing_game_solution(A, B, D, Q, gamma, imag_tol=1e-9, cond_max=1e12):
    """(X, why) for the stabilizing solution of the game ARE from the stable invariant subspace
    of H(gamma) (real Schur form ordered with SciPy, sort="lhp"): X = X2 X1^-1 with A - S X
    stable. X is None and why says what is missing when H has eigenvalues on the imaginary axis
    ("imaginary") or X1 is singular ("singular"); why = "indefinite" when X exists but is not
    positive semidefinite (then it is returned too), "" when X >= 0."""
    n = A.shape[0]
    H = game_hamiltonian(A, B, D, Q, gamma)
    lam = np.linalg.eigvals(H)
    if np.min(np.abs(lam.real)) <= imag_tol * max(1.0, np.max(np.abs(lam))):
        return None, "imaginary"
    _, U, sdim = linalg.schur(H, sort="lhp")
    assert sdim == n  # a Hamiltonian matrix without imaginary eigenvalues: n on each side
    X1, X2 = U[:n, :n], U[n:, :n]
    if np.linalg.cond(X1) > cond_max:
        return None, "singular"
    X = np.linalg.solve(X1.T, X2.T).T
    X = 0.5 * (X + X.T)
    if np.linalg.eigvalsh(X)[0] < -1e-10 * max(1.0, np.max(np.abs(X))):
        return X, "indefinite"
    return X, ""


def full_information_hinf_level(A, B, D, Q, gamma_max=1e3, step=1.01, rtol=1e-13) -> float:
    """The infinite-horizon full-information H-infinity level of dq/dt = A q + B u + D w with
    the cost |q|_Q^2 + |u|^2: the infimum of the gammas above which the game ARE has a
    stabilizing solution X >= 0 (no eigenvalue of H(gamma) on the imaginary axis, X1
    invertible, X positive semidefinite). Every gamma above the level must pass, so the search
    walks down from gamma_max by the factor `step` to the first failure (one admissible
    interval from the top, not just a sign change), then bisects."""

    def admissible(gamma):
        X, why = stabilizing_game_solution(A, B, D, Q, gamma)
        return X is not None and why == ""

    assert admissible(gamma_max), "gamma_max is below the level"
    gamma = gamma_max
    while admissible(gamma / step):
        gamma /= step
        if gamma < 1e-9:
            return 0.0
    lo, hi = gamma / step, gamma
    while hi - lo > rtol * hi:
        mid = 0.5 * (lo + hi)
        if admissible(mid):
            hi = mid
        else:
            lo = mid
    return hi


# ---- conjugate points through the inverse W = Z^-1 ----

def inverse_grde(A_e, S, Q, Qf, t0, tf, rtol=1e-10):
    """W(t) = Z(t)^-1 for the GRDE -dZ/dt = A'Z + ZA + Q - Z S Z, Z(tf) = Qf, integrated backward
    by SciPy (DOP853, dense output) as
        dW/dt = A W + W A' + W Q W - S,   W(tf) = Qf^-1,
    A = A_e(t) a callable. W is smooth through a finite escape of Z: Z exists on [t, tf] exactly
    while lambda_min(W) > 0 there (W is bounded before the escape: Z >= the LQR solution > 0),
    so the first conjugate point is the first zero of lambda_min(W) going backward."""
    from scipy.integrate import solve_ivp

    n = Qf.shape[0]

    def rhs(t, y):
        A = A_e(float(t))
        W = y.reshape(n, n)
        return (A @ W + W @ A.T + W @ Q @ W - S).ravel()

    sol = solve_ivp(rhs, (tf, t0), np.linalg.inv(Qf).ravel(), method="DOP853", rtol=rtol,
                    atol=rtol * 1e-2, dense_output=True)
    assert sol.success, sol.message
    return sol


def inverse_grde_conjugate_point(sol, t0, tf, samples=8001):
    """From inverse_grde's solution: (min over [t0, tf] of lambda_min(W), where, the first zero
    of lambda_min(W) going backward from tf or None). The minimum is refined by a bounded scalar
    search around the best sample, the zero by brentq."""
    from scipy.optimize import brentq, minimize_scalar

    def lam(t):
        W = sol.sol(t).reshape(int(round(math.sqrt(sol.y.shape[0]))), -1)
        return np.linalg.eigvalsh(0.5 * (W + W.T))[0]

    times = np.linspace(tf, t0, samples)
    values = np.array([lam(t) for t in times])
    k = int(np.argmin(values))
    a, b = times[min(k + 1, samples - 1)], times[max(k - 1, 0)]
    best = minimize_scalar(lam, bounds=(min(a, b), max(a, b)), method="bounded", options={"xatol": 1e-10})
    lowest, where = (best.fun, best.x) if best.fun < values[k] else (values[k], times[k])
    negative = np.nonzero(values <= 0.0)[0]
    crossing = None
    if negative.size:
        j = negative[0]
        crossing = brentq(lam, times[j], times[j - 1], xtol=1e-13) if j > 0 else tf
    elif lowest <= 0.0:  # dips below zero between samples only
        crossing = brentq(lam, where, times[max(k - 1, 0)], xtol=1e-13)
    return float(lowest), float(where), crossing


# ---- conjugate points of LTI Riccati equations (tests/python/test_conjugate_points.py) ----
#
# dZ/dtau = F'Z + ZF + R - Z S Z, Z(0) = Z0, with Z = Y X^-1 and
#     d/dtau [X; Y] = M [X; Y],  M = [[-F, S], [R, F']],  X(0) = I, Y(0) = Z0
# (differentiate Y = Z X). The GRDE (13) backward in tau = tf - t is F = A, S = BB' -
# gamma^-2 DD', R = Q, Z0 = Qf (M = -H of the Hamiltonian H = [[A, -S], [-Q, -A']]); the
# filter Riccati equation (36) forward in tau = t - t0 is F = A', S = C'N^-1C - gamma^-2 Q,
# R = DD', Z0 = Sigma0. Z escapes to infinity (a conjugate point) exactly where X becomes
# singular.
#
# The scalar watched is the smallest eigenvalue of the symmetric matrix P = X'(Y + c X), with
# c = max(|Z0|, |R| T) > 0 the scale of Z. While Z exists X'Y = X'ZX, so P = X'(Z + c I)X is
# positive definite (Z >= 0 for R, Z0 >= 0: Z is at least the value of the game with w = 0, or
# the Kalman filter's covariance); P is singular where X is and indefinite just after. Unlike
# det X it cannot miss a tangential conjugate point by a sign that does not change, nor be
# confused by repeated eigenvalues. It is divided by (1 + c) |[X; Y]|_F^2 (never zero: [X; Y]
# has full column rank), which makes it independent of the flow's growth.
#
# The [X; Y] flow is restarted every few sample intervals from an orthonormal basis U of the
# same column space ([X; Y] = U R, QR), so that nothing overflows over long horizons with
# unstable modes and the basis stays well scaled (restarting from [I; Z] instead, with |Z| ~ 1e5
# near a near-escape, put spurious negative eigenvalues into P): X = U_1 R is singular where
# U_1 is, and U_1'(U_2 + c U_1) = R^-T P R^-1 has the inertia of P. Samples are 0.2 / |M|_F
# apart (the flow does not change on a shorter scale); segments span 20 sample
# intervals and overlap by 2, so every time lies strictly inside some segment. Every local
# minimum of the scalar among the samples (and the two ends of [0, T]) is refined on the sample
# intervals around it by three nested grids, each 32 times finer (down to 1/32768 of a sample
# interval, where the scalar's remaining dip is below 1e-9 of its variation over a sample
# interval): a short dip below zero between samples (just below a tangential conjugate point)
# is found there. A sign change is then located by brentq on the exact flow. Every matrix
# exponential needed is exp(M s) with |M s|_F <= 0.2, summed as its Taylor series to degree 12
# (remainder <= 0.2^13 / 13! e^0.2 < 1e-19); scipy.linalg.expm would give the same to round-off
# but costs 40 us .. 5 ms per call for these small matrices (BLAS threads on a loaded machine).

CONJUGATE_SAMPLES_PER_SEGMENT = 20
CONJUGATE_OVERLAP = 2
CONJUGATE_REFINEMENT = 32


def riccati_flow_matrix(F, S, R) -> np.ndarray:
    """M = [[-F, S], [R, F']] of d/dtau [X; Y] = M [X; Y] (Z = Y X^-1 solves
    dZ/dtau = F'Z + ZF + R - Z S Z)."""
    return np.block([[-F, S], [R, F.T]])


def _normalized_pmin(XY: np.ndarray, n: int, c: float) -> np.ndarray:
    """lambda_min(P) / ((1 + c) |[X; Y]|_F^2), P = X'(Y + c X) (its symmetric part), for a stack
    of [X; Y]."""
    X, Y = XY[..., :n, :], XY[..., n:, :]
    P = np.swapaxes(X, -1, -2) @ (Y + c * X)
    lowest = np.linalg.eigvalsh(0.5 * (P + np.swapaxes(P, -1, -2)))[..., 0]
    return lowest / ((1.0 + c) * np.sum(XY**2, axis=(-2, -1)))


def _expm_small(X: np.ndarray) -> np.ndarray:
    """exp(X) for |X|_F <= 0.2: the Taylor series to degree 12 (Horner)."""
    assert np.linalg.norm(X) <= 0.2 * (1.0 + 1e-12), "_expm_small needs |X|_F <= 0.2"
    eye = np.eye(X.shape[0])
    E = eye
    for k in range(12, 0, -1):
        E = eye + (X @ E) / k
    return E


def _powers(step: np.ndarray, count: int) -> np.ndarray:
    """[I, step, step^2, ..., step^count]."""
    out = [np.eye(step.shape[0])]
    for _ in range(count):
        out.append(step @ out[-1])
    return np.array(out)


def first_conjugate_point(F, S, R, Z0, T):
    """First tau in [0, T] where X of d/dtau [X; Y] = M [X; Y], X(0) = I, Y(0) = Z0, is singular
    (Z = Y X^-1 escapes), or None. See the comment above for the method."""
    from scipy.optimize import brentq

    F, S, R, Z0 = (np.atleast_2d(np.asarray(x, dtype=float)) for x in (F, S, R, Z0))
    n = F.shape[0]
    M = riccati_flow_matrix(F, S, R)
    c = max(np.linalg.eigvalsh(Z0)[-1], np.linalg.eigvalsh(R)[-1] * T, 1e-300)
    per, overlap, fine = CONJUGATE_SAMPLES_PER_SEGMENT, CONJUGATE_OVERLAP, CONJUGATE_REFINEMENT
    intervals = max(per, int(math.ceil(T * np.linalg.norm(M) / 0.2)))
    dt = T / intervals
    coarse = _powers(_expm_small(M * dt), per)
    # Nested grids: spacing dt / fine^level, 2 fine + 1 points (two intervals of the level above).
    levels = [(dt / fine**level, _powers(_expm_small(M * (dt / fine**level)), 2 * fine)) for level in (1, 2, 3)]

    def value(s, base):  # 0 <= s <= dt
        return float(_normalized_pmin(_expm_small(M * s) @ base, n, c))

    def crossing(a, b, base, t_base):
        """The first zero of the scalar in [a, b] (from base at t_base; > 0 at a and <= 0 at b as
        sampled; should the exact flow disagree at round-off level, that end)."""
        fa, fb = value(a, base), value(b, base)
        if fa <= 0.0 or fb > 0.0:
            return t_base + (a if fa <= 0.0 else b)
        return t_base + brentq(lambda s: value(s, base), a, b, xtol=1e-14 * max(T, 1.0), rtol=4 * EPS)

    def refine(base, t_base, width):
        """Nested grids over [t_base, t_base + width dt] (width = 1 or 2 sample intervals): the
        first zero of the scalar there, or None."""
        span = width
        for h, table in levels:
            points = table[: span * fine + 1] @ base
            values = _normalized_pmin(points, n, c)
            negative = np.flatnonzero(values <= 0.0)
            if negative.size:
                k = int(negative[0])
                return t_base if k == 0 else crossing(0.0, h, points[k - 1], t_base + (k - 1) * h)
            k = int(np.argmin(values))
            low, high = max(k - 1, 0), min(k + 1, span * fine)
            base, t_base, span = points[low], t_base + low * h, high - low
        return None

    first = 0
    U = np.linalg.qr(np.vstack([np.eye(n), 0.5 * (Z0 + Z0.T)]))[0]
    while True:
        count = min(per, intervals - first)
        start = first * dt
        XY = coarse[: count + 1] @ U
        values = _normalized_pmin(XY, n, c)
        negative = np.flatnonzero(values <= 0.0)
        if negative.size:
            j = int(negative[0])
            return start if j == 0 else crossing(0.0, dt, XY[j - 1], start + (j - 1) * dt)
        last = first + count == intervals
        for j in range(count + 1):
            inner = 0 < j < count
            edge = (j == 0 and first == 0) or (j == count and last)
            if not (inner or edge):
                continue
            left = values[j - 1] if j > 0 else np.inf
            right = values[j + 1] if j < count else np.inf
            if values[j] <= left and values[j] <= right:
                low, high = max(j - 1, 0), min(j + 1, count)
                tau = refine(XY[low], start + low * dt, high - low)
                if tau is not None:
                    return tau
        if last:
            return None
        k = count - overlap  # restart inside this segment, so the segments overlap
        U = np.linalg.qr(XY[k])[0]
        first += k


def grde_conjugate_tau(A, B, D, Q, Qf, gamma, T):
    """First conjugate point of the LTI GRDE (13) in backward time tau = tf - t, or None."""
    S = B @ B.T - (0.0 if math.isinf(gamma) else D @ D.T / gamma**2)
    return first_conjugate_point(A, S, Q, Qf, T)


def filter_conjugate_tau(A, C, D, N, Q, Sigma0, gamma, T):
    """First escape of the LTI filter Riccati equation (36) in forward time tau = t - t0, or None."""
    S = C.T @ np.linalg.solve(N, C) - (0.0 if math.isinf(gamma) else Q / gamma**2)
    return first_conjugate_point(A.T, S, D @ D.T, Sigma0, T)


def threshold_by_bisection(escapes, lo, hi, rtol=1e-9):
    """The smallest gamma without escape, for a predicate escapes(gamma) that is True below it
    and False above it: bisection of the bracket [lo, hi] (escapes(lo), not escapes(hi))."""
    assert escapes(lo) and not escapes(hi), (lo, hi)
    while hi - lo > rtol * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if escapes(mid) else (lo, mid)
    return hi


def bracket_threshold(escapes, guess):
    """(lo, hi) around the threshold of escapes(gamma), starting at guess > 0 and moving by
    factors of 2."""
    lo = hi = guess
    if escapes(guess):
        while escapes(hi):
            lo, hi = hi, 2.0 * hi
            assert hi < 1e12, "no gamma without escape below 1e12"
    else:
        while not escapes(lo):
            lo, hi = 0.5 * lo, lo
            assert lo > 1e-12, "an escape-free system: threshold 0"
    return lo, hi
