"""Comparison of the tracking laws on one scenario: the paper's H-infinity law and the baselines.

``compare(scenario)`` runs the scenario once per law (``"hinf"``: the paper's law at the
scenario's gamma; ``"lqr"``: the same design at gamma = inf, with ``[measurement]`` the
Kalman-Bucy filter; ``"cascade"`` and ``"backstepping"``: the ship baselines of
``docs/baselines.md``, with ``[measurement]`` acting on the H-infinity estimate) and, for a scenario with ``[measurement]``, both with perfect
state feedback (the measurement removed) and with output feedback. It returns the runs and
one metrics dictionary per run, and says which disturbance every number is for.

Laws are :class:`hinf_cpp.Law` values and feedback modes :class:`Feedback` values; their
names (``"hinf,lqr"``, ``"state,output"``) are accepted where they come in and written where
they go out (tables, JSON).

Metrics (:data:`METRICS`): the library's metrics of the results file (``metric_table()``,
``RunResult.metrics``, ``docs/results.md``), with ``disturbance_gain`` taken from a second run
of the same law and disturbance started on the desired trajectory (q(t0) = q_d(t0)) when the
scenario starts elsewhere, so that it is the disturbance's gain alone, not the response to the
initial error (``response_ratio`` is that); and one of the comparison's own,
``induced_l2_gain``: the law's own attenuation level, the induced L2 gain from w to the
weighted error of its closed loop linearized along the desired trajectory over [t0, tf]
(:func:`hinf_cpp.law_gain`), for the state-feedback runs of ``hinf`` and ``lqr``.
"""

from __future__ import annotations

import dataclasses
import json
import math
from typing import Any, Iterable, Sequence

import numpy as np

from hinf_cpp import _core
from hinf_cpp.output.progress import ProgressCallback
# Feedback is defined beside run_key, so that the command line's parser names its members
# without loading the analyses; it is documented under hinf_cpp.analysis, which exports it.
from hinf_cpp.output.tables import Feedback, run_key

__all__ = [
    "METRICS",
    "induced_gain",
    "Comparison",
    "ComparisonRun",
    "MetricInfo",
    "compare",
    "describe_disturbance",
    "heading_error",
    "parse_controllers",
    "parse_feedback",
    "run_law",
    "wrap_angles",
]


@dataclasses.dataclass(frozen=True)
class MetricInfo:
    """A metric of the comparison table that the library does not compute.

    It has the attributes of :class:`hinf_cpp.MetricDefinition`, so that :data:`METRICS`
    lists both kinds alike: ``induced_l2_gain`` is one.

    Parameters
    ----------
    name : str
        The key (tables, JSON).
    label : str
        The name in a table for reading.
    unit : str
        The unit (``"-"`` for none).
    definition : str
        What it measures, in one sentence.

    Examples
    --------
    >>> from hinf_cpp.analysis.comparison import METRICS, MetricInfo
    >>> info = next(m for m in METRICS if isinstance(m, MetricInfo))
    >>> info.name, info.label, info.unit
    ('induced_l2_gain', 'induced L2 gain of the law', '-')
    """

    name: str
    label: str
    unit: str
    definition: str


_INDUCED_L2_GAIN = MetricInfo(
    "induced_l2_gain", "induced L2 gain of the law", "-",
    "the law's induced L2 gain from w to the weighted error, x'Qx + |u - u_d|^2 and x(tf)'Qf x(tf), of its "
    "closed loop linearized along the desired trajectory over [t0, tf] (hinf_cpp.law_gain); hinf and lqr "
    "with state feedback, NaN otherwise")


def _comparison_metrics() -> list:
    """The rows of the comparison table: the library's metrics, induced_l2_gain after
    disturbance_gain (the law's bound beside what the disturbance met)."""
    rows = []
    for definition in _core.metric_table():
        rows.append(definition)
        if definition.name == "disturbance_gain":
            rows.append(_INDUCED_L2_GAIN)
    return rows


