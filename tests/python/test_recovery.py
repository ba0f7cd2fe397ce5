"""Recovery studies with runs that fail: their status reported as such (not judged as recovered
or turned around), and every law's run drawn, the failed ones marked.

The failing start: Figure 1's ship 8 m aside with its heading reversed, q0 = [1, 0, 0, 0, 8, pi],
and [solver] divergence_factor = 100. The H-infinity law runs to tf but ends about 2.9 km off
the path (lost_track: more than [solver] lost_track = 1 m farther than the 8 m it started
from); the LQR law passes the divergence bound (100 times the path's scale, docs/mathematics.md)
before tf (diverged); the cascade and backstepping laws complete. Each status is checked here
from the run's own arrays with NumPy.
"""

from __future__ import annotations

import json
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import hinf_cpp as hc
from hinf_cpp.analysis.comparison import heading_error
from hinf_cpp.analysis.recovery import assess_recovery, failure_status, recovery_study, turn_around
from hinf_cpp.output.plotting import recovery_figure, save_figure
from hinf_cpp.output.tables import text_table

HINF_CPP = pathlib.Path(sys.executable).parent / "hinf-cpp"
needs_cli = pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
NAME = "fig1-8m-aside-reversed"
START = [1.0, 0.0, 0.0, 0.0, 8.0, math.pi]
DIVERGENCE_FACTOR = 100.0


def failing_scenario() -> hc.Scenario:
    s = hc.load_scenario(hc.scenario_path("paper_fig1"))
    s.name = NAME
    s.initial_q0 = START
    s.divergence_factor = DIVERGENCE_FACTOR
    return s


@pytest.fixture(scope="module")
def study():
    return recovery_study([failing_scenario(), hc.scenario_path("poor_heading_180")])


def distance(q: np.ndarray, q_d: np.ndarray) -> np.ndarray:
    return np.hypot(q[:, 3] - q_d[:, 3], q[:, 4] - q_d[:, 4])


def test_failed_runs_keep_their_status(study):
    scenario = failing_scenario()
    statuses = {v.controller.name: v.status for v in study.verdicts if v.scenario == NAME}
    assert statuses == {"hinf": "lost_track", "lqr": "diverged", "cascade": "completed", "backstepping": "completed"}
    # lost_track, from the arrays: it ran to tf and ended more than 1 m farther than it started.
    hinf = study.verdict(NAME, "hinf")
    sim = hinf.result.simulation
    d = distance(sim.q, sim.q_d)
    assert sim.t[-1] == scenario.tf and d[0] == pytest.approx(8.0, abs=1e-12)
    assert d[-1] - d[0] > scenario.lost_track == 1.0 and d[-1] > 1000.0
    # diverged, from the arrays: it stopped before tf, its error (heading wrapped) beyond the
    # bound 100 max(1, |q_e(t0)|_inf, the spreads of x_d and y_d, max |u_d|, |v_d|, |r_d|).
    lqr = study.verdict(NAME, "lqr")
    sim = lqr.result.simulation
    q_e = sim.q - sim.q_d
    q_e[:, 5] = (q_e[:, 5] + math.pi) % (2 * math.pi) - math.pi
    q_d = sim.q_d
    scale = max(1.0, np.max(np.abs(q_e[0])), np.ptp(q_d[:, 3]), np.ptp(q_d[:, 4]), np.max(np.abs(q_d[:, :3])))
    bound = DIVERGENCE_FACTOR * scale
    assert sim.t[-1] < scenario.tf - 1.0
    assert np.max(np.abs(q_e[-1])) > 0.99 * bound   # the last output point, at most one step before the stop
    for v in (hinf, lqr):
        # Not judged as a recovery: it does not recover, and whether it turns around is not
        # judged; the reason is the run's own status message.
        assert v.recovers is False and v.turns_around is None and v.turn is None
        assert v.error == " ".join(v.result.simulation.status_message.split())
    assert "exceeded the divergence bound" in lqr.error and "farther than it started" in hinf.error
    # The old verdict of the diverged run, "turns around", is what its spinning heading gives:
    # not a statement about how the law turns the ship.
    assert turn_around(lqr.result.simulation.t, heading_error(lqr.result)).turned
    # The completed run is judged as before, from its arrays.
    cascade = study.verdict(NAME, "cascade")
    sim = cascade.result.simulation
    final_heading = abs((sim.q[-1, 5] - sim.q_d[-1, 5] + math.pi) % (2 * math.pi) - math.pi)
    assert cascade.recovers == (distance(sim.q, sim.q_d)[-1] < 0.5 and final_heading < math.radians(10.0))
    assert cascade.turns_around in (True, False) and cascade.error is None


def test_table_and_json_show_the_status(study):
    header, rows = study.table()
    assert header[:5] == ["scenario", "controller", "status", "recovers", "turns around"]
    by_law = {row[1]: row for row in rows if row[0] == NAME}
    assert by_law["lqr"][2:5] == ["diverged", False, None]
    assert by_law["hinf"][2:5] == ["lost_track", False, None]
    assert by_law["cascade"][2] == "completed"
    lines = {line.split()[1]: line for line in text_table(header, rows).splitlines()[2:] if line.startswith(NAME)}
    assert lines["lqr"].split()[2:5] == ["diverged", "no", "-"]
    data = json.loads(json.dumps(study.to_dict(), allow_nan=False))
    entries = {v["controller"]: v for v in data["verdicts"] if v["scenario"] == NAME}
    assert entries["lqr"]["status"] == "diverged" and entries["lqr"]["turns_around"] is None
    assert entries["hinf"]["status"] == "lost_track" and entries["hinf"]["recovers"] is False
    assert "status" in data["definitions"]


