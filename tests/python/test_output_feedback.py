"""Imperfect measurements (paper §4): the error decomposition (26)-(31), the H-infinity filter
Riccati equation (36), the estimator (35) and the output-feedback law (34) in closed loop,
the seeded measurement noise, the coupling condition rho(Sigma Z) < gamma^2, and the
[measurement] section of scenario files.

tests/cpp/test_output_feedback.cpp and test_noise.cpp check the numerics: the filter (36)
against closed forms, its Hamiltonian solution, its algebraic Riccati equation and its
residual, for every method; the closed loop against an RK4 of the paper's equations (the ship
with both linearizations of the filter, a linear plant, a stiff one); no noise, no error; the
noise held over each period; the coupling condition on a scalar plant and on the ship; the
paper's Figure 2; the noise's statistics. Here: what the binding takes and returns (one check
against independent truth each: closed forms, a matrix exponential of the Hamiltonian, a SciPy
integration of the closed loop written from the paper's equations, tests/python/_support.py),
the decomposition (26)-(31) written out by hand, the [measurement] section and its errors, the
command lines, and what the C++ tests do not check."""

from __future__ import annotations

import json
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest
from scipy.optimize import brentq

import hinf_cpp as hc
from _support import (
    PAPER_Q0,
    PAPER_Q_D0,
    ROUNDOFF,
    SHIP_B,
    SHIP_C,
    SHIP_D,
    filter_hamiltonian,
    max_rel,
    output_feedback_reference,
    paper_disturbance,
    scalar_escape_tau,
    scalar_grde_closed_form,
    ship_drift,
    ship_error_split,
    ship_jacobian,
    spectral_radius_of_products as spectral_radius,
)

EYE6 = np.eye(6)
PAPER_N = 0.25 * np.eye(3)  # N = sigma^2 I3, sigma = 0.5
PAPER_SEED = 20000601
FIG2_TEXT = pathlib.Path(hc.scenario_path("paper_fig2")).read_text()
BIN = pathlib.Path(sys.executable).parent
HINF_SIM, HINF_CPP = BIN / "hinf-sim", BIN / "hinf-cpp"
HAVE_CLI = HINF_SIM.exists() and HINF_CPP.exists()
TIGHT = dict(rtol=1e-12, atol=1e-14)
# Output times t0 + k dt (library) against NumPy's linspace grid: round-off of times <= 40 s.
TIME_ROUNDOFF = ROUNDOFF * 40.0


def paper_disturbance_signals():
    """0.1 cos(2 pi 0.2 t) on w1..w3 (paper §5); w4..w6 (the noise channels) zero."""
    w = hc.Signal(0.0, [hc.Harmonic(0.1, 2.0 * math.pi * 0.2, 0.0, True)])
    return [w, w, w, 0.0, 0.0, 0.0]


def paper_problem(design, noise, **changes) -> hc.OutputFeedbackProblem:
    """The Figure 2 set-up: sigma = 0.5, T = 0.01, N = 0.25 I, Sigma0 = (2I - I)^-1 = I, Q = I."""
    args = dict(design=design, sigma=0.5, sample_period=0.01, noise=noise, N=PAPER_N, Sigma0=EYE6, Q=EYE6)
    args.update(changes)
    return hc.OutputFeedbackProblem(**args)


DESIRED_A_FLAG = hc.OutputFeedbackOptions(filter_A="desired", on_coupling_violation="flag")


def series(run: hc.SimulationResult, name: str):
    """A time series of a run: a field of the SimulationResult or of its estimator's."""
    return getattr(run.estimator, name) if name in hc.EstimatorSeries.__match_args__ else getattr(run, name)


def paper_noise(seed=PAPER_SEED, t0=0.0, tf=40.0, period=0.01):
    return hc._core.standard_normal_samples(seed, hc._core.noise_sample_count(t0, tf, period), 3)


def mutate(text: str, old: str, new: str) -> str:
    """text with `old` replaced by `new`; `old` must occur exactly once (so no case silently
    tests nothing, or something else)."""
    assert text.count(old) == 1, f"test bug: {old!r} occurs {text.count(old)} times in the scenario text"
    return text.replace(old, new)


def cli(*args) -> subprocess.CompletedProcess:
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=120)


# ======================================================================================
# 1. The decomposition (26)-(31): A(q) q + alpha(q) = f_e(q), A(0) = A_e(t)
# ======================================================================================

def test_error_split_along_the_paper_trajectory(paper_trajectory):
    """At 401 times along the paper's desired path (q_d(t) from the library's trajectory,
    A_e(t) its Jacobian there) and random errors: the identities to round-off, and (A, alpha)
    equal to the docs/mathematics.md decomposition written out by hand (no finite differences). C++ and
    NumPy evaluate the same formulas: compared at ROUNDOFF times the size of the terms."""
    ship = paper_trajectory.model()
    rng = np.random.default_rng(26)
    times = np.linspace(0.0, 40.0, 401)
    q_ds, A_es = paper_trajectory.q_d(times), paper_trajectory.A_e(times)
    for t, q_d, A_e in zip(times, q_ds, A_es):
        q_e = rng.uniform(-1.5, 1.5, size=6)
        q_e[5] = rng.uniform(-2 * math.pi, 2 * math.pi)
        A, alpha = ship.error_split(t, q_d, np.zeros(ship.m()), q_e)
        f_actual, f_desired = ship_drift(q_d + q_e), ship_drift(q_d)
        f_e = f_actual - f_desired
        scale = (1.0 + 6 * np.max(np.abs(A)) * np.max(np.abs(q_e)) + np.max(np.abs(alpha))
                 + np.max(np.abs(f_actual)) + np.max(np.abs(f_desired)))
        np.testing.assert_allclose(A @ q_e + alpha, f_e, rtol=0, atol=ROUNDOFF * scale)
        A_ref, alpha_ref = ship_error_split(q_d, q_e)
        A_scale = 1.0 + np.max(np.abs(A_ref))
        np.testing.assert_allclose(A, A_ref, rtol=0, atol=ROUNDOFF * A_scale)
        np.testing.assert_allclose(alpha, alpha_ref, rtol=0, atol=ROUNDOFF * scale)
        A0, alpha0 = ship.error_split(t, q_d, np.zeros(ship.m()), np.zeros(6))
        np.testing.assert_allclose(A0, A_e, rtol=0, atol=ROUNDOFF * A_scale)
        np.testing.assert_allclose(A0, ship_jacobian(q_d), rtol=0, atol=ROUNDOFF * A_scale)
        # alpha(0) is built of products with 0 and differences x - x: exactly zero.
        np.testing.assert_array_equal(alpha0, 0.0)


