"""The gallery of the built-in vehicles (docs/vehicles.md): the shipped scenario of each vehicle
run with state feedback, its gamma*, its x-y figure and a table of the tracking results
(``hinf-cpp vehicles --out DIR``); and the gallery of the shipped planned scenarios
(docs/planning.md): plan, feasibility, waypoints and tracking (``hinf-cpp planned --out DIR``)."""

from __future__ import annotations

import dataclasses
import math
import pathlib

import numpy as np
from matplotlib.figure import Figure

from hinf_cpp import _core
from hinf_cpp.output.files import write_text
from hinf_cpp.output.tables import markdown_table

__all__ = ["PLANNED", "VEHICLES", "PlannedRun", "VehicleRun", "gallery_figure", "gallery_table", "planned_table",
           "run_planned", "run_vehicle", "write_gallery", "write_planned_gallery"]


@dataclasses.dataclass(frozen=True)
class Vehicle:
    label: str  # for tables and titles
    scenario: str  # the shipped scenario (scenarios/<scenario>.toml)
    length_unit: str  # the model's unit of x and y


#: One shipped scenario per built-in vehicle, in the order of docs/vehicles.md.
VEHICLES = [
    Vehicle("Fossen vessel (supply vessel)", "fossen_vessel_turn", "ship lengths L = 76.2 m"),
    Vehicle("hovercraft", "hovercraft_s_curve", "m"),
    Vehicle("planar VTOL", "pvtol_climb", "normalized"),
    Vehicle("AUV (Sirene)", "auv_s_curve", "m"),
]


@dataclasses.dataclass
class VehicleRun:
    """A built-in vehicle's shipped scenario, run with state feedback.

    What :func:`run_vehicle` returns. ``ratio`` is the final over the initial position error.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (an entry of :data:`VEHICLES`: label, scenario, unit of length).
    result : hinf_cpp.RunResult
        The run; its ``gamma_star`` is set (written to the results file).
    gamma_star : float
        gamma* of the scenario's design (paper eq. 14).
    initial_position_error : float
        |p(t0) - p_d(t0)|, in the model's unit of length.
    final_position_error : float
        |p(tf) - p_d(tf)|, in the model's unit of length.

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import VEHICLES, run_vehicle
    >>> run = run_vehicle(VEHICLES[2])  # the planar VTOL
    >>> run.vehicle.label, round(run.gamma_star, 3), round(run.initial_position_error, 3)
    ('planar VTOL', 2.734, 0.707)
    >>> run.ratio < 0.05
    True
    """

    vehicle: Vehicle
    result: _core.RunResult
    gamma_star: float
    initial_position_error: float  # |p(t0) - p_d(t0)|
    final_position_error: float  # |p(tf) - p_d(tf)|

    @property
    def ratio(self) -> float:
        """Final over initial position error."""
        return self.final_position_error / self.initial_position_error


def run_vehicle(vehicle: Vehicle) -> VehicleRun:
    """Run a vehicle's shipped scenario and compute gamma* of its design (paper eq. 14).

    Parameters
    ----------
    vehicle : Vehicle
        An entry of :data:`VEHICLES`.

    Returns
    -------
    VehicleRun
        The run, gamma* and the initial and final position errors.

    Raises
    ------
    hinf_cpp.HinfError
        The run or the gamma* search failed numerically.

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import VEHICLES, run_vehicle
    >>> run = run_vehicle(VEHICLES[2])  # the planar VTOL
    >>> run.result.scenario_name, run.result.gamma
    ('pvtol-climb', 6.0)
    """
    from hinf_cpp.scenario import scenario_path
    from hinf_cpp.scenario import load_scenario

    scenario = load_scenario(scenario_path(vehicle.scenario))
    result = _core.run_scenario(scenario)
    gamma_star = _core.scenario_gamma_star(scenario).gamma_star
    result.gamma_star = gamma_star  # written to the results file
    position = list(result.trajectory.model().position_indices())
    q_e = np.asarray(result.simulation.q_e())[:, position]
    return VehicleRun(vehicle, result, gamma_star, float(np.linalg.norm(q_e[0])),
                      float(result.metrics.final_position_error))


