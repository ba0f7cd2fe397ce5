"""Benchmark: gamma* by hinf_cpp.gamma_star against a plain SciPy bisection (Figure-1 problem).

    .venv/bin/python benchmarks/bench_gamma_star.py                  # full (about 45 s)
    .venv/bin/python benchmarks/bench_gamma_star.py --quick          # smoke test (~20 s)
    .venv/bin/python benchmarks/bench_gamma_star.py --repeat 100 --scipy-repeat 5 --json out.json

gamma* (paper eq. 14) is the smallest gamma for which the GRDE (13) has no conjugate point on
[t0, tf]. It is computed on scenarios/paper_fig1.toml (Q = Qf = I, horizon [0, 40]) to a
relative tolerance of 1e-6 on the final bracket. The scenario is first checked to be the same
problem as ``scipy_reference.PAPER_FIG1``.

- hinf_cpp: ``hc.gamma_star(trajectory, Q, Qf, GammaStarOptions(threads=k, solver=...))``
  with the solver "bdf" (the default, CVODE BDF) and "erk" (Dormand-Prince 5(4)), each with
  threads = 1 (bisection) and threads = 2 (the default: two gammas per round, evaluated in
  parallel, which splits the bracket into thirds). The bracket is the automatic one (from 1,
  doubling). There are 3 warm-up calls, then --repeat timed calls.
- SciPy: ``scipy_gamma_star.gamma_star``, the same bracket and bisection with
  ``solve_ivp`` RK45, DOP853 and BDF (analytic Jacobian). Each gamma gets the threshold event
  on Z, and the crossing is confirmed by the inverse W = Z^-1 (see that file). There is one
  untimed run for the results, then --scipy-repeat timed runs.
- Both sides get the desired trajectory already built, and both use the GRDE tolerances
  rtol 1e-8 / atol 1e-10 and an escape threshold of 1e6 * max(1, |Qf|_max).

Timings are wall-clock (time.perf_counter) around one Python call, with the garbage collector
off during the timed loops. Each is reported as median [min-max]. OPENBLAS_NUM_THREADS=1 is
set before NumPy is imported. Targets: gamma* in under 100 ms with the default solver (bdf)
and in under 20 ms with the explicit one (erk).
"""

from __future__ import annotations

import os

# Tiny (6x6, 36x36) matrices only: keep OpenBLAS from parking spinning threads on the second
# core of a 2-core machine (which threads=2 needs). Must precede the NumPy import.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import pathlib  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
import scipy  # noqa: E402

import hinf_cpp as hc  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import scipy_gamma_star as sgs  # noqa: E402
from bench_paper_fig1 import core_fingerprint, cpu_model, ms, s_, timed  # noqa: E402
import scipy_reference as ref  # noqa: E402

SCENARIO = pathlib.Path(__file__).resolve().parents[1] / "scenarios" / "paper_fig1.toml"
RTOL, ATOL = 1e-8, 1e-10  # GRDE tolerances (the scenario's and GammaStarOptions' defaults)
RTOL_GAMMA = 1e-6         # final bracket: upper - lower <= RTOL_GAMMA * upper

TARGET_MS = {"bdf": 100.0, "erk": 20.0}

CPP_CONFIGS = [("bdf", 1), ("bdf", 2), ("erk", 1), ("erk", 2)]  # (solver, threads)
SCIPY_METHODS = ["RK45", "DOP853", "BDF"]
# (SciPy method, hinf_cpp solver, why this pairing)
PAIRS = [
    ("RK45", "erk", "same method: Dormand-Prince 5(4)"),
    ("DOP853", "erk", "SciPy's fastest explicit option here"),
    ("BDF", "bdf", "variable-order BDF with the analytic Jacobian on both sides"),
]


def bracket_evaluations(gammas) -> int:
    """How many leading evaluations belong to the automatic bracket (gamma = 1, 2, 4, ... or
    1, 1/2, ...); they run one at a time whatever the thread count."""
    count = 0
    for g in gammas:
        if g > 0 and math.log2(g).is_integer():
            count += 1
        else:
            break
    return count


