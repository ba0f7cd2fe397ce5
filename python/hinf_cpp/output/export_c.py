"""A self-contained C99 controller: the online controller of a fixed-horizon design, written out
as C source with the design's tables (docs/export.md).

:func:`export_controller` writes a folder that builds a static library with nothing but a C99
compiler and libm: ``hinf_controller.h`` (a caller-owned state, ``hinf_controller_init``,
``hinf_controller_reset``, ``hinf_controller_step``), ``hinf_controller.c`` (the arithmetic of
``OnlineController.step``), ``hinf_controller_tables.c`` / ``.h`` (the design at the
controller's samples, every number printed with 17 significant digits, so the tables are the
design's doubles exactly), ``CMakeLists.txt`` and a ``README.md`` with the table size, the horizon
and the options. No heap, no I/O; compiles with ``-std=c99 -Wall -Wextra -Werror -pedantic``.
:func:`export_scenario` does the same for a scenario file's design and ``[sampling]`` options.

Supported: the emulated law (``SampledLaw.emulated``) and the digital law's gains
(``SampledLaw.digital``); state feedback with or without delay compensation; output feedback
with the sampled measurement update (the default); actuator bounds and rate limits; the
heading's wrapping; every status of ``OnlineController.step``. Refused with a ``ValueError``:
the ``held`` and ``discrete`` measurement updates, and u_d given as a function of t.
"""

from __future__ import annotations

import dataclasses
import math
import os
import pathlib
import shutil
import tempfile

import numpy as np

from hinf_cpp import _core
from hinf_cpp.output.export_c_source import HEADER_BODY, SOURCE, TABLES_HEADER
from hinf_cpp.output.files import check_output_folder

__all__ = ["ExportedController", "export_controller", "export_scenario"]

# The files of an exported folder.
FILES = ("hinf_controller.h", "hinf_controller.c", "hinf_controller_tables.h", "hinf_controller_tables.c",
         "CMakeLists.txt", "README.md")


@dataclasses.dataclass(frozen=True)
class ExportedController:
    """What :func:`export_controller` wrote: the folder and the facts its README states.

    Parameters
    ----------
    folder : pathlib.Path
        The folder written.
    kind : str
        ``"emulated"`` or ``"digital"``: the law exported.
    gamma : float
        The design's gamma (inf: LQR).
    t0 : float
        The first sample (s).
    t_end : float
        The end of the horizon covered (s): the controller answers ``past_horizon`` from here on.
    period : float
        The controller's period T (s).
    steps : int
        The number of samples N, t_end = t0 + N T.
    n : int
        The number of states.
    m : int
        The number of inputs.
    p : int
        The number of measured outputs (0: state feedback).
    table_bytes : int
        The size of the constant tables in memory (bytes: 8 per double).

    Examples
    --------
    >>> from hinf_cpp.output.export_c import export_scenario
    >>> exported = export_scenario(hc.load_scenario(hc.scenario_path("paper_fig2_sampled")), "controller")
    >>> exported.steps, exported.t_end, exported.p
    (800, 40.0, 3)
    """

    folder: pathlib.Path
    kind: str
    gamma: float
    t0: float
    t_end: float
    period: float
    steps: int
    n: int
    m: int
    p: int
    table_bytes: int


def _number(x: float) -> str:
    """A double as C text that reads back to the same double."""
    x = float(x)
    if math.isnan(x):
        return "NAN"
    if math.isinf(x):
        return "INFINITY" if x > 0 else "-INFINITY"
    text = format(x, ".17g")
    return text if any(c in text for c in ".eE") else text + ".0"


def _array(values, per_line: int = 6) -> str:
    flat = [_number(v) for v in np.asarray(values, dtype=float).ravel()]
    lines = [", ".join(flat[i:i + per_line]) for i in range(0, len(flat), per_line)]
    return "{" + ",\n  ".join(lines) + "}"


def _table(name: str, shape: str, rows) -> str:
    return f"const double {name}{shape} = {{\n  " + ",\n  ".join(_array(row) for row in rows) + "\n};\n"


# --- u_d: the design's signals in C, evaluated as hinf_cpp's Signal evaluates them -------------

