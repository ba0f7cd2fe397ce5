"""The study figures keep apart what a study varies (hinf_cpp.studies.report, docs/studies.md):
one band per value of the other grid axes in gamma.png, one box per grid point in
distribution.png with its n and failure share, metric axes labelled with their units, and
gamma = inf (the LQR limit) drawn and written everywhere."""

from __future__ import annotations

import io
import pathlib
import subprocess
import sys
import textwrap

import numpy as np
import pandas as pd
import pytest
from matplotlib.collections import PolyCollection

import hinf_cpp as hc
from hinf_cpp.studies import report
from hinf_cpp.studies import study as hs

FIG2 = pathlib.Path(hc.scenario_path("paper_fig2"))
HINF_CPP = pathlib.Path(sys.executable).parent / "hinf-cpp"
METRIC = "rms_position_error_last_half"


def write(folder: pathlib.Path, body: str) -> pathlib.Path:
    """A study file over a copy of paper_fig2.toml with a 5 s horizon (for speed) in `folder`."""
    (folder / "fig2.toml").write_text(FIG2.read_text().replace("tf = 40.0", "tf = 5.0"))
    path = folder / "study.toml"
    path.write_text(textwrap.dedent(body))
    return path


def load(folder: pathlib.Path, body: str) -> hs.Study:
    return hs.load_study(write(folder, body))


def capture_figures(monkeypatch) -> dict:
    """The figures write_study_outputs makes, by file name (still written to disk)."""
    figures = {}
    save = report._save

    def keep(fig, path):
        figures[pathlib.Path(path).name] = fig
        return save(fig, path)

    monkeypatch.setattr(report, "_save", keep)
    return figures


def drawn(figure):
    """The figure, after drawing it as a PNG (where an infinite position would fail)."""
    figure.savefig(io.BytesIO(), format="png")
    return figure


def bands(ax) -> list:
    return [c for c in ax.collections if isinstance(c, PolyCollection)]


def legend_texts(ax) -> list[str]:
    return [t.get_text() for t in ax.get_legend().get_texts()]


def tick_texts(ax) -> list[str]:
    return [t.get_text() for t in ax.get_xticklabels()]


@pytest.fixture(scope="module")
def sigma_study(tmp_path_factory):
    return load(tmp_path_factory.mktemp("sigma"), """\
        [study]
        name = "gamma_sigma"
        scenario = "fig2.toml"
        samples = 3
        [[grid]]
        key = "controller.gamma"
        values = [5.0, 10.0]
        [[grid]]
        key = "measurement.sigma"
        values = [0.1, 0.5]
        [[random]]
        key = "measurement.seed"
        distribution = "seed"
        """)


@pytest.fixture(scope="module")
def sigma_table(sigma_study):
    table = hs.run_study(sigma_study, workers=1, progress=False)
    assert (table["status"] == "completed").all()
    return table


def test_a_gamma_by_sigma_grid_gives_one_band_per_sigma(sigma_table):
    ax = report.gamma_figure(sigma_table, METRIC, other_columns=["measurement.sigma"]).axes[0]
    assert len(bands(ax)) == 2
    assert legend_texts(ax) == ["hinf/output, measurement.sigma = 0.1", "hinf/output, measurement.sigma = 0.5"]
    # Each line is the median of the samples at one grid point, not of the runs over both sigmas.
    for line, band, sigma in zip(ax.get_lines(), bands(ax), (0.1, 0.5)):
        at_point = sigma_table[sigma_table["measurement.sigma"] == sigma].groupby("controller.gamma")[METRIC]
        assert list(line.get_xdata()) == [5.0, 10.0]
        np.testing.assert_allclose(line.get_ydata(), at_point.median().to_numpy())
        # The band spans the 5-95 % of the samples at each grid point of its sigma.
        heights = band.get_paths()[0].vertices[:, 1]
        np.testing.assert_allclose([heights.min(), heights.max()],
                                   [at_point.quantile(0.05).min(), at_point.quantile(0.95).max()])
    # Without the other axes named, the sigmas are pooled into one band (the old figure).
    assert len(bands(report.gamma_figure(sigma_table, METRIC).axes[0])) == 1


