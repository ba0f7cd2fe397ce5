"""A receding-horizon run's path changed under way by a new plan from waypoints (docs/planning.md,
"A path changed under way"): hinf_cpp.planning.plan_path_change from the horizon's desired state
at a window's start, and a scenario file's [path_change] with waypoints or a path, planned from
the run's desired state at its t (after a planned [desired]), in the continuous loop and with
[sampling]; the written scenario for hinf-sim, and the messages for what is wrong."""

from __future__ import annotations

import json
import math
import os
import pathlib
import re
import subprocess
import sys
import tomllib

import numpy as np
import pytest

import hinf_cpp as hc
from _support import numbers_close

pytest.importorskip("casadi")

from hinf_cpp.planning import (PlanOptions, UnreachableWaypointError, Waypoint, default_cache_dir,  # noqa: E402
                               plan_path_change)
from hinf_cpp.scenario.planned import load_planned, needs_planning  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = pathlib.Path(sys.executable).parent

# Figure 1's ship (paper_fig1: S-curve from u2 = 0.3 sin(0.2 t)) is at t = 20 s at (6.83, 12.69)
# m heading 1.74 rad, on its way to (20.8, 22.3) at tf = 40 s. The new plan sends it north
# instead: to (0, 32) heading north at t = 40 s, some 23 m from where the unchanged path ends.
# The bounds are those of the shipped planned ship scenarios.
T_JOIN = 20.0
WAYPOINT = Waypoint(0.0, 32.0, t=40.0, heading=math.pi / 2)
BOUNDS = PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5))
TOLERANCE, HEADING_TOLERANCE = BOUNDS.tolerance, BOUNDS.heading_tolerance  # 0.05 m, 0.01 rad: the defaults
RECEDING = "[receding_horizon]\nwindow = 10.0\n"
CHANGE = RECEDING + f"""
[path_change]
t = {T_JOIN}
waypoints = [ {{ x = {WAYPOINT.x}, y = {WAYPOINT.y}, t = {WAYPOINT.t}, heading = {WAYPOINT.heading!r} }} ]
plan = {{ u_min = [0.0, -0.5], u_max = [2.0, 0.5] }}
"""
SAMPLING = "[sampling]\nperiod = 0.05\n"
# The run starts 1 m behind and 1 m aside of the plan (paper_fig1's [initial]); the shipped planned
# runs must end within 15% of that (test_planned_scenarios.py, test_unstable_plans.py), and so
# must a run whose path changed: the vehicle joined the new path.
FINAL_TOLERANCE = 0.15 * math.hypot(1.0, 1.0)
# The windows before the join are the unchanged run's (the same inputs from the same states,
# integrated by the same code): their q_d is the same to round-off. After it the two paths part
# by metres.
SAME_PATH = 1e-9


def fig1_text(extra: str) -> str:
    with open(hc.scenario_path("paper_fig1")) as f:
        text = f.read()
    return text.replace("[solver]", extra + "\n[solver]")


