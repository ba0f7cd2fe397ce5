"""The Python/C++ boundary: what Python hands over is checked before C++ reads it.

Every binding that takes an array, a matrix, a signal or a user callable gets at least one bad
call here, asserting a ValueError (the C++ InputError) whose message names the argument, what
was expected and what was found. Calls that used to read past an array or corrupt the heap run
in a fresh interpreter (run_isolated), so that a regression fails its test instead of killing
the test run.
"""

from __future__ import annotations

import numpy as np
import pytest

import hinf_cpp as hc
from test_gamma_star import run_isolated

NAN = float("nan")
SHIP_Q_D0 = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]


@pytest.fixture(scope="module")
def ship_design():
    """A short ship trajectory and its GRDE solution (t in [0, 2])."""
    tr = hc.Trajectory(hc.ShipModel(), SHIP_Q_D0, [1.0, 0.0], 0.0, 2.0)
    return tr, hc.solve_grde(tr, np.eye(6), np.eye(6), 5.0)


@pytest.fixture(scope="module")
def lti_design():
    """A 2-state linear model with a measurement, its trajectory and GRDE solution on [0, 1]."""
    model = hc.LinearModel(-np.eye(2), np.array([[0.0], [1.0]]), np.eye(2), np.array([[1.0, 0.0]]))
    tr = hc.Trajectory(model, [1.0, 0.0], [0.0], 0.0, 1.0)
    return tr, hc.solve_grde(tr, np.eye(2), np.eye(2), 5.0)


# ---- models implemented in Python ----

class TwoStates(hc.Model):
    """dq/dt = -q + [0, 1]' u + [0, 1]' w, implemented in Python; subclasses break one thing."""

    def __init__(self):
        hc.Model.__init__(self)

    def n(self):
        return 2

    def m(self):
        return 1

    def nw(self):
        return 1

    def f(self, t, q):
        return -np.asarray(q)

    def dfdq(self, t, q):
        return -np.eye(2)

    def G(self, t, q):
        return np.array([[0.0], [1.0]])

    def D(self, t, q):
        return np.array([[0.0], [1.0]])


def returning(method, value):
    """A TwoStates whose `method`(...) returns `value`. (A subclass, not an instance attribute:
    pybind11 remembers per class which methods Python does not override.)"""
    return type(f"Bad_{method}", (TwoStates,), {method: lambda self, *args: value})()


@pytest.mark.parametrize("method, value, message", [
    ("n", 0, r"number of states n\(\) must be in \[1, 10000\], got 0"),
    ("n", "two", r"the Python model's n\(\) must return an int, got str 'two'"),
    ("m", None, r"the Python model's m\(\) must return an int, got None"),
    ("nw", -1, r"number of disturbance channels nw\(\) must be in \[0, 10000\], got -1"),
    ("state_names", ["a"], r"state_names\(\) has 1 names, expected one per state \(n = 2\)"),
    ("position_indices", [0, 0], r"position_indices\(\) = \[0, 0\] holds 0 twice"),
    ("position_indices", "01", r"position_indices\(\) must return a list of int, got str '01'"),
    ("heading_index", 2, r"heading_index\(\) must be -1 \(no heading\) or a state index \(0 to 1\), got 2"),
    ("noise_channels", [1], r"noise_channels\(\) = \[1\] holds 1, which is not a disturbance channel \(0 to 0\)"),
    ("name", 3, r"the Python model's name\(\) must return a str, got int 3"),
])
def test_python_model_structure_is_validated(method, value, message):
    with pytest.raises(ValueError, match=message):
        hc.Trajectory(returning(method, value), [1.0, 0.0], [0.0], 0.0, 1.0)


class Counting(TwoStates):
    """Counts the calls of its structural methods."""

    def __init__(self):
        TwoStates.__init__(self)
        self.calls = 0

    def n(self):
        self.calls += 1
        return 2

    def position_indices(self):
        self.calls += 1
        return [0, 1]


def test_python_model_structure_is_read_once():
    model = Counting()
    tr = hc.Trajectory(model, [1.0, 0.0], [0.0], 0.0, 1.0)
    sol = hc.solve_grde(tr, np.eye(2), np.eye(2), 5.0)
    run = hc.simulate_state_feedback(tr, hc.HinfStateFeedback(sol), None, [1.5, 0.0],
                                     hc.SimulationOptions(output_dt=0.1))
    hc.compute_metrics(model, run, np.eye(2))
    assert model.calls == 2  # n() and position_indices(), once each


