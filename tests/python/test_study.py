"""Studies (hinf_cpp.studies.study, docs/studies.md): expansion and seeds, the same table whatever the
executor (1 or 2 local threads, a Dask cluster of 2 processes), replay of one row (Python and
the command line), failures as rows, interrupt and resume, outputs, the CLI's errors."""

from __future__ import annotations

import json
import pathlib
import pickle
import socket
import stat
import subprocess
import sys
import textwrap

import numpy as np
import pandas as pd
import pandas.testing as pdt
import pytest

import hinf_cpp as hc
from hinf_cpp.scenario.settings import parse_setting
from hinf_cpp.studies import study as hs
from hinf_cpp.studies.report import paired_differences, status_counts, summarize, summary_markdown, write_study_outputs

BIN = pathlib.Path(sys.executable).parent
HINF_CPP = BIN / "hinf-cpp"
FIG2 = pathlib.Path(hc.scenario_path("paper_fig2"))
METRICS = [d.name for d in hc.metric_table()]


def write_study(folder: pathlib.Path, body: str, name: str = "study.toml") -> pathlib.Path:
    """A study file over a copy of paper_fig2.toml (short horizon, for speed) in `folder`."""
    scenario = FIG2.read_text().replace("tf = 40.0", "tf = 8.0")
    (folder / "fig2.toml").write_text(scenario)
    path = folder / name
    path.write_text(textwrap.dedent(body))
    return path


MONTE_CARLO = """\
[study]
name = "mc"
scenario = "fig2.toml"
seed = 20261124
samples = 4
chunk = 5

[[grid]]
key = "controller.law"
values = ["hinf", "lqr", "cascade"]

[[random]]
key = "measurement.seed"
distribution = "seed"

[[random]]
key = "disturbance.w1.harmonics[0].amplitude"
distribution = "uniform"
low = 0.05
high = 0.15

[[random]]
key = "model.d_u"
distribution = "normal"
mean = 1.0
std = 0.1
relative = true
"""


@pytest.fixture(scope="module")
def mc_study(tmp_path_factory):
    return hs.load_study(write_study(tmp_path_factory.mktemp("mc"), MONTE_CARLO))


@pytest.fixture(scope="module")
def mc_table(mc_study):
    return hs.run_study(mc_study, workers=1, progress=False)


# ---- expansion and seeds ----

def test_seeds_are_the_spawned_children_and_common_to_every_grid_point(mc_study):
    children = np.random.SeedSequence(mc_study.seed).spawn(mc_study.samples)
    assert mc_study.runs == 12 and mc_study.grid_points == 3
    for run in range(mc_study.runs):
        grid, sample, (law,) = mc_study.point(run)
        assert (grid, sample) == divmod(run, 4) and law == grid
        rng = np.random.default_rng(children[sample])
        seed, amplitude, factor = int(rng.integers(0, 2 ** 63)), rng.uniform(0.05, 0.15), rng.normal(1.0, 0.1)
        settings = dict(mc_study.settings(run))
        assert settings == {"controller.law": ["hinf", "lqr", "cascade"][grid], "measurement.seed": seed,
                            "disturbance.w1.harmonics[0].amplitude": amplitude, "model.d_u": factor * 1.0}


def test_table_has_a_row_per_run_with_seed_axes_status_and_every_metric(mc_study, mc_table):
    df = mc_table
    assert list(df["run"]) == list(range(12))
    assert list(df.columns[:4]) == ["run", "grid_point", "sample", "seed"]
    for column in mc_study.columns + ["law", "output_feedback", "gamma", "status", "reason"] + METRICS:
        assert column in df.columns
    assert (df["seed"] == df["measurement.seed"]).all()
    assert list(df["law"]) == [law for law in ["hinf", "lqr", "cascade"] for _ in range(4)]
    assert (df["status"] == "completed").all() and df["output_feedback"].all()
    # common random numbers: sample j has the same draws at every grid point
    for j in range(4):
        assert df[df["sample"] == j]["measurement.seed"].nunique() == 1


def test_the_dict_path_and_a_copied_scenario_agree(mc_study):
    """The scenario of a run (base document + settings, read by the C++ reader) equals the base
    scenario with the same values set as attributes."""
    run = 5
    settings = dict(mc_study.settings(run))
    scenario = hc.scenario_from_dict(mc_study.base, mc_study.source).copy()
    scenario.law = settings["controller.law"]
    measurement = scenario.measurement
    measurement.seed = settings["measurement.seed"]
    scenario.measurement = measurement
    built = mc_study.scenario(run)
    assert built.law == scenario.law and built.measurement.seed == measurement.seed


# ---- executors ----

def test_one_and_two_local_workers_give_the_same_table(mc_study, mc_table):
    pdt.assert_frame_equal(hs.run_study(mc_study, workers=2, progress=False), mc_table, check_exact=True)


