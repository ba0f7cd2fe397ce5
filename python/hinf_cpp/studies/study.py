"""Studies: many runs of one scenario with some of its keys varied (docs/studies.md).

A study file (TOML) names a base scenario and what varies: grid axes (every combination of
their values) and random axes (drawn ``samples`` times per grid point from one master seed).
:func:`load_study` reads it, :func:`run_study` runs it (locally on all cores with the C++
batch runner, or on a Dask cluster) and returns one row per run as a pandas DataFrame;
:func:`replay` runs any one row alone, :func:`replay_command` gives the ``hinf-cpp run``
command that does the same. Failing runs are rows with a status and a reason.

Seeds: ``SeedSequence(seed).spawn(samples)``; sample j draws its random values, in the order
of the [[random]] axes, from ``numpy.random.default_rng(child j)`` at every grid point (common
random numbers: the grid points are compared on the same noise and plants). Run index: grid
points in row-major order of the [[grid]] axes, samples fastest.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import copy
import dataclasses
import functools
import hashlib
import json
import math
import os
import pathlib
import re
import socket
import tempfile
import threading
import time
from typing import Any, Callable, Self

import numpy as np

from hinf_cpp import _core
from hinf_cpp.scenario import scenario_from_dict
from hinf_cpp.scenario.documents import code_allowed
from hinf_cpp.scenario.documents import read_toml_file
from hinf_cpp.scenario.settings import FEEDBACK_KEY, apply_settings, get_key, key_path, set_key, toml_value

__all__ = [
    "GridAxis",
    "RandomAxis",
    "ClusterError",
    "Study",
    "STATUSES",
    "load_study",
    "local_cores",
    "replay",
    "replay_command",
    "replay_commands",
    "run_study",
    "study_from_dict",
    "study_table_schema",
]

#: What a run's status can be (StudyRun.status), in the order of the summary's columns.
STATUSES = ["completed", "diverged", "lost_track", "conjugate_point", "coupling_violation", "solver_failure",
            "invalid_input", "failed"]
METRIC_NAMES = [definition.name for definition in _core.metric_table()]
SEED_KEY = "measurement.seed"
DISTRIBUTIONS = ("seed", "uniform", "normal")
DEFAULT_CHUNK = 100
#: The most runs a study may have (its table alone would take gigabytes beyond it).
MAX_RUNS = 10 ** 7
#: The most parts of a dotted key in a study or base scenario file, as the C++ scenario reader
#: (cpp/src/io/toml_table.cpp, kMaxKeyParts): Python's TOML reader takes memory quadratic in them.
MAX_KEY_PARTS = 16
_SEED_LIMIT = 2 ** 63


class ClusterError(OSError):
    """A Dask cluster could not finish a study: its workers or the scheduler were lost, or a
    worker cannot compile the study's CasADi model.

    Raised by :func:`run_study`. Finished chunks are kept (with ``out``): the same call, or
    command with the same ``--out``, resumes. An OSError: the command line prints its message
    on one line and exits with status 2.

    Examples
    --------
    >>> from hinf_cpp.studies import ClusterError
    >>> issubclass(ClusterError, OSError)
    True
    >>> print(ClusterError("study mc: the Dask cluster lost the study's tasks (...)"))
    study mc: the Dask cluster lost the study's tasks (...)
    """


# --------------------------------------------------------------------------------------------
# The study file


@dataclasses.dataclass(frozen=True)
class GridAxis:
    """A grid axis of a study ([[grid]] of a study file): keys and their values, point by point.

    ``settings(point)`` gives the (key, value) pairs of one point of the axis.

    Parameters
    ----------
    keys : tuple of str
        The scenario keys set (:mod:`hinf_cpp.scenario.settings`): one, or several set
        together.
    values : tuple
        One value per point; with several keys, each value is a list with one entry per key.

    Examples
    --------
    >>> from hinf_cpp.studies import GridAxis
    >>> axis = GridAxis(("controller.law", "feedback"), (["hinf", "state"], ["lqr", "output"]))
    >>> axis.settings(1)
    [('controller.law', 'lqr'), ('feedback', 'output')]
    """

    keys: tuple[str, ...]
    values: tuple

    def settings(self, point: int) -> list[tuple[str, Any]]:
        value = self.values[point]
        if len(self.keys) == 1:
            return [(self.keys[0], value)]
        return list(zip(self.keys, value))

    def column(self, key: str) -> list:
        """The values of one of its keys, point by point."""
        j = self.keys.index(key)
        return [v if len(self.keys) == 1 else v[j] for v in self.values]


@dataclasses.dataclass(frozen=True)
class RandomAxis:
    """A random axis of a study ([[random]] of a study file): a key and its distribution.

    ``draw(rng)`` draws one value with a ``numpy.random.Generator``: "seed" an integer in
    [0, 2^63), "uniform" a number in [low, high), "normal" a number of mean `mean` and
    standard deviation `std`; with `relative` the number drawn is a factor on `base`.

    Parameters
    ----------
    key : str
        The scenario key set (e.g. ``"plant.d_u"``, ``"measurement.seed"``).
    distribution : str
        ``"seed"``, ``"uniform"`` or ``"normal"``.
    low : float, optional
        Lower end of "uniform" (default 0).
    high : float, optional
        Upper end of "uniform" (default 1).
    mean : float, optional
        Mean of "normal" (default 0).
    std : float, optional
        Standard deviation of "normal" (default 1).
    relative : bool, optional
        The draw is a factor on `base` (default False).
    base : float, optional
        The base value of a relative axis: the key's value in the scenario, or the model's
        parameter (:func:`study_from_dict` finds it).

    Examples
    --------
    >>> from hinf_cpp.studies import RandomAxis
    >>> axis = RandomAxis("plant.d_u", "uniform", low=0.8, high=1.2, relative=True, base=2.0)
    >>> value = axis.draw(np.random.default_rng(0))
    >>> bool(1.6 <= value <= 2.4)
    True
    """

    key: str
    distribution: str
    low: float = 0.0
    high: float = 1.0
    mean: float = 0.0
    std: float = 1.0
    relative: bool = False
    base: float | None = None

    def draw(self, rng: np.random.Generator) -> Any:
        if self.distribution == "seed":
            return int(rng.integers(0, _SEED_LIMIT))
        x = float(rng.uniform(self.low, self.high) if self.distribution == "uniform"
                  else rng.normal(self.mean, self.std))
        return x * self.base if self.relative else x


@dataclasses.dataclass(frozen=True)
class Study:
    """A study: a base scenario and the keys that vary (docs/studies.md).

    Read by :func:`load_study` (or :func:`study_from_dict`). Runs are numbered from 0: grid
    points in row-major order of the grid axes, samples fastest. ``runs``, ``grid_shape``,
    ``grid_points`` and ``columns`` (the axis keys) describe it; ``point(run)``,
    ``settings(run)``, ``document(run)`` and ``scenario(run)`` give one run's place, (key,
    value) pairs, scenario document and :class:`hinf_cpp.Scenario`; ``content_hash()``
    changes with anything that changes the table.

    Parameters
    ----------
    name : str
        The study's name ([study] name, default the file's stem).
    description : str
        [study] description.
    source : str
        The base scenario file (messages, relative paths), or ``"<dict>"``.
    base : dict
        The base scenario's document (as tomllib reads it).
    seed : int
        The master seed of the random axes (>= 0).
    samples : int
        Samples per grid point (random draws).
    grid : tuple of GridAxis
        The grid axes.
    random : tuple of RandomAxis
        The random axes.
    chunk : int
        Runs per task (a chunk of the table; default 100).
    definition : dict
        The study's own document.
    report : dict
        Its [report] table (metrics, figures).
    trust_code : bool, optional
        Whether its scenarios may load or run code (docs/trust.md), decided when the study is
        read; it travels with the study to every worker (default False).
    model_files : dict, optional
        What the runs need of the models the base scenario names as files (``[model]`` and
        ``[plant]``, read with trust): section -> for kind ``"casadi"`` {"file": model.json's
        absolute path, "metadata": its text, "source": the C source beside its library, or
        None}; for kind ``"python"`` naming ``FILE.py:CALLABLE`` {"kind": "python", "file":
        its absolute path, "callable": CALLABLE, "text": the file's text}. A Dask worker
        compiles the source, or writes the Python file, into its own cache and runs that
        model, so no worker needs the model folder (default: none). A Python model file
        travels alone: modules it imports from beside it must be installed on the workers.
    model_arrays : dict, optional
        The array parameters that an axis indexes into (``plant.M[0][0]``) but the base
        scenario does not write, written whole into `base` from the model ("plant.M": the
        matrix); the replay command sets them before the entry (default: none).

    Examples
    --------
    >>> from hinf_cpp.studies import study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> study.runs, study.grid_shape, study.columns
    (2, (2,), ['controller.gamma'])
    >>> study.settings(1)
    [('controller.gamma', 10.0)]
    >>> study.scenario(1).gamma
    10.0
    """

    name: str
    description: str
    source: str
    base: dict
    seed: int
    samples: int
    grid: tuple[GridAxis, ...]
    random: tuple[RandomAxis, ...]
    chunk: int
    definition: dict
    report: dict
    trust_code: bool = False
    model_files: dict = dataclasses.field(default_factory=dict)
    model_arrays: dict = dataclasses.field(default_factory=dict)

    @property
    def grid_shape(self) -> tuple[int, ...]:
        return tuple(len(axis.values) for axis in self.grid)

    @property
    def grid_points(self) -> int:
        return math.prod(self.grid_shape)

    @property
    def runs(self) -> int:
        return self.grid_points * self.samples

    @property
    def columns(self) -> list[str]:
        """The axis columns of the table: every grid key, then every random key."""
        return [key for axis in self.grid for key in axis.keys] + [axis.key for axis in self.random]

    def content_hash(self) -> str:
        """Changes with anything that changes the table: the study's definition, the base
        scenario, the CasADi models it names (their model.json and C source) and the library
        (its version and the compiled core's bytes)."""
        carried = [self.model_files] if self.model_files else []  # a study without: its hash as before
        text = json.dumps([_core.__version__, _core_fingerprint(), self.definition, self.base, self.seed,
                           self.samples, self.chunk, *carried], sort_keys=True, default=repr)
        return hashlib.sha256(text.encode()).hexdigest()

    def point(self, run: int) -> tuple[int, int, tuple[int, ...]]:
        """(grid point, sample, index along each grid axis) of a run index."""
        if not 0 <= run < self.runs:
            raise ValueError(f"run index {run} is outside the study's 0..{self.runs - 1}")
        grid, sample = divmod(run, self.samples)
        return grid, sample, tuple(int(i) for i in np.unravel_index(grid, self.grid_shape)) if self.grid else ()

    def settings(self, run: int) -> list[tuple[str, Any]]:
        """The (key, value) pairs that make run `run` from the base scenario, grid keys first,
        then the random draws of its sample."""
        _, sample, indices = self.point(run)
        settings = [s for axis, i in zip(self.grid, indices) for s in axis.settings(i)]
        if self.random:
            rng = np.random.default_rng(np.random.SeedSequence(self.seed, spawn_key=(sample,)))
            settings += [(axis.key, axis.draw(rng)) for axis in self.random]
        return settings

    def document(self, run: int) -> dict:
        """The scenario document of run `run`."""
        settings = self.settings(run)
        # "feedback" first: a drawn measurement seed of a state-feedback run is then dropped.
        feedback = [s for s in settings if s[0] == FEEDBACK_KEY]
        others = [s for s in settings if s[0] != FEEDBACK_KEY]
        document = apply_settings(self.base, others)
        for key, value in feedback:
            set_key(document, key, value)
        return document

    def scenario(self, run: int) -> _core.Scenario:
        """The scenario of run `run` (read by the one C++ reader)."""
        return scenario_from_dict(self.document(run), self.source, trust_code=self.trust_code)


@functools.lru_cache(maxsize=1)
def _core_fingerprint() -> str:
    """SHA-256 of the compiled core: a rebuilt library may give other rows."""
    with open(_core.__file__, "rb") as f:
        return hashlib.file_digest(f, "sha256").hexdigest()


def _carry_models(base: dict, source: str) -> tuple[dict, dict]:
    """The base document with the model files of its [model] and [plant] made absolute (relative to
    the scenario file's folder, as the readers take them): kind "casadi"'s `file`, kind "python"'s
    FILE.py in `callable`; and what the runs need of those models as content (Study.model_files):
    model.json's text and the C source beside its library (None when there is none), the Python
    file's text."""
    carried = {}
    for section in ("model", "plant"):
        table = base.get(section)
        if isinstance(table, dict) and table.get("kind") == "python" and isinstance(table.get("callable"), str):
            where, _, name = table["callable"].rpartition(":")
            if not where.endswith(".py"):
                continue  # MODULE:CALLABLE: an installed module, the same on every machine
            file = pathlib.Path(where)
            if not file.is_absolute() and os.path.isfile(source):
                file = pathlib.Path(source).parent / file
            file = pathlib.Path(os.path.abspath(file))
            try:
                text = file.read_text()
            except (OSError, UnicodeDecodeError) as error:
                raise ValueError(f"{source}: [{section}] callable: cannot read the model {file}: {error}") from None
            carried[section] = {"kind": "python", "file": os.fspath(file), "callable": name, "text": text}
            base = {**base, section: {**table, "callable": f"{file}:{name}"}}
            continue
        if not (isinstance(table, dict) and table.get("kind") == "casadi" and isinstance(table.get("file"), str)):
            continue
        file = pathlib.Path(table["file"])
        if not file.is_absolute() and os.path.isfile(source):
            file = pathlib.Path(source).parent / file
        file = pathlib.Path(os.path.abspath(file))
        try:
            metadata = file.read_text()
            library = json.loads(metadata)["library"]
            c_file = (file.parent / pathlib.Path(library).name).with_suffix(".c")
            c_source = c_file.read_text() if c_file.is_file() else None
        except (OSError, ValueError, KeyError, TypeError) as error:
            raise ValueError(f"{source}: [{section}] file: cannot read the model {file}: {error}") from None
        carried[section] = {"file": os.fspath(file), "metadata": metadata, "source": c_source}
        base = {**base, section: {**table, "file": os.fspath(file)}}
    return base, carried


# One chunk at a time compiles a carried model (the threads of a Dask worker run chunks at once).
_MATERIALIZE_LOCK = threading.Lock()


def _materialize_model(carried: dict) -> str:
    """model.json of a carried CasADi model in this machine's compile cache (codegen's
    default_cache_dir: $HINF_CPP_CACHE, else ~/.cache/hinf_cpp/casadi), its library compiled there
    from the carried C source on first use by codegen.compile_c_source: the library's name is the
    one compile_casadi_functions gives the same source, so the same model compiles once per machine
    and compiler, and an entry is used only if its recorded hash matches and it loads."""
    from hinf_cpp.models import codegen

    source = carried["source"]
    metadata = json.loads(carried["metadata"])
    name = re.sub(r"-[0-9a-f]{32}$", "", pathlib.Path(metadata["library"]).stem)
    name = name if codegen.C_IDENTIFIER.fullmatch(name) else "hinf_model"
    library = codegen.compile_c_source(source, name, "f").path
    metadata["library"] = library.name
    text = json.dumps(metadata, indent=2) + "\n"
    path = library.with_name(f"{library.stem}.study-{hashlib.sha256(text.encode()).hexdigest()[:16]}.json")
    if not path.exists() or path.read_text() != text:
        codegen._write_atomically(path, lambda temporary: temporary.write_text(text))
    return os.fspath(path)


def _materialize_python_model(carried: dict) -> str:
    """The callable of a carried Python model file, written into this machine's cache under its
    content's hash (a private folder: codegen.make_cache_folder) with the file's own name."""
    from hinf_cpp.models import codegen

    text = carried["text"]
    digest = hashlib.sha256(text.encode()).hexdigest()[:32]
    folder = codegen.default_cache_dir().parent / "python_models" / digest
    codegen.make_cache_folder(folder, "the Python model files of studies",
                              "set HINF_CPP_CACHE to a folder of your own")
    path = folder / pathlib.Path(carried["file"]).name
    if not path.is_file() or path.read_text() != text:
        codegen._write_atomically(path, lambda temporary: temporary.write_text(text))
    return f"{path}:{carried['callable']}"


def _on_this_machine(study: Study) -> Study:
    """The study with the models it carries on this machine: CasADi models compiled here, Python
    model files written here, each named by its absolute path here (a Dask worker's view: its
    working folder and files are not the client's). A CasADi model carried without C source keeps
    its absolute path."""
    base = study.base
    for section, carried in study.model_files.items():
        if carried.get("kind") == "python":
            with _MATERIALIZE_LOCK:
                try:
                    spec = _materialize_python_model(carried)
                except OSError as error:
                    raise ClusterError(f"the Dask worker on {socket.gethostname()} cannot write the [{section}] "
                                       f"model of the study ({carried['file']}) into its cache: {error}") from error
            base = {**base, section: {**base[section], "callable": spec}}
            continue
        if carried.get("source") is None:
            continue
        with _MATERIALIZE_LOCK:  # after the first chunk, a hash and a load of the cached library
            try:
                path = _materialize_model(carried)
            except (OSError, RuntimeError) as error:
                raise ClusterError(f"the Dask worker on {socket.gethostname()} cannot compile the [{section}] model "
                                   f"of the study ({carried['file']}) into its cache: {error}") from error
        base = {**base, section: {**base[section], "file": path}}
    return study if base is study.base else dataclasses.replace(study, base=base)


def _model_parameters(scenario: _core.Scenario, head: str) -> dict:
    """The named parameters of the scenario's plant (head "plant", when it has one) or model:
    numbers by key, a matrix entry as NAME[i][j] (Model.named_parameters())."""
    vehicle = getattr(scenario, "plant", None) if head == "plant" else None
    vehicle = vehicle if vehicle is not None else scenario.model
    if hasattr(vehicle, "named_parameters"):
        return dict(vehicle.named_parameters())
    parameters = vehicle.parameters()
    if not isinstance(parameters, dict):
        parameters = {name: getattr(parameters, name) for name in dir(parameters)
                      if not name.startswith("_") and isinstance(getattr(parameters, name), (int, float))}
    return parameters


def _array_parameter(parameters: dict, name: str) -> list | None:
    """A matrix (or vector) parameter as nested lists from its entries NAME[i][j] (None: none)."""
    entries = {}
    for key, value in parameters.items():
        match = re.fullmatch(re.escape(name) + r"((?:\[\d+\])+)", key)
        if match:
            entries[tuple(int(i) for i in re.findall(r"\d+", match.group(1)))] = float(value)
    if not entries or len({len(index) for index in entries}) != 1:
        return None

    def build(prefix: tuple) -> list:
        depth = len(prefix)
        size = 1 + max(index[depth] for index in entries if index[:depth] == prefix)
        if depth + 1 == len(next(iter(entries))):
            return [entries.get(prefix + (i,), 0.0) for i in range(size)]
        return [build(prefix + (i,)) for i in range(size)]
    return build(())


def _with_model_arrays(base: dict, keys: list[str], source: str, trust_code: bool) -> tuple[dict, dict]:
    """The base document with every array parameter that an axis key indexes into (plant.M[0][0],
    model.D[1][2]) written out whole when the scenario does not write it: for plant.X, [model]'s X
    (when [plant] has the same kind), else the model's own parameter (Model.named_parameters(),
    the kind's default or its preset's). An axis then sets one entry of the model's matrix, and a
    relative axis takes that entry as its base (docs/studies.md). Also the arrays written, by key
    ("plant.M": its value), for the replay command (set before the entry)."""
    scenario = None
    written = {}
    for key in keys:
        try:
            path = key_path(key)
        except ValueError:
            continue  # said where the key is read
        if not (len(path) >= 3 and path[0] in ("plant", "model") and isinstance(path[1], str)
                and isinstance(path[2], int)):
            continue
        head, name = path[0], path[1]
        table = base.get(head) if isinstance(base.get(head), dict) else {}
        if name in table:
            continue
        model = base.get("model") if isinstance(base.get("model"), dict) else {}
        value = None
        if head == "plant" and ("kind" not in table or table.get("kind") == model.get("kind")) and name in model:
            value = copy.deepcopy(model[name])
        else:
            if scenario is None:
                scenario = scenario_from_dict(base, source, trust_code=trust_code)
            value = _array_parameter(_model_parameters(scenario, head), name)
        if value is None:
            continue  # not an array parameter of the model: the reader says what is wrong
        base = {**base, head: {**table, name: value}}
        written[f"{head}.{name}"] = value
    return base, written


def _relative_base(base: dict, scenario: _core.Scenario | None, key: str) -> float:
    """The base value of a relative axis: the key in the scenario; for plant.X, else [model]'s X
    (when [plant] has the same kind), else the model's parameter X (Model.named_parameters(),
    of the plant for plant.X: the kind's default or the preset's)."""
    head, _, rest = key.partition(".")
    candidates = [key]
    plant = base.get("plant") if isinstance(base.get("plant"), dict) else {}
    model = base.get("model") if isinstance(base.get("model"), dict) else {}
    other_kind = "kind" in plant and plant.get("kind") != model.get("kind")
    if head == "plant" and rest and not other_kind:
        candidates.append("model." + rest)
    for candidate in candidates:
        try:
            value = get_key(base, candidate)
        except KeyError:
            continue
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value)
        raise ValueError(f"relative = true: '{candidate}' is {value!r} in the scenario, not a number")
    if head in ("plant", "model") and rest and scenario is not None:
        parameters = _model_parameters(scenario, head)
        if rest in parameters:
            return float(parameters[rest])
        raise ValueError(f"relative = true: the model has no parameter '{rest}' "
                         f"(it has {', '.join(sorted(parameters))})")
    raise ValueError(f"relative = true needs a base value: '{key}' is not in the scenario")


# A token of TOML text: a part of a key (a string, basic or literal, single- or multi-line, or a
# bare word), a dot, blanks and comments, or any other character (a line break, "=", ...).
_TOML_TOKEN = re.compile(r'(?P<part>"""[\s\S]*?(?:"""|\Z)|\'\'\'[\s\S]*?(?:\'\'\'|\Z)|"(?:[^"\\\n]|\\.)*"?'
                         r"|'[^'\n]*'?|[A-Za-z0-9_-]+)|(?P<dot>\.)|(?P<blank>[ \t]+|#[^\n]*)|(?P<other>[\s\S])")


def _read_toml(path: pathlib.Path, what: str = "") -> dict:
    """read_toml_file, after refusing a key of more than MAX_KEY_PARTS dotted parts (outside
    strings and comments) as the C++ reader does: tomllib takes memory quadratic in them (2.4 GB
    for 20 000)."""
    try:
        text = path.read_bytes().decode("utf-8", "replace")
    except OSError:
        text = ""  # read_toml_file says why it cannot be read
    parts, after_dot, line, start = 0, False, 1, 0
    for token in _TOML_TOKEN.finditer(text):
        kind = token.lastgroup
        if kind == "part":
            start = start if after_dot else token.start()
            parts, after_dot = (parts + 1 if after_dot else 1), False
            if parts > MAX_KEY_PARTS:
                raise ValueError(f"{path}:{line}: the key '{text[start:start + 40]}...' has more than "
                                 f"{MAX_KEY_PARTS} dotted parts (tables nested too deeply for a study)")
        elif kind == "dot" and parts and not after_dot:
            after_dot = True
        elif kind != "blank":
            parts, after_dot = 0, False
        line += token.group().count("\n")
    return read_toml_file(path, what)


def _number(table: dict, name: str, where: str, default: float | None = None) -> float:
    value = table.get(name, default)
    if value is None:
        raise ValueError(f"{where}: '{name}' is required")
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"{where}: '{name}' must be a finite number, got {value!r}")
    return float(value)


