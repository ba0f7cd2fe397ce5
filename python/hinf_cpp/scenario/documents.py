"""Documents: TOML files read into dictionaries, dictionaries written back as TOML text, and the
Python code a scenario names (``[model] kind = "python"``).

A scenario (or study) document is the dictionary :func:`tomllib.load` gives for its file. The
package edits documents (``--set``, study axes, planned inputs) and hands them to the one C++
reader as TOML text (:func:`toml_text`), so every scenario, from a file or from Python, passes
the same checks.
"""

from __future__ import annotations

import importlib
import importlib.util
import math
import os
import pathlib
import sys
import tomllib
from typing import Any

import tomli_w

from hinf_cpp import _core

__all__ = ["code_allowed", "model_from_callable", "read_toml_file", "resolve_callable", "toml_text"]


def code_allowed(trust_code: bool | None) -> bool:
    """Whether reading a file may load or run the code it names (docs/trust.md).

    Parameters
    ----------
    trust_code : bool or None
        The caller's answer; None asks the environment: ``HINF_TRUST_CODE=1`` yes; unset,
        empty or 0 no.

    Returns
    -------
    bool
        Whether a ``[model]`` of kind ``"casadi"`` or ``"python"`` may be read.

    Raises
    ------
    ValueError
        HINF_TRUST_CODE set to anything but 1, 0 or nothing.

    Examples
    --------
    >>> from hinf_cpp.scenario.documents import code_allowed
    >>> code_allowed(True), code_allowed(False)
    (True, False)
    """
    return bool(trust_code) if trust_code is not None else _core.code_trusted_by_environment()


def _user_code(spec: str, what: str, run):
    """run(), with what the user's code raises (or a sys.exit in it) as a ValueError naming
    `spec`: an error in a user's model is theirs to fix, not an internal error."""
    try:
        return run()
    except SystemExit as error:
        raise ValueError(f"'{spec}': {what} called sys.exit({error.code!r}); a model maker must return a model") \
            from None
    except Exception as error:  # noqa: BLE001 - any error of the user's code is reported as theirs
        raise ValueError(f"'{spec}': {what} raised {type(error).__name__}: {error}") from error


def read_toml_file(path: str | os.PathLike, what: str = "") -> dict:
    """The dictionary of a TOML file.

    Reads the file as :func:`tomllib.load` does (a scenario or study document).

    Parameters
    ----------
    path : str or os.PathLike
        The TOML file.
    what : str, optional
        Words that name the file in the message, with a trailing space (e.g. ``"the study "``);
        default none.

    Returns
    -------
    dict
        The document: tables as dictionaries, arrays as lists.

    Raises
    ------
    ValueError
        ``cannot read <what>'<path>': <reason>`` for a file that cannot be read,
        ``<path>: <problem>`` for one that is not TOML.

    Examples
    --------
    >>> from hinf_cpp.scenario.documents import read_toml_file
    >>> read_toml_file(hc.scenario_path("paper_fig1"))["controller"]
    {'gamma': 5.0, 'Q': 1.0, 'Qf': 1.0, 'kappa': 1.0}
    >>> read_toml_file("missing.toml", "the study ")
    Traceback (most recent call last):
        ...
    ValueError: cannot read the study 'missing.toml': No such file or directory
    """
    try:
        with open(path, "rb") as f:
            return tomllib.load(f, parse_float=file_float)
    except OSError as error:
        raise ValueError(f"cannot read {what}'{path}': {error.strerror}") from None
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{path}: {error}") from None
    except FloatOverflow as overflow:
        raise ValueError(f"{path}: {overflow}") from None


class FloatOverflow(ValueError):
    """A TOML float literal beyond the range of a double (1e400): the scenario reader refuses it."""

    def __init__(self, literal: str):
        super().__init__(f"Error while parsing floating-point: '{literal}' could not be interpreted as a value (it "
                         "overflows a double; write inf for infinity)")
        self.literal = literal


def file_float(literal: str) -> float:
    """A TOML float literal as the scenario file reader (toml++) reads it, for tomllib's
    ``parse_float``: tomllib gives inf for a literal that overflows (1e400), toml++ refuses it
    (:class:`FloatOverflow`); inf, +inf and -inf are infinite."""
    value = float(literal)
    if math.isinf(value) and literal.lstrip("+-") != "inf":
        raise FloatOverflow(literal)
    return value


