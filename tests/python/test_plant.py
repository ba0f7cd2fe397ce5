"""A plant other than the design model (Scenario.plant, [plant]) from Python: the base values of a
model's parameters (Model.named_parameters) perturbed relatively; the run and its results file
say which plant ran; scenarios with a plant pickle and read back; the closed-loop functions take
the plant; errors name [plant]; studies over plants share one design."""

from __future__ import annotations

import json
import math
import pickle

import numpy as np
import pytest

import hinf_cpp as hc


def paper(figure: int = 1, tf: float = 6.0) -> hc.Scenario:
    scenario = hc.load_scenario(hc.scenario_path(f"paper_fig{figure}"))
    scenario.tf = tf
    return scenario


def perturbed(model: hc.ShipModel, factor: float, prefix: str = "d_") -> hc.ShipModel:
    """The ship with every parameter whose name starts with `prefix` times `factor`."""
    values = {k: v * factor if k.startswith(prefix) else v for k, v in model.named_parameters().items()}
    return hc.ShipModel(hc.ShipParameters(**values))


def test_named_parameters_are_the_scenario_keys():
    assert hc.ShipModel().named_parameters() == dict(m_u=0.5, m_v=-2.0, m_r=0.5, d_u=1.0, d_v=2.0, d_r=1.0)
    assert list(hc.Auv().named_parameters()) == ["m11", "m22", "m33", "X_u", "X_uu", "Y_v", "Y_vv", "N_r", "N_rr"]
    assert hc.Hovercraft().named_parameters() == {"d": 0.2, "d_r": 0.5}
    assert hc.PlanarVtol().named_parameters() == {"g": 1.0, "epsilon": 0.1}
    vessel = hc.FossenVessel().named_parameters()
    assert len(vessel) == 18 and vessel["M[1][2]"] == -0.0744 and vessel["D[2][1]"] == -0.0041
    linear = hc.LinearModel(np.eye(2), np.ones((2, 1)), np.eye(2))
    assert linear.named_parameters()["B[1][0]"] == 1.0 and "C[0][0]" not in linear.named_parameters()

    class Scalar(hc.Model):
        def n(self): return 1
        def m(self): return 1
        def nw(self): return 1
        def f(self, t, q): return -2.0 * q
        def G(self, t, q): return np.ones((1, 1))
        def D(self, t, q): return np.ones((1, 1))
        def named_parameters(self): return {"a": -2.0}

    assert hc.Model.named_parameters(Scalar()) == {"a": -2.0}
    assert hc.Model.named_parameters(hc.ShipModel())["d_r"] == 1.0


def test_a_perturbed_plant_runs_and_is_reported():
    scenario = paper()
    assert scenario.plant is None
    nominal = hc.run_scenario(scenario)
    assert nominal.plant is None
    scenario.plant = perturbed(scenario.model, 1.3)
    result = hc.run_scenario(scenario)
    assert result.plant.named_parameters()["d_u"] == pytest.approx(1.3)
    assert np.abs(result.simulation.q - nominal.simulation.q).max() > 1e-2
    document = json.loads(hc._core.results_json(result))
    assert document["model"]["parameters"]["d_u"] == 1.0
    assert document["plant"] == {"name": "ship", "parameters": result.plant.named_parameters()}
    assert "plant" not in json.loads(hc._core.results_json(nominal))
    # The Scenario (its file form) and the result keep the plant through pickling.
    copy = pickle.loads(pickle.dumps(scenario))
    assert copy.plant.named_parameters() == scenario.plant.named_parameters()
    assert "[plant]" in hc._core.scenario_toml(copy)
    assert pickle.loads(pickle.dumps(result)).plant.named_parameters() == result.plant.named_parameters()


def test_the_closed_loop_functions_take_the_plant():
    scenario = paper().resolved()
    trajectory = hc.Trajectory(scenario.model, scenario.desired_q0, scenario.desired_u, scenario.t0, scenario.tf)
    design = hc.solve_grde(trajectory, scenario.Q, scenario.Qf, scenario.gamma, scenario.solver)
    plant = perturbed(scenario.model, 1.3)
    runs = [hc.simulate_state_feedback(trajectory, hc.HinfStateFeedback(design), scenario.disturbance,
                                       scenario.initial_q0, scenario.simulation_options(), p)
            for p in (None, plant)]
    scenario.plant = plant
    via_scenario = hc.run_scenario(scenario).simulation
    np.testing.assert_array_equal(runs[1].q, via_scenario.q)
    assert np.abs(runs[1].q - runs[0].q).max() > 1e-2


def test_plant_sections_and_their_errors(tmp_path):
    text = hc.scenario_path("paper_fig1").read_text()
    path = tmp_path / "damped.toml"
    path.write_text(text + "\n[plant]\nd_u = 1.3\nd_v = 2.6\nd_r = 1.3\n")
    scenario = hc.load_scenario(path)
    assert scenario.plant.named_parameters() == dict(m_u=0.5, m_v=-2.0, m_r=0.5, d_u=1.3, d_v=2.6, d_r=1.3)
    for plant, message in [("kind = \"hovercraft\"", r"\[plant\] the plant 'hovercraft' has heading index = 2"),
                           ("q = 1", r"\[plant\] unknown key 'q'"),
                           ("d_u = [1]", r"\[plant\] d_u: expected a number, got an array")]:
        path.write_text(text + f"\n[plant]\n{plant}\n")
        with pytest.raises(ValueError, match=message):
            hc.load_scenario(path)
    scenario = paper()
    scenario.plant = hc.Hovercraft()  # the ship's sizes, another heading index
    with pytest.raises(ValueError, match=r"\[plant\] the plant 'hovercraft' has heading index = 2"):
        hc.run_scenario(scenario)


def test_a_study_over_plants_shares_one_design():
    base = paper(2)
    runs = []
    for factor in (0.7, 1.0, 1.3):
        scenario = base.copy()
        scenario.plant = perturbed(base.model, factor)
        runs.append(scenario)
    rows = hc.run_scenarios(runs, hc.StudyOptions(threads=2))
    assert [r.status for r in rows] == ["completed"] * 3
    assert len({r.design for r in rows}) == 1
    for row, scenario in zip(rows, runs):
        alone = hc.run_scenario(scenario).metrics
        assert row.metrics.rms_position_error_last_half == alone.rms_position_error_last_half
        assert math.isfinite(row.metrics.rms_estimation_error_last_half)
