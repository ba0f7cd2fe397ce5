"""Ctrl-C: a long C++ call stops at its next step (core/interrupt.hpp), Python raises
KeyboardInterrupt, and every command ends with one line, "interrupted", and exit status 130.

Before: a computation running without the GIL ignored Ctrl-C until it returned (unbounded), then
the command died of SIGINT with a traceback; planning reported it as an IPOPT failure.
The commands are measured in the child's CPU time (from SIGINT to its end), not in wall time."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
import pathlib

import numpy as np
import pytest

import hinf_cpp as hc
from hinf_cpp import _core

BIN = pathlib.Path(sys.executable).parent


class InterruptingShip(hc.Model):
    """The paper's ship, whose drift asks for an interrupt at its `after`-th evaluation, as a
    Ctrl-C during the run would."""

    def __init__(self, after: int):
        super().__init__()
        self.ship, self.calls, self.after = hc.ShipModel(), 0, after

    def name(self): return "interrupting-ship"
    def n(self): return 6
    def m(self): return 2
    def nw(self): return 6
    def position_indices(self): return [3, 4]
    def heading_index(self): return 5

    def f(self, t, q):
        self.calls += 1
        if self.calls == self.after:
            _core.request_interrupt()
        return np.asarray(self.ship.f(t, q))

    def dfdq(self, t, q): return np.asarray(self.ship.dfdq(t, q))
    def G(self, t, q): return np.asarray(self.ship.G(t, q))
    def D(self, t, q): return np.asarray(self.ship.D(t, q))


def test_a_requested_interrupt_stops_a_run_at_its_next_step():
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.model = InterruptingShip(after=2000)
    with pytest.raises(KeyboardInterrupt):
        hc.run_scenario(scenario)
    # Stopped within a step: a step of the closed loop takes at most a few tens of evaluations
    # (7 for a Dormand-Prince step; BDF's Newton iterations and Jacobians more), far from the
    # whole run's tens of thousands.
    assert scenario.model.calls < 2000 + 100
    assert not _core.interrupt_requested()  # answered by the KeyboardInterrupt


def test_a_request_answered_before_a_call_does_not_stop_it():
    """A Ctrl-C that Python code has handled (a notebook cell stopped) leaves the request set;
    the next computation clears it when it starts instead of stopping at once."""
    _core.request_interrupt()
    result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    assert result.simulation.status == hc.RunStatus.completed


def test_a_study_stops_and_records_no_interrupted_run():
    scenarios = [hc.load_scenario(hc.scenario_path("paper_fig1")) for _ in range(3)]
    scenarios[1].model = InterruptingShip(after=500)
    with pytest.raises(KeyboardInterrupt):
        hc.run_scenarios(scenarios, hc.StudyOptions(threads=1))
    assert not _core.interrupt_requested()


def cpu_seconds(pid: int) -> tuple[float, str]:
    """The process's CPU time (user + system) and its state letter, from /proc."""
    fields = pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK"), fields[0]


def interrupt_when_busy(args: list, busy_cpu: float) -> tuple[int, float, str]:
    """Starts the command, sends SIGINT once it has used `busy_cpu` seconds of CPU (it is then in
    its computation), and returns its exit status, the CPU seconds it used after the signal and
    its stderr."""
    process = subprocess.Popen([str(a) for a in args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    for _ in range(100_000):  # polls 10 ms apart: a bound, not a timing
        used, state = cpu_seconds(process.pid)
        if used >= busy_cpu or state == "Z":
            break
        time.sleep(0.01)
    assert state != "Z", f"{args} ended before it was interrupted: make its computation longer"
    process.send_signal(signal.SIGINT)
    _, status, usage = os.wait4(process.pid, 0)  # reaped here, for its resource usage
    process.returncode = os.waitstatus_to_exitcode(status)
    with process.stderr:
        stderr = process.stderr.read()
    return process.returncode, usage.ru_utime + usage.ru_stime - used, stderr


@pytest.fixture(scope="module")
def long_run(tmp_path_factory):
    """Figure 1 over 40 000 s (output every 0.1 s, enough steps allowed): a run and a gamma* of
    several seconds (5 s of CPU for hinf-cpp run on a 2026 desktop core)."""
    path = tmp_path_factory.mktemp("long") / "long.toml"
    text = hc.scenario_path("paper_fig1").read_text()
    for old, new in [("tf = 40.0", "tf = 40000.0"), ("\ndt = 0.01\n", "\ndt = 0.1\n"),
                     ("[solver]\n", "[solver]\nmax_steps = 5000000\n")]:
        assert old in text, old
        text = text.replace(old, new)
    path.write_text(text)
    return path


# The CPU the command uses before its computation starts (Python and the package imported, the
# file read: under a second) stays below these; then the computation runs for seconds more.
@pytest.mark.parametrize("program, busy", [
    (["hinf-sim"], 0.5),
    (["hinf-cpp", "run"], 2.0),
    (["hinf-cpp", "gamma-star"], 4.0),
])
def test_ctrl_c_ends_a_long_command_with_one_line_and_status_130(long_run, program, busy):
    if not (BIN / program[0]).exists():
        pytest.skip(f"{program[0]} is not installed next to this Python")
    status, after, stderr = interrupt_when_busy([BIN / program[0], *program[1:], long_run], busy)
    assert status == 130, stderr
    assert stderr.splitlines() == [f"{program[0]}: {'error: ' if program[0] == 'hinf-cpp' else ''}interrupted"]
    assert after < 2.0, after  # CPU seconds from SIGINT to the end


def test_ctrl_c_while_the_package_is_imported_is_interrupted_too(monkeypatch, capsys):
    """The entry point (hinf_cpp_command) imports the command line itself, so that a Ctrl-C in
    the second or two of imports is the same one line and status 130 (it was a traceback)."""
    import types

    import hinf_cpp_command

    class InterruptedImport(types.ModuleType):
        def __getattr__(self, name):
            raise KeyboardInterrupt

    monkeypatch.setitem(sys.modules, "hinf_cpp.cli", InterruptedImport("hinf_cpp.cli"))
    assert hinf_cpp_command.main() == 130
    assert capsys.readouterr().err == "hinf-cpp: error: interrupted\n"


@pytest.mark.ipopt
def test_ctrl_c_while_planning_is_interrupted_not_an_optimizer_failure(tmp_path):
    """IPOPT took the KeyboardInterrupt as its own failure ("NonIpopt_Exception_Thrown", exit 3)."""
    if not (BIN / "hinf-cpp").exists():
        pytest.skip("hinf-cpp is not installed next to this Python")
    pytest.importorskip("casadi")
    text = hc.scenario_path("planned/ship_lane_change").read_text()
    path = tmp_path / "fine.toml"
    path.write_text(text.replace("[desired.plan]\n", "[desired.plan]\ninterval = 0.02\n", 1))  # ~9 s of IPOPT
    status, after, stderr = interrupt_when_busy([BIN / "hinf-cpp", "plan", path, "-o", tmp_path / "out.toml",
                                                 "--no-cache"], 5.0)
    assert status == 130, stderr
    # CasADi's own warning about the KeyboardInterrupt is held back: one line.
    assert stderr.splitlines() == ["hinf-cpp: error: interrupted"], stderr
    assert after < 2.0, after
