"""Plans along which the vehicle is open-loop unstable (docs/planning.md, "Vehicles unstable
along the plan"): the built-in AUV at 1 m/s (directionally unstable above 0.69 m/s) and a
directionally unstable vessel of the tests' own are planned from waypoints, detected as
unstable, given as states (each interval integrated from its node, checked by its defect) and
tracked by the H-infinity design along them; a stable plan stays as it was (q_d re-simulated
from q0); the default grid follows the waypoints and the vehicle's fastest mode."""

from __future__ import annotations

import copy
import json
import math
import os
import pathlib
import subprocess
import sys
import tomllib

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import hinf_cpp as hc
from _support import numbers_close

pytest.importorskip("casadi")

import hinf_cpp.planning.planner as planner  # noqa: E402
from hinf_cpp.planning.planner import PlanOptions, Waypoint, plan, time_grid  # noqa: E402
from hinf_cpp.scenario.planned import load_planned, plan_scenario, planned_scenario_toml  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = pathlib.Path(sys.executable).parent
# The shipped planned runs start 1 m behind, 1 m aside (1.41 m off) and must end within 15% of
# that (test_planned_scenarios.py); the runs here start and are judged the same way.
START_OFFSET = np.array([0.0, 0.0, 0.0, -1.0, -1.0, 0.3])
FINAL_TOLERANCE = 0.15 * math.hypot(1.0, 1.0)

# The built-in AUV (Sirene; states [u, v, r, x, y, psi] in m/s, rad/s, m, rad; inputs surge
# force tau_u in N and yaw moment tau_r in N m) changes lane by 5 m at 1 m/s over 120 s.
# Holding 1 m/s takes tau_u = 70 + 100 = 170 N; the bounds leave room to manoeuvre.
AUV_Q0 = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]
AUV_WAYPOINTS = [Waypoint(40.0, 0.0, t=40.0, heading=0.0), Waypoint(80.0, 5.0, t=80.0, heading=0.0),
                 Waypoint(120.0, 5.0, t=120.0, heading=0.0)]
AUV_BOUNDS = {"u_min": [0.0, -20.0], "u_max": [400.0, 20.0]}

# A vessel of the tests' own (Fossen's matrix form, SI units): the sway added mass twice the
# surge mass gives a Munk moment (m22 - m11) u v that at speed U outgrows the yaw damping when
# d22 d33 < m11 (m22 - m11) U^2, i.e. above U = sqrt(100 * 70 / (100 * 100)) = 0.84 m/s.
VESSEL_M = [[100.0, 0.0, 0.0], [0.0, 200.0, 0.0], [0.0, 0.0, 50.0]]
VESSEL_D = [[20.0, 0.0, 0.0], [0.0, 100.0, 0.0], [0.0, 0.0, 70.0]]
VESSEL_Q0 = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]  # [u, v, r, x, y, psi]; holding 1 m/s takes tau_u = 20 N
VESSEL_WAYPOINTS = [Waypoint(30.0, 0.0, t=30.0, heading=0.0), Waypoint(60.0, 4.0, t=60.0),
                    Waypoint(90.0, 0.0, t=90.0), Waypoint(120.0, 0.0, t=120.0, heading=0.0)]
VESSEL_BOUNDS = {"u_min": [0.0, -30.0], "u_max": [60.0, 30.0]}


def vessel() -> hc.FossenVessel:
    return hc.FossenVessel(hc.FossenVesselParameters(M=np.array(VESSEL_M), D=np.array(VESSEL_D)))


def largest_real_part(trajectory, t: float) -> float:
    """The largest real part of the eigenvalues of the velocity block (the states u, v, r: rows
    and columns 0..2 for the AUV and the Fossen vessel) of A_e(t) = d/dq [f + G u_d] along q_d,
    by NumPy: the directional stability of docs/vehicles.md. (The position and heading add
    eigenvalues at 0 whatever the speed.)"""
    return float(np.max(np.linalg.eigvals(np.asarray(trajectory.A_e(t))[:3, :3]).real))


