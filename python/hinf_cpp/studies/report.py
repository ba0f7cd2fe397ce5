"""Summaries and figures of a study's table (hinf_cpp.studies.study, docs/studies.md).

:func:`summarize` gives, per group of runs (a grid point), the count of each status and the
mean, standard deviation and 5/50/95 percentiles of each metric over the completed runs;
:func:`distribution_figure` a metric's distribution per law and grid point (box plots),
:func:`roa_figure` a region-of-attraction map over a 2-D grid of initial conditions (the
fraction of runs that recovered, per law, feedback and value of the other grid axes),
:func:`gamma_figure` a metric against gamma with the 5-95 percentile band of the samples, one
line per law and value of the other grid axes. The figures keep apart what the study varies
and pool only the samples of one grid point; gamma = inf (the LQR limit) is drawn to the right
of the finite gammas. :func:`heatmap_figure` draws a metric's mean over a two-axis grid.
:func:`axis_statistics` gives a metric per value of one grid axis with percentile-bootstrap
confidence intervals (:func:`bootstrap_ci`), :func:`paired_tests` the paired differences between
the values of any grid axis under common random numbers with a Wilcoxon signed-rank test and the
rank-biserial correlation, :func:`failed_runs_text` the replay commands of the runs that did not
complete. :func:`write_study_outputs` writes them all with the table (Parquet and CSV) into a
folder, the figures as PNG and PDF.
"""

from __future__ import annotations

import math
import pathlib
import textwrap
from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from hinf_cpp import _core
from hinf_cpp.output.files import atomic_output, write_text
from hinf_cpp.output.tables import markdown_table
from hinf_cpp.studies.study import STATUSES

__all__ = ["BOOTSTRAP_RESAMPLES", "BOOTSTRAP_SEED", "CONFIDENCE", "DEFAULT_METRICS", "axis_statistics", "bootstrap_ci",
           "distribution_figure", "failed_runs_text", "gamma_figure", "heatmap_figure", "key_label",
           "paired_differences", "paired_tests", "recovered", "roa_figure", "status_counts", "summarize",
           "summary_markdown", "write_study_outputs"]

#: The metrics that a study's summary and figures show unless told otherwise.
DEFAULT_METRICS = ["rms_position_error_last_half", "rms_heading_error_last_half", "final_position_error",
                   "max_position_error"]
PERCENTILES = (5, 50, 95)
#: Confidence intervals of summary.md: percentile bootstrap at this level, with this many
#: resamples drawn from numpy.random.default_rng(BOOTSTRAP_SEED) (the same intervals every time).
CONFIDENCE = 0.95
BOOTSTRAP_RESAMPLES = 2000
BOOTSTRAP_SEED = 0
#: Above this many groups summary.md gives the runs per status per value of each grid axis
#: instead of per group, and a grid-only study no table of its runs.
_MAX_GROUP_ROWS = 40
#: The failed runs whose replay commands summary.md (and failed_runs_text) lists.
_FAILED_LISTED = 10
#: Units of scenario keys that an axis label can name without being told ([report] units).
_KEY_UNITS = {"controller.gamma": "-"}
#: Units of the built-in vehicles' states by name (models/vehicles.hpp; lengths in the model's
#: unit, written "m" as hc.metric_table() does).
_STATE_UNITS = {"u": "m/s", "v": "m/s", "vx": "m/s", "vy": "m/s", "x_dot": "m/s", "y_dot": "m/s", "r": "rad/s",
                "theta_dot": "rad/s", "x": "m", "y": "m", "psi": "rad", "theta": "rad"}
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


