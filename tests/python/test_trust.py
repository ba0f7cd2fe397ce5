"""Files are data (docs/trust.md): a scenario or study whose model is code (kind = "casadi" loads
a library, kind = "python" runs Python) is read only with trust, through every front end; a
library is loaded only from beside its model.json and only when it is a whole shared library;
what a user's model code raises is reported as the user's.

Each "was it run" check looks for a file that the planted code writes when it runs."""

from __future__ import annotations

import json
import os
import pathlib
import pickle
import re
import shutil
import subprocess
import sys

import pytest

import hinf_cpp as hc
from hinf_cpp.studies import study_from_dict

BIN = pathlib.Path(sys.executable).parent
FIG1 = hc.scenario_path("paper_fig1").read_text()


def with_model(model: str, text: str = FIG1) -> str:
    """The paper's Figure 1 scenario with its [model] section replaced."""
    return re.sub(r"\[model\]\n.*?\n\n", f"[model]\n{model}\n\n", text, count=1, flags=re.S)


def planting_model(folder: pathlib.Path, marker: pathlib.Path, body: str = "return hc.ShipModel()") -> None:
    (folder / "planted.py").write_text(f"import hinf_cpp as hc\nopen({str(marker)!r}, 'w').close()\n\n"
                                       f"def make():\n    {body}\n")


def run(*args, env_trust: str | None = None, cwd=None) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k != "HINF_TRUST_CODE"}
    if env_trust is not None:
        env["HINF_TRUST_CODE"] = env_trust
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=300, env=env, cwd=cwd)


@pytest.fixture(autouse=True)
def no_trust_from_outside(monkeypatch):
    monkeypatch.delenv("HINF_TRUST_CODE", raising=False)


def test_a_python_model_is_not_run_without_trust(tmp_path):
    marker = tmp_path / "ran"
    planting_model(tmp_path, marker)
    path = tmp_path / "s.toml"
    path.write_text(with_model('kind = "python"\ncallable = "planted.py:make"'))
    with pytest.raises(ValueError, match=r"s\.toml: \[model\] callable: kind = \"python\" loads and runs a program "
                                         r"\(planted\.py:make\).*--trust-code.*trust_code=True.*HINF_TRUST_CODE=1"):
        hc.load_scenario(path)
    with pytest.raises(ValueError, match="loads and runs a program"):
        hc.scenario_from_dict({"model": {"kind": "python", "callable": "planted.py:make"}}, str(path))
    # Another mistake in the file (gamma = -1): still refused for trust, nothing run first.
    bad = tmp_path / "bad.toml"
    bad.write_text(with_model('kind = "python"\ncallable = "planted.py:make"').replace("gamma = 5.0", "gamma = -1.0"))
    for args in (["run", path], ["run", bad], ["gamma-star", path], ["certify", path], ["plan", path, "-o", "x.toml"]):
        done = run(BIN / "hinf-cpp", *args, cwd=tmp_path)
        assert done.returncode == 2 and done.stderr.count("\n") == 1, (args, done.stderr)
        assert "loads and runs a program" in done.stderr, done.stderr
    assert not marker.exists()
    # Allowed three ways: the argument, the flag, the environment.
    assert hc.load_scenario(path, trust_code=True).model.name() == "ship" and marker.exists()
    marker.unlink()
    assert run(BIN / "hinf-cpp", "run", path, "--trust-code").returncode == 0 and marker.exists()
    marker.unlink()
    assert run(BIN / "hinf-cpp", "run", path, env_trust="1").returncode == 0 and marker.exists()
    marker.unlink()
    assert run(BIN / "hinf-cpp", "run", path, env_trust="0").returncode == 2 and not marker.exists()
    done = run(BIN / "hinf-cpp", "run", path, env_trust="yes")
    assert done.returncode == 2 and "HINF_TRUST_CODE = 'yes': set it to 1" in done.stderr
    assert "HINF_TRUST_CODE" not in os.environ  # the flag did not leak out of the command


