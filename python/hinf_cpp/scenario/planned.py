"""Scenario files whose [desired] or [path_change] gives waypoints or a path instead of inputs
(docs/planning.md).

The planner (``hinf_cpp.planning.planner``) turns the waypoints into inputs u_d, which take the place of
the planning keys in [desired] as tables with interpolation = "linear"; the scenario then goes
through the one C++ reader like any other. A [path_change] (a receding-horizon run's path changed
under way) is planned likewise, from the run's desired state at its t
(:func:`hinf_cpp.planning.plan_path_change`), after [desired]. For a vehicle that is open-loop unstable along the
plan, the planned states come too ([desired] states = { t, q } and max_defect = the planner's
max_mismatch): the desired trajectory is then made from the states and inputs, each interval
integrated from its node. Plans are cached by the content of what they depend
on (``hinf_cpp.planning.planner.default_cache_dir``), so running a file again does not optimize again.
``hinf-sim`` does not plan: it refuses these keys and says to run ``hinf-cpp run`` or to write
the planned scenario with ``hinf-cpp plan FILE -o PLANNED.toml`` (:func:`planned_scenario_toml`:
a model compiled from CasADi is copied beside the written file, which never points into a
cache). For example::

    [desired]
    q0 = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    waypoints = [ { x = 20.0, y = 0.0, t = 20.0 },
                  { x = 60.0, y = 3.5, t = 60.0, heading = 0.0 } ]
    # or: path = { x = [...], y = [...], speed = 1.0 }
    [desired.plan]
    u_min = [0.0, -0.5]
    u_max = [2.0, 0.5]
"""

from __future__ import annotations

import contextlib
import copy
import dataclasses
import json
import math
import os
import pathlib
import re
import tomllib
from typing import TYPE_CHECKING

from hinf_cpp import _core
from hinf_cpp.scenario.documents import code_allowed, resolve_callable, toml_text

# Every scenario file is read through this module (load_planned) and most plan nothing: the
# planner (NumPy, the vehicles' CasADi statements) and the compile cache are imported by the
# functions that plan or copy a compiled model.
if TYPE_CHECKING:
    from hinf_cpp.planning.planner import Plan, PlanOptions, Waypoint

__all__ = ["PLANNING_KEYS", "PlannedScenario", "load_planned", "needs_planning", "plan_scenario",
           "planned_scenario_toml"]

#: The keys of [desired] and [path_change] that ask for planning (docs/planning.md).
PLANNING_KEYS = ("waypoints", "path", "plan")
#: The tables that may ask for planning, in the order they are planned ([path_change] starts from
#: the desired trajectory of [desired]).
PLANNED_SECTIONS = ("desired", "path_change")
WAYPOINT_KEYS = ("x", "y", "t", "heading", "speed")
PATH_KEYS = ("x", "y", "speed")
PER_INPUT = ("u_min", "u_max", "input_scale")
INTEGERS = ("substeps", "max_iterations")


