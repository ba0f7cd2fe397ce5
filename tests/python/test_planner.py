"""The trajectory planner (hinf_cpp.planning.planner, docs/planning.md): the CasADi statements of the
built-in models against the C++ models; round trips (simulate a known u_d, sample waypoints
from its path, plan through them: every waypoint met, the re-simulation within 1e-6 of the
planned states, checked again with SciPy's integrator); an unreachable waypoint is a clear
error, fast; bad arguments."""

from __future__ import annotations

import json
import math
import os
import shutil
import stat

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import hinf_cpp as hc
from _support import ROUNDOFF

ca = pytest.importorskip("casadi")

from hinf_cpp.planning.planner import (PlanOptions, UnreachableWaypointError, Waypoint, plan,  # noqa: E402
                              time_grid, waypoints_from_path)
from hinf_cpp.models.builtin import symbolic_model  # noqa: E402
from hinf_cpp.models.codegen import CacheDirectoryError  # noqa: E402

BUILT_IN = {
    "ship": hc.ShipModel(hc.ShipParameters(m_u=0.6, m_v=-1.5, m_r=0.4, d_u=1.1, d_v=2.5, d_r=0.9)),
    "fossen_vessel": hc.FossenVessel(),
    "hovercraft": hc.Hovercraft(hc.HovercraftParameters(d=0.3, d_r=0.7)),
    "pvtol": hc.PlanarVtol(hc.PlanarVtolParameters(g=1.0, epsilon=0.2)),
    "auv": hc.Auv(),
    "linear": hc.LinearModel(np.array([[0.0, 1.0], [-2.0, -0.5]]), np.array([[0.0], [1.0]]), np.eye(2),
                             np.array([[1.0, 0.0]])),
}


# ---- the built-in models in CasADi ----

@pytest.mark.parametrize("name", BUILT_IN)
def test_symbolic_statement_matches_the_cpp_model(name):
    model = BUILT_IN[name]
    symbolic = symbolic_model(model)
    functions = {f.name(): f for f in symbolic.functions()}
    assert (symbolic.n, symbolic.m, symbolic.nw) == (model.n(), model.m(), model.nw())
    assert symbolic.state_names == model.state_names()
    assert symbolic.position_indices == model.position_indices()
    assert symbolic.heading_index == model.heading_index()
    assert symbolic.noise_channels == model.noise_channels()
    # The statement's parameters at the object's values (the planner evaluates it so).
    p = [symbolic.parameter_values[name] for name in symbolic.parameter_names]
    np.testing.assert_array_equal(np.asarray(functions["C"](0.0, p)), model.C(0.0))
    rng = np.random.default_rng(31)
    for _ in range(20):
        # States of the size a vehicle meets (speeds ~ 1, angles ~ pi), both signs.
        q = rng.normal(scale=2.0, size=model.n())
        for label, expected in (("f", model.f(0.0, q)), ("G", model.G(0.0, q)), ("D", model.D(0.0, q)),
                                ("dfdq", model.dfdq(0.0, q))):
            value = np.asarray(functions[label](0.0, q, p)).reshape(np.shape(expected))
            # The built-in vehicles' C++ equations are compiled from these statements (the
            # LinearModel's are written in C++): the same formulas evaluated by CasADi's virtual
            # machine and by its generated code, round-off of the terms, at most 1e3 (the AUV's
            # drag in N at 2 m/s).
            scale = max(1.0, np.abs(expected).max()) * 1e3
            np.testing.assert_allclose(value, expected, rtol=0, atol=ROUNDOFF * scale, err_msg=f"{name} {label}")


def test_models_without_expressions_are_refused():
    class Drift(hc.Model):
        def n(self):
            return 2

        def m(self):
            return 1

        def nw(self):
            return 0

        def f(self, t, q):
            return np.zeros(2)

        def G(self, t, q):
            return np.ones((2, 1))

        def D(self, t, q):
            return np.zeros((2, 0))

    for model in (Drift(), hc.FleetModel(hc.ShipModel(), 2)):
        with pytest.raises(ValueError, match="has no CasADi form: planning needs the model's equations as CasADi"):
            symbolic_model(model)


