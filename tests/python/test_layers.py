"""The layers of the code, read from its include lines and imports: a file uses only its own layer
and the layers below it.

C++ (cpp/include/hinf/<layer>, cpp/src/<layer>, the bindings cpp/python/bind_<layer>.cpp), from
the bottom: core, numerics, models, control, scenario, io; the programs above them all
(cpp/app, the bindings' module and shared headers). Nothing of the project includes the
deprecated 0.1 paths (cpp/deprecated, hinf/<name>.hpp without a layer).

Python (python/hinf_cpp), from the bottom: the extension _core, models, planning, scenario,
output, then analysis and studies (side by side: neither imports the other), then the command
line. A subpackage imports the top-level package only for _core. Imports inside functions count
as much as those at the top of a module. And ``import hinf_cpp`` stays light: no matplotlib,
pandas, scipy or casadi.
"""

from __future__ import annotations

import ast
import pathlib
import re
import subprocess
import sys

import pytest

pytestmark = pytest.mark.text  # run once per CI, not under the sanitizers (conftest.py)

ROOT = pathlib.Path(__file__).resolve().parents[2]

CPP_LAYERS = ["core", "numerics", "models", "control", "scenario", "io"]
CPP_TOP = len(CPP_LAYERS)  # cpp/app and the bindings' module
PYTHON_LAYERS = {"_core": 0, "models": 1, "planning": 2, "scenario": 3, "output": 4, "analysis": 5, "studies": 5,
                 "cli": 6}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def cpp_layer_of(path: pathlib.Path, root: pathlib.Path) -> int | None:
    """The layer of a C++ file of the project (None for files outside the layered folders)."""
    parts = path.relative_to(root).parts
    if parts[:3] == ("cpp", "include", "hinf") and len(parts) > 4:
        return CPP_LAYERS.index(parts[3]) if parts[3] in CPP_LAYERS else None
    if parts[:2] == ("cpp", "src") and len(parts) > 3:
        return CPP_LAYERS.index(parts[2]) if parts[2] in CPP_LAYERS else None
    if parts[:2] == ("cpp", "python"):
        match = re.fullmatch(r"bind_(\w+)\.cpp", parts[-1])
        return CPP_LAYERS.index(match.group(1)) if match and match.group(1) in CPP_LAYERS else CPP_TOP
    if parts[:2] == ("cpp", "app"):
        return CPP_TOP
    return None


def included_layer(include: str) -> tuple[int | None, bool]:
    """(layer, deprecated) of an included path: "hinf/control/riccati.hpp" and the private
    "control/riccati_kernel.hpp" are layer 'control'; "hinf/riccati.hpp" is a deprecated path."""
    parts = include.split("/")
    if parts[0] == "hinf":
        if len(parts) == 2:
            return None, True
        return (CPP_LAYERS.index(parts[1]) if parts[1] in CPP_LAYERS else None), False
    if parts[0] in CPP_LAYERS and len(parts) == 2:
        return CPP_LAYERS.index(parts[0]), False
    return None, False


def cpp_violations(root: pathlib.Path) -> list[str]:
    found = []
    for path in sorted(root.glob("cpp/**/*.[ch]pp")) + sorted(root.glob("tests/cpp/**/*.[ch]pp")) + sorted(
            root.glob("benchmarks/*.cpp")):
        if path.relative_to(root).parts[:2] == ("cpp", "deprecated"):
            continue
        own = cpp_layer_of(path, root)
        for include in INCLUDE.findall(path.read_text(errors="replace")):
            layer, deprecated = included_layer(include)
            where = f"{path.relative_to(root)}: #include \"{include}\""
            if deprecated:
                found.append(f"{where} is a deprecated 0.1 path: include its layer folder")
            elif own is not None and layer is not None and layer > own:
                name = CPP_LAYERS[own] if own < CPP_TOP else "the programs"
                found.append(f"{where}: {name} includes {CPP_LAYERS[layer]}, a layer above it")
    return found


def python_layer_of(path: pathlib.Path, package: pathlib.Path) -> tuple[str, int] | None:
    parts = path.relative_to(package).parts
    if len(parts) == 1:
        name = parts[0].removesuffix(".py")
        return (name, PYTHON_LAYERS[name]) if name in PYTHON_LAYERS else None
    return (parts[0], PYTHON_LAYERS[parts[0]]) if parts[0] in PYTHON_LAYERS else None


