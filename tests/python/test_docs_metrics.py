"""docs/results.md lists the library's metric table: the same keys, labels, units and
definitions in the same order (the table is defined once, in C++; the document is written
from it and this test keeps the two equal)."""
import json
import pathlib
import re

import pytest

import hinf_cpp as hc

pytestmark = pytest.mark.text  # run once per CI, not under the sanitizers (conftest.py)

ROOT = pathlib.Path(__file__).resolve().parents[2]


def documented_metrics():
    rows = []
    text = (ROOT / "docs" / "results.md").read_text()
    table = text[text.index("| key | label | unit | definition |"):]
    for line in table.splitlines()[2:]:
        if not line.startswith("|"):
            break
        # Split on the cell separators, not on the escaped bars of |p - p_d|.
        cells = [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", line)[1:-1]]
        rows.append((cells[0].strip("`"), cells[1], cells[2], cells[3]))
    return rows


def test_results_reference_lists_the_metric_table():
    table = [(d.name, d.label, d.unit, d.definition) for d in hc.metric_table()]
    assert documented_metrics() == table


def test_results_file_has_every_metric_of_the_table():
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.tf = 2.0
    result = hc.run_scenario(scenario)
    data = json.loads(hc._core.results_json(result))
    assert sorted(data["metrics"]) == sorted(d.name for d in hc.metric_table())  # JSON keys are sorted
    # The file's solver is bdf: the method the GRDE solve reports is written as is.
    assert data["solver"]["grde_method"] == result.solution.stats().method
    assert data["solver"]["grde_method"].startswith("bdf")