def induced_gain(scenario: _core.Scenario, result: _core.RunResult) -> float:
    """The induced L2 gain of a run's law, its closed loop linearized along the trajectory.

    :func:`hinf_cpp.law_gain` of the design kept (hinf, lqr) or :func:`hinf_cpp.controller_gain`
    of the baseline's controller (cascade, backstepping), with the scenario's weights.

    Parameters
    ----------
    scenario : hinf_cpp.Scenario
        The scenario run (its Q, Qf, kappa and the baselines' gains).
    result : hinf_cpp.RunResult
        Its run (the law, the trajectory and the design).

    Returns
    -------
    float
        The gain; NaN with an estimator in the loop (output feedback) or without a single
        design over [t0, tf] (a receding horizon).

    Examples
    --------
    >>> from hinf_cpp.analysis.comparison import induced_gain
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf, scenario.law = 10.0, hc.Law.backstepping
    >>> round(induced_gain(scenario, hc.run_scenario(scenario)), 2)
    2.57
    """
    if result.output_feedback or result.trajectory is None:
        return math.nan
    resolved = scenario.resolved()
    if result.law == _core.Law.cascade:
        law = _core.CascadeController(result.trajectory, resolved.cascade)
        return float(_core.controller_gain(result.trajectory, law, resolved.Q, resolved.Qf).gamma_star)
    if result.law == _core.Law.backstepping:
        law = _core.BacksteppingController(result.trajectory, resolved.backstepping)
        return float(_core.controller_gain(result.trajectory, law, resolved.Q, resolved.Qf).gamma_star)
    if result.solution is None:
        return math.nan
    return float(_core.law_gain(result.solution, resolved.Q, resolved.Qf, resolved.kappa).gamma_star)


#: The metrics of a comparison, in the order of its table (MetricInfo: name, label, unit, definition).
METRICS = _comparison_metrics()


def _names(spec: str | Iterable[Any]) -> tuple[list[str], str]:
    """The names of a comma-separated list or a sequence (enums by their name), and the spec as text."""
    raw = spec.split(",") if isinstance(spec, str) else list(spec)
    names = [item.name if hasattr(type(item), "__members__") else str(item).strip() for item in raw]
    return names, ",".join(names)


def parse_controllers(spec: str | Iterable[str | _core.Law] | None) -> list[_core.Law]:
    """The laws to compare, from ``"hinf,lqr"`` or a list of names or laws.

    Parameters
    ----------
    spec : str or iterable of (str or hinf_cpp.Law) or None
        A comma-separated list of names among ``hinf``, ``lqr``, ``cascade``, ``backstepping``,
        or a sequence of names or :class:`hinf_cpp.Law` values; None means all four.

    Returns
    -------
    list of hinf_cpp.Law
        The laws, in the order given.

    Raises
    ------
    ValueError
        For an empty list, an empty or unknown name, or a name given twice.

    Examples
    --------
    >>> from hinf_cpp.analysis.comparison import parse_controllers
    >>> parse_controllers("hinf,lqr")
    [<Law.hinf: 0>, <Law.lqr: 1>]
    >>> len(parse_controllers(None))
    4
    >>> parse_controllers("hinf,mpc")
    Traceback (most recent call last):
        ...
    ValueError: unknown controller 'mpc': choose from hinf, lqr, cascade, backstepping
    """
    laws = _core.Law.__members__
    if spec is None:
        return list(laws.values())
    names, text = _names(spec)
    choices = ", ".join(laws)
    if not names or names == [""]:
        raise ValueError(f"no controller given: choose one or more of {choices} (comma-separated)")
    for name in names:
        if not name:
            raise ValueError(f"empty controller name in '{text}': choose from {choices}")
        if name not in laws:
            raise ValueError(f"unknown controller '{name}': choose from {choices}")
    seen = set()
    for name in names:
        if name in seen:
            raise ValueError(f"controller '{name}' is given twice")
        seen.add(name)
    return [laws[name] for name in names]


