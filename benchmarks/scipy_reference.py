"""Plain NumPy/SciPy implementation of the paper's Figure-1 run, written as a user would.

This is the baseline that ``bench_paper_fig1.py`` times hinf_cpp against. It does the same
computation as ``hinf_cpp.run_scenario`` on ``scenarios/paper_fig1.toml`` with nothing but
NumPy and :func:`scipy.integrate.solve_ivp`:

1. the desired trajectory q_d(t): the undisturbed ship driven by u_d(t) from q_d0, integrated
   forward with ``solve_ivp(..., dense_output=True)`` at tight tolerances (DOP853, rtol 1e-11,
   atol 1e-12 by default -- the tolerances hinf_cpp's trajectory uses);
2. the GRDE (paper eq. 13) backward from Z(tf) = Qf on all 36 entries of Z,
       dZ/dt = -(A_e' Z + Z A_e + Q - Z (B B' - gamma^-2 D D') Z),   A_e(t) = df/dq(q_d(t)),
   with ``solve_ivp(..., dense_output=True)`` for method "RK45", "DOP853", "BDF" or "LSODA".
   For "BDF" (and "LSODA") the analytic Jacobian of the 36-vector right-hand side is passed
   by default (``jacobian=True``, the Kronecker-product form below, which is what a user who
   bothers to write a Jacobian writes); ``jacobian=False`` leaves SciPy to build it by finite
   differences;
3. the state-feedback closed loop dq/dt = f(q) + B u + D w, u = u_d - kappa B' Z(t) (q - q_d(t)),
   with ``solve_ivp(..., t_eval=output grid)`` (0.01 s grid), and the same metrics as
   ``hinf_cpp.compute_metrics``.

The right-hand sides evaluate q_d(t) and Z(t) through the ``OdeSolution`` dense outputs,
exactly as a user script would. Nothing here imports hinf_cpp except the self-check.

Run ``python benchmarks/scipy_reference.py`` for the self-check against hinf_cpp.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Callable

import numpy as np
from scipy.integrate import solve_ivp

__all__ = [
    "Problem",
    "PAPER_FIG1",
    "ship_f",
    "ship_dfdq",
    "output_grid",
    "solve_desired_trajectory",
    "grde_functions",
    "solve_grde",
    "grde_Z",
    "grde_Z0",
    "simulate_closed_loop",
    "compute_metrics",
    "design_and_run",
    "run_reference",
    "dense_solution_bytes",
    "check_matches_scenario",
]


# --------------------------------------------------------------------------------------------
# The problem: the ship of paper eqs. (1)-(6) and the Figure-1 scenario (docs/scenarios.md)
# --------------------------------------------------------------------------------------------


def _paper_desired_inputs(t: float) -> np.ndarray:
    """u_d(t) = [1, 0.3 sin(0.2 t)]."""
    return np.array([1.0, 0.3 * math.sin(0.2 * t)])


def _paper_disturbance(t: float) -> np.ndarray:
    """w(t): 0.1 cos(2 pi 0.2 t) on w1..w3 (the u, v, r equations); w4..w6 = 0."""
    c = 0.1 * math.cos(2.0 * math.pi * 0.2 * t)
    return np.array([c, c, c, 0.0, 0.0, 0.0])


@dataclasses.dataclass(frozen=True)
class Problem:
    """Everything one run needs. Defaults are the paper's Figure-1 run."""

    m_u: float = 0.5
    m_v: float = -2.0
    m_r: float = 0.5
    d_u: float = 1.0
    d_v: float = 2.0
    d_r: float = 1.0
    t0: float = 0.0
    tf: float = 40.0
    gamma: float = 5.0
    kappa: float = 1.0
    Q: np.ndarray = dataclasses.field(default_factory=lambda: np.eye(6))
    Qf: np.ndarray = dataclasses.field(default_factory=lambda: np.eye(6))
    q_d0: np.ndarray = dataclasses.field(
        default_factory=lambda: np.array([1.0, 0.0, 0.0, 0.0, 0.0, 0.0]))
    q0: np.ndarray = dataclasses.field(
        default_factory=lambda: np.array([1.0, 0.0, 0.0, -1.0, -1.0, math.pi / 4]))
    u_d: Callable[[float], np.ndarray] = _paper_desired_inputs
    w: Callable[[float], np.ndarray] = _paper_disturbance
    output_dt: float = 0.01

    @property
    def B(self) -> np.ndarray:
        """Input matrix [e1, e3] (6x2)."""
        B = np.zeros((6, 2))
        B[0, 0] = 1.0
        B[2, 1] = 1.0
        return B

    @property
    def D(self) -> np.ndarray:
        """Disturbance matrix diag(1, 1, 1, 0, 0, 0)."""
        return np.diag([1.0, 1.0, 1.0, 0.0, 0.0, 0.0])

    @property
    def S(self) -> np.ndarray:
        """S = B B' - gamma^-2 D D' of the GRDE."""
        B, D = self.B, self.D
        return B @ B.T - (D @ D.T) / self.gamma**2


