"""Scenario files (TOML, ``docs/scenarios.md``), read by the one C++ reader.

``hinf-sim`` and this package read scenarios with the same C++ code
(``cpp/src/scenario_io.cpp``), so both accept and reject exactly the same files, with the same
messages. A dictionary (the parsed form of a file) is written back to TOML text with
``tomli_w`` and read by the same reader.
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import pathlib
import warnings
from typing import Any

import tomli_w

from . import _core

__all__ = ["load_scenario", "scenario_from_dict", "signal_from_spec"]


def load_scenario(path: str | os.PathLike) -> _core.Scenario:
    """Reads a scenario file; anything wrong with it raises ValueError naming the file and the key.
    What is legal but probably not meant (a table whose cubic spline overshoots its values) is a
    UserWarning naming the file and the key. A file whose [desired] gives waypoints or a path is
    planned first (hinf_cpp.planned_scenario, docs/planning.md; the plan is cached)."""
    from .planned_scenario import load_planned

    planned = load_planned(path)
    if planned is not None:
        return _warn_about(planned.scenario, os.fspath(path))
    return _warn_about(_core.load_scenario_toml(os.fspath(path)), os.fspath(path))


def _warn_about(scenario: _core.Scenario, source: str) -> _core.Scenario:
    for message in _core.scenario_warnings(scenario):
        warnings.warn(f"{source}: {message}", UserWarning, stacklevel=3)
    return scenario


def resolve_callable(spec: str, base: str | os.PathLike | None = None):
    """The callable named by `spec`: "package.module:name", or "path/to/file.py:name" (a relative
    path is taken from the folder `base`, else the current one). ValueError naming what is wrong."""
    where, sep, name = str(spec).rpartition(":")
    if not sep or not where or not name:
        raise ValueError(f"'{spec}': name it as MODULE:CALLABLE or FILE.py:CALLABLE")
    if where.endswith(".py"):
        path = pathlib.Path(where)
        if not path.is_absolute() and base is not None:
            path = pathlib.Path(base) / path
        if not path.is_file():
            raise ValueError(f"'{spec}': no Python file {path}")
        module_spec = importlib.util.spec_from_file_location(f"hinf_cpp_user_{path.stem}", path)
        module = importlib.util.module_from_spec(module_spec)
        module_spec.loader.exec_module(module)
    else:
        try:
            module = importlib.import_module(where)
        except ImportError as error:
            raise ValueError(f"'{spec}': cannot import {where} ({error})") from error
    factory = getattr(module, name, None)
    if not callable(factory):
        raise ValueError(f"'{spec}': {where} has no callable '{name}'")
    return factory


def model_from_callable(spec: str, source: str = "") -> _core.Model:
    """The model of [model] kind = "python" (Python-only: hinf-sim cannot run it): the callable
    `spec` is called with no arguments and returns an hc.Model (a subclass written in Python,
    or a built-in one) or a hinf_cpp.symbolic.SymbolicModel (compiled, cached). A relative file
    path is taken from the scenario file's folder."""
    base = pathlib.Path(source).parent if source and pathlib.Path(source).is_file() else None
    model = resolve_callable(spec, base)()
    if isinstance(model, _core.Model):
        return model
    from .symbolic import SymbolicModel

    if isinstance(model, SymbolicModel):
        return model.compile()
    raise ValueError(f"'{spec}' returned {type(model).__name__}, not an hc.Model or a SymbolicModel")


def _toml_text(document: Any, source: str) -> str:
    """The TOML text of a dictionary; ValueError naming `source` for what TOML cannot hold."""
    if not isinstance(document, dict):
        raise ValueError(f"{source}: expected a dictionary of TOML values, got {type(document).__name__}")
    try:
        return tomli_w.dumps(document)
    except RecursionError:
        raise ValueError(f"{source}: the dictionary is nested too deeply for a scenario") from None
    except (TypeError, ValueError) as error:
        raise ValueError(f"{source}: not a TOML document: {error}") from None


def scenario_from_dict(root: dict, source: str = "<dict>") -> _core.Scenario:
    """Builds a :class:`Scenario` from the dictionary form of a scenario file (as
    :func:`tomllib.load` gives it); the same checks and messages as :func:`load_scenario`."""
    from .planned_scenario import needs_planning, plan_scenario

    if needs_planning(root):
        return _warn_about(plan_scenario(root, source).scenario, source)
    return _warn_about(_core.parse_scenario_toml(_toml_text(root, source), source), source)


def signal_from_spec(spec: Any, name: str = "signal") -> _core.Signal:
    """A :class:`Signal` from its TOML form (a number or a table), e.g.
    ``{"harmonics": [{"amplitude": 0.3, "omega": 0.2}]}``; messages name it `name`."""
    signal = _core.parse_signal_toml(_toml_text({name: spec}, "<python>"), name, "<python>")
    message = _core.overshoot_warning(signal, name)
    if message:
        warnings.warn(message, UserWarning, stacklevel=2)
    return signal
