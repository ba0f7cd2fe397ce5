"""hinf_cpp: H-infinity tracking control of nonlinear underactuated vehicles.

The numerics (models, desired trajectories, the GRDE, the closed loop) live in the C++
core ``hinf_cpp._core``; this package adds scenario files, plots and the command line:
``hinf_cpp.compare`` (the H-infinity law against the lqr and cascade baselines),
``hinf_cpp.recovery`` (poor initial conditions, turning around), ``hinf_cpp.plotting``
(figures), ``hinf_cpp.report`` (a report folder), ``hinf_cpp.export`` (NPZ, tidy CSV, JSON)
and ``hinf_cpp.analysis`` (attenuation against gamma).

Conventions (docs/conventions.md): state order of the ship q = [u, v, r, x, y, psi];
errors q_e = q - q_d; Z(t) > 0 is the cost-to-go matrix of paper eq. (13), solved
backward in time from Z(tf) = Qf; the control is u = u_d - kappa B' Z q_e.
"""

from importlib import resources as _resources
import pathlib as _pathlib

from ._core import (
    CascadeController,
    CascadeGains,
    Certificates,
    ConjugatePointError,
    Controller,
    CouplingConditionError,
    Disturbance,
    FilterRiccatiSolution,
    GammaStarOptions,
    GammaStarResult,
    GammaTrial,
    Harmonic,
    HinfError,
    HinfStateFeedback,
    LinearModel,
    MeasurementSpec,
    Model,
    OutputFeedbackOptions,
    RiccatiSolution,
    RunResult,
    Scenario,
    ShipModel,
    ShipParameters,
    Signal,
    SimulationResult,
    SolverError,
    SolverOptions,
    SolveStats,
    Trajectory,
    VectorSignal,
    __version__,
    certify,
    compute_metrics,
    filter_escape_time,
    gamma_star,
    gamma_star_output_feedback,
    grde_escape_time,
    max_rho_sigma_z,
    noise_sample_count,
    output_grid,
    parse_scenario_toml,
    run_scenario,
    scenario_certificates,
    scenario_gamma_star,
    scenario_gamma_star_output_feedback,
    scenario_noise,
    simulate_output_feedback,
    simulate_state_feedback,
    solve_filter_riccati,
    solve_grde,
    standard_normal_samples,
    wrap_angle,
)
from .scenario import load_scenario, scenario_from_dict, signal_from_spec


def scenario_path(name: str) -> _pathlib.Path:
    """Path of a shipped scenario, e.g. ``scenario_path("paper_fig1")``."""
    path = _pathlib.Path(str(_resources.files(__name__) / "scenarios" / f"{name}.toml"))
    if not path.exists():
        shipped = sorted(p.stem for p in path.parent.glob("*.toml"))
        raise ValueError(f"no shipped scenario '{name}' (shipped: {', '.join(shipped)})")
    return path


__all__ = [
    "CascadeController",
    "CascadeGains",
    "Certificates",
    "ConjugatePointError",
    "Controller",
    "CouplingConditionError",
    "Disturbance",
    "FilterRiccatiSolution",
    "GammaStarOptions",
    "GammaStarResult",
    "GammaTrial",
    "Harmonic",
    "HinfError",
    "HinfStateFeedback",
    "LinearModel",
    "MeasurementSpec",
    "Model",
    "OutputFeedbackOptions",
    "RiccatiSolution",
    "RunResult",
    "Scenario",
    "ShipModel",
    "ShipParameters",
    "Signal",
    "SimulationResult",
    "SolveStats",
    "SolverError",
    "SolverOptions",
    "Trajectory",
    "VectorSignal",
    "__version__",
    "certify",
    "compute_metrics",
    "filter_escape_time",
    "gamma_star",
    "gamma_star_output_feedback",
    "grde_escape_time",
    "max_rho_sigma_z",
    "load_scenario",
    "noise_sample_count",
    "output_grid",
    "parse_scenario_toml",
    "run_scenario",
    "scenario_certificates",
    "scenario_from_dict",
    "scenario_gamma_star",
    "scenario_gamma_star_output_feedback",
    "scenario_noise",
    "scenario_path",
    "signal_from_spec",
    "simulate_output_feedback",
    "simulate_state_feedback",
    "solve_filter_riccati",
    "solve_grde",
    "standard_normal_samples",
    "wrap_angle",
]