def gallery_table(runs: list[VehicleRun]) -> tuple[list[str], list[list[str]]]:
    """The gallery's table: one row per vehicle, every cell a formatted string.

    Columns: vehicle, scenario, gamma*, gamma, initial and final position error, their
    ratio, the RMS position error over the last half, the unit of length.

    Parameters
    ----------
    runs : list of VehicleRun
        The runs (:func:`run_vehicle`).

    Returns
    -------
    tuple of (list of str, list of list of str)
        The header and the rows (for :func:`hinf_cpp.output.tables.markdown_table`).

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import gallery_table
    >>> from hinf_cpp.analysis.gallery import VEHICLES, run_vehicle
    >>> run = run_vehicle(VEHICLES[2])  # the planar VTOL
    >>> header, rows = gallery_table([run])
    >>> header[:3], rows[0][:3]
    (['vehicle', 'scenario', 'gamma*'], ['planar VTOL', 'pvtol-climb', '2.734'])
    """
    header = ["vehicle", "scenario", "gamma*", "gamma", "initial position error", "final position error",
              "final / initial", "RMS position error, last half", "unit of length"]
    rows = [[run.vehicle.label, run.result.scenario_name, f"{run.gamma_star:.4g}", f"{run.result.gamma:g}",
             f"{run.initial_position_error:.3g}", f"{run.final_position_error:.3g}", f"{run.ratio:.2%}",
             f"{run.result.metrics.rms_position_error_last_half:.3g}", run.vehicle.length_unit]
            for run in runs]
    return header, rows


def gallery_figure(runs: list[VehicleRun]) -> Figure:
    """The x-y paths of every vehicle, one panel each (desired solid, actual dashed).

    Two panels a row, with heading arrows, axes in each vehicle's unit of length.

    Parameters
    ----------
    runs : list of VehicleRun
        The runs (:func:`run_vehicle`).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import gallery_figure
    >>> from hinf_cpp.analysis.gallery import VEHICLES, run_vehicle
    >>> run = run_vehicle(VEHICLES[2])  # the planar VTOL
    >>> figure = gallery_figure([run])
    >>> figure.axes[0].get_title()
    'planar VTOL: pvtol-climb'
    """
    from hinf_cpp.output.plotting import paths_figure

    columns = 2
    rows = math.ceil(len(runs) / columns)
    fig = Figure(figsize=(5.6 * columns, 4.8 * rows), layout="constrained")
    axes = np.atleast_1d(fig.subplots(rows, columns)).ravel()
    for ax, run in zip(axes, runs):
        paths_figure(run.result, ax=ax, heading_arrows=4, length_unit=run.vehicle.length_unit,
                     title=f"{run.vehicle.label}: {run.result.scenario_name}")
    for ax in axes[len(runs):]:
        ax.set_visible(False)
    return fig


def write_gallery(out: str | pathlib.Path, runs: list[VehicleRun]) -> list[pathlib.Path]:
    """Write the vehicle gallery into a folder (``hinf-cpp vehicles --out DIR``).

    Per vehicle ``<scenario>.json`` (the results file, gamma* included), ``<scenario>.csv``
    (the time series) and ``<scenario>_xy.png``; ``vehicles_xy.png`` (all paths,
    :func:`gallery_figure`) and ``metrics.md`` (:func:`gallery_table`). Each file is written
    whole or not at all.

    Parameters
    ----------
    out : str or pathlib.Path
        The folder (created if needed).
    runs : list of VehicleRun
        The runs (:func:`run_vehicle`).

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    ValueError
        A path that cannot be written.
    OSError
        A file could not be written.

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import write_gallery
    >>> from hinf_cpp.analysis.gallery import VEHICLES, run_vehicle
    >>> run = run_vehicle(VEHICLES[2])  # the planar VTOL
    >>> [path.name for path in write_gallery("vehicles", [run])]
    ['pvtol_climb.json', 'pvtol_climb.csv', 'pvtol_climb_xy.png', 'vehicles_xy.png', 'metrics.md']
    """
    from hinf_cpp.output.plotting import save_figure, xy_figure

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for run in runs:
        stem = run.vehicle.scenario
        written.append(write_text(out / f"{stem}.json", _core.results_json(run.result) + "\n"))
        written.append(write_text(out / f"{stem}.csv", _core.results_csv(run.result)))
        figure = xy_figure(run.result, title=f"{run.vehicle.label}: {run.result.scenario_name}, "
                                             f"gamma = {run.result.gamma:g}",
                           heading_arrows=6, length_unit=run.vehicle.length_unit)
        written.append(save_figure(figure, out / f"{stem}_xy.png"))
    written.append(save_figure(gallery_figure(runs), out / "vehicles_xy.png"))
    header, rows = gallery_table(runs)
    text = ("# The built-in vehicles: state-feedback tracking of their shipped scenarios\n\n"
            "Position errors over the model's position components (docs/vehicles.md), in its unit "
            "of length; gamma* of eq. (14) for the scenario's design.\n\n"
            + markdown_table(header, rows) + "\n![x-y paths of the vehicles](vehicles_xy.png)\n")
    written.append(write_text(out / "metrics.md", text))
    return [pathlib.Path(p) for p in written]


