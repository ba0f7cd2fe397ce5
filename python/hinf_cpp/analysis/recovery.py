"""Recovery from poor initial conditions, and whether a law turns the ship around.

Definitions (``e(t) = psi(t) - psi_d(t)`` is the heading error as a continuous function of
time that starts at the wrapped initial error, in (-pi, pi], and follows the rotation from
there, so a full turn of the ship changes it by 2 pi; ``wrap`` maps to (-pi, pi]; "last half" =
the output-grid points with t >= (t0 + tf)/2):

recovers
    the final position error ``|p(tf) - p_d(tf)|`` is below ``position_tolerance``
    (default 0.5 m: a quarter of the 2 m offsets of the shipped ``poor_*`` scenarios, and
    about twice the peak of the error the paper's disturbance leaves once the path is
    captured, 0.07 m for the H-infinity law and up to 0.27 m for the cascade baseline, so
    that the verdict does not depend on the phase of the disturbance at tf) **and** the final
    wrapped heading error ``|wrap(e(tf))|`` is below ``heading_tolerance`` (default 10
    degrees).
turns around
    the heading error passes through +-pi, that is ``|e(t)|`` exceeds
    ``max(pi, |e(t0)|) + margin`` at some t (default margin 0.1 rad): the ship rotated past
    pointing backwards, further than it started from, and winds towards e = +-2 pi instead of
    unwinding to 0; **or** the ship tracks backwards: ``|wrap(e)| > pi/2`` on more than
    ``backwards_fraction`` (default one half) of the last half. For a start at exactly
    +-180 degrees both rotations are half turns; by this definition unwinding towards
    e = 0 is not a turn-around and winding towards +-2 pi is (the laws regulate the wrapped
    error to 0, so a start 350 degrees off is a 10 degree error).
settling time
    the first grid time after which the position error stays below ``position_tolerance``
    (None when the final error is not below it).
status
    how the run ended: ``completed``, ``diverged`` (the closed loop stopped at the divergence
    bound), ``lost_track`` (it ran to tf but ended farther from the path than it started, by
    more than ``[solver] lost_track``), or, when there is no closed loop to judge, the
    failure: ``conjugate_point``, ``coupling_violation``, ``solver_failure``, ``failed`` (the
    words of a study's status, :data:`hinf_cpp.studies.study.STATUSES`). Only a completed run
    is judged: a run that did not complete does not recover, and whether it turns around is
    not judged (None, ``-`` in the table), since the heading of a vehicle that diverged or
    lost the path says nothing about how the law turns it.
"""

from __future__ import annotations

import dataclasses
import math
import pathlib
from importlib import resources
from typing import Any, Sequence

import numpy as np

from hinf_cpp import _core
from hinf_cpp.analysis.comparison import Feedback, heading_error, parse_controllers, run_law, wrap_angles
from hinf_cpp.output.progress import ProgressCallback
from hinf_cpp.scenario import load_scenario

__all__ = [
    "BACKWARDS_FRACTION",
    "HEADING_TOLERANCE",
    "POSITION_TOLERANCE",
    "TURN_MARGIN",
    "RecoveryStudy",
    "RecoveryVerdict",
    "TurnAround",
    "assess_recovery",
    "failure_status",
    "recovery_study",
    "shipped_poor_scenarios",
    "turn_around",
]

#: The final position error (m) below which a run has recovered (assess_recovery).
POSITION_TOLERANCE = 0.5
#: The final heading error (rad) below which a run has recovered (assess_recovery).
HEADING_TOLERANCE = math.radians(10.0)
#: How far (rad) the heading error must go beyond max(pi, |e(t0)|) to count as passing
#: through +-pi, i.e. turning around (turn_around).
TURN_MARGIN = 0.1
#: The share of the last half above which a heading error beyond pi/2 counts as tracking
#: backwards (turn_around).
BACKWARDS_FRACTION = 0.5


