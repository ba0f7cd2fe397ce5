"""The exported C99 controller (hinf_cpp.output.export_c, docs/export.md) against the C++ online
controller: the folder compiled alone with the strict flags, a Figure-2 measurement log and a
state-feedback log with limits, a delay and missing samples replayed to the same commands, the
statuses of a crafted log, a CMake build of the folder, and the options the export refuses."""

from __future__ import annotations

import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import hinf_cpp as hc
from hinf_cpp import cli
from hinf_cpp.output.export_c import export_controller, export_scenario

CC = shutil.which("cc")
pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler (cc)")

FLAGS = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2"]

# Replays a log through the exported controller: "R t q..." resets, "S t_now has t_meas v..."
# steps (has = 0: no measurement); one line out per line in.
DRIVER = r"""
#include <stdio.h>
#include "hinf_controller.h"

int main(void) {
  static hinf_controller_state controller;
  char kind;
  double u[HINF_M] = {0};
  int i;
  hinf_controller_init(&controller);
  while (scanf(" %c", &kind) == 1) {
    if (kind == 'R') {
      double t, q[HINF_N];
      if (scanf("%lf", &t) != 1) return 2;
      for (i = 0; i < HINF_N; ++i)
        if (scanf("%lf", &q[i]) != 1) return 2;
      printf("reset %d\n", hinf_controller_reset(&controller, t, q, NULL));
    } else {
      double t_now, t_meas, v[HINF_MEASUREMENT_SIZE];
      int has;
      hinf_status status;
      if (scanf("%lf %d %lf", &t_now, &has, &t_meas) != 3) return 2;
      for (i = 0; i < HINF_MEASUREMENT_SIZE; ++i)
        if (scanf("%lf", &v[i]) != 1) return 2;
      status = hinf_controller_step(&controller, t_now, has ? v : NULL, t_meas, u);
      printf("%d %d", (int)status, (int)controller.report.measurement);
      for (i = 0; i < HINF_M; ++i) printf(" %.17g", u[i]);
      printf(" %.17g\n", controller.report.rho_sigma_z);
    }
  }
  return 0;
}
"""

STATUS = {"ok": 0, "refused": 1, "past_horizon": 2, "not_reset": 3, "lost": 4}
USE = {"used": 0, "missing": 1, "stale": 2, "duplicate": 3, "future": 4, "not_finite": 5}


def compile_replay(folder: pathlib.Path) -> pathlib.Path:
    """The exported folder alone (only its own folder on the include path) and the driver."""
    (folder / "replay_driver.c").write_text(DRIVER)
    binary = folder / "replay"
    sources = [folder / "replay_driver.c", folder / "hinf_controller.c", folder / "hinf_controller_tables.c"]
    done = subprocess.run([CC, *FLAGS, f"-I{folder}", "-o", str(binary), *map(str, sources), "-lm"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return binary


def replay_c(binary: pathlib.Path, reset, steps, size: int):
    """(statuses, uses, u, rho) of the exported controller: reset = (t, q) or None; steps = rows
    (t_now, measurement or None, t_meas), measurement None for none; size = the numbers of one
    measurement."""
    lines = [] if reset is None else ["R " + " ".join(repr(float(x)) for x in [reset[0], *reset[1]])]
    for t_now, y, t_meas in steps:
        values = [0.0] * size if y is None else list(y)
        lines.append(f"S {float(t_now)!r} {int(y is not None)} {float(t_meas)!r} "
                     + " ".join(repr(float(v)) for v in values))
    done = subprocess.run([str(binary)], input="\n".join(lines) + "\n", capture_output=True, text=True, check=True)
    rows = [line.split() for line in done.stdout.splitlines() if not line.startswith("reset")]
    numbers = np.array([[float(x) for x in row] for row in rows])
    return numbers[:, 0].astype(int), numbers[:, 1].astype(int), numbers[:, 2:-1], numbers[:, -1]


def replay_cpp(controller, steps):
    statuses, uses, commands, rhos = [], [], [], []
    for t_now, y, t_meas in steps:
        u, report = controller.step(t_now, y, t_meas)
        statuses.append(STATUS[report.status.name])
        uses.append(USE[report.measurement.name])
        commands.append(u)
        rhos.append(report.rho_sigma_z)
    return np.array(statuses), np.array(uses), np.array(commands), np.array(rhos)


@pytest.fixture(scope="module")
def fig2(tmp_path_factory):
    """Figure 2 on the 20 Hz computer (scenarios/paper_fig2_sampled.toml) exported, its C++
    controller, and a measurement log: x, y, psi of the closed loop at the samples plus noise
    of sigma = 0.5 (seeded), each answered 20 ms later."""
    folder = tmp_path_factory.mktemp("fig2")
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2_sampled"))
    exported = export_scenario(scenario, folder)
    result = hc.run_scenario(scenario)
    law = hc.SampledLaw.emulated(result.solution, 0.05)
    f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6), hold=0.05)
    options = hc.OnlineOptions(filter=f, limits=scenario.sampling.limits)
    C = np.asarray(result.trajectory.model().C(0.0))
    t_meas = 0.05 * np.arange(800)
    q = result.simulation.q[::5][:800]  # the output grid is 0.01 s
    y = q @ C.T + 0.5 * np.random.default_rng(20000601).standard_normal((800, 3))
    return exported, compile_replay(folder), law, options, result.trajectory.q_d0(), t_meas, y


