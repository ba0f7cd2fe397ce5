"""Figures (without a display), the report folder, the exports (NPZ, tidy CSV, JSON), the
progress line, and the command lines `report`, `run --npz` and `paper`.

Files are checked as files: the PNG signature and header, the PDF's lack of raster images,
the exports read back with NumPy / csv / json and compared with the run's own arrays.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import pathlib
import struct
import subprocess
import sys

import numpy as np
import pytest

import hinf_cpp as hc
from hinf_cpp.output import export
from hinf_cpp.output import plotting
from hinf_cpp.analysis.gamma_sweep import sweep_gamma
from hinf_cpp.analysis.comparison import compare, run_law
from hinf_cpp.output.progress import Progress
from hinf_cpp.analysis.report import write_report

HINF_CPP = pathlib.Path(sys.executable).parent / "hinf-cpp"
needs_cli = pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
SHORT_TF = 10.0   # short horizons keep the exports and figures quick


def png_size(path: pathlib.Path) -> tuple[int, int]:
    """(width, height) from a PNG file, after checking its signature and IHDR chunk."""
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE, f"{path} is not a PNG"
    assert data[12:16] == b"IHDR"
    return struct.unpack(">II", data[16:24])


def short(name: str, tf: float = SHORT_TF) -> hc.Scenario:
    s = hc.load_scenario(hc.scenario_path(name))
    s.tf = tf
    return s


def short_file(tmp_path: pathlib.Path, name: str, tf: float = SHORT_TF) -> pathlib.Path:
    text = pathlib.Path(hc.scenario_path(name)).read_text()
    assert "tf = 40.0" in text
    path = tmp_path / f"{name}_short.toml"
    path.write_text(text.replace("tf = 40.0", f"tf = {tf!r}"))
    return path


@pytest.fixture(scope="module")
def comparison():
    """The three laws on the first 10 s of Figure 2, both feedback modes."""
    return compare(short("paper_fig2"))


@pytest.fixture(scope="module")
def state_run():
    return run_law(short("paper_fig1"), "hinf")


@pytest.fixture(scope="module")
def output_run():
    return run_law(short("paper_fig2"), "hinf", "output")


# ---- figures -------------------------------------------------------------------------------------

FIGURES = {
    "paths": lambda c: plotting.paths_figure(c.results()),
    "errors": lambda c: plotting.errors_figure(c.results()),
    "controls": lambda c: plotting.controls_figure(c.results()),
    "eigenvalues": lambda c: plotting.eigenvalues_figure(c.results()),
    "coupling": lambda c: plotting.coupling_figure(c.results()),
    "xy": lambda c: plotting.xy_figure(c["hinf"].result, heading_arrows=4),
}


@pytest.mark.parametrize("name", sorted(FIGURES))
def test_figures_are_labelled_pngs(tmp_path, comparison, name):
    fig = FIGURES[name](comparison)
    axes = [ax for ax in fig.axes if ax.get_visible()]
    assert axes
    for ax in axes:
        # Every panel says what its axes are, with units in brackets; the bottom one carries x.
        assert "[" in ax.get_ylabel() and "]" in ax.get_ylabel(), (name, ax.get_ylabel())
    assert "[" in axes[-1].get_xlabel() and axes[-1].get_xlabel().endswith("]")
    assert axes[0].get_title()
    path = plotting.save_figure(fig, tmp_path / f"{name}.png")
    width, height = png_size(path)
    assert width >= 800 and height >= 500
    assert path.stat().st_size > 10_000


def test_pdf_figures_are_vector(tmp_path, comparison):
    path = plotting.save_figure(plotting.paths_figure(comparison.results()), tmp_path / "paths.pdf")
    data = path.read_bytes()
    assert data.startswith(b"%PDF-") and b"/Subtype /Image" not in data


def test_figures_need_no_display(tmp_path):
    """In a fresh interpreter without DISPLAY or MPLBACKEND: no pyplot, no GUI backend."""
    script = f"""