def _sign(x: float) -> float:
    return float((x > 0.0) - (x < 0.0))


def _pchip_end_slope(h0, h1, m0, m1):
    d = ((2.0 * h0 + h1) * m0 - h0 * m1) / (h0 + h1)
    if _sign(d) != _sign(m0):
        return 0.0
    if _sign(m0) != _sign(m1) and abs(d) > 3.0 * abs(m0):
        return 3.0 * m0
    return d


def _pchip_slopes(t, v):
    n = len(t)
    h = [t[i + 1] - t[i] for i in range(n - 1)]
    secant = [(v[i + 1] - v[i]) / h[i] for i in range(n - 1)]
    if n == 2:
        return [secant[0], secant[0]]
    d = [0.0] * n
    for i in range(1, n - 1):
        s0, s1 = secant[i - 1], secant[i]
        if _sign(s0) != _sign(s1) or s0 == 0.0 or s1 == 0.0:
            continue
        w1, w2 = 2.0 * h[i] + h[i - 1], h[i] + 2.0 * h[i - 1]
        d[i] = (w1 + w2) / (w1 / s0 + w2 / s1)
    d[0] = _pchip_end_slope(h[0], h[1], secant[0], secant[1])
    d[n - 1] = _pchip_end_slope(h[n - 2], h[n - 3], secant[n - 2], secant[n - 3])
    return d


def _natural_spline_second_derivatives(t, v):
    n = len(t)
    m2 = [0.0] * n
    if n <= 2:
        return m2
    diag, rhs, upper = [0.0] * (n - 2), [0.0] * (n - 2), [0.0] * (n - 2)
    for i in range(1, n - 1):
        h0, h1 = t[i] - t[i - 1], t[i + 1] - t[i]
        diag[i - 1] = 2.0 * (h0 + h1)
        upper[i - 1] = h1
        rhs[i - 1] = 6.0 * ((v[i + 1] - v[i]) / h1 - (v[i] - v[i - 1]) / h0)
    for k in range(1, n - 2):
        factor = (t[k + 1] - t[k]) / diag[k - 1]
        diag[k] -= factor * upper[k - 1]
        rhs[k] -= factor * rhs[k - 1]
    for k in range(n - 3, -1, -1):
        value = rhs[k]
        if k + 1 < n - 2:
            value -= upper[k] * m2[k + 2]
        m2[k + 1] = value / diag[k]
    return m2


def _table_pieces(signal: _core.Signal) -> list[tuple[float, float, float, float]]:
    """The cubic pieces c0 + c1 s + c2 s^2 + c3 s^3 of a tabulated signal, as Signal::table makes
    them (cpp/src/numerics/signal.cpp)."""
    t, v = [float(x) for x in signal.table_t()], [float(x) for x in signal.table_values()]
    kind, n = signal.interpolation(), len(t)
    if kind == _core.Interpolation.hold:
        return [(v[i], 0.0, 0.0, 0.0) for i in range(n - 1)]
    if kind == _core.Interpolation.linear:
        return [(v[i], (v[i + 1] - v[i]) / (t[i + 1] - t[i]), 0.0, 0.0) for i in range(n - 1)]
    if kind == _core.Interpolation.pchip:
        d = _pchip_slopes(t, v)
        pieces = []
        for i in range(n - 1):
            h = t[i + 1] - t[i]
            secant = (v[i + 1] - v[i]) / h
            pieces.append((v[i], d[i], (3.0 * secant - 2.0 * d[i] - d[i + 1]) / h,
                           (d[i] + d[i + 1] - 2.0 * secant) / (h * h)))
        return pieces
    m2 = _natural_spline_second_derivatives(t, v)
    pieces = []
    for i in range(n - 1):
        h = t[i + 1] - t[i]
        pieces.append((v[i], (v[i + 1] - v[i]) / h - h * (2.0 * m2[i] + m2[i + 1]) / 6.0, m2[i] / 2.0,
                       (m2[i + 1] - m2[i]) / (6.0 * h)))
    return pieces