PAPER_FIG1 = Problem()


def ship_f(q: np.ndarray, p: Problem) -> np.ndarray:
    """Drift f(q) of the ship, q = [u, v, r, x, y, psi]."""
    u, v, r, _, _, psi = q
    c, s = math.cos(psi), math.sin(psi)
    return np.array([
        p.m_u * v * r - p.d_u * u,
        p.m_v * u * r - p.d_v * v,
        p.m_r * u * v - p.d_r * r,
        u * c - v * s,
        u * s + v * c,
        r,
    ])


def ship_dfdq(q: np.ndarray, p: Problem) -> np.ndarray:
    """Jacobian df/dq (6x6)."""
    u, v, r, _, _, psi = q
    c, s = math.cos(psi), math.sin(psi)
    J = np.zeros((6, 6))
    J[0, 0], J[0, 1], J[0, 2] = -p.d_u, p.m_u * r, p.m_u * v
    J[1, 0], J[1, 1], J[1, 2] = p.m_v * r, -p.d_v, p.m_v * u
    J[2, 0], J[2, 1], J[2, 2] = p.m_r * v, p.m_r * u, -p.d_r
    J[3, 0], J[3, 1], J[3, 5] = c, -s, -u * s - v * c
    J[4, 0], J[4, 1], J[4, 5] = s, c, u * c - v * s
    J[5, 2] = 1.0
    return J


def output_grid(t0: float, tf: float, dt: float) -> np.ndarray:
    """t0, t0 + dt, ..., and tf last (the grid of hinf_cpp.output_grid)."""
    count = math.ceil((tf - t0) / dt - 1e-9)
    return np.append(t0 + dt * np.arange(count), tf)


# --------------------------------------------------------------------------------------------
# 1. desired trajectory
# --------------------------------------------------------------------------------------------


def solve_desired_trajectory(p: Problem = PAPER_FIG1, method: str = "DOP853",
                             rtol: float = 1e-11, atol: float = 1e-12):
    """Forward solve of dq_d/dt = f(q_d) + B u_d(t); returns the solve_ivp result (``.sol``
    is the dense output q_d(t))."""
    B = p.B

    def rhs(t, q):
        return ship_f(q, p) + B @ p.u_d(t)

    result = solve_ivp(rhs, (p.t0, p.tf), p.q_d0, method=method, rtol=rtol, atol=atol,
                       dense_output=True)
    if not result.success:
        raise RuntimeError(f"desired trajectory: {result.message}")
    return result


# --------------------------------------------------------------------------------------------
# 2. the GRDE, backward, on the 36 entries of Z
# --------------------------------------------------------------------------------------------


def grde_functions(trajectory, p: Problem = PAPER_FIG1):
    """The right-hand side rhs(t, z) of the GRDE on Z raveled row-major (36 numbers) and its
    analytic Jacobian jac(t, z) (36 x 36)."""
    n = 6
    q_d = trajectory.sol
    S, Q = p.S, p.Q
    I = np.eye(n)

    def rhs(t, z):
        Z = z.reshape(n, n)
        A = ship_dfdq(q_d(t), p)
        return -(A.T @ Z + Z @ A + Q - Z @ S @ Z).ravel()

    def jac(t, z):
        # d/dZ of -(A'Z + ZA + Q - ZSZ) with row-major vec: vec(X dZ Y) = (X kron Y') vec(dZ).
        Z = z.reshape(n, n)
        A = ship_dfdq(q_d(t), p)
        return -(np.kron(A.T, I) + np.kron(I, A.T) - np.kron(I, (S @ Z).T) - np.kron(Z @ S, I))

    return rhs, jac


