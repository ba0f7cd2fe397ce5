"""Scenario files (TOML, ``shared/scenarios.md``) read with :mod:`tomllib`.

The keys, defaults and error messages match the C++ reader used by ``hinf-sim``
(``cpp/src/scenario_io.cpp``); ``tests/python/test_scenario.py`` checks that both
readers agree on every shipped scenario and reject the same bad files.
"""

from __future__ import annotations

import math
import pathlib
import tomllib
from typing import Any

import numpy as np

from . import _core

__all__ = ["load_scenario", "scenario_from_dict", "signal_from_spec"]

_SECTIONS = ["name", "description", "model", "horizon", "desired", "controller",
             "disturbance", "initial", "measurement", "solver", "output"]
_SHIP_KEYS = ["m_u", "m_v", "m_r", "d_u", "d_v", "d_r"]


def _type_name(value: Any) -> str:
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return "an array"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, int):
        return "an integer"
    if isinstance(value, float):
        return "a float"
    return "a date/time"


class _Table:
    """One TOML table; keys outside ``known`` are rejected up front (as in C++)."""

    def __init__(self, table: dict, where: str, source: str, known: list[str], prefix: str = ""):
        self.table, self.where, self.source, self.prefix = table, where, source, prefix
        for key in table:
            if key not in known:
                raise ValueError(f"{source}: {where} unknown key '{prefix}{key}' "
                                 f"(known keys: {', '.join(known)})")

    def fail(self, key: str, problem: str):
        raise ValueError(f"{self.source}: {self.where} {self.prefix}{key}: {problem}")

    def has(self, key: str) -> bool:
        return key in self.table

    def as_number(self, value: Any, key: str) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(key, f"expected a number, got {_type_name(value)}")
        return float(value)

    def number(self, key: str, default: float | None = None) -> float:
        if key not in self.table:
            if default is None:
                self.fail(key, "is required")
            return default
        return self.as_number(self.table[key], key)

    def string(self, key: str, default: str | None = None) -> str:
        if key not in self.table:
            if default is None:
                self.fail(key, "is required")
            return default
        value = self.table[key]
        if not isinstance(value, str):
            self.fail(key, f"expected a string, got {_type_name(value)}")
        return value

    def integer(self, key: str, default: int) -> int:
        if key not in self.table:
            return default
        value = self.table[key]
        if isinstance(value, bool) or not isinstance(value, int):
            self.fail(key, f"expected an integer, got {_type_name(value)}")
        return value

    def as_vector(self, value: Any, key: str, size: int) -> np.ndarray:
        if not isinstance(value, list):
            self.fail(key, f"expected an array of numbers, got {_type_name(value)}")
        if size >= 0 and len(value) != size:
            self.fail(key, f"expected {size} numbers, got {len(value)}")
        return np.array([self.as_number(v, f"{key}[{i}]") for i, v in enumerate(value)], dtype=float)

    def vector(self, key: str, size: int) -> np.ndarray:
        if key not in self.table:
            self.fail(key, "is required")
        return self.as_vector(self.table[key], key, size)

    def matrix(self, key: str, rows: int, cols: int, allow_scalar: bool) -> np.ndarray:
        if key not in self.table:
            self.fail(key, "is required")
        value = self.table[key]
        if allow_scalar and isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value) * np.eye(rows)
        expected = ("a number or " if allow_scalar else "") + f"a {rows} x {cols} nested list"
        if not isinstance(value, list):
            self.fail(key, f"expected {expected}, got {_type_name(value)}")
        if len(value) != rows:
            self.fail(key, f"expected {expected}, got {len(value)} rows")
        out = np.empty((rows, cols))
        for i, row in enumerate(value):
            if not isinstance(row, list):
                self.fail(key, f"expected {expected}, row {i} is {_type_name(row)}")
            out[i] = self.as_vector(row, f"{key}[{i}]", cols)
        return out

    def signal(self, key: str) -> _core.Signal:
        if key not in self.table:
            self.fail(key, "is required")
        return self.as_signal(self.table[key], key)

    def as_signal(self, value: Any, key: str) -> _core.Signal:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            try:
                return _core.Signal(float(value))
            except ValueError as error:
                self.fail(key, str(error))
        if not isinstance(value, dict):
            self.fail(key, "expected a signal { offset = ..., harmonics = [...] } or { table = {...} }, "
                           f"got {_type_name(value)}")
        spec = _Table(value, self.where, self.source, ["offset", "harmonics", "table"],
                      f"{self.prefix}{key}.")
        if spec.has("table"):
            if spec.has("offset") or spec.has("harmonics"):
                self.fail(key, "a tabulated signal cannot also have offset or harmonics")
            if not isinstance(value["table"], dict):
                self.fail(key + ".table", "expected a table { t = [...], value = [...] }")
            points = _Table(value["table"], self.where, self.source, ["t", "value"],
                            f"{self.prefix}{key}.table.")
            t = points.vector("t", -1)
            v = points.vector("value", -1)
            try:
                return _core.Signal.table(list(t), list(v))
            except ValueError as error:
                self.fail(key, str(error))
        offset = spec.number("offset") if spec.has("offset") else 0.0
        harmonics = []
        if spec.has("harmonics"):
            items = value["harmonics"]
            if not isinstance(items, list):
                self.fail(key + ".harmonics", f"expected an array of tables, got {_type_name(items)}")
            for i, item in enumerate(items):
                hkey = f"{key}.harmonics[{i}]"
                if not isinstance(item, dict):
                    self.fail(hkey, f"expected a table, got {_type_name(item)}")
                h = _Table(item, self.where, self.source,
                           ["amplitude", "omega", "frequency_hz", "phase", "shape"],
                           f"{self.prefix}{hkey}.")
                amplitude = h.number("amplitude")
                if h.has("omega") == h.has("frequency_hz"):
                    self.fail(hkey, "give exactly one of omega (rad/s) and frequency_hz (Hz)")
                omega = h.number("omega") if h.has("omega") else 2.0 * math.pi * h.number("frequency_hz")
                phase = h.number("phase") if h.has("phase") else 0.0
                shape = h.string("shape") if h.has("shape") else "sin"
                if shape not in ("sin", "cos"):
                    h.fail("shape", f'expected "sin" or "cos", got "{shape}"')
                harmonics.append(_core.Harmonic(amplitude, omega, phase, shape == "cos"))
        try:
            return _core.Signal(offset, harmonics)
        except ValueError as error:
            self.fail(key, str(error))