def toml_text(document: Any, source: str) -> str:
    """The TOML text of a dictionary.

    A scenario document edited in Python is handed to the C++ reader as this text.

    Parameters
    ----------
    document : dict
        The document: tables as dictionaries, arrays as lists, values str, int, float, bool
        (or dates).
    source : str
        What the document is called in messages (a file name, ``"<dict>"``).

    Returns
    -------
    str
        The TOML text (``tomli_w.dumps``), ending in a newline.

    Raises
    ------
    ValueError
        ``<source>: ...`` for anything but a dictionary, a value TOML cannot hold (None, an
        object) or a dictionary nested too deeply.

    Examples
    --------
    >>> from hinf_cpp.scenario.documents import toml_text
    >>> print(toml_text({"controller": {"gamma": 5.0, "law": "lqr"}}, "<dict>"), end="")
    [controller]
    gamma = 5.0
    law = "lqr"
    >>> toml_text({"gamma": None}, "<dict>")
    Traceback (most recent call last):
        ...
    ValueError: <dict>: not a TOML document: Object of type 'NoneType' is not TOML serializable
    """
    if not isinstance(document, dict):
        raise ValueError(f"{source}: expected a dictionary of TOML values, got {type(document).__name__}")
    try:
        return tomli_w.dumps(document)
    except RecursionError:
        raise ValueError(f"{source}: the dictionary is nested too deeply for a scenario") from None
    except (TypeError, ValueError) as error:
        raise ValueError(f"{source}: not a TOML document: {error}") from None


def resolve_callable(spec: str, base: str | os.PathLike | None = None):
    """The callable named by `spec`: ``"package.module:name"`` or ``"path/to/file.py:name"``.

    A module is imported; a Python file is executed as a module of its own (it need not be on
    ``sys.path``; its folder is appended to ``sys.path`` so that it can import the modules
    beside it). What the file raises while it runs is a ValueError naming `spec`.

    Parameters
    ----------
    spec : str
        ``MODULE:CALLABLE`` or ``FILE.py:CALLABLE``.
    base : str or os.PathLike, optional
        The folder a relative file path is taken from (default: the current folder).

    Returns
    -------
    callable
        The object named, checked to be callable (not called).

    Raises
    ------
    ValueError
        Naming `spec` and what is wrong: no ``:``, no such Python file, a module that cannot
        be imported, no callable of that name.

    Examples
    --------
    >>> from hinf_cpp.scenario.documents import resolve_callable
    >>> resolve_callable("math:hypot")(3.0, 4.0)
    5.0
    >>> resolve_callable("math")
    Traceback (most recent call last):
        ...
    ValueError: 'math': name it as MODULE:CALLABLE or FILE.py:CALLABLE
    """
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
        # Its folder goes on sys.path (at the end: it shadows nothing), so that it can import a
        # module beside it, as `python file.py` could, also when its callable imports later.
        folder = str(path.resolve().parent)
        if folder not in sys.path:
            sys.path.append(folder)
        _user_code(spec, f"running {path}", lambda: module_spec.loader.exec_module(module))
    else:
        try:
            module = importlib.import_module(where)
        except ImportError as error:
            raise ValueError(f"'{spec}': cannot import {where} ({error})") from error
        except Exception as error:  # noqa: BLE001 - the user's module failed while being imported
            raise ValueError(f"'{spec}': importing {where} raised {type(error).__name__}: {error}") from error
    factory = getattr(module, name, None)
    if not callable(factory):
        raise ValueError(f"'{spec}': {where} has no callable '{name}'")
    return factory


def model_from_callable(spec: str, source: str = "") -> _core.Model:
    """The model of ``[model] kind = "python"``: what the callable `spec` makes.

    Python-only: ``hinf-sim`` cannot run such a scenario. The callable `spec` is called with no
    arguments and returns an ``hc.Model`` (a subclass written in Python, or a built-in one) or
    a :class:`hinf_cpp.models.SymbolicModel` (compiled, cached). The scenario reader of the C++
    core calls this function through the hook that :mod:`hinf_cpp.scenario` installs
    (``_core.set_python_model_hook``).

    Parameters
    ----------
    spec : str
        ``MODULE:CALLABLE`` or ``FILE.py:CALLABLE`` (:func:`resolve_callable`), the value of
        ``[model] callable``.
    source : str, optional
        The scenario file: a relative file path in `spec` is taken from its folder (default:
        the current folder).

    Returns
    -------
    hinf_cpp.Model
        The model, a SymbolicModel compiled to a ``hinf_cpp.GeneratedModel``.

    Raises
    ------
    ValueError
        As :func:`resolve_callable`, and for a callable that returns anything else.

    Examples
    --------
    >>> from hinf_cpp.scenario.documents import model_from_callable
    >>> with open("my_model.py", "w") as f:
    ...     _ = f.write("import hinf_cpp as hc\\n\\ndef make():\\n    return hc.ShipModel()\\n")
    >>> model_from_callable("my_model.py:make").name()
    'ship'
    >>> model_from_callable("builtins:list")
    Traceback (most recent call last):
        ...
    ValueError: 'builtins:list' returned list, not an hc.Model or a SymbolicModel
    """
    base = pathlib.Path(source).parent if source and pathlib.Path(source).is_file() else None
    factory = resolve_callable(spec, base)
    model = _user_code(spec, "the call", factory)
    if isinstance(model, _core.Model):
        return model
    from hinf_cpp.models.symbolic import SymbolicModel

    if isinstance(model, SymbolicModel):
        return model.compile()
    raise ValueError(f"'{spec}' returned {type(model).__name__}, not an hc.Model or a SymbolicModel")
