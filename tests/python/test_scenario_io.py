"""Scenario files (docs/scenarios.md), read by the one C++ reader: a file (hc.load_scenario,
the reader of hinf-sim) and its dictionary form (hc.scenario_from_dict of what tomllib reads,
written back to TOML) build identical scenarios and reject the same bad files with a
ValueError naming the key; both command lines print that same message. Also bad inputs to the
Python API."""

from __future__ import annotations

import math
import pathlib
import subprocess
import sys
import tomllib

import numpy as np
import pytest
from scipy.interpolate import PchipInterpolator

import hinf_cpp as hc
from _support import PAPER_Q0, PAPER_Q_D0, ROUNDOFF

PAPER_TEXT = pathlib.Path(hc.scenario_path("paper_fig1")).read_text()


def mutate(text: str, old: str, new: str) -> str:
    """text with `old` replaced by `new`; `old` must occur (so no case silently tests nothing)."""
    assert old in text, f"test bug: {old!r} not in the scenario text"
    return text.replace(old, new)


def write(tmp_path: pathlib.Path, name: str, text: str) -> pathlib.Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def file_reader(path: pathlib.Path) -> hc.Scenario:
    return hc.load_scenario(path)


def dict_reader(path: pathlib.Path) -> hc.Scenario:
    return hc.scenario_from_dict(tomllib.loads(path.read_text()), str(path))


READERS = {"file": file_reader, "dict": dict_reader}


# ---- comparing scenarios ----

def assert_same_signal(a: hc.Signal, b: hc.Signal, where: str):
    assert a.is_table() == b.is_table(), where
    if a.is_table():
        assert a.interpolation() == b.interpolation(), where
        np.testing.assert_array_equal(a.table_t(), b.table_t(), err_msg=where)
        np.testing.assert_array_equal(a.table_values(), b.table_values(), err_msg=where)
        times = np.linspace(a.table_t()[0], a.table_t()[-1], 97)
    else:
        assert a.offset() == b.offset(), where
        assert len(a.harmonics()) == len(b.harmonics()), where
        for ha, hb in zip(a.harmonics(), b.harmonics()):
            assert (ha.amplitude, ha.omega, ha.phase, ha.cosine) == \
                   (hb.amplitude, hb.omega, hb.phase, hb.cosine), where
        times = np.linspace(-3.0, 50.0, 97)
    np.testing.assert_array_equal(a(times), b(times), err_msg=where)


def assert_same_vector_signal(a: hc.VectorSignal, b: hc.VectorSignal, where: str):
    assert a.dim() == b.dim() and not a.is_function() and not b.is_function(), where
    for i, (sa, sb) in enumerate(zip(a.channels(), b.channels())):
        assert_same_signal(sa, sb, f"{where}[{i}]")


def assert_same_matrix(a, b, where: str):
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape, where
    np.testing.assert_array_equal(a, b, err_msg=where)