@dataclasses.dataclass
class TurnAround:
    """The verdict of :func:`turn_around`: whether the vehicle turned around, and why.

    Parameters
    ----------
    turned : bool
        True when the vehicle turned around (the module's definition).
    reason : str
        Why, in one sentence ("" when not turned).
    t_turn : float or None
        The first time (s) |e| exceeds the limit (None if never).
    limit : float
        max(pi, |e(t0)|) + margin (rad).
    backwards_fraction : float
        The share of the last half with |wrap(e)| > pi/2.

    Examples
    --------
    >>> from hinf_cpp.analysis.recovery import turn_around
    >>> verdict = turn_around([0.0, 1.0, 2.0], [3.0, 4.5, 6.2])
    >>> verdict.turned, verdict.t_turn, round(verdict.limit, 4)
    (True, 1.0, 3.2416)
    """

    turned: bool
    reason: str                   # "" when not turned
    t_turn: float | None          # first time |e| exceeds the limit (None if never)
    limit: float                  # max(pi, |e(t0)|) + margin, rad
    backwards_fraction: float     # share of the last half with |wrap(e)| > pi/2


def turn_around(t: Sequence[float], heading_error: Sequence[float], margin: float = TURN_MARGIN,
                backwards_fraction: float = BACKWARDS_FRACTION) -> TurnAround:
    """Whether a heading-error history turns the vehicle around (see the module docstring).

    It turns around when |e| exceeds max(pi, |e(t0)|) + margin at some t (the error passes
    through +-pi and winds towards +-2 pi), or when |wrap(e)| > pi/2 on more than
    `backwards_fraction` of the last half (t >= (t0 + tf)/2: it tracks backwards).

    Parameters
    ----------
    t : array of float
        Strictly increasing times (s), at least two.
    heading_error : array of float
        e(t) = psi - psi_d, continuous, starting in (-pi, pi] (see the module docstring), rad.
    margin : float
        How far (rad) |e| must go beyond max(pi, |e(t0)|) to count as passing through +-pi.
    backwards_fraction : float
        Share of the last half in (0, 1] above which ``|wrap(e)| > pi/2`` counts as tracking
        backwards.

    Returns
    -------
    TurnAround
        The verdict, its reason and the numbers it rests on.

    Raises
    ------
    ValueError
        Mismatched, too short or non-finite inputs, or options out of range.

    Examples
    --------
    >>> from hinf_cpp.analysis.recovery import turn_around
    >>> t = np.linspace(0.0, 10.0, 11)
    >>> turn_around(t, np.linspace(3.0, 0.0, 11)).turned  # unwinds from 172 degrees to 0
    False
    >>> print(turn_around(t, np.linspace(3.0, 2 * np.pi, 11)).reason)  # winds to a full turn
    the heading error passes through +-pi: |e| exceeds max(pi, |e(t0)|) + margin = 3.2416 rad
    at t = 1 s (max |e| = 6.2832 rad)
    """
    t = np.asarray(t, dtype=float)
    e = np.asarray(heading_error, dtype=float)
    if t.ndim != 1 or e.shape != t.shape or t.size < 2:
        raise ValueError(f"turn_around needs two 1-D arrays of the same length >= 2, got shapes {t.shape} "
                         f"and {e.shape}")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(e))):
        raise ValueError("turn_around needs finite times and heading errors")
    if not np.all(np.diff(t) > 0):
        raise ValueError("turn_around needs strictly increasing times")
    if not (math.isfinite(margin) and margin >= 0.0):
        raise ValueError(f"margin must be >= 0 (rad), got {margin}")
    if not (0.0 < backwards_fraction <= 1.0):
        raise ValueError(f"backwards_fraction must be in (0, 1], got {backwards_fraction}")
    limit = max(math.pi, abs(e[0])) + margin
    beyond = np.flatnonzero(np.abs(e) > limit)
    t_turn = float(t[beyond[0]]) if beyond.size else None
    last = t >= 0.5 * (t[0] + t[-1])
    fraction = float(np.mean(np.abs(wrap_angles(e[last])) > 0.5 * math.pi))
    if t_turn is not None:
        reason = (f"the heading error passes through +-pi: |e| exceeds max(pi, |e(t0)|) + margin = "
                  f"{limit:.4f} rad at t = {t_turn:.4g} s (max |e| = {np.max(np.abs(e)):.4f} rad)")
        return TurnAround(True, reason, t_turn, limit, fraction)
    if fraction > backwards_fraction:
        reason = (f"tracks backwards: |wrap(e)| > pi/2 on {100 * fraction:.0f}% of the last half")
        return TurnAround(True, reason, None, limit, fraction)
    return TurnAround(False, "", None, limit, fraction)