def _only(table: dict, allowed: set[str], where: str) -> None:
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise ValueError(f"{where}: unknown key '{unknown[0]}' (allowed: {', '.join(sorted(allowed))})")


def study_from_dict(definition: dict, source: str = "<study>", folder: str | os.PathLike | None = None,
                    base: dict | None = None, trust_code: bool | None = None) -> Study:
    """A :class:`Study` from the dictionary form of a study file (docs/studies.md).

    The base scenario is read from [study] scenario (relative to `folder`) unless its
    document `base` is given. Every key and value is checked, and the scenario of run 0 is
    read by the C++ reader, so that a key it refuses is an error here.

    Parameters
    ----------
    definition : dict
        The study document: [study] (name, description, scenario, seed, samples, chunk),
        [[grid]] (key, values), [[random]] (key, distribution, low, high, mean, std,
        relative) and [report].
    source : str, optional
        What the study is called in messages (default ``"<study>"``).
    folder : str or os.PathLike, optional
        The folder a relative [study] scenario is taken from (default: the current one).
    base : dict, optional
        The base scenario's document, instead of reading [study] scenario.
    trust_code : bool, optional
        Whether the base scenario's model may load or run code (as
        :func:`hinf_cpp.load_scenario`; default: ``HINF_TRUST_CODE``, else no).

    Returns
    -------
    Study
        The study.

    Raises
    ------
    ValueError
        Anything wrong with the definition or the base scenario, naming `source`, the table
        and the key.

    Examples
    --------
    >>> from hinf_cpp.studies import study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> study.name, study.runs
    ('gammas', 2)
    >>> study_from_dict({"study": {"scenario": str(hc.scenario_path("paper_fig1"))},
    ...                  "grid": [{"key": "controller.gamma", "value": [5.0]}]})
    Traceback (most recent call last):
        ...
    ValueError: <study>: [[grid]] 1: unknown key 'value' (allowed: key, values)
    """
    where = source
    allow_code = code_allowed(trust_code)
    _only(definition, {"study", "grid", "random", "report"}, where)
    head = definition.get("study")
    if not isinstance(head, dict):
        raise ValueError(f"{where}: a [study] table is required")
    _only(head, {"name", "description", "scenario", "seed", "samples", "chunk"}, f"{where}: [study]")
    scenario_source = "<dict>"
    if base is None:
        if not isinstance(head.get("scenario"), str):
            raise ValueError(f"{where}: [study] scenario (the base scenario file) is required")
        path = pathlib.Path(folder or ".") / head["scenario"]
        try:
            base = _read_toml(path)
        except ValueError as error:
            raise ValueError(f"{where}: [study] scenario: {error}") from None
        scenario_source = os.fspath(path)
    seed = head.get("seed", 0)
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ValueError(f"{where}: [study] seed must be an integer >= 0, got {seed!r}")
    chunk = head.get("chunk", DEFAULT_CHUNK)
    if isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1:
        raise ValueError(f"{where}: [study] chunk must be an integer >= 1, got {chunk!r}")

    grid, seen = [], set()
    for i, table in enumerate(definition.get("grid", [])):
        at = f"{where}: [[grid]] {i + 1}"
        if not isinstance(table, dict):
            raise ValueError(f"{at}: expected a table")
        _only(table, {"key", "values"}, at)
        keys = table.get("key")
        keys = (keys,) if isinstance(keys, str) else tuple(keys) if isinstance(keys, list) else None
        if not keys or not all(isinstance(k, str) for k in keys):
            raise ValueError(f"{at}: 'key' must be a key or a list of keys")
        values = table.get("values")
        if not isinstance(values, list) or not values:
            raise ValueError(f"{at}: 'values' must be a non-empty array")
        if len(keys) > 1 and not all(isinstance(v, list) and len(v) == len(keys) for v in values):
            raise ValueError(f"{at}: with {len(keys)} keys each value is an array of {len(keys)} values")
        for j, key in enumerate(keys):
            if key != FEEDBACK_KEY:
                key_path(key)
            elif not all((v if len(keys) == 1 else v[j]) in ("state", "output") for v in values):
                raise ValueError(f"{at}: feedback values are \"state\" and \"output\"")
            if key in seen:
                raise ValueError(f"{at}: key '{key}' is varied twice")
            seen.add(key)
        axis = GridAxis(keys, tuple(values))
        if "controller.gamma" in keys and not _numbers(axis.column("controller.gamma")):
            raise ValueError(f"{at}: controller.gamma values must be numbers (gamma.png draws them)")
        grid.append(axis)

    random_keys = [table.get("key") for table in definition.get("random", [])
                   if isinstance(table, dict) and isinstance(table.get("key"), str)]
    try:
        base, model_arrays = _with_model_arrays(base, [key for axis in grid for key in axis.keys] + random_keys,
                                                scenario_source, allow_code)
    except ValueError as error:
        raise ValueError(f"{where}: [study] scenario: {error}") from None
    base_scenario = None
    random = []
    for i, table in enumerate(definition.get("random", [])):
        at = f"{where}: [[random]] {i + 1}"
        if not isinstance(table, dict):
            raise ValueError(f"{at}: expected a table")
        _only(table, {"key", "distribution", "low", "high", "mean", "std", "relative"}, at)
        key = table.get("key")
        if not isinstance(key, str):
            raise ValueError(f"{at}: 'key' must be a key like 'plant.d_u'")
        key_path(key)
        if key in seen:
            raise ValueError(f"{at}: key '{key}' is varied twice")
        seen.add(key)
        distribution = table.get("distribution")
        if distribution not in DISTRIBUTIONS:
            raise ValueError(f"{at}: distribution must be one of {', '.join(DISTRIBUTIONS)}, got {distribution!r}")
        relative = table.get("relative", False)
        if not isinstance(relative, bool):
            raise ValueError(f"{at}: 'relative' must be true or false")
        axis = RandomAxis(key, distribution, relative=relative)
        if distribution == "uniform":
            _only(table, {"key", "distribution", "low", "high", "relative"}, at)
            low, high = _number(table, "low", at), _number(table, "high", at)
            if not low <= high:
                raise ValueError(f"{at}: low must be <= high")
            axis = dataclasses.replace(axis, low=low, high=high)
        elif distribution == "normal":
            _only(table, {"key", "distribution", "mean", "std", "relative"}, at)
            std = _number(table, "std", at)
            if std < 0:
                raise ValueError(f"{at}: std must be >= 0")
            axis = dataclasses.replace(axis, mean=_number(table, "mean", at), std=std)
        else:
            _only(table, {"key", "distribution"}, at)
        if relative:
            if base_scenario is None and key.split(".")[0] in ("plant", "model"):
                base_scenario = scenario_from_dict(base, scenario_source, trust_code=allow_code)
            try:
                axis = dataclasses.replace(axis, base=_relative_base(base, base_scenario, key))
            except ValueError as error:
                raise ValueError(f"{at}: {error}") from None
        random.append(axis)
    samples = head.get("samples", 1)
    if isinstance(samples, bool) or not isinstance(samples, int) or samples < 1:
        raise ValueError(f"{where}: [study] samples must be an integer >= 1, got {samples!r}")
    if samples > 1 and not random:
        raise ValueError(f"{where}: [study] samples = {samples} but no [[random]] axis: every sample would be "
                         "the same run")
    runs = math.prod(len(axis.values) for axis in grid) * samples
    if runs > MAX_RUNS:
        raise ValueError(f"{where}: the study has {runs} runs, more than the {MAX_RUNS} a study may have: "
                         "split it into studies of fewer grid points or samples")
    report = _check_report(definition.get("report", {}), grid, seen, f"{where}: [report]")

    study = Study(name=str(head.get("name", pathlib.Path(source).stem)), description=str(head.get("description", "")),
                  source=scenario_source, base=base, seed=seed, samples=samples, grid=tuple(grid),
                  random=tuple(random), chunk=chunk, definition=definition, report=report, trust_code=allow_code,
                  model_arrays=model_arrays)
    study.scenario(0)  # a key the reader refuses, or a value it cannot take, is an error here
    _check_laws(study, where)
    if allow_code:  # the model files it names travel with it: a Dask worker needs neither path nor folder
        base, carried = _carry_models(base, scenario_source)
        study = dataclasses.replace(study, base=base, model_files=carried)
    return study


