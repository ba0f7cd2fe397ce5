"""The receding horizon's cost per simulated second against the full-horizon design, and a
one-hour mission against real time.

The paper's Figure 1 (state feedback, default integrator, output every 1 s) run to tf by
run_scenario: once designed over [t0, tf] (the trajectory and the GRDE of the whole horizon,
then the loop), once with [receding_horizon] window = 10 s, update = 1 s (a window's trajectory
and GRDE every second, the loop window by window). Interleaved, medians of the repeats, the load
average written beside them. Then how the cost grows with the window H at tf = 400 s, with the
terminal weight Qf and with the stationary game ARE (which lets a 2 s window track as a long
design does on this path, docs/online.md).

    .venv/bin/python benchmarks/bench_receding_horizon.py [--repeats 5]
"""

import argparse
import os
import statistics
import time

import hinf_cpp as hc


def scenario(tf: float, receding: bool, window: float = 10.0, terminal: str = "qf") -> hc.Scenario:
    s = hc.load_scenario(hc.scenario_path("paper_fig1"))
    s.tf = tf
    s.output_dt = 1.0
    s.solver = hc.SolverOptions()  # the default (automatic) integrator
    if receding:
        s.receding_horizon = hc.RecedingHorizonOptions(window=window, update=1.0, terminal=terminal)
    return s


def seconds(s: hc.Scenario) -> float:
    start = time.perf_counter()
    result = hc.run_scenario(s)
    elapsed = time.perf_counter() - start
    assert result.simulation.status == hc.RunStatus.completed, result.simulation.status_message
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    print(f"load average before: {os.getloadavg()[0]:.2f}")
    print("| tf (s) | full horizon (s) | receding, H = 10 s (s) | receding per simulated second (ms) | ratio |")
    print("|---|---|---|---|---|")
    for tf in (40.0, 400.0):
        full, receding = [], []
        for _ in range(args.repeats):
            full.append(seconds(scenario(tf, False)))
            receding.append(seconds(scenario(tf, True)))
        f, r = statistics.median(full), statistics.median(receding)
        print(f"| {tf:.0f} | {f:.3f} | {r:.3f} | {1e3 * r / tf:.2f} | {r / f:.2f} |")
    print("\n| window H (s) | terminal | receding per simulated second (ms), tf = 400 s |")
    print("|---|---|---|")
    cases = [(2.0, "stationary"), (5.0, "qf"), (10.0, "qf"), (10.0, "stationary"), (20.0, "qf")]
    times = {case: [] for case in cases}
    for _ in range(args.repeats):
        for case in cases:
            times[case].append(seconds(scenario(400.0, True, *case)))
    for window, terminal in cases:
        print(f"| {window:.0f} | {terminal} | {1e3 * statistics.median(times[(window, terminal)]) / 400.0:.3f} |")
    mission = [seconds(scenario(3600.0, True)) for _ in range(max(1, args.repeats // 2))]
    m = statistics.median(mission)
    print(f"one-hour mission (3600 s), receding horizon: {m:.2f} s, {3600.0 / m:.0f} times real time")
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
