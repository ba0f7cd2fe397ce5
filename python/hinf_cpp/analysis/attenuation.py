"""Attenuation of each state-feedback law: its worst-case disturbance and its gain against frequency.

A state-feedback law u = u_d - K(t) q_e, K = kappa B_e' Z (the H-infinity law: Z of the GRDE at
its gamma; the LQR law: at gamma = inf; for the ship baselines K = -du/dq at q_d), linearized
along the desired trajectory, is the closed loop

    dx/dt = A_cl(t) x + D_e(t) w,   A_cl = A_e - B_e K,   x(t0) = 0,

with the weighted error |z|^2 = x'Q x + |K x|^2 and the end cost x(tf)'Qf x(tf). Its induced L2
gain, sup_w sqrt(x(tf)'Qf x(tf) + int |z|^2) / ||w||, is :func:`hinf_cpp.law_gain`
(:func:`hinf_cpp.controller_gain` for the baselines).

:func:`worst_disturbance` finds the disturbance that attains it: the maximizer of that ratio, by
power iteration on T*T (T: w -> (z, x(tf))), on a uniform grid with RK4 and the exact adjoint of
the discrete map. :func:`gain_against_frequency` measures the gain of the NONLINEAR closed loop
for single-channel sinusoids over a range of frequencies (:func:`measured_ratio`), for every
law, and :func:`frequency_figure` draws it against each law's bound. worst_disturbance takes a
design (hinf, lqr); a baseline's worst case is the feedback one of
:func:`hinf_cpp.solve_controller_riccati`.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Iterable, Sequence

import numpy as np

from hinf_cpp import _core
from hinf_cpp.analysis.comparison import induced_gain, parse_controllers
from hinf_cpp.output.progress import ProgressCallback

__all__ = [
    "WorstDisturbance",
    "frequency_figure",
    "gain_against_frequency",
    "law_run",
    "measured_ratio",
    "worst_disturbance",
]

# Colours by law, as the other figures of the package draw them (output/plotting.py).
_LAW_COLOURS = {"hinf": "tab:blue", "lqr": "tab:orange", "cascade": "tab:green", "backstepping": "tab:purple"}


@dataclasses.dataclass
class WorstDisturbance:
    """The worst-case open-loop disturbance of a law's linearized closed loop.

    What :func:`worst_disturbance` returns. ``w`` has unit L2 norm (trapezoid rule on ``t``);
    ``signals(scale)`` gives it as one :class:`hinf_cpp.Signal` table per channel, linearly
    interpolated, the form in which it is applied to a closed loop.

    Parameters
    ----------
    t : numpy.ndarray, shape (steps + 1,)
        The uniform grid on [t0, tf] (s).
    w : numpy.ndarray, shape (steps + 1, nw)
        The signal's samples (w between them: linear), L2 norm 1.
    ratio : float
        The ratio sqrt(x(tf)'Qf x(tf) + int |z|^2) / ||w|| it attains on the discretized
        linear closed loop: the law's induced L2 gain up to the discretization error.
    iterations : int
        The power iterations done.
    converged : bool
        True when the eigen-residual fell below the tolerance within the iteration budget.
    residual : float
        The last relative eigen-residual |T*T w - ratio^2 w| / ratio^2 (L2 norms, |w| = 1).

    Examples
    --------
    >>> from hinf_cpp.analysis.attenuation import WorstDisturbance
    >>> worst = WorstDisturbance(np.array([0.0, 1.0]), np.ones((2, 1)), 2.0, 3, True, 1e-9)
    >>> [signal(0.5) for signal in worst.signals(0.1)]
    [0.1]
    """

    t: np.ndarray
    w: np.ndarray
    ratio: float
    iterations: int
    converged: bool
    residual: float

    def signals(self, scale: float = 1.0) -> list[_core.Signal]:
        """The signal as one linearly interpolated table per channel, times `scale`.

        Parameters
        ----------
        scale : float, optional
            The factor on every sample (default 1: unit L2 norm).

        Returns
        -------
        list of hinf_cpp.Signal
            nw tables on ``t`` (``Signal.table(..., "linear")``); a channel that is zero
            throughout (one the closed loop's D_e does not reach, such as a measurement-noise
            channel) as the constant 0.

        Examples
        --------
        >>> from hinf_cpp.analysis.attenuation import WorstDisturbance
        >>> worst = WorstDisturbance(np.array([0.0, 2.0]), np.array([[0.0], [4.0]]), 1.0, 1, True, 0.0)
        >>> worst.signals(0.5)[0](1.0)
        1.0
        """
        return [_core.Signal.table(self.t, scale * self.w[:, j], "linear") if np.any(self.w[:, j])
                else _core.Signal(0.0) for j in range(self.w.shape[1])]


def _kappa_signal(kappa) -> _core.Signal:
    if isinstance(kappa, _core.Signal):
        return kappa
    return _core.Signal(float(kappa))


def _weights(count: int, h: float) -> np.ndarray:
    """The trapezoid rule's weights on a uniform grid of `count` points `h` apart."""
    c = np.full(count, h)
    c[0] = c[-1] = 0.5 * h
    return c


def _rk4_maps(A: np.ndarray, D: np.ndarray, h: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """One RK4 step of dx/dt = A(t) x + D(t) w(t) per interval, w linear on it, as
    x_{k+1} = Phi_k x_k + G0_k w_k + G1_k w_{k+1}.

    A, D: the matrices at the grid points and the midpoints, (2 steps + 1) of them in time
    order. Every interval's maps at once (batched matrix products)."""
    A0, Am, A1 = A[0:-1:2], A[1::2], A[2::2]
    D0, Dm, D1 = D[0:-1:2], D[1::2], D[2::2]
    steps, n = A0.shape[0], A0.shape[1]

    def step(X, F0, Fm, F1):
        k1 = A0 @ X + F0
        k2 = Am @ (X + 0.5 * h * k1) + Fm
        k3 = Am @ (X + 0.5 * h * k2) + Fm
        k4 = A1 @ (X + h * k3) + F1
        return X + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4)

    eye = np.broadcast_to(np.eye(n), (steps, n, n))
    zero_x = np.zeros((steps, n, n))
    zero_w = np.zeros_like(D0)
    Phi = step(eye, zero_x, zero_x, zero_x)
    G0 = step(zero_x, D0, 0.5 * Dm, zero_w)   # the midpoint sees (w_k + w_{k+1}) / 2
    G1 = step(zero_x, zero_w, 0.5 * Dm, D1)
    return Phi, G0, G1


def _scan_multipliers(M: np.ndarray) -> list[tuple[int, np.ndarray]]:
    """The matrices of a parallel prefix scan (Hillis-Steele) of y_i = M_i y_{i-1} + f_i,
    y_{-1} = 0: round r (shift s = 2^r) adds P_i y_{i-s} for i >= s, P_i = M_i ... M_{i-s+1}.
    They depend on the closed loop alone, so they are made once; each recursion is then
    log2(length) batched products instead of one small product per step."""
    rounds = []
    product, shift = M.copy(), 1
    while shift < len(M):
        rounds.append((shift, product[shift:].copy()))
        product[shift:] = product[shift:] @ product[:-shift]
        shift *= 2
    return rounds


def _scan(rounds: list[tuple[int, np.ndarray]], f: np.ndarray) -> np.ndarray:
    """y_i = M_i y_{i-1} + f_i, y_{-1} = 0, for every i, from :func:`_scan_multipliers`."""
    y = f.copy()
    for shift, product in rounds:
        y[shift:] = y[shift:] + np.einsum("kij,kj->ki", product, y[:-shift])
    return y


class _DiscreteClosedLoop:
    """The law's linearized closed loop on a uniform grid: the map T from the samples of w
    (linear between them) to the states, the weighted cost J(w) = sum_k c_k x_k' M_k x_k +
    x_N' Qf x_N (trapezoid weights c_k, M = Q + K'K) and the exact adjoint of that map."""

    def __init__(self, law: _core.RiccatiSolution, Q: np.ndarray, Qf: np.ndarray, kappa: _core.Signal,
                 steps: int):
        trajectory = law.trajectory()
        t0, tf = law.t0(), law.tf()
        fine = np.linspace(t0, tf, 2 * steps + 1)  # grid points and midpoints
        K = np.asarray(kappa(fine))[:, None, None] * law.gain(fine)
        A_cl = trajectory.A_e(fine) - trajectory.B_e(fine) @ K
        D = trajectory.D_e(fine)
        self.h = (tf - t0) / steps
        self.t = fine[::2]
        self.Phi, self.G0, self.G1 = _rk4_maps(A_cl, D, self.h)
        Kg = K[::2]
        self.c = _weights(steps + 1, self.h)
        self.M = self.c[:, None, None] * (Q[None] + np.swapaxes(Kg, 1, 2) @ Kg)
        self.M[-1] += Qf
        self.nw = D.shape[2]
        self.forward = _scan_multipliers(self.Phi)
        # The adjoint runs backward: nu_j = mu_{N-j} = g_{N-j} + Phi_{N-j}' nu_{j-1}, nu_0 = g_N.
        backward = np.concatenate([np.zeros((1,) + self.Phi.shape[1:]), np.swapaxes(self.Phi, 1, 2)[::-1]])
        self.backward = _scan_multipliers(backward)

    def states(self, w: np.ndarray) -> np.ndarray:
        forcing = np.einsum("kij,kj->ki", self.G0, w[:-1]) + np.einsum("kij,kj->ki", self.G1, w[1:])
        x = np.zeros((len(self.t), self.Phi.shape[1]))
        x[1:] = _scan(self.forward, forcing)
        return x

    def cost(self, x: np.ndarray) -> float:
        return float(np.einsum("ki,kij,kj->", x, self.M, x))

    def normal(self, x: np.ndarray) -> np.ndarray:
        """T' C T w (the gradient of J / 2) from the states x = T w: the discrete adjoint
        mu_k = M_k x_k + Phi_k' mu_{k+1}, mu_N = M_N x_N (the continuous one,
        -dlambda/dt = A_cl' lambda + (Q + K'K) x, lambda(tf) = Qf x(tf), in the limit)."""
        g = np.einsum("kij,kj->ki", self.M, x)
        mu = _scan(self.backward, g[::-1])[::-1]
        out = np.zeros((len(self.t), self.nw))
        out[:-1] += np.einsum("kji,kj->ki", self.G0, mu[1:])
        out[1:] += np.einsum("kji,kj->ki", self.G1, mu[1:])
        return out

    def norm(self, w: np.ndarray) -> float:
        return float(math.sqrt(np.sum(self.c[:, None] * w**2)))


def worst_disturbance(law: _core.RiccatiSolution, Q, Qf, kappa=1.0, *, steps: int = 2000,
                      max_iterations: int = 1000, tolerance: float = 1e-3, seed: int = 0) -> WorstDisturbance:
    """The worst-case open-loop disturbance of a state-feedback law's linearized closed loop.

    The law u = u_d - K(t) q_e, K = kappa B_e' Z (Z: the design `law`), has the closed loop
    dx/dt = A_cl x + D_e w, A_cl = A_e - B_e K, x(t0) = 0, along the design's desired trajectory.
    The disturbance returned maximizes sqrt(x(tf)'Qf x(tf) + int x'Qx + |Kx|^2 dt) / ||w||:
    power iteration on T*T, T the map from w to the weighted error, with the forward closed loop
    and the backward adjoint -dlambda/dt = A_cl' lambda + (Q + K'K) x, lambda(tf) = Qf x(tf),
    w <- D_e' lambda. Both are discretized on a uniform grid of `steps` intervals: RK4 with w
    linear between the samples, the integrals by the trapezoid rule, and the adjoint is the exact
    adjoint of that discrete map, so every iteration's ratio is a lower bound of the discrete
    map's norm and increases to it. That norm is :func:`hinf_cpp.law_gain` up to the
    discretization error (O(h^2), h = (tf - t0) / steps, from the trapezoid rule).

    Parameters
    ----------
    law : hinf_cpp.RiccatiSolution
        The law's design: Z at its gamma (the H-infinity law) or at gamma = inf (LQR).
    Q : array_like, shape (n, n)
        The weight of the tracking error (the scenario's resolved ``Q``).
    Qf : array_like, shape (n, n)
        The weight of the final error (the scenario's resolved ``Qf``).
    kappa : float or hinf_cpp.Signal, optional
        The law's gain scaling kappa(t) > 0 (default 1).
    steps : int, optional
        The intervals of the grid (>= 2; default 2000).
    max_iterations : int, optional
        The iteration budget (>= 1; default 1000).
    tolerance : float, optional
        Stop when the relative eigen-residual |T*T w - ratio^2 w| / ratio^2 (|w| = 1) falls
        below it (> 0; default 1e-3). The ratio converges faster than the signal: on the paper's
        ship, residuals 2e-3 and 3e-4 left the ratio 1e-4 and 2e-5 below law_gain.
    seed : int, optional
        The seed of the random start (default 0).

    Returns
    -------
    WorstDisturbance
        The grid, the samples (unit L2 norm), the ratio attained, the iterations and whether
        the tolerance was met.

    Raises
    ------
    ValueError
        Q or Qf not of shape (n, n), kappa not > 0 on the grid, steps < 2, max_iterations < 1,
        tolerance not > 0, or a closed loop that no disturbance channel reaches (T = 0).

    Examples
    --------
    >>> from hinf_cpp.analysis.attenuation import worst_disturbance
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), float("inf"))
    >>> worst = worst_disturbance(lqr, np.eye(6), np.eye(6), steps=500)
    >>> worst.converged, round(worst.ratio, 3)       # hc.law_gain: 2.134
    (True, 2.134)
    """
    n = law.n()
    Q, Qf = np.asarray(Q, dtype=float), np.asarray(Qf, dtype=float)
    if Q.shape != (n, n) or Qf.shape != (n, n):
        raise ValueError(f"Q and Qf must be {n} x {n} (the law's states), got {Q.shape} and {Qf.shape}")
    if int(steps) != steps or steps < 2:
        raise ValueError(f"steps must be an integer >= 2, got {steps}")
    if int(max_iterations) != max_iterations or max_iterations < 1:
        raise ValueError(f"max_iterations must be an integer >= 1, got {max_iterations}")
    if not tolerance > 0:
        raise ValueError(f"tolerance must be > 0, got {tolerance}")
    kappa = _kappa_signal(kappa)
    loop = _DiscreteClosedLoop(law, Q, Qf, kappa, int(steps))
    if not np.all(np.asarray(kappa(loop.t)) > 0):
        raise ValueError("kappa must be > 0 on [t0, tf]")
    # Power iteration on S = W^-1 T'C T, self-adjoint in the trapezoid inner product <a, b>_W.
    w = np.random.default_rng(seed).standard_normal((len(loop.t), loop.nw))
    w /= loop.norm(w)
    ratio2, residual, iterations = 0.0, math.inf, 0
    while iterations < max_iterations:
        iterations += 1
        Sw = loop.normal(loop.states(w)) / loop.c[:, None]
        ratio2 = float(np.sum(loop.c[:, None] * w * Sw))  # Rayleigh quotient, |w|_W = 1
        if not ratio2 > 0:
            raise ValueError("no disturbance channel reaches the weighted error: the closed loop's gain is 0")
        residual = loop.norm(Sw - ratio2 * w) / ratio2
        w = Sw / loop.norm(Sw)
        if residual < tolerance:
            break
    # The ratio of the signal returned, from one more forward run.
    ratio = math.sqrt(loop.cost(loop.states(w)))
    w *= np.sign(w.flat[np.argmax(np.abs(w))])  # the sign is free: the largest sample positive
    return WorstDisturbance(t=loop.t, w=w, ratio=ratio, iterations=iterations,
                            converged=bool(residual < tolerance), residual=float(residual))


def measured_ratio(simulation: _core.SimulationResult, Q, Qf) -> float:
    """The gain a closed-loop run measured: sqrt(|q_e(tf)|_Qf^2 + int |q_e|_Q^2 + |u - u_d|^2 dt)
    / sqrt(int |w|^2 dt), integrals by the trapezoid rule on the run's output grid.

    It is the ratio that :func:`hinf_cpp.law_gain` bounds for the linearized closed loop when the
    run starts on the desired trajectory (q_e(t0) = 0). The heading error is wrapped
    (``SimulationResult.q_e``).

    Parameters
    ----------
    simulation : hinf_cpp.SimulationResult
        The run's series (``RunResult.simulation``).
    Q : array_like, shape (n, n)
        The weight of the tracking error.
    Qf : array_like, shape (n, n)
        The weight of the final error.

    Returns
    -------
    float
        The ratio; NaN when the run applied no disturbance.

    Examples
    --------
    >>> from hinf_cpp.analysis.attenuation import measured_ratio
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.initial_q0, scenario.tf = scenario.desired_q0, 10.0
    >>> round(measured_ratio(hc.run_scenario(scenario).simulation, np.eye(6), np.eye(6)), 3)
    0.919
    """
    t = np.asarray(simulation.t)
    q_e = np.asarray(simulation.q_e())
    u_e = np.asarray(simulation.u) - np.asarray(simulation.u_d)
    Q, Qf = np.asarray(Q, dtype=float), np.asarray(Qf, dtype=float)
    error = np.trapezoid(np.einsum("ki,ij,kj->k", q_e, Q, q_e) + np.sum(u_e**2, axis=1), t)
    error += q_e[-1] @ Qf @ q_e[-1]
    energy = np.trapezoid(np.sum(np.asarray(simulation.w) ** 2, axis=1), t)
    return float(math.sqrt(error / energy)) if energy > 0 else math.nan


def _variant(scenario: _core.Scenario, law: _core.Law) -> _core.Scenario:
    """The scenario with `law`, state feedback, from the desired start, without its disturbance."""
    if scenario.sampling is not None or scenario.receding_horizon is not None:
        raise ValueError(f"scenario '{scenario.name}': the attenuation of a law is that of its continuous "
                         "state-feedback design over [t0, tf]; remove [sampling] and [receding_horizon]")
    variant = scenario.copy()
    variant.law = law
    variant.measurement = None
    variant.worst_case = False
    variant.initial_q0 = variant.desired_q0
    variant.disturbance = None
    return variant


def law_run(scenario: _core.Scenario, law: _core.Law | str, disturbance=None) -> _core.RunResult:
    """One run of a scenario's law with state feedback from the desired start, under a given
    disturbance (the scenario's own and its worst case replaced).

    Parameters
    ----------
    scenario : hinf_cpp.Scenario
        The scenario (not changed); no [sampling] or [receding_horizon].
    law : hinf_cpp.Law or str
        ``"hinf"``, ``"lqr"``, ``"cascade"`` or ``"backstepping"``.
    disturbance : list of hinf_cpp.Signal or float, or hinf_cpp.VectorSignal, optional
        The nw channels of w (default: none, w = 0).

    Returns
    -------
    hinf_cpp.RunResult
        The run; its ``solution`` is the law's design for hinf and lqr (for
        :func:`worst_disturbance` and :func:`hinf_cpp.law_gain`).

    Raises
    ------
    ValueError
        An unknown law, a scenario with [sampling] or [receding_horizon], a
        disturbance without nw channels.
    hinf_cpp.HinfError
        The design or the run failed numerically.

    Examples
    --------
    >>> from hinf_cpp.analysis.attenuation import law_run
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> result = law_run(scenario, "lqr", [0.01, 0.0, 0.0, 0.0, 0.0, 0.0])
    >>> result.gamma, result.simulation.w[0].tolist()
    (inf, [0.01, 0.0, 0.0, 0.0, 0.0, 0.0])
    """
    (law,) = parse_controllers([law])
    variant = _variant(scenario, law)
    if disturbance is not None:
        variant.disturbance = disturbance
    return _core.run_scenario(variant)


def _frequencies(frequencies) -> np.ndarray:
    values = np.asarray(frequencies, dtype=float).ravel()
    if values.size == 0 or not np.all(np.isfinite(values)) or not np.all(values > 0):
        raise ValueError(f"frequencies must be finite numbers > 0 (rad/s), got {list(values)}")
    return np.sort(values)


def _channels(channels, model: _core.Model) -> list[int]:
    """Channel numbers counted from 1, as the scenario files name them (w1, w2, ...); the
    model's measurement-noise channels are not disturbances."""
    noise = {c + 1 for c in model.noise_channels()}
    usable = [c for c in range(1, model.nw() + 1) if c not in noise]
    choices = ", ".join(f"{c} (w{c})" for c in usable)
    if channels is None:
        return usable
    out = [channels] if isinstance(channels, (int, np.integer)) else list(channels)
    if not out:
        raise ValueError(f"no disturbance channel given: choose among {choices}")
    for c in out:
        if isinstance(c, bool) or not isinstance(c, (int, np.integer)) or not 1 <= c <= model.nw():
            raise ValueError(f"disturbance channel {c!r} does not exist: choose among {choices}")
        if c in noise:
            raise ValueError(f"channel {c} (w{c}) is a measurement-noise channel of the model '{model.name()}', "
                             f"not a disturbance: choose among {choices}")
    if len(set(out)) != len(out):
        raise ValueError(f"a disturbance channel is given twice: {out}")
    return [int(c) for c in out]


def gain_against_frequency(scenario: _core.Scenario, laws: str | Sequence = "hinf,lqr", *,
                           channels: Iterable[int] | int | None = None,
                           frequencies: Iterable[float] | None = None, amplitude: float = 0.01,
                           progress: ProgressCallback | None = None):
    """The measured gain of each law's NONLINEAR closed loop for single-channel sinusoids.

    For each law, channel and frequency omega the scenario runs from the desired start with
    state feedback and w_c(t) = amplitude sin(omega (t - t0)) on channel c alone (the other
    channels 0); the gain is :func:`measured_ratio` of the run. Each law's bound is its induced
    L2 gain, :func:`hinf_cpp.law_gain` of its design: in the linear regime (a small amplitude)
    no disturbance measures more. The baselines' bound is :func:`hinf_cpp.controller_gain`.

    Parameters
    ----------
    scenario : hinf_cpp.Scenario
        The scenario (not changed); no [sampling] or [receding_horizon].
    laws : str or sequence, optional
        ``"hinf,lqr"`` (default), or a list of names or :class:`hinf_cpp.Law` values.
    channels : int or iterable of int, optional
        The disturbance channels, counted from 1 (w1, w2, ...; default every channel of the
        model that is not a measurement-noise channel).
    frequencies : iterable of float, optional
        The angular frequencies (rad/s, > 0; default 17 values log-spaced from 0.01 to 100).
    amplitude : float, optional
        The sinusoid's amplitude (> 0; default 0.01, small enough for the linear regime of the
        paper's ship).
    progress : callable, optional
        ``progress(index, total, message)``, called before each run.

    Returns
    -------
    pandas.DataFrame
        One row per law, channel and frequency: ``law``, ``channel`` (from 1), ``omega``
        (rad/s), ``gain`` (measured), ``bound`` (the law's hinf_cpp.law_gain), ``gamma`` (the
        design's gamma, inf for lqr), ``status`` (of the run; gain NaN unless "completed").

    Raises
    ------
    ValueError
        An unknown law, a channel that does not exist or carries measurement noise,
        frequencies or amplitude not > 0, a scenario with [sampling] or [receding_horizon].
    hinf_cpp.HinfError
        A design failed numerically.

    Examples
    --------
    >>> from hinf_cpp.analysis.attenuation import gain_against_frequency
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> table = gain_against_frequency(scenario, "lqr", channels=3, frequencies=[1.0])
    >>> table[["law", "channel", "omega"]].to_dict("records")
    [{'law': 'lqr', 'channel': 3, 'omega': 1.0}]
    >>> bool(table.gain[0] <= table.bound[0])
    True
    """
    import pandas as pd

    chosen = parse_controllers(laws)
    nw = scenario.model.nw()
    channel_list = _channels(channels, scenario.model)
    omegas = _frequencies(np.geomspace(0.01, 100.0, 17) if frequencies is None else frequencies)
    if not (math.isfinite(amplitude) and amplitude > 0):
        raise ValueError(f"amplitude must be a finite number > 0, got {amplitude}")
    resolved = scenario.resolved()
    total = len(chosen) * (1 + len(channel_list) * len(omegas))
    index = 0
    rows = []
    for law in chosen:
        index += 1
        if progress is not None:
            progress(index, total, f"designing {law.name} on {scenario.name}")
        design = law_run(scenario, law)
        bound = induced_gain(_variant(scenario, law), design)
        # A design's gamma (hinf; inf for lqr); the baselines have none.
        design_gamma = float(design.gamma) if law in (_core.Law.hinf, _core.Law.lqr) else math.nan
        for channel in channel_list:
            for omega in omegas:
                index += 1
                if progress is not None:
                    progress(index, total, f"{law.name}: w{channel} at omega = {omega:.4g} rad/s")
                signals: list = [0.0] * nw
                signals[channel - 1] = _core.Signal(
                    0.0, [_core.Harmonic(amplitude=amplitude, omega=float(omega), phase=-float(omega) * scenario.t0)])
                run = law_run(scenario, law, signals)
                status = run.simulation.status.name
                gain = measured_ratio(run.simulation, resolved.Q, resolved.Qf) if status == "completed" else math.nan
                rows.append({"law": law.name, "channel": channel, "omega": float(omega), "gain": gain,
                             "bound": bound, "gamma": design_gamma, "status": status})
    return pd.DataFrame(rows, columns=["law", "channel", "omega", "gain", "bound", "gamma", "status"])


def frequency_figure(table, channel: int, title: str | None = None):
    """The measured gain against frequency on one disturbance channel, one line per law, each
    law's bound (hinf_cpp.law_gain) dashed in its colour and the H-infinity design's gamma dotted.

    Parameters
    ----------
    table : pandas.DataFrame
        :func:`gain_against_frequency`'s table.
    channel : int
        The channel drawn (from 1).
    title : str, optional
        The title (default: names the channel).

    Returns
    -------
    matplotlib.figure.Figure
        The figure (save it with :func:`hinf_cpp.output.plotting.save_figure`).

    Raises
    ------
    ValueError
        A channel the table does not hold.

    Examples
    --------
    >>> import pandas as pd
    >>> from hinf_cpp.analysis.attenuation import frequency_figure
    >>> table = pd.DataFrame({"law": ["hinf", "hinf"], "channel": [1, 1], "omega": [0.1, 1.0],
    ...                       "gain": [1.5, 1.2], "bound": [2.1, 2.1], "gamma": [5.0, 5.0]})
    >>> figure = frequency_figure(table, 1)
    >>> [line.get_label() for line in figure.axes[0].get_lines()][:2]
    ['hinf', 'hinf: law_gain 2.1']
    """
    from matplotlib.figure import Figure

    rows = table[table["channel"] == channel]
    if rows.empty:
        raise ValueError(f"the table has no rows for channel {channel}: it holds {sorted(set(table['channel']))}")
    fig = Figure(figsize=(7.0, 4.4), layout="constrained")
    ax = fig.subplots()
    for law, part in rows.groupby("law", sort=False):
        colour = _LAW_COLOURS.get(law, "tab:red")
        part = part.sort_values("omega")
        ax.plot(part["omega"], part["gain"], "o-", color=colour, label=law)
        bound = float(part["bound"].iloc[0])
        ax.axhline(bound, color=colour, ls="--", label=f"{law}: law_gain {bound:.4g}")
        gamma = float(part["gamma"].iloc[0])
        if math.isfinite(gamma):
            ax.axhline(gamma, color=colour, ls=":", label=f"{law}: design gamma {gamma:.4g}")
    ax.set_xscale("log")
    ax.set_xlabel("omega [rad/s]")
    ax.set_ylabel("measured gain [-]")
    ax.set_title(title or f"gain against frequency, disturbance channel w{channel}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize="small", loc="best")
    return fig
