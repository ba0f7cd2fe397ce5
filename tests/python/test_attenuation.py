"""Each law's worst-case disturbance and its gain against frequency (hinf_cpp.analysis.attenuation).

The truths: hinf_cpp.law_gain (the law's induced L2 gain, checked against closed forms in C++),
the same closed loop integrated independently with SciPy, and on the paper's ship the measured
gains of the shipped sinusoidal disturbances."""

from __future__ import annotations

import csv
import math
import pathlib

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import hinf_cpp as hc
from hinf_cpp.analysis.attenuation import (frequency_figure, gain_against_frequency, law_run, measured_ratio,
                                           worst_disturbance)
from hinf_cpp.cli import main

ROOT = pathlib.Path(__file__).resolve().parents[2]
A_OPEN = 0.5  # the scalar plant dx/dt = 0.5 x + u + w1 (open-loop unstable); w2 does not reach it


@pytest.fixture(scope="module")
def scalar():
    return hc.scenario_from_dict({
        "name": "scalar", "model": {"kind": "linear", "A": [[A_OPEN]], "B": [[1.0]], "D": [[1.0, 0.0]]},
        "horizon": {"t0": 0.0, "tf": 10.0}, "desired": {"q0": [0.0], "u1": {"offset": 0.0}},
        "controller": {"gamma": 3.0, "Q": 1.0, "Qf": 1.0}, "initial": {"q0": [0.0]}, "output": {"dt": 0.01}})


@pytest.fixture(scope="module")
def ship():
    return hc.load_scenario(hc.scenario_path("paper_fig1"))


