"""Plain NumPy/SciPy implementation of the paper's Figure-2 run (output feedback), written as a
user would.

This is the baseline that ``bench_paper_fig2.py`` times hinf_cpp against. It does the same
computation as ``hinf_cpp.run_scenario`` on ``scenarios/paper_fig2.toml`` with nothing but
NumPy and :func:`scipy.integrate.solve_ivp`:

1. the desired trajectory q_d(t) and the GRDE Z(t), backward from Z(tf) = Qf, exactly as for
   Figure 1 (``scipy_reference.solve_desired_trajectory`` and ``scipy_reference.solve_grde``);
2. the closed loop of paper §4 on the state x = [q (6), q_hat (6), Sigma (36, row-major)]:
       plant (34)     dq/dt = f(q) + B u + D w(t),   u = u_d - kappa B' Z q_hat
       measurement    y = C q + sigma v_k,  v_k held on [t0 + k T, t0 + (k+1) T),  C = [0 I3]
       estimator (35) dq_hat/dt = [A(q_hat) - (kappa B B' - gamma^-2 D D') Z] q_hat
                                  + alpha(q_hat)
                                  + [I - gamma^-2 Sigma Z]^-1 Sigma C' N^-1 (y - C q_d - C q_hat)
       filter (36)    dSigma/dt = A Sigma + Sigma A' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D D'
   with Sigma(t0) = (Q0 - eta I)^-1, q_hat(t0) = 0, and A(q_hat), alpha(q_hat) the ship's split
   of the error dynamics (docs/mathematics.md, paper eqs. 26-31; filter_A = "estimate"). The
   noise is piecewise constant, so the loop is integrated with one ``solve_ivp`` call per
   hold interval (4000 calls of 0.01 s over [0, 40]), the end state of one interval starting
   the next. The output grid (0.01 s) is the hold grid, so each interval's end state is the
   next output point;
3. the outputs on the grid (u, w with the noise channels w4..w6 = v, y, the extreme
   eigenvalues of Sigma, rho(Sigma Z) and the coupling check rho < gamma^2), the eigenvalue
   range of Z on the grid, and the metrics of ``hinf_cpp.compute_metrics``.

The noise samples v_k (4000 x 3, standard normal) are an argument: pass
``hinf_cpp.scenario_noise(scenario)`` to integrate the very problem hinf_cpp integrates. The
right-hand sides evaluate q_d(t) and Z(t) through the ``OdeSolution`` dense outputs, as a user
script would. Nothing here imports hinf_cpp except the self-check.

    .venv/bin/python benchmarks/scipy_output_feedback.py          # self-check, ~10 s
"""

from __future__ import annotations

import dataclasses
import math
import pathlib
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import scipy_reference as ref  # noqa: E402

__all__ = [
    "Measurement",
    "PAPER_FIG2",
    "PAPER_FIG2_MEASUREMENT",
    "SHIP_C",
    "NOISE_CHANNELS",
    "ship_error_split",
    "closed_loop_rhs",
    "simulate_output_feedback",
    "compute_metrics",
    "run_reference",
    "check_matches_scenario",
]


# --------------------------------------------------------------------------------------------
# The problem: Figure 1's ship, path, start and disturbance, plus the measurement of §4
# --------------------------------------------------------------------------------------------

PAPER_FIG2 = ref.PAPER_FIG1  # same parameters, horizon, gamma, Q, Qf, q_d0, q0, u_d, w, kappa

SHIP_C = np.hstack([np.zeros((3, 3)), np.eye(3)])  # x, y, psi are measured
NOISE_CHANNELS = [3, 4, 5]  # w4..w6 carry the held noise samples v


@dataclasses.dataclass(frozen=True)
class Measurement:
    """The [measurement] table of scenarios/paper_fig2.toml."""

    sigma: float = 0.5
    sample_period: float = 0.01
    N: np.ndarray = dataclasses.field(default_factory=lambda: 0.25 * np.eye(3))
    Q0: np.ndarray = dataclasses.field(default_factory=lambda: 2.0 * np.eye(6))
    eta: float = 1.0
    filter_A: str = "estimate"

    @property
    def Sigma0(self) -> np.ndarray:
        """Sigma(t0) = (Q0 - eta I)^-1."""
        return np.linalg.inv(self.Q0 - self.eta * np.eye(self.Q0.shape[0]))


