"""Limits that keep every run meaningful and bounded: solver tolerances, the step budget of a
whole run, divergence, memory, gamma* threads, the heading error as an angle, and sigma = 0.

Each test reproduces a defect of the hardening issue: before the fix it failed (a wrong
number, a hang, an abort, or a run that spun the ship a full turn)."""

from __future__ import annotations

import json
import math
import os
import pathlib
import resource
import subprocess
import sys

import numpy as np
import pytest

import hinf_cpp as hc
from _support import PAPER_Q0, PAPER_Q_D0

BIN = pathlib.Path(sys.executable).parent
METRIC_NAMES = [definition.name for definition in hc.metric_table()]
HINF_SIM, HINF_CPP = BIN / "hinf-sim", BIN / "hinf-cpp"
PAPER_FIG1 = hc.scenario_path("paper_fig1").read_text()


def paper(**changes) -> hc.Scenario:
    """The Figure-1 scenario with some fields changed."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    for key, value in changes.items():
        setattr(scenario, key, value)
    return scenario


def write(tmp_path, name: str, text: str) -> pathlib.Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def replace(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new)


# ======================================================================================
# Solver tolerances that cannot give an answer are refused
# ======================================================================================

@pytest.mark.parametrize("options, kwargs, words", [
    ("SolverOptions", dict(rtol=1.0), r"rtol must be in \[1e-14, 1e-3\]"),
    ("SolverOptions", dict(rtol=1e-2), r"rtol must be in \[1e-14, 1e-3\]"),
    ("SolverOptions", dict(rtol=1e-16), r"rtol must be in \[1e-14, 1e-3\]"),
    ("SolverOptions", dict(atol=1e10), r"atol must be in \(0, 1e-3\]"),
    ("SolverOptions", dict(atol=1.0), r"atol must be in \(0, 1e-3\]"),
    ("SolverOptions", dict(atol=0.0), r"atol must be in \(0, 1e-3\]"),
    ("SolverOptions", dict(method="erk", rtol=1.0, atol=1.0), r"rtol must be in"),
    ("SolverOptions", dict(max_steps=0), r"max_steps must be in \[1, 1e9\]"),
    ("SimulationOptions", dict(divergence_factor=1.0), r"divergence_factor must be a finite number > 1"),
    ("SimulationOptions", dict(divergence_factor=math.nan), r"divergence_factor"),
    ("SimulationOptions", dict(output_dt=0.0), r"dt must be > 0"),
])
def test_meaningless_solver_options_are_refused(options, kwargs, words):
    # Before: rtol = 1 "succeeded" with an RMS error of 0.499 instead of 0.048, atol = 1e10 gave
    # a final position error of 1.6e10, and (erk, 1, 1) reported a conjugate point at gamma = 5.
    with pytest.raises(ValueError, match=words):
        getattr(hc, options)(**kwargs)


@pytest.mark.parametrize("program", ["hinf-sim", "hinf-cpp"])
@pytest.mark.parametrize("old, new", [("rtol = 1e-8", "rtol = 1.0"), ("atol = 1e-10", "atol = 1e10")])
def test_meaningless_tolerances_in_a_scenario_file_are_exit_status_2(tmp_path, program, old, new):
    path = write(tmp_path, "loose.toml", replace(PAPER_FIG1, old, new))
    args = [HINF_SIM, path] if program == "hinf-sim" else [HINF_CPP, "run", path]
    done = subprocess.run(args, capture_output=True, text=True, timeout=120)
    assert done.returncode == 2, done.stderr
    assert len(done.stderr.strip().splitlines()) == 1
    assert "must be in" in done.stderr


# ======================================================================================
# max_steps bounds the whole run, in every loop
# ======================================================================================

@pytest.mark.parametrize("method", ["bdf", "adams"])
def test_max_steps_bounds_the_whole_cvode_closed_loop(paper_trajectory, paper_solutions, method):
    """CVODE's own limit counts per call, and the loop called it once per output time (4000
    calls), so a budget far below the loop's total number of steps never stopped it."""
    law = hc.HinfStateFeedback(paper_solutions["erk"])
    full = hc.simulate_state_feedback(paper_trajectory, law, None, PAPER_Q0,
                                      hc.SimulationOptions(output_dt=0.01, solver=hc.SolverOptions(method)))
    budget = full.stats.steps // 3
    assert budget > 100  # far more than the steps between two output times
    with pytest.raises(hc.SolverError, match=f"max_steps = {budget}") as error:
        solver = hc.SolverOptions(method, max_steps=budget)
        hc.simulate_state_feedback(paper_trajectory, law, None, PAPER_Q0, hc.SimulationOptions(0.01, solver=solver))
    assert 0.0 < error.value.t < 40.0