def parse_feedback(scenario: _core.Scenario, spec: str | Iterable[str | Feedback] | None) -> list[Feedback]:
    """The feedback modes to run, from ``"state,output"`` or a list of names or modes.

    Parameters
    ----------
    scenario : hinf_cpp.Scenario
        The scenario (whether it has ``[measurement]``).
    spec : str or iterable of (str or Feedback) or None
        ``"state"`` and/or ``"output"`` (comma-separated, or a sequence of names or modes).
        None: both for a scenario with ``[measurement]``, state feedback otherwise.

    Returns
    -------
    list of Feedback
        The modes, state feedback first.

    Raises
    ------
    ValueError
        An unknown or repeated mode, or output feedback for a scenario without
        ``[measurement]``.

    Examples
    --------
    >>> from hinf_cpp.analysis.comparison import parse_feedback
    >>> parse_feedback(hc.load_scenario(hc.scenario_path("paper_fig2")), None)
    [<Feedback.state: 'state'>, <Feedback.output: 'output'>]
    >>> parse_feedback(hc.load_scenario(hc.scenario_path("paper_fig1")), "output")
    Traceback (most recent call last):
        ...
    ValueError: output feedback needs a scenario with [measurement]; 'paper-fig1' has none
    """
    has_measurement = scenario.measurement is not None
    if spec is None:
        return list(Feedback) if has_measurement else [Feedback.state]
    names, text = _names(spec)
    if not names or any(m not in Feedback.__members__ for m in names) or len(set(names)) != len(names):
        raise ValueError(f"feedback modes must be one or both of 'state', 'output' (each once), got '{text}'")
    if Feedback.output.name in names and not has_measurement:
        raise ValueError(f"output feedback needs a scenario with [measurement]; '{scenario.name}' has none")
    return [mode for mode in Feedback if mode.name in names]


def wrap_angles(angle: np.ndarray | float) -> np.ndarray:
    """Angles wrapped to (-pi, pi], elementwise (as :func:`hinf_cpp.wrap_angle`).

    Parameters
    ----------
    angle : float or array_like
        Angles (rad), any shape.

    Returns
    -------
    numpy.ndarray
        The wrapped angles (rad), of the same shape; +-pi becomes pi.

    Examples
    --------
    >>> from hinf_cpp.analysis.comparison import wrap_angles
    >>> wrap_angles([np.pi, -np.pi, 1.5 * np.pi, 0.5]).round(4)
    array([ 3.1416,  3.1416, -1.5708,  0.5   ])
    """
    a = np.asarray(angle, dtype=float)
    return np.pi - np.mod(np.pi - a, 2.0 * np.pi)


def heading_error(result: _core.RunResult) -> np.ndarray | None:
    """The heading error psi - psi_d of a run on its output grid, continuous in time.

    It starts at the wrapped initial error (in (-pi, pi]) and follows the rotation from there
    (a full turn adds 2 pi): ``numpy.unwrap`` of the wrapped error q_e = q - q_d.

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.

    Returns
    -------
    numpy.ndarray, shape (k,), or None
        The error (rad) at the k output times; None when the model has no heading.

    Examples
    --------
    >>> from hinf_cpp.analysis.comparison import heading_error
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> e = heading_error(result)
    >>> e.shape, round(float(e[0]), 4)  # starts 45 degrees off
    ((4001,), 0.7854)
    """
    index = result.trajectory.model().heading_index()
    if index < 0:
        return None
    return np.unwrap(result.simulation.q_e()[:, index])


def _describe_signal(signal: _core.Signal) -> str | None:
    """``0.1 cos(1.25664 t)`` and the like; None for the zero signal."""
    if signal.is_table():
        t = signal.table_t()
        return f"a table of {len(t)} points on [{t[0]:g}, {t[-1]:g}] s ({signal.interpolation().name})"
    terms = [f"{signal.offset():g}"] if signal.offset() != 0.0 else []
    for h in signal.harmonics():
        if h.amplitude == 0.0:
            continue
        phase = "" if h.phase == 0.0 else f" {'+' if h.phase > 0 else '-'} {abs(h.phase):.6g}"
        terms.append(f"{h.amplitude:g} {'cos' if h.cosine else 'sin'}({h.omega:.6g} t{phase})")
    return " + ".join(terms) if terms else None