@dataclasses.dataclass
class PlannedScenario:
    """A scenario whose desired inputs, or those of its path change, were planned from
    waypoints or a path.

    What :func:`plan_scenario` and :func:`load_planned` return.

    Parameters
    ----------
    scenario : hinf_cpp.Scenario
        The scenario with the planned inputs, as the C++ reader built it.
    plan : hinf_cpp.planning.Plan or None
        The plan of [desired]: inputs, planned and re-simulated states, feasibility report;
        None when [desired] gives its inputs and only [path_change] is planned.
    document : dict
        The scenario file's dictionary with the planned inputs in [desired] and [path_change]
        (``u1``, ``u2``, ...: tables with interpolation = "linear") in place of the planning
        keys, and for a [desired] plan given as states (``plan.states_given``) the planned
        states (``states = {t, q}``) and ``max_defect``; written as TOML it is a scenario
        ``hinf-sim`` runs (``hinf-cpp plan FILE -o PLANNED.toml``). With [receding_horizon]
        the tables hold their last inputs from tf to the end of the last window a run solves
        (``t0 + (j + 1) * update + window``, j the window of tf).
    source : str
        The scenario file (or the name given to a dictionary), for messages.
    path_change_plan : hinf_cpp.planning.Plan or None, optional
        The plan of [path_change] (:func:`hinf_cpp.planning.plan_path_change`: from the run's
        desired state at its t to tf); None (default) when [path_change] is not planned.

    Examples
    --------
    >>> from hinf_cpp.scenario.planned import plan_scenario
    >>> from hinf_cpp.scenario.documents import read_toml_file
    >>> root = read_toml_file(hc.scenario_path("paper_fig1"))
    >>> root["desired"] = {
    ...     "q0": [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    ...     "waypoints": [{"x": 20.0, "y": 0.0, "t": 20.0}, {"x": 40.0, "y": 3.5, "t": 40.0}],
    ...     "plan": {"u_min": [0.0, -0.5], "u_max": [2.0, 0.5], "interval": 1.0}}
    >>> planned = plan_scenario(root, "lane_change", cache=False)
    >>> sorted(planned.document["desired"])
    ['q0', 'u1', 'u2']
    >>> planned.document["desired"]["u1"]["table"]["interpolation"]
    'linear'
    >>> planned.plan.u.shape  # 40 intervals of 1 s: 41 nodes, 2 inputs
    (41, 2)
    >>> planned.path_change_plan is None, [table for table, _ in planned.plans()]  # no [path_change]
    (True, ['[desired]'])
    """

    scenario: _core.Scenario
    plan: Plan | None  # of [desired]; None when only [path_change] is planned
    document: dict
    source: str
    path_change_plan: Plan | None = None  # of [path_change]

    def plans(self) -> list[tuple[str, Plan]]:
        """(table, plan) of each planned table, in the order planned: ``("[desired]", plan)``
        and ``("[path_change]", path_change_plan)`` where they are planned."""
        return [(name, plan) for name, plan in (("[desired]", self.plan), ("[path_change]", self.path_change_plan))
                if plan is not None]


def needs_planning(root) -> bool:
    """Whether a scenario's dictionary asks for planning.

    Parameters
    ----------
    root : dict
        The scenario document (any other object: False).

    Returns
    -------
    bool
        True when its [desired] or its [path_change] has one of the keys ``waypoints``,
        ``path`` or ``plan`` (:data:`PLANNING_KEYS`).

    Examples
    --------
    >>> from hinf_cpp.scenario.planned import needs_planning
    >>> needs_planning({"desired": {"waypoints": [{"x": 20.0, "y": 0.0}]}})
    True
    >>> needs_planning({"desired": {"u1": 1.0, "u2": 0.0}})
    False
    >>> needs_planning({"desired": {"u1": 1.0, "u2": 0.0},
    ...                 "path_change": {"t": 20.0, "waypoints": [{"x": 30.0, "y": 4.0, "t": 40.0}]}})
    True
    """
    return isinstance(root, dict) and any(_planning_keys(root.get(name)) for name in PLANNED_SECTIONS)


def _planning_keys(table) -> dict:
    """The planning keys of a [desired] or [path_change] table (empty: it gives its inputs)."""
    return {key: table[key] for key in PLANNING_KEYS if key in table} if isinstance(table, dict) else {}


