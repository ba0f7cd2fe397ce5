"""Scenario files planned from waypoints or a path (docs/planning.md): every shipped planned
scenario (re-simulation within 1e-6 of the plan, waypoints met, tracking converges, hinf-sim on
the written scenario gives the results of hinf-cpp run), the plan cache, and the messages for
what is wrong in the planning keys."""

from __future__ import annotations

import json
import os
import pathlib
import shutil
import subprocess
import sys
import tomllib

import numpy as np
import pytest

import hinf_cpp as hc
from _support import numbers_close

pytest.importorskip("casadi")

from hinf_cpp.scenario.planned import load_planned, plan_scenario, planned_scenario_toml  # noqa: E402
from hinf_cpp.planning.planner import UnreachableWaypointError  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
PLANNED = sorted((ROOT / "scenarios" / "planned").glob("*.toml"))
BIN = pathlib.Path(sys.executable).parent
LANE = (ROOT / "scenarios" / "planned" / "ship_lane_change.toml").read_text()


@pytest.fixture(autouse=True)
def trusted_code(monkeypatch):
    """The scenarios here name models that are code, written by these tests: trusted
    (docs/trust.md; test_trust.py checks the refusal without it). Subprocesses inherit it."""
    monkeypatch.setenv("HINF_TRUST_CODE", "1")



@pytest.fixture(autouse=True)
def plan_cache(tmp_path_factory, monkeypatch):
    """A cache of this test session only (the programs started by the tests get it too)."""
    folder = tmp_path_factory.getbasetemp() / "hinf_cpp_cache"
    monkeypatch.setenv("HINF_CPP_CACHE", str(folder))
    return folder


def mutate(text: str, old: str, new: str) -> str:
    assert old in text, f"test bug: {old!r} not in the scenario text"
    return text.replace(old, new)


def test_the_shipped_planned_scenarios():
    names = {path.stem for path in PLANNED}
    for vehicle in ("ship", "hovercraft"):
        for pattern in ("lane_change", "figure_eight", "lawnmower", "docking"):
            assert f"{vehicle}_{pattern}" in names
    assert hc.scenario_path("planned/ship_lane_change").is_file()


@pytest.mark.ipopt
@pytest.mark.parametrize("path", PLANNED, ids=[path.stem for path in PLANNED])
def test_shipped_plan_is_feasible_and_tracked(path):
    planned = load_planned(path)
    report = planned.plan.report
    # The paper's feasibility, checked: the project's integrator re-simulates q_d from the
    # planned u_d to within 1e-6 m of the planned states (at every node).
    assert report.position_mismatch < 1e-6
    options = tomllib.loads(path.read_text())["desired"]["plan"]
    assert max(report.waypoint_errors) <= options.get("tolerance", 0.05)
    for error in report.heading_errors:
        assert error is None or error <= options.get("heading_tolerance", 0.01)
    for error in report.speed_errors:
        assert error is None or error <= options.get("speed_tolerance", 0.01)
    # Inside the input bounds.
    assert np.all(planned.plan.u >= np.array(options["u_min"]) - 1e-9)
    assert np.all(planned.plan.u <= np.array(options["u_max"]) + 1e-9)
    # The tracking converges: from 1.41 m off at t0 to a small fraction of it.
    result = hc.run_scenario(planned.scenario)
    assert result.simulation.status == hc.RunStatus.completed
    assert result.metrics.max_position_error >= np.hypot(1.0, 1.0) - 1e-12
    assert result.metrics.final_position_error < 0.15 * np.hypot(1.0, 1.0)


@pytest.mark.ipopt
@pytest.mark.skipif(not ((BIN / "hinf-sim").exists() and (BIN / "hinf-cpp").exists()),
                    reason="hinf-sim / hinf-cpp are not installed next to this Python")
@pytest.mark.parametrize("path", PLANNED, ids=[path.stem for path in PLANNED])
def test_hinf_sim_on_the_written_scenario_equals_hinf_cpp_run(path, tmp_path):
    def run(*args):
        done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=600,
                              env=dict(os.environ))
        assert done.returncode == 0, done.stderr
        return done

    written = tmp_path / "planned.toml"
    run(BIN / "hinf-cpp", "plan", path, "-o", written, "--json", tmp_path / "plan.json")
    run(BIN / "hinf-sim", written, "--json", tmp_path / "sim.json")
    cpp = run(BIN / "hinf-cpp", "run", path, "--json", tmp_path / "cpp.json")
    assert "planned u_d through" in cpp.stdout and "from the cache" in cpp.stdout
    numbers_close(json.loads((tmp_path / "sim.json").read_text()), json.loads((tmp_path / "cpp.json").read_text()))
    report = json.loads((tmp_path / "plan.json").read_text())["report"]
    assert report["position_mismatch"] < 1e-6
    # hinf-sim refuses the file with the waypoints and says what to do.
    refused = subprocess.run([str(BIN / "hinf-sim"), str(path)], capture_output=True, text=True, timeout=60)
    assert refused.returncode == 2
    assert "needs the planner of the Python package" in refused.stderr and "hinf-cpp plan" in refused.stderr