PAPER_FIG2_MEASUREMENT = Measurement()


def ship_error_split(q_d: np.ndarray, q_e: np.ndarray, p: ref.Problem = PAPER_FIG2):
    """(A(q_e), alpha(q_e)) with A(q_e) q_e + alpha(q_e) = f(q_d + q_e) - f(q_d) exactly and
    A(0) = df/dq(q_d): the split of docs/mathematics.md, q1 = [u, v, x, y], q2 = [r, psi]."""
    ud, vd, rd, psid = q_d[0], q_d[1], q_d[2], q_d[5]
    ue, ve, re, pe = q_e[0], q_e[1], q_e[2], q_e[5]
    c, s = math.cos(psid + pe), math.sin(psid + pe)
    cd, sd = math.cos(psid), math.sin(psid)
    A = np.zeros((6, 6))
    # A11(q2) on rows/columns u, v, x, y
    A[0, 0], A[0, 1] = -p.d_u, p.m_u * (rd + re)
    A[1, 0], A[1, 1] = p.m_v * (rd + re), -p.d_v
    A[3, 0], A[3, 1] = c, -s
    A[4, 0], A[4, 1] = s, c
    # A12 = d alpha1 / d q2 at 0 (columns r, psi)
    A[0, 2] = p.m_u * vd
    A[1, 2] = p.m_v * ud
    A[3, 5] = -ud * sd - vd * cd
    A[4, 5] = ud * cd - vd * sd
    # A21 = d alpha2 / d q1 at 0, and A22
    A[2, 0], A[2, 1] = p.m_r * vd, p.m_r * ud
    A[2, 2] = -p.d_r
    A[5, 2] = 1.0
    alpha = np.array([
        p.m_u * vd * re - A[0, 2] * re,
        p.m_v * ud * re - A[1, 2] * re,
        p.m_r * (ue * vd + ud * ve + ue * ve) - A[2, 0] * ue - A[2, 1] * ve,
        ud * (c - cd) - vd * (s - sd) - A[3, 5] * pe,
        ud * (s - sd) + vd * (c - cd) - A[4, 5] * pe,
        0.0,
    ])
    return A, alpha


# --------------------------------------------------------------------------------------------
# the closed loop, one hold interval at a time
# --------------------------------------------------------------------------------------------


def closed_loop_rhs(trajectory, grde, p: ref.Problem = PAPER_FIG2,
                    m: Measurement = PAPER_FIG2_MEASUREMENT):
    """rhs(t, x, v) of plant (34), estimator (35) and filter (36) on x = [q, q_hat, Sigma
    raveled], for the noise sample v held over the current interval."""
    n = 6
    q_d, Z_of = trajectory.sol, grde.sol
    B, D, C, Q, kappa = p.B, p.D, SHIP_C, p.Q, p.kappa
    g2 = 1.0 / p.gamma**2
    BT = B.T
    N_inv = np.linalg.inv(m.N)
    CtNinv = C.T @ N_inv
    S_f = CtNinv @ C - g2 * Q
    DDt = D @ D.T
    feedback = kappa * B @ BT - g2 * DDt  # (kappa B B' - gamma^-2 D D')
    I = np.eye(n)
    use_estimate = m.filter_A == "estimate"

    def rhs(t, x, v):
        q, q_hat, Sigma = x[:n], x[n:2 * n], x[2 * n:].reshape(n, n)
        qd, Z = q_d(t), Z_of(t).reshape(n, n)
        u = p.u_d(t) - kappa * (BT @ (Z @ q_hat))
        dq = ref.ship_f(q, p) + B @ u + D @ p.w(t)
        y = C @ q + m.sigma * v
        A, alpha = ship_error_split(qd, q_hat, p)
        gain = np.linalg.solve(I - g2 * Sigma @ Z, Sigma @ CtNinv)
        dq_hat = (A - feedback @ Z) @ q_hat + alpha + gain @ (y - C @ qd - C @ q_hat)
        A_f = A if use_estimate else ref.ship_dfdq(qd, p)
        dSigma = A_f @ Sigma + Sigma @ A_f.T - Sigma @ S_f @ Sigma + DDt
        return np.concatenate([dq, dq_hat, dSigma.ravel()])

    return rhs


