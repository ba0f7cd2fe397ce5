"""Scenario files (TOML, ``docs/scenarios.md``), read by the one C++ reader.

``hinf-sim`` and this package read scenarios with the same C++ code
(``cpp/src/io/scenario_reader.cpp``), so both accept and reject exactly the same files, with the
same messages. A dictionary (the parsed form of a file) is written back to TOML text and read by
the same reader. A file whose [desired] gives waypoints or a path is planned first
(:mod:`hinf_cpp.scenario.planned`).
"""

from __future__ import annotations

import os
import pathlib
import warnings
from typing import Any

from hinf_cpp import _core
from hinf_cpp.scenario.documents import code_allowed, toml_text
from hinf_cpp.scenario.planned import load_planned, needs_planning, plan_scenario

__all__ = ["load_scenario", "scenario_from_dict", "scenario_path", "signal_from_spec"]


def load_scenario(path: str | os.PathLike, *, trust_code: bool | None = None) -> _core.Scenario:
    """Read a scenario file (TOML, docs/scenarios.md) into a :class:`hinf_cpp.Scenario`.

    The file is read by the C++ reader that ``hinf-sim`` uses: the same files are accepted and
    refused, with the same messages. What is legal but probably not meant (a table whose cubic
    spline overshoots its values) is a UserWarning naming the file and the key. A file whose
    [desired] gives waypoints or a path is planned first (:mod:`hinf_cpp.scenario.planned`,
    docs/planning.md; the plan is cached in
    :func:`hinf_cpp.planning.default_cache_dir`).

    Parameters
    ----------
    path : str or os.PathLike
        The scenario file; shipped ones are at :func:`scenario_path`.
    trust_code : bool, optional
        Whether the file may load or run code: a ``[model]`` of kind ``"casadi"`` loads the
        compiled library its model.json names, kind ``"python"`` imports and calls Python code.
        Default: the environment (``HINF_TRUST_CODE=1``), else no: such a file is then a
        ValueError naming the key and how to allow it, and nothing is loaded (docs/trust.md).

    Returns
    -------
    hinf_cpp.Scenario
        The scenario, ready for :func:`hinf_cpp.run_scenario`.

    Raises
    ------
    ValueError
        Anything wrong with the file, naming the file and the key (also a file that cannot be
        read); :class:`hinf_cpp.planning.UnreachableWaypointError` (a ValueError) for a
        waypoint out of reach.
    hinf_cpp.planning.PlanningError
        The planner failed on the file's waypoints.

    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.name, scenario.t0, scenario.tf, scenario.gamma
    ('paper-fig1', 0.0, 40.0, 5.0)
    >>> hc.load_scenario("missing.toml")
    Traceback (most recent call last):
        ...
    ValueError: cannot read scenario file 'missing.toml': No such file or directory
    """
    allow_code = code_allowed(trust_code)
    planned = load_planned(path, trust_code=allow_code)
    if planned is not None:
        return _warn_about(planned.scenario, os.fspath(path))
    return _warn_about(_core.load_scenario_toml(os.fspath(path), allow_code), os.fspath(path))


def _warn_about(scenario: _core.Scenario, source: str) -> _core.Scenario:
    for message in _core.scenario_warnings(scenario):
        warnings.warn(f"{source}: {message}", UserWarning, stacklevel=3)
    return scenario


