"""Scenario files (TOML, ``docs/scenarios.md``), read by the one C++ reader.

``hinf-sim`` and this package read scenarios with the same C++ code
(``cpp/src/scenario_io.cpp``), so both accept and reject exactly the same files, with the same
messages. A dictionary (the parsed form of a file) is written back to TOML text with
``tomli_w`` and read by the same reader.
"""

from __future__ import annotations

import os
from typing import Any

import tomli_w

from . import _core

__all__ = ["load_scenario", "scenario_from_dict", "signal_from_spec"]


def load_scenario(path: str | os.PathLike) -> _core.Scenario:
    """Reads a scenario file; anything wrong with it raises ValueError naming the file and the key."""
    return _core.load_scenario_toml(os.fspath(path))


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
    return _core.parse_scenario_toml(_toml_text(root, source), source)


def signal_from_spec(spec: Any, name: str = "signal") -> _core.Signal:
    """A :class:`Signal` from its TOML form (a number or a table), e.g.
    ``{"harmonics": [{"amplitude": 0.3, "omega": 0.2}]}``; messages name it `name`."""
    return _core.parse_signal_toml(_toml_text({name: spec}, "<python>"), name, "<python>")
