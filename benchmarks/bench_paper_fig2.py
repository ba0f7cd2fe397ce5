"""Benchmark: hinf_cpp against plain NumPy/SciPy on the paper's Figure-2 run (output feedback).

    .venv/bin/python benchmarks/bench_paper_fig2.py                 # full (~2 min)
    .venv/bin/python benchmarks/bench_paper_fig2.py --quick         # smoke test (~45 s)
    .venv/bin/python benchmarks/bench_paper_fig2.py --repeat 100 --scipy-repeat 5 --json out.json

Both sides run scenarios/paper_fig2.toml (checked to be the same problem as
``scipy_output_feedback``: parameters, horizon, weights, [measurement], C) with the same noise
samples (``hinf_cpp.scenario_noise``), at the scenario's tolerances rtol 1e-8 / atol 1e-10:
desired trajectory, GRDE backward, then plant + estimator (35) + filter Riccati (36) forward,
one hold interval (0.01 s) at a time, then the analysis and metrics. The C++ side is the whole
``hinf_cpp.run_scenario`` call with solver method "bdf" (the scenario's) and "erk"; the SciPy
side is ``scipy_output_feedback.run_reference``. Before anything is timed, each SciPy pairing
is checked against hinf_cpp (max |q - q_SciPy|, |q_hat - q_hat_SciPy| and every metric within
AGREEMENT_TOL) and both against a tight reference.

Timings are wall-clock (time.perf_counter) around the Python call, with the garbage collector
off during the timed loops; each is reported as median [min - max] over the repetitions.
``--repeat N`` (default 50) sets the C++ repetitions, ``--scipy-repeat M`` (default 3) the
SciPy ones (a SciPy run takes about 5 s); ``--quick`` is ``--repeat 10 --scipy-repeat 1``.
``--json OUT`` saves every number, the machine and the load average.
"""

from __future__ import annotations

import os

# Tiny (6x6) matrices only: keep OpenBLAS from parking spinning threads on the second core of
# a 2-core machine while the C++ side is timed. Must precede the NumPy import.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import json  # noqa: E402
import pathlib  # noqa: E402
import platform  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
import scipy  # noqa: E402

import hinf_cpp as hc  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import scipy_output_feedback as twin  # noqa: E402
import scipy_reference as ref  # noqa: E402
from bench_paper_fig1 import core_fingerprint, cpu_model, max_abs, ms, s_, timed  # noqa: E402

SCENARIO = pathlib.Path(__file__).resolve().parents[1] / "scenarios" / "paper_fig2.toml"
RTOL, ATOL = 1e-8, 1e-10
REFERENCE_RTOL, REFERENCE_ATOL = 1e-11, 1e-13

# Targets of the project for the whole Figure-2 run.
TARGET_BDF_MS = 50.0
TARGET_ERK_MS = 10.0
TARGET_SPEEDUP = 500.0
# hinf_cpp and its SciPy twin must agree this well (q, q_hat on the grid, every metric) at the
# scenario's tolerances before anything is timed: both solve the problem to ~1e-8.
AGREEMENT_TOL = 1e-6

# (hinf_cpp method, SciPy GRDE method, SciPy loop method per hold interval, label, why)
PAIRS = [
    ("bdf", "BDF", "RK45", "bdf vs BDF+jac/RK45",
     "hinf_cpp 'bdf' is CVODE BDF for the GRDE, then Dormand-Prince 5(4) per hold interval "
     "(it would switch to SDIRK4 on detected stiffness; the loop is not stiff here). SciPy: BDF "
     "with the analytic Jacobian for the GRDE, RK45 (the same Dormand-Prince 5(4)) per "
     "interval -- a multistep BDF restarted 4000 times would restart at order 1 every 0.01 s"),
    ("erk", "RK45", "RK45", "erk vs RK45/RK45",
     "the same method everywhere: Dormand-Prince 5(4) for the GRDE and per hold interval"),
    ("erk", "DOP853", "DOP853", "erk vs DOP853/DOP853",
     "SciPy's higher-order explicit option: fewest GRDE steps (Figure 1) and still one step "
     "per hold interval"),
]


# ---------------------------------------------------------------------------------------------
# helpers
# ---------------------------------------------------------------------------------------------


def scenario_with(sc, method: str, rtol: float = RTOL, atol: float = ATOL):
    s = sc.copy()
    s.solver = hc.SolverOptions(method=method, rtol=rtol, atol=atol)
    return s


