"""Summaries and figures of a study's table (hinf_cpp.studies.study, docs/studies.md).

:func:`summarize` gives, per group of runs (a grid point), the count of each status and the
mean, standard deviation and 5/50/95 percentiles of each metric over the completed runs;
:func:`distribution_figure` a metric's distribution per law (box plots),
:func:`roa_figure` a region-of-attraction map over a 2-D grid of initial conditions (the
fraction of runs that recovered, per law and feedback), :func:`gamma_figure` a metric against
gamma with its 5-95 percentile band. :func:`write_study_outputs` writes them all with the
table (Parquet and CSV) into a folder.
"""

from __future__ import annotations

import math
import pathlib
from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from hinf_cpp.output.files import atomic_output, write_text
from hinf_cpp.output.tables import markdown_table

__all__ = ["DEFAULT_METRICS", "distribution_figure", "gamma_figure", "paired_differences", "recovered", "roa_figure",
           "status_counts", "summarize", "summary_markdown", "write_study_outputs"]

#: The metrics that a study's summary and figures show unless told otherwise.
DEFAULT_METRICS = ["rms_position_error_last_half", "rms_heading_error_last_half", "final_position_error",
                   "max_position_error"]
PERCENTILES = (5, 50, 95)
_STATUS_ORDER = ["completed", "diverged", "conjugate_point", "coupling_violation", "solver_failure",
                 "invalid_input", "failed"]
_LAW_COLOURS = {"hinf": "tab:blue", "lqr": "tab:orange", "cascade": "tab:green"}


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
    lines += ["## Runs per status", "", markdown_table(header, counts[header].values.tolist())]
    stats = summarize(df, study, metrics)
    group_columns = _group_columns(df, study)
    for metric in metrics:
        part = stats[stats["metric"] == metric]
        header = group_columns + ["n", "mean", "std", "p5", "p50", "p95"]
        rows = part[group_columns + ["count", "mean", "std", "p5", "p50", "p95"]].values.tolist()
        lines += [f"## {metric} (completed runs)", "", markdown_table(header, rows)]
    law_axis = [axis for axis in study.grid if axis.keys == ("controller.law",)]
    if study.samples > 1 and law_axis and len(law_axis[0].values) > 1:
        lines += ["## Paired differences between the laws (same samples: same noise and plant)", "",
                  "Per sample, the metric of a law minus that of the first law, over the samples where both "
                  "completed; 'lower' is the share of samples where the difference is negative.", ""]
        for metric in metrics:
            pairs = paired_differences(df, study, metric)
            if len(pairs):
                lines += [f"### {metric}", "", markdown_table(list(pairs.columns), pairs.values.tolist())]
    return "\n".join(lines)


def _label(law: str, output_feedback: bool) -> str:
    return f"{law}/{'output' if output_feedback else 'state'}"


