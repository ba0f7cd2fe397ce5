"""Statistics of a study's summary (hinf_cpp.studies.report, docs/studies.md): tables per grid axis
with percentile-bootstrap intervals, paired differences between the values of any grid axis with
the Wilcoxon signed-rank test and the rank-biserial correlation, a compact summary of a grid-only
study, the time of a resumed invocation, the heat map of a two-axis grid and the replay column."""

from __future__ import annotations

import io
import pathlib
import shlex
import textwrap

import numpy as np
import pandas as pd
import pytest

import hinf_cpp as hc
from hinf_cpp.studies import report
from hinf_cpp.studies import study as hs

stats = pytest.importorskip("scipy.stats")

FIG2 = pathlib.Path(hc.scenario_path("paper_fig2"))
METRIC = "rms_position_error_last_half"


def load(folder: pathlib.Path, body: str) -> hs.Study:
    """A study over a copy of paper_fig2.toml with a 5 s horizon (for speed)."""
    (folder / "fig2.toml").write_text(FIG2.read_text().replace("tf = 40.0", "tf = 5.0"))
    path = folder / "study.toml"
    path.write_text(textwrap.dedent(body))
    return hs.load_study(path)


@pytest.fixture(scope="module")
def law_sigma(tmp_path_factory):
    """hinf and lqr at two noise levels, 8 seeds each: 32 runs, two grid axes."""
    study = load(tmp_path_factory.mktemp("law_sigma"), """\
        [study]
        name = "law_sigma"
        scenario = "fig2.toml"
        seed = 7
        samples = 8
        [[grid]]
        key = "controller.law"
        values = ["hinf", "lqr"]
        [[grid]]
        key = "measurement.sigma"
        values = [0.1, 0.5]
        [[random]]
        key = "measurement.seed"
        distribution = "seed"
        [report]
        metrics = ["rms_position_error_last_half", "final_position_error"]
        """)
    table = hs.run_study(study, workers=1, progress=False)
    assert (table["status"] == "completed").all()
    return study, table


# ---- paired tests ----

@pytest.mark.parametrize("key, other, reference, value, comparison", [
    ("measurement.sigma", "controller.law", 0.1, 0.5, "0.5 - 0.1"),
    ("controller.law", "measurement.sigma", "hinf", "lqr", "lqr - hinf"),
])
def test_the_paired_test_of_any_axis_is_scipys_wilcoxon_on_the_runs_paired_by_sample(law_sigma, key, other,
                                                                                    reference, value, comparison):
    study, table = law_sigma
    for metric in ("rms_position_error_last_half", "final_position_error"):
        tests = report.paired_tests(table, study, key, metric)
        assert list(tests["comparison"]) == [comparison]
        # The pairs made here another way: a merge on the sample and the other axis's value.
        first = table[table[key] == reference][["sample", other, metric]]
        second = table[table[key] == value][["sample", other, metric]]
        pairs = second.merge(first, on=["sample", other], suffixes=("", "_reference"))
        d = (pairs[metric] - pairs[f"{metric}_reference"]).to_numpy(dtype=float)
        assert len(d) == 16 and tests["n"][0] == 16
        expected = stats.wilcoxon(d)
        # The same differences in another order: the rank sums are sums of whole and half
        # ranks (exact in doubles), so statistic and p-value agree to rounding.
        np.testing.assert_allclose(tests["statistic"][0], expected.statistic, rtol=0, atol=1e-9)
        np.testing.assert_allclose(tests["p_value"][0], expected.pvalue, rtol=1e-12)
        ranks = stats.rankdata(np.abs(d))
        plus, minus = ranks[d > 0].sum(), ranks[d < 0].sum()
        np.testing.assert_allclose(tests["rank_biserial"][0], (plus - minus) / (plus + minus), rtol=1e-12)
        np.testing.assert_allclose(tests["mean"][0], d.mean(), rtol=1e-12)
        np.testing.assert_allclose(tests["median"][0], np.median(d), rtol=1e-12)
        assert tests["lower"][0] == pytest.approx((d < 0).mean(), abs=0)
        assert tests["mean_low"][0] <= d.mean() <= tests["mean_high"][0]