def load_planned(path: str | os.PathLike, cache: bool = True, trust_code: bool | None = None) -> PlannedScenario | None:
    """The planned scenario of a file whose [desired] or [path_change] asks for planning, else
    None.

    :func:`hinf_cpp.load_scenario` calls it first for every file.

    Parameters
    ----------
    path : str or os.PathLike
        The scenario file.
    cache : bool, optional
        Keep plans in :func:`hinf_cpp.planning.default_cache_dir` and read them back from
        there (default True); False plans anew and writes nothing.
    trust_code : bool, optional
        Whether the file's model may load or run code (as :func:`hinf_cpp.load_scenario`).

    Returns
    -------
    PlannedScenario or None
        None for a file that does not ask for planning, and for one that cannot be read or
        parsed (the C++ reader reports that when the file is loaded).

    Raises
    ------
    ValueError
        As :func:`plan_scenario`.
    hinf_cpp.planning.PlanningError
        The planner failed.

    Examples
    --------
    >>> from hinf_cpp.scenario.planned import load_planned
    >>> load_planned(hc.scenario_path("paper_fig1")) is None
    True
    >>> planned = load_planned(hc.scenario_path("planned/ship_lane_change"), cache=False)
    >>> len(planned.plan.waypoints), planned.scenario.tf
    (3, 60.0)
    """
    path = os.fspath(path)
    try:
        text = pathlib.Path(path).read_text(encoding="utf-8-sig")
        # The C++ parser first, with the reader's guards (tomllib takes time and memory
        # quadratic in the depth of a dotted key).
        if not _core.needs_planning_toml(text, path):
            return None
        root = tomllib.loads(text)
    except (OSError, ValueError):
        return None
    return plan_scenario(root, path, cache, trust_code)