def fig1_horizon() -> hc.RecedingHorizon:
    """paper_fig1's design (gamma 5, Q = Qf = I) over windows of 10 s, a new one every 1 s: the
    horizon of fig1_text(CHANGE)."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    return hc.RecedingHorizon(scenario.model, scenario.desired_q0, scenario.desired_u, scenario.t0, np.eye(6),
                              np.eye(6), scenario.gamma, hc.RecedingHorizonOptions(window=10.0, update=1.0),
                              scenario.solver)


@pytest.fixture(autouse=True)
def plan_cache(tmp_path_factory, monkeypatch):
    """A plan cache of this test session only (the programs started by the tests get it too)."""
    folder = tmp_path_factory.getbasetemp() / "hinf_cpp_cache"
    monkeypatch.setenv("HINF_CPP_CACHE", str(folder))
    return folder


def write(tmp_path, text: str, name: str = "change.toml") -> pathlib.Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def distance_to(q: np.ndarray, waypoint: Waypoint) -> float:
    """|p - (x, y)| of a ship state [u, v, r, x, y, psi]."""
    return float(math.hypot(q[3] - waypoint.x, q[4] - waypoint.y))


@pytest.mark.ipopt
@pytest.mark.parametrize("loop", ["continuous", "sampled"])
def test_a_planned_path_change_is_joined_and_tracked(tmp_path, loop):
    sampling = SAMPLING if loop == "sampled" else ""
    planned = load_planned(write(tmp_path, fig1_text(CHANGE + sampling)))
    assert planned.plan is None  # [desired] gives its inputs
    new_path = planned.path_change_plan
    assert new_path.t0 == T_JOIN and new_path.tf == 40.0 and not new_path.states_given
    assert new_path.report.waypoint_errors[0] <= TOLERANCE
    # The planned inputs took the place of the planning keys, held beyond tf for the last windows.
    change = planned.document["path_change"]
    assert sorted(change) == ["t", "u1", "u2"] and change["u1"]["table"]["interpolation"] == "linear"
    assert change["u1"]["table"]["t"][0] == T_JOIN and change["u1"]["table"]["t"][-1] > 40.0

    result = hc.run_scenario(planned.scenario)
    unchanged = hc.run_scenario(hc.load_scenario(write(tmp_path, fig1_text(RECEDING + sampling), "unchanged.toml")))
    assert result.simulation.status == unchanged.simulation.status == hc.RunStatus.completed
    t, q_d = result.simulation.t, result.simulation.q_d
    assert t[-1] == 40.0 and np.array_equal(t, unchanged.simulation.t)
    # Before the join the desired path is the unchanged run's: they share the inputs until t_join.
    before = t <= T_JOIN
    assert np.max(np.abs(q_d[before] - unchanged.simulation.q_d[before])) <= SAME_PATH
    # At tf the run's q_d (the windows chained through the change, integrated by the run, not by
    # the planner) is at the new waypoint, within the planner's tolerance: the optimizer aims
    # 10 max_mismatch = 1e-5 m inside it, and the windows' integration differs from the plan's
    # re-simulation by the integrators' errors (rtol 1e-10 over 20 s: ~1e-8 m). Where the
    # unchanged path ends is 23 m away.
    assert distance_to(q_d[-1], WAYPOINT) <= TOLERANCE
    assert abs(hc.wrap_angle(q_d[-1, 5] - WAYPOINT.heading)) <= HEADING_TOLERANCE
    assert distance_to(unchanged.simulation.q_d[-1], WAYPOINT) > 20.0
    # The vehicle joined the new path: tracked from 1.41 m off to the shipped planned runs' bound.
    # (Measured: 0.046 m in the continuous loop and in the sampled one; unchanged, 0.038 m.)
    assert result.metrics.final_position_error < FINAL_TOLERANCE
    if loop == "sampled":
        assert result.online.lost == 0


@pytest.mark.ipopt
def test_desired_and_path_change_planned_in_one_file(tmp_path):
    """[desired] planned straight along x at 1 m/s and, at t = 20 s, a lane change of 4 m to the
    left planned from the desired state of the planned [desired]."""
    desired = ("[desired]\nq0 = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]\n"
               "waypoints = [ { x = 20.0, y = 0.0, t = 20.0, heading = 0.0 },\n"
               "              { x = 40.0, y = 0.0, t = 40.0, heading = 0.0 } ]\n"
               "plan = { u_min = [0.0, -0.5], u_max = [2.0, 0.5] }\n")
    change = ("[receding_horizon]\nwindow = 10.0\n\n[path_change]\nt = 20.0\n"
              "waypoints = [ { x = 40.0, y = 4.0, t = 40.0, heading = 0.0 } ]\n"
              "plan = { u_min = [0.0, -0.5], u_max = [2.0, 0.5] }\n")
    text = fig1_text(change)
    start, end = text.index("[desired]"), text.index("[controller]")
    text = text[:start] + desired + "\n" + text[end:]
    planned = load_planned(write(tmp_path, text))
    assert [table for table, _ in planned.plans()] == ["[desired]", "[path_change]"]
    # The new path starts where the planned [desired] is at t = 20 s: the horizon's chained windows
    # there against the desired plan's one re-simulation, equal to the integrators' errors (rtol
    # 1e-10 over 20 s) and well within the plan's max_mismatch (1e-6).
    joined = np.asarray(planned.path_change_plan.q0)
    np.testing.assert_allclose(joined, planned.plan.trajectory.q_d(20.0), rtol=0, atol=1e-6)
    assert distance_to(joined, Waypoint(20.0, 0.0)) <= TOLERANCE
    # [desired]'s tables are held beyond tf too (the windows of the receding horizon reach past it).
    assert planned.document["desired"]["u1"]["table"]["t"][-1] > 40.0
    result = hc.run_scenario(planned.scenario)
    lane = Waypoint(40.0, 4.0)
    assert distance_to(result.simulation.q_d[-1], lane) <= TOLERANCE  # 4 m off the unchanged plan's (40, 0)
    assert result.metrics.final_position_error < FINAL_TOLERANCE


@pytest.mark.ipopt
def test_plan_path_change_with_a_receding_horizon(tmp_path):
    horizon = fig1_horizon()
    new_path = plan_path_change(horizon, T_JOIN, [WAYPOINT], options=BOUNDS,
                                cache_dir=default_cache_dir())
    # From the horizon's desired state at the join, to the last waypoint's time.
    assert np.array_equal(new_path.q0, horizon.desired_state(T_JOIN))
    assert (new_path.t0, new_path.tf) == (T_JOIN, 40.0)
    # The run to tf = 40 s solves windows up to the one of tf (and the online controller the one
    # after it): the inputs are held that far.
    changed = horizon.with_path_change(T_JOIN, new_path.inputs(hold_until=40.0 + 1.0 + 10.0))
    assert [t for t, _ in changed.path_changes()] == [T_JOIN] and horizon.path_changes() == []
    assert distance_to(changed.desired_state(40.0), WAYPOINT) <= TOLERANCE
    assert distance_to(horizon.desired_state(40.0), WAYPOINT) > 20.0  # the horizon itself is unchanged
    scenario = hc.load_scenario(write(tmp_path, fig1_text(CHANGE)))
    run, report = hc.simulate_receding_horizon(changed, scenario.disturbance, scenario.initial_q0, 40.0,
                                               scenario.simulation_options())
    assert report.windows == 40
    assert distance_to(run.q_d[-1], WAYPOINT) <= TOLERANCE
    assert np.hypot(*(run.q[-1, 3:5] - run.q_d[-1, 3:5])) < FINAL_TOLERANCE
    # The scenario file plans the same path (from the cache this plan wrote) and runs the same loop.
    assert scenario.path_change.t == T_JOIN
    np.testing.assert_array_equal(scenario.path_change.u_d(40.0), new_path.inputs()(40.0))
    assert np.array_equal(hc.run_scenario(scenario).simulation.q, run.q)
    # The online controller takes the same change before the window of t_join is solved.
    controller = hc.RecedingOnlineController(horizon, 0.05, background=False)
    controller.reset(0.0, scenario.initial_q0)
    controller.change_path(T_JOIN, new_path.inputs(hold_until=51.0))
    # A second change joins after the first.
    with pytest.raises(ValueError, match=r"after the horizon's last one \(at 20 s\)"):
        plan_path_change(changed, T_JOIN, [WAYPOINT], options=BOUNDS)


@pytest.mark.parametrize("t_join, match", [
    (20.7, r"t_join = 20.7 s is not a window's start: .*update = 1 s\); the nearest is 21 s"),
    (20.2, r"t_join = 20.2 s is not a window's start: .*the nearest is 20 s"),
    (0.0, r"t_join = 0 s: a path change joins after the horizon's t0 = 0 s, .* e\.g\. 1 s"),
    (-3.0, r"after the horizon's t0"),
    (math.nan, r"after the horizon's t0"),
])
def test_plan_path_change_refuses_a_join_that_is_not_a_windows_start(t_join, match):
    """Refused before planning (no IPOPT), naming the nearest window's start."""
    with pytest.raises(ValueError, match=match):
        plan_path_change(fig1_horizon(), t_join, [WAYPOINT], options=BOUNDS)