SHRINKING_MODEL = """
    import numpy as np
    import hinf_cpp as hc

    class Shrinking(hc.Model):
        '''Its state size is len(self.a), which the test changes after building a trajectory:
        n(), f, dfdq, B and D all follow the current size.'''

        def __init__(self):
            hc.Model.__init__(self)
            self.a = -np.ones(3)

        def n(self):
            return len(self.a)

        def m(self):
            return 1

        def nw(self):
            return 1

        def f(self, t, q):
            return self.a * np.asarray(q)[: len(self.a)]

        def dfdq(self, t, q):
            return np.diag(self.a)

        def G(self, t, q):
            return np.ones((len(self.a), 1))

        def D(self, t, q):
            return np.ones((len(self.a), 1))

    def outcome(call):
        try:
            call()
            return {"error": None}
        except Exception as e:
            return {"error": type(e).__name__, "message": str(e)}
"""


def test_python_model_whose_n_changes_raises_instead_of_corrupting_the_heap():
    """Used to abort with free(): invalid next size: the GRDE took the new n() = 2 while the
    trajectory's dense output wrote its 3 states."""
    result = run_isolated(SHRINKING_MODEL, """
        model = Shrinking()
        tr = hc.Trajectory(model, [1.0, 0.5, -0.5], [0.0], 0.0, 1.0)
        sol = hc.solve_grde(tr, np.eye(3), np.eye(3), 5.0)
        model.a = -np.ones(2)
        grde = outcome(lambda: hc.solve_grde(tr, np.eye(2), np.eye(2), 5.0).Z(0.5))
        simulate = outcome(lambda: hc.simulate_state_feedback(tr, hc.HinfStateFeedback(sol), None,
                                                              [1.0, 0.5, -0.5], hc.SimulationOptions(output_dt=0.1)))
        print(json.dumps({"grde": grde, "simulate": simulate}))
    """)
    assert result["grde"]["error"] == "ValueError", result
    assert "Incompatible dimensions of Q: expected (3, 3) but found (2, 2)" in result["grde"]["message"]
    assert result["simulate"]["error"] == "ValueError", result
    assert "the Python model's G(t, q) returned an array of shape (2, 1) at t = 0, expected (3, 1)" \
        in result["simulate"]["message"]


def test_python_model_with_position_indices_out_of_range_raises():
    """compute_metrics used to index the run with them (different garbage on every run)."""
    result = run_isolated("""
        import numpy as np
        import hinf_cpp as hc

        class OutOfRange(hc.Model):
            def __init__(self):
                hc.Model.__init__(self)
            def n(self): return 2
            def m(self): return 1
            def nw(self): return 1
            def f(self, t, q): return -np.asarray(q)
            def dfdq(self, t, q): return -np.eye(2)
            def G(self, t, q): return np.array([[0.0], [1.0]])
            def D(self, t, q): return np.array([[0.0], [1.0]])
            def position_indices(self): return [50, -7]

        good = hc.LinearModel(-np.eye(2), np.array([[0.0], [1.0]]), np.array([[0.0], [1.0]]))
        tr = hc.Trajectory(good, [1.0, 0.0], [0.0], 0.0, 1.0)
        sol = hc.solve_grde(tr, np.eye(2), np.eye(2), 5.0)
        run = hc.simulate_state_feedback(tr, hc.HinfStateFeedback(sol), None, [1.5, 0.0],
                                         hc.SimulationOptions(output_dt=0.1))
        out = {}
        for name, call in [("metrics", lambda: hc.compute_metrics(OutOfRange(), run, np.eye(2))),
                           ("trajectory", lambda: hc.Trajectory(OutOfRange(), [1.0, 0.0], [0.0], 0.0, 1.0))]:
            try:
                out[name] = repr(call())
            except ValueError as e:
                out[name] = "ValueError: " + str(e)
        print(json.dumps(out))
    """)
    for name in ("metrics", "trajectory"):
        assert result[name].startswith("ValueError: "), result
        assert "position_indices() = [50, -7] holds 50, which is not a state index (0 to 1)" in result[name]