def _gamma_text(gamma: float) -> str:
    return "inf" if math.isinf(gamma) else f"{gamma:g}"


def describe_disturbance(scenario: _core.Scenario, output_feedback: bool | None = None,
                         law: _core.Law | None = None) -> dict:
    """Which disturbance a run of ``scenario`` sees.

    The signals of [disturbance] (the non-zero channels; with output feedback the
    measurement-noise channels are left out), the law's worst case when ``worst_case`` is set
    (w* = gamma^-2 D' Z q_e of paper eq. (16) for hinf; for the others their own,
    gamma^-2 D' P q_e with P of their closed loop at gamma: :func:`hinf_cpp.solve_law_riccati`
    for lqr, :func:`hinf_cpp.solve_controller_riccati` for the baselines),
    and with output feedback the measurement noise.

    Parameters
    ----------
    scenario : Scenario
        The scenario (its ``[disturbance]`` signals, ``worst_case`` and ``[measurement]``).
    output_feedback : bool, optional
        Whether the run is output feedback (default: whether the scenario has ``[measurement]``).
    law : hinf_cpp.Law, optional
        The run's law (default: the scenario's).

    Returns
    -------
    dict
        ``signals`` (channel -> description, non-zero channels only), ``worst_case``
        (bool), ``worst_case_gamma`` (the gamma of the worst case applied, or None), ``measurement_noise`` (sigma, sample period, seed, channels; or None) and
        ``description`` (one sentence).

    Raises
    ------
    ValueError
        A scenario without a model.

    Examples
    --------
    >>> from hinf_cpp.analysis.comparison import describe_disturbance
    >>> disturbance = describe_disturbance(hc.load_scenario(hc.scenario_path("paper_fig2")))
    >>> disturbance["signals"]["w1"], disturbance["measurement_noise"]["channels"]
    ('0.1 cos(1.25664 t)', ['w4', 'w5', 'w6'])
    >>> print(disturbance["description"])
    the scenario's signals (w1 = 0.1 cos(1.25664 t); ...), plus measurement noise sigma = 0.5
    held over 0.01 s (seed 20000601) on w4, w5, w6
    """
    model = scenario.model
    if model is None:
        raise ValueError("the scenario has no model")
    if output_feedback is None:
        output_feedback = scenario.measurement is not None
    noise_channels = set(model.noise_channels()) if output_feedback else set()
    signals: dict[str, str] = {}
    disturbance = scenario.disturbance
    if disturbance.dim() and disturbance.is_function():
        signals["w"] = "a function of t (Python callable)"
    elif disturbance.dim():
        for i, channel in enumerate(disturbance.channels()):
            text = _describe_signal(channel)
            if text is not None and i not in noise_channels:
                signals[f"w{i + 1}"] = text
    parts = []
    if signals:
        parts.append("the scenario's signals (" + "; ".join(f"{k} = {v}" for k, v in signals.items()) + ")")
    else:
        parts.append("no disturbance signals")
    if scenario.worst_case:
        law = scenario.law if law is None else law
        if law != _core.Law.hinf:
            parts.append(f"plus the {law.name} law's own worst case w* = gamma^-2 D' P q_e at gamma = "
                         f"{_gamma_text(scenario.gamma)} (P of its closed loop)")
        else:
            parts.append(f"plus the worst case w* = gamma^-2 D' Z q_e of the H-infinity design at gamma = "
                         f"{_gamma_text(scenario.gamma)} (paper eq. 16)")
    noise = None
    if output_feedback:
        ms = scenario.measurement
        channels = [f"w{i + 1}" for i in sorted(noise_channels)]
        noise = {"sigma": ms.sigma, "sample_period": ms.sample_period, "seed": int(ms.seed),
                 "channels": channels}
        parts.append(f"plus measurement noise sigma = {ms.sigma:g} held over {ms.sample_period:g} s "
                     f"(seed {ms.seed}) on {', '.join(channels)}")
    return {
        "signals": signals,
        "worst_case": bool(scenario.worst_case),
        "worst_case_gamma": float(scenario.gamma) if scenario.worst_case else None,
        "measurement_noise": noise,
        "description": ", ".join(parts),
    }