# ---- the shipped planned scenarios (docs/planning.md): ``hinf-cpp planned --out DIR`` ----

@dataclasses.dataclass(frozen=True)
class PlannedCase:
    label: str  # for tables and titles
    scenario: str  # the shipped scenario (scenarios/<scenario>.toml)
    length_unit: str


#: The shipped planned scenarios (scenarios/planned), each vehicle with each pattern.
PLANNED = [PlannedCase(f"{vehicle}: {pattern.replace('_', ' ')}", f"planned/{stem}_{pattern}", "m")
           for vehicle, stem in (("ship", "ship"), ("hovercraft", "hovercraft"))
           for pattern in ("lane_change", "figure_eight", "lawnmower", "docking")]


@dataclasses.dataclass
class PlannedRun:
    """A shipped planned scenario, planned and run: what :func:`run_planned` returns.

    Parameters
    ----------
    case : PlannedCase
        The case (an entry of :data:`PLANNED`: label, scenario, unit of length).
    planned : hinf_cpp.scenario.planned.PlannedScenario
        The planned scenario: its plan and feasibility report.
    result : hinf_cpp.RunResult
        The run of the planned scenario.

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import PLANNED, run_planned
    >>> run = run_planned(PLANNED[4], cache=False)  # the hovercraft's lane change
    >>> run.case.label, len(run.planned.plan.waypoints)
    ('hovercraft: lane change', 3)
    >>> run.result.metrics.final_position_error < 0.5
    True
    """

    case: PlannedCase
    planned: object  # hinf_cpp.scenario.planned.PlannedScenario
    result: _core.RunResult


def run_planned(case: PlannedCase, cache: bool = True) -> PlannedRun:
    """Plan a case's shipped scenario (from the cache when it can) and run it.

    Parameters
    ----------
    case : PlannedCase
        An entry of :data:`PLANNED`.
    cache : bool, optional
        Read and keep the plan in :func:`hinf_cpp.planning.default_cache_dir` (default
        True); False plans anew and writes nothing.

    Returns
    -------
    PlannedRun
        The planned scenario and its run.

    Raises
    ------
    hinf_cpp.planning.PlanningError
        The planner failed.
    hinf_cpp.HinfError
        The run failed numerically.

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import PLANNED, run_planned
    >>> run = run_planned(PLANNED[4], cache=False)  # the hovercraft's lane change
    >>> run.result.scenario_name, run.planned.plan.report.cache_hit
    ('planned-hovercraft-lane-change', False)
    """
    from hinf_cpp.scenario import scenario_path
    from hinf_cpp.scenario.planned import load_planned

    planned = load_planned(scenario_path(case.scenario), cache=cache)
    return PlannedRun(case, planned, _core.run_scenario(planned.scenario))


