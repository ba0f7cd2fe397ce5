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
import os
import pathlib
import tomllib
from typing import Any

import tomli_w

from hinf_cpp import _core

__all__ = ["model_from_callable", "read_toml_file", "resolve_callable", "toml_text"]


def read_toml_file(path: str | os.PathLike, what: str = "") -> dict:
    """The dictionary of a TOML file. ValueError "cannot read <what>'<path>': <reason>" for a
    file that cannot be read, "<path>: <problem>" for one that is not TOML."""
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except OSError as error:
        raise ValueError(f"cannot read {what}'{path}': {error.strerror}") from None
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{path}: {error}") from None


def toml_text(document: Any, source: str) -> str:
    """The TOML text of a dictionary; ValueError naming `source` for what TOML cannot hold."""
    if not isinstance(document, dict):
        raise ValueError(f"{source}: expected a dictionary of TOML values, got {type(document).__name__}")
    try:
        return tomli_w.dumps(document)
    except RecursionError:
        raise ValueError(f"{source}: the dictionary is nested too deeply for a scenario") from None
    except (TypeError, ValueError) as error:
        raise ValueError(f"{source}: not a TOML document: {error}") from None


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
    or a built-in one) or a hinf_cpp.models.SymbolicModel (compiled, cached). A relative file
    path is taken from the scenario file's folder. The scenario reader of the C++ core calls it
    through the hook that :mod:`hinf_cpp.scenario` installs (``_core.set_python_model_hook``)."""
    base = pathlib.Path(source).parent if source and pathlib.Path(source).is_file() else None
    model = resolve_callable(spec, base)()
    if isinstance(model, _core.Model):
        return model
    from hinf_cpp.models.symbolic import SymbolicModel

    if isinstance(model, SymbolicModel):
        return model.compile()
    raise ValueError(f"'{spec}' returned {type(model).__name__}, not an hc.Model or a SymbolicModel")