def simulate_output_feedback(trajectory, grde, noise: np.ndarray, p: ref.Problem = PAPER_FIG2,
                             m: Measurement = PAPER_FIG2_MEASUREMENT, method: str = "RK45",
                             rtol: float = 1e-8, atol: float = 1e-10) -> dict:
    """The output-feedback closed loop from q0, q_hat = 0, Sigma0, one solve_ivp call per hold
    interval; noise[k] is the standard normal sample held on interval k. Returns a dict of
    arrays on the output grid (one row per time): t, q, q_hat, q_d, q_e, u, u_d, w, y,
    sigma_min_eig, sigma_max_eig, rho_sigma_z, plus the summed solve_ivp statistics."""
    n, T = 6, m.sample_period
    # The grid points are the interval ends (output dt = hold period), so no dense output.
    if not math.isclose(p.output_dt, T):
        raise ValueError("this implementation records the hold-interval ends: output dt must "
                         "equal the sample period")
    grid = ref.output_grid(p.t0, p.tf, p.output_dt)
    samples = grid.size - 1
    if noise.shape != (samples, SHIP_C.shape[0]):
        raise ValueError(f"noise must be ({samples}, 3), got {noise.shape}")
    rhs = closed_loop_rhs(trajectory, grde, p, m)

    states = np.empty((grid.size, 2 * n + n * n))
    states[0] = np.concatenate([p.q0, np.zeros(n), m.Sigma0.ravel()])
    nfev = steps = 0
    for k in range(samples):
        result = solve_ivp(rhs, (grid[k], grid[k + 1]), states[k], method=method, rtol=rtol,
                           atol=atol, args=(noise[k],))
        if not result.success:
            raise RuntimeError(f"closed loop ({method}), interval {k}: {result.message}")
        states[k + 1] = result.y[:, -1]
        nfev += result.nfev
        steps += result.t.size - 1

    # Outputs on the grid; the sample held at grid[k] is noise[k] (the last one at tf).
    t = grid
    q, q_hat, Sigma = states[:, :n], states[:, n:2 * n], states[:, 2 * n:].reshape(-1, n, n)
    held = noise[np.minimum(np.arange(t.size), samples - 1)]
    qd = trajectory.sol(t).T
    Zt = ref.grde_Z(grde, t)
    ud = np.array([p.u_d(tk) for tk in t])
    u = ud - p.kappa * np.einsum("ij,kjl,kl->ki", p.B.T, Zt, q_hat)
    w = np.array([p.w(tk) for tk in t])
    w[:, NOISE_CHANNELS] = held
    y = q @ SHIP_C.T + m.sigma * held
    sigma_eig = np.linalg.eigvalsh(0.5 * (Sigma + Sigma.transpose(0, 2, 1)))
    rho = np.max(np.abs(np.linalg.eigvals(Sigma @ Zt)), axis=1)
    if not np.all(sigma_eig[:, 0] > 0.0):
        raise RuntimeError("Sigma lost positive definiteness")
    if not np.all(rho < p.gamma**2):
        k = int(np.argmax(rho >= p.gamma**2))
        raise RuntimeError(f"coupling condition violated at t = {t[k]}: rho(Sigma Z) = {rho[k]}")
    return {"t": t, "q": q, "q_hat": q_hat, "q_d": qd, "q_e": q - qd, "u": u, "u_d": ud, "w": w,
            "y": y, "sigma_min_eig": sigma_eig[:, 0], "sigma_max_eig": sigma_eig[:, -1],
            "rho_sigma_z": rho, "nfev": nfev, "steps": steps, "intervals": samples}


def compute_metrics(run: dict, p: ref.Problem = PAPER_FIG2) -> dict:
    """The metrics of hinf_cpp.compute_metrics for an output-feedback run: Figure 1's plus
    max rho(Sigma Z) and the RMS estimation error |q_hat - q_e| over the last half."""
    metrics = ref.compute_metrics(run, p)
    t = run["t"]
    last_half = t >= 0.5 * (t[0] + t[-1])
    estimation = np.sum((run["q_hat"] - run["q_e"]) ** 2, axis=1)
    metrics["max_rho_sigma_z"] = float(run["rho_sigma_z"].max())
    metrics["rms_estimation_error_last_half"] = math.sqrt(np.mean(estimation[last_half]))
    return metrics


# --------------------------------------------------------------------------------------------
# the whole run
# --------------------------------------------------------------------------------------------


