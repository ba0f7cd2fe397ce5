"""Summaries and figures of a study's table (hinf_cpp.studies.study, docs/studies.md).

:func:`summarize` gives, per group of runs (a grid point), the count of each status and the
mean, standard deviation and 5/50/95 percentiles of each metric over the completed runs;
:func:`distribution_figure` a metric's distribution per law and grid point (box plots),
:func:`roa_figure` a region-of-attraction map over a 2-D grid of initial conditions (the
fraction of runs that recovered, per law, feedback and value of the other grid axes),
:func:`gamma_figure` a metric against gamma with the 5-95 percentile band of the samples, one
line per law and value of the other grid axes. The figures keep apart what the study varies
and pool only the samples of one grid point; gamma = inf (the LQR limit) is drawn to the right
of the finite gammas. :func:`write_study_outputs` writes them all with the table (Parquet and
CSV) into a folder.
"""

from __future__ import annotations

import math
import pathlib
from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from hinf_cpp import _core
from hinf_cpp.output.files import atomic_output, write_text
from hinf_cpp.output.tables import markdown_table
from hinf_cpp.studies.study import STATUSES

__all__ = ["DEFAULT_METRICS", "distribution_figure", "gamma_figure", "paired_differences", "recovered", "roa_figure",
           "status_counts", "summarize", "summary_markdown", "write_study_outputs"]

#: The metrics that a study's summary and figures show unless told otherwise.
DEFAULT_METRICS = ["rms_position_error_last_half", "rms_heading_error_last_half", "final_position_error",
                   "max_position_error"]
PERCENTILES = (5, 50, 95)
# The statuses in the order of the summary's columns: those of a study's table.
_STATUS_ORDER = STATUSES
_LAW_COLOURS = {"hinf": "tab:blue", "lqr": "tab:orange", "cascade": "tab:green"}
#: Grid keys that the law and feedback columns already tell apart in the figures.
_LAW_KEYS = ("controller.law", "feedback")
#: Above this many boxes the box labels are one rotated line each, not several upright lines.
_UPRIGHT_BOXES = 6


def _group_columns(df, study=None) -> list[str]:
    """The groups of the summary: [report] group_by, else every grid key but the two of the
    region-of-attraction map (a group is then a law and feedback mode over the map)."""
    if study is None:
        return []
    if "group_by" in study.report:
        return list(study.report["group_by"])
    skip = set(study.report.get("roa", ()))
    return [key for axis in study.grid for key in axis.keys if key not in skip]


def _groups(df, columns):
    if not columns:
        return [((), df)]
    return list(df.groupby(columns, sort=False, dropna=False))


def _key_cell(value):
    """A grid value for a Markdown table: an infinite one as "inf" (markdown_table shows every
    non-finite number as "-", which for a key would hide gamma = inf)."""
    if isinstance(value, (float, np.floating)) and math.isinf(value):
        return "inf" if value > 0 else "-inf"
    return value


def _key_rows(rows, key_count: int):
    """Rows whose first `key_count` cells are grid values, those shown with :func:`_key_cell`."""
    return [[_key_cell(c) for c in row[:key_count]] + list(row[key_count:]) for row in rows]


def status_counts(df, study=None):
    """Runs per status for each group of a study's table.

    The groups are [report] group_by, else the grid points (every grid key but the two of a
    region-of-attraction map); without a study, the whole table is one group.

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    study : hinf_cpp.studies.Study, optional
        Its study (the groups).

    Returns
    -------
    pandas.DataFrame
        One row per group: its keys, ``runs`` and one column per status (:data:`STATUSES
        <hinf_cpp.studies.study.STATUSES>`: completed, diverged, conjugate_point,
        coupling_violation, solver_failure, invalid_input, failed).

    Examples
    --------
    >>> from hinf_cpp.studies.report import status_counts
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> table = run_study(study, progress=False)
    >>> status_counts(table, study)[["controller.gamma", "runs", "completed", "diverged"]]
       controller.gamma  runs  completed  diverged
    0               5.0     1          1         0
    1              10.0     1          1         0
    """
    import pandas as pd

    columns = _group_columns(df, study)
    rows = []
    for key, group in _groups(df, columns):
        key = key if isinstance(key, tuple) else (key,)
        counts = group["status"].value_counts()
        rows.append({**dict(zip(columns, key)), "runs": len(group),
                     **{status: int(counts.get(status, 0)) for status in _STATUS_ORDER}})
    return pd.DataFrame(rows)


