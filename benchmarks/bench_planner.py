"""Benchmark: the trajectory planner (hinf_cpp.planning.planner, docs/planning.md) on every shipped planned
scenario (scenarios/planned/*.toml).

    .venv/bin/python benchmarks/bench_planner.py                 # 5 plans per scenario
    .venv/bin/python benchmarks/bench_planner.py --repeat 1      # smoke test
    .venv/bin/python benchmarks/bench_planner.py --json benchmarks/results/planner.json

Each scenario is planned from scratch (no cache) `--repeat` times in one process: wall-clock
time of the whole hinf_cpp.scenario.planned.plan_scenario call (reading the scenario, building
the problem, the IPOPT solves, the re-simulation and checks), median [min-max]; IPOPT's
iterations (summed over the solves of one plan: the coarse solve, the accurate one, any
refinement); the re-simulation mismatch. The target: the ship's 60 s lane change in at most 2 s.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import gc  # noqa: E402
import json  # noqa: E402
import pathlib  # noqa: E402
import platform  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402
import tomllib  # noqa: E402

import hinf_cpp as hc  # noqa: E402
from hinf_cpp.scenario.planned import plan_scenario  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
TARGET = ("ship_lane_change", 2.0)  # scenario, seconds


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--json", help="write every number (JSON)")
    args = parser.parse_args()
    rows = []
    for path in sorted((ROOT / "scenarios" / "planned").glob("*.toml")):
        root = tomllib.loads(path.read_text())
        times, planned = [], None
        gc.disable()
        for _ in range(args.repeat):
            started = time.perf_counter()
            planned = plan_scenario(root, str(path), cache=False)
            times.append(time.perf_counter() - started)
        gc.enable()
        report = planned.plan.report
        rows.append({"scenario": path.stem, "median_s": statistics.median(times), "min_s": min(times),
                     "max_s": max(times), "iterations": report.iterations, "intervals": report.intervals,
                     "substeps": report.substeps, "waypoints": len(planned.plan.waypoints),
                     "position_mismatch": report.position_mismatch,
                     "max_waypoint_error": max(report.waypoint_errors)})
    print(f"planner, {args.repeat} plans per scenario (no cache), hinf_cpp {hc.__version__}, "
          f"load average {os.getloadavg()[0]:.1f}")
    print(f"{'scenario':<28} {'median s':>9} {'[min-max]':>14} {'iterations':>10} {'intervals x RK4':>16} "
          f"{'mismatch':>9}")
    for r in rows:
        spread = "[{:.2f}-{:.2f}]".format(r["min_s"], r["max_s"])
        grid = "{} x {}".format(r["intervals"], r["substeps"])
        print(f"{r['scenario']:<28} {r['median_s']:9.3f} {spread:>14} {r['iterations']:10d} {grid:>16} "
              f"{r['position_mismatch']:9.1e}")
    target = next(r for r in rows if r["scenario"] == TARGET[0])
    met = target["median_s"] <= TARGET[1]
    print(f"target: {TARGET[0]} in at most {TARGET[1]:g} s: {'met' if met else 'missed'} "
          f"({target['median_s']:.3f} s)")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(
            {"machine": platform.platform(), "python": platform.python_version(), "hinf_cpp": hc.__version__,
             "load_average": os.getloadavg(), "repeat": args.repeat, "results": rows,
             "target": {"scenario": TARGET[0], "seconds": TARGET[1], "met": met}}, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
