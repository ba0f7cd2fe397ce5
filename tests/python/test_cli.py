"""The two command lines: hinf-sim (C++ only) and hinf-cpp run (Python), on the same files."""

from __future__ import annotations

import csv
import json
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import hinf_cpp as hc
from _support import ROUNDOFF, numbers_close

BIN = pathlib.Path(sys.executable).parent
HINF_SIM = BIN / "hinf-sim"
HINF_CPP = BIN / "hinf-cpp"
PAPER_TEXT = pathlib.Path(hc.scenario_path("paper_fig1")).read_text()
DATA = pathlib.Path(__file__).resolve().parents[1] / "data"

pytestmark = pytest.mark.skipif(not (HINF_SIM.exists() and HINF_CPP.exists()),
                                reason="hinf-sim / hinf-cpp are not installed next to this Python")


def run(*args, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=120, cwd=cwd)


@pytest.fixture(scope="module")
def warm_python_cli():
    """Import the Python CLI once (matplotlib may build its font cache on a first import and
    say so on stderr; that is not the CLI's output)."""
    subprocess.run([sys.executable, "-c", "import hinf_cpp.cli"], capture_output=True, timeout=300)


@pytest.fixture(scope="module")
def paper_outputs(tmp_path_factory, warm_python_cli):
    """Both programs on the shipped paper_fig1.toml, with every output they can write."""
    out = tmp_path_factory.mktemp("cli")
    scenario = hc.scenario_path("paper_fig1")
    sim = run(HINF_SIM, scenario, "--json", out / "sim.json", "--csv", out / "sim.csv")
    cpp = run(HINF_CPP, "run", scenario, "--json", out / "cpp.json", "--csv", out / "cpp.csv",
              "--plot", out / "xy.png")
    return out, sim, cpp


def test_both_programs_succeed(paper_outputs):
    _, sim, cpp = paper_outputs
    assert sim.returncode == 0, sim.stderr
    assert cpp.returncode == 0, cpp.stderr
    assert sim.stderr == "" and cpp.stderr == ""


def test_same_results_file(paper_outputs):
    out, _, _ = paper_outputs
    a = json.loads((out / "sim.json").read_text())
    b = json.loads((out / "cpp.json").read_text())
    numbers_close(a, b)
    # The contract of scenarios.md.
    for key in ("scenario", "gamma", "Z0", "Z_min_eig", "Z_max_eig", "gamma_star", "metrics", "timing_s"):
        assert key in a, key
    assert a["scenario"] == "paper-fig1" and a["gamma"] == 5.0 and a["gamma_star"] is None
    assert np.array(a["Z0"]).shape == (6, 6)
    for key in ("rms_position_error_last_half", "max_position_error", "final_position_error", "control_l2",
                "control_error_l2", "disturbance_l2", "response_ratio", "max_rho_sigma_z",
                "rms_estimation_error_last_half"):
        assert key in a["metrics"], key
    assert a["metrics"]["max_rho_sigma_z"] is None  # NaN (not applicable) is written as null
    for key in ("design", "simulate", "total"):
        assert a["timing_s"][key] >= 0.0
    # Independent closed form: 3 channels of 0.1 cos(2 pi 0.2 t) over 8 whole periods.
    assert a["metrics"]["disturbance_l2"] == pytest.approx(math.sqrt(0.6), rel=1e-10)
    assert a["metrics"]["max_position_error"] == pytest.approx(math.sqrt(2.0), rel=ROUNDOFF)  # hypot(-1, -1)


def test_sampled_loop_same_results_file(tmp_path, warm_python_cli):
    # [sampling]: both programs run the online controller in the same loop; their results files
    # are equal but for the wall-clock times.
    scenario = hc.scenario_path("paper_fig2_sampled")
    sim = run(HINF_SIM, scenario, "--json", tmp_path / "sim.json")
    cpp = run(HINF_CPP, "run", scenario, "--json", tmp_path / "cpp.json")
    assert sim.returncode == 0 and cpp.returncode == 0, sim.stderr + cpp.stderr
    a, b = (json.loads((tmp_path / name).read_text()) for name in ("sim.json", "cpp.json"))
    a.pop("timing_s"), b.pop("timing_s")
    assert a == b
    assert a["sampling"] == {"period": 0.05, "design": "emulated", "delay": 0.02, "compensate_delay": True,
                             "measurement_period": 0.05, "measurement_update": "sampled"}
    online = a["online"]
    assert online["steps"] == 800 and online["measurements_used"] == 800 and online["lost"] == 0
    assert online["largest_command"] <= 3.0 and 0.0 < online["largest_rho_over_gamma2"] < 1.0


