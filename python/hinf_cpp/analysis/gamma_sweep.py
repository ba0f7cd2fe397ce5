"""Attenuation against gamma: the measured L2 gain and the cost L_gamma of paper eq. (12)
over a range of gammas above gamma*."""

from __future__ import annotations

import dataclasses
import itertools
import math
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from hinf_cpp import _core
from hinf_cpp.output.progress import ProgressCallback

__all__ = ["GammaSweep", "cost_L_gamma", "sweep_gamma"]


def cost_L_gamma(result: _core.RunResult, Q: np.ndarray, Qf: np.ndarray) -> float:
    """L_gamma of paper eq. (12) on the run's output grid (trapezoid rule):
    int (|q_e|_Q^2 + |u_e|^2 - gamma^2 |w|^2) dt + |q_e(tf)|_Qf^2, w every applied channel."""
    sim = result.simulation
    q_e = sim.q_e()
    u_e = sim.u - sim.u_d
    integrand = (np.einsum("ki,ij,kj->k", q_e, Q, q_e) + np.sum(u_e**2, axis=1)
                 - result.gamma**2 * np.sum(sim.w**2, axis=1))
    return float(np.trapezoid(integrand, sim.t) + q_e[-1] @ Qf @ q_e[-1])


@dataclasses.dataclass
class GammaSweep:
    """Closed-loop runs of one scenario over a range of gammas."""

    scenario: str
    gamma_star: float
    gamma_star_output_feedback: float | None
    gammas: np.ndarray
    l2_gain: np.ndarray       # sqrt(int |q_e|_Q^2 + |u_e|^2) / sqrt(int |w|^2)
    cost: np.ndarray          # L_gamma of eq. (12)
    zero_initial_error: bool  # True: q(t0) = q_d(t0), so the gain is the disturbance's alone

    def to_dict(self) -> dict:
        return {
            "scenario": self.scenario,
            "gamma_star": self.gamma_star,
            "gamma_star_output_feedback": self.gamma_star_output_feedback,
            "zero_initial_error": self.zero_initial_error,
            "gamma": self.gammas.tolist(),
            "l2_gain": self.l2_gain.tolist(),
            "cost_L_gamma": self.cost.tolist(),
        }


def sweep_gamma(scenario: _core.Scenario, count: int = 12, upper: float | None = None,
                zero_initial_error: bool = True, threads: int = 2,
                gamma_star_options: _core.GammaStarOptions | None = None,
                progress: ProgressCallback | None = None) -> GammaSweep:
    """Runs the scenario at `count` gammas spaced geometrically from just above the smallest
    admissible gamma (gamma*, or the output-feedback one with [measurement]) to `upper`
    (default: the larger of 4 times the scenario's gamma and 10 gamma*).

    With zero_initial_error the runs start on the desired trajectory, so the measured gain is
    the disturbance-to-error gain that the design bounds by gamma for the linearized error
    system (the worst case over all disturbances; the scenario's disturbance gains less).

    ``progress(index, total, message)`` is called as each run starts (from the worker threads)."""
    if count < 2:
        raise ValueError(f"sweep_gamma needs count >= 2, got {count}")
    options = gamma_star_options or _core.GammaStarOptions()
    star = _core.scenario_gamma_star(scenario, options).gamma_star
    star_of = None
    lowest = star
    if scenario.measurement is not None:
        star_of = _core.scenario_gamma_star_output_feedback(scenario, options).gamma_star
        lowest = max(star, star_of)
    top = upper if upper is not None else max(4.0 * scenario.gamma, 10.0 * lowest)
    if not top > lowest:
        raise ValueError(f"the sweep's upper end {top:g} must exceed the smallest admissible gamma {lowest:g}")
    gammas = np.geomspace(lowest * (1.0 + 1e-3), top, count)

    counter, lock = itertools.count(1), threading.Lock()

    def run(gamma: float) -> _core.RunResult:
        if progress is not None:
            with lock:
                index = next(counter)
            progress(index, len(gammas), f"running {scenario.name} at gamma = {gamma:.5g}")
        variant = scenario.copy()
        variant.gamma = float(gamma)
        if zero_initial_error:
            variant.initial_q0 = variant.desired_q0
        return _core.run_scenario(variant)

    if type(scenario.model).__module__ != _core.__name__:
        threads = 1  # a model implemented in Python holds the GIL in every call: no parallel gain
    with ThreadPoolExecutor(max_workers=max(1, threads)) as pool:
        results = list(pool.map(run, gammas))
    resolved = scenario.resolved()
    return GammaSweep(
        scenario=scenario.name,
        gamma_star=star,
        gamma_star_output_feedback=star_of,
        gammas=gammas,
        l2_gain=np.array([r.metrics.l2_gain for r in results]),
        cost=np.array([cost_L_gamma(r, resolved.Q, resolved.Qf) for r in results]),
        zero_initial_error=zero_initial_error,
    )


def sweep_figure(sweep: GammaSweep):
    """Measured L2 gain and L_gamma against gamma, gamma* marked."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.0, 6.4), layout="constrained")
    ax_gain, ax_cost = fig.subplots(2, 1, sharex=True)
    ax_gain.plot(sweep.gammas, sweep.l2_gain, "o-", color="tab:blue", label="measured L2 gain")
    ax_gain.plot(sweep.gammas, sweep.gammas, "--", color="gray",
                 label="gain = gamma (bound for the linearized error system)")
    ax_cost.plot(sweep.gammas, sweep.cost, "o-", color="tab:red", label="L_gamma, eq. (12)")
    ax_cost.axhline(0.0, color="gray", lw=0.8)
    for ax in (ax_gain, ax_cost):
        ax.axvline(sweep.gamma_star, color="black", ls=":", label=f"gamma* = {sweep.gamma_star:.5g}")
        if sweep.gamma_star_output_feedback is not None:
            ax.axvline(sweep.gamma_star_output_feedback, color="tab:purple", ls=":",
                       label=f"output-feedback gamma* = {sweep.gamma_star_output_feedback:.5g}")
        ax.set_xscale("log")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize="small", loc="best")
    start = "from the desired state" if sweep.zero_initial_error else "from the scenario's initial state"
    ax_gain.set_ylabel("L2 gain [-]")
    ax_gain.set_title(f"{sweep.scenario}: attenuation against gamma ({start})")
    ax_cost.set_ylabel("L_gamma [-]")
    ax_cost.set_xlabel("gamma [-]")
    return fig


def certificates_dict(c: _core.Certificates) -> dict:
    """The certificates as a JSON-ready dictionary, every field of :class:`Certificates` in
    order (non-finite numbers as None)."""
    def value(x):
        return None if isinstance(x, float) and not math.isfinite(x) else x

    return {name: value(getattr(c, name)) for name in c.__match_args__}