@pytest.mark.ipopt
def test_the_cache_reads_back_the_same_plan(tmp_path, monkeypatch):
    plan_cache = tmp_path / "cache"  # empty: this test's own
    monkeypatch.setenv("HINF_CPP_CACHE", str(plan_cache))
    path = tmp_path / "lane.toml"
    path.write_text(LANE)
    first = load_planned(path)
    again = load_planned(path)
    assert not first.plan.report.cache_hit and again.plan.report.cache_hit
    np.testing.assert_array_equal(again.plan.u, first.plan.u)
    np.testing.assert_array_equal(again.plan.t, first.plan.t)
    assert again.plan.report.position_mismatch == first.plan.report.position_mismatch
    # Another option is another plan.
    path.write_text(mutate(LANE, "tolerance = 0.05", "tolerance = 0.04"))
    other = load_planned(path)
    assert not other.plan.report.cache_hit and max(other.plan.report.waypoint_errors) <= 0.04
    # A damaged cache file is planned anew.
    for file in (plan_cache / "plans").glob("*.json"):
        file.write_text("{")
    path.write_text(LANE)
    assert not load_planned(path).plan.report.cache_hit


@pytest.mark.ipopt
def test_load_scenario_and_dict_plan_too(tmp_path):
    path = tmp_path / "lane.toml"
    path.write_text(LANE)
    from_file = hc.load_scenario(path)
    from_dict = hc.scenario_from_dict(tomllib.loads(LANE), str(path))
    times = np.linspace(0.0, 60.0, 301)
    np.testing.assert_array_equal(from_file.desired_u(times), from_dict.desired_u(times))
    assert all(s.interpolation() == hc.Interpolation.linear for s in from_file.desired_u.channels())


@pytest.mark.parametrize("old,new,match", [
    ("{ x = 20.0, y = 0.0, t = 20.0, heading = 0.0 }", "{ x = 20.0, y = 0.0, t = 20.0, z = 1.0 }",
     r"\[desired\] waypoints\[0\]: unknown key 'z' \(known keys: x, y, t, heading, speed\)"),
    ("{ x = 20.0, y = 0.0, t = 20.0, heading = 0.0 }", "{ y = 0.0, t = 20.0 }", r"waypoints\[0\]: x is required"),
    ("{ x = 20.0, y = 0.0, t = 20.0, heading = 0.0 }", "{ x = \"20\", y = 0.0, t = 20.0 }",
     r"waypoints\[0\].x: expected a number, got a string"),
    ("tolerance = 0.05", "tolerence = 0.05", r"\[desired.plan\]: unknown key 'tolerence'"),
    ("tolerance = 0.05", "tolerance = -0.05", r"\[desired.plan\] tolerance must be a finite number > 0"),
    ("u_max = [2.0, 0.5]", "u_max = [2.0]", r"\[desired.plan\] u_max needs one number per input \(2\), got 1"),
    ("[desired.plan]", "u1 = 1.0\n[desired.plan]", r"\[desired\] u1: give the inputs or waypoints"),
    ("{ x = 60.0, y = 3.5, t = 60.0, heading = 0.0 },", "{ x = 60.0, y = 3.5, t = 61.0, heading = 0.0 },",
     r"waypoints\[2\] .* comes after the end of the horizon tf = 60"),
])
def test_planning_keys_errors_name_the_file_and_key(tmp_path, old, new, match):
    path = tmp_path / "bad.toml"
    path.write_text(mutate(LANE, old, new))
    with pytest.raises(ValueError, match=match) as caught:
        hc.load_scenario(path)
    assert str(caught.value).startswith(f"{path}: ")