def document(model: dict, q0, waypoints, bounds, Q: float, disturbance: dict) -> dict:
    """A planned scenario like the shipped ones: start 1.41 m off with a 0.3 rad heading error,
    state-feedback H-infinity law at gamma = 5, small sinusoidal disturbances."""
    return {
        "name": "unstable-plan", "model": model,
        "horizon": {"t0": 0.0, "tf": waypoints[-1].t},
        "desired": {"q0": list(q0), "plan": dict(bounds),
                    "waypoints": [{k: v for k, v in vars(w).items() if v is not None} for w in waypoints]},
        "controller": {"gamma": 5.0, "Q": Q, "Qf": Q},
        "disturbance": disturbance,
        "initial": {"q0": (np.array(q0) + START_OFFSET).tolist()},
        "output": {"dt": 0.05},
    }


# The AUV's disturbances as in the shipped auv_s_curve (5 N in surge and sway, 1 N m in yaw) and
# its weights (Q = 1000 I: inputs are forces in N); the vessel's a tenth of its forces.
AUV_DOCUMENT = document({"kind": "auv"}, AUV_Q0, AUV_WAYPOINTS, AUV_BOUNDS, 1000.0, {
    f"w{i}": {"harmonics": [{"amplitude": a, "frequency_hz": 0.05, "shape": "cos"}]}
    for i, a in ((1, 5.0), (2, 5.0), (3, 1.0))})
VESSEL_DOCUMENT = document({"kind": "fossen_vessel", "M": VESSEL_M, "D": VESSEL_D}, VESSEL_Q0, VESSEL_WAYPOINTS,
                           VESSEL_BOUNDS, 100.0, {
                               f"w{i}": {"harmonics": [{"amplitude": a, "frequency_hz": 0.05, "shape": "cos"}]}
                               for i, a in ((1, 2.0), (2, 2.0), (3, 1.0))})


@pytest.fixture(autouse=True)
def plan_cache(tmp_path_factory, monkeypatch):
    """A plan cache of this test session only (the programs started by the tests get it too)."""
    folder = tmp_path_factory.getbasetemp() / "hinf_cpp_cache"
    monkeypatch.setenv("HINF_CPP_CACHE", str(folder))
    return folder


def check_defects_independently(model, result, max_mismatch: float) -> None:
    """Each interval integrated from its node by SciPy (DOP853, rtol 1e-12), with the inputs
    linear between the nodes as np.interp gives them, ends within max_mismatch of the next node.
    Over one interval the unstable mode grows by at most exp(0.4 * 2) = 2.2, so SciPy's own
    error stays near 1e-11, far below max_mismatch = 1e-6."""
    t, u, q = result.t, result.u, result.q

    def rhs(time_, state):
        u_now = np.array([np.interp(time_, t, u[:, i]) for i in range(u.shape[1])])
        return model.f(time_, state) + model.G(time_, state) @ u_now

    defects = []
    for k in range(len(t) - 1):
        end = solve_ivp(rhs, (t[k], t[k + 1]), q[k], method="DOP853", rtol=1e-12, atol=1e-12).y[:, -1]
        defects.append(float(np.max(np.abs(end - q[k + 1]))))
    assert max(defects) <= max_mismatch
    # The library's defects are the same quantity: SciPy's and the library's integrations of one
    # interval agree to their tolerances (1e-12 and 1e-10 relative on states of size <= 120).
    np.testing.assert_allclose(defects, result.trajectory.defects(), rtol=0, atol=1e-7)


# ---- the detection, without IPOPT ----

