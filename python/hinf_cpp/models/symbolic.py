"""Vehicle models written with CasADi symbols, evaluated inside the C++ core.

A :class:`SymbolicModel` states a control-affine model

    dq/dt = f(t, q) + G(t, q) u + D(t, q) w,      y = C(t) q + noise,

with CasADi expressions (SX or MX) of the time ``t``, the state ``q`` and named parameters
``p``, the way models are written for acados or do-mpc. Its Jacobians df/dq and d(G u)/dq come
from CasADi's automatic differentiation (exact). :meth:`SymbolicModel.compile` generates C code
for all of its functions, compiles it once with the system's C compiler into a cached shared
library (``hinf_cpp.models.codegen``) and returns a ``hinf_cpp.GeneratedModel``: a C++ model that
calls that library with no Python in the loop (docs/models.md says why this route and what
it costs). :meth:`SymbolicModel.export` writes the library and its description
(``model.json``) to a folder that a scenario file names with ``[model] kind = "casadi"``, so
``hinf-sim`` runs the same model.

Example (the ship of the paper; in full in :func:`hinf_cpp.models.builtin.ship`)::

    import casadi as ca
    q = ca.SX.sym("q", 6)
    m_u = ca.SX.sym("m_u")
    ...
    model = SymbolicModel("ship", state=q, inputs=2, f=f, G=G, D=D,
                          parameters=ca.vertcat(m_u, ...), parameter_values={"m_u": 0.5, ...})
    cpp_model = model.compile()

Conventions as everywhere in the project (docs/mathematics.md): time in seconds, errors are
actual minus desired, matrices column-major; the heading (if any) is wrapped to (-pi, pi].
"""

from __future__ import annotations

import dataclasses
import json
import math
import os
import pathlib
import shutil
import time
from collections.abc import Callable, Mapping, Sequence

import numpy as np

from hinf_cpp import _core

METADATA_FORMAT = "hinf_cpp.generated_model/1"
METADATA_FILE = "model.json"

# The generated functions, their inputs and what they return (docs/models.md):
#   f(t, q, p) -> n x 1             dfdq(t, q, p) -> n x n
#   G(t, q, p) -> n x m             D(t, q, p) -> n x nw
#   dGudq(t, q, u, p) -> n x n      C(t, p) -> p_y x n               (if there is a measurement)
#   error_split(t, q_d, u_d, q_e, p) -> (A n x n, alpha n x 1)       (if the model gives one)
FUNCTION_NAMES = ("f", "dfdq", "G", "D", "dGudq", "C", "error_split")


def _casadi():
    try:
        import casadi
    except ImportError as e:  # pragma: no cover - casadi is in requirements-dev.txt
        raise ImportError("symbolic models need CasADi: pip install casadi") from e
    return casadi


@dataclasses.dataclass
class CompiledModel:
    """Where a compiled model lives and what compiling it cost.

    What :meth:`SymbolicModel.build` returns.

    Parameters
    ----------
    metadata_path : pathlib.Path
        The model's description (JSON, the content of a ``model.json``) in the cache folder;
        the shared library and its C source are beside it. ``hinf_cpp.GeneratedModel(path)``
        loads it.
    cache_hit : bool
        True: an identical model had been compiled before (same C source, compiler and flags).
    generate_seconds : float
        Seconds of CasADi's code generation (also spent on a cache hit: the cache key is the
        hash of the generated source).
    compile_seconds : float
        Seconds of the C compiler (0 on a cache hit).

    Examples
    --------
    >>> import casadi as ca
    >>> from hinf_cpp.models import SymbolicModel
    >>> q = ca.SX.sym("q", 2)  # [position x (m), velocity v (m/s)]
    >>> d = ca.SX.sym("d")     # damping, 1/s
    >>> cart = SymbolicModel("cart", state=q, inputs=1, f=ca.vertcat(q[1], -d * q[1]),
    ...                      G=[[0.0], [1.0]], D=[[0.0], [1.0]], parameters=d,
    ...                      parameter_values={"d": 0.5}, state_names=["x", "v"])
    >>> built = cart.build(cache_dir="cache")  # compiled once, into ./cache
    >>> built.metadata_path.suffix, built.compile_seconds > 0
    ('.json', True)
    >>> again = cart.build(cache_dir="cache")
    >>> again.cache_hit, again.compile_seconds
    (True, 0.0)
    """

    metadata_path: pathlib.Path  # model.json; the shared library is beside it
    cache_hit: bool          # True: an identical model had been compiled before
    generate_seconds: float  # CasADi's code generation (0 on a cache hit)
    compile_seconds: float   # the C compiler (0 on a cache hit)


