"""The ``hinf-cpp`` command line.

    hinf-cpp run SCENARIO.toml [--json OUT.json] [--csv OUT.csv] [--plot OUT.png]
    hinf-cpp paper [--out DIR]

Exit status: 0 success, 2 bad input, 3 numerical failure (solver, conjugate point,
coupling condition). Errors are one line on stderr.
"""

from __future__ import annotations

import argparse
import math
import pathlib
import sys

from . import _core
from .plotting import save_figure, xy_figure
from .scenario import load_scenario

METRIC_NAMES = [
    "rms_position_error_last_half",
    "max_position_error",
    "final_position_error",
    "control_l2",
    "control_error_l2",
    "disturbance_l2",
    "l2_gain",
    "max_rho_sigma_z",
    "rms_estimation_error_last_half",
]


def _format(value) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "-"
    return f"{value:.6g}"


def summary(result: _core.RunResult) -> str:
    """A plain-text summary of a run: design facts, metrics, timings."""
    metrics = result.metrics
    lines = [f"scenario {result.scenario_name}: controller {result.controller}, "
             f"gamma = {result.gamma:g}",
             f"  Z(t) eigenvalues in [{result.Z_min_eig:.4g}, {result.Z_max_eig:.4g}]"]
    if math.isfinite(result.simulation.coupling_violation_t):
        lines.append(f"  coupling condition rho(Sigma Z) < gamma^2 violated from "
                     f"t = {result.simulation.coupling_violation_t:g}")
    if result.gamma_star is not None:
        lines.append(f"  gamma* = {result.gamma_star:.6g}")
    width = max(len(name) for name in METRIC_NAMES)
    for name in METRIC_NAMES:
        if math.isfinite(metrics[name]):
            lines.append(f"  {name:<{width}}  {_format(metrics[name])}")
    t = result.timing
    lines.append(f"  time: design {t.design * 1e3:.2f} ms, simulate {t.simulate * 1e3:.2f} ms, "
                 f"total {t.total * 1e3:.2f} ms")
    return "\n".join(lines)


def _write(path: str | pathlib.Path, text: str) -> None:
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def cmd_run(args: argparse.Namespace) -> int:
    scenario = load_scenario(args.scenario)
    result = _core.run_scenario(scenario)
    if args.json:
        _write(args.json, result.to_json() + "\n")
    if args.csv:
        _write(args.csv, result.to_csv())
    if args.plot:
        save_figure(xy_figure(result), args.plot)
    print(summary(result))
    return 0


def metrics_markdown(rows: list[tuple[str, _core.RunResult]]) -> str:
    """A Markdown table with one column per run."""
    header = "| metric | " + " | ".join(label for label, _ in rows) + " |"
    lines = [header, "|---" * (len(rows) + 1) + "|"]
    lines.append("| gamma | " + " | ".join(_format(r.gamma) for _, r in rows) + " |")
    for name in METRIC_NAMES:
        values = [r.metrics[name] for _, r in rows]
        if all(not math.isfinite(v) for v in values):
            continue
        lines.append(f"| {name} | " + " | ".join(_format(v) for v in values) + " |")
    return "\n".join(lines) + "\n"


def cmd_paper(args: argparse.Namespace) -> int:
    from . import scenario_path

    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for figure, name in [("Figure 1", "paper_fig1"), ("Figure 2", "paper_fig2")]:
        result = _core.run_scenario(load_scenario(scenario_path(name)))
        stem = name.replace("paper_", "")
        _write(out / f"{stem}.json", result.to_json() + "\n")
        _write(out / f"{stem}.csv", result.to_csv())
        save_figure(xy_figure(result, title=f"Paper {figure}: {result.scenario_name}"), out / f"{stem}_xy.png")
        print(summary(result))
        rows.append((figure, result))
    table = metrics_markdown(rows)
    _write(out / "metrics.md", table)
    print()
    print(table, end="")
    print(f"\nwrote {out}/: " + ", ".join(sorted(p.name for p in out.iterdir())))
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="hinf-cpp", description=__doc__.split("\n")[0])
    parser.add_argument("--version", action="version", version=_core.__version__)
    sub = parser.add_subparsers(dest="command", required=True)

    run = sub.add_parser("run", help="run a scenario and write the results file")
    run.add_argument("scenario", help="scenario file (TOML)")
    run.add_argument("--json", help="write the results file (JSON)")
    run.add_argument("--csv", help="write the time series (CSV)")
    run.add_argument("--plot", help="write the x-y plot (PNG, PDF or SVG)")
    run.set_defaults(handler=cmd_run)

    paper = sub.add_parser("paper", help="the paper's runs: figures, results files and a metrics table")
    paper.add_argument("--out", default="out/paper", help="output folder (default: out/paper)")
    paper.set_defaults(handler=cmd_paper)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.handler(args)
    except ValueError as error:
        return _fail(error, 2)
    except _core.HinfError as error:
        return _fail(error, 3)


def _fail(error: Exception, status: int) -> int:
    message = " ".join(str(error).split()) or type(error).__name__
    print(f"hinf-cpp: error: {message}", file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(main())