def final_position_error(q_e: np.ndarray) -> float:
    return float(np.hypot(*q_e[-1, 3:5]))


def output_feedback_problem(sc, design, noise):
    """The OutputFeedbackProblem (and options) run_scenario builds from [measurement]."""
    m = sc.measurement
    N = np.asarray(m.N)
    N = N[0, 0] * np.eye(3) if N.size == 1 else N
    Sigma0 = np.linalg.inv(m.Q0 - m.eta * np.eye(6))
    problem = hc.OutputFeedbackProblem(design, m.sigma, m.sample_period, noise, N, Sigma0, sc.Q)
    return problem, hc.OutputFeedbackOptions(m.filter_A, m.on_coupling_violation)


def scipy_pieces(noise, grde_method: str, loop_method: str, jacobian: bool = True):
    """One SciPy run (what run_reference does) split into its parts, each timed once
    (seconds); returns (times and counts, the run, its metrics)."""
    p, m = twin.PAPER_FIG2, twin.PAPER_FIG2_MEASUREMENT
    start = time.perf_counter()
    trajectory = ref.solve_desired_trajectory(p)
    t_traj = time.perf_counter()
    grde = ref.solve_grde(trajectory, p, grde_method, RTOL, ATOL, jacobian)
    t_grde = time.perf_counter()
    run = twin.simulate_output_feedback(trajectory, grde, noise, p, m, loop_method, RTOL, ATOL)
    t_loop = time.perf_counter()
    Z_grid = ref.grde_Z(grde, run["t"])
    np.linalg.eigvalsh(0.5 * (Z_grid + Z_grid.transpose(0, 2, 1)))
    metrics = twin.compute_metrics(run, p)
    t_end = time.perf_counter()
    return {"trajectory": t_traj - start, "grde": t_grde - t_traj, "loop": t_loop - t_grde,
            "analysis": t_end - t_loop, "total": t_end - start,
            "grde_steps": int(grde.t.size - 1), "grde_nfev": int(grde.nfev),
            "grde_njev": int(grde.njev), "loop_steps": run["steps"], "loop_nfev": run["nfev"],
            "loop_solve_ivp_calls": run["intervals"]}, run, metrics


# ---------------------------------------------------------------------------------------------
# the benchmark
# ---------------------------------------------------------------------------------------------


def time_run_scenario(sc, repeat: int) -> dict:
    """run_scenario timed from Python, with the library's own timing (result.timing) of the
    same calls (medians, seconds)."""
    inside = []

    def whole():
        inside.append(hc.run_scenario(sc).timing)

    timing = timed(whole, repeat, warmup=3)
    inside = inside[3:]
    return {"time": timing,
            "inside_cpp": {key: float(np.median([getattr(t, key) for t in inside]))
                           for key in ("design", "simulate", "analysis", "total")}}


def fresh_child(repeat: int) -> None:
    """Runs in a fresh interpreter (no SciPy work before): times run_scenario and prints JSON."""
    sc = hc.load_scenario(str(SCENARIO))
    print(json.dumps({method: time_run_scenario(scenario_with(sc, method), repeat)
                      for method in ("bdf", "erk")}))