# ---------------------------------------------------------------------------------------------
# the benchmark
# ---------------------------------------------------------------------------------------------


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=30,
                        help="timed repetitions of each hinf_cpp measurement (default 30)")
    parser.add_argument("--scipy-repeat", type=int, default=3,
                        help="timed repetitions of each SciPy bisection (default 3)")
    parser.add_argument("--quick", action="store_true",
                        help="smoke test: --repeat 5 --scipy-repeat 1")
    parser.add_argument("--json", metavar="OUT", help="save all numbers to this JSON file")
    args = parser.parse_args(argv)
    if args.quick:
        args.repeat, args.scipy_repeat = 5, 1
    N, M = args.repeat, args.scipy_repeat

    out: dict = {
        "machine": {"python": platform.python_version(), "numpy": np.__version__,
                    "scipy": scipy.__version__, "hinf_cpp": hc.__version__,
                    "processor": cpu_model(), "cpus": os.cpu_count(),
                    "load_avg_start": os.getloadavg(), "hinf_cpp_core": core_fingerprint()},
        "settings": {"grde_rtol": RTOL, "grde_atol": ATOL, "gamma_rtol": RTOL_GAMMA,
                     "escape_norm": sgs.ESCAPE_NORM, "bracket": "automatic (from 1, doubling)",
                     "cpp_repeat": N, "cpp_warmup": 3, "scipy_repeat": M,
                     "gc_disabled_while_timing": True,
                     "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS")},
    }
    core = out["machine"]["hinf_cpp_core"]
    print(f"hinf_cpp {hc.__version__} (_core sha256 {core['sha256']}, built {core['mtime']} UTC) "
          f"vs NumPy {np.__version__} / SciPy {scipy.__version__}, "
          f"Python {platform.python_version()}, {os.cpu_count()} CPUs, "
          f"load average {os.getloadavg()[0]:.2f}")
    print(f"scenario {SCENARIO.name}: gamma* to rtol {RTOL_GAMMA:g} on the bracket, GRDE rtol "
          f"{RTOL:g} / atol {ATOL:g}; hinf_cpp x{N}, SciPy x{M}; times are median [min-max]\n")

    sc = hc.load_scenario(str(SCENARIO))
    p = ref.PAPER_FIG1
    ref.check_matches_scenario(sc, p)
    tr = hc.Trajectory(sc.model, sc.desired_q0, sc.desired_u, sc.t0, sc.tf)
    scipy_traj = ref.solve_desired_trajectory(p)

    # ---- hinf_cpp ----
    print("hinf_cpp.gamma_star ...", flush=True)
    cpp = {}
    for method, threads in CPP_CONFIGS:
        options = hc.GammaStarOptions(rtol=RTOL_GAMMA, threads=threads,
                                      solver=hc.SolverOptions(method=method, rtol=RTOL,
                                                              atol=ATOL))
        r = hc.gamma_star(tr, sc.Q, sc.Qf, options)
        timing = timed(lambda: hc.gamma_star(tr, sc.Q, sc.Qf, options), N, warmup=3)
        gammas = [t.gamma for t in r.trials]
        n_bracket = bracket_evaluations(gammas)
        cpp[(method, threads)] = {
            "solver": method, "threads": threads, "time": timing,
            "evaluations": len(r.trials),
            # Sequential depth: bracket steps one by one, then rounds of `threads` gammas.
            "rounds": n_bracket + math.ceil((len(r.trials) - n_bracket) / threads),
            "gamma_star": r.gamma_star, "lower": r.lower, "upper": r.upper,
            "t_escape_lower": r.t_escape_lower, "converged": r.converged,
            "trials": [{"gamma": t.gamma, "passed": t.passed, "t_escape": t.t_escape}
                       for t in r.trials],
        }
        print(f"  {method} threads={threads}: {ms(timing)} ms, {len(r.trials)} evaluations, "
              f"gamma* = {r.gamma_star:.9f}", flush=True)
    default_options = hc.GammaStarOptions()
    whole = hc.scenario_gamma_star(sc, default_options)
    whole_timing = timed(lambda: hc.scenario_gamma_star(sc, default_options), N, warmup=3)
    out["cpp_scenario_gamma_star"] = {
        "options": repr(default_options), "time": whole_timing,
        "evaluations": len(whole.trials), "gamma_star": whole.gamma_star}
    print(f"  scenario_gamma_star (default options, trajectory built inside): "
          f"{ms(whole_timing)} ms, gamma* = {whole.gamma_star:.9f}", flush=True)
    out["cpp"] = list(cpp.values())

    # ---- SciPy ----
    print("\nSciPy bisection (scipy_gamma_star.gamma_star) ...", flush=True)
    sp = {}
    for method in SCIPY_METHODS:
        start = time.perf_counter()
        r = sgs.gamma_star(scipy_traj, p, method, RTOL_GAMMA, rtol=RTOL, atol=ATOL)
        first_run = time.perf_counter() - start
        timing = timed(lambda: sgs.gamma_star(scipy_traj, p, method, RTOL_GAMMA, rtol=RTOL,
                                              atol=ATOL), M, warmup=0)
        sp[method] = {
            "method": method, "time": timing, "untimed_first_run_s": first_run,
            "evaluations": len(r.trials), "rhs_evals": int(sum(t.nfev for t in r.trials)),
            "gamma_star": r.gamma_star, "lower": r.lower, "upper": r.upper,
            "t_escape_lower": r.t_escape_lower, "converged": r.converged,
            "confirmed_by_inverse": sum(t.how == "large Z, W reached t0" for t in r.trials),
            "trials": [{"gamma": t.gamma, "escaped": t.escaped, "t_escape": t.t_escape,
                        "how": t.how, "nfev": t.nfev} for t in r.trials],
        }
        print(f"  {method}: {s_(timing)} s, {len(r.trials)} evaluations, "
              f"gamma* = {r.gamma_star:.9f}", flush=True)
    out["scipy"] = list(sp.values())

    # The naive escape test (threshold crossing = escape), untimed: the bias it would cause.
    naive = sgs.gamma_star(scipy_traj, p, "RK45", RTOL_GAMMA, rtol=RTOL, atol=ATOL,
                           confirm=False)
    out["scipy_threshold_only"] = {"method": "RK45", "gamma_star": naive.gamma_star,
                                   "lower": naive.lower, "upper": naive.upper,
                                   "evaluations": len(naive.trials)}

    # ---- ratios, agreement ----
    rows = []
    for method, cpp_method, why in PAIRS:
        s = sp[method]
        rows.append({
            "scipy_method": method, "cpp_solver": cpp_method, "why": why,
            "ratio_threads1": s["time"]["median"] / cpp[(cpp_method, 1)]["time"]["median"],
            "ratio_threads2": s["time"]["median"] / cpp[(cpp_method, 2)]["time"]["median"],
        })
    out["ratios"] = rows

    reference = cpp[("bdf", 1)]
    values = {f"hinf_cpp {m} threads={t}": c for (m, t), c in cpp.items()}
    values.update({f"SciPy {m}": s for m, s in sp.items()})
    agreement = {}
    for name, v in values.items():
        agreement[name] = {
            "gamma_star": v["gamma_star"],
            "rel_diff_vs_hinf_bdf_t1": abs(v["gamma_star"] - reference["gamma_star"])
            / reference["gamma_star"],
            "bracket_overlaps_hinf_bdf_t1": bool(v["lower"] < reference["upper"]
                                                 and reference["lower"] < v["upper"]),
            "converged": bool(v["converged"]),
        }
    lowers = [v["lower"] for v in values.values()]
    uppers = [v["upper"] for v in values.values()]
    spread = (max(v["gamma_star"] for v in values.values())
              - min(v["gamma_star"] for v in values.values())) / reference["gamma_star"]
    common = max(lowers) < min(uppers)
    out["agreement"] = {"per_run": agreement, "max_relative_spread": spread,
                        "all_brackets_share_a_point": bool(common),
                        "common_bracket": [max(lowers), min(uppers)] if common else None}
    out["machine"]["load_avg_end"] = os.getloadavg()

    report(out, cpp, sp, rows, naive)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=2, default=float)
        print(f"\nnumbers saved to {args.json}")
    return 0