@pytest.mark.parametrize("history,sensitivity,left,unstable", [
    ([2.1e-6], 1.1e-11, 4, False),  # the ship's lawnmower after the first accurate solve: refine
    ([2.1e-6, 2.1e-6 / 16], 1.1e-11, 3, False),  # a doubling divided it by 16
    ([2.1e-6, 1.5e-6], 1.1e-11, 3, True),  # fell by less than 2 over a doubling
    ([19.3], 1.3e-3, 4, True),  # the AUV at 1 m/s: the re-simulation changes with its own tolerance
    ([0.181], 4.0e-7, 4, True),  # the vessel below: 16^4 = 65536 times max_mismatch is 0.066
    ([0.060], 4.0e-7, 4, False),  # below it: refine
    ([math.inf], math.inf, 4, True),  # the re-simulation failed
])
def test_what_counts_as_unstable(history, sensitivity, left, unstable):
    assert planner._unstable(history, sensitivity, PlanOptions(), left) is unstable


# ---- the AUV ----

@pytest.fixture(scope="module")
def auv_plan():
    return plan(hc.Auv(), AUV_WAYPOINTS, q0=AUV_Q0, options=PlanOptions(**{k: tuple(v) for k, v in AUV_BOUNDS.items()}))


@pytest.mark.ipopt
def test_the_auv_at_1_m_s_is_planned_as_states(auv_plan):
    """Today's planner doubled the substeps up to 128 and gave up ("the planned states stay
    0.0226 from their re-simulation"); now the instability is found after the first accurate
    solve and the plan is given as states."""
    report, trajectory = auv_plan.report, auv_plan.trajectory
    assert auv_plan.states_given and report.states_given
    # Unstable along the plan: on the first straight (t = 20 s, u ~ 1 m/s) the linearization
    # has an eigenvalue in the right half-plane (NumPy on the library's A_e; docs/vehicles.md:
    # above 0.69 m/s).
    assert largest_real_part(trajectory, 20.0) > 0.1
    # The re-simulation from q0 drifts: far above max_mismatch, and it changes with the
    # integrator's tolerance by more than max_mismatch (the detection).
    assert report.position_mismatch > 1e3 * 1e-6
    assert report.resimulation_sensitivity > 1e-6
    # Given as states: q_d passes through every planned node, and each interval's defect is at
    # most max_mismatch (the library's own check) ...
    np.testing.assert_array_equal(trajectory.node_times(), auv_plan.t)
    assert report.max_defect == trajectory.max_defect() <= 1e-6
    assert report.max_defect_t in auv_plan.t
    np.testing.assert_array_equal(auv_plan.q[0], AUV_Q0)
    # ... and by SciPy's.
    check_defects_independently(hc.Auv(), auv_plan, 1e-6)
    assert max(report.waypoint_errors) <= 0.05
    assert max(report.heading_errors) <= 0.01
    assert "the vehicle is open-loop unstable along the plan" in report.summary()
    assert report.to_dict()["states_given"] is True
    assert np.all(auv_plan.u >= np.array(AUV_BOUNDS["u_min"])) and np.all(auv_plan.u <= np.array(AUV_BOUNDS["u_max"]))


@pytest.mark.ipopt
@pytest.mark.slow
def test_the_auv_plan_is_tracked_from_a_scenario_file(tmp_path):
    planned = plan_scenario(AUV_DOCUMENT, "auv_lane.toml", cache=False)
    assert planned.plan.states_given
    desired = planned.document["desired"]
    assert desired["states"]["t"] == planned.plan.t.tolist() and desired["max_defect"] == 1e-6
    assert planned.scenario.desired_states is not None
    result = hc.run_scenario(planned.scenario)
    assert result.simulation.status == hc.RunStatus.completed
    assert result.metrics.max_position_error >= math.hypot(1.0, 1.0) - 1e-12
    assert result.metrics.final_position_error < FINAL_TOLERANCE
    # The written planned file carries the states: read back, it runs the same design along them.
    written = tmp_path / "auv_lane_planned.toml"
    written.write_text(planned_scenario_toml(planned, written))
    text = tomllib.loads(written.read_text())
    np.testing.assert_array_equal(text["desired"]["states"]["q"], planned.plan.q)
    again = hc.run_scenario(hc.load_scenario(written))
    assert again.metrics.final_position_error == result.metrics.final_position_error
    if (BIN / "hinf-sim").exists():  # the C++ program on the written file: the same results
        done = subprocess.run([str(BIN / "hinf-sim"), str(written), "--json", str(tmp_path / "sim.json")],
                              capture_output=True, text=True, timeout=600, env=dict(os.environ))
        assert done.returncode == 0, done.stderr
        numbers_close(json.loads((tmp_path / "sim.json").read_text()), json.loads(hc._core.results_json(result)))


