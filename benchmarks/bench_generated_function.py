"""Benchmark: a CasADi model evaluated as compiled generated code (hinf_cpp.GeneratedFunction)
against CasADi's own evaluation, and what the compilation costs.

    .venv/bin/python benchmarks/bench_generated_function.py --json benchmarks/results/generated_function.json
    .venv/bin/python benchmarks/bench_generated_function.py --quick      # smoke test

The model is the ship of docs/mathematics.md with the paper's parameters, written with CasADi
symbols; the function timed is its Jacobian df/dq (6 x 6, 11 structural nonzeros, sin and
cos of the heading), the matrix the GRDE needs at every step.

- generated, C++ loop: ``hinf-bench-generated`` (benchmarks/bench_generated_function.cpp,
  built with the C++ targets in build/cmake) calls GeneratedFunction::eval 1e5 times per
  round, inputs changing every call; median over rounds of the time per call. It first checks
  the generated Jacobian against the hand-written ShipModel::dfdq and times that too.
- CasADi from Python: ``J(q)`` with a NumPy q, 1e5 calls in a Python loop (what a Python
  model callback would cost), and ``J.map(N)`` on a 6 x N matrix: CasADi's virtual machine
  evaluating N Jacobians in one call, i.e. without Python's per-call overhead.
- generated, from Python: ``GeneratedFunction.__call__`` in a Python loop (the binding's
  overhead: argument conversion, output arrays, GIL release).
- compilation: generation + compilation of the ship's functions (f, df/dq, B) into a fresh
  cache folder (first use), and a call that finds them in the cache; then at -O1, -O2 and
  -O3 (``compiler="cc -O1"``, ...) the compilation and evaluation times of the ship's
  functions and of two larger ones: the GRDE right-hand side of a fleet of 4 ships (24 x 24,
  about 20000 lines of straight-line C) and a 40 x 40 MX matrix product (loops).

Wall-clock timings, median [min-max] of the rounds. The machine is a shared 2-core VM.
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import casadi as ca
import numpy as np

import hinf_cpp as hc
from hinf_cpp.models import codegen

ROOT = pathlib.Path(__file__).resolve().parents[1]
DEFAULT_BENCH = ROOT / "build" / "cmake" / "cpp" / "hinf-bench-generated"
PARAMETERS = dict(m_u=0.5, m_v=-2.0, m_r=0.5, d_u=1.0, d_v=2.0, d_r=1.0)


def ship_rhs(q):
    """f(q) of the ship (docs/mathematics.md) with the paper's parameters."""
    p = PARAMETERS
    u, v, r, psi = q[0], q[1], q[2], q[5]
    return ca.vertcat(p["m_u"] * v * r - p["d_u"] * u,
                      p["m_v"] * u * r - p["d_v"] * v,
                      p["m_r"] * u * v - p["d_r"] * r,
                      u * ca.cos(psi) - v * ca.sin(psi),
                      u * ca.sin(psi) + v * ca.cos(psi),
                      r)


SHIP_B = ca.DM([[1, 0], [0, 0], [0, 1], [0, 0], [0, 0], [0, 0]])
SHIP_D = ca.diag(ca.DM([1, 1, 1, 0, 0, 0]))


def ship_functions() -> dict[str, ca.Function]:
    """f(q), df/dq and B of the ship."""
    q = ca.SX.sym("q", 6)
    f = ship_rhs(q)
    return {
        "f": ca.Function("ship_f", [q], [f], ["q"], ["f"]),
        "dfdq": ca.Function("ship_dfdq", [q], [ca.jacobian(f, q)], ["q"], ["A"]),
        "B": ca.Function("ship_B", [q], [ca.SX(SHIP_B)], ["q"], ["B"]),
    }


def large_functions() -> dict[str, ca.Function]:
    """Two larger functions for the optimization levels: the GRDE right-hand side (13) of a
    fleet of 4 ships (24 states, Z a full symbolic 24 x 24 matrix: long straight-line SX code),
    and X X + sin(X) for a 40 x 40 MX matrix (CasADi's matrix product: loops)."""
    k = 4
    q = ca.SX.sym("q", 6 * k)
    f = ca.vertcat(*[ship_rhs(q[6 * i:6 * i + 6]) for i in range(k)])
    A = ca.jacobian(f, q)
    B, D = ca.diagcat(*[SHIP_B] * k), ca.diagcat(*[SHIP_D] * k)
    S = ca.mtimes(B, B.T) - ca.mtimes(D, D.T) / 5.0**2  # gamma = 5
    Z = ca.SX.sym("Z", 6 * k, 6 * k)
    grde = ca.mtimes(A.T, Z) + ca.mtimes(Z, A) + ca.SX.eye(6 * k) - ca.mtimes([Z, S, Z])
    X = ca.MX.sym("X", 40, 40)
    return {"fleet_grde": ca.Function("fleet_grde", [q, Z], [grde], ["q", "Z"], ["F"]),
            "mx_product": ca.Function("mx_product", [X], [ca.mtimes(X, X) + ca.sin(X)], ["X"], ["Y"])}