@pytest.mark.parametrize("method", ["adams", "erk", "bdf"])
def test_max_steps_bounds_the_whole_output_feedback_loop(method):
    """The sampled loop restarts its integrator at each of the 4000 noise samples; the budget
    counted per restart (Adams) or per hold interval (erk, bdf), so max_steps = 2000 never
    stopped a loop that needs ~30000 steps."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    scenario.solver = hc.SolverOptions(method, max_steps=2000)
    with pytest.raises(hc.SolverError, match="max_steps"):
        hc.run_scenario(scenario)


# ======================================================================================
# A closed loop that leaves the neighbourhood of the trajectory stops, and says so
# ======================================================================================

def huge_disturbance_text(amplitude: float = 1e6) -> str:
    return replace(PAPER_FIG1, 'w1 = { harmonics = [ { amplitude = 0.1',
                   f'w1 = {{ harmonics = [ {{ amplitude = {amplitude:g}')


@pytest.mark.parametrize("method", ["bdf", "adams", "erk"])
def test_a_diverging_state_feedback_run_stops_and_says_so(tmp_path, method):
    """w1 with amplitude 1e6 ran for more than 400 s in both front ends (max_steps per output
    point, integrating a state of size 1e7 for the whole horizon). Now the run stops when the
    tracking error exceeds divergence_factor x max(1, |q_e(t0)|, max |q_d|) = 1e3 x 40 m."""
    scenario = hc.load_scenario(write(tmp_path, "storm.toml", huge_disturbance_text()))
    scenario.solver = hc.SolverOptions(method)
    result = hc.run_scenario(scenario)
    sim = result.simulation
    assert sim.status == hc.RunStatus.diverged
    assert "divergence bound" in sim.status_message and "divergence_factor" in sim.status_message
    # The bound: 1e3 times the largest of 1, |q_e(t0)|_inf = 1 and max |q_d|_inf (x_d reaches ~30 m).
    q_d = result.trajectory.q_d(np.linspace(0.0, 40.0, 4001))
    bound = 1e3 * max(1.0, np.abs(q_d).max())
    # The series stop at the last output time before the bound was crossed, well before tf.
    assert sim.t[-1] < 0.5 * scenario.tf and sim.t.size == sim.q.shape[0] == sim.u.shape[0]
    assert np.abs(sim.q_e()).max() <= bound
    assert sim.stats.steps < 5000
    metrics = result.metrics
    assert math.isfinite(metrics.max_position_error)
    for name in ("rms_position_error_last_half", "final_position_error", "response_ratio", "control_l2"):
        assert math.isnan(getattr(metrics, name)), name


@pytest.mark.parametrize("program", ["hinf-sim", "hinf-cpp"])
def test_a_diverging_run_is_a_status_in_the_results_file(tmp_path, program):
    path = write(tmp_path, "storm.toml", huge_disturbance_text())
    out = tmp_path / "out.json"
    args = [HINF_SIM, path, "--json", out] if program == "hinf-sim" else [HINF_CPP, "run", path, "--json", out]
    done = subprocess.run(args, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    warning = done.stderr.strip().splitlines()
    assert len(warning) == 1 and "warning" in warning[0] and "diverged" in warning[0]
    results = json.loads(out.read_text())
    assert results["status"] == "diverged" and "divergence bound" in results["status_message"]
    assert results["metrics"]["final_position_error"] is None


def test_a_completed_run_has_status_completed(paper_run):
    assert paper_run.simulation.status == hc.RunStatus.completed and paper_run.simulation.status_message == ""
    assert json.loads(hc._core.results_json(paper_run))["status"] == "completed"


def test_an_unstable_uncontrolled_plant_diverges_in_output_feedback():
    """A plant with an unstable mode that neither the input nor the disturbance reaches (so the
    design exists at every gamma): the error grows like e^t."""
    A = np.array([[1.0, 0.0], [0.0, -1.0]])
    model = hc.LinearModel(A, np.array([[0.0], [1.0]]), np.array([[0.0], [1.0]]), np.eye(2))
    trajectory = hc.Trajectory(model, np.zeros(2), [0.0], 0.0, 10.0)
    # Barely weighted, the unstable mode keeps Z moderate (z11 = 1e-6 e^20 ~ 500 at t0), so the
    # coupling condition rho(Sigma Z) < gamma^2 = 2500 holds and the run is stopped by divergence.
    design = hc.solve_grde(trajectory, np.diag([0.0, 1.0]), np.diag([1e-6, 1.0]), 50.0)
    noise = hc._core.standard_normal_samples(1, hc._core.noise_sample_count(0.0, 10.0, 0.1), 2)
    problem = hc.OutputFeedbackProblem(design=design, sigma=0.1, sample_period=0.1, noise=noise,
                                       N=0.01 * np.eye(2), Sigma0=np.eye(2), Q=np.eye(2))
    sim = hc.simulate_output_feedback(problem, hc.HinfStateFeedback(design), None, np.array([1.0, 0.0]),
                                      simulation=hc.SimulationOptions(output_dt=0.05))
    # |q_e| = e^t reaches the bound 10 x max(1, |q_e(t0)| = 1, q_d = 0) at t = log(10) ~ 2.30:
    # the series end at the last output time before (dt = 0.05).
    assert sim.status == hc.RunStatus.diverged
    assert math.log(10.0) - 0.1 < sim.t[-1] < math.log(10.0)
    q_hat = sim.estimator.q_hat
    assert np.all(np.isfinite(q_hat)) and q_hat.shape == sim.q.shape


# ======================================================================================
# Memory: a run that would not fit is refused before it allocates
# ======================================================================================

def test_an_output_grid_too_large_for_the_machine_is_refused_before_allocating():
    """dt = 1e-6 on the 40 s paper run: 4e7 output times x 25 columns = 8 GB; before, the run
    failed after gigabytes with bad_alloc / MemoryError. The limit is a quarter of the memory."""
    scenario = paper(output_dt=1e-7)  # 4e8 points: 80 GB, beyond a quarter of any test machine
    with pytest.raises(ValueError, match=r"would need .* GB, more than a quarter of this machine's memory.*\[output\] dt"):
        hc.run_scenario(scenario)


def test_too_many_noise_samples_are_refused_before_allocating():
    with pytest.raises(ValueError, match=r"more than"):
        hc._core.standard_normal_samples(1, 10**11, 3)
    # A scenario whose sample period would need that many samples: refused by the memory limit.
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    measurement = scenario.measurement
    measurement.sample_period = 1e-10
    scenario.measurement = measurement
    with pytest.raises(ValueError, match=r"noise samples would need .* sample_period"):
        hc.run_scenario(scenario)


# ======================================================================================
# gamma* with many threads
# ======================================================================================

THREADS_SCRIPT = r"""
import numpy as np, hinf_cpp as hc
tr = hc.Trajectory(hc.LinearModel(np.array([[0.2, 1.0], [-1.0, -0.5]]), np.array([[0.0], [1.0]]),
                                  np.eye(2)), np.zeros(2), [0.0], 0.0, 10.0)