def run_reference(noise: np.ndarray, p: ref.Problem = PAPER_FIG2,
                  m: Measurement = PAPER_FIG2_MEASUREMENT, grde_method: str = "BDF",
                  loop_method: str = "RK45", rtol: float = 1e-8, atol: float = 1e-10,
                  jacobian: bool = True) -> dict:
    """The whole Figure-2 run, as hinf_cpp.run_scenario does it: trajectory, GRDE
    (``grde_method``, analytic Jacobian for BDF when ``jacobian``), the output-feedback loop
    (``loop_method`` per hold interval), then the analysis (Z(t0), the eigenvalue range of Z
    on the output grid, the metrics)."""
    trajectory = ref.solve_desired_trajectory(p)
    grde = ref.solve_grde(trajectory, p, grde_method, rtol, atol, jacobian)
    run = simulate_output_feedback(trajectory, grde, noise, p, m, loop_method, rtol, atol)
    Z_grid = ref.grde_Z(grde, run["t"])
    eigenvalues = np.linalg.eigvalsh(0.5 * (Z_grid + Z_grid.transpose(0, 2, 1)))
    return {
        "trajectory": trajectory,
        "grde": grde,
        "run": run,
        "Z0": ref.grde_Z0(grde),
        "Z_min_eig": float(eigenvalues.min()),
        "Z_max_eig": float(eigenvalues.max()),
        "metrics": compute_metrics(run, p),
    }


def check_matches_scenario(sc, p: ref.Problem = PAPER_FIG2,
                           m: Measurement = PAPER_FIG2_MEASUREMENT) -> None:
    """Raises AssertionError unless the hinf_cpp Scenario ``sc`` (duck-typed) describes the
    same run as ``p`` and ``m``: Figure 1's checks plus the [measurement] table and C."""
    ref.check_matches_scenario(sc, p)
    ms = sc.measurement
    assert ms is not None, "the scenario has no [measurement]"
    assert (ms.sigma, ms.sample_period, ms.eta, ms.filter_A) == (m.sigma, m.sample_period, m.eta,
                                                                 m.filter_A), \
        "sigma, sample period, eta or filter_A"
    N = np.asarray(ms.N)
    N = N[0, 0] * np.eye(3) if N.size == 1 else N  # a scalar N means N I
    assert np.array_equal(N, m.N) and np.array_equal(ms.Q0, m.Q0), "N or Q0"
    assert np.array_equal(sc.model.C(p.t0), SHIP_C), "C"
    assert list(sc.model.noise_channels()) == NOISE_CHANNELS, "noise channels"


# --------------------------------------------------------------------------------------------
# self-check against hinf_cpp
# --------------------------------------------------------------------------------------------