def summarize(df, study=None, metrics: Sequence[str] | None = None):
    """Statistics of metrics over the completed runs, per group of a study's table.

    One row per (group, metric): count, mean, std (ddof 1), p5, p50, p95 of the metric over
    the group's completed runs (finite values; NaN where there are none). Groups are those of
    :func:`status_counts` (the grid points).

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    study : hinf_cpp.studies.Study, optional
        Its study (the groups); without it the whole table is one group.
    metrics : sequence of str, optional
        Metric columns (default: those of :data:`DEFAULT_METRICS` in the table).

    Returns
    -------
    pandas.DataFrame
        Columns: the group keys, ``metric``, ``count``, ``mean``, ``std``, ``p5``, ``p50``,
        ``p95``.

    Examples
    --------
    >>> from hinf_cpp.studies.report import summarize
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> table = run_study(study, progress=False)
    >>> stats = summarize(table, study, ["final_position_error"])
    >>> stats[["controller.gamma", "metric", "count", "mean"]].round(3)
       controller.gamma                metric  count   mean
    0               5.0  final_position_error      1  0.058
    1              10.0  final_position_error      1  0.057
    """
    import pandas as pd

    columns = _group_columns(df, study)
    metrics = list(metrics) if metrics is not None else [m for m in DEFAULT_METRICS if m in df.columns]
    rows = []
    for key, group in _groups(df, columns):
        key = key if isinstance(key, tuple) else (key,)
        done = group[group["status"] == "completed"]
        for metric in metrics:
            values = done[metric].to_numpy(dtype=float)
            values = values[np.isfinite(values)]
            stats = {"count": len(values), "mean": math.nan, "std": math.nan,
                     **{f"p{p}": math.nan for p in PERCENTILES}}
            if len(values):
                stats.update(mean=float(values.mean()), std=float(values.std(ddof=1)) if len(values) > 1 else math.nan,
                             **{f"p{p}": float(v) for p, v in zip(PERCENTILES, np.percentile(values, PERCENTILES))})
            rows.append({**dict(zip(columns, key)), "metric": metric, **stats})
    return pd.DataFrame(rows)


def paired_differences(df, study, metric: str, key: str = "controller.law"):
    """Paired differences of a metric between the values of a grid axis, sample by sample.

    Per sample (the same noise and plant: common random numbers), the metric of each value of
    the grid axis `key` minus that of its first value, over the samples where both runs
    completed: mean, standard deviation, standard error and the share of samples where it is
    lower.

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    study : hinf_cpp.studies.Study
        Its study.
    metric : str
        The metric column.
    key : str, optional
        A grid axis of one key (default ``"controller.law"``).

    Returns
    -------
    pandas.DataFrame
        One row per value (after the first) and group of the other grid keys: the group
        keys, `key` (``"<value> - <first value>"``), ``n``, ``mean``, ``std``, ``stderr``,
        ``lower``.

    Raises
    ------
    StopIteration
        `key` is not a grid axis of one key of the study.

    Examples
    --------
    >>> from hinf_cpp.studies.report import paired_differences
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "noise", "scenario": str(hc.scenario_path("paper_fig2")), "samples": 3},
    ...     "grid": [{"key": "controller.law", "values": ["hinf", "lqr"]}],
    ...     "random": [{"key": "measurement.seed", "distribution": "seed"}]})
    >>> table = run_study(study, progress=False)
    >>> pairs = paired_differences(table, study, "rms_position_error_last_half")
    >>> pairs[["controller.law", "n"]]
      controller.law  n
    0     lqr - hinf  3
    """
    import pandas as pd

    others = [k for k in _group_columns(df, study) if k != key]
    values = next(axis.values for axis in study.grid if key in axis.keys and len(axis.keys) == 1)
    rows = []
    for group_key, group in _groups(df, others):
        group_key = group_key if isinstance(group_key, tuple) else (group_key,)
        done = group[group["status"] == "completed"]
        table = done.pivot_table(index="sample", columns=key, values=metric, aggfunc="first")
        for value in values[1:]:
            if value not in table or values[0] not in table:
                continue
            d = (table[value] - table[values[0]]).dropna().to_numpy(dtype=float)
            rows.append({**dict(zip(others, group_key)), key: f"{value} - {values[0]}", "n": len(d),
                         "mean": float(d.mean()) if len(d) else math.nan,
                         "std": float(d.std(ddof=1)) if len(d) > 1 else math.nan,
                         "stderr": float(d.std(ddof=1) / math.sqrt(len(d))) if len(d) > 1 else math.nan,
                         "lower": float((d < 0).mean()) if len(d) else math.nan})
    return pd.DataFrame(rows)