@dataclasses.dataclass
class RecoveryVerdict:
    """Recovery of one law on one scenario: the verdict of :func:`assess_recovery`.

    The definitions are those of the module docstring. ``to_dict()`` gives it as a
    JSON-ready dictionary (without the run).

    Parameters
    ----------
    scenario : str
        The scenario's name.
    controller : hinf_cpp.Law
        The law.
    recovers : bool
        The run completed, with the final position error below the position tolerance and the
        final wrapped heading error below the heading tolerance.
    turns_around : bool or None
        :func:`turn_around`'s verdict; None (not judged) for a run that did not complete.
    initial_position_error : float
        |p(t0) - p_d(t0)| (m, the model's unit of length).
    initial_heading_error : float
        e(t0), in (-pi, pi] (rad).
    final_position_error : float
        |p(tf) - p_d(tf)| (m).
    final_heading_error : float
        |wrap(e(tf))| (rad).
    settling_time : float or None
        Time after t0 (s) from which the position error stays below the tolerance; None when
        the final error is not below it.
    max_abs_heading_error : float
        max |e(t)| of the continuous error (rad).
    turn : TurnAround or None
        The turn-around verdict (None when the run did not complete).
    result : hinf_cpp.RunResult, optional
        The run (None when it failed before its closed loop).
    error : str, optional
        The numerical failure, when the run failed (the numbers are then NaN), or the status
        message of a run that diverged or lost track.
    status : str, optional
        How the run ended (module docstring): ``completed`` (default), ``diverged``,
        ``lost_track``, or the failure (``conjugate_point``, ...).

    Examples
    --------
    >>> from hinf_cpp.analysis.recovery import assess_recovery
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("poor_heading_180")))
    >>> verdict = assess_recovery(result)
    >>> verdict.controller, verdict.recovers, verdict.turns_around
    (<Law.hinf: 0>, True, False)
    >>> round(verdict.initial_heading_error, 4), verdict.settling_time, verdict.status
    (3.1416, 5.48, 'completed')
    """

    scenario: str
    controller: _core.Law
    recovers: bool
    turns_around: bool | None       # None: not judged (the run did not complete)
    initial_position_error: float   # m
    initial_heading_error: float    # rad, e(t0), in (-pi, pi]
    final_position_error: float     # m
    final_heading_error: float      # rad, |wrap(e(tf))|
    settling_time: float | None     # s after t0
    max_abs_heading_error: float    # rad, max |e(t)| of the continuous error
    turn: TurnAround | None
    result: _core.RunResult | None = None
    error: str | None = None
    status: str = "completed"

    def to_dict(self) -> dict:
        def number(x):
            return float(x) if x is not None and math.isfinite(x) else None

        return {
            "scenario": self.scenario,
            "controller": self.controller.name,
            "status": self.status,
            "recovers": self.recovers,
            "turns_around": self.turns_around,
            "turn_reason": self.turn.reason if self.turn else "",
            "initial_position_error": number(self.initial_position_error),
            "initial_heading_error": number(self.initial_heading_error),
            "final_position_error": number(self.final_position_error),
            "final_heading_error": number(self.final_heading_error),
            "settling_time": number(self.settling_time),
            "max_abs_heading_error": number(self.max_abs_heading_error),
            "error": self.error,
        }


def _position_error(result: _core.RunResult) -> np.ndarray:
    indices = result.trajectory.model().position_indices()
    if len(indices) != 2:
        raise ValueError(f"recovery needs a planar position: the model '{result.trajectory.model().name()}' "
                         "has none")
    q_e = result.simulation.q_e()
    return np.hypot(q_e[:, indices[0]], q_e[:, indices[1]])