for threads in (1, 200, 2000):
    r = hc.gamma_star(tr, np.eye(2), np.eye(2), hc.GammaStarOptions(threads=threads, max_evaluations=5000))
    print(threads, repr(r.gamma_star), r.converged, len(r.trials))
"""


def test_gamma_star_with_more_threads_than_the_machine_or_the_system_allows():
    """--threads 2000 aborted the process (terminate called without an active exception) when a
    thread could not be created, and --threads 200 returned gamma* = 2, 'not converged', after 2
    evaluations. Threads are now capped at the hardware's; a thread that cannot be created runs
    its gamma on the calling thread. The child runs with a huge default thread stack (glibc
    takes RLIMIT_STACK) under an address-space limit, so that creating threads fails."""
    def limits():
        resource.setrlimit(resource.RLIMIT_STACK, (8 << 30, 8 << 30))
        resource.setrlimit(resource.RLIMIT_AS, (6 << 30, 6 << 30))

    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    for preexec in (None, limits):
        done = subprocess.run([sys.executable, "-c", THREADS_SCRIPT], capture_output=True, text=True,
                              preexec_fn=preexec, env=env, timeout=300)
        assert done.returncode == 0, done.stderr[-2000:]
        rows = [line.split() for line in done.stdout.strip().splitlines()]
        stars = [float(row[1]) for row in rows]
        assert all(row[2] == "True" for row in rows), rows
        # Every thread count brackets the same gamma* to the bisection tolerance (1e-7).
        assert max(stars) - min(stars) <= 2e-7 * max(stars), rows


def test_gamma_star_threads_leave_enough_evaluations_to_converge(lti_trajectory):
    """With few evaluations allowed, fewer gammas per round: the k-section still converges."""
    tr = lti_trajectory([[0.2, 1.0], [-1.0, -0.5]], [[0.0], [1.0]], np.eye(2), 0.0, 10.0)
    result = hc.gamma_star(tr, np.eye(2), np.eye(2), hc.GammaStarOptions(threads=64, max_evaluations=60))
    assert result.converged and len(result.trials) <= 60


# ======================================================================================
# The heading error is an angle
# ======================================================================================

def heading_start(psi0: float, law: hc.Law = hc.Law.hinf, fig: str = "paper_fig1") -> hc.RunResult:
    scenario = hc.load_scenario(hc.scenario_path(fig))
    q0 = np.array(PAPER_Q0)
    q0[5] = psi0
    scenario.initial_q0 = q0
    scenario.law = law
    return hc.run_scenario(scenario)


@pytest.mark.parametrize("law", [hc.Law.hinf, hc.Law.lqr])
def test_a_start_350_degrees_off_is_a_10_degree_error(law):
    """psi(t0) = psi_d + 350 deg is physically 10 deg off. Before, both laws regulated the
    unwrapped 350 deg to zero and spun the ship a full turn."""
    off_350 = heading_start(math.radians(350.0), law)
    off_minus_10 = heading_start(math.radians(-10.0), law)
    q_e_350, q_e_10 = off_350.simulation.q_e(), off_minus_10.simulation.q_e()
    # The same physical start: the runs agree up to the integration error of the closed loop
    # (rtol 1e-8 on states of order 1-30, accumulated over 4000 output times: 1e-5 with margin).
    np.testing.assert_allclose(q_e_350, q_e_10, atol=1e-5)
    # The ship does not spin a full turn: the continuous heading error starts at -10 degrees
    # and stays within 45 degrees (the 1 m offset of the start makes it turn ~21 degrees).
    from hinf_cpp.analysis.comparison import heading_error
    e = heading_error(off_350)
    assert abs(e[0] - math.radians(-10.0)) < 1e-12
    assert np.max(np.abs(e)) < math.radians(45.0)
    for name in METRIC_NAMES:
        assert getattr(off_350.metrics, name) == pytest.approx(getattr(off_minus_10.metrics, name), rel=1e-5,
                                                               abs=1e-9, nan_ok=True), name


@pytest.mark.parametrize("fig", ["paper_fig1", "paper_fig2"])
def test_a_start_two_pi_further_round_gives_the_same_run(fig):
    base = heading_start(PAPER_Q0[5], fig=fig)
    turned = heading_start(PAPER_Q0[5] + 2.0 * math.pi, fig=fig)
    shift = np.zeros(6)
    shift[5] = 2.0 * math.pi
    # Integration error only (see above); output feedback: the same noise, the same estimator.
    np.testing.assert_allclose(turned.simulation.q - shift, base.simulation.q, atol=1e-5)
    np.testing.assert_allclose(turned.simulation.u, base.simulation.u, atol=1e-5)
    for name in METRIC_NAMES:
        assert getattr(turned.metrics, name) == pytest.approx(getattr(base.metrics, name), rel=1e-5, abs=1e-9,
                                                              nan_ok=True), name


def test_recovery_from_350_degrees_does_not_turn_around():
    from hinf_cpp.analysis.recovery import assess_recovery

    verdict = assess_recovery(heading_start(math.radians(350.0)))
    assert verdict.recovers and not verdict.turns_around
    assert abs(verdict.initial_heading_error - math.radians(-10.0)) < 1e-12


# ======================================================================================
# sigma = 0: no noise is applied, so the noise channels of w are zero
# ======================================================================================

def test_noise_free_measurements_do_not_count_as_disturbance():
    """With sigma = 0 the noise channels w4..w6 reach neither the plant nor the measurement;
    before, their unit samples were recorded in w and counted in disturbance_l2 (response_ratio 0.17
    instead of 3.08)."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    measurement = scenario.measurement
    measurement.sigma = 0.0
    measurement.N = 0.25 * np.eye(3)
    scenario.measurement = measurement
    result = hc.run_scenario(scenario)
    w = result.simulation.w
    assert np.all(w[:, 3:] == 0.0)
    t = result.simulation.t
    applied = np.sqrt(np.trapezoid(np.sum(w[:, :3] ** 2, axis=1), t))
    assert result.metrics.disturbance_l2 == pytest.approx(applied, rel=1e-12)
    assert result.metrics.response_ratio > 1.0