def _evaluate_pieces(signal: _core.Signal, pieces, t: float) -> float:
    """The C function's arithmetic in Python: checks the pieces against the Signal."""
    times = [float(x) for x in signal.table_t()]
    if signal.interpolation() == _core.Interpolation.hold and t >= times[-1]:
        return float(signal.table_values()[-1])
    i = int(np.searchsorted(times, t, side="right"))
    i = min(max(i, 1), len(times) - 1) - 1
    c, s = pieces[i], t - times[i]
    return c[0] + s * (c[1] + s * (c[2] + s * c[3]))


def _signal_c(signal: _core.Signal, j: int) -> str:
    """The C function u_d_<j>(t) of one channel."""
    if not signal.is_table():
        body = [f"static double u_d_{j}(double t) {{", f"  double value = {_number(signal.offset())};"]
        for h in signal.harmonics():
            function = "cos" if h.cosine else "sin"
            body.append(f"  value += {_number(h.amplitude)} * {function}({_number(h.omega)} * t + {_number(h.phase)});")
        if not signal.harmonics():
            body.append("  (void)t;")
        return "\n".join(body + ["  return value;", "}\n"])
    times = [float(x) for x in signal.table_t()]
    pieces = _table_pieces(signal)
    probes = times + [0.5 * (a + b) for a, b in zip(times, times[1:])] + [a + 0.3 * (b - a) for a, b in zip(times, times[1:])]
    scale = max(1.0, max(abs(float(v)) for v in signal.table_values()))
    worst = max(abs(_evaluate_pieces(signal, pieces, t) - signal(t)) for t in probes)
    if worst > 1e-12 * scale:  # the formulas above copy the C++ ones; a difference is a bug
        raise RuntimeError(f"u_d channel {j}: the exported table differs from the signal by {worst:g}")
    hold = signal.interpolation() == _core.Interpolation.hold
    count = len(times)
    return "\n".join([
        f"static const double u_d_{j}_t[{count}] = {_array(times)};",
        f"static const double u_d_{j}_c[{count - 1}][4] = {{\n  " + ",\n  ".join(_array(c) for c in pieces) + "};",
        f"static double u_d_{j}(double t) {{",
        "  int lo = 0, hi = %d, i;" % count,
        "  double s;",
        (f"  if (t >= u_d_{j}_t[{count - 1}]) return {_number(signal.table_values()[-1])};" if hold else ""),
        f"  while (lo < hi) {{ /* the first time > t */",
        "    const int mid = (lo + hi) / 2;",
        f"    if (u_d_{j}_t[mid] <= t) lo = mid + 1; else hi = mid;",
        "  }",
        f"  i = (lo < 1 ? 1 : (lo > {count - 1} ? {count - 1} : lo)) - 1;",
        f"  s = t - u_d_{j}_t[i];",
        f"  return u_d_{j}_c[i][0] + s * (u_d_{j}_c[i][1] + s * (u_d_{j}_c[i][2] + s * u_d_{j}_c[i][3]));",
        "}\n"])


# --- the export -------------------------------------------------------------------------------

def _check_supported(options: _core.OnlineOptions) -> None:
    f = options.filter
    if f.N.size == 0:
        return
    if f.update != _core.MeasurementUpdate.sampled:
        raise ValueError(f"the {f.update.name} measurement update is not exported yet: the C export supports "
                         "OnlineFilter(update=\"sampled\") (the default; in a scenario [sampling] "
                         "measurement_update = \"sampled\"); run the held or discrete update with the C++ "
                         "OnlineController")