def signal_from_spec(spec: Any, name: str = "signal") -> _core.Signal:
    """A :class:`Signal` from its TOML form (a number or a table), e.g.
    ``{"harmonics": [{"amplitude": 0.3, "omega": 0.2}]}``."""
    return _Table({name: spec}, "signal", "<python>", [name]).signal(name)


def _section(root: dict, name: str, source: str, required: bool) -> dict | None:
    if name not in root:
        if required:
            raise ValueError(f"{source}: missing required section [{name}]")
        return None
    value = root[name]
    if not isinstance(value, dict):
        raise ValueError(f"{source}: [{name}] must be a table, got {_type_name(value)}")
    return value


def _model(table: dict, source: str) -> _core.Model:
    r = _Table(table, "[model]", source, ["kind", *_SHIP_KEYS, "A", "B", "D"])
    kind = r.string("kind")
    if kind == "ship":
        for key in ("A", "B", "D"):
            if r.has(key):
                r.fail(key, 'is a key of kind = "linear", not of kind = "ship"')
        defaults = _core.ShipParameters()
        params = {key: r.number(key, getattr(defaults, key)) for key in _SHIP_KEYS}
        return _core.ShipModel(_core.ShipParameters(**params))
    if kind == "linear":
        for key in _SHIP_KEYS:
            if r.has(key):
                r.fail(key, 'is a key of kind = "ship", not of kind = "linear"')
        A = table.get("A")
        if not isinstance(A, list):
            r.fail("A", "is required: an n x n nested list")
        n = len(A)
        A = r.matrix("A", n, n, False)
        B = table.get("B")
        if not isinstance(B, list) or not B or not isinstance(B[0], list):
            r.fail("B", "is required: an n x m nested list")
        B = r.matrix("B", n, len(B[0]), False)
        D = np.eye(n)
        if r.has("D"):
            Dv = table["D"]
            if not isinstance(Dv, list) or not Dv or not isinstance(Dv[0], list):
                r.fail("D", "expected an n x nw nested list")
            D = r.matrix("D", n, len(Dv[0]), False)
        return _core.LinearModel(A, B, D)
    r.fail("kind", f'unknown model kind "{kind}": use "ship" or "linear"')