def test_a_noise_channel_set_from_python_is_refused_like_in_a_file():
    """The reader refuses w4..w6 in [disturbance]; a scenario built in Python gets the same rule
    (before, w4 = 0.1 changed disturbance_l2 and response_ratio without changing the motion)."""
    scenario = paper()
    signals = [hc.Signal(0.1), hc.Signal(), hc.Signal(), hc.Signal(0.1), hc.Signal(), hc.Signal()]
    scenario.disturbance = signals
    with pytest.raises(ValueError, match=r"w4 is a measurement-noise channel"):
        hc.run_scenario(scenario)
    scenario.disturbance = lambda t: np.array([0.1, 0, 0, 0, 0.2, 0])
    with pytest.raises(ValueError, match=r"w5 is a measurement-noise channel"):
        hc.run_scenario(scenario)
    scenario.disturbance = lambda t: np.array([0.1, 0, 0, 0, 0, 0])
    assert hc.run_scenario(scenario).simulation.status == hc.RunStatus.completed


def test_divergence_factor_is_a_solver_key(tmp_path):
    """[solver] divergence_factor sets the bound: 1.5 x max(1, 1, max |q_d| = 22 m) stops a run
    whose disturbance (amplitude 30 on the surge force; errors up to ~200) the default bound of
    1e3 x 22 m lets run to tf (where it ends far off the path: lost_track, not diverged)."""
    text = huge_disturbance_text(30.0)
    status = hc.run_scenario(hc.load_scenario(write(tmp_path, "a.toml", text))).simulation.status
    assert status == hc.RunStatus.lost_track
    tight = replace(text, "atol = 1e-10", "atol = 1e-10\ndivergence_factor = 1.5")
    status = hc.run_scenario(hc.load_scenario(write(tmp_path, "b.toml", tight))).simulation.status
    assert status == hc.RunStatus.diverged
    with pytest.raises(ValueError, match=r"b\.toml: \[solver\] divergence_factor must be a finite number > 1"):
        hc.load_scenario(write(tmp_path, "b.toml", replace(tight, "= 1.5", "= 1.0")))