# The tests' directionally unstable vessel (test_unstable_plans.py: Fossen form, unstable above
# 0.84 m/s) going straight at 1 m/s (tau_u = 20 N holds it; straight, its instability is not
# excited), then planned through an S from t = 10 s.
VESSEL = hc.FossenVesselParameters(M=np.diag([100.0, 200.0, 50.0]), D=np.diag([20.0, 100.0, 70.0]))
VESSEL_BOUNDS = PlanOptions(u_min=(0.0, -30.0), u_max=(60.0, 30.0))


@pytest.mark.ipopt
def test_a_new_path_along_which_the_vehicle_is_unstable_is_refused():
    horizon = hc.RecedingHorizon(hc.FossenVessel(VESSEL), [1.0, 0.0, 0.0, 0.0, 0.0, 0.0], [20.0, 0.0], 0.0,
                                 100.0 * np.eye(6), 100.0 * np.eye(6), 5.0,
                                 hc.RecedingHorizonOptions(window=10.0, update=1.0))
    s_curve = [Waypoint(40.0, 4.0, t=40.0), Waypoint(70.0, 0.0, t=70.0), Waypoint(100.0, 0.0, t=100.0, heading=0.0)]
    with pytest.raises(ValueError, match=r"open-loop unstable along it .* a path change takes inputs only.* "
                                         r"Plan over a shorter time"):
        plan_path_change(horizon, 10.0, s_curve, options=VESSEL_BOUNDS)
    # What the message suggests: over 60 s instead of 90 the re-simulation meets max_mismatch
    # (doubling the substeps brings it there), and the plan is given as inputs.
    shorter = plan_path_change(horizon, 10.0, s_curve[:1] + [Waypoint(70.0, 0.0, t=70.0, heading=0.0)],
                               options=VESSEL_BOUNDS)
    assert not shorter.states_given and shorter.report.position_mismatch <= VESSEL_BOUNDS.max_mismatch


