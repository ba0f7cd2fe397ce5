"""Failures at the command line, in both front ends (hinf-sim, C++ only; hinf-cpp, Python).

Every failure is ONE line on stderr, "PROGRAM: error: MESSAGE", with exit status 2 (bad input,
unusable output paths, inputs too large for the machine) or 3 (numerical failure); 1 is left
for genuine bugs. Both front ends read scenario files with the one C++ reader, so they give the
same MESSAGE for the same bad file. Output paths are checked before the computation starts,
and output files are written whole or not at all.
"""

from __future__ import annotations

import os
import pathlib
import re
import resource
import signal
import subprocess
import sys

import pytest

import hinf_cpp as hc

BIN = pathlib.Path(sys.executable).parent
HINF_SIM = BIN / "hinf-sim"
HINF_CPP = BIN / "hinf-cpp"
PAPER_TEXT = pathlib.Path(hc.scenario_path("paper_fig1")).read_text()
FIG2_TEXT = pathlib.Path(hc.scenario_path("paper_fig2")).read_text()

needs_programs = pytest.mark.skipif(not (HINF_SIM.exists() and HINF_CPP.exists()),
                                    reason="hinf-sim / hinf-cpp are not installed next to this Python")


def mutate(text: str, old: str, new: str) -> str:
    """text with `old` replaced by `new`; `old` must occur (so no case silently tests nothing)."""
    assert old in text, f"test bug: {old!r} not in the scenario text"
    return text.replace(old, new)


# gamma = 1 is below gamma* of the paper's run: a computation would end with a conjugate
# point (exit status 3). An output problem reported with status 2 was found before it.
DOOMED_TEXT = mutate(PAPER_TEXT, "gamma = 5.0", "gamma = 1.0")


def run(*args, limits: dict | None = None, cwd=None) -> subprocess.CompletedProcess:
    """Runs a program; `limits` maps resource.RLIMIT_* to a soft and hard limit for it."""

    def apply_limits():
        # Past RLIMIT_FSIZE a write fails with EFBIG (instead of a SIGXFSZ that kills).
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        for which, value in (limits or {}).items():
            resource.setrlimit(which, (value, value))

    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=600, cwd=cwd,
                          preexec_fn=apply_limits if limits else None)


def error_message(result: subprocess.CompletedProcess, program: str, status: int, match: str) -> str:
    """The message of a one-line error with the given exit status; it must match `match`."""
    assert result.returncode == status, (result.returncode, result.stderr)
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    prefix = f"{program}: error: "
    assert lines[0].startswith(prefix), lines[0]
    message = lines[0][len(prefix):]
    assert re.search(match, message), message
    return message


def both_front_ends(scenario, status: int, match: str, *options) -> str:
    """hinf-sim and hinf-cpp run on the same scenario and options: the same one-line error."""
    sim = error_message(run(HINF_SIM, scenario, *options), "hinf-sim", status, match)
    cpp = error_message(run(HINF_CPP, "run", scenario, *options), "hinf-cpp", status, match)
    assert sim == cpp
    return sim


@pytest.fixture(scope="module", autouse=True)
def warm_python_cli():
    """Import the Python CLI once (matplotlib may build its font cache on a first import and
    say so on stderr; that is not the CLI's output)."""
    subprocess.run([sys.executable, "-c", "import hinf_cpp.cli, hinf_cpp.plotting"], capture_output=True,
                   timeout=300)


def write(tmp_path: pathlib.Path, name: str, text: str | bytes) -> pathlib.Path:
    path = tmp_path / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text)
    return path


# ======================================================================================
# Scenario files: the one reader, the same message from both front ends
# ======================================================================================

LINES_Q0 = "q0 = [1.0, 0.0, 0.0, -1.0, -1.0, 0.7853981633974483]"

