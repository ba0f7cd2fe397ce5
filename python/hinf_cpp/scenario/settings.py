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
import unicodedata
from typing import Any, Sequence

from hinf_cpp.scenario.documents import FloatOverflow, file_float

__all__ = ["FEEDBACK_KEY", "apply_settings", "get_key", "key_path", "parse_setting", "set_key", "toml_value"]

#: The key that keeps ("output") or drops ("state") a scenario's [measurement].
FEEDBACK_KEY = "feedback"


_PART = re.compile(r"^([A-Za-z0-9_-]+)((?:\[\d+\])*)$")


def key_path(key: str) -> list[str | int]:
    """The path of a dotted key: its names and array indices, in order.

    Parameters
    ----------
    key : str
        A dotted key with optional 0-based array indices, e.g. ``"initial.q0[2]"``; each name
        is letters, digits, ``_`` and ``-``.

    Returns
    -------
    list of str and int
        The names (str) and indices (int), e.g. ``["initial", "q0", 2]``.

    Raises
    ------
    ValueError
        An empty key or a part that is not a name with optional ``[index]``.

    Examples
    --------
    >>> from hinf_cpp.scenario.settings import key_path
    >>> key_path("disturbance.w1.harmonics[0].amplitude")
    ['disturbance', 'w1', 'harmonics', 0, 'amplitude']
    >>> key_path("initial.q0[x]")
    Traceback (most recent call last):
        ...
    ValueError: key 'initial.q0[x]': 'q0[x]' is not a name with optional [index] (e.g. 'initial.q0[2]')
    """
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
    """The value at a dotted key of a document.

    Parameters
    ----------
    document : dict
        A scenario (or study) document, as :func:`tomllib.load` gives it.
    key : str
        A dotted key (:func:`key_path`), e.g. ``"initial.q0[2]"``.

    Returns
    -------
    object
        The value: a number, string, bool, list or dictionary (a table).

    Raises
    ------
    KeyError
        The key is not in the document.
    ValueError
        A key that is not well formed (:func:`key_path`).

    Examples
    --------
    >>> from hinf_cpp.scenario.settings import get_key
    >>> document = {"initial": {"q0": [1.0, 0.0, 0.5]}}
    >>> get_key(document, "initial.q0[2]")
    0.5
    >>> get_key(document, "controller.gamma")
    Traceback (most recent call last):
        ...
    KeyError: 'controller.gamma'
    """
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
    """Set a dotted key of a scenario document, in place.

    Tables on the way are made if missing; an array index must exist. The key ``"feedback"``
    is special: ``"state"`` drops [measurement], ``"output"`` keeps it.

    Parameters
    ----------
    document : dict
        The scenario document, changed in place.
    key : str
        A dotted key (:func:`key_path`), or ``"feedback"``.
    value : object
        The TOML value (number, str, bool, list, dictionary).

    Raises
    ------
    ValueError
        A key that is not well formed, an array index that does not exist, a part that is not
        inside a table; ``"feedback"`` with a value other than ``"state"`` and ``"output"``,
        or ``"output"`` for a document without [measurement].

    Examples
    --------
    >>> from hinf_cpp.scenario.settings import set_key
    >>> document = {"initial": {"q0": [1.0, 0.0]}, "measurement": {"sigma": 0.5}}
    >>> set_key(document, "controller.gamma", 12.0)
    >>> set_key(document, "feedback", "state")
    >>> document
    {'initial': {'q0': [1.0, 0.0]}, 'controller': {'gamma': 12.0}}
    >>> set_key(document, "initial.q0[5]", 1.0)
    Traceback (most recent call last):
        ...
    ValueError: key 'initial.q0[5]': the scenario has no element 5 there
    """
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
    """The key and value of a ``KEY=VALUE`` setting of ``hinf-cpp run --set``.

    Parameters
    ----------
    text : str
        ``KEY=VALUE``: a dotted key (:func:`key_path`) or ``feedback``, and a TOML value
        (strings quoted: ``controller.law="lqr"``). Spaces around either are ignored.

    Returns
    -------
    tuple of (str, object)
        The key and the parsed value.

    Raises
    ------
    ValueError
        No ``=`` or no key, a value that is not TOML, a key that is not well formed; a line
        break or other control character anywhere in `text` (the value is one TOML value on
        one line: what follows a line break would be dropped); a number the scenario file
        reader refuses: a float literal that overflows a double (``1e400``; ``inf`` and
        ``-inf`` are written so) or an integer outside 64 bits.

    Examples
    --------
    >>> from hinf_cpp.scenario.settings import parse_setting
    >>> parse_setting('controller.law="lqr"')
    ('controller.law', 'lqr')
    >>> parse_setting("initial.q0[2] = 0.5")
    ('initial.q0[2]', 0.5)
    >>> parse_setting("controller.gamma=inf")
    ('controller.gamma', inf)
    >>> parse_setting("controller.law=lqr")
    Traceback (most recent call last):
        ...
    ValueError: --set 'controller.law=lqr': 'lqr' is not a TOML value (quote strings: controller.law="lqr")
    >>> parse_setting("controller.gamma=1e400")
    Traceback (most recent call last):
        ...
    ValueError: --set 'controller.gamma=1e400': invalid TOML in controller.gamma: ... '1e400' could not be ...
    """
    _check_one_line(text)
    key, sep, value = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise ValueError(f"--set '{text}': write it as KEY=VALUE, e.g. controller.gamma=12")
    try:
        parsed = tomllib.loads(f"value = {value.strip()}", parse_float=file_float)["value"]
    except tomllib.TOMLDecodeError:
        raise ValueError(f"--set '{text}': '{value.strip()}' is not a TOML value "
                         "(quote strings: controller.law=\"lqr\")") from None
    except FloatOverflow as overflow:
        raise ValueError(f"--set '{text}': invalid TOML in {key}: {overflow}") from None
    integer = _integer_beyond_64_bits(parsed)
    if integer is not None:
        raise ValueError(f"--set '{text}': invalid TOML in {key}: Error while parsing integer: '{integer}' is not "
                         "representable in 64 bits")
    key_path(key) if key != FEEDBACK_KEY else None
    return key, parsed