def plan_scenario(root: dict, source: str = "<dict>", cache: bool = True,
                  trust_code: bool | None = None) -> PlannedScenario:
    """Plan the inputs of a scenario's dictionary and read the planned scenario.

    The [desired] table gives ``waypoints`` (or a ``path``, timed by
    :func:`hinf_cpp.planning.waypoints_from_path` from the desired start position) and
    optionally ``plan`` (the :class:`hinf_cpp.planning.PlanOptions`) instead of the inputs.
    The rest of the document is checked by the C++ reader first; the planner
    (:func:`hinf_cpp.planning.plan`) then finds the inputs u_d from [desired] q0 at t0 to tf,
    and they take the place of the planning keys as tables with interpolation = "linear"; for
    a vehicle open-loop unstable along the plan the planned states come too ([desired]
    ``states`` and ``max_defect``), and the scenario's desired trajectory is made from them.

    A [path_change] (with [receding_horizon]) may give ``waypoints`` or a ``path`` and ``plan``
    likewise, with its ``t``: the new path is planned after [desired]
    (:func:`hinf_cpp.planning.plan_path_change`) from the desired state of the run without the
    change at t (the receding horizon of the scenario with its [desired] inputs, planned or
    given) to tf, and its inputs take the place of the planning keys of [path_change]. Its
    ``plan`` options are its own (not those of [desired.plan]). With [receding_horizon], the
    planned tables hold their last inputs from tf to the end of the last window a run solves.

    Parameters
    ----------
    root : dict
        The scenario document; its [desired], its [path_change] or both give waypoints or a
        path (not both, and not the inputs).
    source : str, optional
        The scenario file or a name for the dictionary, for messages (default ``"<dict>"``);
        a relative ``[model] callable`` file is taken from the folder of an existing file.
    cache : bool, optional
        Keep plans in :func:`hinf_cpp.planning.default_cache_dir` and read them back from
        there (default True); False plans anew and writes nothing.
    trust_code : bool, optional
        Whether the document's model may load or run code (as :func:`hinf_cpp.load_scenario`).

    Returns
    -------
    PlannedScenario
        The scenario, the plans and the document with the planned inputs.

    Raises
    ------
    ValueError
        Anything wrong with the document, naming the source and the table (waypoints and path
        both or neither, inputs given too, an unknown planning key, a model without a CasADi
        form such as ``kind = "casadi"``; a [path_change] t that is not a window's start, or
        a new path along which the vehicle is open-loop unstable: a path change takes inputs
        only).
    hinf_cpp.planning.UnreachableWaypointError
        A ValueError: a waypoint out of reach with the input bounds and the time given.
    hinf_cpp.planning.PlanningError
        The optimizer failed, or the plan could not be made accurate enough.

    Examples
    --------
    >>> from hinf_cpp.scenario.planned import plan_scenario
    >>> from hinf_cpp.scenario.documents import read_toml_file
    >>> root = read_toml_file(hc.scenario_path("paper_fig1"))
    >>> root["desired"] = {
    ...     "q0": [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    ...     "waypoints": [{"x": 20.0, "y": 0.0, "t": 20.0}, {"x": 40.0, "y": 3.5, "t": 40.0}],
    ...     "plan": {"u_min": [0.0, -0.5], "u_max": [2.0, 0.5], "interval": 1.0}}
    >>> planned = plan_scenario(root, "lane_change", cache=False)
    >>> max(planned.plan.report.waypoint_errors) <= 0.05  # the default tolerance, m
    True
    >>> result = hc.run_scenario(planned.scenario)
    >>> result.metrics.final_position_error < 0.1
    True
    """
    from hinf_cpp.planning.planner import default_cache_dir, plan, plan_path_change

    planning = {name: _planning_keys(root.get(name)) for name in PLANNED_SECTIONS}
    if not any(planning.values()):
        raise ValueError(f"{source}: neither [desired] nor [path_change] gives waypoints, a path or plan options: "
                         "there is nothing to plan (docs/planning.md)")
    for name, keys in planning.items():
        if keys:
            _check_planning_table(root[name], keys, name, source)
    allow_code = code_allowed(trust_code)
    # Everything but the inputs and the sizes the model sets, checked before the model (which may
    # be a program) is loaded; then everything, with zero inputs in their place.
    skeleton = copy.deepcopy(root)
    for name, keys in planning.items():
        if keys:
            skeleton[name] = {key: value for key, value in root[name].items() if key not in PLANNING_KEYS}
    _core.check_scenario_toml(toml_text(skeleton, source), source)
    model = _core.parse_model_toml(toml_text({key: root[key] for key in ("model",) if key in root}, source), source,
                                   allow_code)
    for name, keys in planning.items():
        if keys:
            skeleton[name].update({f"u{i + 1}": 0.0 for i in range(model.m())})
    checked = _core.parse_scenario_toml(toml_text(skeleton, source), source, allow_code)
    planner_model = _planner_model(root.get("model", {}), model, source)
    cache_dir = default_cache_dir() if cache else None
    # A receding horizon's windows reach beyond tf: the planned inputs are held to the end of the
    # last window its loops solve (that of tf's window and the one after it, which the online
    # controller solves ahead).
    hold_until = _windows_end(checked) if checked.receding_horizon is not None else None
    document = copy.deepcopy(skeleton)

    desired_plan = None
    if planning["desired"]:
        keys = planning["desired"]
        options = _plan_options(keys.get("plan", {}), source, model.m(), "desired")
        if "waypoints" in keys:
            waypoints, where = _waypoints(keys["waypoints"], source, "desired"), "[desired]"
        else:
            waypoints = _path_waypoints(keys["path"], source, _start(model, checked.desired_q0), checked.t0,
                                        options.tolerance, "desired")
            where = "[desired] path:"
        with _prefixed(source, where):
            desired_plan = plan(planner_model, waypoints, q0=checked.desired_q0, t0=checked.t0, tf=checked.tf,
                                options=options, cache_dir=cache_dir)
        document["desired"] = dict(skeleton["desired"], **desired_plan.input_tables(hold_until))
        if desired_plan.states_given:
            # The vehicle is open-loop unstable along the plan: the desired trajectory is made from the
            # planned states, each interval integrated from its node, and refused where an interval's
            # defect exceeds what the planner checked (its max_mismatch).
            document["desired"].update(states=desired_plan.desired_states(), max_defect=options.max_mismatch)

    change_plan = None
    if planning["path_change"]:
        keys = planning["path_change"]
        options = _plan_options(keys.get("plan", {}), source, model.m(), "path_change")
        # The run without the change, along its [desired] trajectory (planned or given, inputs or
        # states): its desired state at t is where the new path starts.
        unchanged = _core.parse_scenario_toml(toml_text(document, source), source, allow_code)
        unchanged.path_change = None
        horizon = _core.scenario_receding_horizon(unchanged)
        t_join = checked.path_change.t
        if "waypoints" in keys:
            waypoints, where = _waypoints(keys["waypoints"], source, "path_change"), "[path_change]"
        else:
            with _prefixed(source, "[path_change]"):
                start = _start(model, horizon.desired_state(horizon.window_start(horizon.window_at(t_join))))
            waypoints = _path_waypoints(keys["path"], source, start, t_join, options.tolerance, "path_change")
            where = "[path_change] path:"
        with _prefixed(source, where):
            change_plan = plan_path_change(horizon, t_join, waypoints, tf=checked.tf, options=options,
                                           cache_dir=cache_dir, model=planner_model)
        document["path_change"] = dict(skeleton["path_change"], **change_plan.input_tables(hold_until))

    scenario = _core.parse_scenario_toml(toml_text(document, source), source, allow_code)
    return PlannedScenario(scenario, desired_plan, document, source, change_plan)