def test_wilcoxon_and_rank_biserial_by_hand(tmp_path):
    """Differences 1, -2, 3, 4: ranks 1..4, T+ = 8, T- = 2: r = (8 - 2) / 10 = 0.6; W = 2 and the
    exact two-sided p = 2 P(T+ <= 2) = 2 x 3/16 (the subsets {}, {1}, {2} of the ranks)."""
    study = load(tmp_path, """\
        [study]
        scenario = "fig2.toml"
        samples = 4
        [[grid]]
        key = "controller.gamma"
        values = [5.0, 10.0]
        [[random]]
        key = "measurement.seed"
        distribution = "seed"
        """)
    table = pd.DataFrame({"run": range(8), "grid_point": [0] * 4 + [1] * 4, "sample": [0, 1, 2, 3] * 2,
                          "status": "completed", METRIC: [10.0, 10.0, 10.0, 10.0, 11.0, 8.0, 13.0, 14.0]})
    row = report.paired_tests(table, study, "controller.gamma", METRIC).iloc[0]
    assert row["comparison"] == "10 - 5" and row["n"] == 4
    assert row["rank_biserial"] == pytest.approx(0.6, abs=1e-15)
    assert row["statistic"] == 2.0 and row["p_value"] == pytest.approx(6 / 16, abs=1e-15)
    # A tie and a zero: the zero is left out, |1| and |-1| share rank 1.5, 2 has rank 3:
    # T+ = 4.5, T- = 1.5, r = 3 / 6.
    table[METRIC] = [10.0, 10.0, 10.0, 10.0, 10.0, 11.0, 9.0, 12.0]
    row = report.paired_tests(table, study, "controller.gamma", METRIC).iloc[0]
    assert row["rank_biserial"] == pytest.approx(0.5, abs=1e-15) and row["lower"] == 0.25
    # A run that did not complete has no pair.
    table.loc[5, "status"] = "diverged"
    assert report.paired_tests(table, study, "controller.gamma", METRIC)["n"][0] == 3
    with pytest.raises(ValueError, match="'controller.law' is not a grid key of the study"):
        report.paired_tests(table, study, "controller.law", METRIC)


# ---- bootstrap intervals and tables per grid axis ----

def test_bootstrap_intervals_contain_the_estimate_narrow_with_n_and_repeat():
    rng = np.random.default_rng(20261128)
    widths = {}
    for n in (50, 200, 800):
        values = rng.normal(3.0, 2.0, n)
        for statistic, centre in (("mean", values.mean()), ("median", np.median(values))):
            low, high = report.bootstrap_ci(values, statistic)
            assert low < centre < high
            widths[statistic, n] = high - low
        # The same interval every time (a fixed seed).
        assert report.bootstrap_ci(values) == report.bootstrap_ci(values)
    # The width falls as 1/sqrt(n): a factor 2 from 50 to 200 and from 200 to 800; asserted
    # with room for the spread of the estimates (their relative error is about 10 %).
    for statistic in ("mean", "median"):
        assert widths[statistic, 200] < 0.65 * widths[statistic, 50]
        assert widths[statistic, 800] < 0.65 * widths[statistic, 200]


def test_the_bootstrap_interval_of_a_mean_agrees_with_the_normal_one():
    """For 400 normal values the percentile interval is mean -+ 1.96 s / sqrt(n) up to the Monte
    Carlo error of its ends: with 2000 resamples about 0.06 standard errors each (sqrt(0.025 x
    0.975 / 2000) / phi(1.96)); asserted within 0.25 standard errors."""
    values = np.random.default_rng(3).normal(0.0, 1.0, 400)
    se = values.std() / np.sqrt(len(values))
    low, high = report.bootstrap_ci(values)
    assert abs(low - (values.mean() - 1.96 * se)) < 0.25 * se
    assert abs(high - (values.mean() + 1.96 * se)) < 0.25 * se
    assert report.bootstrap_ci([1.0, np.nan]) == pytest.approx((np.nan, np.nan), nan_ok=True)
    with pytest.raises(ValueError, match="statistic must be 'mean' or 'median'"):
        report.bootstrap_ci(values, "mode")