@pytest.mark.parametrize("edit", [
    ("gamma = 5.0", "gamma = -1.0"),                       # a value
    ("[horizon]", "[horizon]\nt_final = 3.0"),              # an unknown key
    ("[initial]", "[sampling]\nperiod = 0.1\ndelay = 0.5\n\n[initial]"),  # a setting of another section
])
def test_with_trust_a_file_wrong_elsewhere_runs_nothing(tmp_path, edit):
    marker = tmp_path / "ran"
    planting_model(tmp_path, marker)
    path = tmp_path / "s.toml"
    text = with_model('kind = "python"\ncallable = "planted.py:make"')
    assert edit[0] in text
    path.write_text(text.replace(edit[0], edit[1], 1))
    with pytest.raises(ValueError, match=r"s\.toml: "):
        hc.load_scenario(path, trust_code=True)
    done = run(BIN / "hinf-cpp", "run", path, "--trust-code", cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert not marker.exists()
    # The planner's path too: the waypoints replace the inputs, the rest is checked first.
    planned = text.replace(edit[0], edit[1], 1)
    planned = re.sub(r"\[desired\]\n(q0 = .*?\n).*?\n\n",
                     '[desired]\n\\1waypoints = [{ x = 20.0, y = 0.0, t = 20.0 }]\n\n', planned, count=1, flags=re.S)
    assert "waypoints" in planned
    path.write_text(planned)
    done = run(BIN / "hinf-cpp", "plan", path, "-o", tmp_path / "p.toml", "--trust-code", cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert not marker.exists()


def test_a_study_reads_code_only_with_trust_and_carries_the_answer(tmp_path):
    marker = tmp_path / "ran"
    planting_model(tmp_path, marker)
    base = tmp_path / "s.toml"
    base.write_text(with_model('kind = "python"\ncallable = "planted.py:make"'))
    definition = {"study": {"scenario": str(base)}, "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]}
    with pytest.raises(ValueError, match="loads and runs a program"):
        study_from_dict(definition)
    assert not marker.exists()
    study = study_from_dict(definition, trust_code=True)
    assert study.trust_code and marker.exists()
    assert pickle.loads(pickle.dumps(study)).trust_code  # what a Dask worker gets
    assert study.scenario(1).gamma == 10.0


@pytest.fixture(scope="module")
def exported_ship(tmp_path_factory):
    pytest.importorskip("casadi")
    from hinf_cpp.models import builtin

    folder = tmp_path_factory.mktemp("exported")
    return builtin.ship().export(folder / "ship", cache_dir=folder / "cache")


@pytest.fixture(scope="module")
def planted_library(tmp_path_factory):
    """A shared library whose constructor writes a marker file when it is loaded."""
    compiler = shutil.which("cc") or shutil.which("gcc")
    if compiler is None:
        pytest.skip("no C compiler")
    folder = tmp_path_factory.mktemp("planted")
    marker = folder / "loaded"
    (folder / "planted.c").write_text("#include <stdio.h>\n__attribute__((constructor)) static void planted(void) "
                                      f"{{ FILE* f = fopen(\"{marker}\", \"w\"); if (f) fclose(f); }}\n")
    subprocess.run([compiler, "-shared", "-fPIC", "-o", str(folder / "planted.so"), str(folder / "planted.c")],
                   check=True)
    return folder / "planted.so", marker


@pytest.mark.skipif(not (BIN / "hinf-sim").exists(), reason="hinf-sim is not installed next to this Python")
def test_a_compiled_model_is_loaded_only_with_trust_and_only_from_beside_its_description(
        exported_ship, planted_library, tmp_path):
    library, marker = planted_library
    marker.unlink(missing_ok=True)
    folder = tmp_path / "ship"
    shutil.copytree(exported_ship.parent, folder)
    path = tmp_path / "s.toml"
    path.write_text(with_model('kind = "casadi"\nfile = "ship/model.json"'))
    refused = run(BIN / "hinf-sim", path)
    assert refused.returncode == 2 and refused.stderr.count("\n") == 1
    assert "[model] file: kind = \"casadi\" loads and runs a program (ship/model.json)" in refused.stderr
    assert run(BIN / "hinf-sim", path, "--trust-code").returncode == 0
    # A description that names a library elsewhere (any path) is refused before anything loads.
    description = json.loads((folder / "model.json").read_text())
    for elsewhere in (str(library), f"../{library.name}", "sub/planted.so", ".."):
        shutil.copy(library, tmp_path / library.name)
        (folder / "model.json").write_text(json.dumps(dict(description, library=elsewhere)))
        done = run(BIN / "hinf-sim", path, "--trust-code")
        assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
        assert "must be the file name of a library beside model.json" in done.stderr, done.stderr
        with pytest.raises(ValueError, match="must be the file name of a library beside model.json"):
            hc.GeneratedModel(str(folder / "model.json"))
    assert not marker.exists()


@pytest.mark.skipif(not (BIN / "hinf-sim").exists(), reason="hinf-sim is not installed next to this Python")
def test_a_cut_off_library_is_a_message_not_a_crash(exported_ship, tmp_path):
    """dlopen of a truncated library died of SIGBUS (no message) in both programs."""
    folder = tmp_path / "ship"
    shutil.copytree(exported_ship.parent, folder)
    library = folder / json.loads((folder / "model.json").read_text())["library"]
    library.write_bytes(library.read_bytes()[: library.stat().st_size // 2])
    path = tmp_path / "s.toml"
    path.write_text(with_model('kind = "casadi"\nfile = "ship/model.json"'))
    for program in ([BIN / "hinf-sim", path], [BIN / "hinf-cpp", "run", path]):
        done = run(*program, "--trust-code")
        assert done.returncode == 2, (program, done.returncode, done.stderr)  # not -SIGBUS
        assert done.stderr.count("\n") == 1 and "is not a whole shared library for this machine: it is cut off" \
            in done.stderr, done.stderr


@pytest.mark.parametrize("body, said", [
    ("raise RuntimeError('no thrusters')", "'planted.py:make': the call raised RuntimeError: no thrusters"),
    ("return 1 / 0", "'planted.py:make': the call raised ZeroDivisionError: division by zero"),
    ("raise SystemExit(7)", "'planted.py:make': the call called sys.exit(7)"),
    ("import sibling\n    return sibling.make()", None),  # a module beside the file is importable
])
def test_what_a_users_model_raises_is_the_users(tmp_path, body, said):
    planting_model(tmp_path, tmp_path / "ran", body)
    (tmp_path / "sibling.py").write_text("import hinf_cpp as hc\n\ndef make():\n    return hc.ShipModel()\n")
    path = tmp_path / "s.toml"
    path.write_text(with_model('kind = "python"\ncallable = "planted.py:make"'))
    done = run(BIN / "hinf-cpp", "run", path, "--trust-code", cwd=tmp_path / "..")
    if said is None:
        assert done.returncode == 0, done.stderr
        return
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert said in done.stderr, done.stderr


@pytest.mark.parametrize("source, said", [
    ("def make(:\n", "running .*planted.py raised SyntaxError"),
    ("import no_such_module_here\n", "running .*planted.py raised ModuleNotFoundError"),
    ("raise SystemExit(3)\n", "running .*planted.py called sys.exit\\(3\\)"),
])
def test_a_model_file_that_fails_to_run_is_named(tmp_path, source, said):
    (tmp_path / "planted.py").write_text(source)
    path = tmp_path / "s.toml"
    path.write_text(with_model('kind = "python"\ncallable = "planted.py:make"'))
    with pytest.raises(ValueError, match=f"'planted.py:make': {said}"):
        hc.load_scenario(path, trust_code=True)