def assess_recovery(result: _core.RunResult, controller: _core.Law | str | None = None, *,
                    position_tolerance: float = POSITION_TOLERANCE,
                    heading_tolerance: float = HEADING_TOLERANCE, margin: float = TURN_MARGIN,
                    backwards_fraction: float = BACKWARDS_FRACTION) -> RecoveryVerdict:
    """Whether a run recovers and whether it turns the ship around (module docstring).

    Recovers: the run completed, its final position error is below `position_tolerance` and
    its final wrapped heading error below `heading_tolerance`. Turns around: :func:`turn_around`
    of the continuous heading error (:func:`hinf_cpp.analysis.comparison.heading_error`). A run
    that diverged or lost track keeps its status: it does not recover, whether it turns around
    is not judged (None), its final errors are those where it stopped.

    Parameters
    ----------
    result : RunResult
        A closed-loop run of a model with a planar position and a heading (the ship).
    controller : Law or str, optional
        The law (default ``result.law``).
    position_tolerance : float, optional
        Threshold on the final position error (m; default 0.5).
    heading_tolerance : float, optional
        Threshold on the final wrapped heading error (rad; default 10 degrees).
    margin : float, optional
        The margin of :func:`turn_around` (rad; default 0.1).
    backwards_fraction : float, optional
        The backwards fraction of :func:`turn_around` (default 0.5).

    Returns
    -------
    RecoveryVerdict
        The verdict, with the run.

    Raises
    ------
    ValueError
        Tolerances not > 0, a model without a heading or a planar position, options of
        :func:`turn_around` out of range.

    Examples
    --------
    >>> from hinf_cpp.analysis.recovery import assess_recovery
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("poor_heading_180")))
    >>> verdict = assess_recovery(result)
    >>> verdict.recovers, round(verdict.final_position_error, 3)
    (True, 0.071)
    >>> assess_recovery(result, position_tolerance=0.05).recovers
    False
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.initial_q0 = [1.0, 0.0, 0.0, 0.0, 8.0, np.pi]  # 8 m aside, heading reversed
    >>> lost = assess_recovery(hc.run_scenario(scenario))
    >>> lost.status, lost.recovers, lost.turns_around
    ('diverged', False, None)
    """
    if not (position_tolerance > 0.0 and heading_tolerance > 0.0):
        raise ValueError(f"the tolerances must be > 0, got position {position_tolerance} m and heading "
                         f"{heading_tolerance} rad")
    e = heading_error(result)
    if e is None:
        raise ValueError(f"recovery needs a heading: the model '{result.trajectory.model().name()}' has none")
    t = np.asarray(result.simulation.t)
    pe = _position_error(result)
    status = result.simulation.status.name
    completed = status == "completed"
    # Checked for every run (bad options are an error either way), kept for completed ones.
    turn = turn_around(t, e, margin, backwards_fraction) if t.size >= 2 else None
    if not completed:
        turn = None
    final_heading = float(abs(wrap_angles(e[-1])))
    above = np.flatnonzero(pe >= position_tolerance)
    if above.size == 0:
        settling = 0.0
    elif above[-1] == pe.size - 1:
        settling = None
    else:
        settling = float(t[above[-1] + 1] - t[0])
    return RecoveryVerdict(
        scenario=result.scenario_name,
        controller=result.law if controller is None else parse_controllers([controller])[0],
        recovers=bool(completed and pe[-1] < position_tolerance and final_heading < heading_tolerance),
        turns_around=turn.turned if turn is not None else None,
        initial_position_error=float(pe[0]),
        initial_heading_error=float(e[0]),
        final_position_error=float(pe[-1]),
        final_heading_error=final_heading,
        settling_time=settling,
        max_abs_heading_error=float(np.max(np.abs(e))),
        turn=turn,
        result=result,
        error=None if completed else " ".join(result.simulation.status_message.split()),
        status=status,
    )


def failure_status(error: BaseException) -> str:
    """The status word of a run that failed before its closed loop ended, as a study names it.

    Parameters
    ----------
    error : BaseException
        The exception of the run.

    Returns
    -------
    str
        ``conjugate_point``, ``coupling_violation``, ``solver_failure``, ``invalid_input``
        (a ValueError) or ``failed``.

    Examples
    --------
    >>> from hinf_cpp.analysis.recovery import failure_status
    >>> failure_status(hc.SolverError("the integrator failed")), failure_status(RuntimeError("?"))
    ('solver_failure', 'failed')
    """
    for kind, status in ((_core.ConjugatePointError, "conjugate_point"),
                         (_core.CouplingConditionError, "coupling_violation"),
                         (_core.SolverError, "solver_failure"), (ValueError, "invalid_input")):
        if isinstance(error, kind):
            return status
    return "failed"


