"""hinf_cpp: H-infinity tracking control of nonlinear underactuated vehicles.

The numerics (models, desired trajectories, the Riccati equations, the closed loops) are the C++
core; this namespace is its API as a user needs it, plus scenario files:

* scenarios: :func:`load_scenario`, :func:`scenario_from_dict`, :func:`scenario_path`,
  :class:`Scenario`, :func:`run_scenario` -> :class:`RunResult`, :func:`run_scenarios` (many
  scenarios in parallel);
* models: :class:`Model` (subclass it in Python), :class:`ShipModel` (the paper's ship),
  :class:`LinearModel`, the vehicles :class:`FossenVessel`, :class:`Hovercraft`,
  :class:`PlanarVtol`, :class:`Auv`, :class:`FleetModel`, :class:`GeneratedModel`;
* the design: :class:`Trajectory` (q_d, u_d, A_e), :func:`solve_grde` (Z of paper eq. 13),
  :func:`gamma_star` (eq. 14), :func:`certify` (eqs. 22-24), :func:`solve_filter_riccati`
  (eq. 36);
* laws and closed loops: :class:`HinfStateFeedback` (eqs. 17/18), :class:`CascadeController`, :class:`BacksteppingController`,
  :func:`simulate_state_feedback`, :func:`simulate_output_feedback` (eqs. 34-36),
  :class:`Metrics`;
* errors: ValueError for bad input; :class:`HinfError` and its subclasses
  :class:`SolverError`, :class:`ConjugatePointError`, :class:`CouplingConditionError`.

The subpackages add the rest, each imported by name: :mod:`hinf_cpp.models` (your own vehicle in
CasADi symbols), :mod:`hinf_cpp.planning` (desired trajectories from waypoints),
:mod:`hinf_cpp.scenario` (files, keys set by name), :mod:`hinf_cpp.studies` (grid and random
studies as DataFrames), :mod:`hinf_cpp.analysis` (laws compared, recovery, attenuation against
gamma), :mod:`hinf_cpp.output` (figures, exports, tables). Plumbing (the TOML parser entry
points, output grids, the noise generator) stays in ``hinf_cpp._core``.

Conventions (docs/mathematics.md): time in seconds; errors q_e = q - q_d (actual minus desired),
the heading wrapped to (-pi, pi]; Z(t) > 0 is the cost-to-go of paper eq. (13), solved backward
from Z(tf) = Qf; the control is u = u_d - kappa B' Z q_e. The C++ API (cpp/include/hinf) is
exported as it is: the same names, argument order and defaults; a C++ member function is a
method (``trajectory.tf()``), a field of a C++ struct a property (``result.metrics.response_ratio``);
enums also take their names as strings (``scenario.law = "lqr"``). Scenarios, models, options
and results pickle.

Example
-------
>>> import hinf_cpp as hc
>>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
>>> round(result.metrics.rms_position_error_last_half, 3)
0.048
"""

from hinf_cpp._core import (
    ActuatorLimits,
    Auv,
    AuvParameters,
    BacksteppingController,
    BacksteppingGains,
    CascadeController,
    CascadeGains,
    Certificates,
    ConjugatePointError,
    Controller,
    CouplingConditionError,
    CouplingPolicy,
    DiscreteDesign,
    DiscreteOutputFeedback,
    Disturbance,
    EstimatorSeries,
    FilterLinearization,
    FilterRiccatiSolution,
    FleetModel,
    FossenVessel,
    FossenVesselParameters,
    GammaCondition,
    GammaStarOptions,
    GammaStarResult,
    GammaTrial,
    GeneratedModel,
    Harmonic,
    HinfError,
    HinfStateFeedback,
    Hovercraft,
    HovercraftParameters,
    Interpolation,
    Law,
    LinearModel,
    MeasurementSpec,
    MeasurementUpdate,
    MeasurementUse,
    Method,
    MetricDefinition,
    Metrics,
    Model,
    NewtonSystems,
    OnlineController,
    OnlineCounts,
    OnlineFilter,
    OnlineOptions,
    OutputFeedbackOptions,
    OutputFeedbackProblem,
    PiecewisePolynomial,
    PlanarVtol,
    PlanarVtolParameters,
    RiccatiSolution,
    RunOutcome,
    RunResult,
    RecedingHorizon,
    RecedingOnlineController,
    RecedingOnlineStatus,
    simulate_sampled_receding_horizon,
    DesiredStates,
    PathChange,
    RecedingHorizonOptions,
    TerminalWeight,
    RecedingHorizonReport,
    HorizonWindow,
    WindowGammaStar,
    receding_horizon_gamma_star,
    simulate_receding_horizon,
    RunStatus,
    SampledDesign,
    SampledLaw,
    SampledLinearization,
    SampledLoopOptions,
    SamplingSpec,
    Scenario,
    ShipModel,
    ShipParameters,
    Signal,
    SimulationOptions,
    SimulationResult,
    SolverError,
    SolverOptions,
    SolveStats,
    StepReport,
    StepStats,
    StepStatus,
    StudyOptions,
    StudyRun,
    SymmetricSolution,
    Timing,
    Trajectory,
    TrajectoryOptions,
    VectorSignal,
    __version__,
    certify,
    compute_metrics,
    discrete_conjugate_time,
    filter_escape_time,
    gamma_star,
    gamma_star_discrete,
    gamma_star_discrete_output_feedback,
    gamma_star_output_feedback,
    grde_escape_time,
    law_escape_time,
    law_gain,
    controller_gain,
    controller_escape_time,
    solve_controller_riccati,
    solve_law_riccati,
    max_rho_sigma_z,
    metric_table,
    run_scenario,
    run_scenario_with_noise,
    run_scenarios,
    scenario_certificates,
    scenario_receding_horizon,
    scenario_gamma_star,
    scenario_gamma_star_output_feedback,
    scenario_noise,
    simulate_output_feedback,
    simulate_sampled,
    simulate_state_feedback,
    solve_discrete_game,
    solve_discrete_output_feedback,
    solve_filter_riccati,
    solve_grde,
    solve_game_are,
    wrap_angle,
)
from hinf_cpp.scenario import load_scenario, scenario_from_dict, scenario_path, signal_from_spec

