"""The receding horizon through the package and scenario files (its numerics are checked in
tests/cpp/test_receding_horizon.cpp): the binding surface, [receding_horizon] in a scenario file
and its errors, the results file, pickling, and a study that varies the window."""

import json
import pickle
import re

import numpy as np
import pytest

import hinf_cpp as hc
from hinf_cpp.output.export import save_json

U_D = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]  # paper Fig. 1
Q0 = [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4]


def fig1_text(extra: str) -> str:
    with open(hc.scenario_path("paper_fig1")) as f:
        text = f.read()
    return text.replace("[solver]", extra + "\n[solver]")


def test_run_through_the_api_matches_the_scenario_run():
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], U_D, 0.0, np.eye(6), np.eye(6), 5.0,
                                 hc.RecedingHorizonOptions(window=10.0, update=1.0), scenario.solver)
    scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
    result = hc.run_scenario(scenario)
    run, report = hc.simulate_receding_horizon(horizon, scenario.disturbance, scenario.initial_q0, 40.0,
                                               scenario.simulation_options())
    # The same windows and the same loop from two front doors: the same code on the same input.
    assert np.array_equal(run.q, result.simulation.q)
    assert report.windows == result.receding_horizon.windows == 40
    assert result.solution is None
    assert result.trajectory.tf() == 10.0  # the first window's
    assert isinstance(report, hc.RecedingHorizonReport) and report.options.window == 10.0


def test_windows_are_immutable_values_from_any_start():
    horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], U_D, 0.0, np.eye(6), np.eye(6), 5.0,
                                 hc.RecedingHorizonOptions(window=6.0, update=2.0))
    first = horizon.first()
    second = horizon.next(first)
    again = horizon.window(1, first.trajectory.q_d(2.0))
    assert (second.index, second.t_start, second.t_use_end) == (1, 2.0, 4.0)
    assert np.array_equal(second.design.Z(5.0), again.design.Z(5.0))
    assert second.memory_bytes() > 0
    with pytest.raises(ValueError, match="index"):
        horizon.window(-1, [1, 0, 0, 0, 0, 0])
    with pytest.raises(ValueError, match="desired state"):
        horizon.window(0, [1, 0, 0])


@pytest.mark.parametrize("options, match", [
    (dict(window=0.0), "window"),
    (dict(window=5.0, update=6.0), "update"),
    (dict(window=float("inf")), "window"),
])
def test_bad_options_are_named(options, match):
    with pytest.raises(ValueError, match=match):
        hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], U_D, 0.0, np.eye(6), np.eye(6), 5.0,
                           hc.RecedingHorizonOptions(**options))


def test_a_gamma_below_a_windows_gamma_star_names_the_window():
    horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], U_D, 0.0, np.eye(6), np.eye(6), 1.0,
                                 hc.RecedingHorizonOptions(window=10.0, update=1.0))
    with pytest.raises(hc.ConjugatePointError, match="receding-horizon window 0"):
        hc.simulate_receding_horizon(horizon, None, Q0, 20.0)


def test_scenario_file_round_trip_and_results_file(tmp_path):
    path = tmp_path / "rh.toml"
    path.write_text(fig1_text("[receding_horizon]\nwindow = 8.0\nupdate = 2.0\n"))
    scenario = hc.load_scenario(path)
    assert (scenario.receding_horizon.window, scenario.receding_horizon.update) == (8.0, 2.0)
    # The scenario written back reads as the same scenario (and so it pickles).
    again = pickle.loads(pickle.dumps(scenario))
    assert again.receding_horizon == scenario.receding_horizon
    document = json.loads(save_json(hc.run_scenario(scenario), tmp_path / "rh.json").read_text())
    assert document["receding_horizon"]["windows"] == 20
    assert document["receding_horizon"]["window"] == 8.0
    assert document["receding_horizon"]["peak_bytes"] > 0


