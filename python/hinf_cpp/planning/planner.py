"""Feasible desired trajectories from waypoints or a sampled path (docs/planning.md).

The paper tracks "a feasible trajectory": q_d driven by inputs u_d through the model. This
module finds such a pair from where the vehicle should go. :func:`plan` solves::

    minimize    effort_weight * int |u / s|^2 dt + rate_weight * int |du/dt / s|^2 dt
    subject to  dq/dt = f(t, q) + G(t, q) u,  q(t0) = q0,  u_min <= u <= u_max,
                |p(t_j) - (x_j, y_j)| <= tolerance at every waypoint j (and its heading
                and speed when given),

(s: the input scale) by direct multiple shooting with CasADi's Opti and IPOPT: u is piecewise
linear between the nodes of a time grid that contains every waypoint's time, and the state
jumps from node to node by classical Runge-Kutta steps (``substeps`` per interval) in which u is
evaluated exactly where it is. The planned u_d is stored as tables with interpolation =
"linear" (so the signal is the optimizer's u, not an approximation of it), and the project's
own integrator (``hc.Trajectory``: Dormand-Prince at rtol 1e-10, restarting at the table's
points) re-simulates q_d from it. The
open-loop mismatch between the planned states and the re-simulated ones is the report's
``position_mismatch``; the substeps are doubled until it is below ``max_mismatch``. Along a
plan where the vehicle is open-loop unstable that mismatch is the growth of the integrator's
own errors, which no refinement removes: the planner detects it and gives the desired
trajectory as the planned states and inputs (``hc.Trajectory.from_states``: each interval
integrated from its node), checked per interval (its defect below ``max_mismatch``).

The waypoint conditions are soft in the optimization (exact penalty with slacks), so that the
problem always has a solution: a waypoint the inputs cannot reach shows as a miss of the
best compromise, reported by :class:`UnreachableWaypointError` with the waypoint's index and
the distance, instead of a long fruitless search for a feasible point. A waypoint far beyond
what the vehicle's top speed with the input bounds covers is refused before optimizing.

The model's dynamics enter as CasADi expressions: a :class:`~hinf_cpp.models.symbolic.SymbolicModel`,
or a built-in model through :func:`~hinf_cpp.models.builtin.symbolic_model`.

Units are the model's (positions in its unit of length, time in s, angles in rad); times are
absolute.
"""

from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import io
import itertools
import json
import math
import os
import pathlib
import sys
import threading
import time
import warnings
from collections.abc import Sequence

import numpy as np

from hinf_cpp import _core
from hinf_cpp.models.codegen import CacheDirectoryError, _write_atomically, check_cache_folder, make_cache_folder
from hinf_cpp.models.symbolic import SymbolicModel, _casadi
from hinf_cpp.models.builtin import symbolic_model

__all__ = ["FeasibilityReport", "Plan", "PlanOptions", "PlanningError", "UnreachableWaypointError", "Waypoint",
           "default_cache_dir", "plan", "plan_path_change", "waypoints_from_path"]

# What the plan cache keeps, and where else to keep it, for the messages about its folder.
CACHE_WHAT = "planned trajectories"
CACHE_HINT = "Set HINF_CPP_CACHE to a folder of your own (plans go to $HINF_CPP_CACHE/plans), or pass cache_dir="
# Part of every cache key (planned_scenario.py): a change to the formulation changes it. 2: the
# default grid follows the waypoints, and a plan may be given as states (open-loop unstable).
PLANNER_VERSION = 2
# The layout of a cache entry; an entry of another format is planned anew, never misread.
CACHE_FORMAT = 2
# The default spacing of the nodes: at most the horizon / DEFAULT_INTERVALS, and at least
# LEG_INTERVALS intervals between consecutive key times (t0, the waypoints' times, tf). The
# input is linear between nodes: over one or two pieces a leg can only ramp the input, while
# the usual manoeuvre between two waypoints (turn towards the next, hold, straighten onto its
# heading) needs it to rise, hold and fall back: four pieces. Per leg rather than one spacing
# for the whole horizon, so that one short leg does not refine all the others. The shipped
# planned scenarios keep their grids (their shortest default leg has 14 intervals).
DEFAULT_INTERVALS = 60
LEG_INTERVALS = 4
# Open-loop instability along a plan (plan(): _unstable). The re-simulation from q0 is repeated
# with its integrator's relative tolerance 10 times tighter (STRICT_RTOL); where the flow
# amplifies errors, the two differ by the growth of the integrator's own errors (the built-in
# AUV at 1 m/s over 120 s: 1.3e-3 m; the paper's ship on the shipped lane change: 1e-11 m).
STRICT_RTOL = 1e-11
# The largest |lambda h| of a Runge-Kutta step for the fastest mode lambda of the vehicle at the
# start (_stable_substeps): inside the method's stability region (2.79 on the real axis) with a
# margin. The shipped planned scenarios need at most 2 steps per interval by it (their first
# solves take 2: unchanged).
RK4_STEP = 2.0
# A classical Runge-Kutta error falls 16 times when the substeps double; a mismatch that falls
# by less than SHRINK is not the plan's discretization error.
SHRINK = 2.0
# Weights of a waypoint condition's slack (per tolerance). An exact penalty meets every
# reachable waypoint once it exceeds the condition's multiplier; the first weight is enough for
# most plans and keeps IPOPT fast when a waypoint is out of reach, and a miss is confirmed with
# the larger ones before it is reported.
PENALTIES = (1e2, 1e4, 1e6)
# A waypoint farther from the one before (or from the start) than REACH_FACTOR times the
# distance covered at the vehicle's top speed is refused before optimizing. The top speed is
# estimated by simulating constant inputs at the bounds (and 0): a clever input can do better
# than a constant one, hence the factor; IPOPT searches long for a waypoint far out of reach.
REACH_FACTOR = 3.0
# Headings are compared modulo 2 pi; beyond this size (rad) a double no longer resolves the
# heading tolerance after wrapping.
MAX_HEADING = 1e6
# The most intervals of the time grid (each adds n + m unknowns to the optimization).
MAX_INTERVALS = 100_000


class PlanningError(_core.HinfError):
    """The planner failed: no plan to give.

    Raised by :func:`plan` when the optimizer failed (IPOPT's return status and iterations in
    the message), or when the plan could not be made accurate enough (its re-simulation
    mismatch stayed above ``max_mismatch``, or the re-simulated trajectory misses a
    waypoint's tolerance). A :class:`hinf_cpp.HinfError`.

    Examples
    --------
    >>> from hinf_cpp.planning import PlanOptions, PlanningError, Waypoint, plan
    >>> try:
    ...     plan(hc.ShipModel(), [Waypoint(10.0, 0.0, t=10.0)], q0=[1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    ...          options=PlanOptions(interval=1.0, max_iterations=2))
    ... except PlanningError as error:
    ...     print(error)
    the planner's optimizer (IPOPT) stopped without a solution: Maximum_Iterations_Exceeded
    after 2 iterations. ...
    >>> issubclass(PlanningError, hc.HinfError)
    True
    """


class UnreachableWaypointError(ValueError):
    """A waypoint cannot be reached within its tolerance with the input bounds and time given.

    A ValueError. The message names the waypoint, the bounds and how far the best plan comes. When several
    waypoints are missed, the first one the plan cannot reach after meeting the ones before it
    is named.

    Parameters
    ----------
    message : str
        The message.
    index : int
        The waypoint's index (0-based) in the list given to :func:`plan`.
    miss : float
        How far the best plan stays from the waypoint, in units of the condition's tolerance
        (position: distance / ``tolerance``; heading and speed likewise). For a waypoint refused
        before optimizing, an estimate: its distance beyond what the top speed covers.

    Examples
    --------
    >>> from hinf_cpp.planning import PlanOptions, UnreachableWaypointError, Waypoint, plan
    >>> try:  # 20 m in 10 s from 1 m/s: beyond the surge force u1 <= 2
    ...     plan(hc.ShipModel(), [Waypoint(20.0, 0.0, t=10.0)], q0=[1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    ...          options=PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5), interval=1.0))
    ... except UnreachableWaypointError as error:
    ...     print(error.index, error)
    0 waypoints[0] (x = 20, y = 0, t = 10) cannot be reached with the input bounds
    u1 in [0, 2], u2 in [-0.5, 0.5] by t = 10: the best plan comes ... away (tolerance 0.05). ...
    """

    def __init__(self, message: str, index: int, miss: float):
        super().__init__(message)
        self.index = index
        self.miss = miss


@dataclasses.dataclass(frozen=True)
class Waypoint:
    """Where the vehicle should be, and optionally when, heading where and how fast.

    Parameters
    ----------
    x : float
        The position's first component, in the model's unit of length (the first of its
        ``position_indices()`` states).
    y : float
        The position's second component.
    t : float, optional
        The arrival time (absolute, s). Without it :func:`plan` times the waypoint: at
        ``PlanOptions.speed`` from the one before, else the last waypoint at tf and the others
        at constant speed along the polyline between the timed ones.
    heading : float, optional
        The heading on arrival (rad, the model's heading state, compared modulo 2 pi).
    speed : float, optional
        The speed ``|d(x, y)/dt|`` on arrival (unit of length per s, >= 0).

    Examples
    --------
    >>> from hinf_cpp.planning import Waypoint
    >>> waypoint = Waypoint(20.0, 3.5, t=40.0, heading=0.0)
    >>> waypoint
    Waypoint(x=20.0, y=3.5, t=40.0, heading=0.0, speed=None)
    >>> waypoint.describe()
    '(x = 20, y = 3.5, t = 40, heading = 0)'
    """

    x: float
    y: float
    t: float | None = None
    heading: float | None = None
    speed: float | None = None

    def describe(self) -> str:
        parts = [f"x = {self.x:g}, y = {self.y:g}"]
        parts += [f"{name} = {getattr(self, name):g}" for name in ("t", "heading", "speed")
                  if getattr(self, name) is not None]
        return "(" + ", ".join(parts) + ")"