def test_recovery_figure_draws_every_run_and_marks_the_failed(tmp_path, study):
    fig = recovery_figure(study, columns=2)
    ax = fig.axes[0]
    lines = {line.get_label(): line for line in ax.get_lines()}
    for law in ("hinf", "lqr", "cascade"):
        v = study.verdict(NAME, law)
        q = v.result.simulation.q
        (line,) = [line for label, line in lines.items() if label.split()[0] == law]
        # The whole run, point for point (none dropped, not cut at the panel).
        np.testing.assert_array_equal(line.get_xdata(), q[:, 3])
        np.testing.assert_array_equal(line.get_ydata(), q[:, 4])
        if v.status == "completed":
            assert line.get_label() == law and line.get_linestyle() == "--"
        else:
            assert line.get_label().startswith(f"{law} ({v.status}") and line.get_linestyle() == ":"
            # An x at its last point.
            ends = [m for m in ax.get_lines() if m.get_marker() == "x" and m.get_color() == line.get_color()]
            assert len(ends) == 1
            assert (ends[0].get_xdata()[0], ends[0].get_ydata()[0]) == (q[-1, 3], q[-1, 4])
    # The lost run ends 2.9 km away: its label says how far; the panel stays on the desired path
    # and the completed run (within a margin of half their extent).
    hinf = study.verdict(NAME, "hinf")
    far = float(distance(hinf.result.simulation.q, hinf.result.simulation.q_d)[-1])
    (label,) = [label for label in lines if label.startswith("hinf")]
    assert label == f"hinf (lost_track, ends {far:,.0f} m off the path)"
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    q_d = hinf.result.simulation.q_d
    assert x0 < q_d[:, 3].min() and x1 > q_d[:, 3].max() and y0 < q_d[:, 4].min() and y1 > q_d[:, 4].max()
    assert max(x1 - x0, y1 - y0) < 100.0
    legend = [text.get_text() for text in fig.legends[0].get_texts()]
    assert any(text.startswith("lqr (diverged") for text in legend) and "cascade" in legend
    save_figure(fig, tmp_path / "recovery.png")
    # Marine: y (East) horizontal, x (North) vertical.
    marine = recovery_figure(study, columns=2, marine=True)
    (line,) = [line for line in marine.axes[0].get_lines() if line.get_label().startswith("lqr")]
    np.testing.assert_array_equal(line.get_xdata(), study.verdict(NAME, "lqr").result.simulation.q[:, 4])
    assert marine.axes[0].get_xlabel() == "East y [m]" and marine.axes[0].get_ylabel() == "North x [m]"


def test_a_run_without_a_closed_loop_is_named_in_its_panel():
    """gamma = 1 is below gamma* = 1.335 of Figure 1: no H-infinity design (a conjugate point);
    the LQR design (gamma = inf) runs."""
    s = hc.load_scenario(hc.scenario_path("paper_fig1"))
    s.gamma = 1.0
    s.tf = 10.0
    study = recovery_study([s], "hinf,lqr")
    hinf, lqr = study.verdicts
    assert hinf.status == "conjugate_point" and hinf.result is None and hinf.turns_around is None
    assert lqr.status == "completed" and lqr.result is not None
    header, rows = study.table()
    assert rows[0][:5] == ["paper-fig1", "hinf", "conjugate_point", None, None]
    fig = recovery_figure(study)
    texts = [text.get_text() for text in fig.axes[0].texts]
    assert "hinf: conjugate_point, no run to draw" in texts
    assert [line.get_label() for line in fig.axes[0].get_lines()][2] == "lqr"
    assert failure_status(hc.SolverError("x")) == "solver_failure" and failure_status(KeyError("x")) == "failed"


def test_assess_recovery_of_a_lost_run():
    result = hc.run_scenario(failing_scenario())   # the scenario's law: hinf
    verdict = assess_recovery(result)
    assert (verdict.status, verdict.recovers, verdict.turns_around) == ("lost_track", False, None)
    # Its numbers are those where it ended (m, rad), from the arrays.
    sim = result.simulation
    assert verdict.final_position_error == pytest.approx(distance(sim.q, sim.q_d)[-1], rel=1e-12)
    assert verdict.settling_time is None


@needs_cli
def test_cli_recovery_reports_and_draws_failed_runs(tmp_path):
    text = pathlib.Path(hc.scenario_path("paper_fig1")).read_text()
    old = "q0 = [1.0, 0.0, 0.0, -1.0, -1.0, 0.7853981633974483]"
    assert old in text and "[solver]\n" in text
    path = tmp_path / "aside.toml"
    path.write_text(text.replace(old, f"q0 = [1.0, 0.0, 0.0, 0.0, 8.0, {math.pi!r}]")
                    .replace('name = "paper-fig1"', f'name = "{NAME}"')
                    .replace("[solver]\n", f"[solver]\ndivergence_factor = {DIVERGENCE_FACTOR!r}\n"))
    r = subprocess.run([str(HINF_CPP), "recovery", str(path), "--json", str(tmp_path / "r.json"),
                        "--plot", str(tmp_path / "r.png"), "--marine"], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    rows = {line.split()[1]: line.split() for line in r.stdout.splitlines() if line.startswith(NAME)}
    assert rows["lqr"][2:5] == ["diverged", "no", "-"] and rows["hinf"][2:5] == ["lost_track", "no", "-"]
    assert "lqr on fig1-8m-aside-reversed diverged: the tracking error" in r.stdout
    data = json.loads((tmp_path / "r.json").read_text())
    assert [v["status"] for v in data["verdicts"]] == ["lost_track", "diverged", "completed", "completed"]
    assert (tmp_path / "r.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