def test_figure2_log_replays_to_the_cpp_commands(fig2):
    exported, binary, law, options, q_hat0, t_meas, y = fig2
    assert (exported.kind, exported.p, exported.steps, exported.t_end) == ("emulated", 3, 800, 40.0)
    controller = hc.OnlineController(law, options)
    controller.reset(0.0, q_hat0)
    t_now = t_meas + 0.02
    u_cpp, reports = controller.replay(t_now, y, t_meas)
    statuses, uses, u_c, rho_c = replay_c(binary, (0.0, q_hat0), list(zip(t_now, y, t_meas)), 3)
    assert all(r.measurement == hc.MeasurementUse.used for r in reports) and np.all(uses == 0)
    assert np.all(statuses == 0)
    # The two compute the same arithmetic in a different order (Eigen's products and Cholesky
    # solves against plain loops): a few ulp per operation, about 1e-15 of the command per step;
    # the estimator's error dynamics are stable, so round-off does not build up over the 800
    # samples (measured: 6e-16). 1e-12 is the bound, a thousand times that; Runge-Kutta
    # steps of 10 ms instead of 5 ms already move the commands by 3e-10 of their size.
    scale = np.max(np.abs(u_cpp))
    assert np.max(np.abs(u_c - u_cpp)) <= 1e-12 * scale
    rho_cpp = np.array([r.rho_sigma_z for r in reports])
    # rho(Sigma Z): Jacobi rotations against Eigen's symmetric QR, both backward stable (1e-15 of
    # the largest eigenvalue), on the same Sigma.
    assert np.max(np.abs(rho_c - rho_cpp)) <= 1e-12 * np.max(rho_cpp)


def test_figure2_folder_is_self_contained_and_states_its_horizon(fig2):
    exported = fig2[0]
    folder = exported.folder
    text = "".join(p.read_text() for p in folder.glob("hinf_controller*.[ch]"))
    assert "malloc" not in text and "#include <stdlib.h>" not in text
    includes = {line.split()[1] for line in text.splitlines() if line.startswith("#include")}
    assert includes <= {'"hinf_controller.h"', '"hinf_controller_tables.h"', "<math.h>", "<string.h>"}
    readme = (folder / "README.md").read_text()
    assert f"{exported.table_bytes} bytes" in readme and "[0, 40) s" in readme and "past_horizon" in readme.lower()
    # The size stated is what the compiler lays out for the design's arrays.
    nm = shutil.which("nm")
    if nm is not None:
        obj = folder / "tables.o"
        subprocess.run([CC, *FLAGS, "-c", "-o", str(obj), str(folder / "hinf_controller_tables.c")], check=True)
        symbols = subprocess.run([nm, "-S", str(obj)], capture_output=True, text=True, check=True).stdout
        arrays = ("hinf_table_", "hinf_C", "hinf_S_predict", "hinf_Sigma0")
        laid_out = sum(int(fields[1], 16) for fields in (line.split() for line in symbols.splitlines())
                       if len(fields) == 4 and fields[3].startswith(arrays))
        assert laid_out == exported.table_bytes


@pytest.fixture(scope="module")
def state_feedback(tmp_path_factory):
    """Figure 1's design at T = 0.05 s with tight limits, max_age, and a log whose measurements
    arrive 20 ms late, every fifth missing."""
    folder = tmp_path_factory.mktemp("sf")
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    result = hc.run_scenario(scenario)
    limits = hc.ActuatorLimits(u_min=[-1.2, -0.8], u_max=[1.2, 0.8], rate_max=[3.0, np.inf])
    options = hc.OnlineOptions(limits=limits, max_age=0.2, history=8)
    exported = export_controller(result.solution, folder, period=0.05, options=options)
    law = hc.SampledLaw.emulated(result.solution, 0.05)
    t_meas = 0.05 * np.arange(800)
    q = result.simulation.q[::5][:800] + 0.01 * np.random.default_rng(3).standard_normal((800, 6))
    steps = [(t + 0.02, None if k % 5 == 4 else q[k], t) for k, t in enumerate(t_meas)]
    return exported, compile_replay(folder), law, options, scenario.initial_q0, steps