LAW_KEY = "controller.law"


def _check_laws(study: Study, where: str) -> None:
    """Every value of a controller.law grid axis applies to the study's model: the scenario of run 0
    with only its law changed is read and checked whole (Scenario.validate, as a run does: the
    cascade law is written for the ship alone), so that a law that does not apply is an error
    before any run, not an invalid_input row per run. A problem that run 0 has with its own law
    too is not the law's: its rows say it."""
    document = None
    for number, axis in enumerate(study.grid, start=1):
        if LAW_KEY not in axis.keys:
            continue
        for law in dict.fromkeys(axis.column(LAW_KEY)):
            if document is None:
                document = study.document(0)
                try:
                    study.scenario(0).resolved().validate()
                except ValueError:
                    return  # run 0 is refused whatever its law
            changed = copy.deepcopy(document)
            try:
                set_key(changed, LAW_KEY, law)
                scenario_from_dict(changed, study.source, trust_code=study.trust_code).resolved().validate()
            except ValueError as error:
                model = document.get("model", {}).get("kind") if isinstance(document.get("model"), dict) else None
                model = model or study.scenario(0).model.name()
                raise ValueError(f"{where}: [[grid]] {number}: controller.law = {toml_value(law)} does not apply "
                                 f"to the model '{model}' of the base scenario ({error}): remove "
                                 f"{toml_value(law)} from the values of controller.law, or study that law "
                                 "with a model it is written for") from None