def scenario_from_dict(root: dict, source: str = "<dict>") -> _core.Scenario:
    """Builds a :class:`Scenario` from the dictionary form of a scenario file."""
    top = _Table(root, "top level", source, _SECTIONS)
    s = _core.Scenario()
    s.name = top.string("name", pathlib.Path(source).stem)
    s.description = top.string("description", "")
    s.model = _model(_section(root, "model", source, True), source)
    n, m, nw = s.model.n(), s.model.m(), s.model.nw()

    r = _Table(_section(root, "horizon", source, True), "[horizon]", source, ["t0", "tf"])
    s.t0 = r.number("t0", 0.0)
    s.tf = r.number("tf")

    inputs = [f"u{i}" for i in range(1, m + 1)]
    r = _Table(_section(root, "desired", source, True), "[desired]", source, ["q0", *inputs])
    s.desired_q0 = r.vector("q0", n)
    s.desired_u = _core.VectorSignal([r.signal(key) for key in inputs])

    r = _Table(_section(root, "controller", source, True), "[controller]", source,
               ["gamma", "Q", "Qf", "kappa", "law", "cascade"])
    s.gamma = r.number("gamma")
    s.law = r.string("law", s.law)
    if r.has("cascade"):
        table = root["controller"]["cascade"]
        if not isinstance(table, dict):
            r.fail("cascade", f"expected a table {{ k = ..., k1 = ..., k2 = ... }}, got {_type_name(table)}")
        g = _Table(table, "[controller]", source, ["k", "k1", "k2"], "cascade.")
        gains = s.cascade
        gains.k = g.number("k", gains.k)
        gains.k1 = g.number("k1", gains.k1)
        gains.k2 = g.number("k2", gains.k2)
        s.cascade = gains
    if r.has("Q"):
        s.Q = r.matrix("Q", n, n, True)
    if r.has("Qf"):
        s.Qf = r.matrix("Qf", n, n, True)
    if r.has("kappa"):
        s.kappa = r.signal("kappa")

    channels = [_core.Signal() for _ in range(nw)]
    table = _section(root, "disturbance", source, False)
    if table is not None:
        keys = [f"w{i}" for i in range(1, nw + 1)]
        r = _Table(table, "[disturbance]", source, [*keys, "worst_case"])
        if r.has("worst_case"):
            if not isinstance(table["worst_case"], bool):
                r.fail("worst_case", f"expected true or false, got {_type_name(table['worst_case'])}")
            s.worst_case = table["worst_case"]
        for i, key in enumerate(keys):
            if r.has(key):
                channels[i] = r.signal(key)
    s.disturbance = _core.VectorSignal(channels)

    r = _Table(_section(root, "initial", source, True), "[initial]", source, ["q0"])
    s.initial_q0 = r.vector("q0", n)

    table = _section(root, "measurement", source, False)
    if table is not None:
        r = _Table(table, "[measurement]", source,
                   ["sigma", "sample_period", "seed", "N", "Q0", "eta", "filter_A",
                    "on_coupling_violation"])
        ms = _core.MeasurementSpec()
        ms.sigma = r.number("sigma")
        ms.sample_period = r.number("sample_period", ms.sample_period)
        seed = r.integer("seed", 0)
        if seed < 0:
            r.fail("seed", f"must be >= 0, got {seed}")
        ms.seed = seed
        if r.has("N"):
            value = table["N"]
            if isinstance(value, list):
                ms.N = r.matrix("N", len(value), len(value), False)
            else:
                ms.N = np.array([[r.number("N")]])
        if r.has("Q0"):
            ms.Q0 = r.matrix("Q0", n, n, True)
        ms.eta = r.number("eta", ms.eta)
        ms.filter_A = r.string("filter_A", ms.filter_A)
        ms.on_coupling_violation = r.string("on_coupling_violation", ms.on_coupling_violation)
        s.measurement = ms

    table = _section(root, "solver", source, False)
    if table is not None:
        r = _Table(table, "[solver]", source, ["method", "rtol", "atol", "max_steps"])
        options = _core.SolverOptions()
        method = r.string("method", "bdf")
        try:
            options.method = method
        except ValueError as error:
            r.fail("method", str(error))
        options.rtol = r.number("rtol", options.rtol)
        options.atol = r.number("atol", options.atol)
        options.max_steps = r.integer("max_steps", options.max_steps)
        s.solver = options

    table = _section(root, "output", source, False)
    if table is not None:
        r = _Table(table, "[output]", source, ["dt"])
        s.output_dt = r.number("dt", s.output_dt)
    return s


def load_scenario(path: str | pathlib.Path) -> _core.Scenario:
    """Reads a scenario file; unknown keys and wrong types raise ValueError naming the key."""
    path = pathlib.Path(path)
    try:
        text = path.read_text()
    except OSError as error:
        raise ValueError(f"cannot read scenario file '{path}': {error.strerror}") from None
    try:
        root = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{path}: invalid TOML: {error}") from None
    return scenario_from_dict(root, str(path))