def export_controller(design, out_dir: str | os.PathLike, *, period: float | None = None,
                      options: _core.OnlineOptions | None = None, kappa=1.0) -> ExportedController:
    """Write the online controller of a fixed-horizon design as a self-contained C99 folder.

    The folder (see the module's text and docs/export.md) builds a static library that needs only
    libm and no heap; its ``hinf_controller_step`` computes the commands of
    ``OnlineController(law, options).step`` for the same calls. The tables are the law's at its
    samples t_k = t0 + k T: K_k, A_e, B_e (output feedback also D_e D_e', Z_k and the filter's
    data) and q_d with dq_d/dt; between samples q_d is cubic Hermite (exact at the samples),
    where the C++ controller uses the trajectory's dense output. u_d is the design's own signals.

    Parameters
    ----------
    design : RiccatiSolution or DiscreteDesign
        The design: a solution of the GRDE, emulated at `period` (``SampledLaw.emulated``), or a
        discrete game (``solve_discrete_game``: the digital law at its own period).
    out_dir : str or os.PathLike
        The folder to write (made if missing; the files are replaced whole, or not at all).
    period : float, optional
        The controller's period T (s); required with a RiccatiSolution, none with a
        DiscreteDesign (its own).
    options : OnlineOptions, optional
        The controller's options: the filter (output feedback), the limits, max_age,
        compensate_delay and history (the command ring's length). Default: state feedback
        without limits.
    kappa : float or Signal, optional
        The emulated law's gain scaling kappa(t) (``SampledLaw.emulated``).

    Returns
    -------
    ExportedController
        The folder and the facts its README states (horizon, table size).

    Raises
    ------
    ValueError
        An option the export does not support (the held or discrete measurement update), u_d as
        a function of t, a period with a DiscreteDesign or none with a RiccatiSolution, or
        options the controller refuses (the same messages as ``OnlineController``).

    Examples
    --------
    >>> from hinf_cpp.output.export_c import export_controller
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> limits = hc.ActuatorLimits(u_min=[-3.0, -3.0], u_max=[3.0, 3.0], rate_max=[20.0, 20.0])
    >>> exported = export_controller(design, "ship_controller", period=0.05,
    ...                              options=hc.OnlineOptions(limits=limits))
    >>> exported.steps, exported.t_end, exported.table_bytes
    (200, 10.0, 115680)
    >>> sorted(p.name for p in exported.folder.iterdir())[:3]
    ['CMakeLists.txt', 'README.md', 'hinf_controller.c']
    """
    options = _core.OnlineOptions() if options is None else options
    if isinstance(design, _core.DiscreteDesign):
        if period is not None:
            raise ValueError("a DiscreteDesign has its own period: leave period out")
        if not (isinstance(kappa, (int, float)) and kappa == 1.0):
            raise ValueError("kappa scales the emulated law only: leave it out with a DiscreteDesign")
        law = _core.SampledLaw.digital(design)
        trajectory = design.sampled().trajectory()
        Z = [np.asarray(design.M(k)) for k in range(law.steps() + 1)]
    elif isinstance(design, _core.RiccatiSolution):
        if period is None:
            raise ValueError("the controller's period is missing: give period=T (s)")
        law = _core.SampledLaw.emulated(design, float(period), kappa)
        trajectory = design.trajectory()
        Z = None
    else:
        raise ValueError(f"export_controller needs a RiccatiSolution (solve_grde) or a DiscreteDesign "
                         f"(solve_discrete_game), got {type(design).__name__}")
    _check_supported(options)
    _core.OnlineController(law, options)  # the controller's own checks of the options
    check_output_folder(out_dir)

    model = trajectory.model()
    n, m, T, N = law.n(), law.m(), law.period(), law.steps()
    t0, tf = trajectory.t0(), trajectory.tf()
    times = [min(t0 + k * T, tf) for k in range(N + 1)]  # as SampledLaw's constructor
    if Z is None:
        Z = [np.asarray(design.Z(t)) for t in times]
    q_d = [np.asarray(trajectory.q_d(t)) for t in times]
    u_d = [np.asarray(trajectory.u_d(t)) for t in times]
    dq_d = [np.asarray(model.f(t, q)) + np.asarray(model.G(t, q)) @ u for t, q, u in zip(times, q_d, u_d)]
    filter_ = options.filter
    p = int(filter_.N.shape[0]) if filter_.N.size else 0
    gamma = law.gamma()
    inv_gamma2 = 0.0 if math.isinf(gamma) else 1.0 / (gamma * gamma)

    tables = ["/* The design's tables, written by hinf_cpp.output.export_c (see README.md). */",
              '#include "hinf_controller_tables.h"', "", "#include <math.h>", ""]
    tables.append(_table("hinf_table_A", "[HINF_STEPS + 1][HINF_N * HINF_N]",
                         [trajectory.A_e(t) for t in times]))
    tables.append(_table("hinf_table_B", "[HINF_STEPS + 1][HINF_N * HINF_M]",
                         [trajectory.B_e(t) for t in times]))
    tables.append(_table("hinf_table_q_d", "[HINF_STEPS + 1][HINF_N]", q_d))
    tables.append(_table("hinf_table_dq_d", "[HINF_STEPS + 1][HINF_N]", dq_d))
    tables.append(_table("hinf_table_K", "[HINF_STEPS][HINF_M * HINF_N]", [law.gain(k) for k in range(N)]))
    doubles = (N + 1) * (n * n + n * m + 2 * n) + N * m * n
    heading = model.heading_index()
    if p:
        C = np.asarray(model.C(t0))
        heading_row = -1
        for row in range(p):  # the row of C that is the heading's unit row, as the C++ finds it
            if heading >= 0 and C[row, heading] == 1.0 and float(np.sum(C[row] ** 2)) == 1.0:
                heading_row = row
        hold = filter_.hold if filter_.hold > 0.0 else T
        CtNinv = C.T @ np.linalg.inv(np.asarray(filter_.N))
        CtRinv = hold * CtNinv
        DDt = [np.asarray(trajectory.D_e(t)) @ np.asarray(trajectory.D_e(t)).T for t in times]
        tables.append("#if HINF_P > 0")
        tables.append(_table("hinf_table_DDt", "[HINF_STEPS + 1][HINF_N * HINF_N]", DDt))
        tables.append(_table("hinf_table_Z", "[HINF_STEPS + 1][HINF_N * HINF_N]", Z))
        for name, value in (("hinf_C", C), ("hinf_CtRinv", CtRinv), ("hinf_CtRinvC", CtRinv @ C),
                            ("hinf_S_predict", inv_gamma2 * np.asarray(filter_.Q)),
                            ("hinf_Sigma0", np.asarray(filter_.Sigma0))):
            tables.append(f"const double {name}[{value.size}] = {_array(value)};")
        tables.append(f"const int hinf_heading_row = {heading_row};")
        tables.append("#endif")
        doubles += 2 * (N + 1) * n * n + p * n * 2 + 3 * n * n
    limits = options.limits
    tables += [f"const double hinf_gamma = {_number(gamma)};",
               f"const double hinf_inv_gamma2 = {_number(inv_gamma2)};",
               f"const double hinf_max_age = {_number(options.max_age)};",
               f"const int hinf_compensate_delay = {int(options.compensate_delay)};",
               f"const int hinf_heading_index = {heading};"]
    for name in ("u_min", "u_max", "rate_max"):
        values = np.asarray(getattr(limits, name), dtype=float)
        tables.append(f"const int hinf_has_{name} = {int(values.size > 0)};")
        tables.append(f"const double hinf_{name}[HINF_M] = {_array(values if values.size else np.zeros(m))};")
    channels = trajectory.u_d_signal().channels()
    if not channels:
        raise ValueError("u_d is a function of t: the export needs u_d as signals (constants, harmonics or "
                         "tables), which it writes as C")
    tables += ["", *(_signal_c(signal, j) for j, signal in enumerate(channels)),
               "void hinf_u_d(double t, double *u_d) {",
               *(f"  u_d[{j}] = u_d_{j}(t);" for j in range(m)), "}", ""]

    header = "\n".join([
        "/* The H-infinity tracking controller of hinf_cpp, exported for a vehicle computer (README.md).",
        "   C99, libm only, no heap: the caller owns the state. */",
        "#ifndef HINF_CONTROLLER_H", "#define HINF_CONTROLLER_H", "",
        f"#define HINF_N {n}         /* states */",
        f"#define HINF_M {m}         /* inputs */",
        f"#define HINF_P {p}         /* measured outputs (0: state feedback) */",
        f"#define HINF_MEASUREMENT_SIZE {p if p else n}  /* the numbers a step takes: y, or the state */",
        f"#define HINF_HISTORY {options.history}  /* applied commands remembered */",
        f"#define HINF_STEPS {N}   /* samples t_k = HINF_T0 + k HINF_PERIOD, k = 0 .. HINF_STEPS - 1 */",
        f"#define HINF_T0 {_number(t0)}       /* s */",
        f"#define HINF_PERIOD {_number(T)}   /* s */",
        f"#define HINF_T_END {_number(law.t_end())}   /* s: the design ends here */",
    ]) + "\n" + HEADER_BODY
    exported = ExportedController(folder=pathlib.Path(out_dir), kind=law.kind(), gamma=gamma, t0=t0,
                                  t_end=law.t_end(), period=T, steps=N, n=n, m=m, p=p, table_bytes=8 * doubles)
    files = {"hinf_controller.h": header, "hinf_controller.c": SOURCE, "hinf_controller_tables.h": TABLES_HEADER,
             "hinf_controller_tables.c": "\n".join(tables), "CMakeLists.txt": CMAKE,
             "README.md": _readme(exported, options, model.name())}
    _write_folder(pathlib.Path(out_dir), files)
    return exported