import sys, hinf_cpp as hc
from hinf_cpp.output import plotting
from hinf_cpp.analysis.comparison import compare
s = hc.load_scenario(hc.scenario_path("paper_fig2")); s.tf = 5.0
c = compare(s, "hinf,lqr")
for name, fig in [("p", plotting.paths_figure(c.results())), ("e", plotting.eigenvalues_figure(c.results())),
                  ("r", plotting.coupling_figure(c.results()))]:
    plotting.save_figure(fig, r"{tmp_path}/" + name + ".png")
gui = [m for m in sys.modules if m.startswith(("matplotlib.backends.backend_qt", "matplotlib.backends.backend_tk",
                                                 "matplotlib.backends.backend_gtk", "tkinter", "PyQt"))]
print("pyplot" if "matplotlib.pyplot" in sys.modules else "no-pyplot", len(gui))
"""
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY", "MPLBACKEND")}
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["no-pyplot", "0"]
    for name in "per":
        png_size(tmp_path / f"{name}.png")


def test_save_figure_rejects_unknown_formats(tmp_path, state_run):
    with pytest.raises(ValueError, match="image format"):
        plotting.save_figure(plotting.xy_figure(state_run), tmp_path / "xy.toml")


def test_coupling_figure_needs_measurements(state_run):
    with pytest.raises(ValueError, match="measurement"):
        plotting.coupling_figure(state_run)
    with pytest.raises(ValueError, match="no run"):
        plotting.errors_figure([])


def test_eigenvalue_figure_shows_z_and_sigma(comparison):
    """The plotted lines are the eigenvalues of Z(t) (numpy.linalg.eigvalsh, computed here) and
    the run's Sigma bounds; they stay within the library's continuous bounds m, M of eq. (22)."""
    fig = plotting.eigenvalues_figure(comparison.results())
    ax_z, ax_s = fig.axes
    hinf = comparison["hinf"].result
    t = hinf.simulation.t
    eig = np.linalg.eigvalsh(hinf.solution.Z(t))
    lines = {line.get_label(): line for line in ax_z.get_lines()}
    np.testing.assert_allclose(lines["lambda_max(Z), gamma = 5"].get_ydata(), eig[:, -1], rtol=1e-9)
    np.testing.assert_allclose(lines["lambda_min(Z), gamma = 5"].get_ydata(), eig[:, 0], rtol=1e-9)
    assert "lambda_max(Z), gamma = inf (LQR)" in lines
    assert hinf.Z_min_eig <= eig[:, 0].min() * (1 + 1e-6) and eig[:, -1].max() <= hinf.Z_max_eig * (1 + 1e-6)
    assert eig[:, -1].max() >= 0.99 * hinf.Z_max_eig
    sigma = {line.get_label(): line for line in ax_s.get_lines()}
    run = comparison["hinf/output-feedback"].result
    np.testing.assert_array_equal(sigma["lambda_max(Sigma), hinf/output-feedback"].get_ydata(),
                                  run.simulation.estimator.sigma_max_eig)
    coupling = plotting.coupling_figure(comparison.results())
    levels = [line.get_ydata()[0] for line in coupling.axes[0].get_lines() if "gamma^2" in line.get_label()]
    assert levels == [25.0]


def test_paths_figure_arrows_show_the_heading(tmp_path):
    """From a 180 degree heading error the first arrow of the actual path points opposite to the
    desired start arrow; arrows sit on the path."""
    result = run_law(short("poor_heading_180", 20.0), "hinf")
    fig = plotting.paths_figure([("hinf", result)], heading_arrows=4)
    quivers = [c for c in fig.axes[0].collections if c.__class__.__name__ == "Quiver"]
    desired, actual = quivers
    d = np.array([desired.U[0], desired.V[0]])
    a = np.array([actual.U[0], actual.V[0]])
    assert np.dot(d, a) / (np.linalg.norm(d) * np.linalg.norm(a)) == pytest.approx(-1.0, abs=1e-9)
    q = result.simulation.q
    for x, y in actual.XY:
        assert np.min(np.hypot(q[:, 3] - x, q[:, 4] - y)) < 1e-12
    assert len(actual.XY) == 4
    png_size(plotting.save_figure(fig, tmp_path / "arrows.png"))


def test_overlaid_runs_stay_distinguishable(comparison):
    """hinf and lqr nearly coincide on Figure 2 (RMS errors within 5%): every run has its own
    marker and line style (per law), the markers sparse (at most 15 per line, evenly spaced in
    time or arc length) and at other points for each run, so that they do not stack."""
    runs = comparison.results()
    for fig, axes in [(plotting.errors_figure(runs), 2), (plotting.controls_figure(runs), 2),
                      (plotting.paths_figure(runs), 1)]:
        for ax in fig.axes[:axes]:
            lines = [line for line in ax.get_lines() if line.get_label() in dict(runs)]
            assert [line.get_label() for line in lines] == [label for label, _ in runs]
            looks = {(line.get_color(), line.get_marker(), line.get_linestyle()) for line in lines}
            assert len(looks) == len(runs)
            state = [line for line in lines if "output" not in line.get_label()]
            assert len({(line.get_marker(), line.get_linestyle()) for line in state}) == len(state)
            every = [set(line.get_markevery()) for line in lines]
            assert all(10 <= len(e) <= 15 for e in every)
            if ax.get_xlabel() == "time t [s]":
                # One output grid for all: each run's markers at other times.
                assert all(not (a & b) for i, a in enumerate(every) for b in every[i + 1:])
    # On the paths, hinf's and lqr's markers (their paths coincide to centimetres) are apart by
    # at least a tenth of their spacing (they are shifted by a sixth of it in arc length).
    paths = {line.get_label(): line for line in plotting.paths_figure(runs).axes[0].get_lines()}

    def marks(label: str) -> np.ndarray:
        line = paths[label]
        every = line.get_markevery()
        return np.column_stack([line.get_xdata()[every], line.get_ydata()[every]])

    for a, b in [("hinf", "lqr"), ("hinf/output-feedback", "lqr/output-feedback")]:
        pa, pb = marks(a), marks(b)
        spacing = np.mean(np.hypot(*np.diff(pa, axis=0).T))
        gaps = np.hypot(pa[:, None, 0] - pb[None, :, 0], pa[:, None, 1] - pb[None, :, 1])
        assert gaps.min() > 0.1 * spacing, (a, b, gaps.min(), spacing)
    fig = plotting.errors_figure(runs)
    markers = {line.get_label(): line.get_marker() for line in fig.axes[0].get_lines()}
    assert (markers["hinf"], markers["lqr"], markers["cascade"]) == ("o", "s", "^")


def data_box(h: np.ndarray, v: np.ndarray, margin: float = 0.06):
    """The limits an x-y panel should have: the data's box widened by 6% of its larger side."""
    pad = margin * max(np.ptp(h), np.ptp(v))
    return (h.min() - pad, h.max() + pad), (v.min() - pad, v.max() + pad)