def stats(samples) -> dict:
    return {"median": statistics.median(samples), "min": min(samples), "max": max(samples), "n": len(samples)}


def fmt(s: dict, scale: float = 1.0, digits: int = 3) -> str:
    return f"{s['median'] * scale:.{digits}g} [{s['min'] * scale:.{digits}g}-{s['max'] * scale:.{digits}g}]"


def run_bench(bench: pathlib.Path, library: pathlib.Path, name: str, calls: int, repeat: int, threads: int = 1,
              ship: bool = False) -> dict:
    """hinf-bench-generated's timings, in seconds per call."""
    args = [str(bench), str(library), name, "--calls", str(calls), "--repeat", str(repeat), "--threads", str(threads)]
    done = subprocess.run(args + (["--ship"] if ship else []), capture_output=True, text=True, check=True)
    result = {}
    for line in done.stdout.splitlines():
        label, *values = line.split()
        if label in ("generated", "handwritten"):
            result[label] = dict(zip(("median", "min", "max"), (float(v) * 1e-9 for v in values)))
        elif label == "ship_max_abs_difference":
            result[label] = float(values[0])
    return result


def per_call(total_seconds: list[float], calls: int) -> dict:
    return stats([t / calls for t in total_seconds])


def time_loop(fn, calls: int, rounds: int) -> list[float]:
    fn()
    totals = []
    for _ in range(rounds):
        start = time.perf_counter()
        fn()
        totals.append(time.perf_counter() - start)
    return totals


FOLDERS: list[pathlib.Path] = []  # removed at the end