def run_fresh_child(repeat: int) -> dict:
    completed = subprocess.run([sys.executable, __file__, "--fresh-child", "--repeat",
                                str(repeat)], capture_output=True, text=True, check=True)
    return json.loads(completed.stdout.strip().splitlines()[-1])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=50,
                        help="repetitions of each C++ measurement (default 50)")
    parser.add_argument("--scipy-repeat", type=int, default=3,
                        help="repetitions of each SciPy measurement (default 3)")
    parser.add_argument("--quick", action="store_true",
                        help="smoke test: --repeat 10 --scipy-repeat 1")
    parser.add_argument("--json", metavar="OUT", help="save all numbers to this JSON file")
    parser.add_argument("--fresh-child", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.fresh_child:
        fresh_child(args.repeat)
        return 0
    if args.quick:
        args.repeat, args.scipy_repeat = 10, 1
    N, M = args.repeat, args.scipy_repeat

    out: dict = {
        "machine": {"python": platform.python_version(), "numpy": np.__version__,
                    "scipy": scipy.__version__, "hinf_cpp": hc.__version__,
                    "processor": cpu_model(), "cpus": os.cpu_count(),
                    "load_avg_start": os.getloadavg(), "hinf_cpp_core": core_fingerprint()},
        "settings": {"scenario": SCENARIO.name, "rtol": RTOL, "atol": ATOL, "cpp_repeat": N,
                     "scipy_repeat": M, "agreement_tol": AGREEMENT_TOL,
                     "gc_disabled_while_timing": True,
                     "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS")},
    }
    core = out["machine"]["hinf_cpp_core"]
    print(f"hinf_cpp {hc.__version__} (_core sha256 {core['sha256']}, built {core['mtime']} UTC) "
          f"vs NumPy {np.__version__} / SciPy {scipy.__version__}, "
          f"Python {platform.python_version()}, {os.cpu_count()} CPUs, "
          f"load average {os.getloadavg()[0]:.2f}")
    print(f"scenario {SCENARIO.name}, rtol {RTOL:g}, atol {ATOL:g}; C++ x{N}, SciPy x{M}; "
          f"times are median [min-max]\n")

    print("0. run_scenario in a fresh process (nothing else run there first) ...", flush=True)
    fresh = run_fresh_child(N)
    out["cpp_fresh_process"] = fresh

    sc = hc.load_scenario(str(SCENARIO))
    p, m = twin.PAPER_FIG2, twin.PAPER_FIG2_MEASUREMENT
    twin.check_matches_scenario(sc, p, m)
    noise = hc.scenario_noise(sc)
    out["noise"] = {"shape": list(noise.shape), "seed": sc.measurement.seed,
                    "source": "hinf_cpp.scenario_noise, passed to both sides"}

    # ---- tight reference ----
    print(f"reference: SciPy twin, DOP853 rtol {REFERENCE_RTOL:g} atol {REFERENCE_ATOL:g} "
          f"(GRDE and loop) ...", flush=True)
    start = time.perf_counter()
    reference = twin.run_reference(noise, p, m, "DOP853", "DOP853", REFERENCE_RTOL,
                                   REFERENCE_ATOL)["run"]
    ref_seconds = time.perf_counter() - start
    tight = hc.run_scenario(scenario_with(sc, "erk", REFERENCE_RTOL, REFERENCE_ATOL)).simulation
    cross = {"q": max_abs(tight.q - reference["q"]),
             "q_hat": max_abs(tight.estimator.q_hat - reference["q_hat"])}
    final_ref = final_position_error(reference["q_e"])
    print(f"  {ref_seconds:.1f} s. Cross-check against hinf_cpp erk at the same tolerances: "
          f"max|dq| {cross['q']:.1e}, max|dq_hat| {cross['q_hat']:.1e}; final position error "
          f"{final_ref:.10f}\n")
    out["reference"] = {"what": f"SciPy twin, DOP853 rtol {REFERENCE_RTOL:g} atol "
                                f"{REFERENCE_ATOL:g}, GRDE and loop",
                        "seconds": ref_seconds, "cross_check_vs_hinf_erk_same_tol": cross,
                        "final_position_error": final_ref}

    # ---- accuracy: each pairing against hinf_cpp and the reference, before timing ----
    print(f"1. accuracy at rtol {RTOL:g} / atol {ATOL:g} (these SciPy runs are the warm-up) ...",
          flush=True)
    cpp = {}
    for method in ("bdf", "erk"):
        result = hc.run_scenario(scenario_with(sc, method))
        sim = result.simulation
        cpp[method] = {
            "result": result,
            "final_position_error": result.metrics.final_position_error,
            "err_q_vs_reference": max_abs(sim.q - reference["q"]),
            "err_q_hat_vs_reference": max_abs(sim.estimator.q_hat - reference["q_hat"]),
            "trajectory_steps": result.trajectory.stats().steps,
            "grde_steps": result.solution.stats().steps,
            "grde_rhs_evals": result.solution.stats().rhs_evals,
            "grde_jac_evals": result.solution.stats().jac_evals,
            "loop_steps": sim.stats.steps, "loop_rejected": sim.stats.rejected,
            "loop_rhs_evals": sim.stats.rhs_evals, "loop_integrator": sim.integrator,
            "metrics": {d.name: getattr(result.metrics, d.name) for d in hc.metric_table()},
        }
    rows = []
    for cpp_method, grde_method, loop_method, label, why in PAIRS:
        pieces, run, metrics = scipy_pieces(noise, grde_method, loop_method)
        c = cpp[cpp_method]
        sim = c["result"].simulation
        agreement = {"q": max_abs(run["q"] - sim.q), "q_hat": max_abs(run["q_hat"] - sim.estimator.q_hat),
                     "u": max_abs(run["u"] - sim.u),
                     "metrics": max(abs(v - c["metrics"][k]) for k, v in metrics.items())}
        worst = max(agreement["q"], agreement["q_hat"], agreement["metrics"])
        if not worst <= AGREEMENT_TOL:
            raise RuntimeError(f"{label}: SciPy and hinf_cpp disagree by {worst:.2e} "
                               f"(> {AGREEMENT_TOL:g}): {agreement}")
        rows.append({
            "pair": label, "why": why, "cpp_method": cpp_method, "scipy_grde": grde_method,
            "scipy_loop": loop_method, "agreement_max_abs": agreement,
            "scipy": {"final_position_error": metrics["final_position_error"],
                      "err_q_vs_reference": max_abs(run["q"] - reference["q"]),
                      "err_q_hat_vs_reference": max_abs(run["q_hat"] - reference["q_hat"]),
                      "pieces_one_run_s": pieces},
        })
        print(f"  {label}: max|q - q_SciPy| {agreement['q']:.1e}, max|q_hat - q_hat_SciPy| "
              f"{agreement['q_hat']:.1e}, metrics {agreement['metrics']:.1e} -- within "
              f"{AGREEMENT_TOL:g}", flush=True)

    # ---- 2. whole run, C++ ----
    print("\n2. hinf_cpp.run_scenario, whole Figure-2 run ...", flush=True)
    for method in ("bdf", "erk"):
        cpp[method].update(time_run_scenario(scenario_with(sc, method), N))
        print(f"  {method}: {ms(cpp[method]['time'])} ms", flush=True)

    # ---- 3. whole run, SciPy ----
    print("\n3. SciPy twin, whole Figure-2 run ...", flush=True)
    for row in rows:
        timing = timed(lambda: twin.run_reference(noise, p, m, row["scipy_grde"],
                                                  row["scipy_loop"], RTOL, ATOL), M, warmup=0)
        c = cpp[row["cpp_method"]]
        row["scipy"]["time"] = timing
        row["ratio"] = timing["median"] / c["time"]["median"]
        row["ratio_fresh"] = timing["median"] / fresh[row["cpp_method"]]["time"]["median"]
        print(f"  {row['pair']}: SciPy {s_(timing)} s, ratio {row['ratio']:.0f}", flush=True)

    # ---- 4. C++ pieces: where the time of a run goes ----
    print("\n4. C++ pieces ...", flush=True)
    tr = hc.Trajectory(sc.model, sc.desired_q0, sc.desired_u, sc.t0, sc.tf)
    pieces = {"trajectory": {"time": timed(lambda: hc.Trajectory(
        sc.model, sc.desired_q0, sc.desired_u, sc.t0, sc.tf), N, warmup=3),
        "steps": tr.stats().steps}}
    for method in ("bdf", "erk"):
        solver = hc.SolverOptions(method=method, rtol=RTOL, atol=ATOL)
        sol = hc.solve_grde(tr, sc.Q, sc.Qf, sc.gamma, solver)
        pieces[f"GRDE {method}"] = {
            "time": timed(lambda: hc.solve_grde(tr, sc.Q, sc.Qf, sc.gamma, solver), N, 3),
            "steps": sol.stats().steps, "rhs_evals": sol.stats().rhs_evals}

        def simulate(output_dt, sol=sol, solver=solver):
            problem, options = output_feedback_problem(sc, sol, noise)
            return hc.simulate_output_feedback(problem, hc.HinfStateFeedback(sol, sc.kappa), sc.disturbance,
                                               sc.initial_q0, options, hc.SimulationOptions(output_dt, solver=solver))

        sim = simulate(sc.output_dt)
        same = max_abs(sim.q - cpp[method]["result"].simulation.q)
        assert same == 0.0, f"simulate_output_feedback differs from run_scenario by {same}"
        pieces[f"simulate {method}"] = {"time": timed(lambda: simulate(sc.output_dt), N, 3),
                                        "steps": sim.stats.steps,
                                        "rhs_evals": sim.stats.rhs_evals}
        # The same integration with a 2-point output grid: no work at the 4001 grid points
        # (interpolation, eigenvalues of Sigma, rho(Sigma Z), signals).
        pieces[f"simulate {method}, 2-point output grid"] = {
            "time": timed(lambda: simulate(sc.tf - sc.t0), N, 3)}
        pieces[f"Z eigenvalue bounds ({method} GRDE)"] = {
            "time": timed(sol.eigenvalue_bounds, N, 3)}
    sim = cpp["bdf"]["result"].simulation
    pieces["compute_metrics"] = {"time": timed(lambda: hc.compute_metrics(sc.model, sim, sc.Q),
                                               N, 3)}
    out["cpp_pieces"] = pieces
    out["cpp"] = {k: {kk: vv for kk, vv in v.items() if kk != "result"} for k, v in cpp.items()}
    out["pairs"] = rows
    out["machine"]["load_avg_end"] = os.getloadavg()

    report(out, fresh)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=2, default=float)
        print(f"\nnumbers saved to {args.json}")
    return 0