def _numbers(values: list) -> bool:
    return all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values)


def _check_report(report: Any, grid: list[GridAxis], keys: set[str], where: str) -> dict:
    """[report] checked as the study is read (hinf_cpp.studies.report uses it after the runs)."""
    if not isinstance(report, dict):
        raise ValueError(f"{where} must be a table")
    _only(report, {"metrics", "distribution", "roa", "position_tol", "heading_tol", "gamma_metric", "group_by",
                   "heatmap", "heatmap_metric", "units"}, where)
    group_by = report.get("group_by", [])
    if not (isinstance(group_by, list) and all(isinstance(k, str) and k in keys for k in group_by)):
        raise ValueError(f"{where} group_by must list grid or random keys of the study")
    metrics = report.get("metrics", [])
    if not (isinstance(metrics, list) and all(isinstance(name, str) for name in metrics)):
        raise ValueError(f"{where} metrics must be a list of metric names, got {metrics!r}")
    for name in metrics + [report.get("distribution"), report.get("gamma_metric"), report.get("heatmap_metric")]:
        if name is not None and name not in METRIC_NAMES:
            raise ValueError(f"{where}: no metric {name!r} (metrics: {', '.join(METRIC_NAMES)})")
    for name in ("position_tol", "heading_tol"):
        if name in report and _number(report, name, where) <= 0:
            raise ValueError(f"{where}: '{name}' must be > 0, got {report[name]!r}")
    roa = report.get("roa")
    if roa is not None:
        if not (isinstance(roa, list) and len(roa) == 2 and all(isinstance(k, str) and k in keys for k in roa)):
            raise ValueError(f"{where} roa must name two grid keys [x, y]")
        for key in roa:
            values = next((axis.column(key) for axis in grid if key in axis.keys), [])
            if not _numbers(values):
                raise ValueError(f"{where} roa: the values of '{key}' must be numbers (roa.png draws them)")
    heatmap = report.get("heatmap")
    if heatmap is not None:
        axes = [next((i for i, axis in enumerate(grid) if key in axis.keys), None) if isinstance(key, str) else None
                for key in (heatmap if isinstance(heatmap, list) else [])]
        if not (len(axes) == 2 and None not in axes and axes[0] != axes[1]):
            raise ValueError(f"{where} heatmap must name two grid keys of different [[grid]] axes [x, y], "
                             f"got {heatmap!r}")
    units = report.get("units", {})
    if not (isinstance(units, dict) and all(isinstance(unit, str) for unit in units.values())):
        raise ValueError(f"{where} units must be a table of key = \"unit\" (e.g. \"measurement.sigma\" = \"m\")")
    unknown = sorted(set(units) - keys)
    if unknown:
        raise ValueError(f"{where} units: '{unknown[0]}' is not a grid or random key of the study")
    return report