def run_law(scenario: _core.Scenario, law: _core.Law | str, feedback: Feedback | str = Feedback.state, *,
            from_desired: bool = False) -> _core.RunResult:
    """One run of a scenario with a given law and feedback mode.

    The scenario is copied: its law replaced, ``[measurement]`` removed for state feedback,
    and with `from_desired` its initial state set to the desired one.

    Parameters
    ----------
    scenario : hinf_cpp.Scenario
        The scenario (not changed).
    law : hinf_cpp.Law or str
        ``"hinf"``, ``"lqr"`` or ``"cascade"``.
    feedback : Feedback or str, optional
        ``"state"`` (default) or ``"output"`` (needs ``[measurement]``).
    from_desired : bool, optional
        Start on the desired trajectory, q(t0) = q_d(t0) (default False).

    Returns
    -------
    hinf_cpp.RunResult
        The run (:func:`hinf_cpp.run_scenario`).

    Raises
    ------
    ValueError
        An unknown law or mode, output feedback without ``[measurement]``, an invalid
        scenario.
    hinf_cpp.HinfError
        The run failed numerically (a conjugate point, a coupling violation, a solver
        failure).

    Examples
    --------
    >>> from hinf_cpp.analysis.comparison import run_law
    >>> result = run_law(hc.load_scenario(hc.scenario_path("paper_fig2")), "lqr", "output")
    >>> result.law, result.gamma, result.output_feedback
    (<Law.lqr: 1>, inf, True)
    """
    (law,) = parse_controllers([law])
    if not isinstance(feedback, Feedback):
        if feedback not in Feedback.__members__:
            raise ValueError(f"feedback must be 'state' or 'output', got '{feedback}'")
        feedback = Feedback[feedback]
    variant = scenario.copy()
    variant.law = law
    if feedback is Feedback.state:
        variant.measurement = None
    elif variant.measurement is None:
        raise ValueError(f"output feedback needs a scenario with [measurement]; '{scenario.name}' has none")
    if from_desired:
        variant.initial_q0 = variant.desired_q0
    return _core.run_scenario(variant)


@dataclasses.dataclass
class ComparisonRun:
    """One run of a comparison: one law in one feedback mode.

    ``ok`` is True when the run succeeded; ``to_dict()`` gives its entry of the comparison
    JSON (NaN as None).

    Parameters
    ----------
    key : str
        The run's key, :func:`hinf_cpp.output.tables.run_key`: ``"hinf"``, ``"lqr"``,
        ``"cascade"``, ``"hinf/output-feedback"``, ...
    law : hinf_cpp.Law
        The law.
    feedback : Feedback
        The feedback mode.
    design_gamma : float
        The gamma of the law's Riccati design (inf for lqr).
    disturbance : dict
        :func:`describe_disturbance` of this run.
    metrics : dict of str to float
        Every key of :data:`METRICS` (NaN where it does not apply, or the run failed).
    result : hinf_cpp.RunResult, optional
        The run, when it succeeded.
    error : str, optional
        The numerical failure, when the run failed.

    Examples
    --------
    >>> from hinf_cpp.analysis import compare
    >>> run = compare(hc.load_scenario(hc.scenario_path("paper_fig1")), "lqr")["lqr"]
    >>> run.ok, run.design_gamma, run.feedback
    (True, inf, <Feedback.state: 'state'>)
    >>> round(run.metrics["rms_position_error_last_half"], 3)
    0.048
    """

    key: str                     # run_key(): "hinf", "lqr", "cascade", "hinf/output-feedback", ...
    law: _core.Law
    feedback: Feedback
    design_gamma: float          # gamma of the law's Riccati design (inf for lqr)
    disturbance: dict            # describe_disturbance() of this run
    metrics: dict[str, float]    # every key of METRICS (NaN where it does not apply)
    result: _core.RunResult | None = None
    error: str | None = None     # the numerical failure, when the run failed

    @property
    def ok(self) -> bool:
        return self.error is None

    def to_dict(self) -> dict:
        """The run's entry of the comparison JSON: description and metrics (NaN as None)."""
        entry = {
            "law": self.law.name,
            "feedback": self.feedback.name,
            "design_gamma": None if math.isinf(self.design_gamma) else self.design_gamma,
            "disturbance": self.disturbance["description"],
        }
        if self.error is not None:
            entry["error"] = self.error
        entry.update({k: _json_number(v) for k, v in self.metrics.items()})
        return entry


