"""The digital design and the online controller through the Python API: the binding surface
(types, shapes, errors, pickling), the discrete game against SciPy's discrete algebraic Riccati
equation with the indefinite weight, the replay of a log against step() called one by one, and
the fixed-rate loop of examples/online_loop.py against the continuous loop (the numerics
themselves are checked in tests/cpp/test_discrete_design.cpp and test_online_controller.cpp)."""

from __future__ import annotations

import pathlib
import pickle
import runpy

import numpy as np
import pytest
import scipy.linalg

import hinf_cpp as hc

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def trajectory():
    u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    return hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)


@pytest.fixture(scope="module")
def design(trajectory):
    return hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)


def test_converged_recursion_equals_scipys_indefinite_dare():
    # x' = A x + B u + D w, frozen (LTI): the sampled game over a long horizon converges to the
    # stationary solution of M = T Q + A_d' M A_d - A_d' M [B_d D_d] (R + [B_d D_d]' M [B_d D_d])^-1
    # [B_d D_d]' M A_d with R = blockdiag(T I, -gamma^2 T I); SciPy accepts the indefinite R.
    A = np.array([[-0.5, 1.0, 0.2], [-1.0, -0.3, 0.4], [0.1, 0.0, 0.6]])
    B = np.array([[0.0], [1.0], [0.5]])
    D = np.array([[1.0, 0.0], [0.0, 0.3], [0.2, 1.0]])
    T, gamma = 0.1, 4.0
    trajectory = hc.Trajectory(hc.LinearModel(A, B, D), np.zeros(3), [0.0], 0.0, 80.0)
    sampled = hc.SampledLinearization(trajectory, T)
    design = hc.solve_discrete_game(sampled, 0, np.eye(3), np.eye(3), gamma)
    BD = np.hstack([sampled.B(0), sampled.D(0)])
    R = scipy.linalg.block_diag(T * np.eye(1), -gamma**2 * T * np.eye(2))
    M = scipy.linalg.solve_discrete_are(sampled.A(0), BD, T * np.eye(3), R)
    # 800 steps of a contraction: converged to round-off; SciPy's Schur method to about 1e-12 of |M|.
    np.testing.assert_allclose(design.M(0), M, rtol=0, atol=1e-10 * np.abs(M).max())
    # The gain: F = (R_u + B' M B - B' M D (D' M D - gamma^2 T)^-1 D' M B)^-1 (...) A, written as
    # the first block of (R + BD' M BD)^-1 BD' M A.
    F = np.linalg.solve(R + BD.T @ M @ BD, BD.T @ M @ sampled.A(0))[:1]
    np.testing.assert_allclose(design.gain(0), F, rtol=0, atol=1e-9 * np.abs(F).max())


def test_discrete_design_surface(trajectory):
    sampled = hc.SampledLinearization(trajectory, 0.1)
    assert sampled.steps() == 100 and sampled.period() == 0.1 and sampled.time(100) == pytest.approx(10.0)
    assert sampled.A(0).shape == (6, 6) and sampled.B(99).shape == (6, 2) and sampled.D(0).shape == (6, 6)
    with pytest.raises(ValueError, match="k = 0 .. 99"):
        sampled.A(100)
    with pytest.raises(ValueError, match="longer than the horizon"):
        hc.SampledLinearization(trajectory, 20.0)
    design = hc.solve_discrete_game(sampled, 0, np.eye(6), np.eye(6), 5.0)
    assert design.gamma() == 5.0 and design.steps() == 100 and design.sample_index(0.25) == 2
    np.testing.assert_array_equal(design.M(100), np.eye(6))
    with pytest.raises(ValueError, match="Qf"):
        hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.zeros((6, 6)), 5.0)
    with pytest.raises(hc.ConjugatePointError, match="gamma_star_discrete") as error:
        hc.solve_discrete_game(sampled, 0, np.eye(6), np.eye(6), 1.0)
    assert error.value.t_escape == hc.discrete_conjugate_time(sampled, np.eye(6), np.eye(6), 1.0)
    result = hc.gamma_star_discrete(sampled, np.eye(6), np.eye(6))
    assert result.binding == hc.GammaCondition.grde and result.converged
    assert result.gamma_star > hc.gamma_star(trajectory, np.eye(6), np.eye(6)).gamma_star