@pytest.mark.parametrize("marine", [False, True])
def test_xy_panels_are_sized_to_their_data(tmp_path, marine):
    """Limits from the data with a margin (hand computation), equal scale, and the axes box in
    the data's shape: its on-screen aspect is the data's, so it is not padded with empty space,
    and it covers at least 40% of the figure. Marine: y (East) right, x (North) up, the heading
    arrows along (sin psi, cos psi)."""
    result = run_law(short("paper_fig1", 40.0), "hinf")
    q, q_d = result.simulation.q, result.simulation.q_d
    h, v = (4, 3) if marine else (3, 4)
    for fig in (plotting.xy_figure(result, heading_arrows=5, marine=marine),
                plotting.paths_figure([("hinf", result)], heading_arrows=5, marine=marine)):
        ax = fig.axes[0]
        xlim, ylim = data_box(np.concatenate([q[:, h], q_d[:, h]]), np.concatenate([q[:, v], q_d[:, v]]))
        # Limits: the hand-computed box to round-off of the sums (1e-12 m on 20 m).
        assert ax.get_xlim() == pytest.approx(xlim, abs=1e-12)
        assert ax.get_ylim() == pytest.approx(ylim, abs=1e-12)
        assert ax.get_aspect() == 1.0 and ax.get_adjustable() == "box"
        fig.draw_without_rendering()   # the layout and the equal aspect applied, as when saved
        box = ax.get_window_extent()
        # The box's on-screen aspect is the data's, to a pixel of rounding (0.5% of ~800 px).
        assert box.width / box.height == pytest.approx((xlim[1] - xlim[0]) / (ylim[1] - ylim[0]), rel=5e-3)
        position = ax.get_position()
        assert position.width * position.height > 0.4
        actual = [line for line in ax.get_lines() if line.get_label() in ("actual", "hinf")]
        np.testing.assert_array_equal(actual[0].get_xdata(), q[:, h])
        np.testing.assert_array_equal(actual[0].get_ydata(), q[:, v])
        assert ax.get_xlabel() == ("East y [m]" if marine else "x [m]")
        assert ax.get_ylabel() == ("North x [m]" if marine else "y [m]")
        quiver = [c for c in ax.collections if c.__class__.__name__ == "Quiver"][-1]
        psi0 = q[0, 5]
        direction = (math.sin(psi0), math.cos(psi0)) if marine else (math.cos(psi0), math.sin(psi0))
        first = np.array([quiver.U[0], quiver.V[0]])
        np.testing.assert_allclose(first / np.linalg.norm(first), direction, atol=1e-12)
        png_size(plotting.save_figure(fig, tmp_path / f"xy_{marine}.png"))


