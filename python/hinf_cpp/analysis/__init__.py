"""Analyses across runs: the laws compared (:mod:`~hinf_cpp.analysis.comparison`), recovery from
poor initial conditions (:mod:`~hinf_cpp.analysis.recovery`), attenuation against gamma
(:mod:`~hinf_cpp.analysis.gamma_sweep`), each law's worst-case disturbance and gain against
frequency (:mod:`~hinf_cpp.analysis.attenuation`), the vehicle gallery
(:mod:`~hinf_cpp.analysis.gallery`) and report folders (:mod:`~hinf_cpp.analysis.report`). The
last three draw figures (matplotlib) and are imported by name.
"""

from hinf_cpp.analysis.comparison import Comparison, Feedback, compare
from hinf_cpp.analysis.gamma_sweep import GammaSweep, sweep_gamma
from hinf_cpp.analysis.recovery import RecoveryStudy, recovery_study

__all__ = ["Comparison", "Feedback", "GammaSweep", "RecoveryStudy", "compare", "recovery_study", "sweep_gamma"]
