"""The checked-in type stubs of the extension (python/hinf_cpp/_core.pyi) are those of the
built module: regenerated into a temporary folder, they must be the same text."""

from __future__ import annotations

import os
import pathlib
import subprocess
import sys

import pytest

pytestmark = pytest.mark.text  # run once per CI, not under the sanitizers (conftest.py)

ROOT = pathlib.Path(__file__).resolve().parents[2]
REGENERATE = "bash scripts/generate_stubs.sh"


def test_checked_in_stubs_match_the_module(tmp_path):
    done = subprocess.run(["bash", str(ROOT / "scripts" / "generate_stubs.sh"), str(tmp_path)],
                          capture_output=True, text=True, timeout=300, env=dict(os.environ, PYTHON=sys.executable))
    assert done.returncode == 0, f"pybind11-stubgen failed:\n{done.stdout}\n{done.stderr}"
    generated = (tmp_path / "hinf_cpp" / "_core.pyi").read_text()
    checked_in = (ROOT / "python" / "hinf_cpp" / "_core.pyi").read_text()
    assert generated == checked_in, (
        f"python/hinf_cpp/_core.pyi is out of date with the bindings: run `{REGENERATE}` (after rebuilding "
        "the package) and commit the result")
    assert "0x" not in generated and " at 0x" not in generated  # no memory addresses
    assert (ROOT / "python" / "hinf_cpp" / "py.typed").exists()


def test_checked_in_contracts_match_the_headers():
    """cpp/python/contracts.hpp (the header comments the docstrings begin with) is what
    scripts/generate_contracts.py extracts from cpp/include/hinf today."""
    done = subprocess.run([sys.executable, str(ROOT / "scripts" / "generate_contracts.py"), "--check"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, (
        f"cpp/python/contracts.hpp is out of date with the headers: run `python scripts/generate_contracts.py`, "
        f"rebuild and commit the result\n{done.stdout}{done.stderr}")