def test_state_feedback_with_limits_and_delay_replays_to_the_cpp_commands(state_feedback):
    exported, binary, law, options, q0, steps = state_feedback
    controller = hc.OnlineController(law, options)
    controller.reset(0.0, q0)
    statuses, uses, u_cpp, _ = replay_cpp(controller, steps)
    c_statuses, c_uses, u_c, rho_c = replay_c(binary, (0.0, q0), steps, 6)
    assert np.array_equal(c_statuses, statuses) and np.array_equal(c_uses, uses)
    assert np.count_nonzero(uses == USE["missing"]) == 160
    counts = controller.counts()
    assert counts.saturated > 10 and counts.rate_limited > 10  # the limits are exercised
    assert np.all(np.isnan(rho_c))
    # As above: round-off of the prediction's products, without a filter; measured 6e-15.
    assert np.max(np.abs(u_c - u_cpp)) <= 1e-12 * np.max(np.abs(u_cpp))


def test_statuses_of_a_crafted_log_match(state_feedback):
    exported, binary, law, options, q0, _ = state_feedback
    q = np.asarray(q0, dtype=float)
    bad = q.copy()
    bad[2] = np.nan
    steps = [
        (0.05, q, 0.05),            # used
        (0.10, q, 0.05),            # duplicate
        (0.15, q, 0.20),            # future
        (0.20, bad, 0.20),          # not_finite
        (0.25, None, 0.25),         # missing
        (0.60, q, 0.30),            # stale: older than max_age = 0.2 s
        (0.55, q, 0.55),            # refused: earlier than the last call
        (0.65, q, 0.65),            # used
        (1.20, q, 0.70),            # stale: older than the 8 commands remembered... and max_age
        (exported.t_end, q, exported.t_end),  # past_horizon
        (exported.t_end - 0.01, q, exported.t_end - 0.02),  # ok: past_horizon changed nothing
    ]
    controller = hc.OnlineController(law, options)
    controller.reset(0.0, q0)
    statuses, uses, u_cpp, _ = replay_cpp(controller, steps)
    c_statuses, c_uses, u_c, _ = replay_c(binary, (0.0, q0), steps, 6)
    names = {v: k for k, v in STATUS.items()}
    assert [names[s] for s in c_statuses] == ["ok"] * 6 + ["refused", "ok", "ok", "past_horizon", "ok"]
    assert np.array_equal(c_statuses, statuses) and np.array_equal(c_uses, uses)
    assert set(uses) == set(USE.values())
    # The last measurement is taken between samples, where the export's q_d is cubic Hermite and
    # the C++ controller's the trajectory's dense output: they differ by at most
    # T^4/384 max|d^4 q_d/dt^4| (about 1e-11 here: the ship turns at 0.2 rad/s), times the gain
    # |K| ~ 5; measured 5e-12.
    assert np.max(np.abs(u_c[:-1] - u_cpp[:-1])) <= 1e-12 * np.max(np.abs(u_cpp))
    assert np.max(np.abs(u_c[-1] - u_cpp[-1])) <= 1e-9 * np.max(np.abs(u_cpp))
    # Before a reset: not_reset, u untouched (the C++ controller raises in Python).
    c_statuses, _, u_c, _ = replay_c(binary, None, [(0.05, q, 0.05)], 6)
    assert c_statuses[0] == STATUS["not_reset"] and np.all(u_c == 0.0)


def test_output_feedback_without_measurements_is_lost_at_the_same_step(fig2):
    """The H-infinity filter escapes in about 3 s without measurements: both controllers flag the
    coupling condition and then answer lost at the same step, holding the command."""
    _, binary, law, options, q_hat0, _, _ = fig2
    steps = [(0.05 * k, None, 0.05 * k) for k in range(1, 200)]
    controller = hc.OnlineController(law, options)
    controller.reset(0.0, q_hat0)
    statuses, uses, u_cpp, rho_cpp = replay_cpp(controller, steps)
    c_statuses, c_uses, u_c, rho_c = replay_c(binary, (0.0, q_hat0), steps, 3)
    assert STATUS["lost"] in statuses
    assert np.array_equal(c_statuses, statuses) and np.array_equal(c_uses, uses)
    ok = statuses == STATUS["ok"]
    # Sigma grows toward its escape: the relative round-off grows with it; the commands while
    # the estimate is finite and the command held afterwards.
    assert np.max(np.abs(u_c[ok] - u_cpp[ok])) <= 1e-9 * np.max(np.abs(u_cpp[ok]))
    assert np.array_equal(u_c[~ok], u_cpp[~ok]) or np.max(np.abs(u_c[~ok] - u_cpp[~ok])) <= 1e-9


