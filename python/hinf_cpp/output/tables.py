"""Plain-text, Markdown and CSV renderings of small tables (a header and rows of cells).

Cells are strings, numbers (non-finite shown as ``-`` in text and Markdown, empty in CSV),
booleans (``yes`` / ``no``) or None (``-``).
"""

from __future__ import annotations

import csv
import io
import math
from typing import Any, Sequence

from hinf_cpp import _core

__all__ = ["csv_table", "format_cell", "markdown_table", "run_key", "text_table"]


def run_key(law: _core.Law, output_feedback: bool) -> str:
    """The label of a run: the law's name, with ``/output-feedback`` for output feedback."""
    return f"{law.name}/output-feedback" if output_feedback else law.name


def format_cell(value: Any, digits: int = 4) -> str:
    """A cell as text: numbers with ``digits`` significant digits, non-finite as ``-``."""
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
    """Columns aligned with spaces: the first left-aligned, the others right-aligned."""
    cells = _cells(header, rows, digits)
    widths = [max(len(row[j]) for row in cells) for j in range(len(header))]

    def line(row: list[str]) -> str:
        return "  ".join(c.ljust(w) if j == 0 else c.rjust(w) for j, (c, w) in enumerate(zip(row, widths)))

    rule = "  ".join("-" * w for w in widths)
    return "\n".join([line(cells[0]), rule, *(line(r) for r in cells[1:])]) + "\n"


def markdown_table(header: Sequence[Any], rows: Sequence[Sequence[Any]], digits: int = 4) -> str:
    """A GitHub-flavoured Markdown table (``|`` in cells escaped)."""
    cells = [[c.replace("|", "\\|") for c in row] for row in _cells(header, rows, digits)]
    lines = ["| " + " | ".join(cells[0]) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(row) + " |" for row in cells[1:]]
    return "\n".join(lines) + "\n"


def csv_table(header: Sequence[Any], rows: Sequence[Sequence[Any]]) -> str:
    """CSV with numbers at full precision (``repr``), non-finite numbers and None empty."""

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
