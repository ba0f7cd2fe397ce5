"""The tutorial's code blocks run, in order, and print what the text says they print."""

from __future__ import annotations

import contextlib
import io
import os
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_tutorial_code_blocks_run(monkeypatch):
    text = (ROOT / "docs" / "tutorial.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 5
    monkeypatch.chdir(ROOT)
    namespace: dict = {}
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        for block in blocks:
            exec(compile(block, "docs/tutorial.md", "exec"), namespace)  # noqa: S102
    printed = out.getvalue()
    # Statements of the text checked against the run.
    assert printed.startswith("hinf 5.0")
    assert "(4001,) (4001, 6) (4001, 2)" in printed
    assert 1.334 < namespace["star"].gamma_star < 1.336
    assert "conjugate point at t =" in printed
    assert namespace["cert"].p_min > 0
    assert "True\nTrue" in printed  # coupling held; the replay is identical
    assert printed.endswith("True\nTrue\n")  # the pickled scenario and result are the same
    assert namespace["position_error"][-1] < 0.1 * namespace["position_error"][0]
    assert os.path.exists(ROOT / "docs" / "mathematics.md")


def test_readme_python_block_runs(monkeypatch):
    text = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) == 1
    monkeypatch.chdir(ROOT)
    namespace: dict = {}
    with contextlib.redirect_stdout(io.StringIO()) as out:
        exec(compile(blocks[0], "README.md", "exec"), namespace)  # noqa: S102
    # What the comments of the block say.
    assert 0.0 < float(out.getvalue()) < 0.1
    assert namespace["Z"].shape == (5, 6, 6)
    assert abs(namespace["star"].gamma_star - 1.335) < 1e-3
    run = namespace["run"]
    assert run.q.shape[1] == 6 and run.q.shape[0] == run.t.shape[0]