def assert_same_scenario(a: hc.Scenario, b: hc.Scenario):
    assert a.name == b.name and a.description == b.description
    assert type(a.model) is type(b.model)
    assert (a.model.n(), a.model.m(), a.model.nw()) == (b.model.n(), b.model.m(), b.model.nw())
    if isinstance(a.model, hc.ShipModel):
        for key in ("m_u", "m_v", "m_r", "d_u", "d_v", "d_r"):
            assert getattr(a.model.parameters(), key) == getattr(b.model.parameters(), key), key
    else:
        assert_same_matrix(a.model.A(), b.model.A(), "A")
    assert_same_matrix(a.model.G(a.t0, np.zeros(a.model.n())), b.model.G(b.t0, np.zeros(b.model.n())), "B")
    assert_same_matrix(a.model.D(a.t0, np.zeros(a.model.n())), b.model.D(b.t0, np.zeros(b.model.n())), "D")
    assert (a.t0, a.tf, a.gamma, a.output_dt, a.divergence_factor, a.law, a.worst_case) == \
           (b.t0, b.tf, b.gamma, b.output_dt, b.divergence_factor, b.law, b.worst_case)
    assert_same_matrix(a.desired_q0, b.desired_q0, "desired q0")
    assert_same_matrix(a.initial_q0, b.initial_q0, "initial q0")
    assert_same_vector_signal(a.desired_u, b.desired_u, "desired_u")
    assert_same_vector_signal(a.disturbance, b.disturbance, "disturbance")
    assert_same_signal(a.kappa, b.kappa, "kappa")
    assert_same_matrix(a.Q, b.Q, "Q")
    assert_same_matrix(a.Qf, b.Qf, "Qf")
    sa, sb = a.solver, b.solver
    assert (sa.method, sa.rtol, sa.atol, sa.max_steps, sa.escape_norm) == \
           (sb.method, sb.rtol, sb.atol, sb.max_steps, sb.escape_norm)
    assert (a.measurement is None) == (b.measurement is None)
    if a.measurement is not None:
        ma, mb = a.measurement, b.measurement
        assert (ma.sigma, ma.sample_period, ma.seed, ma.eta, ma.filter_A, ma.on_coupling_violation) == \
               (mb.sigma, mb.sample_period, mb.seed, mb.eta, mb.filter_A, mb.on_coupling_violation)
        assert_same_matrix(ma.N, mb.N, "N")
        assert_same_matrix(ma.Q0, mb.Q0, "Q0")


def assert_same_metrics(a: hc.Metrics, b: hc.Metrics):
    for key in (definition.name for definition in hc.metric_table()):
        if math.isnan(getattr(a, key)):
            assert math.isnan(getattr(b, key)), key
        else:
            assert getattr(a, key) == pytest.approx(getattr(b, key), rel=1e-12, abs=1e-300), key


def assert_same_run(a: hc.RunResult, b: hc.RunResult):
    """Runs of two scenarios that assert_same_scenario found identical (every number equal):
    the same code on the same input, so equal (measured bit for bit); the 1e-12 below is no
    round-off allowance between different computations."""
    assert a.scenario_name == b.scenario_name and a.gamma == b.gamma
    np.testing.assert_allclose(a.Z0, b.Z0, rtol=1e-12, atol=1e-14)
    for field in ("t", "q", "q_d", "u", "u_d", "w"):
        np.testing.assert_allclose(getattr(a.simulation, field), getattr(b.simulation, field),
                                   rtol=1e-12, atol=1e-14, err_msg=field)
    assert_same_metrics(a.metrics, b.metrics)


# ---- the variants ----

def tabulated_text() -> str:
    t = np.arange(0.0, 40.0 + 1e-9, 0.5)
    u1 = 1.0 + 0.05 * np.sin(t / 3.0)
    u2 = 0.3 * np.sin(0.2 * t)

    def toml_list(values):
        return "[" + ", ".join(repr(float(v)) for v in values) + "]"

    text = mutate(PAPER_TEXT, "u1 = { offset = 1.0 }",
                  f"u1 = {{ table = {{ t = {toml_list(t)}, value = {toml_list(u1)} }} }}")
    text = mutate(text, "u2 = { harmonics = [ { amplitude = 0.3, omega = 0.2 } ] }",
                  f"u2 = {{ table = {{ t = {toml_list(t)}, value = {toml_list(u2)} }} }}")
    text = mutate(text, "kappa = 1.0", "kappa = { table = { t = [0, 20.0, 40], value = [1.0, 1.5, 1.2] } }")
    return text