@pytest.mark.ipopt
@pytest.mark.skipif(not (BIN / "hinf-cpp").exists(), reason="needs the hinf-cpp command")
def test_an_unreachable_waypoint_in_a_file(tmp_path):
    """The planner's UnreachableWaypointError (test_planner.py) from a file, through the command
    line: one line naming the file, the section and the waypoint; exit status 2."""
    path = tmp_path / "far.toml"
    # The lane change on 40 s with its second waypoint 100 m too far (the ship makes 2 m/s at
    # most, 6 m/s are needed): refused before optimizing, as test_planner's far waypoint.
    text = mutate(LANE, "tf = 60.0", "tf = 40.0")
    text = mutate(text, "  { x = 40.0, y = 3.5, t = 40.0, heading = 0.0 },\n  { x = 60.0, y = 3.5, t = 60.0, heading = 0.0 },",
                  "  { x = 140.0, y = 3.5, t = 40.0 },")
    path.write_text(text)
    done = subprocess.run([str(BIN / "hinf-cpp"), "run", str(path)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1, done.stderr
    assert done.stderr.startswith(f"hinf-cpp: error: {path}: [desired] waypoints[1] (x = 140, y = 3.5, t = 40) "
                                  "cannot be reached"), done.stderr


FIRST_WAYPOINT = "{ x = 20.0, y = 0.0, t = 20.0, heading = 0.0 }"


@pytest.mark.ipopt
@pytest.mark.parametrize("first,error,match", [
    ("{ x = 200.0, y = 0.0, t = 20.0 }", UnreachableWaypointError,
     (r"\[desired\] waypoints\[0\] \(x = 200, y = 0, t = 20\) cannot be reached with the input bounds u1 in "
      r"\[0, 2\], u2 in \[-0.5, 0.5\] by t = 20: it is 199.9 from the start \(x = 0, y = 0\) at t = 0 .*found before "
      r"optimizing")),
    ("{ x = 20.0, y = 0.0, t = 20.0, heading = 1e300 }", ValueError,
     r"\[desired\] waypoints\[0\]\.heading = 1e\+300 rad is too large to compare modulo 2 pi"),
], ids=["out of reach", "heading 1e300"])
def test_a_bad_first_waypoint_is_named_before_optimizing(tmp_path, first, error, match):
    """A first waypoint far out of reach, or with heading = 1e300, used to cost the whole
    iteration budget and end in a PlanningError that names no waypoint. A budget of 3
    iterations: any solve runs out of it."""
    path = tmp_path / "first.toml"
    text = mutate(mutate(LANE, FIRST_WAYPOINT, first), "tolerance = 0.05", "tolerance = 0.05\nmax_iterations = 3")
    path.write_text(text)
    with pytest.raises(error, match=match) as caught:
        hc.load_scenario(path)
    assert str(caught.value).startswith(f"{path}: [desired] waypoints[0]")


def test_models_the_planner_cannot_use(tmp_path):
    text = mutate(LANE, 'kind = "ship"', 'kind = "casadi"\nfile = "model.json"')
    with pytest.raises(ValueError, match=r"model.json|kind = \"casadi\""):
        plan_scenario(tomllib.loads(text), str(tmp_path / "x.toml"))


@pytest.mark.ipopt
def test_a_symbolic_model_named_by_a_python_callable(tmp_path):
    """kind = "python" naming a SymbolicModel (the ship's statement, hinf_cpp.models.builtin:ship):
    planned with its own expressions, compiled from CasADi, and the same plan as the built-in ship's."""
    path = tmp_path / "lane.toml"
    path.write_text(mutate(LANE, 'kind = "ship"', 'kind = "python"\ncallable = "hinf_cpp.models.builtin:ship"'))
    planned = load_planned(path)
    builtin = plan_scenario(tomllib.loads(LANE), "lane.toml")
    assert planned.plan.report.position_mismatch < 1e-6
    assert planned.plan.model.name() == "ship"
    # The same statement, one route compiled from CasADi at run time: the same optimum to IPOPT's
    # tolerance (1e-9 relative), far below the inputs' size (~1).
    np.testing.assert_allclose(planned.plan.u, builtin.plan.u, atol=1e-6)


@pytest.mark.ipopt
def test_a_written_planned_file_does_not_point_into_the_cache(tmp_path, monkeypatch):
    """A SymbolicModel named by kind = "python" is compiled into the compile cache; the planned
    file written for hinf-sim must not name it there (deleting the cache is always safe): the
    model is copied beside the file and named relative to it."""
    cache = tmp_path / "cache"  # this test's own: deleted below
    monkeypatch.setenv("HINF_CPP_CACHE", str(cache))
    path = tmp_path / "lane.toml"
    path.write_text(mutate(LANE, 'kind = "ship"', 'kind = "python"\ncallable = "hinf_cpp.models.builtin:ship"'))
    planned = load_planned(path)
    assert pathlib.Path(planned.scenario.model.metadata_path()).parent == cache
    out = tmp_path / "out" / "planned.toml"
    out.parent.mkdir()
    text = planned_scenario_toml(planned, out)
    out.write_text(text)
    assert str(cache) not in text
    written = tomllib.loads(text)["model"]
    assert written["kind"] == "casadi" and written["file"].startswith("planned.models/")
    copied = sorted(p.suffix for p in (out.parent / "planned.models").iterdir())
    assert copied == [".c", ".json", ".so"]
    expected = hc.run_scenario(planned.scenario)
    shutil.rmtree(cache)
    moved = tmp_path / "moved"  # the folder moves with the file
    shutil.move(out.parent, moved)
    result = hc.run_scenario(hc.load_scenario(moved / "planned.toml"))
    assert result.metrics.final_position_error == expected.metrics.final_position_error
    # A built-in model: written as hinf_cpp.scenario_toml writes it, nothing copied.
    builtin = plan_scenario(tomllib.loads(LANE), "lane.toml")
    assert planned_scenario_toml(builtin, tmp_path / "builtin.toml") == hc._core.scenario_toml(builtin.scenario)
    assert not (tmp_path / "builtin.models").exists()
