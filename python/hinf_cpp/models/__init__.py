"""Models beyond the built-in C++ ones: your own vehicle in CasADi symbols, compiled for the C++ core.

:class:`SymbolicModel` (:mod:`~hinf_cpp.models.symbolic`) states a control-affine model with
CasADi expressions; :meth:`SymbolicModel.compile` turns it into a :class:`hinf_cpp.GeneratedModel`
evaluated in C++ through :mod:`~hinf_cpp.models.codegen` (C code generation, the system C
compiler, a cache). :mod:`~hinf_cpp.models.builtin` states the built-in vehicles in CasADi (the
planner needs their expressions). CasADi itself is imported only when it is used.
"""

from hinf_cpp.models.builtin import symbolic_model
from hinf_cpp.models.codegen import compile_c_source, compile_casadi_functions
from hinf_cpp.models.symbolic import CompiledModel, SymbolicModel

__all__ = ["CompiledModel", "SymbolicModel", "compile_c_source", "compile_casadi_functions", "symbolic_model"]