def test_csv_time_series(paper_outputs):
    out, _, _ = paper_outputs
    with open(out / "sim.csv", newline="") as f:
        rows = list(csv.reader(f))
    names = ["u", "v", "r", "x", "y", "psi"]
    header = (["t"] + names + [n + "_d" for n in names] + ["u1", "u2", "u1_d", "u2_d"]
              + [f"w{i}" for i in range(1, 7)])
    assert rows[0] == header
    grid = hc._core.output_grid(0.0, 40.0, 0.01)
    assert len(grid) == 4001
    data = np.array(rows[1:], dtype=float)
    assert data.shape == (len(grid), len(header))
    np.testing.assert_allclose(data[:, 0], grid, rtol=0, atol=ROUNDOFF * 40.0)  # printed with 17 digits
    np.testing.assert_array_equal(data[0, 1:7], [1.0, 0.0, 0.0, -1.0, -1.0, math.pi / 4])
    # u1_d = 1, u2_d = 0.3 sin(0.2 t), w1 = 0.1 cos(2 pi 0.2 t)
    np.testing.assert_allclose(data[:, header.index("u1_d")], 1.0, rtol=0, atol=0)
    # (the library's sin/cos against NumPy's: round-off of the amplitudes)
    np.testing.assert_allclose(data[:, header.index("u2_d")], 0.3 * np.sin(0.2 * data[:, 0]), rtol=0,
                               atol=ROUNDOFF * 0.3)
    np.testing.assert_allclose(data[:, header.index("w1")], 0.1 * np.cos(2 * np.pi * 0.2 * data[:, 0]),
                               rtol=0, atol=ROUNDOFF * 0.1)
    # Both programs write the same CSV (same run, printed with 17 digits).
    with open(out / "cpp.csv", newline="") as f:
        cpp_rows = list(csv.reader(f))
    assert cpp_rows[0] == header
    cpp = np.array(cpp_rows[1:], dtype=float)
    np.testing.assert_allclose(cpp, data, rtol=1e-9, atol=1e-15)


def test_plot_is_a_png(paper_outputs):
    out, _, _ = paper_outputs
    png = (out / "xy.png").read_bytes()
    assert len(png) > 1000
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("program", ["hinf-sim", "hinf-cpp"])
def test_bad_scenario_exit_status_2(program, warm_python_cli):
    path = DATA / "bad_unknown_key.toml"
    args = [HINF_SIM, path] if program == "hinf-sim" else [HINF_CPP, "run", path]
    result = run(*args)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    assert "gama" in lines[0] and program in lines[0]
    assert result.stdout == ""


@pytest.mark.parametrize("program", ["hinf-sim", "hinf-cpp"])
def test_semantic_error_exit_status_2(tmp_path, program, warm_python_cli):
    path = tmp_path / "bad_gamma.toml"
    path.write_text(PAPER_TEXT.replace("gamma = 5.0", "gamma = -1.0"))
    args = [HINF_SIM, path] if program == "hinf-sim" else [HINF_CPP, "run", path]
    result = run(*args)
    assert result.returncode == 2
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "gamma" in lines[0], result.stderr


@pytest.mark.parametrize("program", ["hinf-sim", "hinf-cpp"])
def test_conjugate_point_exit_status_3(tmp_path, program, warm_python_cli):
    assert "gamma = 5.0" in PAPER_TEXT
    path = tmp_path / "gamma1.toml"
    path.write_text(PAPER_TEXT.replace("gamma = 5.0", "gamma = 1.0"))
    out = tmp_path / "never.json"
    args = [HINF_SIM, path, "--json", out] if program == "hinf-sim" else [HINF_CPP, "run", path, "--json", out]
    result = run(*args)
    assert result.returncode == 3, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "conjugate point" in lines[0], result.stderr
    assert not out.exists()


def test_missing_file_exit_status_2(tmp_path, warm_python_cli):
    for args in ([HINF_SIM, tmp_path / "none.toml"], [HINF_CPP, "run", tmp_path / "none.toml"]):
        result = run(*args)
        assert result.returncode == 2
        assert len(result.stderr.splitlines()) == 1