# ---- round trips ----

def sampled_waypoints(model, q0, u_d, t0, tf, every, heading=False):
    """Waypoints every `every` s on the path of the model driven by u_d (its trajectory, at
    rtol 1e-10), with their times (and headings)."""
    trajectory = hc.Trajectory(model, q0, u_d, t0, tf)
    x, y = model.position_indices()
    out = []
    for t in np.arange(t0 + every, tf + 1e-9, every):
        q = trajectory.q_d(t)
        out.append(Waypoint(float(q[x]), float(q[y]), t=float(t),
                            heading=float(q[model.heading_index()]) if heading else None))
    return out


def scipy_states(model, plan_result):
    """q at the plan's nodes, integrated by SciPy (DOP853, rtol 1e-12) from the plan's inputs,
    linear between the nodes as np.interp gives them: independent of the library's integrator."""
    t, u = plan_result.t, plan_result.u

    def rhs(time_, q):
        u_now = np.array([np.interp(time_, t, u[:, i]) for i in range(u.shape[1])])
        return model.f(time_, q) + model.G(time_, q) @ u_now

    solution = solve_ivp(rhs, (t[0], t[-1]), plan_result.q[0], method="DOP853", t_eval=t, rtol=1e-12, atol=1e-12,
                         max_step=float(np.min(np.diff(t))))
    return solution.y.T


@pytest.mark.ipopt
@pytest.mark.parametrize("name,model,q0,u_d,bounds", [
    ("ship", hc.ShipModel(), [1.0, 0.0, 0.0, 0.0, 0.0, 0.0], [1.0, hc.Signal(0.0, [hc.Harmonic(0.3, 0.2)])],
     ((0.0, -1.0), (2.0, 1.0))),
    ("hovercraft", hc.Hovercraft(), [0.0, 0.0, 0.0, 1.0, 0.0, 0.0],
     [0.2, hc.Signal(0.0, [hc.Harmonic(0.15, 0.3)])], ((-0.5, -0.5), (0.5, 0.5))),
])
def test_round_trip_through_sampled_waypoints(name, model, q0, u_d, bounds):
    waypoints = sampled_waypoints(model, np.array(q0), u_d, 0.0, 40.0, every=5.0, heading=True)
    options = PlanOptions(u_min=bounds[0], u_max=bounds[1], tolerance=0.02, heading_tolerance=0.01)
    result = plan(model, waypoints, q0=q0, options=options)
    report = result.report
    # Every waypoint within its tolerance, on the re-simulated (tracked) trajectory.
    assert len(report.waypoint_errors) == len(waypoints)
    assert max(report.waypoint_errors) <= options.tolerance
    assert max(report.heading_errors) <= options.heading_tolerance
    # The re-simulation matches the planned states within 1e-6 m (the report's max over nodes).
    assert report.position_mismatch <= 1e-6
    resimulated = np.array([result.trajectory.q_d(t) for t in result.t])
    x, y = model.position_indices()
    assert np.max(np.hypot(*(resimulated[:, [x, y]] - result.q[:, [x, y]]).T)) == pytest.approx(
        report.position_mismatch, rel=1e-12)
    # SciPy's integration of the same inputs (accurate to ~1e-10 here) agrees too.
    truth = scipy_states(model, result)
    assert np.max(np.hypot(*(truth[:, [x, y]] - result.q[:, [x, y]]).T)) <= 1e-6
    # The stored inputs are the optimizer's: linear between the nodes, exactly.
    times = np.linspace(result.t0, result.tf, 997)
    expected = np.column_stack([np.interp(times, result.t, result.u[:, i]) for i in range(model.m())])
    np.testing.assert_allclose(result.inputs()(times), expected, rtol=0, atol=ROUNDOFF * np.abs(result.u).max())
    # Inside the bounds (the bounds hold at the nodes, so everywhere for a linear u).
    assert np.all(result.u >= np.array(bounds[0]) - 1e-9) and np.all(result.u <= np.array(bounds[1]) + 1e-9)
    assert report.iterations > 0 and report.status == "Solve_Succeeded"


