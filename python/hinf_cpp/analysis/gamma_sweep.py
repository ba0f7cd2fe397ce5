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
    """The cost L_gamma of paper eq. (12) of a run, on its output grid (trapezoid rule).

    L_gamma = int (|q_e|_Q^2 + |u_e|^2 - gamma^2 |w|^2) dt + |q_e(tf)|_Qf^2, with
    q_e = q - q_d, u_e = u - u_d, gamma the run's design gamma and w every applied
    disturbance channel. It is <= 0 for every w when the run starts on the desired trajectory
    and the design attenuates to level gamma (for the linearized error system).

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.
    Q : array_like, shape (n, n)
        The state weight (the scenario's resolved ``Q``).
    Qf : array_like, shape (n, n)
        The terminal weight (the scenario's resolved ``Qf``).

    Returns
    -------
    float
        L_gamma.

    Examples
    --------
    >>> from hinf_cpp.analysis.gamma_sweep import cost_L_gamma
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.initial_q0 = scenario.desired_q0  # start on the desired trajectory
    >>> resolved = scenario.resolved()
    >>> cost_L_gamma(hc.run_scenario(scenario), resolved.Q, resolved.Qf) < 0
    True
    """
    sim = result.simulation
    q_e = sim.q_e()
    u_e = sim.u - sim.u_d
    integrand = (np.einsum("ki,ij,kj->k", q_e, Q, q_e) + np.sum(u_e**2, axis=1)
                 - result.gamma**2 * np.sum(sim.w**2, axis=1))
    return float(np.trapezoid(integrand, sim.t) + q_e[-1] @ Qf @ q_e[-1])


@dataclasses.dataclass
class GammaSweep:
    """Attenuation against gamma: closed-loop runs of one scenario over a range of gammas.

    What :func:`sweep_gamma` returns; ``to_dict()`` gives it as a JSON-ready dictionary.

    Parameters
    ----------
    scenario : str
        The scenario's name.
    gamma_star : float
        gamma* of the state-feedback design (paper eq. 14).
    gamma_star_output_feedback : float or None
        The smallest gamma of the output-feedback design, for a scenario with [measurement].
    gammas : numpy.ndarray, shape (count,)
        The gammas run, increasing.
    response_ratio : numpy.ndarray, shape (count,)
        The measured ratio of each run (metric ``response_ratio``): sqrt(|q_e(tf)|_Qf^2 +
        int |q_e|_Q^2 + |u_e|^2 dt) / sqrt(int |w|^2 dt); the L2 gain of the disturbance alone
        when ``zero_initial_error``.
    cost : numpy.ndarray, shape (count,)
        L_gamma of paper eq. (12) of each run (:func:`cost_L_gamma`).
    zero_initial_error : bool
        True: q(t0) = q_d(t0), so the gain is the disturbance's alone.
    induced_gain : numpy.ndarray, shape (count,)
        The induced L2 gain of the state-feedback law designed at each gamma, its closed loop
        linearized along the desired trajectory (:func:`hinf_cpp.law_gain`): the worst case
        over all disturbances, below gamma; NaN where the run keeps no design.

    Examples
    --------
    >>> from hinf_cpp.analysis import sweep_gamma
    >>> sweep = sweep_gamma(hc.load_scenario(hc.scenario_path("paper_fig1")), count=3)
    >>> round(sweep.gamma_star, 3), sweep.gammas.shape
    (1.335, (3,))
    >>> bool(np.all(sweep.response_ratio < sweep.gammas)), bool(np.all(sweep.cost < 0))
    (True, True)
    >>> bool(np.all((sweep.response_ratio <= sweep.induced_gain) & (sweep.induced_gain < sweep.gammas)))
    True
    """

    scenario: str
    gamma_star: float
    gamma_star_output_feedback: float | None
    gammas: np.ndarray
    response_ratio: np.ndarray  # sqrt(|q_e(tf)|_Qf^2 + int |q_e|_Q^2 + |u_e|^2) / sqrt(int |w|^2)
    cost: np.ndarray          # L_gamma of eq. (12)
    zero_initial_error: bool  # True: q(t0) = q_d(t0), so the gain is the disturbance's alone
    induced_gain: np.ndarray  # hinf_cpp.law_gain of the design at each gamma (NaN: no design kept)

    def to_dict(self) -> dict:
        return {
            "scenario": self.scenario,
            "gamma_star": self.gamma_star,
            "gamma_star_output_feedback": self.gamma_star_output_feedback,
            "zero_initial_error": self.zero_initial_error,
            "gamma": self.gammas.tolist(),
            "response_ratio": self.response_ratio.tolist(),
            "cost_L_gamma": self.cost.tolist(),
            "induced_l2_gain": self.induced_gain.tolist(),
        }