def planned_table(runs: list[PlannedRun]) -> tuple[list[str], list[list[str]]]:
    """The planned gallery's table: one row per scenario, every cell a formatted string.

    The plan's cost and feasibility and the tracking. Columns: scenario, waypoints, intervals x RK4
    steps, IPOPT iterations, planning time ("cached" for a plan from the cache), re-simulation
    mismatch, largest waypoint error, final position error, RMS position error over the last half.

    Parameters
    ----------
    runs : list of PlannedRun
        The runs (:func:`run_planned`).

    Returns
    -------
    tuple of (list of str, list of list of str)
        The header and the rows.

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import planned_table
    >>> from hinf_cpp.analysis.gallery import PLANNED, run_planned
    >>> run = run_planned(PLANNED[4], cache=False)  # the hovercraft's lane change
    >>> header, rows = planned_table([run])
    >>> header[:3], rows[0][:2]
    (['scenario', 'waypoints', 'intervals x RK4 steps'], ['planned-hovercraft-lane-change', '3'])
    """
    header = ["scenario", "waypoints", "intervals x RK4 steps", "IPOPT iterations", "planning time",
              "re-simulation mismatch", "largest waypoint error", "final position error",
              "RMS position error, last half"]
    rows = []
    for run in runs:
        report = run.planned.plan.report
        rows.append([run.result.scenario_name, str(len(run.planned.plan.waypoints)),
                     f"{report.intervals} x {report.substeps}", str(report.iterations),
                     "cached" if report.cache_hit else f"{report.seconds:.2f} s",
                     f"{report.position_mismatch:.1e} m", f"{max(report.waypoint_errors):.3g} m",
                     f"{run.result.metrics.final_position_error:.3g} m",
                     f"{run.result.metrics.rms_position_error_last_half:.3g} m"])
    return header, rows


def write_planned_gallery(out: str | pathlib.Path, runs: list[PlannedRun]) -> list[pathlib.Path]:
    """Write the planned gallery into a folder (``hinf-cpp planned --out DIR``).

    Per scenario ``<name>.json`` (the results file) and ``<name>_xy.png`` (waypoints, planned
    path, tracked path); ``planned_xy.png`` (all of them, four a row) and ``planned.md``
    (:func:`planned_table`). Each file is written whole or not at all.

    Parameters
    ----------
    out : str or pathlib.Path
        The folder (created if needed).
    runs : list of PlannedRun
        The runs (:func:`run_planned`), at least one.

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    ValueError
        A path that cannot be written.
    OSError
        A file could not be written.

    Examples
    --------
    >>> from hinf_cpp.analysis.gallery import write_planned_gallery
    >>> from hinf_cpp.analysis.gallery import PLANNED, run_planned
    >>> run = run_planned(PLANNED[4], cache=False)  # the hovercraft's lane change
    >>> [path.name for path in write_planned_gallery("planned", [run])]
    ['hovercraft_lane_change.json', 'hovercraft_lane_change_xy.png', 'planned_xy.png', 'planned.md']
    """
    from hinf_cpp.output.plotting import save_figure, xy_figure

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    columns = 4
    rows = math.ceil(len(runs) / columns)
    overview = Figure(figsize=(4.6 * columns, 4.0 * rows), layout="constrained")
    axes = np.atleast_1d(overview.subplots(rows, columns)).ravel()
    for ax, run in zip(axes, runs):
        stem = pathlib.Path(run.case.scenario).name
        waypoints = run.planned.plan.waypoints
        written.append(write_text(out / f"{stem}.json", _core.results_json(run.result) + "\n"))
        figure = xy_figure(run.result, title=f"{run.case.label}: planned and tracked", heading_arrows=6,
                           length_unit=run.case.length_unit, waypoints=waypoints)
        written.append(save_figure(figure, out / f"{stem}_xy.png"))
        xy_figure(run.result, title=run.case.label, length_unit=run.case.length_unit, waypoints=waypoints, ax=ax)
        ax.legend().set_visible(False)
    for ax in axes[len(runs):]:
        ax.set_visible(False)
    axes[0].legend(loc="best", fontsize="x-small")
    written.append(save_figure(overview, out / "planned_xy.png"))
    header, table_rows = planned_table(runs)
    text = ("# Planned desired trajectories: planning and tracking\n\n"
            "Each scenario's inputs planned from its waypoints (docs/planning.md); the re-simulation "
            "mismatch is the largest distance between the planned positions and those the project's "
            "integrator re-simulates from the planned inputs; the tracking is the scenario's H-infinity "
            "state feedback from 1.41 m off.\n\n"
            + markdown_table(header, table_rows) + "\n![planned and tracked paths](planned_xy.png)\n")
    written.append(write_text(out / "planned.md", text))
    return [pathlib.Path(p) for p in written]