def test_online_controller_surface(design):
    limits = hc.ActuatorLimits(u_min=[-2.0, -2.0], u_max=[2.0, 2.0], rate_max=[50.0, np.inf])
    options = hc.OnlineOptions(limits=limits, max_age=0.3)
    assert pickle.loads(pickle.dumps(options)) == options
    law = hc.SampledLaw.emulated(design, 0.1)
    assert (law.kind(), law.n(), law.m(), law.steps(), law.t_end()) == ("emulated", 6, 2, 100, 10.0)
    controller = hc.OnlineController(law, options)
    q0 = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
    with pytest.raises(ValueError, match="before reset"):
        controller.step(0.0, q0)
    controller.reset(0.0, q0)
    u, report = controller.step(0.1, q0, 0.05)
    assert u.shape == (2,) and report.status == hc.StepStatus.ok and report.measurement == hc.MeasurementUse.used
    assert np.all(np.abs(u) <= 2.0) and np.array_equal(u, controller.held_command())
    u_back, report = controller.step(0.05, q0)
    assert report.status == hc.StepStatus.refused and np.array_equal(u_back, u)
    _, report = controller.step(0.2, None)
    assert report.measurement == hc.MeasurementUse.missing and controller.estimate_time() == pytest.approx(0.2)
    _, report = controller.step(0.3, q0 * np.nan, 0.3)
    assert report.measurement == hc.MeasurementUse.not_finite
    _, report = controller.step(10.0, q0)
    assert report.status == hc.StepStatus.past_horizon
    counts = controller.counts()
    assert (counts.steps, counts.used, counts.predicted, counts.refused, counts.past_horizon) == (5, 1, 2, 1, 1)
    with pytest.raises(ValueError, match="q must have shape"):
        controller.step(0.4, np.zeros(3))
    with pytest.raises(ValueError, match="shape"):
        controller.step(0.4, np.zeros((2, 3)))
    with pytest.raises(ValueError, match="u_min <= u_max"):
        hc.OnlineController(law, hc.OnlineOptions(limits=hc.ActuatorLimits(u_min=[1.0, 1.0], u_max=[0.0, 0.0])))
    with pytest.raises(ValueError, match="2 numbers"):
        hc.OnlineController(law, hc.OnlineOptions(limits=hc.ActuatorLimits(u_max=[1.0])))


def test_digital_law_runs_the_same_controller(trajectory):
    law = hc.SampledLaw.digital(hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0))
    controller = hc.OnlineController(law)
    controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
    u, report = controller.step(0.1, np.array([1.0, 0.0, 0.0, -1.0, -1.0, 0.0]), 0.1)
    # u = u_d(t) - F_k q_e with k the sample of t: F_1 of the design.
    q_e = np.array([1.0, 0.0, 0.0, -1.0, -1.0, 0.0]) - trajectory.q_d(0.1)
    np.testing.assert_allclose(u, trajectory.u_d(0.1) - law.gain(1) @ q_e, rtol=1e-10, atol=1e-10)  # the same sums in two orders: round-off