def sweep_gamma(scenario: _core.Scenario, count: int = 12, upper: float | None = None,
                zero_initial_error: bool = True, threads: int = 2,
                gamma_star_options: _core.GammaStarOptions | None = None,
                progress: ProgressCallback | None = None) -> GammaSweep:
    """Run a scenario over a range of gammas: the measured L2 gain and the cost L_gamma.

    The gammas are `count` values spaced geometrically from just above the smallest
    admissible gamma (gamma* of paper eq. 14, or the output-feedback one with [measurement],
    times 1.001) to `upper`. With `zero_initial_error` the runs start on the desired
    trajectory, so the measured gain is the disturbance-to-error gain that the design bounds
    by gamma for the linearized error system (the worst case over all disturbances; the
    scenario's disturbance gains less).

    Parameters
    ----------
    scenario : hinf_cpp.Scenario
        The scenario (not changed).
    count : int, optional
        The number of gammas (>= 2; default 12).
    upper : float, optional
        The largest gamma (default: the larger of 4 times the scenario's gamma and 10 gamma*).
    zero_initial_error : bool, optional
        Start every run on the desired trajectory (default True).
    threads : int, optional
        Runs at once (default 2; 1 for a model implemented in Python).
    gamma_star_options : hinf_cpp.GammaStarOptions, optional
        The options of the gamma* searches.
    progress : callable, optional
        ``progress(index, total, message)``, called as each run starts (from the worker
        threads).

    Returns
    -------
    GammaSweep
        The gammas, gains and costs.

    Raises
    ------
    ValueError
        `count` < 2, or `upper` not above the smallest admissible gamma.
    hinf_cpp.HinfError
        A gamma* search or a run failed numerically.

    Examples
    --------
    >>> from hinf_cpp.analysis import sweep_gamma
    >>> sweep = sweep_gamma(hc.load_scenario(hc.scenario_path("paper_fig1")), count=3, upper=20.0)
    >>> sweep.gammas.round(2)
    array([ 1.34,  5.17, 20.  ])
    >>> sweep.response_ratio.round(2)
    array([1.15, 1.05, 1.03])
    """
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

    def induced(result: _core.RunResult) -> float:
        if result.solution is None:
            return math.nan
        return float(_core.law_gain(result.solution, resolved.Q, resolved.Qf, resolved.kappa, options).gamma_star)

    return GammaSweep(
        scenario=scenario.name,
        gamma_star=star,
        gamma_star_output_feedback=star_of,
        gammas=gammas,
        response_ratio=np.array([r.metrics.response_ratio for r in results]),
        cost=np.array([cost_L_gamma(r, resolved.Q, resolved.Qf) for r in results]),
        zero_initial_error=zero_initial_error,
        induced_gain=np.array([induced(r) for r in results]),
    )


def sweep_figure(sweep: GammaSweep):
    """Measured L2 gain and L_gamma against gamma, gamma* marked."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.0, 6.4), layout="constrained")
    ax_gain, ax_cost = fig.subplots(2, 1, sharex=True)
    ax_gain.plot(sweep.gammas, sweep.response_ratio, "o-", color="tab:blue", label="measured L2 gain")
    ax_gain.plot(sweep.gammas, sweep.induced_gain, "s-", color="tab:green",
                 label="induced L2 gain of the law (linearized, worst case over all w)")
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