def shipped_poor_scenarios() -> list[pathlib.Path]:
    """The shipped ``poor_*.toml`` scenarios (poor initial conditions), sorted by name.

    The ship of the paper started 2 m off the path or with a heading 90 to 180 degrees off.

    Returns
    -------
    list of pathlib.Path
        The scenario files.

    Examples
    --------
    >>> from hinf_cpp.analysis.recovery import shipped_poor_scenarios
    >>> [path.stem for path in shipped_poor_scenarios()][:3]
    ['poor_heading_090', 'poor_heading_135', 'poor_heading_180']
    """
    folder = pathlib.Path(str(resources.files("hinf_cpp") / "scenarios"))
    return sorted(folder.glob("poor_*.toml"))


@dataclasses.dataclass
class RecoveryStudy:
    """Verdicts of :func:`recovery_study`: scenario x controller.

    ``scenarios`` and ``controllers`` list them in order; ``verdict(scenario, controller)``
    gives one (KeyError otherwise); ``table()`` a header and one row per verdict (angles in
    degrees); ``to_dict()`` the definitions, tolerances and verdicts, JSON-ready.

    Parameters
    ----------
    verdicts : list of RecoveryVerdict
        One per scenario and law, scenarios in the order given.
    position_tolerance : float
        The position tolerance used (m).
    heading_tolerance : float
        The heading tolerance used (rad).
    margin : float
        The turn-around margin used (rad).
    backwards_fraction : float
        The backwards fraction used.

    Examples
    --------
    >>> from hinf_cpp.analysis import recovery_study
    >>> study = recovery_study([hc.scenario_path("poor_heading_180")], "hinf,cascade")
    >>> study.scenarios, study.controllers
    (['poor-heading-180'], [<Law.hinf: 0>, <Law.cascade: 2>])
    >>> study.verdict("poor-heading-180", "cascade").recovers
    True
    >>> header, rows = study.table()
    >>> header[:5], rows[0][:5]
    (['scenario', 'controller', 'status', 'recovers', 'turns around'], ['poor-heading-180', 'hinf', 'completed', True, False])
    """

    verdicts: list[RecoveryVerdict]
    position_tolerance: float
    heading_tolerance: float
    margin: float
    backwards_fraction: float

    @property
    def scenarios(self) -> list[str]:
        return list(dict.fromkeys(v.scenario for v in self.verdicts))

    @property
    def controllers(self) -> list[_core.Law]:
        return list(dict.fromkeys(v.controller for v in self.verdicts))

    def verdict(self, scenario: str, controller: _core.Law | str) -> RecoveryVerdict:
        """The verdict of one law (or its name) on one scenario."""
        law = parse_controllers([controller])[0]
        for v in self.verdicts:
            if v.scenario == scenario and v.controller == law:
                return v
        raise KeyError(f"no verdict for controller '{law.name}' on scenario '{scenario}'")

    def table(self) -> tuple[list[str], list[list[Any]]]:
        """Header and rows: one row per scenario and controller; a run that did not complete
        shows its status, does not recover, and its turn-around is not judged (None)."""
        header = ["scenario", "controller", "status", "recovers", "turns around", "final |p_e| [m]",
                  "final |wrap(e_psi)| [deg]", "settling time [s]", "max |e_psi| [deg]"]
        rows = []
        for v in self.verdicts:
            if v.result is None:
                rows.append([v.scenario, v.controller.name, v.status, None, None, None, None, None, None])
                continue
            rows.append([v.scenario, v.controller.name, v.status, v.recovers, v.turns_around,
                         v.final_position_error, math.degrees(v.final_heading_error), v.settling_time,
                         math.degrees(v.max_abs_heading_error)])
        return header, rows

    def to_dict(self) -> dict:
        return {
            "definitions": {
                "status": "how the run ended: completed, diverged, lost_track, or the failure before the closed "
                          "loop ended (conjugate_point, coupling_violation, solver_failure, failed); only "
                          "completed runs are judged",
                "recovers": f"the run completed, final position error < {self.position_tolerance:g} m and final "
                            f"wrapped heading error < {math.degrees(self.heading_tolerance):g} deg",
                "turns_around": f"|psi - psi_d| (unwrapped) exceeds max(pi, |e(t0)|) + {self.margin:g} rad, or "
                                f"|wrap(psi - psi_d)| > pi/2 on more than {100 * self.backwards_fraction:g}% "
                                "of the last half",
                "settling_time": f"first time after which the position error stays below "
                                 f"{self.position_tolerance:g} m",
            },
            "position_tolerance": self.position_tolerance,
            "heading_tolerance": self.heading_tolerance,
            "margin": self.margin,
            "backwards_fraction": self.backwards_fraction,
            "verdicts": [v.to_dict() for v in self.verdicts],
        }