def test_error_split_structure_and_order(paper_trajectory):
    """Paper §4: each subsystem is affine when the other's state is known. A(q) depends on
    q2 = (r, psi) only; alpha's q1-rows depend on q2 only, its q2-rows on q1 only. And the
    remainder alpha is second order: alpha(eps q)/eps^2 converges as eps -> 0."""
    ship = paper_trajectory.model()
    i1, i2 = [0, 1, 3, 4], [2, 5]
    rng = np.random.default_rng(31)
    for t in (0.0, 7.3, 21.9, 40.0):
        q_d = paper_trajectory.q_d(t)
        q_e = rng.uniform(-1.0, 1.0, size=6)
        A, alpha = ship.error_split(t, q_d, np.zeros(ship.m()), q_e)
        # The same code on the inputs it depends on: exactly equal.
        other = q_e.copy()
        other[i1] = rng.uniform(-1.0, 1.0, size=4)
        A1, alpha1 = ship.error_split(t, q_d, np.zeros(ship.m()), other)
        np.testing.assert_array_equal(A1, A)
        np.testing.assert_array_equal(alpha1[i1], alpha[i1])
        other = q_e.copy()
        other[i2] = rng.uniform(-1.0, 1.0, size=2)
        _, alpha2 = ship.error_split(t, q_d, np.zeros(ship.m()), other)
        np.testing.assert_array_equal(alpha2[i2], alpha[i2])
        ratios = [ship.error_split(t, q_d, np.zeros(ship.m()), eps * q_e)[1] / eps**2 for eps in (1e-2, 1e-3, 1e-4)]
        assert np.max(np.abs(ratios[0])) > 1e-3  # nonzero second-order term
        np.testing.assert_allclose(ratios[2], ratios[1], rtol=0, atol=2e-3 * np.max(np.abs(ratios[0])))


def test_measurement_model_of_the_ship_and_of_linear_models():
    ship = hc.ShipModel()
    np.testing.assert_array_equal(ship.C(3.0), SHIP_C)
    assert list(ship.noise_channels()) == [3, 4, 5]
    np.testing.assert_array_equal(ship.D(0.0, np.zeros(ship.n()))[:, 3:], 0.0)  # noise enters through E, not D

    rng = np.random.default_rng(4)
    A, B, D = rng.standard_normal((4, 4)), rng.standard_normal((4, 2)), rng.standard_normal((4, 3))
    C = rng.standard_normal((2, 4))
    model = hc.LinearModel(A, B, D, C)
    assert (model.n(), model.m(), model.nw()) == (4, 2, 5)
    np.testing.assert_array_equal(model.D(1.0, np.zeros(model.n())), np.hstack([D, np.zeros((4, 2))]))
    np.testing.assert_array_equal(model.C(1.0), C)
    assert list(model.noise_channels()) == [3, 4]
    for _ in range(5):
        q_d, q_e = rng.standard_normal(4), rng.standard_normal(4)
        A_split, alpha = model.error_split(0.5, q_d, np.zeros(model.m()), q_e)
        np.testing.assert_array_equal(A_split, A)  # the model's own matrix
        # alpha = A (q_d + q_e) - A q_d - A q_e: zero up to the round-off of these products.
        terms = np.max(np.abs(A) @ (np.abs(q_d) + np.abs(q_e)))
        np.testing.assert_allclose(alpha, 0.0, rtol=0, atol=ROUNDOFF * terms)
    plain = hc.LinearModel(A, B, D)
    assert plain.nw() == 3
    with pytest.raises(ValueError, match="C"):
        plain.C(0.0)


# ======================================================================================
# 2. The filter Riccati equation (36): exact solution, Kalman-Bucy, residual, escape
# ======================================================================================

def lti_measured(A, B, D, C, t0=0.0, tf=1.0) -> hc.Trajectory:
    """An LTI trajectory with measurements (q_d = 0, u_d = 0, so A_e(t) = A)."""
    model = hc.LinearModel(A, B, D, C)
    return hc.Trajectory(model, np.zeros(A.shape[0]), [0.0] * B.shape[1], t0, tf)


@pytest.mark.parametrize("gamma", [3.0, math.inf], ids=["hinf", "kalman-bucy"])
def test_filter_matches_the_hamiltonian_solution(gamma):
    """Short horizon, random A, non-diagonal N and Sigma0, t0 != 0: Sigma = Y X^-1 with
    [X; Y](t) = expm([[-A', S], [DD', A]] (t - t0)) [I; Sigma0], exactly, at the default
    options (every method, rtol 1e-12, dSigma/dt, the ARE limit: tests/cpp/test_output_feedback.cpp).
    Measured at the default tolerances: bdf 1.3e-7, adams 1.1e-8, erk 2.6e-8."""
    rng = np.random.default_rng(36)
    n, p = 4, 2
    A = rng.standard_normal((n, n))
    B = rng.standard_normal((n, 1))
    D = rng.standard_normal((n, 3))
    C = rng.standard_normal((p, n))
    N = np.array([[0.5, 0.1], [0.1, 0.3]])
    L = rng.standard_normal((n, n))
    Q = L @ L.T + 0.1 * np.eye(n)
    Sigma0 = 0.4 * np.eye(n) + 0.05 * np.ones((n, n))
    t0, tf = 1.5, 3.5
    S = C.T @ np.linalg.solve(N, C) - (0.0 if math.isinf(gamma) else Q / gamma**2)
    times = np.linspace(t0, tf, 241)
    exact = filter_hamiltonian(A, S, D @ D.T, Sigma0, t0, times)
    assert np.all(np.linalg.eigvalsh(exact) > 0)
    tr = lti_measured(A, B, D, C, t0, tf)
    sol = hc.solve_filter_riccati(tr, N, Q, gamma, Sigma0)
    assert sol.gamma() == gamma and sol.t0() == t0 and sol.tf() == tf and sol.n() == n
    Sigma = sol.Sigma(times)
    assert Sigma.shape == (times.size, n, n)
    assert max_rel(Sigma, exact) < 5e-7


def test_filter_residual_along_the_paper_trajectory(paper_trajectory):
    """Time-varying A_e(t): dSigma/dt - (A_e Sigma + Sigma A_e' - Sigma (C'N^-1C - Q/gamma^2)
    Sigma + DD') = 0 at a grid and at the step midpoints, relative to the size of the terms, at
    the default options (every method: tests/cpp/test_output_feedback.cpp): Sigma, dSigma_dt
    and A_e at arrays of times, eigenvalue_range of a list of times. Measured: bdf 1.3e-6,
    adams 5.5e-7, erk 6.3e-8."""
    sol = hc.solve_filter_riccati(paper_trajectory, PAPER_N, EYE6, 5.0, EYE6)
    steps = np.asarray(sol.dense().breakpoints())
    assert steps[0] == pytest.approx(0.0) and steps[-1] == pytest.approx(40.0)
    times = np.concatenate([np.linspace(0.0, 40.0, 801), 0.5 * (steps[1:] + steps[:-1])])
    Sigma, dSigma, A = sol.Sigma(times), sol.dSigma_dt(times), paper_trajectory.A_e(times)
    # Symmetric by construction: the library integrates one triangle and mirrors it.
    np.testing.assert_array_equal(Sigma, np.transpose(Sigma, (0, 2, 1)))
    assert np.min(np.linalg.eigvalsh(Sigma)) > 0
    S = SHIP_C.T @ np.linalg.solve(PAPER_N, SHIP_C) - EYE6 / 25.0
    ASigma = A @ Sigma
    SSS = Sigma @ S @ Sigma
    residual = dSigma - (ASigma + np.transpose(ASigma, (0, 2, 1)) - SSS + SHIP_D @ SHIP_D.T)
    scale = 2 * np.max(np.abs(ASigma), axis=(1, 2)) + np.max(np.abs(SSS), axis=(1, 2)) + 1.0
    relative = np.max(np.abs(residual), axis=(1, 2)) / scale
    assert relative.max() < 1e-5
    # Sigma(t0) = I from the first step's polynomial: round-off.
    np.testing.assert_allclose(sol.Sigma(0.0), EYE6, rtol=0, atol=ROUNDOFF)
    # The library's extreme eigenvalues against LAPACK's: round-off relative to |Sigma|.
    lo, hi = sol.eigenvalue_range(list(times[:801]))
    eig = np.linalg.eigvalsh(Sigma[:801])
    slack = ROUNDOFF * np.max(np.abs(eig))
    assert lo == pytest.approx(eig.min(), abs=slack) and hi == pytest.approx(eig.max(), abs=slack)


