"""Sphinx configuration of the API reference (scripts/build_docs.sh builds it into build/docs/html).

The reference is generated from the docstrings of the installed package: numpydoc renders their
sections. A docstring of the extension begins with the contract of its C++ declaration, the
comment of its header (cpp/python/contracts.hpp): it is shown as written, in a literal block.
Each subpackage's page is generated here from the package's ``__all__`` lists, so that every
public name is documented exactly once, under the name users import it by. The build is strict:
a warning (a reference that does not resolve, a malformed section) fails it (-W -n).
"""

import importlib
import pathlib
import re

import hinf_cpp

project = "hinf_cpp"
release = version = hinf_cpp.__version__
extensions = ["sphinx.ext.autodoc", "numpydoc"]

autodoc_default_options = {"members": True, "undoc-members": True, "member-order": "bysource"}
# A class and its constructor apart: pybind11's constructor signatures then read cleanly.
autodoc_class_signature = "separated"
autodoc_typehints = "none"  # the signatures (pybind11's, Python's) give the types; the sections explain them
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
html_theme = "alabaster"
exclude_patterns = ["_build"]

# Types of other projects that docstrings and signatures name: not links.
nitpick_ignore_regex = [
    (r"py:.*", r"(numpy|np|typing|collections\.abc|pathlib|os|io|matplotlib|pandas|pyarrow|casadi|dask|tomllib)(\..*)?"),
    (r"py:.*", r"(int|float|str|bool|dict|list|tuple|object|None|callable|Callable|Sequence|Mapping|Any|Iterator)"),
]

HERE = pathlib.Path(__file__).resolve().parent
SUBPACKAGES = {
    "scenario": "Scenarios: files, keys set by name, planned trajectories",
    "models": "Models in CasADi symbols, and the built-in vehicles' statements",
    "planning": "Desired trajectories from waypoints",
    "output": "Figures, exports, tables, files, progress",
    "analysis": "Analyses across runs",
    "studies": "Studies",
}


def _write_subpackage_pages() -> None:
    """api/<subpackage>.rst: the subpackage's own names, then each module's names that the
    subpackage does not re-export."""
    folder = HERE / "api"
    folder.mkdir(exist_ok=True)
    for name, title in SUBPACKAGES.items():
        package = importlib.import_module(f"hinf_cpp.{name}")
        heading = f"``hinf_cpp.{name}``: {title}"
        lines = [heading, "=" * len(heading), "", f".. automodule:: hinf_cpp.{name}"]
        # Classes and functions re-exported by the subpackage are documented there; data where it
        # is defined (its documentation comment is there).
        exported = {n for n in getattr(package, "__all__", []) if callable(getattr(package, n))}
        if exported:
            lines.append(f"   :members: {', '.join(sorted(exported))}")
        else:
            lines.append("   :no-members:")
        for path in sorted((pathlib.Path(package.__file__).parent).glob("*.py")):
            if path.name == "__init__.py":
                continue
            module_name = f"hinf_cpp.{name}.{path.stem}"
            module = importlib.import_module(module_name)
            own = [n for n in getattr(module, "__all__", []) if n not in exported]
            lines += ["", f"``{module_name}``", "-" * (len(module_name) + 4), "", f".. automodule:: {module_name}"]
            lines.append(f"   :members: {', '.join(own)}" if own else "   :no-members:")
        (folder / f"{name}.rst").write_text("\n".join(lines) + "\n")


_write_subpackage_pages()

_SECTION = re.compile(r"^(Parameters|Returns|Yields|Raises|Attributes|Examples|Notes|See Also|Methods)$")
_ROLE = re.compile(r":(func|class|meth|data|attr|exc|obj):`(~?)([A-Za-z_][\w.]*)`")


def _prepare_docstring(app, what, name, obj, options, lines):
    """Before numpydoc reads a docstring: the extension's C++ contract (before the numpydoc
    sections) as written, a literal block after its first line (the summary); '|' escaped outside
    examples and literal blocks (|x| is a norm here, not a substitution); a reference by a short
    name ("assess_recovery", "SymbolicModel.export") looked up wherever the name is documented."""
    if not lines:
        return
    from_extension = getattr(obj, "__module__", None) == "hinf_cpp._core" or name.startswith("hinf_cpp._core")
    end = next((i for i in range(len(lines) - 1) if _SECTION.match(lines[i]) and set(lines[i + 1].strip()) == {"-"}),
               len(lines))
    if from_extension and end > 1:
        rest = lines[1:end]
        while rest and not rest[0].strip():
            rest.pop(0)
        while rest and not rest[-1].strip():
            rest.pop()
        lines[:end] = [lines[0], ""] + (["::", ""] + ["    " + line for line in rest] + [""] if rest else [])
    # A paragraph ending with ':' before an indented block (a table, equations) introduces a
    # literal block, as it reads in plain text.
    for i, line in enumerate(lines[:-1]):
        following = next((later for later in lines[i + 1:] if later.strip()), "")
        indent = len(line) - len(line.lstrip())
        if (line.rstrip().endswith(":") and not line.rstrip().endswith("::") and not line.lstrip().startswith(">>>")
                and len(following) - len(following.lstrip()) > indent and lines[i + 1].strip() == ""):
            lines[i] = line.rstrip() + ":"
    literal = False
    for i, line in enumerate(lines):
        if literal and line.strip() and not line.startswith((" ", "\t")):
            literal = False
        if literal or line.lstrip().startswith((">>>", "...")):
            continue
        line = line.replace("|", r"\|")
        lines[i] = _ROLE.sub(lambda m: f":{m.group(1)}:`{m.group(2)}{'' if m.group(3).startswith('hinf_cpp') else '.'}"
                                       f"{m.group(3)}`", line)
        if line.rstrip().endswith("::"):
            literal = True


def _escape_attribute_summaries() -> None:
    """numpydoc describes an Attributes entry that is a documented property by the first sentence
    of the property's docstring, read after _prepare_docstring ran: escape its '|' too (norms such
    as |p - p_d| in the extension's contracts)."""
    from numpydoc.docscrape_sphinx import SphinxDocString

    process = SphinxDocString._process_param

    def process_escaped(self, param, desc, fake_autosummary):
        shown, summary = process(self, param, desc, fake_autosummary)
        if summary is not desc:
            summary = [line.replace("|", r"\|") for line in summary]
        return shown, summary

    SphinxDocString._process_param = process_escaped


_escape_attribute_summaries()


def setup(app):
    app.connect("autodoc-process-docstring", _prepare_docstring, priority=100)
