"""Benchmark: how the cost of a GRDE solve grows with the state size, against SciPy's LSODA.

    .venv/bin/python benchmarks/bench_riccati_scaling.py                 # full (a few minutes)
    .venv/bin/python benchmarks/bench_riccati_scaling.py --quick         # smoke test
    .venv/bin/python benchmarks/bench_riccati_scaling.py --json benchmarks/results/riccati_scaling.json

Problems (every random matrix from numpy.random.default_rng(seed)):
- "random": random stable LTI systems of n = 6, 12, 24, 48 states, m = max(1, n // 3) inputs,
  A = M - (max Re eig(M) + 0.5) I with M standard normal / sqrt(n) (slowest mode -0.5),
  gamma = inf, Q = Qf = I, horizon 20.
- "stiff": the random system of 24 states with one more mode 1e4 times faster than the
  horizon: A - (1e4 / 20) v v' for a random unit vector v (an eigenvalue near -500).
- "fleet": the paper's ship linearized along the Figure-1 trajectory (time-varying A_e(t)),
  stacked into a block-diagonal fleet of 2, 4 and 8 ships (n = 12, 24, 48; hc.FleetModel),
  gamma = 5, Q = Qf = I, horizon 40.

Methods, all at rtol 1e-8 / atol 1e-10:
- hinf_cpp "auto" (the default: Dormand-Prince until a stiffness test fires, then BDF),
  "erk" (Dormand-Prince 5(4)), "bdf" (CVODE BDF; Newton systems as Lyapunov equations from
  8 states, "newton_systems = auto"), "bdf dense" (the packed n(n+1)/2 Jacobian and LU, up
  to 24 states: 18 s per solve at 48);
- SciPy: ``solve_ivp(method="LSODA")`` on the matrix equation with the n x n Z flattened,
  backward from tf, with A(t) from the same trajectory object for the fleet: the code a user
  would write.

Accuracy: max |Z(t0) - Z_ref(t0)| / max |Z_ref(t0)| against hinf_cpp "erk" at rtol 1e-12 /
atol 1e-14 (for the stiff case "bdf" at the same tolerances), the error of each method at equal
tolerances. Timing: wall-clock around one call, median [min-max] of repeated calls (at least 3,
more while the total stays under about a second), garbage collector off; the machine is shared,
so compare medians side by side in one process.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # before NumPy: no spinning BLAS threads

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import pathlib  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
import scipy  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

import hinf_cpp as hc  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from bench_paper_fig1 import cpu_model, ms, timed  # noqa: E402

RTOL, ATOL = 1e-8, 1e-10
REF_RTOL, REF_ATOL = 1e-12, 1e-14
SIZES = (6, 12, 24, 48)
FLEETS = (2, 4, 8)
DENSE_MAX = 24  # "bdf dense" beyond this takes tens of seconds per solve
STIFF_N = 24
STIFF_FACTOR = 1e4  # the fast mode's rate times the horizon


def random_stable(n: int, seed: int, horizon: float, stiff: bool = False):
    rng = np.random.default_rng(seed)
    M = rng.standard_normal((n, n)) / math.sqrt(n)
    A = M - (np.max(np.linalg.eigvals(M).real) + 0.5) * np.eye(n)
    if stiff:
        v = rng.standard_normal(n)
        v /= np.linalg.norm(v)
        A = A - (STIFF_FACTOR / horizon) * np.outer(v, v)
    B = rng.standard_normal((n, max(1, n // 3)))
    D = rng.standard_normal((n, 1))
    model = hc.LinearModel(A, B, D)
    trajectory = hc.Trajectory(model, np.zeros(n), [0.0] * B.shape[1], 0.0, horizon)
    return {"trajectory": trajectory, "A": lambda t: A, "S": B @ B.T, "gamma": math.inf, "n": n}


def ship_fleet(count: int):
    ship = hc.ShipModel()
    u_d = [hc.Signal(1.0), hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    q_d0 = np.tile([1.0, 0.0, 0.0, 0.0, 0.0, 0.0], count)
    trajectory = hc.Trajectory(hc.FleetModel(ship, count), q_d0, u_d * count, 0.0, 40.0)
    gamma = 5.0
    model = trajectory.model()
    q = np.zeros(model.n())
    B, D = model.G(0.0, q), model.D(0.0, q)
    return {"trajectory": trajectory, "A": trajectory.A_e, "S": B @ B.T - D @ D.T / gamma**2,
            "gamma": gamma, "n": 6 * count}


def options(method: str) -> hc.SolverOptions:
    if method == "bdf dense":
        return hc.SolverOptions("bdf", rtol=RTOL, atol=ATOL, newton_systems="dense")
    return hc.SolverOptions(method, rtol=RTOL, atol=ATOL)


def cpp_solve(problem, method: str):
    n = problem["n"]
    return hc.solve_grde(problem["trajectory"], np.eye(n), np.eye(n), problem["gamma"], options(method))


def scipy_solve(problem):
    """Z(t0) by LSODA on the flattened n x n matrix equation, integrated from tf to t0."""
    n, A_of, S = problem["n"], problem["A"], problem["S"]
    Q = np.eye(n)
    tr = problem["trajectory"]

    def rhs(t, z):
        Z = z.reshape(n, n)
        A = A_of(t)
        return -(A.T @ Z + Z @ A - Z @ S @ Z + Q).ravel()

    sol = solve_ivp(rhs, (tr.tf(), tr.t0()), np.eye(n).ravel(), method="LSODA", rtol=RTOL, atol=ATOL)
    if not sol.success:
        raise RuntimeError(sol.message)
    Z = sol.y[:, -1].reshape(n, n)
    return 0.5 * (Z + Z.T), sol.nfev


def repeats_for(seconds_once: float, quick: bool) -> int:
    if quick:
        return 1
    return int(min(15, max(3, 1.0 / max(seconds_once, 1e-6))))


def measure(problem, methods, quick: bool, reference_method: str = "erk") -> dict:
    n = problem["n"]
    t0 = problem["trajectory"].t0()
    ref_options = hc.SolverOptions(reference_method, rtol=REF_RTOL, atol=REF_ATOL)
    Z_ref = hc.solve_grde(problem["trajectory"], np.eye(n), np.eye(n), problem["gamma"], ref_options).Z(t0)
    scale = np.max(np.abs(Z_ref))
    row = {"n": n, "methods": {}}
    for method in methods:
        start = time.perf_counter()
        sol = cpp_solve(problem, method)
        once = time.perf_counter() - start
        row["methods"][method] = {
            "time": timed(lambda: cpp_solve(problem, method), repeats_for(once, quick), warmup=0),
            "error": float(np.max(np.abs(sol.Z(t0) - Z_ref)) / scale),
            "steps": sol.stats().steps, "rhs_evals": sol.stats().rhs_evals,
            "jac_evals": sol.stats().jac_evals, "memory_bytes": sol.stats().memory_bytes,
            "used": sol.stats().method}
    start = time.perf_counter()
    Z_scipy, nfev = scipy_solve(problem)
    once = time.perf_counter() - start
    row["methods"]["scipy lsoda"] = {
        "time": timed(lambda: scipy_solve(problem), repeats_for(once, quick), warmup=0),
        "error": float(np.max(np.abs(Z_scipy - Z_ref)) / scale), "rhs_evals": int(nfev)}
    return row


def print_rows(title: str, rows: list, methods: list) -> None:
    print(f"\n{title}")
    head = f"{'n':>3} " + " ".join(f"{m:>22}" for m in methods + ["scipy lsoda"])
    print(head + "   default/LSODA  bdf/LSODA")
    for row in rows:
        cells = []
        for m in methods + ["scipy lsoda"]:
            r = row["methods"].get(m)
            cells.append(f"{1e3 * r['time']['median']:>11.2f} ms {r['error']:7.1e}" if r else f"{'-':>22}")
        lsoda = row["methods"]["scipy lsoda"]["time"]["median"]
        ratio_default = lsoda / row["methods"]["auto"]["time"]["median"]
        ratio_bdf = lsoda / row["methods"]["bdf"]["time"]["median"]
        print(f"{row['n']:>3} " + " ".join(cells) + f"   {ratio_default:12.1f}x {ratio_bdf:9.1f}x")
    print("  (each cell: median time, relative error of Z(t0) against the tight reference)")


def growth(rows: list, method: str, n_from: int, n_to: int) -> float:
    by_n = {row["n"]: row["methods"][method]["time"]["median"] for row in rows if method in row["methods"]}
    return math.log(by_n[n_to] / by_n[n_from]) / math.log(n_to / n_from)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one call per cell, n up to 24")
    parser.add_argument("--json", type=pathlib.Path, help="write every number to this file")
    args = parser.parse_args(argv)
    sizes = SIZES[:3] if args.quick else SIZES
    fleets = FLEETS[:2] if args.quick else FLEETS
    out = {"machine": {"cpu": cpu_model(), "python": platform.python_version(), "numpy": np.__version__,
                       "scipy": scipy.__version__, "load_average": os.getloadavg()},
           "rtol": RTOL, "atol": ATOL}

    methods = ["auto", "erk", "bdf", "bdf dense"]
    random_rows = []
    for n in sizes:
        use = [m for m in methods if m != "bdf dense" or n <= DENSE_MAX]
        random_rows.append(measure(random_stable(n, seed=n, horizon=20.0), use, args.quick))
        print(f"  random n = {n} done", flush=True)
    print_rows("Random stable LTI, gamma = inf, horizon 20", random_rows, methods)

    stiff = measure(random_stable(STIFF_N, seed=STIFF_N, horizon=20.0, stiff=True), ["auto", "erk", "bdf"],
                    args.quick, reference_method="bdf")
    print_rows(f"Stiff: n = {STIFF_N} with a mode {STIFF_FACTOR:.0e} times faster than the horizon", [stiff],
               ["auto", "erk", "bdf"])

    fleet_rows = []
    for count in fleets:
        fleet_rows.append(measure(ship_fleet(count), ["auto", "erk", "bdf"], args.quick))
        print(f"  fleet of {count} done", flush=True)
    print_rows("Fleet of ships (time-varying A_e(t)), gamma = 5, horizon 40", fleet_rows, ["auto", "erk", "bdf"])

    summary = {}
    if not args.quick:
        summary = {m: growth(random_rows, m, 12, 48) for m in ("auto", "erk", "bdf", "scipy lsoda")}
        print("\nGrowth of the time from n = 12 to 48 (exponent p of n^p): "
              + ", ".join(f"{m} {p:.2f}" for m, p in summary.items()))
    s = stiff["methods"]
    print(f"Stiff case: bdf {s['erk']['time']['median'] / s['bdf']['time']['median']:.1f}x faster than erk; "
          f"auto used: {s['auto']['used']}")
    out.update({"random": random_rows, "stiff": stiff, "fleet": fleet_rows, "growth_12_to_48": summary})
    if args.json:
        args.json.write_text(json.dumps(out, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
