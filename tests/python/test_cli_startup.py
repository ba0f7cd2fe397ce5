"""The command line imports what a command needs: a plain ``hinf-cpp run`` (no plot, no plan) and
``hinf-cpp --help`` load none of the heavy optional libraries, and loading the package does not
import NumPy (start-up time).

Each case runs in a fresh interpreter, since the test process itself has imported them. The
time is measured by benchmarks/bench_startup.py, not here.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

import hinf_cpp as hc

HEAVY = ("pandas", "matplotlib", "casadi", "scipy", "PIL", "dask")

# Runs the command line in-process, then prints its exit status and the heavy modules loaded.
SCRIPT = """
import json, sys
import hinf_cpp.cli
try:
    status = hinf_cpp.cli.main(json.loads(sys.argv[1]))
except SystemExit as stop:  # --help exits
    status = stop.code
print(json.dumps({"status": status, "loaded": sorted(m for m in json.loads(sys.argv[2]) if m in sys.modules)}))
"""


def command_line(argv: list[str], cwd) -> dict:
    done = subprocess.run([sys.executable, "-c", SCRIPT, json.dumps(argv), json.dumps(HEAVY)], capture_output=True,
                          text=True, timeout=300, cwd=cwd)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])


@pytest.mark.parametrize("settings", [[], ["--set", "controller.gamma=6"]],
                         ids=["plain", "with --set"])
def test_run_loads_no_heavy_library(tmp_path, settings):
    out = tmp_path / "run.json"
    done = command_line(["run", str(hc.scenario_path("paper_fig1")), "--json", str(out), *settings], tmp_path)
    assert done == {"status": 0, "loaded": []}
    assert json.loads(out.read_text())["scenario"] == "paper-fig1"


def test_help_loads_no_heavy_library(tmp_path):
    assert command_line(["--help"], tmp_path) == {"status": 0, "loaded": []}


def test_loading_the_package_does_not_import_numpy():
    """NumPy (~50-80 ms) loads at the first array conversion, not with the extension: no default
    argument of the bindings is an array or prints one (cpp/python/fields.hpp)."""
    script = "import sys, hinf_cpp, hinf_cpp.cli; print('numpy' in sys.modules)"
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "False"