@dataclasses.dataclass
class Comparison:
    """The runs of :func:`compare` on one scenario.

    ``comparison[key]`` is the run of that key (KeyError naming the keys otherwise);
    ``keys`` lists them; ``results(feedback)`` gives (key, RunResult) of the runs that
    succeeded; ``table(keys)`` a header and rows (one per metric that applies to some run);
    ``to_dict()`` and ``to_json()`` the comparison JSON.

    Parameters
    ----------
    scenario : str
        The scenario's name.
    gamma : float
        The scenario's gamma (of the hinf and cascade designs).
    disturbance : dict
        :func:`describe_disturbance` of the scenario (state feedback).
    runs : list of ComparisonRun
        The runs, state feedback first, laws in the order given.

    Examples
    --------
    >>> from hinf_cpp.analysis import compare
    >>> comparison = compare(hc.load_scenario(hc.scenario_path("paper_fig1")), "hinf,lqr")
    >>> comparison.keys
    ['hinf', 'lqr']
    >>> header, rows = comparison.table(keys=True)
    >>> header, rows[0][:2]
    (['metric', 'unit', 'hinf', 'lqr'], ['rms_position_error_last_half', 'm'])
    >>> sorted(comparison.to_dict())
    ['controllers', 'disturbance', 'gamma', 'metric_definitions', 'scenario']
    """

    scenario: str
    gamma: float
    disturbance: dict            # describe_disturbance() of the scenario (state feedback)
    runs: list[ComparisonRun]

    def __getitem__(self, key: str) -> ComparisonRun:
        for run in self.runs:
            if run.key == key:
                return run
        raise KeyError(f"no run '{key}' in the comparison (runs: {', '.join(self.keys)})")

    @property
    def keys(self) -> list[str]:
        return [run.key for run in self.runs]

    def results(self, feedback: Feedback | None = None) -> list[tuple[str, _core.RunResult]]:
        """(key, RunResult) of the runs that succeeded, optionally of one feedback mode."""
        return [(r.key, r.result) for r in self.runs
                if r.ok and (feedback is None or r.feedback == feedback)]

    def table(self, keys: bool = False) -> tuple[list[str], list[list[Any]]]:
        """Header ``[metric, unit, run...]`` and one row per metric that applies to some run;
        the metric is named by its label, or by its key with ``keys=True``."""
        header = ["metric", "unit", *self.keys]
        rows = []
        for info in METRICS:
            values = [run.metrics.get(info.name, math.nan) for run in self.runs]
            if all(not math.isfinite(v) for v in values):
                continue
            rows.append([info.name if keys else info.label, info.unit, *values])
        failed = [run for run in self.runs if not run.ok]
        if failed:
            rows.append(["failed", "", *["" if run.ok else "yes" for run in self.runs]])
        return header, rows

    def to_dict(self) -> dict:
        """The comparison JSON: scenario, gamma, disturbance, one entry per run under
        ``controllers`` and the metric definitions."""
        return {
            "scenario": self.scenario,
            "gamma": _json_number(self.gamma),
            "disturbance": self.disturbance,
            "controllers": {run.key: run.to_dict() for run in self.runs},
            "metric_definitions": {m.name: f"{m.definition} [{m.unit}]" for m in METRICS},
        }

    def to_json(self, indent: int = 2) -> str:
        return json.dumps(self.to_dict(), indent=indent)


def _json_number(x: float | None) -> float | None:
    return float(x) if x is not None and math.isfinite(x) else None


