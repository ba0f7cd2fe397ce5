"""The code blocks of the docs run, in order, and print what the text says they print: the
tutorial, the README's example and docs/end_to_end.md (in a scratch folder, with hinf-sim); and
what docs/models.md says about constant_input_matrices() holds."""

from __future__ import annotations

import contextlib
import io
import os
import pathlib
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

pytestmark = pytest.mark.text  # run once per CI, not under the sanitizers (conftest.py)

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = pathlib.Path(sys.executable).parent


def test_tutorial_code_blocks_run(monkeypatch):
    text = (ROOT / "docs" / "tutorial.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 10
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
    assert "True\nTrue\n4000 True\n" in printed  # the pickled scenario and result are the same
    assert namespace["position_error"][-1] < 0.1 * namespace["position_error"][0]
    assert os.path.exists(ROOT / "docs" / "mathematics.md")
    # Section 8: the output-feedback run from the pieces is section 5's run_scenario, bit for
    # bit (the same design, noise and options: no tolerance), and its series are as printed.
    assert "4000 True\nTrue True\n" in printed
    run2, result2 = namespace["run2"], namespace["result2"]
    assert np.array_equal(run2.estimator.q_hat, result2.simulation.estimator.q_hat)
    assert np.array_equal(run2.u, result2.simulation.u)
    assert "(4001, 6) (4001, 3)\n[0. 0. 0. 0. 0. 0.] [-0.1   -1.334  1.269]\n0.1043 0.1043\n20.82 0\nTrue nan\n" in printed
    assert printed.endswith("4.59 GammaCondition.coupling\n")
    assert re.search(r"^\(20\.81\d*, 0\.0\)$", printed, flags=re.M)


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


def fenced_blocks(text: str) -> list[tuple[str, str]]:
    """The fenced code blocks of a Markdown text, in order: (language, code)."""
    return re.findall(r"```(\w*)\n(.*?)```", text, flags=re.S)


def with_free_numbers(line: str, free: list[str]) -> str:
    """A regular expression matching `line` exactly, except the numbers that the patterns of
    `free` find in it, which may be any number."""
    parts = re.split("(" + "|".join(free) + ")", line)
    return "".join(re.escape(part) if i % 2 == 0 else r"[\d.e+-]+" for i, part in enumerate(parts))


@pytest.mark.ipopt
@pytest.mark.skipif(not (BIN / "hinf-sim").exists(), reason="hinf-sim is not installed next to this Python")
def test_end_to_end_page_runs_and_prints_what_it_says(tmp_path, monkeypatch):
    """docs/end_to_end.md: the Python blocks and the shell command, in order, in a scratch folder
    holding a copy of examples/catamaran.py (the page's own set-up). Runs the planner (IPOPT)."""
    pytest.importorskip("casadi")
    text = (ROOT / "docs" / "end_to_end.md").read_text()
    blocks = [(language, code) for language, code in fenced_blocks(text) if language in ("python", "bash")]
    assert [language for language, _ in blocks] == ["python"] * 4 + ["bash", "python"]
    (tmp_path / "examples").mkdir()
    shutil.copy(ROOT / "examples" / "catamaran.py", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("HINF_CPP_CACHE", str(tmp_path / "cache"))  # this test's own compiled models
    monkeypatch.setenv("PATH", f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}")
    monkeypatch.setattr(sys, "path", list(sys.path))  # the page's sys.path.insert is undone afterwards
    monkeypatch.delitem(sys.modules, "catamaran", raising=False)
    namespace: dict = {}
    printed = []
    for language, code in blocks:
        if language == "bash":
            done = subprocess.run(code, shell=True, capture_output=True, text=True, timeout=600)
            assert done.returncode == 0, done.stderr
            printed.append(done.stdout)
            continue
        with contextlib.redirect_stdout(io.StringIO()) as out:
            exec(compile(code, "docs/end_to_end.md", "exec"), namespace)  # noqa: S102
        printed.append(out.getvalue())
    sys.modules.pop("catamaran", None)
    model, plan, run, export, sim, compare = printed

    # What the page says each step prints: the indented block after "prints", in order (steps
    # 1, 2, 3, 5 and 6), and step 4's inline one.
    said = [block.replace("\n    ", "\n")[4:] for block in
            re.findall(r"^prints(?: \(the time varies\))?\n\n((?:    .*\n)+)", text, flags=re.M)]
    assert len(said) == 5
    said_model, said_plan, said_run, said_sim, said_compare = said
    # 1. The vehicle, 3. output feedback, 6. the comparison: exactly as on the page. Step 3's
    # numbers (rounded to 3 digits) rest on IPOPT's plan, an optimum to IPOPT's tolerance: on
    # another BLAS or CPU its last digits may differ, and a printed digit with them.
    assert model == said_model
    assert run == said_run
    assert compare == said_compare  # equal, not close: the same library code, scenario and model
    # 2. The plan: the summary as on the page but for the numbers of this machine's solve (its
    # time, IPOPT's iterations, the mismatch); the thrusts to the page's two decimals.
    summary, extremes = said_plan.splitlines()
    assert re.fullmatch(with_free_numbers(summary, [r"\d+(?= IPOPT iterations)", r"[\d.]+(?= s;)",
                                                    r"(?<=mismatch )[\d.e+-]+"]), plan.splitlines()[0]), plan
    assert plan.splitlines()[1] == extremes
    report = namespace["planned"].report
    assert report.position_mismatch < 1e-6 and max(report.waypoint_errors) <= 0.05
    assert np.all(namespace["planned"].u >= 0.0) and np.all(namespace["planned"].u <= 12.0)
    metrics = namespace["result"].metrics
    assert metrics.max_rho_sigma_z < namespace["scenario"].gamma ** 2
    # 4. The export and the file's head as shown.
    assert f"prints `{export.strip()}`" in text
    toml_blocks = [code for language, code in fenced_blocks(text) if language == "toml"]
    assert (tmp_path / "catamaran.toml").read_text().startswith(toml_blocks[0])
    assert (tmp_path / "catamaran" / "model.json").is_file()
    # 5. hinf-sim's line as on the page but for its run time.
    assert re.fullmatch(with_free_numbers(said_sim.strip(), [r"(?<=total )[\d.]+(?= ms)"]), sim.strip()), sim


def test_models_page_on_constant_input_matrices():
    """docs/models.md, "Input matrices that change": the default, which would freeze a G(t) at
    t0, is refused for such a model; the override gives the closed form; both flags True is
    refused. Closed form: with G = [0, 1 + t]' and u = 1 from rest, v(t) = t + t^2/2 and
    x(t) = t^2/2 + t^3/6."""
    import hinf_cpp as hc

    class TimeVaryingInput(hc.Model):
        def n(self): return 2
        def m(self): return 1
        def nw(self): return 1
        def f(self, t, q): return np.array([q[1], 0.0])
        def G(self, t, q): return np.array([[0.0], [1.0 + t]])
        def D(self, t, q): return np.array([[0.0], [1.0]])

    class Declared(TimeVaryingInput):
        def constant_input_matrices(self): return False

    class Contradictory(TimeVaryingInput):
        def state_dependent_inputs(self): return True

    # The default would freeze G at t0 (q_d(2) = [2, 2] instead of [3.33, 4]): refused, naming
    # the declaration to change.
    with pytest.raises(ValueError, match=r"returns another G at t = 1, .* than at t = 0, .*override "
                                         r"constant_input_matrices\(\) to return false"):
        hc.Trajectory(TimeVaryingInput(), [0.0, 0.0], [1.0], 0.0, 2.0)
    # Integrated at rtol 1e-10: 1e-8 is far below the differences the page describes.
    right = hc.Trajectory(Declared(), [0.0, 0.0], [1.0], 0.0, 2.0)
    np.testing.assert_allclose(right.q_d(2.0), [2.0 + 8.0 / 6.0, 4.0], rtol=1e-8)
    np.testing.assert_allclose(hc.solve_grde(right, np.eye(2), np.eye(2), 10.0).gain(2.0), [[0.0, 3.0]], atol=1e-12)
    with pytest.raises(ValueError, match="state_dependent_inputs"):
        hc.Trajectory(Contradictory(), [0.0, 0.0], [1.0], 0.0, 2.0)
