"""Figures of runs, drawn on matplotlib Figure objects (no pyplot, no display needed).

Every function takes one :class:`RunResult` or a list of ``(label, RunResult)`` pairs (the
runs of a comparison, overlaid) and returns a :class:`matplotlib.figure.Figure`; save it
with :func:`save_figure` (PNG, or vector PDF / SVG from the file name's suffix).

Line styles of overlaid runs: colour by law (hinf blue, lqr orange, cascade green) and a
marker by law (hinf circles, lqr squares, cascade triangles) at sparse intervals, shifted per
run, so that runs whose lines coincide stay distinguishable; paths dashed for state feedback
and dash-dotted for output feedback, time series by law (hinf solid, lqr dashed, cascade
dash-dotted; backstepping, where the library has it: purple diamonds, dotted); the desired path
is solid black. A run that did not complete (diverged,
lost_track) is dotted, an x marks its last point, and its status is in its label.

x-y panels are sized to their data: equal scale on both axes, limits from the data with a
margin (the axes box takes the data's shape instead of padding it with empty space). With
``marine=True`` they follow the marine convention, North up and East right: for the ship x is
North and y is East, so y is drawn horizontally and x vertically.
"""

from __future__ import annotations

import math
import pathlib
from typing import Sequence, Union

import numpy as np
from matplotlib.figure import Figure

from hinf_cpp import _core
from hinf_cpp.output.tables import run_key
from hinf_cpp.output.files import atomic_output

__all__ = [
    "controls_figure",
    "coupling_figure",
    "eigenvalues_figure",
    "errors_figure",
    "paths_figure",
    "position_error",
    "recovery_figure",
    "save_figure",
    "xy_figure",
]

Runs = Union[_core.RunResult, Sequence[tuple[str, _core.RunResult]]]

_LAW_COLOURS = {_core.Law.hinf: "tab:blue", _core.Law.lqr: "tab:orange", _core.Law.cascade: "tab:green"}
_LAW_COLOURS_OUTPUT = {_core.Law.hinf: "#0b2e73", _core.Law.lqr: "#9c4200", _core.Law.cascade: "#145214"}
_OTHER_COLOURS = ["tab:red", "tab:brown", "tab:pink", "tab:olive", "tab:cyan", "tab:gray"]
_LAW_MARKERS = {_core.Law.hinf: "o", _core.Law.lqr: "s", _core.Law.cascade: "^"}
_OTHER_MARKERS = ["v", "P", "X", "*", "h", "p"]
_LAW_DASHES = {_core.Law.hinf: "-", _core.Law.lqr: "--", _core.Law.cascade: "-."}
if hasattr(_core.Law, "backstepping"):  # the second ship baseline, where the library has it
    _LAW_COLOURS[_core.Law.backstepping] = "tab:purple"
    _LAW_COLOURS_OUTPUT[_core.Law.backstepping] = "#4b2673"
    _LAW_MARKERS[_core.Law.backstepping] = "D"
    _LAW_DASHES[_core.Law.backstepping] = ":"
# Markers per line: evenly spaced in time (time series) or in arc length (paths), each run's
# shifted by a share of the spacing so that coinciding lines do not stack them.
_MARKS = 14
# The margin of an x-y panel around its data, a fraction of the data's larger side.
_XY_MARGIN = 0.06


def _runs(runs: Runs) -> list[tuple[str, _core.RunResult]]:
    if isinstance(runs, _core.RunResult):
        return [(run_key(runs.law, runs.output_feedback), runs)]
    out = list(runs)
    if not out:
        raise ValueError("no run to plot")
    for item in out:
        if not (isinstance(item, tuple) and len(item) == 2 and isinstance(item[1], _core.RunResult)):
            raise ValueError("runs must be a RunResult or a list of (label, RunResult) pairs")
    return out


def _completed(result: _core.RunResult) -> bool:
    return result.simulation.status == _core.RunStatus.completed


def _run_label(label: str, result: _core.RunResult) -> str:
    """The label, with the run's status when it did not complete ("lqr (diverged)")."""
    return label if _completed(result) else f"{label} ({result.simulation.status.name})"


def _styles(runs: list[tuple[str, _core.RunResult]]) -> list[dict]:
    """Per run: colour by law (a darker shade for output feedback); ``ls`` for paths: dashed for
    state feedback, dash-dotted for output feedback, dotted for a run that did not complete;
    ``dash`` for time series by law; ``marker`` by law; ``shift`` the run's shift of its markers,
    a share of their spacing."""
    styles, spare, spare_markers = [], iter(_OTHER_COLOURS * 4), iter(_OTHER_MARKERS * 4)
    for i, (_, result) in enumerate(runs):
        palette = _LAW_COLOURS_OUTPUT if result.output_feedback else _LAW_COLOURS
        colour = palette.get(result.law) or next(spare)
        path_ls = "-." if result.output_feedback else "--"
        styles.append({"color": colour, "ls": path_ls if _completed(result) else ":",
                       "dash": _LAW_DASHES.get(result.law, ":"),
                       "marker": _LAW_MARKERS.get(result.law) or next(spare_markers),
                       "shift": i / len(runs),
                       "output": bool(result.output_feedback)})
    # Two runs with the same law and mode (e.g. two scenarios) get distinct colours and markers.
    seen, seen_styles = set(), set()
    for style in styles:
        if style["color"] in seen:
            style["color"] = next(spare)
        seen.add(style["color"])
        if (style["marker"], style["dash"]) in seen_styles:
            style["marker"] = next(spare_markers)
        seen_styles.add((style["marker"], style["dash"]))
    return styles