def _integer_beyond_64_bits(value: Any) -> int | None:
    """The first integer of a TOML value outside int64 (toml++ refuses it), else None."""
    if isinstance(value, int) and not isinstance(value, bool):
        return value if not -2**63 <= value < 2**63 else None
    items = value.values() if isinstance(value, dict) else value if isinstance(value, list) else ()
    for item in items:
        found = _integer_beyond_64_bits(item)
        if found is not None:
            return found
    return None


def _check_one_line(text: str) -> None:
    """Refuses a control character (a line break, a tab, ...) in a KEY=VALUE setting: TOML
    would read the first line and silently drop the rest."""
    def control(char: str) -> bool:
        return unicodedata.category(char) in ("Cc", "Zl", "Zp")

    for position, char in enumerate(text):
        if control(char):
            shown = "".join(_ESCAPES.get(c, f"\\u{ord(c):04x}") if control(c) else c for c in text[:60])
            raise ValueError(f"--set '{shown}{'...' if len(text) > 60 else ''}': a line break or control "
                             f"character (U+{ord(char):04X}) at position {position}: give one KEY=VALUE on one line, "
                             "without line breaks or tabs")


_ESCAPES = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}


def apply_settings(document: dict, settings: Sequence[tuple[str, Any]], seed: int | None = None) -> dict:
    """A copy of a scenario document with settings applied.

    The settings are applied in order with :func:`set_key`, then [measurement] seed = `seed`
    if given. The document passed in is not changed.

    Parameters
    ----------
    document : dict
        The scenario document.
    settings : sequence of (str, object)
        (key, value) pairs, as :func:`parse_setting` gives them.
    seed : int, optional
        The measurement noise seed (``hinf-cpp run --seed``).

    Returns
    -------
    dict
        The new document (a deep copy).

    Raises
    ------
    ValueError
        As :func:`set_key`; a `seed` for a document without [measurement].

    Examples
    --------
    >>> from hinf_cpp.scenario.settings import apply_settings
    >>> document = {"controller": {"gamma": 5.0}, "measurement": {"sigma": 0.5}}
    >>> apply_settings(document, [("controller.gamma", 10.0)], seed=7)
    {'controller': {'gamma': 10.0}, 'measurement': {'sigma': 0.5, 'seed': 7}}
    >>> document["controller"]["gamma"]
    5.0
    """
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
    """A value as TOML text, as it is written after ``KEY=`` in ``--set``.

    Floats are written exactly (their ``repr``): the text reads back to the same double.

    Parameters
    ----------
    value : object
        A TOML value: number, str, bool, list or dictionary.

    Returns
    -------
    str
        Its TOML text (strings quoted).

    Examples
    --------
    >>> from hinf_cpp.scenario.settings import toml_value
    >>> toml_value(0.1), toml_value("lqr"), toml_value(True)
    ('0.1', '"lqr"', 'true')
    """
    import tomli_w

    return tomli_w.dumps({"v": value}).strip()[len("v = "):]