@pytest.mark.ipopt
@pytest.mark.slow  # plans the AUV twice
def test_a_plan_given_as_states_is_cached_with_its_form(tmp_path):
    """The cache keeps the form: read back, the plan is given as states again (its intervals
    integrated and their defects checked), with the report's re-simulation numbers kept."""
    options = PlanOptions(**{k: tuple(v) for k, v in AUV_BOUNDS.items()})
    first = plan(hc.Auv(), AUV_WAYPOINTS, q0=AUV_Q0, options=options, cache_dir=tmp_path)
    again = plan(hc.Auv(), AUV_WAYPOINTS, q0=AUV_Q0, options=options, cache_dir=tmp_path)
    assert again.report.cache_hit and again.states_given and again.report.states_given
    np.testing.assert_array_equal(again.u, first.u)
    np.testing.assert_array_equal(again.q, first.q)
    assert again.report.max_defect == first.report.max_defect
    assert again.report.position_mismatch == first.report.position_mismatch
    assert again.report.resimulation_sensitivity == first.report.resimulation_sensitivity
    # An entry of the earlier format (no "format", no form) is planned anew, not misread.
    (entry,) = tmp_path.glob("*.json")
    data = json.loads(entry.read_text())
    del data["format"], data["states_given"]
    entry.write_text(json.dumps(data))
    anew = plan(hc.Auv(), AUV_WAYPOINTS, q0=AUV_Q0, options=options, cache_dir=tmp_path)
    assert not anew.report.cache_hit and anew.states_given


# ---- a directionally unstable vessel of the tests' own ----

@pytest.mark.ipopt
def test_an_unstable_vessel_of_our_own_is_planned_and_tracked():
    # Straight at 1 m/s it is unstable; at 0.5 m/s it is not (so the check can tell).
    straight = {speed: hc.Trajectory(vessel(), [speed, 0.0, 0.0, 0.0, 0.0, 0.0], [20.0 * speed, 0.0], 0.0, 1.0)
                for speed in (0.5, 1.0)}
    assert largest_real_part(straight[0.5], 0.5) < 0.0 < largest_real_part(straight[1.0], 0.5)
    planned = plan_scenario(VESSEL_DOCUMENT, "vessel_s.toml", cache=False)
    result, report = planned.plan, planned.plan.report
    assert result.states_given and report.position_mismatch > 1e-6 and report.max_defect <= 1e-6
    # Along the plan itself (t = 100 s, on the way back to the line at about 1 m/s): unstable too.
    assert largest_real_part(result.trajectory, 100.0) > 0.0
    check_defects_independently(vessel(), result, 1e-6)
    assert max(report.waypoint_errors) <= 0.05
    run = hc.run_scenario(planned.scenario)
    assert run.simulation.status == hc.RunStatus.completed
    assert run.metrics.max_position_error >= math.hypot(1.0, 1.0) - 1e-12
    assert run.metrics.final_position_error < FINAL_TOLERANCE