def summary_markdown(df, study, seconds: float | None = None) -> str:
    """The text of a study's ``summary.md`` (Markdown).

    What the study is, the status counts per group (:func:`status_counts`; with [report] roa
    the runs that recovered), the statistics of the report's metrics per group
    (:func:`summarize`) and, with several samples and a law axis, the paired differences
    between the laws (:func:`paired_differences`).

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    study : hinf_cpp.studies.Study
        Its study.
    seconds : float, optional
        The study's wall time (s), stated with the runs per second when given.

    Returns
    -------
    str
        The Markdown text.

    Examples
    --------
    >>> from hinf_cpp.studies.report import summary_markdown
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> table = run_study(study, progress=False)
    >>> for line in summary_markdown(table, study).splitlines()[:3]:
    ...     print(line)
    # Study gammas
    <BLANKLINE>
    2 runs: 2 grid points x 1 samples; master seed 0; base scenario `paper_fig1.toml`.
    """
    metrics = study.report.get("metrics", DEFAULT_METRICS)
    lines = [f"# Study {study.name}", ""]
    if study.description:
        lines += [study.description, ""]
    lines += [f"{study.runs} runs: {study.grid_points} grid points x {study.samples} samples; master seed "
              f"{study.seed}; base scenario `{pathlib.Path(study.source).name}`."
              + (f" Wall time {seconds:.1f} s ({study.runs / seconds:.0f} runs/s)." if seconds else ""), ""]
    counts = status_counts(df, study)
    shown = [s for s in _STATUS_ORDER if counts[s].sum() > 0] if len(counts) else []
    header = [c for c in counts.columns if c not in _STATUS_ORDER] + shown
    if study.report.get("roa"):
        tol, deg = study.report.get("position_tol", 0.5), study.report.get("heading_tol", 10.0)
        ok = df.assign(_ok=recovered(df, tol, deg))
        columns = _group_columns(df, study)
        shares = [int(group["_ok"].sum()) for _, group in _groups(ok, columns)]
        counts = counts.assign(recovered=shares)
        header.append("recovered")
        lines += [f"Recovered: completed with |p_e(tf)| < {tol:g} and |psi_e(tf)| < {deg:g} degrees.", ""]
    group_columns = _group_columns(df, study)
    lines += ["## Runs per status", "",
              markdown_table(header, _key_rows(counts[header].values.tolist(), len(group_columns)))]
    stats = summarize(df, study, metrics)
    for metric in metrics:
        part = stats[stats["metric"] == metric]
        header = group_columns + ["n", "mean", "std", "p5", "p50", "p95"]
        rows = part[group_columns + ["count", "mean", "std", "p5", "p50", "p95"]].values.tolist()
        lines += [f"## {metric} (completed runs)", "", markdown_table(header, _key_rows(rows, len(group_columns)))]
    law_axis = [axis for axis in study.grid if axis.keys == ("controller.law",)]
    if study.samples > 1 and law_axis and len(law_axis[0].values) > 1:
        lines += ["## Paired differences between the laws (same samples: same noise and plant)", "",
                  "Per sample, the metric of a law minus that of the first law, over the samples where both "
                  "completed; 'lower' is the share of samples where the difference is negative.", ""]
        for metric in metrics:
            pairs = paired_differences(df, study, metric)
            if len(pairs):
                key_count = list(pairs.columns).index("controller.law")
                lines += [f"### {metric}", "",
                          markdown_table(list(pairs.columns), _key_rows(pairs.values.tolist(), key_count))]
    return "\n".join(lines)


def _label(law: str, output_feedback: bool) -> str:
    if not law:  # every run of the group was refused before a law was built
        return "?"
    return f"{law}/{'output' if output_feedback else 'state'}"


def _metric_label(metric: str) -> str:
    """A metric's axis label, "label [unit]" from hc.metric_table(); another column's name."""
    for definition in _core.metric_table():
        if definition.name == metric:
            return f"{definition.label} [{definition.unit}]"
    return metric


