"""
hinf_cpp core: H-infinity tracking control of nonlinear underactuated vehicles
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['Auv', 'AuvParameters', 'CascadeController', 'CascadeGains', 'Certificates', 'ConjugatePointError', 'Controller', 'CouplingConditionError', 'CouplingPolicy', 'Disturbance', 'EstimatorSeries', 'FilterLinearization', 'FilterRiccatiSolution', 'FleetModel', 'FossenVessel', 'FossenVesselParameters', 'GammaCondition', 'GammaStarOptions', 'GammaStarResult', 'GammaTrial', 'GeneratedFunction', 'GeneratedModel', 'Harmonic', 'HinfError', 'HinfStateFeedback', 'Hovercraft', 'HovercraftParameters', 'Interpolation', 'Law', 'LinearModel', 'MeasurementSpec', 'Method', 'MetricDefinition', 'Metrics', 'Model', 'ModelStructure', 'NewtonSystems', 'OutputFeedbackOptions', 'OutputFeedbackProblem', 'PiecewisePolynomial', 'PlanarVtol', 'PlanarVtolParameters', 'RiccatiSolution', 'RunOutcome', 'RunResult', 'RunStatus', 'Scenario', 'ShipModel', 'ShipParameters', 'Signal', 'SimulationOptions', 'SimulationResult', 'SolveStats', 'SolverError', 'SolverOptions', 'StepStats', 'StudyOptions', 'StudyRun', 'SymmetricSolution', 'Timing', 'Trajectory', 'TrajectoryOptions', 'VectorSignal', 'certify', 'check_model_structure', 'compute_metrics', 'filter_escape_time', 'gamma_star', 'gamma_star_output_feedback', 'grde_escape_time', 'l2_norm', 'load_scenario_toml', 'max_rho_sigma_z', 'metric_table', 'needs_planning_toml', 'noise_sample_count', 'output_count', 'output_grid', 'overshoot_warning', 'parse_model_toml', 'parse_scenario_toml', 'parse_signal_toml', 'results_csv', 'results_json', 'run_scenario', 'run_scenario_with_noise', 'run_scenarios', 'scenario_certificates', 'scenario_gamma_star', 'scenario_gamma_star_output_feedback', 'scenario_noise', 'scenario_toml', 'scenario_warnings', 'set_python_model_hook', 'simulate_output_feedback', 'simulate_state_feedback', 'solve_filter_riccati', 'solve_grde', 'standard_normal_samples', 'wrap_angle']
class HinfError(RuntimeError):
    """
    Base class of the numerical failures of hinf_cpp.
    """
class SolverError(HinfError):
    pass
class ConjugatePointError(HinfError):
    pass
class CouplingConditionError(HinfError):
    pass
class Method:
    """
    Integrator of every ODE solve (solver_options.hpp)
    
    Members:
    
      auto
    
      bdf
    
      adams
    
      erk
    """
    __members__: typing.ClassVar[dict[str, Method]]
    adams: typing.ClassVar[Method]
    auto: typing.ClassVar[Method]
    bdf: typing.ClassVar[Method]
    erk: typing.ClassVar[Method]
    def __eq__(self: Method | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: Method | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: Method | str) -> int:
        ...
    def __ne__(self: Method | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class NewtonSystems:
    """
    How BDF solves the Newton systems of a Riccati equation (solver_options.hpp)
    
    Members:
    
      auto
    
      dense
    
      lyapunov
    """
    __members__: typing.ClassVar[dict[str, NewtonSystems]]
    auto: typing.ClassVar[NewtonSystems]
    dense: typing.ClassVar[NewtonSystems]
    lyapunov: typing.ClassVar[NewtonSystems]
    def __eq__(self: NewtonSystems | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: NewtonSystems | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: NewtonSystems | str) -> int:
        ...
    def __ne__(self: NewtonSystems | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class Interpolation:
    """
    How a table Signal is interpolated between its points (signal.hpp)
    
    Members:
    
      pchip
    
      linear
    
      hold
    
      cubic
    """
    __members__: typing.ClassVar[dict[str, Interpolation]]
    cubic: typing.ClassVar[Interpolation]
    hold: typing.ClassVar[Interpolation]
    linear: typing.ClassVar[Interpolation]
    pchip: typing.ClassVar[Interpolation]
    def __eq__(self: Interpolation | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: Interpolation | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: Interpolation | str) -> int:
        ...
    def __ne__(self: Interpolation | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class Harmonic:
    """
    a sin(omega t + phase) (or cos) term of a Signal
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('amplitude', 'omega', 'phase', 'cosine')
    cosine: bool
    def __eq__(self, arg0: Harmonic) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, amplitude: typing.SupportsFloat | typing.SupportsIndex = 0.0, omega: typing.SupportsFloat | typing.SupportsIndex = 0.0, phase: typing.SupportsFloat | typing.SupportsIndex = 0.0, cosine: bool = False) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def amplitude(self) -> float:
        ...
    @amplitude.setter
    def amplitude(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def omega(self) -> float:
        ...
    @omega.setter
    def omega(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def phase(self) -> float:
        ...
    @phase.setter
    def phase(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Signal:
    """
    A scalar signal of absolute time: offset + harmonics, or a table
    """
    @staticmethod
    def table(t: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], values: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], interpolation: Interpolation | str = Interpolation.pchip) -> Signal:
        """
        The table (t_i, v_i), interpolated by "pchip" (default, no overshoot), "linear", "hold" (the value of the last point at or before t) or "cubic" (natural spline; a UserWarning when it overshoots the values' range); at least two points, strictly increasing t
        """
    def __call__(self, t: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    @typing.overload
    def __init__(self) -> None:
        ...
    @typing.overload
    def __init__(self, constant: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, offset: typing.SupportsFloat | typing.SupportsIndex, harmonics: collections.abc.Sequence[Harmonic]) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def describe(self) -> str:
        ...
    def harmonics(self) -> list[Harmonic]:
        ...
    def interpolation(self) -> Interpolation:
        ...
    def is_constant(self) -> bool:
        ...
    def is_table(self) -> bool:
        ...
    def minimum(self, t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex) -> tuple[float, float]:
        """
        (the smallest value on [t0, tf], where it is taken)
        """
    def offset(self) -> float:
        ...
    def overshoot(self) -> tuple[float, float]:
        """
        (how far a table's interpolant leaves the range of its values, where); (0, t_first) inside it
        """
    def table_t(self) -> list[float]:
        ...
    def table_values(self) -> list[float]:
        ...
class VectorSignal:
    """
    A vector signal: one Signal per channel, or a function of t
    """
    @staticmethod
    def zeros(dim: typing.SupportsInt | typing.SupportsIndex) -> VectorSignal:
        ...
    def __call__(self, t: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[int, list[Signal]]:
        ...
    @typing.overload
    def __init__(self, channels: collections.abc.Sequence) -> None:
        """
        one Signal (or number) per channel
        """
    @typing.overload
    def __init__(self, dim: typing.SupportsInt | typing.SupportsIndex, function: collections.abc.Callable) -> None:
        """
        function(t) must return an array of dim numbers
        """
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def channels(self) -> list[Signal]:
        ...
    def dim(self) -> int:
        ...
    def is_function(self) -> bool:
        ...
class SolverOptions:
    """
    Integrator and tolerances ([solver] of a scenario)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('method', 'rtol', 'atol', 'max_steps', 'escape_norm', 'newton_systems')
    def __eq__(self, arg0: SolverOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, method: Method | str = Method.auto, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-08, atol: typing.SupportsFloat | typing.SupportsIndex = 1e-10, max_steps: typing.SupportsInt | typing.SupportsIndex = 500000, escape_norm: typing.SupportsFloat | typing.SupportsIndex = 1000000.0, newton_systems: NewtonSystems | str = NewtonSystems.auto) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def atol(self) -> float:
        ...
    @atol.setter
    def atol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def escape_norm(self) -> float:
        ...
    @escape_norm.setter
    def escape_norm(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_steps(self) -> int:
        ...
    @max_steps.setter
    def max_steps(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def method(self) -> Method:
        ...
    @method.setter
    def method(self, arg1: Method | str) -> None:
        ...
    @property
    def newton_systems(self) -> NewtonSystems:
        ...
    @newton_systems.setter
    def newton_systems(self, arg1: NewtonSystems | str) -> None:
        ...
    @property
    def rtol(self) -> float:
        ...
    @rtol.setter
    def rtol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class PiecewisePolynomial:
    """
    Dense output of an ODE solve: one polynomial per step
    """
    def __getstate__(self) -> tuple:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def breakpoints(self) -> list[float]:
        """
        the ends of the pieces, increasing
        """
    def dim(self) -> int:
        ...
    def empty(self) -> bool:
        ...
    def eval(self, t: typing.Any) -> typing.Any:
        ...
    def eval_derivative(self, t: typing.Any) -> typing.Any:
        ...
    def memory_bytes(self) -> int:
        ...
    def num_pieces(self) -> int:
        ...
    def t_max(self) -> float:
        ...
    def t_min(self) -> float:
        ...
class StepStats:
    """
    Counts of an integration
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('steps', 'rejected', 'rhs_evals', 'jac_evals')
    def __eq__(self, arg0: StepStats) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def jac_evals(self) -> int:
        ...
    @property
    def rejected(self) -> int:
        ...
    @property
    def rhs_evals(self) -> int:
        ...
    @property
    def steps(self) -> int:
        ...
class GeneratedFunction:
    """
    A function of a shared library compiled from CasADi generated C code (hinf_cpp.codegen.compile_casadi_functions), evaluated in C++
    """
    def __call__(self, *args) -> list[numpy.typing.NDArray[numpy.float64]]:
        """
        Evaluates in C++ (the GIL released): one input per argument (a number, a 1-D array for a vector, or an array of the input's shape); one 2-D array per output
        """
    def __init__(self, path: str, name: str) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def input_name(self, i: typing.SupportsInt | typing.SupportsIndex) -> str:
        ...
    def input_shape(self, i: typing.SupportsInt | typing.SupportsIndex) -> tuple[int, int]:
        ...
    def n_in(self) -> int:
        ...
    def n_out(self) -> int:
        ...
    def name(self) -> str:
        ...
    def output_name(self, i: typing.SupportsInt | typing.SupportsIndex) -> str:
        ...
    def output_shape(self, i: typing.SupportsInt | typing.SupportsIndex) -> tuple[int, int]:
        ...
    def path(self) -> str:
        ...
class Model:
    """
    Control-affine model dq/dt = f(t, q) + G(t, q) u + D(t, q) w (paper eq. 7; model.hpp).
    Subclass it in Python and implement n(), m(), nw(), f(t, q), G(t, q), D(t, q), and if you can
    dfdq(t, q) (else a numerical Jacobian is used: the complex step when f accepts complex q, else
    central differences; jacobian_method() says which). A G or D that depends on q needs
    state_dependent_inputs() -> True and constant_input_matrices() -> False (dGudq(t, q, u) =
    d/dq [G(t, q) u] is optional: central differences otherwise). Its structure (n, m, nw, name,
    state_names, position_indices, heading_index, noise_channels, constant_input_matrices,
    state_dependent_inputs) is read once, when the library first needs it, and validated; it must not
    change afterwards. What f, dfdq, G, D, C and error_split return is checked at every call.
    A model implemented in Python does not pickle.
    """
    def C(self, t: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        measurement matrix of y = C q + E w (paper eq. 25)
        """
    def D(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        disturbance matrix D(t, q) (n x nw)
        """
    def G(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        input matrix G(t, q) (n x m)
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self) -> None:
        ...
    def constant_input_matrices(self) -> bool:
        ...
    def dGudq(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        d/dq [G(t, q) u] (n x n; zero when G does not depend on q)
        """
    def dfdq(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    def error_split(self, t: typing.SupportsFloat | typing.SupportsIndex, q_d: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u_d: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], q_e: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
        """
        (A, alpha) of f_e = A(t, q_e) q_e + alpha (paper 26-31; f_e includes G(q) u_d - G(q_d) u_d)
        """
    def f(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    def heading_index(self) -> int:
        ...
    def jacobian_method(self) -> str:
        """
        how dfdq is obtained: analytic, automatic differentiation, complex step or central differences
        """
    def linearize(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        d/dq [f(t, q) + G(t, q) u] (A_e(t) at q_d(t), u_d(t))
        """
    def m(self) -> int:
        ...
    def n(self) -> int:
        ...
    def name(self) -> str:
        ...
    def named_parameters(self) -> dict[str, float]:
        """
        the parameters by name, the keys of the model's scenario-file section ([model], [plant]); a matrix entry as NAME[i][j] (from 0); empty for a model without named parameters. A model implemented in Python may define it (returning a dict of numbers)
        """
    def noise_channels(self) -> list[int]:
        """
        the w channels that carry measurement noise
        """
    def nw(self) -> int:
        ...
    def position_indices(self) -> list[int]:
        ...
    def remainder_bound(self, t: typing.SupportsFloat | typing.SupportsIndex, q_d: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], radius: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        L with |f_e - A_e q_e| <= L |q_e|^2 for |q_e| <= radius, or NaN if the model has none
        """
    def state_dependent_inputs(self) -> bool:
        ...
    def state_names(self) -> list[str]:
        ...
class ShipParameters:
    """
    Parameters of the ship of paper eqs. (1)-(6)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('m_u', 'm_v', 'm_r', 'd_u', 'd_v', 'd_r')
    def __eq__(self, arg0: ShipParameters) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, m_u: typing.SupportsFloat | typing.SupportsIndex = 0.5, m_v: typing.SupportsFloat | typing.SupportsIndex = -2.0, m_r: typing.SupportsFloat | typing.SupportsIndex = 0.5, d_u: typing.SupportsFloat | typing.SupportsIndex = 1.0, d_v: typing.SupportsFloat | typing.SupportsIndex = 2.0, d_r: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def d_r(self) -> float:
        ...
    @d_r.setter
    def d_r(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def d_u(self) -> float:
        ...
    @d_u.setter
    def d_u(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def d_v(self) -> float:
        ...
    @d_v.setter
    def d_v(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m_r(self) -> float:
        ...
    @m_r.setter
    def m_r(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m_u(self) -> float:
        ...
    @m_u.setter
    def m_u(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m_v(self) -> float:
        ...
    @m_v.setter
    def m_v(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class ShipModel(Model):
    """
    The underactuated ship of paper eqs. (1)-(6)
    """
    def __getstate__(self) -> tuple[ShipParameters]:
        ...
    def __init__(self, parameters: ShipParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> ShipParameters:
        ...
class LinearModel(Model):
    """
    dq/dt = A q + B u + D w; with C (p x n), y = C q + noise on p extra w channels
    """
    def A(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    def B(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    def __getstate__(self) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]]:
        ...
    def __init__(self, A: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], B: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], D: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], C: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def measurement_C(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        C as given to the constructor (empty if none)
        """
    def process_D(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        D as given to the constructor (without the noise channels)
        """
class FleetModel(Model):
    """
    count independent copies of a model stacked block-diagonally (fleet.hpp)
    """
    def __getstate__(self) -> tuple[Model, int]:
        ...
    def __init__(self, member: Model, count: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def count(self) -> int:
        ...
    def member(self) -> Model:
        ...
class FossenVesselParameters:
    """
    M (mass) and D (damping) of the 3-DOF vessel in Fossen's form; defaults: the supply vessel (bis units)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('M', 'D')
    @staticmethod
    def supply_vessel() -> FossenVesselParameters:
        """
        Fossen, Sagatun and Sorensen (1996), in bis units (the defaults)
        """
    def __eq__(self, arg0: FossenVesselParameters) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, M: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ..., D: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def D(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @D.setter
    def D(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def M(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @M.setter
    def M(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
class HovercraftParameters:
    """
    Damping per unit mass (d) and inertia (d_r) of the planar hovercraft (1/s)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('d', 'd_r')
    def __eq__(self, arg0: HovercraftParameters) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, d: typing.SupportsFloat | typing.SupportsIndex = 0.2, d_r: typing.SupportsFloat | typing.SupportsIndex = 0.5) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def d(self) -> float:
        ...
    @d.setter
    def d(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def d_r(self) -> float:
        ...
    @d_r.setter
    def d_r(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class PlanarVtolParameters:
    """
    Gravity g and coupling epsilon of the planar VTOL (normalized units)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('g', 'epsilon')
    def __eq__(self, arg0: PlanarVtolParameters) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, g: typing.SupportsFloat | typing.SupportsIndex = 1.0, epsilon: typing.SupportsFloat | typing.SupportsIndex = 0.1) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def epsilon(self) -> float:
        ...
    @epsilon.setter
    def epsilon(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def g(self) -> float:
        ...
    @g.setter
    def g(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class AuvParameters:
    """
    Masses (kg, kg m^2) and drag coefficients of the AUV; defaults: the Sirene AUV
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('m11', 'm22', 'm33', 'X_u', 'X_uu', 'Y_v', 'Y_vv', 'N_r', 'N_rr')
    @staticmethod
    def sirene() -> AuvParameters:
        """
        Aguiar and Pascoal (2007) (the defaults)
        """
    def __eq__(self, arg0: AuvParameters) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, m11: typing.SupportsFloat | typing.SupportsIndex = 215.0, m22: typing.SupportsFloat | typing.SupportsIndex = 265.0, m33: typing.SupportsFloat | typing.SupportsIndex = 80.0, X_u: typing.SupportsFloat | typing.SupportsIndex = 70.0, X_uu: typing.SupportsFloat | typing.SupportsIndex = 100.0, Y_v: typing.SupportsFloat | typing.SupportsIndex = 100.0, Y_vv: typing.SupportsFloat | typing.SupportsIndex = 200.0, N_r: typing.SupportsFloat | typing.SupportsIndex = 50.0, N_rr: typing.SupportsFloat | typing.SupportsIndex = 100.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def N_r(self) -> float:
        ...
    @N_r.setter
    def N_r(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def N_rr(self) -> float:
        ...
    @N_rr.setter
    def N_rr(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def X_u(self) -> float:
        ...
    @X_u.setter
    def X_u(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def X_uu(self) -> float:
        ...
    @X_uu.setter
    def X_uu(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def Y_v(self) -> float:
        ...
    @Y_v.setter
    def Y_v(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def Y_vv(self) -> float:
        ...
    @Y_vv.setter
    def Y_vv(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m11(self) -> float:
        ...
    @m11.setter
    def m11(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m22(self) -> float:
        ...
    @m22.setter
    def m22(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m33(self) -> float:
        ...
    @m33.setter
    def m33(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class FossenVessel(Model):
    """
    3-DOF underactuated surface vessel M nu' + C(nu) nu + D nu = tau (vehicles.hpp)
    """
    def __getstate__(self) -> tuple[FossenVesselParameters]:
        ...
    def __init__(self, parameters: FossenVesselParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> FossenVesselParameters:
        ...
class Hovercraft(Model):
    """
    Planar hovercraft in inertial coordinates (vehicles.hpp)
    """
    def __getstate__(self) -> tuple[HovercraftParameters]:
        ...
    def __init__(self, parameters: HovercraftParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> HovercraftParameters:
        ...
class PlanarVtol(Model):
    """
    Planar VTOL aircraft of Hauser, Sastry and Meyer (1992) (vehicles.hpp)
    """
    def __getstate__(self) -> tuple[PlanarVtolParameters]:
        ...
    def __init__(self, parameters: PlanarVtolParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> PlanarVtolParameters:
        ...
class Auv(Model):
    """
    Underactuated AUV in the horizontal plane (vehicles.hpp)
    """
    def __getstate__(self) -> tuple[AuvParameters]:
        ...
    def __init__(self, parameters: AuvParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> AuvParameters:
        ...
class GeneratedModel(Model):
    """
    A model evaluated by CasADi-generated C code (generated_model.hpp; build it with hinf_cpp.symbolic.SymbolicModel)
    """
    def __getstate__(self) -> tuple[str, dict[str, float]]:
        ...
    def __init__(self, metadata_path: str, parameters: collections.abc.Mapping[str, typing.SupportsFloat | typing.SupportsIndex] = {}) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def library_path(self) -> str:
        ...
    def metadata_path(self) -> str:
        ...
    def parameter_names(self) -> list[str]:
        ...
    def parameters(self) -> dict[str, float]:
        ...
class ModelStructure:
    """
    What a model says about itself (model.hpp)
    """
    constant_input_matrices: bool
    name: str
    state_dependent_inputs: bool
    def __init__(self) -> None:
        ...
    @property
    def heading_index(self) -> int:
        ...
    @heading_index.setter
    def heading_index(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def m(self) -> int:
        ...
    @m.setter
    def m(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def n(self) -> int:
        ...
    @n.setter
    def n(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def noise_channels(self) -> list[int]:
        ...
    @noise_channels.setter
    def noise_channels(self, arg0: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex]) -> None:
        ...
    @property
    def nw(self) -> int:
        ...
    @nw.setter
    def nw(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def position_indices(self) -> list[int]:
        ...
    @position_indices.setter
    def position_indices(self, arg0: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex]) -> None:
        ...
    @property
    def state_names(self) -> list[str]:
        ...
    @state_names.setter
    def state_names(self, arg0: collections.abc.Sequence[str]) -> None:
        ...
class RunStatus:
    """
    How a closed-loop run ended (simulation.hpp)
    
    Members:
    
      completed
    
      diverged
    """
    __members__: typing.ClassVar[dict[str, RunStatus]]
    completed: typing.ClassVar[RunStatus]
    diverged: typing.ClassVar[RunStatus]
    def __eq__(self: RunStatus | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: RunStatus | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: RunStatus | str) -> int:
        ...
    def __ne__(self: RunStatus | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class FilterLinearization:
    """
    Which A the filter Riccati equation (36) uses (output_feedback.hpp)
    
    Members:
    
      estimate
    
      desired
    """
    __members__: typing.ClassVar[dict[str, FilterLinearization]]
    desired: typing.ClassVar[FilterLinearization]
    estimate: typing.ClassVar[FilterLinearization]
    def __eq__(self: FilterLinearization | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: FilterLinearization | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: FilterLinearization | str) -> int:
        ...
    def __ne__(self: FilterLinearization | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class CouplingPolicy:
    """
    What a violation of rho(Sigma Z) < gamma^2 does (output_feedback.hpp)
    
    Members:
    
      error
    
      flag
    """
    __members__: typing.ClassVar[dict[str, CouplingPolicy]]
    error: typing.ClassVar[CouplingPolicy]
    flag: typing.ClassVar[CouplingPolicy]
    def __eq__(self: CouplingPolicy | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: CouplingPolicy | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: CouplingPolicy | str) -> int:
        ...
    def __ne__(self: CouplingPolicy | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class GammaCondition:
    """
    The condition a gamma fails (analysis.hpp)
    
    Members:
    
      none
    
      grde
    
      filter
    
      coupling
    """
    __members__: typing.ClassVar[dict[str, GammaCondition]]
    coupling: typing.ClassVar[GammaCondition]
    filter: typing.ClassVar[GammaCondition]
    grde: typing.ClassVar[GammaCondition]
    none: typing.ClassVar[GammaCondition]
    def __eq__(self: GammaCondition | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: GammaCondition | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: GammaCondition | str) -> int:
        ...
    def __ne__(self: GammaCondition | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class SimulationOptions:
    """
    How a closed loop is simulated ([output] dt and [solver] of a scenario)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('output_dt', 'divergence_factor', 'solver')
    solver: SolverOptions
    def __eq__(self, arg0: SimulationOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, output_dt: typing.SupportsFloat | typing.SupportsIndex = 0.01, divergence_factor: typing.SupportsFloat | typing.SupportsIndex = 1000.0, solver: SolverOptions = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def divergence_factor(self) -> float:
        ...
    @divergence_factor.setter
    def divergence_factor(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def output_dt(self) -> float:
        ...
    @output_dt.setter
    def output_dt(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class TrajectoryOptions:
    """
    Tolerances of the desired trajectory's integration
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('rtol', 'atol', 'max_steps')
    def __eq__(self, arg0: TrajectoryOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-10, atol: typing.SupportsFloat | typing.SupportsIndex = 1e-12, max_steps: typing.SupportsInt | typing.SupportsIndex = 2000000) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def atol(self) -> float:
        ...
    @atol.setter
    def atol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_steps(self) -> int:
        ...
    @max_steps.setter
    def max_steps(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def rtol(self) -> float:
        ...
    @rtol.setter
    def rtol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Trajectory:
    """
    Desired trajectory of paper eq. (8) with dense output
    """
    def A_e(self, t: typing.Any) -> typing.Any:
        """
        d/dq [f + G u_d] at q_d(t)
        """
    def B_e(self, t: typing.Any) -> typing.Any:
        """
        G(t, q_d(t))
        """
    def D_e(self, t: typing.Any) -> typing.Any:
        """
        D(t, q_d(t))
        """
    def __getstate__(self) -> tuple[Model, typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"], VectorSignal, float, float, PiecewisePolynomial, StepStats]:
        ...
    def __init__(self, model: Model, q_d0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u_d: typing.Any, t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex, options: TrajectoryOptions = ...) -> None:
        """
        u_d: a VectorSignal, a callable u_d(t) -> array, or a list of Signals/numbers
        """
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def dense(self) -> PiecewisePolynomial:
        ...
    def m(self) -> int:
        ...
    def model(self) -> Model:
        ...
    def n(self) -> int:
        ...
    def q_d(self, t: typing.Any) -> typing.Any:
        ...
    def q_d0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    def stats(self) -> StepStats:
        ...
    def t0(self) -> float:
        ...
    def tf(self) -> float:
        ...
    def u_d(self, t: typing.Any) -> typing.Any:
        ...
    def u_d_signal(self) -> VectorSignal:
        ...
class SolveStats:
    """
    Counts and stored size of a Riccati solve
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('steps', 'rejected', 'rhs_evals', 'jac_evals', 'memory_bytes', 'method')
    def __eq__(self, arg0: SolveStats) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def jac_evals(self) -> int:
        ...
    @property
    def memory_bytes(self) -> int:
        ...
    @property
    def method(self) -> str:
        ...
    @property
    def rejected(self) -> int:
        ...
    @property
    def rhs_evals(self) -> int:
        ...
    @property
    def steps(self) -> int:
        ...
class SymmetricSolution:
    """
    A symmetric-matrix-valued solution X(t) on [t0, tf] (dense output)
    """
    def dense(self) -> PiecewisePolynomial:
        ...
    def derivative(self, t: typing.Any) -> typing.Any:
        ...
    def eigenvalue_bounds(self) -> tuple:
        """
        (m, M) with m I <= X(t) <= M I on [t0, tf] (paper eq. 22)
        """
    def eigenvalue_range(self, times: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex]) -> tuple:
        """
        (smallest, largest) eigenvalue of X over the given times
        """
    def gamma(self) -> float:
        ...
    def n(self) -> int:
        ...
    def stats(self) -> SolveStats:
        ...
    def t0(self) -> float:
        ...
    def tf(self) -> float:
        ...
    def trajectory(self) -> Trajectory:
        ...
    def value(self, t: typing.Any) -> typing.Any:
        """
        X(t): (n, n) for a number, (len(t), n, n) for an array
        """
class RiccatiSolution(SymmetricSolution):
    """
    Z(t) of the GRDE (13) on [t0, tf]
    """
    def Z(self, t: typing.Any) -> typing.Any:
        """
        Z(t): (n, n) for a number, (len(t), n, n) for an array
        """
    def __getstate__(self) -> tuple[Trajectory, float, PiecewisePolynomial, SolveStats]:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def dZdt(self, t: typing.Any) -> typing.Any:
        ...
    def gain(self, t: typing.Any) -> typing.Any:
        """
        K(t) = B' Z(t): (m, n) for a number, (len(t), m, n) for an array
        """
    def m(self) -> int:
        ...
class FilterRiccatiSolution(SymmetricSolution):
    """
    Sigma(t) of the filter Riccati equation (36), A = A_e(t)
    """
    def Sigma(self, t: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[Trajectory, float, PiecewisePolynomial, SolveStats]:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def dSigma_dt(self, t: typing.Any) -> typing.Any:
        ...
class Controller:
    """
    Tracking controller u = control(t, q)
    """
    def __init__(self) -> None:
        ...
    def control(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    def m(self) -> int:
        ...
    def n(self) -> int:
        """
        the state size (0: a Python controller that does not say)
        """
    def name(self) -> str:
        ...
class HinfStateFeedback(Controller):
    """
    u = u_d - kappa B' Z (q - q_d), paper (17)/(18)
    """
    def __init__(self, solution: RiccatiSolution, kappa: typing.Any = ...) -> None:
        ...
    def checked_kappa(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        kappa(t); a ValueError if not > 0
        """
    def kappa(self) -> Signal:
        ...
    def solution(self) -> RiccatiSolution:
        ...
class CascadeGains:
    """
    Gains k, k1, k2 > 0 of the cascade baseline
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('k', 'k1', 'k2')
    def __eq__(self, arg0: CascadeGains) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, k: typing.SupportsFloat | typing.SupportsIndex = 0.2, k1: typing.SupportsFloat | typing.SupportsIndex = 2.0, k2: typing.SupportsFloat | typing.SupportsIndex = 3.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def k(self) -> float:
        ...
    @k.setter
    def k(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def k1(self) -> float:
        ...
    @k1.setter
    def k1(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def k2(self) -> float:
        ...
    @k2.setter
    def k2(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class CascadeController(Controller):
    """
    Cascaded tracking baseline for the ship (Lefeber, Pettersen, Nijmeijer type)
    """
    def __init__(self, trajectory: Trajectory, gains: CascadeGains = ...) -> None:
        ...
    def gains(self) -> CascadeGains:
        ...
class Disturbance:
    """
    w(t, q) = signals(t) [+ gamma^-2 D' Z q_e, the worst case of paper eq. (16)]
    """
    @typing.overload
    def __init__(self, signals: VectorSignal) -> None:
        ...
    @typing.overload
    def __init__(self, signals: VectorSignal, design: RiccatiSolution) -> None:
        """
        signals plus the worst-case disturbance of the design (a finite gamma)
        """
    def design(self) -> RiccatiSolution:
        ...
    def dim(self) -> int:
        ...
    def eval(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        w at time t for the actual state q (used by the worst case only)
        """
    def signals(self) -> VectorSignal:
        ...
    def worst_case(self) -> bool:
        ...
class EstimatorSeries:
    """
    The estimator's series of an output-feedback run (paper §4)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('q_hat', 'y', 'sigma_min_eig', 'sigma_max_eig', 'rho_sigma_z', 'coupling_violation_t')
    def __eq__(self, arg0: EstimatorSeries) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def coupling_violation_t(self) -> float:
        ...
    @property
    def q_hat(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @property
    def rho_sigma_z(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    @property
    def sigma_max_eig(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    @property
    def sigma_min_eig(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    @property
    def y(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
class SimulationResult:
    """
    Time series on the output grid, one row per time
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('t', 'q', 'q_d', 'u', 'u_d', 'w', 'estimator', 'status', 'status_message', 'heading_index', 'integrator', 'stats')
    def __eq__(self, arg0: SimulationResult) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def q_e(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        q - q_d, the heading component wrapped to (-pi, pi]
        """
    @property
    def estimator(self) -> EstimatorSeries:
        """
        the estimator's series (output feedback), else None
        """
    @property
    def heading_index(self) -> int:
        ...
    @property
    def integrator(self) -> str:
        ...
    @property
    def q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @property
    def q_d(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @property
    def stats(self) -> SolveStats:
        ...
    @property
    def status(self) -> RunStatus:
        ...
    @property
    def status_message(self) -> str:
        ...
    @property
    def t(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    @property
    def u(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @property
    def u_d(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @property
    def w(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
class OutputFeedbackProblem:
    """
    The output-feedback problem: design, measurement noise, filter weights (paper §4); noise: standard normal samples, one row per hold interval
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('design', 'sigma', 'sample_period', 'noise', 'N', 'Sigma0', 'Q')
    design: RiccatiSolution
    def __eq__(self, arg0: OutputFeedbackProblem) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, design: RiccatiSolution = None, sigma: typing.SupportsFloat | typing.SupportsIndex = 0.0, sample_period: typing.SupportsFloat | typing.SupportsIndex = 0.01, noise: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ..., N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ..., Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ..., Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def N(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @N.setter
    def N(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @Q.setter
    def Q(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Sigma0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @Sigma0.setter
    def Sigma0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def noise(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @noise.setter
    def noise(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def sample_period(self) -> float:
        ...
    @sample_period.setter
    def sample_period(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def sigma(self) -> float:
        ...
    @sigma.setter
    def sigma(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class OutputFeedbackOptions:
    """
    Choices of the output-feedback loop (paper §4)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('filter_A', 'on_coupling_violation', 'sigma_eigenvalues')
    sigma_eigenvalues: bool
    def __eq__(self, arg0: OutputFeedbackOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, filter_A: FilterLinearization | str = FilterLinearization.estimate, on_coupling_violation: CouplingPolicy | str = CouplingPolicy.error, sigma_eigenvalues: bool = True) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def filter_A(self) -> FilterLinearization:
        ...
    @filter_A.setter
    def filter_A(self, arg1: FilterLinearization | str) -> None:
        ...
    @property
    def on_coupling_violation(self) -> CouplingPolicy:
        ...
    @on_coupling_violation.setter
    def on_coupling_violation(self, arg1: CouplingPolicy | str) -> None:
        ...
class MetricDefinition:
    """
    One metric of a run: name, label, unit, definition
    """
    def __repr__(self) -> str:
        ...
    @property
    def definition(self) -> str:
        ...
    @property
    def label(self) -> str:
        ...
    @property
    def name(self) -> str:
        """
        its key in the results file and Metrics' property
        """
    @property
    def unit(self) -> str:
        ...
class Metrics:
    """
    Metrics of a closed-loop run (metric_table() defines each)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: Metrics) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def control_error_l2(self) -> float:
        """
        sqrt(integral of |u - u_d|^2)
        """
    @property
    def control_l2(self) -> float:
        """
        sqrt(integral of |u|^2)
        """
    @property
    def disturbance_l2(self) -> float:
        """
        sqrt(integral of |w|^2) over every applied channel (the noise channels when sigma > 0)
        """
    @property
    def final_heading_error(self) -> float:
        """
        |wrap(psi - psi_d)| at tf
        """
    @property
    def final_position_error(self) -> float:
        """
        |p - p_d| at tf
        """
    @property
    def l2_gain(self) -> float:
        """
        sqrt(integral of |q - q_d|_Q^2 + |u - u_d|^2) / disturbance_l2 (includes the response to the initial error)
        """
    @property
    def max_position_error(self) -> float:
        """
        max over the grid of |p - p_d|
        """
    @property
    def max_rho_sigma_z(self) -> float:
        """
        max over the grid of the spectral radius of Sigma Z (output feedback; below gamma^2)
        """
    @property
    def rms_estimation_error_last_half(self) -> float:
        """
        sqrt(mean over the last half of |q_hat - (q - q_d)|^2) (output feedback)
        """
    @property
    def rms_heading_error_last_half(self) -> float:
        """
        sqrt(mean over the last half of wrap(psi - psi_d)^2)
        """
    @property
    def rms_position_error_last_half(self) -> float:
        """
        sqrt(mean over the last half of |p - p_d|^2)
        """
class GammaStarOptions:
    """
    Options of the gamma* search. threads: gammas evaluated in parallel per round (one for a model implemented in Python, whose calls hold the GIL)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('lower', 'upper', 'rtol', 'max_evaluations', 'threads', 'solver')
    solver: SolverOptions
    def __eq__(self, arg0: GammaStarOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, lower: typing.SupportsFloat | typing.SupportsIndex = 0.0, upper: typing.SupportsFloat | typing.SupportsIndex = 0.0, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-07, max_evaluations: typing.SupportsInt | typing.SupportsIndex = 200, threads: typing.SupportsInt | typing.SupportsIndex = 2, solver: SolverOptions = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def lower(self) -> float:
        ...
    @lower.setter
    def lower(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_evaluations(self) -> int:
        ...
    @max_evaluations.setter
    def max_evaluations(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def rtol(self) -> float:
        ...
    @rtol.setter
    def rtol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def threads(self) -> int:
        ...
    @threads.setter
    def threads(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def upper(self) -> float:
        ...
    @upper.setter
    def upper(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class GammaTrial:
    """
    One gamma tried by the gamma* search
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('gamma', 'passed', 't_escape', 'condition')
    def __eq__(self, arg0: GammaTrial) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def condition(self) -> GammaCondition:
        ...
    @property
    def gamma(self) -> float:
        ...
    @property
    def passed(self) -> bool:
        ...
    @property
    def t_escape(self) -> float:
        ...
class GammaStarResult:
    """
    gamma*, the final bracket and every gamma tried
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('gamma_star', 'lower', 'upper', 't_escape_lower', 'binding', 'converged', 'trials')
    def __eq__(self, arg0: GammaStarResult) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def binding(self) -> GammaCondition:
        ...
    @property
    def converged(self) -> bool:
        ...
    @property
    def gamma_star(self) -> float:
        ...
    @property
    def lower(self) -> float:
        ...
    @property
    def t_escape_lower(self) -> float:
        ...
    @property
    def trials(self) -> list[GammaTrial]:
        ...
    @property
    def upper(self) -> float:
        ...
class Certificates:
    """
    The stability certificates of paper §3 (eqs. 22-24)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('m', 'M', 'kappa_min', 'p_min', 'p_min_t', 'remainder_L', 'remainder_method', 'remainder_is_bound', 'epsilon', 'epsilon_t', 'attraction_radius', 'decay_rate')
    def __eq__(self, arg0: Certificates) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def M(self) -> float:
        ...
    @property
    def attraction_radius(self) -> float:
        ...
    @property
    def decay_rate(self) -> float:
        ...
    @property
    def epsilon(self) -> float:
        ...
    @property
    def epsilon_t(self) -> float:
        ...
    @property
    def kappa_min(self) -> float:
        ...
    @property
    def m(self) -> float:
        ...
    @property
    def p_min(self) -> float:
        ...
    @property
    def p_min_t(self) -> float:
        ...
    @property
    def remainder_L(self) -> float:
        ...
    @property
    def remainder_is_bound(self) -> bool:
        ...
    @property
    def remainder_method(self) -> str:
        ...
class Law:
    """
    The tracking law of a scenario (scenario.hpp)
    
    Members:
    
      hinf
    
      lqr
    
      cascade
    """
    __members__: typing.ClassVar[dict[str, Law]]
    cascade: typing.ClassVar[Law]
    hinf: typing.ClassVar[Law]
    lqr: typing.ClassVar[Law]
    def __eq__(self: Law | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: Law | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: Law | str) -> int:
        ...
    def __ne__(self: Law | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class RunOutcome:
    """
    How a run of a study ended (study.hpp)
    
    Members:
    
      completed
    
      diverged
    
      conjugate_point
    
      coupling_violation
    
      solver_failure
    
      invalid_input
    
      failed
    """
    __members__: typing.ClassVar[dict[str, RunOutcome]]
    completed: typing.ClassVar[RunOutcome]
    conjugate_point: typing.ClassVar[RunOutcome]
    coupling_violation: typing.ClassVar[RunOutcome]
    diverged: typing.ClassVar[RunOutcome]
    failed: typing.ClassVar[RunOutcome]
    invalid_input: typing.ClassVar[RunOutcome]
    solver_failure: typing.ClassVar[RunOutcome]
    def __eq__(self: RunOutcome | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: RunOutcome | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        ...
    def __int__(self: RunOutcome | str) -> int:
        ...
    def __ne__(self: RunOutcome | str, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class MeasurementSpec:
    """
    [measurement] of a scenario (paper §4)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('sigma', 'sample_period', 'seed', 'N', 'Q0', 'eta', 'filter_A', 'on_coupling_violation')
    def __eq__(self, arg0: MeasurementSpec) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, sigma: typing.SupportsFloat | typing.SupportsIndex = 0.0, sample_period: typing.SupportsFloat | typing.SupportsIndex = 0.01, seed: typing.SupportsInt | typing.SupportsIndex = 0, N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ..., Q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] = ..., eta: typing.SupportsFloat | typing.SupportsIndex = 1.0, filter_A: FilterLinearization | str = FilterLinearization.estimate, on_coupling_violation: CouplingPolicy | str = CouplingPolicy.error) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def N(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @N.setter
    def N(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Q0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @Q0.setter
    def Q0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def eta(self) -> float:
        ...
    @eta.setter
    def eta(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def filter_A(self) -> FilterLinearization:
        ...
    @filter_A.setter
    def filter_A(self, arg1: FilterLinearization | str) -> None:
        ...
    @property
    def on_coupling_violation(self) -> CouplingPolicy:
        ...
    @on_coupling_violation.setter
    def on_coupling_violation(self, arg1: CouplingPolicy | str) -> None:
        ...
    @property
    def sample_period(self) -> float:
        ...
    @sample_period.setter
    def sample_period(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def seed(self) -> int:
        ...
    @seed.setter
    def seed(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def sigma(self) -> float:
        ...
    @sigma.setter
    def sigma(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Scenario:
    """
    Everything one run needs (docs/scenarios.md).
    Pickles as its scenario file (scenario_toml) and solver.escape_norm, which the file does not hold;
    a scenario whose model or signals are implemented in Python does not pickle (TypeError).
    """
    cascade: CascadeGains
    description: str
    measurement: MeasurementSpec | None
    model: Model
    name: str
    solver: SolverOptions
    worst_case: bool
    def __copy__(self) -> Scenario:
        ...
    def __getstate__(self) -> tuple[str, float]:
        ...
    def __init__(self) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def copy(self) -> Scenario:
        """
        an independent copy (signals and model shared)
        """
    def resolved(self) -> Scenario:
        ...
    def simulation_options(self) -> SimulationOptions:
        ...
    def validate(self) -> None:
        ...
    @property
    def Q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @Q.setter
    def Q(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Qf(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @Qf.setter
    def Qf(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def desired_q0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    @desired_q0.setter
    def desired_q0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        ...
    @property
    def desired_u(self) -> VectorSignal:
        ...
    @desired_u.setter
    def desired_u(self, arg1: typing.Any) -> None:
        ...
    @property
    def disturbance(self) -> VectorSignal:
        ...
    @disturbance.setter
    def disturbance(self, arg1: typing.Any) -> None:
        ...
    @property
    def divergence_factor(self) -> float:
        ...
    @divergence_factor.setter
    def divergence_factor(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def gamma(self) -> float:
        ...
    @gamma.setter
    def gamma(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def initial_q0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        ...
    @initial_q0.setter
    def initial_q0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        ...
    @property
    def kappa(self) -> Signal:
        ...
    @kappa.setter
    def kappa(self, arg1: typing.Any) -> None:
        ...
    @property
    def law(self) -> Law:
        ...
    @law.setter
    def law(self, arg1: Law | str) -> None:
        ...
    @property
    def output_dt(self) -> float:
        ...
    @output_dt.setter
    def output_dt(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def plant(self) -> Model | None:
        """
        [plant]: the vehicle the closed loop integrates, or None (the design model)
        """
    @plant.setter
    def plant(self, arg1: Model | None) -> None:
        ...
    @property
    def t0(self) -> float:
        ...
    @t0.setter
    def t0(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def tf(self) -> float:
        ...
    @tf.setter
    def tf(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Timing:
    """
    Wall-clock seconds of a run
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('design', 'simulate', 'analysis', 'total')
    def __eq__(self, arg0: Timing) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def analysis(self) -> float:
        ...
    @property
    def design(self) -> float:
        ...
    @property
    def simulate(self) -> float:
        ...
    @property
    def total(self) -> float:
        ...
class RunResult:
    """
    Result of run_scenario (gamma_star may be set afterwards, as hinf-sim does, for the results file); == is not defined (its trajectory and design are shared objects)
    """
    __match_args__: typing.ClassVar[tuple] = ('scenario_name', 'law', 'output_feedback', 'gamma', 'trajectory', 'plant', 'solution', 'Z0', 'Z_min_eig', 'Z_max_eig', 'gamma_star', 'simulation', 'metrics', 'timing')
    def __getstate__(self) -> tuple:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def to_csv(self) -> str:
        """
        The time series on the output grid (results_csv)
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = 2) -> str:
        """
        The results file (results_json)
        """
    @property
    def Z0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        ...
    @property
    def Z_max_eig(self) -> float:
        ...
    @property
    def Z_min_eig(self) -> float:
        ...
    @property
    def gamma(self) -> float:
        ...
    @property
    def gamma_star(self) -> float | None:
        ...
    @gamma_star.setter
    def gamma_star(self, arg0: typing.SupportsFloat | typing.SupportsIndex | None) -> None:
        ...
    @property
    def law(self) -> Law:
        ...
    @property
    def metrics(self) -> Metrics:
        ...
    @property
    def output_feedback(self) -> bool:
        ...
    @property
    def plant(self) -> Model | None:
        """
        the scenario's [plant], the vehicle the closed loop integrated; None: the design model
        """
    @property
    def scenario_name(self) -> str:
        ...
    @property
    def simulation(self) -> SimulationResult:
        ...
    @property
    def solution(self) -> RiccatiSolution:
        ...
    @property
    def timing(self) -> Timing:
        ...
    @property
    def trajectory(self) -> Trajectory:
        ...
class StudyOptions:
    """
    Options of run_scenarios. threads: worker threads (0: the hardware's; never more than runs; one when a model or signal is implemented in Python); share_designs: compute each distinct design (trajectory and Riccati solutions) once
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('threads', 'share_designs')
    share_designs: bool
    def __eq__(self, arg0: StudyOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, threads: typing.SupportsInt | typing.SupportsIndex = 0, share_designs: bool = True) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def threads(self) -> int:
        ...
    @threads.setter
    def threads(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
class StudyRun:
    """
    One row of run_scenarios: status (its name: 'completed', 'diverged', 'conjugate_point', 'coupling_violation', 'solver_failure', 'invalid_input', 'failed'; outcome is the RunOutcome), reason (empty when completed), metrics (as RunResult.metrics; NaN when the run failed), gamma, law, output_feedback, design_seconds, simulate_seconds, design (runs with the same number shared one design; -1: none was made)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('status', 'reason', 'metrics', 'gamma', 'law', 'output_feedback', 'design_seconds', 'simulate_seconds', 'design')
    def __eq__(self, arg0: StudyRun) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def design(self) -> int:
        ...
    @property
    def design_seconds(self) -> float:
        ...
    @property
    def gamma(self) -> float:
        ...
    @property
    def law(self) -> Law:
        ...
    @property
    def metrics(self) -> Metrics:
        ...
    @property
    def outcome(self) -> RunOutcome:
        """
        how the run ended
        """
    @property
    def output_feedback(self) -> bool:
        ...
    @property
    def reason(self) -> str:
        ...
    @property
    def simulate_seconds(self) -> float:
        ...
    @property
    def status(self) -> str:
        """
        how the run ended, by name (outcome: the RunOutcome)
        """
def certify(Z: RiccatiSolution, kappa: typing.Any, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> Certificates:
    """
    The certificates of paper §3 for a design Z (its gamma), the gain scaling kappa(t) and the weight Q
    """
def check_model_structure(structure: ModelStructure) -> None:
    """
    ValueError naming the first fault of a model's structure (names per state, indices in range)
    """
def compute_metrics(model: Model, run: SimulationResult, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> Metrics:
    ...
def filter_escape_time(trajectory: Trajectory, N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: SolverOptions = ...) -> float:
    """
    Time of the first escape of the filter Riccati equation (36) on [t0, tf], NaN if none
    """
def gamma_star(trajectory: Trajectory, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: GammaStarOptions = ...) -> GammaStarResult:
    """
    gamma* (paper eq. 14): the smallest gamma without a conjugate point of the GRDE on [t0, tf]
    """
def gamma_star_output_feedback(trajectory: Trajectory, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: GammaStarOptions = ...) -> GammaStarResult:
    """
    The smallest gamma for output feedback: GRDE, filter (36) with A_e and rho(Sigma Z) < gamma^2
    """
def grde_escape_time(trajectory: Trajectory, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, options: SolverOptions = ...) -> float:
    """
    Time of the first conjugate point of the GRDE on [t0, tf] (integrating backward), NaN if none
    """
def l2_norm(t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], series: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> float:
    """
    sqrt of the trapezoid integral of the squared row norms of series over times t
    """
def load_scenario_toml(path: str) -> Scenario:
    """
    Reads a scenario file (parse_scenario_toml)
    """
def max_rho_sigma_z(Z: RiccatiSolution, Sigma: FilterRiccatiSolution) -> tuple[float, float]:
    """
    (max over [t0, tf] of rho(Sigma Z), where)
    """
def metric_table() -> list[MetricDefinition]:
    """
    The metrics of a run, in the order of the results file
    """
def needs_planning_toml(text: str, source: str) -> bool:
    """
    Whether a scenario document's [desired] gives waypoints, a path or plan options (parsed with every guard of the reader)
    """
def noise_sample_count(t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex, period: typing.SupportsFloat | typing.SupportsIndex) -> int:
    ...
def output_count(t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex, dt: typing.SupportsFloat | typing.SupportsIndex) -> int:
    ...
def output_grid(t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex, dt: typing.SupportsFloat | typing.SupportsIndex) -> list[float]:
    ...
def overshoot_warning(signal: Signal, name: str) -> str:
    """
    The warning for a table whose interpolant overshoots the range of its values, naming it `name`; '' otherwise
    """
def parse_model_toml(text: str, source: str) -> Model:
    """
    The model of a document's [model] section, read as parse_scenario_toml reads it
    """
def parse_scenario_toml(text: str, source: str) -> Scenario:
    """
    The one scenario reader (the one hinf-sim uses): same checks, same messages
    """
def parse_signal_toml(text: str, key: str, source: str) -> Signal:
    """
    A Signal from a TOML document whose one key is `key` (as in a scenario)
    """
def results_csv(result: RunResult) -> str:
    """
    The time series on the output grid (CSV, one row per time)
    """
def results_json(result: RunResult, indent: typing.SupportsInt | typing.SupportsIndex = 2) -> str:
    """
    The results file of scenarios.md (JSON; non-finite numbers as null)
    """
def run_scenario(scenario: Scenario) -> RunResult:
    """
    Run a scenario
    """
def run_scenario_with_noise(scenario: Scenario, noise: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> RunResult:
    """
    Run a scenario with [measurement] on the given noise samples (one row per hold interval, one column per measured output) instead of the seeded ones, so that a run can be replayed exactly
    """
def run_scenarios(scenarios: collections.abc.Sequence[Scenario], options: StudyOptions = ..., progress: collections.abc.Callable[[int, int], None] | None = None) -> list[StudyRun]:
    """
    Runs every scenario (in parallel, designs shared; study.hpp) and returns one StudyRun per scenario, in order: each row is what run_scenario gives for that scenario alone, and a run that fails is a row with its status and reason. progress(done, total), if given, is called on this thread about every 0.1 s and at the end; an exception it raises (or Ctrl-C) stops the study and is raised here
    """
def scenario_certificates(scenario: Scenario) -> Certificates:
    """
    The certificates of paper §3 for a scenario's design
    """
def scenario_gamma_star(scenario: Scenario, options: GammaStarOptions = ...) -> GammaStarResult:
    """
    gamma* of a scenario's state-feedback design
    """
def scenario_gamma_star_output_feedback(scenario: Scenario, options: GammaStarOptions = ...) -> GammaStarResult:
    """
    The smallest gamma of a scenario's output-feedback design
    """
def scenario_noise(scenario: Scenario) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
    """
    The seeded standard normal noise samples of a scenario with [measurement]
    """
def scenario_toml(scenario: Scenario) -> str:
    """
    The scenario as a scenario file that reads back to an equal scenario
    """
def scenario_warnings(scenario: Scenario) -> list[str]:
    """
    What is legal in a scenario but probably not meant (a table whose interpolation overshoots its values), one message per finding naming the key
    """
def set_python_model_hook(make_model: collections.abc.Callable) -> None:
    """
    Registers make_model(callable: str, source: str) -> Model, the maker of the models that a scenario file names with [model] kind = "python" (hinf_cpp.scenario registers it when imported)
    """
def simulate_output_feedback(problem: OutputFeedbackProblem, controller: Controller, disturbance: typing.Any, q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], options: OutputFeedbackOptions = ..., simulation: SimulationOptions = ..., plant: Model | None = None) -> SimulationResult:
    """
    Output-feedback closed loop (paper 34-36): filter and estimator of the problem's design, control by `controller` at the estimated state; disturbance as in simulate_state_feedback; plant: the vehicle integrated (None: the design's model)
    """
def simulate_state_feedback(trajectory: Trajectory, controller: Controller, disturbance: typing.Any, q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], options: SimulationOptions = ..., plant: Model | None = None) -> SimulationResult:
    """
    Closed loop under state feedback (paper eq. 7); disturbance: a Disturbance, a VectorSignal, a callable w(t) -> array, a list of Signals/numbers, or None (zero); plant: the vehicle integrated (None: the trajectory's model)
    """
def solve_filter_riccati(trajectory: Trajectory, N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: SolverOptions = ...) -> FilterRiccatiSolution:
    """
    Solve the filter Riccati equation (36) forward from Sigma(t0) = Sigma0 with A = A_e(t)
    """
def solve_grde(trajectory: Trajectory, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, options: SolverOptions = ...) -> RiccatiSolution:
    """
    Solve the GRDE (13) backward from Z(tf) = Qf; raises ConjugatePointError when gamma <= gamma*
    """
def standard_normal_samples(seed: typing.SupportsInt | typing.SupportsIndex, count: typing.SupportsInt | typing.SupportsIndex, channels: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
    """
    Seeded standard normal samples, one row per sample (mt19937_64, polar method)
    """
def wrap_angle(angle: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    the angle wrapped to (-pi, pi]
    """
__version__: str = '0.2.0'
