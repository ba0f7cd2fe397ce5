"""Benchmark: the paper's ship as a symbolic (CasADi) model, as a Python subclass of hc.Model,
and as the built-in ShipModel, on the Figure 1 and Figure 2 runs.

    .venv/bin/python benchmarks/bench_symbolic_model.py                # full (about a minute)
    .venv/bin/python benchmarks/bench_symbolic_model.py --quick        # smoke test
    .venv/bin/python benchmarks/bench_symbolic_model.py --json benchmarks/results/symbolic_model.json

Models, all the same equations (docs/mathematics.md):
- "built-in": hc.ShipModel (C++, the C code generated from the ship's statement compiled in);
- "casadi": the same statement (hinf_cpp.models.builtin.ship) compiled at run time by
  hinf_cpp.models.symbolic (generated C code in a shared library in a cache, called from C++);
- "python": a subclass of hc.Model in this file (NumPy; every call goes through Python).

Workloads: "design" (the GRDE of Figure 1, method bdf), "state feedback" (the whole Figure 1
run: trajectory, GRDE, closed loop, metrics) and "output feedback" (the whole Figure 2 run),
each as hc.run_scenario / hc.solve_grde on the shipped scenario with the model swapped in.
Timing: wall-clock around one call, median [min-max] of repeated calls, garbage collector off;
the machine is shared, so the ratios to "built-in" are taken side by side in one process.
First use: generation and compilation of the symbolic model into an empty cache, and the same
build again (a cache hit), median of 3.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import json  # noqa: E402
import pathlib  # noqa: E402
import pickle  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

import hinf_cpp as hc  # noqa: E402
from hinf_cpp.models import builtin  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from bench_paper_fig1 import cpu_model, ms, timed  # noqa: E402

P = {"m_u": 0.5, "m_v": -2.0, "m_r": 0.5, "d_u": 1.0, "d_v": 2.0, "d_r": 1.0}


class PythonShip(hc.Model):
    """The ship as a user would first write it: a Python subclass with NumPy."""

    def name(self): return "python-ship"
    def n(self): return 6
    def m(self): return 2
    def nw(self): return 6

    def f(self, t, q):
        u, v, r, x, y, psi = q
        c, s = np.cos(psi), np.sin(psi)
        return np.array([P["m_u"] * v * r - P["d_u"] * u, P["m_v"] * u * r - P["d_v"] * v,
                         P["m_r"] * u * v - P["d_r"] * r, u * c - v * s, u * s + v * c, r])

    def dfdq(self, t, q):
        u, v, r, x, y, psi = q
        c, s = np.cos(psi), np.sin(psi)
        J = np.zeros((6, 6))
        J[0, :3] = [-P["d_u"], P["m_u"] * r, P["m_u"] * v]
        J[1, :3] = [P["m_v"] * r, -P["d_v"], P["m_v"] * u]
        J[2, :3] = [P["m_r"] * v, P["m_r"] * u, -P["d_r"]]
        J[3, 0], J[3, 1], J[3, 5] = c, -s, -u * s - v * c
        J[4, 0], J[4, 1], J[4, 5] = s, c, u * c - v * s
        J[5, 2] = 1.0
        return J

    def G(self, t, q):
        G = np.zeros((6, 2))
        G[0, 0] = G[2, 1] = 1.0
        return G

    def D(self, t, q): return np.diag([1.0, 1.0, 1.0, 0.0, 0.0, 0.0])
    def C(self, t): return np.hstack([np.zeros((3, 3)), np.eye(3)])
    def noise_channels(self): return [3, 4, 5]
    def state_names(self): return ["u", "v", "r", "x", "y", "psi"]
    def position_indices(self): return [3, 4]
    def heading_index(self): return 5


def with_model(scenario, model):
    copy = pickle.loads(pickle.dumps(scenario))
    copy.model = model
    return copy


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--json")
    args = parser.parse_args()
    repeat = 1 if args.quick else 7

    with tempfile.TemporaryDirectory() as cache:
        first = [builtin.ship().build(pathlib.Path(cache) / f"first{k}") for k in range(1 if args.quick else 3)]
        again = [builtin.ship().build(pathlib.Path(cache) / "first0") for _ in range(3)]
        build_first = float(np.median([b.generate_seconds + b.compile_seconds for b in first]))
        generate = float(np.median([b.generate_seconds for b in first]))
        started = time.perf_counter()
        for _ in range(3):
            builtin.ship().build(pathlib.Path(cache) / "first0")
        build_hit = (time.perf_counter() - started) / 3
        assert all(b.cache_hit for b in again)
        casadi_ship = builtin.ship().compile(cache_dir=pathlib.Path(cache) / "first0")

        models = {"built-in": hc.ShipModel(), "casadi": casadi_ship, "python": PythonShip()}
        fig1 = hc.load_scenario(hc.scenario_path("paper_fig1"))
        fig2 = hc.load_scenario(hc.scenario_path("paper_fig2"))
        rows = {}
        for label, model in models.items():
            s1, s2 = with_model(fig1, model), with_model(fig2, model)
            trajectory = hc.Trajectory(model, s1.desired_q0, s1.desired_u, s1.t0, s1.tf)
            solver = hc.SolverOptions("bdf")
            rows[label] = {
                "design": timed(lambda: hc.solve_grde(trajectory, s1.Q, s1.Qf, s1.gamma, solver), repeat),
                "state feedback": timed(lambda: hc.run_scenario(s1), repeat),
                "output feedback": timed(lambda: hc.run_scenario(s2), max(1, repeat // 2)),
            }

    workloads = ("design", "state feedback", "output feedback")
    lines = [f"# ship as built-in, CasADi-generated and Python-subclass model ({cpu_model()}, {platform.python_version()})",
             f"# median [min-max] ms over {repeat} calls; ratio = median / built-in median", ""]
    lines.append(f"{'workload':<16} {'model':<9} {'ms':>28} {'ratio':>7}")
    for workload in workloads:
        base = rows["built-in"][workload]["median"]
        for label in models:
            t = rows[label][workload]
            lines.append(f"{workload:<16} {label:<9} {ms(t):>28} {t['median'] / base:7.2f}")
    lines += ["", f"first use of the symbolic ship: generation + compilation {build_first:.2f} s "
                  f"(generation {generate:.2f} s); a second build (cache hit) {1e3 * build_hit:.1f} ms"]
    text = "\n".join(lines)
    print(text)
    if args.json:
        out = {"cpu": cpu_model(), "python": platform.python_version(), "repeat": repeat,
               "timings_s": rows, "ratios": {w: {m: rows[m][w]["median"] / rows["built-in"][w]["median"]
                                                  for m in models} for w in workloads},
               "first_build_s": build_first, "generate_s": generate, "cache_hit_build_s": build_hit}
        pathlib.Path(args.json).write_text(json.dumps(out, indent=2) + "\n")
        pathlib.Path(args.json).with_suffix(".txt").write_text(text + "\n")


if __name__ == "__main__":
    main()