def test_scalar_filter_escape_time():
    """Scalar filter with s_f = c^2/N - q/gamma^2 < 0: Sigma escapes forward at the closed-form
    time tau_c of dSigma/dtau = 2 a Sigma + d^2 - s_f Sigma^2; the solve raises there, naming the
    filter (every method, and Sigma before the escape: tests/cpp/test_output_feedback.cpp)."""
    a, b, d, c, nn, q, gamma, sigma0 = 0.2, 1.0, 1.0, 0.5, 1.0, 1.0, 0.4, 1.0
    s_f = c * c / nn - q / gamma**2
    tau_c = scalar_escape_tau(a, s_f, d * d, sigma0)
    t0, tf = 2.0, 12.0
    assert 0.0 < tau_c < tf - t0
    tr = lti_measured(np.array([[a]]), np.array([[b]]), np.array([[d]]), np.array([[c]]), t0, tf)
    with pytest.raises(hc.ConjugatePointError) as info:
        hc.solve_filter_riccati(tr, np.array([[nn]]), np.array([[q]]), gamma, np.array([[sigma0]]))
    # The escape time of a scalar Riccati equation at the default tolerances: to ~1e-7 of the
    # horizon.
    assert abs(info.value.t_escape - (t0 + tau_c)) < 1e-5 * (tf - t0)
    assert info.value.gamma == gamma and "filter" in str(info.value)


# ======================================================================================
# 3. The closed loop against independent references
# ======================================================================================

def test_estimate_and_desired_filters_coincide_when_the_estimate_is_zero(paper_trajectory, paper_solutions):
    """A(q_hat = 0) = A_e(t): with no noise, no disturbance and q0 = q_d0 the estimate stays 0
    (up to the plant's integration error, |q_hat| ~ 3e-12), so filter_A = "estimate" and
    "desired" integrate the same Sigma. The two code paths (A(q_hat) and A_e) may steer the
    adaptive steps apart, so the runs agree to the integrator's accuracy: they run at rtol 1e-11
    (measured 1e-14)."""
    grde = paper_solutions["erk"]
    rtol = 1e-11
    solver = hc.SolverOptions(method="erk", rtol=rtol, atol=rtol * 1e-2)
    runs = [hc.simulate_output_feedback(paper_problem(grde, paper_noise(), sigma=0.0), hc.HinfStateFeedback(grde),
                                        None, PAPER_Q_D0, hc.OutputFeedbackOptions(filter_A=fa),
                                        hc.SimulationOptions(solver=solver))
            for fa in hc.FilterLinearization.__members__.values()]
    for field in ("sigma_min_eig", "sigma_max_eig", "rho_sigma_z"):
        # Two runs, each within a few rtol of the exact Sigma (|Sigma| ~ 1): 10 rtol.
        assert max_rel(series(runs[0], field), series(runs[1], field)) < 10.0 * rtol, field


