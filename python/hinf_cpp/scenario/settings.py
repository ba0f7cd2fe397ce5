"""Setting scenario keys by name: ``hinf-cpp run --set KEY=VALUE`` and the axes of a study.

A key names a value of a scenario document (the dictionary of a scenario file) by its dotted
path, with array indices: ``controller.gamma``, ``initial.q0[2]``,
``disturbance.w1.harmonics[0].amplitude``. The key ``feedback`` is special: "state" drops the
[measurement] section, "output" keeps it. Values are TOML values (strings quoted).
"""

from __future__ import annotations

import copy
import re
import tomllib
from typing import Any, Sequence

__all__ = ["FEEDBACK_KEY", "apply_settings", "get_key", "key_path", "parse_setting", "set_key", "toml_value"]

FEEDBACK_KEY = "feedback"  # the key that keeps ("output") or drops ("state") [measurement]


_PART = re.compile(r"^([A-Za-z0-9_-]+)((?:\[\d+\])*)$")


def key_path(key: str) -> list[str | int]:
    """The path of a dotted key: names and array indices, e.g. ["initial", "q0", 2]."""
    if not isinstance(key, str) or not key:
        raise ValueError(f"a key must be a non-empty string like 'controller.gamma', got {key!r}")
    path: list[str | int] = []
    for part in key.split("."):
        match = _PART.match(part)
        if not match:
            raise ValueError(f"key '{key}': '{part}' is not a name with optional [index] (e.g. 'initial.q0[2]')")
        path.append(match.group(1))
        path += [int(i) for i in re.findall(r"\[(\d+)\]", match.group(2))]
    return path


def get_key(document: dict, key: str) -> Any:
    """The value at `key`; KeyError if it is not there."""
    node: Any = document
    for part in key_path(key):
        if isinstance(part, int):
            if not isinstance(node, list) or part >= len(node):
                raise KeyError(key)
        elif not isinstance(node, dict) or part not in node:
            raise KeyError(key)
        node = node[part]
    return node


def set_key(document: dict, key: str, value: Any) -> None:
    """Sets `key` in the scenario document: tables on the way are made if missing, an array
    index must exist. "feedback" = "state" drops [measurement], "output" keeps it."""
    if key == FEEDBACK_KEY:
        if value == "state":
            document.pop("measurement", None)
        elif value == "output":
            if "measurement" not in document:
                raise ValueError("feedback = \"output\" needs a scenario with [measurement]")
        else:
            raise ValueError(f"feedback must be \"state\" or \"output\", got {value!r}")
        return
    path = key_path(key)
    node: Any = document
    for depth, part in enumerate(path[:-1]):
        following = path[depth + 1]
        if isinstance(part, int):
            if not isinstance(node, list) or part >= len(node):
                raise ValueError(f"key '{key}': the scenario has no element {part} there")
            node = node[part]
            continue
        if not isinstance(node, dict):
            raise ValueError(f"key '{key}': '{part}' is not inside a table")
        if part not in node:
            if isinstance(following, int):
                raise ValueError(f"key '{key}': the scenario has no array '{part}' to index")
            node[part] = {}
        node = node[part]
    last = path[-1]
    if isinstance(last, int):
        if not isinstance(node, list) or last >= len(node):
            raise ValueError(f"key '{key}': the scenario has no element {last} there")
        node[last] = value
    elif isinstance(node, dict):
        node[last] = value
    else:
        raise ValueError(f"key '{key}': '{last}' is not inside a table")


def parse_setting(text: str) -> tuple[str, Any]:
    """``KEY=VALUE`` of ``hinf-cpp run --set``: VALUE is a TOML value (strings quoted)."""
    key, sep, value = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise ValueError(f"--set '{text}': write it as KEY=VALUE, e.g. controller.gamma=12")
    try:
        parsed = tomllib.loads(f"value = {value.strip()}")["value"]
    except tomllib.TOMLDecodeError:
        raise ValueError(f"--set '{text}': '{value.strip()}' is not a TOML value "
                         "(quote strings: controller.law=\"lqr\")") from None
    key_path(key) if key != FEEDBACK_KEY else None
    return key, parsed


def apply_settings(document: dict, settings: Sequence[tuple[str, Any]], seed: int | None = None) -> dict:
    """A copy of a scenario document with the settings (key, value) applied in order, then
    [measurement] seed = `seed` if given (ValueError if the scenario has no [measurement])."""
    document = copy.deepcopy(document)
    for key, value in settings:
        set_key(document, key, value)
    if seed is not None:
        if "measurement" not in document:
            raise ValueError("--seed sets [measurement] seed, but the scenario has no [measurement] "
                             "(a state-feedback run has no noise)")
        document["measurement"]["seed"] = seed
    return document


def toml_value(value: Any) -> str:
    """A value as TOML text (floats exactly: repr)."""
    import tomli_w

    return tomli_w.dumps({"v": value}).strip()[len("v = "):]