def test_a_straight_path_is_not_a_strip():
    """Along a straight line (u_d = [1, 0], started on it; the disturbance moves it by
    centimetres) the shorter side of the panel is still a fifth of the longer: (0.2 + 2 * 0.06)
    / (1 + 2 * 0.06) of it with the margins."""
    s = short("paper_fig1", 10.0)
    s.desired_u = [1.0, 0.0]
    s.initial_q0 = s.desired_q0
    result = run_law(s, "hinf")
    ax = plotting.xy_figure(result).axes[0]
    width = ax.get_xlim()[1] - ax.get_xlim()[0]
    height = ax.get_ylim()[1] - ax.get_ylim()[0]
    assert height / width == pytest.approx((0.2 + 2 * 0.06) / (1 + 2 * 0.06), rel=0.05)


# ---- exports ---------------------------------------------------------------------------------------

def test_npz_round_trip_is_exact(tmp_path, output_run):
    path = export.save_npz(output_run, tmp_path / "run.npz")
    data = export.load_npz(path)
    series = export.time_series(output_run)
    assert set(data.arrays) == set(series) | {"Z"}
    for name, values in series.items():
        assert data[name].dtype == np.float64
        np.testing.assert_array_equal(data[name], values)
    sim = output_run.simulation
    np.testing.assert_array_equal(data["q"], sim.q)
    np.testing.assert_array_equal(data["q_hat"], sim.estimator.q_hat)
    np.testing.assert_array_equal(data["rho_sigma_z"], sim.estimator.rho_sigma_z)
    np.testing.assert_array_equal(data["Z"], output_run.solution.Z(sim.t))
    assert data.meta["results"] == json.loads(hc._core.results_json(output_run))
    assert data.meta["components"]["y"] == ["x", "y", "psi"]
    assert data.meta["state_names"] == ["u", "v", "r", "x", "y", "psi"]
    # Plain NumPy reads it without pickle.
    with np.load(path, allow_pickle=False) as raw:
        assert json.loads(str(raw["meta"]))["format"] == export.FORMAT