def solve_grde(trajectory, p: Problem = PAPER_FIG1, method: str = "RK45", rtol: float = 1e-8,
               atol: float = 1e-10, jacobian: bool = True):
    """Backward solve of the GRDE from Z(tf) = Qf to t0 with solve_ivp.

    ``trajectory`` is the result of :func:`solve_desired_trajectory`. The state is Z raveled
    row-major (36 numbers). ``jacobian`` matters only for the implicit methods ("BDF",
    "Radau", "LSODA"): True passes the analytic Jacobian, False lets SciPy difference.
    Returns the solve_ivp result; ``.sol(t)`` is the dense Z(t) (raveled).
    """
    rhs, jac = grde_functions(trajectory, p)
    kwargs = {}
    if jacobian and method in ("BDF", "Radau", "LSODA"):
        kwargs["jac"] = jac
    result = solve_ivp(rhs, (p.tf, p.t0), p.Qf.ravel(), method=method, rtol=rtol, atol=atol,
                       dense_output=True, **kwargs)
    if not result.success:
        raise RuntimeError(f"GRDE ({method}): {result.message}")
    return result


def grde_Z(grde, t) -> np.ndarray:
    """Z(t) from the dense GRDE solution: (6, 6) for a number, (len(t), 6, 6) for an array."""
    values = grde.sol(t)
    if np.ndim(t) == 0:
        return values.reshape(6, 6)
    return values.T.reshape(-1, 6, 6)


def grde_Z0(grde) -> np.ndarray:
    """Z(t0): the last point of the backward solve."""
    return grde.y[:, -1].reshape(6, 6)


# --------------------------------------------------------------------------------------------
# 3. the closed loop
# --------------------------------------------------------------------------------------------


def simulate_closed_loop(trajectory, grde, p: Problem = PAPER_FIG1, method: str = "RK45",
                         rtol: float = 1e-8, atol: float = 1e-10, jacobian: bool = True) -> dict:
    """State-feedback closed loop u = u_d - kappa B' Z(t) (q - q_d(t)) under the disturbance,
    sampled on the output grid. Returns a dict of arrays (one row per time): t, q, q_d, q_e, u,
    u_d, w, plus the solve_ivp statistics nfev / njev / nlu."""
    q_d, Z_of = trajectory.sol, grde.sol
    B, D, kappa = p.B, p.D, p.kappa
    BT = B.T

    def rhs(t, q):
        Z = Z_of(t).reshape(6, 6)
        u = p.u_d(t) - kappa * (BT @ (Z @ (q - q_d(t))))
        return ship_f(q, p) + B @ u + D @ p.w(t)

    def jac(t, q):
        Z = Z_of(t).reshape(6, 6)
        return ship_dfdq(q, p) - kappa * (B @ (BT @ Z))

    kwargs = {}
    if jacobian and method in ("BDF", "Radau", "LSODA"):
        kwargs["jac"] = jac
    grid = output_grid(p.t0, p.tf, p.output_dt)
    result = solve_ivp(rhs, (p.t0, p.tf), p.q0, method=method, rtol=rtol, atol=atol,
                       t_eval=grid, **kwargs)
    if not result.success:
        raise RuntimeError(f"closed loop ({method}): {result.message}")

    t = result.t
    q = result.y.T
    qd = q_d(t).T
    Zt = Z_of(t).T.reshape(-1, 6, 6)
    ud = np.array([p.u_d(tk) for tk in t])
    q_e = q - qd
    u = ud - kappa * np.einsum("ij,kjl,kl->ki", BT, Zt, q_e)
    w = np.array([p.w(tk) for tk in t])
    return {"t": t, "q": q, "q_d": qd, "q_e": q_e, "u": u, "u_d": ud, "w": w,
            "nfev": result.nfev, "njev": result.njev, "nlu": result.nlu}