def load_study(path: str | os.PathLike, trust_code: bool | None = None) -> Study:
    """Read a study file (TOML, docs/studies.md).

    Its [study] scenario is taken from the study file's folder when relative.

    Parameters
    ----------
    path : str or os.PathLike
        The study file.
    trust_code : bool, optional
        As :func:`study_from_dict`.

    Returns
    -------
    Study
        The study (:func:`study_from_dict` of the file's document).

    Raises
    ------
    ValueError
        Anything wrong with the file, naming the file and the key (also a study file or base
        scenario that cannot be read).

    Examples
    --------
    >>> from hinf_cpp.studies import load_study
    >>> with open("gammas.toml", "w") as f:
    ...     _ = f.write(f'[study]\\nscenario = "{hc.scenario_path("paper_fig1")}"\\n'
    ...                 '[[grid]]\\nkey = "controller.gamma"\\nvalues = [5.0, 10.0]\\n')
    >>> study = load_study("gammas.toml")
    >>> study.name, study.runs
    ('gammas', 2)
    >>> load_study("missing.toml")
    Traceback (most recent call last):
        ...
    ValueError: cannot read the study 'missing.toml': No such file or directory
    """
    path = pathlib.Path(path)
    return study_from_dict(_read_toml(path, "the study "), os.fspath(path), path.parent, trust_code=trust_code)


# --------------------------------------------------------------------------------------------
# Running


def _batch(scenarios: list, threads: int, progress: Callable[[int, int], None] | None = None) -> list[dict]:
    """Rows of hc.run_scenarios (the C++ batch runner: threads in C++, the GIL released, one design
    per distinct design input) for a list of scenarios."""
    runs = _core.run_scenarios(scenarios, _core.StudyOptions(threads=threads, share_designs=True), progress)
    return [{"status": r.status, "reason": r.reason, "metrics": {name: getattr(r.metrics, name) for name in METRIC_NAMES},
             "gamma": r.gamma, "law": r.law.name, "output_feedback": bool(r.output_feedback)} for r in runs]


def study_table_schema(study: Study):
    """The Arrow schema of a study's table.

    Columns: ``run``, ``grid_point``, ``sample``, ``seed`` (the measurement seed, or null),
    one per axis key (a grid key typed from its values: bool, int64, float64, or string with
    arrays written as TOML text; a random key int64 for "seed", else float64), then ``law``,
    ``output_feedback``, ``gamma``, ``status``, ``reason`` and one float64 per metric
    (:func:`hinf_cpp.metric_table`).

    Parameters
    ----------
    study : Study
        The study.

    Returns
    -------
    pyarrow.Schema
        The schema.

    Examples
    --------
    >>> from hinf_cpp.studies import study_table_schema
    >>> from hinf_cpp.studies import study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> schema = study_table_schema(study)
    >>> schema.names[:6]
    ['run', 'grid_point', 'sample', 'seed', 'controller.gamma', 'law']
    >>> str(schema.field("controller.gamma").type)
    'double'
    """
    import pyarrow as pa

    def grid_type(values) -> pa.DataType:
        if all(isinstance(v, bool) for v in values):
            return pa.bool_()
        if all(isinstance(v, int) and not isinstance(v, bool) for v in values):
            return pa.int64()
        if _numbers(values):
            return pa.float64()
        return pa.string()  # strings; arrays are written as TOML text

    fields = [pa.field("run", pa.int64()), pa.field("grid_point", pa.int64()), pa.field("sample", pa.int64()),
              pa.field("seed", pa.int64())]
    for axis in study.grid:
        for key in axis.keys:
            fields.append(pa.field(key, grid_type(axis.column(key))))
    for axis in study.random:
        fields.append(pa.field(axis.key, pa.int64() if axis.distribution == "seed" else pa.float64()))
    fields += [pa.field("law", pa.string()), pa.field("output_feedback", pa.bool_()), pa.field("gamma", pa.float64()),
               pa.field("status", pa.string()), pa.field("reason", pa.string())]
    fields += [pa.field(name, pa.float64()) for name in METRIC_NAMES]
    return pa.schema(fields)


def _cell(value: Any, arrow_type) -> Any:
    import pyarrow as pa

    if arrow_type == pa.string() and not isinstance(value, str):
        return toml_value(value)
    if arrow_type == pa.float64():
        return float(value)
    return value