def test_replay_of_a_log_equals_the_steps_one_by_one(design):
    # A log at 20 Hz with jitter, a missing row (NaN), a late measurement and a duplicate: replay()
    # is the same code as step() called from Python, so the commands are equal bit for bit.
    rng = np.random.default_rng(7)
    t_now = np.arange(1, 61) * 0.05 + rng.uniform(0, 0.004, 60)
    t_meas = t_now - rng.uniform(0, 0.02, 60)
    t_meas[20] = t_meas[19]
    q = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4]) + 0.05 * rng.standard_normal((60, 6))
    q[30] = np.nan
    options = hc.OnlineOptions(limits=hc.ActuatorLimits(u_min=[-1.5, -1.5], u_max=[1.5, 1.5], rate_max=[5.0, 5.0]))
    law = hc.SampledLaw.emulated(design, 0.05)
    one_by_one = hc.OnlineController(law, options)
    replayed = hc.OnlineController(law, options)
    for controller in (one_by_one, replayed):
        controller.reset(0.0, q[0])
    u_steps, statuses = [], []
    for i in range(60):
        u, report = one_by_one.step(t_now[i], q[i], t_meas[i])
        u_steps.append(u)
        statuses.append(report.measurement)
    u_replay, reports = replayed.replay(t_now, q, t_meas)
    np.testing.assert_array_equal(u_replay, np.array(u_steps))
    assert [r.measurement for r in reports] == statuses
    assert statuses[20] == hc.MeasurementUse.duplicate and statuses[30] == hc.MeasurementUse.not_finite
    assert replayed.counts() == one_by_one.counts()
    with pytest.raises(ValueError, match="shape"):
        replayed.replay(t_now, q[:, :3])
    with pytest.raises(ValueError, match="before reset"):
        hc.OnlineController(law).replay(t_now, q)


@pytest.mark.slow
def test_the_fixed_rate_loop_example_tracks_like_the_continuous_loop():
    # examples/online_loop.py: the plant integrated in NumPy, the controller called at 20 Hz. The
    # held command costs about 2% at T = 0.05 s (tests/cpp/test_online_controller.cpp measures the
    # same in C++); within 5% of the continuous loop's RMS (run_scenario, CVODE).
    example = runpy.run_path(str(ROOT / "examples" / "online_loop.py"), run_name="example")
    trajectory, design = example["paper_design"]()
    sampled = example["run_loop"](trajectory, hc.SampledLaw.emulated(design, 0.05), 0.05)
    continuous = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1"))).metrics.rms_position_error_last_half
    assert 1.0 <= sampled / continuous <= 1.05, (sampled, continuous)


def test_simulate_sampled_surface(trajectory, design):
    w = hc.Signal(0.0, [hc.Harmonic(0.1, 2 * np.pi * 0.2, cosine=True)])
    q0 = [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4]
    controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
    run = hc.simulate_sampled(trajectory, controller, [w, w, w, 0, 0, 0], q0)
    assert run.status == hc.RunStatus.completed and run.q.shape == (1001, 6) and run.u.shape == (1001, 2)
    # The command is held between samples: within each 0.1 s it takes one value.
    np.testing.assert_array_equal(run.u[1:10], np.repeat(run.u[1:2], 9, axis=0))
    assert controller.counts().steps == 100
    metrics = hc.compute_metrics(trajectory.model(), run, np.eye(6))
    assert 0 < metrics.rms_position_error_last_half < 0.2
    options = hc.SampledLoopOptions(delay=0.1)
    assert pickle.loads(pickle.dumps(options)) == options
    with pytest.raises(ValueError, match=r"delay must be in \[0, T\]"):
        hc.simulate_sampled(trajectory, controller, None, q0, hc.SampledLoopOptions(delay=0.2))
    other = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 10.0)
    with pytest.raises(ValueError, match="another trajectory"):
        hc.simulate_sampled(other, controller, None, q0)