# id -> (scenario text, pattern the message must match)
BAD_FILES = {
    "seed beyond 64 bits": (mutate(FIG2_TEXT, "seed = 20000601", "seed = 18446744073709551616"),
                            r"\[measurement\] seed.*64 bits|64 bits.*\[measurement\] seed"),
    "parameter as a huge integer": (mutate(PAPER_TEXT, "m_u = 0.5", "m_u = 100000000000000000000"),
                                    r"\[model\] m_u"),
    "huge integer on its own line of a list": (
        mutate(PAPER_TEXT, LINES_Q0, "q0 = [\n  1.0,\n  0.0,\n  -99999999999999999999,\n  -1.0, -1.0, 0.78]"),
        r"\[initial\] q0"),
    "N = []": (mutate(FIG2_TEXT, "N = 0.25", "N = []"), r"\[measurement\] N: .*empty"),
    "Q0 = []": (mutate(FIG2_TEXT, "Q0 = 2.0", "Q0 = []"), r"\[measurement\] Q0: .*empty"),
    "empty table": (mutate(PAPER_TEXT, "u1 = { offset = 1.0 }", "u1 = { table = { t = [], value = [] } }"),
                    r"\[desired\] u1\.table\.t: .*empty"),
    "deeply nested dotted key": (PAPER_TEXT + "\nx" + ".x" * 200000 + " = 1\n", r"nested|dotted"),
    "deeply nested table header": (PAPER_TEXT + "\n[" + "x." * 200000 + "x]\n", r"nested|dotted"),
    "deeply nested arrays": (PAPER_TEXT + "\nx = " + "[" * 100000 + "]" * 100000 + "\n", r"nested"),
    "deeply nested inline tables": (PAPER_TEXT + "\nx = " + "{ a = " * 100000 + "1" + " }" * 100000 + "\n",
                                    r"nested"),
    "Q = inf": (mutate(PAPER_TEXT, "Q = 1.0", "Q = inf"), r"\[controller\] Q: .*finite.*inf"),
    "tf = inf": (mutate(PAPER_TEXT, "tf = 40.0", "tf = inf"), r"\[horizon\] tf: .*finite"),
    "m_u = nan": (mutate(PAPER_TEXT, "m_u = 0.5", "m_u = nan"), r"\[model\] m_u: .*finite"),
    "amplitude = -inf": (mutate(PAPER_TEXT, "amplitude = 0.3", "amplitude = -inf"),
                         r"\[desired\] u2\.harmonics\[0\]\.amplitude: .*finite"),
    "sigma = inf": (mutate(FIG2_TEXT, "sigma = 0.5", "sigma = inf"), r"\[measurement\] sigma: .*finite"),
    "gamma = nan": (mutate(PAPER_TEXT, "gamma = 5.0", "gamma = nan"), r"\[controller\] gamma"),
    "w4 in [disturbance]": (mutate(PAPER_TEXT, "\n[initial]", "w4 = 0.1\n\n[initial]"),
                            r"\[disturbance\] w4: .*measurement-noise channel.*\[measurement\]"),
    "w6 in [disturbance] with output feedback": (
        mutate(FIG2_TEXT, "\n[initial]", "w6 = { harmonics = [ { amplitude = 0.2, omega = 1.0 } ] }\n\n[initial]"),
        r"\[disturbance\] w6: .*measurement-noise channel.*\[measurement\]"),
}


@needs_programs
@pytest.mark.parametrize("case", list(BAD_FILES))
def test_bad_scenario_file_same_error_from_both_front_ends(tmp_path, case):
    text, match = BAD_FILES[case]
    path = write(tmp_path, "bad.toml", text)
    message = both_front_ends(path, 2, match)
    assert str(path) in message


