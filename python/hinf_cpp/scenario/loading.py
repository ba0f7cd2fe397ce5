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
from importlib import resources
from typing import Any

from hinf_cpp import _core
from hinf_cpp.scenario.documents import toml_text
from hinf_cpp.scenario.planned import load_planned, needs_planning, plan_scenario

__all__ = ["load_scenario", "scenario_from_dict", "scenario_path", "signal_from_spec"]


def load_scenario(path: str | os.PathLike) -> _core.Scenario:
    """Reads a scenario file; anything wrong with it raises ValueError naming the file and the key.
    What is legal but probably not meant (a table whose cubic spline overshoots its values) is a
    UserWarning naming the file and the key. A file whose [desired] gives waypoints or a path is
    planned first (hinf_cpp.scenario.planned, docs/planning.md; the plan is cached)."""
    planned = load_planned(path)
    if planned is not None:
        return _warn_about(planned.scenario, os.fspath(path))
    return _warn_about(_core.load_scenario_toml(os.fspath(path)), os.fspath(path))


def _warn_about(scenario: _core.Scenario, source: str) -> _core.Scenario:
    for message in _core.scenario_warnings(scenario):
        warnings.warn(f"{source}: {message}", UserWarning, stacklevel=3)
    return scenario


def scenario_from_dict(root: dict, source: str = "<dict>") -> _core.Scenario:
    """Builds a :class:`Scenario` from the dictionary form of a scenario file (as
    :func:`tomllib.load` gives it); the same checks and messages as :func:`load_scenario`."""
    if needs_planning(root):
        return _warn_about(plan_scenario(root, source).scenario, source)
    return _warn_about(_core.parse_scenario_toml(toml_text(root, source), source), source)


def signal_from_spec(spec: Any, name: str = "signal") -> _core.Signal:
    """A :class:`Signal` from its TOML form (a number or a table), e.g.
    ``{"harmonics": [{"amplitude": 0.3, "omega": 0.2}]}``; messages name it `name`."""
    signal = _core.parse_signal_toml(toml_text({name: spec}, "<python>"), name, "<python>")
    message = _core.overshoot_warning(signal, name)
    if message:
        warnings.warn(message, UserWarning, stacklevel=2)
    return signal


def scenario_path(name: str) -> pathlib.Path:
    """Path of a shipped scenario, e.g. ``scenario_path("paper_fig1")`` or
    ``scenario_path("planned/ship_lane_change")``."""
    folder = pathlib.Path(str(resources.files("hinf_cpp") / "scenarios"))
    path = folder / f"{name}.toml"
    if not path.exists():
        shipped = sorted(p.relative_to(folder).with_suffix("").as_posix() for p in folder.glob("**/*.toml"))
        raise ValueError(f"no shipped scenario '{name}' (shipped: {', '.join(shipped)})")
    return path