def compare(scenario: _core.Scenario, controllers: str | Sequence[str] | None = None, *,
            feedback: str | Sequence[str] | None = None, worst_case: bool | None = None,
            progress: ProgressCallback | None = None) -> Comparison:
    """Run a scenario with each law and return the runs and their metrics.

    ``"hinf"`` is the paper's law at the scenario's gamma, ``"lqr"`` the same design at
    gamma = inf (with ``[measurement]`` the Kalman-Bucy filter), ``"cascade"`` the cascaded
    ship baseline. The metrics are those of :data:`METRICS`: the library's, with
    ``disturbance_gain`` from the same run started on the desired trajectory, and
    ``induced_l2_gain``.

    Parameters
    ----------
    scenario : Scenario
        The scenario (its own ``[controller] law`` is ignored).
    controllers : str or sequence of str or Law, optional
        Laws among ``"hinf"``, ``"lqr"``, ``"cascade"`` (``"hinf,lqr"`` or a list); default all.
    feedback : str or sequence of str or Feedback, optional
        ``"state"`` and/or ``"output"``; default both with ``[measurement]``, else state.
    worst_case : bool, optional
        Overrides ``[disturbance] worst_case``: add each law's own worst case (w* of eq. 16 for
        hinf; for the others gamma^-2 D' P q_e of their own closed loop at gamma).
    progress : callable, optional
        Called as ``progress(index, total, message)`` before each run (e.g. a
        :class:`~hinf_cpp.output.progress.Progress`).

    Returns
    -------
    Comparison
        Runs keyed ``law`` (state feedback) or ``law/output-feedback``. A run that fails
        numerically (a conjugate point, a coupling violation) is kept with ``error`` set and
        NaN metrics; bad input raises.

    Raises
    ------
    ValueError
        Bad controller names or feedback modes, or an invalid scenario.

    Examples
    --------
    >>> from hinf_cpp.analysis import compare
    >>> comparison = compare(hc.load_scenario(hc.scenario_path("paper_fig2")), "hinf,lqr")
    >>> comparison.keys
    ['hinf', 'lqr', 'hinf/output-feedback', 'lqr/output-feedback']
    >>> round(comparison["hinf"].metrics["rms_position_error_last_half"], 3)
    0.048
    """
    laws = parse_controllers(controllers)
    modes = parse_feedback(scenario, feedback)
    base = scenario.copy()
    if worst_case is not None:
        base.worst_case = bool(worst_case)
    for law in laws:   # bad input (e.g. cascade on a non-ship model) fails before any run
        variant = base.copy()
        variant.law = law
        variant.resolved().validate()
    starts_on_desired = np.array_equal(np.asarray(base.initial_q0), np.asarray(base.desired_q0))
    plan = [(law, mode) for mode in modes for law in laws]
    runs = []
    for index, (law, mode) in enumerate(plan, start=1):
        key = run_key(law, mode is Feedback.output)
        if progress is not None:
            progress(index, len(plan), f"running {key} on {base.name}")
        disturbance = describe_disturbance(base, mode is Feedback.output, law)
        design_gamma = math.inf if law == _core.Law.lqr else float(base.gamma)
        try:
            result = run_law(base, law, mode)
            gain_alone = (result.metrics.disturbance_gain if starts_on_desired
                          else run_law(base, law, mode, from_desired=True).metrics.disturbance_gain)
        except _core.HinfError as error:
            metrics = {m.name: math.nan for m in METRICS}
            runs.append(ComparisonRun(key, law, mode, design_gamma, disturbance, metrics,
                                      error=" ".join(str(error).split())))
            continue
        metrics = {m.name: getattr(result.metrics, m.name) for m in _core.metric_table()}
        metrics["disturbance_gain"] = gain_alone
        metrics[_INDUCED_L2_GAIN.name] = induced_gain(base, result)
        metrics = {m.name: float(metrics[m.name]) for m in METRICS}
        runs.append(ComparisonRun(key, law, mode, design_gamma, disturbance, metrics, result=result))
    return Comparison(scenario=base.name, gamma=float(base.gamma),
                      disturbance=describe_disturbance(base, False), runs=runs)
