"""Benchmark: the cost of gamma* in units of one GRDE solve on the same trajectory.

    .venv/bin/python benchmarks/bench_gamma_star_ratio.py                # ~1 min
    .venv/bin/python benchmarks/bench_gamma_star_ratio.py --rounds 3 --json benchmarks/results/gamma_star_ratio.json

Problems:
- "paper_fig1": the Figure-1 design (scenarios/paper_fig1.toml), horizon 40 s;
- "sb10fd": SLICOT's SB10FD example system, its state-feedback part
  (tests/data/sb10fd_state_feedback.toml: w = the first three inputs, u = the last two,
  Q = C1'C1, Qf = 1e-9 I, horizon 14.35 s);
- "fleet k": k copies of the paper's ship (`FleetModel`), gamma* of the fleet is the ship's.

For each: `gamma_star` with the default options (rtol 1e-7, 2 threads) and one `solve_grde` at
2 gamma* (the default solver), side by side in interleaved rounds, medians, and the same ratio in
right-hand sides (`GammaStarResult.rhs_evals`, independent of the machine's load); the same gamma*
with `escape_norm = 1e6` (the default before the escape test switched to W at 1e3 times the
solution's scale) to show what the switch buys. The target of the speed issue: gamma* at most
1000 solves. Wall-clock, the load average printed before and after.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # before NumPy: no spinning BLAS threads

import argparse  # noqa: E402
import json  # noqa: E402
import pathlib  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

import hinf_cpp as hc  # noqa: E402

SB10FD = pathlib.Path(__file__).resolve().parents[1] / "tests" / "data" / "sb10fd_state_feedback.toml"


def problems() -> dict:
    """name -> (trajectory, Q, Qf)."""
    out = {}
    sc = hc.load_scenario(hc.scenario_path("paper_fig1"))
    out["paper_fig1"] = (hc.Trajectory(sc.model, sc.desired_q0, sc.desired_u, sc.t0, sc.tf), sc.Q, sc.Qf)
    sb = hc.load_scenario(str(SB10FD))
    out["sb10fd"] = (hc.Trajectory(sb.model, sb.desired_q0, sb.desired_u, sb.t0, sb.tf), sb.Q, sb.Qf)
    for k in (2, 8):
        fleet = hc.FleetModel(sc.model, k)
        out[f"fleet {k}"] = (hc.Trajectory(fleet, np.tile(sc.desired_q0, k), list(sc.desired_u.channels()) * k, sc.t0, sc.tf),
                             np.kron(np.eye(k), sc.Q), np.kron(np.eye(k), sc.Qf))
    return out


def seconds(call) -> float:
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=5, help="interleaved rounds (default 5)")
    parser.add_argument("--json", metavar="OUT", help="save the numbers to this JSON file")
    args = parser.parse_args(argv)
    load_start = os.getloadavg()
    old = hc.GammaStarOptions(solver=hc.SolverOptions(escape_norm=1e6))
    rows = []
    for name, (tr, Q, Qf) in problems().items():
        star = hc.gamma_star(tr, Q, Qf)
        star_old = hc.gamma_star(tr, Q, Qf, old)
        times = {"gamma_star": [], "gamma_star escape_norm 1e6": [], "solve_grde": []}
        for _ in range(args.rounds):
            times["gamma_star"].append(seconds(lambda: hc.gamma_star(tr, Q, Qf)))
            times["gamma_star escape_norm 1e6"].append(seconds(lambda: hc.gamma_star(tr, Q, Qf, old)))
            times["solve_grde"].append(seconds(lambda: hc.solve_grde(tr, Q, Qf, 2.0 * star.gamma_star)))
        median = {key: statistics.median(values) for key, values in times.items()}
        solve_rhs = hc.solve_grde(tr, Q, Qf, 2.0 * star.gamma_star).stats().rhs_evals
        row = {"problem": name, "n": tr.n(), "gamma_star": star.gamma_star, "evaluations": len(star.trials),
               "gamma_star_escape_norm_1e6": star_old.gamma_star, "median_s": median,
               "ratio": median["gamma_star"] / median["solve_grde"],
               "ratio_escape_norm_1e6": median["gamma_star escape_norm 1e6"] / median["solve_grde"],
               "rhs_evals": star.rhs_evals, "rhs_evals_escape_norm_1e6": star_old.rhs_evals,
               "solve_rhs_evals": solve_rhs}
        rows.append(row)
        print(f"{name:<11} n={tr.n():<3} gamma* {star.gamma_star:.9f} ({len(star.trials)} gammas): "
              f"{1e3 * median['gamma_star']:8.1f} ms = {row['ratio']:6.0f} solves "
              f"(one solve {1e3 * median['solve_grde']:.3f} ms); right-hand sides {star.rhs_evals} = "
              f"{star.rhs_evals / solve_rhs:.0f} solves; escape_norm 1e6: "
              f"{1e3 * median['gamma_star escape_norm 1e6']:8.1f} ms = {row['ratio_escape_norm_1e6']:6.0f} solves, "
              f"{star_old.rhs_evals / solve_rhs:.0f} solves' right-hand sides, gamma* {star_old.gamma_star:.9f}",
              flush=True)
    load_end = os.getloadavg()
    print(f"load average {load_start[0]:.2f} before, {load_end[0]:.2f} after; {args.rounds} rounds, medians")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"rows": rows, "load_avg_start": load_start, "load_avg_end": load_end, "rounds": args.rounds,
                       "hinf_cpp": hc.__version__}, fh, indent=2)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
