"""A report folder for one scenario: the comparison of the laws, its figures, tables and results files.

``write_report(scenario, out)`` runs :func:`~hinf_cpp.analysis.comparison.compare` and writes into ``out``:

    report.md            everything below in one page (tables, definitions, figures)
    metrics.md           the comparison table (Markdown), one column per run
    metrics.csv          the same table with the metric keys, numbers at full precision
    comparison.json      the comparison (Comparison.to_dict(): metrics per run, disturbance)
    paths.png            overlaid x-y paths with start markers and heading arrows
    errors.png           position and heading errors against time
    controls.png         control inputs against time, desired and applied
    eigenvalues.png      eigenvalue bounds of Z(t) (and of Sigma(t) with [measurement])
    coupling.png         rho(Sigma Z)(t) against gamma^2 (only with [measurement])
    <run>.json           the results file of each run (results_json(result))
    <run>.npz, <run>.csv every time series of each run (hinf_cpp.output.export: NPZ, tidy CSV)

``<run>`` is the run's key with ``/`` replaced by ``-`` (``hinf``, ``lqr-output-feedback``).
With ``pdf=True`` every figure is also written as a vector PDF next to its PNG.
"""

from __future__ import annotations

import dataclasses
import pathlib
from typing import Callable, Sequence

from hinf_cpp import _core
from hinf_cpp.analysis.comparison import METRICS, Comparison, Feedback, compare
from hinf_cpp.output.export import save_csv, save_json, save_npz
from hinf_cpp.output.files import check_output_folder, write_text
from hinf_cpp.output.plotting import (controls_figure, coupling_figure, eigenvalues_figure, errors_figure, paths_figure,
                       save_figure)
from hinf_cpp.output.progress import ProgressCallback
from hinf_cpp.output.tables import csv_table, markdown_table

__all__ = ["Report", "run_file_stem", "write_report"]


def run_file_stem(key: str) -> str:
    """The file stem of a run in a report folder: its key with '/' replaced by '-'.

    Parameters
    ----------
    key : str
        The run's key (:func:`hinf_cpp.output.tables.run_key`).

    Returns
    -------
    str
        The stem of ``<run>.json``, ``<run>.npz`` and ``<run>.csv``.

    Examples
    --------
    >>> from hinf_cpp.analysis.report import run_file_stem
    >>> run_file_stem("lqr/output-feedback")
    'lqr-output-feedback'
    """
    return key.replace("/", "-")


@dataclasses.dataclass
class Report:
    """What :func:`write_report` wrote.

    Parameters
    ----------
    folder : pathlib.Path
        The report folder.
    files : list of pathlib.Path
        The files written, in order (tables, report.md, figures, results files).
    comparison : hinf_cpp.analysis.Comparison
        The comparison the report shows.

    Examples
    --------
    >>> from hinf_cpp.analysis.report import write_report
    >>> report = write_report(hc.load_scenario(hc.scenario_path("paper_fig1")), "report", "hinf")
    >>> report.folder.name, report.comparison.keys
    ('report', ['hinf'])
    """

    folder: pathlib.Path
    files: list[pathlib.Path]
    comparison: Comparison


def _figures(comparison: Comparison, marine: bool = False) -> list[tuple[str, str, Callable]]:
    """(file name, caption, factory) of the figures that apply to the comparison's runs."""
    runs = comparison.results()
    if not runs:
        return []
    model = runs[0][1].trajectory.model()
    planar = len(model.position_indices()) == 2
    output = any(r.feedback is Feedback.output and r.ok for r in comparison.runs)
    figures = []
    if planar:
        figures.append(("paths.png", "x-y paths: desired (solid), actual (dashed; dash-dotted for output "
                        "feedback), starts marked, arrows along the paths show the heading",
                        lambda: paths_figure(runs, marine=marine)))
        figures.append(("errors.png", "position error |p - p_d| and wrapped heading error against time, "
                        "per law (colour, line style and marker)",
                        lambda: errors_figure(runs)))
    figures.append(("controls.png", "control inputs against time: desired u_d and applied u",
                    lambda: controls_figure(runs)))
    figures.append(("eigenvalues.png", "smallest and largest eigenvalue of Z(t) per design"
                    + (" and of the filter's Sigma(t)" if output else ""), lambda: eigenvalues_figure(runs)))
    if output:
        figures.append(("coupling.png", "coupling condition of the output-feedback design: rho(Sigma Z)(t) "
                        "against gamma^2", lambda: coupling_figure(runs)))
    return figures