LINEAR_TEXT = """
name = "lti-variant"
description = "two states, one input, two disturbance channels"

[model]
kind = "linear"
A = [[0.0, 1.0], [-2.0, -0.5]]
B = [[0.0], [1.0]]
D = [[0.1, 0.0], [1.0, 0.3]]

[horizon]
t0 = 1.0
tf = 6.0

[desired]
q0 = [0.5, 0]
u1 = { offset = 0.2, harmonics = [ { amplitude = 0.5, omega = 1.5, phase = 0.3, shape = "cos" } ] }

[controller]
gamma = 3.0
Q = [[2.0, 0.5], [0.5, 1]]
Qf = 0.5
kappa = { offset = 1.0, harmonics = [ { amplitude = 0.2, frequency_hz = 0.1 } ] }

[disturbance]
w2 = { harmonics = [ { amplitude = 0.2, frequency_hz = 0.5 } ] }

[initial]
q0 = [0.0, 1.0]

[solver]
method = "erk"
rtol = 1e-9
atol = 1e-11
max_steps = 100000

[output]
dt = 0.05
"""

LINEAR_DEFAULT_D_TEXT = """
[model]
kind = "linear"
A = [[-1, 2], [0, -3]]
B = [[1, 0], [0, 1]]

[horizon]
tf = 2

[desired]
q0 = [1, 1]
u1 = 0
u2 = -0.5

[controller]
gamma = inf

[initial]
q0 = [0, 0]
"""

OMEGA_TEXT = mutate(PAPER_TEXT, "frequency_hz = 0.2", f"omega = {2.0 * math.pi * 0.2!r}")

MEASUREMENT_TEXT = PAPER_TEXT + """
[measurement]
sigma = 0.5
sample_period = 0.02
seed = 20000601
N = [[0.25, 0, 0], [0, 0.3, 0], [0, 0, 0.25]]
Q0 = 3.0
eta = 0.5
filter_A = "desired"
"""

VARIANTS = {
    "paper_fig1": PAPER_TEXT,
    "tabulated": tabulated_text(),
    "linear": LINEAR_TEXT,
    "linear_default_D": LINEAR_DEFAULT_D_TEXT,
    "omega": OMEGA_TEXT,
}


@pytest.mark.parametrize("variant", list(VARIANTS))
def test_file_and_dict_agree(tmp_path, variant):
    """The dictionary form, written back to TOML, is the same scenario, number for number."""
    path = write(tmp_path, f"{variant}.toml", VARIANTS[variant])
    assert_same_scenario(file_reader(path), dict_reader(path))


def test_file_and_dict_agree_on_measurement_section(tmp_path):
    path = write(tmp_path, "fig2like.toml", MEASUREMENT_TEXT)
    a, b = file_reader(path), dict_reader(path)
    assert_same_scenario(a, b)
    assert a.measurement.sigma == 0.5 and a.measurement.seed == 20000601
    assert a.measurement.filter_A == hc.FilterLinearization.desired


def test_paper_scenario_values(paper_scenario_path):
    """The shipped file holds the paper's run as scenarios.md fixes it."""
    for reader in READERS.values():
        s = reader(pathlib.Path(paper_scenario_path))
        assert s.name == "paper-fig1"
        assert isinstance(s.model, hc.ShipModel)
        p = s.model.parameters()
        assert (p.m_u, p.m_v, p.m_r, p.d_u, p.d_v, p.d_r) == (0.5, -2.0, 0.5, 1.0, 2.0, 1.0)
        assert (s.t0, s.tf, s.gamma) == (0.0, 40.0, 5.0)
        np.testing.assert_array_equal(s.desired_q0, PAPER_Q_D0)
        np.testing.assert_array_equal(s.initial_q0, PAPER_Q0)
        np.testing.assert_array_equal(s.Q, np.eye(6))
        np.testing.assert_array_equal(s.Qf, np.eye(6))
        times = np.linspace(-1.0, 41.0, 211)
        # The library's sin/cos against NumPy's (which has its own SIMD kernels): round-off of
        # the amplitudes 0.3 and 0.1.
        np.testing.assert_allclose(s.desired_u(times), np.column_stack([np.ones_like(times), 0.3 * np.sin(0.2 * times)]),
                                   rtol=0, atol=ROUNDOFF * 0.3)
        w = 0.1 * np.cos(2 * math.pi * 0.2 * times)
        np.testing.assert_allclose(s.disturbance(times), np.column_stack([w, w, w] + [0 * w] * 3), rtol=0,
                                   atol=ROUNDOFF * 0.1)
        assert s.kappa(7.0) == 1.0
        assert s.measurement is None and s.solver.method == hc.Method.bdf and s.output_dt == 0.01