@pytest.mark.ipopt
def test_unreachable_waypoint_is_a_clear_error_fast():
    ship = hc.ShipModel()
    # Fast means few iterations, not seconds: the exact penalty meets or misses the waypoints in
    # one bounded solve (measured: 103 IPOPT iterations, then 17, 12 and 5 to confirm the
    # miss), so 400 per solve holds it to a few times that; a search for a feasible point would
    # run out of them and end in a PlanningError instead.
    options = PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5), max_iterations=400)
    # At most 2 m/s (u1 <= 2 against the surge damping 1): 60 m in the 20 s after the first
    # waypoint is out of reach (the first waypoint alone is not), but within REACH_FACTOR of
    # the top speed: the optimizer finds the miss.
    with pytest.raises(UnreachableWaypointError) as caught:
        plan(ship, [Waypoint(20.0, 0.0, t=20.0), Waypoint(80.0, 3.5, t=40.0)], q0=[1, 0, 0, 0, 0, 0], options=options)
    assert caught.value.index == 1
    message = str(caught.value)
    assert message.startswith("waypoints[1] (x = 80, y = 3.5, t = 40) cannot be reached with the input bounds "
                              "u1 in [0, 2], u2 in [-0.5, 0.5] by t = 40: the best plan comes ")
    # The ship at full speed (2 m/s) stays about 20 m short (measured: 20.04 m).
    assert caught.value.miss * options.tolerance > 10.0
    assert isinstance(caught.value, ValueError)


@pytest.mark.ipopt
@pytest.mark.parametrize("waypoints,index,start", [
    ([Waypoint(200.0, 0.0, t=20.0)], 0, "it is 198.9 from the start (x = 1, y = 0) at t = 0"),
    ([Waypoint(20.0, 0.0, t=20.0), Waypoint(200.0, 3.5, t=40.0)], 1,
     "it is 179.9 from waypoints[0] (x = 20, y = 0) at t = 20"),
], ids=["first", "second"])
def test_a_waypoint_far_out_of_reach_is_refused_before_optimizing(waypoints, index, start):
    """A first waypoint far out of reach used to cost the whole iteration budget and end in a
    PlanningError (IPOPT's feasibility restoration does not converge) that names no waypoint.
    With an iteration budget of 1 any solve runs out: the error comes before IPOPT."""
    options = PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5), max_iterations=1)
    with pytest.raises(UnreachableWaypointError) as caught:
        plan(hc.ShipModel(), waypoints, q0=[0, 0, 0, 1, 0, 0], options=options)
    w = waypoints[index]
    assert caught.value.index == index
    assert str(caught.value).startswith(
        f"waypoints[{index}] (x = {w.x:g}, y = {w.y:g}, t = {w.t:g}) cannot be reached with the input bounds u1 in "
        f"[0, 2], u2 in [-0.5, 0.5] by t = {w.t:g}: {start} (beyond the tolerances), ")
    # The ship's top speed is 2 m/s (u1 <= 2 against the surge damping 1).
    assert "more than 3 times the vehicle's top speed with constant inputs at the bounds (2;" in str(caught.value)
    assert caught.value.miss * options.tolerance > 100.0


@pytest.mark.ipopt
def test_unbounded_inputs_reach_anywhere():
    """No input bound, no top speed: nothing is refused before optimizing (a budget of 1
    iteration ends the solve)."""
    with pytest.raises(hc.HinfError, match="Maximum_Iterations_Exceeded after 1 iterations"):
        plan(hc.ShipModel(), [Waypoint(200.0, 0.0, t=20.0)], q0=[0, 0, 0, 1, 0, 0],
             options=PlanOptions(max_iterations=1))


# ---- the plan cache ----

CACHED_WAYPOINTS = [Waypoint(10.0, 0.0, t=10.0), Waypoint(20.0, 2.0, t=20.0)]
CACHED_OPTIONS = PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5), interval=1.0)