def test_output_feedback_controller_surface(trajectory, design):
    # The filter of the paper's Figure 2: y = (x, y, psi) with sigma = 0.5, N = sigma^2 I.
    f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
    law = hc.SampledLaw.emulated(design, 0.05)
    options = hc.OnlineOptions(filter=f, limits=hc.ActuatorLimits(u_min=[-3.0, -3.0], u_max=[3.0, 3.0]))
    assert pickle.loads(pickle.dumps(options)) == options
    one_by_one, replayed = hc.OnlineController(law, options), hc.OnlineController(law, options)
    assert one_by_one.output_feedback() and one_by_one.measurement_size() == 3
    rng = np.random.default_rng(11)
    t_now = np.arange(0, 60) * 0.05
    y = np.array([-1.0, -1.0, np.pi / 4]) + 0.5 * rng.standard_normal((60, 3))
    y[25] = np.nan
    for controller in (one_by_one, replayed):
        controller.reset(0.0, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    u_steps = np.array([one_by_one.step(t, row, t)[0] for t, row in zip(t_now, y)])
    u_replay, reports = replayed.replay(t_now, y)
    np.testing.assert_array_equal(u_replay, u_steps)
    np.testing.assert_array_equal(replayed.sigma(), one_by_one.sigma())
    assert reports[25].measurement == hc.MeasurementUse.not_finite
    assert all(0.0 < r.rho_sigma_z < 25.0 and not r.coupling_violated for r in reports)
    assert replayed.counts().used == 59 and 0.0 < replayed.counts().largest_rho < 1.0
    with pytest.raises(ValueError, match=r"shape \(3,\) \(the measured outputs"):
        one_by_one.step(3.0, np.zeros(6))
    with pytest.raises(ValueError, match="N"):
        hc.OnlineController(law, hc.OnlineOptions(filter=hc.OnlineFilter(N=np.eye(2), Sigma0=np.eye(6), Q=np.eye(6))))


def test_simulate_sampled_with_output_feedback(trajectory, design):
    w = hc.Signal(0.0, [hc.Harmonic(0.1, 2 * np.pi * 0.2, cosine=True)])
    f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
    controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1), hc.OnlineOptions(filter=f))
    noise = hc._core.standard_normal_samples(5, hc._core.noise_sample_count(0.0, 10.0, 0.1), 3)
    options = hc.SampledLoopOptions(sigma=0.5, noise=noise)
    run = hc.simulate_sampled(trajectory, controller, [w, w, w, 0, 0, 0], [1.0, 0.0, 0.0, -1.0, -1.0, 0.0], options)
    assert run.status == hc.RunStatus.completed and controller.counts().used == 100
    # A sensor read every second sample: half the steps predict.
    hc.simulate_sampled(trajectory, controller, None, np.zeros(6),
                        hc.SampledLoopOptions(sigma=0.5, noise=noise, measurement_every=2))
    assert controller.counts().used == 50 and controller.counts().predicted == 50
    with pytest.raises(ValueError, match="measurement_every must be >= 1"):
        hc.simulate_sampled(trajectory, controller, None, np.zeros(6), hc.SampledLoopOptions(measurement_every=0))
    with pytest.raises(ValueError, match="rows"):
        hc.simulate_sampled(trajectory, controller, None, np.zeros(6), hc.SampledLoopOptions(sigma=0.5, noise=noise[:5]))
    state_feedback = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
    with pytest.raises(ValueError, match="output-feedback controller"):
        hc.simulate_sampled(trajectory, state_feedback, None, np.zeros(6), options)


def test_a_sampled_law_pickles_to_the_same_controller(trajectory, design):
    # A law shipped to another process (a Dask worker, say) runs the same steps bit for bit.
    for law in (hc.SampledLaw.emulated(design, 0.1),
                hc.SampledLaw.digital(hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0))):
        copy = pickle.loads(pickle.dumps(law))
        assert (copy.kind(), copy.gamma(), copy.period(), copy.steps()) == (law.kind(), law.gamma(), law.period(),
                                                                          law.steps())
        f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
        controllers = [hc.OnlineController(x, hc.OnlineOptions(filter=f)) for x in (law, copy)]
        y = np.tile([-1.0, -1.0, 0.5], (20, 1))
        results = []
        for controller in controllers:
            controller.reset(0.0, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
            results.append(controller.replay(np.arange(20) * 0.1 + 0.05, y)[0])
        np.testing.assert_array_equal(results[0], results[1])
    # A damaged state is an error naming what is wrong, not a crash.
    state = hc.SampledLaw.emulated(design, 0.1).__getstate__()
    with pytest.raises(ValueError, match="gains"):
        hc.SampledLaw.__new__(hc.SampledLaw).__setstate__((*state[:4], state[4][:3], state[5]))
    with pytest.raises(ValueError, match="emulated"):
        hc.SampledLaw.__new__(hc.SampledLaw).__setstate__((state[0], "analog", *state[2:]))