def test_cmake_builds_the_folder_alone(fig2, tmp_path):
    cmake = shutil.which("cmake")
    if cmake is None:
        pytest.skip("no cmake")
    source = tmp_path / "src"
    shutil.copytree(fig2[0].folder, source, ignore=shutil.ignore_patterns("replay*"))
    build = tmp_path / "build"
    for command in ([cmake, "-S", str(source), "-B", str(build), "-DCMAKE_C_FLAGS=-Werror"],
                    [cmake, "--build", str(build)]):
        done = subprocess.run(command, capture_output=True, text=True)
        assert done.returncode == 0, done.stdout + done.stderr
    assert (build / "libhinf_controller.a").exists()


@pytest.fixture(scope="module")
def short_design():
    u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 4.0)
    return hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)


@pytest.mark.parametrize("update", ["held", "discrete"])
def test_unsupported_measurement_updates_are_refused(short_design, tmp_path, update):
    f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6), update=getattr(hc.MeasurementUpdate, update))
    with pytest.raises(ValueError, match=rf"the {update} measurement update is not exported yet.*update=\"sampled\""):
        export_controller(short_design, tmp_path / "out", period=0.1, options=hc.OnlineOptions(filter=f))
    assert not (tmp_path / "out").exists()


def test_bad_arguments_are_refused(short_design, tmp_path):
    with pytest.raises(ValueError, match="period is missing"):
        export_controller(short_design, tmp_path / "a")
    discrete = hc.solve_discrete_game(short_design.trajectory(), 0.1, np.eye(6), np.eye(6), 5.0)
    with pytest.raises(ValueError, match="its own period"):
        export_controller(discrete, tmp_path / "a", period=0.1)
    with pytest.raises(ValueError, match="RiccatiSolution"):
        export_controller("design", tmp_path / "a", period=0.1)
    with pytest.raises(ValueError, match="rate_max"):
        export_controller(short_design, tmp_path / "a", period=0.1,
                          options=hc.OnlineOptions(limits=hc.ActuatorLimits(rate_max=[1.0])))
    trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], lambda t: np.array([1.0, 0.0]), 0.0, 2.0)
    with pytest.raises(ValueError, match="u_d"):
        export_controller(hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0), tmp_path / "a", period=0.1)
    assert not (tmp_path / "a").exists()


def test_tabulated_u_d_is_written_as_the_signal_evaluates_it(tmp_path):
    """A pchip table of u_d (as the planner writes linear ones): the C function's value at any t
    is the signal's (the exporter checks its pieces against the Signal and raises otherwise)."""
    t = [0.0, 0.7, 1.5, 2.0, 3.1, 4.0]
    u2 = hc.Signal.table(t, [0.0, 0.2, 0.1, -0.3, 0.0, 0.25], hc.Interpolation.pchip)
    trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], [1.0, u2], 0.0, 4.0)
    design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    exported = export_controller(design, tmp_path / "table", period=0.1)
    binary = compile_replay(exported.folder)
    controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
    q0 = np.array([1.0, 0.0, 0.0, -0.5, 0.3, 0.2])
    controller.reset(0.0, q0)
    steps = [(0.1 * k + 0.03, None if k % 3 else q0 + 0.01 * k, 0.1 * k) for k in range(1, 39)]
    _, _, u_cpp, _ = replay_cpp(controller, steps)
    _, _, u_c, _ = replay_c(binary, (0.0, q0), steps, 6)
    assert np.max(np.abs(u_c - u_cpp)) <= 1e-12 * np.max(np.abs(u_cpp))


def test_cli_export_controller(tmp_path, capsys):
    out = tmp_path / "controller"
    assert cli.main(["export-controller", str(hc.scenario_path("paper_fig1")), "--out", str(out),
                     "--sample-period", "0.1"]) == 0
    printed = capsys.readouterr().out
    assert "state feedback, every 0.1 s on [0, 40) s (400 samples)" in printed
    assert sorted(p.name for p in out.iterdir()) == sorted(
        ["CMakeLists.txt", "README.md", "hinf_controller.c", "hinf_controller.h", "hinf_controller_tables.c",
         "hinf_controller_tables.h"])
    # Bad input: one line on stderr, exit status 2, nothing written.
    assert cli.main(["export-controller", str(hc.scenario_path("paper_fig1")), "--out", str(tmp_path / "x")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no [sampling] period: give the controller's period (--sample-period T)" in err
    assert cli.main(["export-controller", str(hc.scenario_path("paper_fig2_sampled")), "--out", str(tmp_path / "x"),
                     "--sample-period", "0"]) == 2
    assert "period must be > 0 s" in capsys.readouterr().err
    assert not (tmp_path / "x").exists()
    plain = tmp_path / "plain_file"
    plain.write_text("x")
    assert cli.main(["export-controller", str(hc.scenario_path("paper_fig1")), "--out", str(plain),
                     "--sample-period", "0.1"]) == 2
    assert "not a directory" in capsys.readouterr().err