__all__ = [
    # scenarios
    "Scenario", "MeasurementSpec", "SamplingSpec", "SampledDesign", "Law", "load_scenario", "scenario_from_dict", "scenario_path", "signal_from_spec",
    "run_scenario", "run_scenario_with_noise", "RunResult", "Timing", "scenario_gamma_star",
    "scenario_gamma_star_output_feedback", "scenario_certificates", "scenario_receding_horizon", "scenario_noise", "run_scenarios",
    "StudyOptions", "StudyRun", "RunOutcome",
    # signals
    "Signal", "VectorSignal", "Harmonic", "Interpolation",
    # models
    "Model", "LinearModel", "ShipModel", "ShipParameters", "FossenVessel", "FossenVesselParameters", "Hovercraft",
    "HovercraftParameters", "PlanarVtol", "PlanarVtolParameters", "Auv", "AuvParameters", "FleetModel",
    "GeneratedModel",
    # the design
    "Trajectory", "TrajectoryOptions", "SolverOptions", "Method", "NewtonSystems", "StepStats", "PiecewisePolynomial",
    "solve_grde", "solve_game_are", "SymmetricSolution", "RiccatiSolution", "SolveStats", "solve_filter_riccati",
    "FilterRiccatiSolution", "grde_escape_time", "filter_escape_time", "law_gain", "law_escape_time", "solve_law_riccati",
    "controller_gain", "controller_escape_time", "solve_controller_riccati", "gamma_star", "gamma_star_output_feedback",
    "GammaStarOptions", "GammaStarResult", "GammaTrial", "GammaCondition", "max_rho_sigma_z", "certify",
    "Certificates",
    # laws and closed loops
    "Controller", "HinfStateFeedback", "CascadeController", "CascadeGains",
    "BacksteppingController", "BacksteppingGains", "Disturbance", "wrap_angle",
    "simulate_state_feedback", "SimulationOptions", "SimulationResult", "RunStatus", "simulate_output_feedback",
    "OutputFeedbackProblem", "OutputFeedbackOptions", "FilterLinearization", "CouplingPolicy", "EstimatorSeries",
    "Metrics", "MetricDefinition", "metric_table", "compute_metrics",
    # on a vehicle: the digital design and the online controller
    "SampledLinearization", "solve_discrete_game", "DiscreteDesign", "solve_discrete_output_feedback",
    "DiscreteOutputFeedback", "discrete_conjugate_time", "gamma_star_discrete",
    "gamma_star_discrete_output_feedback",
    "SampledLaw", "ActuatorLimits", "OnlineFilter", "OnlineOptions", "OnlineController", "StepReport", "StepStatus",
    "MeasurementUse", "MeasurementUpdate", "OnlineCounts", "simulate_sampled", "SampledLoopOptions",
    "RecedingHorizon", "RecedingHorizonOptions", "TerminalWeight", "HorizonWindow", "RecedingHorizonReport", "simulate_receding_horizon",
    "WindowGammaStar", "receding_horizon_gamma_star", "RecedingOnlineController", "RecedingOnlineStatus",
    "simulate_sampled_receding_horizon", "DesiredStates", "PathChange",
    # errors
    "HinfError", "SolverError", "ConjugatePointError", "CouplingConditionError",
    "__version__",
]