@pytest.mark.ipopt
def test_an_unstable_plan_is_tracked_over_receding_windows():
    """A mission of any length on an unstable vehicle: the receding horizon along the planned
    states (each window the states form over its interval), where windows that integrate the
    inputs from the chained state drift as one integration does."""
    document = copy.deepcopy(VESSEL_DOCUMENT)
    document["receding_horizon"] = {"window": 10.0, "update": 1.0}
    planned = plan_scenario(document, "vessel_s_receding.toml", cache=False)
    assert planned.plan.states_given and planned.scenario.desired_states is not None
    run = hc.run_scenario(planned.scenario)
    assert run.simulation.status == hc.RunStatus.completed
    assert run.receding_horizon.windows == int(planned.scenario.tf)
    # The run's desired trajectory is the plan: at tf the last node, up to the defects allowed
    # (max_defect 1e-6 per interval, a few intervals' growth at most in between).
    q_d_end = run.simulation.q_d[-1]
    assert np.abs(q_d_end - planned.plan.q[-1]).max() < 1e-5
    assert run.metrics.final_position_error < FINAL_TOLERANCE
    # The same windows on the inputs alone drift from the plan (the mismatch the planner found).
    scenario = planned.scenario
    horizon = hc.RecedingHorizon(scenario.model, scenario.desired_q0, scenario.desired_u, 0.0, scenario.Q,
                                 scenario.Qf, scenario.gamma, scenario.receding_horizon)
    drift = np.abs(horizon.desired_state(scenario.tf) - planned.plan.q[-1]).max()
    assert drift > 1e3 * np.abs(q_d_end - planned.plan.q[-1]).max()


# ---- a stable plan stays as it was ----

@pytest.mark.ipopt
@pytest.mark.parametrize("name,substeps", [("ship_lane_change", 8), ("ship_lawnmower", 16)])
def test_a_stable_plan_is_re_simulated_from_q0_as_before(name, substeps):
    """The shipped ship plans: q_d is the re-simulation of u_d from q0 (no nodes, no states in
    the document), with the grids and substeps of docs/planning.md's table; the lawnmower's
    first accurate solve missed max_mismatch and was refined (its re-simulation did not change
    with the integrator's tolerance: no instability)."""
    planned = load_planned(hc.scenario_path(f"planned/{name}"), cache=False)
    result, report = planned.plan, planned.plan.report
    assert not result.states_given and not report.states_given
    assert report.max_defect is None and report.max_defect_t is None
    assert list(result.trajectory.node_times()) == [] and "states" not in planned.document["desired"]
    assert planned.scenario.desired_states is None
    assert report.substeps == substeps and report.position_mismatch <= 1e-6
    if substeps == 16:
        assert report.resimulation_sensitivity <= 1e-9
    else:
        assert report.resimulation_sensitivity is None
    # The same code on the same input: the trajectory is the library's integration of u_d from
    # q0, bit for bit.
    fresh = hc.Trajectory(result.model, planned.scenario.desired_q0, result.inputs(), result.t0, result.tf)
    np.testing.assert_array_equal([fresh.q_d(t) for t in result.t], [result.trajectory.q_d(t) for t in result.t])
    assert "open-loop unstable" not in report.summary()


# ---- the default grid ----

def test_the_default_grid_has_four_intervals_per_leg():
    # A 4 s leg in a 120 s horizon: 2 s by the horizon / 60 alone, 4 intervals of 1 s by the rule.
    grid = time_grid(0.0, 120.0, [30.0, 34.0], 2.0, divisions=planner.LEG_INTERVALS)
    leg = grid[(grid >= 30.0) & (grid <= 34.0)]
    np.testing.assert_allclose(np.diff(leg), 1.0, rtol=1e-15)
    assert len(grid) - 1 == 15 + 4 + 43
    assert planner.LEG_INTERVALS == 4
    # An explicit interval is the same between every two key times.
    assert len(time_grid(0.0, 120.0, [30.0, 34.0], 2.0)) - 1 == 15 + 2 + 43