def test_ship_closed_loop_matches_an_independent_integration():
    """Plant, estimator (35) and filter (36) integrated by SciPy from the paper's equations
    (NumPy ship, hand-written decomposition for A(q_hat), NumPy disturbance), one hold
    interval at a time; only Z(t), q_d(t), u_d(t) come from the library (tested elsewhere).
    Every argument the binding passes matters here: kappa = 0.75 as a number, non-diagonal N
    and Sigma0, noise held over 0.25 s, a disturbance of Signals and numbers, filter_A (the loop
    with either linearization, a linear plant and a stiff one against an RK4:
    tests/cpp/test_output_feedback.cpp). Horizon 6 s. Measured: |q| 1.4e-11, |q_hat| 2.0e-11,
    Sigma eigenvalues and rho 1e-11."""
    filter_A = hc.FilterLinearization.estimate
    t0, tf, T, gamma, kappa, sigma = 0.0, 6.0, 0.25, 5.0, 0.75, 0.5
    u_d = [hc.Signal(1.0), hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    tr = hc.Trajectory(hc.ShipModel(), PAPER_Q_D0, u_d, t0, tf)
    grde = hc.solve_grde(tr, EYE6, EYE6, gamma, hc.SolverOptions(method="erk", **TIGHT))
    N = np.array([[0.25, 0.02, 0.0], [0.02, 0.3, 0.0], [0.0, 0.0, 0.2]])
    Sigma0 = 0.8 * EYE6 + 0.1 * np.ones((6, 6))
    noise = hc._core.standard_normal_samples(3, hc._core.noise_sample_count(t0, tf, T), 3)
    problem = hc.OutputFeedbackProblem(grde, sigma, T, noise, N, Sigma0, EYE6)
    run = hc.simulate_output_feedback(problem, hc.HinfStateFeedback(grde, kappa), paper_disturbance_signals(),
                                      PAPER_Q0, hc.OutputFeedbackOptions(filter_A=filter_A),
                                      hc.SimulationOptions(0.05, solver=hc.SolverOptions("erk", 1e-11, 1e-13)))
    def A_filter(t, q_d, q_hat):
        return ship_error_split(q_d, q_hat)[0]

    q, q_hat, Sigma = output_feedback_reference(
        t0, tf, PAPER_Q0, run.t, f=lambda t, x: ship_drift(x), B=SHIP_B, D=SHIP_D, C=SHIP_C,
        A_filter=A_filter, q_d=tr.q_d, u_d=tr.u_d, Z=grde.Z, w=paper_disturbance, kappa=kappa,
        gamma=gamma, N=N, Q=EYE6, Sigma0=Sigma0, sigma=sigma, noise=noise, period=T)
    assert np.max(np.abs(q_hat)) > 0.5  # the estimator is doing something
    # Library and SciPy, each at rtol 1e-11 (|q| up to 7): 10 x the sum of their tolerances.
    tolerance = 10.0 * (1e-11 + 1e-11) * max(1.0, np.max(np.abs(q)))
    np.testing.assert_allclose(run.q, q, rtol=0, atol=tolerance)
    np.testing.assert_allclose(run.estimator.q_hat, q_hat, rtol=0, atol=tolerance)
    eig = np.linalg.eigvalsh(Sigma)
    np.testing.assert_allclose(run.estimator.sigma_min_eig, eig[:, 0], rtol=1e-8, atol=0)
    np.testing.assert_allclose(run.estimator.sigma_max_eig, eig[:, -1], rtol=1e-8, atol=0)
    np.testing.assert_allclose(run.estimator.rho_sigma_z, spectral_radius(Sigma, grde.Z(run.t)), rtol=1e-8, atol=0)
    # The recorded control is the law (34) at the recorded estimate; y = C q + sigma v (C++
    # against NumPy: round-off of the size of the terms).
    K = grde.gain(run.t)
    terms = np.max(np.abs(run.u_d)) + kappa * np.max(np.einsum("kij,kj->ki", np.abs(K), np.abs(run.estimator.q_hat)))
    np.testing.assert_allclose(run.u, run.u_d - kappa * np.einsum("kij,kj->ki", K, run.estimator.q_hat), rtol=0,
                               atol=ROUNDOFF * terms)
    held = noise[np.minimum(np.floor(run.t / T + 1e-9).astype(int), noise.shape[0] - 1)]
    terms = np.max(np.abs(run.q[:, 3:])) + sigma * np.max(np.abs(held))
    expected = run.q[:, 3:] + sigma * held
    # The heading as an angle: the nearest value of expected + 2 pi k to the recorded one
    # (wrapping moves it by a multiple of 2 pi: a round-off of 2 pi more).
    turns = np.round((expected[:, 2] - run.estimator.y[:, 2]) / (2 * np.pi))
    assert np.all(np.abs(run.estimator.y[:, 2]) <= np.pi)
    expected[:, 2] -= 2 * np.pi * turns
    np.testing.assert_allclose(run.estimator.y, expected, rtol=0, atol=ROUNDOFF * (terms + 2 * np.pi))


# ======================================================================================
# 4. Without noise or error: the estimate stays exact
# ======================================================================================

def test_no_noise_no_error_stays_on_the_trajectory(paper_solutions):
    """sigma = 0 (N given), no disturbance, q0 = q_d0: q_hat(t) = 0 and q(t) = q_d(t) exactly,
    so the run stays there to integration accuracy (measured 1.3e-12), whatever the noise array
    holds (sigma multiplies it); the series' shapes (erk and bdf, and the estimation error from
    another start decaying for both linearizations: tests/cpp/test_output_feedback.cpp)."""
    design = paper_solutions["auto"]
    run = hc.simulate_output_feedback(paper_problem(design, paper_noise(seed=5), sigma=0.0),
                                      hc.HinfStateFeedback(design), None, PAPER_Q_D0)
    assert run.t.shape == (4001,) and run.estimator.q_hat.shape == (4001, 6) and run.estimator.y.shape == (4001, 3)
    assert np.max(np.abs(run.estimator.q_hat)) < 1e-8
    assert np.max(np.abs(run.q - run.q_d)) < 1e-8
    assert np.max(np.abs(run.u - run.u_d)) < 1e-8
    np.testing.assert_array_equal(run.estimator.q_hat[0], 0.0)
    np.testing.assert_array_equal(run.estimator.y, run.q[:, 3:])  # sigma = 0 and C selects: y = C q exactly
    np.testing.assert_array_equal(run.w[:, :3], 0.0)


# ======================================================================================
# 6. The noise: seeded, reproducible
# ======================================================================================

def test_noise_sample_count():
    """ceil((tf - t0) / T) samples, the last one possibly partial (the rounding cases:
    tests/cpp/test_noise.cpp); a bad period is a ValueError naming it."""
    assert hc._core.noise_sample_count(0.0, 40.0, 0.01) == 4000
    assert hc._core.noise_sample_count(0.0, 1.0, 0.3) == 4
    for bad in (0.0, -0.01, math.nan):
        with pytest.raises(ValueError, match="period"):
            hc._core.noise_sample_count(0.0, 1.0, bad)


@pytest.mark.parametrize("seed", [PAPER_SEED, 2**63 + 12345])
def test_standard_normal_samples(seed):
    """The samples as a NumPy array, for any 64-bit seed (above 2^63 too): the same seed gives
    the same numbers, another seed others; each channel's mean 0 and variance 1 (5-sigma bounds
    of the sample statistics of 4000 samples) show that they are standard normal numbers
    (moments, tails, the normal distribution and independence of 1e5 samples:
    tests/cpp/test_noise.cpp)."""
    x = hc._core.standard_normal_samples(seed, 4000, 3)
    assert isinstance(x, np.ndarray) and x.dtype == np.float64 and x.shape == (4000, 3)
    assert np.all(np.isfinite(x))
    assert np.all(np.abs(x.mean(axis=0)) < 5.0 / math.sqrt(4000))
    assert np.all(np.abs(x.var(axis=0, ddof=1) - 1.0) < 5.0 * math.sqrt(2.0 / 3999))
    np.testing.assert_array_equal(hc._core.standard_normal_samples(seed, 4000, 3), x)
    assert not np.any(hc._core.standard_normal_samples(seed - 1, 4000, 3) == x)
    assert hc._core.standard_normal_samples(seed, 0, 3).shape == (0, 3)


@pytest.fixture(scope="module")
def fig2_scenario():
    return hc.load_scenario(hc.scenario_path("paper_fig2"))


@pytest.fixture(scope="module")
def fig2_run(fig2_scenario):
    return hc.run_scenario(fig2_scenario)


def test_scenario_noise_replays_the_run(fig2_scenario, fig2_run):
    """scenario_noise is the seeded standard normal sequence, one row per 0.01 s; passed to
    run_scenario_with_noise it replays the run exactly (the same computation: every series and
    field, and the metrics). (Another seed, another run, and one changed sample changing the run
    from its period on: tests/cpp/test_output_feedback.cpp.)"""
    noise = hc.scenario_noise(fig2_scenario)
    np.testing.assert_array_equal(noise, hc._core.standard_normal_samples(PAPER_SEED, 4000, 3))
    replay = hc.run_scenario_with_noise(fig2_scenario, noise)
    assert replay.simulation == fig2_run.simulation  # every series and field, exactly
    for field in ("t", "q", "q_d", "u", "u_d", "w", "q_hat", "y", "sigma_min_eig", "sigma_max_eig",
                  "rho_sigma_z"):
        np.testing.assert_array_equal(series(replay.simulation, field), series(fig2_run.simulation, field),
                                      err_msg=field)
    assert replay.metrics == fig2_run.metrics


def test_the_seed_is_set_from_python():
    """A seed set on the scenario's [measurement] from Python reaches its noise (another seed,
    another run: tests/cpp/test_output_feedback.cpp)."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    scenario.measurement.seed = PAPER_SEED + 1
    assert scenario.measurement.seed == PAPER_SEED + 1
    np.testing.assert_array_equal(hc.scenario_noise(scenario),
                                  hc._core.standard_normal_samples(PAPER_SEED + 1, 4000, 3))
    assert not np.array_equal(hc.scenario_noise(scenario), paper_noise())


def test_scenario_noise_needs_a_measurement_section():
    with pytest.raises(ValueError, match="measurement"):
        hc.scenario_noise(hc.load_scenario(hc.scenario_path("paper_fig1")))
    with pytest.raises(ValueError, match="measurement"):
        hc.run_scenario_with_noise(hc.load_scenario(hc.scenario_path("paper_fig1")), paper_noise())


def json_close(a, b, path="$"):
    """Same structure, same strings, numbers within 1e-12 relative; timing_s excluded. For two
    programs running the same library code on the same file: equal up to the printed digits."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and set(a) == set(b), path
        for key in a:
            if key != "timing_s":
                json_close(a[key], b[key], f"{path}.{key}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            json_close(x, y, f"{path}[{i}]")
    elif isinstance(a, (int, float)) and not isinstance(a, bool):
        assert isinstance(b, (int, float)) and not isinstance(b, bool), path
        assert b == pytest.approx(a, rel=1e-12, abs=1e-300), path
    else:
        assert a == b, path


@pytest.mark.skipif(not HAVE_CLI, reason="hinf-sim / hinf-cpp are not installed next to this Python")
def test_both_programs_agree_on_figure2(tmp_path, fig2_run):
    scenario = hc.scenario_path("paper_fig2")
    sim = cli(HINF_SIM, scenario, "--json", tmp_path / "sim.json")
    cpp = cli(HINF_CPP, "run", scenario, "--json", tmp_path / "cpp.json")
    assert sim.returncode == 0, sim.stderr
    assert cpp.returncode == 0, cpp.stderr
    a = json.loads((tmp_path / "sim.json").read_text())
    b = json.loads((tmp_path / "cpp.json").read_text())
    json_close(a, b)
    assert a["scenario"] == "paper-fig2" and a["coupling_violation_t"] is None
    # ... and the numbers are those of the Python API's run of the same file (the same code).
    assert set(a["metrics"]) == {d.name for d in hc.metric_table()}
    for key in a["metrics"]:
        value = getattr(fig2_run.metrics, key)
        if math.isnan(value):  # a metric that does not apply is null in the file
            assert a["metrics"][key] is None, key
        else:
            assert a["metrics"][key] == pytest.approx(value, rel=1e-12), key


# ======================================================================================
# 7. The coupling condition rho(Sigma Z) < gamma^2
# ======================================================================================

# Scalar LTI (a, b, d, c, q, qf, gamma, N, Sigma0) on [0, 5]: Z(t) -> 2 (stable root of
# 0.75 z^2 - z - 1 = 0), Sigma(t) -> 2.42 (of 0.583 s^2 - s - 1 = 0), so Sigma Z rises from
# 1 through gamma^2 = 4 and falls back below it near tf (Z(tf) = 1).
SCALAR_COUPLING = (0.5, 1.0, 1.0, 1.0, 1.0, 1.0, 2.0, 1.2, 0.5)


def scalar_coupling_case():
    a, b, d, c, q, qf, gamma, nn, s0 = SCALAR_COUPLING
    t0, tf, dt = 0.0, 5.0, 0.01
    s = b * b - d * d / gamma**2
    s_f = c * c / nn - q / gamma**2

    def rho(t):
        z = scalar_grde_closed_form(a, s, q, qf, tf - np.asarray(t, dtype=float))
        sig = scalar_grde_closed_form(a, s_f, d * d, s0, np.asarray(t, dtype=float) - t0)
        return z * sig

    grid = np.linspace(t0, tf, 501)
    r = rho(grid)
    first = int(np.flatnonzero(r >= gamma**2)[0])
    t_cross = brentq(lambda t: float(rho(t)) - gamma**2, grid[first - 1], grid[first], xtol=1e-14)
    # The grid point after the crossing is clearly above gamma^2 (no tie to break).
    assert r[first] - gamma**2 > 1e-4 and gamma**2 - r[first - 1] > 1e-4
    model = hc.LinearModel(np.array([[a]]), np.array([[b]]), np.array([[d]]), np.array([[c]]))
    tr = hc.Trajectory(model, [0.0], [0.0], t0, tf)
    grde = hc.solve_grde(tr, np.array([[q]]), np.array([[qf]]), gamma)
    noise = np.zeros((hc._core.noise_sample_count(t0, tf, dt), 1))
    problem = hc.OutputFeedbackProblem(design=grde, sigma=0.0, sample_period=dt, noise=noise, N=np.array([[nn]]),
                                       Sigma0=np.array([[s0]]), Q=np.array([[q]]))
    return grde, problem, rho, grid, grid[first], t_cross, gamma


def test_coupling_violation_raises_at_the_first_output_time():
    """rho = Sigma Z from the two scalar closed forms crosses gamma^2 = 4 at t_c = 1.27394:
    the run raises CouplingConditionError at the first output time after it (1.28, where
    rho = 4.00800), with that rho (measured agreement 1e-8 relative), and a message saying
    what to change (every method, and the ship: tests/cpp/test_output_feedback.cpp)."""
    grde, problem, rho, grid, t_first, t_cross, gamma = scalar_coupling_case()
    with pytest.raises(hc.CouplingConditionError) as info:
        hc.simulate_output_feedback(problem, hc.HinfStateFeedback(grde), None, [0.0])
    error = info.value
    assert isinstance(error, hc.HinfError) and isinstance(error, RuntimeError)
    assert error.t == pytest.approx(t_first, abs=TIME_ROUNDOFF)
    assert error.gamma == gamma
    assert error.rho == pytest.approx(float(rho(t_first)), rel=1e-6)
    assert error.rho >= gamma**2
    message = str(error)
    assert "coupling" in message and "rho(Sigma Z)" in message
    assert "increase gamma" in message.lower()
    assert "Q0 - eta I" in message


def test_coupling_violation_flagged_run_completes():
    """on_coupling_violation = flag: the run (zero state, so the singular gain multiplies
    a zero innovation) completes, reports the first violation time, and rho_sigma_z is the
    closed form along the whole run (it rises above gamma^2 and falls below it again)."""
    grde, problem, rho, grid, t_first, t_cross, gamma = scalar_coupling_case()
    run = hc.simulate_output_feedback(problem, hc.HinfStateFeedback(grde), None, [0.0],
                                      hc.OutputFeedbackOptions(on_coupling_violation=hc.CouplingPolicy.flag))
    assert run.estimator.coupling_violation_t == pytest.approx(t_first, abs=TIME_ROUNDOFF)
    np.testing.assert_allclose(run.t, grid, rtol=0, atol=TIME_ROUNDOFF)
    np.testing.assert_allclose(run.estimator.rho_sigma_z, rho(grid), rtol=1e-6)
    above = np.flatnonzero(run.estimator.rho_sigma_z >= gamma**2)
    assert run.t[above[0]] == run.estimator.coupling_violation_t
    assert run.estimator.rho_sigma_z[-1] < gamma**2  # back below: the first time is reported, not the last
    np.testing.assert_array_equal(run.estimator.q_hat, 0.0)


# The ship at gamma = 2.5 with a small Sigma(t0) = 0.01 I (Q0 = 101, eta = 1), filter_A =
# "desired": rho(Sigma Z) starts at 0.26 and crosses 6.25 at t = 1.3738 s (from
# solve_filter_riccati and solve_grde), so the first output time with rho >= gamma^2 is 1.38.
SHIP_COUPLING_GAMMA = 2.5


@pytest.fixture(scope="module")
def ship_coupling_reference(paper_trajectory):
    """(grde, first output time with rho >= gamma^2, rho there, crossing time) for a gamma."""

    def make(gamma, sigma0=0.01):
        grde = hc.solve_grde(paper_trajectory, EYE6, EYE6, gamma)
        filt = hc.solve_filter_riccati(paper_trajectory, PAPER_N, EYE6, gamma, sigma0 * EYE6)
        grid = np.linspace(0.0, 40.0, 4001)[:500]

        def rho(t):
            return spectral_radius(filt.Sigma(t), grde.Z(t))

        r = rho(grid)
        first = int(np.flatnonzero(r >= gamma**2)[0])
        assert first > 0 and r[first] - gamma**2 > 1e-3 * gamma**2
        t_cross = brentq(lambda t: float(rho(t)) - gamma**2, grid[first - 1], grid[first], xtol=1e-12)
        return grde, grid[first], float(r[first]), t_cross

    return make


def test_ship_flagged_coupling_violation_is_not_lost(ship_coupling_reference):
    """on_coupling_violation = flag on the ship (gamma = 2.5, violation first at 1.38 s):
    the run either completes and reports coupling_violation_t = 1.38, or, if the singular
    estimator makes the integration fail afterwards, the error says that the coupling
    condition was violated (and when).
    Regression: the run used to fail later with SolverError "Dormand-Prince: more than 2000
    steps before reaching t = 2.64 ...; raise max_steps or loosen rtol" (with the default
    500000 steps it ground for about a minute, then failed the same way at t = 3.37), without
    mentioning the flagged violation."""
    grde, t_first, _, t_cross = ship_coupling_reference(SHIP_COUPLING_GAMMA)
    try:
        run = hc.simulate_output_feedback(paper_problem(grde, paper_noise(), Sigma0=0.01 * EYE6),
                                          hc.HinfStateFeedback(grde), paper_disturbance_signals(), PAPER_Q0,
                                          DESIRED_A_FLAG, hc.SimulationOptions(solver=hc.SolverOptions(max_steps=2000)))
    except hc.CouplingConditionError:
        pytest.fail("flag mode raised CouplingConditionError")
    except hc.HinfError as error:
        # The violation is named, at the first output time past it (1.38) or where the
        # integration stopped at the crossing.
        assert "coupling condition" in str(error) and "violated" in str(error), str(error)
        assert error.t >= t_cross - 1e-6
    else:
        assert run.estimator.coupling_violation_t == pytest.approx(t_first, abs=TIME_ROUNDOFF)


COUPLING_TEXT = mutate(mutate(mutate(FIG2_TEXT, "gamma = 5.0", f"gamma = {SHIP_COUPLING_GAMMA}"),
                              "Q0 = 2.0", "Q0 = 101.0"),
                       'filter_A = "estimate"', 'filter_A = "desired"')


@pytest.mark.parametrize("reader", ["python", "c++"])
def test_coupling_violation_from_a_scenario_file(tmp_path, reader, ship_coupling_reference):
    _, t_first, _, t_cross = ship_coupling_reference(SHIP_COUPLING_GAMMA)
    path = tmp_path / "coupling.toml"
    path.write_text(COUPLING_TEXT)
    load = hc.load_scenario if reader == "python" else (lambda p: hc._core.parse_scenario_toml(p.read_text(), str(p)))
    scenario = load(path)
    assert scenario.measurement.on_coupling_violation == hc.CouplingPolicy.error
    with pytest.raises(hc.CouplingConditionError) as info:
        hc.run_scenario(scenario)
    # The file's solver is bdf: its integration reaches the output time 1.38 past the crossing.
    assert info.value.t == pytest.approx(t_first, abs=TIME_ROUNDOFF)
    # "flag": the run goes on past the violation (on the ship the singular estimator may then
    # end it; the error names the violation: see test_ship_flagged_coupling_violation_is_not_lost).
    flagged = 'filter_A = "desired"\non_coupling_violation = "flag"'
    path.write_text(mutate(COUPLING_TEXT, 'filter_A = "desired"', flagged))
    scenario = load(path)
    assert scenario.measurement.on_coupling_violation == hc.CouplingPolicy.flag
    scenario.solver = hc.SolverOptions(max_steps=2000)
    try:
        result = hc.run_scenario(scenario)
    except hc.CouplingConditionError:
        pytest.fail("on_coupling_violation = \"flag\" raised CouplingConditionError")
    except hc.SolverError as error:
        assert error.t >= t_cross - 1e-6  # at or past the crossing (see the test above)
    else:
        assert result.simulation.estimator.coupling_violation_t == pytest.approx(t_first, abs=TIME_ROUNDOFF)


@pytest.mark.skipif(not HAVE_CLI, reason="hinf-sim / hinf-cpp are not installed next to this Python")
@pytest.mark.parametrize("program", ["hinf-sim", "hinf-cpp"])
def test_coupling_violation_exit_status_3(tmp_path, program):
    path = tmp_path / "coupling.toml"
    path.write_text(COUPLING_TEXT)
    out = tmp_path / "never.json"
    args = [HINF_SIM, path, "--json", out] if program == "hinf-sim" else [HINF_CPP, "run", path, "--json", out]
    result = cli(*args)
    assert result.returncode == 3, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "coupling condition" in lines[0] and "1.38" in lines[0], result.stderr
    assert program in lines[0]
    assert not out.exists()


# ======================================================================================
# 9. Bad inputs: [measurement] in scenario files, and the Python API
# ======================================================================================

def python_reader(path):
    return hc.load_scenario(path)


def cpp_reader(path):
    return hc._core.parse_scenario_toml(path.read_text(), str(path))


READERS = {"python": python_reader, "c++": cpp_reader}


def reader_error(reader, path):
    """(stage, message) of the first ValueError from reading or running the scenario."""
    try:
        scenario = reader(path)
    except ValueError as error:
        return "read", str(error)
    try:
        hc.run_scenario(scenario)
    except ValueError as error:
        return "run", str(error)
    return None, None


def measurement_case(old, new):
    return mutate(FIG2_TEXT, old, new)


# id -> (scenario text, words the message must contain)
BAD_MEASUREMENT = {
    "sigma < 0": (measurement_case("\nsigma = 0.5", "\nsigma = -0.5"), ["sigma", ">= 0"]),
    # Regression: with N left to its default, the message used to be "[measurement] N must be
    # given when sigma = 0 ..." for sigma = -0.5, instead of naming sigma.
    "sigma < 0 without N": (mutate(measurement_case("\nsigma = 0.5", "\nsigma = -0.5"), "N = 0.25\n", ""),
                            ["sigma", ">= 0"]),
    "sigma NaN": (measurement_case("\nsigma = 0.5", "\nsigma = nan"), ["sigma"]),
    "sigma a string": (measurement_case("\nsigma = 0.5", '\nsigma = "0.5"'), ["sigma"]),
    "sigma missing": (measurement_case("\nsigma = 0.5\n", "\n"), ["sigma"]),
    "sample_period zero": (measurement_case("sample_period = 0.01", "sample_period = 0.0"), ["sample_period"]),
    "sample_period negative": (measurement_case("sample_period = 0.01", "sample_period = -0.01"),
                               ["sample_period"]),
    "Q0 - eta I zero": (measurement_case("Q0 = 2.0", "Q0 = 1.0"), ["Q0 - eta I", "positive definite"]),
    "Q0 - eta I indefinite": (
        measurement_case("Q0 = 2.0", "Q0 = [[2,0,0,0,0,0],[0,2,0,0,0,0],[0,0,0.5,0,0,0],[0,0,0,2,0,0],"
                                     "[0,0,0,0,2,0],[0,0,0,0,0,2]]"),
        ["Q0 - eta I", "positive definite"]),
    "Q0 not symmetric": (
        measurement_case("Q0 = 2.0", "Q0 = [[2,1,0,0,0,0],[0,2,0,0,0,0],[0,0,2,0,0,0],[0,0,0,2,0,0],"
                                     "[0,0,0,0,2,0],[0,0,0,0,0,2]]"),
        ["Q0", "symmetric"]),
    "Q0 wrong size": (measurement_case("Q0 = 2.0", "Q0 = [[2,0],[0,2]]"), ["Q0"]),
    "N zero": (measurement_case("N = 0.25", "N = 0.0"), ["N", "positive definite"]),
    "N indefinite": (measurement_case("N = 0.25", "N = [[0.25, 0, 0], [0, -0.1, 0], [0, 0, 0.25]]"),
                     ["N", "positive definite"]),
    "N wrong size": (measurement_case("N = 0.25", "N = [[0.25, 0], [0, 0.25]]"), ["N"]),
    "N missing with sigma = 0": (mutate(measurement_case("\nsigma = 0.5", "\nsigma = 0.0"), "N = 0.25\n", ""),
                                 ["N", "sigma = 0"]),
    "eta zero": (measurement_case("eta = 1.0", "eta = 0.0"), ["eta"]),
    "eta negative": (measurement_case("eta = 1.0", "eta = -1.0"), ["eta"]),
    "filter_A unknown": (measurement_case('filter_A = "estimate"', 'filter_A = "actual"'), ["filter_A", "actual"]),
    "on_coupling_violation unknown": (
        measurement_case('filter_A = "estimate"', 'filter_A = "estimate"\non_coupling_violation = "ignore"'),
        ["on_coupling_violation", "ignore"]),
    "unknown key": (measurement_case("eta = 1.0", "eta = 1.0\nsigma_noise = 0.1"), ["sigma_noise"]),
    "seed negative": (measurement_case("seed = 20000601", "seed = -1"), ["seed"]),
    "seed not an integer": (measurement_case("seed = 20000601", "seed = 1.5"), ["seed"]),
}


@pytest.mark.parametrize("case", list(BAD_MEASUREMENT))
def test_bad_measurement_section_rejected(tmp_path, case):
    text, words = BAD_MEASUREMENT[case]
    path = tmp_path / "bad.toml"
    path.write_text(text)
    results = {name: reader_error(reader, path) for name, reader in READERS.items()}
    for name, (stage, message) in results.items():
        assert stage is not None, f"{name} reader accepted the scenario"
        for word in words:
            assert word in message, f"{name} reader: {word!r} not in {message!r}"
    assert results["python"] == results["c++"]


@pytest.mark.skipif(not HAVE_CLI, reason="hinf-sim / hinf-cpp are not installed next to this Python")
@pytest.mark.parametrize("case", list(BAD_MEASUREMENT))
def test_bad_measurement_section_exit_status_2(tmp_path, case):
    text, words = BAD_MEASUREMENT[case]
    path = tmp_path / "bad.toml"
    path.write_text(text)
    result = cli(HINF_SIM, path)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("hinf-sim: error:"), result.stderr
    assert words[0] in lines[0]
    assert result.stdout == ""


def test_measurement_fixture_file_is_rejected_by_every_front_end():
    """tests/data/bad_measurement_eta.toml: eta = 0 (the paper requires eta > 0)."""
    path = pathlib.Path(__file__).resolve().parents[1] / "data" / "bad_measurement_eta.toml"
    for reader in READERS.values():
        stage, message = reader_error(reader, path)
        assert stage == "run" and "eta" in message
    if HAVE_CLI:
        for args in ([HINF_SIM, path], [HINF_CPP, "run", path]):
            result = cli(*args)
            assert result.returncode == 2 and "eta" in result.stderr, result.stderr


def test_paper_fig2_file_is_fig1_with_a_measurement_section(fig2_scenario):
    """scenarios.md: Figure 2 is the Figure 1 scenario plus [measurement] (sigma = 0.5 over
    0.01 s, N = sigma^2 I3, Q0 = 2I, eta = 1, filter_A = estimate)."""
    fig1 = hc.load_scenario(hc.scenario_path("paper_fig1"))
    s = fig2_scenario
    assert (s.t0, s.tf, s.gamma, s.output_dt) == (fig1.t0, fig1.tf, fig1.gamma, fig1.output_dt)
    np.testing.assert_array_equal(s.desired_q0, fig1.desired_q0)
    np.testing.assert_array_equal(s.initial_q0, fig1.initial_q0)
    np.testing.assert_array_equal(s.Q, fig1.Q)
    times = np.linspace(0.0, 40.0, 101)
    np.testing.assert_array_equal(s.desired_u(times), fig1.desired_u(times))
    np.testing.assert_array_equal(s.disturbance(times), fig1.disturbance(times))
    m = s.resolved().measurement
    assert (m.sigma, m.sample_period, m.seed, m.eta, m.filter_A, m.on_coupling_violation) == \
           (0.5, 0.01, PAPER_SEED, 1.0, hc.FilterLinearization.estimate, hc.CouplingPolicy.error)
    np.testing.assert_array_equal(m.N, PAPER_N)
    np.testing.assert_array_equal(m.Q0, 2.0 * EYE6)
    # The default N is sigma^2 I: dropping N from the file gives the same run.
    implicit = hc._core.parse_scenario_toml(mutate(FIG2_TEXT, "N = 0.25\n", ""), "implicit-N")
    np.testing.assert_array_equal(implicit.resolved().measurement.N, PAPER_N)


@pytest.mark.parametrize("reader", ["python", "c++"])
def test_scenario_filter_initialization(tmp_path, reader):
    """Q0 = 3, eta = 0.5: Sigma(t0) = (Q0 - eta I)^-1 = 0.4 I; a full N, a full Q0."""
    text = mutate(mutate(FIG2_TEXT, "Q0 = 2.0", "Q0 = 3.0"), "eta = 1.0", "eta = 0.5")
    text = mutate(text, "tf = 40.0", "tf = 2.0")
    path = tmp_path / "init.toml"
    path.write_text(text)
    load = hc.load_scenario if reader == "python" else (lambda p: hc._core.parse_scenario_toml(p.read_text(), str(p)))
    run = hc.run_scenario(load(path)).simulation
    # (2.5 I)^-1 and its eigenvalues, in the library: round-off.
    assert run.estimator.sigma_min_eig[0] == pytest.approx(0.4, rel=ROUNDOFF)
    assert run.estimator.sigma_max_eig[0] == pytest.approx(0.4, rel=ROUNDOFF)
    Q0 = np.diag([3.0, 4.0, 5.0, 3.0, 4.0, 6.0])
    Q0[0, 3] = Q0[3, 0] = 0.5
    text2 = mutate(text, "Q0 = 3.0", "Q0 = " + json.dumps(Q0.tolist()))
    text2 = mutate(text2, "N = 0.25", "N = [[0.25, 0.05, 0.0], [0.05, 0.3, 0.0], [0.0, 0.0, 0.2]]")
    path.write_text(text2)
    run = hc.run_scenario(load(path)).simulation
    eig = np.linalg.eigvalsh(np.linalg.inv(Q0 - 0.5 * EYE6))
    # Inverse and eigenvalues in the library and in NumPy: round-off amplified by the
    # condition number of Q0 - eta I (2.6), relative to the largest eigenvalue.
    slack = ROUNDOFF * np.linalg.cond(Q0 - 0.5 * EYE6) * eig[-1]
    assert run.estimator.sigma_min_eig[0] == pytest.approx(eig[0], abs=slack)
    assert run.estimator.sigma_max_eig[0] == pytest.approx(eig[-1], abs=slack)


@pytest.fixture(scope="module")
def short_design(paper_u_d):
    tr = hc.Trajectory(hc.ShipModel(), PAPER_Q_D0, paper_u_d, 0.0, 2.0)
    return hc.solve_grde(tr, EYE6, EYE6, 5.0)


def short_noise(rows=200, cols=3):
    return np.zeros((rows, cols))


@pytest.mark.parametrize("change,words", [
    (dict(noise=short_noise(199)), ["noise", "200 rows", "(199, 3)"]),
    (dict(noise=short_noise(201)), ["noise", "200 rows", "(201, 3)"]),
    (dict(noise=short_noise(200, 2)), ["noise", "3 columns", "(200, 2)"]),
    (dict(noise=np.where(np.arange(600).reshape(200, 3) == 301, np.nan, 0.0)), ["noise", "non-finite"]),
    (dict(q0=PAPER_Q0[:5]), ["q0", "6", "5"]),
    (dict(q0=np.append(PAPER_Q0, 0.0)), ["q0", "6", "7"]),
    (dict(q0=np.array([1.0, 0, 0, np.nan, 0, 0])), ["q0", "non-finite"]),
    (dict(problem=dict(sigma=-0.1)), ["sigma"]),
    (dict(problem=dict(sigma=math.nan)), ["sigma"]),
    (dict(problem=dict(sample_period=0.0)), ["period"]),
    (dict(problem=dict(N=np.eye(2))), ["N", "(3, 3)"]),
    (dict(problem=dict(N=np.diag([0.25, 0.0, 0.25]))), ["N", "positive definite"]),
    (dict(problem=dict(Sigma0=-EYE6)), ["Sigma0", "positive definite"]),
    (dict(problem=dict(Sigma0=np.eye(5))), ["Sigma0", "(6, 6)"]),
    (dict(problem=dict(Q=-EYE6)), ["Q", "semidefinite"]),
    (dict(disturbance=[0.0] * 3), ["disturbance"]),
], ids=["noise 199 rows", "noise 201 rows", "noise 2 columns", "NaN in noise", "q0 5 states",
        "q0 7 states", "q0 NaN", "sigma < 0", "sigma NaN", "period 0", "N 2x2", "N singular",
        "Sigma0 negative", "Sigma0 5x5", "Q negative", "disturbance 3 channels"])
def test_simulate_output_feedback_bad_inputs(short_design, change, words):
    """Each bad input is a ValueError naming it: from the OutputFeedbackProblem constructor
    where it can tell without the model, else from simulate_output_feedback; set after
    construction, the same input is refused by simulate_output_feedback."""
    args = dict(noise=short_noise(), q0=PAPER_Q0, disturbance=None, problem={})
    args.update(change)
    controller = hc.HinfStateFeedback(short_design)
    with pytest.raises(ValueError) as info:
        hc.simulate_output_feedback(paper_problem(short_design, args["noise"], **args["problem"]), controller,
                                    args["disturbance"], args["q0"])
    for word in words:
        assert word in str(info.value), (word, str(info.value))
    problem = paper_problem(short_design, short_noise())
    for key, value in dict(noise=args["noise"], **args["problem"]).items():
        setattr(problem, key, value)
    with pytest.raises(ValueError) as info:
        hc.simulate_output_feedback(problem, controller, args["disturbance"], args["q0"])
    for word in words:
        assert word in str(info.value), (word, str(info.value))


def test_output_feedback_options_and_models_without_measurements(lti_trajectory):
    with pytest.raises(ValueError, match="filter_A"):
        hc.OutputFeedbackOptions(filter_A="actual")
    with pytest.raises(ValueError, match="on_coupling_violation"):
        hc.OutputFeedbackOptions(on_coupling_violation="ignore")
    options = hc.OutputFeedbackOptions()
    assert (options.filter_A, options.on_coupling_violation) == (hc.FilterLinearization.estimate,
                                                                 hc.CouplingPolicy.error)
    with pytest.raises(ValueError, match="filter_A"):
        options.filter_A = "truth"
    options.filter_A = "desired"
    assert options.filter_A == hc.FilterLinearization.desired
    # A model without C cannot be simulated (or filtered) with measurements.
    tr = lti_trajectory(-np.eye(2), np.ones((2, 1)), np.eye(2), 0.0, 1.0)
    grde = hc.solve_grde(tr, np.eye(2), np.eye(2), 5.0)
    problem = hc.OutputFeedbackProblem(grde, 0.1, 0.01, np.zeros((100, 1)), np.eye(1), np.eye(2), np.eye(2))
    with pytest.raises(ValueError, match="C"):
        hc.simulate_output_feedback(problem, hc.HinfStateFeedback(grde), None, np.zeros(2))
    with pytest.raises(ValueError, match="C"):
        hc.solve_filter_riccati(tr, np.eye(1), np.eye(2), 5.0, np.eye(2))


# ======================================================================================
# 10. The paper's Figure 2
# ======================================================================================

def test_paper_figure2_run_from_python(fig2_run):
    """What run_scenario returns for an output-feedback scenario (its tracking, estimate,
    coupling condition and metrics against the series: tests/cpp/test_output_feedback.cpp)."""
    run = fig2_run.simulation
    assert fig2_run.scenario_name == "paper-fig2" and fig2_run.law == hc.Law.hinf and fig2_run.output_feedback
    assert run.t.shape == (4001,) and run.estimator.q_hat.shape == (4001, 6) and run.estimator.y.shape == (4001, 3)
    for field in ("sigma_min_eig", "sigma_max_eig", "rho_sigma_z"):
        assert series(run, field).shape == (4001,), field
    assert math.isnan(run.estimator.coupling_violation_t)
    assert math.isfinite(fig2_run.metrics.rms_estimation_error_last_half)
    # The largest of the same recorded values.
    assert fig2_run.metrics.max_rho_sigma_z == np.max(run.estimator.rho_sigma_z)
    # Sigma(t0) = (Q0 - eta I)^-1 = I (its eigenvalues computed by the library: round-off) and
    # q_hat(t0) = 0.
    assert run.estimator.sigma_min_eig[0] == pytest.approx(1.0, rel=ROUNDOFF)
    assert run.estimator.sigma_max_eig[0] == pytest.approx(1.0, rel=ROUNDOFF)
    np.testing.assert_array_equal(run.estimator.q_hat[0], 0.0)


def test_paper_figure2_methods_agree(fig2_run):
    """The three methods give the same trajectory, to 1e-6 (tests/cpp/test_output_feedback.cpp
    allows 100 rtol times |q|, 4e-5). Measured max |q - q_erk|: bdf 2.1e-8, adams 1.7e-7
    (q_hat 2.1e-8 and 2.0e-7, rho 1.7e-8 and 1.8e-8 relative)."""
    runs = {"bdf": fig2_run.simulation}
    for method in ("erk", "adams"):
        scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
        scenario.solver = hc.SolverOptions(method=method)
        runs[method] = hc.run_scenario(scenario).simulation
    assert "dormand-prince" in runs["bdf"].integrator.lower()
    assert "adams" in runs["adams"].integrator.lower()
    for method in ("bdf", "adams"):
        for field, tol in (("q", 1e-6), ("q_hat", 1e-6), ("u", 1e-5)):
            difference = np.max(np.abs(series(runs[method], field) - series(runs["erk"], field)))
            assert difference < tol, f"{method} {field}: {difference:.2e}"
        assert max_rel(runs[method].estimator.rho_sigma_z, runs["erk"].estimator.rho_sigma_z) < 1e-6