def _write_folder(folder: pathlib.Path, files: dict[str, str]) -> None:
    """All the files at once: written into a scratch folder beside `folder`, then moved in."""
    folder.mkdir(parents=True, exist_ok=True)
    scratch = pathlib.Path(tempfile.mkdtemp(prefix=".export-", dir=folder))
    try:
        for name, text in files.items():
            (scratch / name).write_text(text)
        for name in files:
            os.replace(scratch / name, folder / name)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


CMAKE = """# The exported controller as a static library: cmake -S . -B build && cmake --build build
cmake_minimum_required(VERSION 3.10)
project(hinf_controller C)
add_library(hinf_controller STATIC hinf_controller.c hinf_controller_tables.c)
set_target_properties(hinf_controller PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_include_directories(hinf_controller PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(hinf_controller PRIVATE -Wall -Wextra -pedantic)
endif()
find_library(HINF_LIBM m)  # libm where it is a library of its own
if(HINF_LIBM)
  target_link_libraries(hinf_controller PUBLIC ${HINF_LIBM})
endif()
"""


def _readme(e: ExportedController, options: _core.OnlineOptions, model: str) -> str:
    limits = options.limits
    def vector(v):
        return "none" if len(v) == 0 else "[" + ", ".join(f"{x:g}" for x in v) + "]"
    feedback = (f"output feedback: y = C q ({e.p} numbers per measurement), the estimator and the H-infinity "
                "filter with the sampled measurement update" if e.p else
                f"state feedback: the full state ({e.n} numbers per measurement)")
    return f"""# hinf_controller: an exported H-infinity tracking controller

Written by `hinf_cpp.output.export_c` (hinf_cpp docs/export.md). C99, libm only, no heap, no I/O.

- model: {model}, n = {e.n} states, m = {e.m} inputs; {feedback}
- law: {e.kind}, gamma = {e.gamma:g}, period T = {e.period:g} s
- horizon: [t0, t_end) = [{e.t0:g}, {e.t_end:g}) s, {e.steps} samples
- past the horizon: `hinf_controller_step` answers `HINF_STATUS_PAST_HORIZON` and returns the
  command held; a new design (a new export) is needed to continue
- tables: {e.table_bytes} bytes of constant data ({e.table_bytes / 2**20:.2f} MiB; 8 bytes per double,
  printed with 17 significant digits: the design's doubles exactly)
- limits: u_min {vector(limits.u_min)}, u_max {vector(limits.u_max)}, rate_max {vector(limits.rate_max)}
  (per second; the rate first, then the bounds)
- delay compensation: {"on" if options.compensate_delay else "off"}; max_age {options.max_age:g} s;
  {options.history} commands remembered

## Build

    cmake -S . -B build && cmake --build build      # libhinf_controller.a
    cc -std=c99 -c hinf_controller.c hinf_controller_tables.c   # or any C99 compiler; link with -lm

## Use

```c
#include "hinf_controller.h"

static hinf_controller_state controller;           /* owned by the caller */
hinf_controller_init(&controller);
hinf_controller_reset(&controller, t0, q0, NULL);   /* output feedback: q0 is the initial estimate */
/* every sample: */
hinf_status status = hinf_controller_step(&controller, t_now, measurement_or_NULL, t_meas, u);
/* apply u and hold it; controller.report.measurement says what became of the measurement */
```

The statuses and measurement uses are those of hinf_cpp's `OnlineController.step`
(docs/online.md): `HINF_STATUS_REFUSED` (t_now earlier than the last call, or NaN),
`HINF_STATUS_PAST_HORIZON`, `HINF_STATUS_NOT_RESET`, `HINF_STATUS_LOST` (the estimate is not
finite: held until a reset); `HINF_MEASUREMENT_USED`, `MISSING`, `STALE`, `DUPLICATE`, `FUTURE`,
`NOT_FINITE`.

## What is tabulated

At the samples t_k: the gains K_k, A_e, B_e, q_d and dq_d/dt{", D_e D_e', Z_k" if e.p else ""}; the
linearization is linear between samples, as in the C++ controller. q_d between samples
(a measurement taken between samples, or a reset there) is the cubic Hermite interpolant of q_d
and dq_d/dt, where the C++ controller uses the trajectory's dense output: the two agree exactly
at the samples and to O(T^4) between them. u_d(t) is the design's own signals (constants,
harmonics, tables) written as C. The model's equations are not needed: the estimator runs on
the linearization's tables.
"""