def test_needs_planning_sees_the_path_change():
    assert needs_planning(tomllib.loads(fig1_text(CHANGE)))
    assert not needs_planning(tomllib.loads(fig1_text(CHANGE.split("waypoints")[0] + "u1 = 1.0\nu2 = 0.0\n")))
    assert hc._core.needs_planning_toml(fig1_text(CHANGE), "change.toml")


@pytest.mark.parametrize("old, new, match", [
    ("plan = {", 'path = { x = [0.0], y = [32.0], speed = 1.0 }\nplan = {',
     r"\[path_change\] give either waypoints or path \(docs/planning.md\), not both"),
    ("waypoints = [", "# waypoints = [", r"\[path_change\] give either waypoints or path .*got neither"),
    ("plan = {", "u1 = 1.0\nu2 = 0.0\nplan = {", r"\[path_change\] u1: give the inputs or waypoints"),
    ("u_max = [2.0, 0.5]", "u_max = [2.0]", r"\[path_change.plan\] u_max needs one number per input \(2\), got 1"),
    ("plan = {", "plan = { tolerence = 0.1 }\n# {", r"\[path_change.plan\]: unknown key 'tolerence'"),
    ("heading =", "z = 1.0, heading =", r"\[path_change\] waypoints\[0\]: unknown key 'z'"),
    ("t = 20.0", "t = 20.5", r"\[path_change\] t_join = 20.5 s is not a window's start: .*the nearest is 20 s"),
    ("window = 10.0", "window = 10.0\n[measurement]\nsigma = 0.5", r"add \[sampling\]"),
])
def test_path_change_planning_errors_name_the_file_and_table(tmp_path, old, new, match):
    """Refused before planning (no IPOPT); through hc.load_scenario like any scenario file."""
    assert old in CHANGE, f"test bug: {old!r} not in CHANGE"
    path = write(tmp_path, fig1_text(CHANGE.replace(old, new, 1)), "bad.toml")
    with pytest.raises(ValueError, match=match) as caught:
        hc.load_scenario(path)
    assert str(caught.value).startswith(f"{path}: ")


@pytest.mark.ipopt
def test_an_unreachable_path_change_waypoint_names_the_table(tmp_path):
    """200 m in 20 s for a ship that cannot exceed 2 m/s: refused before optimizing."""
    path = write(tmp_path, fig1_text(CHANGE.replace(f"x = {WAYPOINT.x}", "x = 200.0")), "far.toml")
    with pytest.raises(UnreachableWaypointError, match=r"cannot be reached .* found before optimizing") as caught:
        hc.load_scenario(path)
    assert str(caught.value).startswith(f"{path}: [path_change] waypoints[0] (x = 200, y = 32, t = 40")
    assert caught.value.index == 0