def test_a_table_per_grid_axis_pools_the_other_axes_and_the_samples(law_sigma):
    study, table = law_sigma
    for key in ("controller.law", "measurement.sigma"):
        pivot = report.axis_statistics(table, study, key, [METRIC])
        expected = table.groupby(key, sort=False)[METRIC]
        assert list(pivot[key]) == list(expected.mean().index)
        np.testing.assert_allclose(pivot["mean"], expected.mean().to_numpy(), rtol=1e-12)
        np.testing.assert_allclose(pivot["median"], expected.median().to_numpy(), rtol=1e-12)
        assert list(pivot["n"]) == [16, 16] and list(pivot["runs"]) == [16, 16]
        assert (pivot["mean_low"] < pivot["mean"]).all() and (pivot["mean"] < pivot["mean_high"]).all()
        assert (pivot["median_low"] <= pivot["median"]).all() and (pivot["median"] <= pivot["median_high"]).all()
    text = report.summary_markdown(table, study)
    assert "### RMS position error, last half [m] (`rms_position_error_last_half`) by measurement.sigma" in text
    assert "95 % percentile-bootstrap confidence interval (2000 resamples, seed 0)" in text
    assert "### final position error [m] (`final_position_error`): measurement.sigma" in text
    assert "| 0.5 - 0.1 | 16 |" in text and "| lqr - hinf | 16 |" in text


# ---- a grid-only study ----

def test_a_grid_only_study_is_summarized_per_axis_not_per_run(tmp_path):
    """6 x 7 grid points without samples: no table of 42 groups of one run, but the runs per
    status and the metrics per value of each axis (and the failed runs' replay commands)."""
    study = load(tmp_path, """\
        [study]
        scenario = "fig2.toml"
        [[grid]]
        key = "controller.gamma"
        values = [3.0, 5.0, 8.0, 10.0, 20.0, 50.0]
        [[grid]]
        key = "initial.q0[4]"
        values = [-4.0, -2.0, -1.0, 0.0, 1.0, 2.0, 4.0]
        [report]
        metrics = ["final_position_error"]
        """)
    table = hs.run_study(study, workers=2, progress=False)
    text = report.summary_markdown(table, study)
    lines = text.splitlines()
    assert len(lines) < 70, text
    assert "| n | mean | std |" not in text  # no statistics of groups of one run
    assert "## By grid axis" in text and "no confidence intervals" in text
    # gamma = 3 is below the output-feedback bound (4.59): its 7 runs fail at t0.
    assert "| 3 | 7 | 0 | 7 |" in text
    assert "run 0 (coupling_violation): hinf-cpp run " in text
    pivot = report.axis_statistics(table, study, "initial.q0[4]", ["final_position_error"])
    done = table[table["status"] == "completed"]
    np.testing.assert_allclose(pivot["max"], done.groupby("initial.q0[4]")["final_position_error"].max(), rtol=0)
    # A small grid lists its runs, one line each.
    small = load(tmp_path, """\
        [study]
        scenario = "fig2.toml"
        [[grid]]
        key = "controller.gamma"
        values = [5.0, 10.0]
        """)
    text = report.summary_markdown(hs.run_study(small, workers=1, progress=False), small)
    assert "## Runs\n" in text and "| n | mean | std |" not in text


# ---- time of a resumed invocation ----

def test_a_resumed_summary_states_the_runs_this_invocation_ran(law_sigma):
    study, table = law_sigma
    resumed = table.copy()
    resumed.attrs.update(reused_runs=24, reused_chunks=3)
    text = report.summary_markdown(resumed, study, seconds=2.0)
    assert "This invocation ran 8 of the 32 runs in 2.0 s (4 runs/s); the other 24 were reused from 3 chunks" in text
    assert "16 runs/s" not in text  # 32 runs / 2 s: the whole study as if this invocation ran it
    resumed.attrs.update(reused_runs=32, reused_chunks=4)
    assert "ran none of the runs: all 32 were reused" in report.summary_markdown(resumed, study, seconds=0.5)
    assert "Wall time 2.0 s (16 runs/s)." in report.summary_markdown(table, study, seconds=2.0)


