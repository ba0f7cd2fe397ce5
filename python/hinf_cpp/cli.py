"""The ``hinf-cpp`` command line.

    hinf-cpp run SCENARIO.toml [--set KEY=VALUE ...] [--seed N] [--json OUT.json] [--csv OUT.csv] [--npz OUT.npz]
                 [--plot OUT.png] [--marine] [--gamma-star]
    hinf-cpp plan SCENARIO.toml -o PLANNED.toml [--json REPORT.json] [--plot OUT.png] [--no-cache]
    hinf-cpp compare SCENARIO.toml [--controllers hinf,lqr,cascade] [--feedback state,output]
                     [--worst-case] [--json OUT.json] [--plot OUT.png] [--marine] [--quiet]
    hinf-cpp recovery [SCENARIO.toml ...] [--controllers ...] [--json OUT.json] [--plot OUT.png] [--marine] [--quiet]
    hinf-cpp report SCENARIO.toml --out DIR [--controllers ...] [--pdf] [--marine] [--quiet]
    hinf-cpp gamma-star SCENARIO.toml [--output-feedback] [--json OUT.json] [bracket options]
    hinf-cpp certify SCENARIO.toml [--json OUT.json]
    hinf-cpp sweep-gamma SCENARIO.toml [--plot OUT.png] [--json OUT.json] [--count N] [--quiet]
    hinf-cpp gain-frequency SCENARIO.toml -o OUTDIR [--laws hinf,lqr] [--channels 1,2,3]
                            [--frequencies LOW:HIGH:COUNT | W1,W2,...] [--amplitude A] [--quiet]
    hinf-cpp paper [--out DIR] [--marine] [--quiet]
    hinf-cpp animate SCENARIO.toml -o RUN.gif|RUN.mp4 [--frames N] [--fps F] [--width PIXELS] [--marine]
    hinf-cpp vehicles [--out DIR] [--quiet]
    hinf-cpp planned [--out DIR] [--no-cache] [--quiet]
    hinf-cpp study STUDY.toml --out DIR [--workers N | --scheduler ADDRESS] [--quiet]
    hinf-cpp export-controller SCENARIO.toml --out DIR [--sample-period T]

Every command takes --trust-code (the same as HINF_TRUST_CODE=1): without it a file that names
code to run (a [model] of kind "casadi" or "python") is refused before anything is loaded
(docs/trust.md).

Exit status: 0 success, 2 bad input (bad options, unusable output paths, a full disk and runs
too large for the memory included), 3 numerical failure (solver, conjugate point, coupling
condition), 130 interrupted (Ctrl-C stops a computation at its next step: "interrupted"), 1 a
bug, and for `study` a study whose runs all failed. Errors are one line on stderr, with nothing before them. Every output
path is checked before the computation starts, and every file is written whole or not at
all. The longer commands show a live progress line on stderr when it is a terminal (off with
--quiet).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import pathlib
import sys
import time
import warnings

from hinf_cpp import _core
from hinf_cpp.output.animation_options import (DEFAULT_FPS, DEFAULT_FRAMES, DEFAULT_WIDTH, MAX_FPS, MAX_FRAMES,
                                               MAX_WIDTH, MIN_WIDTH)
from hinf_cpp.output.files import check_output_folder, check_output_path, write_text
from hinf_cpp.output.tables import Feedback, markdown_table, run_key, text_table
from hinf_cpp.scenario import load_scenario

# Above: what every command and the parser need, all light. Each command imports the rest itself
# (analyses, figures, exports, the planner, studies): a plain `run` loads none of pandas,
# matplotlib, SciPy, CasADi or Pillow (tests/python/test_cli_startup.py).

# Words shared with hinf-sim (cpp/app/hinf_sim.cpp).
OUT_OF_MEMORY = "not enough memory for this run: shorten the horizon, use a larger [output] dt or shorter tables"

METRIC_NAMES = [definition.name for definition in _core.metric_table()]


def _format(value) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "-"
    return f"{value:.6g}"


def summary(result: _core.RunResult) -> str:
    """A plain-text summary of a run: design facts, metrics, timings."""
    metrics = result.metrics
    lines = [f"scenario {result.scenario_name}: controller {run_key(result.law, result.output_feedback)}, "
             f"gamma = {result.gamma:g}",
             f"  Z(t) eigenvalues in [{result.Z_min_eig:.4g}, {result.Z_max_eig:.4g}]"]
    if result.plant is not None:
        # [plant]: the vehicle integrated differs from the design model; say how.
        design = result.trajectory.model().named_parameters()
        changed = [f"{name} = {value:g}" for name, value in result.plant.named_parameters().items()
                   if design.get(name) != value]
        lines.append(f"  plant: {result.plant.name()}"
                     + (f" ({', '.join(changed)})" if changed else " (the design model's parameters)"))
    if result.sampling is not None:
        # [sampling]: the loop ran through the online controller; what its steps did.
        online, sampling = result.online, result.sampling
        lines.append(f"  sampled: {sampling.design.name} law every {sampling.period:g} s, delay {sampling.delay:g} s; "
                     f"{online.steps} steps, {online.used} measurements used, {online.saturated} saturated, "
                     f"largest |u| {online.largest_command:.4g}"
                     + (f", {online.lost} lost" if online.lost else "")
                     + (f", coupling violated at {online.coupling_violated} steps" if online.coupling_violated else ""))
    estimator = result.simulation.estimator
    if estimator is not None and math.isfinite(estimator.coupling_violation_t):
        lines.append(f"  coupling condition rho(Sigma Z) < gamma^2 violated from "
                     f"t = {estimator.coupling_violation_t:g}")
    if result.simulation.status != _core.RunStatus.completed:
        lines.append(f"  status: {result.simulation.status.name} ({result.simulation.status_message})")
    if result.gamma_star is not None:
        lines.append(f"  gamma* = {result.gamma_star:.6g}")
    width = max(len(name) for name in METRIC_NAMES)
    for name in METRIC_NAMES:
        value = getattr(metrics, name)
        if math.isfinite(value):
            lines.append(f"  {name:<{width}}  {_format(value)}")
    t = result.timing
    lines.append(f"  time: design {t.design * 1e3:.2f} ms, simulate {t.simulate * 1e3:.2f} ms, "
                 f"total {t.total * 1e3:.2f} ms")
    return "\n".join(lines)


def _check_outputs(files=(), figures=(), folders=()) -> None:
    """Checks the output paths given (None: not asked for) before any computation."""
    for path in files:
        if path is not None:
            check_output_path(path)
    for path in figures:
        if path is not None:
            check_output_path(path, figure=True)
    for path in folders:
        if path is not None:
            check_output_folder(path)


def _seed(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid seed '{text}': an integer in [0, 2^63)") from None
    if not 0 <= value < 2 ** 63:
        raise argparse.ArgumentTypeError(f"invalid seed '{text}': an integer in [0, 2^63)")
    return value


def _gamma_star_options(args: argparse.Namespace) -> _core.GammaStarOptions:
    return _core.GammaStarOptions(lower=args.lower, upper=args.upper, rtol=args.rtol,
                                  max_evaluations=args.max_evaluations, threads=args.threads)


def _number(x):
    return float(x) if x is not None and math.isfinite(x) else None


def _load_with_plan(path: str):
    """(scenario, PlannedScenario or None): a file whose [desired] or [path_change] gives
    waypoints or a path is planned (cached; docs/planning.md)."""
    from hinf_cpp.scenario.planned import load_planned

    planned = load_planned(path)
    if planned is None:
        return load_scenario(path), None
    load_scenario(path)  # the warnings of the file (the plan comes from the cache)
    return planned.scenario, planned


def _planned_what(planned, table: str, plan) -> str:
    """What a plan of a planned scenario is, for the lines that report it."""
    if table == "[path_change]":
        return f"the path change at t = {plan.t0:g} s through {len(plan.waypoints)} waypoints"
    return f"u_d through {len(plan.waypoints)} waypoints"


def _print_plans(planned) -> None:
    for table, plan in planned.plans():
        print(f"planned {_planned_what(planned, table, plan)}: {plan.report.summary()}")


def _planned_waypoints(planned) -> list:
    """The waypoints of every plan of a planned scenario (none without one), for the x-y figure."""
    return [w for _, plan in planned.plans() for w in plan.waypoints] if planned is not None else []


def _load_with_settings(path: str, settings: list[str], seed: int | None):
    """The scenario file with --set KEY=VALUE applied in order, then --seed N ([measurement]
    seed), read by the one C++ reader (hinf_cpp.scenario.settings.apply_settings)."""
    from hinf_cpp.scenario import scenario_from_dict
    from hinf_cpp.scenario.documents import read_toml_file
    from hinf_cpp.scenario.settings import apply_settings, parse_setting

    pairs = [parse_setting(text) for text in settings]
    document = read_toml_file(path)
    try:
        document = apply_settings(document, pairs, seed)
    except ValueError as error:
        raise ValueError(f"{path}: {error}") from None
    return scenario_from_dict(document, path)


def cmd_run(args: argparse.Namespace) -> int:
    if args.npz is not None:
        from hinf_cpp.output.export import npz_path, save_npz

    _check_outputs(files=[args.json, args.csv, None if args.npz is None else npz_path(args.npz)],
                   figures=[args.plot])
    if args.set or args.seed is not None:
        scenario, planned = _load_with_settings(args.scenario, args.set, args.seed), None
    else:
        scenario, planned = _load_with_plan(args.scenario)
    if planned is not None:
        _print_plans(planned)
    result = _core.run_scenario(scenario)
    if args.gamma_star:
        result.gamma_star = _core.scenario_gamma_star(scenario).gamma_star
    if args.json is not None:
        write_text(args.json, _core.results_json(result) + "\n")
    if args.csv is not None:
        write_text(args.csv, _core.results_csv(result))
    if args.npz is not None:
        save_npz(result, args.npz)
    if args.plot is not None:
        from hinf_cpp.output.plotting import save_figure, xy_figure

        save_figure(xy_figure(result, waypoints=_planned_waypoints(planned), marine=args.marine), args.plot)
    print(summary(result))
    if result.simulation.status != _core.RunStatus.completed:
        print(f"hinf-cpp: warning: the run {result.simulation.status.name}: {result.simulation.status_message}",
              file=sys.stderr)
    return 0


def planned_scenario_text(planned, output) -> str:
    """The planned scenario as a scenario file to be written at `output` (hinf-sim runs it as
    is), with a header saying where its inputs come from. A model compiled from CasADi is copied
    beside `output` (hinf_cpp.scenario.planned.planned_scenario_toml): the file never points
    into a cache."""
    from hinf_cpp.scenario.planned import planned_scenario_toml

    lines = []
    for table, plan in planned.plans():
        what = "u_d" if table == "[desired]" else f"the inputs of [path_change] (the path from t = {plan.t0:g} s)"
        lines += [f"# Planned by hinf-cpp plan from {planned.source}: {what} through the waypoints below,",
                  "# as tables with interpolation = \"linear\" (the optimizer's inputs, docs/planning.md).",
                  f"# {plan.report.summary()}.",
                  "# Waypoints:"]
        lines += [f"#   {j}: {w.describe()}" for j, w in enumerate(plan.waypoints)]
    return "\n".join(lines) + "\n" + planned_scenario_toml(planned, output)


def plan_dict(planned) -> dict:
    """The plans' reports for --json: the feasibility check, the solver's effort, the waypoints;
    those of [desired] at the top level, those of [path_change] under "path_change" (with its t)."""
    import dataclasses

    document = {"scenario": planned.scenario.name, "model": planned.scenario.model.name()}
    for table, plan in planned.plans():
        entry = {"waypoints": [dataclasses.asdict(w) for w in plan.waypoints], "report": plan.report.to_dict()}
        if table == "[path_change]":
            document["path_change"] = dict(t=plan.t0, **entry)
        else:
            document.update(entry)
    return document


def cmd_plan(args: argparse.Namespace) -> int:
    from hinf_cpp.scenario.planned import load_planned

    _check_outputs(files=[args.output, args.json], figures=[args.plot])
    planned = load_planned(args.scenario, cache=not args.no_cache)
    if planned is None:
        load_scenario(args.scenario)  # a file that cannot be read or parsed: the reader's message
        raise ValueError(f"{args.scenario}: neither [desired] nor [path_change] gives waypoints or a path: there is "
                         "nothing to plan (docs/planning.md)")
    write_text(args.output, planned_scenario_text(planned, args.output))
    for table, plan in planned.plans():
        report = plan.report
        print(f"scenario {planned.scenario.name}: planned {_planned_what(planned, table, plan)} for the "
              f"{plan.model.name()} model")
        print(f"  {report.summary()}")
        print(f"  waypoint errors (re-simulated): max {max(report.waypoint_errors):.3g}; IPOPT {report.status}")
    if args.json is not None:
        write_text(args.json, json.dumps(plan_dict(planned), indent=2) + "\n")
    if args.plot is not None:
        from hinf_cpp.output.plotting import plan_figure, save_figure

        # The plan of [desired], else that of [path_change].
        table, plan = planned.plans()[0]
        title = f"{planned.scenario.name}: planned" + ("" if table == "[desired]" else f" {table}")
        save_figure(plan_figure(plan, title=title), args.plot)
    print(f"wrote {args.output}")
    return 0


def gamma_star_dict(result: _core.GammaStarResult) -> dict:
    return {
        "gamma_star": _number(result.gamma_star),
        "lower": _number(result.lower),
        "upper": _number(result.upper),
        "t_escape_lower": _number(result.t_escape_lower),
        "binding": result.binding.name,
        "converged": result.converged,
        "evaluations": len(result.trials),
        "trials": [{"gamma": t.gamma, "passed": t.passed, "t_escape": _number(t.t_escape),
                    "condition": t.condition.name} for t in result.trials],
    }


def cmd_gamma_star(args: argparse.Namespace) -> int:
    _check_outputs(files=[args.json])
    scenario = load_scenario(args.scenario)
    options = _gamma_star_options(args)
    if args.output_feedback:
        result = _core.scenario_gamma_star_output_feedback(scenario, options)
        what = "output-feedback gamma (GRDE, filter (36) with A_e, rho(Sigma Z) < gamma^2)"
    else:
        result = _core.scenario_gamma_star(scenario, options)
        what = "gamma* (eq. 14, no conjugate point of the GRDE on [t0, tf])"
    print(f"scenario {scenario.name}: {what}")
    print(f"  gamma* = {result.gamma_star:.8g}")
    print(f"  bracket [{result.lower:.8g}, {result.upper:.8g}]"
          + ("" if result.converged else "  (not converged: max_evaluations reached)"))
    if math.isfinite(result.t_escape_lower):
        print(f"  at gamma = {result.lower:.8g}: {result.binding.name} fails at t = {result.t_escape_lower:.6g}")
    elif result.binding != _core.GammaCondition.none:
        print(f"  at gamma = {result.lower:.8g}: {result.binding.name} fails")
    print(f"  {len(result.trials)} evaluations")
    if args.json is not None:
        write_text(args.json, json.dumps({"scenario": scenario.name, **gamma_star_dict(result)}, indent=2) + "\n")
    return 0


def cmd_certify(args: argparse.Namespace) -> int:
    from hinf_cpp.analysis.gamma_sweep import certificates_dict

    _check_outputs(files=[args.json])
    scenario = load_scenario(args.scenario)
    c = _core.scenario_certificates(scenario)
    print(f"scenario {scenario.name}: certificates of paper §3 at gamma = {scenario.gamma:g}")
    print(f"  (22)  m = {c.m:.6g}, M = {c.M:.6g}   (m I <= Z(t) <= M I on [t0, tf])")
    print(f"        kappa >= {c.kappa_min:.6g}" + ("" if c.kappa_min >= 0.5 else
                                                    "  (below 1/2: the proof of eq. 23 does not apply)"))
    print(f"  (23)  lambda_min(Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z) = {c.p_min:.6g}"
          f" at t = {c.p_min_t:.6g}")
    print(f"        remainder |f_e - A_e q_e| <= L |q_e|^2 with L = {c.remainder_L:.6g}: {c.remainder_method}")
    print(f"  (24)  epsilon = {c.epsilon:.6g} (at t = {c.epsilon_t:.6g}): dV/dt <= -(p/2)|q_e|^2 for |q_e| < epsilon")
    print(f"        errors with |q_e(t0)| < {c.attraction_radius:.6g} stay in that ball and decay:"
          f" V(t) <= V(t0) exp(-{c.decay_rate:.6g} (t - t0))")
    if args.json is not None:
        write_text(args.json, json.dumps({"scenario": scenario.name, "gamma": scenario.gamma,
                                      **certificates_dict(c)}, indent=2) + "\n")
    return 0


def cmd_sweep_gamma(args: argparse.Namespace) -> int:
    from hinf_cpp.analysis.gamma_sweep import sweep_figure, sweep_gamma
    from hinf_cpp.output.plotting import save_figure
    from hinf_cpp.output.progress import Progress

    _check_outputs(files=[args.json], figures=[args.plot])
    scenario = load_scenario(args.scenario)
    with Progress(quiet=args.quiet) as progress:
        sweep = sweep_gamma(scenario, count=args.count, upper=args.upper,
                            zero_initial_error=not args.keep_initial_error, threads=args.threads,
                            progress=progress)
    print(f"scenario {scenario.name}: gamma* = {sweep.gamma_star:.6g}")
    print(f"  {'gamma':>10}  {'L2 gain':>10}  {'L_gamma':>12}")
    for g, gain, cost in zip(sweep.gammas, sweep.response_ratio, sweep.cost):
        print(f"  {g:10.5g}  {gain:10.5g}  {cost:12.5g}")
    if args.plot is not None:
        save_figure(sweep_figure(sweep), args.plot)
        print(f"wrote {args.plot}")
    if args.json is not None:
        write_text(args.json, json.dumps(sweep.to_dict(), indent=2) + "\n")
    return 0


def _frequency_grid(text: str) -> list[float]:
    """--frequencies: LOW:HIGH:COUNT (log-spaced, rad/s) or a comma-separated list (rad/s)."""
    import numpy as np

    def bad(why: str) -> argparse.ArgumentTypeError:
        return argparse.ArgumentTypeError(f"invalid frequencies '{text}': {why}; give LOW:HIGH:COUNT "
                                          "(log-spaced, rad/s) or a comma-separated list such as 0.1,1,10")
    try:
        if ":" in text:
            parts = text.split(":")
            if len(parts) != 3:
                raise bad("three fields LOW:HIGH:COUNT are needed")
            low, high, count = float(parts[0]), float(parts[1]), int(parts[2])
            if not (0 < low < high < math.inf) or count < 2:
                raise bad("0 < LOW < HIGH and COUNT >= 2 are needed")
            return [float(x) for x in np.geomspace(low, high, count)]
        values = [float(part) for part in text.split(",")]
    except ValueError:
        raise bad("not numbers") from None
    if not all(0 < x < math.inf for x in values):
        raise bad("every frequency must be a finite number > 0")
    return values


def _channel_list(text: str) -> list[int]:
    try:
        values = [int(part) for part in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid channels '{text}': comma-separated channel numbers "
                                         "counted from 1 (w1, w2, ...), such as 1,2,3") from None
    return values


def cmd_gain_frequency(args: argparse.Namespace) -> int:
    from hinf_cpp.analysis.attenuation import frequency_figure, gain_against_frequency
    from hinf_cpp.analysis.comparison import parse_controllers
    from hinf_cpp.output.plotting import save_figure
    from hinf_cpp.output.progress import Progress

    laws = parse_controllers(args.laws)
    _check_outputs(folders=[args.out])
    scenario = load_scenario(args.scenario)
    with Progress(quiet=args.quiet) as progress:
        table = gain_against_frequency(scenario, laws, channels=args.channels, frequencies=args.frequencies,
                                       amplitude=args.amplitude, progress=progress)
    out = pathlib.Path(args.out)
    print(f"scenario {scenario.name}: measured gain of the nonlinear closed loop for w_c = {args.amplitude:g} "
          "sin(omega (t - t0)) on one channel, from the desired start; bound: the law's induced L2 gain")
    print(f"  {'law':<5} {'channel':>7}  {'omega':>9}  {'gain':>8}  {'bound':>8}  status")
    for row in table.itertuples():
        print(f"  {row.law:<5} {'w' + str(row.channel):>7}  {row.omega:9.4g}  {row.gain:8.4g}  {row.bound:8.4g}  "
              f"{row.status}")
    csv = out / "gain_frequency.csv"
    write_text(csv, table.to_csv(index=False))
    written = [csv]
    for channel in sorted(set(table["channel"])):
        written.append(save_figure(frequency_figure(table, channel, f"{scenario.name}: gain against frequency, "
                                                                    f"disturbance channel w{channel}"),
                                   out / f"gain_frequency_w{channel}.png"))
    print(f"wrote {', '.join(str(path) for path in written)}")
    return 0


def metrics_markdown(rows: list[tuple[str, _core.RunResult]], alone: list[float] | None = None) -> str:
    """A Markdown table with one column per run; `alone`, one per run, is the disturbance's gain
    of the same run started on the desired trajectory (the run's own is NaN from elsewhere),
    shown next to gamma."""
    header = "| metric | " + " | ".join(label for label, _ in rows) + " |"
    lines = [header, "|---" * (len(rows) + 1) + "|"]
    lines.append("| gamma | " + " | ".join(_format(r.gamma) for _, r in rows) + " |")
    gains = alone if alone is not None else [r.metrics.disturbance_gain for _, r in rows]
    if any(math.isfinite(g) for g in gains):
        lines.append("| disturbance_gain (from the desired start) | " + " | ".join(_format(g) for g in gains) + " |")
    for name in METRIC_NAMES:
        if name == "disturbance_gain":
            continue
        values = [getattr(r.metrics, name) for _, r in rows]
        if all(not math.isfinite(v) for v in values):
            continue
        lines.append(f"| {name} | " + " | ".join(_format(v) for v in values) + " |")
    return "\n".join(lines) + "\n"


def _comparison_header(comparison) -> str:
    return (f"scenario {comparison.scenario}: comparison of tracking laws (H-infinity design at gamma = "
            f"{comparison.gamma:g})\n  disturbance: {comparison.disturbance['description']}")


def _comparison_notes(comparison) -> list[str]:
    notes = []
    noisy = [run for run in comparison.runs if run.disturbance["measurement_noise"]]
    if noisy:
        noise = noisy[0].disturbance["measurement_noise"]
        notes.append(f"  output-feedback runs: plus measurement noise sigma = {noise['sigma']:g} held over "
                     f"{noise['sample_period']:g} s (seed {noise['seed']}) on {', '.join(noise['channels'])}")
    for run in comparison.runs:
        if run.error:
            notes.append(f"  {run.key} failed: {run.error}")
    return notes


def cmd_compare(args: argparse.Namespace) -> int:
    from hinf_cpp.analysis.comparison import compare, parse_controllers
    from hinf_cpp.output.plotting import paths_figure, save_figure
    from hinf_cpp.output.progress import Progress

    controllers = parse_controllers(args.controllers)
    _check_outputs(files=[args.json], figures=[args.plot])
    scenario = load_scenario(args.scenario)
    with Progress(quiet=args.quiet) as progress:
        comparison = compare(scenario, controllers, feedback=args.feedback,
                             worst_case=True if args.worst_case else None, progress=progress)
    print(_comparison_header(comparison))
    notes = _comparison_notes(comparison)
    if notes:
        print("\n".join(notes))
    print()
    print(text_table(*comparison.table()), end="")
    if args.json is not None:
        write_text(args.json, comparison.to_json() + "\n")
        print(f"wrote {args.json}")
    if args.plot is not None:
        runs = comparison.results()
        if not runs:
            raise _core.HinfError("every run failed: nothing to plot")
        save_figure(paths_figure(runs, marine=args.marine), args.plot)
        print(f"wrote {args.plot}")
    return 0


def cmd_recovery(args: argparse.Namespace) -> int:
    from hinf_cpp.analysis.comparison import parse_controllers
    from hinf_cpp.output.plotting import recovery_figure, save_figure
    from hinf_cpp.output.progress import Progress
    from hinf_cpp.analysis.recovery import recovery_study

    controllers = parse_controllers(args.controllers)
    _check_outputs(files=[args.json], figures=[args.plot])
    if not (args.position_tol > 0 and args.heading_tol > 0):
        raise ValueError(f"--position-tol and --heading-tol must be > 0, got {args.position_tol:g} m and "
                         f"{args.heading_tol:g} deg")
    with Progress(quiet=args.quiet) as progress:
        study = recovery_study(args.scenarios or None, controllers, position_tolerance=args.position_tol,
                               heading_tolerance=math.radians(args.heading_tol), progress=progress)
    definitions = study.to_dict()["definitions"]
    print("recovery from poor initial conditions")
    for key in ("status", "recovers", "turns_around", "settling_time"):
        print(f"  {key.replace('_', ' ')}: {definitions[key]}")
    print()
    print(text_table(*study.table()), end="")
    for v in study.verdicts:
        if v.status != "completed":
            print(f"  {v.controller.name} on {v.scenario} {v.status}: {v.error}")
        elif v.turns_around:
            print(f"  {v.controller.name} on {v.scenario} turns around: {v.turn.reason}")
    if args.json is not None:
        write_text(args.json, json.dumps(study.to_dict(), indent=2) + "\n")
        print(f"wrote {args.json}")
    if args.plot is not None:
        save_figure(recovery_figure(study, marine=args.marine), args.plot)
        print(f"wrote {args.plot}")
    return 0


def cmd_report(args: argparse.Namespace) -> int:
    from hinf_cpp.analysis.comparison import parse_controllers
    from hinf_cpp.analysis.report import write_report
    from hinf_cpp.output.progress import Progress

    controllers = parse_controllers(args.controllers)
    _check_outputs(folders=[args.out])
    scenario = load_scenario(args.scenario)
    with Progress(quiet=args.quiet) as progress:
        report = write_report(scenario, args.out, controllers, feedback=args.feedback,
                              worst_case=True if args.worst_case else None, pdf=args.pdf, marine=args.marine,
                              progress=progress)
    print(_comparison_header(report.comparison))
    notes = _comparison_notes(report.comparison)
    if notes:
        print("\n".join(notes))
    print()
    print(text_table(*report.comparison.table()), end="")
    for run in report.comparison.runs:
        if run.error:
            print(f"  {run.key} failed: {run.error}")
    names = ", ".join(sorted(p.name for p in report.files))
    print(f"\nwrote the report to {report.folder}/ ({len(report.files)} files; open report.md): {names}")
    return 0


def load_symbolic_model(spec: str):
    """The SymbolicModel made by `spec`, "module:callable" or "path/to/file.py:callable"."""
    from hinf_cpp.scenario.documents import resolve_callable
    from hinf_cpp.models.symbolic import SymbolicModel

    model = resolve_callable(spec)()
    if not isinstance(model, SymbolicModel):
        raise ValueError(f"'{spec}' returned {type(model).__name__}, not a hinf_cpp.models.symbolic.SymbolicModel")
    return model


def cmd_model_export(args: argparse.Namespace) -> int:
    model = load_symbolic_model(args.model)
    started = time.perf_counter()
    built = model.build()
    path = model.export(args.out)
    how = "from the cache" if built.cache_hit else (
        f"generated in {built.generate_seconds:.2f} s, compiled in {built.compile_seconds:.2f} s")
    print(f"{path} ({how}; {time.perf_counter() - started:.2f} s in all)")
    return 0


def cmd_export_controller(args: argparse.Namespace) -> int:
    from hinf_cpp.output.export_c import export_scenario

    _check_outputs(folders=[args.out])
    scenario, planned = _load_with_plan(args.scenario)  # as `run` reads it
    if planned is not None:
        _print_plans(planned)
    exported = export_scenario(scenario, args.out, period=args.sample_period)
    feedback = f"output feedback ({exported.p} measured outputs)" if exported.p else "state feedback"
    print(f"scenario {scenario.name}: {exported.kind} law, {feedback}, every {exported.period:g} s on "
          f"[{exported.t0:g}, {exported.t_end:g}) s ({exported.steps} samples)")
    print(f"  tables {exported.table_bytes} bytes ({exported.table_bytes / 2**20:.2f} MiB); past t_end the "
          "controller answers past_horizon and holds its command")
    print(f"wrote {exported.folder}/ (hinf_controller.h, .c, tables, CMakeLists.txt, README.md)")
    return 0


def cmd_paper(args: argparse.Namespace) -> int:
    from hinf_cpp.scenario import scenario_path
    from hinf_cpp.analysis.comparison import compare
    from hinf_cpp.output.plotting import controls_figure, errors_figure, paths_figure, save_figure, xy_figure
    from hinf_cpp.output.progress import Progress

    _check_outputs(folders=[args.out])
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows, alone = [], []
    scenarios = {}
    for figure, name in [("Figure 1", "paper_fig1"), ("Figure 2", "paper_fig2")]:
        scenarios[name] = load_scenario(scenario_path(name))
        result = _core.run_scenario(scenarios[name])
        stem = name.replace("paper_", "")
        write_text(out / f"{stem}.json", _core.results_json(result) + "\n")
        write_text(out / f"{stem}.csv", _core.results_csv(result))
        save_figure(xy_figure(result, title=f"Paper {figure}: {result.scenario_name}", marine=args.marine),
                    out / f"{stem}_xy.png")
        print(summary(result))
        rows.append((figure, result))
        # The disturbance's own gain: the same run from the desired start.
        from_desired = scenarios[name].copy()
        from_desired.initial_q0 = from_desired.desired_q0
        alone.append(_core.run_scenario(from_desired).metrics.disturbance_gain)
    table = metrics_markdown(rows, alone)
    write_text(out / "metrics.md", table)
    print()
    print(table, end="")

    # The laws on Figure 1 (state feedback) and on Figure 2 (output feedback).
    sections = ["# The tracking laws compared on the paper's runs", "",
                "hinf: the paper's H-infinity law (gamma = 5); lqr: the same design at gamma = inf (with "
                "measurements, the Kalman-Bucy filter); cascade and backstepping: the ship baselines (with "
                "measurements, on the H-infinity estimate). Heading errors are wrapped to (-pi, pi]; 'last "
                f"half' is t >= {0.5 * (scenarios['paper_fig1'].t0 + scenarios['paper_fig1'].tf):g} s; 'L2 "
                "gain from the desired start' is that of the same run started on the desired trajectory, "
                "the disturbance's gain alone, to hold against the law's own induced L2 gain.", ""]
    with Progress(quiet=args.quiet) as progress:
        for figure, name, feedback in [("Figure 1", "paper_fig1", Feedback.state),
                                       ("Figure 2", "paper_fig2", Feedback.output)]:
            comparison = compare(scenarios[name], feedback=[feedback], progress=progress)
            stem = name.replace("paper_", "")
            mode = f"{feedback.name} feedback"
            write_text(out / f"comparison_{stem}.json", comparison.to_json() + "\n")
            runs, title = comparison.results(), f"Paper {figure} scenario: the laws compared, {mode}"
            # The paths, the tracking errors and the inputs against time, per law.
            save_figure(paths_figure(runs, title=title, marine=args.marine), out / f"comparison_{stem}_paths.png")
            save_figure(errors_figure(runs, title=f"{title}: tracking errors"), out / f"comparison_{stem}_errors.png")
            save_figure(controls_figure(runs, title=f"{title}: inputs"), out / f"comparison_{stem}_controls.png")
            header, table_rows = comparison.table()
            sections += [f"## {figure} scenario ({comparison.scenario}), {mode}", "",
                         f"Disturbance: {comparison.runs[0].disturbance['description']}.", "",
                         markdown_table(header, table_rows),
                         f"![{figure}: x-y paths of the laws](comparison_{stem}_paths.png)", "",
                         f"![{figure}: position and heading errors of the laws against time]"
                         f"(comparison_{stem}_errors.png)", "",
                         f"![{figure}: inputs u of the laws and the desired u_d against time]"
                         f"(comparison_{stem}_controls.png)", ""]
            print(f"\n{figure} scenario, {mode}: the laws compared")
            print(text_table(header, table_rows), end="")
    write_text(out / "comparison.md", "\n".join(sections))
    print(f"\nwrote {out}/: " + ", ".join(sorted(p.name for p in out.iterdir())))
    print(f"output folder: {out.resolve()}")
    return 0


def cmd_animate(args: argparse.Namespace) -> int:
    from hinf_cpp.output.animation import animate_run, check_animation_path

    check_animation_path(args.output)  # before the run: the suffix, ffmpeg for .mp4, the folder
    scenario, planned = _load_with_plan(args.scenario)
    if planned is not None:
        _print_plans(planned)
    result = _core.run_scenario(scenario)
    animation = animate_run(result, args.output, frames=args.frames, fps=args.fps, width=args.width,
                            marine=args.marine)
    status = result.simulation.status
    print(f"scenario {result.scenario_name}: {run_key(result.law, result.output_feedback)}, t in "
          f"[{animation.times[0]:g}, {animation.times[-1]:g}] s" + ("" if status == _core.RunStatus.completed
                                                                  else f" ({status.name})"))
    print(f"wrote {animation.path} ({animation.frames} frames at {animation.fps:g} fps, "
          f"{animation.pixel_map.width}x{animation.pixel_map.height} pixels)")
    return 0


def cmd_vehicles(args: argparse.Namespace) -> int:
    from hinf_cpp.analysis.gallery import VEHICLES, gallery_table, run_vehicle, write_gallery
    from hinf_cpp.output.progress import Progress

    _check_outputs(folders=[args.out])
    runs = []
    with Progress(quiet=args.quiet) as progress:
        for index, vehicle in enumerate(VEHICLES, start=1):
            progress(index, len(VEHICLES), f"running {vehicle.scenario}")
            runs.append(run_vehicle(vehicle))
    print("the built-in vehicles: state-feedback tracking of their shipped scenarios (docs/vehicles.md)")
    print(text_table(*gallery_table(runs)), end="")
    written = write_gallery(args.out, runs)
    print(f"\nwrote {args.out}/: " + ", ".join(sorted(p.name for p in written)))
    return 0


def cmd_planned(args: argparse.Namespace) -> int:
    from hinf_cpp.analysis.gallery import PLANNED, planned_table, run_planned, write_planned_gallery
    from hinf_cpp.output.progress import Progress

    _check_outputs(folders=[args.out])
    runs = []
    with Progress(quiet=args.quiet) as progress:
        for index, case in enumerate(PLANNED, start=1):
            progress(index, len(PLANNED), f"planning and running {case.scenario}")
            runs.append(run_planned(case, cache=not args.no_cache))
    print("the shipped planned scenarios: planning (docs/planning.md) and state-feedback tracking")
    print(text_table(*planned_table(runs)), end="")
    written = write_planned_gallery(args.out, runs)
    print(f"\nwrote {args.out}/: " + ", ".join(sorted(p.name for p in written)))
    return 0


def cmd_study(args: argparse.Namespace) -> int:
    from hinf_cpp.studies.study import load_study, local_cores, run_study
    from hinf_cpp.studies.report import failed_runs_text, status_counts, write_study_outputs
    from hinf_cpp.output.progress import Progress

    if args.workers is not None and args.scheduler is not None:
        raise ValueError("--workers and --scheduler exclude each other: --workers sets the local threads, "
                         "a Dask cluster runs on its own workers")
    _check_outputs(folders=[args.out])
    study = load_study(args.study)  # --trust-code: HINF_TRUST_CODE, set by _run
    client = None
    if args.scheduler is not None:
        try:
            from dask.distributed import Client
        except ImportError:
            raise ValueError("--scheduler needs Dask: pip install 'hinf_cpp[dask]'") from None
        client = Client(args.scheduler, timeout="20s")
    started = time.perf_counter()
    try:
        with Progress(quiet=args.quiet) as progress:
            table = run_study(study, workers=args.workers, client=client, out=args.out, progress=progress)
    finally:
        if client is not None:
            client.close()
    seconds = time.perf_counter() - started
    written = write_study_outputs(study, table, args.out, seconds)
    if table.attrs.get("restarted"):
        print(f"note: {args.out}/partial held runs of another version of this study (the study, its scenario "
              "or the library changed): started over")
    if table.attrs.get("reused_chunks"):
        reused = table.attrs.get("reused_statuses", {})
        kept = ", ".join(f"{status} {count}" for status, count in reused.items())
        print(f"resumed: reused {table.attrs['reused_chunks']} of {table.attrs['chunks']} chunks saved in "
              f"{args.out}/partial ({sum(reused.values())} runs: {kept})")
        if reused.get("invalid_input"):
            print(f"note: their invalid_input runs ({reused['invalid_input']}) were refused for the scenario "
                  "itself and were not run again (runs refused for a missing or unreadable file run again)")
    if table.attrs.get("rerun_chunks"):
        print(f"note: {table.attrs['rerun_chunks']} saved chunks held runs that failed for a reason outside the "
              "scenario (a lost worker, a missing file): they ran again")
    counts = status_counts(table)
    statuses = ", ".join(f"{name} {int(counts[name].sum())}" for name in counts.columns
                         if name != "runs" and counts[name].sum() > 0)
    where = f"Dask scheduler {args.scheduler}" if client is not None else \
        f"{args.workers or local_cores()} local threads"
    ran = study.runs - int(table.attrs.get("reused_runs", 0))
    done = f"{study.runs} runs" if ran == study.runs else f"{study.runs} runs, {ran} run by this invocation"
    print(f"study {study.name}: {done} ({statuses}) in {seconds:.1f} s on {where}")
    print(f"wrote {args.out}/: " + ", ".join(sorted(p.name for p in written)))
    failed = failed_runs_text(table, table=str(pathlib.Path(args.out) / "runs.csv"))
    if failed:
        print("runs that did not complete (each runs again alone with its command):")
        print(failed)
    if not (table["status"] == "completed").any():
        return _fail(f"all {study.runs} runs of the study failed (none completed): their statuses and reasons "
                     f"are in {pathlib.Path(args.out) / 'runs.parquet'}", 1)
    return 0


class _Parser(argparse.ArgumentParser):
    """argparse with errors on one line of stderr (exit status 2), like every other error."""

    def error(self, message: str):
        self.exit(2, f"{self.prog}: error: {' '.join(message.split())} (see {self.prog} --help)\n")


def _add_law_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--controllers", default=",".join(_core.Law.__members__),
                        help=f"comma-separated laws among {', '.join(_core.Law.__members__)} (default: all)")


def _add_comparison_options(parser: argparse.ArgumentParser) -> None:
    """The laws, feedback modes and worst case of compare and report."""
    _add_law_options(parser)
    modes = [mode.name for mode in Feedback]
    parser.add_argument("--feedback", help=f"{', '.join(modes)} or {','.join(modes)} (default: all with [measurement])")
    parser.add_argument("--worst-case", action="store_true",
                        help="add each law's own worst-case disturbance at gamma (hinf: w* of eq. 16; the others: "
                             "that of their own closed loop)")


def _add_marine(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--marine", action="store_true",
                        help="x-y figures in the marine convention: North up, East right (the ship's x is North, "
                             "y East: y drawn horizontally, x vertically)")


def _add_quiet(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--quiet", action="store_true", help="no progress line on stderr")


def _add_outputs(parser: argparse.ArgumentParser, json: str | None = None, plot: str | None = None,
                 quiet: bool = False) -> None:
    """--json (writes `json`), --plot (writes `plot`) and --quiet, those asked for."""
    if json is not None:
        parser.add_argument("--json", help=f"write {json} (JSON)")
    if plot is not None:
        parser.add_argument("--plot", help=f"write {plot} (PNG, PDF or SVG)")
    if quiet:
        _add_quiet(parser)


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="hinf-cpp", description=__doc__.split("\n")[0])
    parser.add_argument("--version", action="version", version=_core.__version__)
    sub = parser.add_subparsers(dest="command", required=True)

    run = sub.add_parser("run", help="run a scenario and write the results file")
    run.add_argument("scenario", help="scenario file (TOML)")
    run.add_argument("--json", help="write the results file (JSON)")
    run.add_argument("--csv", help="write the time series (CSV)")
    run.add_argument("--npz", help="write every time series, the metrics and the metadata (NPZ)")
    run.add_argument("--plot", help="write the x-y plot (PNG, PDF or SVG)")
    _add_marine(run)
    run.add_argument("--gamma-star", action="store_true", help="also compute gamma* (eq. 14) for the results file")
    run.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                     help="set a scenario key (VALUE is a TOML value: controller.gamma=12, "
                          "'controller.law=\"lqr\"', initial.q0[5]=0.5, feedback=\"state\"); repeatable")
    run.add_argument("--seed", type=_seed, help="set [measurement] seed (the noise of an output-feedback run)")
    run.set_defaults(handler=cmd_run)

    planner = sub.add_parser("plan", help="plan the desired inputs of a scenario that gives waypoints or a path, "
                                          "and write the planned scenario (which hinf-sim runs as is)")
    planner.add_argument("scenario", help="scenario file (TOML) whose [desired] gives waypoints or a path")
    planner.add_argument("-o", "--output", required=True, help="write the planned scenario (TOML)")
    planner.add_argument("--no-cache", action="store_true", help="plan anew even if this plan is cached")
    _add_outputs(planner, json="the feasibility report", plot="the planned path and the waypoints")
    planner.set_defaults(handler=cmd_plan)

    comp = sub.add_parser("compare", help="the H-infinity law against the baselines (lqr, cascade)")
    comp.add_argument("scenario", help="scenario file (TOML)")
    _add_comparison_options(comp)
    _add_outputs(comp, json="the metrics of every run", plot="the overlaid x-y paths", quiet=True)
    _add_marine(comp)
    comp.set_defaults(handler=cmd_compare)

    rec = sub.add_parser("recovery", help="recovery from poor initial conditions, turning around")
    rec.add_argument("scenarios", nargs="*", help="scenario files (default: the shipped poor_*.toml)")
    _add_law_options(rec)
    rec.add_argument("--position-tol", type=float, default=0.5,
                     help="recovered: final position error below this (m, default 0.5)")
    rec.add_argument("--heading-tol", type=float, default=10.0,
                     help="recovered: final wrapped heading error below this (degrees, default 10)")
    _add_outputs(rec, json="the verdicts", plot="the x-y paths, one panel per scenario (every law's run; "
                                                 "those that did not complete dotted, an x where they stop)",
                 quiet=True)
    _add_marine(rec)
    rec.set_defaults(handler=cmd_recovery)

    rep = sub.add_parser("report", help="comparison, figures, tables and results files in a folder")
    rep.add_argument("scenario", help="scenario file (TOML)")
    rep.add_argument("--out", required=True, help="output folder")
    _add_comparison_options(rep)
    rep.add_argument("--pdf", action="store_true", help="also write every figure as a vector PDF")
    _add_marine(rep)
    _add_quiet(rep)
    rep.set_defaults(handler=cmd_report)

    star = sub.add_parser("gamma-star", help="gamma* (eq. 14) of a scenario's design, by bisection")
    star.add_argument("scenario", help="scenario file (TOML)")
    star.add_argument("--output-feedback", action="store_true",
                      help="the smallest gamma of the output-feedback design (needs [measurement])")
    star.add_argument("--lower", type=float, default=0.0, help="lower end of the bracket (must fail)")
    star.add_argument("--upper", type=float, default=0.0, help="upper end of the bracket (must pass)")
    star.add_argument("--rtol", type=float, default=1e-7, help="relative width of the final bracket")
    star.add_argument("--max-evaluations", type=int, default=200)
    star.add_argument("--threads", type=int, default=2, help="evaluations in parallel per round")
    _add_outputs(star, json="the result with every gamma tried")
    star.set_defaults(handler=cmd_gamma_star)

    certify = sub.add_parser("certify", help="the certificates of paper §3 (eqs. 22-24)")
    certify.add_argument("scenario", help="scenario file (TOML)")
    _add_outputs(certify, json="the certificates")
    certify.set_defaults(handler=cmd_certify)

    sweep = sub.add_parser("sweep-gamma", help="measured L2 gain and L_gamma against gamma")
    sweep.add_argument("scenario", help="scenario file (TOML)")
    sweep.add_argument("--count", type=int, default=12, help="number of gammas (default 12)")
    sweep.add_argument("--upper", type=float, help="largest gamma (default max(4 gamma, 10 gamma*))")
    sweep.add_argument("--keep-initial-error", action="store_true",
                       help="start from the scenario's initial state (default: from the desired state)")
    sweep.add_argument("--threads", type=int, default=2)
    _add_outputs(sweep, json="the sweep", plot="the figure", quiet=True)
    sweep.set_defaults(handler=cmd_sweep_gamma)

    gains = sub.add_parser("gain-frequency", help="each law's measured gain against the frequency of a "
                                                   "single-channel sinusoid, with its bound (law_gain)")
    gains.add_argument("scenario", help="scenario file (TOML)")
    gains.add_argument("-o", "--out", required=True, help="output folder (gain_frequency.csv, "
                                                          "gain_frequency_wC.png per channel)")
    gains.add_argument("--laws", default="hinf,lqr",
                       help="comma-separated laws among hinf, lqr (default hinf,lqr; cascade has no "
                            "linearization)")
    gains.add_argument("--channels", type=_channel_list,
                       help="comma-separated disturbance channels from 1 (default: all but "
                            "measurement-noise channels)")
    gains.add_argument("--frequencies", type=_frequency_grid,
                       help="LOW:HIGH:COUNT log-spaced or a comma-separated list, rad/s (default 0.01:100:17)")
    gains.add_argument("--amplitude", type=float, default=0.01, help="sinusoid amplitude (default 0.01)")
    _add_quiet(gains)
    gains.set_defaults(handler=cmd_gain_frequency)

    model = sub.add_parser("model", help="symbolic models (CasADi): export one for scenario files")
    model_sub = model.add_subparsers(dest="model_command", required=True)
    export = model_sub.add_parser("export", help="generate, compile and write a model's folder (model.json, "
                                                 "the library and its C source) for [model] kind = \"casadi\"")
    export.add_argument("model", help="MODULE:CALLABLE or FILE.py:CALLABLE returning a hinf_cpp.models.symbolic.SymbolicModel")
    export.add_argument("--out", required=True, help="output folder")
    export.set_defaults(handler=cmd_model_export)

    exporter = sub.add_parser("export-controller", help="the scenario's online controller as self-contained C99 "
                                                        "(docs/export.md)")
    exporter.add_argument("scenario", help="scenario file (TOML); [sampling] gives the period, design and filter")
    exporter.add_argument("--out", required=True, help="output folder")
    exporter.add_argument("--sample-period", type=float, metavar="T",
                          help="the controller's period (s), in place of [sampling] period")
    exporter.set_defaults(handler=cmd_export_controller)

    paper = sub.add_parser("paper", help="the paper's runs: figures, results files, metrics and the "
                                         "comparison of the laws")
    paper.add_argument("--out", default="out/paper", help="output folder (default: out/paper)")
    _add_marine(paper)
    _add_quiet(paper)
    paper.set_defaults(handler=cmd_paper)

    animate = sub.add_parser("animate", help="an animation of a run (GIF; MP4 with ffmpeg on PATH): the vessel "
                                             "oriented by its heading, the desired position, the trail")
    animate.add_argument("scenario", help="scenario file (TOML)")
    animate.add_argument("-o", "--output", required=True, help="write the animation (.gif, or .mp4 with ffmpeg)")
    animate.add_argument("--frames", type=_frame_count, default=DEFAULT_FRAMES, metavar="N",
                         help=f"frames, 2 to {MAX_FRAMES} (default {DEFAULT_FRAMES})")
    animate.add_argument("--fps", type=_frame_rate, default=DEFAULT_FPS, metavar="F",
                         help=f"frames per second, in (0, {MAX_FPS:g}] (default {DEFAULT_FPS:g})")
    animate.add_argument("--width", type=_frame_width, default=DEFAULT_WIDTH, metavar="PIXELS",
                         help=f"frame width in pixels (default {DEFAULT_WIDTH}; the height follows the path)")
    _add_marine(animate)
    animate.set_defaults(handler=cmd_animate)

    vehicles = sub.add_parser("vehicles", help="the built-in vehicles' shipped scenarios: results files, "
                                               "x-y figures and a table of the tracking")
    vehicles.add_argument("--out", default="out/vehicles", help="output folder (default: out/vehicles)")
    _add_quiet(vehicles)
    vehicles.set_defaults(handler=cmd_vehicles)
    planned = sub.add_parser("planned", help="the shipped planned scenarios (waypoints, a path): plans, their "
                                             "feasibility, tracking, figures and a table")
    planned.add_argument("--out", default="out/planned", help="output folder (default: out/planned)")
    planned.add_argument("--no-cache", action="store_true", help="plan anew even where a plan is cached")
    _add_quiet(planned)
    planned.set_defaults(handler=cmd_planned)

    study = sub.add_parser("study", help="a study (Monte Carlo, model uncertainty, grids of initial conditions, "
                                         "gamma sweeps): one row per run, a summary and figures (docs/studies.md)")
    study.add_argument("study", help="study file (TOML)")
    study.add_argument("--out", required=True, help="output folder (finished runs are kept in OUT/partial: "
                                                    "an interrupted study resumes)")
    study.add_argument("--workers", type=_positive_int, metavar="N", help="local threads (default: all cores)")
    study.add_argument("--scheduler", metavar="ADDRESS",
                       help="run on the Dask cluster with this scheduler address (tcp://host:port)")
    _add_quiet(study)
    study.set_defaults(handler=cmd_study)
    for command in sub.choices.values():
        command.add_argument("--trust-code", action="store_true",
                             help="let the files read load and run the code they name (a [model] of kind "
                                  "\"casadi\" or \"python\"); the same as HINF_TRUST_CODE=1 (docs/trust.md)")
    return parser


def _frame_count(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = None
    if value is None or not 2 <= value <= MAX_FRAMES:
        raise argparse.ArgumentTypeError(f"invalid frame count '{text}': an integer from 2 to {MAX_FRAMES}")
    return value


def _frame_rate(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not 0.0 < value <= MAX_FPS:
        raise argparse.ArgumentTypeError(f"invalid frame rate '{text}': a number of frames per second in "
                                         f"(0, {MAX_FPS:g}]")
    return value


def _frame_width(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = None
    if value is None or not MIN_WIDTH <= value <= MAX_WIDTH:
        raise argparse.ArgumentTypeError(f"invalid width '{text}': an integer number of pixels from {MIN_WIDTH} "
                                         f"to {MAX_WIDTH}")
    return value


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid count '{text}': an integer >= 1") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"invalid count '{text}': an integer >= 1")
    return value


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    # Warnings are held back while the command runs: a failure is one line on stderr with
    # nothing before it; a command that succeeds shows them at its end, one line each (as
    # hinf-sim does).
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("default")
        status = _run(args)
    if status == 0:
        for w in caught:
            print(f"hinf-cpp: warning: {' '.join(str(w.message).split())}", file=sys.stderr)
    return status


def _run(args: argparse.Namespace) -> int:
    """The command's exit status; every exception becomes one line on stderr."""
    trust_before = os.environ.get("HINF_TRUST_CODE")
    try:
        if getattr(args, "trust_code", False):
            # One mechanism: --trust-code is HINF_TRUST_CODE=1 for this command, so every reader
            # of the package (load_scenario, studies, plans) sees the same answer.
            os.environ["HINF_TRUST_CODE"] = "1"
        return args.handler(args)
    except BrokenPipeError:
        # The reader went away (e.g. `| head`): stop quietly, as other command-line tools do.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except ValueError as error:  # bad input (hinf::InputError), UnicodeDecodeError included
        return _fail(error, 2)
    except _core.HinfError as error:  # numerical failure
        return _fail(error, 3)
    except MemoryError:
        return _fail(OUT_OF_MEMORY, 2)
    except OSError as error:  # an output that cannot be written (a full disk, ...)
        message = error.strerror or str(error)
        return _fail(f"'{error.filename}': {message}" if error.filename else message, 2)
    except KeyboardInterrupt:
        return _fail("interrupted", 130)
    except Exception as error:  # noqa: BLE001 - a bug: still one line, exit status 1
        return _fail(f"internal error: {type(error).__name__}: {error}", 1)
    finally:
        if trust_before is None:
            os.environ.pop("HINF_TRUST_CODE", None)
        else:
            os.environ["HINF_TRUST_CODE"] = trust_before


def _fail(error: Exception | str, status: int) -> int:
    message = " ".join(str(error).split()) or type(error).__name__
    print(f"hinf-cpp: error: {message}", file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(main())
