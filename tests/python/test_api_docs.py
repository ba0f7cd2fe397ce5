"""Every public name documents itself: a numpydoc docstring with its parameters and an example,
and the examples run.

The public names are those of ``hinf_cpp.__all__`` (the curated namespace, mostly the C++ core)
and of the ``__all__`` of every module of the subpackages (scenario, models, planning, studies,
analysis, output). For each function and class:
  * a docstring whose first paragraph says what it is;
  * a ``Parameters`` section naming every parameter of its signature (the constructor's for a
    class; pybind11's signature line for the extension's functions), when it has any;
  * an ``Examples`` section with at least one ``>>>`` line;
and every example runs (doctest, with ``hc`` = hinf_cpp and ``np`` = numpy already imported)
and prints what it says. Constants are exempt.
"""

from __future__ import annotations

import doctest
import enum
import importlib
import inspect
import pathlib
import re

import numpy as np
import pytest

import hinf_cpp as hc

pytestmark = pytest.mark.text  # run once per CI, not under the sanitizers (conftest.py)

ROOT = pathlib.Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "python" / "hinf_cpp"
SUBPACKAGES = ("scenario", "models", "planning", "studies", "analysis", "output")


def subpackage_modules() -> list[str]:
    names = []
    for sub in SUBPACKAGES:
        for path in sorted((PACKAGE / sub).glob("*.py")):
            names.append(f"hinf_cpp.{sub}" if path.name == "__init__.py" else f"hinf_cpp.{sub}.{path.stem}")
    return names


def public_objects() -> list[tuple[str, object]]:
    """(qualified name, object) of every public function and class, each object once (the
    first place it is listed: the top-level namespace, then the subpackages)."""
    found, seen = [], set()
    for module_name in ["hinf_cpp", *subpackage_modules()]:
        module = importlib.import_module(module_name)
        for name in getattr(module, "__all__", []):
            obj = getattr(module, name)
            routine = inspect.isclass(obj) or inspect.isfunction(obj) or inspect.isbuiltin(obj)
            if not routine or id(obj) in seen:  # constants and type aliases are exempt
                continue
            seen.add(id(obj))
            found.append((f"{module_name}.{name}", obj))
    return found


OBJECTS = public_objects()


def section(doc: str, title: str) -> str | None:
    """The body of a numpydoc section (``Title`` underlined by dashes), or None."""
    match = re.search(rf"^\s*{title}\n\s*-{{{len(title)}}}\n(.*?)(?=^\s*\w[\w ]*\n\s*-{{3,}}\n|\Z)", doc,
                      flags=re.M | re.S)
    return match.group(1) if match else None


def parameter_names(obj) -> list[str]:
    """The parameters a user passes: of the signature (the constructor's for a class), or, for
    the extension's functions and classes, of pybind11's signature lines."""
    target = obj.__init__ if inspect.isclass(obj) else obj
    try:
        signature = inspect.signature(target)
        names = [p.name for p in signature.parameters.values()
                 if p.name not in ("self", "cls") and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
        return names
    except (TypeError, ValueError):
        pass
    doc = getattr(target, "__doc__", None) or ""
    names = []
    for line in doc.splitlines():
        match = re.match(r"^\s*(?:\d+\. )?\w+\((.*)\) -> ", line)
        if not match:
            continue
        for part in top_level_parts(match.group(1)):
            name = part.split(":")[0].split("=")[0].strip()
            if name and name not in ("self", "*", "/") and name not in names:
                names.append(name)
    return names


def top_level_parts(arguments: str) -> list[str]:
    """`arguments` split at the commas outside brackets, parentheses and quotes: a type such as
    ``Annotated[ArrayLike, float64, "[m, n]"]`` or a default such as ``SolverOptions(rtol=1e-08,
    ...)`` stays one part."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(arguments):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(arguments[start:i])
            start = i + 1
    parts.append(arguments[start:])
    return parts


def documented(obj) -> str:
    return inspect.getdoc(obj) or ""


@pytest.mark.parametrize("name,obj", OBJECTS, ids=[name for name, _ in OBJECTS])
def test_every_public_name_has_a_numpydoc_docstring_with_an_example(name, obj):
    doc = documented(obj)
    assert doc.strip(), f"{name} has no docstring"
    examples = section(doc, "Examples")
    assert examples is not None and ">>> " in examples, f"{name}: no Examples section with a >>> line"
    if isinstance(obj, type) and issubclass(obj, (enum.Enum, BaseException)):
        return  # an enum's members and an exception's attributes are described in its text
    names = parameter_names(obj)
    if names:
        parameters = section(doc, "Parameters")
        assert parameters is not None, f"{name}: no Parameters section (parameters {names})"
        missing = [p for p in names if not re.search(rf"^\s*{re.escape(p)}\b", parameters, flags=re.M)]
        assert not missing, f"{name}: the Parameters section does not describe {missing}"


@pytest.mark.parametrize("name,obj", OBJECTS, ids=[name for name, _ in OBJECTS])
def test_the_examples_run(name, obj, tmp_path, monkeypatch):
    """Each example in the docstring runs and prints what it shows (from a scratch folder, with
    hc and np imported)."""
    monkeypatch.chdir(tmp_path)
    finder = doctest.DocTestFinder(recurse=False)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    tests = finder.find(obj, name, globs={"hc": hc, "np": np})
    assert tests and any(t.examples for t in tests), f"{name}: no example to run"
    for test in tests:
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{name}: {result.failed} of {result.attempted} example lines failed (output above)"