def _check_planning_table(table: dict, keys: dict, name: str, source: str) -> None:
    """Waypoints or a path (one of them), and no inputs beside them."""
    if ("waypoints" in keys) == ("path" in keys):
        raise ValueError(f"{source}: [{name}] give either waypoints or path (docs/planning.md), "
                         f"{'not both' if 'path' in keys else 'got neither'}")
    inputs = sorted((key for key in table if re.fullmatch(r"u\d+", key)), key=lambda key: int(key[1:]))
    if inputs:
        raise ValueError(f"{source}: [{name}] {inputs[0]}: give the inputs or {next(iter(keys))} "
                         "(planned inputs), not both")
    for key in ("states", "max_defect"):
        if key in table:
            raise ValueError(f"{source}: [{name}] {key}: the planner gives the states when the vehicle is open-loop "
                             f"unstable along the plan; leave it out with {next(iter(keys))}")


@contextlib.contextmanager
def _prefixed(source: str, where: str):
    """The planner's ValueErrors with the source and the table in front (the model's section for
    a model without a CasADi form); an unreachable waypoint stays an UnreachableWaypointError."""
    from hinf_cpp.planning.planner import UnreachableWaypointError

    try:
        yield
    except UnreachableWaypointError as error:
        raise UnreachableWaypointError(f"{source}: {where} {error}", error.index, error.miss) from None
    except ValueError as error:
        text = str(error)
        section = "[model]" if "has no CasADi form" in text else where
        raise ValueError(f"{source}: {section} {text}") from None


def _start(model: _core.Model, q) -> list[float]:
    """The position of the state q (where a path starts)."""
    positions = model.position_indices()
    return [q[i] for i in positions] if len(positions) == 2 else [0.0, 0.0]


def _windows_end(scenario: _core.Scenario) -> float:
    """The end of the last receding-horizon window a run of the scenario solves: the window of tf
    and the one after it, which the online controller solves ahead, each `window` long."""
    unchanged = copy.copy(scenario)
    unchanged.path_change = None  # checked with its plan (plan_path_change names a bad t there)
    horizon = _core.scenario_receding_horizon(unchanged)
    return horizon.window_start(horizon.window_at(scenario.tf) + 1) + scenario.receding_horizon.window