def _self_check() -> int:
    import time

    import hinf_cpp as hc

    scenario_file = pathlib.Path(__file__).resolve().parents[1] / "scenarios" / "paper_fig2.toml"
    sc = hc.load_scenario(str(scenario_file))
    p, m = PAPER_FIG2, PAPER_FIG2_MEASUREMENT
    check_matches_scenario(sc, p, m)
    noise = hc.scenario_noise(sc)
    failures = 0

    # The split against the library's and against its two defining identities.
    rng = np.random.default_rng(2)
    split_error = identity_error = 0.0
    for _ in range(20):
        qd, qe = rng.standard_normal(6), rng.standard_normal(6)
        A, alpha = ship_error_split(qd, qe, p)
        A_lib, alpha_lib = sc.model.error_split(1.0, qd, np.zeros(sc.model.m()), qe)
        split_error = max(split_error, np.max(np.abs(A - A_lib)), np.max(np.abs(alpha - alpha_lib)))
        fe = ref.ship_f(qd + qe, p) - ref.ship_f(qd, p)
        A0 = ship_error_split(qd, np.zeros(6), p)[0]
        identity_error = max(identity_error, np.max(np.abs(A @ qe + alpha - fe)),
                             np.max(np.abs(A0 - ref.ship_dfdq(qd, p))))
    failures += split_error > 1e-14 or identity_error > 1e-13
    print(f"error split: max |A, alpha - hinf_cpp's| = {split_error:.1e}; "
          f"A q + alpha = f_e and A(0) = A_e to {identity_error:.1e}")

    def compare(label, ours, theirs, seconds, tol):
        nonlocal failures
        run, sim = ours["run"], theirs.simulation
        diffs = {"q": np.max(np.abs(run["q"] - sim.q)),
                 "q_hat": np.max(np.abs(run["q_hat"] - sim.q_hat)),
                 "u": np.max(np.abs(run["u"] - sim.u)),
                 "rho": np.max(np.abs(run["rho_sigma_z"] / sim.rho_sigma_z - 1.0)),
                 "Sigma eig": max(np.max(np.abs(run["sigma_min_eig"] / sim.sigma_min_eig - 1.0)),
                                  np.max(np.abs(run["sigma_max_eig"] / sim.sigma_max_eig - 1.0)))}
        metric_diff = max(abs(value - theirs.metrics[key])
                          for key, value in ours["metrics"].items())
        exact = (np.array_equal(run["w"], sim.w) and np.array_equal(run["t"], sim.t)
                 and np.max(np.abs(run["y"] - sim.y)) <= 1e-14 + 2 * diffs["q"])
        ok = max(diffs["q"], diffs["q_hat"], metric_diff) < tol and exact
        failures += not ok
        print(f"{label}: {seconds:.1f} s, {run['steps']} steps, {run['nfev']} RHS evaluations "
              f"(hinf_cpp: {sim.stats.steps} steps, {sim.stats.rhs_evals} RHS)")
        print("  max |SciPy - hinf_cpp| over the 4001-point grid: "
              + ", ".join(f"{k} {v:.1e}" for k, v in diffs.items() if k in ("q", "q_hat", "u"))
              + f"; relative: rho(Sigma Z) {diffs['rho']:.1e}, Sigma eigenvalues "
              f"{diffs['Sigma eig']:.1e}; metrics {metric_diff:.1e}; w, t identical: {exact}")
        for tk in (0.0, 10.0, 20.0, 40.0):
            k = int(round(tk / p.output_dt))
            for who, value in (("SciPy   ", run["q_hat"][k]), ("hinf_cpp", sim.q_hat[k])):
                print(f"  q_hat({tk:4.1f}) {who} "
                      f"{np.array2string(value, precision=9, max_line_width=200)}")
        final_s = ours["metrics"]["final_position_error"]
        final_c = theirs.metrics["final_position_error"]
        print(f"  final position error SciPy {final_s:.10f}, hinf_cpp {final_c:.10f} "
              f"(diff {abs(final_s - final_c):.1e}); rms last half "
              f"{ours['metrics']['rms_position_error_last_half']:.10f} vs "
              f"{theirs.metrics['rms_position_error_last_half']:.10f}; rms estimation error "
              f"{ours['metrics']['rms_estimation_error_last_half']:.10f} vs "
              f"{theirs.metrics['rms_estimation_error_last_half']:.10f}")
        print(f"  Z eigenvalue range on the grid [{ours['Z_min_eig']:.6f}, {ours['Z_max_eig']:.6f}]"
              f" vs hinf_cpp [{theirs.Z_min_eig:.6f}, {theirs.Z_max_eig:.6f}]; "
              f"{'ok' if ok else 'MISMATCH'} (tolerance {tol:g})")

    # 1. Tight: both sides at rtol 1e-11 -- the same problem to integration accuracy.
    tight = sc.copy()
    tight.solver = hc.SolverOptions(method="erk", rtol=1e-11, atol=1e-13)
    theirs = hc.run_scenario(tight)
    start = time.perf_counter()
    ours = run_reference(noise, p, m, "DOP853", "DOP853", rtol=1e-11, atol=1e-13)
    compare("tight: SciPy DOP853 rtol 1e-11 vs hinf_cpp erk rtol 1e-11", ours, theirs,
            time.perf_counter() - start, 1e-8)

    # 2. The scenario as it is (bdf, rtol 1e-8 / atol 1e-10) against its SciPy twin.
    theirs = hc.run_scenario(sc)
    start = time.perf_counter()
    ours = run_reference(noise, p, m, "BDF", "RK45")
    compare("scenario tolerances: SciPy BDF+jac GRDE, RK45 per interval vs hinf_cpp bdf", ours,
            theirs, time.perf_counter() - start, 1e-6)

    print("SELF-CHECK", "PASSED" if failures == 0 else f"FAILED ({failures})")
    return 1 if failures else 0


if __name__ == "__main__":
    raise SystemExit(_self_check())
