"""Exports of a run: NPZ (every time series, metrics and metadata), tidy CSV, the JSON results file.

Time series of a run (:func:`time_series`), one row per output time, k rows:

    t (k,)              output grid, s
    q, q_d, q_e (k, n)  actual, desired and error state (q_e = q - q_d)
    u, u_d (k, m)       applied and desired input
    w (k, nw)           applied disturbance (signals, worst case, measurement noise)
    z_min_eig, z_max_eig (k,)  extreme eigenvalues of the design's Z(t) at the grid times
    q_hat (k, n), y (k, p), sigma_min_eig, sigma_max_eig, rho_sigma_z (k,)
                        output feedback only (absent for state feedback)

NPZ (:func:`save_npz`, compressed, readable with ``numpy.load(path, allow_pickle=False)``):
those arrays under their names, ``Z`` (k, n, n) = Z(t) at the grid times, and ``meta``, a 0-d
string array holding JSON: ``format``, ``results`` (the results file, ``results_json(result)``:
scenario, gamma, Z0, metrics, timing), ``components`` (the column names of every 2-D series)
and the model's ``state_names``, ``position_indices`` and ``heading_index``. The round trip
through :func:`load_npz` is exact.

Tidy CSV (:func:`save_csv`): LONG format, header ``t,variable,value``, one row per time and
series component; ``variable`` is ``<series>.<component>`` for 2-D series (``q.x``,
``q_d.psi``, ``u.u1``, ``w.w3``, ``q_hat.y``, ``y.psi``) and the series name for 1-D ones
(``z_min_eig``, ``rho_sigma_z``); rows are grouped by variable, in time order within each. Numbers
are written with ``repr`` (the shortest text that reads back to the same double: the round
trip is exact) or, with ``digits``, to that many significant digits. ``Z`` is left out of the
CSV (36 series for the ship; use the NPZ).
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import os
import pathlib
from typing import Any

import numpy as np

from hinf_cpp import _core
from hinf_cpp.output.files import atomic_output, write_text

__all__ = ["FORMAT", "RunData", "component_names", "load_csv", "load_json", "load_npz", "npz_path",
           "save_csv", "save_json", "save_npz", "time_series"]

#: The format name that an exported run carries (NPZ, JSON).
FORMAT = "hinf_cpp-run/1"


@dataclasses.dataclass
class RunData:
    """Arrays and metadata read back from an export (:func:`load_npz`, :func:`load_csv`).

    ``data[name]`` is the array of that name, ``name in data`` whether there is one.

    Parameters
    ----------
    arrays : dict of str to numpy.ndarray
        The time series by name (module docstring): ``t`` (k,), ``q`` (k, n), ...; from an
        NPZ also ``Z`` (k, n, n).
    meta : dict
        The metadata: from an NPZ ``format``, ``results`` (the results file), ``components``,
        ``state_names``, ``position_indices``, ``heading_index``; from a CSV ``components``.

    Examples
    --------
    >>> from hinf_cpp.output.export import load_npz, save_npz
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> data = load_npz(save_npz(result, "run.npz"))
    >>> data["q"].shape, data["Z"].shape, "q_hat" in data
    ((4001, 6), (4001, 6, 6), False)
    >>> data.meta["state_names"], data.meta["results"]["gamma"]
    (['u', 'v', 'r', 'x', 'y', 'psi'], 5.0)
    """

    arrays: dict[str, np.ndarray]
    meta: dict[str, Any]

    def __getitem__(self, name: str) -> np.ndarray:
        return self.arrays[name]

    def __contains__(self, name: str) -> bool:
        return name in self.arrays


def _output_names(model: _core.Model, t0: float, p: int) -> list[str]:
    """Names of the measured outputs: the state measured when a row of C picks one state."""
    states = model.state_names()
    names = []
    try:
        C = np.asarray(model.C(t0))
    except Exception:  # noqa: BLE001 - a model without C: generic names
        C = np.zeros((0, 0))
    for i in range(p):
        row = C[i] if i < C.shape[0] else None
        if row is not None and np.count_nonzero(row) == 1 and row[np.flatnonzero(row)[0]] == 1.0:
            names.append(states[int(np.flatnonzero(row)[0])])
        else:
            names.append(f"y{i + 1}")
    return names if len(set(names)) == len(names) else [f"y{i + 1}" for i in range(p)]


def component_names(result: _core.RunResult) -> dict[str, list[str]]:
    """Column names of the 2-D series of :func:`time_series`.

    The model's state names for ``q``, ``q_d``, ``q_e`` (and ``q_hat``), ``u1``, ``u2``, ...
    for ``u`` and ``u_d``, ``w1``, ... for ``w``, and for ``y`` the state a row of C picks
    (``y1``, ... otherwise).

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.

    Returns
    -------
    dict of str to list of str
        The names by series.

    Examples
    --------
    >>> from hinf_cpp.output.export import component_names
    >>> names = component_names(hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig2"))))
    >>> names["q"], names["u"], names["y"]
    (['u', 'v', 'r', 'x', 'y', 'psi'], ['u1', 'u2'], ['x', 'y', 'psi'])
    """
    model = result.trajectory.model()
    sim = result.simulation
    states = list(model.state_names())
    names = {"q": states, "q_d": states, "q_e": states,
             "u": [f"u{i + 1}" for i in range(np.shape(sim.u)[1])],
             "u_d": [f"u{i + 1}" for i in range(np.shape(sim.u_d)[1])],
             "w": [f"w{i + 1}" for i in range(np.shape(sim.w)[1])]}
    if sim.estimator is not None:
        names["q_hat"] = states
        names["y"] = _output_names(model, float(sim.t[0]), np.shape(sim.estimator.y)[1])
    return names


def time_series(result: _core.RunResult) -> dict[str, np.ndarray]:
    """Every time series of a run (module docstring), as NumPy arrays.

    On the output grid of k times: ``t`` (s), ``q``, ``q_d``, ``q_e`` = q - q_d, ``u``,
    ``u_d``, ``w``, ``z_min_eig`` and ``z_max_eig`` (NaN without a design); for output
    feedback also ``q_hat``, ``y``, ``sigma_min_eig``, ``sigma_max_eig``, ``rho_sigma_z``.

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.

    Returns
    -------
    dict of str to numpy.ndarray
        The series by name, shape (k,) or (k, columns).

    Examples
    --------
    >>> from hinf_cpp.output.export import time_series
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> series = time_series(result)
    >>> list(series)
    ['t', 'q', 'q_d', 'q_e', 'u', 'u_d', 'w', 'z_min_eig', 'z_max_eig']
    >>> series["t"].shape, series["q"].shape, series["u"].shape
    ((4001,), (4001, 6), (4001, 2))
    """
    sim = result.simulation
    t = np.asarray(sim.t, dtype=float)
    series = {"t": t, "q": np.asarray(sim.q), "q_d": np.asarray(sim.q_d), "q_e": sim.q_e(),
              "u": np.asarray(sim.u), "u_d": np.asarray(sim.u_d), "w": np.asarray(sim.w)}
    if result.solution is not None:
        eig = np.linalg.eigvalsh(_symmetric(result.solution.Z(t)))
        series["z_min_eig"] = eig[:, 0]
        series["z_max_eig"] = eig[:, -1]
    else:  # the cascade law with state feedback at a gamma without design
        series["z_min_eig"] = series["z_max_eig"] = np.full_like(t, np.nan)
    if sim.estimator is not None:  # the estimator's time series (its array fields)
        for name in sim.estimator.__match_args__:
            value = np.asarray(getattr(sim.estimator, name))
            if value.ndim > 0:
                series[name] = value
    return series


def _symmetric(Z: np.ndarray) -> np.ndarray:
    return 0.5 * (Z + np.swapaxes(Z, -1, -2))


def _meta(result: _core.RunResult) -> dict[str, Any]:
    model = result.trajectory.model()
    return {
        "format": FORMAT,
        "results": json.loads(_core.results_json(result)),
        "components": component_names(result),
        "state_names": list(model.state_names()),
        "position_indices": list(model.position_indices()),
        "heading_index": int(model.heading_index()),
    }


def npz_path(path: str | pathlib.Path) -> pathlib.Path:
    """The file :func:`save_npz` writes for `path`.

    `path` itself, with ``.npz`` appended when it has another suffix (as
    ``numpy.savez_compressed`` names files).

    Parameters
    ----------
    path : str or pathlib.Path
        The path asked for.

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    ValueError
        An empty path.

    Examples
    --------
    >>> from hinf_cpp.output.export import npz_path
    >>> str(npz_path("run")), str(npz_path("run.npz")), str(npz_path("run.v1"))
    ('run.npz', 'run.npz', 'run.v1.npz')
    """
    if os.fspath(path) == "":
        raise ValueError("an output file name is empty")
    path = pathlib.Path(path)
    return path if path.suffix == ".npz" else path.with_name(path.name + ".npz")


def save_npz(result: _core.RunResult, path: str | pathlib.Path) -> pathlib.Path:
    """Write every time series, Z(t) on the grid and the metadata to a compressed NPZ.

    The metadata is JSON; the file is written whole or not at all. ``.npz`` is appended to a name
    without it (:func:`npz_path`). The file reads with ``numpy.load(path, allow_pickle=False)``;
    :func:`load_npz` reads it back exactly.

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.
    path : str or pathlib.Path
        The file.

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    ValueError
        A path that cannot be written (empty, a directory, below a plain file).
    OSError
        The file could not be written.

    Examples
    --------
    >>> from hinf_cpp.output.export import save_npz
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> path = save_npz(result, "run")
    >>> str(path)
    'run.npz'
    >>> with np.load(path, allow_pickle=False) as data:
    ...     data["Z"].shape
    (4001, 6, 6)
    """
    path = npz_path(path)
    arrays = time_series(result)
    if result.solution is not None:
        arrays["Z"] = np.asarray(result.solution.Z(arrays["t"]))
    arrays["meta"] = np.array(json.dumps(_meta(result)))
    with atomic_output(path) as handle:
        np.savez_compressed(handle, **arrays)
    return path


def load_npz(path: str | pathlib.Path) -> RunData:
    """Read a file of :func:`save_npz`: the arrays (exactly as written) and the metadata.

    Parameters
    ----------
    path : str or pathlib.Path
        The NPZ file.

    Returns
    -------
    RunData
        The arrays and the metadata (``meta``: format, results file, components, state names,
        position and heading indices).

    Raises
    ------
    ValueError
        A file without the metadata, or of another format.
    OSError
        A file that cannot be read.

    Examples
    --------
    >>> from hinf_cpp.output.export import load_npz, save_npz
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> data = load_npz(save_npz(result, "run.npz"))
    >>> bool(np.array_equal(data["q"], result.simulation.q)), data.meta["format"]
    (True, 'hinf_cpp-run/1')
    """
    with np.load(pathlib.Path(path), allow_pickle=False) as data:
        if "meta" not in data.files:
            raise ValueError(f"{path}: not a hinf_cpp run export (no 'meta' entry)")
        meta = json.loads(str(data["meta"]))
        if meta.get("format") != FORMAT:
            raise ValueError(f"{path}: unknown export format {meta.get('format')!r} (expected {FORMAT!r})")
        arrays = {name: data[name] for name in data.files if name != "meta"}
    return RunData(arrays, meta)


def _text(x: float, digits: int | None) -> str:
    return repr(float(x)) if digits is None else f"{x:.{digits}g}"


def save_csv(result: _core.RunResult, path: str | pathlib.Path, digits: int | None = None) -> pathlib.Path:
    """Write the time series as a tidy (long) CSV: ``t,variable,value`` (module docstring).

    One row per time and series component, grouped by variable (``q.x``, ``u.u1``,
    ``z_min_eig``, ...), in time order within each; ``Z`` is left out. Written whole or not
    at all.

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.
    path : str or pathlib.Path
        The file.
    digits : int, optional
        Significant digits of every number (1 to 17); None (default) writes the shortest
        exact text (``repr``: the round trip is exact).

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    ValueError
        `digits` out of range, or a path that cannot be written.
    OSError
        The file could not be written.

    Examples
    --------
    >>> from hinf_cpp.output.export import save_csv
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> path = save_csv(result, "run.csv", digits=6)
    >>> for line in path.read_text().splitlines()[:4]:
    ...     print(line)
    t,variable,value
    0,q.u,1
    0.01,q.u,1.01125
    0.02,q.u,1.02231
    """
    if digits is not None and not (isinstance(digits, int) and 1 <= digits <= 17):
        raise ValueError(f"digits must be an integer in [1, 17] or None, got {digits!r}")
    series = time_series(result)
    names = component_names(result)
    t = series.pop("t")
    times = [_text(x, digits) for x in t]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["t", "variable", "value"])
    for name, values in series.items():
        columns = [(name, values)] if values.ndim == 1 else \
            [(f"{name}.{c}", values[:, j]) for j, c in enumerate(names[name])]
        for variable, column in columns:
            writer.writerows(zip(times, [variable] * len(times), (_text(v, digits) for v in column)))
    return write_text(path, buffer.getvalue())


def load_csv(path: str | pathlib.Path) -> RunData:
    """Read a file of :func:`save_csv` back into the arrays of :func:`time_series`.

    ``meta`` holds ``components`` (the column names found for every 2-D series).

    Parameters
    ----------
    path : str or pathlib.Path
        The CSV file.

    Returns
    -------
    RunData
        The arrays (``t`` and every series) and ``meta["components"]``.

    Raises
    ------
    ValueError
        A file that is not a tidy export (header, times that differ between variables).

    Examples
    --------
    >>> from hinf_cpp.output.export import load_csv, save_csv
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> data = load_csv(save_csv(result, "run.csv"))
    >>> data["q"].shape, data.meta["components"]["u"]
    ((4001, 6), ['u1', 'u2'])
    >>> bool(np.array_equal(data["q"], result.simulation.q))  # exact round trip
    True
    """
    path = pathlib.Path(path)
    with path.open(newline="") as handle:
        reader = csv.reader(handle)
        header = next(reader, None)
        if header != ["t", "variable", "value"]:
            raise ValueError(f"{path}: expected the header t,variable,value, got {header}")
        columns: dict[str, tuple[list[float], list[float]]] = {}
        for line, row in enumerate(reader, start=2):
            if len(row) != 3:
                raise ValueError(f"{path}:{line}: expected 3 fields, got {len(row)}")
            times, values = columns.setdefault(row[1], ([], []))
            times.append(float(row[0]))
            values.append(float(row[2]))
    if not columns:
        raise ValueError(f"{path}: no data rows")
    t = None
    grouped: dict[str, list[tuple[str, np.ndarray]]] = {}
    for variable, (times, values) in columns.items():
        times = np.array(times)
        if t is None:
            t = times
        elif times.shape != t.shape or not np.array_equal(times, t):
            raise ValueError(f"{path}: variable '{variable}' is not on the same times as the others")
        name, _, component = variable.partition(".")
        grouped.setdefault(name, []).append((component, np.array(values)))
    arrays = {"t": t}
    components = {}
    for name, parts in grouped.items():
        if len(parts) == 1 and parts[0][0] == "":
            arrays[name] = parts[0][1]
        else:
            components[name] = [c for c, _ in parts]
            arrays[name] = np.column_stack([v for _, v in parts])
    return RunData(arrays, {"components": components})


def save_json(result: _core.RunResult, path: str | pathlib.Path) -> pathlib.Path:
    """Write the results file of a run (JSON, docs/results.md), whole or not at all.

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run.
    path : str or pathlib.Path
        The file.

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    ValueError
        A path that cannot be written.
    OSError
        The file could not be written.

    Examples
    --------
    >>> from hinf_cpp.output.export import save_json
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> save_json(result, "run.json").name
    'run.json'
    """
    return write_text(path, _core.results_json(result) + "\n")


def load_json(path: str | pathlib.Path) -> dict:
    """Read a results file (JSON, docs/results.md).

    Non-finite numbers are ``null`` in the file, None here.

    Parameters
    ----------
    path : str or pathlib.Path
        The results file.

    Returns
    -------
    dict
        Its content: scenario, gamma, Z0, metrics, timing, ...

    Raises
    ------
    ValueError
        A file that is not JSON.
    OSError
        A file that cannot be read.

    Examples
    --------
    >>> from hinf_cpp.output.export import load_json, save_json
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> results = load_json(save_json(result, "run.json"))
    >>> results["gamma"], round(results["metrics"]["rms_position_error_last_half"], 3)
    (5.0, 0.048)
    """
    text = pathlib.Path(path).read_text()
    try:
        return json.loads(text)
    except json.JSONDecodeError as error:
        raise ValueError(f"{path}: invalid JSON: {error}") from None