class SymbolicModel:
    """A control-affine model dq/dt = f(t, q) + G(t, q) u + D(t, q) w in CasADi expressions.

    The model is stated with CasADi expressions (SX or MX) of the time t (s), the state q and
    named parameters p; y = C(t) q + noise is its optional measurement. The Jacobians df/dq
    and d(G u)/dq are CasADi's automatic differentiation (exact). :meth:`compile` turns it
    into a ``hinf_cpp.GeneratedModel`` (C code generated, compiled once with the system C
    compiler, cached; docs/models.md), :meth:`export` writes a folder for a scenario file's
    ``[model] kind = "casadi"``, and the planner (:func:`hinf_cpp.planning.plan`) uses its
    expressions. Every argument is checked at construction.

    Parameters
    ----------
    name : str
        The model's name (results files, tables).
    state : casadi.SX or casadi.MX, shape (n, 1)
        The state q, a column of n CasADi symbols.
    inputs : int
        The number of inputs m (>= 1).
    f : CasADi expression or array_like, shape (n, 1)
        The drift, an expression of t, q and the parameters (not of u: the model is
        control-affine, the inputs enter through G).
    G : CasADi expression or array_like, shape (n, m)
        The input matrix, one column per input; may depend on t, q and the parameters.
    D : CasADi expression or array_like, shape (n, nw)
        The disturbance matrix (nw may be 0: pass an n x 0 matrix); may depend on t, q and
        the parameters.
    time : casadi.SX or casadi.MX, optional
        The time symbol t (s), if f, G, D or C depend on it.
    parameters : casadi.SX or casadi.MX, shape (k, 1), optional
        A column of named scalar symbols (``ca.SX.sym("m_u")``), or None.
    parameter_values : mapping of str to float, optional
        A value for every parameter, by name (the defaults; a scenario file or
        :meth:`compile` may set others).
    C : CasADi expression or array_like, shape (p_y, n), optional
        The measurement matrix of y = C q + noise, an expression of t and the parameters.
    noise_channels : sequence of int, optional
        With C: the p_y channels of w (0-based) that carry the measurement noise (their
        columns of D should be zero: the noise enters through E).
    state_names : sequence of str, optional
        One name per state (default ``q0``, ``q1``, ...), as ``hc.Model.state_names()``.
    position_indices : sequence of int, optional
        The inertial position components (two for a planar vehicle), as
        ``hc.Model.position_indices()``.
    heading_index : int, optional
        The heading angle's state (rad), or -1 for none.
    error_split : callable, optional
        ``(q_d, u_d, q_e) -> (A, alpha)`` of CasADi expressions with
        A(q_e) q_e + alpha(q_e) = f_e(q_e) and A(0) = A_e (paper eqs. 26-31); it is checked at
        random points when the model is compiled. Without it the always-valid split A = A_e,
        alpha = f_e - A_e q_e is used.
    nominal_state : array_like, shape (n,), optional
        A state where the model is defined (default zeros): the expressions are evaluated
        there at construction, and an expression that is not finite there is an error.

    Attributes
    ----------
    n, m, nw : int
        The sizes of q, u and w.
    f, G, D, C, dfdq, dGudq : CasADi expressions
        The model's expressions and their exact Jacobians.
    parameter_names : list of str
        The parameters, in order; ``parameter_values`` their defaults by name.

    Raises
    ------
    ValueError
        Naming the model and the problem: shapes of f, G, D and C, one noise channel per
        measured output, indices out of range, expressions that depend on other symbols
        (f, G, D on u), a missing or unknown parameter value, f, G, D or df/dq not finite at
        `nominal_state`.

    Examples
    --------
    >>> import casadi as ca
    >>> from hinf_cpp.models import SymbolicModel
    >>> q = ca.SX.sym("q", 2)  # [position x (m), velocity v (m/s)]
    >>> d = ca.SX.sym("d")     # damping, 1/s
    >>> cart = SymbolicModel("cart", state=q, inputs=1, f=ca.vertcat(q[1], -d * q[1]),
    ...                      G=[[0.0], [1.0]], D=[[0.0], [1.0]], parameters=d,
    ...                      parameter_values={"d": 0.5}, state_names=["x", "v"])
    >>> cart.n, cart.m, cart.nw, cart.parameter_names
    (2, 1, 1, ['d'])
    >>> model = cart.compile(cache_dir="cache")  # an hc.GeneratedModel, compiled into ./cache
    >>> model.f(0.0, [0.0, 2.0])                 # f at x = 0 m, v = 2 m/s
    array([ 2., -1.])
    >>> cart.compile({"d": 1.0}, cache_dir="cache").f(0.0, [0.0, 2.0])
    array([ 2., -2.])
    """

    def __init__(self, name: str, *, state, inputs: int, f, G, D, time=None, parameters=None,
                 parameter_values: Mapping[str, float] | None = None, C=None,
                 noise_channels: Sequence[int] = (), state_names: Sequence[str] | None = None,
                 position_indices: Sequence[int] = (), heading_index: int = -1,
                 error_split: Callable | None = None, nominal_state: Sequence[float] | None = None):
        ca = _casadi()
        self.name = _checked_name(name)
        self.q = _symbol_column(state, "state")
        self.n = self.q.shape[0]
        if not isinstance(inputs, (int, np.integer)) or inputs < 1:
            raise ValueError(f"the symbolic model '{name}': inputs must be the number of inputs m >= 1, got {inputs!r}")
        self.m = int(inputs)
        self.t = _symbol_column(time, "time") if time is not None else type(self.q).sym("t")
        if self.t.shape != (1, 1):
            raise ValueError(f"the symbolic model '{name}': time must be one scalar symbol, got shape {self.t.shape}")
        self.p = _symbol_column(parameters, "parameters") if parameters is not None else type(self.q).sym("p", 0)
        self.parameter_names = [self.p[i].name() for i in range(self.p.shape[0])]
        if len(set(self.parameter_names)) != len(self.parameter_names):
            raise ValueError(f"the symbolic model '{name}': parameter names must be distinct, got {self.parameter_names}")
        values = dict(parameter_values or {})
        missing = [p for p in self.parameter_names if p not in values]
        unknown = [p for p in values if p not in self.parameter_names]
        if missing or unknown:
            raise ValueError(f"the symbolic model '{name}': parameter_values must give a value for every parameter "
                             f"({', '.join(self.parameter_names) or 'none'}); missing: {missing}, unknown: {unknown}")
        self.parameter_values = {p: _finite(values[p], f"the parameter '{p}'", name) for p in self.parameter_names}
        self.u = type(self.q).sym("u", self.m)

        self.f = _expression(f, (self.n, 1), "f", name, like=self.q)
        self.G = _expression(G, (self.n, self.m), "G", name, f"(n x m = {self.n} x {self.m}: one column per input)", like=self.q)
        D = _expression(D, None, "D", name, like=self.q)
        if D.shape[0] != self.n:
            raise ValueError(f"the symbolic model '{name}': D has shape {D.shape}, expected {self.n} rows (n x nw)")
        self.D = D
        self.nw = D.shape[1]
        for label, expr in (("f", self.f), ("G", self.G), ("D", self.D)):
            _require_arguments(expr, [self.t, self.q, self.p], label, name, "t, q and the parameters")
        self.C = None
        if C is not None:
            self.C = _expression(C, None, "C", name, like=self.q)
            if self.C.shape[1] != self.n or self.C.shape[0] < 1:
                raise ValueError(f"the symbolic model '{name}': C has shape {self.C.shape}, expected (p_y, {self.n})")
            _require_arguments(self.C, [self.t, self.p], "C", name, "t and the parameters (not of q: y = C q)")
        self.noise_channels = [int(i) for i in noise_channels]
        if (self.C is None) != (len(self.noise_channels) == 0) or (
                self.C is not None and len(self.noise_channels) != self.C.shape[0]):
            rows = 0 if self.C is None else self.C.shape[0]
            raise ValueError(f"the symbolic model '{name}': noise_channels must name one w channel per measured "
                             f"output ({rows}), got {self.noise_channels}")
        self.state_names = list(state_names) if state_names is not None else [f"q{i}" for i in range(self.n)]
        self.position_indices = [int(i) for i in position_indices]
        self.heading_index = int(heading_index)
        _core.check_model_structure(self._structure())  # ranges of the indices, names per state

        # Automatic differentiation: exact Jacobians.
        self.dfdq = ca.jacobian(self.f, self.q)
        self.dGudq = ca.jacobian(ca.mtimes(self.G, self.u), self.q)
        input_matrices = ca.vertcat(ca.vec(self.G), ca.vec(self.D))
        self.state_dependent_inputs = bool(ca.depends_on(input_matrices, self.q))
        self.constant_input_matrices = not (self.state_dependent_inputs or ca.depends_on(input_matrices, self.t))

        self.error_split = None
        if error_split is not None:
            q_d, u_d, q_e = (type(self.q).sym(s, k) for s, k in (("q_d", self.n), ("u_d", self.m), ("q_e", self.n)))
            result = error_split(q_d, u_d, q_e)
            if not isinstance(result, (tuple, list)) or len(result) != 2:
                raise ValueError(f"the symbolic model '{name}': error_split(q_d, u_d, q_e) must return (A, alpha)")
            A = _expression(result[0], (self.n, self.n), "error_split's A", name, like=self.q)
            alpha = _expression(result[1], (self.n, 1), "error_split's alpha", name, like=self.q)
            for label, expr in (("error_split's A", A), ("error_split's alpha", alpha)):
                _require_arguments(expr, [self.t, q_d, u_d, q_e, self.p], label, name, "t, q_d, u_d, q_e and the parameters")
            self.error_split = (q_d, u_d, q_e, A, alpha)

        nominal = np.zeros(self.n) if nominal_state is None else np.asarray(nominal_state, dtype=float)
        if nominal.shape != (self.n,):
            raise ValueError(f"the symbolic model '{name}': nominal_state must have {self.n} numbers, got shape {nominal.shape}")
        self._check_finite_at(nominal)

    # ---- the functions and the compiled model ----

    def functions(self) -> list:
        """The CasADi functions of the model, named as in FUNCTION_NAMES."""
        ca = _casadi()
        t, q, u, p = self.t, self.q, self.u, self.p
        out = [ca.Function("f", [t, q, p], [self.f]),
               ca.Function("dfdq", [t, q, p], [self.dfdq]),
               ca.Function("G", [t, q, p], [self.G]),
               ca.Function("D", [t, q, p], [self.D]),
               ca.Function("dGudq", [t, q, u, p], [self.dGudq])]
        if self.C is not None:
            out.append(ca.Function("C", [t, p], [self.C]))
        if self.error_split is not None:
            q_d, u_d, q_e, A, alpha = self.error_split
            out.append(ca.Function("error_split", [t, q_d, u_d, q_e, p], [A, alpha]))
        return out

    def metadata(self) -> dict:
        """What model.json says about the model (everything but the library's file name)."""
        return {"format": METADATA_FORMAT, "name": self.name, "n": self.n, "m": self.m, "nw": self.nw,
                "state_names": self.state_names, "position_indices": self.position_indices,
                "heading_index": self.heading_index, "noise_channels": self.noise_channels,
                "constant_input_matrices": bool(self.constant_input_matrices),
                "state_dependent_inputs": bool(self.state_dependent_inputs),
                "measurement": self.C is not None, "error_split": self.error_split is not None,
                "parameters": [{"name": p, "default": self.parameter_values[p]} for p in self.parameter_names]}

    def build(self, cache_dir: str | os.PathLike | None = None) -> CompiledModel:
        """Generates and compiles the model's C code once (cached by its content: a second build
        of the same model costs nothing but a hash) and writes model.json beside the library."""
        from hinf_cpp.models.codegen import compile_casadi_functions

        library = compile_casadi_functions(self.functions(), _library_stem(self.name), cache_dir=cache_dir)
        directory = pathlib.Path(library.path).parent
        metadata = dict(self.metadata(), library=pathlib.Path(library.path).name)
        path = directory / f"{pathlib.Path(library.path).stem}.json"
        text = json.dumps(metadata, indent=2) + "\n"
        if not path.exists() or path.read_text() != text:
            _write_atomically(path, text)
        if self.error_split is not None:  # a few evaluations: checked on every build, cached or not
            self._check_error_split(_core.GeneratedModel(str(path)))
        return CompiledModel(path, library.cache_hit, library.generate_seconds, library.compile_seconds)

    def compile(self, parameter_values: Mapping[str, float] | None = None,
                cache_dir: str | os.PathLike | None = None) -> "_core.GeneratedModel":
        """The model as a C++ ``GeneratedModel`` (built and cached on first use), with its
        parameters at their defaults or as given by name."""
        built = self.build(cache_dir)
        return _core.GeneratedModel(str(built.metadata_path), dict(parameter_values or {}))

    def export(self, directory: str | os.PathLike, cache_dir: str | os.PathLike | None = None) -> pathlib.Path:
        """Writes model.json, the shared library and its C source into `directory` (created if
        needed), for a scenario file: ``[model] kind = "casadi"``, ``file = "<directory>/model.json"``.
        Returns the path of model.json."""
        path = self.build(cache_dir).metadata_path
        target = pathlib.Path(directory)
        try:
            target.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise OSError(f"cannot export the model '{self.name}' to '{target}': {e.strerror}") from e
        metadata = json.loads(path.read_text())
        library = path.parent / metadata["library"]
        shutil.copyfile(library, target / metadata["library"])
        source = library.with_suffix(".c")
        if source.exists():
            shutil.copyfile(source, target / source.name)
        _write_atomically(target / METADATA_FILE, json.dumps(metadata, indent=2) + "\n")
        return target / METADATA_FILE

    # ---- checks ----

    def _structure(self):
        s = _core.ModelStructure()
        s.name, s.n, s.m, s.nw = self.name, self.n, self.m, self.nw
        s.state_names, s.position_indices, s.heading_index = self.state_names, self.position_indices, self.heading_index
        s.noise_channels = self.noise_channels
        return s

    def _check_finite_at(self, q) -> None:
        ca = _casadi()
        p = np.array([self.parameter_values[name] for name in self.parameter_names])
        for label, expr, shape in (("f", self.f, None), ("G", self.G, None), ("D", self.D, None),
                                   ("df/dq", self.dfdq, None)):
            value = np.asarray(ca.Function("check", [self.t, self.q, self.p], [expr])(0.0, q, p), dtype=float)
            if not np.all(np.isfinite(value)):
                raise ValueError(f"the symbolic model '{self.name}': {label} is not finite at the nominal state "
                                 f"q = {q.tolist()} (t = 0, default parameters): fix the expression, or pass "
                                 f"nominal_state= a state where the model is defined")

    def _check_error_split(self, model) -> None:
        """A(q_e) q_e + alpha(q_e) = f_e(q_e) and A(0) = A_e at seeded random points (the
        always-valid split's identities, docs/mathematics.md), to round-off of the terms."""
        rng = np.random.default_rng(0)
        for _ in range(8):
            q_d, u_d, q_e = rng.normal(size=self.n), rng.normal(size=self.m), rng.normal(size=self.n)
            A, alpha = model.error_split(0.0, q_d, u_d, q_e)
            f_e = (model.f(0.0, q_d + q_e) + model.G(0.0, q_d + q_e) @ u_d
                   - model.f(0.0, q_d) - model.G(0.0, q_d) @ u_d)
            scale = 1.0 + np.abs(f_e).max() + np.abs(A).max() * np.abs(q_e).max()
            A0, alpha0 = model.error_split(0.0, q_d, u_d, np.zeros(self.n))
            if (np.abs(A @ q_e + alpha - f_e).max() > 1e-10 * scale
                    or np.abs(A0 - model.linearize(0.0, q_d, u_d)).max() > 1e-10 * (1.0 + np.abs(A0).max())):
                raise ValueError(f"the symbolic model '{self.name}': error_split is not a decomposition of the "
                                 "error dynamics: A(q_e) q_e + alpha(q_e) must equal f_e(q_e) and A(0) must be "
                                 "A_e (docs/mathematics.md); leave it out to use the always-valid split")