def compute_metrics(run: dict, p: Problem = PAPER_FIG1) -> dict:
    """The state-feedback metrics of docs/scenarios.md (trapezoid integrals on the grid)."""
    t, q_e = run["t"], run["q_e"]
    u_e = run["u"] - run["u_d"]
    position_error = np.hypot(q_e[:, 3], q_e[:, 4])
    last_half = t >= 0.5 * (t[0] + t[-1])

    def l2(series):
        return math.sqrt(np.trapezoid(np.sum(series**2, axis=1), t))

    disturbance_l2 = l2(run["w"])
    performance = np.einsum("ki,ij,kj->k", q_e, p.Q, q_e) + np.sum(u_e**2, axis=1)
    return {
        "rms_position_error_last_half": math.sqrt(np.mean(position_error[last_half] ** 2)),
        "max_position_error": float(position_error.max()),
        "final_position_error": float(position_error[-1]),
        "control_l2": l2(run["u"]),
        "control_error_l2": l2(u_e),
        "disturbance_l2": disturbance_l2,
        # The cost of eq. (37), its terminal term included.
        "response_ratio": math.sqrt(np.trapezoid(performance, t) + q_e[-1] @ p.Qf @ q_e[-1]) / disturbance_l2,
    }


# --------------------------------------------------------------------------------------------
# whole runs
# --------------------------------------------------------------------------------------------


def design_and_run(p: Problem = PAPER_FIG1, method: str = "RK45", rtol: float = 1e-8,
                   atol: float = 1e-10, jacobian: bool = True):
    """Trajectory + GRDE + closed loop (the 'design + closed-loop run' of the benchmark)."""
    trajectory = solve_desired_trajectory(p)
    grde = solve_grde(trajectory, p, method, rtol, atol, jacobian)
    run = simulate_closed_loop(trajectory, grde, p, method, rtol, atol, jacobian)
    return trajectory, grde, run


def run_reference(p: Problem = PAPER_FIG1, method: str = "RK45", rtol: float = 1e-8,
                  atol: float = 1e-10, jacobian: bool = True) -> dict:
    """The whole run, as hinf_cpp.run_scenario does it: design, closed loop, then the analysis
    (Z(t0), the eigenvalue range of Z over the output grid, the metrics)."""
    trajectory, grde, run = design_and_run(p, method, rtol, atol, jacobian)
    Z_grid = grde_Z(grde, run["t"])
    eigenvalues = np.linalg.eigvalsh(0.5 * (Z_grid + Z_grid.transpose(0, 2, 1)))
    return {
        "trajectory": trajectory,
        "grde": grde,
        "run": run,
        "Z0": grde_Z0(grde),
        "Z_min_eig": float(eigenvalues.min()),
        "Z_max_eig": float(eigenvalues.max()),
        "metrics": compute_metrics(run, p),
    }


def dense_solution_bytes(result) -> int:
    """Bytes of NumPy data held by a solve_ivp dense output (``result.sol``): the breakpoints
    and every array attribute of every step interpolant. Python object overhead (about
    50-100 bytes per interpolant object and its dict) is not counted."""
    sol = result.sol
    total = sol.ts.nbytes
    for interpolant in sol.interpolants:
        for value in vars(interpolant).values():
            if isinstance(value, np.ndarray):
                total += value.nbytes
    return total


def check_matches_scenario(sc, p: Problem = PAPER_FIG1) -> None:
    """Raises AssertionError unless the hinf_cpp Scenario ``sc`` (duck-typed; hinf_cpp is not
    imported here) describes the same run as ``p``: parameters, horizon, weights, initial
    states, and u_d, w, kappa sampled at 17 times."""
    mp = sc.model.parameters
    assert (mp.m_u, mp.m_v, mp.m_r, mp.d_u, mp.d_v, mp.d_r) == (p.m_u, p.m_v, p.m_r, p.d_u,
                                                                 p.d_v, p.d_r), "ship parameters"
    assert (sc.t0, sc.tf, sc.gamma, sc.output_dt) == (p.t0, p.tf, p.gamma, p.output_dt), \
        "horizon, gamma or output dt"
    assert np.array_equal(sc.Q, p.Q) and np.array_equal(sc.Qf, p.Qf), "Q or Qf"
    assert np.allclose(sc.desired_q0, p.q_d0) and np.allclose(sc.initial_q0, p.q0), "q_d0 or q0"
    probe = np.linspace(p.t0, p.tf, 17)
    assert np.allclose(sc.desired_u(probe), [p.u_d(t) for t in probe], atol=1e-14), "u_d"
    assert np.allclose(sc.disturbance(probe), [p.w(t) for t in probe], atol=1e-14), "w"
    assert np.allclose(np.ravel(sc.kappa(probe)), p.kappa, atol=0), "kappa"


# --------------------------------------------------------------------------------------------
# self-check against hinf_cpp
# --------------------------------------------------------------------------------------------