def run_chunk(study: Study, start: int, stop: int, threads: int = 0,
              progress: Callable[[int, int], None] | None = None):
    """Runs start..stop-1 of a study (the task of a worker, local or Dask); an Arrow table.
    A run whose scenario the reader refuses is a row with status "invalid_input".
    `progress(done, total)` is hc.run_scenarios's (about every 0.1 s, on this thread)."""
    import pyarrow as pa

    schema = study_table_schema(study)
    scenarios, settings, failed = [], [], {}
    for run in range(start, stop):
        s = study.settings(run)
        settings.append(s)
        try:
            scenarios.append(study.scenario(run))
        except ValueError as error:
            failed[run] = str(error)
    rows = iter(_batch(scenarios, threads, progress))
    columns: dict[str, list] = {field.name: [] for field in schema}
    for run, s in zip(range(start, stop), settings):
        grid, sample, _ = study.point(run)
        if run in failed:
            row = {"status": "invalid_input", "reason": failed[run], "metrics": {}, "gamma": math.nan,
                   "law": "", "output_feedback": False}
            document = None
        else:
            row = next(rows)
        values = dict(s)
        document = study.document(run) if run not in failed else None
        measurement = (document or {}).get("measurement")
        columns["run"].append(run)
        columns["grid_point"].append(grid)
        columns["sample"].append(sample)
        columns["seed"].append(int(measurement.get("seed", 0)) if isinstance(measurement, dict) else None)
        for key in study.columns:
            columns[key].append(_cell(values[key], schema.field(key).type))
        for name in ("law", "output_feedback", "gamma", "status", "reason"):
            columns[name].append(row[name])
        for name in METRIC_NAMES:
            columns[name].append(float(row["metrics"].get(name, math.nan)))
    return pa.table(columns, schema=schema)


def _to_pandas(table):
    import pandas as pd
    import pyarrow as pa

    return table.to_pandas(types_mapper={pa.int64(): pd.Int64Dtype()}.get)


# What the reader says of a file the scenario names (a model.json, its library, a Python model
# file or module) that is missing or unreadable where the run ran: not about the run's values.
_FILE_PROBLEM = re.compile(r"No such file or directory|Permission denied|Input/output error|Stale file handle"
                           r"|Too many open files|cannot load '.*' as a shared library|cannot import ")


def _outside_the_scenario(reason: str | None) -> bool:
    """Whether a run refused as invalid_input was refused for a file that was missing or could
    not be read where it ran (which a resumed study runs again), not for its values."""
    return bool(reason) and _FILE_PROBLEM.search(reason) is not None


_MARKER_TEXT = ("The saved runs of a hinf_cpp study (hinf-cpp study --out, docs/studies.md). A study deletes "
                "and rewrites its chunk files here.\n")