def test_stationary_terminal_weight_from_a_scenario_file(tmp_path):
    path = tmp_path / "rh.toml"
    path.write_text(fig1_text("[receding_horizon]\nwindow = 2.0\nterminal = \"stationary\"\n"))
    scenario = hc.load_scenario(path)
    assert scenario.receding_horizon.terminal == hc.TerminalWeight.stationary
    assert pickle.loads(pickle.dumps(scenario)).receding_horizon == scenario.receding_horizon
    # The rule reaches the windows: the first window's Z at its end is the game ARE's solution
    # of the linearization there (SciPy's solve_continuous_are with the indefinite weight
    # diag(I, -gamma^2 I) on [B D]: an independent solver; both are accurate to ~1e-12 relative).
    horizon = hc.RecedingHorizon(scenario.model, scenario.desired_q0, scenario.desired_u, 0.0, scenario.Q,
                                 scenario.Qf, scenario.gamma, scenario.receding_horizon, scenario.solver)
    window = horizon.first()
    trajectory, gamma = window.trajectory, scenario.gamma
    A, B, D = trajectory.A_e(2.0), trajectory.B_e(2.0), trajectory.D_e(2.0)
    import scipy.linalg
    weights = np.diag([1.0] * B.shape[1] + [-gamma**2] * D.shape[1])
    oracle = scipy.linalg.solve_continuous_are(A, np.hstack([B, D]), scenario.Q, weights)
    assert np.abs(window.design.Z(2.0) - oracle).max() <= 1e-9 * np.abs(oracle).max()
    # A 2 s window with this rule tracks as the full-horizon design does (tests/cpp: within 2%).
    result = hc.run_scenario(scenario)
    assert result.receding_horizon.windows == 40
    full = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    assert result.metrics.rms_position_error_last_half == pytest.approx(full.metrics.rms_position_error_last_half,
                                                                         rel=0.02)


@pytest.mark.parametrize("extra, match", [
    ("[receding_horizon]\nupdate = 1.0\n", "window"),
    ("[receding_horizon]\nwindow = 5.0\nupdate = 9.0\n", r"\[receding_horizon\] .*update"),
    ("[receding_horizon]\nwindow = 5.0\nhorizon = 9.0\n", "horizon"),
    ("[receding_horizon]\nwindow = 5.0\n[measurement]\nsigma = 0.5\n", r"add \[sampling\]"),
    ("[receding_horizon]\nwindow = 5.0\nterminal = \"are\"\n", r"terminal.*'qf', 'stationary'|terminal.*qf.*stationary"),
])
def test_scenario_errors_name_the_key(tmp_path, extra, match):
    path = tmp_path / "bad.toml"
    path.write_text(fig1_text(extra))
    with pytest.raises(ValueError, match=match):
        hc.run_scenario(hc.load_scenario(path))


def test_output_feedback_is_refused_with_what_to_do():
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0)
    with pytest.raises(ValueError, match=r"add \[sampling\]"):
        hc.run_scenario(scenario)


def test_largest_gamma_star_over_windows_is_one_of_the_windows():
    horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], U_D, 0.0, np.eye(6), np.eye(6), 5.0,
                                 hc.RecedingHorizonOptions(window=5.0, update=5.0))
    worst = hc.receding_horizon_gamma_star(horizon, 10.0, hc.GammaStarOptions(rtol=1e-5))
    assert worst.windows == 2 and worst.window in (0, 1)
    assert worst.result.gamma_star == worst.gamma_star
    assert worst.t_start == 5.0 * worst.window


def test_online_controller_switches_windows_and_reports_them():
    horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], U_D, 0.0, np.eye(6), np.eye(6), 5.0,
                                 hc.RecedingHorizonOptions(window=5.0, update=1.0))
    controller = hc.RecedingOnlineController(horizon, 0.1, background=False)
    with pytest.raises(ValueError, match="before reset"):
        controller.step(0.0, Q0)
    controller.reset(0.0, Q0)
    for k in range(31):
        controller.synchronize(0.1 * k)
        u, report = controller.step(0.1 * k, Q0)
        assert u.shape == (2,) and report.status == hc.StepStatus.ok and not report.window_stale
    status = controller.status()
    assert isinstance(status, hc.RecedingOnlineStatus)
    assert (status.window_in_use, status.windows_failed) == (3, 0)
    assert controller.controller().law().t0() == 3.0
    with pytest.raises(ValueError, match="shape"):
        controller.step(3.1, [1.0, 2.0])
    with pytest.raises(ValueError, match="whole multiple"):
        hc.RecedingOnlineController(horizon, 0.3)


def test_sampled_scenario_with_the_receding_horizon(tmp_path):
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2_sampled"))
    full = hc.run_scenario(scenario).metrics.rms_position_error_last_half
    scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
    result = hc.run_scenario(scenario)
    assert result.receding_horizon.windows == 40
    assert result.online.lost == 0
    # The same loop, noise and filter with windows instead of one design: the C++ tests hold it
    # within 2% of the full design; here that it runs through the scenario and differs.
    assert result.metrics.rms_position_error_last_half == pytest.approx(full, rel=0.02)
    path = tmp_path / "rh.toml"
    path.write_text(hc.scenario.scenario_toml(scenario))
    assert hc.load_scenario(path).receding_horizon.window == 10.0