def test_tidy_csv_round_trip(tmp_path, output_run, state_run):
    exact = export.save_csv(output_run, tmp_path / "exact.csv")
    rounded = export.save_csv(output_run, tmp_path / "six.csv", digits=6)
    series = export.time_series(output_run)
    back = export.load_csv(exact)
    assert set(back.arrays) == set(series)
    for name, values in series.items():
        np.testing.assert_array_equal(back[name], values)   # repr: the exact doubles
    six = export.load_csv(rounded)
    for name, values in series.items():
        np.testing.assert_allclose(six[name], values, rtol=5e-6, atol=0)
    # Long format, read with the csv module: header, variable names, one row per time and variable.
    with exact.open(newline="") as handle:
        rows = list(csv.reader(handle))
    assert rows[0] == ["t", "variable", "value"]
    k = output_run.simulation.t.size
    assert k == 1001
    count = sum(1 if v.ndim == 1 else v.shape[1] for n, v in series.items() if n != "t")
    assert len(rows) == 1 + count * k
    first = {r[1]: float(r[2]) for r in rows[1:] if float(r[0]) == 0.0}
    assert first["q.x"] == -1.0 and first["q.psi"] == pytest.approx(math.pi / 4, abs=0)
    assert first["q_hat.x"] == 0.0 and "y.psi" in first and "w.w4" in first and "sigma_max_eig" in first
    assert back.meta["components"]["u"] == ["u1", "u2"]
    # A state-feedback run has no estimator series.
    plain = export.load_csv(export.save_csv(state_run, tmp_path / "state.csv"))
    assert "q_hat" not in plain.arrays and "rho_sigma_z" not in plain.arrays
    np.testing.assert_array_equal(plain["u"], state_run.simulation.u)


def test_json_results_file_round_trip(tmp_path, state_run):
    path = export.save_json(state_run, tmp_path / "run.json")
    data = export.load_json(path)
    assert data == json.loads(hc._core.results_json(state_run))
    assert data["metrics"]["final_position_error"] == pytest.approx(state_run.metrics.final_position_error,
                                                                    rel=1e-15)


def test_export_rejects_bad_input(tmp_path, state_run):
    with pytest.raises(ValueError, match="digits"):
        export.save_csv(state_run, tmp_path / "x.csv", digits=0)
    bad = tmp_path / "bad.csv"
    bad.write_text("a,b\n1,2\n")
    with pytest.raises(ValueError, match="header"):
        export.load_csv(bad)
    np.savez(tmp_path / "other.npz", x=np.zeros(3))
    with pytest.raises(ValueError, match="not a hinf_cpp run export"):
        export.load_npz(tmp_path / "other.npz")
    (tmp_path / "bad.json").write_text("{")
    with pytest.raises(ValueError, match="invalid JSON"):
        export.load_json(tmp_path / "bad.json")


# ---- report ----------------------------------------------------------------------------------------