@dataclasses.dataclass(frozen=True)
class PlanOptions:
    """The planner's settings; each is also a key of a scenario file's [desired.plan] (and of a
    planned [path_change]'s ``plan``).

    The options are checked by :meth:`checked` (which :func:`plan` calls), not at
    construction. Units are the model's: length, s, rad.

    Parameters
    ----------
    tolerance : float, optional
        How close to each waypoint's position (unit of length, > 10 ``max_mismatch``;
        default 0.05).
    heading_tolerance : float, optional
        How close to a waypoint's heading (rad; default 0.01).
    speed_tolerance : float, optional
        How close to a waypoint's speed (unit of length per s; default 0.01).
    speed : float, optional
        Nominal speed that times the waypoints given without t (unit of length per s).
    u_min : float or tuple of float, optional
        Lower input bounds, one number for every input or one per input (-inf: unbounded;
        default unbounded).
    u_max : float or tuple of float, optional
        Upper input bounds, likewise (inf: unbounded; default unbounded).
    input_scale : float or tuple of float, optional
        The scale s of each input in the cost; default max(|u_min|, |u_max|) of its finite
        bounds, else 1.
    effort_weight : float, optional
        Weight of int |u / s|^2 dt (>= 0; default 1).
    rate_weight : float, optional
        Weight of int |du/dt / s|^2 dt (>= 0; default 1; not both 0).
    interval : float, optional
        Largest spacing of the input's nodes (s), the same between every two key times (t0,
        the waypoints' times, tf). Default: the horizon / 60, and between two consecutive key
        times at least 4 intervals (so at most a quarter of the time between two waypoints):
        the manoeuvre between two waypoints needs an input that can rise, hold and fall back,
        and a short leg gets its nodes without refining the others.
    substeps : int, optional
        Runge-Kutta steps per interval (doubled until the mismatch is met; default 8).
    max_mismatch : float, optional
        Largest distance of the re-simulated from the planned positions (unit of length;
        default 1e-6); for a plan given as states (a vehicle open-loop unstable along it),
        the largest defect of an interval (the states' units).
    max_iterations : int, optional
        IPOPT's iteration limit per solve (default 1000).

    Examples
    --------
    >>> from hinf_cpp.planning import PlanOptions
    >>> options = PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5)).checked(2)
    >>> options.input_scale
    (2.0, 0.5)
    >>> PlanOptions(tolerance=0.0).checked(2)
    Traceback (most recent call last):
        ...
    ValueError: tolerance must be a finite number > 0, got 0.0
    """

    tolerance: float = 0.05  # how close to each waypoint's position (unit of length)
    heading_tolerance: float = 0.01  # rad
    speed_tolerance: float = 0.01  # unit of length per s
    speed: float | None = None  # nominal speed that times waypoints given without t
    u_min: tuple[float, ...] | None = None  # per input; -inf: unbounded
    u_max: tuple[float, ...] | None = None
    input_scale: tuple[float, ...] | None = None  # s of the cost; default max(|u_min|, |u_max|) or 1
    effort_weight: float = 1.0
    rate_weight: float = 1.0
    interval: float | None = None  # largest spacing of the nodes (s); default horizon / 60, >= 4 per leg
    substeps: int = 8  # Runge-Kutta steps per interval (doubled until the mismatch is met)
    max_mismatch: float = 1e-6  # re-simulated against planned positions; states given: largest defect
    max_iterations: int = 1000  # of IPOPT

    def checked(self, m: int) -> "PlanOptions":
        """The options with the per-input tuples resolved to m numbers; ValueError naming the
        first bad one."""
        for name in ("tolerance", "heading_tolerance", "speed_tolerance", "max_mismatch"):
            _positive(getattr(self, name), name)
        for name in ("effort_weight", "rate_weight"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
                raise ValueError(f"{name} must be a number >= 0, got {value!r}")
        if self.effort_weight == 0 and self.rate_weight == 0:
            raise ValueError("effort_weight and rate_weight are both 0: nothing to minimize; make one > 0")
        for name in ("speed", "interval"):
            if getattr(self, name) is not None:
                _positive(getattr(self, name), name)
        for name in ("substeps", "max_iterations"):
            value = getattr(self, name)
            if not (isinstance(value, int) and not isinstance(value, bool) and value >= 1):
                raise ValueError(f"{name} must be an integer >= 1, got {value!r}")
        if self.tolerance <= 10 * self.max_mismatch:
            raise ValueError(f"tolerance ({self.tolerance:g}) must be more than 10 max_mismatch "
                             f"({self.max_mismatch:g}): the optimizer aims 10 max_mismatch inside it")
        u_min = _per_input(self.u_min, m, "u_min", -math.inf)
        u_max = _per_input(self.u_max, m, "u_max", math.inf)
        for i in range(m):
            if not u_min[i] < u_max[i]:
                raise ValueError(f"u_min[{i}] = {u_min[i]:g} must be below u_max[{i}] = {u_max[i]:g}")
        default_scale = tuple(max(abs(a) if math.isfinite(a) else 0.0, abs(b) if math.isfinite(b) else 0.0) or 1.0
                              for a, b in zip(u_min, u_max))
        scale = _per_input(self.input_scale, m, "input_scale", None) if self.input_scale is not None else default_scale
        for i, s in enumerate(scale):
            _positive(s, f"input_scale[{i}]")
        return dataclasses.replace(self, u_min=u_min, u_max=u_max, input_scale=scale)


def _positive(value, name: str) -> None:
    if not (isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and value > 0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")


def _per_input(values, m: int, name: str, fallback) -> tuple[float, ...]:
    """m numbers from None (fallback), a number (for every input) or m numbers."""
    if values is None:
        return (fallback,) * m
    if isinstance(values, (int, float)):
        values = (values,) * m
    values = tuple(values)
    if len(values) != m:
        raise ValueError(f"{name} needs one number per input ({m}), got {len(values)}")
    for i, v in enumerate(values):
        if not isinstance(v, (int, float)) or isinstance(v, bool) or math.isnan(v):
            raise ValueError(f"{name}[{i}] must be a number, got {v!r}")
    return tuple(float(v) for v in values)


@dataclasses.dataclass
class FeasibilityReport:
    """How well the plan is feasible for the model, checked by re-simulating it.

    The report of a :class:`Plan`: the planned inputs are integrated again by the project's
    integrator (``hc.Trajectory``) from q0 and compared with the planned states; the waypoint
    errors are those of the desired trajectory (what is tracked). When the vehicle is
    open-loop unstable along the plan (``states_given``), that re-simulation drifts away and
    the desired trajectory is given as the planned states instead, each interval integrated
    from its node: its check is the largest defect of an interval (``max_defect``).
    ``summary()`` gives it in one line, ``to_dict()`` as a dictionary (a number that is not
    finite as None).

    Parameters
    ----------
    position_mismatch : float
        Max over the nodes of |p_planned - p_re-simulated| (unit of length); inf when the
        re-simulation from q0 failed (left the finite numbers).
    position_mismatch_t : float
        The time where it is largest (s; NaN when the re-simulation failed).
    state_mismatch : float
        Max over the nodes and states of |q_planned - q_re-simulated|.
    waypoint_errors : list of float
        |p(t_j) - (x_j, y_j)| of the re-simulated trajectory, per waypoint.
    heading_errors : list of float or None
        |wrap(psi(t_j) - heading_j)| (rad) where a heading is given, else None.
    speed_errors : list of float or None
        ||dp/dt(t_j)| - speed_j| where a speed is given, else None.
    iterations : int
        IPOPT iterations, summed over the refinements.
    solve_seconds : float
        IPOPT's wall time, summed (s).
    seconds : float
        All of :func:`plan`: formulation, solves, re-simulation (s).
    substeps : int
        Runge-Kutta steps per interval of the final solve.
    intervals : int
        Intervals of the input's time grid.
    status : str
        IPOPT's return status of the final solve.
    cache_hit : bool, optional
        True: read back from the plan cache (default False).
    states_given : bool, optional
        True: the vehicle is open-loop unstable along the plan, and the desired trajectory is
        the planned states and inputs (``hc.Trajectory.from_states``); False (default): q_d is
        the re-simulation from q0.
    max_defect : float, optional
        States given: the largest defect of an interval, |end of interval k - q_{k+1}|_inf
        (the states' units), at most ``max_mismatch``; else None.
    max_defect_t : float, optional
        States given: the start of that interval (s); else None.
    resimulation_sensitivity : float, optional
        Computed when the re-simulation from q0 missed ``max_mismatch``: max over the nodes of
        the distance between the positions re-simulated at the integrator's relative tolerance
        (1e-10) and at 1e-11, the growth of the integrator's own error along the plan (inf:
        the second integration failed); else None.

    Examples
    --------
    >>> from hinf_cpp.planning import PlanOptions, Waypoint, plan
    >>> result = plan(hc.ShipModel(), [Waypoint(10.0, 0.0, t=10.0), Waypoint(20.0, 2.0, t=20.0)],
    ...               q0=[1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    ...               options=PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5), interval=1.0))
    >>> report = result.report
    >>> report.intervals, report.status, report.cache_hit
    (20, 'Solve_Succeeded', False)
    >>> report.position_mismatch <= 1e-6, max(report.waypoint_errors) <= 0.05
    (True, True)
    >>> print(report.summary())
    20 intervals x ... RK4 steps, ... IPOPT iterations, ... s; re-simulation mismatch ...
    (max over the nodes), waypoints met within 0.05
    """

    position_mismatch: float  # max over the nodes of |p_planned - p_re-simulated| (unit of length)
    position_mismatch_t: float  # where it is largest (s)
    state_mismatch: float  # max over the nodes and states of |q_planned - q_re-simulated|
    waypoint_errors: list[float]  # |p(t_j) - (x_j, y_j)| of the re-simulated trajectory
    heading_errors: list[float | None]  # |psi(t_j) - heading_j| wrapped, where a heading is given
    speed_errors: list[float | None]  # ||dp/dt(t_j)| - speed_j|, where a speed is given
    iterations: int  # IPOPT iterations, summed over the refinements
    solve_seconds: float  # IPOPT's wall time, summed
    seconds: float  # all of plan(): formulation, solves, re-simulation
    substeps: int  # Runge-Kutta steps per interval of the final solve
    intervals: int  # of the input's time grid
    status: str  # IPOPT's return status of the final solve
    cache_hit: bool = False  # True: read back from the plan cache (planned_scenario.py)
    states_given: bool = False  # True: open-loop unstable along the plan; q_d given as the planned states
    max_defect: float | None = None  # states given: largest |end of interval k - q_{k+1}|_inf
    max_defect_t: float | None = None  # states given: the start of that interval (s)
    resimulation_sensitivity: float | None = None  # re-simulation at rtol 1e-10 against 1e-11, when computed

    def summary(self) -> str:
        how = "from the cache" if self.cache_hit else f"{self.iterations} IPOPT iterations, {self.seconds:.2f} s"
        met = f"waypoints met within {max(self.waypoint_errors, default=0.0):.3g}"
        if not self.states_given:
            return (f"{self.intervals} intervals x {self.substeps} RK4 steps, {how}; re-simulation mismatch "
                    f"{self.position_mismatch:.2e} (max over the nodes), {met}")
        return (f"{self.intervals} intervals x {self.substeps} RK4 steps, {how}; the vehicle is open-loop unstable "
                f"along the plan (its re-simulation from q0 drifts {self.position_mismatch:.3g} away by t = "
                f"{self.position_mismatch_t:g}): q_d is given as the planned states, largest defect of an interval "
                f"{self.max_defect:.2e} (at t = {self.max_defect_t:g}), {met}")

    def to_dict(self) -> dict:
        return {key: None if isinstance(value, float) and not math.isfinite(value) else value
                for key, value in dataclasses.asdict(self).items()}


@dataclasses.dataclass
class Plan:
    """A desired trajectory planned for a model: what :func:`plan` returns.

    The inputs u_d (as signals and at the nodes; linear in between), the planned states at the
    nodes, and q_d re-simulated from u_d by the project's integrator, or, when the vehicle is
    open-loop unstable along the plan (``states_given``), q_d given as the planned states with
    each interval integrated from its node (``hc.Trajectory.from_states``). ``inputs()`` gives
    u_d as an ``hc.VectorSignal`` (one "linear" table per input), ``input_tables()`` in the
    form of a scenario file's [desired] (``{"u1": {"table": {...}}, ...}``), both with
    ``hold_until=T`` the inputs at tf held up to T (for receding-horizon windows beyond tf),
    ``desired_states()`` the planned states in the form of its ``states`` key (for a plan given
    as states); ``t0``, ``tf`` and ``q0`` are the first and last node and the planned state at
    t0.

    Parameters
    ----------
    model : hinf_cpp.Model
        The C++ model that re-simulated it (a SymbolicModel is compiled).
    waypoints : list of Waypoint
        The waypoints, with their times resolved.
    waypoint_nodes : list of int
        The node of each waypoint's time.
    t : numpy.ndarray, shape (N + 1,)
        The nodes (s), containing every waypoint's time.
    q : numpy.ndarray, shape (N + 1, n)
        The planned states at the nodes.
    u : numpy.ndarray, shape (N + 1, m)
        The inputs at the nodes; linear in between.
    trajectory : hinf_cpp.Trajectory
        q_d re-simulated from u_d (Dormand-Prince at rtol 1e-10), or given as the states (each
        interval integrated from its node) when ``states_given``: the desired trajectory to
        design for (``hc.solve_grde``) and track.
    report : FeasibilityReport
        The feasibility check.
    states_given : bool, optional
        True: the vehicle is open-loop unstable along the plan and ``trajectory`` is made from
        the planned states and inputs; False (default): from q0 and the inputs.

    Examples
    --------
    >>> from hinf_cpp.planning import PlanOptions, Waypoint, plan
    >>> result = plan(hc.ShipModel(), [Waypoint(10.0, 0.0, t=10.0), Waypoint(20.0, 2.0, t=20.0)],
    ...               q0=[1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    ...               options=PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5), interval=1.0))
    >>> result.t.shape, result.q.shape, result.u.shape
    ((21,), (21, 6), (21, 2))
    >>> result.t0, result.tf, result.waypoint_nodes
    (0.0, 20.0, [10, 20])
    >>> sorted(result.input_tables())
    ['u1', 'u2']
    >>> held = result.inputs(hold_until=25.0)  # the inputs at tf held to t = 25 s
    >>> bool(np.array_equal(held(25.0), held(20.0))), bool(held(20.0)[0] == result.u[-1, 0])
    (True, True)
    >>> q_d = result.trajectory.q_d(20.0)  # [u, v, r, x, y, psi] at the last waypoint
    >>> bool(np.hypot(q_d[3] - 20.0, q_d[4] - 2.0) <= 0.05)
    True
    """

    model: _core.Model  # the C++ model that re-simulated it
    waypoints: list[Waypoint]  # with their times resolved
    waypoint_nodes: list[int]  # the node of each waypoint's time
    t: np.ndarray  # the nodes, (N + 1,)
    q: np.ndarray  # planned states at the nodes, (N + 1, n)
    u: np.ndarray  # inputs at the nodes, (N + 1, m); linear in between
    trajectory: _core.Trajectory  # q_d re-simulated from u_d, or from the states (states_given)
    report: FeasibilityReport
    states_given: bool = False  # True: q_d given as the planned states (open-loop unstable along the plan)

    @property
    def q0(self) -> np.ndarray:
        return self.q[0]

    @property
    def t0(self) -> float:
        return float(self.t[0])

    @property
    def tf(self) -> float:
        return float(self.t[-1])

    def inputs(self, hold_until: float | None = None) -> _core.VectorSignal:
        """u_d as signals: one table per input, interpolation "linear" (the optimizer's); with
        `hold_until` > tf, the last inputs held from tf to it (a receding horizon's windows
        reach a window beyond the mission's end)."""
        t, u = self._held(hold_until)
        return _input_signal(t, u)

    def input_tables(self, hold_until: float | None = None) -> dict:
        """u_d in the form of a scenario file's [desired]: {"u1": {"table": {...}}, ...};
        `hold_until` as for :meth:`inputs`."""
        t, u = self._held(hold_until)
        return {f"u{i + 1}": {"table": {"t": t.tolist(), "value": u[:, i].tolist(), "interpolation": "linear"}}
                for i in range(u.shape[1])}

    def _held(self, hold_until: float | None) -> tuple[np.ndarray, np.ndarray]:
        """The nodes and inputs, with a last node at `hold_until` repeating the inputs at tf
        (linear between equal values: held) when it is after tf."""
        if hold_until is None or not hold_until > self.tf:
            return self.t, self.u
        if not math.isfinite(hold_until):
            raise ValueError(f"hold_until must be a finite time (s), got {hold_until!r}")
        return np.append(self.t, float(hold_until)), np.vstack([self.u, self.u[-1:]])

    def desired_states(self) -> dict:
        """The planned states in the form of a scenario file's [desired] states: {"t": [...],
        "q": [[...], ...]} (the nodes, and the states at them, row 0 the plan's q0)."""
        return {"t": self.t.tolist(), "q": self.q.tolist()}


def _input_signal(t: np.ndarray, u: np.ndarray) -> _core.VectorSignal:
    return _core.VectorSignal([_core.Signal.table(t, u[:, i], "linear") for i in range(u.shape[1])])


def waypoints_from_path(x: Sequence[float], y: Sequence[float], speed, start: Sequence[float], t0: float = 0.0,
                        tolerance: float = 0.0) -> list[Waypoint]:
    """The samples (x_i, y_i) of a path as waypoints, timed by a speed profile.

    The vehicle starts at the position `start` at t0. The time to cover a piece of length L
    whose speeds at its ends are a and b is 2 L / (a + b) (constant acceleration along the
    path); from `start` to the first sample, at the first sample's speed. A first sample
    within `tolerance` of the start is the start itself and is left out.

    Parameters
    ----------
    x : array_like, shape (k,)
        The samples' first position component (unit of length), k >= 1, finite.
    y : array_like, shape (k,)
        The samples' second position component.
    speed : float or array_like, shape (k,)
        One speed for every sample or one per sample (> 0, unit of length per s; linear in
        between along the path).
    start : array_like, shape (2,)
        The position at t0.
    t0 : float, optional
        The start time (s; default 0).
    tolerance : float, optional
        A first sample this close to `start` is left out (default 0).

    Returns
    -------
    list of Waypoint
        One per sample (but a first one at the start), with its time t.

    Raises
    ------
    ValueError
        x and y of different shapes or empty, non-finite samples, speeds that are not one or
        one per sample or not > 0, a sample repeated.

    Examples
    --------
    >>> from hinf_cpp.planning import waypoints_from_path
    >>> waypoints = waypoints_from_path([10.0, 20.0], [0.0, 0.0], [1.0, 2.0], start=(0.0, 0.0))
    >>> [(w.x, round(w.t, 2)) for w in waypoints]  # 10 m at 1 m/s, then 10 m from 1 to 2 m/s
    [(10.0, 10.0), (20.0, 16.67)]
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if x.ndim != 1 or x.shape != y.shape or len(x) < 1:
        raise ValueError(f"a path needs x and y of the same length >= 1, got {x.shape} and {y.shape}")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
        raise ValueError("a path's x and y must be finite")
    speeds = np.broadcast_to(np.asarray(speed, dtype=float), x.shape) if np.ndim(speed) == 0 else np.asarray(speed, dtype=float)
    if speeds.shape != x.shape:
        raise ValueError(f"a path's speed must be one number or one per sample ({len(x)}), got {speeds.shape[0]}")
    if not np.all(np.isfinite(speeds) & (speeds > 0)):
        raise ValueError("a path's speed must be finite and > 0 at every sample")
    px, py = np.concatenate([[start[0]], x]), np.concatenate([[start[1]], y])
    v = np.concatenate([[speeds[0]], speeds])
    lengths = np.hypot(np.diff(px), np.diff(py))
    times = t0 + np.concatenate([[0.0], np.cumsum(2.0 * lengths / (v[:-1] + v[1:]))])
    points = [Waypoint(float(x[i]), float(y[i]), t=float(times[i + 1])) for i in range(len(x))]
    if lengths[0] <= tolerance:
        points = points[1:]
    for a, b in zip(points[:-1], points[1:]):
        if not b.t > a.t:
            raise ValueError(f"a path's samples must be distinct: ({a.x:g}, {a.y:g}) repeats")
    return points


def resolve_times(waypoints: Sequence[Waypoint], start: Sequence[float], t0: float, tf: float | None,
                  speed: float | None) -> list[Waypoint]:
    """Waypoints with every time given: a waypoint without t is reached at `speed` from the one
    before (the start, at t0, for the first); without a speed, the last waypoint is reached at
    tf and the others without t at constant speed along the polyline between the timed ones."""
    if len(waypoints) == 0:
        raise ValueError("plan needs at least one waypoint")
    points = [(float(start[0]), float(start[1]))] + [(w.x, w.y) for w in waypoints]
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(np.array(points), axis=0).T))])
    times: list[float | None] = [t0] + [w.t for w in waypoints]
    if speed is not None:
        for j in range(1, len(times)):
            if times[j] is None:
                times[j] = times[j - 1] + (arc[j] - arc[j - 1]) / speed
    else:
        if times[-1] is None:
            if tf is None:
                raise ValueError("the last waypoint has no time t: give it one, or a speed, or tf")
            times[-1] = tf
        anchors = [j for j, t in enumerate(times) if t is not None]
        for a, b in zip(anchors[:-1], anchors[1:]):
            for j in range(a + 1, b):
                share = (arc[j] - arc[a]) / (arc[b] - arc[a]) if arc[b] > arc[a] else (j - a) / (b - a)
                times[j] = times[a] + share * (times[b] - times[a])
    resolved = [dataclasses.replace(w, t=float(t)) for w, t in zip(waypoints, times[1:])]
    previous = t0
    for j, w in enumerate(resolved):
        if not (math.isfinite(w.t) and w.t > previous):
            raise ValueError(f"waypoints[{j}] {w.describe()}: its time must be after "
                             f"{'t0' if j == 0 else f'waypoints[{j - 1}]'}'s ({previous:g} s): times must increase")
        previous = w.t
    if tf is not None and resolved[-1].t > tf * (1 + 1e-12) + 1e-12:
        raise ValueError(f"waypoints[{len(resolved) - 1}] {resolved[-1].describe()} comes after the end of the "
                         f"horizon tf = {tf:g}: give a later tf or an earlier time")
    return resolved


def time_grid(t0: float, tf: float, key_times: Sequence[float], interval: float, divisions: int = 1) -> np.ndarray:
    """Nodes from t0 to tf that contain every key time, equally spaced between consecutive key
    times at most `interval` apart, and at least `divisions` intervals between them."""
    knots = sorted({t0, tf, *key_times})
    nodes = [t0]
    for a, b in zip(knots[:-1], knots[1:]):
        count = max(divisions, math.ceil((b - a) / interval - 1e-9))
        nodes += [a + (b - a) * i / count for i in range(1, count)] + [b]
    return np.array(nodes)


def plan(model, waypoints: Sequence[Waypoint], q0: Sequence[float], t0: float = 0.0, tf: float | None = None,
         options: PlanOptions | None = None, cache_dir: str | os.PathLike | None = None) -> Plan:
    """Plan a feasible desired trajectory (q_d, u_d) through the waypoints.

    Solves the problem of the module's documentation (docs/planning.md): the least input
    effort and rate from the state q0 at t0 to tf subject to the model's dynamics, the input
    bounds and the waypoint conditions, by direct multiple shooting with CasADi and IPOPT.
    The planned inputs are re-simulated by the project's integrator and checked against the
    planned states and the waypoints. When the re-simulation's mismatch is the open-loop growth
    of errors along the plan (it changes with the integrator's tolerance by more than
    ``max_mismatch``, is too large for the doublings of the substeps left to remove, or falls
    by less than half when the substeps double), the vehicle is unstable along the plan: the desired trajectory is then the planned states and inputs
    (``Plan.states_given``), each interval integrated from its node and checked by its defect.
    Units are the model's; times are absolute (s).

    Parameters
    ----------
    model : hinf_cpp.Model or hinf_cpp.models.SymbolicModel
        A built-in model (its CasADi statement: :func:`hinf_cpp.models.symbolic_model`) or a
        SymbolicModel; it needs two position components.
    waypoints : sequence of Waypoint
        At least one; their times, given or resolved, must increase after t0.
    q0 : array_like, shape (n,)
        The desired state at t0.
    t0 : float, optional
        The start time (s; default 0).
    tf : float, optional
        The end time (s; default the last waypoint's time).
    options : PlanOptions, optional
        The planner's settings (default ``PlanOptions()``).
    cache_dir : str or os.PathLike, optional
        A folder (e.g. :func:`default_cache_dir`) where plans are kept by the content of
        what they depend on (the model's equations, q0, the horizon, the waypoints, the
        options, the planner's version): the same request again is read back, re-simulated
        and checked instead of optimized; an entry that cannot be read or fails its checks is
        planned anew and replaced. The folder is made with mode 0700. None (default): no cache.

    Returns
    -------
    Plan
        The inputs, the planned and re-simulated states, the report.

    Raises
    ------
    ValueError
        Bad arguments (q0 not n finite numbers, a model without two position components or
        without a CasADi form, bad waypoints or options, times that do not increase, a heading
        beyond +-1e6 rad, a time grid of more than 100000 intervals).
    hinf_cpp.models.codegen.CacheDirectoryError
        An OSError: `cache_dir` is owned by another user, or group or others can write it
        (the message says what to do).
    UnreachableWaypointError
        A ValueError: a waypoint cannot be met with the input bounds and the time given; one
        more than 3 times as far as the vehicle's top speed takes it (simulated with constant
        inputs at the bounds) is refused before optimizing.
    PlanningError
        IPOPT fails, or the plan cannot be made accurate enough (its re-simulation mismatch,
        or given as states its largest defect, stays above ``max_mismatch`` with 16 times the
        substeps).

    Examples
    --------
    >>> from hinf_cpp.planning import PlanOptions, Waypoint, plan
    >>> waypoints = [Waypoint(10.0, 0.0, t=10.0), Waypoint(20.0, 2.0, t=20.0)]
    >>> options = PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5), interval=1.0)
    >>> result = plan(hc.ShipModel(), waypoints, q0=[1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    ...               options=options, cache_dir="plans")
    >>> result.u.shape, max(result.report.waypoint_errors) <= options.tolerance
    ((21, 2), True)
    >>> again = plan(hc.ShipModel(), waypoints, q0=[1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    ...              options=options, cache_dir="plans")
    >>> again.report.cache_hit
    True
    >>> design = hc.solve_grde(result.trajectory, np.eye(6), np.eye(6), gamma=5.0)
    """
    started = time.perf_counter()
    ca = _casadi()
    symbolic = symbolic_model(model)
    cpp_model = model if isinstance(model, _core.Model) else symbolic.compile()
    n, m = symbolic.n, symbolic.m
    options = (options or PlanOptions()).checked(m)
    q0 = np.asarray(q0, dtype=float)
    if q0.shape != (n,) or not np.all(np.isfinite(q0)):
        raise ValueError(f"q0 must be {n} finite numbers (the model's state), got {q0.tolist()}")
    positions = list(symbolic.position_indices)
    if len(positions) != 2:
        raise ValueError(f"the model '{symbolic.name}' has {len(positions)} position components; waypoints "
                         "(x, y) need exactly two (position_indices)")
    heading = symbolic.heading_index
    for j, w in enumerate(waypoints):
        _check_waypoint(j, w, heading)
    t0 = float(t0)
    waypoints = resolve_times(waypoints, q0[positions], t0, tf, options.speed)
    tf = waypoints[-1].t if tf is None else float(tf)
    interval = options.interval or (tf - t0) / DEFAULT_INTERVALS
    divisions = 1 if options.interval else LEG_INTERVALS
    if not ((tf - t0) / interval <= MAX_INTERVALS and divisions * (len(waypoints) + 1) <= MAX_INTERVALS):
        raise ValueError(f"the horizon from t0 = {t0:g} to tf = {tf:g} s in intervals of at most {interval:g} s "
                         f"needs more than {MAX_INTERVALS} intervals: give a larger interval or a shorter horizon")
    t = time_grid(t0, tf, [w.t for w in waypoints], interval, divisions)
    nodes = [int(np.searchsorted(t, w.t)) for w in waypoints]

    dynamics = _dynamics_function(ca, symbolic)
    cache_path = None
    if cache_dir is not None:
        cache_path = pathlib.Path(cache_dir) / f"{_cache_key(dynamics, cpp_model, q0, t0, tf, waypoints, options)}.json"
        if check_cache_folder(cache_path.parent, CACHE_WHAT, CACHE_HINT):
            cached = _read_cached(cache_path, cpp_model, waypoints, nodes, t, q0, options, started)
            if cached is not None:
                return cached
    _check_reach(dynamics, symbolic, q0, t, waypoints, nodes, options)
    iterate = _Iterate(*_initial_guess(dynamics, symbolic, q0, t, waypoints, nodes, options))
    # A first solve with a quarter of the substeps finds the solution (or the unreachable
    # waypoint) at a quarter of the cost per iteration; each solve after it starts from the
    # previous one's primal and dual values and takes a few iterations. No solve takes
    # Runge-Kutta steps beyond the stability of the vehicle's fastest mode at the start.
    least = _stable_substeps(dynamics, q0, t, iterate.u[0])
    accurate = max(options.substeps, least)
    substeps = min(accurate, max(2, options.substeps // 4, least))
    penalties = list(PENALTIES)
    iterations, solve_seconds = 0, 0.0
    # The re-simulation mismatch after each accurate solve, its sensitivity to the integrator's
    # tolerance, and whether the plan is given as states (the vehicle open-loop unstable along it).
    history, sensitivity, states_given = [], None, False
    while True:
        iterate = _solve(ca, dynamics, symbolic, q0, t, waypoints, nodes, options, substeps, penalties[0], iterate)
        iterations += iterate.stats["iter_count"]
        solve_seconds += iterate.stats["seconds"]
        missed = _missed_waypoints(symbolic, iterate.q, dynamics, t, iterate.u, waypoints, nodes, options)
        if missed and len(penalties) > 1:  # a larger penalty confirms a miss (or meets the waypoint)
            penalties.pop(0)
            continue
        if substeps < accurate:  # the accurate solve, also to confirm a miss
            substeps = accurate
            continue
        if len(missed) > 1:  # which one is out of reach: meet the earlier ones first
            iterate = _solve(ca, dynamics, symbolic, q0, t, waypoints, nodes, options, substeps, penalties[0],
                             iterate, ordered=True)
            missed = _missed_waypoints(symbolic, iterate.q, dynamics, t, iterate.u, waypoints, nodes, options) or missed
        if missed:
            raise _unreachable(missed, waypoints, options)
        inputs = _input_signal(t, iterate.u)
        resimulated, mismatch = _resimulate(cpp_model, q0, inputs, t, iterate.q, positions)
        if not states_given:
            if mismatch[0] <= options.max_mismatch:
                trajectory, q_nodes = resimulated, iterate.q
                break
            history.append(mismatch[0])
            sensitivity = _sensitivity(cpp_model, q0, inputs, t, resimulated, positions)
            states_given = _unstable(history, sensitivity, options, round(math.log2(16 * accurate / substeps)))
        if states_given:  # the planned states themselves, checked interval by interval
            q_nodes = iterate.q.copy()
            q_nodes[0] = q0  # the plan's constraint X[:, 0] == q0, met to IPOPT's round-off: exactly
            trajectory = _core.Trajectory.from_states(cpp_model, t, q_nodes, inputs)
            if trajectory.max_defect() <= options.max_mismatch:
                break
        if substeps >= 16 * accurate:
            if states_given:
                raise PlanningError(
                    f"the vehicle is open-loop unstable along the plan, and its planned states miss the integration "
                    f"of an interval by up to {trajectory.max_defect():.3g} (the interval from t = "
                    f"{trajectory.max_defect_t():g}) with {substeps} Runge-Kutta steps per interval, more than "
                    f"max_mismatch = {options.max_mismatch:g}: give a smaller interval")
            raise PlanningError(f"the planned states stay {mismatch[0]:.3g} from their re-simulation (at t = "
                                f"{mismatch[1]:g}) with {substeps} Runge-Kutta steps per interval, more than "
                                f"max_mismatch = {options.max_mismatch:g}: give a smaller interval")
        substeps *= 2
    report = FeasibilityReport(
        position_mismatch=mismatch[0], position_mismatch_t=mismatch[1], state_mismatch=mismatch[2],
        waypoint_errors=[], heading_errors=[], speed_errors=[], iterations=iterations,
        solve_seconds=solve_seconds, seconds=0.0, substeps=substeps, intervals=len(t) - 1,
        status=iterate.stats["return_status"], resimulation_sensitivity=sensitivity)
    if states_given:
        report.states_given = True
        report.max_defect, report.max_defect_t = trajectory.max_defect(), trajectory.max_defect_t()
    result = Plan(cpp_model, waypoints, nodes, t, q_nodes, iterate.u, trajectory, report, states_given)
    _check_waypoints(result, options)
    report.seconds = time.perf_counter() - started
    if cache_path is not None:
        _write_cached(cache_path, result)
    return result


def plan_path_change(horizon: _core.RecedingHorizon, t_join: float, waypoints: Sequence[Waypoint],
                     tf: float | None = None, options: PlanOptions | None = None,
                     cache_dir: str | os.PathLike | None = None, *, model=None) -> Plan:
    """Plan a new path for a receding-horizon run, from its desired state where a window starts.

    A path changed under way (docs/planning.md, "A path changed under way"): :func:`plan` runs
    from the horizon's desired state ``horizon.desired_state(t_join)`` (q_d of the chained
    windows at t_join, earlier path changes included) at t0 = t_join, with the horizon's model,
    through `waypoints` to tf. Give the plan's inputs to the horizon
    (``horizon.with_path_change(t_join, result.inputs(hold_until=...))``) or to the online
    controller (``controller.change_path(t_join, ...)``): the windows from the one that starts
    at t_join on follow them, and the desired trajectory continues from q_d(t_join), so it is
    continuous there. The inputs end at tf; the windows of a run to t_end reach up to
    ``update + window`` beyond it, so hold the last inputs that far
    (``result.inputs(hold_until=t_end + update + window)``).

    Parameters
    ----------
    horizon : hinf_cpp.RecedingHorizon
        The receding horizon whose path changes (with its path changes so far).
    t_join : float
        Where the new path joins (s): a window's start t0 + j * update after t0 and after the
        horizon's last path change.
    waypoints : sequence of Waypoint
        The new path's waypoints, their times (given or resolved) after t_join.
    tf : float, optional
        The end of the plan (s; default the last waypoint's time).
    options : PlanOptions, optional
        The planner's settings (default ``PlanOptions()``).
    cache_dir : str or os.PathLike, optional
        The plan cache, as for :func:`plan` (default None: no cache).
    model : hinf_cpp.models.SymbolicModel, optional
        The model to plan with when the horizon's model has no CasADi form of its own (a
        SymbolicModel compiled into the horizon's GeneratedModel); it must have the horizon
        model's numbers of states and inputs. Default: ``horizon.model()``.

    Returns
    -------
    Plan
        The new path from the desired state at t_join: its ``t0`` is t_join and its ``q0`` that
        state; ``inputs()`` are the u_d for the change.

    Raises
    ------
    ValueError
        t_join is not a window's start (the message gives the nearest), not after t0 or after
        the last path change; `model` does not fit the horizon; the plan had to be given as
        states (the vehicle is open-loop unstable along the new path: a path change takes
        inputs only); and as :func:`plan` (bad waypoints or options).
    UnreachableWaypointError
        A ValueError: a waypoint cannot be reached from the desired state at t_join.
    PlanningError
        As :func:`plan`.

    Examples
    --------
    Figure 1's ship (``paper_fig1``) leaves its S-curve at t = 10 s for a waypoint to the
    north:

    >>> from hinf_cpp.planning import PlanOptions, Waypoint, plan_path_change
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
    >>> new_path = plan_path_change(horizon, 10.0, [Waypoint(6.0, 16.0, t=25.0)],
    ...                             options=PlanOptions(u_min=(0.0, -0.5), u_max=(2.0, 0.5)))
    >>> bool(np.array_equal(new_path.q0, horizon.desired_state(10.0))), new_path.t0, new_path.tf
    (True, 10.0, 25.0)
    >>> changed = horizon.with_path_change(10.0, new_path.inputs(hold_until=25.0 + 1.0 + 10.0))
    >>> q_d = changed.desired_state(25.0)  # [u, v, r, x, y, psi] of the chained windows
    >>> bool(np.hypot(q_d[3] - 6.0, q_d[4] - 16.0) <= 0.05)  # the waypoint, within its tolerance
    True
    >>> plan_path_change(horizon, 10.5, [Waypoint(6.0, 16.0, t=25.0)])
    Traceback (most recent call last):
        ...
    ValueError: t_join = 10.5 s is not a window's start: a path change joins where a window starts, at
    t0 + j * update (t0 = 0 s, update = 1 s); the nearest is 10 s
    """
    t0, update = horizon.t0(), horizon.options().update
    try:
        t_join = float(t_join)
    except (TypeError, ValueError):
        raise ValueError(f"t_join must be a time (s), got {t_join!r}") from None
    if not (math.isfinite(t_join) and t_join > t0):
        raise ValueError(f"t_join = {t_join:.10g} s: a path change joins after the horizon's t0 = {t0:.10g} s, at a "
                         f"window's start t0 + j * update with j >= 1 (update = {update:.10g} s), e.g. "
                         f"{horizon.window_start(1):.10g} s")
    j = horizon.window_at(t_join)
    start = horizon.window_start(j)
    if abs(start - t_join) > 1e-9 * max(1.0, abs(t_join)):  # as RecedingHorizon.with_path_change
        nearest = min(start, horizon.window_start(j + 1), key=lambda s: abs(s - t_join))
        raise ValueError(f"t_join = {t_join:.10g} s is not a window's start: a path change joins where a window "
                         f"starts, at t0 + j * update (t0 = {t0:.10g} s, update = {update:.10g} s); the nearest is "
                         f"{nearest:.10g} s")
    changes = horizon.path_changes()
    if changes and not start > changes[-1][0]:
        raise ValueError(f"t_join = {t_join:.10g} s: a path change joins after the horizon's last one (at "
                         f"{changes[-1][0]:.10g} s); give a later window's start, or change the horizon before that "
                         "change")
    design_model = horizon.model()
    if model is None:
        model = design_model
    else:
        symbolic = symbolic_model(model)
        if (symbolic.n, symbolic.m) != (design_model.n(), design_model.m()):
            raise ValueError(f"model '{symbolic.name}' has {symbolic.n} states and {symbolic.m} inputs, the horizon's "
                             f"model '{design_model.name()}' {design_model.n()} and {design_model.m()}: plan with the "
                             "model of the horizon")
    q_join = np.asarray(horizon.desired_state(start), dtype=float)
    result = plan(model, waypoints, q0=q_join, t0=start, tf=tf, options=options, cache_dir=cache_dir)
    if result.states_given:
        raise ValueError(
            f"the new path from t_join = {start:.10g} s: the vehicle is open-loop unstable along it (its re-simulation "
            f"from the desired state at t_join drifts {result.report.position_mismatch:.3g} away by t = "
            f"{result.report.position_mismatch_t:.10g} s, so the planner gives it as states), and a path change takes "
            "inputs only (the windows integrate them from the desired state at t_join). Plan over a shorter time (an "
            "earlier tf or last waypoint), or along a path where the vehicle is stable (e.g. slower)")
    return result


def default_cache_dir() -> pathlib.Path:
    """The folder where scenario files' plans are cached.

    ``$HINF_CPP_CACHE/plans``, else ``$XDG_CACHE_HOME/hinf_cpp/plans`` or
    ``~/.cache/hinf_cpp/plans``; it is created (mode 0700) when a plan is written. A folder
    that another user owns or that group or others can write is refused, as the compile
    cache's (``hinf_cpp.models.codegen.check_cache_folder``).

    Returns
    -------
    pathlib.Path
        The folder.

    Examples
    --------
    >>> from hinf_cpp.planning import default_cache_dir
    >>> default_cache_dir().name
    'plans'
    """
    if os.environ.get("HINF_CPP_CACHE"):
        return pathlib.Path(os.environ["HINF_CPP_CACHE"]) / "plans"
    base = os.environ.get("XDG_CACHE_HOME") or pathlib.Path.home() / ".cache"
    return pathlib.Path(base) / "hinf_cpp" / "plans"


def _cache_key(F, cpp_model, q0, t0, tf, waypoints, options) -> str:
    """SHA-256 of everything the plan depends on; the dynamics by CasADi's serialization of
    F(t, q, u) (which holds the parameters' values)."""
    content = {"planner": PLANNER_VERSION, "package": _core.__version__, "model": cpp_model.name(),
               "dynamics": F.serialize(), "q0": q0.tolist(), "t0": t0, "tf": tf,
               "waypoints": [dataclasses.asdict(w) for w in waypoints], "options": dataclasses.asdict(options)}
    return hashlib.sha256(json.dumps(content, sort_keys=True).encode()).hexdigest()


def _read_cached(path: pathlib.Path, cpp_model, waypoints, nodes, t, q0, options, started) -> Plan | None:
    """The cached plan, re-simulated (given as states: its intervals integrated) and checked
    again; None if absent, unreadable, of another format, damaged or failing its checks (then it is planned anew and the entry replaced): an entry never makes
    planning fail."""
    try:
        data = json.loads(path.read_text())
        if data.get("format") != CACHE_FORMAT:  # an entry of another layout: planned anew
            return None
        q, u = np.array(data["q"], dtype=float), np.array(data["u"], dtype=float)
        stats = data["stats"]
        iterations, solve_seconds = int(stats["iterations"]), float(stats["solve_seconds"])
        substeps, status = int(stats["substeps"]), str(stats["status"])
        states_given = data["states_given"]
        if not (isinstance(states_given, bool) and np.array_equal(np.array(data["t"]), t)
                and q.shape == (len(t), len(q0)) and u.shape == (len(t), cpp_model.m())
                and np.all(np.isfinite(q)) and np.all(np.isfinite(u))):
            return None
        inputs = _input_signal(t, u)
        if states_given:
            # The check of a plan given as states: the defect of every interval. Its re-simulation
            # from q0 (which drifts away) is not repeated: the numbers of the report are kept.
            kept = stats["resimulation"]
            mismatch = tuple(float(kept[key]) for key in ("position_mismatch", "position_mismatch_t",
                                                          "state_mismatch"))
            sensitivity = float(kept["sensitivity"])
            if not np.array_equal(q[0], q0):
                return None
            trajectory = _core.Trajectory.from_states(cpp_model, t, q, inputs)
            if not trajectory.max_defect() <= options.max_mismatch:  # NaN too
                return None
        else:
            trajectory = _core.Trajectory(cpp_model, q0, inputs, float(t[0]), float(t[-1]))
            mismatch = _mismatch(trajectory, t, q, list(cpp_model.position_indices()))
            sensitivity = None
            if not mismatch[0] <= options.max_mismatch:  # NaN too
                return None
        report = FeasibilityReport(
            position_mismatch=mismatch[0], position_mismatch_t=mismatch[1], state_mismatch=mismatch[2],
            waypoint_errors=[], heading_errors=[], speed_errors=[], iterations=iterations,
            solve_seconds=solve_seconds, seconds=0.0, substeps=substeps, intervals=len(t) - 1, status=status,
            cache_hit=True, resimulation_sensitivity=sensitivity)
        if states_given:
            report.states_given = True
            report.max_defect, report.max_defect_t = trajectory.max_defect(), trajectory.max_defect_t()
        result = Plan(cpp_model, waypoints, nodes, t, q, u, trajectory, report, states_given)
        _check_waypoints(result, options)
    except Exception:  # noqa: BLE001 - whatever is wrong with an entry (its file, its JSON, its numbers), plan anew
        return None
    report.seconds = time.perf_counter() - started
    return result


def _write_cached(path: pathlib.Path, result: Plan) -> None:
    """Keeps the plan (written whole or not at all, replacing a damaged entry) in a folder made
    private (0700); a cache that cannot be written is a warning."""
    r = result.report
    data = {"format": CACHE_FORMAT, "states_given": result.states_given,
            "t": result.t.tolist(), "q": result.q.tolist(), "u": result.u.tolist(),
            "stats": {"iterations": r.iterations, "solve_seconds": r.solve_seconds, "substeps": r.substeps,
                      "status": r.status}}
    if result.states_given:  # the re-simulation from q0, not repeated when read (json keeps inf and NaN)
        data["stats"]["resimulation"] = {"position_mismatch": r.position_mismatch,
                                         "position_mismatch_t": r.position_mismatch_t,
                                         "state_mismatch": r.state_mismatch,
                                         "sensitivity": r.resimulation_sensitivity}
    try:
        make_cache_folder(path.parent, CACHE_WHAT, CACHE_HINT)
        _write_atomically(path, lambda temporary: temporary.write_text(json.dumps(data)))
    except CacheDirectoryError as error:  # its message names the folder and says what to do
        warnings.warn(f"the plan could not be cached: {error}", UserWarning, stacklevel=3)
    except OSError as error:
        warnings.warn(f"the plan could not be cached in {path.parent}: {error.strerror or error} (set HINF_CPP_CACHE "
                      "to a writable folder)", UserWarning, stacklevel=3)


@dataclasses.dataclass
class _Iterate:
    """A point of the optimization: states and inputs at the nodes, and after a solve the
    slacks, the constraints' multipliers (to start the next solve from) and IPOPT's stats."""

    q: np.ndarray
    u: np.ndarray
    slack: np.ndarray | None = None
    duals: np.ndarray | None = None
    stats: dict | None = None


def _check_waypoint(j: int, w: Waypoint, heading: int) -> None:
    if not isinstance(w, Waypoint):
        raise ValueError(f"waypoints[{j}] must be a hinf_cpp.planning.planner.Waypoint, got {type(w).__name__}")
    for name in ("x", "y", "t", "heading", "speed"):
        value = getattr(w, name)
        if value is None and name not in ("x", "y"):
            continue
        if not (isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)):
            raise ValueError(f"waypoints[{j}].{name} must be a finite number, got {value!r}")
    if w.speed is not None and w.speed < 0:
        raise ValueError(f"waypoints[{j}].speed must be >= 0, got {w.speed:g}")
    if w.heading is not None and abs(w.heading) > MAX_HEADING:
        raise ValueError(f"waypoints[{j}].heading = {w.heading:g} rad is too large to compare modulo 2 pi: give it "
                         f"within +-{MAX_HEADING:g} rad (e.g. in [-pi, pi])")
    if w.heading is not None and heading < 0:
        raise ValueError(f"waypoints[{j}] gives a heading, but the model has no heading state (heading_index)")


def _check_reach(F, symbolic: SymbolicModel, q0: np.ndarray, t: np.ndarray, waypoints: list[Waypoint],
                 nodes: list[int], options: PlanOptions) -> None:
    """Raises UnreachableWaypointError for the first waypoint farther from the one before it (the
    start, for the first) than REACH_FACTOR times the distance the vehicle covers in between at
    its top speed. The top speed up to each node: the largest speed over ground of the model
    simulated from q0 with each constant input whose components are at a bound or 0 (3^m of
    them), by classical Runge-Kutta on the time grid. No check where an input is unbounded or a
    simulation leaves the finite numbers (the speed is then not bounded by them)."""
    ca = _casadi()
    n, m = symbolic.n, symbolic.m
    if not (all(map(math.isfinite, options.u_min)) and all(map(math.isfinite, options.u_max))) or 3**m > 729:
        return
    levels = [sorted({low, min(max(0.0, low), high), high}) for low, high in zip(options.u_min, options.u_max)]
    inputs = np.array(list(itertools.product(*levels)), dtype=float).T  # m x K
    count = inputs.shape[1]
    positions = list(symbolic.position_indices)
    step = _build_interval(ca, F, n, m, 4).map(count)
    symbol = ca.SX if F.is_a("SXFunction") else ca.MX
    tk, q, u = symbol.sym("t"), symbol.sym("q", n), symbol.sym("u", m)
    speed = ca.Function("speed", [tk, q, u], [ca.norm_2(F(tk, q, u)[positions])]).map(count)
    states = np.tile(q0.reshape(-1, 1), (1, count))
    top = np.full(len(t), math.inf)  # the top speed up to each node
    fastest = 0.0
    for k in range(len(t)):
        if k > 0:
            states = np.asarray(step(t[k - 1], t[k] - t[k - 1], states, inputs, inputs))
        speeds = np.asarray(speed(t[k], states, inputs)).ravel()
        if not (np.all(np.isfinite(states)) and np.all(np.isfinite(speeds))):
            break  # no bound from here on
        fastest = top[k] = max(fastest, float(np.max(speeds)))
    before, start, tolerances = tuple(q0[positions]), t[0], options.tolerance
    for j, (w, k) in enumerate(zip(waypoints, nodes)):
        distance = math.hypot(w.x - before[0], w.y - before[1]) - tolerances
        covered = top[k] * (w.t - start)
        if distance > REACH_FACTOR * covered:
            origin = "the start" if j == 0 else f"waypoints[{j - 1}]"
            raise UnreachableWaypointError(
                f"waypoints[{j}] {w.describe()} cannot be reached with {_bounds_text(options)} by t = {w.t:g}: it is "
                f"{distance:.4g} from {origin} (x = {before[0]:g}, y = {before[1]:g}) at t = {start:g} (beyond the "
                f"tolerances), {distance / (w.t - start):.4g} per s, more than {REACH_FACTOR:g} times the vehicle's "
                f"top speed with constant inputs at the bounds ({top[k]:.4g}; found before optimizing). Give it more "
                "time, move it, or widen the input bounds",
                j, (distance - covered) / options.tolerance)
        before, start, tolerances = (w.x, w.y), w.t, 2 * options.tolerance


def _dynamics_function(ca, symbolic: SymbolicModel):
    """F(t, q, u) = f + G u with the model's parameters at their values."""
    rhs = symbolic.f + ca.mtimes(symbolic.G, symbolic.u)
    values = ca.DM([symbolic.parameter_values[name] for name in symbolic.parameter_names])
    F = ca.Function("F", [symbolic.t, symbolic.q, symbolic.u, symbolic.p], [rhs])
    t, q, u = ca.SX.sym("t"), ca.SX.sym("q", symbolic.n), ca.SX.sym("u", symbolic.m)
    try:
        return ca.Function("F", [t, q, u], [F(t, q, u, values)])
    except RuntimeError:  # MX-only operations: keep the function as it is
        t, q, u = ca.MX.sym("t"), ca.MX.sym("q", symbolic.n), ca.MX.sym("u", symbolic.m)
        return ca.Function("F", [t, q, u], [F(t, q, u, values)])


def _build_interval(ca, F, n: int, m: int, substeps: int):
    """The state at the end of an interval [t0, t0 + h]: `substeps` classical Runge-Kutta steps
    with u linear from u0 to u1, evaluated at each stage's time (so exactly the "linear" table)."""
    symbol = ca.SX if F.is_a("SXFunction") else ca.MX
    t0, h = symbol.sym("t0"), symbol.sym("h")
    x0, u0, u1 = symbol.sym("x0", n), symbol.sym("u0", m), symbol.sym("u1", m)
    step = h / substeps
    x = x0
    for j in range(substeps):
        a, b, c = j / substeps, (j + 0.5) / substeps, (j + 1) / substeps
        k1 = F(t0 + a * h, x, u0 + a * (u1 - u0))
        k2 = F(t0 + b * h, x + step / 2 * k1, u0 + b * (u1 - u0))
        k3 = F(t0 + b * h, x + step / 2 * k2, u0 + b * (u1 - u0))
        k4 = F(t0 + c * h, x + step * k3, u0 + c * (u1 - u0))
        x = x + step / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return ca.Function("interval", [t0, h, x0, u0, u1], [x])


def _moves_where_it_points(F, symbolic: SymbolicModel, q0: np.ndarray, t0: float, scale) -> bool:
    """Whether the input that accelerates the position most (d^2 p/dt^2 per input, times its
    scale) pushes along the heading (cos psi, sin psi): a vehicle that goes where it points (the
    ship's surge force, the hovercraft's thrust), whose heading is then guessed along the path.
    Not so for the VTOL, whose thrust is across its roll angle."""
    ca = _casadi()
    positions, heading = list(symbolic.position_indices), symbolic.heading_index
    t, q, u = ca.SX.sym("t"), ca.SX.sym("q", symbolic.n), ca.SX.sym("u", symbolic.m)
    rhs = F(t, q, u)
    acceleration = ca.mtimes(ca.jacobian(rhs[positions], q), rhs)  # d^2 p/dt^2
    per_input = ca.Function("a", [t, q, u], [ca.jacobian(acceleration, u)])
    effect = np.asarray(per_input(t0, q0, np.zeros(symbolic.m))) * np.asarray(scale)  # 2 x m
    strongest = effect[:, int(np.argmax(np.linalg.norm(effect, axis=0)))]
    size = np.linalg.norm(strongest)
    along = np.array([math.cos(q0[heading]), math.sin(q0[heading])])
    return bool(size > 0 and abs(strongest @ along) >= 0.99 * size)


def _initial_guess(F, symbolic: SymbolicModel, q0: np.ndarray, t: np.ndarray, waypoints: list[Waypoint],
                   nodes: list[int], options: PlanOptions) -> tuple[np.ndarray, np.ndarray]:
    """States: q0 everywhere but the position, straight from waypoint to waypoint in time (held
    after the last), and for a vehicle that goes where it points the heading along that
    polyline. Inputs: 0, or the bound nearest to it."""
    positions, heading = list(symbolic.position_indices), symbolic.heading_index
    times = np.concatenate([[t[0]], [w.t for w in waypoints]])
    xs = np.concatenate([[q0[positions[0]]], [w.x for w in waypoints]])
    ys = np.concatenate([[q0[positions[1]]], [w.y for w in waypoints]])
    q = np.tile(q0, (len(t), 1))
    q[:, positions[0]] = np.interp(t, times, xs)
    q[:, positions[1]] = np.interp(t, times, ys)
    if heading >= 0 and _moves_where_it_points(F, symbolic, q0, float(t[0]), options.input_scale):
        directions = np.unwrap(np.arctan2(np.diff(ys), np.diff(xs)))
        # Start within pi of the initial heading, and keep each leg's direction from its start.
        directions += 2 * math.pi * round((q0[heading] - directions[0]) / (2 * math.pi))
        leg = np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(directions) - 1)
        q[1:, heading] = directions[leg[1:]]
    u = np.clip(np.zeros((len(t), symbolic.m)), options.u_min, options.u_max)
    return q, u


def _solve(ca, F, symbolic: SymbolicModel, q0: np.ndarray, t: np.ndarray, waypoints: list[Waypoint],
           nodes: list[int], options: PlanOptions, substeps: int, penalty: float, start: _Iterate,
           ordered: bool = False) -> _Iterate:
    """One IPOPT solve of the multiple-shooting problem from `start` (warm with its multipliers)."""
    n, m, count = symbolic.n, symbolic.m, len(t) - 1
    positions, heading = list(symbolic.position_indices), symbolic.heading_index
    h = np.diff(t)
    opti = ca.Opti()
    X, U = opti.variable(n, count + 1), opti.variable(m, count + 1)
    interval = _build_interval(ca, F, n, m, substeps).map(count)
    opti.subject_to(X[:, 0] == q0)
    opti.subject_to(X[:, 1:] == interval(t[:-1].reshape(1, -1), h.reshape(1, -1), X[:, :-1], U[:, :-1], U[:, 1:]))
    for i in range(m):
        low, high = options.u_min[i], options.u_max[i]
        if math.isfinite(low) and math.isfinite(high):
            opti.subject_to(opti.bounded(low, U[i, :], high))
        elif math.isfinite(low):
            opti.subject_to(U[i, :] >= low)
        elif math.isfinite(high):
            opti.subject_to(U[i, :] <= high)

    # Cost: the exact integrals of the piecewise linear u / s squared and of its slope squared.
    scaled = U / np.asarray(options.input_scale).reshape(-1, 1)
    a, b = scaled[:, :-1], scaled[:, 1:]
    effort = ca.sum2(ca.sum1(a * a + a * b + b * b) * (h / 3.0).reshape(1, -1))
    rate = ca.sum2(ca.sum1((b - a) ** 2) * (1.0 / h).reshape(1, -1))

    # The waypoint conditions, each relaxed by a slack >= 0 that the penalty drives to 0 where
    # it can. The optimizer aims 10 max_mismatch inside each tolerance, so that the re-simulated
    # trajectory, within max_mismatch of the planned one, is inside it.
    # The slacks are in units of the tolerance, and the penalty is linear in them (an L1 penalty
    # on the distance beyond the tolerance): a compromise puts the miss on the waypoint that
    # cannot be reached instead of spreading it over its neighbours.
    margin = 10.0 * options.max_mismatch
    conditions = []  # (left, right as a function of the slack, the slack's weight): left <= right(slack)
    for j, (w, k) in enumerate(zip(waypoints, nodes)):
        # Earlier waypoints weigh more: a compromise misses the later end of a chain that cannot
        # be met, so the first miss names the waypoint out of reach. Mildly (twice as much for
        # the first as for the last) while planning, which keeps IPOPT fast; strongly (1000
        # times) to name the culprit once a miss is certain, as reaching further ahead at one
        # waypoint can bring the next one closer by more.
        share = (len(waypoints) - 1 - j) / max(1, len(waypoints) - 1)
        weight = 1000.0**share if ordered else 1.0 + share
        tolerance = options.tolerance - margin
        distance2 = ((X[positions[0], k] - w.x) ** 2 + (X[positions[1], k] - w.y) ** 2) / tolerance**2
        conditions.append((distance2, lambda s: (1.0 + s) ** 2, weight))
        if w.heading is not None:
            tolerance = options.heading_tolerance - min(margin, 0.5 * options.heading_tolerance)
            off = (1.0 - ca.cos(X[heading, k] - w.heading)) / (1.0 - math.cos(tolerance))
            conditions.append((off, lambda s: 1.0 + s, weight))
        if w.speed is not None:
            tolerance = options.speed_tolerance - min(margin, 0.5 * options.speed_tolerance)
            speed2 = ca.sumsqr(F(t[k], X[:, k], U[:, k])[positions])
            conditions.append((speed2 / (w.speed + tolerance) ** 2, lambda s: 1.0 + s, weight))
            if w.speed > tolerance:
                conditions.append((1.0 - speed2 / (w.speed - tolerance) ** 2, lambda s: s, weight))
    slack = opti.variable(len(conditions))
    opti.subject_to(slack >= 0)
    for i, (left, right, _) in enumerate(conditions):
        opti.subject_to(left <= right(slack[i]))
    weights = np.array([weight for _, _, weight in conditions])
    opti.minimize(options.effort_weight * effort + options.rate_weight * rate
                  + penalty * ca.dot(weights, slack))

    opti.set_initial(X, start.q.T)
    opti.set_initial(U, start.u.T)
    opti.set_initial(slack, 0.0 if start.slack is None else start.slack)
    ipopt = {"print_level": 0, "sb": "yes", "max_iter": options.max_iterations, "tol": 1e-9,
             "constr_viol_tol": 1e-10, "acceptable_iter": 0}
    if start.duals is not None:  # next to the solution: start there, with a small barrier
        opti.set_initial(opti.lam_g, start.duals)
        ipopt.update(warm_start_init_point="yes", mu_init=1e-6, warm_start_bound_push=1e-9,
                     warm_start_mult_bound_push=1e-9)
    # Evaluation warnings (a trial step where the model overflows) are IPOPT's business: it
    # backs off; they are not the user's.
    opti.solver("ipopt", {"print_time": False, "show_eval_warnings": False}, ipopt)
    advice = ("Give the waypoints more time, an interval that resolves the manoeuvres, or (if it ran out) "
              "more max_iterations")
    started = time.perf_counter()
    # CasADi writes its warnings to Python's sys.stderr; they are held until the solve ends and
    # written then, but for the one it prints when Ctrl-C stops IPOPT (the command then says
    # "interrupted" in one line). Only on the main thread, where Ctrl-C arrives: sys.stderr is
    # the process's, and another thread's swap would interleave with this one's.
    held = io.StringIO()
    main_thread = threading.current_thread() is threading.main_thread()
    try:
        with contextlib.redirect_stderr(held) if main_thread else contextlib.nullcontext():
            solution = opti.solve()
    except RuntimeError:  # Opti raises when IPOPT does not succeed; its stats say why
        if _core.interrupt_requested():
            # Ctrl-C: CasADi takes Python's KeyboardInterrupt and stops IPOPT with an exception
            # of its own; the request the core's SIGINT handler recorded says it was the user.
            _core.clear_interrupt()
            raise KeyboardInterrupt from None
        sys.stderr.write(held.getvalue())
        stats = opti.stats()
        raise PlanningError(f"the planner's optimizer (IPOPT) stopped without a solution: "
                            f"{stats.get('return_status', 'unknown status')} after {stats.get('iter_count', 0)} "
                            f"iterations. {advice}") from None
    sys.stderr.write(held.getvalue())
    stats = dict(solution.stats(), seconds=time.perf_counter() - started)
    return _Iterate(q=np.asarray(solution.value(X)).reshape(n, count + 1).T,
                    u=np.asarray(solution.value(U)).reshape(m, count + 1).T,
                    slack=np.atleast_1d(solution.value(slack)), duals=np.asarray(solution.value(opti.lam_g)),
                    stats=stats)


def _bounds_text(options: PlanOptions) -> str:
    parts = [f"u{i + 1} in [{low:g}, {high:g}]" for i, (low, high) in enumerate(zip(options.u_min, options.u_max))
             if math.isfinite(low) or math.isfinite(high)]
    return "the input bounds " + ", ".join(parts) if parts else "unbounded inputs"


def _missed_waypoints(symbolic: SymbolicModel, q: np.ndarray, F, t: np.ndarray, u: np.ndarray,
                      waypoints: list[Waypoint], nodes: list[int], options: PlanOptions) -> list[tuple]:
    """(index, what, miss in tolerances, text) of each waypoint condition the plan misses."""
    positions, heading = list(symbolic.position_indices), symbolic.heading_index
    missed = []
    for j, (w, k) in enumerate(zip(waypoints, nodes)):
        distance = math.hypot(q[k, positions[0]] - w.x, q[k, positions[1]] - w.y)
        if distance > options.tolerance:
            missed.append((j, distance / options.tolerance, f"{distance:.4g} away (tolerance {options.tolerance:g})"))
        if w.heading is not None:
            error = abs(_core.wrap_angle(q[k, heading] - w.heading))
            if error > options.heading_tolerance:
                missed.append((j, error / options.heading_tolerance,
                               f"with a heading {error:.4g} rad off (tolerance {options.heading_tolerance:g})"))
        if w.speed is not None:
            speed = float(np.linalg.norm(np.asarray(F(t[k], q[k], u[k])).ravel()[positions]))
            if abs(speed - w.speed) > options.speed_tolerance:
                missed.append((j, abs(speed - w.speed) / options.speed_tolerance,
                               f"at a speed of {speed:.4g} (tolerance {options.speed_tolerance:g})"))
    return missed


def _unreachable(missed: list[tuple], waypoints: list[Waypoint], options: PlanOptions) -> UnreachableWaypointError:
    """The error for the first miss: the waypoint that cannot be reached after the ones before it."""
    j, miss, text = missed[0]
    w = waypoints[j]
    others = f" ({len(missed) - 1} later waypoint condition(s) missed too)" if len(missed) > 1 else ""
    return UnreachableWaypointError(
        f"waypoints[{j}] {w.describe()} cannot be reached with {_bounds_text(options)} by t = {w.t:g}: the best "
        f"plan comes {text}{others}. Give it more time, move it, or widen the input bounds", j, miss)


def _mismatch(trajectory: _core.Trajectory, t: np.ndarray, q: np.ndarray, positions: list[int]):
    """(max position distance, its time, max state difference) of planned and re-simulated states."""
    resimulated = np.array([trajectory.q_d(float(tk)) for tk in t])
    distance = np.hypot(*(resimulated[:, positions] - q[:, positions]).T)
    k = int(np.argmax(distance))
    return float(distance[k]), float(t[k]), float(np.max(np.abs(resimulated - q)))


def _stable_substeps(F, q0: np.ndarray, t: np.ndarray, u0: np.ndarray) -> int:
    """The fewest Runge-Kutta steps per interval that keep the step h on the longest interval
    within RK4_STEP / rho, rho the spectral radius of d(f + G u)/dq at (t0, q0, u0). Beyond the
    stability region of the classical Runge-Kutta method (-2.79 on the real axis, +-2.83i on
    the imaginary) the discrete plan's fast modes grow from step to step and IPOPT fails (the
    paper's ship, rho = 1.73 /s, on a 300 s horizon: 5 s intervals in 2 steps, "Restoration
    failed")."""
    ca = _casadi()
    symbol = ca.SX if F.is_a("SXFunction") else ca.MX
    q = symbol.sym("q", len(q0))
    jacobian = ca.Function("A", [q], [ca.jacobian(F(float(t[0]), q, ca.DM(u0)), q)])
    A = np.asarray(jacobian(q0), dtype=float)
    rho = float(np.max(np.abs(np.linalg.eigvals(A)))) if np.all(np.isfinite(A)) else 0.0
    return max(1, math.ceil(float(np.max(np.diff(t))) * rho / RK4_STEP - 1e-9))


def _resimulate(cpp_model, q0: np.ndarray, inputs: _core.VectorSignal, t: np.ndarray, q: np.ndarray,
                positions: list[int], options: _core.TrajectoryOptions | None = None):
    """The model integrated from q0 with the planned inputs over the nodes, and its mismatch
    (_mismatch) to the planned states q; (None, (inf, NaN, inf)) when the integration fails or
    leaves the finite numbers (an open-loop-unstable vehicle may diverge so far)."""
    try:
        trajectory = _core.Trajectory(cpp_model, q0, inputs, float(t[0]), float(t[-1]),
                                      *([] if options is None else [options]))
        mismatch = _mismatch(trajectory, t, q, positions)
    except _core.SolverError:
        return None, (math.inf, math.nan, math.inf)
    if not all(math.isfinite(value) for value in (mismatch[0], mismatch[2])):
        return None, (math.inf, math.nan, math.inf)
    return trajectory, mismatch


def _sensitivity(cpp_model, q0: np.ndarray, inputs: _core.VectorSignal, t: np.ndarray,
                 resimulated: _core.Trajectory | None, positions: list[int]) -> float:
    """Max over the nodes of the distance between the positions of the re-simulation (rtol
    1e-10) and of one at STRICT_RTOL: an estimate of the re-simulation's own error, grown along
    the plan; inf when either integration failed."""
    if resimulated is None:
        return math.inf
    options = _core.TrajectoryOptions()
    options.rtol = STRICT_RTOL
    q = np.array([resimulated.q_d(float(tk)) for tk in t])
    return _resimulate(cpp_model, q0, inputs, t, q, positions, options)[1][0]


def _unstable(history: list[float], sensitivity: float, options: PlanOptions, doublings_left: int) -> bool:
    """Whether the re-simulation mismatch (history: after each accurate solve, all above
    max_mismatch) is the open-loop growth of errors along the plan rather than the plan's
    discretization error, which doubling the substeps would shrink. Either

    - the re-simulation failed, or changes by more than max_mismatch when its integrator's
      tolerance is made 10 times tighter (sensitivity): its own errors, relative 1e-10 at each
      step, grow beyond what it is to check, so no refinement of the plan can pass the check
      (found after the first accurate solve, without solving again; the AUV at 1 m/s);
    - the mismatch is more than 16 times max_mismatch per doubling of the substeps left: even
      falling as a Runge-Kutta error (16 times per doubling) it would still miss at the last
      one, where the planner gave up before (a directionally unstable vessel whose growth,
      about 1e5 along its plan, multiplies the plan's discretization error: 0.18 m with 8
      steps per interval, still 6.4e-6 m with 128); or
    - the mismatch fell by less than SHRINK over the last doubling of the substeps, where a
      classical Runge-Kutta error falls 16 times (a mismatch that grows with the nonlinearity
      can fall fast at first, then stalls on the integrator's amplified error).

    For a stable plan the sensitivity is about 1e-11 m (the shipped planned scenarios) and a
    doubling divides the mismatch by about 16 (the ship's lawnmower: 2.1e-6 to 1.3e-7 m): the
    plan is refined as it always was."""
    if not math.isfinite(history[-1]) or not sensitivity <= options.max_mismatch:
        return True
    if history[-1] > options.max_mismatch * 16.0**doublings_left:
        return True
    return len(history) >= 2 and history[-1] > history[-2] / SHRINK


def _check_waypoints(result: Plan, options: PlanOptions) -> None:
    """Fills the report's waypoint errors from the desired trajectory (what is tracked: the
    re-simulated one, or the one given as states) and raises PlanningError if one is outside
    its tolerance."""
    model, report = result.model, result.report
    positions, heading = list(model.position_indices()), model.heading_index()
    report.waypoint_errors, report.heading_errors, report.speed_errors = [], [], []
    for j, w in enumerate(result.waypoints):
        q = np.asarray(result.trajectory.q_d(w.t))
        report.waypoint_errors.append(float(math.hypot(q[positions[0]] - w.x, q[positions[1]] - w.y)))
        report.heading_errors.append(None if w.heading is None else
                                     float(abs(_core.wrap_angle(q[heading] - w.heading))))
        if w.speed is None:
            report.speed_errors.append(None)
        else:
            u = np.asarray(result.trajectory.u_d(w.t))
            velocity = (np.asarray(model.f(w.t, q)) + np.asarray(model.G(w.t, q)) @ u)[positions]
            report.speed_errors.append(float(abs(np.linalg.norm(velocity) - w.speed)))
        for name, errors, tolerance in (("position", report.waypoint_errors, options.tolerance),
                                        ("heading", report.heading_errors, options.heading_tolerance),
                                        ("speed", report.speed_errors, options.speed_tolerance)):
            if errors[j] is not None and errors[j] > tolerance:
                what = "desired trajectory (given as states)" if result.states_given else "re-simulated trajectory"
                raise PlanningError(f"waypoints[{j}] {w.describe()}: the {what} misses its {name} "
                                    f"by {errors[j]:.4g}, more than the tolerance {tolerance:g}")