class _Partial:
    """DIR/partial: the saved chunks of a study, so that an interrupted study resumes.

    Its files: MARKER, written as the folder is made (a folder "partial" without it is not a
    study's: it is refused, nothing in it is touched); "lock", held (flock) while a study
    writes, so that a second study on the same folder is refused; "study.json", the content
    hash of the study that wrote last (another hash: its chunks are deleted, the study starts
    over); chunk-NNNNN.parquet, each with its study's content hash in its metadata (a chunk
    with another hash is run again, never mixed in). A study deletes only its chunk files.
    Used with `with`: the lock is held inside."""

    MARKER = "HINF_CPP_STUDY"
    _CHUNK = re.compile(r"chunk-\d{5,}\.parquet")
    _HASH = b"hinf_cpp_study_hash"

    def __init__(self, out: pathlib.Path, study: Study):
        self.folder = out / "partial"
        self.study = study
        self.hash = study.content_hash()
        self.restarted = False
        self._lock = None

    def __enter__(self) -> Self:
        import fcntl

        from hinf_cpp.output.files import write_text

        if not self.folder.exists():
            self._create()
        if self._made_before_the_marker():
            write_text(self.folder / self.MARKER, _MARKER_TEXT)
        if not (self.folder / self.MARKER).is_file():
            raise ValueError(f"{self.folder} is not the partial folder of a hinf_cpp study (it has no file "
                             f"{self.MARKER}); a study saves its runs there and deletes them: move it away or "
                             "choose another output folder")
        self._lock = open(self.folder / "lock", "a")
        try:
            try:
                fcntl.flock(self._lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                raise ValueError(f"another study is writing {self.folder.parent} (it holds "
                                 f"{self.folder / 'lock'}): wait for it to end or choose another output "
                                 "folder") from None
            manifest = self.folder / "study.json"
            try:
                same = json.loads(manifest.read_text())["hash"] == self.hash
            except (OSError, ValueError, KeyError, TypeError):
                same = False
            if not same:
                for path in self.folder.iterdir():
                    if self._CHUNK.fullmatch(path.name) and path.is_file():
                        path.unlink()
                        self.restarted = True
            write_text(manifest, json.dumps({"study": self.study.name, "hash": self.hash, "runs": self.study.runs,
                                             "chunk": self.study.chunk}, indent=2) + "\n")
        except BaseException:
            self._lock.close()
            raise
        return self

    def __exit__(self, *exception) -> None:
        self._lock.close()  # releases the lock (the file stays: deleting it would race)

    def _made_before_the_marker(self) -> bool:
        """A folder of an earlier hinf_cpp, made before the marker: its study.json as they wrote it."""
        try:
            manifest = json.loads((self.folder / "study.json").read_text())
        except (OSError, ValueError):
            return False
        return not (self.folder / self.MARKER).exists() and isinstance(manifest, dict) and \
            set(manifest) == {"study", "hash", "runs", "chunk"}

    def _create(self) -> None:
        """Makes the folder with its marker in one step (made aside, then renamed), so that
        another study never sees it without the marker."""
        self.folder.parent.mkdir(parents=True, exist_ok=True)
        made = pathlib.Path(tempfile.mkdtemp(prefix=".partial-", dir=self.folder.parent))
        (made / self.MARKER).write_text(_MARKER_TEXT)
        try:
            made.rename(self.folder)
        except OSError:  # made meanwhile (by another study), or cannot be
            (made / self.MARKER).unlink()
            made.rmdir()
            if not self.folder.exists():
                raise

    def path(self, chunk: int) -> pathlib.Path:
        return self.folder / f"chunk-{chunk:05d}.parquet"

    def load(self, chunk: int):
        """The saved table of a chunk; None when it is not saved, unreadable or of another
        study; "rerun" when a run of it failed for a reason outside the scenario, which may
        not happen again: a row of status "failed" (an exception that is not about the run's
        values) or an "invalid_input" row whose file was missing or unreadable where it ran
        (:func:`_outside_the_scenario`)."""
        import pyarrow.parquet as pq

        path = self.path(chunk)
        if not path.exists():
            return None
        try:
            table = pq.read_table(path)
        except Exception:  # noqa: BLE001 - an unreadable chunk is run again
            return None
        if (table.schema.metadata or {}).get(self._HASH) != self.hash.encode():
            return None
        if not table.schema.equals(study_table_schema(self.study)):
            return None
        statuses, reasons = table["status"].to_pylist(), table["reason"].to_pylist()
        if any(status == "failed" or (status == "invalid_input" and _outside_the_scenario(reason))
               for status, reason in zip(statuses, reasons)):
            return "rerun"
        return table.replace_schema_metadata(None)

    def save(self, chunk: int, table) -> None:
        import pyarrow.parquet as pq

        from hinf_cpp.output.files import atomic_output

        with atomic_output(self.path(chunk)) as f:
            pq.write_table(table.replace_schema_metadata({self._HASH: self.hash.encode()}), f)


def local_cores() -> int:
    """The number of cores this process may run on (its CPU affinity; at least 1).

    The default number of chunks :func:`run_study` runs at once.

    Returns
    -------
    int
        The cores.

    Examples
    --------
    >>> from hinf_cpp.studies import local_cores
    >>> local_cores() >= 1
    True
    """
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def _worker_threads() -> int:
    """The threads of the Dask worker running this task (1 outside a worker)."""
    try:
        from dask.distributed import get_worker

        return max(1, int(get_worker().state.nthreads))
    except (ImportError, ValueError, AttributeError):
        return 1


def _identity() -> dict:
    """Who runs a chunk: the hinf_cpp version, the compiled core's fingerprint, the host and the
    Dask worker's address (empty outside a worker)."""
    try:
        from dask.distributed import get_worker

        address = str(get_worker().address)
    except (ImportError, ValueError, AttributeError):
        address = ""
    return {"version": _core.__version__, "core": _core_fingerprint(), "host": socket.gethostname(),
            "address": address}


def _dask_chunk(study: Study, start: int, stop: int) -> tuple[Any, dict]:
    """A chunk on a Dask worker: its table, and who ran it (checked by the client)."""
    return run_chunk(_on_this_machine(study), start, stop, _worker_threads()), _identity()


def _checked_result(result: Any, who: Callable[[], str]) -> Any:
    """The table of a Dask chunk's result, after checking that the worker runs this hinf_cpp
    build (the same version and compiled core: another gives other rows); a ValueError naming
    the worker and both versions otherwise. who() names the worker of a result without identity."""
    mine = f"hinf_cpp {_core.__version__} (core {_core_fingerprint()[:12]})"
    if not (isinstance(result, tuple) and len(result) == 2 and isinstance(result[1], dict)):
        raise ValueError(f"the Dask worker {who()} runs another hinf_cpp than this process's {mine} (its chunks "
                         "do not say which): install the same hinf_cpp build on every worker")
    table, worker = result
    if (worker.get("version"), worker.get("core")) != (_core.__version__, _core_fingerprint()):
        raise ValueError(f"the Dask worker {worker.get('address') or who()} on {worker.get('host', '?')} runs "
                         f"hinf_cpp {worker.get('version')} (core {str(worker.get('core'))[:12]}), this process "
                         f"{mine}: their rows could differ; install the same hinf_cpp build on every worker")
    return table


def _holder(client, future) -> str:
    """The address of the worker holding a finished future's result ("?" if unknown)."""
    try:
        return ", ".join(client.who_has([future]).get(future.key, ())) or "?"
    except Exception:  # noqa: BLE001 - only for a message
        return "?"


def _progress_callback(progress) -> tuple[Callable[[int, int, str], None], Callable[[], None]]:
    if callable(progress):
        return progress, lambda: None
    from hinf_cpp.output.progress import Progress

    display = Progress(quiet=not progress)
    return display, display.close


def _eta(started: float, done: int, new: int, total: int) -> str:
    elapsed = time.perf_counter() - started
    if new <= 0 or done >= total:
        return ""
    left = elapsed / new * (total - done)
    return f", {left:.0f} s left" if left < 120 else f", {left / 60:.1f} min left"


def run_study(study: Study | str | os.PathLike, workers: int | None = None, client=None,
              out: str | os.PathLike | None = None, progress: bool | Callable[[int, int, str], None] = True):
    """Run every run of a study into a table with one row per run, in run order.

    The runs are cut into chunks of ``study.chunk`` runs; each chunk runs through
    ``hc.run_scenarios`` (the C++ batch runner), locally or on a Dask cluster. A run that
    fails is a row with its status (:data:`STATUSES`) and reason and NaN metrics; a run
    whose scenario the reader refuses is "invalid_input". A study whose runs all failed still
    returns its table (the command line then exits with status 1).

    Parameters
    ----------
    study : Study or str or os.PathLike
        The study, or the path of a study file.
    workers : int, optional
        Chunks run at once locally, each on one thread of the C++ batch runner (default: all
        cores). Not with `client`.
    client : dask.distributed.Client, optional
        Runs the chunks on this Dask cluster instead (the same table, bit for bit). A CasADi
        model the study carries (``Study.model_files``) is compiled in each worker's own cache.
    out : str or os.PathLike, optional
        Keeps finished chunks in out/partial/ so that an interrupted study resumes where it
        stopped (a study that changed starts over; a chunk of another study, or with a row of
        status "failed" or refused for a missing file, runs again). The folder is locked while the study runs; an
        out/partial that this function did not make is refused, not deleted.
    progress : bool or callable, optional
        True (default): a progress line on a terminal; False: none; a callable is called as
        ``progress(done, total, message)`` after every chunk.

    Returns
    -------
    pandas.DataFrame
        The columns of :func:`study_table_schema` (integers as nullable Int64), then
        ``replay``: the command that runs the row alone (:func:`replay_commands`).
        ``attrs["restarted"]`` is True when saved chunks in `out` were of another study and
        were deleted; ``attrs["reused_chunks"]`` is the number of saved chunks used, of
        ``attrs["chunks"]``, ``attrs["reused_runs"]`` their runs and
        ``attrs["reused_statuses"]`` the statuses of those (status -> count; their
        ``invalid_input`` rows were not run again); ``attrs["rerun_chunks"]`` counts the saved
        chunks run again because a run of theirs failed for a reason outside the scenario
        (status "failed", or a file missing where it ran).

    Raises
    ------
    ValueError
        `workers` with `client`, `workers` not an integer >= 1; out/partial not a study's
        folder, or in use by another study; a Dask worker running another hinf_cpp version or
        core build (naming the worker and both); as :func:`load_study` for a path.
    ClusterError
        The Dask cluster lost the study's tasks (workers or scheduler gone), or a worker cannot
        compile the study's CasADi model (an OSError; finished chunks are kept in `out`, and
        the same call resumes).

    Examples
    --------
    >>> from hinf_cpp.studies import run_study
    >>> from hinf_cpp.studies import study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> table = run_study(study, workers=1, progress=False)
    >>> table[["run", "controller.gamma", "status"]]
       run  controller.gamma     status
    0    0               5.0  completed
    1    1              10.0  completed
    >>> bool((table["final_position_error"] < 0.1).all())
    True
    """
    import pyarrow as pa

    if not isinstance(study, Study):
        study = load_study(study)
    if client is not None and workers is not None:
        raise ValueError("workers is for local runs; a Dask client runs on its cluster's workers")
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise ValueError(f"workers must be an integer >= 1, got {workers!r}")
    chunks = [(start, min(start + study.chunk, study.runs)) for start in range(0, study.runs, study.chunk)]
    with _Partial(pathlib.Path(out), study) if out is not None else contextlib.nullcontext() as partial:
        tables: dict[int, Any] = {}
        rerun_chunks = 0  # saved, but run again: a run failed for a reason outside the scenario
        if partial is not None:
            for index in range(len(chunks)):
                table = partial.load(index)
                if isinstance(table, str):
                    rerun_chunks += 1
                elif table is not None:
                    tables[index] = table
        todo = [index for index in range(len(chunks)) if index not in tables]
        reused_chunks = len(tables)
        reused = [status for table in tables.values() for status in table["status"].to_pylist()]
        reused_statuses = {status: reused.count(status) for status in STATUSES if status in reused}
        callback, close = _progress_callback(progress)
        started, resumed = time.perf_counter(), sum(chunks[i][1] - chunks[i][0] for i in tables)
        lock = threading.Lock()

        def done_runs() -> int:
            return sum(chunks[i][1] - chunks[i][0] for i in tables)

        def show(done: int) -> None:
            callback(done, study.runs, f"study {study.name}: runs done" + _eta(started, done, done - resumed, study.runs))

        def finished(index: int, table) -> None:
            with lock:
                if partial is not None:
                    partial.save(index, table)
                tables[index] = table
                show(done_runs())

        try:
            if client is None:
                # The chunks are tasks, as on Dask: each of `workers` threads runs one chunk at a time
                # through hc.run_scenarios on one C++ thread (which releases the GIL), so that building a
                # chunk's scenarios in Python overlaps the other threads' runs and no core idles at
                # the end of a chunk. After an interruption, chunks still running are not saved.
                running: dict[int, int] = {}  # runs done in the chunks being run (terminal line)

                def inner_progress(index: int):
                    if callable(progress) or not progress:
                        return None  # a callable is called per chunk

                    def inner(done: int, total: int) -> None:
                        with lock:
                            running[index] = done
                            show(done_runs() + sum(running.values()))
                    return inner

                threads = min(workers or local_cores(), max(1, len(todo)))
                with concurrent.futures.ThreadPoolExecutor(max_workers=threads) as pool:
                    tasks = {pool.submit(run_chunk, study, *chunks[index], 1, inner_progress(index)): index
                             for index in todo}
                    try:
                        for task in concurrent.futures.as_completed(tasks):
                            index = tasks[task]
                            table = task.result()
                            with lock:
                                running.pop(index, None)
                            finished(index, table)
                    except BaseException:
                        for task in tasks:
                            task.cancel()
                        raise
            else:
                import uuid

                from dask.distributed import as_completed
                from distributed import KilledWorker
                from distributed.client import ClosedClientError
                from distributed.comm import CommClosedError

                # Keys unique to this call: a second run of the same study on the same client must
                # not meet the first one's futures while the scheduler releases them.
                remote = client.scatter(study, broadcast=True, hash=False)
                key = f"study-{study.content_hash()[:12]}-{uuid.uuid4().hex[:8]}"
                futures = {client.submit(_dask_chunk, remote, *chunks[index], key=f"{key}-{index}", pure=False): index
                           for index in todo}
                try:
                    for future in as_completed(futures):
                        try:
                            result = future.result()
                        except (concurrent.futures.CancelledError, KilledWorker, CommClosedError, ClosedClientError,
                                TimeoutError, ClusterError) as error:
                            # Lost workers or scheduler (every task cancelled), or a worker that cannot build
                            # the study's model: not an internal error, and resumable.
                            kept = (f"the {len(tables)} finished chunks are kept in {partial.folder}: run the same "
                                    f"command with the same --out (or run_study with the same out) to resume"
                                    if partial is not None else "pass --out (out=) to keep finished chunks")
                            detail = str(error) if isinstance(error, ClusterError) else \
                                f"the Dask cluster lost the study's tasks ({type(error).__name__}: {error})"
                            raise ClusterError(f"study {study.name}: {detail.rstrip('.')}; {kept}") from error
                        finished(futures[future], _checked_result(result, functools.partial(_holder, client, future)))
                except BaseException:
                    with contextlib.suppress(Exception):  # a closed client cannot cancel
                        client.cancel(list(futures))
                    raise
        finally:
            close()
    table = pa.concat_tables([tables[i] for i in range(len(chunks))]) if chunks else \
        study_table_schema(study).empty_table()
    frame = _to_pandas(table)
    frame["replay"] = replay_commands(study)
    frame.attrs["restarted"] = bool(partial is not None and partial.restarted)
    frame.attrs["reused_chunks"] = reused_chunks
    frame.attrs["reused_statuses"] = reused_statuses
    frame.attrs["reused_runs"] = int(sum(reused_statuses.values()))
    frame.attrs["rerun_chunks"] = rerun_chunks
    frame.attrs["chunks"] = len(chunks)
    return frame


# --------------------------------------------------------------------------------------------
# Replaying one run


def replay(study: Study | str | os.PathLike, run: int) -> _core.RunResult:
    """Run one run of a study alone: the same metrics as its row of :func:`run_study`.

    Parameters
    ----------
    study : Study or str or os.PathLike
        The study, or the path of a study file.
    run : int
        The run index (0-based, the table's ``run`` column).

    Returns
    -------
    hinf_cpp.RunResult
        The result of :func:`hinf_cpp.run_scenario` on the run's scenario.

    Raises
    ------
    ValueError
        A run index outside the study, or a scenario the reader refuses.
    hinf_cpp.HinfError
        The run failed numerically (its row has the status).

    Examples
    --------
    >>> from hinf_cpp.studies import replay
    >>> from hinf_cpp.studies import study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> result = replay(study, 1)
    >>> result.gamma, round(result.metrics.final_position_error, 3)
    (10.0, 0.057)
    """
    if not isinstance(study, Study):
        study = load_study(study)
    return _core.run_scenario(study.scenario(run))


def replay_command(study: Study, run: int, scenario: str | None = None) -> str:
    """The ``hinf-cpp run`` command that runs one run of a study alone.

    ``--set KEY=VALUE`` for each value of its row (floats written exactly), "feedback" last,
    and ``--seed N`` for a drawn measurement seed (left out for a state-feedback run, which
    has no noise); first, ``--set`` of each array parameter that the study wrote whole into
    its base scenario (``Study.model_arrays``: an axis ``plant.M[0][0]`` of a scenario that
    does not write M).

    Parameters
    ----------
    study : Study
        The study.
    run : int
        The run index (0-based).
    scenario : str, optional
        The scenario file as written in the command (default ``study.source``).

    Returns
    -------
    str
        The command, its arguments quoted for a POSIX shell.

    Raises
    ------
    ValueError
        A run index outside the study.

    Examples
    --------
    >>> from hinf_cpp.studies import replay_command
    >>> from hinf_cpp.studies import study_from_dict
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> replay_command(study, 1, scenario="paper_fig1.toml")
    'hinf-cpp run paper_fig1.toml --set controller.gamma=10.0'
    """
    import shlex

    document = study.document(run)
    settings = study.settings(run)
    parts = ["hinf-cpp", "run", shlex.quote(scenario or study.source), *_set_arguments(study.model_arrays.items())]
    ordered = [s for s in settings if s[0] != FEEDBACK_KEY] + [s for s in settings if s[0] == FEEDBACK_KEY]
    parts += _set_arguments(ordered)
    if any(key == SEED_KEY for key, _ in settings) and "measurement" in document:
        parts += ["--seed", str(document["measurement"]["seed"])]
    return " ".join(parts)


def _inline_toml(value: Any) -> str:
    """A value as TOML text on one line (``--set`` takes one line): arrays inline."""
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_inline_toml(v) for v in value) + "]"
    return toml_value(value)


