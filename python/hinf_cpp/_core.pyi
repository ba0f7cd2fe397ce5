"""
hinf_cpp core: H-infinity tracking control of nonlinear underactuated vehicles
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['ActuatorLimits', 'Auv', 'AuvParameters', 'BacksteppingController', 'BacksteppingGains', 'CascadeController', 'CascadeGains', 'Certificates', 'ConjugatePointError', 'Controller', 'CouplingConditionError', 'CouplingPolicy', 'DesiredStates', 'DiscreteDesign', 'DiscreteOutputFeedback', 'Disturbance', 'EstimatorSeries', 'FilterLinearization', 'FilterRiccatiSolution', 'FleetModel', 'FossenVessel', 'FossenVesselParameters', 'GammaCondition', 'GammaStarOptions', 'GammaStarResult', 'GammaTrial', 'GeneratedFunction', 'GeneratedModel', 'Harmonic', 'HinfError', 'HinfStateFeedback', 'HorizonWindow', 'Hovercraft', 'HovercraftParameters', 'Interpolation', 'Law', 'LinearModel', 'MeasurementSpec', 'MeasurementUpdate', 'MeasurementUse', 'Method', 'MetricDefinition', 'Metrics', 'Model', 'ModelStructure', 'NewtonSystems', 'OnlineController', 'OnlineCounts', 'OnlineFilter', 'OnlineOptions', 'OutputFeedbackOptions', 'OutputFeedbackProblem', 'PathChange', 'PiecewisePolynomial', 'PlanarVtol', 'PlanarVtolParameters', 'RecedingHorizon', 'RecedingHorizonOptions', 'RecedingHorizonReport', 'RecedingOnlineController', 'RecedingOnlineStatus', 'RiccatiSolution', 'RunOutcome', 'RunResult', 'RunStatus', 'SampledDesign', 'SampledLaw', 'SampledLinearization', 'SampledLoopOptions', 'SamplingSpec', 'Scenario', 'ShipModel', 'ShipParameters', 'Signal', 'SimulationOptions', 'SimulationResult', 'SolveStats', 'SolverError', 'SolverOptions', 'StepReport', 'StepStats', 'StepStatus', 'StudyOptions', 'StudyRun', 'SymmetricSolution', 'TerminalWeight', 'Timing', 'Trajectory', 'TrajectoryOptions', 'VectorSignal', 'WindowGammaStar', 'certify', 'check_model_structure', 'check_scenario_toml', 'clear_interrupt', 'code_trusted_by_environment', 'compute_metrics', 'controller_escape_time', 'controller_gain', 'discrete_conjugate_time', 'filter_escape_time', 'gamma_star', 'gamma_star_discrete', 'gamma_star_discrete_output_feedback', 'gamma_star_output_feedback', 'grde_escape_time', 'interrupt_requested', 'l2_norm', 'law_escape_time', 'law_gain', 'load_scenario_toml', 'max_rho_sigma_z', 'metric_table', 'needs_planning_toml', 'noise_sample_count', 'output_count', 'output_grid', 'overshoot_warning', 'parse_model_toml', 'parse_scenario_toml', 'parse_signal_toml', 'receding_horizon_gamma_star', 'request_interrupt', 'results_csv', 'results_json', 'run_scenario', 'run_scenario_with_noise', 'run_scenarios', 'scenario_certificates', 'scenario_gamma_star', 'scenario_gamma_star_output_feedback', 'scenario_noise', 'scenario_receding_horizon', 'scenario_toml', 'scenario_warnings', 'set_python_model_hook', 'simulate_output_feedback', 'simulate_receding_horizon', 'simulate_sampled', 'simulate_sampled_receding_horizon', 'simulate_state_feedback', 'solve_controller_riccati', 'solve_discrete_game', 'solve_discrete_output_feedback', 'solve_filter_riccati', 'solve_game_are', 'solve_grde', 'solve_law_riccati', 'standard_normal_samples', 'wrap_angle']
class HinfError(RuntimeError):
    """
    The exceptions of hinf_cpp.
    
      InputError             bad input: wrong shape, NaN, non-symmetric or indefinite weight,
                             gamma <= 0, tf <= t0, unknown scenario key ...   (Python: ValueError)
      SolverError            an integrator failed (step size too small, too many steps,
                             non-finite values); carries the time and the solver's flag.
      ConjugatePointError    the GRDE (paper eq. 13) escaped to infinity: gamma is at or below
                             gamma* (eq. 14) for this trajectory and horizon; carries the time.
      CouplingConditionError the output-feedback coupling condition rho(Sigma Z) < gamma^2
                             (paper §4) failed; carries the time and rho.
    SolverError, ConjugatePointError and CouplingConditionError derive from HinfError
    (Python: hinf_cpp.HinfError, a RuntimeError).
    
    Examples
    --------
    A bad input is a ValueError; a numerical failure is a HinfError subclass:
    
    >>> issubclass(hc.SolverError, hc.HinfError), issubclass(hc.HinfError, RuntimeError)
    (True, True)
    >>> try:
    ...     hc.SolverOptions(rtol=2.0)
    ... except ValueError as error:
    ...     print(error)
    solver rtol must be in [1e-14, 1e-3], got 2
    """
class SolverError(HinfError):
    """
    An integrator failed: the step size became too small, too many steps, non-finite values.
    
    Attributes
    ----------
    t : float
        The time (s) at which it failed.
    flag : str
        The integrator's reason (CVODE's flag name, or the project's integrators' own).
    
    Examples
    --------
    >>> model = hc.LinearModel(np.array([[1.0]]), np.array([[1.0]]), np.array([[1.0]]))
    >>> trajectory = hc.Trajectory(model, [1.0], [0.0], 0.0, 50.0)
    >>> try:
    ...     hc.solve_grde(trajectory, np.eye(1), np.eye(1), 5.0, hc.SolverOptions(method="erk", max_steps=3))
    ... except hc.SolverError as error:
    ...     print(type(error).__name__, error.flag)
    SolverError ...
    """
class ConjugatePointError(HinfError):
    """
    The GRDE (paper eq. 13) escaped to infinity: gamma is at or below gamma* (eq. 14) for this
    trajectory and horizon. Raise gamma (hc.gamma_star finds the smallest one that passes).
    
    Attributes
    ----------
    t_escape : float
        The estimated time (s) at which Z(t) escapes, integrating backward from tf.
    gamma : float
        The gamma that failed.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.gamma = 1.2                              # below gamma* = 1.335
    >>> try:
    ...     hc.run_scenario(scenario)
    ... except hc.ConjugatePointError as error:
    ...     print(error.gamma, round(error.t_escape, 1))
    1.2 ...
    """
class CouplingConditionError(HinfError):
    """
    The output-feedback coupling condition rho(Sigma Z) < gamma^2 (paper §4) failed.
    
    Attributes
    ----------
    t : float
        The time (s) of the first violation.
    rho : float
        rho(Sigma(t) Z(t)) there.
    gamma : float
        The design's gamma.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    >>> scenario.gamma = 4.0                              # coupling-bound below 4.59
    >>> try:
    ...     hc.run_scenario(scenario)
    ... except hc.CouplingConditionError as error:
    ...     print(error.t, error.rho > error.gamma ** 2)
    0.0 True
    """
class Method:
    """
    The integrator of the Riccati equations (13) and (36) and of the closed loops
    (SolverOptions::method; the desired trajectory is always integrated by Dormand-Prince).
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    auto
        Dormand-Prince while the problem is not stiff; once its stiffness test fires (15
        accepted steps in a row limited by stability), BDF from there on (the default)
    bdf
        CVODE BDF with Newton iteration: for stiff problems. The Riccati equations solve
        the Newton systems as Lyapunov equations (O(n^3)) beyond small n, else densely
    adams
        CVODE Adams-Moulton with fixed-point iteration: non-stiff, high order
    erk
        explicit Dormand-Prince 5(4) with its 4th-order dense output: non-stiff
    
    Examples
    --------
    >>> hc.SolverOptions(method="erk").method
    <Method.erk: 3>
    >>> list(hc.Method.__members__), hc.Method("bdf") == hc.Method.bdf
    (['auto', 'bdf', 'adams', 'erk'], True)
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    How BDF solves the Newton systems of the Riccati equations (13) and (36).
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    auto
        densely up to kDenseNewtonMaxStates states, as Lyapunov equations beyond
    dense
        the packed Jacobian (n(n+1)/2 unknowns) and LU: O(n^6) per factorization
    lyapunov
        Schur form and Bartels-Stewart: O(n^3) per factorization and per solve
    
    Examples
    --------
    >>> hc.SolverOptions(method="bdf", newton_systems="lyapunov").newton_systems
    <NewtonSystems.lyapunov: 2>
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    How a table (t_i, v_i) is interpolated between its points (docs/scenarios.md).
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    pchip
        piecewise cubic Hermite with the slopes of Fritsch and Carlson, weighted harmonic
        mean of Fritsch and Butland (as SciPy's PchipInterpolator): C1, and on each
        interval between v_i and v_{i+1}: no overshoot (the default)
    linear
        straight lines between the points: C0, no overshoot
    hold
        zero-order hold: the value of the last point at or before t; no overshoot
    cubic
        natural cubic spline (second derivative zero at both ends): C2, but it can leave
        the range of the values (a step rings on both sides)
    
    Examples
    --------
    >>> step = hc.Signal.table([0.0, 1.0, 2.0], [0.0, 1.0, 0.0], "linear")
    >>> step.interpolation(), step(0.5)
    (<Interpolation.linear: 1>, 0.5)
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    One term of a harmonic Signal: amplitude sin(omega t + phase), or the cosine.
    
    Parameters
    ----------
    amplitude : float, default 0.0
        in the unit of the signal
    omega : float, default 0.0
        rad/s
    phase : float, default 0.0
        rad
    cosine : bool, default False
        false: sin(omega t + phase), true: cos(omega t + phase)
    
    Examples
    --------
    >>> term = hc.Harmonic(amplitude=0.3, omega=0.2)
    >>> term
    Harmonic(amplitude=0.3, omega=0.2, phase=0.0, cosine=False)
    >>> round(hc.Signal(0.0, [term])(np.pi / 0.4), 6)         # 0.3 sin(pi / 2)
    0.3
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('amplitude', 'omega', 'phase', 'cosine')
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
        """
        in the unit of the signal
        """
    @amplitude.setter
    def amplitude(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def cosine(self) -> bool:
        """
        false: sin(omega t + phase), true: cos(omega t + phase)
        """
    @cosine.setter
    def cosine(self, arg0: bool) -> None:
        ...
    @property
    def omega(self) -> float:
        """
        rad/s
        """
    @omega.setter
    def omega(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def phase(self) -> float:
        """
        rad
        """
    @phase.setter
    def phase(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Signal:
    """
    A scalar signal of absolute time t (s): offset + harmonics, or a table (t_i, v_i)
    interpolated between its points. A Signal is a value: it keeps no state, and may be
    evaluated from several threads at once.
    
    Wherever a Signal is expected, a number is taken too (a constant).
    
    Parameters
    ----------
    constant : float
        ``Signal(constant)``: the constant signal. ``Signal()`` is zero.
    offset : float
        ``Signal(offset, harmonics)``: offset + the sum of the harmonics, in the signal's unit.
    harmonics : list of Harmonic
        The terms added to `offset`.
    
    Raises
    ------
    ValueError
        A constant, offset or harmonic that is not finite.
    
    See Also
    --------
    Signal.table : a signal interpolated between points.
    
    Examples
    --------
    >>> u2 = hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])
    >>> u2(np.array([0.0, 2.5])).round(4)                       # 0.3 sin(0.2 t)
    array([0.    , 0.1438])
    >>> u2.describe(), hc.Signal(1.0).is_constant()
    ('0 + 0.3 sin(0.2 t + 0)', True)
    """
    @staticmethod
    def table(t: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], values: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], interpolation: Interpolation | str = Interpolation.pchip) -> Signal:
        """
        The table (t_i, v_i), interpolated as `interpolation` says; at least two points, strictly
        increasing t.
        
        Parameters
        ----------
        t : array_like, shape (k,)
            The times t_i (s), k >= 2, finite and strictly increasing.
        values : array_like, shape (k,)
            The values v_i, finite.
        interpolation : Interpolation or str, default "pchip"
            "pchip", "linear", "hold" or "cubic".
        
        Returns
        -------
        Signal
        
        Raises
        ------
        ValueError
            Fewer than two points, times not strictly increasing, a value not finite, lengths that differ.
        
        Warns
        -----
        UserWarning
            When the "cubic" interpolant overshoots the range of the values (see overshoot()).
        
        Examples
        --------
        >>> ramp = hc.Signal.table([0.0, 10.0, 20.0], [0.0, 1.0, 1.0])
        >>> ramp(np.array([5.0, 15.0])), ramp.is_table()
        (array([0.5, 1. ]), True)
        """
    def __call__(self, t: typing.Any) -> typing.Any:
        """
        The value at t (s): a float for a number, an array of shape (k,) for a 1-D array of k times. A table outside [t_first, t_last] is a ValueError.
        """
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
        """
        The definition in one line: "1 + 0.3 sin(0.2 t + 0)", "table of 5 points on [0, 4], pchip".
        """
    def harmonics(self) -> list[Harmonic]:
        """
        The harmonics of offset + harmonics (none for a table).
        """
    def interpolation(self) -> Interpolation:
        """
        How a table is interpolated (Pchip for offset + harmonics, where it means nothing).
        """
    def is_constant(self) -> bool:
        """
        True for a constant: no harmonics and not a table.
        """
    def is_table(self) -> bool:
        """
        True for a table, false for offset + harmonics.
        """
    def minimum(self, t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex) -> tuple[float, float]:
        """
        The smallest value on [t0, tf] and where it is taken: exact for constants and tables
        (cubic pieces); for harmonics, sampled at 64 points per period of the fastest term and
        refined by golden-section search.
        
        Returns (value, t), t in seconds.
        """
    def offset(self) -> float:
        """
        The offset of offset + harmonics (0 for a table).
        """
    def overshoot(self) -> tuple[float, float]:
        """
        How far a table's interpolant leaves the range [min v_i, max v_i] of its values on
        [t_first, t_last], and where (exact: the extremes of each cubic piece); (0, t_first) when
        it stays inside, and (0, 0) for a signal that is not a table. Only Interpolation::Cubic
        can overshoot.
        
        Returns (amount, t), t in seconds.
        """
    def table_t(self) -> list[float]:
        """
        A table's times t_i (s), strictly increasing (empty for offset + harmonics).
        """
    def table_values(self) -> list[float]:
        """
        A table's values v_i, one per time (empty for offset + harmonics).
        """
class VectorSignal:
    """
    A vector signal of absolute time t (s): one scalar Signal per channel, or a function of t.
    
    Wherever a VectorSignal is expected, a list of Signals or numbers, or a callable f(t), is taken
    too. A function of t implemented in Python holds the GIL at each call, and does not pickle.
    
    Parameters
    ----------
    channels : list of Signal or float
        ``VectorSignal(channels)``: one Signal (or number) per channel.
    dim : int
        ``VectorSignal(dim, function)``: the number of channels, >= 0.
    function : callable
        ``function(t) -> array_like, shape (dim,)``, t in seconds; its values must be finite.
    
    Raises
    ------
    ValueError
        A channel that is not a Signal or a finite number; dim out of range; later, a function that
        returns the wrong length or a non-finite value (naming t).
    
    Examples
    --------
    >>> w = hc.VectorSignal([hc.Signal(0.1), 0.0])
    >>> w.dim(), w(2.0)
    (2, array([0.1, 0. ]))
    >>> hc.VectorSignal(2, lambda t: [t, 2 * t])(np.array([0.0, 1.0]))
    array([[0., 0.],
           [1., 2.]])
    """
    @staticmethod
    def zeros(dim: typing.SupportsInt | typing.SupportsIndex) -> VectorSignal:
        """
        dim zero channels.
        """
    def __call__(self, t: typing.Any) -> typing.Any:
        """
        The values at t (s): shape (dim,) for a number, (k, dim) for a 1-D array of k times.
        """
    def __getstate__(self) -> tuple[int, list[Signal]]:
        ...
    @typing.overload
    def __init__(self, channels: collections.abc.Sequence) -> None:
        ...
    @typing.overload
    def __init__(self, dim: typing.SupportsInt | typing.SupportsIndex, function: collections.abc.Callable) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def channels(self) -> list[Signal]:
        """
        The Signals of the channels (empty for a function of t).
        """
    def dim(self) -> int:
        """
        The number of channels.
        """
    def is_function(self) -> bool:
        """
        True for a function of t, false for channels of Signals.
        """
class SolverOptions:
    """
    Integrator and tolerances of one solve or closed loop (scenario section [solver]). Each
    field says its admissible range; validate() checks them.
    
    Parameters
    ----------
    method : Method or str, default 'auto'
        the integrator
    rtol : float, default 1e-08
        relative tolerance, in [1e-14, 1e-3]
    atol : float, default 1e-10
        absolute tolerance (about rtol/100 for O(1) solutions), in (0, 1e-3];
        Riccati solves use atol * min(1, the solution's scale)
    max_steps : int, default 500000
        steps of one whole solve or closed-loop run (all its restarts
        included), in [1, 1e9]; exceeding it is a SolverError
    escape_norm : float, default 1000.0
        Riccati solves: when |X|_max passes escape_norm times the solution's scale, the escape
        test (riccati.hpp) decides whether X escapes to infinity (a conjugate point, paper eq. 14)
        or is only large, on W = c (X + c I)^-1, which stays smooth through a tall peak of X. A
        larger value follows X itself further into the peak: near gamma* that takes tiny steps
        (gamma* of SLICOT's SB10FD system: 2.7 s at 1e6, 11 ms at 1e3) and is less accurate.
        finite and > 1
    newton_systems : NewtonSystems or str, default 'auto'
        Riccati equations with BDF
    
    Raises
    ------
    ValueError
        An option out of its range, naming it.
    
    Examples
    --------
    >>> options = hc.SolverOptions(method="erk", rtol=1e-6, atol=1e-8)
    >>> options.method, options.max_steps
    (<Method.erk: 3>, 500000)
    >>> try:
    ...     hc.SolverOptions(atol=0.0)
    ... except ValueError as error:
    ...     print(error)
    solver atol must be in (0, 1e-3] (about rtol / 100 for solutions of order 1), got 0
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('method', 'rtol', 'atol', 'max_steps', 'escape_norm', 'newton_systems')
    def __eq__(self, arg0: SolverOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, method: Method | str = Method.auto, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-08, atol: typing.SupportsFloat | typing.SupportsIndex = 1e-10, max_steps: typing.SupportsInt | typing.SupportsIndex = 500000, escape_norm: typing.SupportsFloat | typing.SupportsIndex = 1000.0, newton_systems: NewtonSystems | str = NewtonSystems.auto) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def atol(self) -> float:
        """
        absolute tolerance (about rtol/100 for O(1) solutions), in (0, 1e-3];
        Riccati solves use atol * min(1, the solution's scale)
        """
    @atol.setter
    def atol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def escape_norm(self) -> float:
        """
        Riccati solves: when |X|_max passes escape_norm times the solution's scale, the escape
        test (riccati.hpp) decides whether X escapes to infinity (a conjugate point, paper eq. 14)
        or is only large, on W = c (X + c I)^-1, which stays smooth through a tall peak of X. A
        larger value follows X itself further into the peak: near gamma* that takes tiny steps
        (gamma* of SLICOT's SB10FD system: 2.7 s at 1e6, 11 ms at 1e3) and is less accurate.
        finite and > 1
        """
    @escape_norm.setter
    def escape_norm(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_steps(self) -> int:
        """
        steps of one whole solve or closed-loop run (all its restarts
        included), in [1, 1e9]; exceeding it is a SolverError
        """
    @max_steps.setter
    def max_steps(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def method(self) -> Method:
        """
        the integrator
        """
    @method.setter
    def method(self, arg1: Method | str) -> None:
        ...
    @property
    def newton_systems(self) -> NewtonSystems:
        """
        Riccati equations with BDF
        """
    @newton_systems.setter
    def newton_systems(self, arg1: NewtonSystems | str) -> None:
        ...
    @property
    def rtol(self) -> float:
        """
        relative tolerance, in [1e-14, 1e-3]
        """
    @rtol.setter
    def rtol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class PiecewisePolynomial:
    """
    Dense output of an ODE solve: one polynomial piece per integrator step.
    
    Piece k covers the step from t_k to e_k (e_k < t_k for backward integration) and is
        y(t) = sum_{j=0..d_k} c_kj theta^j,   theta = (t - t_k) / (e_k - t_k) in [0, 1],
    with c_kj in R^p. The pieces come from the integrator's own interpolant (Dormand-Prince
    dense output, CVODE's Nordsieck history), so y(t) has the integrator's accuracy at every t,
    and their ends are the integrator's own step ends, so the first and last pieces reach the
    ends of the integration exactly. At a time shared by several pieces (a step end, or steps
    shorter than the spacing of doubles) the piece first in integration order is used: y at the
    start of the integration is the initial value exactly.
    Lookups take an optional cursor (index of the last piece used) so that a sweep over sorted
    times costs O(1) per lookup; without it a binary search is used. Const lookups without a
    cursor are thread-safe.
    
    Made by the solvers (Trajectory.dense(), RiccatiSolution.dense()); it pickles.
    
    Examples
    --------
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 10.0)
    >>> dense = trajectory.dense()                               # q_d: surge 1 m/s along x
    >>> dense.dim(), dense.t_min(), dense.t_max()
    (6, 0.0, 10.0)
    >>> dense.eval(5.0).round(6)
    array([1., 0., 0., 5., 0., 0.])
    """
    def __getstate__(self) -> tuple:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def breakpoints(self) -> list[float]:
        """
        The ends of the pieces, increasing (num_pieces + 1 values).
        """
    def dim(self) -> int:
        """
        The number of components of y.
        """
    def empty(self) -> bool:
        """
        True before the first piece is appended.
        """
    def eval(self, t: typing.Any) -> typing.Any:
        """
        y(t) into out (dim numbers); t outside [t_min, t_max] is an InputError.
        
        Shape (dim,) for a number t, (k, dim) for a 1-D array of k times.
        """
    def eval_derivative(self, t: typing.Any) -> typing.Any:
        """
        dy/dt at t (per second) into out: the derivative of the piece's polynomial.
        
        Shape (dim,) for a number t, (k, dim) for a 1-D array of k times.
        """
    def memory_bytes(self) -> int:
        """
        Bytes of the stored solution (coefficients and piece data).
        """
    def num_pieces(self) -> int:
        """
        The number of pieces (integrator steps).
        """
    def t_max(self) -> float:
        """
        The interval covered, [t_min, t_max] (s).
        """
    def t_min(self) -> float:
        """
        The interval covered, [t_min, t_max] (s).
        """
class StepStats:
    """
    The counts of one integration (the desired trajectory's, Trajectory::stats()).
    
    Attributes
    ----------
    steps : int
        accepted steps
    rejected : int
        rejected step attempts
    rhs_evals : int
        right-hand-side evaluations
    jac_evals : int
        Jacobian evaluations (implicit methods)
    
    Examples
    --------
    >>> stats = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 10.0).stats()
    >>> stats.steps > 0, stats.jac_evals                         # Dormand-Prince: no Jacobian
    (True, 0)
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
        """
        Jacobian evaluations (implicit methods)
        """
    @property
    def rejected(self) -> int:
        """
        rejected step attempts
        """
    @property
    def rhs_evals(self) -> int:
        """
        right-hand-side evaluations
        """
    @property
    def steps(self) -> int:
        """
        accepted steps
        """
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
    The interface every model implements. Its structure (name, sizes, state names, position and
    heading indices, noise channels, the two flags about the input matrices: ModelStructure) must
    not change over the model's life.
    
    The model interface and the built-in models.
    
    A model is a control-affine system (paper eq. 7 with state-dependent input matrices):
        dq/dt = f(t, q) + G(t, q) u + D(t, q) w,
    with state q (n), control u (m) and disturbance w (nw). Everything downstream uses only this
    interface: the desired trajectory, the linearization along it (docs/mathematics.md,
    "State-dependent input matrices")
        A_e(t) = d/dq [f(t, q) + G(t, q) u_d(t)] at q_d(t),  B_e(t) = G(t, q_d(t)),
        D_e(t) = D(t, q_d(t)),
    the GRDE and filter designed on (A_e, B_e, D_e), and the closed loops, which apply the full
    nonlinear f, G and D. The paper's ship is the special case with constant G = B and D.
    
    Conventions, fixed once for the project:
      * time t is absolute, in seconds;
      * the error is q_e = q - q_d (actual minus desired), likewise u_e = u - u_d;
      * matrices are column-major Eigen objects; G is n x m, D is n x nw.
    
    Notes
    -----
    Subclass it in Python and implement n(), m(), nw(), f(t, q), G(t, q), D(t, q), and if you can
    dfdq(t, q) (else the Jacobian is numerical: the complex step when f accepts complex q, else
    central differences; jacobian_method() says which). q arrives as a float64 array of shape (n,);
    f returns shape (n,), dfdq (n, n), G (n, m), D (n, nw). A G or D that depends on q needs
    state_dependent_inputs() -> True and constant_input_matrices() -> False (dGudq(t, q, u) is
    optional: central differences otherwise). The other methods have defaults. The structure is
    read once, when the library first needs it, and validated; what f, dfdq, G, D, C and
    error_split return is checked at every call (ValueError naming the method). Each call holds the
    GIL, so computations with a Python model run on one thread; such a model does not pickle.
    
    Examples
    --------
    >>> class DoubleIntegrator(hc.Model):
    ...     def n(self): return 2
    ...     def m(self): return 1
    ...     def nw(self): return 1
    ...     def f(self, t, q): return np.array([q[1], 0.0])
    ...     def G(self, t, q): return np.array([[0.0], [1.0]])
    ...     def D(self, t, q): return np.array([[0.0], [1.0]])
    >>> model = DoubleIntegrator()
    >>> model.dfdq(0.0, np.array([0.0, 2.0]))                    # no dfdq: numerical
    array([[0., 1.],
           [0., 0.]])
    >>> model.jacobian_method(), model.state_names()
    ('complex step', ['q0', 'q1'])
    """
    def C(self, t: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Measurement y = C(t) q + E w (paper eq. 25), C is p x n. The measurement noise is carried
        by the w channels noise_channels() (p of them): E = sigma [those unit columns], so
        N = E E' = sigma^2 I. The default model has no measurement (C throws InputError).
        
        Returns C, shape (p, n).
        """
    def D(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Input matrix G(t, q) (n x m) and disturbance matrix D(t, q) (n x nw).
        
        t in seconds, q of shape (n,); returns D, shape (n, nw).
        """
    def G(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Input matrix G(t, q) (n x m) and disturbance matrix D(t, q) (n x nw).
        
        t in seconds, q of shape (n,); returns G, shape (n, m).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self) -> None:
        ...
    def constant_input_matrices(self) -> bool:
        """
        True when G and D depend on neither t nor q (lets solvers precompute B B' and D D').
        """
    def dGudq(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        d/dq [G(t, q) u] for a fixed u (n x n): the input's part of the linearization. Zero for
        models whose G does not depend on q; a model with state_dependent_inputs() overrides it
        (the default then throws InputError).
        
        q of shape (n,), u of shape (m,); returns shape (n, n).
        """
    def dfdq(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Drift f(t, q) (n) and its Jacobian df/dq (n x n).
        
        t in seconds, q of shape (n,); returns df/dq, shape (n, n).
        """
    def error_split(self, t: typing.SupportsFloat | typing.SupportsIndex, q_d: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u_d: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], q_e: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
        """
        Decomposition of the error dynamics (paper eqs. 26-31, with the input's drift):
            f_e(t, q_e) := f(t, q_d + q_e) + G(t, q_d + q_e) u_d - f(t, q_d) - G(t, q_d) u_d
                         = A(t, q_e) q_e + alpha(t, q_e),
        with A(t, 0) = A_e(t). q_d and u_d are the desired state and input at t (u_d matters only
        when G depends on q). The default is the always-valid split A = A_e(t),
        alpha = f_e - A_e q_e; models with structure (the ship) override it.
        
        q_d, q_e of shape (n,), u_d of shape (m,); returns (A, alpha) of shapes (n, n) and (n,).
        """
    def f(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Drift f(t, q) (n) and its Jacobian df/dq (n x n).
        
        t in seconds, q of shape (n,); returns f, shape (n,).
        """
    def heading_index(self) -> int:
        """
        Index of the heading angle (rad), or -1.
        """
    def jacobian_method(self) -> str:
        """
        How dfdq and dGudq are obtained, for the results file: "analytic" (written out), or what
        the model does instead ("automatic differentiation", "complex step", "central differences").
        """
    def linearize(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        The linearization of the drift with the input held at u: A = d/dq [f(t, q) + G(t, q) u]
        (n x n) = df/dq, plus dGudq when the inputs depend on the state. At (q_d(t), u_d(t)) this is
        A_e(t).
        
        q of shape (n,), u of shape (m,); returns A, shape (n, n).
        """
    def m(self) -> int:
        """
        The sizes: n states, m control inputs, nw disturbance channels.
        """
    def n(self) -> int:
        """
        The sizes: n states, m control inputs, nw disturbance channels.
        """
    def name(self) -> str:
        """
        The model's name (the results file, tables, messages).
        """
    def named_parameters(self) -> dict[str, float]:
        """
        The model's parameters by name, in a fixed order: a number by its key in the model's
        scenario-file section ([model], [plant]: "d_u" of the ship), an entry of a matrix as
        NAME[i][j] (row i, column j, from 0: "D[1][2]" of the Fossen vessel). Empty for a model
        without named parameters. Studies perturb a model from these base values; the results file
        records them.
        
        Returns a dict name -> value; a model implemented in Python may define it (returning a dict of numbers).
        """
    def noise_channels(self) -> list[int]:
        """
        Measurement y = C(t) q + E w (paper eq. 25), C is p x n. The measurement noise is carried
        by the w channels noise_channels() (p of them): E = sigma [those unit columns], so
        N = E E' = sigma^2 I. The default model has no measurement (C throws InputError).
        
        Returns the noise channels, indices into w.
        """
    def nw(self) -> int:
        """
        The sizes: n states, m control inputs, nw disturbance channels.
        """
    def position_indices(self) -> list[int]:
        """
        Indices of the inertial position components used by the position-error metrics
        (empty: the model has no position, and those metrics are NaN).
        """
    def remainder_bound(self, t: typing.SupportsFloat | typing.SupportsIndex, q_d: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], radius: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        A bound L with |f_e(t, q_e) - A_e(t) q_e| <= L |q_e|^2 for all |q_e| <= radius (the
        remainder of the linearization, paper eqs. 11 and 24), or NaN if the model has none (the
        certificates then fall back on a sampled estimate, reported as such).
        """
    def state_dependent_inputs(self) -> bool:
        """
        True when G or D depend on q (then constant_input_matrices() must be false, and dGudq
        must be implemented).
        """
    def state_names(self) -> list[str]:
        """
        Names of the state components (for tables, CSV headers and plots).
        """
class ShipParameters:
    """
    The underactuated surface ship of paper eqs. (1)-(6) (docs/mathematics.md):
      state q = [u, v, r, x, y, psi]: surge, sway (m/s), yaw rate (rad/s) in the body frame;
                inertial position x, y (m) and heading psi (rad);
      control [u1, u2]: surge force and yaw torque (per unit mass / inertia);
      disturbance w = [w1..w6]: w1..w3 act on the u, v, r equations (D = diag(1,1,1,0,0,0));
                w4..w6 are the measurement-noise channels of paper §4 (they enter through E).
        du/dt   = m_u v r - d_u u + u1 + w1
        dv/dt   = m_v u r - d_v v      + w2
        dr/dt   = m_r u v - d_r r + u2 + w3
        dx/dt   = u cos(psi) - v sin(psi)
        dy/dt   = u sin(psi) + v cos(psi)
        dpsi/dt = r
    
    Parameters
    ----------
    m_u : float, default 0.5
        coefficient of v r in du/dt (m_u v r), finite
    m_v : float, default -2.0
        coefficient of u r in dv/dt (m_v u r), finite
    m_r : float, default 0.5
        coefficient of u v in dr/dt (m_r u v), finite
    d_u : float, default 1.0
        surge damping (1/s), finite
    d_v : float, default 2.0
        sway damping (1/s), finite
    d_r : float, default 1.0
        yaw damping (1/s), finite
    
    Examples
    --------
    >>> hc.ShipParameters(d_u=1.5)
    ShipParameters(m_u=0.5, m_v=-2.0, m_r=0.5, d_u=1.5, d_v=2.0, d_r=1.0)
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
        """
        yaw damping (1/s), finite
        """
    @d_r.setter
    def d_r(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def d_u(self) -> float:
        """
        surge damping (1/s), finite
        """
    @d_u.setter
    def d_u(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def d_v(self) -> float:
        """
        sway damping (1/s), finite
        """
    @d_v.setter
    def d_v(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m_r(self) -> float:
        """
        coefficient of u v in dr/dt (m_r u v), finite
        """
    @m_r.setter
    def m_r(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m_u(self) -> float:
        """
        coefficient of v r in du/dt (m_u v r), finite
        """
    @m_u.setter
    def m_u(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m_v(self) -> float:
        """
        coefficient of u r in dv/dt (m_v u r), finite
        """
    @m_v.setter
    def m_v(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class ShipModel(Model):
    """
    The paper's underactuated ship: the model of paper eqs. (1)-(6), with its error split
    (26)-(31) and analytic remainder bound. The cascaded baseline law written for it is
    control/cascade.hpp.
    
    The underactuated surface ship of paper eqs. (1)-(6) (docs/mathematics.md):
      state q = [u, v, r, x, y, psi]: surge, sway (m/s), yaw rate (rad/s) in the body frame;
                inertial position x, y (m) and heading psi (rad);
      control [u1, u2]: surge force and yaw torque (per unit mass / inertia);
      disturbance w = [w1..w6]: w1..w3 act on the u, v, r equations (D = diag(1,1,1,0,0,0));
                w4..w6 are the measurement-noise channels of paper §4 (they enter through E).
        du/dt   = m_u v r - d_u u + u1 + w1
        dv/dt   = m_v u r - d_v v      + w2
        dr/dt   = m_r u v - d_r r + u2 + w3
        dx/dt   = u cos(psi) - v sin(psi)
        dy/dt   = u sin(psi) + v cos(psi)
        dpsi/dt = r
    
    Its equations are generated from its statement (python/hinf_cpp/models/builtin.py, ship();
    models/builtin_vehicle.hpp), the error split (26)-(31) included.
    
    InputError unless every parameter is finite.
    
    Parameters
    ----------
    parameters : ShipParameters, optional
        The paper's parameters by default.
    
    Raises
    ------
    ValueError
        A parameter that is not finite.
    
    Examples
    --------
    >>> ship = hc.ShipModel(hc.ShipParameters(d_u=1.5))
    >>> ship.n(), ship.m(), ship.nw(), ship.state_names()
    (6, 2, 6, ['u', 'v', 'r', 'x', 'y', 'psi'])
    >>> ship.f(0.0, np.array([1.0, 0.0, 0.0, 0.0, 0.0, 0.0]))[[0, 3]]   # du/dt = -d_u u, dx/dt = u
    array([-1.5,  1. ])
    """
    def __getstate__(self) -> tuple[ShipParameters]:
        ...
    def __init__(self, parameters: ShipParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> ShipParameters:
        """
        The parameters it was made with.
        """
class LinearModel(Model):
    """
    A linear time-invariant model dq/dt = A q + B u + D w (for LTI studies and tests).
    With a measurement matrix C (p x n), w gets p more channels for the measurement noise:
    w = [process disturbance (D.cols()), measurement noise (p)], and D is padded with zeros.
    
    Parameters
    ----------
    A : array_like, shape (n, n)
        The state matrix.
    B : array_like, shape (n, m)
        The input matrix.
    D : array_like, shape (n, nw)
        The disturbance matrix.
    C : array_like, shape (p, n), optional
        The measurement matrix; without it the model has no measurement.
    
    Raises
    ------
    ValueError
        Matrices whose shapes do not fit, or entries that are not finite.
    
    Examples
    --------
    >>> model = hc.LinearModel(np.array([[0.0, 1.0], [0.0, 0.0]]), np.array([[0.0], [1.0]]), np.eye(2),
    ...                        C=np.array([[1.0, 0.0]]))
    >>> model.n(), model.m(), model.nw(), model.noise_channels()      # w = [process (2), noise (1)]
    (2, 1, 3, [2])
    """
    def A(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        A (n x n) and B (n x m) as given to the constructor.
        """
    def B(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        A (n x n) and B (n x m) as given to the constructor.
        """
    def __getstate__(self) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]]:
        ...
    def __init__(self, A: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], B: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], D: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], C: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = None) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def measurement_C(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        The matrices as given to the constructor: D without the noise channels, C empty if none.
        """
    def process_D(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        The matrices as given to the constructor: D without the noise channels, C empty if none.
        """
class FleetModel(Model):
    """
    A fleet: k independent copies of one model stacked into a block-diagonal model.
    
    The state is q = [q_1; ...; q_k] (vehicle i's states at rows i n_1 .. (i+1) n_1 - 1), likewise
    u and w; f, df/dq, G, D, C and the error split are block-diagonal in the member's. The
    vehicles are not coupled, so a fleet's design is k single designs; it exists as a test bed for
    the cost of the Riccati solves in the state size (n = k n_1) on a time-varying system, and
    for controllers designed on the joint state. The fleet's position components are those of
    every vehicle (the position-error metrics are norms over the fleet); it has no single heading
    (heading_index() = -1: tracking errors of headings are not wrapped).
    
    InputError unless member is set and count >= 1 (with count times its size within
    kMaxDimension).
    
    Parameters
    ----------
    member : Model
        The model of one vehicle (n_1 states).
    count : int
        The number of vehicles, >= 1.
    
    Raises
    ------
    ValueError
        No member, or count < 1 or too large.
    
    Examples
    --------
    >>> fleet = hc.FleetModel(hc.ShipModel(), 3)
    >>> fleet.n(), fleet.m(), fleet.state_names()[:4], fleet.heading_index()
    (18, 6, ['u_1', 'v_1', 'r_1', 'x_1'], -1)
    """
    def __getstate__(self) -> tuple[Model, int]:
        ...
    def __init__(self, member: Model, count: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def count(self) -> int:
        """
        The model of one vehicle, and the number of vehicles.
        """
    def member(self) -> Model:
        """
        The model of one vehicle, and the number of vehicles.
        """
class FossenVesselParameters:
    """
    Fossen's 3-DOF horizontal-plane model (T. I. Fossen, Handbook of Marine Craft Hydrodynamics
    and Motion Control, Wiley, 2011):
        M nu_dot + C(nu) nu + D nu = B_tau tau + w,    eta_dot = R(psi) nu,
    nu = [u, v, r], eta = [x, y, psi], tau = [tau_u, tau_r] (surge force, yaw moment; no sway
    force: B_tau = [[1, 0], [0, 0], [0, 1]]), M symmetric positive definite (rigid body plus added
    mass), C(nu) its Coriolis-centripetal matrix in the skew-symmetric form
        C(nu) = [[0, 0, -a2], [0, 0, a1], [a2, -a1, 0]],   [a1, a2, a3] = M nu,
    (for M = [[m11, 0, 0], [0, m22, m23], [0, m23, m33]]: a1 = m11 u, a2 = m22 v + m23 r), and
    linear damping D whose symmetric part is positive definite (D itself need not be symmetric).
    So f = [M^-1 (-C(nu) nu - D nu); R(psi) nu], G = [M^-1 B_tau; 0] (constant; the yaw moment
    also accelerates sway through m23), and the disturbance w1..w3 enters as forces: D_w =
    [M^-1; 0] on w1..w3.
    
    Parameters
    ----------
    M : array_like, shape (3, 3), optional
        Defaults: the supply vessel (supply_vessel()).
        mass matrix, 3 x 3, symmetric positive definite
    D : array_like, shape (3, 3), optional
        linear damping, 3 x 3, (D + D') / 2 positive definite
    
    Examples
    --------
    >>> vessel = hc.FossenVesselParameters.supply_vessel()
    >>> float(vessel.M[1, 2]), vessel.D.shape
    (-0.0744, (3, 3))
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('M', 'D')
    @staticmethod
    def supply_vessel() -> FossenVesselParameters:
        """
        The supply vessel of Fossen, Sagatun and Sorensen, "Identification of dynamically
        positioned ships", Control Engineering Practice 4(3), 369-376, 1996, in bis units
        (length L = 76.2 m, mass 6000 t):
          M = [[1.1274, 0, 0], [0, 1.8902, -0.0744], [0, -0.0744, 0.1278]],
          D = [[0.0358, 0, 0], [0, 0.1183, -0.0124], [0, -0.0041, 0.0308]].
        """
    def __eq__(self, arg0: FossenVesselParameters) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, M: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., D: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def D(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        linear damping, 3 x 3, (D + D') / 2 positive definite
        """
    @D.setter
    def D(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def M(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Defaults: the supply vessel (supply_vessel()).
        mass matrix, 3 x 3, symmetric positive definite
        """
    @M.setter
    def M(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
class HovercraftParameters:
    """
    A planar hovercraft in inertial coordinates (the model of Aguiar, Cremean and Hespanha,
    "Position tracking for a nonlinear underactuated hovercraft: controller design and
    experimental results", IEEE CDC 2003; and of Fantoni, Lozano, Mazenc and Pettersen,
    "Stabilization of a nonlinear underactuated hovercraft", Int. J. Robust Nonlinear Control
    10(8), 2000), with inputs per unit mass and inertia, u = [F, T]:
        dvx/dt = F cos(psi) - d vx + w1,   dvy/dt = F sin(psi) - d vy + w2,   dr/dt = T - d_r r + w3,
        dx/dt = vx,   dy/dt = vy,   dpsi/dt = r.
    No force across the body axis: the thrust acts along the heading. G depends on psi.
    
    Parameters
    ----------
    d : float, default 0.2
        translational damping per unit mass (1/s), >= 0
    d_r : float, default 0.5
        rotational damping per unit inertia (1/s), >= 0
    
    Examples
    --------
    >>> hc.HovercraftParameters(d=0.1)
    HovercraftParameters(d=0.1, d_r=0.5)
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
        """
        translational damping per unit mass (1/s), >= 0
        """
    @d.setter
    def d(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def d_r(self) -> float:
        """
        rotational damping per unit inertia (1/s), >= 0
        """
    @d_r.setter
    def d_r(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class PlanarVtolParameters:
    """
    The planar vertical take-off and landing aircraft of Hauser, Sastry and Meyer, "Nonlinear
    control design for slightly non-minimum phase systems: application to V/STOL aircraft",
    Automatica 28(4), 665-679, 1992, in their normalized form, u = [u1, u2] (thrust, rolling
    moment):
        x_ddot = -u1 sin(theta) + epsilon u2 cos(theta) + w1,
        y_ddot =  u1 cos(theta) + epsilon u2 sin(theta) - g + w2,
        theta_ddot = u2 + w3.
    Gravity is part of f; G depends on theta. epsilon couples the rolling moment into the lateral
    acceleration (the slightly non-minimum-phase effect).
    
    Parameters
    ----------
    g : float, default 1.0
        gravity (1: the normalized form), >= 0
    epsilon : float, default 0.1
        coupling of the rolling moment into the translation, finite
    
    Examples
    --------
    >>> hc.PlanarVtolParameters(epsilon=0.0)
    PlanarVtolParameters(g=1.0, epsilon=0.0)
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
        """
        coupling of the rolling moment into the translation, finite
        """
    @epsilon.setter
    def epsilon(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def g(self) -> float:
        """
        gravity (1: the normalized form), >= 0
        """
    @g.setter
    def g(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class AuvParameters:
    """
    An underactuated AUV in the horizontal plane with linear and quadratic drag (diagonal mass
    matrix; no sway thrust), u = [tau_u, tau_r] (N, N m):
        m11 u_dot = m22 v r - X_u u - X_uu |u| u + tau_u + w1,
        m22 v_dot = -m11 u r - Y_v v - Y_vv |v| v + w2,
        m33 r_dot = (m11 - m22) u v - N_r r - N_rr |r| r + tau_r + w3,
        x_dot = u cos(psi) - v sin(psi),   y_dot = u sin(psi) + v cos(psi),   psi_dot = r.
    |u| u is continuously differentiable (derivative 2 |u|), so the analytic Jacobian exists
    everywhere; its second derivative jumps at zero speed.
    
    Parameters
    ----------
    m11 : float, default 215.0
        Defaults: the Sirene AUV (sirene()).
        kg, > 0 (mass plus added mass in surge)
    m22 : float, default 265.0
        kg, > 0 (sway)
    m33 : float, default 80.0
        kg m^2, > 0 (yaw)
    X_u : float, default 70.0
        kg/s, >= 0
    X_uu : float, default 100.0
        kg/m, >= 0
    Y_v : float, default 100.0
        kg/s, >= 0
    Y_vv : float, default 200.0
        kg/m, >= 0
    N_r : float, default 50.0
        kg m^2/s, >= 0
    N_rr : float, default 100.0
        kg m^2, >= 0
    
    Examples
    --------
    >>> sirene = hc.AuvParameters.sirene()
    >>> sirene.m11, sirene == hc.AuvParameters()
    (215.0, True)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('m11', 'm22', 'm33', 'X_u', 'X_uu', 'Y_v', 'Y_vv', 'N_r', 'N_rr')
    @staticmethod
    def sirene() -> AuvParameters:
        """
        The Sirene AUV as in Aguiar and Pascoal, "Dynamic positioning and way-point tracking of
        underactuated AUVs in the presence of ocean currents", Int. J. Control 80(7), 1092-1108,
        2007 (the defaults of the fields).
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
        """
        kg m^2/s, >= 0
        """
    @N_r.setter
    def N_r(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def N_rr(self) -> float:
        """
        kg m^2, >= 0
        """
    @N_rr.setter
    def N_rr(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def X_u(self) -> float:
        """
        kg/s, >= 0
        """
    @X_u.setter
    def X_u(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def X_uu(self) -> float:
        """
        kg/m, >= 0
        """
    @X_uu.setter
    def X_uu(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def Y_v(self) -> float:
        """
        kg/s, >= 0
        """
    @Y_v.setter
    def Y_v(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def Y_vv(self) -> float:
        """
        kg/m, >= 0
        """
    @Y_vv.setter
    def Y_vv(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m11(self) -> float:
        """
        Defaults: the Sirene AUV (sirene()).
        kg, > 0 (mass plus added mass in surge)
        """
    @m11.setter
    def m11(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m22(self) -> float:
        """
        kg, > 0 (sway)
        """
    @m22.setter
    def m22(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def m33(self) -> float:
        """
        kg m^2, > 0 (yaw)
        """
    @m33.setter
    def m33(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class FossenVessel(Model):
    """
    A 3-DOF surface vessel in Fossen's matrix form (the supply vessel preset).
    State order, units and what the built-in vehicles share: models/vehicles.hpp.
    
    Fossen's 3-DOF horizontal-plane model (T. I. Fossen, Handbook of Marine Craft Hydrodynamics
    and Motion Control, Wiley, 2011):
        M nu_dot + C(nu) nu + D nu = B_tau tau + w,    eta_dot = R(psi) nu,
    nu = [u, v, r], eta = [x, y, psi], tau = [tau_u, tau_r] (surge force, yaw moment; no sway
    force: B_tau = [[1, 0], [0, 0], [0, 1]]), M symmetric positive definite (rigid body plus added
    mass), C(nu) its Coriolis-centripetal matrix in the skew-symmetric form
        C(nu) = [[0, 0, -a2], [0, 0, a1], [a2, -a1, 0]],   [a1, a2, a3] = M nu,
    (for M = [[m11, 0, 0], [0, m22, m23], [0, m23, m33]]: a1 = m11 u, a2 = m22 v + m23 r), and
    linear damping D whose symmetric part is positive definite (D itself need not be symmetric).
    So f = [M^-1 (-C(nu) nu - D nu); R(psi) nu], G = [M^-1 B_tau; 0] (constant; the yaw moment
    also accelerates sway through m23), and the disturbance w1..w3 enters as forces: D_w =
    [M^-1; 0] on w1..w3.
    
    InputError unless M and D are finite 3 x 3 matrices, M symmetric positive definite and the
    symmetric part of D positive definite.
    
    Parameters
    ----------
    parameters : FossenVesselParameters, optional
        M and D; the supply vessel by default.
    
    Raises
    ------
    ValueError
        M or D not finite 3 x 3, M not symmetric positive definite, or the symmetric part of D not.
    
    Examples
    --------
    >>> vessel = hc.FossenVessel()
    >>> vessel.name(), vessel.state_names(), vessel.m()
    ('fossen_vessel', ['u', 'v', 'r', 'x', 'y', 'psi'], 2)
    """
    def __getstate__(self) -> tuple[FossenVesselParameters]:
        ...
    def __init__(self, parameters: FossenVesselParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> FossenVesselParameters:
        """
        The parameters it was made with.
        """
class Hovercraft(Model):
    """
    A planar hovercraft in inertial coordinates (its input matrix depends on the heading).
    State order, units and what the built-in vehicles share: models/vehicles.hpp.
    
    A planar hovercraft in inertial coordinates (the model of Aguiar, Cremean and Hespanha,
    "Position tracking for a nonlinear underactuated hovercraft: controller design and
    experimental results", IEEE CDC 2003; and of Fantoni, Lozano, Mazenc and Pettersen,
    "Stabilization of a nonlinear underactuated hovercraft", Int. J. Robust Nonlinear Control
    10(8), 2000), with inputs per unit mass and inertia, u = [F, T]:
        dvx/dt = F cos(psi) - d vx + w1,   dvy/dt = F sin(psi) - d vy + w2,   dr/dt = T - d_r r + w3,
        dx/dt = vx,   dy/dt = vy,   dpsi/dt = r.
    No force across the body axis: the thrust acts along the heading. G depends on psi.
    
    InputError unless d and d_r are finite and >= 0.
    
    Parameters
    ----------
    parameters : HovercraftParameters, optional
        The damping d and d_r (1/s).
    
    Raises
    ------
    ValueError
        d or d_r not finite or negative.
    
    Examples
    --------
    >>> hover = hc.Hovercraft()
    >>> hover.state_names(), hover.state_dependent_inputs()
    (['x', 'y', 'psi', 'vx', 'vy', 'r'], True)
    >>> hover.G(0.0, np.array([0.0, 0.0, np.pi / 2, 0.0, 0.0, 0.0]))[3:5, 0].round(6)   # thrust along y
    array([0., 1.])
    """
    def __getstate__(self) -> tuple[HovercraftParameters]:
        ...
    def __init__(self, parameters: HovercraftParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> HovercraftParameters:
        """
        The parameters it was made with.
        """
class PlanarVtol(Model):
    """
    The planar VTOL aircraft of Hauser, Sastry and Meyer (its input matrix depends on the roll angle).
    State order, units and what the built-in vehicles share: models/vehicles.hpp.
    
    The planar vertical take-off and landing aircraft of Hauser, Sastry and Meyer, "Nonlinear
    control design for slightly non-minimum phase systems: application to V/STOL aircraft",
    Automatica 28(4), 665-679, 1992, in their normalized form, u = [u1, u2] (thrust, rolling
    moment):
        x_ddot = -u1 sin(theta) + epsilon u2 cos(theta) + w1,
        y_ddot =  u1 cos(theta) + epsilon u2 sin(theta) - g + w2,
        theta_ddot = u2 + w3.
    Gravity is part of f; G depends on theta. epsilon couples the rolling moment into the lateral
    acceleration (the slightly non-minimum-phase effect).
    
    InputError unless g is finite and >= 0 and epsilon finite.
    
    Parameters
    ----------
    parameters : PlanarVtolParameters, optional
        Gravity g and the coupling epsilon (normalized units).
    
    Raises
    ------
    ValueError
        g not finite or negative, or epsilon not finite.
    
    Examples
    --------
    >>> vtol = hc.PlanarVtol()
    >>> vtol.state_names()[:3], float(vtol.f(0.0, np.zeros(6))[4])   # y_ddot = -g without thrust
    (['x', 'y', 'theta'], -1.0)
    """
    def __getstate__(self) -> tuple[PlanarVtolParameters]:
        ...
    def __init__(self, parameters: PlanarVtolParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> PlanarVtolParameters:
        """
        The parameters it was made with.
        """
class Auv(Model):
    """
    An AUV in the horizontal plane with quadratic drag (the Sirene preset).
    State order, units and what the built-in vehicles share: models/vehicles.hpp.
    
    An underactuated AUV in the horizontal plane with linear and quadratic drag (diagonal mass
    matrix; no sway thrust), u = [tau_u, tau_r] (N, N m):
        m11 u_dot = m22 v r - X_u u - X_uu |u| u + tau_u + w1,
        m22 v_dot = -m11 u r - Y_v v - Y_vv |v| v + w2,
        m33 r_dot = (m11 - m22) u v - N_r r - N_rr |r| r + tau_r + w3,
        x_dot = u cos(psi) - v sin(psi),   y_dot = u sin(psi) + v cos(psi),   psi_dot = r.
    |u| u is continuously differentiable (derivative 2 |u|), so the analytic Jacobian exists
    everywhere; its second derivative jumps at zero speed.
    
    InputError unless the masses are finite and > 0 and the drag coefficients finite and >= 0.
    
    Parameters
    ----------
    parameters : AuvParameters, optional
        Masses and drag coefficients (SI); the Sirene AUV by default.
    
    Raises
    ------
    ValueError
        A mass not finite or not > 0, or a drag coefficient not finite or negative.
    
    Examples
    --------
    >>> auv = hc.Auv()
    >>> auv.named_parameters()["m11"], auv.state_names()[3:]
    (215.0, ['x', 'y', 'psi'])
    """
    def __getstate__(self) -> tuple[AuvParameters]:
        ...
    def __init__(self, parameters: AuvParameters = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def parameters(self) -> AuvParameters:
        """
        The parameters it was made with.
        """
class GeneratedModel(Model):
    """
    A model whose functions are C code generated by CasADi from symbolic expressions
    (hinf_cpp.symbolic.SymbolicModel in Python; docs/models.md), compiled into a shared library
    and described by a JSON file, model.json:
    
      {"format": "hinf_cpp.generated_model/1", "name": ..., "n": ..., "m": ..., "nw": ...,
       "state_names": [...], "position_indices": [...], "heading_index": -1 or i,
       "noise_channels": [...], "constant_input_matrices": bool, "state_dependent_inputs": bool,
       "measurement": bool, "error_split": bool,
       "parameters": [{"name": ..., "default": ...}, ...], "library": "<file beside model.json>"}
    
    The library holds the generated functions (every matrix dense or sparse, column-major):
      f(t, q, p) -> n x 1          dfdq(t, q, p) -> n x n      (automatic differentiation)
      G(t, q, p) -> n x m          D(t, q, p) -> n x nw
      dGudq(t, q, u, p) -> n x n   C(t, p) -> p_y x n          (C if "measurement")
      error_split(t, q_d, u_d, q_e, p) -> (A n x n, alpha n x 1)  (if "error_split")
    with p the parameter vector in the order of "parameters". Everything is evaluated by the
    generated code (GeneratedFunction): no Python runs, and one model may be used from several
    threads at once.
    
    hinf_cpp.models.SymbolicModel writes model.json and its library (build(), compile()).
    
    Parameters
    ----------
    metadata_path : str
        The path of model.json.
    parameters : dict of str to float, optional
        Parameter values by name; the others keep their defaults.
    
    Raises
    ------
    ValueError
        Naming the file: a missing file or not a model description, a missing function or one of
        other sizes than the description says, an invalid structure, an unknown or non-finite
        parameter.
    
    Examples
    --------
    >>> import casadi as ca
    >>> from hinf_cpp.models import SymbolicModel
    >>> q, d = ca.SX.sym("q", 2), ca.SX.sym("d")
    >>> cart = SymbolicModel("cart", state=q, inputs=1, f=ca.vertcat(q[1], -d * q[1]), G=[[0.0], [1.0]],
    ...                      D=[[0.0], [1.0]], parameters=d, parameter_values={"d": 0.5})
    >>> built = cart.build(cache_dir="cache")                    # model.json and its library
    >>> model = hc.GeneratedModel(str(built.metadata_path), {"d": 1.0})
    >>> model.parameters(), model.f(0.0, np.array([0.0, 2.0]))
    ({'d': 1.0}, array([ 2., -2.]))
    """
    def __getstate__(self) -> tuple[str, dict[str, float]]:
        ...
    def __init__(self, metadata_path: str, parameters: collections.abc.Mapping[str, typing.SupportsFloat | typing.SupportsIndex] = {}) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def library_path(self) -> str:
        """
        The path of the shared library that holds the functions.
        """
    def metadata_path(self) -> str:
        """
        model.json's path (empty for compiled-in code).
        """
    def parameter_names(self) -> list[str]:
        """
        The names of the parameters, in the order of the functions' parameter vector p.
        """
    def parameters(self) -> dict[str, float]:
        """
        The values by name (what a scenario file writes back).
        """
class ModelStructure:
    """
    What a model says about itself that depends on neither t nor q. Everything downstream
    sizes its arrays and indexes its states by these numbers, so a model must keep them fixed.
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
    How a closed-loop run ended.
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    completed
        integrated over the whole horizon
    diverged
        stopped when the tracking error exceeded the divergence bound (see above):
        divergence_factor times the path's scale
    lost_track
        integrated over the whole horizon, but it ended more than the scenario's
        lost_track farther from the desired path than it started (scenario.hpp)
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> hc.run_scenario(scenario).simulation.status
    <RunStatus.completed: 0>
    """
    __members__: typing.ClassVar[dict[str, RunStatus]]
    completed: typing.ClassVar[RunStatus]
    diverged: typing.ClassVar[RunStatus]
    lost_track: typing.ClassVar[RunStatus]
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    Which A the filter Riccati equation (36) uses (scenario key [measurement] filter_A).
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    estimate
        A(q_hat(t)): the decomposition (26)-(31) at the current estimate
    desired
        A_e(t): the linearization along the desired trajectory
    
    Examples
    --------
    >>> hc.OutputFeedbackOptions(filter_A="desired").filter_A
    <FilterLinearization.desired: 1>
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    What a violation of the coupling condition rho(Sigma Z) < gamma^2 does (scenario key
    [measurement] on_coupling_violation).
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    error
        a CouplingConditionError at the first output time with a violation
    flag
        continue, and report the first violation's time in the estimator series
    
    Examples
    --------
    >>> hc.OutputFeedbackOptions(on_coupling_violation="flag").on_coupling_violation
    <CouplingPolicy.flag: 1>
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    The condition a gamma fails.
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    none
        passed (or, for the bracket's lower end 0, never evaluated)
    grde
        a conjugate point of the GRDE (13), or of its discrete game (gamma_star_discrete)
    filter
        the filter Riccati equation (36) escapes or loses positive definiteness
    coupling
        rho(Sigma Z) >= gamma^2 somewhere on [t0, tf]
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    >>> scenario.tf = 10.0
    >>> hc.scenario_gamma_star(scenario).binding              # state feedback: the GRDE
    <GammaCondition.grde: 1>
    >>> hc.scenario_gamma_star_output_feedback(scenario).binding
    <GammaCondition.coupling: 3>
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    How a closed loop is simulated (scenario keys [output] dt and [solver]).
    
    Parameters
    ----------
    output_dt : float, default 0.01
        step of the output grid (s)
    divergence_factor : float, default 10.0
        stop as diverged beyond this times the path's scale (> 1)
    solver : SolverOptions, optional
        the integrator of the closed loop
    
    Raises
    ------
    ValueError
        An option out of its range, naming it.
    
    Examples
    --------
    >>> options = hc.SimulationOptions(output_dt=0.05, solver=hc.SolverOptions(method="erk"))
    >>> options.output_dt, options.solver.method
    (0.05, <Method.erk: 3>)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('output_dt', 'divergence_factor', 'solver')
    def __eq__(self, arg0: SimulationOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, output_dt: typing.SupportsFloat | typing.SupportsIndex = 0.01, divergence_factor: typing.SupportsFloat | typing.SupportsIndex = 10.0, solver: SolverOptions = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def divergence_factor(self) -> float:
        """
        stop as diverged beyond this times the path's scale (> 1)
        """
    @divergence_factor.setter
    def divergence_factor(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def output_dt(self) -> float:
        """
        step of the output grid (s)
        """
    @output_dt.setter
    def output_dt(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def solver(self) -> SolverOptions:
        """
        the integrator of the closed loop
        """
    @solver.setter
    def solver(self, arg0: SolverOptions) -> None:
        ...
class TrajectoryOptions:
    """
    Tolerances of the desired trajectory's integration (Dormand-Prince 5(4)). Tight by default:
    the trajectory is integrated once, and every design along it inherits its error.
    
    Parameters
    ----------
    rtol : float, default 1e-10
        relative tolerance, > 0
    atol : float, default 1e-12
        absolute tolerance, > 0
    max_steps : int, default 2000000
        step attempts over [t0, tf], > 0; exceeding it is a SolverError
    
    Examples
    --------
    >>> options = hc.TrajectoryOptions(rtol=1e-8, atol=1e-10)
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], [1.0, 0.0], 0.0, 10.0, options)
    >>> round(float(trajectory.q_d(10.0)[3]), 6)                # x_d(10) = 10 m at 1 m/s
    10.0
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
        """
        absolute tolerance, > 0
        """
    @atol.setter
    def atol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_steps(self) -> int:
        """
        step attempts over [t0, tf], > 0; exceeding it is a SolverError
        """
    @max_steps.setter
    def max_steps(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def rtol(self) -> float:
        """
        relative tolerance, > 0
        """
    @rtol.setter
    def rtol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Trajectory:
    """
    The desired trajectory q_d(t), u_d(t) on [t0, tf] and the linearization A_e, B_e, D_e along it.
    
    The desired (feasible) trajectory of paper eq. (8):
        dq_d/dt = f(t, q_d) + G(t, q_d) u_d(t),   q_d(t0) = q_d0,
    integrated forward once with Dormand-Prince 5(4) at tight tolerances (restarting at the points
    of table inputs, where u_d is not smooth) and kept as its dense output, so q_d(t), u_d(t) and
    the linearization along it (paper eq. 10, model.hpp)
        A_e(t) = d/dq [f + G u_d](t, q_d(t)),  B_e(t) = G(t, q_d(t)),  D_e(t) = D(t, q_d(t))
    are available at any t in [t0, tf]. A desired trajectory may also be given as states and inputs
    (a plan's nodes): each interval between nodes is then integrated from its node, so that an
    open-loop-unstable vehicle's growth acts over one interval only (second constructor).
    A Trajectory is immutable once made: its const functions
    keep no state (lookups take caller-owned cursors), so one trajectory may be read from several
    threads at once (run_scenarios shares one between runs, study.hpp).
    
    Parameters
    ----------
    model : Model
        The design model.
    q_d0 : array_like, shape (n,)
        The desired initial state q_d(t0).
    u_d : VectorSignal, callable, or list of Signal or float
        The desired inputs, m channels: a VectorSignal, a callable ``u_d(t) -> array_like, shape (m,)``
        (t in seconds), or one Signal or number per input.
    t0 : float
        The start of the horizon (s).
    tf : float
        The end of the horizon (s), > t0.
    options : TrajectoryOptions, optional
        Tolerances of the integration.
    
    Raises
    ------
    ValueError
        A model that is not valid, q_d0 not of shape (n,) or not finite, u_d without m channels,
        tf <= t0, bad options.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> trajectory.q_d(10.0).round(3)                            # [u, v, r, x, y, psi] at t = 10 s
    array([ 0.981, -0.192,  0.191,  8.814,  3.236,  1.331])
    >>> trajectory.A_e(np.array([0.0, 5.0])).shape, trajectory.B_e(0.0).shape
    ((2, 6, 6), (6, 2))
    """
    @staticmethod
    def from_states(model: Model, t: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], u_d: typing.Any, options: TrajectoryOptions = ...) -> Trajectory:
        """
        Integrates eq. (8) forward from q_d(t0) = q_d0 (n numbers) with the inputs u_d (m
        channels) over [t0, tf] (s), t0 < tf. InputError for a bad model (check_structure,
        validate_model at (t0, q_d0)), q_d0 of another size or not finite, u_d with another number
        of channels, a bad horizon or options; SolverError when the integration fails.
        
        The desired trajectory given as states and inputs: q_d(t_k) = row k of q_nodes ((N + 1) x n)
        at the nodes t_0 < t_1 < ... < t_N (t0 = t_0, tf = t_N), and on each interval [t_k, t_{k+1}]
        eq. (8) integrated from row k with u_d. The end of interval k misses node k + 1 by its defect
        d_k = |q(t_{k+1}-) - q_{k+1}|_inf, and q_d jumps by d_k there: small wherever the nodes are
        a trajectory of the model (a planner's, say), also for an open-loop-unstable vehicle, along
        which one integration over [t0, tf] from q_d0 would drift away. InputError as the
        constructor above, and for nodes that are not finite and increasing (N >= 1) or q_nodes of
        another shape or not finite; SolverError when an interval's integration fails.
        
        A trajectory from a dense output integrated before (by a constructor above; e.g. read back
        from a pickle): the same input checks, and `dense` must have n components and cover
        [t0, tf]; the nodes and defects of a trajectory given as states, if it was one.
        
        The desired trajectory given as states and inputs.
        
        Parameters
        ----------
        model : Model
            The design model.
        t : array_like, shape (N + 1,)
            The nodes t_0 < ... < t_N (s): the horizon [t_0, t_N].
        q : array_like, shape (N + 1, n)
            The desired states at the nodes.
        u_d : VectorSignal, callable, or list of Signal or float
            The desired inputs, m channels.
        options : TrajectoryOptions, optional
            Tolerances of each interval's integration.
        
        Returns
        -------
        Trajectory
            Each interval integrated from its node; defects() are the misses at the next nodes.
        
        Raises
        ------
        ValueError
            Nodes not increasing or not finite, q not of shape (N + 1, n), a bad model or u_d.
        SolverError
            An interval's integration failed.
        
        Examples
        --------
        >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
        >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
        >>> t = np.linspace(0.0, 10.0, 11)
        >>> again = hc.Trajectory.from_states(hc.ShipModel(), t, trajectory.q_d(t), u_d)
        >>> len(again.defects()), bool(again.max_defect() < 1e-8)
        (10, True)
        """
    def A_e(self, t: typing.Any) -> typing.Any:
        """
        A_e(t) = d/dq [f + G u_d] at q_d(t), B_e(t) = G(t, q_d(t)), D_e(t) = D(t, q_d(t)).
        
        Shape (n, n) for a number t, (k, n, n) for a 1-D array of k times.
        """
    def B_e(self, t: typing.Any) -> typing.Any:
        """
        A_e(t) = d/dq [f + G u_d] at q_d(t), B_e(t) = G(t, q_d(t)), D_e(t) = D(t, q_d(t)).
        
        Shape (n, m) for a number t, (k, n, m) for a 1-D array of k times.
        """
    def D_e(self, t: typing.Any) -> typing.Any:
        """
        A_e(t) = d/dq [f + G u_d] at q_d(t), B_e(t) = G(t, q_d(t)), D_e(t) = D(t, q_d(t)).
        
        Shape (n, nw) for a number t, (k, n, nw) for a 1-D array of k times.
        """
    def __getstate__(self) -> tuple[Model, typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"], VectorSignal, float, float, PiecewisePolynomial, StepStats, list[float], list[float]]:
        ...
    def __init__(self, model: Model, q_d0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u_d: typing.Any, t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex, options: TrajectoryOptions = ...) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def defects(self) -> list[float]:
        """
        A trajectory given as states: its nodes t_0 .. t_N (s) and the defect d_k of each interval
        (N numbers, in the states' units); both empty for a trajectory integrated from q_d0 alone.
        """
    def dense(self) -> PiecewisePolynomial:
        """
        The dense output of q_d (n components) and the counts of its integration.
        """
    def m(self) -> int:
        """
        The model's number of states and of inputs.
        """
    def max_defect(self) -> float:
        """
        The largest defect (0 without nodes) and the start of its interval (NaN without nodes).
        """
    def max_defect_t(self) -> float:
        """
        The largest defect (0 without nodes) and the start of its interval (NaN without nodes).
        """
    def model(self) -> Model:
        """
        The model integrated: the design model of everything built on this trajectory.
        """
    def n(self) -> int:
        """
        The model's number of states and of inputs.
        """
    def node_times(self) -> list[float]:
        """
        A trajectory given as states: its nodes t_0 .. t_N (s) and the defect d_k of each interval
        (N numbers, in the states' units); both empty for a trajectory integrated from q_d0 alone.
        """
    def q_d(self, t: typing.Any) -> typing.Any:
        """
        The desired state q_d(t) (n) from the dense output; t outside [t0, tf] is an InputError.
        
        Shape (n,) for a number t, (k, n) for a 1-D array of k times.
        """
    def q_d0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        The desired initial state q_d(t0) and the desired inputs u_d, as given.
        """
    def stats(self) -> StepStats:
        """
        The dense output of q_d (n components) and the counts of its integration.
        """
    def t0(self) -> float:
        """
        The horizon [t0, tf] (s).
        """
    def tf(self) -> float:
        """
        The horizon [t0, tf] (s).
        """
    def u_d(self, t: typing.Any) -> typing.Any:
        """
        The desired input u_d(t) (m): the signal, at any t.
        
        Shape (m,) for a number t, (k, m) for a 1-D array of k times.
        """
    def u_d_signal(self) -> VectorSignal:
        """
        The desired initial state q_d(t0) and the desired inputs u_d, as given.
        """
class SolveStats:
    """
    The counts of a Riccati solve or a closed-loop run, and the size of what it stored.
    
    Attributes
    ----------
    steps : int
        accepted steps
    rejected : int
        rejected steps (error test failures)
    rhs_evals : int
        right-hand-side evaluations
    jac_evals : int
        Jacobians (dense) or Schur factorizations (Lyapunov Newton systems)
    memory_bytes : int
        stored dense output
    method : str
        the integrator that solved it: "erk", "adams", "bdf (dense Newton)",
        "bdf (Lyapunov Newton)", or "erk, then bdf (...) from t = ..." for
        Method::Auto
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> stats = design.stats()
    >>> stats.method, stats.steps > 0, stats.memory_bytes == design.dense().memory_bytes()
    ('erk', True, True)
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
        """
        Jacobians (dense) or Schur factorizations (Lyapunov Newton systems)
        """
    @property
    def memory_bytes(self) -> int:
        """
        stored dense output
        """
    @property
    def method(self) -> str:
        """
        the integrator that solved it: "erk", "adams", "bdf (dense Newton)",
        "bdf (Lyapunov Newton)", or "erk, then bdf (...) from t = ..." for
        Method::Auto
        """
    @property
    def rejected(self) -> int:
        """
        rejected steps (error test failures)
        """
    @property
    def rhs_evals(self) -> int:
        """
        right-hand-side evaluations
        """
    @property
    def steps(self) -> int:
        """
        accepted steps
        """
class SymmetricSolution:
    """
    A symmetric-matrix-valued solution X(t) on [t0, tf] kept as dense output.
    
    The base of RiccatiSolution (Z) and FilterRiccatiSolution (Sigma), made by the solvers.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> isinstance(design, hc.SymmetricSolution), design.n(), design.gamma()
    (True, 6, 5.0)
    >>> np.round(design.eigenvalue_bounds(), 3)                   # m and M of eq. (22)
    array([ 0.219, 20.815])
    """
    def blocks(self) -> list[int]:
        """
        The sizes of the diagonal blocks X is stored in ({n}: the whole X).
        """
    def dense(self) -> PiecewisePolynomial:
        """
        The dense output of X as stored (PackedBlocks of blocks(): the packed upper triangle,
        n(n+1)/2 components, unless X was solved in uncoupled blocks) and the counts of its solve.
        """
    def derivative(self, t: typing.Any) -> typing.Any:
        """
        dX/dt at t (per second): the derivative of the dense output.
        
        Shape (n, n) for a number t, (k, n, n) for a 1-D array of k times.
        """
    def eigenvalue_bounds(self) -> tuple:
        """
        m and M with m I <= X(t) <= M I on the whole interval (paper eq. 22): the extremes over
        the ends and midpoints of the solver's steps, each refined by a golden-section search
        over the neighbouring steps.
        
        Returns (m, M).
        """
    def eigenvalue_range(self, times: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex]) -> tuple:
        """
        Smallest and largest eigenvalue of X over the given times.
        
        Returns (smallest, largest); times (s): a non-empty list.
        """
    def gamma(self) -> float:
        """
        The gamma of the equation (+inf: LQR, or the Kalman-Bucy filter).
        """
    def n(self) -> int:
        """
        The size of X: n x n, the trajectory's states.
        """
    def stats(self) -> SolveStats:
        """
        The dense output of X as stored (PackedBlocks of blocks(): the packed upper triangle,
        n(n+1)/2 components, unless X was solved in uncoupled blocks) and the counts of its solve.
        """
    def t0(self) -> float:
        """
        The horizon [t0, tf] (s), the trajectory's.
        """
    def tf(self) -> float:
        """
        The horizon [t0, tf] (s), the trajectory's.
        """
    def trajectory(self) -> Trajectory:
        """
        The desired trajectory it was solved along.
        """
    def value(self, t: typing.Any) -> typing.Any:
        """
        X(t) (n x n, symmetric) from the dense output; t outside [t0, tf] is an InputError.
        
        Shape (n, n) for a number t, (k, n, n) for a 1-D array of k times.
        """
class RiccatiSolution(SymmetricSolution):
    """
    Z(t) of the GRDE (13).
    
    The matrix Riccati differential equations of the paper, solved along a desired trajectory.
    
    GRDE, paper eq. (13), solved BACKWARD from Z(tf) = Qf:
        -dZ/dt = A_e' Z + Z A_e + Q - Z (B B' - gamma^-2 D D') Z.
    Sign convention: Z > 0 is the cost-to-go matrix, V(t, q_e) = q_e' Z(t) q_e; the
    state-feedback law (17)/(18) is u = u_d - kappa B' Z q_e. gamma = +inf gives LQR. Here
    A = A_e(t), B = B_e(t) and D = D_e(t), the linearization along the desired trajectory
    (model.hpp, trajectory.hpp).
    
    Filter Riccati equation, paper eq. (36), solved FORWARD from Sigma(t0) = (Q0 - eta I)^-1:
        dSigma/dt = A Sigma + Sigma A' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D D',
    here with A = A_e(t) (the linearization along the desired path; the output-feedback
    simulation also offers A(q_hat(t)), see output_feedback.hpp).
    
    Both solutions are kept as the integrator's dense output (symmetric half, types.hpp), so
    they are available at any t in [t0, tf] with the integrator's accuracy. A finite escape
    (a conjugate point: gamma <= gamma*, eq. 14) raises ConjugatePointError with the
    estimated escape time. A solution is immutable once solved (no caches; lookups take
    caller-owned cursors): several threads may evaluate one at once (run_scenarios shares one
    between runs, study.hpp).
    
    Made by solve_grde (and run_scenario); it pickles with its trajectory.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> design.Z(np.array([0.0, 5.0, 10.0])).shape                  # Z(t) at three times
    (3, 6, 6)
    >>> np.allclose(design.Z(10.0), np.eye(6)), design.gain(0.0).shape   # Z(tf) = Qf; K = B' Z
    (True, (2, 6))
    """
    def Z(self, t: typing.Any) -> typing.Any:
        """
        Z(t) (n x n) and dZ/dt: value(t) and derivative(t).
        
        Shape (n, n) for a number t, (k, n, n) for a 1-D array of k times.
        """
    def __getstate__(self) -> tuple[Trajectory, float, PiecewisePolynomial, SolveStats, list[int]]:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def dZdt(self, t: typing.Any) -> typing.Any:
        """
        Z(t) (n x n) and dZ/dt: value(t) and derivative(t).
        
        Shape (n, n) for a number t, (k, n, n) for a 1-D array of k times.
        """
    def gain(self, t: typing.Any) -> typing.Any:
        """
        K(t) = B_e(t)' Z(t) (m x n), the gain of the state-feedback law (17), B_e(t) = G(t, q_d(t)).
        
        Shape (m, n) for a number t, (k, m, n) for a 1-D array of k times.
        """
    def m(self) -> int:
        """
        The model's number of inputs (the rows of the gain).
        """
class FilterRiccatiSolution(SymmetricSolution):
    """
    Sigma(t) of the filter Riccati equation (36) with A = A_e(t).
    
    Made by solve_filter_riccati; it pickles with its trajectory.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> Sigma = hc.solve_filter_riccati(trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
    >>> np.allclose(Sigma.Sigma(0.0), np.eye(6)), Sigma.Sigma(10.0).diagonal().round(3)
    (True, array([0.431, 0.377, 0.384, 0.276, 0.298, 0.272]))
    """
    def Sigma(self, t: typing.Any) -> typing.Any:
        """
        Sigma(t) (n x n) and dSigma/dt: value(t) and derivative(t).
        
        Shape (n, n) for a number t, (k, n, n) for a 1-D array of k times.
        """
    def __getstate__(self) -> tuple[Trajectory, float, PiecewisePolynomial, SolveStats, list[int]]:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def dSigma_dt(self, t: typing.Any) -> typing.Any:
        """
        Sigma(t) (n x n) and dSigma/dt: value(t) and derivative(t).
        
        Shape (n, n) for a number t, (k, n, n) for a 1-D array of k times.
        """
class Controller:
    """
    A tracking law u = control(t, q) of the actual state q; the closed loops call it at every
    stage of the integrator.
    
    Tracking controllers: u = control(t, q) for the actual state q.
    
    Notes
    -----
    Subclass it in Python and implement m() and control(t, q) -> array_like of shape (m,) (q: the
    actual state, shape (n,); t in seconds), and optionally name() and n(). It is called at every
    stage of the integrator, holding the GIL.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> class OpenLoop(hc.Controller):
    ...     def m(self): return 2
    ...     def control(self, t, q): return trajectory.u_d(t)      # u = u_d(t): no feedback
    >>> run = hc.simulate_state_feedback(trajectory, OpenLoop(), None, [1, 0, 0, 0, 0, 0])
    >>> bool(np.abs(run.q - run.q_d).max() < 1e-6)               # from q_d(t0): stays on q_d
    True
    """
    def __init__(self) -> None:
        ...
    def control(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        u (m) at time t for the actual state q (n). Controllers may keep lookup cursors: use one
        controller object per thread.
        
        Returns u, shape (m,).
        """
    def m(self) -> int:
        """
        The number of inputs: control() writes u of m() numbers.
        """
    def n(self) -> int:
        """
        The state size: control() takes q of n() numbers. A controller implemented in Python may
        leave n() out (it reads q as a NumPy array of whatever length it is given): it then
        reports 0, and callers check q against their model instead.
        """
    def name(self) -> str:
        """
        The law's name ("hinf", "lqr", "cascade", ...), for results and messages.
        """
class HinfStateFeedback(Controller):
    """
    The H-infinity state-feedback tracking law, paper eqs. (17)/(18):
        u = u_d(t) - kappa(t) B_e(t)' Z(t) (q - q_d(t)),  B_e(t) = G(t, q_d(t)),
    with the heading component of q - q_d wrapped to (-pi, pi] (angles.hpp).
    kappa = 1 is the saddle-point (optimal) law (15); kappa >= 1/2 keeps the Lyapunov proof
    of local exponential stability (eq. 23). kappa must stay > 0.
    
    The law of the design `solution` (Z of the GRDE along its trajectory) with the gain
    scaling kappa(t) (checked > 0 where the law evaluates it). InputError without a solution.
    
    Parameters
    ----------
    solution : RiccatiSolution
        The design Z (solve_grde).
    kappa : Signal or float, default 1.0
        The gain scaling kappa(t), > 0 (>= 1/2 for the certificates).
    
    Raises
    ------
    ValueError
        No solution; later, kappa(t) <= 0 where the law evaluates it.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> law = hc.HinfStateFeedback(design, kappa=1.0)
    >>> q0 = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])      # 1 m behind, 1 m aside, 45 deg off
    >>> law.name(), law.control(0.0, q0).round(3)
    ('hinf', array([ 2.035, -1.947]))
    """
    def __init__(self, solution: RiccatiSolution, kappa: typing.Any = ...) -> None:
        ...
    def checked_kappa(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        kappa(t); an InputError if it is not > 0.
        """
    def kappa(self) -> Signal:
        """
        The design Z and the gain scaling kappa(t) of the law.
        """
    def solution(self) -> RiccatiSolution:
        """
        The design Z and the gain scaling kappa(t) of the law.
        """
class BacksteppingGains:
    """
    The gains of the backstepping law (BacksteppingController), each finite and > 0.
    
    Parameters
    ----------
    k : float, default 0.5
        position: commanded velocity p_d' - k (p - p_d) (1/s)
    k1 : float, default 1.0
        heading towards the commanded velocity (1/s)
    k2 : float, default 2.0
        yaw rate (1/s)
    k3 : float, default 1.0
        surge speed (1/s)
    
    Examples
    --------
    >>> hc.BacksteppingGains(k=0.3)
    BacksteppingGains(k=0.3, k1=1.0, k2=2.0, k3=1.0)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('k', 'k1', 'k2', 'k3')
    def __eq__(self, arg0: BacksteppingGains) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, k: typing.SupportsFloat | typing.SupportsIndex = 0.5, k1: typing.SupportsFloat | typing.SupportsIndex = 1.0, k2: typing.SupportsFloat | typing.SupportsIndex = 2.0, k3: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def k(self) -> float:
        """
        position: commanded velocity p_d' - k (p - p_d) (1/s)
        """
    @k.setter
    def k(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def k1(self) -> float:
        """
        heading towards the commanded velocity (1/s)
        """
    @k1.setter
    def k1(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def k2(self) -> float:
        """
        yaw rate (1/s)
        """
    @k2.setter
    def k2(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def k3(self) -> float:
        """
        surge speed (1/s)
        """
    @k3.setter
    def k3(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class BacksteppingController(Controller):
    """
    With p = (x, y), the commanded earth-frame velocity v_c = dp_d/dt - k (p - p_d) gives the
    heading command psi_c = atan2(v_c) - beta_d and the surge command u_c = |v_c| cos(beta_d),
    beta_d = atan2(v_d, u_d) the desired sideslip (the heading and surge that make the commanded
    course and speed on the desired trajectory); the yaw rate is backstepped through
    r_c = dpsi_c/dt - k1 z1:
        z1 = wrap(psi - psi_c),  z2 = r - r_c,
        u2 = -m_r u v + d_r r + dr_d/dt - z1 - k2 z2,
        u1 = -m_u v r + d_u u + du_c/dt - k3 (u - u_c),
    with dpsi_c/dt and du_c/dt exact (from dv_c/dt = d2p_d/dt2 - k (dp/dt - dp_d/dt)) and dr_c/dt
    replaced by the desired yaw acceleration dr_d/dt, equal on the desired trajectory: the desired
    trajectory is a solution of the closed loop. The sideslip is the desired one, not the
    measured atan2(v, u): fed back, the measured one makes the sway's zero dynamics
    (1 + m_v) dv/dt = -d_v v + ... unstable for m_v < -1 (the paper's ship has m_v = -2). The
    ship moves forward (u_c >= 0 while |beta_d| < pi/2), so a desired point behind it is reached
    by turning round. Where |v_c| vanishes the heading command holds the heading. Needs the
    ShipModel (its parameters). Written from the ship's equations after Godhavn's construction
    (position as the output, the commanded velocity's direction as the heading command,
    backstepping through the yaw rate), not transcribed from his text.
    
    InputError unless the trajectory's model is a ShipModel and the gains are finite and > 0.
    
    Parameters
    ----------
    trajectory : Trajectory
        A desired trajectory of a ShipModel.
    gains : BacksteppingGains, optional
        k, k1, k2, k3 > 0.
    
    Raises
    ------
    ValueError
        A model other than the ship, or gains not > 0.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> law = hc.BacksteppingController(trajectory)
    >>> run = hc.simulate_state_feedback(trajectory, law, None, [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
    >>> law.name(), bool(np.hypot(*run.q_e()[-1, 3:5]) < np.hypot(1.0, 1.0))  # closer at 10 s
    ('backstepping', True)
    """
    def __init__(self, trajectory: Trajectory, gains: BacksteppingGains = ...) -> None:
        ...
    def gains(self) -> BacksteppingGains:
        """
        The gains it was made with.
        """
class CascadeGains:
    """
    The gains of the cascade law (CascadeController), each finite and > 0.
    
    Parameters
    ----------
    k : float, default 0.2
        surge/position loop (0.2 converges fastest on the paper's path)
    k1 : float, default 2.0
        heading
    k2 : float, default 3.0
        yaw rate
    
    Examples
    --------
    >>> hc.CascadeGains(k=0.5)
    CascadeGains(k=0.5, k1=2.0, k2=3.0)
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
        """
        surge/position loop (0.2 converges fastest on the paper's path)
        """
    @k.setter
    def k(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def k1(self) -> float:
        """
        heading
        """
    @k1.setter
    def k1(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def k2(self) -> float:
        """
        yaw rate
        """
    @k2.setter
    def k2(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class CascadeController(Controller):
    """
    A cascaded tracking controller for the ship, of the type of Lefeber, Pettersen & Nijmeijer
    (IEEE TCST 11(1), 2003), used as a baseline. With z1 = x cos(psi) + y sin(psi) (the same for
    the desired state), z1e = z1 - z1d, z3e = psi - psi_d wrapped to (-pi, pi], u_e = u - u_d,
    v_e = v - v_d, r_e = r - r_d and gains k, k1, k2 > 0:
        p  = z1e - (m_v / d_v) u_e,
        u1 = u1d + (d_u + d_v / m_v) u_e - (m_u + 1 / m_v) r_d v_e + k (d_v / m_v) p,
        u2 = u2d - m_r (u v - u_d v_d) + d_r r_e - k1 z3e - k2 r_e.
    The yaw loop is an exact feedback linearization; the surge loop relies on the desired yaw
    rate r_d being persistently exciting: on a straight line (r_d = 0) a lateral offset is not
    corrected (docs/baselines.md). Needs the ShipModel (it uses its parameters).
    
    InputError unless the trajectory's model is a ShipModel (with m_v != 0 and d_v != 0) and
    the gains are finite and > 0.
    
    Parameters
    ----------
    trajectory : Trajectory
        A desired trajectory of a ShipModel.
    gains : CascadeGains, optional
        k, k1, k2 > 0.
    
    Raises
    ------
    ValueError
        A model other than the ship, or gains not > 0.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> law = hc.CascadeController(trajectory, hc.CascadeGains(k=0.2))
    >>> run = hc.simulate_state_feedback(trajectory, law, None, [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
    >>> law.name(), round(float(np.hypot(*run.q_e()[-1, 3:5])), 2)  # position error at 10 s (m)
    ('cascade', 1.34)
    """
    def __init__(self, trajectory: Trajectory, gains: CascadeGains = ...) -> None:
        ...
    def gains(self) -> CascadeGains:
        """
        The gains it was made with.
        """
class Disturbance:
    """
    The disturbance w(t, q) applied to a closed loop: signals, plus the worst-case disturbance of
    a design when one is given.
    
    The disturbance w applied to the plant (all nw channels of the model):
        w(t, q) = signals(t) [+ w*(t, q)],
    where w* = gamma^-2 D_e(t)' Z(t) (q - q_d(t)) is the worst-case disturbance of paper eq. (16)
    for a design Z at gamma (scenario key [disturbance] worst_case = true): the adversary of the
    game, feeding back the true error. Z may also be a law's closed-loop P at gamma
    (solve_law_riccati): then w* is that law's own worst case (for the H-infinity law at its gamma
    P = Z).
    
    Wherever a Disturbance is expected, a VectorSignal (or what one is made from) is taken too.
    
    Parameters
    ----------
    signals : VectorSignal
        w(t), the model's nw channels: ``Disturbance(signals)`` is the signals alone.
    design : RiccatiSolution or SymmetricSolution
        ``Disturbance(signals, design)`` adds the worst-case disturbance gamma^-2 D_e' X q_e of this
        solution X at its finite gamma: a design Z (eq. 16), or a law's own P
        (solve_law_riccati).
    
    Raises
    ------
    ValueError
        signals without nw channels, no design, or a design at gamma = inf.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> w = hc.Disturbance(hc.VectorSignal([0.1, 0.1, 0.1, 0, 0, 0]), design)
    >>> q0 = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
    >>> w.worst_case(), w.eval(0.0, q0).round(4)                  # signals + gamma^-2 D' Z q_e
    (True, array([0.0586, 0.1472, 0.1779, 0.    , 0.    , 0.    ]))
    """
    @typing.overload
    def __init__(self, signals: VectorSignal) -> None:
        ...
    @typing.overload
    def __init__(self, signals: VectorSignal, design: SymmetricSolution) -> None:
        ...
    def design(self) -> SymmetricSolution:
        """
        The design of the worst-case part (null without one); q in eval() has design()->n() numbers.
        """
    def dim(self) -> int:
        """
        The number of channels: the model's nw.
        """
    def eval(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        w at time t for the actual state q (n numbers); writes dim() numbers. Safe to call from
        several threads at once (it keeps no state between calls).
        
        Returns w, shape (nw,); q is read by the worst case only.
        """
    def signals(self) -> VectorSignal:
        """
        The signals w(t) without the worst-case part.
        """
    def worst_case(self) -> bool:
        """
        True when the worst-case disturbance of a design is added.
        """
class EstimatorSeries:
    """
    The estimator's series of an output-feedback run (paper §4), on the same output grid.
    
    Attributes
    ----------
    q_hat : ndarray, shape (k, n)
        estimate of the error q_e (n)
    y : ndarray, shape (k, p)
        measurement y (p)
    sigma_min_eig : ndarray, shape (k,)
        smallest eigenvalue of the filter Riccati solution Sigma(t)
    sigma_max_eig : ndarray, shape (k,)
        largest eigenvalue of Sigma(t)
    rho_sigma_z : ndarray, shape (k,)
        spectral radius of Sigma(t) Z(t)
    coupling_violation_t : float
        first output time with rho(Sigma Z) >= gamma^2, if any
    
    Notes
    -----
    k is the number of output times, p the number of measured outputs.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    >>> scenario.tf = 10.0
    >>> estimator = hc.run_scenario(scenario).simulation.estimator
    >>> estimator.q_hat.shape, estimator.y.shape, bool(estimator.rho_sigma_z.max() < 25.0)
    ((1001, 6), (1001, 3), True)
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
        """
        first output time with rho(Sigma Z) >= gamma^2, if any
        """
    @property
    def q_hat(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        estimate of the error q_e (n)
        """
    @property
    def rho_sigma_z(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        spectral radius of Sigma(t) Z(t)
        """
    @property
    def sigma_max_eig(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        largest eigenvalue of Sigma(t)
        """
    @property
    def sigma_min_eig(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        smallest eigenvalue of the filter Riccati solution Sigma(t)
        """
    @property
    def y(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        measurement y (p)
        """
class SimulationResult:
    """
    Time series on the output grid, one row per time.
    
    Attributes
    ----------
    t : ndarray, shape (k,)
        output times (s), from t0
    q : ndarray, shape (k, n)
        actual state (n)
    q_d : ndarray, shape (k, n)
        desired state (n)
    u : ndarray, shape (k, m)
        applied control (m)
    u_d : ndarray, shape (k, m)
        desired control (m)
    w : ndarray, shape (k, nw)
        applied disturbance (nw), noise channels included for output feedback
    estimator : EstimatorSeries or None
        output feedback only
    status : RunStatus
        how the run ended
    status_message : str
        why the run stopped early or lost the track; empty when completed
    heading_index : int
        the model's heading component (angles.hpp), -1 if none
    integrator : str
        how the closed loop was integrated
    stats : SolveStats
        the counts of the closed loop's integration
    
    Notes
    -----
    k is the number of output times.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> run = hc.run_scenario(scenario).simulation
    >>> run.t.shape, run.q.shape, run.u.shape, run.status
    ((1001,), (1001, 6), (1001, 2), <RunStatus.completed: 0>)
    >>> round(float(np.hypot(*run.q_e()[0, 3:5])), 3)              # initial position error (m)
    1.414
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
        The tracking errors q - q_d, one row per output time, the heading component wrapped to
        (-pi, pi].
        
        Shape (k, n).
        """
    @property
    def estimator(self) -> EstimatorSeries:
        """
        output feedback only
        
        None under state feedback.
        """
    @property
    def heading_index(self) -> int:
        """
        the model's heading component (angles.hpp), -1 if none
        """
    @property
    def integrator(self) -> str:
        """
        how the closed loop was integrated
        """
    @property
    def q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        actual state (n)
        """
    @property
    def q_d(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        desired state (n)
        """
    @property
    def stats(self) -> SolveStats:
        """
        the counts of the closed loop's integration
        """
    @property
    def status(self) -> RunStatus:
        """
        how the run ended
        """
    @property
    def status_message(self) -> str:
        """
        why the run stopped early or lost the track; empty when completed
        """
    @property
    def t(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        output times (s), from t0
        """
    @property
    def u(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        applied control (m)
        """
    @property
    def u_d(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        desired control (m)
        """
    @property
    def w(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        applied disturbance (nw), noise channels included for output feedback
        """
class OutputFeedbackProblem:
    """
    The output-feedback problem: the design, the measurement noise and the filter's weights.
    
    Parameters
    ----------
    design : RiccatiSolution, optional
        Z of the GRDE (13): its gamma and trajectory
    sigma : float, default 0.0
        noise standard deviation: E w = sigma v on the noise channels
    sample_period : float, default 0.01
        T (s): v is held over [t0 + k T, t0 + (k+1) T)
    noise : array_like, shape (k, p), optional
        v: standard normal samples, one row per hold interval
        (noise_sample_count rows), one column per measured output
    N : array_like, shape (p, p), optional
        filter weight N = E E' (p x p, positive definite)
    Sigma0 : array_like, shape (n, n), optional
        Sigma(t0) = (Q0 - eta I)^-1 (n x n, positive definite)
    Q : array_like, shape (n, n), optional
        weight of the performance index, in (36)
    
    Notes
    -----
    k is noise_sample_count(t0, tf, sample_period), p the number of measured outputs (rows of the
    model's C).
    
    Raises
    ------
    ValueError
        sigma < 0, sample_period <= 0, N or Sigma0 not symmetric positive definite, Q not
        symmetric positive semidefinite of Sigma0's size, noise not finite; the sizes against the
        design's model are checked by simulate_output_feedback.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> noise = hc.scenario_noise(hc.load_scenario(hc.scenario_path("paper_fig2")))[:1000]
    >>> problem = hc.OutputFeedbackProblem(design, sigma=0.5, sample_period=0.01, noise=noise,
    ...                                    N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
    >>> problem.noise.shape, problem.design.gamma()
    ((1000, 3), 5.0)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('design', 'sigma', 'sample_period', 'noise', 'N', 'Sigma0', 'Q')
    def __eq__(self, arg0: OutputFeedbackProblem) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, design: RiccatiSolution = None, sigma: typing.SupportsFloat | typing.SupportsIndex = 0.0, sample_period: typing.SupportsFloat | typing.SupportsIndex = 0.01, noise: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def N(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        filter weight N = E E' (p x p, positive definite)
        """
    @N.setter
    def N(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        weight of the performance index, in (36)
        """
    @Q.setter
    def Q(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Sigma0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Sigma(t0) = (Q0 - eta I)^-1 (n x n, positive definite)
        """
    @Sigma0.setter
    def Sigma0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def design(self) -> RiccatiSolution:
        """
        Z of the GRDE (13): its gamma and trajectory
        """
    @design.setter
    def design(self, arg0: RiccatiSolution) -> None:
        ...
    @property
    def noise(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        v: standard normal samples, one row per hold interval
        (noise_sample_count rows), one column per measured output
        """
    @noise.setter
    def noise(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def sample_period(self) -> float:
        """
        T (s): v is held over [t0 + k T, t0 + (k+1) T)
        """
    @sample_period.setter
    def sample_period(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def sigma(self) -> float:
        """
        noise standard deviation: E w = sigma v on the noise channels
        """
    @sigma.setter
    def sigma(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class OutputFeedbackOptions:
    """
    The choices of the output-feedback loop.
    
    Parameters
    ----------
    filter_A : FilterLinearization or str, default 'estimate'
        the A of the filter (36)
    on_coupling_violation : CouplingPolicy or str, default 'error'
        what a violation does
    sigma_eigenvalues : bool, default True
        the series EstimatorSeries::sigma_min_eig and sigma_max_eig
        (false: NaN). Every other output, the metrics and the check
        that Sigma stays positive semidefinite are the same either
        way; run_scenarios, which keeps only the metrics, turns it
        off (a third of a Figure 2 run's time goes to eigenvalues on
        the output grid).
    
    Examples
    --------
    >>> hc.OutputFeedbackOptions(on_coupling_violation="flag", sigma_eigenvalues=False)
    OutputFeedbackOptions(filter_A='estimate', on_coupling_violation='flag', sigma_eigenvalues=False)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('filter_A', 'on_coupling_violation', 'sigma_eigenvalues')
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
        """
        the A of the filter (36)
        """
    @filter_A.setter
    def filter_A(self, arg1: FilterLinearization | str) -> None:
        ...
    @property
    def on_coupling_violation(self) -> CouplingPolicy:
        """
        what a violation does
        """
    @on_coupling_violation.setter
    def on_coupling_violation(self, arg1: CouplingPolicy | str) -> None:
        ...
    @property
    def sigma_eigenvalues(self) -> bool:
        """
        the series EstimatorSeries::sigma_min_eig and sigma_max_eig
        (false: NaN). Every other output, the metrics and the check
        that Sigma stays positive semidefinite are the same either
        way; run_scenarios, which keeps only the metrics, turns it
        off (a third of a Figure 2 run's time goes to eigenvalues on
        the output grid).
        """
    @sigma_eigenvalues.setter
    def sigma_eigenvalues(self, arg0: bool) -> None:
        ...
class MetricDefinition:
    """
    The definition of one metric: a row of metric_table().
    
    Examples
    --------
    >>> definition = hc.metric_table()[0]
    >>> definition.name, definition.unit, definition.definition
    ('rms_position_error_last_half', 'm', 'sqrt(mean over the last half of |p - p_d|^2)')
    """
    def __repr__(self) -> str:
        ...
    @property
    def definition(self) -> str:
        """
        what is computed
        """
    @property
    def label(self) -> str:
        """
        for tables
        """
    @property
    def name(self) -> str:
        """
        key in the results file and in Python's RunResult.metrics
        """
    @property
    def unit(self) -> str:
        """
        for the ship; "-" is dimensionless
        """
class Metrics:
    """
    The metrics of one run, each defined by its row of metric_table().
    
    Metrics of a closed-loop run. metric_table() is their one definition (name, label, unit,
    definition): the results file, the bindings, the Python tables and docs/results.md all
    come from it. Integrals are trapezoid sums over the output grid; "position" is the model's
    position_indices() (x, y for the ship), "heading" its heading_index(); the heading error is
    wrapped to (-pi, pi] (angles.hpp); "last half" is the grid points with t >= (t0 + tf)/2.
    The tracking cost is the paper's L of eq. (37) on the run's errors (epsilon = 0):
        L = |q_e(tf)|_Qf^2 + integral of |q_e|_Q^2 + |u - u_d|^2 dt,
    and the attenuation margin compares it with the right side of the H-infinity law's bound
    (eq. 39 with M = 0, which holds for the linearized loop):
        margin = 1 - L / (gamma^2 ||w||^2 + initial_term),
    initial_term = q_e(t0)' Z(t0) q_e(t0) with state feedback (the game's value), gamma^2
    q_e(t0)' Q0 q_e(t0) with output feedback (eq. 39; the estimate starts at 0, w includes the
    measurement noise channels); negative when the bound is exceeded.
    A metric that does not apply (no position, no heading, no disturbance, no output feedback,
    no bound) is NaN. A run that stopped early (status Diverged) reports only
    max_position_error and heading_excursion, over the part it ran.
    
    Attributes
    ----------
    rms_position_error_last_half : float
        sqrt(mean over the last half of |p - p_d|^2) (unit: m)
    max_position_error : float
        max over the grid of |p - p_d| (unit: m)
    final_position_error : float
        |p - p_d| at tf (unit: m)
    rms_heading_error_last_half : float
        sqrt(mean over the last half of wrap(psi - psi_d)^2) (unit: rad)
    final_heading_error : float
        |wrap(psi - psi_d)| at tf (unit: rad)
    heading_excursion : float
        max over the grid of |e|, e = psi - psi_d followed continuously from wrap(e(t0)) (a full
        turn reads 2 pi) (unit: rad)
    turned_around : float
        1 when |e| passes max(pi, |e(t0)|) + 0.1 (through +-pi) or |wrap(e)| > pi/2 on more than
        half of the last half (tracks backwards), else 0 (docs/baselines.md) (unit: -)
    control_l2 : float
        sqrt(integral of |u|^2) (unit: input s^1/2)
    control_error_l2 : float
        sqrt(integral of |u - u_d|^2) (unit: input s^1/2)
    disturbance_l2 : float
        sqrt(integral of |w|^2) over every applied channel (the noise channels when sigma > 0)
        (unit: w s^1/2)
    disturbance_gain : float
        sqrt(tracking_cost) / disturbance_l2 for a run that starts on the desired trajectory
        (q_e(t0) = 0); NaN from any other start (see response_ratio) (unit: -)
    response_ratio : float
        sqrt(tracking_cost) / disturbance_l2 from any start: includes the response to the initial
        error (unit: -)
    tracking_cost : float
        |q_e(tf)|_Qf^2 + integral of |q - q_d|_Q^2 + |u - u_d|^2 (unit: -)
    attenuation_margin : float
        1 - tracking_cost / (gamma^2 disturbance_l2^2 + the initial-error term): >= 0 when the
        H-infinity law's bound holds (hinf law only) (unit: -)
    max_rho_sigma_z : float
        max over the grid of the spectral radius of Sigma Z (output feedback; below gamma^2) (unit:
        -)
    rms_estimation_error_last_half : float
        sqrt(mean over the last half of |q_hat - (q - q_d)|^2) (output feedback) (unit: state)
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> metrics = hc.run_scenario(scenario).metrics
    >>> round(metrics.max_position_error, 3), metrics.max_rho_sigma_z        # NaN: state feedback
    (1.414, nan)
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
    def attenuation_margin(self) -> float:
        """
        1 - tracking_cost / (gamma^2 disturbance_l2^2 + the initial-error term): >= 0 when the H-infinity law's bound holds (hinf law only) (unit: -)
        """
    @property
    def control_error_l2(self) -> float:
        """
        sqrt(integral of |u - u_d|^2) (unit: input s^1/2)
        """
    @property
    def control_l2(self) -> float:
        """
        sqrt(integral of |u|^2) (unit: input s^1/2)
        """
    @property
    def disturbance_gain(self) -> float:
        """
        sqrt(tracking_cost) / disturbance_l2 for a run that starts on the desired trajectory (q_e(t0) = 0); NaN from any other start (see response_ratio) (unit: -)
        """
    @property
    def disturbance_l2(self) -> float:
        """
        sqrt(integral of |w|^2) over every applied channel (the noise channels when sigma > 0) (unit: w s^1/2)
        """
    @property
    def final_heading_error(self) -> float:
        """
        |wrap(psi - psi_d)| at tf (unit: rad)
        """
    @property
    def final_position_error(self) -> float:
        """
        |p - p_d| at tf (unit: m)
        """
    @property
    def heading_excursion(self) -> float:
        """
        max over the grid of |e|, e = psi - psi_d followed continuously from wrap(e(t0)) (a full turn reads 2 pi) (unit: rad)
        """
    @property
    def max_position_error(self) -> float:
        """
        max over the grid of |p - p_d| (unit: m)
        """
    @property
    def max_rho_sigma_z(self) -> float:
        """
        max over the grid of the spectral radius of Sigma Z (output feedback; below gamma^2) (unit: -)
        """
    @property
    def response_ratio(self) -> float:
        """
        sqrt(tracking_cost) / disturbance_l2 from any start: includes the response to the initial error (unit: -)
        """
    @property
    def rms_estimation_error_last_half(self) -> float:
        """
        sqrt(mean over the last half of |q_hat - (q - q_d)|^2) (output feedback) (unit: state)
        """
    @property
    def rms_heading_error_last_half(self) -> float:
        """
        sqrt(mean over the last half of wrap(psi - psi_d)^2) (unit: rad)
        """
    @property
    def rms_position_error_last_half(self) -> float:
        """
        sqrt(mean over the last half of |p - p_d|^2) (unit: m)
        """
    @property
    def tracking_cost(self) -> float:
        """
        |q_e(tf)|_Qf^2 + integral of |q - q_d|_Q^2 + |u - u_d|^2 (unit: -)
        """
    @property
    def turned_around(self) -> float:
        """
        1 when |e| passes max(pi, |e(t0)|) + 0.1 (through +-pi) or |wrap(e)| > pi/2 on more than half of the last half (tracks backwards), else 0 (docs/baselines.md) (unit: -)
        """
class GammaStarOptions:
    """
    Options of the gamma* search (gamma_star, gamma_star_output_feedback). validate() checks
    them: a bracket of finite numbers >= 0 with lower < upper (or both 0), rtol in (0, 1),
    max_evaluations >= 2, threads >= 1, and the solver options.
    
    Parameters
    ----------
    lower : float, default 0.0
        the bracket's lower end: a gamma that fails (0 with upper: found
        automatically)
    upper : float, default 0.0
        the bracket's upper end: a gamma that passes; lower = upper = 0:
        the bracket is found by doubling / halving from 1
    rtol : float, default 1e-07
        stop when upper - lower <= rtol * upper (1e-7: with the integration
        error of the default solver options, gamma* is good to 1e-6)
    max_evaluations : int, default 200
        gammas evaluated at most, >= 2 (then converged is false)
    threads : int, default 2
        gammas evaluated in parallel per round (>= 1); at most the hardware's
        threads are used, and fewer when max_evaluations would not
        suffice to converge with that many per round
    solver : SolverOptions, optional
        for every Riccati solve
    
    Notes
    -----
    For a model implemented in Python the search evaluates one gamma at a time (its calls hold the
    GIL).
    
    Raises
    ------
    ValueError
        An option out of its range, naming it.
    
    Examples
    --------
    >>> options = hc.GammaStarOptions(lower=1.0, upper=2.0, rtol=1e-4)
    >>> options.threads, options.solver.method
    (2, <Method.auto: 0>)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('lower', 'upper', 'rtol', 'max_evaluations', 'threads', 'solver')
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
        """
        the bracket's lower end: a gamma that fails (0 with upper: found
        automatically)
        """
    @lower.setter
    def lower(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_evaluations(self) -> int:
        """
        gammas evaluated at most, >= 2 (then converged is false)
        """
    @max_evaluations.setter
    def max_evaluations(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def rtol(self) -> float:
        """
        stop when upper - lower <= rtol * upper (1e-7: with the integration
        error of the default solver options, gamma* is good to 1e-6)
        """
    @rtol.setter
    def rtol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def solver(self) -> SolverOptions:
        """
        for every Riccati solve
        """
    @solver.setter
    def solver(self, arg0: SolverOptions) -> None:
        ...
    @property
    def threads(self) -> int:
        """
        gammas evaluated in parallel per round (>= 1); at most the hardware's
        threads are used, and fewer when max_evaluations would not
        suffice to converge with that many per round
        """
    @threads.setter
    def threads(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def upper(self) -> float:
        """
        the bracket's upper end: a gamma that passes; lower = upper = 0:
        the bracket is found by doubling / halving from 1
        """
    @upper.setter
    def upper(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class GammaTrial:
    """
    One gamma evaluated by the gamma* search.
    
    Attributes
    ----------
    gamma : float
        the gamma tried
    passed : bool
        no condition failed on [t0, tf]
    t_escape : float
        failure time (escape, coupling violation, or where a solution too
        close to its escape could not be integrated), NaN if passed
    condition : GammaCondition
        what failed; None if passed
    rhs_evals : int
        right-hand sides of the Riccati equations its test evaluated (the
        output-feedback search: of the solves that completed; 0 for the
        discrete designs, which solve no ODE)
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> first = hc.gamma_star(trajectory, np.eye(6), np.eye(6)).trials[0]
    >>> first.gamma, first.passed, first.condition, round(first.t_escape, 2)
    (1.0, False, <GammaCondition.grde: 1>, 7.56)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('gamma', 'passed', 't_escape', 'condition', 'rhs_evals')
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
        """
        what failed; None if passed
        """
    @property
    def gamma(self) -> float:
        """
        the gamma tried
        """
    @property
    def passed(self) -> bool:
        """
        no condition failed on [t0, tf]
        """
    @property
    def rhs_evals(self) -> int:
        """
        right-hand sides of the Riccati equations its test evaluated (the
        output-feedback search: of the solves that completed; 0 for the
        discrete designs, which solve no ODE)
        """
    @property
    def t_escape(self) -> float:
        """
        failure time (escape, coupling violation, or where a solution too
        close to its escape could not be integrated), NaN if passed
        """
class GammaStarResult:
    """
    The result of a gamma* search: gamma* (the final bracket's upper end), the bracket, the
    condition that binds, and every gamma tried.
    
    Attributes
    ----------
    gamma_star : float
        the upper end of the final bracket: the smallest gamma known to pass
    lower : float
        final bracket: lower fails (0 when every gamma > 0 passes)
    upper : float
        final bracket: upper passes (= gamma_star)
    t_escape_lower : float
        where the lower end fails
    binding : GammaCondition
        the condition that fails at the lower end
    converged : bool
        false: max_evaluations reached first
    trials : list of GammaTrial
        every gamma tried, in the order evaluated
    rhs_evals : int
        the search's cost: the trials' right-hand sides, summed
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> result = hc.gamma_star(trajectory, np.eye(6), np.eye(6))
    >>> round(result.gamma_star, 4), result.binding, result.converged
    (1.3346, <GammaCondition.grde: 1>, True)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('gamma_star', 'lower', 'upper', 't_escape_lower', 'binding', 'converged', 'trials', 'rhs_evals')
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
        """
        the condition that fails at the lower end
        """
    @property
    def converged(self) -> bool:
        """
        false: max_evaluations reached first
        """
    @property
    def gamma_star(self) -> float:
        """
        the upper end of the final bracket: the smallest gamma known to pass
        """
    @property
    def lower(self) -> float:
        """
        final bracket: lower fails (0 when every gamma > 0 passes)
        """
    @property
    def rhs_evals(self) -> int:
        """
        the search's cost: the trials' right-hand sides, summed
        """
    @property
    def t_escape_lower(self) -> float:
        """
        where the lower end fails
        """
    @property
    def trials(self) -> list[GammaTrial]:
        """
        every gamma tried, in the order evaluated
        """
    @property
    def upper(self) -> float:
        """
        final bracket: upper passes (= gamma_star)
        """
class Certificates:
    """
    The certificates of paper §3 for a design Z and a gain scaling kappa(t).
    
    Attributes
    ----------
    m : float
        m I <= Z(t) <= M I on [t0, tf] (eq. 22)
    M : float
        m I <= Z(t) <= M I on [t0, tf] (eq. 22)
    kappa_min : float
        min kappa(t); the proof needs kappa >= 1/2
    p_min : float
        Smallest eigenvalue over [t0, tf] of P(t) = Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z:
        V = q_e' Z q_e has dV/dt = -q_e' P q_e + 2 q_e' Z r(q_e) (eq. 23).
        p_min, and p_min_t the time (s) where it is taken
    p_min_t : float
        Smallest eigenvalue over [t0, tf] of P(t) = Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z:
        V = q_e' Z q_e has dV/dt = -q_e' P q_e + 2 q_e' Z r(q_e) (eq. 23).
        p_min, and p_min_t the time (s) where it is taken
    remainder_L : float
        L with |r(q_e)| <= L |q_e|^2, r the remainder of the error dynamics beyond A_e q_e (with
        state-dependent inputs it includes (G(q) - B_e) u_e; analysis.cpp).
        the largest L over [t0, tf]
    remainder_method : str
        how L was obtained (see Model::remainder_bound)
    remainder_is_bound : bool
        false: a sampled estimate, not a proof
    epsilon : float
        Radius of eq. (24): with |r| <= L |q_e|^2 and |q_e| < epsilon = min_t p(t) / (4 M L(t)),
        |r| <= p |q_e| / (4 M), so dV/dt <= -(p/2) |q_e|^2 (exponential decay).
        epsilon, and epsilon_t the time (s) of the minimum
    epsilon_t : float
        Radius of eq. (24): with |r| <= L |q_e|^2 and |q_e| < epsilon = min_t p(t) / (4 M L(t)),
        |r| <= p |q_e| / (4 M), so dV/dt <= -(p/2) |q_e|^2 (exponential decay).
        epsilon, and epsilon_t the time (s) of the minimum
    attraction_radius : float
        Initial errors with |q_e(t0)| < epsilon sqrt(m / M) never leave the epsilon-ball (V decays).
        a bound on the Euclidean norm |q_e(t0)|
    decay_rate : float
        V(t) <= V(t0) exp(-decay_rate (t - t0)) inside the ball: decay_rate = p_min / (2 M).
        in 1/s
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> certificates = hc.certify(design, 1.0, np.eye(6))
    >>> round(certificates.m, 3), round(certificates.M, 3), round(certificates.p_min, 3)
    (0.219, 20.815, 1.0)
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
        """
        m I <= Z(t) <= M I on [t0, tf] (eq. 22)
        """
    @property
    def attraction_radius(self) -> float:
        """
        Initial errors with |q_e(t0)| < epsilon sqrt(m / M) never leave the epsilon-ball (V decays).
        a bound on the Euclidean norm |q_e(t0)|
        """
    @property
    def decay_rate(self) -> float:
        """
        V(t) <= V(t0) exp(-decay_rate (t - t0)) inside the ball: decay_rate = p_min / (2 M).
        in 1/s
        """
    @property
    def epsilon(self) -> float:
        """
        Radius of eq. (24): with |r| <= L |q_e|^2 and |q_e| < epsilon = min_t p(t) / (4 M L(t)),
        |r| <= p |q_e| / (4 M), so dV/dt <= -(p/2) |q_e|^2 (exponential decay).
        epsilon, and epsilon_t the time (s) of the minimum
        """
    @property
    def epsilon_t(self) -> float:
        """
        Radius of eq. (24): with |r| <= L |q_e|^2 and |q_e| < epsilon = min_t p(t) / (4 M L(t)),
        |r| <= p |q_e| / (4 M), so dV/dt <= -(p/2) |q_e|^2 (exponential decay).
        epsilon, and epsilon_t the time (s) of the minimum
        """
    @property
    def kappa_min(self) -> float:
        """
        min kappa(t); the proof needs kappa >= 1/2
        """
    @property
    def m(self) -> float:
        """
        m I <= Z(t) <= M I on [t0, tf] (eq. 22)
        """
    @property
    def p_min(self) -> float:
        """
        Smallest eigenvalue over [t0, tf] of P(t) = Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z:
        V = q_e' Z q_e has dV/dt = -q_e' P q_e + 2 q_e' Z r(q_e) (eq. 23).
        p_min, and p_min_t the time (s) where it is taken
        """
    @property
    def p_min_t(self) -> float:
        """
        Smallest eigenvalue over [t0, tf] of P(t) = Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z:
        V = q_e' Z q_e has dV/dt = -q_e' P q_e + 2 q_e' Z r(q_e) (eq. 23).
        p_min, and p_min_t the time (s) where it is taken
        """
    @property
    def remainder_L(self) -> float:
        """
        L with |r(q_e)| <= L |q_e|^2, r the remainder of the error dynamics beyond A_e q_e (with
        state-dependent inputs it includes (G(q) - B_e) u_e; analysis.cpp).
        the largest L over [t0, tf]
        """
    @property
    def remainder_is_bound(self) -> bool:
        """
        false: a sampled estimate, not a proof
        """
    @property
    def remainder_method(self) -> str:
        """
        how L was obtained (see Model::remainder_bound)
        """
class SampledLinearization:
    """
    The linearization along the desired trajectory sampled at period T with the inputs held: A_k,
    B_k, D_k for k = 0 .. steps() - 1 (see above). Immutable; may be read from several threads.
    
    Integrates the variational equations over each sample with classical Runge-Kutta steps of at
    most kMaxSubstep (at least two per sample): their error, O(h^4), is far below the O(T)
    difference between the sampled and the continuous design. InputError for a period that is
    not finite and > 0, or longer than the horizon.
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory.
    period : float
        The sample period T (s), > 0 and at most the horizon.
    
    Raises
    ------
    ValueError
        A bad period.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> sampled = hc.SampledLinearization(trajectory, 0.1)
    >>> sampled.steps(), sampled.A(0).shape, sampled.B(0).shape, sampled.D(0).shape
    (100, (6, 6), (6, 2), (6, 6))
    """
    def A(self, k: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        A_k (n x n), B_k (n x m), D_k (n x nw), k = 0 .. steps() - 1 (unchecked index).
        
        k : int
            0 .. steps() - 1 (ValueError outside).
        """
    def B(self, k: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        A_k (n x n), B_k (n x m), D_k (n x nw), k = 0 .. steps() - 1 (unchecked index).
        """
    def D(self, k: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        A_k (n x n), B_k (n x m), D_k (n x nw), k = 0 .. steps() - 1 (unchecked index).
        """
    def __init__(self, trajectory: Trajectory, period: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    def period(self) -> float:
        """
        The period T (s).
        """
    def steps(self) -> int:
        """
        The number of samples N.
        """
    def time(self, k: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        t_k = t0 + k T (s), k = 0 .. N.
        """
    def trajectory(self) -> Trajectory:
        """
        The desired trajectory it samples.
        """
class DiscreteDesign:
    """
    The solution of the game Riccati difference equation: M_k and the gains F_k of the law.
    Immutable; may be read from several threads.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0)
    >>> design.steps(), design.M(0).shape, design.gain(0).shape
    (100, (6, 6), (2, 6))
    """
    def M(self, k: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        M_k (n x n, symmetric), k = 0 .. steps(); M_steps = Qf. InputError outside.
        """
    def gain(self, k: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        F_k (m x n): u_k = u_d(t_k) - F_k q_e(t_k), k = 0 .. steps() - 1. InputError outside.
        """
    def gamma(self) -> float:
        """
        The gamma of the game (+inf: the discrete LQR).
        """
    def period(self) -> float:
        """
        The period T (s).
        """
    def sample_index(self, t: typing.SupportsFloat | typing.SupportsIndex) -> int:
        """
        The sample that holds t: floor((t - t0) / T), within 1e-9 T of a sample time that sample;
        InputError for t outside [t0, t_N).
        """
    def sampled(self) -> SampledLinearization:
        """
        The sampled linearization it was solved on, and its trajectory.
        """
    def steps(self) -> int:
        """
        The number of samples N.
        """
    def time(self, k: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        t_k = t0 + k T (s), k = 0 .. N.
        """
    def worst_case_gain(self, k: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        The worst-case disturbance's gain (nw x n): w_k = W_k q_e(t_k); zero for gamma = inf.
        """
class DiscreteOutputFeedback:
    """
    The filter Riccati solution along a digital design, with the coupling condition. Immutable;
    may be read from several threads.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0)
    >>> C = np.hstack([np.zeros((3, 3)), np.eye(3)])
    >>> feedback = hc.solve_discrete_output_feedback(design, C, 0.25 * np.eye(3), np.eye(6), np.eye(6))
    >>> bool(feedback.largest_coupling() < 1.0)
    True
    """
    def C(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        C (p x n), R (p x p), Q (n x n) as given.
        """
    def Q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        C (p x n), R (p x p), Q (n x n) as given.
        """
    def R(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        C (p x n), R (p x p), Q (n x n) as given.
        """
    def Sigma(self, k: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Sigma_k (n x n), k = 0 .. steps(). InputError outside.
        """
    def coupling(self, k: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        rho(Sigma_k M_k) / gamma^2, k = 0 .. steps() (0 at gamma = inf): the coupling condition wants
        < 1. InputError outside.
        """
    def design(self) -> DiscreteDesign:
        """
        The state-feedback game it completes.
        """
    def largest_coupling(self) -> float:
        """
        The largest coupling(k).
        """
    def steps(self) -> int:
        """
        The number of samples N.
        """
class SampledLaw:
    """
    The law u = u_d(t) - K_k q_e tabulated at t_k = t0 + k T, k = 0 .. steps() - 1, with the
    linearization A_e(t_k), B_e(t_k), D_e(t_k) D_e(t_k)' and the game's value matrix Z_k (k = 0 .. steps())
    for the prediction and the estimator. Immutable.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> law = hc.SampledLaw.emulated(design, 0.1)
    >>> law.kind(), law.steps(), law.t_end()
    ('emulated', 100, 10.0)
    """
    @staticmethod
    def digital(design: DiscreteDesign) -> SampledLaw:
        """
        The digital design: K_k = F_k of the discrete game (discrete_design.hpp), at its period.
        
        Parameters
        ----------
        design : DiscreteDesign
            The digital design (solve_discrete_game).
        
        Returns
        -------
        SampledLaw
        
        Examples
        --------
        >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
        >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
        >>> law = hc.SampledLaw.digital(hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0))
        >>> law.kind(), law.gamma()
        ('digital', 5.0)
        """
    @staticmethod
    def emulated(design: RiccatiSolution, period: typing.SupportsFloat | typing.SupportsIndex, kappa: typing.Any = ...) -> SampledLaw:
        """
        The continuous design emulated: K_k = kappa(t_k) B_e(t_k)' Z(t_k), held over each sample of
        `period` (s). InputError for a period that is not > 0 or longer than the horizon, kappa not
        > 0 at a sample, or u_d given as a function of t (a function may allocate and throw in
        step(): give u_d as signals: constants, harmonics or tables).
        
        Parameters
        ----------
        design : RiccatiSolution
            The continuous design (solve_grde).
        period : float
            The controller's period T (s).
        kappa : Signal or float, default 1.0
            The gain scaling kappa(t), > 0.
        
        Returns
        -------
        SampledLaw
        
        Examples
        --------
        >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
        >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
        >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
        >>> hc.SampledLaw.emulated(design, 0.05).period()
        0.05
        """
    def __getstate__(self) -> tuple[Trajectory, str, float, float, list, list]:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def gain(self, k: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        K_k (m x n), and A_e(t_k) (n x n), B_e(t_k) (n x m); unchecked indices.
        """
    def gamma(self) -> float:
        """
        The gamma of the design (+inf: LQR).
        """
    def kind(self) -> str:
        """
        "emulated" or "digital".
        """
    def m(self) -> int:
        """
        The number of states n and of inputs m.
        """
    def n(self) -> int:
        """
        The number of states n and of inputs m.
        """
    def period(self) -> float:
        """
        The period T (s).
        """
    def steps(self) -> int:
        """
        The number of samples N.
        """
    def t0(self) -> float:
        """
        The law is defined on [t0, t_end), t_end = t0 + N T <= tf (s).
        """
    def t_end(self) -> float:
        """
        The law is defined on [t0, t_end), t_end = t0 + N T <= tf (s).
        """
class ActuatorLimits:
    """
    The actuators' limits. Empty vectors: no limit of that kind.
    
    Parameters
    ----------
    u_min : array_like, shape (m,) or (0,), optional
        lower bounds of the command (m numbers; -inf: free)
    u_max : array_like, shape (m,) or (0,), optional
        upper bounds of the command (m numbers; +inf: free)
    rate_max : array_like, shape (m,) or (0,), optional
        largest |du/dt| per channel (units of u per second; +inf: free), > 0
    
    Examples
    --------
    >>> limits = hc.ActuatorLimits(u_min=[-2.0, -1.0], u_max=[2.0, 1.0], rate_max=[4.0, np.inf])
    >>> limits.u_max
    array([2., 1.])
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('u_min', 'u_max', 'rate_max')
    def __eq__(self, arg0: ActuatorLimits) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, u_min: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"] | None = ..., u_max: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"] | None = ..., rate_max: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"] | None = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def rate_max(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        largest |du/dt| per channel (units of u per second; +inf: free), > 0
        """
    @rate_max.setter
    def rate_max(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        ...
    @property
    def u_max(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        upper bounds of the command (m numbers; +inf: free)
        """
    @u_max.setter
    def u_max(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        ...
    @property
    def u_min(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        lower bounds of the command (m numbers; -inf: free)
        """
    @u_min.setter
    def u_min(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        ...
class MeasurementUpdate:
    """
    How a measurement enters the output-feedback estimator.
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    held
        held in the innovation of (35)-(36) for `hold` seconds after its time (a continuous
        measurement, as the batch loop's held noise)
    sampled
        once, at its time, as a jump of the estimate and Sigma (the sampled-measurement
        form of (35)-(36), see the top of this file): the command of the same step sees it
    discrete
        the digital law's own filter: the central controller of the discrete game with
        one-step-delayed measurements (discrete_output_feedback.hpp), run on the law's
        samples (see the top of this file); the digital law only
    
    Examples
    --------
    >>> hc.OnlineFilter().update
    <MeasurementUpdate.sampled: 1>
    """
    __members__: typing.ClassVar[dict[str, MeasurementUpdate]]
    discrete: typing.ClassVar[MeasurementUpdate]
    held: typing.ClassVar[MeasurementUpdate]
    sampled: typing.ClassVar[MeasurementUpdate]
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        """
        The member of that name (ValueError listing the names for another).
        """
    def __int__(self) -> int:
        ...
    def __ne__(self, other: typing.Any) -> bool:
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
class OnlineFilter:
    """
    The filter of an output-feedback controller (see the top of this file). An empty N: state
    feedback (step() takes the full state).
    
    Parameters
    ----------
    N : array_like, shape (p, p) or (0, 0), optional
        p x p, symmetric positive definite: the weight of the measurement noise
        in (36); for noise of standard deviation sigma per sample held over the
        sensor's period T_s, the continuous filter's intensity sigma^2 T_s
    Sigma0 : array_like, shape (n, n), optional
        n x n, symmetric positive definite: Sigma at reset(), (Q0 - eta I)^-1
    Q : array_like, shape (n, n), optional
        n x n, symmetric positive semidefinite: the performance weight in (36)
    hold : float, default 0.0
        s: the sensor's period; 0: the law's period. Held: how long a measurement
        stays in the innovation after its time; sampled: the noise covariance of
        one measurement is N / hold
    update : MeasurementUpdate or str, default 'sampled'
    
    Examples
    --------
    >>> f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))   # paper Fig. 2
    >>> f.hold
    0.0
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('N', 'Sigma0', 'Q', 'hold', 'update')
    update: MeasurementUpdate
    def __eq__(self, arg0: OnlineFilter) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., hold: typing.SupportsFloat | typing.SupportsIndex = 0.0, update: MeasurementUpdate = MeasurementUpdate.sampled) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def N(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        p x p, symmetric positive definite: the weight of the measurement noise
        in (36); for noise of standard deviation sigma per sample held over the
        sensor's period T_s, the continuous filter's intensity sigma^2 T_s
        """
    @N.setter
    def N(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        n x n, symmetric positive semidefinite: the performance weight in (36)
        """
    @Q.setter
    def Q(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Sigma0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        n x n, symmetric positive definite: Sigma at reset(), (Q0 - eta I)^-1
        """
    @Sigma0.setter
    def Sigma0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def hold(self) -> float:
        """
        s: the sensor's period; 0: the law's period. Held: how long a measurement
        stays in the innovation after its time; sampled: the noise covariance of
        one measurement is N / hold
        """
    @hold.setter
    def hold(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class OnlineOptions:
    """
    The choices of an online controller.
    
    Parameters
    ----------
    filter : OnlineFilter, optional
        output feedback (empty N: state feedback)
    limits : ActuatorLimits, optional
        bounds and rate limits of the command
    max_age : float, default 1e+300
        s: a measurement older than this at t_now is stale (not used)
    compensate_delay : bool, default True
        predict a measurement from t_meas to t_now (false: the command
        is the law's at t_meas, u_d(t_meas) - K q_e(t_meas), as if
        computed then and applied late)
    history : int, default 64
        applied commands remembered (>= 2): a measurement older than
        the oldest is stale
    
    Examples
    --------
    >>> hc.OnlineOptions(max_age=0.2).compensate_delay
    True
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('filter', 'limits', 'max_age', 'compensate_delay', 'history')
    def __eq__(self, arg0: OnlineOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, filter: OnlineFilter = ..., limits: ActuatorLimits = ..., max_age: typing.SupportsFloat | typing.SupportsIndex = 1e+300, compensate_delay: bool = True, history: typing.SupportsInt | typing.SupportsIndex = 64) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def compensate_delay(self) -> bool:
        """
        predict a measurement from t_meas to t_now (false: the command
        is the law's at t_meas, u_d(t_meas) - K q_e(t_meas), as if
        computed then and applied late)
        """
    @compensate_delay.setter
    def compensate_delay(self, arg0: bool) -> None:
        ...
    @property
    def filter(self) -> OnlineFilter:
        """
        output feedback (empty N: state feedback)
        """
    @filter.setter
    def filter(self, arg0: OnlineFilter) -> None:
        ...
    @property
    def history(self) -> int:
        """
        applied commands remembered (>= 2): a measurement older than
        the oldest is stale
        """
    @history.setter
    def history(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def limits(self) -> ActuatorLimits:
        """
        bounds and rate limits of the command
        """
    @limits.setter
    def limits(self, arg0: ActuatorLimits) -> None:
        ...
    @property
    def max_age(self) -> float:
        """
        s: a measurement older than this at t_now is stale (not used)
        """
    @max_age.setter
    def max_age(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class StepStatus:
    """
    What step() did.
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    ok
        a command was computed (see MeasurementUse for the measurement)
    refused
        t_now is not finite or earlier than the last call's: nothing changed, u is the
        command held
    past_horizon
        t_now >= t_end, where the design ends: u is the command held; reset() with a
        new design to continue
    not_reset
        step() before reset(): u is left as it is
    lost
        the estimate is not finite (output feedback: the filter's Sigma escaped, as the
        H-infinity filter's does in a long enough time without measurements, or the
        estimator's gain became singular at a coupling violation): u is the command held,
        and every step answers Lost until reset()
    
    Examples
    --------
    >>> hc.StepStatus("refused")
    <StepStatus.refused: 1>
    """
    __members__: typing.ClassVar[dict[str, StepStatus]]
    lost: typing.ClassVar[StepStatus]
    not_reset: typing.ClassVar[StepStatus]
    ok: typing.ClassVar[StepStatus]
    past_horizon: typing.ClassVar[StepStatus]
    refused: typing.ClassVar[StepStatus]
    def __eq__(self: StepStatus | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: StepStatus | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        """
        The member of that name (ValueError listing the names for another).
        """
    def __int__(self: StepStatus | str) -> int:
        ...
    def __ne__(self: StepStatus | str, other: typing.Any) -> bool:
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
class MeasurementUse:
    """
    What became of the measurement given to step(). Anything but Used: the estimate was predicted.
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    used
        used (and predicted to t_now with delay compensation)
    missing
        none given
    stale
        older than max_age at t_now, or than the commands remembered
    duplicate
        not newer than the last measurement used (the same one again, or out of order)
    future
        t_meas > t_now
    not_finite
        t_meas or a component of q is NaN or infinite
    
    Examples
    --------
    >>> hc.MeasurementUse("stale")
    <MeasurementUse.stale: 2>
    """
    __members__: typing.ClassVar[dict[str, MeasurementUse]]
    duplicate: typing.ClassVar[MeasurementUse]
    future: typing.ClassVar[MeasurementUse]
    missing: typing.ClassVar[MeasurementUse]
    not_finite: typing.ClassVar[MeasurementUse]
    stale: typing.ClassVar[MeasurementUse]
    used: typing.ClassVar[MeasurementUse]
    def __eq__(self: MeasurementUse | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: MeasurementUse | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        """
        The member of that name (ValueError listing the names for another).
        """
    def __int__(self: MeasurementUse | str) -> int:
        ...
    def __ne__(self: MeasurementUse | str, other: typing.Any) -> bool:
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
class StepReport:
    """
    The report of one step().
    
    Attributes
    ----------
    status : StepStatus
        what step() did
    measurement : MeasurementUse
        what became of the measurement
    saturated : bool
        a bound of u_min / u_max was active
    rate_limited : bool
        the rate limit was active
    rho_sigma_z : float
        output feedback: rho(Sigma Z) at t_now, against gamma^2 (NaN: state
        feedback)
    coupling_violated : bool
        output feedback: rho(Sigma Z) >= gamma^2 (the estimator's
        gain is singular)
    window_stale : bool
        receding horizon (online_receding_horizon.hpp): the law in use is
        past its update period (the next window is late or failed)
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
    >>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
    >>> controller.step(0.1, None)[1]
    StepReport(status='ok', measurement='missing', saturated=False, rate_limited=False, rho_sigma_z=nan, coupling_violated=False, window_stale=False)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('status', 'measurement', 'saturated', 'rate_limited', 'rho_sigma_z', 'coupling_violated', 'window_stale')
    def __eq__(self, arg0: StepReport) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def coupling_violated(self) -> bool:
        """
        output feedback: rho(Sigma Z) >= gamma^2 (the estimator's
        gain is singular)
        """
    @property
    def measurement(self) -> MeasurementUse:
        """
        what became of the measurement
        """
    @property
    def rate_limited(self) -> bool:
        """
        the rate limit was active
        """
    @property
    def rho_sigma_z(self) -> float:
        """
        output feedback: rho(Sigma Z) at t_now, against gamma^2 (NaN: state
        feedback)
        """
    @property
    def saturated(self) -> bool:
        """
        a bound of u_min / u_max was active
        """
    @property
    def status(self) -> StepStatus:
        """
        what step() did
        """
    @property
    def window_stale(self) -> bool:
        """
        receding horizon (online_receding_horizon.hpp): the law in use is
        past its update period (the next window is late or failed)
        """
class OnlineCounts:
    """
    Counts since reset().
    
    Attributes
    ----------
    steps : int
        calls of step() (any status)
    used : int
        measurements used
    predicted : int
        commands computed without a measurement (MeasurementUse other than Used)
    refused : int
        StepStatus::Refused
    past_horizon : int
        StepStatus::PastHorizon
    lost : int
        StepStatus::Lost
    saturated : int
        commands with a bound active
    rate_limited : int
        commands with the rate limit active
    largest_command : float
        max |u_i| over the commands computed
    coupling_violated : int
        output feedback: steps with rho(Sigma Z) >= gamma^2
    coupling_violation_t : float
        output feedback: the t_now of the first such step
    largest_rho : float
        output feedback: max rho(Sigma Z) / gamma^2 over the steps
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
    >>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
    >>> u, report = controller.step(0.1, None)
    >>> controller.counts().steps, controller.counts().predicted
    (1, 1)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('steps', 'used', 'predicted', 'refused', 'past_horizon', 'lost', 'saturated', 'rate_limited', 'largest_command', 'coupling_violated', 'coupling_violation_t', 'largest_rho')
    def __eq__(self, arg0: OnlineCounts) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def coupling_violated(self) -> int:
        """
        output feedback: steps with rho(Sigma Z) >= gamma^2
        """
    @property
    def coupling_violation_t(self) -> float:
        """
        output feedback: the t_now of the first such step
        """
    @property
    def largest_command(self) -> float:
        """
        max |u_i| over the commands computed
        """
    @property
    def largest_rho(self) -> float:
        """
        output feedback: max rho(Sigma Z) / gamma^2 over the steps
        """
    @property
    def lost(self) -> int:
        """
        StepStatus::Lost
        """
    @property
    def past_horizon(self) -> int:
        """
        StepStatus::PastHorizon
        """
    @property
    def predicted(self) -> int:
        """
        commands computed without a measurement (MeasurementUse other than Used)
        """
    @property
    def rate_limited(self) -> int:
        """
        commands with the rate limit active
        """
    @property
    def refused(self) -> int:
        """
        StepStatus::Refused
        """
    @property
    def saturated(self) -> int:
        """
        commands with a bound active
        """
    @property
    def steps(self) -> int:
        """
        calls of step() (any status)
        """
    @property
    def used(self) -> int:
        """
        measurements used
        """
class OnlineController:
    """
    The controller of one vehicle, state or output feedback (see the top of this file).
    
    InputError for a null law or bad options (a filter whose shapes do not fit the model's
    measurement). Takes all the memory step() uses.
    
    Parameters
    ----------
    law : SampledLaw
        The law (SampledLaw.emulated or SampledLaw.digital), shared by any number of controllers.
    options : OnlineOptions, optional
        Actuator limits, the largest age of a measurement, delay compensation; a filter (its N
        given) makes it an output-feedback controller, whose step() takes the measurement y = C q.
    
    Raises
    ------
    ValueError
        Bad options (a filter whose shapes do not fit the model's measurement C).
    
    Notes
    -----
    One object per vehicle: its calls change it, so two threads must not call one object at once.
    With output feedback the estimator and the filter run along the desired trajectory's
    linearization (docs/online.md).
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> limits = hc.ActuatorLimits(u_min=[-2.0, -2.0], u_max=[2.0, 2.0])
    >>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1), hc.OnlineOptions(limits=limits))
    >>> q0 = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
    >>> controller.reset(0.0, q0)
    >>> u, report = controller.step(0.1, q0, 0.1)
    >>> u.round(3), report.status, report.saturated
    (array([ 2.   , -1.941]), <StepStatus.ok: 0>, True)
    """
    def __init__(self, law: SampledLaw, options: OnlineOptions = ...) -> None:
        ...
    def counts(self) -> OnlineCounts:
        """
        The counts since reset().
        """
    def estimate(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        The estimate of q_e at estimate_time() (n), the command held since held_time() (m).
        """
    def estimate_time(self) -> float:
        """
        The estimate of q_e at estimate_time() (n), the command held since held_time() (m).
        """
    def held_command(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        The estimate of q_e at estimate_time() (n), the command held since held_time() (m).
        """
    def held_time(self) -> float:
        """
        The estimate of q_e at estimate_time() (n), the command held since held_time() (m).
        """
    def law(self) -> SampledLaw:
        """
        The law and the options it was made with.
        """
    def m(self) -> int:
        """
        The number of states n (of q) and of inputs m (of u).
        """
    def measurement_size(self) -> int:
        """
        The numbers step() takes: n (the state) or p (the measurement y = C q).
        """
    def n(self) -> int:
        """
        The number of states n (of q) and of inputs m (of u).
        """
    def options(self) -> OnlineOptions:
        """
        The law and the options it was made with.
        """
    def output_feedback(self) -> bool:
        """
        Output feedback (a filter in the options)?
        """
    def replay(self, t_now: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], t_meas: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"] | None = None) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], list[StepReport]]:
        """
        The commands the controller would have sent for a log of measurements: step() for each row,
        in order, in one call (the GIL released for the whole log).
        
        Parameters
        ----------
        t_now : array_like, shape (k,)
            The times of the commands (s).
        q : array_like, shape (k, n) or (k, p)
            The measured states (output feedback: the measurements y), one row per time; a row with NaN
            is a non-finite measurement (the estimate is predicted).
        t_meas : array_like, shape (k,), optional
            The times of the measurements (s); default t_now.
        
        Returns
        -------
        u : numpy.ndarray, shape (k, m)
            The commands, as step() returns them one by one.
        reports : list of StepReport
        
        Raises
        ------
        ValueError
            Shapes that do not match; replay() before reset().
        
        Examples
        --------
        >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
        >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
        >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
        >>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
        >>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
        >>> ts = np.array([0.1, 0.2, 0.3])
        >>> log = np.tile([1.0, 0.0, 0.0, -1.0, -1.0, 0.0], (3, 1))
        >>> u, reports = controller.replay(ts, log)
        >>> u.shape, [r.measurement for r in reports][-1]
        ((3, 2), <MeasurementUse.used: 0>)
        """
    def reset(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u_held: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"] | None = None) -> None:
        """
        Starts at time t (in [t0, t_end)) from the state q (n; with output feedback the initial
        estimate of the state, and Sigma = Sigma0): the estimate is q - q_d(t) and the command held is
        u_held (m; empty: u_d(t) within the limits). InputError for a bad t, q or u_held (reset() may
        allocate and throw; step() does neither).
        
        Parameters
        ----------
        t : float
            The time (s), in [t0, t_end).
        q : array_like, shape (n,)
            The full state at t (output feedback: the initial estimate of the state).
        u_held : array_like, shape (m,), optional
            The command held before t (default: u_d(t) within the limits).
        
        Raises
        ------
        ValueError
            A bad t, q or u_held.
        
        Examples
        --------
        >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
        >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
        >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
        >>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
        >>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
        >>> controller.held_command()
        array([1., 0.])
        """
    def sigma(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        The filter's Sigma at estimate_time() (n x n; empty for state feedback).
        
        Examples
        --------
        >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
        >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
        >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
        >>> f = hc.OnlineFilter(N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
        >>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1), hc.OnlineOptions(filter=f))
        >>> controller.reset(0.0, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0])   # the estimate: on the path
        >>> u, report = controller.step(0.1, [-1.0, -1.0, 0.8], 0.1)  # y = (x, y, psi)
        >>> controller.sigma().shape, bool(report.rho_sigma_z < 25.0)
        ((6, 6), True)
        """
    def step(self, t_now: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64] | None = None, t_meas: typing.SupportsFloat | typing.SupportsIndex | None = None) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"], StepReport]:
        """
        One sample: the measurement (measurement_size() numbers: q, or y with output feedback; null:
        none) taken at t_meas, the command for t_now into u (m numbers). Never throws, never
        allocates.
        
        Parameters
        ----------
        t_now : float
            The time of the command (s).
        q : array_like, shape (n,) or (p,), optional
            The full state measured at t_meas (output feedback: the measurement y, p =
            measurement_size()); None: no measurement this sample.
        t_meas : float, optional
            The time of the measurement (s), <= t_now; default t_now.
        
        Returns
        -------
        u : numpy.ndarray, shape (m,)
            The command to apply now and hold.
        report : StepReport
            The status, what became of the measurement, whether a limit was active.
        
        Raises
        ------
        ValueError
            q of another size than measurement_size(); step() before reset() (the C++ step() returns
            NotReset).
        
        Examples
        --------
        >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
        >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
        >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
        >>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
        >>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
        >>> u, report = controller.step(0.2, None)                      # no measurement: predicted
        >>> report.measurement
        <MeasurementUse.missing: 1>
        """
class SampledLoopOptions:
    """
    The choices of the sampled loop.
    
    Parameters
    ----------
    delay : float, default 0.0
        s, in [0, T]: the command computed from the measurement of
        t_k is applied from t_k + delay (T: one sample late)
    simulation : SimulationOptions, optional
        output grid, divergence bound, tolerances (method: erk always)
    measurement_every : int, default 1
        the sensor is read at every this many-th sample (k = 0, e,
        2e, ...); the other samples are steps without a measurement
    sigma : float, default 0.0
        output feedback: the noise's standard deviation per sample
    noise : array_like, shape (k, p) or (0, 0), optional
        output feedback: v, one row per sample, one column per output
        (empty when sigma = 0)
    
    Examples
    --------
    >>> hc.SampledLoopOptions(delay=0.1).simulation.output_dt
    0.01
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('delay', 'simulation', 'measurement_every', 'sigma', 'noise')
    def __eq__(self, arg0: SampledLoopOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, delay: typing.SupportsFloat | typing.SupportsIndex = 0.0, simulation: SimulationOptions = ..., measurement_every: typing.SupportsInt | typing.SupportsIndex = 1, sigma: typing.SupportsFloat | typing.SupportsIndex = 0.0, noise: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def delay(self) -> float:
        """
        s, in [0, T]: the command computed from the measurement of
        t_k is applied from t_k + delay (T: one sample late)
        """
    @delay.setter
    def delay(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def measurement_every(self) -> int:
        """
        the sensor is read at every this many-th sample (k = 0, e,
        2e, ...); the other samples are steps without a measurement
        """
    @measurement_every.setter
    def measurement_every(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def noise(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        output feedback: v, one row per sample, one column per output
        (empty when sigma = 0)
        """
    @noise.setter
    def noise(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def sigma(self) -> float:
        """
        output feedback: the noise's standard deviation per sample
        """
    @sigma.setter
    def sigma(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def simulation(self) -> SimulationOptions:
        """
        output grid, divergence bound, tolerances (method: erk always)
        """
    @simulation.setter
    def simulation(self, arg0: SimulationOptions) -> None:
        ...
class TerminalWeight:
    """
    The weight Z(t_j + H) at the end of every window.
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    qf
        the design's Qf
    stationary
        the stabilizing solution of the stationary game ARE at the window's end
    
    Examples
    --------
    >>> hc.RecedingHorizonOptions(window=10.0, terminal="stationary").terminal
    <TerminalWeight.stationary: 1>
    """
    __members__: typing.ClassVar[dict[str, TerminalWeight]]
    qf: typing.ClassVar[TerminalWeight]
    stationary: typing.ClassVar[TerminalWeight]
    def __eq__(self: TerminalWeight | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: TerminalWeight | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        """
        The member of that name (ValueError listing the names for another).
        """
    def __int__(self: TerminalWeight | str) -> int:
        ...
    def __ne__(self: TerminalWeight | str, other: typing.Any) -> bool:
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
class RecedingHorizonOptions:
    """
    The window of the receding horizon (scenario table [receding_horizon]).
    
    Parameters
    ----------
    window : float, default 10.0
        H (s): the length of every window's design, > 0
    update : float, default 1.0
        s: a new window every this long, in (0, H]
    terminal : TerminalWeight or str, default 'qf'
        the weight at every window's end
    
    Raises
    ------
    ValueError
        From RecedingHorizon: a window that is not > 0, an update period outside (0, window].
    
    Examples
    --------
    >>> hc.RecedingHorizonOptions(window=10.0, update=1.0)
    RecedingHorizonOptions(window=10.0, update=1.0, terminal='qf')
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('window', 'update', 'terminal')
    def __eq__(self, arg0: RecedingHorizonOptions) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, window: typing.SupportsFloat | typing.SupportsIndex = 10.0, update: typing.SupportsFloat | typing.SupportsIndex = 1.0, terminal: TerminalWeight | str = TerminalWeight.qf) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def terminal(self) -> TerminalWeight:
        """
        the weight at every window's end
        """
    @terminal.setter
    def terminal(self, arg1: TerminalWeight | str) -> None:
        ...
    @property
    def update(self) -> float:
        """
        s: a new window every this long, in (0, H]
        """
    @update.setter
    def update(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def window(self) -> float:
        """
        H (s): the length of every window's design, > 0
        """
    @window.setter
    def window(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class HorizonWindow:
    """
    One window: its desired trajectory and its design on [t_start, t_start + H].
    
    Attributes
    ----------
    index : int
        j
    t_start : float
        t_j (s)
    t_use_end : float
        t_{j+1} = t_j + update: the window's law is used on [t_j, t_{j+1})
    trajectory : Trajectory
        q_d, u_d and the linearization on [t_j, t_j + H]
    design : RiccatiSolution
        Z of the GRDE on [t_j, t_j + H], Z(t_j + H) = Qf
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
    >>> window = horizon.next(horizon.first())
    >>> window.index, window.t_start, window.t_use_end, window.trajectory.tf()
    (1, 1.0, 2.0, 11.0)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('index', 't_start', 't_use_end', 'trajectory', 'design')
    def __eq__(self, arg0: HorizonWindow) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def memory_bytes(self) -> int:
        """
        The bytes the window stores (the dense outputs of q_d and of Z).
        """
    @property
    def design(self) -> RiccatiSolution:
        """
        Z of the GRDE on [t_j, t_j + H], Z(t_j + H) = Qf
        """
    @property
    def index(self) -> int:
        """
        j
        """
    @property
    def t_start(self) -> float:
        """
        t_j (s)
        """
    @property
    def t_use_end(self) -> float:
        """
        t_{j+1} = t_j + update: the window's law is used on [t_j, t_{j+1})
        """
    @property
    def trajectory(self) -> Trajectory:
        """
        q_d, u_d and the linearization on [t_j, t_j + H]
        """
class RecedingHorizonReport:
    """
    What a receding-horizon run solved and held.
    
    Attributes
    ----------
    options : RecedingHorizonOptions
        the window and update period of the run
    windows : int
        windows solved
    largest_window_bytes : int
        the largest window's stored dense outputs
    peak_bytes : int
        the most held at once (the window in use and the next)
    grde : SolveStats
        the windows' GRDE solves, summed (memory_bytes: the largest)
    divergence_bound : float
        the last divergence bound of the run (see simulate_receding_horizon)
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
    >>> report = hc.run_scenario(scenario).receding_horizon
    >>> report.windows, bool(report.peak_bytes < 2**20)
    (40, True)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('options', 'windows', 'largest_window_bytes', 'peak_bytes', 'grde', 'divergence_bound')
    def __eq__(self, arg0: RecedingHorizonReport) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def divergence_bound(self) -> float:
        """
        the last divergence bound of the run (see simulate_receding_horizon)
        """
    @property
    def grde(self) -> SolveStats:
        """
        the windows' GRDE solves, summed (memory_bytes: the largest)
        """
    @property
    def largest_window_bytes(self) -> int:
        """
        the largest window's stored dense outputs
        """
    @property
    def options(self) -> RecedingHorizonOptions:
        """
        the window and update period of the run
        """
    @property
    def peak_bytes(self) -> int:
        """
        the most held at once (the window in use and the next)
        """
    @property
    def windows(self) -> int:
        """
        windows solved
        """
class WindowGammaStar:
    """
    The largest gamma* (eq. 14) over the windows used on [t0, tf): the gamma a receding-horizon
    run certifies (each window is a game of its own with its terminal weight).
    
    Attributes
    ----------
    gamma_star : float
        the largest window's gamma*
    window : int
        the window where it occurs
    t_start : float
        its t_j (s)
    windows : int
        windows evaluated
    converged : bool
        every window's bisection converged
    result : GammaStarResult
        that window's search
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=5.0, update=5.0))
    >>> worst = hc.receding_horizon_gamma_star(horizon, 20.0)
    >>> worst.windows, worst.window >= 0, bool(worst.gamma_star < 5.0)
    (4, True, True)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('gamma_star', 'window', 't_start', 'windows', 'converged', 'result')
    def __eq__(self, arg0: WindowGammaStar) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def converged(self) -> bool:
        """
        every window's bisection converged
        """
    @property
    def gamma_star(self) -> float:
        """
        the largest window's gamma*
        """
    @property
    def result(self) -> GammaStarResult:
        """
        that window's search
        """
    @property
    def t_start(self) -> float:
        """
        its t_j (s)
        """
    @property
    def window(self) -> int:
        """
        the window where it occurs
        """
    @property
    def windows(self) -> int:
        """
        windows evaluated
        """
class RecedingHorizon:
    """
    The windows of a receding-horizon design along the desired trajectory from q_d(t0) = q_d0 with
    the inputs u_d. Immutable: window() is a pure function of its arguments, so windows may be
    solved on any thread.
    
    The model, q_d0 and u_d as for a Trajectory (trajectory.hpp); Q (n x n) symmetric positive
    semidefinite, Qf symmetric positive definite, gamma > 0 (may be +inf: LQR), as for
    solve_grde. InputError for any of them, or for bad options.
    
    The desired trajectory given as states: q_d(t_k) = row k of q_nodes at the nodes t_nodes
    (increasing, t0 = t_nodes[0], q_d0 = row 0), as for Trajectory's states form; the rest as
    above. InputError for nodes that are not finite and increasing or rows of another shape.
    
    The receding-horizon design: the GRDE (13) solved over a window that moves with time, so that a
    mission of any length is designed with memory that depends on the window, not on the mission.
    
    Window j starts at t_j = t0 + j * update and covers [t_j, t_j + H] (H = window):
      - its desired trajectory is eq. (8) integrated from q_d(t_j) of window j - 1 (q_d0 for
        j = 0) with the same u_d: the windows chain into one desired trajectory, continuous at every
        t_j, whose value differs from one integration over the whole mission by the integration
        error only (trajectory.hpp);
      - its design is the GRDE solved backward from Z(t_j + H) = the terminal weight, with its own
        conjugate-point check (ConjugatePointError names the window). The terminal weight is Qf
        (TerminalWeight::Qf), or the stabilizing solution of the stationary game ARE of the
        linearization frozen at the window's end (TerminalWeight::Stationary, solve_game_are): the
        cost-to-go of an infinite horizon beyond the window, so that the window's Z is that of a
        longer horizon already at its start (for a slowly varying trajectory);
      - the law of window j is used on [t_j, t_{j+1}): u = u_d - kappa B_e' Z_j (q - q_d), so the
        Z in use is always at least H - update before its window's end, where the terminal weight
        has decayed (the gain of a fixed-horizon design collapses towards B' Qf over its last
        seconds; the receding horizon never reaches them).
    The gamma a receding-horizon run certifies is the largest gamma* over its windows: each window
    is a finite-horizon game of its own (receding_horizon_gamma_star).
    
    A desired trajectory given as states (a planner's nodes, for a vehicle open-loop unstable
    along its plan; trajectory.hpp): each window is the states form over its own interval, from its
    start (the node there, or the chained q_d) through the nodes inside it, each interval
    integrated from its node; beyond the last node the window integrates from it. The windows
    then chain without the open-loop drift of one integration. The nodes are kept whole (their
    memory grows with the mission: n + 1 numbers per node).
    
    A path changed under way (with_path_change): from the window that starts at t_join on, the
    windows' trajectories continue from the chained q_d(t_join) with other inputs (a new plan from
    that state); the windows before it keep the old inputs to their ends.
    
    Parameters
    ----------
    model : Model
        The design model.
    q_d0 : array_like, shape (n,)
        The desired initial state q_d(t0).
    u_d : VectorSignal, callable, or list of Signal or float
        The desired inputs, m channels, as for Trajectory; defined for every t of the mission.
    t0 : float
        The start of the mission (s).
    Q : array_like, shape (n, n)
        Weight of the tracking error, symmetric positive semidefinite.
    Qf : array_like, shape (n, n)
        Every window's terminal weight Z(t_j + H), symmetric positive definite.
    gamma : float
        The attenuation level, > 0 (inf: LQR).
    options : RecedingHorizonOptions
        The window H and the update period (s).
    solver : SolverOptions, optional
        The integrator of every window's GRDE.
    trajectory_options : TrajectoryOptions, optional
        Tolerances of every window's desired trajectory.
    
    Raises
    ------
    ValueError
        A bad model, q_d0, u_d, weight, gamma or option.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
    >>> horizon.window_at(3.5), horizon.window_start(3)
    (3, 3.0)
    >>> first = horizon.first()
    >>> first.design.Z(0.0).shape, first.trajectory.tf()
    ((6, 6), 10.0)
    """
    @staticmethod
    def from_states(model: Model, t: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], u_d: typing.Any, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, options: RecedingHorizonOptions, solver: SolverOptions = ..., trajectory_options: TrajectoryOptions = ...) -> RecedingHorizon:
        """
        The model, q_d0 and u_d as for a Trajectory (trajectory.hpp); Q (n x n) symmetric positive
        semidefinite, Qf symmetric positive definite, gamma > 0 (may be +inf: LQR), as for
        solve_grde. InputError for any of them, or for bad options.
        
        The desired trajectory given as states: q_d(t_k) = row k of q_nodes at the nodes t_nodes
        (increasing, t0 = t_nodes[0], q_d0 = row 0), as for Trajectory's states form; the rest as
        above. InputError for nodes that are not finite and increasing or rows of another shape.
        
        The receding horizon along a desired trajectory given as states and inputs.
        
        Parameters
        ----------
        model : Model
            The design model.
        t : array_like, shape (N + 1,)
            The nodes t_0 < ... < t_N (s); t_0 is the mission's start.
        q : array_like, shape (N + 1, n)
            The desired states at the nodes (a planner's, e.g. ``Plan.t`` and ``Plan.q``).
        u_d : VectorSignal, callable, or list of Signal or float
            The desired inputs, m channels, defined beyond the last node for the last windows.
        Q, Qf, gamma, options, solver, trajectory_options
            As for the constructor.
        
        Returns
        -------
        RecedingHorizon
            Every window the states form over its interval: from its start through the nodes inside it.
        
        Raises
        ------
        ValueError
            Nodes that are not finite and increasing, states of another shape, and as the constructor.
        
        Examples
        --------
        >>> t = np.arange(0.0, 60.5, 0.5)                          # dq/dt = 2 q + u: unstable, q_d = sin t
        >>> model = hc.LinearModel([[2.0]], [[1.0]], [[1.0]])
        >>> u_d = [hc.Signal(0.0, [hc.Harmonic(1.0, 1.0, cosine=True), hc.Harmonic(-2.0, 1.0)])]
        >>> horizon = hc.RecedingHorizon.from_states(model, t, np.sin(t)[:, None], u_d, [[1.0]], [[1.0]], 5.0,
        ...                                          hc.RecedingHorizonOptions(window=5.0))
        >>> bool(abs(horizon.desired_state(40.3)[0] - np.sin(40.3)) < 1e-8)   # one integration: off by e^(2 t)
        True
        """
    def __init__(self, model: Model, q_d0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u_d: typing.Any, t0: typing.SupportsFloat | typing.SupportsIndex, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, options: RecedingHorizonOptions, solver: SolverOptions = ..., trajectory_options: TrajectoryOptions = ...) -> None:
        ...
    def desired_state(self, t: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        q_d(t) of the chained windows (path changes included), t >= t0: the windows' trajectories
        integrated from q_d0 up to the window that holds t.
        """
    def first(self) -> HorizonWindow:
        """
        Window 0, from q_d0.
        """
    def gamma(self) -> float:
        """
        The attenuation level of every window.
        """
    def model(self) -> Model:
        """
        The design model of every window.
        """
    def next(self, previous: HorizonWindow) -> HorizonWindow:
        """
        The window after `previous`, from its q_d at the next t_j.
        """
    def node_states(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        The desired states at the nodes, one row per node (0 x 0 otherwise).
        """
    def node_times(self) -> list[float]:
        """
        The nodes of a desired trajectory given as states (s; empty otherwise).
        """
    def options(self) -> RecedingHorizonOptions:
        """
        The window and update period.
        """
    def path_changes(self) -> list[tuple[float, VectorSignal]]:
        """
        The path changes so far: (t_join, u_d), in order.
        """
    def reference(self, tf: typing.SupportsFloat | typing.SupportsIndex) -> Trajectory:
        """
        The desired trajectory of a run on [t0, tf] (tf > t0), the reference of its q_d series:
        without path changes one integration from q_d0 (the states form of the nodes, for a
        trajectory given as states); with them the chained q_d given as states
        at the window starts (Trajectory's states form), each interval integrated with the inputs in
        effect (a function of t, so not for the online controller, which takes the windows').
        """
    def t0(self) -> float:
        """
        The start of the mission (s).
        """
    def terminal_weight(self, j: typing.SupportsInt | typing.SupportsIndex, window: Trajectory) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        The weight Z(t_j + H) of window j whose desired trajectory is `window` (window_trajectory):
        Qf, or the stationary game ARE's solution at the window's end (options().terminal).
        InputError naming the window when the ARE has no stabilizing, positive definite solution.
        """
    def window(self, j: typing.SupportsInt | typing.SupportsIndex, q_d_start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> HorizonWindow:
        """
        Window j (>= 0) from the desired state q_d(t_j) = q_d_start (n). InputError for a bad j or
        q_d_start; SolverError when the integration fails; ConjugatePointError (naming the window)
        when the GRDE of the window has a conjugate point at gamma.
        """
    def window_at(self, t: typing.SupportsFloat | typing.SupportsIndex) -> int:
        """
        The window whose law is used at t >= t0: floor((t - t0) / update) (a t within 1e-9 of the
        update period's multiple belongs to the later window).
        """
    def window_inputs(self, j: typing.SupportsInt | typing.SupportsIndex) -> VectorSignal:
        """
        The desired inputs of window j: u_d, or those of the last change at or before t_j.
        """
    def window_start(self, j: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        t_j = t0 + j * update (s).
        """
    def window_trajectory(self, j: typing.SupportsInt | typing.SupportsIndex, q_d_start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> Trajectory:
        """
        The desired trajectory of window j alone (no design), as window() integrates it.
        """
    def with_path_change(self, t_join: typing.SupportsFloat | typing.SupportsIndex, u_d: typing.Any) -> RecedingHorizon:
        """
        The changed horizon: from the window that starts at t_join on, u_d is `u_d` (m channels),
        the desired trajectory continuing from q_d(t_join). t_join must be a window start after t0
        and after the last change (InputError otherwise). This horizon stays as it is.
        """
class RecedingOnlineStatus:
    """
    What the receding horizon of an online controller has done since reset().
    
    Attributes
    ----------
    window_in_use : int
        the index j of the window whose law step() uses
    windows_solved : int
        windows solved and handed over (the first, at reset(), included)
    windows_failed : int
        windows whose solve failed (not handed over)
    failed_t_start : float
        the t_j of the last window that failed (s)
    last_failure : str
        its error message; empty when none failed
    stale_steps : int
        steps with StepReport::window_stale
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
    >>> controller = hc.RecedingOnlineController(horizon, 0.05, background=False)   # no thread: synchronize solves
    >>> controller.reset(0.0, [1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
    >>> status = controller.status()
    >>> status.window_in_use, status.windows_solved, status.windows_failed
    (0, 1, 0)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('window_in_use', 'windows_solved', 'windows_failed', 'failed_t_start', 'last_failure', 'stale_steps')
    def __eq__(self, arg0: RecedingOnlineStatus) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def failed_t_start(self) -> float:
        """
        the t_j of the last window that failed (s)
        """
    @property
    def last_failure(self) -> str:
        """
        its error message; empty when none failed
        """
    @property
    def stale_steps(self) -> int:
        """
        steps with StepReport::window_stale
        """
    @property
    def window_in_use(self) -> int:
        """
        the index j of the window whose law step() uses
        """
    @property
    def windows_failed(self) -> int:
        """
        windows whose solve failed (not handed over)
        """
    @property
    def windows_solved(self) -> int:
        """
        windows solved and handed over (the first, at reset(), included)
        """
class RecedingOnlineController:
    """
    The online controller of one vehicle over a receding horizon (see the top of this file).
    
    horizon: the windows' design; period: the controller's T (s), with update a whole multiple of
    it; options as for OnlineController (a filter gives output feedback); kappa the gain scaling.
    InputError for a null horizon, a period that does not divide the update period, or bad
    options.
    
    The online controller over a receding horizon (receding_horizon.hpp): the design of window j,
    emulated at the controller's period (SampledLaw::emulated), is the law from t_j on.
    
    Double buffering: while window j runs, the next window is solved on a thread of its own and
    handed over whole (OnlineController::set_successor); step() switches to it at its first sample
    by swapping two pointers. step() never waits for a solve, allocates nothing, takes no lock and
    never throws: the solver's thread allocates, and frees the laws left behind.
    
    A window that fails (its GRDE has a conjugate point at gamma, or an integration fails) is not
    handed over: the controller keeps the last good window, which serves until its own end t_j + H
    (StepReport::window_stale says so; past that end step() answers PastHorizon), status() names the
    failure, and the window after it is tried next. So does a window that is late (its solve took
    longer than the update period).
    
    With background = false nothing runs on another thread: synchronize(t) solves what is due.
    Simulations call synchronize(t) before every step in either mode, so that their results do not
    depend on how fast the windows are solved (simulate_sampled of sampled_loop.hpp).
    
    Parameters
    ----------
    horizon : RecedingHorizon
        The windows' design.
    period : float
        The controller's period T (s); the horizon's update period is a whole multiple of it.
    options : OnlineOptions, optional
        As for OnlineController: limits, delay compensation, a filter for output feedback.
    kappa : Signal or float, optional
        The gain scaling kappa(t) > 0.
    background : bool, optional
        Solve the next window on a thread of its own (True); False: synchronize() solves it. A model
        implemented in Python is always solved by synchronize() (the thread would need the GIL).
    
    Raises
    ------
    ValueError
        A period that does not divide the update period, bad options, u_d given as a function.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
    >>> controller = hc.RecedingOnlineController(horizon, 0.05)
    >>> q = np.array([1.0, 0.0, 0.0, -1.0, -1.0, 0.0])
    >>> controller.reset(0.0, q)
    >>> for k in range(41):                                         # two seconds at 20 Hz
    ...     controller.synchronize(0.05 * k)                        # a simulation waits for the solver
    ...     u, report = controller.step(0.05 * k, q)
    >>> controller.status().window_in_use, report.window_stale
    (2, False)
    """
    def __init__(self, horizon: RecedingHorizon, period: typing.SupportsFloat | typing.SupportsIndex, options: OnlineOptions = ..., kappa: typing.Any = 1.0, background: bool = True) -> None:
        ...
    def change_path(self, t_join: typing.SupportsFloat | typing.SupportsIndex, u_d: typing.Any) -> None:
        """
        A path changed under way (RecedingHorizon::with_path_change): the windows from the one that
        starts at t_join on follow u_d (a new plan from the desired state there). t_join must be the
        start of a window not yet solved: at least one update period after the window last handed
        over, and not the one being solved (InputError otherwise, or before reset()). Takes the
        solver's lock: from any thread but not in the stepping thread's real-time loop.
        """
    def controller(self) -> OnlineController:
        """
        The online controller that steps (its law is the window in use); InputError before reset().
        """
    def options(self) -> OnlineOptions:
        """
        The options of every window's OnlineController.
        """
    def period(self) -> float:
        """
        The controller's period T (s).
        """
    def reset(self, t: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], u_held: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"] | None = None) -> None:
        """
        Starts at t >= t0 from q (as OnlineController::reset): the windows' trajectories are chained
        from q_d0 up to the window of t, which is solved here (blocking; ConjugatePointError when it
        has no design at gamma), and the solver's thread starts on the next one. Stops a thread that
        runs. May allocate and throw; step() does neither.
        """
    def status(self) -> RecedingOnlineStatus:
        """
        What the horizon has done (takes a lock: not from the stepping thread in real time).
        """
    def step(self, t_now: typing.SupportsFloat | typing.SupportsIndex, q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64] | None = None, t_meas: typing.SupportsFloat | typing.SupportsIndex | None = None) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"], StepReport]:
        """
        One sample, as OnlineController::step; report.window_stale when the law in use is past its
        update period. Never throws, never allocates, takes no lock.
        
        As OnlineController.step; raises ValueError before reset().
        """
    def synchronize(self, t: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Blocks until every window that starts at or before t has been solved (handed over, or
        failed). For simulations and tests, not for a vehicle's loop.
        """
class Law:
    """
    The tracking law of a scenario ([controller] law).
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    hinf
        the paper's H-infinity law (17)/(18), and (34) with measurements
    lqr
        the same design at gamma = inf; with [measurement] also the Kalman-Bucy filter
    cascade
        the cascaded ship baseline (control/cascade.hpp); with [measurement] on the H-infinity estimate
    backstepping
        the backstepping ship baseline (control/backstepping.hpp); likewise
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> scenario.law = "lqr"
    >>> result = hc.run_scenario(scenario)
    >>> result.law, result.gamma
    (<Law.lqr: 1>, inf)
    """
    __members__: typing.ClassVar[dict[str, Law]]
    backstepping: typing.ClassVar[Law]
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    How a run of a study ended.
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    completed
        the closed loop ran over the whole horizon
    diverged
        the closed loop stopped at the divergence bound (simulation.hpp)
    lost_track
        it ran to tf but ended off the path (Scenario::lost_track)
    conjugate_point
        no design: the GRDE escapes at this gamma (gamma <= gamma*)
    coupling_violation
        output feedback: rho(Sigma Z) < gamma^2 failed
    solver_failure
        an integrator failed (SolverError)
    invalid_input
        the scenario is invalid (Scenario::validate, or an InputError later)
    failed
        any other exception
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> low = scenario.copy()
    >>> low.gamma = 1.2                                          # below gamma*
    >>> [run.outcome for run in hc.run_scenarios([scenario, low])]
    [<RunOutcome.completed: 0>, <RunOutcome.conjugate_point: 3>]
    """
    __members__: typing.ClassVar[dict[str, RunOutcome]]
    completed: typing.ClassVar[RunOutcome]
    conjugate_point: typing.ClassVar[RunOutcome]
    coupling_violation: typing.ClassVar[RunOutcome]
    diverged: typing.ClassVar[RunOutcome]
    failed: typing.ClassVar[RunOutcome]
    invalid_input: typing.ClassVar[RunOutcome]
    lost_track: typing.ClassVar[RunOutcome]
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
        """
        The member of that name (ValueError listing the names for another).
        """
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
    [measurement]: imperfect, noisy measurements (paper §4).
    
    Parameters
    ----------
    sigma : float, default 0.0
        std of the noise on each measured output
    sample_period : float, default 0.01
        noise held constant over each period (s)
    seed : int, default 0
        seed of the noise samples (scenario_noise)
    N : array_like, shape (p, p) or (1, 1), optional
        filter weight N = E E' (empty: sigma^2 I)
    Q0 : array_like, shape (n, n) or (1, 1), optional
        Sigma(t0) = (Q0 - eta I)^-1 (empty: 2 I)
    eta : float, default 1.0
        > 0, with Q0 - eta I positive definite
    filter_A : FilterLinearization or str, default 'estimate'
        the A of the filter (36)
    on_coupling_violation : CouplingPolicy or str, default 'error'
        what a violation does
    
    Notes
    -----
    p is the number of measured outputs (rows of the model's C); a 1 x 1 N or Q0 is that many times
    the identity. The values are checked with the scenario (Scenario.validate()).
    
    Examples
    --------
    >>> measurement = hc.load_scenario(hc.scenario_path("paper_fig2")).measurement
    >>> measurement.sigma, measurement.sample_period, measurement.filter_A
    (0.5, 0.01, <FilterLinearization.estimate: 0>)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('sigma', 'sample_period', 'seed', 'N', 'Q0', 'eta', 'filter_A', 'on_coupling_violation')
    def __eq__(self, arg0: MeasurementSpec) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, sigma: typing.SupportsFloat | typing.SupportsIndex = 0.0, sample_period: typing.SupportsFloat | typing.SupportsIndex = 0.01, seed: typing.SupportsInt | typing.SupportsIndex = 0, N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., Q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., eta: typing.SupportsFloat | typing.SupportsIndex = 1.0, filter_A: FilterLinearization | str = FilterLinearization.estimate, on_coupling_violation: CouplingPolicy | str = CouplingPolicy.error) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def N(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        filter weight N = E E' (empty: sigma^2 I)
        """
    @N.setter
    def N(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Q0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Sigma(t0) = (Q0 - eta I)^-1 (empty: 2 I)
        """
    @Q0.setter
    def Q0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def eta(self) -> float:
        """
        > 0, with Q0 - eta I positive definite
        """
    @eta.setter
    def eta(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def filter_A(self) -> FilterLinearization:
        """
        the A of the filter (36)
        """
    @filter_A.setter
    def filter_A(self, arg1: FilterLinearization | str) -> None:
        ...
    @property
    def on_coupling_violation(self) -> CouplingPolicy:
        """
        what a violation does
        """
    @on_coupling_violation.setter
    def on_coupling_violation(self, arg1: CouplingPolicy | str) -> None:
        ...
    @property
    def sample_period(self) -> float:
        """
        noise held constant over each period (s)
        """
    @sample_period.setter
    def sample_period(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def seed(self) -> int:
        """
        seed of the noise samples (scenario_noise)
        """
    @seed.setter
    def seed(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def sigma(self) -> float:
        """
        std of the noise on each measured output
        """
    @sigma.setter
    def sigma(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class DesiredStates:
    """
    [desired] states: the desired trajectory given as states and inputs (trajectory.hpp), e.g. a
    plan of an open-loop-unstable vehicle.
    
    Parameters
    ----------
    t : list of float, optional
        the nodes t_0 = t0 < ... < t_N = tf (s)
    q : array_like, shape (N + 1, n), optional
        the desired states at the nodes, (N + 1) x n; row 0 is [desired] q0
    max_defect : float, default 1e-06
        the largest defect d_k of an interval allowed (the states' units, > 0)
    
    Notes
    -----
    The values are checked with the scenario (Scenario.validate()) and when its trajectory is made;
    docs/scenarios.md has [desired] states.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 2.0
    >>> t = [0.0, 1.0, 2.0]
    >>> trajectory = hc.Trajectory(scenario.model, scenario.desired_q0, scenario.desired_u, 0.0, 2.0)
    >>> scenario.desired_states = hc.DesiredStates(t=t, q=trajectory.q_d(np.array(t)))
    >>> result = hc.run_scenario(scenario)
    >>> len(result.trajectory.node_times()), bool(result.trajectory.max_defect() < 1e-8)
    (3, True)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('t', 'q', 'max_defect')
    def __eq__(self, arg0: DesiredStates) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, t: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex] = [], q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = ..., max_defect: typing.SupportsFloat | typing.SupportsIndex = 1e-06) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def max_defect(self) -> float:
        """
        the largest defect d_k of an interval allowed (the states' units, > 0)
        """
    @max_defect.setter
    def max_defect(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        the desired states at the nodes, (N + 1) x n; row 0 is [desired] q0
        """
    @q.setter
    def q(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def t(self) -> list[float]:
        """
        the nodes t_0 = t0 < ... < t_N = tf (s)
        """
    @t.setter
    def t(self, arg0: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex]) -> None:
        ...
class PathChange:
    """
    [path_change]: the path changed under way, with [receding_horizon] (receding_horizon.hpp): from
    the window that starts at t on, the desired trajectory continues from q_d(t) with the inputs u_d.
    
    Parameters
    ----------
    t : float, default 0.0
        s: a window's start after t0
    u_d : VectorSignal, optional
        the new desired inputs, m channels
    
    Notes
    -----
    Checked with the scenario (Scenario.validate()); docs/scenarios.md has [path_change].
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
    >>> scenario.path_change = hc.PathChange(t=20.0, u_d=hc.VectorSignal([hc.Signal(1.0), hc.Signal(-0.2)]))
    >>> result = hc.run_scenario(scenario)
    >>> bool(np.hypot(*result.simulation.q_e()[-1, 3:5]) < 0.1)      # on the new path at tf
    True
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('t', 'u_d')
    def __eq__(self, arg0: PathChange) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, t: typing.SupportsFloat | typing.SupportsIndex = 0.0, u_d: VectorSignal = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def t(self) -> float:
        """
        s: a window's start after t0
        """
    @t.setter
    def t(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def u_d(self) -> VectorSignal:
        """
        the new desired inputs, m channels
        """
    @u_d.setter
    def u_d(self, arg0: VectorSignal) -> None:
        ...
class SampledDesign:
    """
    Which design a sampled loop runs ([sampling] design).
    
    Parameters
    ----------
    value : int
        The member's number, as its repr shows it.
    name : str
        The member's name, one of those below.
    
    Attributes
    ----------
    emulated
        the continuous design held over each sample (SampledLaw::emulated)
    digital
        the discrete game at the period (SampledLaw::digital, solve_discrete_game)
    
    Examples
    --------
    >>> hc.SamplingSpec(period=0.05, design="digital").design
    <SampledDesign.digital: 1>
    """
    __members__: typing.ClassVar[dict[str, SampledDesign]]
    digital: typing.ClassVar[SampledDesign]
    emulated: typing.ClassVar[SampledDesign]
    def __eq__(self: SampledDesign | str, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self: SampledDesign | str) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, name: str) -> None:
        """
        The member of that name (ValueError listing the names for another).
        """
    def __int__(self: SampledDesign | str) -> int:
        ...
    def __ne__(self: SampledDesign | str, other: typing.Any) -> bool:
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
class SamplingSpec:
    """
    [sampling]: the closed loop as on a vehicle (sampled_loop.hpp): the online controller called
    every `period`, its command held, with a computation delay and actuator limits.
    
    Parameters
    ----------
    period : float, default 0.0
        s: the controller's period T, > 0
    design : SampledDesign or str, default 'emulated'
        the law it runs
    delay : float, default 0.0
        s, in [0, T]: the command is applied this late
    compensate_delay : bool, default True
        predict the measurement over the delay
    limits : ActuatorLimits, optional
        u_min, u_max, rate_max (empty: none)
    max_age : float, default inf
        s: an older measurement is stale
    measurement_period : float, default 0.0
        s: the sensor's period, a multiple of T (0: T)
    measurement_update : MeasurementUpdate or str, default 'sampled'
        how the output-feedback
    
    Notes
    -----
    The values are checked with the scenario (Scenario.validate()); docs/scenarios.md has the
    [sampling] table.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.sampling = hc.SamplingSpec(period=0.1, delay=0.02)
    >>> scenario.tf = 10.0
    >>> result = hc.run_scenario(scenario)
    >>> result.online.steps, result.online.saturated
    (100, 0)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('period', 'design', 'delay', 'compensate_delay', 'limits', 'max_age', 'measurement_period', 'measurement_update')
    def __eq__(self, arg0: SamplingSpec) -> bool:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, period: typing.SupportsFloat | typing.SupportsIndex = 0.0, design: SampledDesign | str = SampledDesign.emulated, delay: typing.SupportsFloat | typing.SupportsIndex = 0.0, compensate_delay: bool = True, limits: ActuatorLimits = ..., max_age: typing.SupportsFloat | typing.SupportsIndex = ..., measurement_period: typing.SupportsFloat | typing.SupportsIndex = 0.0, measurement_update: MeasurementUpdate = MeasurementUpdate.sampled) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def compensate_delay(self) -> bool:
        """
        predict the measurement over the delay
        """
    @compensate_delay.setter
    def compensate_delay(self, arg0: bool) -> None:
        ...
    @property
    def delay(self) -> float:
        """
        s, in [0, T]: the command is applied this late
        """
    @delay.setter
    def delay(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def design(self) -> SampledDesign:
        """
        the law it runs
        """
    @design.setter
    def design(self, arg1: SampledDesign | str) -> None:
        ...
    @property
    def limits(self) -> ActuatorLimits:
        """
        u_min, u_max, rate_max (empty: none)
        """
    @limits.setter
    def limits(self, arg0: ActuatorLimits) -> None:
        ...
    @property
    def max_age(self) -> float:
        """
        s: an older measurement is stale
        """
    @max_age.setter
    def max_age(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def measurement_period(self) -> float:
        """
        s: the sensor's period, a multiple of T (0: T)
        """
    @measurement_period.setter
    def measurement_period(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def measurement_update(self) -> MeasurementUpdate:
        """
        how the output-feedback
        """
    @measurement_update.setter
    def measurement_update(self, arg1: MeasurementUpdate) -> None:
        ...
    @property
    def period(self) -> float:
        """
        s: the controller's period T, > 0
        """
    @period.setter
    def period(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Scenario:
    """
    A scenario: the model, the horizon, the desired trajectory, the law and its design, the
    disturbance, the initial state, the measurement (output feedback) and the solver. Fields left
    empty take the defaults that resolved() fills in.
    
    A scenario: everything one run needs (docs/scenarios.md is the reference of its TOML form).
    Both front ends (the Python package and the hinf-sim executable) build a Scenario and call
    run_scenario(), so they give the same numbers.
    
    Attributes
    ----------
    name : str
        for results and messages (a file's stem by default)
    description : str
        free text
    model : Model
        the design model: desired trajectory, GRDE, controller, estimator
    plant : Model or None
        [plant]: the vehicle the closed loop integrates (its f, G, D),
        when it differs from the design model; null: the design model.
        Same structure as the model (check_plant).
    t0 : float
        [horizon] t0 (s)
    tf : float
        [horizon] tf (s), > t0
    desired_q0 : ndarray, shape (n,)
        q_d(t0)
    desired_u : VectorSignal (set: also a callable or a list of Signal or float)
        u_d(t), m channels
    desired_states : DesiredStates or None
        [desired] states: q_d given at nodes, each
    path_change : PathChange or None
        [path_change]: a new path from t on (with
        [receding_horizon] in the continuous loop)
    gamma : float
        interval integrated from its node; none: q_d integrated from q0
        > 0, may be +inf (LQR)
    Q : ndarray, shape (n, n)
        empty: identity
    Qf : ndarray, shape (n, n)
        empty: identity
    kappa : Signal (set: also a float)
        gain scaling kappa(t) of the law (17)/(18), > 0
    law : Law (set: also its name)
        the tracking law
    cascade : CascadeGains
        the gains of the cascade law
    backstepping : BacksteppingGains
        the gains of the backstepping law
    disturbance : VectorSignal (set: also a callable, a list of Signal or float, or None)
        w(t), nw channels (dim 0: all zero)
    worst_case : bool
        adds the worst-case disturbance gamma^-2 D' Z q_e of paper
        eq. (16) (Z of the H-infinity design at gamma, whatever the
        law) to the disturbance signals
    initial_q0 : ndarray, shape (n,)
        q(t0)
    measurement : MeasurementSpec or None
        imperfect measurements; none: state feedback
    sampling : SamplingSpec or None
        a sampled loop through the online controller;
        none: the continuous loop
    receding_horizon : RecedingHorizonOptions or None
        [receding_horizon]: the law designed
    solver : SolverOptions
        over a moving window (receding_horizon.hpp), state
        feedback in the continuous loop; none: one design
        over [t0, tf]
        every integration: the Riccati equations and the closed loop
    output_dt : float
        [output] dt
    divergence_factor : float
        [solver] divergence_factor (simulation.hpp)
    lost_track : float
        [solver] lost_track (m, > 0, may be inf): a run that ends
        more than this farther from the desired path than it
        started has status LostTrack (models with a position only)
    
    Notes
    -----
    ``Scenario()`` is empty: hc.load_scenario and hc.scenario_from_dict make complete ones. Set model
    before desired_u and disturbance (their number of channels is the model's). A scenario pickles as
    its scenario file (hinf_cpp.scenario.scenario_toml) and solver.escape_norm, which the file does
    not hold; one whose model or signals are implemented in Python does not pickle (TypeError).
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.name, scenario.gamma, scenario.model.name(), scenario.measurement is None
    ('paper-fig1', 5.0, 'ship', True)
    >>> scenario.tf = 10.0                                      # a shorter horizon (s)
    >>> round(hc.run_scenario(scenario).metrics.final_position_error, 3)
    0.084
    """
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
        An independent copy: its fields can be set without changing this one (the model and the signals, which are immutable, are shared).
        """
    def resolved(self) -> Scenario:
        """
        A copy with the defaults filled in (Q = Qf = I, zero disturbance, N = sigma^2 I (a 1 x 1
        N is that many times I), Q0 = 2 I).
        """
    def simulation_options(self) -> SimulationOptions:
        """
        output_dt, divergence_factor and solver, for the closed loop.
        """
    def validate(self) -> None:
        """
        Throws InputError naming the first problem found. Call on a resolved scenario.
        
        An InputError is a ValueError.
        """
    @property
    def Q(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        empty: identity
        """
    @Q.setter
    def Q(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def Qf(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        empty: identity
        """
    @Qf.setter
    def Qf(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        ...
    @property
    def backstepping(self) -> BacksteppingGains:
        """
        the gains of the backstepping law
        """
    @backstepping.setter
    def backstepping(self, arg0: BacksteppingGains) -> None:
        ...
    @property
    def cascade(self) -> CascadeGains:
        """
        the gains of the cascade law
        """
    @cascade.setter
    def cascade(self, arg0: CascadeGains) -> None:
        ...
    @property
    def description(self) -> str:
        """
        free text
        """
    @description.setter
    def description(self, arg0: str) -> None:
        ...
    @property
    def desired_q0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        q_d(t0)
        """
    @desired_q0.setter
    def desired_q0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        ...
    @property
    def desired_states(self) -> DesiredStates | None:
        """
        [desired] states: q_d given at nodes, each
        """
    @desired_states.setter
    def desired_states(self, arg0: DesiredStates | None) -> None:
        ...
    @property
    def desired_u(self) -> VectorSignal:
        """
        u_d(t), m channels
        """
    @desired_u.setter
    def desired_u(self, arg1: typing.Any) -> None:
        ...
    @property
    def disturbance(self) -> VectorSignal:
        """
        w(t), nw channels (dim 0: all zero)
        """
    @disturbance.setter
    def disturbance(self, arg1: typing.Any) -> None:
        ...
    @property
    def divergence_factor(self) -> float:
        """
        [solver] divergence_factor (simulation.hpp)
        """
    @divergence_factor.setter
    def divergence_factor(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def gamma(self) -> float:
        """
        interval integrated from its node; none: q_d integrated from q0
        > 0, may be +inf (LQR)
        """
    @gamma.setter
    def gamma(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def initial_q0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        q(t0)
        """
    @initial_q0.setter
    def initial_q0(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        ...
    @property
    def kappa(self) -> Signal:
        """
        gain scaling kappa(t) of the law (17)/(18), > 0
        """
    @kappa.setter
    def kappa(self, arg1: typing.Any) -> None:
        ...
    @property
    def law(self) -> Law:
        """
        the tracking law
        """
    @law.setter
    def law(self, arg1: Law | str) -> None:
        ...
    @property
    def lost_track(self) -> float:
        """
        [solver] lost_track (m, > 0, may be inf): a run that ends
        more than this farther from the desired path than it
        started has status LostTrack (models with a position only)
        """
    @lost_track.setter
    def lost_track(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def measurement(self) -> MeasurementSpec | None:
        """
        imperfect measurements; none: state feedback
        """
    @measurement.setter
    def measurement(self, arg0: MeasurementSpec | None) -> None:
        ...
    @property
    def model(self) -> Model:
        """
        the design model: desired trajectory, GRDE, controller, estimator
        """
    @model.setter
    def model(self, arg0: Model) -> None:
        ...
    @property
    def name(self) -> str:
        """
        for results and messages (a file's stem by default)
        """
    @name.setter
    def name(self, arg0: str) -> None:
        ...
    @property
    def output_dt(self) -> float:
        """
        [output] dt
        """
    @output_dt.setter
    def output_dt(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def path_change(self) -> PathChange | None:
        """
        [path_change]: a new path from t on (with
        [receding_horizon] in the continuous loop)
        """
    @path_change.setter
    def path_change(self, arg0: PathChange | None) -> None:
        ...
    @property
    def plant(self) -> Model | None:
        """
        [plant]: the vehicle the closed loop integrates (its f, G, D),
        when it differs from the design model; null: the design model.
        Same structure as the model (check_plant).
        """
    @plant.setter
    def plant(self, arg1: Model | None) -> None:
        ...
    @property
    def receding_horizon(self) -> RecedingHorizonOptions | None:
        """
        [receding_horizon]: the law designed
        """
    @receding_horizon.setter
    def receding_horizon(self, arg0: RecedingHorizonOptions | None) -> None:
        ...
    @property
    def sampling(self) -> SamplingSpec | None:
        """
        a sampled loop through the online controller;
        none: the continuous loop
        """
    @sampling.setter
    def sampling(self, arg0: SamplingSpec | None) -> None:
        ...
    @property
    def solver(self) -> SolverOptions:
        """
        over a moving window (receding_horizon.hpp), state
        feedback in the continuous loop; none: one design
        over [t0, tf]
        every integration: the Riccati equations and the closed loop
        """
    @solver.setter
    def solver(self, arg0: SolverOptions) -> None:
        ...
    @property
    def t0(self) -> float:
        """
        [horizon] t0 (s)
        """
    @t0.setter
    def t0(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def tf(self) -> float:
        """
        [horizon] tf (s), > t0
        """
    @tf.setter
    def tf(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def worst_case(self) -> bool:
        """
        adds the worst-case disturbance gamma^-2 D' Z q_e of paper
        eq. (16) (Z of the H-infinity design at gamma, whatever the
        law) to the disturbance signals
        """
    @worst_case.setter
    def worst_case(self, arg0: bool) -> None:
        ...
class Timing:
    """
    The wall-clock time of a run's parts (s).
    
    Attributes
    ----------
    design : float
        desired trajectory, GRDE, eigenvalue bounds of Z
    simulate : float
        closed loop
    analysis : float
        metrics
    total : float
        the whole run_scenario, checks included
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> timing = hc.run_scenario(scenario).timing
    >>> timing.total >= timing.design + timing.simulate
    True
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
        """
        metrics
        """
    @property
    def design(self) -> float:
        """
        desired trajectory, GRDE, eigenvalue bounds of Z
        """
    @property
    def simulate(self) -> float:
        """
        closed loop
        """
    @property
    def total(self) -> float:
        """
        the whole run_scenario, checks included
        """
class RunResult:
    """
    What run_scenario gives: the design, the closed loop and its metrics.
    
    Attributes
    ----------
    scenario_name : str
        the scenario's name
    law : Law
        the scenario's law
    output_feedback : bool
        true with [measurement]
    gamma : float
        of the law's design: the scenario's gamma, inf for lqr
    trajectory : Trajectory
        its model is the design model; with [receding_horizon] the first
        window's desired trajectory (the run's q_d is simulation.q_d)
    plant : Model or None
        the scenario's plant; null when the closed loop integrated the design model
    solution : RiccatiSolution or None
        the law's design; null for the cascade law with state feedback
        when no design exists at gamma (gamma <= gamma*), and with
        [receding_horizon] (the windows are not kept)
    Z0 : ndarray, shape (n, n)
        Z(t0) (n x n); empty without a design
    Z_min_eig : float
        m and M of paper eq. (22) over [t0, tf]
    Z_max_eig : float
        m and M of paper eq. (22) over [t0, tf]
    gamma_star : float or None
        not computed by run_scenario; set by the caller for
        the results file (scenario_gamma_star)
    simulation : SimulationResult
        the closed loop's time series
    sampling : SamplingSpec or None
        the scenario's [sampling]
    online : OnlineCounts or None
        with [sampling]: what the online controller's steps did
    receding_horizon : RecedingHorizonReport or None
        with [receding_horizon]: what was solved
    metrics : Metrics
        of the closed loop (metrics.hpp)
    timing : Timing
        the wall-clock time of its parts
    
    Notes
    -----
    gamma_star may be set (a float or None), as for the results file; the other attributes are
    read-only. == is not defined (the trajectory and the design are shared objects). It pickles with
    its trajectory and design.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> result = hc.run_scenario(scenario)
    >>> result.law, result.gamma, result.output_feedback, result.Z0.shape
    (<Law.hinf: 0>, 5.0, False, (6, 6))
    >>> round(result.metrics.final_position_error, 3), result.simulation.q.shape
    (0.084, (1001, 6))
    """
    __match_args__: typing.ClassVar[tuple] = ('scenario_name', 'law', 'output_feedback', 'gamma', 'trajectory', 'plant', 'solution', 'Z0', 'Z_min_eig', 'Z_max_eig', 'gamma_star', 'simulation', 'sampling', 'online', 'receding_horizon', 'metrics', 'timing')
    def __getstate__(self) -> tuple:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def to_csv(self) -> str:
        """
        The time series on the output grid, one row per time, with a header line: t, the states,
        the desired states (suffix _d), u1.., u1_d.., w1..; with output feedback also the estimated
        errors (suffix _e_hat), the measurements y1.., sigma_min_eig, sigma_max_eig, rho_sigma_z.
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = 2) -> str:
        """
        The results file of scenarios.md (one JSON object, matrices as nested row-major lists,
        non-finite numbers as null).
        """
    @property
    def Z0(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Z(t0) (n x n); empty without a design
        """
    @property
    def Z_max_eig(self) -> float:
        """
        m and M of paper eq. (22) over [t0, tf]
        """
    @property
    def Z_min_eig(self) -> float:
        """
        m and M of paper eq. (22) over [t0, tf]
        """
    @property
    def gamma(self) -> float:
        """
        of the law's design: the scenario's gamma, inf for lqr
        """
    @property
    def gamma_star(self) -> float | None:
        """
        not computed by run_scenario; set by the caller for
        the results file (scenario_gamma_star)
        """
    @gamma_star.setter
    def gamma_star(self, arg0: typing.SupportsFloat | typing.SupportsIndex | None) -> None:
        ...
    @property
    def law(self) -> Law:
        """
        the scenario's law
        """
    @property
    def metrics(self) -> Metrics:
        """
        of the closed loop (metrics.hpp)
        """
    @property
    def online(self) -> OnlineCounts | None:
        """
        with [sampling]: what the online controller's steps did
        """
    @property
    def output_feedback(self) -> bool:
        """
        true with [measurement]
        """
    @property
    def plant(self) -> Model | None:
        """
        the scenario's plant; null when the closed loop integrated the design model
        """
    @property
    def receding_horizon(self) -> RecedingHorizonReport | None:
        """
        with [receding_horizon]: what was solved
        """
    @property
    def sampling(self) -> SamplingSpec | None:
        """
        the scenario's [sampling]
        """
    @property
    def scenario_name(self) -> str:
        """
        the scenario's name
        """
    @property
    def simulation(self) -> SimulationResult:
        """
        the closed loop's time series
        """
    @property
    def solution(self) -> RiccatiSolution:
        """
        the law's design; null for the cascade law with state feedback
        when no design exists at gamma (gamma <= gamma*), and with
        [receding_horizon] (the windows are not kept)
        """
    @property
    def timing(self) -> Timing:
        """
        the wall-clock time of its parts
        """
    @property
    def trajectory(self) -> Trajectory:
        """
        its model is the design model; with [receding_horizon] the first
        window's desired trajectory (the run's q_d is simulation.q_d)
        """
class StudyOptions:
    """
    Options of run_scenarios.
    
    Parameters
    ----------
    threads : int, default 0
        worker threads (>= 0); 0: the hardware's threads; never more than runs
    share_designs : bool, default True
        compute each distinct design once: runs with equal design
        inputs share it (see above)
    
    Notes
    -----
    run_scenarios uses one thread when a model or a signal is implemented in Python.
    
    Raises
    ------
    ValueError
        threads < 0.
    
    Examples
    --------
    >>> hc.StudyOptions(threads=2, share_designs=False)
    StudyOptions(threads=2, share_designs=False)
    """
    __hash__: typing.ClassVar[None] = None
    __match_args__: typing.ClassVar[tuple] = ('threads', 'share_designs')
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
    def share_designs(self) -> bool:
        """
        compute each distinct design once: runs with equal design
        inputs share it (see above)
        """
    @share_designs.setter
    def share_designs(self, arg0: bool) -> None:
        ...
    @property
    def threads(self) -> int:
        """
        worker threads (>= 0); 0: the hardware's threads; never more than runs
        """
    @threads.setter
    def threads(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
class StudyRun:
    """
    One row of a study.
    
    Attributes
    ----------
    status : str
        how the run ended
    reason : str
        empty when completed; else the error message or the status message
    metrics : Metrics
        all NaN when the run failed before its closed loop ended; a diverged
        run has what compute_metrics gives for the part it ran
    gamma : float
        of the law's design (inf for lqr), as RunResult::gamma
    law : Law
        the scenario's law
    output_feedback : bool
        true with [measurement]
    design_seconds : float
        wall-clock time of the design the run used (a shared design's
        time is given in each of its runs)
    simulate_seconds : float
        closed loop and metrics
    design : int
        which of the study's designs the run used: runs with the same number shared
        one; -1 when the run failed before a design was made (invalid input)
    
    Notes
    -----
    status is the name of the outcome ('completed', 'diverged', 'conjugate_point', 'coupling_violation',
    'solver_failure', 'invalid_input', 'failed'); the property outcome is the RunOutcome.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> low = scenario.copy()
    >>> low.gamma = 1.2                                          # below gamma*
    >>> done, failed = hc.run_scenarios([scenario, low])
    >>> done.status, round(done.metrics.max_position_error, 3), failed.status, failed.reason[:15]
    ('completed', 1.414, 'conjugate_point', 'conjugate point')
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
        """
        which of the study's designs the run used: runs with the same number shared
        one; -1 when the run failed before a design was made (invalid input)
        """
    @property
    def design_seconds(self) -> float:
        """
        wall-clock time of the design the run used (a shared design's
        time is given in each of its runs)
        """
    @property
    def gamma(self) -> float:
        """
        of the law's design (inf for lqr), as RunResult::gamma
        """
    @property
    def law(self) -> Law:
        """
        the scenario's law
        """
    @property
    def metrics(self) -> Metrics:
        """
        all NaN when the run failed before its closed loop ended; a diverged
        run has what compute_metrics gives for the part it ran
        """
    @property
    def outcome(self) -> RunOutcome:
        """
        how the run ended
        """
    @property
    def output_feedback(self) -> bool:
        """
        true with [measurement]
        """
    @property
    def reason(self) -> str:
        """
        empty when completed; else the error message or the status message
        """
    @property
    def simulate_seconds(self) -> float:
        """
        closed loop and metrics
        """
    @property
    def status(self) -> str:
        """
        how the run ended
        
        By name (outcome: the RunOutcome).
        """
def certify(Z: RiccatiSolution, kappa: typing.Any, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> Certificates:
    """
    The certificates of the design Z (its trajectory and gamma) for the law (17)/(18) with gain
    scaling kappa(t), and Q, the weight of the GRDE (n x n, symmetric positive semidefinite;
    InputError otherwise). L is the model's remainder_bound where it has one, else a sampled
    estimate (remainder_is_bound false).
    
    Parameters
    ----------
    Z : RiccatiSolution
        The design (solve_grde).
    kappa : Signal or float
        The gain scaling kappa(t) of the law.
    Q : array_like, shape (n, n)
        The GRDE's weight Q.
    
    Returns
    -------
    Certificates
    
    Raises
    ------
    ValueError
        kappa not a Signal or a finite number; Q not a symmetric positive semidefinite (n, n) matrix.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> certificates = hc.certify(design, 1.0, np.eye(6))
    >>> certificates.remainder_is_bound, certificates.decay_rate > 0      # the ship's analytic L
    (True, True)
    """
def check_model_structure(structure: ModelStructure) -> None:
    """
    check_dimensions, and: n state names, position indices distinct and in [0, n), heading
    index -1 or in [0, n), noise channels distinct and in [0, nw), and not both constant and
    state-dependent input matrices. InputError naming the first fault.
    """
def check_scenario_toml(text: str, source: str) -> None:
    """
    Every check that needs no model, with nothing loaded or run whatever the model's kind: the
    reader's keys, types and values, and Scenario::validate_settings (trust aside). The sizes a
    model sets (the length of q0, the inputs u1..um, the channels w1..wnw) are not checked.
    InputError naming the source, as parse_scenario_toml. parse_scenario_toml runs these checks
    first when a model section's kind is a program.
    """
def clear_interrupt() -> None:
    """
    Withdraws a request (a computation's front end does, before it starts, for one that was
    already answered).
    """
def code_trusted_by_environment() -> bool:
    """
    The environment's answer to "may files run code": HINF_TRUST_CODE = 1 yes, unset, empty or 0
    no, anything else an InputError. The front ends use it as the default of their --trust-code.
    """
def compute_metrics(model: Model, run: SimulationResult, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"] | None = None, gamma: typing.SupportsFloat | typing.SupportsIndex = ..., initial_term: typing.SupportsFloat | typing.SupportsIndex = ...) -> Metrics:
    """
    The metrics of a closed-loop run of `model` (whose position and heading indices they use),
    with Q (n x n, symmetric positive semidefinite) weighting q_e in the costs and gains.
    InputError when the run's series do not fit the model or Q is not such a weight.
    
    The same with the terminal weight and the bound of the H-infinity law (CostWeights); Qf must
    be an n x n symmetric positive semidefinite weight when given, gamma > 0, initial_term >= 0.
    
    Parameters
    ----------
    model : Model
        The model simulated (its position and heading indices).
    run : SimulationResult
        The closed-loop run.
    Q : array_like, shape (n, n)
        The weight of q_e in the tracking cost and the gains.
    Qf : array_like, shape (n, n), optional
        The weight of q_e(tf) in the tracking cost; none: no terminal term.
    gamma : float, default inf
        The H-infinity law's attenuation level, for attenuation_margin; inf: no margin.
    initial_term : float, default nan
        The initial-error term of the law's bound (q_e0' Z(t0) q_e0 with state feedback); nan: no
        margin.
    
    Returns
    -------
    Metrics
    
    Raises
    ------
    ValueError
        Series whose shapes do not fit the model, Q or Qf not symmetric positive semidefinite, gamma
        not > 0 or initial_term negative.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> run = hc.simulate_state_feedback(trajectory, hc.HinfStateFeedback(design), None,
    ...                               [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
    >>> metrics = hc.compute_metrics(trajectory.model(), run, np.eye(6))
    >>> round(metrics.max_position_error, 3), metrics.response_ratio         # no disturbance: no gain
    (1.414, nan)
    """
def controller_escape_time(trajectory: Trajectory, controller: Controller, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, options: SolverOptions = ...) -> float:
    """
    The same two for any state-feedback controller of the trajectory's model (the ship
    baselines, a law written in Python), linearized along the trajectory: K(t) = -du/dq at
    (t, q_d(t)) from controller.control_jacobian (central differences unless it has its own).
    Calls the controller from this thread only. InputError for a controller of other sizes.
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory the controller tracks.
    controller : Controller
        The controller (see controller_gain).
    Q : array_like, shape (n, n)
        The weight of the tracking error in z.
    Qf : array_like, shape (n, n)
        The weight of the final error.
    gamma : float
        The level tested.
    options : SolverOptions, optional
        Integrator and tolerances.
    
    Returns
    -------
    float
        The first escape of the controller's closed-loop Riccati equation (backward from tf), or
        NaN: its induced L2 gain is below gamma.
    
    Raises
    ------
    ValueError
        As controller_gain.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> law = hc.BacksteppingController(trajectory)
    >>> hc.controller_escape_time(trajectory, law, np.eye(6), np.eye(6), 10.0)
    nan
    """
def controller_gain(trajectory: Trajectory, controller: Controller, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: GammaStarOptions = ...) -> GammaStarResult:
    """
    The same for any state-feedback controller of the trajectory's model, linearized along it
    (controller_escape_time, riccati.hpp): the ship baselines have one too. The
    gammas are tried one at a time (the controller is called from this thread only).
    
    gamma*, conjugate points and the certificates of paper §3.
    
    gamma* (eq. 14) is the infimum of the gammas for which the GRDE (13) has no conjugate point
    on [t0, tf]. Whether a given gamma passes is decided by grde_escape_time(), which follows
    the inverse W = Z^-1 through an escape, so no escape between solver steps is missed. The
    pass/fail answer is monotone in gamma, so gamma* is found by bisection (k-section: one
    evaluation per thread and round).
    
    With imperfect measurements (paper §4) a gamma must also keep the filter Riccati equation
    (36) (here with A = A_e(t)) bounded and positive definite and satisfy the coupling
    condition rho(Sigma Z) < gamma^2 on [t0, tf]; each condition is monotone in gamma too.
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory the controller tracks (its model's n and m).
    controller : Controller
        Any state-feedback controller: CascadeController, BacksteppingController, a law written in
        Python. It is linearized along the trajectory, K(t) = -du/dq at q_d(t), by its
        control_jacobian (central differences unless it has its own).
    Q : array_like, shape (n, n)
        Weight of the tracking error in z, symmetric positive semidefinite.
    Qf : array_like, shape (n, n)
        Weight of the final error, symmetric positive definite.
    options : GammaStarOptions, optional
        The bracket, tolerance, evaluations and solver options of the search (one gamma at a time).
    
    Returns
    -------
    GammaStarResult
        The induced L2 gain of the controller's linearized closed loop from w to z on [t0, tf] as
        gamma_star.
    
    Raises
    ------
    ValueError
        A controller of other sizes than the model, Q or Qf not such weights, bad options.
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> gains = [hc.controller_gain(trajectory, law, np.eye(6), np.eye(6)).gamma_star
    ...          for law in (hc.CascadeController(trajectory), hc.BacksteppingController(trajectory))]
    >>> [round(gain, 2) for gain in gains]                       # the ship baselines' attenuation
    [4.33, 2.57]
    """
def discrete_conjugate_time(sampled: SampledLinearization, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    The latest sample time t_k at which the existence condition fails (the recursion stops there),
    or NaN when it holds for every k: the pass/fail test of the discrete gamma*. Nothing is
    stored; the same input checks as solve_discrete_game.
    
    Parameters
    ----------
    sampled : SampledLinearization
    Q : array_like, shape (n, n)
        Weight of the tracking error, as for solve_discrete_game.
    Qf : array_like, shape (n, n)
        M_N, as for solve_discrete_game.
    gamma : float
        The attenuation level.
    
    Returns
    -------
    float
        t_k (s), or nan.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> sampled = hc.SampledLinearization(trajectory, 0.1)
    >>> hc.discrete_conjugate_time(sampled, np.eye(6), np.eye(6), 5.0), hc.discrete_conjugate_time(sampled, np.eye(6), np.eye(6), 1.0)
    (nan, 7.6000000000000005)
    """
def filter_escape_time(trajectory: Trajectory, N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: SolverOptions = ...) -> float:
    """
    The same for the filter Riccati equation (36) (forward from Sigma0, A = A_e(t)).
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory (A = A_e(t); C of its model).
    N : array_like, shape (p, p)
        The measurement noise weight.
    Q : array_like, shape (n, n)
        The weight of the performance index.
    gamma : float
        The attenuation level.
    Sigma0 : array_like, shape (n, n)
        Sigma(t0).
    options : SolverOptions, optional
        Integrator and tolerances.
    
    Returns
    -------
    float
        The first time (s) Sigma escapes or loses positive definiteness, or NaN.
    
    Raises
    ------
    ValueError
        As solve_filter_riccati.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> hc.filter_escape_time(trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
    nan
    """
def gamma_star(trajectory: Trajectory, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: GammaStarOptions = ...) -> GammaStarResult:
    """
    gamma* of the state-feedback design (trajectory, Q, Qf, horizon).
    
    gamma*, conjugate points and the certificates of paper §3.
    
    gamma* (eq. 14) is the infimum of the gammas for which the GRDE (13) has no conjugate point
    on [t0, tf]. Whether a given gamma passes is decided by grde_escape_time(), which follows
    the inverse W = Z^-1 through an escape, so no escape between solver steps is missed. The
    pass/fail answer is monotone in gamma, so gamma* is found by bisection (k-section: one
    evaluation per thread and round).
    
    With imperfect measurements (paper §4) a gamma must also keep the filter Riccati equation
    (36) (here with A = A_e(t)) bounded and positive definite and satisfy the coupling
    condition rho(Sigma Z) < gamma^2 on [t0, tf]; each condition is monotone in gamma too.
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory (its horizon [t0, tf]).
    Q : array_like, shape (n, n)
        Weight of the tracking error, symmetric positive semidefinite.
    Qf : array_like, shape (n, n)
        Final value Z(tf), symmetric positive definite.
    options : GammaStarOptions, optional
        The bracket, tolerance, evaluations, threads and solver options.
    
    Returns
    -------
    GammaStarResult
        gamma*, the final bracket and every gamma tried.
    
    Raises
    ------
    ValueError
        Q or Qf not such weights, bad options.
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> result = hc.gamma_star(trajectory, np.eye(6), np.eye(6))
    >>> round(result.gamma_star, 4), result.binding                  # below it, no design
    (1.3346, <GammaCondition.grde: 1>)
    """
def gamma_star_discrete(sampled: SampledLinearization, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: GammaStarOptions = ...) -> GammaStarResult:
    """
    The discrete gamma*_d of the digital design at the sampled linearization's period
    (discrete_design.hpp): the smallest gamma that keeps gamma^2 T I - D_k' M_{k+1} D_k > 0 at every
    sample. binding is Grde (the discrete conjugate point) and t_escape_lower the latest sample
    time where the lower end fails. The recursion is exact: options.solver is not used.
    
    Parameters
    ----------
    sampled : SampledLinearization
        The linearization sampled at the controller's period.
    Q : array_like, shape (n, n)
        Weight of the tracking error, as for solve_discrete_game.
    Qf : array_like, shape (n, n)
        M_N, as for solve_discrete_game.
    options : GammaStarOptions, optional
        The bracket, tolerance, evaluations and threads.
    
    Returns
    -------
    GammaStarResult
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> sampled = hc.SampledLinearization(trajectory, 0.1)
    >>> round(hc.gamma_star_discrete(sampled, np.eye(6), np.eye(6)).gamma_star, 4)
    1.3992
    """
def gamma_star_discrete_output_feedback(sampled: SampledLinearization, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], C: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], R: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: GammaStarOptions = ...) -> GammaStarResult:
    """
    The smallest gamma of the digital output feedback (discrete_output_feedback.hpp): the discrete
    game exists (binding Grde), its filter exists from Sigma0 (Filter) and rho(Sigma_k M_k) < gamma^2
    at every sample (Coupling); C, R (the covariance of one measurement) and Sigma0 as for
    solve_discrete_output_feedback. The recursions are exact: options.solver is not used.
    
    Parameters
    ----------
    sampled : SampledLinearization
        The linearization sampled at the controller's period.
    Q : array_like, shape (n, n)
        Weight of the tracking error, as for solve_discrete_game (and the filter's).
    Qf : array_like, shape (n, n)
        M_N, as for solve_discrete_game.
    C : array_like, shape (p, n)
        The measurement matrix.
    R : array_like, shape (p, p)
        The covariance of one measurement.
    Sigma0 : array_like, shape (n, n)
        The initial uncertainty.
    options : GammaStarOptions, optional
        The bracket, tolerance, evaluations and threads.
    
    Returns
    -------
    GammaStarResult
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> sampled = hc.SampledLinearization(trajectory, 0.1)
    >>> C = np.hstack([np.zeros((3, 3)), np.eye(3)])
    >>> result = hc.gamma_star_discrete_output_feedback(sampled, np.eye(6), np.eye(6), C, 0.25 * np.eye(3), np.eye(6))
    >>> result.binding, bool(result.gamma_star > hc.gamma_star_discrete(sampled, np.eye(6), np.eye(6)).gamma_star)
    (<GammaCondition.coupling: 3>, True)
    """
def gamma_star_output_feedback(trajectory: Trajectory, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: GammaStarOptions = ...) -> GammaStarResult:
    """
    The smallest gamma for the output-feedback design: no conjugate point of the GRDE, the
    filter Riccati equation (36) with A_e(t) bounded and positive definite from Sigma0, and
    rho(Sigma Z) < gamma^2 on [t0, tf]. binding names the condition that limits it.
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory (its model has a measurement, Model.C).
    Q : array_like, shape (n, n)
        Weight of the tracking error.
    Qf : array_like, shape (n, n)
        Final value Z(tf).
    N : array_like, shape (p, p)
        The measurement noise weight, symmetric positive definite.
    Sigma0 : array_like, shape (n, n)
        Sigma(t0), symmetric positive definite.
    options : GammaStarOptions, optional
        The bracket, tolerance, evaluations, threads and solver options.
    
    Returns
    -------
    GammaStarResult
        The smallest gamma; binding is the condition that limits it.
    
    Raises
    ------
    ValueError
        A model without a measurement, matrices that are not such weights, bad options.
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> N, Sigma0 = 0.25 * np.eye(3), np.eye(6)                  # x, y, psi measured; Sigma(t0)
    >>> result = hc.gamma_star_output_feedback(trajectory, np.eye(6), np.eye(6), N, Sigma0)
    >>> round(result.gamma_star, 2), result.binding                  # the GRDE alone allows 1.33
    (4.59, <GammaCondition.coupling: 3>)
    """
def grde_escape_time(trajectory: Trajectory, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, options: SolverOptions = ...) -> float:
    """
    The first finite escape of Z (integrating the GRDE backward from tf): a conjugate point
    on [t0, tf] (paper eq. 14), or NaN when there is none. Nothing is stored; the same input
    checks as solve_grde. The escape is located on the inverse W = Z^-1, which is smooth
    there, so no escape between solver steps is missed.
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory.
    Q : array_like, shape (n, n)
        Weight of the tracking error.
    Qf : array_like, shape (n, n)
        Final value Z(tf).
    gamma : float
        The attenuation level.
    options : SolverOptions, optional
        Integrator and tolerances.
    
    Returns
    -------
    float
        The escape time (s), or NaN when Z stays finite on [t0, tf].
    
    Raises
    ------
    ValueError
        As solve_grde.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> hc.grde_escape_time(trajectory, np.eye(6), np.eye(6), 5.0)              # gamma > gamma*
    nan
    >>> round(hc.grde_escape_time(trajectory, np.eye(6), np.eye(6), 1.0), 2)     # gamma < gamma* = 1.33
    7.56
    """
def interrupt_requested() -> bool:
    """
    Whether an interrupt is requested.
    """
def l2_norm(t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], series: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> float:
    """
    sqrt of the trapezoid integral of the squared row norms of series over times t.
    """
def law_escape_time(law: RiccatiSolution, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, kappa: Signal = ..., options: SolverOptions = ...) -> float:
    """
    The closed loop of a state-feedback law: u = u_d - kappa(t) K(t) (q - q_d), K = B_e' Z(t) of
    `law` (a design at any gamma: the H-infinity law at its own gamma, the LQR law at gamma = inf),
    linearized along the design's trajectory, with x = q - q_d and the weighted error z,
        dx/dt = (A_e - B_e K) x + D_e w,   z'z = x'Q x + |K x|^2 (kappa folded into K),
    plus x(tf)' Qf x(tf) at the end. From x(t0) = 0 its induced L2 gain over [t0, tf],
    sup_w (|z|^2 + x(tf)'Qf x(tf)) / |w|^2, is below gamma exactly when
        -dP/dt = A_cl' P + P A_cl + Q + K'K + gamma^-2 P D_e D_e' P,   P(tf) = Qf,
    has no conjugate point on [t0, tf]. The first escape of P (backward from tf), or NaN;
    nothing is stored. Q symmetric positive semidefinite, Qf positive definite, gamma > 0, kappa > 0.
    
    Parameters
    ----------
    law : RiccatiSolution
        The law's design (see law_gain).
    Q : array_like, shape (n, n)
        The weight of the tracking error in z.
    Qf : array_like, shape (n, n)
        The weight of the final error.
    gamma : float
        The level tested.
    kappa : float or Signal, optional
        The law's gain scaling (default 1).
    options : SolverOptions, optional
        Integrator and tolerances.
    
    Returns
    -------
    float
        The first escape of the law's closed-loop Riccati equation (backward from tf), or NaN when
        there is none: the law's induced L2 gain is below gamma.
    
    Raises
    ------
    ValueError
        As law_gain.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), float("inf"))
    >>> hc.law_escape_time(lqr, np.eye(6), np.eye(6), 2.2)             # above its gain 2.134
    nan
    >>> round(hc.law_escape_time(lqr, np.eye(6), np.eye(6), 2.0), 2)   # below: P escapes at t = 3.35
    3.35
    """
def law_gain(law: RiccatiSolution, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], kappa: Signal = ..., options: GammaStarOptions = ...) -> GammaStarResult:
    """
    The induced L2 gain of a state-feedback law's closed loop (law_escape_time, riccati.hpp): the
    smallest gamma whose closed-loop Riccati equation has no conjugate point on [t0, tf], found as
    gamma* is (binding Grde). For the H-infinity law at its gamma it lies between gamma* and that
    gamma; the LQR law (a design at gamma = inf) has one too.
    
    gamma*, conjugate points and the certificates of paper §3.
    
    gamma* (eq. 14) is the infimum of the gammas for which the GRDE (13) has no conjugate point
    on [t0, tf]. Whether a given gamma passes is decided by grde_escape_time(), which follows
    the inverse W = Z^-1 through an escape, so no escape between solver steps is missed. The
    pass/fail answer is monotone in gamma, so gamma* is found by bisection (k-section: one
    evaluation per thread and round).
    
    With imperfect measurements (paper §4) a gamma must also keep the filter Riccati equation
    (36) (here with A = A_e(t)) bounded and positive definite and satisfy the coupling
    condition rho(Sigma Z) < gamma^2 on [t0, tf]; each condition is monotone in gamma too.
    
    Parameters
    ----------
    law : RiccatiSolution
        The law's design: Z of the GRDE at the law's gamma (the H-infinity law), or at gamma = inf
        (the LQR law). The law is u = u_d - kappa B_e' Z (q - q_d).
    Q : array_like, shape (n, n)
        Weight of the tracking error in z, symmetric positive semidefinite.
    Qf : array_like, shape (n, n)
        Weight of the final error, symmetric positive definite.
    kappa : float or Signal, optional
        The law's gain scaling kappa(t) > 0 (default 1).
    options : GammaStarOptions, optional
        The bracket, tolerance, evaluations, threads and solver options of the search.
    
    Returns
    -------
    GammaStarResult
        The induced L2 gain of the law's linearized closed loop from w to z on [t0, tf] as
        gamma_star, with its bracket and every gamma tried.
    
    Raises
    ------
    ValueError
        Q or Qf not such weights, kappa not > 0, bad options.
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> hinf = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), float("inf"))
    >>> gains = [hc.law_gain(law, np.eye(6), np.eye(6)).gamma_star for law in (hinf, lqr)]
    >>> [round(gain, 3) for gain in gains]                       # each law's own attenuation
    [2.071, 2.134]
    """
def load_scenario_toml(path: str, allow_code: bool = False) -> Scenario:
    """
    Reads and parses a scenario file; a file that cannot be read (missing, a directory) is an
    InputError naming the path.
    """
def max_rho_sigma_z(Z: RiccatiSolution, Sigma: FilterRiccatiSolution) -> tuple[float, float]:
    """
    The largest value of rho(Sigma(t) Z(t)) on [t0, tf] and where it is taken.
    
    Parameters
    ----------
    Z : RiccatiSolution
        The GRDE's solution.
    Sigma : FilterRiccatiSolution
        The filter's solution along the same trajectory.
    
    Returns
    -------
    tuple of float
        (the largest rho(Sigma(t) Z(t)), t in seconds).
    
    Raises
    ------
    ValueError
        Solutions of different sizes.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> Sigma = hc.solve_filter_riccati(trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
    >>> rho, t = hc.max_rho_sigma_z(design, Sigma)
    >>> round(rho, 2), t, rho < design.gamma() ** 2              # the coupling condition holds
    (20.81, 0.0, True)
    """
def metric_table() -> list[MetricDefinition]:
    """
    The metrics, in the order of the results file.
    
    Returns
    -------
    list of MetricDefinition
    
    Examples
    --------
    >>> [definition.name for definition in hc.metric_table()][:3]
    ['rms_position_error_last_half', 'max_position_error', 'final_position_error']
    """
def needs_planning_toml(text: str, source: str) -> bool:
    """
    Whether a scenario document's [desired] or [path_change] gives waypoints, a path or plan
    options (the planner of the Python package replaces them by inputs), parsed with every guard of parse_scenario_toml
    (an InputError for what it refuses).
    """
def noise_sample_count(t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex, period: typing.SupportsFloat | typing.SupportsIndex) -> int:
    """
    Number of noise samples held over `period` that cover [t0, tf] (the last may be partial).
    """
def output_count(t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex, dt: typing.SupportsFloat | typing.SupportsIndex) -> int:
    """
    The number of points of output_grid(t0, tf, dt), without building it.
    """
def output_grid(t0: typing.SupportsFloat | typing.SupportsIndex, tf: typing.SupportsFloat | typing.SupportsIndex, dt: typing.SupportsFloat | typing.SupportsIndex) -> list[float]:
    """
    t0, t0 + dt, t0 + 2 dt, ..., ending exactly at tf: the last interval may be shorter, or up
    to 1e-6 dt longer (rather than leave a sliver of an interval).
    """
def overshoot_warning(signal: Signal, name: str) -> str:
    """
    A warning when a table's interpolant overshoots the range of its values (see
    Signal::overshoot), naming the signal `name`; empty otherwise.
    """
def parse_model_toml(text: str, source: str, allow_code: bool = False) -> Model:
    """
    The model of a document's [model] section, read as parse_scenario_toml reads it (the planner
    of the Python package needs the model before the desired inputs exist).
    """
def parse_scenario_toml(text: str, source: str, allow_code: bool = False) -> Scenario:
    """
    The one scenario reader: hinf-sim and the Python package (hinf_cpp.load_scenario,
    scenario_from_dict) both read scenarios through it, so they accept and reject the same files
    with the same messages.
    
    Parses a scenario (UTF-8 TOML; a leading byte-order mark is allowed). Everything wrong is an
    InputError naming the source, and the key where there is one: unknown keys, wrong types,
    integers beyond 64 bits, non-finite numbers (only gamma may be inf), empty arrays, noise
    channels of the model in [disturbance], keys nested too deeply, text that is not UTF-8.
    source names the text in messages (usually the file path); the scenario name defaults to
    the file's stem.
    
    Trust: a file is data. A model section whose kind loads or runs a program (kind = "casadi"
    loads the compiled library its model.json names; kind = "python" imports and calls Python
    code) is read only with allow_code; otherwise it is an InputError naming the key and how to
    allow it (hinf-sim and hinf-cpp --trust-code, trust_code=True in Python, HINF_TRUST_CODE=1).
    
    A model section whose kind is a program is loaded only after every other check of the file
    has passed (the sizes that the model sets are checked after it, as they must be).
    """
def parse_signal_toml(text: str, key: str, source: str) -> Signal:
    """
    A signal from a TOML document whose one key is `key` (a number or a signal table, as in a
    scenario), e.g. "kappa = { offset = 1.0 }".
    """
def receding_horizon_gamma_star(horizon: RecedingHorizon, tf: typing.SupportsFloat | typing.SupportsIndex, options: GammaStarOptions = ...) -> WindowGammaStar:
    """
    Each window's gamma* (gamma_star, analysis.hpp, with the horizon's solver) from t0 to the last
    window that starts before tf, and the largest. The horizon's gamma is used only by the
    stationary terminal weight (the ARE at the design's gamma; the search keeps it fixed).
    
    The receding-horizon design: the GRDE (13) solved over a window that moves with time, so that a
    mission of any length is designed with memory that depends on the window, not on the mission.
    
    Window j starts at t_j = t0 + j * update and covers [t_j, t_j + H] (H = window):
      - its desired trajectory is eq. (8) integrated from q_d(t_j) of window j - 1 (q_d0 for
        j = 0) with the same u_d: the windows chain into one desired trajectory, continuous at every
        t_j, whose value differs from one integration over the whole mission by the integration
        error only (trajectory.hpp);
      - its design is the GRDE solved backward from Z(t_j + H) = the terminal weight, with its own
        conjugate-point check (ConjugatePointError names the window). The terminal weight is Qf
        (TerminalWeight::Qf), or the stabilizing solution of the stationary game ARE of the
        linearization frozen at the window's end (TerminalWeight::Stationary, solve_game_are): the
        cost-to-go of an infinite horizon beyond the window, so that the window's Z is that of a
        longer horizon already at its start (for a slowly varying trajectory);
      - the law of window j is used on [t_j, t_{j+1}): u = u_d - kappa B_e' Z_j (q - q_d), so the
        Z in use is always at least H - update before its window's end, where the terminal weight
        has decayed (the gain of a fixed-horizon design collapses towards B' Qf over its last
        seconds; the receding horizon never reaches them).
    The gamma a receding-horizon run certifies is the largest gamma* over its windows: each window
    is a finite-horizon game of its own (receding_horizon_gamma_star).
    
    A desired trajectory given as states (a planner's nodes, for a vehicle open-loop unstable
    along its plan; trajectory.hpp): each window is the states form over its own interval, from its
    start (the node there, or the chained q_d) through the nodes inside it, each interval
    integrated from its node; beyond the last node the window integrates from it. The windows
    then chain without the open-loop drift of one integration. The nodes are kept whole (their
    memory grows with the mission: n + 1 numbers per node).
    
    A path changed under way (with_path_change): from the window that starts at t_join on, the
    windows' trajectories continue from the chained q_d(t_join) with other inputs (a new plan from
    that state); the windows before it keep the old inputs to their ends.
    
    Parameters
    ----------
    horizon : RecedingHorizon
        The windows' design (its gamma is not used: each window's gamma* is searched).
    tf : float
        The end of the mission (s): the windows that start before it are searched.
    options : GammaStarOptions, optional
        The bisection of each window (its solver is replaced by the horizon's).
    
    Returns
    -------
    WindowGammaStar
        The largest gamma* over the windows, the window where it occurs and its search.
    
    Raises
    ------
    ValueError
        tf <= t0, bad options.
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=5.0, update=5.0))
    >>> hc.receding_horizon_gamma_star(horizon, 10.0).windows
    2
    """
def request_interrupt() -> None:
    """
    Requests that the running computations stop at their next step (as Ctrl-C does); safe in a
    signal handler.
    
    Ctrl-C for long computations. A process-wide request that a signal handler may set (a
    lock-free atomic store: async-signal-safe) and that every integrator reads after each step:
    a request ends the computation with Interrupted within one step. hinf-sim installs a SIGINT
    handler that sets it; the Python module chains one before Python's own, so that a Ctrl-C
    stops a C++ call that runs without the GIL and Python then raises KeyboardInterrupt.
    
    A computation that it stops raises KeyboardInterrupt.
    """
def results_csv(result: RunResult) -> str:
    """
    The time series on the output grid, one row per time, with a header line: t, the states,
    the desired states (suffix _d), u1.., u1_d.., w1..; with output feedback also the estimated
    errors (suffix _e_hat), the measurements y1.., sigma_min_eig, sigma_max_eig, rho_sigma_z.
    """
def results_json(result: RunResult, indent: typing.SupportsInt | typing.SupportsIndex = 2) -> str:
    """
    The results file of scenarios.md (one JSON object, matrices as nested row-major lists,
    non-finite numbers as null).
    """
def run_scenario(scenario: Scenario) -> RunResult:
    """
    One run: resolves and validates the scenario (InputError naming the key), designs the law
    (the desired trajectory, Z of the GRDE at the law's gamma), simulates the closed loop (state
    feedback, or output feedback with [measurement], its noise from the seed), and computes the
    metrics. ConjugatePointError when the design needs Z and gamma <= gamma*;
    CouplingConditionError and SolverError as the closed loops raise them.
    
    Parameters
    ----------
    scenario : Scenario
        The scenario (hc.load_scenario, hc.scenario_from_dict).
    
    Returns
    -------
    RunResult
        The design, the closed loop's series and its metrics.
    
    Raises
    ------
    ValueError
        An invalid scenario, naming the key.
    ConjugatePointError
        gamma <= gamma* for the law's design.
    CouplingConditionError
        With [measurement], rho(Sigma Z) >= gamma^2 (unless on_coupling_violation = "flag").
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> result = hc.run_scenario(scenario)
    >>> result.simulation.status, round(result.metrics.max_position_error, 3)   # the initial error (m)
    (<RunStatus.completed: 0>, 1.414)
    """
def run_scenario_with_noise(scenario: Scenario, noise: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> RunResult:
    """
    As run_scenario, with explicit noise samples (one row per hold interval, one column per
    measured output; see output_feedback.hpp) instead of the seeded ones.
    
    Parameters
    ----------
    scenario : Scenario
        A scenario with [measurement].
    noise : array_like, shape (k, p)
        Standard normal samples, k = noise_sample_count(t0, tf, sample_period) hold intervals, p
        measured outputs; scaled by sigma in the loop.
    
    Returns
    -------
    RunResult
    
    Raises
    ------
    ValueError
        An invalid scenario, one without [measurement], or noise of another shape.
    ConjugatePointError, CouplingConditionError, SolverError
        As run_scenario.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    >>> scenario.tf = 10.0
    >>> noise = hc.scenario_noise(scenario)                      # the seeded samples
    >>> replay = hc.run_scenario_with_noise(scenario, noise)
    >>> np.array_equal(replay.simulation.q, hc.run_scenario(scenario).simulation.q)
    True
    >>> quiet = hc.run_scenario_with_noise(scenario, np.zeros_like(noise))   # no measurement noise
    >>> quiet.metrics.rms_estimation_error_last_half < replay.metrics.rms_estimation_error_last_half
    True
    """
def run_scenarios(scenarios: collections.abc.Sequence[Scenario], options: StudyOptions = ..., progress: collections.abc.Callable[[int, int], None] | None = None) -> list[StudyRun]:
    """
    Runs every scenario, in parallel, and returns one StudyRun per scenario, in the order given:
    each row is what run_scenario gives for that scenario alone. InputError only for invalid
    options; whatever a run raises is its row's outcome and reason.
    
    Studies: many scenarios run as one batch (a Monte Carlo over noise seeds, initial states,
    disturbances or plants; a sweep over gamma or weights), in parallel, one row per run.
    
      run_scenarios(scenarios, options, progress) -> one StudyRun per scenario, in the order given.
    (The Python package's hinf_cpp.studies.run_study runs a study file on top of it.)
    
    Independence. Every row is what run_scenario gives for that scenario alone, bit for bit,
    whatever the number of threads and whether designs are shared: each run is computed by one
    thread with the code of run_scenario (its design part and its closed-loop part), nothing
    mutable is shared between runs, and every row is written only by the thread of its run, at
    its index.
    
    Failures. No run stops the study: a run whose design or closed loop fails is a row with the
    failure's RunOutcome and message (ConjugatePointError, CouplingConditionError, SolverError,
    InputError, any other std::exception); a closed loop that stops as diverged is a row with
    outcome Diverged and the run's status message.
    
    Design sharing (StudyOptions::share_designs). Runs whose design inputs are equal share one
    desired trajectory and one set of Riccati solutions, computed once. The design inputs are the
    model (its kind and parameters), t0, tf, desired q0 and u_d, Q, Qf, the [solver] options and
    the gamma of the law's design (the scenario's gamma for hinf and cascade, inf for lqr; with
    [disturbance] worst_case and the lqr law also the scenario's gamma, for the game design).
    Everything else differs freely between runs that share a design: the initial state, the
    disturbance, the plant ([plant]), kappa, the cascade gains, [measurement] (seed, sigma, N,
    Q0, eta: the filter Riccati equation is integrated with each closed loop), [output], the
    divergence factor.
    The inputs are compared as values: models by Model::same_as (a built-in model by its type
    and parameters; a model implemented in Python only with itself, the same object), signals by
    their definitions (a function of t, such as a Python callable, equals no other signal).
    Distinct designs used by several runs are computed first, in parallel; a design used by a
    single run is computed by that run's thread, and a shared design is released once its last
    run is done.
    
    Threads. Runs (and designs) are spread over min(threads, number of runs) worker threads.
    Trajectories, Riccati solutions, models, signals and disturbances are only read by the runs
    (their const evaluations keep no state: lookups take caller-owned cursors); controllers,
    which keep cursors, are made per run. A model implemented in Python holds the GIL in each
    call, so its runs do not overlap (the Python binding gives such a study one thread).
    
    Progress. progress(done, total) is called on the calling thread only: it waits while the
    workers run and calls progress about every 0.1 s when the number of finished runs changed,
    and once at the end with done == total. An exception thrown by progress stops the study:
    the workers take no new run, finish the ones they are in, are joined, and the exception is
    rethrown to the caller of run_scenarios.
    
    Parameters
    ----------
    scenarios : list of Scenario
        The runs.
    options : StudyOptions, optional
        Worker threads (one when a model or signal is implemented in Python) and design sharing.
    progress : callable or None, optional
        ``progress(done, total)``, called on this thread about every 0.1 s and once at the end.
    
    Returns
    -------
    list of StudyRun
        One row per scenario, in order.
    
    Raises
    ------
    ValueError
        Invalid options.
    Exception
        What progress raises (KeyboardInterrupt for Ctrl-C) stops the study and is raised here.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> gammas = [2.0, 5.0, 10.0]
    >>> runs = []
    >>> for gamma in gammas:
    ...     run = scenario.copy()
    ...     run.gamma = gamma
    ...     runs.append(run)
    >>> rows = hc.run_scenarios(runs, hc.StudyOptions(threads=2))
    >>> [row.status for row in rows], [row.design for row in rows]   # three designs
    (['completed', 'completed', 'completed'], [0, 1, 2])
    """
def scenario_certificates(scenario: Scenario) -> Certificates:
    """
    The certificates of paper §3 for the scenario's design (gamma, Q, Qf, kappa).
    
    Parameters
    ----------
    scenario : Scenario
        The scenario (its gamma, Q, Qf, kappa, model and desired trajectory).
    
    Returns
    -------
    Certificates
    
    Raises
    ------
    ValueError
        An invalid scenario.
    ConjugatePointError
        gamma <= gamma*: there is no design.
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> certificates = hc.scenario_certificates(scenario)
    >>> round(certificates.M, 2), certificates.kappa_min, certificates.remainder_is_bound
    (20.81, 1.0, True)
    """
def scenario_gamma_star(scenario: Scenario, options: GammaStarOptions = ...) -> GammaStarResult:
    """
    gamma* (eq. 14) of the scenario's state-feedback design (trajectory, Q, Qf, horizon; also
    for a scenario with [measurement]). options.solver is replaced by the scenario's [solver].
    
    Parameters
    ----------
    scenario : Scenario
        The scenario (its model, horizon, desired trajectory, Q, Qf and [solver]).
    options : GammaStarOptions, optional
        The bracket, tolerance, evaluations and threads; its solver is replaced by the scenario's.
    
    Returns
    -------
    GammaStarResult
    
    Raises
    ------
    ValueError
        An invalid scenario or options.
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> round(hc.scenario_gamma_star(scenario).gamma_star, 3)
    1.335
    """
def scenario_gamma_star_output_feedback(scenario: Scenario, options: GammaStarOptions = ...) -> GammaStarResult:
    """
    The smallest gamma of the scenario's output-feedback design (needs [measurement]).
    
    Parameters
    ----------
    scenario : Scenario
        A scenario with [measurement] (N, Q0, eta give the filter's weights).
    options : GammaStarOptions, optional
        The bracket, tolerance, evaluations and threads; its solver is replaced by the scenario's.
    
    Returns
    -------
    GammaStarResult
        binding names the condition that limits gamma.
    
    Raises
    ------
    ValueError
        An invalid scenario or options, or no [measurement].
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    >>> scenario.tf = 10.0
    >>> result = hc.scenario_gamma_star_output_feedback(scenario)
    >>> round(result.gamma_star, 2), result.binding
    (4.59, <GammaCondition.coupling: 3>)
    """
def scenario_noise(scenario: Scenario) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
    """
    The standard normal noise samples of a scenario with [measurement] (from its seed): one row
    per hold interval of [measurement] sample_period, or with [sampling] one per sample of its
    period (a measurement's noise is that of its sample).
    
    Parameters
    ----------
    scenario : Scenario
        A scenario with [measurement] (its seed, sample period and horizon).
    
    Returns
    -------
    ndarray, shape (k, p)
        k = noise_sample_count(t0, tf, sample_period) hold intervals, p measured outputs.
    
    Raises
    ------
    ValueError
        A scenario without a model or without [measurement], or an invalid horizon or sample period.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig2"))
    >>> scenario.tf = 10.0
    >>> noise = hc.scenario_noise(scenario)
    >>> noise.shape, np.array_equal(noise, hc.scenario_noise(scenario))     # 10 s / 0.01 s, seeded
    ((1000, 3), True)
    """
def scenario_receding_horizon(scenario: Scenario) -> RecedingHorizon:
    """
    The receding horizon a run of the scenario follows: its [receding_horizon] over its [desired]
    trajectory (inputs, or states and inputs), its [path_change] applied. InputError without
    [receding_horizon] or for an invalid scenario.
    
    Parameters
    ----------
    scenario : Scenario
        A scenario with [receding_horizon].
    
    Returns
    -------
    RecedingHorizon
        The windows a run of the scenario solves, along its [desired] trajectory (from inputs, or
        from states and inputs) with its [path_change] applied.
    
    Raises
    ------
    ValueError
        A scenario without [receding_horizon], or an invalid scenario.
    
    Examples
    --------
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.tf = 10.0
    >>> scenario.receding_horizon = hc.RecedingHorizonOptions(window=10.0, update=1.0)
    >>> horizon = hc.scenario_receding_horizon(scenario)
    >>> horizon.window_at(20.5), horizon.window_start(21)
    (20, 21.0)
    """
def scenario_toml(scenario: Scenario) -> str:
    """
    The inverse of parse_scenario_toml: the scenario as a scenario file that reads back to an
    equal scenario (numbers written exactly). A model or signal that has no file form (a model
    or a signal implemented in Python) is an InputError naming it.
    
    Scenario files (TOML; docs/scenarios.md is the reference): the one reader and the writer.
    Model sections ([model], [plant]) are read and written through the table of model kinds
    (io/model_kinds.hpp).
    
    Parameters
    ----------
    scenario : Scenario
        The scenario to write.
    
    Returns
    -------
    str
        The scenario file (TOML; docs/scenarios.md).
    
    Raises
    ------
    ValueError
        A model or a signal implemented in Python (it has no file form), naming it.
    
    Examples
    --------
    >>> from hinf_cpp.scenario import scenario_toml
    >>> scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    >>> scenario.gamma = 4.0
    >>> text = scenario_toml(scenario)
    >>> "gamma = 4.0" in text, scenario_toml(hc._core.parse_scenario_toml(text, "copy")) == text
    (True, True)
    """
def scenario_warnings(scenario: Scenario) -> list[str]:
    """
    What is legal but probably not meant, one message per finding, naming the key: a table
    whose interpolation overshoots the range of its values ([desired] u1, [disturbance] w2,
    [controller] kappa). The front ends print them (hinf-sim) or warn (Python).
    """
def set_python_model_hook(make_model: collections.abc.Callable) -> None:
    """
    Registers make_model(callable: str, source: str) -> Model, the maker of the models that a scenario file names with [model] kind = "python" (hinf_cpp.scenario registers it when imported)
    """
def simulate_output_feedback(problem: OutputFeedbackProblem, controller: Controller, disturbance: typing.Any, q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], options: OutputFeedbackOptions = ..., simulation: SimulationOptions = ..., plant: Model | None = None) -> SimulationResult:
    """
    Simulates the output-feedback closed loop: filter and estimator of the problem's design
    (Z, gamma; its trajectory), control by `controller` at the estimated state q_d + q_hat.
    The result carries the estimator series. Throws CouplingConditionError when
    rho(Sigma Z) >= gamma^2 at an output time (unless options.on_coupling_violation is Flag), or
    when the integration stops between output times at the estimator gain's pole, where
    rho(Sigma Z) reaches gamma^2 (to 1e-3; with Flag this is a SolverError naming the violation).
    The measured heading (the row of C that picks the model's heading) and its innovation are
    angles, wrapped to (-pi, pi].
    The vehicle integrated is `plant` (null: the design's model), with y = C q of the plant; the
    estimator, the filter and the control stay those of the design (its model and trajectory).
    
    Imperfect measurements (paper §4): the H-infinity filter, the estimator and the
    output-feedback tracking law, simulated together with the nonlinear plant.
    
      measurement (25):  y = C q + E w,  E w = sigma v_k on the model's noise channels, v_k a
                         standard normal sample held on [t0 + k T, t0 + (k+1) T);
      estimator (35):    dq_hat/dt = A(q_hat) q_hat + alpha(q_hat)
                                     + G(t, q_d + q_hat) (u - u_d) + gamma^-2 D D' Z q_hat
                                     + [I - gamma^-2 Sigma Z]^-1 Sigma C' N^-1 (y_e - C q_hat),
                         q_hat(t0) = 0, y_e = y - C q_d(t); q_hat estimates the error q_e;
                         A, alpha: the model's error_split; B = B_e(t), D = D_e(t) (model.hpp);
                         with the paper's law and constant G = B the input terms are
                         -(kappa B B' - gamma^-2 D D') Z q_hat, as in the paper;
      filter (36):       dSigma/dt = A Sigma + Sigma A' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D D',
                         Sigma(t0) = (Q0 - eta I)^-1, A = A(q_hat(t)) or A_e(t) (filter_A);
      control (34):      u = u_d(t) - kappa B' Z(t) q_hat (the paper's law, kappa = 1), or any
                         Controller evaluated at the estimated state q_d + q_hat (certainty
                         equivalence, for the baselines); the estimator uses the control applied.
    The central controller needs I - gamma^-2 Sigma Z invertible: the coupling condition
    rho(Sigma Z) < gamma^2 is checked at every output time.
    
    The noise is piecewise constant, so the closed loop is integrated one hold interval at a
    time, and every interval is a restart. One-step methods restart at no cost, multistep
    methods restart at first order. Per SolverOptions::method:
      erk    Dormand-Prince 5(4), its step size carried from interval to interval;
      auto, bdf  the same while the problem is not stiff; once Dormand-Prince's stiffness test
             fires, the L-stable SDIRK4 (sdirk4.hpp) takes over, keeping its Jacobian across
             intervals (a multistep BDF would restart at first order at every sample);
      adams  CVODE Adams restarted at every sample (correct but slow).
    SimulationResult::integrator says what was used. The measured heading (and the heading
    innovation) is an angle, wrapped to (-pi, pi] (angles.hpp).
    
    Parameters
    ----------
    problem : OutputFeedbackProblem
        The design (Z, gamma, trajectory), the noise samples and the filter's weights.
    controller : Controller
        The law, applied at the estimated state q_d + q_hat (HinfStateFeedback of the design: eq. 34).
    disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
        The disturbance on the model's nw channels, as for simulate_state_feedback (zero on the
        noise channels).
    q0 : array_like, shape (n,)
        The initial state q(t0).
    options : OutputFeedbackOptions, optional
        The filter's A and what a coupling violation does.
    simulation : SimulationOptions, optional
        Output step (s), divergence factor and integrator.
    plant : Model or None, optional
        The vehicle integrated, of the design model's structure; None: the design's model.
    
    Returns
    -------
    SimulationResult
        The series on the output grid, with the estimator's series.
    
    Raises
    ------
    ValueError
        A problem without a design, or whose sizes do not fit the model; q0 not of shape (n,);
        a controller, disturbance or plant of other sizes; bad options.
    CouplingConditionError
        rho(Sigma Z) >= gamma^2 (unless on_coupling_violation is "flag").
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> noise = hc._core.standard_normal_samples(1, hc._core.noise_sample_count(0.0, 10.0, 0.01), 3)
    >>> problem = hc.OutputFeedbackProblem(design, sigma=0.5, sample_period=0.01, noise=noise,
    ...                                    N=0.25 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6))
    >>> run = hc.simulate_output_feedback(problem, hc.HinfStateFeedback(design), None,
    ...                                   [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
    >>> run.estimator.q_hat.shape, round(float(run.estimator.rho_sigma_z.max()), 2)  # < gamma^2 = 25
    ((1001, 6), 20.81)
    """
def simulate_receding_horizon(horizon: RecedingHorizon, disturbance: typing.Any, q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], tf: typing.SupportsFloat | typing.SupportsIndex, options: SimulationOptions = ..., plant: Model | None = None, kappa: typing.Any = 1.0) -> tuple[SimulationResult, RecedingHorizonReport]:
    """
    The state-feedback closed loop (simulation.hpp) under the receding-horizon law from q0 at t0 to
    tf (> t0; any length: the mission), the law kappa B_e' Z_j of window j on [t_j, t_{j+1}). The
    loop is integrated window by window, restarting at each t_j (the gain jumps there), and the
    windows are solved as it goes: at most two are held at once. The output grid restarts at each
    t_j (an update period that is a multiple of the output dt gives one regular grid). The
    divergence bound (simulation.hpp) takes the scale of the mission so far: max(1, |q_e(t0)|,
    max |q_d| over the windows used up to t). The series grow with tf / dt: choose dt for the
    mission. q_d in the results is the windows' chained desired trajectory. report (optional) says
    what was solved. Errors as simulate_state_feedback and RecedingHorizon::window.
    
    The receding-horizon design: the GRDE (13) solved over a window that moves with time, so that a
    mission of any length is designed with memory that depends on the window, not on the mission.
    
    Window j starts at t_j = t0 + j * update and covers [t_j, t_j + H] (H = window):
      - its desired trajectory is eq. (8) integrated from q_d(t_j) of window j - 1 (q_d0 for
        j = 0) with the same u_d: the windows chain into one desired trajectory, continuous at every
        t_j, whose value differs from one integration over the whole mission by the integration
        error only (trajectory.hpp);
      - its design is the GRDE solved backward from Z(t_j + H) = the terminal weight, with its own
        conjugate-point check (ConjugatePointError names the window). The terminal weight is Qf
        (TerminalWeight::Qf), or the stabilizing solution of the stationary game ARE of the
        linearization frozen at the window's end (TerminalWeight::Stationary, solve_game_are): the
        cost-to-go of an infinite horizon beyond the window, so that the window's Z is that of a
        longer horizon already at its start (for a slowly varying trajectory);
      - the law of window j is used on [t_j, t_{j+1}): u = u_d - kappa B_e' Z_j (q - q_d), so the
        Z in use is always at least H - update before its window's end, where the terminal weight
        has decayed (the gain of a fixed-horizon design collapses towards B' Qf over its last
        seconds; the receding horizon never reaches them).
    The gamma a receding-horizon run certifies is the largest gamma* over its windows: each window
    is a finite-horizon game of its own (receding_horizon_gamma_star).
    
    A desired trajectory given as states (a planner's nodes, for a vehicle open-loop unstable
    along its plan; trajectory.hpp): each window is the states form over its own interval, from its
    start (the node there, or the chained q_d) through the nodes inside it, each interval
    integrated from its node; beyond the last node the window integrates from it. The windows
    then chain without the open-loop drift of one integration. The nodes are kept whole (their
    memory grows with the mission: n + 1 numbers per node).
    
    A path changed under way (with_path_change): from the window that starts at t_join on, the
    windows' trajectories continue from the chained q_d(t_join) with other inputs (a new plan from
    that state); the windows before it keep the old inputs to their ends.
    
    Parameters
    ----------
    horizon : RecedingHorizon
        The windows' design.
    disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
        The disturbance on the model's nw channels, as for simulate_state_feedback.
    q0 : array_like, shape (n,)
        The initial state q(t0).
    tf : float
        The end of the mission (s), > t0: any length.
    options : SimulationOptions, optional
        Output step (s), divergence factor and integrator.
    plant : Model or None, optional
        The vehicle integrated, of the design model's structure; None: the design model.
    kappa : Signal or float, optional
        The gain scaling kappa(t) > 0 of the law.
    
    Returns
    -------
    tuple of (SimulationResult, RecedingHorizonReport)
        The series on the output grid, and what was solved and held.
    
    Raises
    ------
    ValueError
        Sizes that do not match, tf <= t0, bad options.
    ConjugatePointError
        A window's GRDE has a conjugate point at gamma (the message names the window).
    SolverError
        An integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
    >>> run, report = hc.simulate_receding_horizon(horizon, None, [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4], 100.0)
    >>> run.status, report.windows, bool(np.hypot(*run.q_e()[-1, 3:5]) < 0.01)
    (<RunStatus.completed: 0>, 100, True)
    """
def simulate_sampled(trajectory: Trajectory, controller: OnlineController, disturbance: typing.Any, q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], options: SampledLoopOptions = ..., plant: Model | None = None) -> SimulationResult:
    """
    The loop of `plant` (null: the trajectory's model) under `controller` (reset here at t0 with
    q0), from q0 at t0 to the trajectory's tf. InputError for sizes that do not match (as
    simulate_state_feedback), a controller on another trajectory than `trajectory`, bad options;
    SolverError when the integration fails.
    
    The same loop under the receding horizon's online controller (online_receding_horizon.hpp),
    synchronized before every step (the run does not depend on how fast its windows are solved).
    `trajectory` is the reference of the run's q_d series and divergence bound: the desired
    trajectory integrated over [t0, tf] from the horizon's q_d0 with its u_d (the windows chain into
    it within their integration error); InputError when it does not start as the horizon does.
    
    The sampled-data closed loop, as on a vehicle: the plant integrated continuously,
        dq/dt = f(t, q) + G(t, q) u + D(t, q) w(t),
    its full state measured at t_k = t0 + k T (T the law's period), the measurement handed to the
    online controller (online_controller.hpp) at t_k + delay, and the command it returns applied
    from then on and held. The loop calls exactly the code a vehicle runs: OnlineController::step.
    Between events (samples, commands, output times) the plant is integrated by Dormand-Prince
    5(4) at the solver options' tolerances, restarted at each event (the command jumps there).
    The time series are those of simulate_state_feedback (simulation.hpp): u is the command
    applied; a run that leaves the neighbourhood of the desired trajectory stops as Diverged.
    Past the law's last sample (t_end <= tf) the controller answers PastHorizon and the last
    command stays held; controller.counts() tells.
    An output-feedback controller (OnlineController::output_feedback()) is handed the measurement
    y_k = C q(t_k) + sigma v_k instead (C the plant's, v_k row k of the noise: standard normal
    samples, one per sample and measured output, as noise_sample_count and
    standard_normal_samples of output_feedback.hpp give them for the law's period), and starts
    from the estimate q_hat(t0) = 0 (the state q_d(t0)), as the paper's estimator.
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory of the controller's law.
    controller : OnlineController
        The controller, reset here at t0 with q0; its counts() tell afterwards what its steps did.
    disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
        The disturbance on the model's nw channels, as for simulate_state_feedback.
    q0 : array_like, shape (n,)
        The initial state q(t0).
    options : SampledLoopOptions, optional
        The computation delay (s), the output grid, divergence factor and tolerances; for an
        output-feedback controller the noise's sigma and its samples (one row per sample).
    plant : Model or None, optional
        The vehicle integrated, of the design model's structure; None: the trajectory's model.
    
    Returns
    -------
    SimulationResult
        The series on the output grid (u: the command applied, piecewise constant).
    
    Raises
    ------
    ValueError
        Sizes that do not match, a controller of another trajectory, a delay outside [0, T].
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> controller = hc.OnlineController(hc.SampledLaw.emulated(design, 0.1))
    >>> w = hc.Signal(0.0, [hc.Harmonic(0.1, 2 * np.pi * 0.2, cosine=True)])     # paper Fig. 1
    >>> q0 = [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4]
    >>> run = hc.simulate_sampled(trajectory, controller, [w, w, w, 0, 0, 0], q0, hc.SampledLoopOptions(delay=0.1))
    >>> run.status, controller.counts().steps
    (<RunStatus.completed: 0>, 100)
    """
def simulate_sampled_receding_horizon(trajectory: Trajectory, controller: RecedingOnlineController, disturbance: typing.Any, q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], options: SampledLoopOptions = ..., plant: Model | None = None) -> SimulationResult:
    """
    The loop of `plant` (null: the trajectory's model) under `controller` (reset here at t0 with
    q0), from q0 at t0 to the trajectory's tf. InputError for sizes that do not match (as
    simulate_state_feedback), a controller on another trajectory than `trajectory`, bad options;
    SolverError when the integration fails.
    
    The same loop under the receding horizon's online controller (online_receding_horizon.hpp),
    synchronized before every step (the run does not depend on how fast its windows are solved).
    `trajectory` is the reference of the run's q_d series and divergence bound: the desired
    trajectory integrated over [t0, tf] from the horizon's q_d0 with its u_d (the windows chain into
    it within their integration error); InputError when it does not start as the horizon does.
    
    The sampled-data closed loop, as on a vehicle: the plant integrated continuously,
        dq/dt = f(t, q) + G(t, q) u + D(t, q) w(t),
    its full state measured at t_k = t0 + k T (T the law's period), the measurement handed to the
    online controller (online_controller.hpp) at t_k + delay, and the command it returns applied
    from then on and held. The loop calls exactly the code a vehicle runs: OnlineController::step.
    Between events (samples, commands, output times) the plant is integrated by Dormand-Prince
    5(4) at the solver options' tolerances, restarted at each event (the command jumps there).
    The time series are those of simulate_state_feedback (simulation.hpp): u is the command
    applied; a run that leaves the neighbourhood of the desired trajectory stops as Diverged.
    Past the law's last sample (t_end <= tf) the controller answers PastHorizon and the last
    command stays held; controller.counts() tells.
    An output-feedback controller (OnlineController::output_feedback()) is handed the measurement
    y_k = C q(t_k) + sigma v_k instead (C the plant's, v_k row k of the noise: standard normal
    samples, one per sample and measured output, as noise_sample_count and
    standard_normal_samples of output_feedback.hpp give them for the law's period), and starts
    from the estimate q_hat(t0) = 0 (the state q_d(t0)), as the paper's estimator.
    
    Parameters
    ----------
    trajectory : Trajectory
        The reference: the desired trajectory over [t0, tf] from the horizon's q_d0 with its u_d
        (the run's q_d series and divergence bound; the windows chain into it);
        ``horizon.reference(tf)`` gives it, path changes included.
    controller : RecedingOnlineController
        The controller, reset here at t0; synchronized before every step.
    disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
        The disturbance on the model's nw channels, as for simulate_state_feedback.
    q0 : array_like, shape (n,)
        The initial state q(t0).
    options : SampledLoopOptions, optional
        The computation delay (s), the output grid, tolerances, and for output feedback the noise.
    plant : Model or None, optional
        The vehicle integrated, of the design model's structure; None: the design model.
    
    Returns
    -------
    SimulationResult
        The series on the output grid (u: the command applied, piecewise constant).
    
    Raises
    ------
    ValueError
        A reference that does not start as the horizon does, sizes that do not match.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> horizon = hc.RecedingHorizon(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, np.eye(6), np.eye(6), 5.0,
    ...                              hc.RecedingHorizonOptions(window=10.0, update=1.0))
    >>> reference = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 30.0)
    >>> controller = hc.RecedingOnlineController(horizon, 0.05)
    >>> run = hc.simulate_sampled_receding_horizon(reference, controller, None, [1.0, 0.0, 0.0, -1.0, -1.0, 0.5])
    >>> run.status, controller.status().window_in_use
    (<RunStatus.completed: 0>, 29)
    """
def simulate_state_feedback(trajectory: Trajectory, controller: Controller, disturbance: typing.Any, q0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], options: SimulationOptions = ..., plant: Model | None = None) -> SimulationResult:
    """
    The closed loop of `plant` (null: the trajectory's model) under `controller`: the plant's f,
    G and D are integrated; the trajectory (of the design model) gives q_d and the divergence
    bound. A plant other than the design model is the model error of a robustness study.
    
    Closed-loop simulation of the nonlinear model under a tracking controller (paper eq. 7):
        dq/dt = f(t, q) + G(t, q) u + D(t, q) w(t),   u = controller(t, q),   q(t0) = q0,
    integrated with the chosen method; the time series are sampled on the output grid. f, G and
    D are the plant's: the design model's, or another model of the same structure (a plant with
    other parameters, for robustness studies), while the desired trajectory and the controller
    stay those of the design model.
    
    A closed loop that leaves the neighbourhood of the desired trajectory where the linearized
    design means anything stops early with status Diverged: when the tracking error |q_e|_inf
    (heading wrapped, angles.hpp) exceeds
        divergence_bound = divergence_factor * max(1, |q_e(t0)|_inf, path scale),
    the path scale being the largest extent of the desired path on the output grid: the spread
    (max - min) of each position component, and the largest |q_d_i| of each other component but
    the heading (speeds and rates: a speed's scale is its size). On the paper's ship over 40 s
    that is the path's 40 m, so the default factor 10 stops a run 400 m or 400 m/s off, where a
    ship has physically left its path. Its time series then end at the last output time before.
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory (of the design model): q_d and the divergence bound.
    controller : Controller
        The law, e.g. HinfStateFeedback, CascadeController, or a Python Controller.
    disturbance : Disturbance, VectorSignal, callable, list of Signal or float, or None
        The disturbance on the model's nw channels: a callable is ``w(t) -> array_like, shape (nw,)``
        (t in seconds); None is zero.
    q0 : array_like, shape (n,)
        The initial state q(t0).
    options : SimulationOptions, optional
        Output step (s), divergence factor and integrator.
    plant : Model or None, optional
        The vehicle integrated, of the design model's structure; None: the trajectory's model.
    
    Returns
    -------
    SimulationResult
        The series on the output grid; status diverged when the run stopped early.
    
    Raises
    ------
    ValueError
        q0 not of shape (n,) or not finite, a controller or disturbance of other sizes, a plant of
        another structure, bad options.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> law = hc.HinfStateFeedback(design)
    >>> w = hc.Signal(0.0, [hc.Harmonic(0.1, 2 * np.pi * 0.2, cosine=True)])     # paper Fig. 1
    >>> q0 = [1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4]                 # 1 m behind, 1 m aside, 45 deg off
    >>> run = hc.simulate_state_feedback(trajectory, law, [w, w, w, 0, 0, 0], q0)
    >>> error = np.hypot(run.q_e()[:, 3], run.q_e()[:, 4])       # position error (m)
    >>> round(float(error[0]), 3), bool(error[-1] < 0.1)
    (1.414, True)
    """
def solve_controller_riccati(trajectory: Trajectory, controller: Controller, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, options: SolverOptions = ...) -> SymmetricSolution:
    """
    P at gamma for that controller, stored (its worst case is w = gamma^-2 D_e' P x).
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory the controller tracks.
    controller : Controller
        The controller (see controller_gain).
    Q : array_like, shape (n, n)
        The weight of the tracking error in z.
    Qf : array_like, shape (n, n)
        The weight of the final error.
    gamma : float
        Above the controller's gain (controller_gain).
    options : SolverOptions, optional
        Integrator and tolerances.
    
    Returns
    -------
    SymmetricSolution
        P(t) of the controller's closed-loop Riccati equation; its worst-case disturbance at gamma
        is w = gamma^-2 D_e' P (q - q_d) (hc.Disturbance takes it).
    
    Raises
    ------
    ValueError
        As controller_gain.
    ConjugatePointError
        gamma is at or below the controller's gain.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> P = hc.solve_controller_riccati(trajectory, hc.BacksteppingController(trajectory), np.eye(6), np.eye(6), 10.0)
    >>> bool(np.all(np.linalg.eigvalsh(P.value(0.0)) > 0))
    True
    """
def solve_discrete_game(trajectory: typing.Any, period: typing.SupportsFloat | typing.SupportsIndex, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex) -> DiscreteDesign:
    """
    Solves the game Riccati difference equation backward from M_N = Qf. Q (n x n) symmetric
    positive semidefinite, Qf symmetric positive definite, gamma > 0 (may be +inf). InputError for
    bad input; ConjugatePointError when gamma^2 T I - D_k' M_{k+1} D_k is not positive definite at
    some k (its t_escape() is t_k, the latest such sample: gamma is below gamma*_d).
    
    The same, sampling the trajectory at `period` first.
    
    The digital design: the H-infinity tracking design for a computer that measures every T seconds
    and holds its command until the next sample (zero-order hold). Basar & Bernhard, "H-infinity
    optimal control and related minimax design problems", 2nd ed. 1995, ch. 3 (the discrete-time
    game with perfect state measurements).
    
    Sampling the error dynamics along the desired trajectory (trajectory.hpp)
        dq_e/dt = A_e(t) q_e + B_e(t) u_e + D_e(t) w,   u_e and w held over [t_k, t_k + T),
    with t_k = t0 + k T, k = 0 .. N-1, gives exactly the linear recursion
        x_{k+1} = A_k x_k + B_k u_k + D_k w_k,
        A_k = Phi(t_{k+1}, t_k),  B_k = int_{t_k}^{t_{k+1}} Phi(t_{k+1}, s) B_e(s) ds,  D_k alike,
    Phi the transition matrix of A_e. The game's cost, the sampled counterpart of the GRDE's (it
    converges to it as T -> 0: weights T Q, T I and gamma^2 T),
        |x_N|^2_Qf + sum_{k<N} ( T |x_k|^2_Q + T |u_k|^2 - gamma^2 T |w_k|^2 ),
    has the game Riccati difference equation, solved backward from M_N = Qf:
        Lambda_k = I + (B_k B_k' - gamma^-2 D_k D_k') M_{k+1} / T,
        M_k = T Q + A_k' M_{k+1} Lambda_k^-1 A_k.
    A saddle point exists if and only if (the discrete conjugate point condition)
        gamma^2 T I - D_k' M_{k+1} D_k > 0   for every k;
    the smallest gamma that keeps it is the discrete gamma*_d (gamma_star_discrete, analysis.hpp),
    which tends to the continuous gamma* as T -> 0. The law and the worst-case disturbance are
        u_k = u_d(t_k) - F_k q_e(t_k),   F_k = B_k' M_{k+1} Lambda_k^-1 A_k / T,
        w_k = gamma^-2 D_k' M_{k+1} Lambda_k^-1 A_k q_e(t_k) / T.
    N is the number of whole samples in [t0, tf]: the design ends at t_N = t0 + N T <= tf (a
    remainder of the horizon shorter than T is not designed for). gamma = +inf is the discrete LQR.
    
    Parameters
    ----------
    trajectory : Trajectory or SampledLinearization
        The desired trajectory, or its linearization sampled before (then `period` is its own and
        the argument is ignored; pass 0).
    period : float
        The sample period T (s).
    Q : array_like, shape (n, n)
        Weight of the tracking error, symmetric positive semidefinite (per second, as in the GRDE).
    Qf : array_like, shape (n, n)
        M_N, symmetric positive definite.
    gamma : float
        The attenuation level, > 0 (inf: the discrete LQR).
    
    Returns
    -------
    DiscreteDesign
    
    Raises
    ------
    ValueError
        Bad weights, gamma or period.
    ConjugatePointError
        gamma^2 T I - D_k' M_{k+1} D_k is not positive definite at some sample: gamma is below
        the discrete gamma* (its t_escape is that sample's time).
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0)
    >>> K = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0).gain(0.0)    # the continuous law's
    >>> float(round(np.linalg.norm(design.gain(0) - K) / np.linalg.norm(K), 3))   # first order in T
    0.059
    """
def solve_discrete_output_feedback(design: DiscreteDesign, C: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], R: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> DiscreteOutputFeedback:
    """
    Solves the filter Riccati difference equation forward from Sigma0 along `design` and checks the
    coupling condition at every sample. C (p x n), R (p x p) symmetric positive definite, Sigma0
    (n x n) symmetric positive definite, Q (n x n) the game's state weight (the one `design` was
    solved with), symmetric positive semidefinite. InputError for bad input; ConjugatePointError
    when (b) fails at some k (its t_escape() is t_k: the filter escapes); CouplingConditionError
    when (c) fails (its t() is the first t_k, rho() is rho(Sigma_k M_k)). Both mean gamma is too
    small for this output feedback.
    
    The digital output feedback: the discrete game of discrete_design.hpp with imperfect, sampled
    measurements, the command of sample k computed from y_0 .. y_k (the current-information
    pattern of Basar & Bernhard, "H-infinity optimal control and related minimax design problems",
    2nd ed. 1995, ch. 6: a computer that measures at t_k and answers within the sample).
    
    The sampled error dynamics of discrete_design.hpp, measured:
        x_{k+1} = A_k x_k + B_k u_k + D_k w_k,   y_k = C x_k + v_k,
    with the game's cost of discrete_design.hpp less gamma^2 (sum_k |v_k|^2_{R^-1} +
    |x_0|^2_{Sigma0^-1}): R is the covariance of one measurement (sigma^2 per sample, as on a
    datasheet), Sigma0 the initial uncertainty. In the variables that make the game's weights unit
    (u and w scaled by sqrt(T)), its filter Riccati difference equation runs forward from Sigma0:
        Pi_k          = (Sigma_k^-1 + C' R^-1 C - gamma^-2 T Q)^-1,
        Sigma_{k+1}   = A_k Pi_k A_k' + D_k D_k' / T,
    and the central controller acts on the worst-case state given y_0 .. y_k,
        x_w           = x_hat_k + H_k (gamma^-2 M_k x_hat_k + C' R^-1 (y_k - C x_hat_k)),
        H_k           = (Sigma_k^-1 + C' R^-1 C - gamma^-2 M_k)^-1,
        u_k           = u_d(t_k) - F_k x_w,
        x_hat_{k+1}   = A_k x_hat_k + B_k u_k + A_k Pi_k (gamma^-2 T Q x_hat_k + C' R^-1 (y_k - C x_hat_k)),
    with x_hat_0 the initial estimate (without y_k: x_w = (I - gamma^-2 Sigma_k M_k)^-1 x_hat_k and no
    C' R^-1 terms). It exists, and keeps the game's value below gamma^2, when for every k
        (a) the state-feedback game exists (gamma^2 T I - D_k' M_{k+1} D_k > 0, discrete_design.hpp),
        (b) Sigma_k^-1 + C' R^-1 C - gamma^-2 T Q > 0 (the filter exists),
        (c) rho(Sigma_k M_k) < gamma^2 (the coupling condition).
    On a time-invariant plant the smallest gamma that keeps (a)-(c) is the optimal H-infinity norm of
    SLICOT's SB10DD (tests/python/test_discrete_output_feedback.py, to 1e-8), and the closed loop of
    the central controller has an H-infinity norm below gamma. As T -> 0 with R = N / T these become
    the continuous (36) and rho(Sigma Z) < gamma^2; at gamma = inf it is the discrete LQG controller
    (the Kalman filter and the discrete LQR).
    
    Parameters
    ----------
    design : DiscreteDesign
        The digital design (solve_discrete_game).
    C : array_like, shape (p, n)
        The measurement matrix (the model's C).
    R : array_like, shape (p, p)
        The covariance of one measurement (sigma^2 per sample), symmetric positive definite.
    Sigma0 : array_like, shape (n, n)
        The initial uncertainty, symmetric positive definite.
    Q : array_like, shape (n, n)
        The game's state weight (the one the design was solved with).
    
    Returns
    -------
    DiscreteOutputFeedback
    
    Raises
    ------
    ValueError
        Bad shapes or weights.
    ConjugatePointError
        The filter does not exist at some sample (its t_escape is that sample's time).
    CouplingConditionError
        rho(Sigma_k M_k) >= gamma^2 at some sample (its t is the first such sample's time).
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> C = np.hstack([np.zeros((3, 3)), np.eye(3)])
    >>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 5.0)
    >>> feedback = hc.solve_discrete_output_feedback(design, C, 0.25 * np.eye(3), np.eye(6), np.eye(6))
    >>> round(feedback.largest_coupling(), 3)      # rho(Sigma_k M_k) / gamma^2 < 1 at every sample
    0.835
    >>> design = hc.solve_discrete_game(trajectory, 0.1, np.eye(6), np.eye(6), 1.5)
    >>> try:
    ...     hc.solve_discrete_output_feedback(design, C, 0.25 * np.eye(3), np.eye(6), np.eye(6))
    ... except hc.CouplingConditionError as error:
    ...     print(error.t, error.rho > error.gamma ** 2)   # at t0: Sigma0 = I is too uncertain for 1.5
    0.0 True
    """
def solve_filter_riccati(trajectory: Trajectory, N: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, Sigma0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], options: SolverOptions = ...) -> FilterRiccatiSolution:
    """
    Solves the filter Riccati equation (36) forward from Sigma(t0) = Sigma0, with the model's
    measurement matrix C (Model::C), N (p x p) positive definite, Q (n x n) positive
    semidefinite, gamma > 0 (may be +inf: the Kalman-Bucy filter), A = A_e(t).
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory: A = A_e(t) and D = D_e(t) along it; its model gives C (Model.C).
    N : array_like, shape (p, p)
        The measurement noise weight N = E E' (p measured outputs, the rows of C).
    Q : array_like, shape (n, n)
        The weight of the performance index (the GRDE's Q).
    gamma : float
        The attenuation level; ``np.inf`` gives the Kalman-Bucy filter.
    Sigma0 : array_like, shape (n, n)
        Sigma(t0), symmetric positive definite.
    options : SolverOptions, optional
        Integrator and tolerances.
    
    Returns
    -------
    FilterRiccatiSolution
        Sigma(t) on [t0, tf].
    
    Raises
    ------
    ValueError
        A model without a measurement; matrices of other shapes, not symmetric or not (semi)definite;
        gamma <= 0 or NaN; bad options.
    ConjugatePointError
        Sigma escapes to infinity or loses positive definiteness at t_escape (s).
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> Sigma = hc.solve_filter_riccati(trajectory, 0.25 * np.eye(3), np.eye(6), 5.0, np.eye(6))
    >>> np.round(Sigma.eigenvalue_bounds(), 3)
    array([0.101, 1.005])
    """
def solve_game_are(A: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], B: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], D: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
    """
    The stabilizing solution P of the stationary game Riccati equation, the GRDE (13) with its
    derivative zero at constant A, B, D (n x n, n x m, n x nw):
        A' P + P A + Q - P (B B' - gamma^-2 D D') P = 0,   A - (B B' - gamma^-2 D D') P stable.
    Q (n x n) symmetric positive semidefinite, gamma > 0 (may be +inf: the LQR equation).
    InputError for bad sizes or values, or when there is no stabilizing, positive semidefinite
    solution (gamma at or below the stationary game's gamma*, or (A, B) not stabilizable).
    
    The matrix Riccati differential equations of the paper, solved along a desired trajectory.
    
    GRDE, paper eq. (13), solved BACKWARD from Z(tf) = Qf:
        -dZ/dt = A_e' Z + Z A_e + Q - Z (B B' - gamma^-2 D D') Z.
    Sign convention: Z > 0 is the cost-to-go matrix, V(t, q_e) = q_e' Z(t) q_e; the
    state-feedback law (17)/(18) is u = u_d - kappa B' Z q_e. gamma = +inf gives LQR. Here
    A = A_e(t), B = B_e(t) and D = D_e(t), the linearization along the desired trajectory
    (model.hpp, trajectory.hpp).
    
    Filter Riccati equation, paper eq. (36), solved FORWARD from Sigma(t0) = (Q0 - eta I)^-1:
        dSigma/dt = A Sigma + Sigma A' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D D',
    here with A = A_e(t) (the linearization along the desired path; the output-feedback
    simulation also offers A(q_hat(t)), see output_feedback.hpp).
    
    Both solutions are kept as the integrator's dense output (symmetric half, types.hpp), so
    they are available at any t in [t0, tf] with the integrator's accuracy. A finite escape
    (a conjugate point: gamma <= gamma*, eq. 14) raises ConjugatePointError with the
    estimated escape time. A solution is immutable once solved (no caches; lookups take
    caller-owned cursors): several threads may evaluate one at once (run_scenarios shares one
    between runs, study.hpp).
    
    Parameters
    ----------
    A : array_like, shape (n, n)
        The state matrix.
    B : array_like, shape (n, m)
        The input matrix.
    D : array_like, shape (n, nw)
        The disturbance matrix.
    Q : array_like, shape (n, n)
        Weight of the state, symmetric positive semidefinite.
    gamma : float
        The attenuation level; ``np.inf`` gives the LQR equation.
    
    Returns
    -------
    numpy.ndarray, shape (n, n)
        The stabilizing solution P.
    
    Raises
    ------
    ValueError
        Bad sizes or values, or no stabilizing solution (gamma at or below the stationary game's
        gamma*, or (A, B) not stabilizable).
    
    Examples
    --------
    >>> P = hc.solve_game_are([[0.0, 1.0], [0.0, 0.0]], [[0.0], [1.0]], [[0.0], [1.0]], np.eye(2), np.inf)
    >>> np.round(P, 6)                     # the double integrator's LQR: [[sqrt 3, 1], [1, sqrt 3]]
    array([[1.732051, 1.      ],
           [1.      , 1.732051]])
    >>> P = hc.solve_game_are([[1.0]], [[1.0]], [[1.0]], [[1.0]], 2.0)   # 2 P + 1 - 0.75 P^2 = 0
    >>> round(float(P[0, 0]), 6), round((2 + 7 ** 0.5) / 1.5, 6)
    (3.097168, 3.097168)
    """
def solve_grde(trajectory: Trajectory, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, options: SolverOptions = ...) -> RiccatiSolution:
    """
    Solves the GRDE (13) backward from Z(tf) = Qf over the trajectory's horizon.
    Q (n x n) symmetric positive semidefinite, Qf symmetric positive definite, gamma > 0
    (may be +inf). Throws InputError, SolverError or ConjugatePointError.
    
    The matrix Riccati differential equations of the paper, solved along a desired trajectory.
    
    GRDE, paper eq. (13), solved BACKWARD from Z(tf) = Qf:
        -dZ/dt = A_e' Z + Z A_e + Q - Z (B B' - gamma^-2 D D') Z.
    Sign convention: Z > 0 is the cost-to-go matrix, V(t, q_e) = q_e' Z(t) q_e; the
    state-feedback law (17)/(18) is u = u_d - kappa B' Z q_e. gamma = +inf gives LQR. Here
    A = A_e(t), B = B_e(t) and D = D_e(t), the linearization along the desired trajectory
    (model.hpp, trajectory.hpp).
    
    Filter Riccati equation, paper eq. (36), solved FORWARD from Sigma(t0) = (Q0 - eta I)^-1:
        dSigma/dt = A Sigma + Sigma A' - Sigma (C' N^-1 C - gamma^-2 Q) Sigma + D D',
    here with A = A_e(t) (the linearization along the desired path; the output-feedback
    simulation also offers A(q_hat(t)), see output_feedback.hpp).
    
    Both solutions are kept as the integrator's dense output (symmetric half, types.hpp), so
    they are available at any t in [t0, tf] with the integrator's accuracy. A finite escape
    (a conjugate point: gamma <= gamma*, eq. 14) raises ConjugatePointError with the
    estimated escape time. A solution is immutable once solved (no caches; lookups take
    caller-owned cursors): several threads may evaluate one at once (run_scenarios shares one
    between runs, study.hpp).
    
    Parameters
    ----------
    trajectory : Trajectory
        The desired trajectory: the horizon [t0, tf] and A_e, B_e, D_e along it.
    Q : array_like, shape (n, n)
        Weight of the tracking error q_e.
    Qf : array_like, shape (n, n)
        Final value, Z(tf) = Qf.
    gamma : float
        The attenuation level; ``np.inf`` gives LQR.
    options : SolverOptions, optional
        Integrator and tolerances.
    
    Returns
    -------
    RiccatiSolution
        Z(t) on [t0, tf].
    
    Raises
    ------
    ValueError
        Q or Qf of another shape, not symmetric or not (semi)definite; gamma <= 0 or NaN; bad options.
    ConjugatePointError
        Z escapes to infinity at t_escape (s): gamma is at or below gamma*.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> design = hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)
    >>> np.round(design.eigenvalue_bounds(), 3)                   # m I <= Z(t) <= M I
    array([ 0.219, 20.815])
    >>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), np.inf)
    >>> bool(np.all(np.linalg.eigvalsh(design.Z(0.0) - lqr.Z(0.0)) >= 0))  # Z grows as gamma falls
    True
    """
def solve_law_riccati(law: RiccatiSolution, Q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], Qf: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], gamma: typing.SupportsFloat | typing.SupportsIndex, kappa: Signal = ..., options: SolverOptions = ...) -> SymmetricSolution:
    """
    P of that equation at gamma, stored: the law's worst-case disturbance is w = gamma^-2 D_e' P x.
    ConjugatePointError when gamma is at or below the law's gain.
    
    Parameters
    ----------
    law : RiccatiSolution
        The law's design (see law_gain).
    Q : array_like, shape (n, n)
        The weight of the tracking error in z.
    Qf : array_like, shape (n, n)
        The weight of the final error.
    gamma : float
        Above the law's gain (law_gain).
    kappa : float or Signal, optional
        The law's gain scaling (default 1).
    options : SolverOptions, optional
        Integrator and tolerances.
    
    Returns
    -------
    SymmetricSolution
        P(t) of the law's closed-loop Riccati equation; the law's worst-case disturbance at gamma
        is w = gamma^-2 D_e' P (q - q_d).
    
    Raises
    ------
    ValueError
        As law_gain.
    ConjugatePointError
        gamma is at or below the law's gain.
    SolverError
        The integration failed.
    
    Examples
    --------
    >>> u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]       # paper Fig. 1
    >>> trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, 10.0)
    >>> lqr = hc.solve_grde(trajectory, np.eye(6), np.eye(6), float("inf"))
    >>> P = hc.solve_law_riccati(lqr, np.eye(6), np.eye(6), 2.2)
    >>> bool(np.all(np.linalg.eigvalsh(P.value(0.0)) > 0))
    True
    """
def standard_normal_samples(seed: typing.SupportsInt | typing.SupportsIndex, count: typing.SupportsInt | typing.SupportsIndex, channels: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
    """
    count x channels standard normal samples from a seeded generator (mt19937_64 and the
    Marsaglia polar method): the same numbers for the same seed on every run.
    
    At most 1e9 numbers (count x channels).
    """
def wrap_angle(angle: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    The angle wrapped to (-pi, pi].
    
    Angles, and the tracking error of a model whose state has a heading angle.
    
    The heading error psi - psi_d is an angle: wherever it enters a control law, an estimator or
    a metric it is wrapped to (-pi, pi], so that a start at psi_d + 350 degrees is the 10 degree
    error it physically is, and a state 2 pi further round gives the same run.
    
    Parameters
    ----------
    angle : float
        An angle (rad).
    
    Returns
    -------
    float
        The angle wrapped to (-pi, pi].
    
    Examples
    --------
    >>> import math
    >>> hc.wrap_angle(3 * math.pi / 2), hc.wrap_angle(-math.pi) == math.pi
    (-1.5707963267948966, True)
    """
__version__: str = '0.2.0'