def imported_subpackages(path: pathlib.Path, package: pathlib.Path) -> list[tuple[int, str]]:
    """(line, first part below hinf_cpp) of every import of the package in a module, at any
    depth; relative imports resolved."""
    tree = ast.parse(path.read_text(), filename=str(path))
    here = path.relative_to(package.parent).with_suffix("").parts  # ("hinf_cpp", "scenario", "loading")
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = here[:len(here) - node.level] if path.name != "__init__.py" else here[:len(here) - node.level + 1]
                base = ".".join(anchor + ((base,) if base else ()))
            names = [base] if base != "hinf_cpp" else [f"hinf_cpp.{alias.name}" for alias in node.names]
        else:
            continue
        for name in names:
            parts = name.split(".")
            if parts[0] == "hinf_cpp":
                found.append((node.lineno, parts[1] if len(parts) > 1 else ""))
    return found


def python_violations(root: pathlib.Path) -> list[str]:
    package = root / "python" / "hinf_cpp"
    found = []
    for path in sorted(package.rglob("*.py")):
        if path == package / "__init__.py":
            continue  # the curated namespace: the top of the package
        placed = python_layer_of(path, package)
        if placed is None:
            continue
        own_name, own = placed
        for line, target in imported_subpackages(path, package):
            where = f"{path.relative_to(root)}:{line}"
            if target == own_name:
                continue
            if target not in PYTHON_LAYERS:
                found.append(f"{where} imports hinf_cpp.{target or '(the top-level package)'}: import the "
                             "subpackage that owns the name (the top level is the curated namespace)")
            elif PYTHON_LAYERS[target] >= own:
                found.append(f"{where}: {own_name} imports {target}, "
                             f"{'a layer above it' if PYTHON_LAYERS[target] > own else 'a layer beside it'}")
    return found


def test_cpp_files_include_only_their_layer_and_those_below():
    assert cpp_violations(ROOT) == []


def test_python_modules_import_only_their_layer_and_those_below():
    assert python_violations(ROOT) == []


def test_the_checks_find_a_wrong_include_and_a_wrong_import(tmp_path):
    """Each check on a tree with one deliberate fault of each kind reports exactly those."""
    def write(relative: str, text: str) -> None:
        path = tmp_path / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)

    write("cpp/src/models/ship.cpp", '#include "hinf/models/ship.hpp"\n#include "hinf/control/riccati.hpp"\n')
    write("cpp/src/control/riccati.cpp", '#include "hinf/models/model.hpp"\n#include "numerics/extremum.hpp"\n')
    write("cpp/include/hinf/numerics/signal.hpp", '#include "hinf/core/types.hpp"\n#include "models/parts.hpp"\n')
    write("cpp/python/bind_models.cpp", '#include "hinf/models/ship.hpp"\n#include "hinf/io/results.hpp"\n')
    write("cpp/app/main.cpp", '#include "hinf/io/results.hpp"\n#include "hinf/riccati.hpp"\n')
    assert cpp_violations(tmp_path) == [
        'cpp/app/main.cpp: #include "hinf/riccati.hpp" is a deprecated 0.1 path: include its layer folder',
        'cpp/include/hinf/numerics/signal.hpp: #include "models/parts.hpp": numerics includes models, a layer above it',
        'cpp/python/bind_models.cpp: #include "hinf/io/results.hpp": models includes io, a layer above it',
        'cpp/src/models/ship.cpp: #include "hinf/control/riccati.hpp": models includes control, a layer above it',
    ]

    write("python/hinf_cpp/__init__.py", "from hinf_cpp.scenario import load_scenario\n")
    write("python/hinf_cpp/models/symbolic.py", "from hinf_cpp import _core\n")
    write("python/hinf_cpp/scenario/planned.py", "from hinf_cpp.planning.planner import plan\n")
    write("python/hinf_cpp/output/plotting.py",
          "def f():\n    from hinf_cpp.analysis.compare import run_key\n")
    write("python/hinf_cpp/studies/study.py", "from ..analysis import compare\nimport hinf_cpp.models.codegen\n")
    write("python/hinf_cpp/planning/planner.py", "from hinf_cpp import scenario_path\n")
    assert python_violations(tmp_path) == [
        "python/hinf_cpp/output/plotting.py:2: output imports analysis, a layer above it",
        "python/hinf_cpp/planning/planner.py:1 imports hinf_cpp.scenario_path: import the subpackage that owns the "
        "name (the top level is the curated namespace)",
        "python/hinf_cpp/studies/study.py:1: studies imports analysis, a layer beside it",
    ]


def test_import_hinf_cpp_stays_light():
    """The package and its scenario reader load without the heavy optional libraries."""
    script = ("import sys, hinf_cpp, hinf_cpp.scenario, hinf_cpp.models, hinf_cpp.planning, hinf_cpp.studies\n"
              "print(sorted(m for m in ('matplotlib', 'pandas', 'scipy', 'casadi', 'dask') if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"