def test_write_report_state_feedback(tmp_path):
    calls = []
    report = write_report(short("paper_fig1"), tmp_path / "rep", "hinf,cascade",
                          progress=lambda i, n, m: calls.append((i, n, m)))
    names = {p.name for p in report.files}
    assert {"report.md", "metrics.md", "metrics.csv", "comparison.json", "paths.png", "errors.png",
            "controls.png", "eigenvalues.png", "hinf.json", "hinf.npz", "hinf.csv", "cascade.npz"} <= names
    assert "coupling.png" not in names          # no [measurement]
    assert all(p.exists() and p.stat().st_size > 0 for p in report.files)
    for p in report.files:
        if p.suffix == ".png":
            png_size(p)
    assert calls[:2] == [(1, 2, "running hinf on paper-fig1"), (2, 2, "running cascade on paper-fig1")]
    assert any("drawing paths.png" in m for _, _, m in calls)
    # metrics.csv holds the numbers of comparison.json, by metric key.
    data = json.loads((tmp_path / "rep" / "comparison.json").read_text())
    with (tmp_path / "rep" / "metrics.csv").open(newline="") as handle:
        rows = list(csv.DictReader(handle))
    for row in rows:
        for key in ("hinf", "cascade"):
            value = data["controllers"][key][row["metric"]]
            # A metric that does not apply (the cascade law's induced_l2_gain) is empty in the
            # CSV and null in the JSON.
            assert (row[key] == "" and value is None) or float(row[key]) == value
    text = (tmp_path / "rep" / "report.md").read_text()
    assert "](paths.png)" in text and "| metric | unit | hinf | cascade |" in text


def test_write_report_with_vector_figures(tmp_path):
    report = write_report(short("paper_fig1"), tmp_path / "rep", "hinf", pdf=True)
    pngs = sorted(p.stem for p in report.files if p.suffix == ".png")
    pdfs = sorted(p for p in report.files if p.suffix == ".pdf")
    assert pngs and [p.stem for p in pdfs] == pngs
    for p in pdfs:
        assert p.read_bytes()[:5] == b"%PDF-" and p.stat().st_size > 1000