def _self_check() -> int:
    import pathlib
    import time

    import hinf_cpp as hc

    scenario_file = pathlib.Path(__file__).resolve().parents[1] / "scenarios" / "paper_fig1.toml"
    sc = hc.load_scenario(str(scenario_file))
    p = PAPER_FIG1

    check_matches_scenario(sc, p)

    # The analytic GRDE Jacobian against central differences.
    probe = np.linspace(p.t0, p.tf, 17)
    trajectory = solve_desired_trajectory(p)
    tr = hc.Trajectory(sc.model, sc.desired_q0, sc.desired_u, sc.t0, sc.tf)
    traj_error = np.max(np.abs(trajectory.sol(probe).T - tr.q_d(probe)))
    print(f"desired trajectory: max |q_d SciPy - q_d hinf_cpp| on 17 times = {traj_error:.2e}")

    failures = 0
    rhs, jac = grde_functions(trajectory, p)
    rng = np.random.default_rng(1)
    Zs = rng.standard_normal((6, 6))
    z, t, h = (Zs + Zs.T).ravel(), 12.3, 1e-6
    fd = np.column_stack([(rhs(t, z + h * e) - rhs(t, z - h * e)) / (2 * h) for e in np.eye(36)])
    jac_error = np.max(np.abs(jac(t, z) - fd))
    failures += jac_error > 1e-6
    print(f"analytic GRDE Jacobian vs central differences: max error {jac_error:.1e}"
          f"{'' if jac_error <= 1e-6 else '  MISMATCH'}")
    pairs = [("RK45", "erk", True), ("DOP853", "erk", True), ("BDF", "bdf", True),
             ("BDF", "bdf", False), ("LSODA", "adams", True)]
    print(f"{'SciPy method':<20} {'hinf_cpp':<8} {'max|dZ(t0)|':>12} {'final pos err SciPy':>20} "
          f"{'hinf_cpp':>12} {'diff':>9} {'SciPy s':>8}")
    for method, cpp_method, jacobian in pairs:
        options = hc.SolverOptions(method=cpp_method, rtol=1e-8, atol=1e-10)
        sol = hc.solve_grde(tr, sc.Q, sc.Qf, sc.gamma, options)
        sim = hc.simulate_state_feedback(tr, hc.HinfStateFeedback(sol, sc.kappa), sc.disturbance,
                                         sc.initial_q0, sc.output_dt, options)
        start = time.perf_counter()
        grde = solve_grde(trajectory, p, method, jacobian=jacobian)
        run = simulate_closed_loop(trajectory, grde, p, method, jacobian=jacobian)
        seconds = time.perf_counter() - start
        dZ0 = np.max(np.abs(grde_Z0(grde) - sol.Z(sc.t0)))
        final_scipy = compute_metrics(run, p)["final_position_error"]
        final_cpp = float(np.hypot(*sim.q_e[-1, 3:5]))
        ok = dZ0 < 1e-6 and abs(final_scipy - final_cpp) < 1e-6
        failures += not ok
        label = method + ("" if jacobian or method != "BDF" else " (FD jac)")
        print(f"{label:<20} {cpp_method:<8} {dZ0:12.2e} {final_scipy:20.10f} {final_cpp:12.10f} "
              f"{abs(final_scipy - final_cpp):9.1e} {seconds:8.2f}  {'ok' if ok else 'MISMATCH'}")

    # Whole run vs run_scenario (metrics).
    result = hc.run_scenario(sc)
    ref = run_reference(p, "BDF")
    for key, value in ref["metrics"].items():
        if abs(value - result.metrics[key]) > 1e-6 * max(1.0, abs(value)):
            print(f"metric {key}: SciPy {value} vs hinf_cpp {result.metrics[key]}  MISMATCH")
            failures += 1
    print(f"metrics of run_reference vs run_scenario: "
          f"{'all agree to 1e-6' if not failures else 'see above'}; "
          f"rms last half {ref['metrics']['rms_position_error_last_half']:.6f}, "
          f"Z eig range [{ref['Z_min_eig']:.4f}, {ref['Z_max_eig']:.4f}] vs "
          f"[{result.Z_min_eig:.4f}, {result.Z_max_eig:.4f}]")
    print("SELF-CHECK", "PASSED" if failures == 0 else f"FAILED ({failures})")
    return 1 if failures else 0


if __name__ == "__main__":
    raise SystemExit(_self_check())