def test_frequency_hz_equals_omega(tmp_path):
    """frequency_hz = f is omega = 2 pi f: same scenario, same run."""
    hz = write(tmp_path, "hz.toml", PAPER_TEXT)
    omega = write(tmp_path, "omega.toml", OMEGA_TEXT)
    for reader in READERS.values():
        a, b = reader(hz), reader(omega)
        h = a.disturbance.channels()[0].harmonics()[0]
        assert h.omega == pytest.approx(2 * math.pi * 0.2, rel=1e-15) and h.cosine
        assert_same_scenario(a, b)
    assert_same_run(hc.run_scenario(file_reader(hz)), hc.run_scenario(dict_reader(omega)))


def test_tabulated_signal_is_pchip_by_default(tmp_path):
    t = np.array([0.0, 0.7, 1.5, 3.0, 3.2, 5.0, 8.0])
    v = np.array([1.0, -0.5, 0.25, 2.0, 1.5, -1.0, 0.0])
    pchip = PchipInterpolator(t, v)
    times = np.linspace(0.0, 8.0, 801)
    direct = hc.Signal.table(list(t), list(v))
    # The same slopes and cubic pieces from two codes: round-off of the terms (|v| <= 2, slopes
    # at most 3 secants, times intervals up to 15 times the shortest).
    atol = ROUNDOFF * np.max(np.abs(v)) * 15
    np.testing.assert_allclose(direct(times), pchip(times), rtol=0, atol=atol)
    text = mutate(LINEAR_DEFAULT_D_TEXT, "u1 = 0", f"u1 = {{ table = {{ t = {t.tolist()}, value = {v.tolist()} }} }}")
    text = mutate(text, "tf = 2", "tf = 8")
    path = write(tmp_path, "table.toml", text)
    for reader in READERS.values():
        np.testing.assert_allclose(reader(path).desired_u(times)[:, 0], pchip(times), rtol=0, atol=atol)
    with pytest.raises(ValueError, match="outside"):
        direct(8.5)


def test_harmonic_signal_formula():
    s = hc.Signal(0.5, [hc.Harmonic(0.3, 2.0, 0.1, True), hc.Harmonic(-1.2, 0.7, -0.4)])
    times = np.linspace(-5.0, 5.0, 101)
    expected = 0.5 + 0.3 * np.cos(2.0 * times + 0.1) - 1.2 * np.sin(0.7 * times - 0.4)
    # C++ against NumPy: round-off of the terms (0.5 + 0.3 + 1.2).
    np.testing.assert_allclose(s(times), expected, rtol=0, atol=ROUNDOFF * 2.0)
    # Scalar and array evaluation: the same code on the same time.
    assert isinstance(s(1.25), float) and s(1.25) == s(np.array([1.25]))[0]
    assert s(np.float32(1.25)) == s(np.array([np.float32(1.25)]))[0]


# ---- bad scenario files: ValueError naming the key, the same message everywhere ----

def drop_section(text: str, header: str) -> str:
    start = text.index(header)
    end = text.find("\n[", start + 1)
    return text[:start] + (text[end + 1:] if end >= 0 else "")


Q_ROWS = "[[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,0,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]]"
HARMONIC = "{ amplitude = 0.3, omega = 0.2 }"
FIRST_Q0 = "q0 = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]"
INITIAL_Q0 = "q0 = [1.0, 0.0, 0.0, -1.0, -1.0, 0.7853981633974483]"

