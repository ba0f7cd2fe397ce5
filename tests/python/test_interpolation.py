"""Table signals and their interpolation (docs/scenarios.md, "Signals"): "pchip" against SciPy's
PchipInterpolator on step-like and smooth tables, and each other mode once against an
independent definition: "cubic" against CubicSpline(bc_type="natural"), "linear" against
np.interp, "hold" against the last point at or before t (np.searchsorted); the warning for a
cubic spline that overshoots, from Python, a scenario file and both command lines.

tests/cpp/test_signal.cpp checks the other modes on many tables (hand-solved and independently
solved splines, the definitions of linear and hold), no overshoot for pchip, linear and hold,
and the exact overshoot of a spline, but PCHIP's values only against slopes derived by hand on
two small tables: SciPy's PchipInterpolator on the random and step-like tables here is the
stronger check."""

from __future__ import annotations

import pathlib
import pickle
import subprocess
import sys
import warnings

import numpy as np
import pytest
from scipy.interpolate import CubicSpline, PchipInterpolator

import hinf_cpp as hc
from _support import ROUNDOFF

MODES = ("pchip", "linear", "hold", "cubic")
PAPER_TEXT = pathlib.Path(hc.scenario_path("paper_fig1")).read_text()
BIN = pathlib.Path(sys.executable).parent


def tables():
    """(name, t, v): step-like tables (runs of equal values, jumps between them) and smooth
    ones, with unequal spacing; random ones seeded."""
    rng = np.random.default_rng(20240611)
    out = [("step", np.array([0.0, 10.0, 20.0, 20.5, 30.0, 60.0]), np.array([0.0, 0.0, 0.0, 1.0, 1.0, 1.0])),
           ("pulse", np.array([0.0, 5.0, 5.1, 12.0, 12.2, 30.0]), np.array([0.2, 0.2, -0.3, -0.3, 0.2, 0.2])),
           ("two points", np.array([1.0, 4.0]), np.array([2.0, -1.0]))]
    t = np.cumsum(rng.uniform(0.1, 1.0, 25)) - 3.0
    out.append(("smooth", t, np.sin(0.7 * t) + 0.1 * t))
    for k in range(4):
        t = np.cumsum(rng.uniform(0.01, 2.0, 15))
        v = rng.uniform(-2.0, 2.0, 15)
        if k % 2 == 0:  # step-like: each value repeats the previous one with probability 1/2
            for i in range(1, len(v)):
                if rng.uniform() < 0.5:
                    v[i] = v[i - 1]
        out.append((f"random {k}", t, v))
    return out


def hold_reference(t, v, x):
    """The value of the last point at or before x."""
    return v[np.searchsorted(t, x, side="right") - 1]


def reference(mode, t, v):
    if mode == "pchip":
        return PchipInterpolator(t, v)
    if mode == "cubic":
        return CubicSpline(t, v, bc_type="natural")
    if mode == "linear":
        return lambda x: np.interp(x, t, v)
    return lambda x: hold_reference(t, v, x)


def cases():
    """(mode, name, t, v): PCHIP on every table, each other mode on one (which shows that its
    name selects it)."""
    out = [("pchip", name, t, v) for name, t, v in tables()]
    name, t, v = next(table for table in tables() if table[0] == "random 1")
    return out + [(mode, name, t, v) for mode in MODES if mode != "pchip"]


@pytest.mark.parametrize("mode,name,t,v", cases(), ids=[f"{mode}-{name}" for mode, name, _, _ in cases()])
def test_each_interpolation_matches_its_definition(mode, name, t, v):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the cubic spline of a step overshoots: tested below
        signal = hc.Signal.table(t, v, interpolation=mode)
    assert signal.interpolation() == hc.Interpolation(mode)
    x = np.concatenate([np.linspace(t[0], t[-1], 2001), t])
    if mode == "hold":
        np.testing.assert_array_equal(signal(x), hold_reference(t, v, x))  # a copy of a value: exact
        return
    # The same piecewise cubics in another evaluation (SciPy's PPoly, or np.interp), with slopes
    # or second derivatives from another solve: round-off of the terms. The terms are the size
    # of the values times the ratio of the longest to the shortest interval (the spline's
    # solve; PCHIP's slopes are at most 3 secants), here below 200.
    ratio = np.max(np.diff(t)) / np.min(np.diff(t))
    atol = ROUNDOFF * np.max(np.abs(v)) * max(1.0, ratio)
    np.testing.assert_allclose(signal(x), reference(mode, t, v)(x), rtol=0, atol=atol)


