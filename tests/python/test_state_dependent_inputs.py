"""Models whose input matrix depends on the state, dq/dt = f(t, q) + G(t, q) u + D(t, q) w, and
Python models without a hand-written Jacobian.

The design linearizes along the desired trajectory (docs/mathematics.md, "State-dependent
input matrices"): A_e = d/dq [f + G u_d] at q_d, B_e = G(t, q_d), D_e = D(t, q_d). Checked here
against independent computations: central differences of the full right-hand side written out
in this file, a SciPy solution of the GRDE on those matrices, and a SciPy closed loop with the
full nonlinear G(q).
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import hinf_cpp as hc

DAMPING = 0.5


def hover_rhs(q, u):
    """The planar hovercraft in inertial coordinates, written out independently of the models
    below: q = [x, y, psi, vx, vy, r], u = [thrust along the body axis, torque]."""
    x, y, psi, vx, vy, r = q
    return np.array([vx, vy, r,
                     u[0] * np.cos(psi) - DAMPING * vx,
                     u[0] * np.sin(psi) - DAMPING * vy,
                     u[1] - DAMPING * r])


class NumericalHovercraft(hc.Model):
    """The same model as an hc.Model without dfdq and dGudq: f computes with complex q (NumPy),
    so its Jacobian is the complex step; d(G u)/dq is by central differences."""

    def name(self): return "python-hovercraft"
    def n(self): return 6
    def m(self): return 2
    def nw(self): return 3
    def f(self, t, q): return np.array([q[3], q[4], q[5], -DAMPING * q[3], -DAMPING * q[4], -DAMPING * q[5]])

    def G(self, t, q):
        G = np.zeros((6, 2), dtype=np.result_type(q, float))
        G[3, 0], G[4, 0], G[5, 1] = np.cos(q[2]), np.sin(q[2]), 1.0
        return G

    def D(self, t, q): return np.vstack([np.zeros((3, 3)), np.eye(3)])
    def constant_input_matrices(self): return False
    def state_dependent_inputs(self): return True
    def position_indices(self): return [0, 1]
    def heading_index(self): return 2


class Hovercraft(NumericalHovercraft):
    """With analytic dfdq and dGudq."""

    def dfdq(self, t, q):
        J = np.zeros((6, 6))
        J[0, 3] = J[1, 4] = J[2, 5] = 1.0
        J[3, 3] = J[4, 4] = J[5, 5] = -DAMPING
        return J

    def dGudq(self, t, q, u):
        J = np.zeros((6, 6))
        J[3, 2], J[4, 2] = -u[0] * np.sin(q[2]), u[0] * np.cos(q[2])
        return J


U_D = [1.0, 0.2]  # constant thrust and torque: a spiral with growing heading
Q_D0 = np.array([0.0, 0.0, 0.0, 1.0, 0.0, 0.0])
T0, TF = 0.0, 8.0


@pytest.fixture(scope="module")
def turn():
    return hc.Trajectory(Hovercraft(), Q_D0, U_D, T0, TF)


def central_jacobian(fun, x, h=1e-6):
    """Central differences, step h: truncation h^2 |f'''| / 6 ~ 1e-13 and round-off
    eps |f| / h ~ 1e-10 for the O(1) functions here."""
    J = np.zeros((len(fun(x)), len(x)))
    for j in range(len(x)):
        e = np.zeros(len(x))
        e[j] = h
        J[:, j] = (fun(x + e) - fun(x - e)) / (2 * h)
    return J


def test_linearization_along_the_trajectory_against_finite_differences(turn):
    """A_e(t) = d/dq [f + G u_d] at q_d(t) and B_e(t) = G(q_d(t)), against central differences of
    the right-hand side written out above (the d(G u_d)/dpsi column is what state-dependent
    inputs add: without it A_e would miss u_d [-sin psi, cos psi])."""
    for t in np.linspace(T0, TF, 9):
        q_d = turn.q_d(t)
        J = central_jacobian(lambda q: hover_rhs(q, U_D), q_d)
        np.testing.assert_allclose(turn.A_e(t), J, atol=1e-8)  # FD accuracy ~1e-10, margin 100
        np.testing.assert_allclose(turn.B_e(t), Hovercraft().G(t, q_d), rtol=0, atol=0)
        assert abs(turn.A_e(t)[3, 2] + U_D[0] * math.sin(q_d[2])) < 1e-12  # the input's own term


def test_numerical_jacobians_of_a_python_model(turn):
    """No dfdq: the complex step (f computes with complex q), exact to round-off; no dGudq:
    central differences, accurate to about eps^(2/3) ~ 4e-11 of the scale."""
    analytic = Hovercraft()
    numerical = NumericalHovercraft()
    assert analytic.jacobian_method() == "analytic"
    rng = np.random.default_rng(5)
    for _ in range(10):
        q, u = rng.normal(size=6), rng.normal(size=2)
        np.testing.assert_allclose(numerical.dfdq(0.0, q), analytic.dfdq(0.0, q), rtol=0, atol=1e-14)
        np.testing.assert_allclose(numerical.dGudq(0.0, q, u), analytic.dGudq(0.0, q, u), rtol=0,
                                   atol=1e-8 * (1 + np.abs(u).max()))
    assert numerical.jacobian_method() == "complex step; d(G u)/dq by central differences"


class Pendulum(hc.Model):
    """dtheta/dt = omega, domega/dt = -sin(theta) + u: f with math.sin (no complex numbers)."""

    def n(self): return 2
    def m(self): return 1
    def nw(self): return 1
    def f(self, t, q): return np.array([q[1], -math.sin(q[0])])
    def G(self, t, q): return np.array([[0.0], [1.0]])
    def D(self, t, q): return np.array([[0.0], [1.0]])


class AbsSpring(Pendulum):
    """f computes with complex q, but abs() drops the imaginary part: the complex step would
    give 0 for d|theta|/dtheta; the first call sees it disagree with central differences and
    takes those."""

    def f(self, t, q):
        q = np.asarray(q)
        return np.array([q[1], -np.abs(q[0])])


@pytest.mark.parametrize("model, d_omega_d_theta", [(Pendulum(), -math.cos(0.7)), (AbsSpring(), -1.0)])
def test_models_the_complex_step_cannot_serve_get_central_differences(model, d_omega_d_theta):
    J = model.dfdq(0.0, np.array([0.7, -0.3]))
    np.testing.assert_allclose(J, [[0.0, 1.0], [d_omega_d_theta, 0.0]], rtol=0, atol=1e-8)  # FD: ~1e-10
    assert model.jacobian_method() == "central differences"


def test_grde_against_scipy_on_the_linearization(turn):
    """The GRDE on (A_e, B_e, D_e) of the state-dependent model against SciPy's Radau on the
    matrices computed in this file (A_e by central differences of hover_rhs along the
    library's q_d(t), which is itself checked above)."""
    gamma, Q, Qf = 4.0, np.eye(6), np.eye(6)
    sol = hc.solve_grde(turn, Q, Qf, gamma, hc.SolverOptions("bdf", rtol=1e-10, atol=1e-12))
    D = Hovercraft().D(0.0, Q_D0)

    def rhs(t, z):
        Z = z.reshape(6, 6)
        q_d = turn.q_d(t)
        A = central_jacobian(lambda q: hover_rhs(q, U_D), q_d, h=1e-5)
        B = Hovercraft().G(t, q_d)
        S = B @ B.T - D @ D.T / gamma**2
        return (-(A.T @ Z + Z @ A + Q - Z @ S @ Z)).ravel()

    ref = solve_ivp(rhs, (TF, T0), Qf.ravel(), method="Radau", rtol=1e-9, atol=1e-11)
    Z0 = ref.y[:, -1].reshape(6, 6)
    # Both solves at rtol <= 1e-9 and A_e by differences to ~1e-10: agreement to 1e-6 of |Z|.
    np.testing.assert_allclose(sol.Z(T0), Z0, rtol=0, atol=1e-6 * np.abs(Z0).max())


def test_closed_loop_with_the_full_nonlinear_input_matrix(turn):
    """The state-feedback run against SciPy's DOP853 on hover_rhs with u = u_d - B_e' Z q_e
    (the library's gain), both at tight tolerances; and the loop converges."""
    sol = hc.solve_grde(turn, np.eye(6), np.eye(6), 4.0)
    q0 = Q_D0 + np.array([0.5, -0.4, 0.3, 0.0, 0.2, 0.0])
    options = hc.SimulationOptions(output_dt=0.5, solver=hc.SolverOptions("erk", rtol=1e-10, atol=1e-12))
    run = hc.simulate_state_feedback(turn, hc.HinfStateFeedback(sol), None, q0, options)

    def closed_loop(t, q):
        q_e = q - turn.q_d(t)
        u = np.asarray(U_D) - sol.gain(t) @ q_e
        return hover_rhs(q, u)

    ref = solve_ivp(closed_loop, (T0, TF), q0, method="DOP853", t_eval=run.t, rtol=1e-11, atol=1e-12)
    # Both integrations at rtol <= 1e-10 over an O(1) state on 8 s: 1e-7 leaves a wide margin.
    np.testing.assert_allclose(run.q, ref.y.T, rtol=0, atol=1e-7)
    initial = np.linalg.norm(q0[:2] - Q_D0[:2])
    final = np.linalg.norm(run.q[-1, :2] - run.q_d[-1, :2])
    assert final < 0.1 * initial


def test_zero_error_start_stays_on_the_trajectory(turn):
    """q0 = q_d0, no disturbance: the closed loop is the desired trajectory; the error stays at
    the integration's tolerance times the state's scale (rtol 1e-8, |q| <= 10)."""
    sol = hc.solve_grde(turn, np.eye(6), np.eye(6), 4.0)
    run = hc.simulate_state_feedback(turn, hc.HinfStateFeedback(sol), None, Q_D0, hc.SimulationOptions(output_dt=0.1))
    assert np.abs(run.q - run.q_d).max() < 1e-5


def test_error_split_includes_the_inputs_drift(turn):
    """f_e(q_e) = f(q_d + q_e) + G(q_d + q_e) u_d - f(q_d) - G(q_d) u_d = A(q_e) q_e + alpha,
    A(0) = A_e (the default split), with f_e from hover_rhs."""
    model = Hovercraft()
    rng = np.random.default_rng(8)
    for t in (0.0, 3.0, 7.5):
        q_d = turn.q_d(t)
        for _ in range(5):
            q_e = 0.3 * rng.normal(size=6)
            A, alpha = model.error_split(t, q_d, np.asarray(U_D), q_e)
            f_e = hover_rhs(q_d + q_e, U_D) - hover_rhs(q_d, U_D)
            np.testing.assert_allclose(A @ q_e + alpha, f_e, rtol=0, atol=1e-13)
        A0, alpha0 = model.error_split(t, q_d, np.asarray(U_D), np.zeros(6))
        np.testing.assert_allclose(A0, turn.A_e(t), rtol=0, atol=1e-15)
        np.testing.assert_array_equal(alpha0, 0.0)


def test_output_feedback_with_state_dependent_inputs_tracks(turn):
    """The estimator applies G at q_d + q_hat; with measured positions and heading the loop
    converges (final position error below a tenth of the initial one)."""

    class Measured(Hovercraft):
        def nw(self): return 6
        def D(self, t, q): return np.hstack([np.vstack([np.zeros((3, 3)), np.eye(3)]), np.zeros((6, 3))])
        def C(self, t): return np.hstack([np.eye(3), np.zeros((3, 3))])
        def noise_channels(self): return [3, 4, 5]

    tr = hc.Trajectory(Measured(), Q_D0, U_D, T0, 15.0)
    design = hc.solve_grde(tr, np.eye(6), np.eye(6), 5.0)
    noise = np.random.default_rng(3).standard_normal((150, 3))
    problem = hc.OutputFeedbackProblem(design=design, sigma=0.01, sample_period=0.1, noise=noise,
                                       N=1e-4 * np.eye(3), Sigma0=0.5 * np.eye(6), Q=np.eye(6))
    q0 = Q_D0 + np.array([0.4, -0.3, 0.1, 0.0, 0.0, 0.0])
    run = hc.simulate_output_feedback(problem, hc.HinfStateFeedback(design), None, q0,
                                      hc.OutputFeedbackOptions(), hc.SimulationOptions(output_dt=0.1))
    final = np.linalg.norm(run.q[-1, :2] - run.q_d[-1, :2])
    assert final < 0.1 * np.linalg.norm(q0[:2] - Q_D0[:2])


# ---- bad models: clear errors where the model enters ----

class ConstantAndStateDependent(Hovercraft):
    def constant_input_matrices(self): return True


class WrongInputColumns(Hovercraft):
    def G(self, t, q): return np.zeros((6, 3))


class NanInput(Hovercraft):
    def G(self, t, q):
        G = super().G(t, q)
        G[3, 0] = math.nan
        return G


@pytest.mark.parametrize("model, message", [
    (ConstantAndStateDependent(), "says its input matrices are constant and also that they depend on the state"),
    (WrongInputColumns(), r"G\(t, q\) returned an array of shape \(6, 3\) at t = 0, expected \(6, 2\)"),
    (NanInput(), r"G\(t, q\) at t = 0 has a non-finite entry nan at \(3, 0\)"),
])
def test_bad_models_are_clear_errors_at_construction(model, message):
    with pytest.raises(ValueError, match=message):
        hc.Trajectory(model, Q_D0, U_D, T0, TF)