def _set_arguments(settings) -> list[str]:
    """``--set KEY=VALUE`` arguments of (key, value) pairs, quoted for a POSIX shell; the
    measurement seed is left to ``--seed``."""
    import shlex

    return [part for key, value in settings if key != SEED_KEY
            for part in ("--set", shlex.quote(f"{key}={_inline_toml(value)}"))]


def replay_commands(study: Study, scenario: str | None = None) -> list[str]:
    """:func:`replay_command` of every run of a study, in run order (the table's ``replay``
    column).

    The same text as ``replay_command(study, run, scenario)`` for each run, made from the
    settings of each grid point and of each sample once (a study of 1000 samples at 3 grid
    points makes 3 + 1000 pieces, not 3000 documents).

    Parameters
    ----------
    study : Study
        The study.
    scenario : str, optional
        The scenario file as written in the commands (default ``study.source``).

    Returns
    -------
    list of str
        One command per run.

    Examples
    --------
    >>> from hinf_cpp.studies import study_from_dict
    >>> from hinf_cpp.studies.study import replay_commands
    >>> study = study_from_dict({
    ...     "study": {"name": "gammas", "scenario": str(hc.scenario_path("paper_fig1"))},
    ...     "grid": [{"key": "controller.gamma", "values": [5.0, 10.0]}]})
    >>> for command in replay_commands(study, scenario="paper_fig1.toml"):
    ...     print(command)
    hinf-cpp run paper_fig1.toml --set controller.gamma=5.0
    hinf-cpp run paper_fig1.toml --set controller.gamma=10.0
    """
    import shlex

    head = " ".join(["hinf-cpp", "run", shlex.quote(scenario or study.source),
                     *_set_arguments(study.model_arrays.items())])
    # run = grid point x samples + sample: the grid keys' part once per grid point, the random
    # keys' part once per sample, "feedback" last, --seed when the run keeps [measurement].
    seeded = SEED_KEY in study.columns
    points = []
    for point in range(study.grid_points):
        run = point * study.samples
        settings = study.settings(run)
        settings = settings[:len(settings) - len(study.random)]
        measured = seeded and "measurement" in study.document(run)
        points.append((" ".join(_set_arguments([s for s in settings if s[0] != FEEDBACK_KEY])),
                       " ".join(_set_arguments([s for s in settings if s[0] == FEEDBACK_KEY])),
                       measured, dict(settings).get(SEED_KEY)))
    samples = []
    for sample in range(study.samples):
        settings = study.settings(sample)  # grid point 0: its random draws are those of every grid point
        drawn = settings[len(settings) - len(study.random):]
        samples.append((" ".join(_set_arguments(drawn)), dict(drawn).get(SEED_KEY)))
    commands = []
    for grid_part, feedback_part, measured, grid_seed in points:
        for random_part, drawn_seed in samples:
            seed = drawn_seed if drawn_seed is not None else grid_seed
            parts = (head, grid_part, random_part, feedback_part, f"--seed {seed}" if measured else "")
            commands.append(" ".join(part for part in parts if part))
    return commands