def distribution_figure(df, metric: str, title: str | None = None) -> Figure:
    """Box plots of a metric over the completed runs, one per law and feedback mode.

    Whiskers at the 5th and 95th percentiles; the runs beyond them drawn as points.

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    metric : str
        The metric column.
    title : str, optional
        The title (default names the metric).

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
    ['hinf/output', 'lqr/output']
    >>> figure.savefig("distribution.png")
    """
    done = df[(df["status"] == "completed") & np.isfinite(df[metric].to_numpy(dtype=float))]
    keys = sorted({(law, bool(of)) for law, of in zip(done["law"], done["output_feedback"])},
                  key=lambda k: (k[1], list(_LAW_COLOURS).index(k[0]) if k[0] in _LAW_COLOURS else 9))
    fig = Figure(figsize=(1.6 + 1.3 * max(1, len(keys)), 3.4), layout="constrained")
    ax = fig.add_subplot()
    data = [done[(done["law"] == law) & (done["output_feedback"] == of)][metric].to_numpy(dtype=float)
            for law, of in keys]
    if data:
        boxes = ax.boxplot(data, patch_artist=True, whis=(5, 95), showfliers=True,
                           flierprops={"markersize": 2, "alpha": 0.4})
        ax.set_xticks(range(1, len(keys) + 1), [_label(*k) for k in keys])
        for patch, (law, _) in zip(boxes["boxes"], keys):
            patch.set_facecolor(_LAW_COLOURS.get(law, "tab:gray"))
            patch.set_alpha(0.5)
    ax.set_ylabel(metric)
    ax.set_title(title or f"{metric}: completed runs (whiskers 5-95 %)", fontsize=9)
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
               title: str | None = None, state_names: Sequence[str] = ()) -> Figure:
    """Region of attraction: the fraction of runs that recovered over a 2-D grid of initial states.

    One panel per law and feedback mode. Recovered as :func:`recovered`; each cell of the grid
    (x, y) is coloured by the fraction of its runs that recovered (red 0 to green 1).

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

    Returns
    -------
    matplotlib.figure.Figure
        The figure: one panel per law and feedback mode, and a colour bar.

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
    keys = sorted({(law, bool(of)) for law, of in zip(frame["law"], frame["output_feedback"]) if law},
                  key=lambda k: (k[1], list(_LAW_COLOURS).index(k[0]) if k[0] in _LAW_COLOURS else 9))
    xs = np.sort(frame[x].astype(float).unique())
    ys = np.sort(frame[y].astype(float).unique())
    columns = min(3, max(1, len(keys)))
    rows = math.ceil(max(1, len(keys)) / columns)
    fig = Figure(figsize=(2.6 * columns + 0.8, 2.4 * rows + 0.5), layout="constrained")
    axes = fig.subplots(rows, columns, squeeze=False)
    image = None
    for ax, (law, of) in zip(axes.flat, keys):
        part = frame[(frame["law"] == law) & (frame["output_feedback"] == of)]
        share = part.groupby([part[y].astype(float), part[x].astype(float)])["_ok"].mean()
        grid = np.full((len(ys), len(xs)), np.nan)
        for (yv, xv), value in share.items():
            grid[np.searchsorted(ys, yv), np.searchsorted(xs, xv)] = value
        image = ax.pcolormesh(_edges(xs), _edges(ys), grid, cmap="RdYlGn", vmin=0.0, vmax=1.0, shading="flat")
        ax.set_title(_label(law, of), fontsize=9)
        ax.set_xlabel(axis_label(x, state_names), fontsize=8)
        ax.set_ylabel(axis_label(y, state_names), fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in list(axes.flat)[len(keys):]:
        ax.set_visible(False)
    if image is not None:
        fig.colorbar(image, ax=axes, shrink=0.8, label="recovered (fraction of runs)")
    fig.suptitle(title or f"Region of attraction: recovered = |p_e(tf)| < {position_tol:g} and "
                 f"|psi_e(tf)| < {heading_tol_deg:g} deg", fontsize=9)
    return fig


def _edges(values: np.ndarray) -> np.ndarray:
    if len(values) == 1:
        return np.array([values[0] - 0.5, values[0] + 0.5])
    middle = (values[1:] + values[:-1]) / 2
    return np.concatenate([[2 * values[0] - middle[0]], middle, [2 * values[-1] - middle[-1]]])


def gamma_figure(df, metric: str, gamma_key: str = "controller.gamma", title: str | None = None) -> Figure:
    """A metric against gamma: the median and the 5-95 % band of the completed runs.

    One line and band per law and feedback mode. Failed runs (e.g. below gamma*) leave gaps, their
    gammas marked by dotted red lines; the gamma axis is logarithmic when it spans more than a
    factor 20.

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
    >>> figure.axes[0].get_xlabel(), len(figure.axes[0].lines)
    ('gamma', 1)
    """
    fig = Figure(figsize=(5.6, 3.4), layout="constrained")
    ax = fig.add_subplot()
    done = df[df["status"] == "completed"]
    keys = sorted({(law, bool(of)) for law, of in zip(done["law"], done["output_feedback"])})
    for law, of in keys:
        part = done[(done["law"] == law) & (done["output_feedback"] == of)]
        stats = part.groupby(part[gamma_key].astype(float))[metric].quantile([0.05, 0.5, 0.95]).unstack()
        colour = _LAW_COLOURS.get(law, None)
        ax.plot(stats.index, stats[0.5], "o-", ms=3, color=colour, label=_label(law, of))
        ax.fill_between(stats.index, stats[0.05], stats[0.95], color=colour, alpha=0.15, lw=0)
    failed = df[(df["status"] != "completed")]
    if len(failed):
        gammas = np.unique(failed[gamma_key].astype(float))
        ax.plot(gammas, np.full(len(gammas), np.nan), "x")  # keeps them in the axis range
        for g in gammas:
            ax.axvline(g, color="tab:red", lw=0.6, ls=":", alpha=0.7)
        ax.plot([], [], color="tab:red", lw=0.6, ls=":", label="some runs failed")
    values = df[gamma_key].astype(float)
    if len(values) and values.min() > 0 and values.max() / values.min() > 20:
        from matplotlib.ticker import NullFormatter

        ax.set_xscale("log")
        ticks = np.unique(values)
        ax.set_xticks(ticks, [f"{g:g}" for g in ticks], fontsize=7)
        ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("gamma")
    ax.set_ylabel(metric)
    ax.set_title(title or f"{metric} against gamma: median, 5-95 % band", fontsize=9)
    ax.grid(True, alpha=0.3)
    if keys or len(failed):
        ax.legend(fontsize=8)
    return fig


def _save(fig: Figure, path: pathlib.Path) -> pathlib.Path:
    from hinf_cpp.output.plotting import save_figure

    return save_figure(fig, path)


def write_study_outputs(study, df, out, seconds: float | None = None) -> list[pathlib.Path]:
    """Write a study's table, summary and figures into a folder.

    ``runs.parquet``, ``runs.csv`` (numbers at full precision), ``summary.md``
    (:func:`summary_markdown`) and the figures the study asks for: ``distribution.png`` (a
    metric's distribution per law, when a run completed), with [report] roa ``roa.png`` (the
    region-of-attraction map), with a controller.gamma grid axis ``gamma.png`` (the metric
    against gamma). Each file is written whole or not at all.

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
    metric = report.get("distribution", "rms_position_error_last_half")
    if (df["status"] == "completed").any():
        written.append(_save(distribution_figure(df, metric, title=f"{study.name}: {metric}"),
                             out / "distribution.png"))
    if report.get("roa"):
        x, y = report["roa"]
        names = study.scenario(0).model.state_names()
        written.append(_save(roa_figure(df, x, y, report.get("position_tol", 0.5), report.get("heading_tol", 10.0),
                                        state_names=names), out / "roa.png"))
    if any("controller.gamma" in axis.keys for axis in study.grid):
        gamma_metric = report.get("gamma_metric", "rms_position_error_last_half")
        written.append(_save(gamma_figure(df, gamma_metric, title=f"{study.name}: {gamma_metric} against gamma"),
                             out / "gamma.png"))
    return written