@pytest.mark.ipopt
def test_the_default_grid_follows_the_waypoints_and_the_vehicle():
    ship = hc.ShipModel()
    options = PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5))
    # A 4 s jog of 0.4 m: 4 intervals on it.
    jog = plan(ship, [Waypoint(30.0, 0.0, t=30.0, heading=0.0), Waypoint(34.0, 0.4, t=34.0, heading=0.0),
                      Waypoint(120.0, 0.4, t=120.0, heading=0.0)], q0=[1.0, 0, 0, 0, 0, 0], options=options)
    assert np.count_nonzero((jog.t > 30.0) & (jog.t <= 34.0)) == 4
    assert max(jog.report.waypoint_errors) <= 0.05
    # A 10 m lane change over 300 s: nodes 5 s apart. The ship's fastest mode (|lambda| = 1.73
    # /s) puts 2 Runge-Kutta steps of 2.5 s outside the method's stability region, where IPOPT
    # failed ("Restoration_Failed"); the solves take at least 5 steps of 1 s.
    lane = plan(ship, [Waypoint(100.0, 0.0, t=100.0, heading=0.0), Waypoint(200.0, 10.0, t=200.0, heading=0.0),
                       Waypoint(300.0, 10.0, t=300.0, heading=0.0)], q0=[1.0, 0, 0, 0, 0, 0], options=options)
    assert lane.report.intervals == 60 and not lane.states_given
    assert planner._stable_substeps(planner._dynamics_function(planner._casadi(), planner.symbolic_model(ship)),
                                    np.array([1.0, 0, 0, 0, 0, 0]), lane.t, np.zeros(2)) == 5
    assert max(lane.report.waypoint_errors) <= 0.05 and lane.report.position_mismatch <= 1e-6


def test_states_are_the_planners_to_give():
    """[desired] states (or max_defect) beside waypoints: refused, naming the key."""
    for key, value in (("states", {"t": [0.0, 120.0], "q": [AUV_Q0, AUV_Q0]}), ("max_defect", 1e-6)):
        root = {**AUV_DOCUMENT, "desired": {**AUV_DOCUMENT["desired"], key: value}}
        with pytest.raises(ValueError, match=rf"^auv\.toml: \[desired\] {key}: the planner gives the states"):
            plan_scenario(root, "auv.toml", cache=False)


@pytest.mark.ipopt
def test_a_path_change_on_an_unstable_plan_starts_from_the_planned_states():
    """[path_change] waypoints on a receding-horizon run whose [desired] is planned as states: the
    new path starts from the run's desired state at the join (the planned node there), not from
    the inputs integrated from q0 (which drift from the plan with the open-loop growth)."""
    document = copy.deepcopy(VESSEL_DOCUMENT)
    document["receding_horizon"] = {"window": 10.0, "update": 1.0}
    # At t = 100 s the vessel is near (100.7, -0.3) m at about 1 m/s: slow down towards a point
    # 11 m ahead on the line y = 0 at 120 s.
    target = Waypoint(112.0, 0.0, t=120.0, heading=0.0)
    document["path_change"] = {"t": 100.0, "plan": dict(VESSEL_BOUNDS),
                               "waypoints": [{"x": target.x, "y": target.y, "t": target.t, "heading": 0.0}]}
    planned = plan_scenario(document, "vessel_s_change.toml", cache=False)
    assert planned.plan.states_given and not planned.path_change_plan.states_given
    node = int(np.argmin(np.abs(np.asarray(planned.plan.t) - 100.0)))
    assert planned.plan.t[node] == pytest.approx(100.0, abs=1e-9)
    # The new path's first state is the plan's node at 60 s, up to the defects the states form
    # allows between nodes (max_defect 1e-6 per interval).
    assert np.abs(planned.path_change_plan.q[0] - planned.plan.q[node]).max() < 1e-5
    # The inputs alone, integrated from q0, are 5e-3 away at 100 s (the open-loop growth, about
    # e-fold in 9 s here): where the new path would start without the states.
    scenario = planned.scenario
    inputs_only = hc.RecedingHorizon(scenario.model, scenario.desired_q0, planned.plan.inputs(), 0.0, scenario.Q,
                                     scenario.Qf, scenario.gamma, scenario.receding_horizon)
    assert np.abs(inputs_only.desired_state(100.0) - planned.plan.q[node]).max() > 1e-3
    run = hc.run_scenario(scenario)
    assert run.simulation.status == hc.RunStatus.completed
    q_end = run.simulation.q[-1]
    assert math.hypot(q_end[3] - target.x, q_end[4] - target.y) < FINAL_TOLERANCE