def test_the_study_outputs_keep_the_other_axes_apart(sigma_study, sigma_table, tmp_path, monkeypatch):
    figures = capture_figures(monkeypatch)
    report.write_study_outputs(sigma_study, sigma_table, tmp_path)
    gamma_ax = figures["gamma.png"].axes[0]
    assert len(bands(gamma_ax)) == 2
    assert [t for t in legend_texts(gamma_ax) if "sigma" in t] == [
        "hinf/output, measurement.sigma = 0.1", "hinf/output, measurement.sigma = 0.5"]
    labels = tick_texts(figures["distribution.png"].axes[0])
    assert labels == [f"hinf/output\ncontroller.gamma = {g}\nmeasurement.sigma = {s}\nn = 3, failed 0 %"
                      for g in (5, 10) for s in (0.1, 0.5)]


def test_many_boxes_get_one_rotated_line_each_with_their_keys_below(sigma_table):
    # 8 boxes: the runs at gamma 5 again as gamma 20 and 40 (more than 6 boxes are not upright).
    at_5 = sigma_table[sigma_table["controller.gamma"] == 5.0]
    table = pd.concat([sigma_table, at_5.assign(**{"controller.gamma": 20.0}),
                       at_5.assign(**{"controller.gamma": 40.0})])
    ax = report.distribution_figure(table, METRIC, other_columns=["controller.gamma", "measurement.sigma"]).axes[0]
    assert len(ax.patches) == 8
    assert tick_texts(ax) == [f"hinf/output, {g}, {s}: n = 3, failed 0 %"
                              for g in (5, 10, 20, 40) for s in (0.1, 0.5)]
    assert ax.get_xticklabels()[0].get_rotation() == 45
    assert ax.get_xlabel().startswith("boxes: law/feedback, controller.gamma, measurement.sigma\n")


def test_hinf_at_two_gammas_gives_two_boxes_with_n_and_failure_share(tmp_path):
    # gamma = 4 is below the output-feedback bound (4.59): every run there fails at t0.
    study = load(tmp_path, """\
        [study]
        scenario = "fig2.toml"
        samples = 2
        [[grid]]
        key = "controller.gamma"
        values = [4.0, 20.0]
        [[random]]
        key = "measurement.seed"
        distribution = "seed"
        """)
    table = hs.run_study(study, workers=1, progress=False)
    assert list(table["status"]) == ["coupling_violation"] * 2 + ["completed"] * 2
    ax = report.distribution_figure(table, METRIC, other_columns=["controller.gamma"]).axes[0]
    assert len(ax.patches) == 2  # the boxes
    assert tick_texts(ax) == ["hinf/output\ncontroller.gamma = 4\nn = 0, failed 100 %",
                              "hinf/output\ncontroller.gamma = 20\nn = 2, failed 0 %"]
    pooled = report.distribution_figure(table, METRIC).axes[0]
    assert len(pooled.patches) == 1 and tick_texts(pooled) == ["hinf/output\nn = 2, failed 50 %"]


def test_a_gamma_inf_grid_finishes_with_every_output(tmp_path, monkeypatch):
    study = load(tmp_path, """\
        [study]
        name = "lqr_limit"
        scenario = "fig2.toml"
        [[grid]]
        key = "controller.gamma"
        values = [5.0, 10.0, inf]
        """)
    table = hs.run_study(study, workers=1, progress=False)
    figures = capture_figures(monkeypatch)
    written = report.write_study_outputs(study, table, tmp_path / "out")
    assert [p.name for p in written] == ["runs.parquet", "runs.csv", "summary.md", "distribution.png",
                                         "distribution.pdf", "gamma.png", "gamma.pdf"]
    assert all(p.stat().st_size > 0 for p in written)
    assert (tmp_path / "out" / "gamma.pdf").read_bytes().startswith(b"%PDF")
    ax = figures["gamma.png"].axes[0]
    assert tick_texts(ax) == ["5", "10", "inf"]
    assert list(ax.get_xticks()) == [5.0, 10.0, 15.0]  # one step of the grid right of 10
    assert ax.get_xlabel() == "gamma [-] (inf: the LQR limit)"
    assert list(ax.get_lines()[0].get_xdata()) == [5.0, 10.0, 15.0]
    assert "controller.gamma = inf" in tick_texts(figures["distribution.png"].axes[0])[-1]
    assert "| inf | 1 | 1 |" in (tmp_path / "out" / "summary.md").read_text()
    assert np.isposinf(pd.read_csv(tmp_path / "out" / "runs.csv")["controller.gamma"]).sum() == 1
    assert np.isposinf(pd.read_parquet(tmp_path / "out" / "runs.parquet")["controller.gamma"]).sum() == 1


@pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
def test_the_command_line_finishes_a_gamma_inf_study(tmp_path):
    path = write(tmp_path, """\
        [study]
        scenario = "fig2.toml"
        [[grid]]
        key = "controller.gamma"
        values = [5.0, inf]
        """)
    done = subprocess.run([str(HINF_CPP), "study", str(path), "--out", str(tmp_path / "out"), "--quiet"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert {"gamma.png", "distribution.png", "summary.md"} <= {p.name for p in (tmp_path / "out").iterdir()}


def test_a_refused_run_counts_as_failed_in_the_box_of_its_grid_point():
    """A run the reader refused has no law (status invalid_input): it belongs to its grid point's box."""
    table = pd.DataFrame({"controller.gamma": [5.0, 5.0, 5.0, 10.0], "law": ["hinf", "hinf", "", "hinf"],
                          "output_feedback": False, "status": ["completed", "completed", "invalid_input", "completed"],
                          METRIC: [0.1, 0.2, np.nan, 0.3]})
    ax = report.distribution_figure(table, METRIC, other_columns=["controller.gamma"]).axes[0]
    assert tick_texts(ax) == ["hinf/state\ncontroller.gamma = 5\nn = 2, failed 33 %",
                              "hinf/state\ncontroller.gamma = 10\nn = 1, failed 0 %"]


def synthetic_table(gammas) -> pd.DataFrame:
    """A table as run_study gives it, for the figures alone: one completed hinf run per gamma."""
    return pd.DataFrame({"controller.gamma": gammas, "law": "hinf", "output_feedback": False,
                         "status": "completed", METRIC: np.linspace(0.1, 0.2, len(gammas)),
                         "final_position_error": 0.1, "final_heading_error": 0.0,
                         "initial.q0[3]": 0.0, "initial.q0[5]": 0.0})


def test_gamma_inf_on_a_logarithmic_axis_sits_at_twice_the_largest_gamma():
    ax = drawn(report.gamma_figure(synthetic_table([2.0, 10.0, 100.0, np.inf]), METRIC)).axes[0]
    assert ax.get_xscale() == "log"
    assert tick_texts(ax) == ["2", "10", "100", "inf"] and ax.get_xticks()[-1] == 200.0
    assert ax.get_xlim()[1] > 200.0


def test_the_region_of_attraction_has_a_panel_per_gamma_including_inf():
    table = synthetic_table([5.0, np.inf])
    figure = drawn(report.roa_figure(table, "initial.q0[3]", "initial.q0[5]", other_columns=["controller.gamma"]))
    titles = [ax.get_title() for ax in figure.axes if ax.get_visible() and ax.get_title()]
    assert titles == ["hinf/state\ncontroller.gamma = 5", "hinf/state\ncontroller.gamma = inf"]
    # gamma on an axis of the map: inf gets a cell of its own right of the finite gammas.
    ax = drawn(report.roa_figure(table, "controller.gamma", "initial.q0[5]")).axes[0]
    assert tick_texts(ax) == ["5", "inf"] and list(ax.get_xticks()) == [5.0, 6.0]


def test_metric_axes_carry_their_units(sigma_table):
    distribution = report.distribution_figure(sigma_table, METRIC).axes[0]
    assert distribution.get_ylabel() == "RMS position error, last half [m]"
    # A dimensionless metric of hc.metric_table() (its name and label read there, not written here).
    ratio = next(d for d in hc.metric_table() if d.unit == "-")
    gamma = report.gamma_figure(sigma_table, ratio.name).axes[0]
    assert (gamma.get_ylabel(), gamma.get_xlabel()) == (f"{ratio.label} [-]", "gamma [-]")
    heading = report.gamma_figure(sigma_table, "rms_heading_error_last_half").axes[0]
    assert heading.get_ylabel() == "RMS heading error, last half [rad]"
    # A column that is not a metric of hc.metric_table() keeps its name.
    assert report.distribution_figure(sigma_table, "gamma").axes[0].get_ylabel() == "gamma"