def test_noise_channel_keys_follow_the_model():
    """A model without measurement noise channels (kind = "linear") keeps every w key."""
    text = """
[model]
kind = "linear"
A = [[-1.0]]
B = [[1.0]]
D = [[1.0, 0.5]]
[horizon]
tf = 1.0
[desired]
q0 = [0.0]
u1 = 0.0
[controller]
gamma = 3.0
[disturbance]
w2 = 0.1
[initial]
q0 = [0.0]
"""
    assert hc.parse_scenario_toml(text, "linear.toml").disturbance(0.5)[1] == 0.1
    assert hc.ShipModel(hc.ShipParameters()).noise_channels() == [3, 4, 5]


@needs_programs
def test_byte_order_mark_is_accepted_by_both(tmp_path):
    path = write(tmp_path, "bom.toml", b"\xef\xbb\xbf" + PAPER_TEXT.encode())
    plain = write(tmp_path, "plain.toml", PAPER_TEXT)
    for program in ([HINF_SIM], [HINF_CPP, "run"]):
        for scenario, out in ((path, "bom.json"), (plain, "plain.json")):
            result = run(*program, scenario, "--json", tmp_path / out)
            assert result.returncode == 0 and result.stderr == "", result.stderr
        assert (tmp_path / "bom.json").read_text().split('"timing_s"')[0] == \
               (tmp_path / "plain.json").read_text().split('"timing_s"')[0]
    assert hc.load_scenario(path).name == "paper-fig1"


@needs_programs
def test_non_utf8_file_is_named(tmp_path):
    path = write(tmp_path, "latin1.toml", PAPER_TEXT.encode() + "# café\n".encode("latin-1"))
    message = both_front_ends(path, 2, r"(?i)utf-8")
    assert str(path) in message


@needs_programs
def test_scenario_path_is_a_directory(tmp_path):
    message = both_front_ends(tmp_path, 2, r"is a directory")
    assert f"'{tmp_path}'" in message and "[model]" not in message


@needs_programs
def test_scenario_path_unreadable(tmp_path):
    parent = write(tmp_path, "plain_file", "x")
    message = both_front_ends(parent / "scenario.toml", 2, r"cannot read scenario file .*Not a directory")
    assert str(parent / "scenario.toml") in message
    both_front_ends(tmp_path / "missing.toml", 2, r"cannot read scenario file .*No such file")


# ======================================================================================
# scenario_from_dict and signal_from_spec: through the same reader
# ======================================================================================

def test_scenario_from_dict_bad_values_are_value_errors():
    import tomllib

    spec = tomllib.loads(PAPER_TEXT)
    deep = current = {}
    for _ in range(5000):
        current["a"] = {}
        current = current["a"]
    with pytest.raises(ValueError, match=r"<dict>: .*nested"):
        hc.scenario_from_dict(dict(spec, x=deep))
    with pytest.raises(ValueError, match=r"<dict>: .*None"):
        hc.scenario_from_dict(dict(spec, horizon={"tf": None}))
    spec["measurement"] = {"sigma": 0.5, "seed": 2 ** 64}
    with pytest.raises(ValueError, match=r"<dict>.*\[measurement\] seed"):
        hc.scenario_from_dict(spec)
    spec["measurement"] = {"sigma": 0.5, "N": []}
    with pytest.raises(ValueError, match=r"\[measurement\] N: .*empty"):
        hc.scenario_from_dict(spec)


def test_signal_from_spec():
    s = hc.signal_from_spec({"offset": 0.5, "harmonics": [{"amplitude": 0.3, "omega": 0.2, "shape": "cos"}]})
    assert s(2.0) == pytest.approx(0.5 + 0.3 * __import__("math").cos(0.4), rel=1e-15)
    assert hc.signal_from_spec(1.5)(3.0) == 1.5
    with pytest.raises(ValueError, match=r"kappa\.harmonics\[0\]: give exactly one of omega"):
        hc.signal_from_spec({"harmonics": [{"amplitude": 1.0}]}, "kappa")
    with pytest.raises(ValueError, match=r"w1: .*finite"):
        hc.signal_from_spec(float("inf"), "w1")
