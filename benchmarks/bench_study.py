"""Benchmark: a study's throughput, the Figure-2 Monte Carlo (output feedback, one design shared
across the noise seeds).

    .venv/bin/python benchmarks/bench_study.py                  # full (~4 min)
    .venv/bin/python benchmarks/bench_study.py --quick          # smoke test
    .venv/bin/python benchmarks/bench_study.py --seeds 300 --repeat 5 --json out.json

The study is scenarios/paper_fig2.toml with the H-infinity law and `--seeds` measurement-noise
seeds (a [[random]] "seed" axis): every run has the same design (trajectory, Z(t)) and its own
noise. Measured, each as runs per second, median [min - max] over `--repeat` repetitions:

1. a Python loop over hinf_cpp.run_scenario, one seed at a time (the scenarios built first);
2. hc.run_scenarios (the C++ batch runner, designs shared) on the same scenarios, 1 and 2 threads;
3. hinf_cpp.studies.study.run_study, the whole study (expansion, scenarios, table), 1 and 2 workers;
4. the same on a Dask LocalCluster of 2 worker processes (1 thread each), started before the
   timing (its start-up is reported apart);
5. the SciPy twin (run_reference of benchmarks/scipy_output_feedback.py), one seed at a time as a user
   would write the study with SciPy (design and loop per seed), on `--scipy-repeat` seeds.

Every timed call is preceded by a warm-up. ``--json OUT`` saves every number, the machine and
the load average.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # see bench_paper_fig2.py

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import pathlib  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import tomllib  # noqa: E402

import numpy as np  # noqa: E402

import hinf_cpp as hc  # noqa: E402
from hinf_cpp.studies import study as hs# noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from bench_paper_fig1 import core_fingerprint, cpu_model  # noqa: E402

SCENARIO = pathlib.Path(__file__).resolve().parents[1] / "scenarios" / "paper_fig2.toml"


def make_study(seeds: int, chunk: int) -> hs.Study:
    definition = {"study": {"name": "bench_fig2_monte_carlo", "seed": 20261124, "samples": seeds, "chunk": chunk},
                  "random": [{"key": "measurement.seed", "distribution": "seed"}]}
    base = tomllib.loads(SCENARIO.read_text())
    return hs.study_from_dict(definition, "bench", base=base)


class _Lines(list):
    """The report's lines, each printed as it is added."""

    def __init__(self, lines):
        super().__init__()
        for line in lines:
            self.append(line)

    def append(self, line: str) -> None:
        print(line, flush=True)
        super().append(line)


def rate(fn, runs: int, repeat: int) -> dict:
    """Runs per second of fn() (which does `runs` runs): median, min, max over `repeat`; and
    this process's CPU seconds per wall second (the cores it kept busy: a check on whether
    threads ran in parallel when other jobs share the machine)."""
    fn()  # warm-up
    samples, busy = [], []
    for _ in range(repeat):
        start, cpu = time.perf_counter(), time.process_time()
        fn()
        wall = time.perf_counter() - start
        samples.append(runs / wall)
        busy.append((time.process_time() - cpu) / wall)
    return {"median": float(np.median(samples)), "min": min(samples), "max": max(samples), "all": samples,
            "cores_busy": float(np.median(busy))}