def _value_text(value) -> str:
    """A grid value as text: an integer as it is, a float as %g (gamma = inf as "inf")."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return f"{float(value):g}"
    return str(value)


def _point_text(columns: Sequence[str], values: Sequence, separator: str = ", ") -> str:
    """The values of grid keys as "key = value" joined by `separator`, for a legend or a label."""
    return separator.join(f"{key} = {_value_text(value)}" for key, value in zip(columns, values))


def _shown_columns(other_columns: Sequence[str]) -> list[str]:
    """The grid keys a figure names: the law and feedback keys are named by law/feedback already."""
    return [key for key in other_columns if key not in _LAW_KEYS]


def _series(df, other_columns: Sequence[str] = ()) -> list[tuple]:
    """The runs of a table per law, feedback mode and values of `other_columns`.

    A list of (law, output_feedback, values of the shown other columns, runs), state feedback
    first, then the laws in the order of _LAW_COLOURS, then the order of the grid. A run the
    reader refused (status invalid_input) has no law: it belongs to the law of the other runs of
    its group (grouped by the law and feedback keys too when they are columns), so that it
    counts among the runs of that law's box or line.
    """
    shown = _shown_columns(other_columns)
    split = [key for key in _LAW_KEYS if key in df.columns] + shown
    found = []
    for order, (key, group) in enumerate(_groups(df, split)):
        key = key if isinstance(key, tuple) else (key,)
        values = tuple(key[len(split) - len(shown):])
        known = group[group["law"] != ""]
        laws = list(dict.fromkeys(zip(known["law"], known["output_feedback"].astype(bool))))
        if len(laws) == 1:
            found.append((*laws[0], values, group, order))
        elif not laws:
            found.append(("", False, values, group, order))
        else:  # laws that no column tells apart: the refused runs cannot be assigned to one
            for law, of in laws:
                found.append((law, of, values, known[(known["law"] == law) & (known["output_feedback"] == of)],
                              order))
    laws = list(_LAW_COLOURS)
    found.sort(key=lambda s: (s[1], laws.index(s[0]) if s[0] in laws else len(laws), s[4]))
    return [s[:4] for s in found]


def distribution_figure(df, metric: str, title: str | None = None, other_columns: Sequence[str] = ()) -> Figure:
    """Box plots of a metric over the completed runs, one per law, feedback mode and grid point.

    One box per law and feedback mode and per combination of the values of `other_columns`
    (the grid keys that the study varies besides the law and feedback): a box pools only the
    samples of one grid point. Each box is labelled with its law, its grid values, n (the
    completed runs with a value of the metric) and the share of its runs that failed (did not
    complete). Whiskers at the 5th and 95th percentiles; the runs beyond them drawn as points.
    Up to 6 boxes have upright labels of several lines ("key = value"); more boxes, or longer
    lines, have one rotated line each (the values, their keys named under the axis) and the
    figure widens with their count.

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    metric : str
        The metric column.
    title : str, optional
        The title (default names the metric).
    other_columns : sequence of str, optional
        Grid keys (columns of `df`) whose values get boxes of their own (default none: one box
        per law and feedback mode).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (one axes).

    Examples
    --------
    >>> from hinf_cpp.studies.report import distribution_figure
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "noise", "scenario": str(hc.scenario_path("paper_fig2")), "samples": 3},
    ...     "grid": [{"key": "controller.law", "values": ["hinf", "lqr"]}],
    ...     "random": [{"key": "measurement.seed", "distribution": "seed"}]})
    >>> table = run_study(study, progress=False)
    >>> figure = distribution_figure(table, "rms_position_error_last_half")
    >>> [label.get_text() for label in figure.axes[0].get_xticklabels()]
    ['hinf/output\\nn = 3, failed 0 %', 'lqr/output\\nn = 3, failed 0 %']
    >>> figure.axes[0].get_ylabel()
    'RMS position error, last half [m]'
    >>> figure.savefig("distribution.png")
    """
    shown = _shown_columns(other_columns)
    series = _series(df, other_columns)
    data, upright_labels, rotated_labels, colours = [], [], [], []
    for law, of, values, runs in series:
        metric_values = runs.loc[runs["status"] == "completed", metric].to_numpy(dtype=float)
        metric_values = metric_values[np.isfinite(metric_values)]
        failed = int((runs["status"] != "completed").sum())
        counts = f"n = {len(metric_values)}, failed {100 * failed / max(1, len(runs)):.0f} %"
        data.append(metric_values)
        upright_labels.append("\n".join([_label(law, of), *(f"{k} = {_value_text(v)}" for k, v in zip(shown, values)),
                                         counts]))
        # One line: the values alone, their keys named once below the axis.
        rotated_labels.append(", ".join([_label(law, of), *(_value_text(v) for v in values)]) + f": {counts}")
        colours.append(_LAW_COLOURS.get(law, "tab:gray"))
    # Several upright lines while they fit under their box (about 1.3 in: 24 characters).
    upright = len(series) <= _UPRIGHT_BOXES and all(
        len(line) <= 24 for label in upright_labels for line in label.splitlines())
    labels = upright_labels if upright else rotated_labels
    note = "n: completed runs with a value; failed: share of the runs that did not complete"
    if upright:
        size = (1.6 + 1.3 * max(1, len(series)), 3.4)
    else:  # rotated by 45 degrees: each label needs about 0.05 in per character of height
        size = (2.0 + 0.45 * len(series), 3.6 + min(4.0, 0.04 * max(len(label) for label in labels)))
    fig = Figure(figsize=size, layout="constrained")
    ax = fig.add_subplot()
    if data:
        boxes = ax.boxplot(data, patch_artist=True, whis=(5, 95), showfliers=True,
                           flierprops={"markersize": 2, "alpha": 0.4})
        if upright:
            ax.set_xticks(range(1, len(labels) + 1), labels, fontsize=7)
        else:
            ax.set_xticks(range(1, len(labels) + 1), labels, fontsize=7, rotation=45, ha="right",
                          rotation_mode="anchor")
            note = f"boxes: {', '.join(['law/feedback', *shown])}\n{note}"
        for patch, colour in zip(boxes["boxes"], colours):
            patch.set_facecolor(colour)
            patch.set_alpha(0.5)
    ax.set_xlabel(note, fontsize=7)
    ax.set_ylabel(_metric_label(metric))
    ax.set_title(title or f"{_metric_label(metric)}: completed runs (whiskers 5-95 %)", fontsize=9)
    ax.grid(True, axis="y", alpha=0.3)
    return fig


def recovered(df, position_tol: float = 0.5, heading_tol_deg: float = 10.0) -> np.ndarray:
    """Which runs of a table recovered: the verdict of :mod:`hinf_cpp.analysis.recovery`.

    A run recovered when it completed with a final position error below `position_tol` and a
    final wrapped heading error below `heading_tol_deg` (a NaN heading error, a model without
    heading, does not count against it).

    Parameters
    ----------
    df : pandas.DataFrame
        A table with the columns ``status``, ``final_position_error`` and
        ``final_heading_error`` (rad).
    position_tol : float, optional
        The position tolerance, in the model's unit of length (default 0.5).
    heading_tol_deg : float, optional
        The heading tolerance, degrees (default 10).

    Returns
    -------
    numpy.ndarray of bool, shape (len(df),)
        True for the runs that recovered.

    Examples
    --------
    >>> import pandas as pd
    >>> from hinf_cpp.studies.report import recovered
    >>> table = pd.DataFrame({"status": ["completed", "completed", "diverged"],
    ...                       "final_position_error": [0.1, 0.9, 0.1],
    ...                       "final_heading_error": [0.05, 0.0, 0.0]})
    >>> recovered(table)
    array([ True, False, False])
    """
    position = df["final_position_error"].to_numpy(dtype=float)
    heading = np.abs(df["final_heading_error"].to_numpy(dtype=float))
    with np.errstate(invalid="ignore"):
        ok = (position < position_tol) & ~(heading >= math.radians(heading_tol_deg))
    return (df["status"].to_numpy() == "completed") & ok


def axis_label(key: str, state_names: Sequence[str] = ()) -> str:
    """"initial.q0[5]" as "psi(t0) (initial.q0[5])" when the model names its states."""
    import re

    match = re.fullmatch(r"initial\.q0\[(\d+)\]", key)
    if match and int(match.group(1)) < len(state_names):
        return f"{state_names[int(match.group(1))]}(t0)  ({key})"
    return key


def roa_figure(df, x: str, y: str, position_tol: float = 0.5, heading_tol_deg: float = 10.0,
               title: str | None = None, state_names: Sequence[str] = (),
               other_columns: Sequence[str] = ()) -> Figure:
    """Region of attraction: the fraction of runs that recovered over a 2-D grid of initial states.

    One panel per law and feedback mode and per combination of the values of `other_columns`
    (the grid keys the study varies besides the map's and the law and feedback), named in the
    panel's title. Recovered as :func:`recovered`; each cell of the grid (x, y) is coloured by
    the fraction of its runs that recovered (red 0 to green 1).

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study` with x and y as grid keys.
    x : str
        The key on the horizontal axis (e.g. ``"initial.q0[3]"``).
    y : str
        The key on the vertical axis.
    position_tol : float, optional
        The position tolerance of :func:`recovered` (default 0.5).
    heading_tol_deg : float, optional
        The heading tolerance of :func:`recovered`, degrees (default 10).
    title : str, optional
        The title (default states the tolerances).
    state_names : sequence of str, optional
        The model's state names, to label ``initial.q0[i]`` axes with the state's name.
    other_columns : sequence of str, optional
        Grid keys (columns of `df`) whose values get panels of their own (default none).

    Returns
    -------
    matplotlib.figure.Figure
        The figure: one panel per law, feedback mode and values of `other_columns`, and a
        colour bar.

    Examples
    --------
    >>> from hinf_cpp.studies.report import roa_figure
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "roa", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "initial.q0[3]", "values": [-2.0, 2.0]},
    ...              {"key": "initial.q0[5]", "values": [0.0, 1.5]}],
    ...     "report": {"roa": ["initial.q0[3]", "initial.q0[5]"]}})
    >>> table = run_study(study, progress=False)
    >>> figure = roa_figure(table, "initial.q0[3]", "initial.q0[5]",
    ...                     state_names=["u", "v", "r", "x", "y", "psi"])
    >>> figure.axes[0].get_title(), figure.axes[0].get_xlabel()
    ('hinf/state', 'x(t0)  (initial.q0[3])')
    """
    frame = df.assign(_ok=recovered(df, position_tol, heading_tol_deg))
    shown = _shown_columns(other_columns)
    panels = _series(frame, other_columns)
    xs = np.sort(frame[x].astype(float).unique())
    ys = np.sort(frame[y].astype(float).unique())
    x_at, y_at = _cell_positions(xs), _cell_positions(ys)
    columns = min(3, max(1, len(panels)))
    rows = math.ceil(max(1, len(panels)) / columns)
    fig = Figure(figsize=(2.6 * columns + 0.8, (2.4 + 0.15 * len(shown)) * rows + 0.5), layout="constrained")
    axes = fig.subplots(rows, columns, squeeze=False)
    image = None
    for ax, (law, of, values, part) in zip(axes.flat, panels):
        share = part.groupby([part[y].astype(float), part[x].astype(float)])["_ok"].mean()
        grid = np.full((len(ys), len(xs)), np.nan)
        for (yv, xv), value in share.items():
            grid[np.searchsorted(ys, yv), np.searchsorted(xs, xv)] = value
        image = ax.pcolormesh(_edges(x_at), _edges(y_at), grid, cmap="RdYlGn", vmin=0.0, vmax=1.0, shading="flat")
        # An infinite value (gamma = inf on an axis of the map) has a cell beyond the others, named.
        if np.isinf(xs).any():
            ax.set_xticks(x_at, [_value_text(v) for v in xs])
        if np.isinf(ys).any():
            ax.set_yticks(y_at, [_value_text(v) for v in ys])
        ax.set_title("\n".join([_label(law, of), *(f"{k} = {_value_text(v)}" for k, v in zip(shown, values))]),
                     fontsize=9 if not shown else 8)
        ax.set_xlabel(axis_label(x, state_names), fontsize=8)
        ax.set_ylabel(axis_label(y, state_names), fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in list(axes.flat)[len(panels):]:
        ax.set_visible(False)
    if image is not None:
        fig.colorbar(image, ax=axes, shrink=0.8, label="recovered (fraction of runs)")
    fig.suptitle(title or f"Region of attraction: recovered = |p_e(tf)| < {position_tol:g} and "
                 f"|psi_e(tf)| < {heading_tol_deg:g} deg", fontsize=9)
    return fig


def _cell_positions(values: np.ndarray) -> np.ndarray:
    """Where the sorted values of a map's axis are drawn: a finite one at itself, inf one step of
    the grid beyond the largest finite value (-inf one step below the smallest)."""
    finite = values[np.isfinite(values)]
    if not len(finite):
        return np.arange(len(values), dtype=float)
    step_up = finite[-1] - finite[-2] if len(finite) > 1 else 1.0
    step_down = finite[1] - finite[0] if len(finite) > 1 else 1.0
    return np.where(values == np.inf, finite[-1] + step_up, np.where(values == -np.inf, finite[0] - step_down, values))


def _edges(values: np.ndarray) -> np.ndarray:
    if len(values) == 1:
        return np.array([values[0] - 0.5, values[0] + 0.5])
    middle = (values[1:] + values[:-1]) / 2
    return np.concatenate([[2 * values[0] - middle[0]], middle, [2 * values[-1] - middle[-1]]])


def _gamma_scale(gammas: np.ndarray) -> tuple[bool, float | None]:
    """How a gamma axis draws `gammas`: logarithmic or not, and where gamma = inf goes.

    Logarithmic when the finite gammas are > 0 and span more than a factor 20. gamma = inf (the
    LQR limit) is drawn to the right of the largest finite gamma: at twice it on a logarithmic
    axis, one spacing of the two largest further on a linear one (None: no gamma is inf).
    """
    finite = np.unique(gammas[np.isfinite(gammas)])
    log = len(finite) > 1 and finite[0] > 0 and finite[-1] / finite[0] > 20
    if not np.isposinf(gammas).any():
        return log, None
    if not len(finite):
        return False, 1.0
    top = finite[-1]
    if log:
        return True, 2.0 * top
    step = top - finite[-2] if len(finite) > 1 else (abs(top) if top != 0 else 1.0)
    return False, top + step


def _gamma_positions(gammas: np.ndarray, inf_at: float | None) -> np.ndarray:
    """Where gammas are drawn: a finite one at itself, inf at `inf_at`, anything else nowhere (NaN)."""
    gammas = np.asarray(gammas, dtype=float)
    at_inf = np.nan if inf_at is None else inf_at
    return np.where(np.isposinf(gammas), at_inf, np.where(np.isfinite(gammas), gammas, np.nan))


def _gamma_axis(ax, gammas: np.ndarray, log: bool, inf_at: float | None) -> None:
    """The gamma axis's scale, range and ticks; with gamma = inf a tick "inf" at `inf_at`."""
    from matplotlib.ticker import MaxNLocator, NullFormatter

    finite = np.unique(gammas[np.isfinite(gammas)])
    ticks = None
    if log:
        ax.set_xscale("log")
        ticks = list(finite)
    elif inf_at is not None:
        ticks = list(finite) if len(finite) <= 8 else [
            t for t in MaxNLocator(6).tick_values(finite[0], finite[-1]) if finite[0] <= t <= finite[-1]]
    if ticks is not None:
        labels = [f"{t:g}" for t in ticks]
        if inf_at is not None:
            ticks, labels = ticks + [inf_at], labels + ["inf"]
        ax.set_xticks(ticks, labels, fontsize=7)
        ax.xaxis.set_minor_formatter(NullFormatter())
    # The range holds every gamma of the table, also those where every run failed (no line).
    positions = _gamma_positions(gammas, inf_at)
    positions = positions[np.isfinite(positions)]
    if len(positions):
        low, high = positions.min(), positions.max()
        if log:
            pad = (high / low) ** 0.05
            ax.set_xlim(low / pad, high * pad)
        else:
            pad = 0.05 * (high - low) if high > low else max(0.5, 0.1 * abs(high))
            ax.set_xlim(low - pad, high + pad)
    ax.set_xlabel("gamma [-]" + (" (inf: the LQR limit)" if inf_at is not None else ""))


def gamma_figure(df, metric: str, gamma_key: str = "controller.gamma", title: str | None = None,
                 other_columns: Sequence[str] = ()) -> Figure:
    """A metric against gamma: the median and the 5-95 % band of the completed runs at each gamma.

    One line and band per law and feedback mode and per combination of the values of
    `other_columns` (the grid keys that the study varies besides gamma, the law and feedback;
    the legend names their values): the band is then the spread of the samples at one grid
    point. Failed runs (e.g. below gamma*) leave gaps, their gammas marked by dotted red lines;
    the gamma axis is logarithmic when it spans more than a factor 20. gamma = inf (the LQR
    limit) is drawn right of the largest finite gamma (twice it on a logarithmic axis, one step
    of the grid further on a linear one) with the tick label "inf".

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study` with a gamma grid axis.
    metric : str
        The metric column.
    gamma_key : str, optional
        The gamma column (default ``"controller.gamma"``).
    title : str, optional
        The title (default names the metric).
    other_columns : sequence of str, optional
        Grid keys (columns of `df`) whose values get lines of their own (default none: one
        line per law and feedback mode).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (one axes).

    Examples
    --------
    >>> from hinf_cpp.studies.report import gamma_figure
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> table = run_study(study, progress=False)
    >>> figure = gamma_figure(table, "final_position_error")
    >>> figure.axes[0].get_xlabel(), figure.axes[0].get_ylabel(), len(figure.axes[0].lines)
    ('gamma [-]', 'final position error [m]', 1)

    gamma = inf, the LQR limit, right of the finite gammas:

    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, float("inf")]}]})
    >>> figure = gamma_figure(run_study(study, progress=False), "final_position_error")
    >>> [label.get_text() for label in figure.axes[0].get_xticklabels()]
    ['5', 'inf']
    >>> figure.axes[0].get_xlabel()
    'gamma [-] (inf: the LQR limit)'
    """
    shown = _shown_columns(other_columns)
    gammas = df[gamma_key].to_numpy(dtype=float)
    log, inf_at = _gamma_scale(gammas)
    # With other axes the legend is long: beside the axes, not over the lines.
    fig = Figure(figsize=(5.6 + (2.6 if shown else 0.0), 3.4), layout="constrained")
    ax = fig.add_subplot()
    styles = {"hinf": "-", "lqr": "--", "cascade": "-."}
    drawn = 0
    for law, of, values, runs in _series(df, other_columns):
        done = runs[runs["status"] == "completed"]
        if not len(done):
            continue
        stats = done.groupby(done[gamma_key].astype(float))[metric].quantile([0.05, 0.5, 0.95]).unstack()
        x = _gamma_positions(stats.index.to_numpy(dtype=float), inf_at)
        # One colour per law without other axes; with them one per line, the law in the line style.
        colour = f"C{drawn % 10}" if shown else _LAW_COLOURS.get(law, None)
        label = ", ".join([_label(law, of), _point_text(shown, values)]) if shown else _label(law, of)
        ax.plot(x, stats[0.5], marker="o", ms=3, ls=styles.get(law, "-") if shown else "-", color=colour,
                label=label)
        ax.fill_between(x, stats[0.05], stats[0.95], color=colour, alpha=0.15, lw=0)
        drawn += 1
    failed = df[df["status"] != "completed"]
    if len(failed):
        for position in np.unique(_gamma_positions(failed[gamma_key].to_numpy(dtype=float), inf_at)):
            if np.isfinite(position):
                ax.axvline(position, color="tab:red", lw=0.6, ls=":", alpha=0.7)
        ax.plot([], [], color="tab:red", lw=0.6, ls=":", label="some runs failed")
    _gamma_axis(ax, gammas, log, inf_at)
    ax.set_ylabel(_metric_label(metric))
    ax.set_title(title or f"{_metric_label(metric)} against gamma: median, 5-95 % band of the samples", fontsize=9)
    ax.grid(True, alpha=0.3)
    if drawn or len(failed):
        if shown:
            ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
        else:
            ax.legend(fontsize=8)
    return fig


def _save(fig: Figure, path: pathlib.Path) -> pathlib.Path:
    from hinf_cpp.output.plotting import save_figure

    return save_figure(fig, path)


def write_study_outputs(study, df, out, seconds: float | None = None) -> list[pathlib.Path]:
    """Write a study's table, summary and figures into a folder.

    ``runs.parquet``, ``runs.csv`` (numbers at full precision), ``summary.md``
    (:func:`summary_markdown`) and the figures the study asks for: ``distribution.png`` (a
    metric's distribution per law and grid point, when a run completed), with [report] roa
    ``roa.png`` (the region-of-attraction map), with a controller.gamma grid axis ``gamma.png``
    (the metric against gamma). The figures keep the values of the grid axes apart (boxes,
    panels or lines of their own) but for the roa keys, which the map spreads out, and the
    gamma axis in ``gamma.png``. Each file is written whole or not at all.

    Parameters
    ----------
    study : hinf_cpp.studies.Study
        The study.
    df : pandas.DataFrame
        Its table (:func:`hinf_cpp.studies.run_study`).
    out : str or os.PathLike
        The folder (created if needed).
    seconds : float, optional
        The study's wall time (s), for the summary.

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    ValueError
        A folder that cannot be written.
    OSError
        A file could not be written.

    Examples
    --------
    >>> from hinf_cpp.studies.report import write_study_outputs
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> table = run_study(study, progress=False)
    >>> [path.name for path in write_study_outputs(study, table, "gammas")]
    ['runs.parquet', 'runs.csv', 'summary.md', 'distribution.png', 'gamma.png']
    """
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    with atomic_output(out / "runs.parquet") as f:
        df.to_parquet(f, index=False)
    written.append(out / "runs.parquet")
    with atomic_output(out / "runs.csv") as f:
        f.write(df.to_csv(index=False, float_format="%.17g").encode())
    written.append(out / "runs.csv")
    written.append(write_text(out / "summary.md", summary_markdown(df, study, seconds)))
    report = study.report
    # The grid keys whose values each figure keeps apart: all but the map's (roa.png spreads
    # them out, the other figures pool them as the summary does).
    roa_keys = set(report.get("roa", ()))
    point_columns = [key for axis in study.grid for key in axis.keys if key not in roa_keys]
    metric = report.get("distribution", "rms_position_error_last_half")
    if (df["status"] == "completed").any():
        written.append(_save(distribution_figure(df, metric, title=f"{study.name}: {_metric_label(metric)}",
                                                 other_columns=point_columns), out / "distribution.png"))
    if report.get("roa"):
        x, y = report["roa"]
        names = study.scenario(0).model.state_names()
        written.append(_save(roa_figure(df, x, y, report.get("position_tol", 0.5), report.get("heading_tol", 10.0),
                                        state_names=names, other_columns=point_columns), out / "roa.png"))
    gamma_axes = [axis for axis in study.grid if "controller.gamma" in axis.keys]
    if gamma_axes:
        gamma_metric = report.get("gamma_metric", "rms_position_error_last_half")
        # The keys set together with gamma move with it: they are the gamma axis, not other axes.
        other_columns = [key for key in point_columns if key not in gamma_axes[0].keys]
        written.append(_save(gamma_figure(df, gamma_metric,
                                          title=f"{study.name}: {_metric_label(gamma_metric)} against gamma",
                                          other_columns=other_columns), out / "gamma.png"))
    return written