# ---- helpers ----

def _checked_name(name) -> str:
    if not isinstance(name, str) or not name.strip():
        raise ValueError(f"a symbolic model needs a name (a non-empty str), got {name!r}")
    return name


def _library_stem(name: str) -> str:
    stem = "".join(c if c.isalnum() else "_" for c in name.lower()).strip("_")
    return f"hinf_model_{stem or 'model'}"


def _symbol_column(value, label):
    ca = _casadi()
    if not isinstance(value, (ca.SX, ca.MX)):
        raise ValueError(f"the model's {label} must be CasADi symbols (ca.SX.sym or ca.MX.sym), got {type(value).__name__}")
    if value.shape[1] != 1 and value.numel() > 0:
        raise ValueError(f"the model's {label} must be a column of symbols, got shape {value.shape}")
    if value.numel() > 0 and not value.is_valid_input():
        raise ValueError(f"the model's {label} must be plain symbols (ca.SX.sym(...)), not expressions")
    return value


def _expression(value, shape, label, name, hint="", like=None):
    """value as a CasADi expression (numbers and arrays become constants of the type of `like`)."""
    ca = _casadi()
    if isinstance(value, (int, float, np.ndarray, list)):
        value = ca.DM(np.asarray(value, dtype=float))
    if isinstance(value, ca.DM):
        value = (type(like) if like is not None else ca.SX)(value)
    if not isinstance(value, (ca.SX, ca.MX)):
        raise ValueError(f"the symbolic model '{name}': {label} must be a CasADi expression or an array, "
                         f"got {type(value).__name__}")
    if shape is not None and value.shape != shape:
        raise ValueError(f"the symbolic model '{name}': {label} has shape {value.shape}, expected {shape} {hint}".rstrip())
    return value


def _require_arguments(expr, arguments, label, name, allowed):
    ca = _casadi()
    try:
        ca.Function("check", arguments, [expr])
    except RuntimeError as e:
        free = [str(s) for s in ca.symvar(expr) if not any(ca.depends_on(s, a) for a in arguments if a.numel() > 0)]
        raise ValueError(f"the symbolic model '{name}': {label} may only depend on {allowed}; it also depends on "
                         f"{', '.join(free) or 'other symbols'}") from e


def _finite(value, label, name) -> float:
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"the symbolic model '{name}': {label} must be a number, got {value!r}") from None
    if not math.isfinite(number):
        raise ValueError(f"the symbolic model '{name}': {label} must be finite, got {number}")
    return number


def _write_atomically(path: pathlib.Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.{os.getpid()}.{time.monotonic_ns()}.tmp")
    tmp.write_text(text)
    os.replace(tmp, path)