# id -> (scenario text, words the message must contain)
BAD_CASES = {
    "unknown key": (mutate(PAPER_TEXT, "gamma = 5.0", "gama = 5.0"), ["gama"]),
    "unknown key in a harmonic": (mutate(PAPER_TEXT, HARMONIC, "{ amplitude = 0.3, omega = 0.2, freq = 1 }"), ["freq"]),
    "unknown section": (PAPER_TEXT + "\n[extra]\na = 1\n", ["extra"]),
    "string for a number (tf)": (mutate(PAPER_TEXT, "tf = 40.0", 'tf = "40"'), ["tf"]),
    "string for a number (gamma)": (mutate(PAPER_TEXT, "gamma = 5.0", 'gamma = "5.0"'), ["gamma"]),
    "boolean for a signal (kappa)": (mutate(PAPER_TEXT, "kappa = 1.0", "kappa = true"), ["kappa"]),
    "number for a string (method)": (mutate(PAPER_TEXT, 'method = "bdf"', "method = 3"), ["method"]),
    "vector too short": (mutate(PAPER_TEXT, FIRST_Q0, "q0 = [1.0, 0.0, 0.0, 0.0, 0.0]"), ["q0"]),
    "vector too long": (mutate(PAPER_TEXT, INITIAL_Q0, "q0 = [1.0, 0.0, 0.0, -1.0, -1.0, 0.78, 0.0]"), ["q0"]),
    "Q with 5 rows": (mutate(PAPER_TEXT, "Q = 1.0", "Q = " + Q_ROWS.replace(",[0,0,0,0,0,1]", "")), ["Q"]),
    "non-symmetric Q": (mutate(PAPER_TEXT, "Q = 1.0", "Q = " + Q_ROWS.replace("[[1,0,", "[[1,0.5,", 1)),
                        ["Q", "symmetric"]),
    "indefinite Q": (mutate(PAPER_TEXT, "Q = 1.0", "Q = " + Q_ROWS.replace("[0,1,0,0,0,0]", "[0,-1,0,0,0,0]")),
                     ["Q", "semidefinite"]),
    "Qf zero": (mutate(PAPER_TEXT, "Qf = 1.0", "Qf = 0.0"), ["Qf", "positive definite"]),
    "Qf only semidefinite": (mutate(PAPER_TEXT, "Qf = 1.0", "Qf = " + Q_ROWS.replace("[0,0,0,0,0,1]", "[0,0,0,0,0,0]")),
                             ["Qf", "positive definite"]),
    "NaN gamma": (mutate(PAPER_TEXT, "gamma = 5.0", "gamma = nan"), ["gamma"]),
    "NaN Q": (mutate(PAPER_TEXT, "Q = 1.0", "Q = nan"), ["Q"]),
    "NaN tf": (mutate(PAPER_TEXT, "tf = 40.0", "tf = nan"), ["tf"]),
    "NaN in q0": (mutate(PAPER_TEXT, INITIAL_Q0, "q0 = [1.0, 0.0, nan, -1.0, -1.0, 0.78]"), ["q0"]),
    "NaN amplitude": (mutate(PAPER_TEXT, "amplitude = 0.3", "amplitude = nan"), ["u2", "amplitude"]),
    "NaN offset": (mutate(PAPER_TEXT, "u1 = { offset = 1.0 }", "u1 = { offset = nan }"), ["u1", "offset"]),
    "NaN constant signal (u1)": (mutate(PAPER_TEXT, "u1 = { offset = 1.0 }", "u1 = nan"), ["u1"]),
    "NaN kappa": (mutate(PAPER_TEXT, "kappa = 1.0", "kappa = nan"), ["kappa"]),
    "gamma zero": (mutate(PAPER_TEXT, "gamma = 5.0", "gamma = 0.0"), ["gamma"]),
    "gamma negative": (mutate(PAPER_TEXT, "gamma = 5.0", "gamma = -5.0"), ["gamma"]),
    "tf equal to t0": (mutate(PAPER_TEXT, "tf = 40.0", "tf = 0.0"), ["tf"]),
    "tf before t0": (mutate(PAPER_TEXT, "tf = 40.0", "tf = -1.0"), ["tf"]),
    "kappa zero": (mutate(PAPER_TEXT, "kappa = 1.0", "kappa = 0.0"), ["kappa"]),
    "kappa negative somewhere": (
        mutate(PAPER_TEXT, "kappa = 1.0", "kappa = { offset = 0.5, harmonics = [ { amplitude = 1.0, omega = 0.3 } ] }"),
        ["kappa"]),
    "both omega and frequency_hz": (mutate(PAPER_TEXT, HARMONIC, "{ amplitude = 0.3, omega = 0.2, frequency_hz = 0.1 }"),
                                    ["omega", "frequency_hz"]),
    "neither omega nor frequency_hz": (mutate(PAPER_TEXT, HARMONIC, "{ amplitude = 0.3 }"),
                                       ["omega", "frequency_hz"]),
    "missing [initial]": (drop_section(PAPER_TEXT, "[initial]"), ["initial"]),
    "missing [controller]": (drop_section(PAPER_TEXT, "[controller]"), ["controller"]),
    "missing [model]": (drop_section(PAPER_TEXT, "[model]"), ["model"]),
    "missing gamma": (mutate(PAPER_TEXT, "gamma = 5.0\n", ""), ["gamma"]),
    "unknown solver method": (mutate(PAPER_TEXT, 'method = "bdf"', 'method = "rk4"'), ["method", "rk4"]),
    "unknown shape": (mutate(PAPER_TEXT, 'shape = "cos" } ] }\nw2', 'shape = "tan" } ] }\nw2'), ["shape"]),
    "unknown model kind": (mutate(PAPER_TEXT, 'kind = "ship"', 'kind = "boat"'), ["kind", "boat"]),
    "ship with a linear key": (mutate(PAPER_TEXT, 'kind = "ship"', 'kind = "ship"\nA = [[1.0]]'), ["A"]),
    "dt zero": (mutate(PAPER_TEXT, "dt = 0.01", "dt = 0.0"), ["dt"]),
    "table not increasing": (
        mutate(PAPER_TEXT, "u1 = { offset = 1.0 }", "u1 = { table = { t = [0.0, 50.0, 40.0], value = [1.0, 1.0, 1.0] } }"),
        ["u1", "increasing"]),
}


