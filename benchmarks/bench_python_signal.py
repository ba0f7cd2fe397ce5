"""Benchmark: the desired input u_d(t) as a Python function against the built-in signals.

    .venv/bin/python benchmarks/bench_python_signal.py                 # full (about a minute)
    .venv/bin/python benchmarks/bench_python_signal.py --quick         # smoke test
    .venv/bin/python benchmarks/bench_python_signal.py --json benchmarks/results/python_signal.json

The paper's u_d(t) = [1, 0.3 sin(0.2 t)] given four ways:

- "harmonics": the scenario's own hc.VectorSignal (a constant and one harmonic, evaluated in C++);
- "table": an hc.Signal table per input, sampled every 0.1 s ("pchip"; the form of planned and
  measured inputs, evaluated in C++; an approximation of u_d, and a table makes the trajectory's
  integrator stop at every point);
- "NumPy function": ``lambda t: np.array([1.0, 0.3 * np.sin(0.2 * t)])``, the way a user writes it;
- "math function": the same with ``math.sin`` and a tuple (no NumPy array per call).

Workloads: the desired trajectory alone (``hc.Trajectory(ShipModel, q0, u_d, 0, 40)``: q_d
integrated by Dormand-Prince at rtol 1e-10), ``hc.run_scenario`` of scenarios/paper_fig1.toml
(state feedback, the scenario's BDF solver) and scenarios/paper_fig2.toml (output feedback) with
``scenario.desired_u`` set to each form, and ``hc.run_scenarios`` (the batch runner of studies)
on 4 copies of that paper_fig1 scenario with 1 thread. A function is called from C++ with the
GIL taken at every evaluation of u_d: in the trajectory's integrator, the closed loop and on the
output grid (the calls per workload are counted and printed).

Timing: wall-clock around one call, garbage collector off. Repetitions are interleaved: each
round times every form of every workload once, in an order that rotates from round to round,
so that a change of the machine's load hits all forms alike; median [min-max] over the rounds,
after a warm-up round. The ratio is median / median of "harmonics". The load average (1, 5 and
15 min) is written before and after. The answers are checked first: the NumPy and math
functions give the harmonics' q_d and metrics to the last bit (the same sin); the table's differ
by its interpolation error.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # see bench_paper_fig1.py

import argparse  # noqa: E402
import gc  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import pathlib  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

import hinf_cpp as hc  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from bench_paper_fig1 import core_fingerprint, cpu_model  # noqa: E402

FORMS = ("harmonics", "table", "NumPy function", "math function")
WORKLOADS = ("trajectory", "paper_fig1 run", "paper_fig2 run", "run_scenarios")
BATCH = 4  # copies of paper_fig1 in the run_scenarios workload


def numpy_u_d(t):
    return np.array([1.0, 0.3 * np.sin(0.2 * t)])


def math_u_d(t):
    return (1.0, 0.3 * math.sin(0.2 * t))


def table_u_d(t0: float, tf: float, step: float = 0.1) -> hc.VectorSignal:
    t = np.linspace(t0, tf, int(round((tf - t0) / step)) + 1)
    return hc.VectorSignal([hc.Signal.table(t, np.ones_like(t)), hc.Signal.table(t, 0.3 * np.sin(0.2 * t))])


class Counted:
    """u_d that counts its calls (used once, untimed, to count the evaluations of a workload)."""

    def __init__(self):
        self.calls = 0

    def __call__(self, t):
        self.calls += 1
        return numpy_u_d(t)


def forms(scenario: hc.Scenario) -> dict:
    return {"harmonics": scenario.desired_u, "table": table_u_d(scenario.t0, scenario.tf),
            "NumPy function": numpy_u_d, "math function": math_u_d}


def with_u_d(scenario: hc.Scenario, u_d) -> hc.Scenario:
    copy = scenario.copy()
    copy.desired_u = u_d
    return copy


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=21, help="timed rounds (each times every form once)")
    parser.add_argument("--quick", action="store_true", help="--repeat 3")
    parser.add_argument("--json", help="write every number (JSON) and the printed report beside it (.txt)")
    args = parser.parse_args()
    repeat = 3 if args.quick else args.repeat
    load_before = os.getloadavg()

    fig1 = hc.load_scenario(hc.scenario_path("paper_fig1"))
    fig2 = hc.load_scenario(hc.scenario_path("paper_fig2"))
    ship, q0 = fig1.model, fig1.desired_q0
    u_d = forms(fig1)
    jobs = {}
    for form, signal in u_d.items():
        s1, s2 = with_u_d(fig1, signal), with_u_d(fig2, signal)
        jobs[("trajectory", form)] = lambda signal=signal: hc.Trajectory(ship, q0, signal, fig1.t0, fig1.tf)
        jobs[("paper_fig1 run", form)] = lambda s=s1: hc.run_scenario(s)
        jobs[("paper_fig2 run", form)] = lambda s=s2: hc.run_scenario(s)
        jobs[("run_scenarios", form)] = lambda s=s1: hc.run_scenarios([s] * BATCH, hc.StudyOptions(threads=1))

    # The same answers first.
    grid = np.linspace(fig1.t0, fig1.tf, 4001)
    q_d = {form: jobs[("trajectory", form)]().q_d(grid) for form in FORMS}
    runs = {(w, form): jobs[(w, form)]() for w in WORKLOADS[1:3] for form in FORMS}
    for form in FORMS:  # the batch rows are run_scenario's
        batch = jobs[("run_scenarios", form)]()
        assert all(row.metrics == runs[("paper_fig1 run", form)].metrics for row in batch), form
    checks = {}
    for form in FORMS:
        checks[form] = {"max |q_d - q_d(harmonics)|": float(np.abs(q_d[form] - q_d["harmonics"]).max())}
        for w in WORKLOADS[1:3]:
            a, b = runs[(w, form)].metrics, runs[(w, "harmonics")].metrics
            checks[form][f"{w}: rms position error, last half, difference"] = abs(
                a.rms_position_error_last_half - b.rms_position_error_last_half)
        if form.endswith("function"):
            assert all(value == 0.0 for value in checks[form].values()), (form, checks[form])
        else:
            assert all(value < 1e-5 for value in checks[form].values()), (form, checks[form])

    calls = {}
    for w in WORKLOADS:
        counter = Counted()
        if w == "trajectory":
            hc.Trajectory(ship, q0, counter, fig1.t0, fig1.tf)
        elif w == "run_scenarios":
            hc.run_scenarios([with_u_d(fig1, counter)] * BATCH, hc.StudyOptions(threads=1))
        else:
            hc.run_scenario(with_u_d(fig1 if w == "paper_fig1 run" else fig2, counter))
        calls[w] = counter.calls

    # Interleaved rounds: every (workload, form) once per round, the order rotating.
    order = [(w, form) for w in WORKLOADS for form in FORMS]
    samples = {key: [] for key in order}
    gc.collect()
    gc.disable()
    try:
        for round_ in range(repeat + 1):
            shift = round_ % len(order)
            for key in order[shift:] + order[:shift]:
                started = time.perf_counter()
                jobs[key]()
                elapsed = time.perf_counter() - started
                if round_ > 0:  # round 0 is the warm-up
                    samples[key].append(elapsed)
    finally:
        gc.enable()
    load_after = os.getloadavg()

    stats = {}
    for (w, form), s in samples.items():
        stats.setdefault(w, {})[form] = {"median": float(np.median(s)), "min": min(s), "max": max(s), "all": s}
    lines = [(f"u_d as a Python function against the built-in signals (hinf_cpp {hc.__version__}, {cpu_model()}, "
              f"{os.cpu_count()} CPUs, Python {platform.python_version()}, NumPy {np.__version__})"),
             (f"load average before {load_before[0]:.2f} {load_before[1]:.2f} {load_before[2]:.2f}, "
              f"after {load_after[0]:.2f} {load_after[1]:.2f} {load_after[2]:.2f} (1, 5, 15 min)"),
             f"median [min-max] ms over {repeat} interleaved rounds; ratio = median / median of harmonics", ""]
    lines.append(f"{'workload':<15} {'u_d':<15} {'ms':>26} {'ratio':>7}")
    for w in WORKLOADS:
        base = stats[w]["harmonics"]["median"]
        for form in FORMS:
            t = stats[w][form]
            spread = f"{1e3 * t['median']:.3f} [{1e3 * t['min']:.3f}-{1e3 * t['max']:.3f}]"
            lines.append(f"{w:<15} {form:<15} {spread:>26} {t['median'] / base:7.2f}")
    lines.append("")
    for w in WORKLOADS:
        extra = stats[w]["NumPy function"]["median"] - stats[w]["harmonics"]["median"]
        lines.append(f"{w}: {calls[w]} calls of u_d; the NumPy function adds {1e3 * extra:.2f} ms, "
                     f"{1e6 * extra / calls[w]:.2f} us per call")
    lines.append("answers: the functions' q_d and metrics equal the harmonics' to the last bit; the table's q_d "
                 f"differs by up to {checks['table']['max |q_d - q_d(harmonics)|']:.1e} (its interpolation)")
    text = "\n".join(lines)
    print(text)
    if args.json:
        out = {"machine": {"cpu": cpu_model(), "cpus": os.cpu_count(), "python": platform.python_version(),
                           "numpy": np.__version__, "hinf_cpp": hc.__version__, "hinf_cpp_core": core_fingerprint(),
                           "load_avg_before": load_before, "load_avg_after": load_after},
               "repeat": repeat, "timings_s": stats, "calls": calls, "checks": checks,
               "ratios": {w: {form: stats[w][form]["median"] / stats[w]["harmonics"]["median"] for form in FORMS}
                          for w in WORKLOADS}}
        pathlib.Path(args.json).write_text(json.dumps(out, indent=2) + "\n")
        pathlib.Path(args.json).with_suffix(".txt").write_text(text + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