def bootstrap_ci(values, statistic: str = "mean", confidence: float = CONFIDENCE,
                 resamples: int = BOOTSTRAP_RESAMPLES, seed: int = BOOTSTRAP_SEED) -> tuple[float, float]:
    """A percentile-bootstrap confidence interval of the mean or median of some values.

    `resamples` samples of len(values) values drawn with replacement (indices from
    ``numpy.random.default_rng(seed).integers``), the statistic of each, and the
    (1 - confidence) / 2 and (1 + confidence) / 2 percentiles of those (linear interpolation).
    Non-finite values are left out first. With a fixed seed the interval is the same every time.

    Parameters
    ----------
    values : array_like
        The values (1-D).
    statistic : str, optional
        ``"mean"`` (default) or ``"median"``.
    confidence : float, optional
        The level, in (0, 1) (default :data:`CONFIDENCE`, 0.95).
    resamples : int, optional
        The bootstrap resamples, >= 1 (default ``BOOTSTRAP_RESAMPLES``, 2000).
    seed : int, optional
        The seed of the resampling (default ``BOOTSTRAP_SEED``).

    Returns
    -------
    tuple of float
        (low, high); (nan, nan) for fewer than 2 finite values.

    Raises
    ------
    ValueError
        An unknown statistic, a confidence outside (0, 1), resamples < 1.

    Examples
    --------
    >>> from hinf_cpp.studies.report import bootstrap_ci
    >>> values = np.random.default_rng(1).normal(10.0, 2.0, 400)
    >>> low, high = bootstrap_ci(values)
    >>> bool(low < values.mean() < high), round(high - low, 2)  # about 2 x 1.96 x std / sqrt(400)
    (True, 0.35)
    >>> round(float(2 * 1.96 * values.std() / 20), 2)
    0.36
    >>> bootstrap_ci([1.0])
    (nan, nan)
    """
    functions = {"mean": np.mean, "median": np.median}
    if statistic not in functions:
        raise ValueError(f"statistic must be 'mean' or 'median', got {statistic!r}")
    if not 0.0 < confidence < 1.0:
        raise ValueError(f"confidence must be in (0, 1), got {confidence!r}")
    if isinstance(resamples, bool) or not isinstance(resamples, (int, np.integer)) or resamples < 1:
        raise ValueError(f"resamples must be an integer >= 1, got {resamples!r}")
    values = np.asarray(values, dtype=float).ravel()
    values = values[np.isfinite(values)]
    n = len(values)
    if n < 2:
        return math.nan, math.nan
    rng = np.random.default_rng(seed)
    estimates = np.empty(resamples)
    batch = max(1, min(resamples, 4_000_000 // n))  # index arrays of at most 32 MB at a time
    for start in range(0, resamples, batch):
        stop = min(resamples, start + batch)
        estimates[start:stop] = functions[statistic](values[rng.integers(0, n, size=(stop - start, n))], axis=1)
    tail = 50.0 * (1.0 - confidence)
    low, high = np.percentile(estimates, [tail, 100.0 - tail])
    return float(low), float(high)


def _axis_of(study, key: str):
    """The grid axis holding `key` and its position (a ValueError naming the grid keys if none)."""
    for index, axis in enumerate(study.grid):
        if key in axis.keys:
            return index, axis
    keys = [k for axis in study.grid for k in axis.keys]
    raise ValueError(f"'{key}' is not a grid key of the study (its grid keys: {', '.join(keys) or 'none'})")


def _axis_indices(df, study) -> np.ndarray:
    """Each row's index along every grid axis, shape (rows, axes), from its grid_point."""
    points = df["grid_point"].to_numpy(dtype=np.int64)
    if not study.grid:
        return np.zeros((len(points), 0), dtype=np.int64)
    return np.stack(np.unravel_index(points, study.grid_shape), axis=1)


def _finite_completed(values: np.ndarray, status: np.ndarray) -> np.ndarray:
    return (status == "completed") & np.isfinite(values)


def axis_statistics(df, study, key: str, metrics: Sequence[str] | None = None, confidence: float = CONFIDENCE,
                    resamples: int = BOOTSTRAP_RESAMPLES, seed: int = BOOTSTRAP_SEED):
    """A metric per value of one grid axis, pooled over the other axes and the samples.

    For each value of the grid axis holding `key` (keys set together are one axis) and each
    metric: the runs with that value, how many completed, and over the completed runs with a
    finite value: n, mean, median, min, max and percentile-bootstrap confidence intervals of
    the mean and the median (:func:`bootstrap_ci`).

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    study : hinf_cpp.studies.Study
        Its study.
    key : str
        A grid key of the study.
    metrics : sequence of str, optional
        Metric columns (default: those of :data:`DEFAULT_METRICS` in the table).
    confidence : float, optional
        The level of the intervals (default 0.95).
    resamples : int, optional
        Bootstrap resamples (default ``BOOTSTRAP_RESAMPLES``).
    seed : int, optional
        Bootstrap seed (default ``BOOTSTRAP_SEED``).

    Returns
    -------
    pandas.DataFrame
        One row per (value, metric), values in the order of the axis: the axis's keys,
        ``metric``, ``runs``, ``completed``, ``n``, ``mean``, ``mean_low``, ``mean_high``,
        ``median``, ``median_low``, ``median_high``, ``min``, ``max``.

    Raises
    ------
    ValueError
        `key` is not a grid key of the study.

    Examples
    --------
    >>> from hinf_cpp.studies.report import axis_statistics
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "noise", "scenario": str(hc.scenario_path("paper_fig2")), "samples": 4},
    ...     "grid": [{"key": "controller.law", "values": ["hinf", "lqr"]}],
    ...     "random": [{"key": "measurement.seed", "distribution": "seed"}]})
    >>> table = run_study(study, progress=False)
    >>> stats = axis_statistics(table, study, "controller.law", ["final_position_error"])
    >>> stats[["controller.law", "runs", "completed", "n"]]
      controller.law  runs  completed  n
    0           hinf     4          4  4
    1            lqr     4          4  4
    >>> bool((stats["mean_low"] <= stats["mean"]).all() and (stats["mean"] <= stats["mean_high"]).all())
    True
    """
    import pandas as pd

    position, axis = _axis_of(study, key)
    metrics = list(metrics) if metrics is not None else [m for m in DEFAULT_METRICS if m in df.columns]
    along = _axis_indices(df, study)[:, position] if len(df) else np.zeros(0, dtype=np.int64)
    status = df["status"].to_numpy()
    rows = []
    for index in range(len(axis.values)):
        at = along == index
        point = dict(axis.settings(index))
        for metric in metrics:
            values = df[metric].to_numpy(dtype=float)
            values = values[at & _finite_completed(values, status)]
            row = {**point, "metric": metric, "runs": int(at.sum()),
                   "completed": int((at & (status == "completed")).sum()), "n": len(values)}
            for name in ("mean", "median"):
                centre = float(getattr(np, name)(values)) if len(values) else math.nan
                low, high = bootstrap_ci(values, name, confidence, resamples, seed)
                row.update({name: centre, f"{name}_low": low, f"{name}_high": high})
            row.update(min=float(values.min()) if len(values) else math.nan,
                       max=float(values.max()) if len(values) else math.nan)
            rows.append(row)
    return pd.DataFrame(rows)


def _rank_biserial(differences: np.ndarray) -> float:
    """The matched-pairs rank-biserial correlation of paired differences: (T+ - T-) / (T+ + T-),
    T+- the sums of the ranks of |d| (average ranks for ties) of the positive and negative
    differences, zeros left out (as the Wilcoxon test does); in [-1, 1], NaN without a nonzero."""
    import pandas as pd

    nonzero = differences[differences != 0]
    if not len(nonzero):
        return math.nan
    ranks = pd.Series(np.abs(nonzero)).rank(method="average").to_numpy()
    positive, negative = ranks[nonzero > 0].sum(), ranks[nonzero < 0].sum()
    return float((positive - negative) / (positive + negative))


def paired_tests(df, study, key: str, metric: str, confidence: float = CONFIDENCE,
                 resamples: int = BOOTSTRAP_RESAMPLES, seed: int = BOOTSTRAP_SEED):
    """Paired differences of a metric between the values of any grid axis, with a Wilcoxon
    signed-rank test and effect sizes.

    The runs are paired under common random numbers: a run at a value of the axis holding
    `key` and the run at its first value with the same sample (the same random draws) and the
    same values of every other grid axis, over the pairs where both completed with a finite
    metric. Per value after the first: the number of pairs, the mean paired difference (value
    minus first value) with its percentile-bootstrap interval, the median difference, the
    share of pairs where it is negative, ``scipy.stats.wilcoxon`` of the differences (default
    options: two-sided, zero differences left out, exact or normal approximation as SciPy
    chooses) and the matched-pairs rank-biserial correlation (T+ - T-) / (T+ + T-) (positive:
    the value gives larger metrics). The p-values are not adjusted for the number of tests.

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    study : hinf_cpp.studies.Study
        Its study.
    key : str
        A grid key of the study (keys set together with it are the same axis).
    metric : str
        The metric column.
    confidence : float, optional
        The level of the interval of the mean difference (default 0.95).
    resamples : int, optional
        Bootstrap resamples (default ``BOOTSTRAP_RESAMPLES``).
    seed : int, optional
        Bootstrap seed (default ``BOOTSTRAP_SEED``).

    Returns
    -------
    pandas.DataFrame
        One row per value after the first: ``comparison`` (``"lqr - hinf"``; several keys'
        values joined by ", "), ``n``, ``mean``, ``mean_low``, ``mean_high``, ``median``,
        ``lower``, ``statistic`` (SciPy's: the smaller of T+ and T-), ``p_value``,
        ``rank_biserial`` (NaN where there is no nonzero difference).

    Raises
    ------
    ValueError
        `key` is not a grid key of the study.
    ImportError
        SciPy is not installed (``pip install scipy``).

    Examples
    --------
    >>> from hinf_cpp.studies.report import paired_tests
    >>> from hinf_cpp.studies import run_study, study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "noise", "scenario": str(hc.scenario_path("paper_fig2")), "samples": 6},
    ...     "grid": [{"key": "controller.law", "values": ["hinf", "cascade"]}],
    ...     "random": [{"key": "measurement.seed", "distribution": "seed"}]})
    >>> table = run_study(study, progress=False)
    >>> tests = paired_tests(table, study, "controller.law", "rms_position_error_last_half")
    >>> tests[["comparison", "n", "lower", "statistic", "rank_biserial"]]
             comparison  n  lower  statistic  rank_biserial
    0  cascade - hinf  6    0.0        0.0            1.0
    >>> round(float(tests["p_value"][0]), 5)  # exact: 2 / 2^6
    0.03125
    """
    import pandas as pd
    from scipy import stats

    position, axis = _axis_of(study, key)
    indices = _axis_indices(df, study)
    along = indices[:, position]
    # The pair of a run: its sample and its indices along the other grid axes.
    others = np.delete(indices, position, axis=1)
    shape = tuple(s for i, s in enumerate(study.grid_shape) if i != position)
    other_point = np.ravel_multi_index(others.T, shape) if shape else np.zeros(len(df), dtype=np.int64)
    pair = other_point * study.samples + df["sample"].to_numpy(dtype=np.int64)
    values = df[metric].to_numpy(dtype=float)
    ok = _finite_completed(values, df["status"].to_numpy())

    def by_pair(index: int) -> pd.Series:
        at = (along == index) & ok
        return pd.Series(values[at], index=pair[at])

    def text(index: int) -> str:
        return ", ".join(_value_text(v) for _, v in axis.settings(index))

    reference = by_pair(0)
    rows = []
    for index in range(1, len(axis.values)):
        current = by_pair(index)
        common = current.index.intersection(reference.index).sort_values()
        d = (current.loc[common] - reference.loc[common]).to_numpy(dtype=float)
        row = {"comparison": f"{text(index)} - {text(0)}", "n": len(d),
               "mean": float(d.mean()) if len(d) else math.nan}
        row["mean_low"], row["mean_high"] = bootstrap_ci(d, "mean", confidence, resamples, seed)
        row.update(median=float(np.median(d)) if len(d) else math.nan,
                   lower=float((d < 0).mean()) if len(d) else math.nan,
                   statistic=math.nan, p_value=math.nan, rank_biserial=_rank_biserial(d))
        if np.count_nonzero(d):
            result = stats.wilcoxon(d)
            row.update(statistic=float(result.statistic), p_value=float(result.pvalue))
        rows.append(row)
    return pd.DataFrame(rows, columns=["comparison", "n", "mean", "mean_low", "mean_high", "median", "lower",
                                       "statistic", "p_value", "rank_biserial"])


def failed_runs_text(df, limit: int = _FAILED_LISTED, table: str = "runs.csv") -> str:
    """The runs of a table that did not complete, one line each with the command that runs it
    again alone (the ``replay`` column), for the command line and summary.md.

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study` (with its ``replay`` column).
    limit : int, optional
        The most runs listed (default 10); a last line says how many more there are.
    table : str, optional
        Where the other commands are, for that line (default ``"runs.csv"``).

    Returns
    -------
    str
        ``run N (STATUS): COMMAND`` lines (empty when every run completed).

    Examples
    --------
    >>> import pandas as pd
    >>> from hinf_cpp.studies.report import failed_runs_text
    >>> table = pd.DataFrame({"run": [0, 1, 2], "status": ["completed", "diverged", "conjugate_point"],
    ...                       "replay": ["hinf-cpp run a.toml --set controller.gamma=5.0",
    ...                                  "hinf-cpp run a.toml --set controller.gamma=1.0",
    ...                                  "hinf-cpp run a.toml --set controller.gamma=0.5"]})
    >>> print(failed_runs_text(table, limit=1))
    run 1 (diverged): hinf-cpp run a.toml --set controller.gamma=1.0
    ... and 1 more run that did not complete: its command is in the replay column of runs.csv
    """
    failed = df[df["status"] != "completed"]
    if not len(failed) or "replay" not in df.columns:
        return ""
    lines = [f"run {int(run)} ({status}): {command}"
             for run, status, command in zip(failed["run"][:limit], failed["status"][:limit], failed["replay"][:limit])]
    more = len(failed) - min(limit, len(failed))
    if more:
        lines.append(f"... and {more} more run{'s' if more > 1 else ''} that did not complete: "
                     f"{'their commands are' if more > 1 else 'its command is'} in the replay column of {table}")
    return "\n".join(lines)


def _ci_text(low: float, high: float) -> str:
    if not (math.isfinite(low) and math.isfinite(high)):
        return "-"
    return f"[{low:.4g}, {high:.4g}]"


def _timing_text(df, study, seconds: float | None) -> str:
    """The time of this invocation and the runs it ran: a resumed study ran only the chunks
    that were not saved, so its runs per second are those runs' (not the whole study's)."""
    if not seconds:
        return ""
    reused = int(df.attrs.get("reused_runs", 0) or 0)
    ran = max(0, study.runs - reused)
    if not reused:
        return f" Wall time {seconds:.1f} s ({study.runs / seconds:.0f} runs/s)."
    chunks = df.attrs.get("reused_chunks", "?")
    chunks = f"{chunks} chunk" + ("" if chunks == 1 else "s")
    if not ran:
        return (f" This invocation ran none of the runs: all {study.runs} were reused from {chunks} saved by "
                f"an earlier one ({seconds:.1f} s to load them and write the outputs).")
    return (f" This invocation ran {ran} of the {study.runs} runs in {seconds:.1f} s ({ran / seconds:.0f} runs/s); "
            f"the other {reused} were reused from {chunks} saved by an earlier invocation, whose time "
            "is not counted.")


def _grid_only(df, study) -> bool:
    """Every group of the summary holds one run: a grid without random samples (nothing to pool)."""
    columns = _group_columns(df, study)
    return study.samples == 1 and set(columns) == {key for axis in study.grid for key in axis.keys}


def summary_markdown(df, study, seconds: float | None = None) -> str:
    """The text of a study's ``summary.md`` (Markdown).

    What the study is (and the time of this invocation: of a resumed study, the runs it ran
    itself), the status counts per group (:func:`status_counts`; with [report] roa the runs
    that recovered), the statistics of the report's metrics per group (:func:`summarize`),
    a table per grid axis of each metric's mean and median per value of the axis with
    bootstrap confidence intervals (:func:`axis_statistics`), with random samples the paired
    differences between the values of every grid axis with a Wilcoxon signed-rank test
    (:func:`paired_tests`), and the replay commands of the first runs that did not complete.

    A grid-only study (no [[random]] axis: every group one run) has no statistics per group:
    its runs are one table (up to 40 grid points; beyond, runs.csv) and the tables per grid
    axis give mean, median, min and max over the other axes, without intervals or tests
    (there is no sampling to resample). Above 40 groups, the runs per status are given per
    value of each grid axis instead of per group.

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study`.
    study : hinf_cpp.studies.Study
        Its study.
    seconds : float, optional
        The wall time of this invocation (s), stated with the runs per second of the runs it
        ran (``df.attrs["reused_runs"]`` of a resumed study were not run).

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
              + _timing_text(df, study, seconds), ""]
    grid_only = _grid_only(df, study)
    group_columns = _group_columns(df, study)
    counts = status_counts(df, study)
    shown = [s for s in _STATUS_ORDER if counts[s].sum() > 0] if len(counts) else []
    header = [c for c in counts.columns if c not in _STATUS_ORDER] + shown
    if study.report.get("roa"):
        tol, deg = study.report.get("position_tol", 0.5), study.report.get("heading_tol", 10.0)
        ok = df.assign(_ok=recovered(df, tol, deg))
        shares = [int(group["_ok"].sum()) for _, group in _groups(ok, group_columns)]
        counts = counts.assign(recovered=shares)
        header.append("recovered")
        lines += [f"Recovered: completed with |p_e(tf)| < {tol:g} and |psi_e(tf)| < {deg:g} degrees.", ""]
    totals = ", ".join(f"{status} {int(counts[status].sum())}" for status in shown)
    if len(counts) <= _MAX_GROUP_ROWS and not (grid_only and len(counts) > 1):
        lines += ["## Runs per status", "",
                  markdown_table(header, _key_rows(counts[header].values.tolist(), len(group_columns)))]
    else:
        lines += ["## Runs per status", "", f"All runs: {totals}. Per value of each grid axis (pooled over the "
                  "other axes):", ""]
        indices = _axis_indices(df, study)
        status = df["status"].to_numpy()
        for position, axis in enumerate(study.grid):
            if len(axis.values) > 1:
                rows = [[*(_key_cell(v) for _, v in axis.settings(index)), int((indices[:, position] == index).sum()),
                         *(int(((indices[:, position] == index) & (status == s)).sum()) for s in shown)]
                        for index in range(len(axis.values))]
                lines += [markdown_table(list(axis.keys) + ["runs", *shown], rows)]
    if grid_only:
        if len(df) <= _MAX_GROUP_ROWS:
            keys = [key for axis in study.grid for key in axis.keys]
            rows = _key_rows(df[keys + ["status"] + metrics].values.tolist(), len(keys))
            lines += ["## Runs", "", "One run per grid point (no random samples): its status and metrics.", "",
                      markdown_table(keys + ["status"] + [_metric_column(m) for m in metrics], rows)]
        else:
            lines += [f"A grid of {len(df)} points without random samples: each run is one row of runs.csv; the "
                      "tables below pool the other grid axes.", ""]
    else:
        stats = summarize(df, study, metrics)
        for metric in metrics:
            part = stats[stats["metric"] == metric]
            header = group_columns + ["n", "mean", "std", "p5", "p50", "p95"]
            rows = part[group_columns + ["count", "mean", "std", "p5", "p50", "p95"]].values.tolist()
            lines += [f"## {_metric_heading(metric)} (completed runs)", "",
                      markdown_table(header, _key_rows(rows, len(group_columns)))]
    varied = [axis for axis in study.grid if len(axis.values) > 1]
    if varied and not (grid_only and len(study.grid) == 1):
        if grid_only:
            lines += ["## By grid axis", "",
                      "Per value of each grid axis, the completed runs over the values of the other grid axes "
                      "(no random samples: no confidence intervals).", ""]
        else:
            lines += ["## By grid axis", "",
                      f"Per value of each grid axis, the completed runs pooled over the samples and the other grid "
                      f"axes; in brackets the {100 * CONFIDENCE:g} % percentile-bootstrap confidence interval "
                      f"({BOOTSTRAP_RESAMPLES} resamples, seed {BOOTSTRAP_SEED}).", ""]
        for axis in varied:
            table = axis_statistics(df, study, axis.keys[0], metrics)
            for metric in metrics:
                part = table[table["metric"] == metric]
                keys = list(axis.keys)
                records = part.to_dict("records")
                if grid_only:
                    header = keys + ["runs", "completed", "mean", "median", "min", "max"]
                    rows = [[r[c] for c in header] for r in records]
                else:
                    level = f"{100 * CONFIDENCE:g} % CI"
                    header = keys + ["runs", "completed", "n", "mean", f"mean {level}", "median", f"median {level}"]
                    rows = [[*(r[k] for k in keys), r["runs"], r["completed"], r["n"], r["mean"],
                             _ci_text(r["mean_low"], r["mean_high"]), r["median"],
                             _ci_text(r["median_low"], r["median_high"])] for r in records]
                lines += [f"### {_metric_heading(metric)} by {', '.join(keys)}", "",
                          markdown_table(header, _key_rows(rows, len(keys)))]
    if study.samples > 1 and varied:
        lines += ["## Paired differences between the values of each grid axis (common random numbers)", "",
                  "A run at a value minus the run at the axis's first value with the same sample (the same noise "
                  "and plant) and the same values of the other grid axes, over the pairs where both completed: "
                  "the mean difference with its "
                  f"{100 * CONFIDENCE:g} % percentile-bootstrap interval ({BOOTSTRAP_RESAMPLES} resamples, seed "
                  f"{BOOTSTRAP_SEED}), the median difference, the share of pairs where it is negative, the "
                  "Wilcoxon signed-rank test (scipy.stats.wilcoxon, two-sided, zero differences left out; W the "
                  "smaller rank sum; p not adjusted for the number of tests) and the matched-pairs rank-biserial "
                  "correlation r = (T+ - T-) / (T+ + T-) (+1: larger at every pair).", ""]
        try:
            import scipy.stats  # noqa: F401 - the paired tests need it
        except ImportError:
            lines += ["The paired tests need SciPy (pip install scipy): not given.", ""]
            varied = []
        for axis in varied:
            for metric in metrics:
                tests = paired_tests(df, study, axis.keys[0], metric)
                if not len(tests):
                    continue
                header = [", ".join(axis.keys), "pairs", "mean", f"{100 * CONFIDENCE:g} % CI", "median", "lower",
                          "W", "p", "r"]
                rows = [[r["comparison"], r["n"], r["mean"], _ci_text(r["mean_low"], r["mean_high"]), r["median"],
                         r["lower"], r["statistic"], r["p_value"], r["rank_biserial"]]
                        for r in tests.to_dict("records")]
                lines += [f"### {_metric_heading(metric)}: {', '.join(axis.keys)}", "", markdown_table(header, rows)]
    failed = failed_runs_text(df)
    if failed:
        lines += ["## Runs that did not complete", "",
                  "Each runs again alone with its command (the `replay` column of runs.csv):", "", "```", failed,
                  "```", ""]
    return "\n".join(lines)


def _label(law: str, output_feedback: bool) -> str:
    if not law:  # every run of the group was refused before a law was built
        return "?"
    return f"{law}/{'output' if output_feedback else 'state'}"


def _wrapped(text: str, width: int) -> str:
    """Text broken into lines of about `width` characters (at least 30): a long metric label
    ran off the figure's edges."""
    return textwrap.fill(text, width=max(30, width))


def _metric_label(metric: str) -> str:
    """A metric's axis label, "label [unit]" from hc.metric_table(); another column's name."""
    for definition in _core.metric_table():
        if definition.name == metric:
            return f"{definition.label} [{definition.unit}]"
    return metric


def _metric_column(metric: str) -> str:
    """A metric as a column of a table in summary.md: its name in runs.csv and its unit."""
    for definition in _core.metric_table():
        if definition.name == metric:
            return f"{metric} [{definition.unit}]"
    return metric


def _metric_heading(metric: str) -> str:
    """A metric in a heading of summary.md: its label and unit, and its column in runs.csv."""
    label = _metric_label(metric)
    return label if label == metric else f"{label} (`{metric}`)"


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
    ax.set_ylabel(_wrapped(_metric_label(metric), 40))
    ax.set_title(_wrapped(title or f"{_metric_label(metric)}: completed runs (whiskers 5-95 %)",
                          int(11 * fig.get_figwidth())), fontsize=9)
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


def key_label(key: str, state_names: Sequence[str] = (), units: dict | None = None) -> str:
    """An axis label for a scenario key, with its unit where it is known.

    The unit is `units`' entry for the key ([report] units), else the known one: gamma
    ``[-]``, an initial state ``initial.q0[i]`` of a built-in vehicle by its state's name
    (``psi(t0) [rad]``). A key of unknown unit is labelled by its name alone.

    Parameters
    ----------
    key : str
        A scenario key (a grid or random key of a study).
    state_names : sequence of str, optional
        The model's state names (``Model.state_names()``).
    units : dict, optional
        Units by key, which take precedence ([report] units).

    Returns
    -------
    str
        The label.

    Examples
    --------
    >>> from hinf_cpp.studies.report import key_label
    >>> key_label("controller.gamma")
    'gamma [-]'
    >>> key_label("initial.q0[5]", ["u", "v", "r", "x", "y", "psi"])
    'psi(t0) [rad]  (initial.q0[5])'
    >>> key_label("measurement.sigma", units={"measurement.sigma": "m"})
    'measurement.sigma [m]'
    """
    import re

    unit = (units or {}).get(key)
    if key == "controller.gamma":
        return f"gamma [{unit or _KEY_UNITS[key]}]"
    match = re.fullmatch(r"initial\.q0\[(\d+)\]", key)
    if match and int(match.group(1)) < len(state_names):
        name = state_names[int(match.group(1))]
        unit = unit or _STATE_UNITS.get(name)
        return f"{name}(t0)" + (f" [{unit}]" if unit else "") + f"  ({key})"
    unit = unit or _KEY_UNITS.get(key)
    return f"{key} [{unit}]" if unit else key


def heatmap_figure(df, x: str, y: str, metric: str, other_columns: Sequence[str] = (), state_names: Sequence[str] = (),
                   units: dict | None = None, title: str | None = None) -> Figure:
    """A metric's mean over a two-axis grid: one cell per pair of values, a colour bar.

    Each cell is the mean of the metric over the completed runs with those values of `x` and
    `y` (its samples; NaN values left out), written in the cell when there are at most 150
    cells; a cell without such a run is grey. The axes keep the order of the values in the table
    (the grid's), one tick per value (gamma = inf as "inf"), labelled by :func:`key_label`; one
    panel per combination of the values of `other_columns` (the other grid keys), all on one
    colour scale.

    Parameters
    ----------
    df : pandas.DataFrame
        A table of :func:`hinf_cpp.studies.run_study` with `x` and `y` as grid keys.
    x : str
        The key along the horizontal axis.
    y : str
        The key along the vertical axis.
    metric : str
        The metric column.
    other_columns : sequence of str, optional
        Grid keys whose values get panels of their own (default none: pooled).
    state_names : sequence of str, optional
        The model's state names (``initial.q0[i]`` axes named by their state).
    units : dict, optional
        Units of keys ([report] units), for the axis labels.
    title : str, optional
        The title (default names the metric).

    Returns
    -------
    matplotlib.figure.Figure
        The figure: one panel per value of `other_columns`, and a colour bar.

    Examples
    --------
    >>> import pandas as pd
    >>> from hinf_cpp.studies.report import heatmap_figure
    >>> table = pd.DataFrame({"controller.gamma": [5.0, 5.0, 10.0, 10.0],
    ...                       "measurement.sigma": [0.1, 0.5, 0.1, 0.5], "status": "completed",
    ...                       "final_position_error": [0.1, 0.3, 0.2, 0.4]})
    >>> figure = heatmap_figure(table, "controller.gamma", "measurement.sigma", "final_position_error",
    ...                         units={"measurement.sigma": "m"})
    >>> ax = figure.axes[0]
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('gamma [-]', 'measurement.sigma [m]')
    >>> figure.axes[1].get_ylabel()
    'mean final position error [m]'
    >>> [t.get_text() for t in ax.texts]
    ['0.1', '0.2', '0.3', '0.4']
    """
    import pandas as pd

    others = [key for key in other_columns if key not in (x, y)]
    xs, ys = list(pd.unique(df[x])), list(pd.unique(df[y]))
    panels = []
    for values, part in _groups(df, others):
        values = values if isinstance(values, tuple) else (values,)
        done = part[(part["status"] == "completed") & np.isfinite(part[metric].to_numpy(dtype=float))]
        grid = np.full((len(ys), len(xs)), np.nan)
        for (yv, xv), mean in done.groupby([y, x], sort=False)[metric].mean().items():
            grid[ys.index(yv), xs.index(xv)] = mean
        panels.append((values if others else (), grid))
    finite = np.concatenate([grid[np.isfinite(grid)] for _, grid in panels]) if panels else np.array([])
    vmin, vmax = (float(finite.min()), float(finite.max())) if len(finite) else (0.0, 1.0)
    columns = min(3, max(1, len(panels)))
    rows = math.ceil(max(1, len(panels)) / columns)
    width = max(3.2, 0.55 * len(xs) + 1.6)
    fig = Figure(figsize=(width * columns + 1.0, (max(2.6, 0.4 * len(ys) + 1.4) + 0.15 * len(others)) * rows + 0.4),
                 layout="constrained")
    axes = fig.subplots(rows, columns, squeeze=False)
    import matplotlib

    colours = matplotlib.colormaps["viridis"].with_extremes(bad="lightgrey")
    image = None
    for ax, (values, grid) in zip(axes.flat, panels):
        image = ax.pcolormesh(np.arange(len(xs) + 1) - 0.5, np.arange(len(ys) + 1) - 0.5,
                              np.ma.masked_invalid(grid), cmap=colours, vmin=vmin, vmax=vmax, shading="flat")
        ax.set_xticks(range(len(xs)), [_value_text(v) for v in xs], fontsize=7,
                      rotation=45 if max((len(_value_text(v)) for v in xs), default=0) > 4 else 0)
        ax.set_yticks(range(len(ys)), [_value_text(v) for v in ys], fontsize=7)
        ax.set_xlabel(key_label(x, state_names, units), fontsize=8)
        ax.set_ylabel(key_label(y, state_names, units), fontsize=8)
        if grid.size <= 150:
            middle = (vmin + vmax) / 2
            for (i, j), value in np.ndenumerate(grid):
                if np.isfinite(value):
                    ax.text(j, i, f"{value:.3g}", ha="center", va="center", fontsize=6,
                            color="white" if value < middle else "black")
        if others:
            ax.set_title("\n".join(f"{k} = {_value_text(v)}" for k, v in zip(others, values)), fontsize=8)
    for ax in list(axes.flat)[len(panels):]:
        ax.set_visible(False)
    if image is not None:
        bar = fig.colorbar(image, ax=axes, shrink=0.9)
        bar.set_label(f"mean {_metric_label(metric)}", fontsize=8)
        bar.ax.tick_params(labelsize=7)
    text = title or f"{_metric_label(metric)}: mean of the completed runs per cell (grey: none)"
    fig.suptitle(_wrapped(text, int(11 * fig.get_figwidth())), fontsize=9)
    return fig


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
    ax.set_ylabel(_wrapped(_metric_label(metric), 40))
    ax.set_title(_wrapped(title or f"{_metric_label(metric)} against gamma: median, 5-95 % band of the samples",
                          int(11 * fig.get_figwidth())), fontsize=9)
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


def _save_figure(fig: Figure, out: pathlib.Path, stem: str) -> list[pathlib.Path]:
    """A figure as PNG (150 dpi) and PDF (vector, for a paper)."""
    return [_save(fig, out / f"{stem}.png"), _save(fig, out / f"{stem}.pdf")]


def _heatmap_axes(study) -> tuple[str, str] | None:
    """The keys of heatmap.png: [report] heatmap, else the two grid axes of more than one value
    (their first keys) when exactly two vary and there is no region-of-attraction map."""
    if study.report.get("heatmap"):
        return tuple(study.report["heatmap"])
    varied = [axis for axis in study.grid if len(axis.values) > 1]
    if len(varied) == 2 and not study.report.get("roa"):
        return varied[0].keys[0], varied[1].keys[0]
    return None


def write_study_outputs(study, df, out, seconds: float | None = None) -> list[pathlib.Path]:
    """Write a study's table, summary and figures into a folder.

    ``runs.parquet``, ``runs.csv`` (numbers at full precision), ``summary.md``
    (:func:`summary_markdown`) and the figures the study asks for, each as PNG and PDF:
    ``distribution`` (a metric's distribution per law and grid point, when a run completed),
    with [report] roa ``roa`` (the region-of-attraction map), with a controller.gamma grid
    axis ``gamma`` (the metric against gamma), with two grid axes of more than one value (and
    no roa map) or [report] heatmap ``heatmap`` (the mean of [report] heatmap_metric, else
    distribution, per cell of the two axes: :func:`heatmap_figure`). The figures keep the
    values of the grid axes apart (boxes, panels or lines of their own) but for the roa keys,
    which the map spreads out, and the gamma axis in ``gamma.png``. Each file is written whole
    or not at all.

    Parameters
    ----------
    study : hinf_cpp.studies.Study
        The study.
    df : pandas.DataFrame
        Its table (:func:`hinf_cpp.studies.run_study`).
    out : str or os.PathLike
        The folder (created if needed).
    seconds : float, optional
        The wall time of this invocation (s), for the summary.

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
    ['runs.parquet', 'runs.csv', 'summary.md', 'distribution.png', 'distribution.pdf', 'gamma.png', 'gamma.pdf']
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
    names = None
    if (df["status"] == "completed").any():
        written += _save_figure(distribution_figure(df, metric, title=f"{study.name}: {_metric_label(metric)}",
                                                    other_columns=point_columns), out, "distribution")
    if report.get("roa"):
        x, y = report["roa"]
        names = study.scenario(0).model.state_names()
        written += _save_figure(roa_figure(df, x, y, report.get("position_tol", 0.5), report.get("heading_tol", 10.0),
                                           state_names=names, other_columns=point_columns), out, "roa")
    gamma_axes = [axis for axis in study.grid if "controller.gamma" in axis.keys]
    if gamma_axes:
        gamma_metric = report.get("gamma_metric", "rms_position_error_last_half")
        # The keys set together with gamma move with it: they are the gamma axis, not other axes.
        other_columns = [key for key in point_columns if key not in gamma_axes[0].keys]
        written += _save_figure(gamma_figure(df, gamma_metric,
                                             title=f"{study.name}: {_metric_label(gamma_metric)} against gamma",
                                             other_columns=other_columns), out, "gamma")
    heatmap = _heatmap_axes(study)
    if heatmap is not None:
        x, y = heatmap
        # The keys set together with x or y move with them; every other grid key gets panels.
        moving = {key for axis in study.grid if x in axis.keys or y in axis.keys for key in axis.keys}
        heat_metric = report.get("heatmap_metric", metric)
        names = names if names is not None else study.scenario(0).model.state_names()
        written += _save_figure(heatmap_figure(df, x, y, heat_metric,
                                               other_columns=[k for axis in study.grid for k in axis.keys
                                                              if k not in moving],
                                               state_names=names, units=report.get("units"),
                                               title=f"{study.name}: {_metric_label(heat_metric)}, mean of the "
                                                     "completed runs per cell (grey: none)"),
                                out, "heatmap")
    return written
