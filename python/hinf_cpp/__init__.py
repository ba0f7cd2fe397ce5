"""hinf_cpp: H-infinity tracking control of nonlinear underactuated vehicles.

The numerics (models, desired trajectories, the GRDE, the closed loop) live in the C++
core ``hinf_cpp._core``; this package adds scenario files, plots and the command line:
``hinf_cpp.analysis.compare`` (the H-infinity law against the lqr and cascade baselines),
``hinf_cpp.analysis.recovery`` (poor initial conditions, turning around), ``hinf_cpp.output.plotting``
(figures), ``hinf_cpp.analysis.report`` (a report folder), ``hinf_cpp.output.export`` (NPZ, tidy CSV, JSON),
``hinf_cpp.analysis`` (attenuation against gamma), ``hinf_cpp.analysis.gallery`` (the built-in
vehicles' shipped runs: FossenVessel, Hovercraft, PlanarVtol, Auv; docs/vehicles.md),
``hinf_cpp.models.symbolic`` (your own vehicle in CasADi symbols, evaluated in C++; docs/models.md),
``hinf_cpp.models.codegen`` (CasADi functions compiled for the C++ core; needs casadi) and
``hinf_cpp.planning.planner`` (feasible desired trajectories from waypoints or a path; needs casadi;
docs/planning.md) and ``hinf_cpp.studies.study`` (studies: grid and random axes over scenario keys, one
row per run as a pandas DataFrame, locally or on Dask; ``hinf_cpp.studies.report`` summarizes and
plots them; docs/studies.md).

Conventions (docs/mathematics.md): state order of the ship q = [u, v, r, x, y, psi];
errors q_e = q - q_d; Z(t) > 0 is the cost-to-go matrix of paper eq. (13), solved
backward in time from Z(tf) = Qf; the control is u = u_d - kappa B' Z q_e.

The C++ API (``cpp/include/hinf/*.hpp``) is exported as it is: the same names, argument order
and defaults; a C++ member function is a method (``trajectory.tf()``), a field of a C++ struct
a property (``result.metrics.l2_gain``); enums (``Law``, ``Method``, ...) also take their names
as strings (``scenario.law = "lqr"``). Scenarios, models, options and results pickle.
"""

from hinf_cpp import _core
from hinf_cpp._core import *  # noqa: F403 - the C++ API, typed in _core.pyi
from hinf_cpp._core import __version__
from hinf_cpp.scenario import load_scenario, scenario_from_dict, scenario_path, signal_from_spec

__all__ = sorted([name for name in vars(_core) if not name.startswith("_")]
                 + ["__version__", "load_scenario", "scenario_from_dict", "scenario_path", "signal_from_spec"])