def reader_error(reader, path):
    """(stage, message) of the first ValueError from reading or running the scenario."""
    try:
        scenario = reader(path)
    except ValueError as error:
        return "read", str(error)
    try:
        hc.run_scenario(scenario)
    except ValueError as error:
        return "run", str(error)
    return None, None


@pytest.mark.parametrize("case", list(BAD_CASES))
def test_bad_scenario_rejected_naming_the_key(tmp_path, case):
    text, words = BAD_CASES[case]
    path = write(tmp_path, "bad.toml", text)
    results = {name: reader_error(reader, path) for name, reader in READERS.items()}
    for name, (stage, message) in results.items():
        assert stage is not None, f"{name}: the scenario was accepted"
        for word in words:
            assert word in message, f"{name}: {word!r} not in {message!r}"
        if stage == "read":
            assert message.count(str(path)) == 1, f"{name}: the file is not named once in {message!r}"
    assert results["file"] == results["dict"]


BIN = pathlib.Path(sys.executable).parent


@pytest.mark.skipif(not ((BIN / "hinf-sim").exists() and (BIN / "hinf-cpp").exists()),
                    reason="hinf-sim / hinf-cpp are not installed next to this Python")
@pytest.mark.parametrize("case", list(BAD_CASES))
def test_bad_scenario_same_message_from_both_front_ends(tmp_path, case):
    """hinf-sim and hinf-cpp run print the library's message, one line, exit status 2."""
    path = write(tmp_path, "bad.toml", BAD_CASES[case][0])
    _, expected = reader_error(file_reader, path)
    for program, args in (("hinf-sim", [BIN / "hinf-sim", path]), ("hinf-cpp", [BIN / "hinf-cpp", "run", path])):
        result = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=120)
        assert result.returncode == 2, (program, result.stderr)
        assert result.stderr == f"{program}: error: {expected}\n"