@pytest.mark.parametrize("method, value, message", [
    ("G", np.ones((2, 2)), r"G\(t, q\) returned an array of shape \(2, 2\) at t = 0, expected \(2, 1\)"),
    ("D", np.array([[0.0], [NAN]]), r"D\(t, q\) at t = 0 has a non-finite entry nan at \(1, 0\)"),
    ("f", None, r"f\(t, q\) must return an array of 2 numbers, got None at t = 0"),
    ("f", [1.0, "x"], r"f\(t, q\) must return an array of 2 numbers, got list \[1.0, 'x'\]"),
    ("dfdq", np.eye(3), r"dfdq\(t, q\) returned an array of shape \(3, 3\) at t = [0-9.]+, expected \(2, 2\)"),
])
def test_python_model_results_are_checked(method, value, message):
    model = returning(method, value)
    with pytest.raises(ValueError, match=message):
        tr = hc.Trajectory(model, [1.0, 0.0], [0.0], 0.0, 1.0)
        hc.solve_grde(tr, np.eye(2), np.eye(2), 5.0)


@pytest.mark.parametrize("value, message", [
    (np.eye(2), r"error_split\(t, q_d, u_d, q_e\) must return a pair \(A, alpha\) of shapes \(2, 2\) and \(2,\)"),
    ((np.eye(2), np.zeros(3)), r"error_split\(t, q_d, u_d, q_e\)\[1\] \(alpha\) returned an array of length 3 at t = 0, "
                               r"expected 2 numbers"),
    ((None, np.zeros(2)), r"error_split\(t, q_d, u_d, q_e\)\[0\] \(A\) must return an array of shape \(2, 2\), got None"),
])
def test_python_model_error_split_is_checked(value, message):
    model = returning("error_split", value)
    with pytest.raises(ValueError, match=message):
        # Through C++ (the Python method itself returns anything).
        hc.Model.error_split(model, 0.0, [0.0, 0.0], [0.0], [0.1, 0.0])


def test_python_model_measurement_matrix_is_checked():
    model = returning("C", np.ones((1, 3)))
    tr = hc.Trajectory(model, [1.0, 0.0], [0.0], 0.0, 1.0)
    with pytest.raises(ValueError, match=r"C\(t\) must return an array of shape \(p, 2\), p >= 1, got numpy"):
        hc.solve_filter_riccati(tr, np.eye(1), np.eye(2), 5.0, np.eye(2))


def test_exception_inside_a_python_model_reaches_the_caller():
    class Raising(TwoStates):
        def G(self, t, q):
            raise KeyError("no B here")

    with pytest.raises(KeyError, match="no B here"):
        hc.Trajectory(Raising(), [1.0, 0.0], [0.0], 0.0, 1.0)


# ---- built-in models ----

def test_model_functions_check_their_arguments():
    ship = hc.ShipModel()
    with pytest.raises(ValueError, match="Incompatible length of q: expected 6 but found 2"):
        ship.f(0.0, [1.0, 2.0])
    with pytest.raises(ValueError, match="Incompatible length of q: expected 6 but found 7"):
        ship.dfdq(0.0, np.zeros(7))
    with pytest.raises(ValueError, match="Incompatible length of q_e: expected 6 but found 1"):
        ship.error_split(0.0, np.zeros(6), np.zeros(2), [0.0])
    with pytest.raises(ValueError, match="q has a non-finite entry nan"):
        ship.f(0.0, [NAN, 0, 0, 0, 0, 0])
    with pytest.raises(ValueError, match="Incompatible dimensions of C: expected 2 columns but found 3"):
        hc.LinearModel(-np.eye(2), np.ones((2, 1)), np.eye(2), np.ones((1, 3)))


# ---- signals ----

