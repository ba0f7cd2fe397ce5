"""Feasible desired trajectories from waypoints or a path (docs/planning.md).

:func:`plan` turns waypoints (or :func:`waypoints_from_path` of a sampled path) into desired
inputs u_d and states q_d by trajectory optimization (CasADi and IPOPT; imported when used);
:func:`plan_path_change` plans a receding-horizon run's new path from its desired state where a
window starts.
"""

from hinf_cpp.planning.planner import (FeasibilityReport, Plan, PlanningError, PlanOptions, UnreachableWaypointError,
                                       Waypoint, default_cache_dir, plan, plan_path_change,
                                       waypoints_from_path)

__all__ = ["FeasibilityReport", "Plan", "PlanOptions", "PlanningError", "UnreachableWaypointError", "Waypoint",
           "default_cache_dir", "plan", "plan_path_change", "waypoints_from_path"]