@pytest.fixture(scope="module")
def dask_client():
    distributed = pytest.importorskip("dask.distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None, silence_logs=50)
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


@pytest.mark.slow
def test_a_dask_cluster_of_two_processes_gives_the_same_table(mc_study, mc_table, dask_client):
    assert len(dask_client.scheduler_info()["workers"]) == 2
    table = hs.run_study(mc_study, client=dask_client, progress=False)
    pdt.assert_frame_equal(table, mc_table, check_exact=True)
    # twice on the same client (fresh task keys), and from the command line with --scheduler
    pdt.assert_frame_equal(hs.run_study(mc_study, client=dask_client, progress=False), mc_table, check_exact=True)
    if HINF_CPP.exists():
        out = pathlib.Path(mc_study.source).parent / "dask-out"
        study_file = pathlib.Path(mc_study.source).parent / "study.toml"
        done = cli("study", study_file, "--out", out, "--scheduler", dask_client.scheduler.address, "--quiet")
        assert done.returncode == 0, done.stderr
        assert "on Dask scheduler" in done.stdout
        pdt.assert_frame_equal(pd.read_parquet(out / "runs.parquet"), mc_table.astype({"seed": "Int64"}),
                               check_exact=True, check_dtype=False)


# ---- on other machines: a carried model, the workers' build, a lost cluster ----

@pytest.fixture(scope="module")
def inprocess_client():
    """A Dask cluster of one worker in this process (its files and working folder are this process's:
    the tests below take away what the client had)."""
    distributed = pytest.importorskip("dask.distributed")
    # An in-process scheduler serves HTTP even with dashboard_address=None (on 8787, with a warning if that
    # is taken): a free local port instead.
    cluster = distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                       dashboard_address="127.0.0.1:0", silence_logs=50)
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


CASADI_STUDY = """\
[study]
name = "casadi"
scenario = "fig2.toml"
chunk = 1

[[grid]]
key = "controller.gamma"
values = [5.0, 10.0]
"""


@pytest.mark.slow
def test_a_study_carries_its_casadi_model_to_workers_without_its_folder(tmp_path, monkeypatch, inprocess_client):
    """[model] kind = "casadi" with a relative file: every row was invalid_input on a worker with
    another working folder or without the model folder. The study now carries model.json and the
    C source; the worker compiles them in its own cache and gives the local table bit for bit."""
    pytest.importorskip("casadi")
    from hinf_cpp.models import builtin

    folder = tmp_path / "project"
    folder.mkdir()
    builtin.ship().export(folder / "ship", cache_dir=tmp_path / "export-cache")
    path = write_study(folder, CASADI_STUDY)
    scenario = (folder / "fig2.toml").read_text()
    start, end = scenario.index("[model]"), scenario.index("[horizon]")
    (folder / "fig2.toml").write_text(scenario[:start] + '[model]\nkind = "casadi"\nfile = "ship/model.json"\n\n'
                                      + scenario[end:])
    monkeypatch.chdir(folder)
    study = hs.load_study(path.name, trust_code=True)  # the scenario as "fig2.toml", its model as "ship/model.json"
    assert study.source == "fig2.toml"
    local = hs.run_study(study, workers=1, progress=False)
    assert (local["status"] == "completed").all(), local["reason"].tolist()

    elsewhere = tmp_path / "worker"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)  # another working folder, and no model folder anywhere
    (folder / "ship").rename(tmp_path / "moved")
    # A worker that cannot compile it (a cache folder others can write is refused) stops the study, naming it.
    (tmp_path / "shared-cache").mkdir(mode=0o777)
    (tmp_path / "shared-cache").chmod(0o777)
    monkeypatch.setenv("HINF_CPP_CACHE", str(tmp_path / "shared-cache"))
    with pytest.raises(OSError, match="cannot compile") as error:
        hs.run_study(study, client=inprocess_client, progress=False)
    assert f"the Dask worker on {socket.gethostname()} cannot compile the [model] model of the study " \
           f"({tmp_path / 'project' / 'ship' / 'model.json'})" in str(error.value)
    assert "others can write it" in str(error.value) and "pass --out" in str(error.value)
    monkeypatch.setenv("HINF_CPP_CACHE", str(tmp_path / "worker-cache"))
    table = hs.run_study(study, client=inprocess_client, progress=False)
    pdt.assert_frame_equal(table, local, check_exact=True)
    assert len(list((tmp_path / "worker-cache").glob("hinf_model_ship-*.so"))) == 1  # compiled once, there