def scenario_from_dict(root: dict, source: str = "<dict>", *, trust_code: bool | None = None) -> _core.Scenario:
    """Build a :class:`hinf_cpp.Scenario` from the dictionary form of a scenario file.

    The dictionary (as :func:`tomllib.load` gives it for a file) is written back as TOML text
    and read by the same C++ reader as :func:`load_scenario`: the same checks and messages. A
    [desired] with waypoints or a path is planned first (the plan is cached).

    Parameters
    ----------
    root : dict
        The scenario document: its tables ([model], [horizon], [desired], ...) as
        dictionaries.
    source : str, optional
        What the document is called in messages (default ``"<dict>"``).
    trust_code : bool, optional
        Whether the document's model may load or run code (as :func:`load_scenario`).

    Returns
    -------
    hinf_cpp.Scenario
        The scenario.

    Raises
    ------
    ValueError
        Anything wrong with the document, naming `source` and the key.
    hinf_cpp.planning.PlanningError
        The planner failed on the document's waypoints.

    Examples
    --------
    >>> import tomllib
    >>> with open(hc.scenario_path("paper_fig1"), "rb") as f:
    ...     root = tomllib.load(f)
    >>> root["controller"]["gamma"] = 10.0
    >>> hc.scenario_from_dict(root).gamma
    10.0
    >>> root["controller"]["gama"] = 10.0
    >>> hc.scenario_from_dict(root)
    Traceback (most recent call last):
        ...
    ValueError: <dict>: [controller] unknown key 'gama' (known keys: gamma, Q, Qf, kappa, law, cascade, backstepping)
    """
    allow_code = code_allowed(trust_code)
    if needs_planning(root):
        return _warn_about(plan_scenario(root, source, trust_code=allow_code).scenario, source)
    return _warn_about(_core.parse_scenario_toml(toml_text(root, source), source, allow_code), source)


def signal_from_spec(spec: Any, name: str = "signal") -> _core.Signal:
    """A :class:`hinf_cpp.Signal` from its TOML form (a number or a table).

    The forms are those of a scenario file's signals (docs/scenarios.md): a constant, an
    offset with harmonics (``{"harmonics": [{"amplitude": 0.3, "omega": 0.2}]}``, omega in
    rad/s, or ``frequency_hz`` in Hz), or a table of times (s) and values with its
    interpolation. A table whose cubic spline overshoots its values is a UserWarning.

    Parameters
    ----------
    spec : float or dict
        The signal's TOML value.
    name : str, optional
        What the signal is called in messages (default ``"signal"``).

    Returns
    -------
    hinf_cpp.Signal
        The signal, a function of time t (s).

    Raises
    ------
    ValueError
        A value that is not a signal, naming `name` and the key.

    Examples
    --------
    >>> u2 = hc.signal_from_spec({"harmonics": [{"amplitude": 0.3, "omega": 0.2}]}, "u2")
    >>> round(u2(1.0), 4)  # 0.3 sin(0.2 t) at t = 1 s
    0.0596
    >>> hc.signal_from_spec({"harmonics": [{"amplitude": 0.3}]}, "u2")
    Traceback (most recent call last):
        ...
    ValueError: <python>: signal u2.harmonics[0]: give exactly one of omega (rad/s) and frequency_hz (Hz)
    """
    signal = _core.parse_signal_toml(toml_text({name: spec}, "<python>"), name, "<python>")
    message = _core.overshoot_warning(signal, name)
    if message:
        warnings.warn(message, UserWarning, stacklevel=2)
    return signal


def scenario_path(name: str) -> pathlib.Path:
    """The path of a scenario file shipped with the package.

    Parameters
    ----------
    name : str
        The scenario's name: its file name without ``.toml``, relative to the shipped
        scenarios folder, e.g. ``"paper_fig1"`` or ``"planned/ship_lane_change"``.

    Returns
    -------
    pathlib.Path
        The file (inside the installed package).

    Raises
    ------
    ValueError
        No shipped scenario of that name; the message lists the shipped ones.

    Examples
    --------
    >>> hc.scenario_path("paper_fig1").name
    'paper_fig1.toml'
    >>> hc.scenario_path("planned/ship_lane_change").parent.name
    'planned'
    >>> hc.scenario_path("paper_fig9")
    Traceback (most recent call last):
        ...
    ValueError: no shipped scenario 'paper_fig9' (shipped: auv_s_curve, ...)
    """
    from importlib import resources  # here: it brings tempfile and shutil, which reading a file does not need

    folder = pathlib.Path(str(resources.files("hinf_cpp") / "scenarios"))
    path = folder / f"{name}.toml"
    if not path.exists():
        shipped = sorted(p.relative_to(folder).with_suffix("").as_posix() for p in folder.glob("**/*.toml"))
        raise ValueError(f"no shipped scenario '{name}' (shipped: {', '.join(shipped)})")
    return path