def compile_fresh(functions: list, name: str, compiler: str | None = None) -> codegen.CompiledLibrary:
    """Generation and compilation into a new cache folder: a first use."""
    folder = pathlib.Path(tempfile.mkdtemp(prefix="hinf_bench_cache_"))
    FOLDERS.append(folder)
    return codegen.compile_casadi_functions(functions, name, cache_dir=folder, compiler=compiler)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bench", type=pathlib.Path, default=DEFAULT_BENCH, help="hinf-bench-generated")
    parser.add_argument("--calls", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=21, help="rounds of the C++ loop")
    parser.add_argument("--python-repeat", type=int, default=5, help="rounds of the Python loops")
    parser.add_argument("--compile-repeat", type=int, default=5)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--json", type=pathlib.Path)
    args = parser.parse_args()
    if args.quick:
        args.calls, args.repeat, args.python_repeat, args.compile_repeat = 2000, 3, 1, 1
    if not args.bench.exists():
        sys.exit(f"{args.bench} not found: build it (cmake --build build/cmake --target hinf-bench-generated)")

    fun = ship_functions()
    ship = [fun["f"], fun["dfdq"], fun["B"]]
    cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name")),
               platform.machine())
    results: dict = {"machine": {"cpu": cpu, "cores": os.cpu_count(),
                                 "load_average": list(map(float, open("/proc/loadavg").read().split()[:3])),
                                 "python": platform.python_version(), "casadi": ca.__version__,
                                 "hinf_cpp": hc.__version__, "compiler": subprocess.run(
                                     ["cc", "--version"], capture_output=True, text=True).stdout.splitlines()[0]},
                     "calls": args.calls}
    print(f"CasADi {ca.__version__}, {results['machine']['compiler']}, load average "
          f"{results['machine']['load_average']}, {args.calls} calls per round")

    # ---- compilation: first use and cache hit ----
    first = [compile_fresh(ship, "ship") for _ in range(args.compile_repeat)]
    library = first[-1].path
    hits = []
    for _ in range(max(5, args.compile_repeat)):
        start = time.perf_counter()
        hit = codegen.compile_casadi_functions(ship, "ship", cache_dir=library.parent)
        hits.append(time.perf_counter() - start)
        assert hit.cache_hit and hit.path == library
    results["ship_compile"] = {"generate": stats([c.generate_seconds for c in first]),
                               "compile": stats([c.compile_seconds for c in first]),
                               "cache_hit": stats(hits), "source_lines": library.with_suffix(".c").read_text().count("\n")}
    rc = results["ship_compile"]
    print(f"ship f, df/dq, B ({rc['source_lines']} lines of C): generation {fmt(rc['generate'], 1e3)} ms, "
          f"compilation {fmt(rc['compile'], 1e3)} ms, cache hit {fmt(rc['cache_hit'], 1e3)} ms")

    # ---- evaluation of df/dq ----
    cpp = run_bench(args.bench, library, "ship_dfdq", args.calls, args.repeat, ship=True)
    cpp2 = run_bench(args.bench, library, "ship_dfdq", args.calls, args.repeat, threads=2)
    assert cpp["ship_max_abs_difference"] <= 1e-14, cpp
    J = fun["dfdq"]
    states = np.random.default_rng(1).uniform(-1, 1, size=(args.calls, 6))
    loop_calls = min(args.calls, 100_000)
    casadi_python = per_call(time_loop(lambda: [J(x) for x in states[:loop_calls]], loop_calls, args.python_repeat),
                             loop_calls)
    chunk = min(1000, args.calls)  # evaluations per J.map call: large enough to hide the call's cost
    J_map = J.map(chunk)
    chunks = [ca.DM(states[k:k + chunk].T) for k in range(0, args.calls - chunk + 1, chunk)]
    casadi_vm = per_call(time_loop(lambda: [J_map(c) for c in chunks], args.calls, args.python_repeat),
                         chunk * len(chunks))
    g = hc._core.GeneratedFunction(str(library), "ship_dfdq")
    binding = per_call(time_loop(lambda: [g(x) for x in states[:loop_calls]], loop_calls, args.python_repeat),
                       loop_calls)
    # The results agree before the timings mean anything.
    for x in states[:100]:
        assert np.abs(g(x)[0] - J(x).full()).max() <= 1e-14
    base = cpp["generated"]["median"]
    rows = [("generated code, C++ loop (GeneratedFunction::eval)", cpp["generated"]),
            ("generated code, C++ loop, 2 threads (throughput)", cpp2["generated"]),
            ("hand-written ShipModel::dfdq, C++ loop", cpp["handwritten"]),
            ("CasADi VM, J.map(1000) (no per-call Python)", casadi_vm),
            ("CasADi from Python, J(q) in a loop", casadi_python),
            ("generated code from Python, GeneratedFunction(q) in a loop", binding)]
    results["dfdq"] = {label: {**s, "ratio_to_generated": s["median"] / base} for label, s in rows}
    print(f"\ndf/dq of the ship, time per evaluation (ns), median [min-max]; ratio to the generated code in C++")
    for label, s in rows:
        print(f"  {label:<62} {fmt(s, 1e9):>26}   x{s['median'] / base:.2f}")

    # ---- optimization levels: compilation against evaluation ----
    results["levels"] = {}
    cases = [("ship f, df/dq, B", ship, "ship_dfdq", args.calls)]
    cases += [(name, [f], name, max(args.calls // 50, 1)) for name, f in large_functions().items()]
    print("\nby optimization level: lines of C, first-use generation + compilation (ms), evaluation (ns)")
    for label, functions, timed_name, calls in cases:
        for level in ("-O1", "-O2", "-O3"):
            builds = [compile_fresh(functions, "level", compiler=f"cc {level}")
                      for _ in range(max(1, min(args.compile_repeat, 3)))]
            lines = builds[0].path.with_suffix(".c").read_text().count("\n")
            timing = run_bench(args.bench, builds[0].path, timed_name, calls, args.repeat)["generated"]
            entry = {"source_lines": lines, "generate": stats([b.generate_seconds for b in builds]),
                     "compile": stats([b.compile_seconds for b in builds]), "evaluation": timing}
            results["levels"][f"{label} {level}"] = entry
            print(f"  {label:<18} {level}: {lines:>6} lines, generation {fmt(entry['generate'], 1e3)}, "
                  f"compilation {fmt(entry['compile'], 1e3)}, evaluation {fmt(timing, 1e9)}")

    if args.json:
        args.json.write_text(json.dumps(results, indent=2) + "\n")
    for folder in FOLDERS:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