def report(out: dict, fresh: dict) -> None:
    line = "-" * 132
    cpp, rows, pieces, reference = out["cpp"], out["pairs"], out["cpp_pieces"], out["reference"]
    print("\n" + "=" * 132)
    print("1. Accuracy (rtol 1e-8 / atol 1e-10). Agreement: max |C++ - SciPy| over the "
          "4001-point grid. Error: max |q - q_ref| against the SciPy twin at DOP853 rtol 1e-11")
    print(f"   (which agrees with hinf_cpp erk at rtol 1e-11 to "
          f"{reference['cross_check_vs_hinf_erk_same_tol']['q']:.1e} in q, "
          f"{reference['cross_check_vs_hinf_erk_same_tol']['q_hat']:.1e} in q_hat). "
          f"Reference final position error {reference['final_position_error']:.10f}.")
    print(line)
    print(f"{'pairing':<22} {'|dq|':>8} {'|dq_hat|':>9} {'|du|':>8} {'|dmetric|':>9} "
          f"{'final pos err C++ / SciPy':>29} {'q err C++/SciPy':>18} {'q_hat err C++/SciPy':>20}")
    for r in rows:
        a, c, s = r["agreement_max_abs"], cpp[r["cpp_method"]], r["scipy"]
        print(f"{r['pair']:<22} {a['q']:8.1e} {a['q_hat']:9.1e} {a['u']:8.1e} "
              f"{a['metrics']:9.1e} {c['final_position_error']:14.10f} / "
              f"{s['final_position_error']:.10f} {c['err_q_vs_reference']:8.1e}/"
              f"{s['err_q_vs_reference']:8.1e}  {c['err_q_hat_vs_reference']:9.1e}/"
              f"{s['err_q_hat_vs_reference']:8.1e}")
    print("  pairing: " + "\n           ".join(f"{r['pair']}: {r['why']}" for r in rows))

    print("\n2. Whole Figure-2 run: hinf_cpp.run_scenario vs scipy_output_feedback.run_reference "
          "(trajectory + GRDE + output-feedback loop + analysis)")
    print(line)
    print(f"{'pairing':<22} {'C++ ms':>26} {'C++ fresh ms':>26} {'SciPy s':>22} {'ratio':>6} "
          f"{'fresh':>6}")
    for r in rows:
        c = cpp[r["cpp_method"]]
        print(f"{r['pair']:<22} {ms(c['time']):>26} {ms(fresh[r['cpp_method']]['time']):>26} "
              f"{s_(r['scipy']['time']):>22} {r['ratio']:6.0f} {r['ratio_fresh']:6.0f}")
    print("\n   Work done (steps / RHS evaluations):")
    for method in ("bdf", "erk"):
        c = cpp[method]
        print(f"   C++ {method}: trajectory {c['trajectory_steps']} steps; GRDE {c['grde_steps']} "
              f"steps / {c['grde_rhs_evals']} RHS / {c['grde_jac_evals']} Jacobians; loop "
              f"{c['loop_steps']} steps ({c['loop_rejected']} rejected) / {c['loop_rhs_evals']} "
              f"RHS over 4000 hold intervals ({c['loop_integrator']})")
    for r in rows:
        s = r["scipy"]["pieces_one_run_s"]
        print(f"   SciPy {r['scipy_grde']}/{r['scipy_loop']}: GRDE {s['grde_steps']} steps / "
              f"{s['grde_nfev']} RHS / {s['grde_njev']} Jacobians; loop {s['loop_steps']} steps "
              f"/ {s['loop_nfev']} RHS in {s['loop_solve_ivp_calls']} solve_ivp calls")

    print("\n3. Where the time goes (ms; C++: result.timing medians of the timed calls, and "
          "pieces timed alone; SciPy: one run, timed by part)")
    print(line)
    print(f"{'':<26} {'design':>9} {'simulate':>9} {'analysis':>9} {'total':>9}")
    for method in ("bdf", "erk"):
        i = cpp[method]["inside_cpp"]
        print(f"{'C++ ' + method + ' result.timing':<26} {1e3 * i['design']:9.3f} "
              f"{1e3 * i['simulate']:9.3f} {1e3 * i['analysis']:9.3f} {1e3 * i['total']:9.3f}")
    for r in rows:
        s = r["scipy"]["pieces_one_run_s"]
        print(f"{'SciPy ' + r['scipy_grde'] + '/' + r['scipy_loop']:<26} "
              f"{1e3 * (s['trajectory'] + s['grde']):9.1f} {1e3 * s['loop']:9.1f} "
              f"{1e3 * s['analysis']:9.1f} {1e3 * s['total']:9.1f}")
    print(f"\n{'C++ piece':<40} {'ms':>26} {'steps':>6} {'RHS':>6} {'ns/RHS':>7}")
    for name, entry in pieces.items():
        t = entry["time"]
        rhs = entry.get("rhs_evals")
        # Per RHS evaluation only for the explicit pieces: BDF time is mostly CVODE's Newton.
        explicit = rhs and name != "GRDE bdf"
        per_rhs = f"{1e9 * t['median'] / rhs:7.0f}" if explicit else " " * 7
        print(f"{name:<40} {ms(t):>26} {entry.get('steps') or '':>6} {rhs or '':>6} {per_rhs}")
    for method in ("bdf", "erk"):
        full = pieces[f"simulate {method}"]["time"]["median"]
        bare = pieces[f"simulate {method}, 2-point output grid"]["time"]["median"]
        rhs = pieces[f"simulate {method}"]["rhs_evals"]
        print(f"  simulate {method}: integration {1e3 * bare:.2f} ms ({1e9 * bare / rhs:.0f} ns "
              f"per RHS evaluation, stepping included), work at the 4001 output points "
              f"{1e3 * (full - bare):.2f} ms ({1e6 * (full - bare) / 4001:.2f} us each)")

    # ---- targets ----
    print("\nTARGETS (MET only if met both in this process and in the fresh process)")
    print(line)
    verdicts = {}

    def verdict(name, met, text):
        verdicts[name] = {"met": bool(met), "detail": text}
        print(f"  [{'MET   ' if met else 'MISSED'}] {name}: {text}")

    for method, target in (("bdf", TARGET_BDF_MS), ("erk", TARGET_ERK_MS)):
        here = 1e3 * cpp[method]["time"]["median"]
        there = 1e3 * fresh[method]["time"]["median"]
        verdict(f"whole Figure-2 run < {target:g} ms ({method})", max(here, there) < target,
                f"{here:.2f} ms median here (min {1e3 * cpp[method]['time']['min']:.2f}), "
                f"{there:.2f} ms in a fresh process -- target < {target:g} ms")
    parts = [f"{r['ratio']:.0f}x ({r['ratio_fresh']:.0f}x fresh) {r['pair']}" for r in rows]
    verdict(f"whole run >= {TARGET_SPEEDUP:.0f}x faster than SciPy",
            all(min(r["ratio"], r["ratio_fresh"]) >= TARGET_SPEEDUP for r in rows),
            "; ".join(parts) + f" -- target >= {TARGET_SPEEDUP:.0f}x for every pairing")
    for r in rows:
        needed = 1e3 * r["scipy"]["time"]["median"] / TARGET_SPEEDUP
        print(f"           {r['pair']}: {TARGET_SPEEDUP:.0f}x needs the C++ run at "
              f"{needed:.2f} ms or less")
    out["targets"] = verdicts
    print(f"\nload average at the end: {out['machine']['load_avg_end'][0]:.2f} "
          f"(2-core shared machine: compare medians, see the min-max spread)")


if __name__ == "__main__":
    raise SystemExit(main())