def test_toml_syntax_error_names_the_line(tmp_path):
    path = write(tmp_path, "syntax.toml", mutate(PAPER_TEXT, "gamma = 5.0", "gamma = = 5.0"))
    line = PAPER_TEXT.splitlines().index("gamma = 5.0") + 1
    with pytest.raises(ValueError, match="invalid TOML") as info:
        hc.load_scenario(path)
    assert f"{path}:{line}:" in str(info.value)
    assert "[controller] gamma" in str(info.value)


def test_missing_file():
    with pytest.raises(ValueError, match="cannot read"):
        hc.load_scenario("/nonexistent/scenario.toml")


def test_shipped_bad_unknown_key_fixture():
    path = pathlib.Path(__file__).resolve().parents[1] / "data" / "bad_unknown_key.toml"
    for reader in READERS.values():
        with pytest.raises(ValueError, match="gama"):
            reader(path)


# ---- bad inputs to the Python API ----

@pytest.fixture(scope="module")
def short_trajectory(ship):
    return hc.Trajectory(ship, PAPER_Q_D0, [1.0, 0.0], 0.0, 2.0)


@pytest.fixture(scope="module")
def short_solution(short_trajectory):
    return hc.solve_grde(short_trajectory, np.eye(6), np.eye(6), 5.0)


EYE = np.eye(6)
NAN_Q = np.eye(6)
NAN_Q[2, 4] = NAN_Q[4, 2] = np.nan


@pytest.mark.parametrize("Q,Qf,gamma,words", [
    (np.eye(5), EYE, 5.0, ["Q", "(6, 6)", "(5, 5)"]),
    (np.ones(6), EYE, 5.0, ["Q", "(6, 6)"]),
    (EYE, np.ones((6, 5)), 5.0, ["Qf", "(6, 5)"]),
    (NAN_Q, EYE, 5.0, ["Q", "non-finite"]),
    (EYE, np.where(EYE > 0, np.inf, 0.0), 5.0, ["Qf", "non-finite"]),
    (EYE + np.triu(np.ones((6, 6)), 1) * 0.1, EYE, 5.0, ["Q", "symmetric"]),
    (-EYE, EYE, 5.0, ["Q", "semidefinite"]),
    (EYE, np.diag([1.0] * 5 + [0.0]), 5.0, ["Qf", "positive definite"]),
    (EYE, EYE, 0.0, ["gamma"]),
    (EYE, EYE, -1.0, ["gamma"]),
    (EYE, EYE, float("nan"), ["gamma"]),
    (EYE, EYE, -math.inf, ["gamma"]),
], ids=["Q 5x5", "Q 1-D", "Qf 6x5", "NaN in Q", "inf in Qf", "Q not symmetric", "Q negative",
        "Qf singular", "gamma 0", "gamma < 0", "gamma NaN", "gamma -inf"])
def test_solve_grde_bad_inputs(short_trajectory, Q, Qf, gamma, words):
    with pytest.raises(ValueError) as info:
        hc.solve_grde(short_trajectory, Q, Qf, gamma)
    for word in words:
        assert word in str(info.value)


def test_definiteness_is_judged_relative_to_the_weight_scale(short_trajectory):
    # A tiny positive definite weight is as valid as I; a tiny indefinite one is still rejected.
    Z = hc.solve_grde(short_trajectory, 1e-12 * EYE, 1e-12 * EYE, math.inf)
    assert np.all(np.isfinite(Z.Z(0.0)))
    with pytest.raises(ValueError, match="Qf must be positive definite"):
        hc.solve_grde(short_trajectory, EYE, 1e-12 * np.diag([1.0] * 5 + [-1.0]), 5.0)
    with pytest.raises(ValueError, match="Qf must be positive definite"):
        hc.solve_grde(short_trajectory, EYE, np.diag([1.0] * 5 + [1e-14]), 5.0)