def show(label: str, r: dict) -> str:
    return (f"  {label:<52} {r['median']:8.1f} runs/s  [{r['min']:.1f}-{r['max']:.1f}]"
            f"  cores busy {r['cores_busy']:.2f}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seeds", type=int, default=300)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--chunk", type=int, default=25,
                        help="runs per chunk (Dask task); 150 seeds in chunks of 25 keep 2 workers evenly busy")
    parser.add_argument("--scipy-repeat", type=int, default=2)
    parser.add_argument("--quick", action="store_true", help="--seeds 40 --repeat 1 --scipy-repeat 1")
    parser.add_argument("--json", help="write every number (JSON)")
    args = parser.parse_args(argv)
    if args.quick:
        args.seeds, args.repeat, args.scipy_repeat = 40, 1, 1
    study = make_study(args.seeds, args.chunk)
    scenarios = [study.scenario(i) for i in range(study.runs)]
    batch = "hc.run_scenarios (C++ batch runner)"
    results: dict = {"seeds": args.seeds, "repeat": args.repeat, "chunk": args.chunk, "batch_runner": batch}
    lines = _Lines([f"Figure-2 Monte Carlo: {args.seeds} noise seeds in chunks of {args.chunk}, hinf, output feedback "
                    "(design shared)",
             f"  load average before: {os.getloadavg()}"])

    results["python_loop"] = rate(lambda: [hc.run_scenario(s) for s in scenarios], len(scenarios), args.repeat)
    lines.append(show("Python loop over run_scenario", results["python_loop"]))
    for threads in (1, 2):
        results[f"batch_{threads}"] = rate(lambda: hs._batch(scenarios, threads), len(scenarios), args.repeat)
        lines.append(show(f"{batch}, {threads} thread(s)", results[f"batch_{threads}"]))
    for workers in (1, 2):
        results[f"study_{workers}"] = rate(lambda: hs.run_study(study, workers=workers, progress=False),
                                           study.runs, args.repeat)
        lines.append(show(f"hinf_cpp.studies.study.run_study, {workers} worker(s)", results[f"study_{workers}"]))
    results["speedup_1_to_2"] = results["study_2"]["median"] / results["study_1"]["median"]
    lines.append(f"  speed-up 1 -> 2 workers: {results['speedup_1_to_2']:.2f}x (target >= 1.8)")

    from dask.distributed import Client, LocalCluster

    start = time.perf_counter()
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                           silence_logs=50)
    client = Client(cluster)
    results["dask_startup_s"] = time.perf_counter() - start
    try:
        results["dask_2"] = rate(lambda: hs.run_study(study, client=client, progress=False), study.runs, args.repeat)
    finally:
        client.close()
        cluster.close()
    results["dask_vs_local"] = results["dask_2"]["median"] / results["study_2"]["median"]
    lines.append(show("Dask LocalCluster, 2 processes x 1 thread", results["dask_2"]))
    lines.append(f"  Dask / local 2 workers: {results['dask_vs_local']:.2f} (target >= 0.75); "
                 f"cluster start-up {results['dask_startup_s']:.1f} s (not timed above)")

    import scipy_output_feedback as twin

    seconds = []
    for i in range(args.scipy_repeat):
        noise = hc.scenario_noise(scenarios[i])
        start = time.perf_counter()
        twin.run_reference(noise)
        seconds.append(time.perf_counter() - start)
    scipy_rate = [1.0 / s for s in seconds]
    results["scipy_one_seed_at_a_time"] = {"median": float(np.median(scipy_rate)), "min": min(scipy_rate),
                                           "max": max(scipy_rate), "all": scipy_rate, "cores_busy": math.nan}
    lines.append(show("SciPy twin, one seed at a time (design per seed)", results["scipy_one_seed_at_a_time"]))
    results["study_2_vs_scipy"] = results["study_2"]["median"] / results["scipy_one_seed_at_a_time"]["median"]
    lines.append(f"  study (2 workers) / SciPy: {results['study_2_vs_scipy']:.0f}x")
    lines.append(f"  load average after: {os.getloadavg()}")
    if args.json:
        import scipy

        results["machine"] = {"cpu": cpu_model(), "cores": os.cpu_count(), "python": platform.python_version(),
                              "numpy": np.__version__, "scipy": scipy.__version__, "hinf_cpp": hc.__version__,
                              "core": core_fingerprint(), "load_average_after": os.getloadavg(),
                              "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())}
        pathlib.Path(args.json).write_text(json.dumps(results, indent=2) + "\n")
        pathlib.Path(args.json).with_suffix(".txt").write_text("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