@pytest.mark.ipopt
def test_a_path_given_as_samples(tmp_path):
    """path = { x, y, speed }: timed from the desired position at t (6.83, 12.69) along the samples."""
    text = fig1_text(CHANGE.replace(f"waypoints = [ {{ x = {WAYPOINT.x}, y = {WAYPOINT.y}, t = {WAYPOINT.t}, "
                                    f"heading = {WAYPOINT.heading!r} }} ]",
                                    "path = { x = [6.0, 4.0], y = [20.0, 30.0], speed = 1.0 }"))
    planned = load_planned(write(tmp_path, text))
    waypoints = planned.path_change_plan.waypoints
    start = planned.path_change_plan.q0[3:5]
    # The first sample is reached at 1 m/s from the start position, the second 10.2 m further on.
    assert waypoints[0].t == pytest.approx(T_JOIN + math.hypot(6.0 - start[0], 20.0 - start[1]), rel=1e-12)
    assert waypoints[1].t - waypoints[0].t == pytest.approx(math.hypot(2.0, 10.0), rel=1e-12)
    result = hc.run_scenario(planned.scenario)
    q_d = result.simulation.q_d[np.searchsorted(result.simulation.t, waypoints[1].t)]
    assert distance_to(q_d, Waypoint(4.0, 30.0)) <= TOLERANCE + 0.02  # + the output grid: 0.01 s at 1 m/s


@pytest.mark.ipopt
@pytest.mark.skipif(not ((BIN / "hinf-sim").exists() and (BIN / "hinf-cpp").exists()),
                    reason="hinf-sim / hinf-cpp are not installed next to this Python")
def test_hinf_sim_refuses_the_planning_keys_and_runs_the_written_file(tmp_path):
    def run(*args, code=0):
        done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=600,
                              env=dict(os.environ))
        assert done.returncode == code, done.stderr
        return done

    path = write(tmp_path, fig1_text(CHANGE))
    refused = run(BIN / "hinf-sim", path, code=2)
    assert refused.stderr.count("\n") == 1, refused.stderr
    assert "[path_change] waypoints" in refused.stderr and "hinf-cpp plan" in refused.stderr
    written = tmp_path / "planned.toml"
    planning = run(BIN / "hinf-cpp", "plan", path, "-o", written, "--json", tmp_path / "plan.json")
    assert "planned the path change at t = 20 s through 1 waypoints" in planning.stdout
    change = tomllib.loads(written.read_text())["path_change"]
    assert sorted(change) == ["t", "u1", "u2"] and change["u2"]["table"]["interpolation"] == "linear"
    report = json.loads((tmp_path / "plan.json").read_text())["path_change"]
    assert report["t"] == T_JOIN and report["report"]["waypoint_errors"][0] <= TOLERANCE
    run(BIN / "hinf-sim", written, "--json", tmp_path / "sim.json")
    cpp = run(BIN / "hinf-cpp", "run", path, "--json", tmp_path / "cpp.json")
    assert "planned the path change at t = 20 s" in cpp.stdout and "from the cache" in cpp.stdout
    numbers_close(json.loads((tmp_path / "sim.json").read_text()), json.loads((tmp_path / "cpp.json").read_text()))


@pytest.mark.ipopt
def test_the_documented_scenario_is_the_tested_one(tmp_path):
    """docs/planning.md's complete scenario runs as the file of these tests and ends where the
    text says."""
    text = (ROOT / "docs" / "planning.md").read_text()
    section = text[text.index("## A path changed under way"):text.index("## The plan cache")]
    block = re.search(r"```toml\n(.*?)```", section, flags=re.S).group(1)
    documented = hc.run_scenario(load_planned(write(tmp_path, block, "documented.toml")).scenario)
    tested = hc.run_scenario(load_planned(write(tmp_path, fig1_text(CHANGE))).scenario)
    assert np.array_equal(documented.simulation.q, tested.simulation.q)
    assert f"ends {tested.metrics.final_position_error:.3f} m from the new path" in section