def cached_plan(cache_dir):
    return plan(hc.ShipModel(), CACHED_WAYPOINTS, q0=[1.0, 0, 0, 0, 0, 0], options=CACHED_OPTIONS, cache_dir=cache_dir)


@pytest.fixture(scope="module")
def good_entry(tmp_path_factory):
    """A plan cache with one good entry: (the plan, the entry's file)."""
    folder = tmp_path_factory.mktemp("plans") / "plans"
    first = cached_plan(folder)
    (entry,) = folder.glob("*.json")
    return first, entry


def without_stats(data):
    del data["stats"]


def stats_of_another_type(data):
    data["stats"]["iterations"] = "many"


def one_input_missing(data):
    data["u"] = [row[:1] for row in data["u"]]


def not_a_number(data):
    data["q"][3][0] = None


def another_document(data):
    data.clear()
    data["plan"] = "elsewhere"


@pytest.mark.ipopt
@pytest.mark.parametrize("damage", [without_stats, stats_of_another_type, one_input_missing, not_a_number,
                                    another_document, "truncated", "not UTF-8", "a folder"],
                         ids=lambda d: d if isinstance(d, str) else d.__name__)
def test_a_damaged_plan_cache_entry_is_planned_anew_and_replaced(good_entry, tmp_path, damage):
    """An entry that cannot be read, or fails a check, is planned anew (never an error): valid
    JSON without the key 'stats' used to fail every run with KeyError."""
    first, good = good_entry
    folder = tmp_path / "plans"
    folder.mkdir(mode=0o700)
    entry = folder / good.name
    if damage == "truncated":
        entry.write_text(good.read_text()[:200])
    elif damage == "not UTF-8":
        entry.write_bytes(b"\xff\xfe" + good.read_bytes())
    elif damage == "a folder":
        entry.mkdir()
    else:
        data = json.loads(good.read_text())
        damage(data)
        entry.write_text(json.dumps(data))
    if damage == "a folder":  # planned, and not cached: a folder is not replaced by a file
        with pytest.warns(UserWarning, match=rf"the plan could not be cached in {folder}: Is a directory"):
            again = cached_plan(folder)
    else:
        again = cached_plan(folder)
    assert not again.report.cache_hit
    np.testing.assert_allclose(again.u, first.u, atol=1e-8)
    if damage != "a folder":  # replaced by a good entry
        assert json.loads(entry.read_text())["stats"]["status"] == "Solve_Succeeded"
        assert cached_plan(folder).report.cache_hit


@pytest.mark.ipopt
def test_the_plan_cache_folder_is_private_whatever_the_umask(good_entry, tmp_path):
    folder = tmp_path / "made" / "plans"
    previous = os.umask(0)
    try:
        cached_plan(folder)
    finally:
        os.umask(previous)
    assert stat.S_IMODE(folder.stat().st_mode) == 0o700
    assert stat.S_IMODE(folder.parent.stat().st_mode) == 0o700
    (entry,) = folder.glob("*.json")
    assert stat.S_IMODE(entry.stat().st_mode) & 0o022 == 0


@pytest.mark.ipopt  # good_entry plans
def test_a_plan_cache_folder_others_can_write_is_refused(good_entry, tmp_path):
    """Refused before anything is read from it (its entry is good: a cache hit otherwise)."""
    folder = tmp_path / "plans"
    folder.mkdir()
    shutil.copy(good_entry[1], folder)
    folder.chmod(0o777)
    with pytest.raises(CacheDirectoryError, match=rf"refusing the cache folder {folder} for planned trajectories: "
                       rf"group and others can write it.*chmod 700 {folder}.*HINF_CPP_CACHE"):
        cached_plan(folder)


@pytest.mark.ipopt  # good_entry plans
@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() != 0, reason="chown to another user needs root")
def test_a_plan_cache_folder_of_another_user_is_refused(good_entry, tmp_path):
    folder = tmp_path / "plans"
    folder.mkdir(mode=0o700)
    shutil.copy(good_entry[1], folder)
    os.chown(folder, 65534, -1)
    with pytest.raises(CacheDirectoryError, match=rf"refusing the cache folder {folder} .*owned by another user"):
        cached_plan(folder)