def test_signal_arguments():
    with pytest.raises(ValueError, match="as many values as times: 2 times, 3 values"):
        hc.Signal.table([0.0, 1.0], [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="table value must be finite, got nan"):
        hc.Signal.table([0.0, 1.0], [1.0, NAN])
    with pytest.raises(ValueError, match="signal constant must be finite"):
        hc.Signal(NAN)
    with pytest.raises(ValueError, match="times must be finite numbers, got nan at index 1"):
        hc.Signal(1.0)(np.array([0.0, NAN]))
    with pytest.raises(ValueError, match="times must be a number or a 1-D array"):
        hc.Signal(1.0)(np.zeros((2, 2)))


def test_vector_signal_arguments():
    with pytest.raises(ValueError, match=r"channels\[1\] must be a Signal or a finite number, got str 'x'"):
        hc.VectorSignal([1.0, "x"])
    with pytest.raises(ValueError, match=r"channels\[0\] must be a Signal or a finite number, got float nan"):
        hc.VectorSignal([NAN])
    with pytest.raises(ValueError, match=r"dimension of a vector signal must be in \[0, 10000\], got -1"):
        hc.VectorSignal.zeros(-1)
    with pytest.raises(ValueError, match=r"dimension of a vector signal must be in \[0, 10000\], got 1000000000"):
        hc.VectorSignal.zeros(10**9)
    with pytest.raises(ValueError, match=r"function\(t\) must return an array of 2 numbers, got None at t = 0.5"):
        hc.VectorSignal(2, lambda t: None)(0.5)
    with pytest.raises(ValueError, match=r"function\(t\) returned an array of length 1 at t = 0, expected 2 numbers"):
        hc.VectorSignal(2, lambda t: [1.0])(0.0)
    with pytest.raises(ValueError, match=r"function\(t\) returned a non-finite value at t = 0: list \[1.0, nan\]"):
        hc.VectorSignal(2, lambda t: [1.0, NAN])(0.0)
    with pytest.raises(ZeroDivisionError):
        hc.VectorSignal(1, lambda t: [1.0 / 0.0])(0.0)


# ---- trajectories and u_d ----

@pytest.mark.parametrize("u_d, message", [
    (lambda t: None, r"u_d\(t\) must return an array of 2 numbers, got None at t = 0"),
    (lambda t: 1.0, r"u_d\(t\) must return an array of 2 numbers, got float 1.0 at t = 0"),
    (lambda t: [1.0, NAN], r"u_d\(t\) returned a non-finite value at t = 0: list \[1.0, nan\]"),
    (lambda t: np.zeros(3), r"u_d\(t\) returned an array of length 3 at t = 0, expected 2 numbers"),
    (["1.0", 0.0], r"u_d\[0\] must be a Signal or a finite number, got str '1.0'"),
    ([NAN, 0.0], r"u_d\[0\] must be a Signal or a finite number, got float nan"),
    ([1.0], r"u_d has 1 channels, expected 2"),
    (5.0, r"u_d must be a VectorSignal, a callable f\(t\) -> array, a list of 2 Signals or numbers, or None"),
    (hc.VectorSignal.zeros(3), r"u_d has 3 channels, expected 2"),
])
def test_desired_input_of_the_wrong_kind(u_d, message):
    with pytest.raises(ValueError, match=message):
        hc.Trajectory(hc.ShipModel(), SHIP_Q_D0, u_d, 0.0, 1.0)


def test_desired_input_exception_reaches_the_caller():
    def u_d(t):
        raise ArithmeticError("u_d failed")

    with pytest.raises(ArithmeticError, match="u_d failed"):
        hc.Trajectory(hc.ShipModel(), SHIP_Q_D0, u_d, 0.0, 1.0)


def test_trajectory_arguments_and_evaluations(ship_design):
    tr, _ = ship_design
    with pytest.raises(ValueError, match="Incompatible length of the desired initial state q_d0: expected 6"):
        hc.Trajectory(hc.ShipModel(), [1.0, 0.0], [1.0, 0.0], 0.0, 1.0)
    with pytest.raises(ValueError, match=r"t = 2.5 is outside the solved interval \[0, 2\]"):
        tr.q_d(2.5)
    with pytest.raises(ValueError, match=r"t = -1 is outside the solved interval"):
        tr.A_e(np.array([0.0, -1.0]))
    with pytest.raises(ValueError, match="times must be finite numbers, got nan"):
        tr.u_d(NAN)


# ---- Riccati solutions ----

def test_riccati_solution_evaluations(ship_design, lti_design):
    _, sol = ship_design
    for evaluate in (sol.Z, sol.dZdt, sol.gain):
        with pytest.raises(ValueError, match=r"t = 3 is outside the solved interval \[0, 2\]"):
            evaluate(3.0)
        with pytest.raises(ValueError, match="times must be finite numbers, got nan"):
            evaluate(NAN)
        with pytest.raises(ValueError, match="times must be a number or a 1-D array"):
            evaluate(np.zeros((2, 1)))
    with pytest.raises(ValueError, match="eigenvalue_range needs at least one time"):
        sol.eigenvalue_range([])
    with pytest.raises(ValueError, match="outside the solved interval"):
        sol.eigenvalue_range([0.5, 7.0])
    tr2, _ = lti_design
    Sigma = hc.solve_filter_riccati(tr2, np.eye(1), np.eye(2), 5.0, np.eye(2))
    with pytest.raises(ValueError, match=r"t = -0.5 is outside the solved interval \[0, 1\]"):
        Sigma.Sigma(-0.5)
    with pytest.raises(ValueError, match="eigenvalue_range needs at least one time"):
        Sigma.eigenvalue_range([])


def test_max_rho_sigma_z_of_two_designs_raises():
    """Z (6 x 6) against Sigma (2 x 2) of another model used to read past Sigma."""
    result = run_isolated("""
        import numpy as np
        import hinf_cpp as hc
        tr = hc.Trajectory(hc.ShipModel(), [1.0, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 1.0)
        Z = hc.solve_grde(tr, np.eye(6), np.eye(6), 5.0)
        lti = hc.LinearModel(-np.eye(2), np.ones((2, 1)), np.eye(2), np.eye(2))
        tr2 = hc.Trajectory(lti, [1.0, 0.0], [0.0], 0.0, 1.0)
        Sigma = hc.solve_filter_riccati(tr2, np.eye(2), np.eye(2), 5.0, np.eye(2))
        try:
            print(json.dumps({"value": repr(hc.max_rho_sigma_z(Z, Sigma))}))
        except ValueError as e:
            print(json.dumps({"error": str(e)}))
    """)
    assert "Z is 6 x 6 but Sigma is 2 x 2" in result.get("error", ""), result


# ---- controllers ----

def test_hinf_state_feedback_checks_q(ship_design):
    """control(1.0, [5.0]) used to return [-2.06, -1.27e+296] (a read past q)."""
    result = run_isolated("""
        import numpy as np
        import hinf_cpp as hc
        tr = hc.Trajectory(hc.ShipModel(), [1.0, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 2.0)
        law = hc.HinfStateFeedback(hc.solve_grde(tr, np.eye(6), np.eye(6), 5.0))
        try:
            print(json.dumps({"value": list(law.control(1.0, [5.0]))}))
        except ValueError as e:
            print(json.dumps({"error": str(e)}))
    """)
    assert result.get("error") == "Incompatible length of q: expected 6 but found 1", result
    _, sol = ship_design
    law = hc.HinfStateFeedback(sol)
    assert (law.n(), law.m()) == (6, 2)
    with pytest.raises(ValueError, match="t must be finite, got nan"):
        law.control(NAN, np.zeros(6))
    with pytest.raises(ValueError, match="kappa must be a Signal or a finite number, got float nan"):
        hc.HinfStateFeedback(sol, NAN)
    with pytest.raises(ValueError, match="kappa must be a Signal or a finite number, got str 'one'"):
        hc.HinfStateFeedback(sol, "one")


def test_cascade_controller_checks_q(ship_design):
    tr, _ = ship_design
    law = hc.CascadeController(tr)
    with pytest.raises(ValueError, match="Incompatible length of q: expected 6 but found 3"):
        law.control(0.5, [1.0, 2.0, 3.0])


def python_controller(value, n=None, m=2):
    """A Python controller with m() = m whose control returns `value`; n() only when n is given."""

    class Controller(hc.Controller):
        def __init__(self):
            hc.Controller.__init__(self)

        def m(self):
            return m

        def control(self, t, q):
            return value

    if n is not None:
        Controller.n = lambda self: n
    return Controller()


@pytest.mark.parametrize("controller, message", [
    (python_controller(None), r"the Python controller's control\(t, q\) must return an array of 2 numbers, got None at t = 0"),
    (python_controller([1.0]), r"control\(t, q\) returned an array of length 1 at t = 0, expected 2 numbers"),
    (python_controller([0.0, 0.0], m="two"), r"the Python controller's m\(\) must return an int, got str 'two'"),
    (python_controller([0.0, 0.0], m=0), r"the Python controller's m\(\) must be in \[1, 10000\], got 0"),
    (python_controller([0.0, 0.0], n=3), r"takes q of 3 numbers, the model 'ship' has n = 6 states"),
    (python_controller([0.0, 0.0], n=-1), r"the Python controller's n\(\) must be in \[1, 10000\], got -1"),
])
def test_python_controller_of_the_wrong_kind(ship_design, controller, message):
    tr, _ = ship_design
    with pytest.raises(ValueError, match=message):
        hc.simulate_state_feedback(tr, controller, None, SHIP_Q_D0, hc.SimulationOptions(output_dt=0.5))


def test_python_controller_without_n_keeps_working(ship_design):
    tr, _ = ship_design
    controller = python_controller([1.0, 0.0])
    assert controller.n() == 0
    run = hc.simulate_state_feedback(tr, controller, None, SHIP_Q_D0, hc.SimulationOptions(output_dt=0.5))
    np.testing.assert_array_equal(run.u, np.tile([1.0, 0.0], (len(run.t), 1)))


# ---- disturbances ----

def test_disturbance_checks_q(ship_design):
    """The worst-case disturbance used to read q past its end."""
    result = run_isolated("""
        import numpy as np
        import hinf_cpp as hc
        tr = hc.Trajectory(hc.ShipModel(), [1.0, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 2.0)
        d = hc.Disturbance(hc.VectorSignal.zeros(6), hc.solve_grde(tr, np.eye(6), np.eye(6), 5.0))
        try:
            print(json.dumps({"value": list(d.eval(1.0, [5.0]))}))
        except ValueError as e:
            print(json.dumps({"error": str(e)}))
    """)
    assert result.get("error") == "Incompatible length of q: expected 6 but found 1", result
    with pytest.raises(ValueError, match=r"the dimension of a vector signal must be in \[0, 10000\], got -1"):
        hc.Disturbance(hc.VectorSignal(-1, lambda t: None))
    with pytest.raises(ValueError, match=r"function\(t\) must return an array of 3 numbers, got None at t = 0"):
        hc.Disturbance(hc.VectorSignal(3, lambda t: None)).eval(0.0, np.zeros(6))
    _, sol = ship_design
    with pytest.raises(ValueError, match="t must be finite"):
        hc.Disturbance(hc.VectorSignal.zeros(6), sol).eval(NAN, np.zeros(6))
    with pytest.raises(ValueError, match="the disturbance has 2 channels, the model 'ship' has 6"):
        hc.Disturbance(hc.VectorSignal.zeros(2), sol)


# ---- simulation ----

def test_simulate_state_feedback_arguments(ship_design):
    tr, sol = ship_design
    law = hc.HinfStateFeedback(sol)
    with pytest.raises(ValueError, match="Incompatible length of the initial state q0: expected 6 but found 5"):
        hc.simulate_state_feedback(tr, law, None, np.zeros(5), hc.SimulationOptions(output_dt=0.5))
    with pytest.raises(ValueError, match="disturbance has 2 channels, expected 6"):
        hc.simulate_state_feedback(tr, law, [0.0, 0.0], SHIP_Q_D0, hc.SimulationOptions(output_dt=0.5))
    with pytest.raises(ValueError, match=r"disturbance\(t\) must return an array of 6 numbers, got str 'w'"):
        hc.simulate_state_feedback(tr, law, lambda t: "w", SHIP_Q_D0, hc.SimulationOptions(output_dt=0.5))


def test_output_feedback_arguments(lti_design):
    tr, sol = lti_design
    noise = np.zeros((2, 1))
    problem = hc.OutputFeedbackProblem(sol, 0.1, 0.5, noise, np.eye(1), np.eye(2), np.eye(2))
    law = hc.HinfStateFeedback(sol)
    with pytest.raises(ValueError, match=r"the noise must have 2 rows .* and 1 columns, got \(3, 1\)"):
        hc.simulate_output_feedback(hc.OutputFeedbackProblem(sol, 0.1, 0.5, np.zeros((3, 1)), np.eye(1), np.eye(2),
                                                             np.eye(2)), law, None, [1.0, 0.0])
    with pytest.raises(ValueError, match="takes q of 3 numbers, the model 'linear' has n = 2"):
        hc.simulate_output_feedback(problem, python_controller([0.0], n=3, m=1), None, [1.0, 0.0])
    with pytest.raises(ValueError, match="needs a design"):
        hc.simulate_output_feedback(hc.OutputFeedbackProblem(), law, None, [1.0, 0.0])
    with pytest.raises(ValueError, match="sigma must be >= 0, got -1"):
        hc.OutputFeedbackProblem(sol, -1.0, 0.5, noise, np.eye(1), np.eye(2), np.eye(2))
    with pytest.raises(ValueError, match="sample_period must be > 0, got nan"):
        hc.OutputFeedbackProblem(sol, 0.1, NAN, noise, np.eye(1), np.eye(2), np.eye(2))
    with pytest.raises(ValueError, match=r"Incompatible dimensions of N: expected \(2, 2\) but found \(2, 3\)"):
        hc.OutputFeedbackProblem(sol, 0.1, 0.5, noise, np.ones((2, 3)), np.eye(2), np.eye(2))
    with pytest.raises(ValueError, match=r"Incompatible dimensions of Q \(the size of Sigma0\): expected \(2, 2\)"):
        hc.OutputFeedbackProblem(sol, 0.1, 0.5, noise, np.eye(1), np.eye(2), np.eye(3))
    with pytest.raises(ValueError, match="noise has a non-finite entry nan"):
        hc.OutputFeedbackProblem(sol, 0.1, 0.5, np.full((2, 1), NAN), np.eye(1), np.eye(2), np.eye(2))


def test_standard_normal_samples_refuses_absurd_counts():
    with pytest.raises(ValueError, match=r"count x channels = 1000000000000 x 3 is more than the 1000000000 numbers"):
        hc._core.standard_normal_samples(1, 10**12, 3)
    with pytest.raises(ValueError, match="count must be >= 0, got -5"):
        hc._core.standard_normal_samples(1, -5, 3)
    with pytest.raises(ValueError, match=r"channels must be in \[0, 10000\], got -1"):
        hc._core.standard_normal_samples(1, 5, -1)
    assert hc._core.standard_normal_samples(1, 4, 3).shape == (4, 3)


# ---- metrics ----

def test_compute_metrics_of_a_run_of_another_model(ship_design):
    tr, sol = ship_design
    run = hc.simulate_state_feedback(tr, hc.HinfStateFeedback(sol), None, SHIP_Q_D0,
                                     hc.SimulationOptions(output_dt=0.5))
    lti = hc.LinearModel(-np.eye(2), np.ones((2, 1)), np.eye(2))
    with pytest.raises(ValueError, match=r"run.q has shape \(5, 6\), expected \(5, 2\) for the model 'linear'"):
        hc.compute_metrics(lti, run, np.eye(2))
    with pytest.raises(ValueError, match=r"Incompatible dimensions of Q: expected \(6, 6\) but found \(2, 2\)"):
        hc.compute_metrics(hc.ShipModel(), run, np.eye(2))


# ---- scenarios ----

def test_scenario_fields_of_the_wrong_kind():
    s = hc.Scenario()
    s.model = hc.ShipModel()
    with pytest.raises(ValueError, match="kappa must be a Signal or a finite number, got float nan"):
        s.kappa = NAN
    with pytest.raises(ValueError, match="desired_u has 1 channels, expected 2"):
        s.desired_u = [1.0]
    with pytest.raises(ValueError, match=r"disturbance\[2\] must be a Signal or a finite number, got None"):
        s.disturbance = [0.0, 0.0, None, 0.0, 0.0, 0.0]
    s.t0, s.tf, s.gamma = 0.0, 1.0, 5.0
    s.desired_q0 = np.array(SHIP_Q_D0)
    s.initial_q0 = np.array(SHIP_Q_D0)
    s.desired_u = lambda t: None
    with pytest.raises(ValueError, match=r"desired_u\(t\) must return an array of 2 numbers, got None at t = 0"):
        hc.run_scenario(s)


def test_scenario_with_a_faulty_python_model():
    s = hc.Scenario()
    s.model = returning("heading_index", 7)
    s.t0, s.tf, s.gamma = 0.0, 1.0, 5.0
    with pytest.raises(ValueError, match=r"heading_index\(\) must be -1 \(no heading\) or a state index"):
        hc.run_scenario(s)