def report(out: dict, cpp: dict, sp: dict, rows: list, naive) -> None:
    line = "-" * 118
    print("\n" + "=" * 118)
    print("1. gamma* to rtol 1e-6, trajectory prebuilt. Evaluations: gammas tried (GRDE "
          "integrations); rounds: sequential depth with threads=2 evaluating 2 gammas at once.")
    print(line)
    print(f"{'side':<26} {'time':>30} {'evals':>6} {'rounds':>7} {'per eval':>10} "
          f"{'gamma*':>13} {'t_escape(lower) s':>18}")
    for (method, threads), c in cpp.items():
        per = 1e3 * c["time"]["median"] / c["evaluations"]
        label = f"hinf_cpp {method} threads={threads}"
        if (method, threads) == ("bdf", 2):
            label += " *"
        print(f"{label:<26} {ms(c['time']) + ' ms':>30} {c['evaluations']:>6} {c['rounds']:>7} "
              f"{per:7.2f} ms {c['gamma_star']:13.9f} {c['t_escape_lower']:18.4f}")
    w = out["cpp_scenario_gamma_star"]
    print(f"{'hinf_cpp scenario_gamma_star':<26} {ms(w['time']) + ' ms':>30} "
          f"{w['evaluations']:>6} {'':>7} {'':>10} {w['gamma_star']:13.9f}")
    for method, s in sp.items():
        per = 1e3 * s["time"]["median"] / s["evaluations"]
        print(f"{'SciPy ' + method:<26} {s_(s['time']) + ' s':>30} {s['evaluations']:>6} "
              f"{s['evaluations']:>7} {per:7.1f} ms {s['gamma_star']:13.9f} "
              f"{s['t_escape_lower']:18.4f}")
    print("  * default GammaStarOptions (bdf, threads=2). scenario_gamma_star: default options, "
          "includes building the trajectory.")
    print("  SciPy per bisection: " + ", ".join(
        f"{m} {s['rhs_evals']} RHS calls ({s['confirmed_by_inverse']} passing gamma(s) crossed "
        f"the 1e6 threshold, decided by the inverse)" for m, s in sp.items()))

    print("\n2. Ratio SciPy / hinf_cpp (medians)")
    print(line)
    for r in rows:
        print(f"  SciPy {r['scipy_method']:<7} / hinf_cpp {r['cpp_solver']}: "
              f"{r['ratio_threads1']:6.0f}x (threads=1), {r['ratio_threads2']:6.0f}x "
              f"(threads=2)   {r['why']}")

    print("\n3. gamma* agreement (relative to hinf_cpp bdf threads=1; tolerance 1e-6 on each "
          "bracket)")
    print(line)
    for name, a in out["agreement"]["per_run"].items():
        print(f"  {name:<26} gamma* = {a['gamma_star']:.9f}  rel diff "
              f"{a['rel_diff_vs_hinf_bdf_t1']:.1e}  bracket overlap "
              f"{'yes' if a['bracket_overlaps_hinf_bdf_t1'] else 'NO'}  converged "
              f"{a['converged']}")
    ag = out["agreement"]
    common = ag["common_bracket"]
    print(f"  largest relative spread {ag['max_relative_spread']:.1e}; all final brackets "
          + (f"contain [{common[0]:.9f}, {common[1]:.9f}]" if common else "do NOT share a point"))
    bias = (naive.gamma_star - cpp[("bdf", 1)]["gamma_star"]) / cpp[("bdf", 1)]["gamma_star"]
    print(f"  threshold crossing taken as the escape without confirming (SciPy RK45, untimed): "
          f"gamma* = {naive.gamma_star:.9f}, {bias:.1e} too high")

    print("\nTARGETS")
    print(line)
    verdicts = {}
    for (method, threads), c in cpp.items():
        target = TARGET_MS[method]
        median = 1e3 * c["time"]["median"]
        met = median < target
        name = f"gamma* with {method}, threads={threads} < {target:g} ms"
        verdicts[name] = {"met": bool(met), "median_ms": median,
                          "min_ms": 1e3 * c["time"]["min"], "target_ms": target}
        default = " (default options)" if (method, threads) == ("bdf", 2) else ""
        print(f"  [{'MET   ' if met else 'MISSED'}] {name}{default}: {median:.2f} ms median "
              f"(min {1e3 * c['time']['min']:.2f})")
    out["targets"] = verdicts
    print(f"\nload average: {out['machine']['load_avg_start'][0]:.2f} at the start, "
          f"{out['machine']['load_avg_end'][0]:.2f} at the end (2-core shared machine: threads=2 "
          f"needs the second core free)")


if __name__ == "__main__":
    raise SystemExit(main())