def test_path_with_a_speed_profile_and_grid():
    start = (0.0, 0.0)
    points = waypoints_from_path([3.0, 6.0, 10.0], [4.0, 8.0, 8.0], [1.0, 2.0, 2.0], start=start, t0=5.0)
    # Pieces of length 5, 5, 4 at speeds (1 -> 1), (1 -> 2), (2 -> 2): 5, 10/3, 2 s.
    assert [p.t for p in points] == pytest.approx([10.0, 10.0 + 10.0 / 3.0, 12.0 + 10.0 / 3.0], rel=1e-15)
    assert len(waypoints_from_path([0.0, 1.0], [0.0, 0.0], 1.0, start=start, tolerance=0.05)) == 1  # the start dropped
    grid = time_grid(0.0, 10.0, [2.5, 7.0], 1.0)
    assert set([2.5, 7.0]) <= set(grid.tolist()) and np.max(np.diff(grid)) <= 1.0 + 1e-12
    assert grid[0] == 0.0 and grid[-1] == 10.0


@pytest.mark.parametrize("kwargs,match", [
    (dict(options=PlanOptions(u_min=(1.0, 0.0), u_max=(0.5, 1.0))), r"u_min\[0\] = 1 must be below u_max\[0\] = 0.5"),
    (dict(options=PlanOptions(u_min=(0.0,))), r"u_min needs one number per input \(2\), got 1"),
    (dict(options=PlanOptions(tolerance=-1.0)), "tolerance must be a finite number > 0, got -1.0"),
    (dict(waypoints=[Waypoint(1.0, 0.0, t=5.0), Waypoint(2.0, 0.0, t=4.0)]),
     r"waypoints\[1\] \(x = 2, y = 0, t = 4\): its time must be after waypoints\[0\]'s \(5 s\)"),
    (dict(waypoints=[Waypoint(1.0, 0.0)]), "the last waypoint has no time t: give it one, or a speed, or tf"),
    (dict(waypoints=[Waypoint(1.0, math.nan, t=3.0)]), r"waypoints\[0\].y must be a finite number"),
    (dict(q0=[1.0, 0.0]), r"q0 must be 6 finite numbers"),
    (dict(waypoints=[Waypoint(5.0, 0.0, t=5.0), Waypoint(6.0, 0.0, t=6.0, heading=-1e300)]),
     r"^waypoints\[1\]\.heading = -1e\+300 rad is too large to compare modulo 2 pi: give it within \+-1e\+06 rad"),
])
def test_bad_arguments_name_the_problem(kwargs, match):
    # An iteration budget: a bad argument let through ends in IPOPT's maximum iterations.
    arguments = dict(waypoints=[Waypoint(5.0, 0.0, t=5.0)], q0=[1.0, 0, 0, 0, 0, 0],
                     options=PlanOptions(max_iterations=3))
    arguments.update(kwargs)
    with pytest.raises(ValueError, match=match):
        plan(hc.ShipModel(), arguments["waypoints"], q0=arguments["q0"], options=arguments["options"])


@pytest.mark.ipopt
def test_a_time_grid_too_fine_is_refused(monkeypatch):
    """A waypoint at t = 1e12 with interval = 1 s asked for 1e12 nodes (memory and time without
    end); the grid is limited (here to 50 intervals, the default horizon / 60 needs 60)."""
    from hinf_cpp.planning import planner

    monkeypatch.setattr(planner, "MAX_INTERVALS", 50)
    with pytest.raises(ValueError, match=r"^the horizon from t0 = 0 to tf = 60 s in intervals of at most 1 s needs "
                                         r"more than 50 intervals: give a larger interval or a shorter horizon"):
        plan(hc.ShipModel(), [Waypoint(5.0, 0.0, t=60.0)], q0=[1.0, 0, 0, 0, 0, 0], options=PlanOptions(max_iterations=3))
