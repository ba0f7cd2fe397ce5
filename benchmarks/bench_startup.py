"""Benchmark: the start-up of the ``hinf-cpp`` command against the whole ``hinf-sim`` process.

    .venv/bin/python benchmarks/bench_startup.py                 # 25 rounds (about 10 s)
    .venv/bin/python benchmarks/bench_startup.py --quick         # smoke test
    .venv/bin/python benchmarks/bench_startup.py --json benchmarks/results/startup.json

Five whole processes, each started from here and timed from start to exit (wall clock around
``subprocess.run``, output discarded):

- (a) ``python -c pass``: the interpreter alone (the venv's python);
- (b) ``python -c "import hinf_cpp._core"``: the extension alone;
- (c) ``hinf-sim scenarios/paper_fig1.toml --json OUT``: the C++ program, the Figure-1 run;
- (d) ``hinf-cpp run scenarios/paper_fig1.toml --json OUT``: the same run by the command line;
- (e) ``hinf-cpp --help``: the command line's imports and parser, no work.

Rounds are interleaved (a, b, c, d, e, a, b, ...), after one warm-up round that is not
counted, so that a change of the machine's load hits every process alike; median [min-max] over
the rounds. The children get this process's environment as it is (no OPENBLAS_NUM_THREADS
set: NumPy's start-up is what a user's command pays). The load average (1, 5 and 15 min) is
written before and after. The target (issue 24): (d) at most 1.5 times (c). Before anything is
timed, (c) and (d) must write the same metrics. The package is measured as installed: with
stale bytecode (sources copied over an install while PYTHONDONTWRITEBYTECODE is set) every
process compiles the modules it imports, so run ``python -m compileall`` on it first.
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import platform
import statistics
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
SCENARIO = ROOT / "scenarios" / "paper_fig1.toml"
TARGET = 1.5  # (d) / (c), issue 24
# The programs of the environment this benchmark runs in (not resolved: a venv's python is a link).
BIN = pathlib.Path(sys.executable).parent


def commands(out: pathlib.Path) -> dict[str, list[str]]:
    """The five processes, by label; `out` is the folder of the results files."""
    python = str(BIN / "python") if (BIN / "python").exists() else sys.executable
    return {
        "python -c pass": [python, "-c", "pass"],
        "import hinf_cpp._core": [python, "-c", "import hinf_cpp._core"],
        "hinf-sim run": [str(BIN / "hinf-sim"), str(SCENARIO), "--json", str(out / "sim.json")],
        "hinf-cpp run": [str(BIN / "hinf-cpp"), "run", str(SCENARIO), "--json", str(out / "cpp.json")],
        "hinf-cpp --help": [str(BIN / "hinf-cpp"), "--help"],
    }


def timed(command: list[str]) -> float:
    """Wall time (s) of one whole process; a failure stops the benchmark."""
    started = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    elapsed = time.perf_counter() - started
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed ({done.returncode}): {done.stderr.decode().strip()}")
    return elapsed


def same_metrics(out: pathlib.Path) -> None:
    """(c) and (d) ran the same scenario: their results files give the same metrics."""
    sim, cpp = (json.loads((out / name).read_text()) for name in ("sim.json", "cpp.json"))
    if sim.get("metrics") != cpp.get("metrics"):
        raise SystemExit("hinf-sim and hinf-cpp run wrote different metrics")


def machine() -> dict:
    """What ran: CPU, Python, the package and the fingerprint of its extension (this process
    imports them only to say so; the timed processes are separate)."""
    sys.path.insert(0, str(HERE))
    from bench_paper_fig1 import core_fingerprint, cpu_model, hc  # noqa: E402 - beside this file

    return {"cpu": cpu_model(), "cpus": os.cpu_count(), "python": platform.python_version(),
            "hinf_cpp": hc.__version__, "hinf_cpp_core": core_fingerprint()}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=25, help="timed rounds (each starts every process once)")
    parser.add_argument("--quick", action="store_true", help="--rounds 3")
    parser.add_argument("--json", help="write every number (JSON) and the printed report beside it (.txt)")
    args = parser.parse_args()
    rounds = 3 if args.quick else args.rounds
    about = machine()

    with tempfile.TemporaryDirectory() as folder:
        out = pathlib.Path(folder)
        jobs = commands(out)
        samples = {label: [] for label in jobs}
        load_before = os.getloadavg()
        for round_ in range(rounds + 1):
            for label, command in jobs.items():
                elapsed = timed(command)
                if round_ > 0:  # round 0 is the warm-up (the page cache)
                    samples[label].append(elapsed)
            if round_ == 0:
                same_metrics(out)
        load_after = os.getloadavg()

    stats = {label: {"median": statistics.median(s), "min": min(s), "max": max(s), "all": s}
             for label, s in samples.items()}
    ratio = stats["hinf-cpp run"]["median"] / stats["hinf-sim run"]["median"]
    lines = [(f"start-up of hinf-cpp against hinf-sim, scenarios/paper_fig1.toml (hinf_cpp {about['hinf_cpp']}, "
              f"{about['cpu']}, {about['cpus']} CPUs, Python {about['python']})"),
             (f"load average before {load_before[0]:.2f} {load_before[1]:.2f} {load_before[2]:.2f}, "
              f"after {load_after[0]:.2f} {load_after[1]:.2f} {load_after[2]:.2f} (1, 5, 15 min)"),
             f"whole-process wall time, median [min-max] ms over {rounds} interleaved rounds", ""]
    for key, label in zip("abcde", jobs):
        t = stats[label]
        lines.append(f"({key}) {label:<22} {1e3 * t['median']:8.1f} [{1e3 * t['min']:.1f}-{1e3 * t['max']:.1f}]")
    lines += ["", f"hinf-cpp run / hinf-sim run: {ratio:.2f} (target at most {TARGET:g}: "
                  f"{'met' if ratio <= TARGET else 'missed'})"]
    text = "\n".join(lines)
    print(text)
    if args.json:
        document = {"machine": {**about, "load_avg_before": load_before, "load_avg_after": load_after},
                    "rounds": rounds, "commands": {label: command[:1] + [part.replace(str(ROOT) + "/", "")
                                                                            for part in command[1:]]
                                                   for label, command in commands(pathlib.Path("OUT")).items()},
                    "timings_s": stats, "ratio_run": ratio, "target_ratio": TARGET}
        pathlib.Path(args.json).write_text(json.dumps(document, indent=2) + "\n")
        pathlib.Path(args.json).with_suffix(".txt").write_text(text + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