def recovery_study(scenarios: Sequence[_core.Scenario | str | pathlib.Path] | None = None,
                   controllers: str | Sequence[str] | None = None, *,
                   position_tolerance: float = POSITION_TOLERANCE,
                   heading_tolerance: float = HEADING_TOLERANCE, margin: float = TURN_MARGIN,
                   backwards_fraction: float = BACKWARDS_FRACTION,
                   progress: ProgressCallback | None = None) -> RecoveryStudy:
    """Run every scenario with every law and assess recovery and turning around.

    Parameters
    ----------
    scenarios : sequence of Scenario or path, optional
        Default: :func:`shipped_poor_scenarios`. Each runs as written (output feedback when it
        has ``[measurement]``) with its law replaced.
    controllers : str or sequence of str, optional
        Laws among ``"hinf"``, ``"lqr"``, ``"cascade"``; default all three.
    position_tolerance : float, optional
        As in :func:`assess_recovery` (m; default 0.5).
    heading_tolerance : float, optional
        As in :func:`assess_recovery` (rad; default 10 degrees).
    margin : float, optional
        As in :func:`assess_recovery` (rad; default 0.1).
    backwards_fraction : float, optional
        As in :func:`assess_recovery` (default 0.5).
    progress : callable, optional
        ``progress(index, total, message)`` before each run.

    Returns
    -------
    RecoveryStudy
        A run that fails numerically is kept with ``error`` and ``status`` set; a run that
        diverged or lost track keeps its run, its status and its status message.

    Raises
    ------
    ValueError
        Bad controller names, no scenario, a scenario file that cannot be read, a model
        without a heading or planar position, tolerances not > 0.

    Examples
    --------
    >>> from hinf_cpp.analysis import recovery_study
    >>> study = recovery_study([hc.scenario_path("poor_heading_180")], "hinf")
    >>> [(v.controller.name, v.recovers, v.turns_around) for v in study.verdicts]
    [('hinf', True, False)]
    """
    laws = parse_controllers(controllers)
    if scenarios is None:
        scenarios = shipped_poor_scenarios()
        if not scenarios:
            raise ValueError("no shipped poor_*.toml scenario found")
    loaded = [s if isinstance(s, _core.Scenario) else load_scenario(s) for s in scenarios]
    if not loaded:
        raise ValueError("recovery_study needs at least one scenario")
    total = len(loaded) * len(laws)
    verdicts = []
    for i, scenario in enumerate(loaded):
        feedback = Feedback.state if scenario.measurement is None else Feedback.output
        for j, law in enumerate(laws):
            if progress is not None:
                progress(i * len(laws) + j + 1, total, f"running {law.name} on {scenario.name}")
            try:
                result = run_law(scenario, law, feedback)
            except _core.HinfError as error:
                verdicts.append(RecoveryVerdict(scenario.name, law, False, None, math.nan, math.nan, math.nan,
                                                math.nan, None, math.nan, None,
                                                error=" ".join(str(error).split()), status=failure_status(error)))
                continue
            verdicts.append(assess_recovery(result, law, position_tolerance=position_tolerance,
                                            heading_tolerance=heading_tolerance, margin=margin,
                                            backwards_fraction=backwards_fraction))
    return RecoveryStudy(verdicts, position_tolerance, heading_tolerance, margin, backwards_fraction)