def _report_markdown(comparison: Comparison, figures: list[tuple[str, str, Callable]],
                     scenario: _core.Scenario) -> str:
    header, rows = comparison.table()
    lines = [f"# Comparison of tracking laws: {comparison.scenario}", ""]
    if scenario.description:
        lines += [scenario.description, ""]
    lines += [f"Horizon [{scenario.t0:g}, {scenario.tf:g}] s; H-infinity design at gamma = {comparison.gamma:g}; "
              f"lqr = the same design at gamma = inf; cascade = the cascaded baseline.", "",
              "Disturbance of every run:", ""]
    for run in comparison.runs:
        lines.append(f"- `{run.key}`: {run.disturbance['description']}")
        if run.error:
            lines.append(f"  - failed: {run.error}")
    lines += ["", "## Metrics", "", markdown_table(header, rows), "Definitions:", ""]
    lines += [f"- {m.label} [{m.unit}]: {m.definition}" for m in METRICS]
    lines += ["", "## Figures", ""]
    for name, caption, _ in figures:
        lines += [f"![{caption}]({name})", "", f"*{caption}*", ""]
    lines += ["## Files", "",
              "`metrics.md`, `metrics.csv`, `comparison.json`; per run `<run>.json` (results file), "
              "`<run>.npz` (every time series, metrics and metadata) and `<run>.csv` (tidy: t,variable,value).",
              ""]
    return "\n".join(lines)


def write_report(scenario: _core.Scenario, out: str | pathlib.Path,
                 controllers: str | Sequence[str] | None = None, *,
                 feedback: str | Sequence[str] | None = None, worst_case: bool | None = None,
                 pdf: bool = False, marine: bool = False, progress: ProgressCallback | None = None) -> Report:
    """Run the comparison of the laws on a scenario and write the report folder.

    Runs :func:`~hinf_cpp.analysis.comparison.compare` and writes into `out` the files of the
    module docstring: report.md, metrics.md, metrics.csv, comparison.json, the figures
    (paths, errors, controls, eigenvalues; coupling with output feedback) and per run
    ``<run>.json``, ``<run>.npz`` and ``<run>.csv``.

    Parameters
    ----------
    scenario : Scenario
        The scenario.
    out : path
        The folder (created if needed; files of the same names are overwritten, each written
        whole or not at all). A path that cannot be a folder is a ValueError before the runs.
    controllers : str or sequence of str, optional
        Laws among ``"hinf"``, ``"lqr"``, ``"cascade"``; default all three (as in
        :func:`~hinf_cpp.analysis.comparison.compare`).
    feedback : str or sequence of str, optional
        ``"state"`` and/or ``"output"``; default both with ``[measurement]``, else state.
    worst_case : bool, optional
        Overrides ``[disturbance] worst_case`` (add w* of paper eq. (16)).
    pdf : bool
        Also write each figure as a vector PDF (``paths.pdf``, ...).
    marine : bool
        Draw the x-y paths in the marine convention: North up, East right (y horizontal, x
        vertical).
    progress : callable, optional
        ``progress(index, total, message)``: the runs, then each file group written.

    Returns
    -------
    Report
        The folder, the files written and the comparison.

    Raises
    ------
    ValueError
        A path that cannot be a folder (before the runs); bad controller names or feedback
        modes, an invalid scenario.
    OSError
        A file could not be written.

    Examples
    --------
    >>> from hinf_cpp.analysis.report import write_report
    >>> report = write_report(hc.load_scenario(hc.scenario_path("paper_fig1")), "report", "hinf")
    >>> [path.name for path in report.files]
    ['metrics.md', 'metrics.csv', 'comparison.json', 'report.md',
     'paths.png', 'errors.png', 'controls.png', 'eigenvalues.png',
     'hinf.json', 'hinf.npz', 'hinf.csv']
    """
    folder = pathlib.Path(out)
    check_output_folder(folder)
    comparison = compare(scenario, controllers, feedback=feedback, worst_case=worst_case, progress=progress)
    folder.mkdir(parents=True, exist_ok=True)
    figures = _figures(comparison, marine)
    steps = len(figures) + len(comparison.results()) + 1
    step = 0

    def advance(message: str) -> None:
        nonlocal step
        step += 1
        if progress is not None:
            progress(step, steps, message)

    files = []
    advance("writing the tables")
    header, rows = comparison.table()
    for name, text in [("metrics.md", markdown_table(header, rows)), ("metrics.csv", csv_table(*comparison.table(keys=True))),
                       ("comparison.json", comparison.to_json() + "\n"),
                       ("report.md", _report_markdown(comparison, figures, scenario))]:
        files.append(write_text(folder / name, text))
    for name, _, factory in figures:
        advance(f"drawing {name}")
        fig = factory()
        files.append(save_figure(fig, folder / name))
        if pdf:
            files.append(save_figure(fig, (folder / name).with_suffix(".pdf")))
    for key, result in comparison.results():
        stem = run_file_stem(key)
        advance(f"writing the results files of {key}")
        files.append(save_json(result, folder / f"{stem}.json"))
        files.append(save_npz(result, folder / f"{stem}.npz"))
        files.append(save_csv(result, folder / f"{stem}.csv"))
    return Report(folder, files, comparison)