def test_the_overshoot_example_of_the_reference():
    """docs/scenarios.md: zeros up to t = 10, then 1 from t = 20. The natural spline rings, and
    says so in a UserWarning; overshoot() gives the amount and where (the amount against dense
    sampling, and PCHIP, the line and the hold staying in [0, 1]: tests/cpp/test_signal.cpp)."""
    t, v = [0.0, 10.0, 20.0, 30.0, 40.0], [0.0, 0.0, 1.0, 1.0, 1.0]
    with pytest.warns(UserWarning, match=r"Signal.table: the cubic interpolation of the table leaves the range "
                                         r"\[0, 1\] of its values by 0\.13"):
        cubic = hc.Signal.table(t, v, interpolation="cubic")
    amount, where = cubic.overshoot()
    assert 0.125 <= amount < 0.135  # the amount the warning prints
    # The spline at `where` is 1 + amount above the step or -amount below it: the same pieces
    # evaluated again, round-off.
    assert abs(cubic(where) - (1.0 + amount if cubic(where) > 0.5 else -amount)) < ROUNDOFF
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # none of these warns
        for mode in ("pchip", "linear", "hold"):
            assert hc.Signal.table(t, v, interpolation=mode).overshoot()[0] == 0.0
        hc.Signal.table(t, [0.0, 1.0, 2.0, 3.0, 4.0], interpolation="cubic")  # a line: no overshoot


def test_default_is_pchip_and_bad_names_are_refused():
    assert hc.Signal.table([0.0, 1.0, 2.0], [0.0, 1.0, 1.0]).interpolation() == hc.Interpolation.pchip
    with pytest.raises(ValueError, match='unknown interpolation "spline": use "pchip", "linear", "hold" or "cubic"'):
        hc.Signal.table([0.0, 1.0], [0.0, 1.0], interpolation="spline")


@pytest.mark.parametrize("mode", MODES)
def test_pickle_keeps_the_interpolation(mode):
    t, v = [-2.0, 0.0, 5.5, 13.0], [1.0, -1.0, 2.5, 0.0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        signal = hc.Signal.table(t, v, interpolation=mode)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # unpickling does not warn again
        copy = pickle.loads(pickle.dumps(signal))
    assert copy.interpolation() == signal.interpolation()
    x = np.linspace(-2.0, 13.0, 301)
    np.testing.assert_array_equal(copy(x), signal(x))


def step_scenario_text(interpolation: str | None) -> str:
    """The paper's scenario with u2 a step-like table (zeros, then 0.1 from t = 20)."""
    key = "" if interpolation is None else f', interpolation = "{interpolation}"'
    table = f"u2 = {{ table = {{ t = [0.0, 10.0, 20.0, 30.0, 40.0], value = [0.0, 0.0, 0.1, 0.1, 0.1]{key} }} }}"
    old = "u2 = { harmonics = [ { amplitude = 0.3, omega = 0.2 } ] }"
    assert old in PAPER_TEXT
    return PAPER_TEXT.replace(old, table)


@pytest.mark.parametrize("interpolation", [None, "pchip", "linear", "hold", "cubic"])
def test_scenario_key_file_and_dict(tmp_path, interpolation):
    import tomllib

    path = tmp_path / "step.toml"
    path.write_text(step_scenario_text(interpolation))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        from_file = hc.load_scenario(path)
        from_dict = hc.scenario_from_dict(tomllib.loads(path.read_text()), str(path))
    expected = interpolation or "pchip"
    for scenario in (from_file, from_dict):
        assert scenario.desired_u.channels()[1].interpolation() == hc.Interpolation(expected)
    messages = [str(w.message) for w in caught]
    if expected == "cubic":  # warned once per reader, naming the file and the key
        assert len(messages) == 2 and all(f"{path}: [desired] u2: the cubic interpolation" in m for m in messages)
    else:
        assert messages == []
    # Written with its interpolation; reads back to the same signal.
    text = hc._core.scenario_toml(from_file)
    assert f'interpolation = "{expected}"' in text
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        again = hc.scenario_from_dict(tomllib.loads(text))
    x = np.linspace(0.0, 40.0, 401)
    np.testing.assert_array_equal(again.desired_u(x), from_file.desired_u(x))


def test_signal_from_spec_warns_about_an_overshooting_spline():
    spec = {"table": {"t": [0.0, 1.0, 2.0], "value": [0.0, 1.0, 1.0], "interpolation": "cubic"}}
    with pytest.warns(UserWarning, match=r"kappa: the cubic interpolation of the table leaves"):
        hc.signal_from_spec(spec, "kappa")


@pytest.mark.skipif(not ((BIN / "hinf-sim").exists() and (BIN / "hinf-cpp").exists()),
                    reason="hinf-sim / hinf-cpp are not installed next to this Python")
def test_both_command_lines_warn_after_a_successful_run(tmp_path):
    path = tmp_path / "step.toml"
    path.write_text(step_scenario_text("cubic"))
    for program, args in (("hinf-sim", [path]), ("hinf-cpp", ["run", path])):
        done = subprocess.run([str(BIN / program), *map(str, args)], capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr
        lines = done.stderr.splitlines()
        assert len(lines) == 1, done.stderr
        assert lines[0].startswith(f"{program}: warning: {path}: [desired] u2: the cubic interpolation of the table "
                                   "leaves the range [0, 0.1]"), lines[0]
    path.write_text(step_scenario_text("pchip"))
    done = subprocess.run([str(BIN / "hinf-sim"), str(path)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0 and done.stderr == ""