def test_solver_options_bad_inputs(short_trajectory):
    with pytest.raises(ValueError, match="rk4"):
        hc.SolverOptions(method="rk4")
    with pytest.raises(ValueError, match="rtol"):
        hc.SolverOptions(rtol=-1.0)
    with pytest.raises(ValueError, match="atol"):
        hc.SolverOptions(atol=0.0)
    options = hc.SolverOptions()
    options.max_steps = 0
    with pytest.raises(ValueError, match="max_steps"):
        hc.solve_grde(short_trajectory, EYE, EYE, 5.0, options)


@pytest.mark.parametrize("q0,words", [
    (np.zeros(5), ["q0", "6", "5"]),
    (np.zeros(7), ["q0", "6", "7"]),
    (np.array([1.0, 0, 0, np.nan, 0, 0]), ["q0", "non-finite"]),
], ids=["5 states", "7 states", "NaN"])
def test_simulate_bad_initial_state(short_trajectory, short_solution, q0, words):
    with pytest.raises(ValueError) as info:
        hc.simulate_state_feedback(short_trajectory, hc.HinfStateFeedback(short_solution), None, q0)
    for word in words:
        assert word in str(info.value)


def test_simulate_other_bad_inputs(short_trajectory, short_solution):
    controller = hc.HinfStateFeedback(short_solution)
    with pytest.raises(ValueError, match="disturbance"):
        hc.simulate_state_feedback(short_trajectory, controller, [0.0] * 3, PAPER_Q_D0)
    with pytest.raises(ValueError, match="length 3"):
        hc.simulate_state_feedback(short_trajectory, controller, lambda t: np.zeros(3), PAPER_Q_D0)
    with pytest.raises(ValueError, match="dt"):
        hc.simulate_state_feedback(short_trajectory, controller, None, PAPER_Q_D0, hc.SimulationOptions(output_dt=0.0))

    class ThreeInputs(hc.Controller):
        def __init__(self):
            hc.Controller.__init__(self)

        def m(self):
            return 3

        def control(self, t, q):
            return np.zeros(3)

    with pytest.raises(ValueError, match="3 inputs"):
        hc.simulate_state_feedback(short_trajectory, ThreeInputs(), None, PAPER_Q_D0)


@pytest.mark.parametrize("u_d,words", [
    (lambda t: np.array([1.0]), ["length 1", "expected 2"]),
    (lambda t: np.array([1.0, 0.0, 0.0]), ["length 3", "expected 2"]),
    (lambda t: np.array([math.nan, 0.0]), ["non-finite"]),
    ([1.0], ["u_d", "1 channels", "expected 2"]),
    ([1.0, 0.0, 0.0], ["u_d", "3 channels", "expected 2"]),
], ids=["callable short", "callable long", "callable NaN", "list short", "list long"])
def test_trajectory_bad_desired_input(ship, u_d, words):
    with pytest.raises(ValueError) as info:
        hc.Trajectory(ship, PAPER_Q_D0, u_d, 0.0, 1.0)
    for word in words:
        assert word in str(info.value)


def test_trajectory_bad_horizon_and_state(ship):
    with pytest.raises(ValueError, match="tf > t0"):
        hc.Trajectory(ship, PAPER_Q_D0, [1.0, 0.0], 1.0, 0.5)
    with pytest.raises(ValueError, match="q_d0"):
        hc.Trajectory(ship, PAPER_Q_D0[:5], [1.0, 0.0], 0.0, 1.0)
    with pytest.raises(ValueError, match="outside"):
        hc.Trajectory(ship, PAPER_Q_D0, [hc.Signal.table([0.0, 0.5], [1.0, 1.0]), 0.0], 0.0, 1.0)
