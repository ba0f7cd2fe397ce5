"""Plain-text, Markdown and CSV renderings of small tables (a header and rows of cells).

Cells are strings, numbers (non-finite shown as ``-`` in text and Markdown, empty in CSV),
booleans (``yes`` / ``no``) or None (``-``). Runs are named by :func:`run_key`; what a run's law
acts on, :class:`~hinf_cpp.analysis.Feedback`, is defined here, beside it (the command line's
parser names its members without loading the analyses), and imported from
:mod:`hinf_cpp.analysis`.
"""

from __future__ import annotations

import csv
import enum
import io
import math
from typing import Any, Sequence

from hinf_cpp import _core

__all__ = ["csv_table", "format_cell", "markdown_table", "run_key", "text_table"]


class Feedback(enum.Enum):
    """What a run's law acts on: the true state, or the estimate from the measurements.

    ``Feedback.state``: perfect state feedback (the scenario's [measurement] removed);
    ``Feedback.output``: output feedback (paper §4: the filter of paper eq. (36), the
    estimator, the law on the estimate), for a scenario with [measurement]. The members'
    values are their names, as written in tables and JSON.

    Examples
    --------
    >>> from hinf_cpp.analysis import Feedback
    >>> Feedback("output"), [mode.name for mode in Feedback]
    (<Feedback.output: 'output'>, ['state', 'output'])
    """

    state = "state"    # perfect state feedback ([measurement] removed)
    output = "output"  # output feedback (paper §4): filter, estimator, law on the estimate


def run_key(law: _core.Law, output_feedback: bool) -> str:
    """The label of a run: the law's name, with ``/output-feedback`` for output feedback.

    The key of a run in comparisons, tables and figure legends.

    Parameters
    ----------
    law : hinf_cpp.Law
        The law.
    output_feedback : bool
        Whether the run is output feedback.

    Returns
    -------
    str
        ``"hinf"``, ``"lqr/output-feedback"``, ...

    Examples
    --------
    >>> from hinf_cpp.output.tables import run_key
    >>> run_key(hc.Law.lqr, True), run_key(hc.Law.hinf, False)
    ('lqr/output-feedback', 'hinf')
    """
    return f"{law.name}/output-feedback" if output_feedback else law.name


def format_cell(value: Any, digits: int = 4) -> str:
    """A cell of a text or Markdown table as text.

    Numbers with `digits` significant digits, non-finite numbers and None as ``-``, booleans
    as ``yes`` / ``no``, anything else as ``str``.

    Parameters
    ----------
    value : object
        The cell.
    digits : int, optional
        Significant digits of numbers (default 4).

    Returns
    -------
    str
        The text.

    Examples
    --------
    >>> from hinf_cpp.output.tables import format_cell
    >>> format_cell(0.047907816), format_cell(float("nan")), format_cell(True), format_cell(None)
    ('0.04791', '-', 'yes', '-')
    """
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, float)):
        if not math.isfinite(value):
            return "-"
        return f"{value:.{digits}g}"
    return str(value)


def _cells(header: Sequence[Any], rows: Sequence[Sequence[Any]], digits: int) -> list[list[str]]:
    width = len(header)
    for i, row in enumerate(rows):
        if len(row) != width:
            raise ValueError(f"table row {i} has {len(row)} cells, the header has {width}")
    return [[format_cell(c, digits) for c in header]] + [[format_cell(c, digits) for c in row] for row in rows]


def text_table(header: Sequence[Any], rows: Sequence[Sequence[Any]], digits: int = 4) -> str:
    """A plain-text table: columns aligned with spaces, a rule under the header.

    The first column is left-aligned, the others right-aligned.

    Parameters
    ----------
    header : sequence
        The column names.
    rows : sequence of sequence
        The rows, each with one cell per column (:func:`format_cell`).
    digits : int, optional
        Significant digits of numbers (default 4).

    Returns
    -------
    str
        The table, ending in a newline.

    Raises
    ------
    ValueError
        A row whose length differs from the header's.

    Examples
    --------
    >>> from hinf_cpp.output.tables import text_table
    >>> print(text_table(["law", "RMS [m]"], [["hinf", 0.047907], ["lqr", float("nan")]]), end="")
    law   RMS [m]
    ----  -------
    hinf  0.04791
    lqr         -
    """
    cells = _cells(header, rows, digits)
    widths = [max(len(row[j]) for row in cells) for j in range(len(header))]

    def line(row: list[str]) -> str:
        return "  ".join(c.ljust(w) if j == 0 else c.rjust(w) for j, (c, w) in enumerate(zip(row, widths)))

    rule = "  ".join("-" * w for w in widths)
    return "\n".join([line(cells[0]), rule, *(line(r) for r in cells[1:])]) + "\n"


def markdown_table(header: Sequence[Any], rows: Sequence[Sequence[Any]], digits: int = 4) -> str:
    """A GitHub-flavoured Markdown table (``|`` in cells escaped).

    Parameters
    ----------
    header : sequence
        The column names.
    rows : sequence of sequence
        The rows, each with one cell per column (:func:`format_cell`).
    digits : int, optional
        Significant digits of numbers (default 4).

    Returns
    -------
    str
        The table, ending in a newline.

    Raises
    ------
    ValueError
        A row whose length differs from the header's.

    Examples
    --------
    >>> from hinf_cpp.output.tables import markdown_table
    >>> print(markdown_table(["law", "recovers"], [["hinf", True], ["lqr|kf", False]]), end="")
    | law | recovers |
    |---|---|
    | hinf | yes |
    | lqr\\|kf | no |
    """
    cells = [[c.replace("|", "\\|") for c in row] for row in _cells(header, rows, digits)]
    lines = ["| " + " | ".join(cells[0]) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(row) + " |" for row in cells[1:]]
    return "\n".join(lines) + "\n"


def csv_table(header: Sequence[Any], rows: Sequence[Sequence[Any]]) -> str:
    """A CSV table with numbers at full precision (``repr``).

    Non-finite numbers and None are empty cells, booleans ``true`` / ``false``.

    Parameters
    ----------
    header : sequence
        The column names.
    rows : sequence of sequence
        The rows, each with one cell per column.

    Returns
    -------
    str
        The CSV text, one line per row after the header.

    Raises
    ------
    ValueError
        A row whose length differs from the header's.

    Examples
    --------
    >>> from hinf_cpp.output.tables import csv_table
    >>> rows = [["hinf", 0.1, True], ["lqr", float("nan"), None]]
    >>> print(csv_table(["law", "rms", "recovers"], rows), end="")
    law,rms,recovers
    hinf,0.1,true
    lqr,,
    """

    def cell(value: Any) -> str:
        if value is None:
            return ""
        if isinstance(value, bool):
            return "true" if value else "false"
        if isinstance(value, (int, float)):
            return repr(float(value)) if math.isfinite(value) else ""
        return str(value)

    _cells(header, rows, 4)  # checks the row widths
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow([str(h) for h in header])
    writer.writerows([[cell(c) for c in row] for row in rows])
    return buffer.getvalue()