def _path_style(style: dict, h: np.ndarray, v: np.ndarray) -> dict:
    """Keyword arguments of an x-y path's line: colour, line style, markers evenly spaced in arc
    length (not at the start, which has its own mark)."""
    every = _arrow_indices(h, v, _MARKS + 1, offset=style["shift"])[1:]
    return {"color": style["color"], "ls": style["ls"], "marker": style["marker"], "markevery": list(every),
            "ms": 5, "mec": "white", "mew": 0.6}


def _series_style(style: dict, points: int) -> dict:
    """Line style of a time plot of `points` samples: by law (solid, dashed, dash-dotted) with
    markers evenly spaced in time; output-feedback runs (noisy) thinner, lighter, below."""
    step = max(1, points // _MARKS)
    every = list(range(int(style["shift"] * step), points, step))
    common = {"color": style["color"], "ls": style["dash"], "marker": style["marker"], "markevery": every, "ms": 4}
    if style["output"]:
        return {**common, "lw": 0.8, "alpha": 0.8, "zorder": 2}
    return {**common, "lw": 1.4, "zorder": 3}


def _mark_end(ax, h: np.ndarray, v: np.ndarray, result: _core.RunResult, colour: str) -> None:
    """An x at the last point of a run that did not complete."""
    if not _completed(result) and h.size:
        ax.plot(h[-1], v[-1], "x", color=colour, ms=10, mew=2.2, zorder=8)


def _plane(q: np.ndarray, ix: int, iy: int, marine: bool) -> tuple[np.ndarray, np.ndarray]:
    """(horizontal, vertical) coordinates of positions: (x, y), or (y, x) in the marine
    convention (North up, East right)."""
    q = np.atleast_2d(q)
    return (q[:, iy], q[:, ix]) if marine else (q[:, ix], q[:, iy])


def _plane_labels(ax, length_unit: str, marine: bool) -> None:
    if marine:
        ax.set_xlabel(f"East y [{length_unit}]")
        ax.set_ylabel(f"North x [{length_unit}]")
    else:
        ax.set_xlabel(f"x [{length_unit}]")
        ax.set_ylabel(f"y [{length_unit}]")


def _data_box(points: list[tuple[np.ndarray, np.ndarray]], margin: float = _XY_MARGIN):
    """(h limits, v limits): the data's bounding box (finite points), each side widened by
    `margin` times its larger side, the shorter side at least a fifth of the longer (a
    straight path is not drawn as a strip one line high)."""
    h = np.concatenate([np.asarray(p[0], dtype=float).ravel() for p in points])
    v = np.concatenate([np.asarray(p[1], dtype=float).ravel() for p in points])
    keep = np.isfinite(h) & np.isfinite(v)
    h, v = h[keep], v[keep]
    lo = np.array([h.min(), v.min()])
    hi = np.array([h.max(), v.max()])
    span = hi - lo
    longest = max(float(span.max()), 1e-9 * max(1.0, float(np.abs(np.concatenate([lo, hi])).max())))
    pad = margin * longest
    grow = np.maximum(0.2 * longest - span, 0.0) / 2.0
    lo, hi = lo - grow - pad, hi + grow + pad
    return (float(lo[0]), float(hi[0])), (float(lo[1]), float(hi[1]))


def _fit_to_data(ax, points: list[tuple[np.ndarray, np.ndarray]], margin: float = _XY_MARGIN) -> None:
    """Equal scale, limits from the data with a margin, the axes box in the data's shape."""
    xlim, ylim = _data_box(points, margin)
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal", adjustable="box")


def _view_data(data: list[tuple[np.ndarray, np.ndarray]], results: list[_core.RunResult]):
    """The points an x-y panel of overlaid runs is sized to: the desired path (``data[0]``), the
    completed runs, every run's start, and the points of failed runs within half the longer
    side of that box (a run that diverged or lost track thousands of metres away would
    otherwise shrink the rest to a dot; its label says how far off it ended, an arrow where it
    leaves the panel)."""
    core = [data[0]] + [hv for hv, r in zip(data[1:], results) if _completed(r)]
    core += [(hv[0][:1], hv[1][:1]) for hv in data[1:]]
    failed = [hv for hv, r in zip(data[1:], results) if not _completed(r)]
    if not failed:
        return data
    (h0, h1), (v0, v1) = _data_box(core, 0.0)
    reach = 0.5 * max(h1 - h0, v1 - v0)
    near = []
    for h, v in failed:
        keep = (h >= h0 - reach) & (h <= h1 + reach) & (v >= v0 - reach) & (v <= v1 + reach)
        near.append((h[keep], v[keep]))
    return core + near


def _inside(h: np.ndarray, v: np.ndarray, box) -> np.ndarray:
    (h0, h1), (v0, v1) = box
    return (h >= h0) & (h <= h1) & (v >= v0) & (v <= v1)


def _exit_arrow(ax, h: np.ndarray, v: np.ndarray, box, colour: str) -> None:
    """An arrow where a path that ends outside the panel last leaves it, along its direction."""
    inside = _inside(h, v, box)
    if not inside.any() or inside[-1]:
        return
    k = int(np.flatnonzero(inside)[-1])
    direction = np.array([h[k + 1] - h[k], v[k + 1] - v[k]])  # equal aspect: the same on screen
    direction = direction / max(float(np.hypot(*direction)), 1e-300)
    ax.annotate("", (h[k], v[k]), xytext=tuple(-22.0 * direction), textcoords="offset points",
                arrowprops={"arrowstyle": "-|>", "color": colour, "lw": 1.6}, zorder=9)


def _xy_figsize(points: list[tuple[np.ndarray, np.ndarray]], width: float, extra: float) -> tuple[float, float]:
    """A figure size whose height follows the data's aspect (between 0.45 and 1.3 widths), so
    that the equal-aspect panel fills it: `extra` inches for the title and labels."""
    xlim, ylim = _data_box(points)
    ratio = (ylim[1] - ylim[0]) / (xlim[1] - xlim[0])
    return width, float(np.clip(0.85 * width * ratio + extra, 0.45 * width, 1.3 * width))


def _position_indices(result: _core.RunResult) -> tuple[int, int]:
    indices = result.trajectory.model().position_indices()
    if len(indices) != 2:
        raise ValueError(f"the model '{result.trajectory.model().name()}' has no planar position "
                         "(position_indices() must give two indices) to draw an x-y plot")
    return indices[0], indices[1]


def position_error(result: _core.RunResult) -> np.ndarray:
    """The position error |p - p_d| of a run on its output grid.

    p is the model's planar position (its two ``position_indices()`` states).

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.

    Returns
    -------
    numpy.ndarray, shape (k,)
        The error at the k output times, in the model's unit of length.

    Raises
    ------
    ValueError
        A model without a planar position.

    Examples
    --------
    >>> from hinf_cpp.output.plotting import position_error
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> error = position_error(result)
    >>> error.shape, round(float(error[0]), 4)  # starts 1 m behind and 1 m aside
    ((4001,), 1.4142)
    """
    ix, iy = _position_indices(result)
    q_e = result.simulation.q_e()
    return np.hypot(q_e[:, ix], q_e[:, iy])


def _arrow_indices(x: np.ndarray, y: np.ndarray, count: int, offset: float = 0.0) -> np.ndarray:
    """The start, then ``count - 1`` grid indices evenly spaced in arc length along the path,
    shifted by ``offset`` (a fraction of the spacing, so that overlaid paths do not stack
    their arrows)."""
    if count <= 0:
        return np.zeros(0, dtype=int)
    s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
    if count == 1 or s[-1] <= 0.0:
        return np.zeros(1, dtype=int)
    spacing = s[-1] / count
    targets = spacing * (np.arange(1, count) + (offset % 1.0) - 0.5)
    return np.unique(np.concatenate([[0], np.searchsorted(s, targets)]))


def _heading_arrows(ax, q: np.ndarray, model: _core.Model, count: int, length: float, color: str,
                    offset: float = 0.0, marine: bool = False) -> None:
    heading = model.heading_index()
    if heading < 0 or count <= 0:
        return
    ix, iy = model.position_indices()
    k = _arrow_indices(q[:, ix], q[:, iy], count, offset)
    psi = q[k, heading]
    # The heading's direction (cos psi, sin psi) in (x, y); swapped with the axes in the marine view.
    dx, dy = length * np.cos(psi), length * np.sin(psi)
    h, v = _plane(q[k], ix, iy, marine)
    u, w = (dy, dx) if marine else (dx, dy)
    ax.quiver(h, v, u, w, angles="xy", scale_units="xy", scale=1.0, color=color, width=0.005, headwidth=4,
              headlength=5, zorder=6)


def _window(result: _core.RunResult, t_max: float | None) -> np.ndarray:
    """Rows of the output grid with t <= t_max (all rows for None)."""
    t = np.asarray(result.simulation.t)
    return np.ones(t.size, dtype=bool) if t_max is None else t <= t_max


def _span(paths: list[np.ndarray]) -> float:
    points = np.vstack(paths)
    return float(max(np.ptp(points[:, 0]), np.ptp(points[:, 1]), 1e-9))


def xy_figure(result: _core.RunResult, title: str | None = None, heading_arrows: int = 0,
              length_unit: str = "m", waypoints=(), ax=None, marine: bool = False) -> Figure:
    """The paper's x-y plot of one run: desired path solid, actual path dashed, starts marked.

    Optionally arrows of the heading along the actual path, and the waypoints a desired
    trajectory was planned through (crosses, numbered, and a short line for a waypoint's
    heading).

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.
    title : str, optional
        The title (default: scenario, law and gamma).
    heading_arrows : int, optional
        Arrows of the heading along the actual path (default 0: none).
    length_unit : str, optional
        The unit in the axis labels (the model's unit of length; default ``"m"``).
    waypoints : sequence of hinf_cpp.planning.Waypoint, optional
        The waypoints to mark.
    ax : matplotlib.axes.Axes, optional
        Draw into these axes (their figure is returned) instead of a new figure.
    marine : bool, optional
        The marine convention: North up, East right (y horizontal, x vertical; default False).

    Returns
    -------
    matplotlib.figure.Figure
        The figure: equal scale, limits from the data with a margin.

    Raises
    ------
    ValueError
        A model without a planar position.

    Examples
    --------
    >>> from hinf_cpp.output.plotting import save_figure, xy_figure
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> figure = xy_figure(result, heading_arrows=6)
    >>> figure.axes[0].get_title(), figure.axes[0].get_xlabel()
    ('paper-fig1: hinf, gamma = 5', 'x [m]')
    >>> save_figure(figure, "paper_fig1_xy.png").name
    'paper_fig1_xy.png'
    >>> xy_figure(result, marine=True).axes[0].get_xlabel()  # North up, East right
    'East y [m]'
    """
    ix, iy = _position_indices(result)
    sim = result.simulation
    desired_hv, actual_hv = _plane(sim.q_d, ix, iy, marine), _plane(sim.q, ix, iy, marine)
    data = [desired_hv, actual_hv]
    if waypoints:
        data.append(_plane(np.array([[w.x, w.y] for w in waypoints]), 0, 1, marine))
    if ax is None:
        fig = Figure(figsize=_xy_figsize(data, 6.4, 1.2), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    desired = "planned (desired)" if waypoints else "desired"
    ax.plot(*desired_hv, "-", color="black", lw=1.5, label=desired)
    ax.plot(*actual_hv, ":" if not _completed(result) else "--", color="tab:blue", lw=1.5,
            label=_run_label("actual", result))
    _mark_end(ax, *actual_hv, result, "tab:blue")
    if waypoints:
        _waypoint_marks(ax, waypoints, 0.04 * _span([sim.q_d[:, [ix, iy]]]), marine)
    ax.plot(desired_hv[0][0], desired_hv[1][0], "o", color="black", ms=5, label="desired start")
    ax.plot(actual_hv[0][0], actual_hv[1][0], "s", color="tab:blue", ms=5, label="actual start")
    if heading_arrows > 0:
        length = 0.05 * _span([sim.q[:, [ix, iy]], sim.q_d[:, [ix, iy]]])
        _heading_arrows(ax, sim.q, result.trajectory.model(), heading_arrows, length, "tab:blue", marine=marine)
    _plane_labels(ax, length_unit, marine)
    _fit_to_data(ax, data)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    ax.set_title(title if title is not None else
                 f"{result.scenario_name}: {run_key(result.law, result.output_feedback)}, gamma = {result.gamma:g}")
    return fig


def _waypoint_marks(ax, waypoints, length: float, marine: bool = False) -> None:
    """Crosses at the waypoints, a line along each given heading, and the waypoint's number."""
    def plane(x: float, y: float) -> tuple[float, float]:
        return (y, x) if marine else (x, y)

    h, v = zip(*(plane(w.x, w.y) for w in waypoints))
    ax.plot(h, v, "x", color="tab:red", ms=7, mew=1.6, label="waypoints", zorder=7)
    for j, w in enumerate(waypoints):
        if w.heading is not None:
            end = plane(w.x + length * math.cos(w.heading), w.y + length * math.sin(w.heading))
            start = plane(w.x, w.y)
            ax.plot([start[0], end[0]], [start[1], end[1]], "-", color="tab:red", lw=1.2, zorder=7)
        if len(waypoints) <= 12:
            ax.annotate(str(j), plane(w.x, w.y), textcoords="offset points", xytext=(4, 4), fontsize="x-small",
                        color="tab:red")


def plan_figure(planned_plan, title: str | None = None, length_unit: str = "m", marine: bool = False) -> Figure:
    """A plan (hinf_cpp.planning.planner.Plan) before any tracking: the re-simulated desired path, the
    planned states at the nodes, and the waypoints (``marine``: North up, East right)."""
    model = planned_plan.model
    ix, iy = model.position_indices()
    t = np.linspace(planned_plan.t0, planned_plan.tf, 2001)
    q = np.array([planned_plan.trajectory.q_d(tk) for tk in t])
    desired_hv, nodes_hv = _plane(q, ix, iy, marine), _plane(planned_plan.q, ix, iy, marine)
    data = [desired_hv, nodes_hv, _plane(np.array([[w.x, w.y] for w in planned_plan.waypoints]), 0, 1, marine)]
    fig = Figure(figsize=_xy_figsize(data, 6.4, 1.2), layout="constrained")
    ax = fig.subplots()
    ax.plot(*desired_hv, "-", color="black", lw=1.5, label="desired (re-simulated)")
    ax.plot(*nodes_hv, ".", color="tab:gray", ms=3, label="planned nodes")
    _waypoint_marks(ax, planned_plan.waypoints, 0.04 * _span([q[:, [ix, iy]]]), marine)
    _plane_labels(ax, length_unit, marine)
    _fit_to_data(ax, data)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    ax.set_title(title or f"plan for the {model.name()} model: {len(planned_plan.waypoints)} waypoints")
    return fig


def paths_figure(runs: Runs, title: str | None = None, heading_arrows: int | None = None, ax=None,
                 t_max: float | None = None, legend: bool = True, length_unit: str = "m",
                 marine: bool = False) -> Figure:
    """Overlaid x-y paths of runs of the same desired path.

    The desired path (solid black, its start heading arrowed) and each run's actual path
    (coloured by law, with the law's marker at sparse intervals; dashed, dash-dotted for
    output feedback) with its start marked (square) and ``heading_arrows`` arrows of the
    heading along it (the first at the start). A run that did not complete (diverged,
    lost_track) is dotted, with an x at its last point and its status in its label. The panel
    is sized to the data (equal scale, a margin around the paths).

    Parameters
    ----------
    runs : RunResult or list of (str, RunResult)
        The runs (of the same desired path), labelled.
    title : str, optional
        Default: the scenario name.
    heading_arrows : int, optional
        Arrows per run (0: none); default 5 for up to two runs, fewer (at least 2) for more.
    ax : matplotlib Axes, optional
        Draw into this Axes (its figure is returned) instead of a new figure.
    t_max : float, optional
        Draw only t <= t_max (default: the whole horizon).
    legend : bool
        Draw the legend in the axes.
    length_unit : str
        The unit of x and y in the axis labels (the model's unit of length).
    marine : bool
        The marine convention: North up, East right (y horizontal, x vertical; default False).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Raises
    ------
    ValueError
        No run, runs not given as (label, RunResult) pairs, a model without a planar
        position.

    Examples
    --------
    >>> from hinf_cpp.output.plotting import paths_figure
    >>> from hinf_cpp.analysis import compare
    >>> runs = compare(hc.load_scenario(hc.scenario_path("paper_fig2")), "hinf,lqr").results()
    >>> [label for label, _ in runs]
    ['hinf', 'lqr', 'hinf/output-feedback', 'lqr/output-feedback']
    >>> figure = paths_figure(runs[:2], t_max=20.0)
    >>> figure.axes[0].get_title()
    'paper-fig2: x-y paths (arrows: heading, t <= 20 s)'
    >>> [line.get_marker() for line in figure.axes[0].get_lines() if line.get_label() in ("hinf", "lqr")]
    ['o', 's']
    >>> paths_figure(runs[:2], marine=True).axes[0].get_ylabel()
    'North x [m]'
    """
    runs = _runs(runs)
    first = runs[0][1]
    ix, iy = _position_indices(first)
    model = first.trajectory.model()
    if heading_arrows is None:
        heading_arrows = max(2, min(5, 12 // len(runs)))
    q_d = first.simulation.q_d[_window(first, t_max)]
    paths = [r.simulation.q[_window(r, t_max)] for _, r in runs]
    data = [_plane(q_d, ix, iy, marine)] + [_plane(q, ix, iy, marine) for q in paths]
    view = _data_box(_view_data(data, [r for _, r in runs]))
    if ax is None:
        fig = Figure(figsize=_xy_figsize(_view_data(data, [r for _, r in runs]), 7.2, 1.4), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    length = 0.045 * max(view[0][1] - view[0][0], view[1][1] - view[1][0]) / (1.0 + 2.0 * _XY_MARGIN)
    desired_hv = data[0]
    ax.plot(*desired_hv, "-", color="black", lw=2.0, label="desired", zorder=2)
    ax.plot(desired_hv[0][0], desired_hv[1][0], "o", color="black", ms=6, zorder=5)
    _heading_arrows(ax, q_d, model, 1, length, "black", marine=marine)
    widths = np.linspace(2.4, 1.2, len(runs)) if len(runs) > 1 else [1.6]
    for i, ((label, result), q, hv, style, width) in enumerate(zip(runs, paths, data[1:], _styles(runs), widths)):
        name = _run_label(label, result)
        inside = _inside(*hv, view)
        if not _completed(result) and not inside[-1]:
            # It ends outside the panel: how far, in the label; the arrows on the part inside.
            off = float(position_error(result)[-1])
            name = (f"{label} ({result.simulation.status.name}, ends "
                    f"{f'{off:,.0f}' if off >= 100.0 else f'{off:.3g}'} {length_unit} off the path)")
            q = q[:max(int(np.argmin(inside)), 1)]
        ax.plot(*hv, lw=width, label=name, zorder=3, **_path_style(style, *hv))
        ax.plot(hv[0][0], hv[1][0], "s", color=style["color"], ms=6, zorder=5)
        _mark_end(ax, *hv, result, style["color"])
        _exit_arrow(ax, *hv, view, style["color"])
        _heading_arrows(ax, q, model, heading_arrows, length, style["color"], offset=i / len(runs), marine=marine)
    ax.plot([], [], "o", color="black", ms=6, label="desired start")
    ax.plot([], [], "s", color="gray", ms=6, label="actual start")
    if any(not _completed(r) for _, r in runs):
        ax.plot([], [], "x", color="gray", ms=8, mew=2.0, label="where a failed run stops")
    _plane_labels(ax, length_unit, marine)
    ax.set_xlim(*view[0])
    ax.set_ylim(*view[1])
    ax.set_aspect("equal", adjustable="box")
    ax.grid(True, alpha=0.3)
    if legend:
        ax.legend(loc="best", fontsize="small")
    window = "" if t_max is None else f", t <= {t_max:g} s"
    ax.set_title(title if title is not None else
                 f"{first.scenario_name}: x-y paths (arrows: heading{window})")
    return fig


def errors_figure(runs: Runs, title: str | None = None) -> Figure:
    """Position error |p - p_d| (log scale) and wrapped heading error against time.

    Two panels sharing the time axis (s); the heading error wrap(psi - psi_d) in degrees. Runs
    are told apart by colour, line style and a marker per law at sparse intervals; a run that
    did not complete has its status in its label and an x where it stops.

    Parameters
    ----------
    runs : RunResult or list of (str, RunResult)
        One run, or labelled runs of the same scenario (overlaid).
    title : str, optional
        The title (default: the scenario's name and what is shown).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Raises
    ------
    ValueError
        No run, or a model without a planar position.

    Examples
    --------
    >>> from hinf_cpp.output.plotting import errors_figure
    >>> from hinf_cpp.analysis import compare
    >>> runs = compare(hc.load_scenario(hc.scenario_path("paper_fig2")), "hinf,lqr").results()
    >>> [label for label, _ in runs]
    ['hinf', 'lqr', 'hinf/output-feedback', 'lqr/output-feedback']
    >>> figure = errors_figure(runs)
    >>> [axes.get_ylabel() for axes in figure.axes]
    ['position error |p - p_d| [m]', 'heading error wrap(psi - psi_d) [deg]']
    """
    runs = _runs(runs)
    fig = Figure(figsize=(7.6, 6.0), layout="constrained")
    ax_p, ax_h = fig.subplots(2, 1, sharex=True)
    errors = [position_error(result) for _, result in runs]
    peak = max(float(np.max(e)) for e in errors)
    # Four decades below the peak of the completed runs: a start on the path (error 0) stays
    # readable on a log axis, and a run that diverged does not push the others below the floor.
    completed = [float(np.max(e)) for e, (_, r) in zip(errors, runs) if _completed(r)]
    reference = max(completed) if completed else peak
    floor = 1e-4 * reference if reference > 0.0 else 1e-12
    largest = 0.0
    for (label, result), error, style in zip(runs, errors, _styles(runs)):
        t = result.simulation.t
        ax_p.plot(t, np.maximum(error, floor), label=_run_label(label, result), **_series_style(style, len(t)))
        _mark_end(ax_p, np.asarray(t), np.maximum(error, floor), result, style["color"])
        heading = result.trajectory.model().heading_index()
        if heading >= 0:
            e = np.degrees(result.simulation.q_e()[:, heading])
            largest = max(largest, float(np.max(np.abs(e))))
            ax_h.plot(t, e, label=_run_label(label, result), **_series_style(style, len(t)))
    ax_p.set_yscale("log")
    ax_p.set_ylim(floor, 2.0 * max(peak, floor))
    ax_p.set_ylabel("position error |p - p_d| [m]")
    ax_h.set_ylabel("heading error wrap(psi - psi_d) [deg]")
    if largest > 90.0:
        ax_h.set_yticks(np.arange(-180, 181, 45))
        ax_h.set_ylim(-185, 185)
    ax_h.axhline(0.0, color="black", lw=0.8)
    ax_h.set_xlabel("time t [s]")
    for ax in (ax_p, ax_h):
        ax.grid(True, alpha=0.3)
    ax_p.legend(loc="best", fontsize="small")
    ax_p.set_title(title if title is not None else f"{runs[0][1].scenario_name}: tracking errors")
    return fig


def controls_figure(runs: Runs, title: str | None = None) -> Figure:
    """Each input against time: the desired input u_d (solid black) and the applied ones.

    One panel per input, sharing the time axis (s); the ship's inputs labelled in m/s^2 and
    rad/s^2. Runs are told apart by colour, line style and a marker per law at sparse intervals.

    Parameters
    ----------
    runs : RunResult or list of (str, RunResult)
        One run, or labelled runs of the same scenario (overlaid).
    title : str, optional
        The title (default: the scenario's name and what is shown).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Raises
    ------
    ValueError
        No run.

    Examples
    --------
    >>> from hinf_cpp.output.plotting import controls_figure
    >>> from hinf_cpp.analysis import compare
    >>> runs = compare(hc.load_scenario(hc.scenario_path("paper_fig2")), "hinf,lqr").results()
    >>> [label for label, _ in runs]
    ['hinf', 'lqr', 'hinf/output-feedback', 'lqr/output-feedback']
    >>> figure = controls_figure(runs)
    >>> [axes.get_ylabel() for axes in figure.axes]
    ['u1 [m/s^2]', 'u2 [rad/s^2]']
    """
    runs = _runs(runs)
    first = runs[0][1]
    m = first.simulation.u.shape[1]
    units = ["m/s^2", "rad/s^2"] if isinstance(first.trajectory.model(), _core.ShipModel) else ["-"] * m
    fig = Figure(figsize=(7.6, 2.6 + 2.2 * m), layout="constrained")
    axes = np.atleast_1d(fig.subplots(m, 1, sharex=True))
    for i, ax in enumerate(axes):
        for (label, result), style in zip(runs, _styles(runs)):
            ax.plot(result.simulation.t, result.simulation.u[:, i], label=_run_label(label, result),
                    **_series_style(style, len(result.simulation.t)))
        ax.plot(first.simulation.t, first.simulation.u_d[:, i], "-", color="black", lw=1.8,
                label="desired u_d", zorder=4)
        ax.set_ylabel(f"u{i + 1} [{units[i]}]")
        ax.grid(True, alpha=0.3)
    axes[0].legend(loc="best", fontsize="small")
    axes[-1].set_xlabel("time t [s]")
    axes[0].set_title(title if title is not None else f"{first.scenario_name}: control inputs")
    return fig


def _z_eigenvalues(result: _core.RunResult) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    t = np.asarray(result.simulation.t)
    Z = np.asarray(result.solution.Z(t))
    eig = np.linalg.eigvalsh(0.5 * (Z + np.swapaxes(Z, 1, 2)))
    return t, eig[:, 0], eig[:, -1]


def _has_output_feedback(result: _core.RunResult) -> bool:
    return result.simulation.estimator is not None


def eigenvalues_figure(runs: Runs, title: str | None = None) -> Figure:
    """Smallest and largest eigenvalue of Z(t) of each design, and of Sigma(t), against time.

    One design per distinct gamma; Sigma(t), the filter's, for output-feedback runs. Z(t) is the
    solution of paper eq. (13), Sigma(t) that of the filter equation (36); log scale, against time
    (s).

    Parameters
    ----------
    runs : RunResult or list of (str, RunResult)
        One run, or labelled runs of the same scenario (overlaid).
    title : str, optional
        The title (default: the scenario's name and what is shown).

    Returns
    -------
    matplotlib.figure.Figure
        The figure: one panel, two with output-feedback runs.

    Raises
    ------
    ValueError
        No run.

    Examples
    --------
    >>> from hinf_cpp.output.plotting import eigenvalues_figure
    >>> from hinf_cpp.analysis import compare
    >>> runs = compare(hc.load_scenario(hc.scenario_path("paper_fig2")), "hinf,lqr").results()
    >>> [label for label, _ in runs]
    ['hinf', 'lqr', 'hinf/output-feedback', 'lqr/output-feedback']
    >>> figure = eigenvalues_figure(runs)
    >>> [axes.get_ylabel() for axes in figure.axes]
    ['eigenvalue of Z(t) [-]', 'eigenvalue of Sigma(t) [-]']
    """
    runs = _runs(runs)
    designs, seen = [], set()
    for label, result in runs:
        if result.solution is not None and result.gamma not in seen:
            seen.add(result.gamma)
            designs.append(result)
    filtered = [(label, r) for label, r in runs if _has_output_feedback(r)]
    fig = Figure(figsize=(7.6, 6.0 if filtered else 3.8), layout="constrained")
    axes = np.atleast_1d(fig.subplots(2 if filtered else 1, 1, sharex=True))
    ax_z = axes[0]
    colours = ["tab:blue", "tab:orange", "tab:red", "tab:purple"]
    for result, colour in zip(designs, colours * 4):
        t, lo, hi = _z_eigenvalues(result)
        name = "gamma = inf (LQR)" if math.isinf(result.gamma) else f"gamma = {result.gamma:g}"
        ax_z.plot(t, hi, "-", color=colour, lw=1.5, label=f"lambda_max(Z), {name}")
        ax_z.plot(t, lo, ":", color=colour, lw=1.8, label=f"lambda_min(Z), {name}")
    ax_z.set_yscale("log")
    ax_z.set_ylabel("eigenvalue of Z(t) [-]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    if filtered:
        ax_s = axes[1]
        for (label, result), style in zip(filtered, _styles(filtered)):
            sim = result.simulation
            ax_s.plot(sim.t, sim.estimator.sigma_max_eig, "-", color=style["color"], lw=1.3,
                      label=f"lambda_max(Sigma), {label}")
            ax_s.plot(sim.t, sim.estimator.sigma_min_eig, ":", color=style["color"], lw=1.6,
                      label=f"lambda_min(Sigma), {label}")
        ax_s.set_yscale("log")
        ax_s.set_ylabel("eigenvalue of Sigma(t) [-]")
        ax_s.legend(loc="best", fontsize="small")
    ax_z.legend(loc="best", fontsize="small")
    axes[-1].set_xlabel("time t [s]")
    ax_z.set_title(title if title is not None else
                   f"{runs[0][1].scenario_name}: eigenvalue bounds of Z(t)"
                   + (" and Sigma(t)" if filtered else ""))
    return fig


def coupling_figure(runs: Runs, title: str | None = None) -> Figure:
    """The coupling condition of the output-feedback design: rho(Sigma Z)(t) against gamma^2.

    The spectral radius of Sigma(t) Z(t) of each output-feedback run, against time (s), and
    gamma^2 of each finite design gamma (the condition is rho < gamma^2). State-feedback runs
    are left out.

    Parameters
    ----------
    runs : RunResult or list of (str, RunResult)
        One run, or labelled runs of the same scenario (overlaid).
    title : str, optional
        The title (default: the scenario's name and what is shown).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Raises
    ------
    ValueError
        When no run has output feedback (a scenario without [measurement]).

    Examples
    --------
    >>> from hinf_cpp.output.plotting import coupling_figure
    >>> from hinf_cpp.analysis import compare
    >>> runs = compare(hc.load_scenario(hc.scenario_path("paper_fig2")), "hinf,lqr").results()
    >>> [label for label, _ in runs]
    ['hinf', 'lqr', 'hinf/output-feedback', 'lqr/output-feedback']
    >>> figure = coupling_figure(runs)
    >>> [line.get_label() for line in figure.axes[0].get_lines()]
    ['hinf/output-feedback', 'lqr/output-feedback', 'gamma^2 = 25 (coupling condition rho < gamma^2)']
    """
    runs = [(label, r) for label, r in _runs(runs) if _has_output_feedback(r)]
    if not runs:
        raise ValueError("rho(Sigma Z) needs an output-feedback run (a scenario with [measurement])")
    fig = Figure(figsize=(7.6, 4.2), layout="constrained")
    ax = fig.subplots()
    gammas = set()
    for (label, result), style in zip(runs, _styles(runs)):
        ax.plot(result.simulation.t, result.simulation.estimator.rho_sigma_z, "-", color=style["color"], lw=1.3,
                label=label)
        if math.isfinite(result.gamma):
            gammas.add(result.gamma)
    for gamma in sorted(gammas):
        ax.axhline(gamma**2, color="black", lw=1.2, ls=":",
                   label=f"gamma^2 = {gamma**2:g} (coupling condition rho < gamma^2)")
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel("time t [s]")
    ax.set_ylabel("spectral radius rho(Sigma Z) [-]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    ax.set_title(title if title is not None else f"{runs[0][1].scenario_name}: coupling condition")
    return fig


def recovery_figure(study, columns: int = 3, t_max: float | None = None, marine: bool = False) -> Figure:
    """One panel of overlaid x-y paths per scenario of a recovery study, every law's run drawn.

    Each panel is :func:`paths_figure` of the scenario's runs, labelled by law. A run that did
    not complete (diverged, lost_track) is drawn dotted with an x where it stops and its status
    in the legend (and, when it ends outside the panel, a note where it leaves it); a run that
    failed before its closed loop (a conjugate point, a solver failure) is named in the panel
    with its status. One legend for the figure.

    Parameters
    ----------
    study : hinf_cpp.analysis.RecoveryStudy
        The study (:func:`hinf_cpp.analysis.recovery_study`).
    columns : int, optional
        Panels per row (default 3).
    t_max : float, optional
        The time window drawn (s, absolute); default per panel: the latest settling time of
        its runs plus 5 s (the whole horizon when a run does not settle).
    marine : bool, optional
        The marine convention: North up, East right (y horizontal, x vertical; default False).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Raises
    ------
    ValueError
        A study without scenarios.

    Examples
    --------
    >>> from hinf_cpp.analysis import recovery_study
    >>> from hinf_cpp.output.plotting import recovery_figure
    >>> study = recovery_study([hc.scenario_path("poor_heading_180"), hc.scenario_path("poor_position_ahead")],
    ...                        "hinf,cascade")
    >>> figure = recovery_figure(study, columns=2)
    >>> [axes.get_title() for axes in figure.axes]
    ['poor-heading-180 (t <= 54 s)', 'poor-position-ahead (t <= 25 s)']
    """
    scenarios = study.scenarios
    if not scenarios:
        raise ValueError("the recovery study has no scenario")
    columns = max(1, min(columns, len(scenarios)))
    rows = math.ceil(len(scenarios) / columns)
    fig = Figure(figsize=(4.6 * columns, 4.3 * rows + 0.6), layout="constrained")
    axes = np.atleast_1d(fig.subplots(rows, columns)).ravel()
    legend: dict[str, object] = {}
    for ax, name in zip(axes, scenarios):
        verdicts = [v for v in study.verdicts if v.scenario == name]
        drawn = [v for v in verdicts if v.result is not None]
        no_run = [v for v in verdicts if v.result is None]
        if not drawn:
            ax.set_title(f"{name}: every run failed")
        else:
            window = t_max
            if window is None:
                settling = [v.settling_time for v in drawn]
                if all(s is not None for s in settling):
                    window = max(settling) + 5.0 + float(drawn[0].result.simulation.t[0])
            paths_figure([(v.controller.name, v.result) for v in drawn], heading_arrows=4, ax=ax,
                         t_max=window, legend=False, marine=marine,
                         title=name + ("" if window is None else f" (t <= {window:.0f} s)"))
        if no_run:
            ax.text(0.02, 0.02, "\n".join(f"{v.controller.name}: {v.status}, no run to draw" for v in no_run),
                    transform=ax.transAxes, fontsize="x-small", color="tab:red", va="bottom", ha="left")
        for handle, label in zip(*ax.get_legend_handles_labels()):
            legend.setdefault(label, handle)
    for ax in axes[len(scenarios):]:
        ax.set_visible(False)
    if legend:
        fig.legend(list(legend.values()), list(legend), loc="outside lower center",
                   ncol=min(len(legend), 2 * columns), fontsize="small")
    return fig


def save_figure(fig: Figure, path: str | pathlib.Path) -> pathlib.Path:
    """Save a figure, whole or not at all (:func:`hinf_cpp.output.files.atomic_output`).

    The format is the suffix: .png (150 dpi), .pdf and .svg (vector), or any other format
    matplotlib writes.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : str or pathlib.Path
        The file.

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    ValueError
        A suffix that is not an image format (the message lists the formats), or a path that
        cannot be written (a directory, below a plain file).
    OSError
        The file could not be written (a full disk); the message names the path.

    Examples
    --------
    >>> from hinf_cpp.output.plotting import errors_figure, save_figure
    >>> figure = errors_figure(hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1"))))
    >>> save_figure(figure, "errors.pdf").name
    'errors.pdf'
    >>> save_figure(figure, "errors.txt")
    Traceback (most recent call last):
        ...
    ValueError: figure file 'errors.txt': the suffix must name an image format
    (.png, .pdf, .svg, ...; supported: ...)
    """
    path = pathlib.Path(path)
    formats = fig.canvas.get_supported_filetypes()
    suffix = path.suffix.lower().lstrip(".")
    if suffix not in formats:
        raise ValueError(f"figure file '{path}': the suffix must name an image format "
                         f"(.png, .pdf, .svg, ...; supported: {', '.join(sorted(formats))})")
    with atomic_output(path) as handle:  # whole or not at all
        fig.savefig(handle, format=suffix, dpi=150)
    return path