def export_scenario(scenario: _core.Scenario, out_dir: str | os.PathLike, *,
                    period: float | None = None) -> ExportedController:
    """Write the online controller of a scenario as a C99 folder (:func:`export_controller`).

    The design is the scenario's (``run_scenario``, the code path of ``hinf-cpp run``), the
    options those of its ``[sampling]`` table as the sampled loop builds them: the limits,
    max_age, compensate_delay, the design (emulated or digital) and, with ``[measurement]``, the
    filter (N, Sigma0 = (Q0 - eta I)^-1, the design's Q, hold = the measurement period, the
    measurement update).

    Parameters
    ----------
    scenario : Scenario
        The scenario (``load_scenario``).
    out_dir : str or os.PathLike
        The folder to write.
    period : float, optional
        The controller's period T (s), in place of ``[sampling] period``; required when the
        scenario has no ``[sampling]``.

    Returns
    -------
    ExportedController

    Raises
    ------
    ValueError
        No period, the cascade law, or what :func:`export_controller` refuses.

    Examples
    --------
    >>> from hinf_cpp.output.export_c import export_scenario
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> export_scenario(scenario, "fig1_controller", period=0.1).steps
    400
    """
    scenario = scenario.copy()
    sampling = scenario.sampling
    if sampling is None:
        if period is None:
            raise ValueError(f"scenario {scenario.name} has no [sampling] period: give the controller's period "
                             "(--sample-period T)")
        sampling = _core.SamplingSpec(period=float(period))
    elif period is not None:
        sampling.period = float(period)
    if not (math.isfinite(sampling.period) and sampling.period > 0.0):
        raise ValueError(f"the controller's period must be > 0 s, got {sampling.period:g}")
    if scenario.law == _core.Law.cascade:
        raise ValueError("the cascade law is not an online controller: export law = \"hinf\" or \"lqr\"")
    scenario.sampling = sampling
    result = _core.run_scenario(scenario)  # the design of `hinf-cpp run`, and a check that it runs
    resolved = scenario.resolved()
    options = _core.OnlineOptions(limits=sampling.limits, max_age=sampling.max_age,
                                  compensate_delay=sampling.compensate_delay)
    every = 1
    if sampling.measurement_period > 0.0:  # SamplingSpec::measurement_every
        every = max(1, int(math.floor(sampling.measurement_period / sampling.period + 0.5)))
    if resolved.measurement is not None:
        ms = resolved.measurement
        n = scenario.model.n()
        Sigma0 = np.linalg.inv(np.asarray(ms.Q0) - ms.eta * np.eye(n))
        options.filter = _core.OnlineFilter(N=ms.N, Sigma0=0.5 * (Sigma0 + Sigma0.T), Q=resolved.Q,
                                            hold=every * sampling.period, update=sampling.measurement_update)
    if sampling.design == _core.SampledDesign.digital:
        design = _core.solve_discrete_game(result.trajectory, sampling.period, resolved.Q, resolved.Qf,
                                           result.gamma)
        return export_controller(design, out_dir, options=options)
    return export_controller(result.solution, out_dir, period=sampling.period, options=options,
                             kappa=scenario.kappa)