def planned_scenario_toml(planned: PlannedScenario, output: str | os.PathLike) -> str:
    """The planned scenario as the text of a scenario file to be written at `output`, which does
    not depend on any cache.

    ``hinf_cpp.scenario.scenario_toml`` writes a model compiled from CasADi (``[model] kind =
    "python"`` naming a SymbolicModel, or the same in [plant]) as ``kind = "casadi"`` with the
    absolute path of its description in the compile cache, which may be deleted at any time.
    Such a model's description, library and C source are copied here into the folder
    ``<output's stem>.models`` beside `output`, and the file names them relative to itself
    (the folder moves with the file). Other models are written as
    ``hinf_cpp.scenario.scenario_toml`` writes them.

    Parameters
    ----------
    planned : PlannedScenario
        What :func:`plan_scenario` or :func:`load_planned` returned.
    output : str or os.PathLike
        Where the text will be written (a device such as ``/dev/stdout`` too: then the folder
        is made in the working directory and named by its absolute path).

    Returns
    -------
    str
        The scenario file's text (TOML), which ``hinf-sim`` runs.

    Raises
    ------
    OSError
        The folder beside `output` cannot be written.

    Examples
    --------
    >>> from hinf_cpp.scenario.planned import load_planned, planned_scenario_toml
    >>> planned = load_planned(hc.scenario_path("planned/ship_lane_change"), cache=False)
    >>> text = planned_scenario_toml(planned, "lane_change.toml")  # a built-in ship: nothing copied
    >>> 'kind = "ship"' in text
    True
    """
    import shutil

    from hinf_cpp.models.codegen import _write_atomically
    from hinf_cpp.models.codegen import default_cache_dir as compile_cache_dir

    output = pathlib.Path(output)
    text = _core.scenario_toml(planned.scenario)
    cache = os.path.realpath(compile_cache_dir())
    cached = {}  # the description's path as written -> its copy
    for model in (planned.scenario.model, planned.scenario.plant):
        if not isinstance(model, _core.GeneratedModel):
            continue
        description = os.path.normpath(os.path.abspath(model.metadata_path()))
        if os.path.commonpath([os.path.realpath(description), cache]) == cache:
            cached[description] = pathlib.Path(description)
    if not cached:
        return text
    device = output.exists() and not output.is_file()
    folder = (pathlib.Path.cwd() / f"{planned.scenario.name or 'planned'}.models" if device
              else output.parent / f"{output.stem}.models")
    folder.mkdir(parents=True, exist_ok=True)
    written = {}
    for description, path in cached.items():
        library = path.parent / json.loads(path.read_text())["library"]
        c_source = library.with_suffix(".c")  # for reading: copied when there
        for source in (path, library, *([c_source] if c_source.exists() else [])):
            _write_atomically(folder / source.name, lambda temporary, source=source: shutil.copyfile(source, temporary))
        written[description] = str((folder / path.name).resolve()) if device else f"{folder.name}/{path.name}"
    lines = text.splitlines(keepends=True)
    for i, line in enumerate(lines):
        match = re.fullmatch(r"(\s*file\s*=\s*)(\".*\")(\s*)", line)
        if match is None:
            continue
        try:
            value = tomllib.loads(f"v = {match.group(2)}")["v"]
        except tomllib.TOMLDecodeError:
            continue
        if value in written:
            lines[i] = match.group(1) + json.dumps(written[value]) + match.group(3)
    return "".join(lines)


def _planner_model(table: dict, model: _core.Model, source: str):
    """The model for the planner: its CasADi expressions are needed. kind = "python" may name a
    SymbolicModel (called again here: the C++ reader got its compiled form); kind = "casadi" has
    only a compiled library."""
    kind = table.get("kind") if isinstance(table, dict) else None
    if kind == "casadi":
        raise ValueError(f"{source}: [model] kind = \"casadi\": the planner needs the model's CasADi expressions, and "
                         "model.json holds only compiled functions; name the SymbolicModel itself with kind = "
                         "\"python\", callable = \"FILE.py:FUNCTION\" to plan (docs/planning.md)")
    if kind == "python":
        from hinf_cpp.models.symbolic import SymbolicModel

        base = pathlib.Path(source).parent if source and pathlib.Path(source).is_file() else None
        made = resolve_callable(table["callable"], base)()
        if isinstance(made, SymbolicModel):
            return made
    return model