def linear_ratio(law, w, t_end):
    """sqrt(x(tf)^2 + int (1 + K^2) x^2 dt) / ||w|| of the scalar closed loop dx/dt = (a - K) x + w(t),
    x(0) = 0, integrated by SciPy (DOP853, tight tolerances) with the cost and |w|^2 as states."""
    def rhs(t, y):
        k, wt = law.gain(t)[0, 0], w(t)
        return [(A_OPEN - k) * y[0] + wt, (1.0 + k * k) * y[0] ** 2, wt * wt]
    sol = solve_ivp(rhs, (0.0, t_end), [0.0, 0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-13, max_step=0.01)
    x, cost, energy = sol.y[:, -1]
    return math.sqrt((cost + x * x) / energy)


@pytest.mark.parametrize("law_name", ["hinf", "lqr"])
def test_scalar_worst_case_attains_the_laws_gain(scalar, law_name):
    law = law_run(scalar, law_name).solution
    gain = hc.law_gain(law, np.eye(1), np.eye(1)).gamma_star
    steps = 200
    h = 10.0 / steps
    worst = worst_disturbance(law, np.eye(1), np.eye(1), steps=steps)
    assert worst.converged and worst.w.shape == (steps + 1, 2)
    assert np.all(worst.w[:, 1] == 0.0)  # D_e does not reach w2: T*T maps it to 0
    assert math.isclose(math.sqrt(np.trapezoid(np.sum(worst.w ** 2, axis=1), worst.t)), 1.0, rel_tol=1e-12)
    # The ratio reported is that of the signal: SciPy's integration of the same closed loop with
    # the same (linearly interpolated) w agrees up to the grid's discretization error. The
    # trapezoid rule's relative error on int |z|^2 is h^2/12 |f''/f|, f varying on the closed
    # loop's time scale, |f''/f| <= (2 |a - K|)^2 <= 9 here (K <= 2): 0.75 h^2 on the squared
    # ratio, 0.375 h^2 < h^2 / 2 on the ratio (RK4's O(h^4) is far below).
    exact = linear_ratio(law, lambda t: np.interp(t, worst.t, worst.w[:, 0]), 10.0)
    assert abs(worst.ratio / exact - 1.0) <= h * h / 2  # 1.25e-3; measured 1.5e-5
    # The maximizer: within 1% of the law's gain (the brief's tolerance; measured 2e-5 below),
    # and not above it beyond law_gain's bisection (rtol 1e-7) and the discretization (h^2 / 2):
    # a signal linear between samples is one of the disturbances the gain is the sup over.
    assert gain * 0.99 <= worst.ratio <= gain * (1.0 + 1e-7 + h * h / 2)


def test_power_iteration_respects_budget_and_tolerance(scalar):
    law = law_run(scalar, "lqr").solution
    short = worst_disturbance(law, np.eye(1), np.eye(1), steps=100, max_iterations=2, tolerance=1e-12)
    assert short.iterations == 2 and not short.converged and short.residual > 1e-12
    full = worst_disturbance(law, np.eye(1), np.eye(1), steps=100, tolerance=1e-8)
    assert full.converged and full.residual < 1e-8 and full.iterations > short.iterations
    assert full.ratio >= short.ratio  # the Rayleigh quotient of power iteration increases


def test_a_sinusoid_on_a_linear_plant_measures_its_linear_ratio(scalar):
    """The sinusoid is w1 = A sin(omega t) in rad/s on channel 1: the measured gain of the (here
    exactly linear) loop equals SciPy's ratio for that signal; w2 does not reach the plant: 0.
    Another channel index, unit (Hz) or phase fails one of the two."""
    table = gain_against_frequency(scalar, "lqr", frequencies=[0.7, 3.0], amplitude=0.5)
    assert list(table.channel) == [1, 1, 2, 2]
    law = law_run(scalar, "lqr").solution
    for omega in (0.7, 3.0):
        gain = table[(table.channel == 1) & (table.omega == omega)].gain.item()
        exact = linear_ratio(law, lambda t: 0.5 * math.sin(omega * t), 10.0)
        # The measured gain's integrals: trapezoid on the output grid (dt 0.01), relative error
        # dt^2/12 |f''/f| <= dt^2/12 (2 omega)^2 < 4e-5 at omega = 3; the simulator's tolerances
        # (rtol 1e-8) are below that.
        assert gain == pytest.approx(exact, rel=1e-4)
    assert np.all(table[table.channel == 2].gain == 0.0)


@pytest.fixture(scope="module")
def ship_worst(ship):
    resolved = ship.resolved()
    out = {}
    for law_name in ("hinf", "lqr"):
        law = law_run(ship, law_name).solution
        out[law_name] = (law, worst_disturbance(law, resolved.Q, resolved.Qf, resolved.kappa, steps=1000))
    return out


def shipped_sinusoids() -> list[tuple[str, list]]:
    """The sinusoidal disturbances of the shipped scenarios (w1..w3; the ship's w4..w6 are noise
    channels), each as given and each channel alone."""
    found, seen = [], set()
    for path in sorted((ROOT / "scenarios").glob("*.toml")):
        channels = hc.load_scenario(str(path)).disturbance.channels()[:3]
        if not any(c.harmonics() for c in channels):
            continue
        key = tuple(c.describe() for c in channels)
        if key in seen:
            continue
        seen.add(key)
        found.append((path.stem, channels))
        for i, c in enumerate(channels):
            found.append((f"{path.stem} w{i + 1}", [c if j == i else hc.Signal(0.0) for j in range(3)]))
    return found


def l2_norm(signals: list, t0: float, tf: float) -> float:
    t = np.linspace(t0, tf, 40001)
    return math.sqrt(np.trapezoid(sum(np.asarray(s(t)) ** 2 for s in signals), t))


def scaled(signal: hc.Signal, factor: float) -> hc.Signal:
    return hc.Signal(factor * signal.offset(),
                     [hc.Harmonic(factor * h.amplitude, h.omega, h.phase, h.cosine) for h in signal.harmonics()])


@pytest.mark.parametrize("law_name", ["hinf", "lqr"])
def test_ship_worst_case_beats_every_shipped_sinusoid(ship, ship_worst, law_name):
    """On the paper's ship (Figure 1, 40 s): the worst case of each law attains its law_gain on
    the linearized loop, measures the same on the nonlinear loop when small, and measures more
    than any shipped sinusoid of the same L2 norm."""
    resolved = ship.resolved()
    law, worst = ship_worst[law_name]
    gain = hc.law_gain(law, resolved.Q, resolved.Qf, resolved.kappa).gamma_star
    assert worst.converged
    # Above law_gain only by the discretization: as in the scalar test, h^2/24 (2 rho)^2 on the
    # ratio, rho <= 2.3 the closed loop's largest eigenvalue modulus on the path: < h^2 (h = 0.04).
    h = (ship.tf - ship.t0) / 1000
    assert gain * 0.99 <= worst.ratio <= gain * (1.0 + 1e-7 + h * h)  # hinf 2.12877 / 2.12886
    scale = 0.01 / np.abs(worst.w).max()  # peak 0.01: the linear regime
    signals = worst.signals(scale)
    run = law_run(ship, law_name, signals)
    measured = measured_ratio(run.simulation, resolved.Q, resolved.Qf)
    # Nonlinear against linear: the remainder of the linearization grows with the error, about
    # 0.013 x the peak (1.2e-3 at peak 0.1, 1.3e-4 at 0.01, measured), plus the two grids'
    # trapezoid rules (h = 0.04, dt = 0.01; ~1e-5): 1e-3 leaves a margin of 7.
    assert measured == pytest.approx(worst.ratio, rel=1e-3)
    norm = l2_norm(signals[:3], ship.t0, ship.tf)
    sinusoids = shipped_sinusoids()
    assert len(sinusoids) >= 8
    for name, channels in sinusoids:
        factor = norm / l2_norm(channels, ship.t0, ship.tf)
        w = [scaled(c, factor) for c in channels] + [0.0, 0.0, 0.0]
        other = law_run(ship, law_name, w)
        ratio = measured_ratio(other.simulation, resolved.Q, resolved.Qf)
        assert ratio < measured, name  # the largest, 1.80 (lqr, w2 at 0.02 Hz), against 2.20


def test_ship_frequency_gains_stay_below_each_laws_bound(ship):
    table = gain_against_frequency(ship, channels=[1, 2, 3], frequencies=[0.01, 0.3, 3.0, 30.0])
    assert len(table) == 2 * 3 * 4 and set(table.status) == {"completed"}
    # In the linear regime (amplitude 0.01) no signal measures more than the law's gain; the
    # nonlinear remainder adds about 1.3e-4 (test above): 1e-3.
    assert np.all(table.gain <= table.bound * (1.0 + 1e-3))
    # The ship's loop rolls off: at 30 rad/s the gain is a small fraction of the bound.
    fast = table[table.omega == 30.0]
    assert np.all(fast.gain < 0.05 * fast.bound)
    assert set(table[table.law == "hinf"].gamma) == {5.0} and set(table[table.law == "lqr"].gamma) == {math.inf}


@pytest.mark.parametrize("call, match", [
    (lambda s: gain_against_frequency(s, "hinf", channels=7), "does not exist"),
    (lambda s: gain_against_frequency(s, "hinf", channels=4), "measurement-noise channel"),
    (lambda s: gain_against_frequency(s, "hinf", frequencies=[1.0, 0.0]), "frequencies must be"),
    (lambda s: gain_against_frequency(s, "hinf", amplitude=-1.0), "amplitude must be"),
    (lambda s: law_run(s, "mpc"), "unknown controller 'mpc'"),
])
def test_bad_input_is_a_value_error(ship, call, match):
    with pytest.raises(ValueError, match=match):
        call(ship)


@pytest.mark.parametrize("kwargs, match", [
    ({"steps": 1}, "steps must be"),
    ({"max_iterations": 0}, "max_iterations must be"),
    ({"tolerance": 0.0}, "tolerance must be"),
    ({"kappa": -1.0}, "kappa must be > 0"),
])
def test_worst_disturbance_bad_input(scalar, kwargs, match):
    law = law_run(scalar, "lqr").solution
    with pytest.raises(ValueError, match=match):
        worst_disturbance(law, np.eye(1), np.eye(1), **kwargs)
    with pytest.raises(ValueError, match="Q and Qf must be 1 x 1"):
        worst_disturbance(law, np.eye(2), np.eye(1))


def test_frequency_figure_draws_each_bound_in_its_laws_colour():
    import pandas as pd
    table = pd.DataFrame({"law": ["hinf", "hinf", "lqr", "lqr"], "channel": [2] * 4, "omega": [0.1, 1.0] * 2,
                          "gain": [1.5, 1.2, 1.6, 1.1], "bound": [2.1, 2.1, 2.2, 2.2],
                          "gamma": [5.0, 5.0, math.inf, math.inf]})
    ax = frequency_figure(table, 2).axes[0]
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert lines["hinf: law_gain 2.1"].get_color() == lines["hinf"].get_color() == "tab:blue"
    assert lines["lqr: law_gain 2.2"].get_color() == lines["lqr"].get_color() == "tab:orange"
    assert lines["hinf: law_gain 2.1"].get_linestyle() == "--"
    assert list(lines["hinf: law_gain 2.1"].get_ydata()) == [2.1, 2.1]
    assert "hinf: design gamma 5" in lines and not any("lqr: design gamma" in label for label in lines)
    with pytest.raises(ValueError, match="no rows for channel 1"):
        frequency_figure(table, 1)


def test_cli_writes_the_table_and_one_figure_per_channel(tmp_path, capsys):
    out = tmp_path / "gains"
    status = main(["gain-frequency", str(hc.scenario_path("paper_fig1")), "-o", str(out), "--laws", "lqr",
                   "--channels", "1,3", "--frequencies", "0.1:10:3"])
    assert status == 0
    with open(out / "gain_frequency.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [(r["channel"], float(r["omega"])) for r in rows] == [
        ("1", pytest.approx(0.1)), ("1", pytest.approx(1.0)), ("1", pytest.approx(10.0)),
        ("3", pytest.approx(0.1)), ("3", pytest.approx(1.0)), ("3", pytest.approx(10.0))]
    assert all(float(r["gain"]) <= float(r["bound"]) for r in rows)
    for channel in (1, 3):
        assert (out / f"gain_frequency_w{channel}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "wrote" in capsys.readouterr().out


@pytest.mark.parametrize("args, match", [
    (["--frequencies", "1:0.1:3"], "invalid frequencies '1:0.1:3'"),
    (["--frequencies", "a,b"], "not numbers"),
    (["--channels", "x"], "invalid channels 'x'"),
    (["--channels", "9"], "disturbance channel 9 does not exist"),
    (["--laws", "mpc"], "unknown controller 'mpc'"),
])
def test_cli_bad_input_is_one_line(tmp_path, capsys, args, match):
    try:
        status = main(["gain-frequency", str(hc.scenario_path("paper_fig1")), "-o", str(tmp_path / "x"), *args])
    except SystemExit as stop:  # argparse's own errors (an option's value)
        status = stop.code
    assert status == 2
    err = capsys.readouterr().err
    assert match in err and err.count("\n") == 1 and "Traceback" not in err


def test_cli_checks_its_output_folder_first(tmp_path, capsys):
    plain = tmp_path / "plain_file"
    plain.write_text("x")
    status = main(["gain-frequency", str(hc.scenario_path("paper_fig1")), "-o", str(plain / "gains")])
    assert status == 2
    err = capsys.readouterr().err
    assert "not a directory" in err and err.count("\n") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plain_file"]


def test_the_baselines_gain_against_frequency_stays_below_their_own_bound(ship):
    """The ship baselines, linearized along the path (hinf_cpp.controller_gain), have a bound
    too: the measured gains of small sinusoids stay below it (the same 1e-3 margin), and they
    have no design gamma."""
    table = gain_against_frequency(ship, "cascade,backstepping", channels=[2], frequencies=[0.05, 1.0])
    assert set(table.status) == {"completed"} and set(table.law) == {"cascade", "backstepping"}
    assert np.all(table.gain <= table.bound * (1.0 + 1e-3))
    assert np.all(np.isnan(table.gamma))
