"""Failures at the command line, in both front ends (hinf-sim, C++ only; hinf-cpp, Python).

Every failure is ONE line on stderr, "PROGRAM: error: MESSAGE", with exit status 2 (bad input,
unusable output paths, inputs too large for the machine) or 3 (numerical failure); 1 is left
for genuine bugs. Both front ends read scenario files with the one C++ reader, so they give the
same MESSAGE for the same bad file. Output paths are checked before the computation starts,
and output files are written whole or not at all.
"""

from __future__ import annotations

import errno
import os
import pathlib
import re
import resource
import signal
import subprocess
import sys
import warnings

import pytest

import hinf_cpp as hc
from hinf_cpp import cli

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
    subprocess.run([sys.executable, "-c", "import hinf_cpp.cli, hinf_cpp.output.plotting"], capture_output=True,
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
    assert hc._core.parse_scenario_toml(text, "linear.toml").disturbance(0.5)[1] == 0.1
    assert hc.ShipModel(hc.ShipParameters()).noise_channels() == [3, 4, 5]


# ======================================================================================
# hinf-cpp run --set KEY=VALUE: the value is read as the file reader reads it
# ======================================================================================

# What the reader says of each literal refused (None: accepted). 1e400 overflows a double:
# tomllib reads it as inf, toml++ refuses it; inf is how TOML writes infinity (gamma may be inf).
GAMMA_LITERALS = {
    "1e400": "could not be interpreted as a value",
    "-1e400": "could not be interpreted as a value",
    "1.8e308": "could not be interpreted as a value",
    "99999999999999999999": "not representable in 64 bits",
    "nan": "expected a number",
    "-inf": "must be > 0",
    "inf": None,
    "+inf": None,
    "1.7976931348623157e308": None,
}


@pytest.mark.parametrize("literal", list(GAMMA_LITERALS))
def test_set_accepts_and_refuses_a_number_as_the_file_reader_does(tmp_path, capsys, literal):
    """`--set controller.gamma=1e400` ran with gamma = inf, where the same literal in the file is
    refused."""
    in_file = write(tmp_path, "gamma.toml", mutate(PAPER_TEXT, "gamma = 5.0", f"gamma = {literal}"))
    file_status = cli.main(["run", str(in_file)])
    file_error = capsys.readouterr().err
    set_status = cli.main(["run", str(hc.scenario_path("paper_fig1")), "--set", f"controller.gamma={literal}"])
    set_error = capsys.readouterr().err
    reason = GAMMA_LITERALS[literal]
    assert (file_status, set_status) == ((0, 0) if reason is None else (2, 2)), (file_error, set_error)
    if reason is not None:
        assert reason in file_error and reason in set_error, (file_error, set_error)
        assert len(set_error.splitlines()) == 1 and "gamma" in set_error
    # The file's literal with another key --set: the file is then read in Python (to apply the
    # setting), with the reader's accept/reject too.
    both_status = cli.main(["run", str(in_file), "--set", "controller.Q=1.0"])
    both_error = capsys.readouterr().err
    assert both_status == file_status, (file_error, both_error)


@pytest.mark.parametrize("setting", ["controller.gamma=5\n[initial]\nq0 = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]",
                                     "controller.gamma=5\r", "controller.gamma=\t5", "controller.gamma=5\x00",
                                     'controller.law="lqr\u2028"', "controller.gam\nma=5"])
def test_set_refuses_a_line_break_or_control_character(capsys, setting):
    """What followed a line break in a --set value was silently dropped (the run went on)."""
    status = cli.main(["run", str(hc.scenario_path("paper_fig1")), "--set", setting])
    error = capsys.readouterr().err
    assert status == 2
    lines = error.splitlines()
    assert len(lines) == 1, error
    assert re.match(r"hinf-cpp: error: --set 'controller\.(gam\\nma|gamma|law)=.*': a line break or control "
                    r"character \(U\+[0-9A-F]{4}\) at position \d+: give one KEY=VALUE on one line", lines[0]), error


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


@needs_programs
def test_out_of_memory_is_exit_status_2(tmp_path):
    """A run larger than the memory it may use: 1e8 output times of 22 columns."""
    path = write(tmp_path, "huge.toml", mutate(PAPER_TEXT, "dt = 0.01", "dt = 4.1e-7"))
    limits = {resource.RLIMIT_AS: 3 << 30}
    for program, args in (("hinf-sim", [HINF_SIM, path]), ("hinf-cpp", [HINF_CPP, "run", path])):
        error_message(run(*args, limits=limits), program, 2, r"memory")


# ======================================================================================
# Output paths: checked before the computation, written atomically
# ======================================================================================

@needs_programs
@pytest.mark.parametrize("option", ["--json", "--csv"])
def test_output_parent_is_a_file(tmp_path, option):
    scenario = write(tmp_path, "doomed.toml", DOOMED_TEXT)
    parent = write(tmp_path, "plain_file", "x")
    target = parent / "sub" / "out.txt"
    message = both_front_ends(scenario, 2, r"not a directory", option, target)
    assert str(target) in message and str(parent) in message


@needs_programs
@pytest.mark.parametrize("option", ["--json", "--csv"])
def test_output_path_is_a_directory(tmp_path, option):
    scenario = write(tmp_path, "doomed.toml", DOOMED_TEXT)
    message = both_front_ends(scenario, 2, r"is a directory", option, tmp_path)
    assert str(tmp_path) in message


@needs_programs
def test_output_path_empty(tmp_path):
    scenario = write(tmp_path, "doomed.toml", DOOMED_TEXT)
    both_front_ends(scenario, 2, r"empty", "--json", "")
    for option in ("--csv", "--npz", "--plot"):
        error_message(run(HINF_CPP, "run", scenario, option, ""), "hinf-cpp", 2, r"^an output file name is empty$")


@needs_programs
@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full")
@pytest.mark.parametrize("option", ["--json", "--csv"])
def test_full_disk(tmp_path, option):
    scenario = hc.scenario_path("paper_fig1")
    both_front_ends(scenario, 2, r"cannot write '/dev/full': No space left on device", option, "/dev/full")


@needs_programs
@pytest.mark.parametrize("program", ["hinf-sim", "hinf-cpp"])
def test_failed_write_keeps_the_old_file(tmp_path, program):
    """A write that fails half-way (file size limit: as a full disk) leaves the previous file
    as it was and no temporary file behind."""
    out = tmp_path / "out"
    out.mkdir()
    old_csv = write(out, "run.csv", "old contents\n")
    args = [HINF_SIM] if program == "hinf-sim" else [HINF_CPP, "run"]
    result = run(*args, hc.scenario_path("paper_fig1"), "--json", out / "run.json", "--csv", old_csv,
                 limits={resource.RLIMIT_FSIZE: 256 << 10})
    error_message(result, program, 2, f"cannot write '{re.escape(str(old_csv))}': File too large")
    assert old_csv.read_text() == "old contents\n"
    assert sorted(p.name for p in out.iterdir()) == ["run.csv", "run.json"]
    assert (out / "run.json").read_text().rstrip().endswith("}")


@needs_programs
def test_failed_npz_write_leaves_no_file(tmp_path):
    result = run(HINF_CPP, "run", hc.scenario_path("paper_fig1"), "--npz", tmp_path / "run.npz",
                 limits={resource.RLIMIT_FSIZE: 256 << 10})
    error_message(result, "hinf-cpp", 2, r"run\.npz': File too large")
    assert list(tmp_path.iterdir()) == []


@needs_programs
def test_bad_plot_suffix_is_refused_before_anything_is_written(tmp_path):
    scenario = write(tmp_path, "doomed.toml", DOOMED_TEXT)
    result = run(HINF_CPP, "run", scenario, "--json", tmp_path / "a.json", "--csv", tmp_path / "a.csv",
                 "--plot", tmp_path / "a.xyz")
    error_message(result, "hinf-cpp", 2, r"a\.xyz.*\.png, \.pdf or \.svg")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["doomed.toml"]


def subcommand_cases():
    """(subcommand arguments with {scenario}, {file} (a plain file), {tmp}) -> message pattern."""
    bad = "{file}/out.json"
    return {
        "run --npz": (["run", "{scenario}", "--npz", "{file}/out.npz"], r"not a directory"),
        "run --plot .jpg": (["run", "{scenario}", "--plot", "{tmp}/xy.jpg"], r"\.png, \.pdf or \.svg"),
        "compare --json": (["compare", "{scenario}", "--json", bad], r"not a directory"),
        "compare --plot": (["compare", "{scenario}", "--plot", "{tmp}/paths"], r"\.png, \.pdf or \.svg"),
        "recovery --json": (["recovery", "--json", bad], r"not a directory"),
        "recovery --plot": (["recovery", "--plot", "{tmp}"], r"is a directory"),
        "report --out a file": (["report", "{scenario}", "--out", "{file}"], r"not a directory"),
        "report --out below a file": (["report", "{scenario}", "--out", "{file}/report"], r"not a directory"),
        "gamma-star --json": (["gamma-star", "{scenario}", "--json", bad], r"not a directory"),
        "certify --json": (["certify", "{scenario}", "--json", "{tmp}"], r"is a directory"),
        "sweep-gamma --plot": (["sweep-gamma", "{scenario}", "--plot", "{tmp}/sweep.txt"], r"\.png, \.pdf or \.svg"),
        "sweep-gamma --json": (["sweep-gamma", "{scenario}", "--json", bad], r"not a directory"),
        "paper --out a file": (["paper", "--out", "{file}"], r"not a directory"),
        "export-controller --out a file": (["export-controller", "{scenario}", "--out", "{file}"], r"not a directory"),
    }


@needs_programs
@pytest.mark.parametrize("case", list(subcommand_cases()))
def test_every_subcommand_checks_its_outputs_first(tmp_path, case):
    args, match = subcommand_cases()[case]
    scenario = write(tmp_path, "doomed.toml", DOOMED_TEXT)
    plain = write(tmp_path, "plain_file", "x")
    args = [a.format(scenario=scenario, file=plain, tmp=tmp_path) for a in args]
    result = run(HINF_CPP, *args)
    error_message(result, "hinf-cpp", 2, match)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["doomed.toml", "plain_file"]


@needs_programs
@pytest.mark.parametrize("args,match", [
    (["--json"], r"--json needs a file name"),
    (["--csv"], r"--csv needs a file name"),
    (["--bogus"], r"unknown option '--bogus'"),
    (["{scenario}", "{scenario}"], r"more than one scenario file"),
    ([], r"no scenario file given"),
], ids=["--json without a value", "--csv without a value", "unknown option", "two scenarios", "none"])
def test_hinf_sim_usage_errors(tmp_path, args, match):
    scenario = write(tmp_path, "doomed.toml", DOOMED_TEXT)
    result = run(HINF_SIM, *[a.format(scenario=scenario) for a in args])
    error_message(result, "hinf-sim", 2, match)


# ======================================================================================
# hinf-cpp's last resort: no exception type prints a traceback
# ======================================================================================

@pytest.mark.parametrize("exception,status,match", [
    (MemoryError(), 2, r"^not enough memory"),
    (OSError(errno.ENOSPC, "No space left on device", "/some/file"), 2, r"^'/some/file': No space left on device$"),
    (UnicodeDecodeError("utf-8", b"\xe9", 0, 1, "invalid continuation byte"), 2, r"utf-8"),
    (RecursionError("maximum recursion depth exceeded"), 1, r"^internal error: RecursionError: maximum recursion"),
    (TypeError("unsupported operand"), 1, r"^internal error: TypeError: unsupported operand"),
    (KeyError("x"), 1, r"^internal error: KeyError: 'x'"),
    (KeyboardInterrupt(), 130, r"^interrupted$"),
], ids=["MemoryError", "OSError", "UnicodeDecodeError", "RecursionError", "TypeError", "KeyError",
        "KeyboardInterrupt"])
def test_main_maps_every_exception_to_one_line(monkeypatch, capsys, exception, status, match):
    def handler(args):
        raise exception

    monkeypatch.setattr(cli, "cmd_certify", handler)
    assert cli.main(["certify", "any.toml"]) == status
    captured = capsys.readouterr()
    lines = captured.err.splitlines()
    assert len(lines) == 1, captured.err
    assert lines[0].startswith("hinf-cpp: error: ")
    assert re.search(match, lines[0][len("hinf-cpp: error: "):]), lines[0]


def test_main_prints_no_warning_before_an_error(monkeypatch, capsys):
    def handler(args):
        warnings.warn("invalid value encountered in multiply", RuntimeWarning)
        raise ValueError("[controller] Q: expected a finite number, got inf")

    monkeypatch.setattr(cli, "cmd_certify", handler)
    assert cli.main(["certify", "any.toml"]) == 2
    assert capsys.readouterr().err == "hinf-cpp: error: [controller] Q: expected a finite number, got inf\n"


def test_main_shows_the_warnings_of_a_successful_command(monkeypatch, capsys):
    def handler(args):
        warnings.warn("something\nto know", UserWarning)
        print("the output")
        return 0

    monkeypatch.setattr(cli, "cmd_certify", handler)
    assert cli.main(["certify", "any.toml"]) == 0
    captured = capsys.readouterr()
    assert captured.out == "the output\n"
    assert captured.err == "hinf-cpp: warning: something to know\n"  # after the command, one line


# ======================================================================================
# The Python writers: whole files or none
# ======================================================================================

@pytest.mark.parametrize("suffix", ["png", "pdf", "svg"])
def test_failing_figure_keeps_the_old_file(tmp_path, suffix):
    import matplotlib.pyplot as plt

    from hinf_cpp.output.plotting import save_figure

    target = write(tmp_path, f"xy.{suffix}", "old contents")
    fig, ax = plt.subplots()
    ax.set_title(r"$\frac{$")  # mathtext that fails while drawing (PDF and SVG: after the file was opened)
    try:
        with pytest.raises(ValueError):
            save_figure(fig, target)
    finally:
        plt.close(fig)
    assert target.read_text() == "old contents"
    assert [p.name for p in tmp_path.iterdir()] == [f"xy.{suffix}"]


def test_failed_replace_keeps_the_old_file(tmp_path, monkeypatch, paper_run):
    from hinf_cpp.output import export

    target = write(tmp_path, "run.json", "old contents")

    def refuse(src, dst):
        raise OSError(errno.EXDEV, "Invalid cross-device link")

    monkeypatch.setattr(os, "replace", refuse)
    with pytest.raises(OSError, match="run.json"):
        export.save_json(paper_run, target)
    assert target.read_text() == "old contents"
    assert [p.name for p in tmp_path.iterdir()] == ["run.json"]


def test_written_files_have_the_usual_permissions(tmp_path, paper_run):
    from hinf_cpp.output import export

    umask = os.umask(0o022)
    os.umask(umask)
    path = export.save_json(paper_run, tmp_path / "sub" / "run.json")
    assert path.stat().st_mode & 0o777 == 0o666 & ~umask


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