# ---- the planning keys, read with messages that name the source and the key ----

def _number(value, where: str, allow_infinite: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ValueError(f"{where}: expected a number, got {_type_name(value)}")
    if math.isnan(value) or (math.isinf(value) and not allow_infinite):
        raise ValueError(f"{where}: expected a finite number, got {value}")
    return float(value)


def _type_name(value) -> str:
    return {bool: "a boolean", str: "a string", list: "an array", dict: "a table"}.get(type(value), type(value).__name__)


def _known(table, known: tuple[str, ...], where: str) -> dict:
    if not isinstance(table, dict):
        raise ValueError(f"{where}: expected a table, got {_type_name(table)}")
    for key in table:
        if key not in known:
            raise ValueError(f"{where}: unknown key '{key}' (known keys: {', '.join(known)})")
    return table


def _plan_options(table, source: str, m: int, section: str) -> PlanOptions:
    from hinf_cpp.planning.planner import PlanOptions

    where = f"{source}: [{section}.plan]"
    fields = tuple(field.name for field in dataclasses.fields(PlanOptions))
    values = {}
    for key, value in _known(table, fields, where).items():
        if key in PER_INPUT:
            items = value if isinstance(value, list) else [value]
            if not items:
                raise ValueError(f"{where} {key}: expected a number or one number per input, got an empty array")
            values[key] = tuple(_number(v, f"{where} {key}", allow_infinite=key != "input_scale") for v in items)
        elif key in INTEGERS:
            if isinstance(value, bool) or not isinstance(value, int):
                raise ValueError(f"{where} {key}: expected an integer, got {_type_name(value)}")
            values[key] = value
        else:
            values[key] = _number(value, f"{where} {key}")
    options = PlanOptions(**values)
    try:
        options.checked(m)
    except ValueError as error:
        raise ValueError(f"{where} {error}") from None
    return options


def _waypoints(value, source: str, section: str) -> list[Waypoint]:
    from hinf_cpp.planning.planner import Waypoint

    where = f"{source}: [{section}] waypoints"
    if not isinstance(value, list) or not value:
        raise ValueError(f"{where}: expected an array of tables {{ x = ..., y = ..., t = ... }}, got "
                         f"{'an empty array' if isinstance(value, list) else _type_name(value)}")
    out = []
    for i, item in enumerate(value):
        table = _known(item, WAYPOINT_KEYS, f"{where}[{i}]")
        for key in ("x", "y"):
            if key not in table:
                raise ValueError(f"{where}[{i}]: {key} is required")
        out.append(Waypoint(**{key: _number(v, f"{where}[{i}].{key}") for key, v in table.items()}))
    return out


def _path_waypoints(value, source: str, start, t0: float, tolerance: float, section: str) -> list[Waypoint]:
    from hinf_cpp.planning.planner import waypoints_from_path

    where = f"{source}: [{section}] path"
    table = _known(value, PATH_KEYS, where)
    for key in PATH_KEYS:
        if key not in table:
            raise ValueError(f"{where}: {key} is required")
    columns = {}
    for key in ("x", "y"):
        if not isinstance(table[key], list) or not table[key]:
            raise ValueError(f"{where}.{key}: expected an array of numbers")
        columns[key] = [_number(v, f"{where}.{key}[{i}]") for i, v in enumerate(table[key])]
    speed = table["speed"]
    speed = ([_number(v, f"{where}.speed[{i}]") for i, v in enumerate(speed)] if isinstance(speed, list)
             else _number(speed, f"{where}.speed"))
    try:
        return waypoints_from_path(columns["x"], columns["y"], speed, start=start, t0=t0, tolerance=tolerance)
    except ValueError as error:
        raise ValueError(f"{where}: {error}") from None