def test_a_study_carries_its_python_model_file_to_workers_without_its_folder(tmp_path, monkeypatch,
                                                                           inprocess_client):
    """[model] kind = "python" naming FILE.py:CALLABLE, read with trust: the study carries the file's
    text; a worker with another working folder and without the file writes it into its own cache
    and gives the local table bit for bit. The file's text is part of the study's hash."""
    folder = tmp_path / "project"
    folder.mkdir()
    (folder / "vessel.py").write_text("import hinf_cpp as hc\n\ndef make():\n    return hc.ShipModel()\n")
    path = write_study(folder, CASADI_STUDY)
    scenario = (folder / "fig2.toml").read_text()
    start, end = scenario.index("[model]"), scenario.index("[horizon]")
    (folder / "fig2.toml").write_text(scenario[:start] + '[model]\nkind = "python"\ncallable = "vessel.py:make"\n\n'
                                      + scenario[end:])
    monkeypatch.chdir(folder)
    study = hs.load_study(path.name, trust_code=True)
    assert study.model_files["model"]["text"] == (folder / "vessel.py").read_text()
    local = hs.run_study(study, workers=1, progress=False)
    assert (local["status"] == "completed").all(), local["reason"].tolist()

    elsewhere = tmp_path / "worker"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    (folder / "vessel.py").rename(tmp_path / "moved.py")
    monkeypatch.setenv("HINF_CPP_CACHE", str(tmp_path / "worker-cache" / "casadi"))
    table = hs.run_study(study, client=inprocess_client, progress=False)
    pdt.assert_frame_equal(table, local, check_exact=True)
    written = list((tmp_path / "worker-cache" / "python_models").glob("*/vessel.py"))
    assert len(written) == 1 and written[0].read_text() == study.model_files["model"]["text"]
    assert stat.S_IMODE(written[0].parent.stat().st_mode) == 0o700

    (tmp_path / "moved.py").write_text((tmp_path / "moved.py").read_text().replace("ShipModel()", "ShipModel() "))
    (tmp_path / "moved.py").rename(folder / "vessel.py")
    monkeypatch.chdir(folder)
    assert hs.load_study(path.name, trust_code=True).content_hash() != study.content_hash()


@pytest.mark.slow
@pytest.mark.parametrize("worker", ["another version", "another core", "an older hinf_cpp"])
def test_a_worker_of_another_build_stops_the_study_naming_it(mc_study, monkeypatch, inprocess_client, worker):
    """The workers' hinf_cpp was never compared with the client's: their rows were mixed in."""
    real = hs._dask_chunk

    def other_build(study, start, stop):
        table, identity = real(study, start, stop)
        if worker == "an older hinf_cpp":
            return table  # before chunks said who ran them
        changed = {"another version": {"version": "0.0.1"}, "another core": {"core": "f" * 64}}[worker]
        return table, {**identity, **changed}

    monkeypatch.setattr(hs, "_dask_chunk", other_build)
    address = next(iter(inprocess_client.scheduler_info()["workers"]))
    with pytest.raises(ValueError, match="install the same hinf_cpp build on every worker") as error:
        hs.run_study(mc_study, client=inprocess_client, progress=False)
    message = str(error.value)
    assert address in message and f"hinf_cpp {hc._core.__version__}" in message
    if worker != "an older hinf_cpp":
        assert ("0.0.1" if worker == "another version" else "core ffffffffffff") in message


@pytest.mark.slow
def test_losing_every_worker_is_a_resumable_error_not_an_internal_one(mc_study, mc_table, tmp_path):
    """It was FutureCancelledError ("internal error" on the command line)."""
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address="127.0.0.1:0", silence_logs=50) as cluster, distributed.Client(cluster) as client:
        def lose_the_workers(done, total, message):
            for worker in list(cluster.workers.values()):
                client.sync(worker.close)

        with pytest.raises(OSError, match="the same --out .* to resume") as error:  # the CLI: one line, status 2
            hs.run_study(mc_study, client=client, out=tmp_path, progress=lose_the_workers)
    assert "the Dask cluster lost the study's tasks (FutureCancelledError" in str(error.value)
    assert str(tmp_path / "partial") in str(error.value)
    saved = len(list((tmp_path / "partial").glob("chunk-*.parquet")))  # the first; the second if it ended first
    assert 1 <= saved < 3
    resumed = hs.run_study(mc_study, workers=1, out=tmp_path, progress=False)
    assert resumed.attrs["reused_chunks"] == saved
    pdt.assert_frame_equal(resumed, mc_table, check_exact=True)


# ---- replay ----

def test_replay_gives_the_row_exactly(mc_study, mc_table):
    for run in (1, 10):
        result = hs.replay(mc_study, run)
        row = mc_table.iloc[run]
        for name in METRICS:
            np.testing.assert_array_equal(getattr(result.metrics, name), row[name], err_msg=name)


@pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
def test_replay_command_gives_the_row_exactly(mc_study, mc_table, tmp_path):
    run = 6
    command = hs.replay_command(mc_study, run)
    assert "--seed" in command and "--set" in command
    import shlex

    argv = shlex.split(command)
    out = tmp_path / "run.json"
    done = subprocess.run([str(HINF_CPP)] + argv[1:] + ["--json", str(out)], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    metrics = json.loads(out.read_text())["metrics"]
    row = mc_table.iloc[run]
    for name in METRICS:
        value = metrics.get(name)
        if value is None:
            assert np.isnan(row[name]), name
        else:
            np.testing.assert_array_equal(value, row[name], err_msg=name)


# ---- failures are rows ----

FAILURES = """\
[study]
name = "failures"
scenario = "fig2.toml"
chunk = 2

[[grid]]
key = ["controller.gamma", "disturbance.w1.harmonics[0].amplitude", "solver.divergence_factor", "feedback"]
values = [
    [5.0, 0.1, 1000.0, "output"],   # completes
    [0.5, 0.1, 1000.0, "state"],    # below gamma* (1.33): conjugate point
    [3.0, 0.1, 1000.0, "output"],   # above gamma*, below the output-feedback 4.59: coupling fails
    [5.0, 100.0, 1.01, "state"],    # a surge force of 100: the loop leaves the divergence bound
    [5.0, 0.1, 0.5, "output"],      # divergence_factor must be > 1: the reader refuses it
]
"""


def test_failing_runs_are_rows_with_status_and_reason(tmp_path):
    path = write_study(tmp_path, FAILURES)
    df = hs.run_study(path, progress=False)
    assert list(df["status"]) == ["completed", "conjugate_point", "coupling_violation", "diverged", "invalid_input"]
    assert (df["reason"][1:] != "").all() and df["reason"][0] == ""
    assert np.isnan(df["rms_position_error_last_half"][1]) and np.isfinite(df["rms_position_error_last_half"][0])
    assert pd.isna(df["seed"][1]) and df["seed"][0] == 20000601
    counts = status_counts(df)
    assert counts["runs"][0] == 5 and counts["completed"][0] == 1


# ---- interrupt and resume ----

class Stop(Exception):
    pass


def test_an_interrupted_study_resumes_to_the_same_table(mc_study, mc_table, tmp_path):
    calls = []

    def stop_after_two(done, total, message):
        calls.append(done)
        if len(calls) == 2:
            raise Stop

    with pytest.raises(Stop):
        hs.run_study(mc_study, workers=2, out=tmp_path, progress=stop_after_two)
    # The two chunks that finished first were saved (with 2 workers, which two depends on the
    # timing); the one still running when the study stopped was not.
    chunks = sorted(p.name for p in (tmp_path / "partial").glob("chunk-*.parquet"))
    assert len(chunks) == 2
    seen = []
    resumed = hs.run_study(mc_study, workers=2, out=tmp_path, progress=lambda d, t, m: seen.append(d))
    assert seen == [mc_study.runs]  # one call: only the missing chunk ran
    pdt.assert_frame_equal(resumed, mc_table, check_exact=True)
    assert not resumed.attrs["restarted"]


def test_a_changed_study_starts_over(mc_study, tmp_path):
    hs.run_study(mc_study, workers=2, out=tmp_path, progress=False)
    changed = hs.study_from_dict({**mc_study.definition, "study": {**mc_study.definition["study"], "seed": 1}},
                                 "changed", pathlib.Path(mc_study.source).parent)
    seen = []
    table = hs.run_study(changed, workers=2, out=tmp_path, progress=lambda d, t, m: seen.append(d))
    # Every chunk ran again (called once per chunk, in the order they finish: 5 + 5 + 2 runs).
    assert len(seen) == 3 and seen[-1] == mc_study.runs and table.attrs["restarted"]


# ---- the output folder: only the study's own files, one study at a time ----

def small_study(tmp_path, seed=0):
    """6 runs in 2 chunks (the Monte Carlo with 2 samples)."""
    body = MONTE_CARLO.replace("samples = 4", "samples = 2").replace("seed = 20261124", f"seed = {seed}")
    return hs.load_study(write_study(tmp_path, body, f"study{seed}.toml"))


def test_a_folder_partial_that_is_not_a_studys_is_refused_and_kept(tmp_path):
    study = small_study(tmp_path)
    out = tmp_path / "out"
    (out / "partial" / "mine").mkdir(parents=True)
    (out / "partial" / "notes.txt").write_text("my notes")
    (out / "partial" / "mine" / "data.csv").write_text("1,2")
    with pytest.raises(ValueError, match=r"out/partial.* not the partial folder of a hinf_cpp study"):
        hs.run_study(study, workers=1, out=out, progress=False)
    assert (out / "partial" / "notes.txt").read_text() == "my notes"
    assert (out / "partial" / "mine" / "data.csv").read_text() == "1,2"
    # The folder of an earlier hinf_cpp (without the marker, with its study.json) is a study's.
    (out / "partial" / "study.json").write_text('{"study": "mc", "hash": "0", "runs": 6, "chunk": 5}')
    assert hs.run_study(study, workers=1, out=out, progress=False).attrs["reused_chunks"] == 0
    assert (out / "partial" / "notes.txt").read_text() == "my notes"


def test_a_changed_study_deletes_only_its_own_chunks(tmp_path):
    out = tmp_path / "out"
    first = hs.run_study(small_study(tmp_path, seed=0), workers=1, out=out, progress=False)
    (out / "partial" / "notes.txt").write_text("my notes")
    (out / "partial" / "mine").mkdir()
    (out / "partial" / "chunk-00009.parquet").write_text("a stale chunk of an older study")
    second = hs.run_study(small_study(tmp_path, seed=1), workers=1, out=out, progress=False)
    assert second.attrs["restarted"] and second.attrs["reused_chunks"] == 0
    assert not second["seed"].equals(first["seed"])
    assert (out / "partial" / "notes.txt").read_text() == "my notes" and (out / "partial" / "mine").is_dir()
    assert sorted(p.name for p in (out / "partial").glob("chunk-*")) == ["chunk-00000.parquet", "chunk-00001.parquet"]


def test_a_second_study_on_the_same_folder_is_refused_while_the_first_writes(tmp_path):
    first, second = small_study(tmp_path, seed=0), small_study(tmp_path, seed=1)
    out = tmp_path / "out"
    errors = []

    def start_the_second(done, total, message):
        with pytest.raises(ValueError, match="another study is writing") as error:
            hs.run_study(second, workers=1, out=out, progress=False)
        errors.append(str(error.value))

    table = hs.run_study(first, workers=1, out=out, progress=start_the_second)
    assert len(errors) == 2 and str(out) in errors[0]
    assert (table["seed"].to_numpy() == hs.run_study(first, workers=1, progress=False)["seed"].to_numpy()).all()
    # Once the first has ended, the folder is free again.
    assert hs.run_study(second, workers=1, out=out, progress=False).attrs["restarted"]


def test_a_chunk_of_another_study_is_run_again_not_mixed_in(tmp_path):
    mine, other = small_study(tmp_path, seed=0), small_study(tmp_path, seed=1)
    expected = hs.run_study(mine, workers=1, out=tmp_path / "mine", progress=False)
    hs.run_study(other, workers=1, out=tmp_path / "other", progress=False)
    chunk = "partial/chunk-00000.parquet"
    (tmp_path / "mine" / chunk).write_bytes((tmp_path / "other" / chunk).read_bytes())
    resumed = hs.run_study(mine, workers=1, out=tmp_path / "mine", progress=False)
    pdt.assert_frame_equal(resumed, expected, check_exact=True)
    assert resumed.attrs["reused_chunks"] == 1 and resumed.attrs["chunks"] == 2


def test_a_chunk_with_a_failed_row_is_run_again_on_resume(tmp_path):
    """status "failed" (an exception that is not about the run's values: out of memory, a bug)
    is not kept: the chunk runs again."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    study = small_study(tmp_path)
    expected = hs.run_study(study, workers=1, out=tmp_path, progress=False)
    path = tmp_path / "partial" / "chunk-00001.parquet"
    table = pq.read_table(path)
    status = pa.array(["failed"] + table["status"].to_pylist()[1:])
    pq.write_table(table.set_column(table.schema.get_field_index("status"), "status", status), path)
    resumed = hs.run_study(study, workers=1, out=tmp_path, progress=False)
    pdt.assert_frame_equal(resumed, expected, check_exact=True)
    assert resumed.attrs["reused_chunks"] == 1 and not resumed.attrs["restarted"]


def test_a_resumed_study_says_the_statuses_of_the_runs_it_reused(tmp_path):
    """invalid_input rows are kept on resume: the study says so (it said only how many chunks)."""
    path = write_study(tmp_path, FAILURES)
    first = hs.run_study(path, workers=1, out=tmp_path / "out", progress=False)
    assert first.attrs["reused_statuses"] == {}
    resumed = hs.run_study(path, workers=1, out=tmp_path / "out", progress=False)
    assert resumed.attrs["reused_chunks"] == 3
    assert resumed.attrs["reused_statuses"] == {"completed": 1, "conjugate_point": 1, "coupling_violation": 1,
                                                "diverged": 1, "invalid_input": 1}


# ---- round trips ----

def test_a_pickled_and_a_rewritten_scenario_run_to_the_same_result(mc_study):
    scenario = mc_study.scenario(3)
    copies = [pickle.loads(pickle.dumps(scenario)), hc._core.parse_scenario_toml(hc._core.scenario_toml(scenario), "<toml>")]
    expected = hc.run_scenario(scenario).metrics
    for copy in copies:
        assert hc.run_scenario(copy).metrics == expected


# ---- study files: errors ----

@pytest.mark.parametrize("body, message", [
    ("[study]\nscenario = 'fig2.toml'\n[[grid]]\nkey = 'controller.gamma'\nvalues = []\n", "non-empty"),
    ("[study]\nscenario = 'fig2.toml'\nsamples = 3\n", "no [[random]] axis"),
    ("[study]\nscenario = 'fig2.toml'\n[[random]]\nkey = 'x.y'\ndistribution = 'beta'\n", "distribution"),
    ("[study]\nscenario = 'missing.toml'\n", "cannot read"),
    ("[study]\nscenario = 'fig2.toml'\n[[grid]]\nkey = 'controller.gamma'\nvalues = ['x']\n", "gamma"),
    ("[study]\nscenario = 'fig2.toml'\n[[random]]\nkey = 'model.nope'\ndistribution = 'uniform'\n"
     "low = 0.5\nhigh = 1.5\nrelative = true\n", "no parameter 'nope'"),
    ("[study]\nscenario = 'fig2.toml'\nseeds = 3\n", "unknown key 'seeds'"),
    ("[study]\nscenario = 'fig2.toml'\n" + ".".join(["a"] * 30) + " = 1\n",
     "study.toml:3: the key '" + "a." * 20 + "...' has more than 16 dotted parts"),
    ("[study]\nscenario = 'fig2.toml'\n[[grid]]\nkey = 'controller.gamma'\nvalues = [5.0, 'x']\n",
     "[[grid]] 1: controller.gamma values must be numbers"),
    ("[study]\nscenario = 'fig2.toml'\n[report]\nheading_tol = 'x'\n", "[report]: 'heading_tol' must be a finite number"),
    ("[study]\nscenario = 'fig2.toml'\n[report]\nposition_tol = -1\n", "[report]: 'position_tol' must be > 0"),
    ("[study]\nscenario = 'fig2.toml'\n[report]\nmetrics = 'final_position_error'\n",
     "[report] metrics must be a list of metric names"),
    ("[study]\nscenario = 'fig2.toml'\n[[grid]]\nkey = 'initial.q0[5]'\nvalues = [0.0, '1']\n"
     "[[grid]]\nkey = 'initial.q0[4]'\nvalues = [0.0]\n[report]\nroa = ['initial.q0[5]', 'initial.q0[4]']\n",
     "[report] roa: the values of 'initial.q0[5]' must be numbers"),
    ("[study]\nscenario = 'fig2.toml'\nsamples = 1000000000000\n[[random]]\nkey = 'measurement.seed'\n"
     "distribution = 'seed'\n", "1000000000000 runs, more than the 10000000"),
])
def test_bad_study_files_are_refused_naming_the_problem(tmp_path, body, message):
    with pytest.raises(ValueError, match=message.replace("[", r"\[")):
        hs.load_study(write_study(tmp_path, body))


def test_settings_parse_toml_values():
    assert parse_setting("controller.gamma=12") == ("controller.gamma", 12)
    assert parse_setting('controller.law="lqr"') == ("controller.law", "lqr")
    assert parse_setting("initial.q0[5]=0.5") == ("initial.q0[5]", 0.5)
    with pytest.raises(ValueError, match="not a TOML value"):
        parse_setting("controller.law=lqr")
    with pytest.raises(ValueError, match="KEY=VALUE"):
        parse_setting("controller.gamma")


# ---- the command line ----

def cli(*args, cwd=None):
    return subprocess.run([str(HINF_CPP), *map(str, args)], capture_output=True, text=True, timeout=300, cwd=cwd)


@pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
def test_cli_study_writes_the_table_summary_and_figures(tmp_path):
    body = MONTE_CARLO.replace("samples = 4", "samples = 2") + textwrap.dedent("""\
        [report]
        metrics = ["rms_position_error_last_half"]
        """)
    path = write_study(tmp_path, body)
    done = cli("study", path, "--out", tmp_path / "out", "--workers", "2", "--quiet")
    assert done.returncode == 0, done.stderr
    out = tmp_path / "out"
    for name in ["runs.parquet", "runs.csv", "summary.md", "distribution.png"]:
        assert (out / name).is_file(), name
    df = pd.read_parquet(out / "runs.parquet")
    assert len(df) == 6 and (df["status"] == "completed").all()
    csv = pd.read_csv(out / "runs.csv")
    np.testing.assert_array_equal(csv["rms_position_error_last_half"], df["rms_position_error_last_half"])
    assert "rms_position_error_last_half" in (out / "summary.md").read_text()
    assert "6 runs (completed 6)" in done.stdout and "resumed" not in done.stdout
    again = cli("study", path, "--out", out, "--quiet")
    assert again.returncode == 0 and "resumed: reused 2 of 2 chunks" in again.stdout, again.stderr
    assert f"saved in {out}/partial (6 runs: completed 6)" in again.stdout and "note:" not in again.stdout


@pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
def test_cli_study_resumed_says_which_failed_runs_it_did_not_run_again(tmp_path):
    path = write_study(tmp_path, FAILURES)
    assert cli("study", path, "--out", tmp_path / "out", "--quiet").returncode == 0
    again = cli("study", path, "--out", tmp_path / "out", "--quiet")
    assert again.returncode == 0, again.stderr
    assert "(5 runs: completed 1, diverged 1, conjugate_point 1, coupling_violation 1, invalid_input 1)" in again.stdout
    assert "their invalid_input runs (1) were refused for the scenario itself and were not run again" in again.stdout
    # Each run that did not complete is listed with the command that runs it again alone.
    assert "runs that did not complete (each runs again alone with its command):" in again.stdout
    assert again.stdout.count("hinf-cpp run ") >= 4, again.stdout


@pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
def test_cli_study_whose_runs_all_failed_exits_with_status_1(tmp_path):
    path = write_study(tmp_path, """\
        [study]
        scenario = "fig2.toml"
        [[grid]]
        key = "controller.gamma"
        values = [0.5, 1.0]
        """)
    done = cli("study", path, "--out", tmp_path / "out", "--quiet")
    assert done.returncode == 1
    assert done.stderr.count("\n") == 1 and "all 2 runs of the study failed" in done.stderr, done.stderr
    assert f"{tmp_path / 'out' / 'runs.parquet'}" in done.stderr
    assert len(pd.read_parquet(tmp_path / "out" / "runs.parquet")) == 2


@pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
@pytest.mark.parametrize("args, message", [
    (["run", FIG2, "--set", "controller.law=lqr"], "not a TOML value"),
    (["run", FIG2, "--set", "controller.gamma"], "KEY=VALUE"),
    (["run", FIG2, "--set", "feedback=\"state\"", "--seed", "3"], "no [measurement]"),
    (["run", FIG2, "--seed", "-1"], "invalid seed"),
    (["run", FIG2, "--set", "controller.colour=1"], "colour"),
    (["study", "missing.toml", "--out", "x"], "cannot read the study"),
    (["study", "missing.toml", "--out", "x", "--workers", "2", "--scheduler", "tcp://x:1"], "exclude each other"),
])
def test_cli_errors_are_one_line_and_exit_status_2(tmp_path, args, message):
    done = cli(*args, cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1 and message in done.stderr, done.stderr


def test_summary_statistics(mc_study, mc_table):
    stats = summarize(mc_table, mc_study, ["final_position_error"])
    assert list(stats["controller.law"]) == ["hinf", "lqr", "cascade"]
    hinf = mc_table[mc_table["law"] == "hinf"]["final_position_error"]
    row = stats.iloc[0]
    assert row["count"] == 4 and row["mean"] == pytest.approx(hinf.mean()) and row["p50"] == pytest.approx(hinf.median())
    pairs = paired_differences(mc_table, mc_study, "final_position_error")
    lqr = mc_table[mc_table["law"] == "lqr"]["final_position_error"].to_numpy()
    assert list(pairs["controller.law"]) == ["lqr - hinf", "cascade - hinf"]
    assert pairs["mean"][0] == pytest.approx(np.mean(lqr - hinf.to_numpy()))
    assert "Paired differences" in summary_markdown(mc_table, mc_study)


def test_outputs_with_roa_and_gamma_figures(tmp_path):
    body = """\
    [study]
    name = "roa"
    scenario = "fig2.toml"
    [[grid]]
    key = "controller.gamma"
    values = [5.0, 10.0]
    [[grid]]
    key = "initial.q0[5]"
    values = [0.0, 1.5]
    [[grid]]
    key = "initial.q0[4]"
    values = [-1.0, 1.0]
    [report]
    roa = ["initial.q0[5]", "initial.q0[4]"]
    """
    study = hs.load_study(write_study(tmp_path, body))
    df = hs.run_study(study, progress=False)
    written = {p.name for p in write_study_outputs(study, df, tmp_path / "out")}
    assert {"roa.png", "gamma.png", "distribution.png", "summary.md"} <= written


def test_a_relative_axis_takes_its_base_from_the_model_when_the_scenario_omits_it(tmp_path):
    """[model] without d_r: the base value is the model's parameter (the ship's default, 1.0)."""
    path = write_study(tmp_path, """\
        [study]
        scenario = "fig2.toml"
        samples = 2
        [[random]]
        key = "model.d_r"
        distribution = "uniform"
        low = 0.7
        high = 1.3
        relative = true
        """)
    path.parent.joinpath("fig2.toml").write_text(path.parent.joinpath("fig2.toml").read_text().replace("d_r = 1.0\n", ""))
    study = hs.load_study(path)
    assert study.random[0].base == 1.0  # ShipParameters().d_r, the paper's
    rng = np.random.default_rng(np.random.SeedSequence(0).spawn(2)[1])
    assert dict(study.settings(1))["model.d_r"] == rng.uniform(0.7, 1.3) * 1.0


def test_plant_axes_perturb_the_simulated_plant_only(tmp_path):
    """plant.<name> sets [plant] (the design stays on [model]): base values from [model], rows
    replay exactly, and the designs are those of the nominal model (same gamma, same Z0)."""
    path = write_study(tmp_path, """\
        [study]
        scenario = "fig2.toml"
        samples = 3
        seed = 5
        [[random]]
        key = "plant.d_u"
        distribution = "uniform"
        low = 0.7
        high = 1.3
        relative = true
        [[random]]
        key = "plant.m_v"
        distribution = "normal"
        mean = 1.0
        std = 0.1
        relative = true
        """)
    study = hs.load_study(path)
    assert [axis.base for axis in study.random] == [1.0, -2.0]
    df = hs.run_study(study, progress=False)
    assert (df["status"] == "completed").all()
    assert df["rms_position_error_last_half"].nunique() == 3
    nominal = hc.run_scenario(hc.scenario_from_dict(study.base, study.source))
    for run in range(3):
        result = hs.replay(study, run)
        assert study.scenario(run).plant is not None
        np.testing.assert_array_equal(result.Z0, nominal.Z0)  # the design is the nominal model's
        np.testing.assert_array_equal(result.metrics.rms_position_error_last_half,
                                      df["rms_position_error_last_half"][run])


# ---- matrix parameters, laws that do not apply, files missing where a run ran ----

FOSSEN = pathlib.Path(hc.scenario_path("fossen_vessel_turn"))


def write_fossen_study(folder: pathlib.Path, body: str) -> pathlib.Path:
    """A study over a copy of fossen_vessel_turn.toml (preset supply_vessel, no M or D written;
    a 5-unit horizon for speed)."""
    (folder / "fossen.toml").write_text(FOSSEN.read_text().replace("tf = 200.0", "tf = 5.0"))
    path = folder / "study.toml"
    path.write_text(textwrap.dedent(body))
    return path


def test_a_relative_axis_on_a_matrix_entry_takes_the_models_entry_as_its_base(tmp_path):
    """plant.M[0][0] with neither [plant] nor [model] writing M: the base is the preset's m11
    (1.1274, docs/vehicles.md), the plant's other entries are the model's, and the replay
    command (which sets the whole matrix first) gives the row exactly."""
    path = write_fossen_study(tmp_path, """\
        [study]
        scenario = "fossen.toml"
        samples = 2
        [[random]]
        key = "plant.M[0][0]"
        distribution = "uniform"
        low = 0.8
        high = 1.2
        relative = true
        """)
    study = hs.load_study(path)
    preset = hc.load_scenario(FOSSEN).model.named_parameters()
    assert study.random[0].base == 1.1274 == preset["M[0][0]"]
    df = hs.run_study(study, workers=1, progress=False)
    assert (df["status"] == "completed").all()
    rng = np.random.default_rng(np.random.SeedSequence(0).spawn(2)[1])
    assert df["plant.M[0][0]"][1] == rng.uniform(0.8, 1.2) * 1.1274
    plant = study.scenario(1).plant.named_parameters()
    assert plant["M[0][0]"] == df["plant.M[0][0]"][1]
    assert all(plant[name] == value for name, value in preset.items() if name != "M[0][0]")
    assert study.model_arrays == {"plant.M": [[1.1274, 0.0, 0.0], [0.0, 1.8902, -0.0744], [0.0, -0.0744, 0.1278]]}
    command = df["replay"][1]
    assert command.startswith("hinf-cpp run ") and "--set 'plant.M=[[1.1274, 0.0, 0.0], " in command
    if HINF_CPP.exists():
        import shlex

        out = tmp_path / "run.json"
        done = subprocess.run([str(HINF_CPP)] + shlex.split(command)[1:] + ["--json", str(out)], capture_output=True,
                              text=True, timeout=120)
        assert done.returncode == 0, done.stderr
        metrics = json.loads(out.read_text())["metrics"]
        assert metrics["final_position_error"] == df["final_position_error"][1]


def test_a_law_that_does_not_apply_to_the_model_is_an_error_when_the_study_is_read(tmp_path):
    path = write_fossen_study(tmp_path, """\
        [study]
        scenario = "fossen.toml"
        [[grid]]
        key = "controller.law"
        values = ["hinf", "lqr", "cascade"]
        """)
    with pytest.raises(ValueError) as error:
        hs.load_study(path)
    message = str(error.value)
    assert message.startswith(f"{path}: [[grid]] 1: controller.law = \"cascade\" does not apply to the model "
                              "'fossen_vessel'")
    assert "remove \"cascade\" from the values of controller.law" in message and "\n" not in message
    # The laws that apply: no error, and no row refused.
    path.write_text(path.read_text().replace(', "cascade"', ""))
    assert hs.load_study(path).runs == 2


@pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
def test_cli_a_law_that_does_not_apply_is_one_line_and_exit_status_2(tmp_path):
    path = write_fossen_study(tmp_path, """\
        [study]
        scenario = "fossen.toml"
        [[grid]]
        key = ["controller.law", "feedback"]
        values = [["hinf", "state"], ["cascade", "state"]]
        """)
    done = cli("study", path, "--out", tmp_path / "out", "--quiet")
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert "controller.law = \"cascade\" does not apply to the model 'fossen_vessel'" in done.stderr
    assert not (tmp_path / "out" / "runs.parquet").exists()


def test_a_chunk_refused_for_a_missing_file_is_run_again_on_resume(tmp_path):
    """An invalid_input row whose file was missing where it ran (not about its values) is not
    kept: its chunk runs again, and the study says how many chunks it ran again; a value the
    reader refuses stays an invalid_input row that is kept."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    study = small_study(tmp_path)
    expected = hs.run_study(study, workers=1, out=tmp_path, progress=False)
    path = tmp_path / "partial" / "chunk-00001.parquet"
    table = pq.read_table(path)
    missing = "[plant] file: cannot read model description '/gone/model.json': No such file or directory"
    table = table.set_column(table.schema.get_field_index("status"), "status",
                             pa.array(["invalid_input"] + table["status"].to_pylist()[1:]))
    table = table.set_column(table.schema.get_field_index("reason"), "reason",
                             pa.array([missing] + table["reason"].to_pylist()[1:]))
    pq.write_table(table, path)
    resumed = hs.run_study(study, workers=1, out=tmp_path, progress=False)
    pdt.assert_frame_equal(resumed, expected, check_exact=True)
    assert resumed.attrs["reused_chunks"] == 1 and resumed.attrs["rerun_chunks"] == 1
    assert resumed.attrs["reused_runs"] == 5
    # A refused value is kept (it would be refused again).
    table = pq.read_table(path)
    table = table.set_column(table.schema.get_field_index("status"), "status",
                             pa.array(["invalid_input"] + table["status"].to_pylist()[1:]))
    pq.write_table(table, path)
    kept = hs.run_study(study, workers=1, out=tmp_path, progress=False)
    assert kept.attrs["reused_chunks"] == 2 and kept.attrs["rerun_chunks"] == 0
    assert kept["status"][5] == "invalid_input"