@needs_cli
def test_cli_report(tmp_path):
    out = tmp_path / "report"
    r = subprocess.run([str(HINF_CPP), "report", str(short_file(tmp_path, "paper_fig2")), "--out", str(out),
                        "--controllers", "hinf,lqr"], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    assert f"wrote the report to {out}/" in r.stdout
    expected = {"report.md", "metrics.md", "metrics.csv", "comparison.json", "paths.png", "errors.png",
                "controls.png", "eigenvalues.png", "coupling.png"}
    for key in ("hinf", "lqr", "hinf-output-feedback", "lqr-output-feedback"):
        expected |= {f"{key}.json", f"{key}.npz", f"{key}.csv"}
    assert {p.name for p in out.iterdir()} == expected
    for name in expected:
        if name.endswith(".png"):
            png_size(out / name)
    data = json.loads((out / "comparison.json").read_text())
    assert list(data["controllers"]) == ["hinf", "lqr", "hinf/output-feedback", "lqr/output-feedback"]
    run = export.load_npz(out / "lqr-output-feedback.npz")
    assert run.meta["results"]["controller"] == "lqr-output-feedback"
    assert run.meta["results"]["metrics"]["final_position_error"] == \
        data["controllers"]["lqr/output-feedback"]["final_position_error"]


@needs_cli
def test_cli_run_npz(tmp_path):
    path = short_file(tmp_path, "paper_fig2")
    r = subprocess.run([str(HINF_CPP), "run", str(path), "--npz", str(tmp_path / "r.npz"), "--json",
                        str(tmp_path / "r.json")], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    data = export.load_npz(tmp_path / "r.npz")
    results = json.loads((tmp_path / "r.json").read_text())
    results.pop("timing_s")
    data.meta["results"].pop("timing_s")
    assert data.meta["results"] == results
    assert data["t"].shape == (1001,) and data["q_hat"].shape == (1001, 6) and data["y"].shape == (1001, 3)


@needs_cli
def test_cli_paper_writes_the_comparison(tmp_path):
    out = tmp_path / "paper"
    r = subprocess.run([str(HINF_CPP), "paper", "--out", str(out)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    assert r.stdout.rstrip().splitlines()[-1] == f"output folder: {out.resolve()}"
    names = {p.name for p in out.iterdir()}
    assert {"fig1_xy.png", "fig2_xy.png", "fig1.json", "fig2.json", "metrics.md", "comparison.md",
            "comparison_fig1_paths.png", "comparison_fig2_paths.png", "comparison_fig1.json",
            "comparison_fig2.json", "comparison_fig1_errors.png", "comparison_fig2_errors.png",
            "comparison_fig1_controls.png", "comparison_fig2_controls.png"} <= names
    for name in names:
        if name.endswith(".png"):
            png_size(out / name)
    text = (out / "comparison.md").read_text()
    for stem in ("fig1", "fig2"):
        for kind in ("paths", "errors", "controls"):
            assert f"](comparison_{stem}_{kind}.png)" in text
    assert "| metric | unit | hinf | lqr | cascade |" in text
    assert "| metric | unit | hinf/output-feedback | lqr/output-feedback | cascade/output-feedback |" in text
    fig2 = json.loads((out / "comparison_fig2.json").read_text())
    assert all(v["feedback"] == "output" for v in fig2["controllers"].values())
    # metrics.md leads with the disturbance's own gain (Figure 1 starts off the path, so it is
    # that of the same run from the desired start: the comparison's hinf entry, the same run).
    rows = {line.split("|")[1].strip(): line.split("|")[2:-1] for line in (out / "metrics.md").read_text().splitlines()}
    assert list(rows)[2:4] == ["gamma", "disturbance_gain (from the desired start)"]
    fig1 = json.loads((out / "comparison_fig1.json").read_text())
    gain = float(rows["disturbance_gain (from the desired start)"][0])
    assert gain == pytest.approx(fig1["controllers"]["hinf"]["disturbance_gain"], rel=1e-5)  # 6 digits
    assert gain < 5.0 < float(rows["response_ratio"][0]) * 2  # below gamma; the ratio with the start is not


# ---- progress ----------------------------------------------------------------------------------------

class FakeTerminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_progress_line_on_a_terminal_only():
    scenario = short("paper_fig1", 5.0)
    terminal = FakeTerminal()
    with Progress(stream=terminal) as progress:
        compare(scenario, progress=progress)
    text = terminal.getvalue()
    assert "\r[1/4] running hinf on paper-fig1 ..." in text and "[4/4] running backstepping on paper-fig1 ..." in text
    assert text.endswith("\r") and text.split("\r")[-2].strip() == ""   # the line is erased at the end
    quiet = FakeTerminal()
    with Progress(quiet=True, stream=quiet) as progress:
        compare(scenario, "hinf", progress=progress)
    assert quiet.getvalue() == ""
    pipe = io.StringIO()   # not a terminal
    with Progress(stream=pipe) as progress:
        compare(scenario, "hinf", progress=progress)
    assert pipe.getvalue() == ""


def test_sweep_gamma_reports_progress():
    scenario = short("paper_fig1", 5.0)
    calls = []
    sweep = sweep_gamma(scenario, count=3, threads=2, progress=lambda i, n, m: calls.append((i, n, m)))
    assert sorted(i for i, _, _ in calls) == [1, 2, 3] and {n for _, n, _ in calls} == {3}
    assert all(m.startswith("running paper-fig1 at gamma = ") for _, _, m in calls)
    assert sweep.gammas.size == 3


@needs_cli
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="uses a pseudo-terminal")
@pytest.mark.parametrize("quiet", [False, True])
def test_cli_progress_on_a_pseudo_terminal(tmp_path, quiet):
    import pty

    master, slave = pty.openpty()
    args = [str(HINF_CPP), "compare", str(short_file(tmp_path, "paper_fig1", 5.0))] + (["--quiet"] if quiet else [])
    process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=slave)
    os.close(slave)
    stdout, _ = process.communicate(timeout=120)
    chunks = []
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(master)
    stderr = b"".join(chunks).decode()
    assert process.returncode == 0, stderr
    assert b"RMS position error" in stdout
    if quiet:
        assert stderr == ""
    else:
        assert "[1/4] running hinf on paper-fig1 ..." in stderr and "[4/4] running backstepping" in stderr