@pytest.mark.parametrize("change, match", [
    (lambda s: setattr(s.sampling, "design", hc.SampledDesign.digital), "emulated"),
    (lambda s: setattr(s.receding_horizon, "update", 0.075), "whole multiple"),
])
def test_sampled_receding_horizon_errors(change, match):
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2_sampled"))
    scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
    sampling, receding = scenario.sampling, scenario.receding_horizon
    change(scenario)
    scenario.sampling, scenario.receding_horizon = sampling, receding
    with pytest.raises(ValueError, match=match):
        hc.run_scenario(scenario)


def test_desired_states_round_trip_and_defects(tmp_path):
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.tf = 6.0
    t = np.linspace(0.0, 6.0, 7)
    reference = hc.Trajectory(scenario.model, scenario.desired_q0, scenario.desired_u, 0.0, 6.0)
    scenario.desired_states = hc.DesiredStates(t=t, q=reference.q_d(t), max_defect=1e-6)
    path = tmp_path / "states.toml"
    path.write_text(hc.scenario.scenario_toml(scenario))
    again = hc.load_scenario(path)
    assert np.array_equal(again.desired_states.q, scenario.desired_states.q)
    result = hc.run_scenario(again)
    assert len(result.trajectory.defects()) == 6
    assert result.trajectory.max_defect() < 1e-8  # two integrations at rtol 1e-10 over 1 s
    trajectory = pickle.loads(pickle.dumps(result.trajectory))
    assert trajectory.defects() == result.trajectory.defects()
    text = path.read_text()
    assert "max_defect = " in text
    path.write_text(re.sub(r"max_defect = \S+", "max_defect = -1.0", text))
    with pytest.raises(ValueError, match="max_defect"):
        hc.run_scenario(hc.load_scenario(path))


def test_path_change_in_a_scenario_file_and_online(tmp_path):
    path = tmp_path / "change.toml"
    path.write_text(fig1_text("[receding_horizon]\nwindow = 10.0\n\n[path_change]\nt = 20.0\nu1 = 1.0\nu2 = -0.2\n"))
    scenario = hc.load_scenario(path)
    assert scenario.path_change.t == 20.0
    again = pickle.loads(pickle.dumps(scenario))
    assert again.path_change == scenario.path_change
    result = hc.run_scenario(scenario)
    unchanged = hc.Trajectory(scenario.model, scenario.desired_q0, scenario.desired_u, 0.0, 40.0)
    # The run's q_d is the new path (the C++ tests check it against its own integration).
    assert np.hypot(*(result.simulation.q_d[-1, 3:5] - unchanged.q_d(40.0)[3:5])) > 1.0
    horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], U_D, 0.0, np.eye(6), np.eye(6), 5.0,
                                 hc.RecedingHorizonOptions(window=10.0, update=1.0))
    changed = horizon.with_path_change(20.0, [1.0, -0.2])
    assert [t for t, _ in changed.path_changes()] == [20.0] and horizon.path_changes() == []
    controller = hc.RecedingOnlineController(horizon, 0.1, background=False)
    with pytest.raises(ValueError, match="before reset"):
        controller.change_path(20.0, [1.0, -0.2])
    controller.reset(0.0, Q0)
    controller.change_path(20.0, [1.0, -0.2])
    with pytest.raises(ValueError, match="window's start"):
        controller.change_path(25.5, [1.0, 0.0])


@pytest.mark.parametrize("extra, match", [
    ("[path_change]\nt = 20.0\nu1 = 1.0\nu2 = 0.0\n", r"add \[receding_horizon\]"),
    ("[receding_horizon]\nwindow = 10.0\n[path_change]\nt = 50.0\nu1 = 1.0\nu2 = 0.0\n", "inside the horizon"),
    ("[receding_horizon]\nwindow = 10.0\n[path_change]\nt = 20.5\nu1 = 1.0\nu2 = 0.0\n", "window's start"),
    ("[receding_horizon]\nwindow = 10.0\n[path_change]\nu1 = 1.0\nu2 = 0.0\n", "t"),
])
def test_path_change_errors(tmp_path, extra, match):
    path = tmp_path / "bad.toml"
    path.write_text(fig1_text(extra))
    with pytest.raises(ValueError, match=match):
        hc.run_scenario(hc.load_scenario(path))