def test_a_resumed_study_counts_the_runs_it_reused(law_sigma, tmp_path):
    study, table = law_sigma
    first = hs.run_study(study, workers=1, out=tmp_path, progress=False)
    assert first.attrs["reused_runs"] == 0
    for path in sorted((tmp_path / "partial").glob("chunk-*.parquet")):
        path.unlink()  # the only chunk (32 runs < chunk = 100)
        break
    resumed = hs.run_study(study, workers=1, out=tmp_path, progress=False)
    assert resumed.attrs["reused_runs"] == 0 and resumed.attrs["reused_chunks"] == 0
    again = hs.run_study(study, workers=1, out=tmp_path, progress=False)
    assert again.attrs["reused_runs"] == 32 and again.attrs["reused_chunks"] == 1
    pd.testing.assert_frame_equal(again, table, check_exact=True)


# ---- the heat map ----

def test_a_two_axis_grid_gets_a_heat_map_of_the_mean_per_cell(law_sigma, tmp_path, monkeypatch):
    study, table = law_sigma
    figures = {}
    save = report._save

    def keep(fig, path):
        figures[pathlib.Path(path).name] = fig
        return save(fig, path)

    monkeypatch.setattr(report, "_save", keep)
    written = [p.name for p in report.write_study_outputs(study, table, tmp_path)]
    assert {"heatmap.png", "heatmap.pdf", "distribution.png", "distribution.pdf"} <= set(written)
    assert (tmp_path / "heatmap.pdf").read_bytes().startswith(b"%PDF")
    ax, bar = figures["heatmap.png"].axes
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("controller.law", "measurement.sigma")
    assert bar.get_ylabel() == "mean RMS position error, last half [m]"
    assert [t.get_text() for t in ax.get_xticklabels()] == ["hinf", "lqr"]
    assert [t.get_text() for t in ax.get_yticklabels()] == ["0.1", "0.5"]
    cells = np.asarray(ax.collections[0].get_array()).reshape(2, 2)  # rows: sigma, columns: law
    expected = table.groupby(["measurement.sigma", "controller.law"], sort=False)[METRIC].mean()
    for i, sigma in enumerate((0.1, 0.5)):
        for j, law in enumerate(("hinf", "lqr")):
            assert cells[i, j] == pytest.approx(expected[sigma, law], rel=1e-12)


def test_heat_map_axes_carry_units_and_missing_cells_are_grey():
    table = pd.DataFrame({"controller.gamma": [5.0, 5.0, 10.0, 10.0, np.inf, np.inf],
                          "initial.q0[5]": [0.0, 1.0] * 3, "status": ["completed"] * 5 + ["diverged"],
                          METRIC: [0.1, 0.2, 0.3, 0.4, 0.5, np.nan]})
    figure = report.heatmap_figure(table, "controller.gamma", "initial.q0[5]", METRIC,
                                   state_names=["u", "v", "r", "x", "y", "psi"])
    ax = figure.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("gamma [-]", "psi(t0) [rad]  (initial.q0[5])")
    assert [t.get_text() for t in ax.get_xticklabels()] == ["5", "10", "inf"]
    missing = np.ma.getmaskarray(ax.collections[0].get_array()).reshape(2, 3)  # rows: psi(0), columns: gamma
    assert missing.tolist() == [[False, False, False], [False, False, True]]  # gamma = inf, psi(0) = 1 diverged
    figure.savefig(io.BytesIO(), format="png")


# ---- the replay column ----

def test_the_table_has_each_runs_replay_command(law_sigma):
    study, table = law_sigma
    assert list(table["replay"]) == [hs.replay_command(study, run) for run in range(study.runs)]
    command = shlex.split(table["replay"][9])
    assert command[:3] == ["hinf-cpp", "run", study.source] and command[-2] == "--seed"
    assert int(command[-1]) == table["seed"][9]


def test_failed_runs_are_listed_with_their_replay_commands():
    table = pd.DataFrame({"run": range(14), "status": ["completed"] * 2 + ["diverged"] * 12,
                          "replay": [f"hinf-cpp run a.toml --set controller.gamma={g}.0" for g in range(14)]})
    text = report.failed_runs_text(table)
    lines = text.splitlines()
    assert lines[0] == "run 2 (diverged): hinf-cpp run a.toml --set controller.gamma=2.0"
    assert len(lines) == 11 and lines[-1].startswith("... and 2 more runs that did not complete")
    assert report.failed_runs_text(table[table["status"] == "completed"]) == ""
