"""Scenarios: files and dictionaries read by the one C++ reader, keys set by name, and planned
desired trajectories.

:func:`load_scenario` and :func:`scenario_from_dict` give a :class:`hinf_cpp.Scenario`, and
:func:`scenario_toml` writes one back as a file's text;
:mod:`~hinf_cpp.scenario.settings` sets keys by name (``--set``, study axes);
:mod:`~hinf_cpp.scenario.planned` plans the inputs of a file that gives waypoints or a path;
:mod:`~hinf_cpp.scenario.documents` reads and writes the TOML documents.
"""

from hinf_cpp import _core
from hinf_cpp._core import scenario_toml
from hinf_cpp.scenario.documents import model_from_callable
from hinf_cpp.scenario.loading import load_scenario, scenario_from_dict, scenario_path, signal_from_spec

# [model] kind = "python" in a scenario file names a callable that makes the model: the C++
# reader calls back into Python for it through this hook.
_core.set_python_model_hook(model_from_callable)

__all__ = ["load_scenario", "scenario_from_dict", "scenario_path", "scenario_toml", "signal_from_spec"]
