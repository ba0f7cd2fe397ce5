"""The built-in vehicles, each stated once: its equations in CasADi symbols with named parameters.

A statement is a function returning the vehicle's :class:`~hinf_cpp.models.SymbolicModel`: the
drift f, the input matrix G, the disturbance matrix D, the measurement C with its noise
channels, the names and roles of the states, and (the ship) the decomposition of the error
dynamics of paper eqs. (26)-(31). Its parameters are symbols named by the keys of the vehicle's
scenario-file section ([model] d_u = ..., M = [[...]] as M[i][j]); their defaults are those of
the C++ class. These statements are the vehicles' equations everywhere:

* the C++ core compiles in the C code CasADi generates from them
  (``cpp/src/models/generated/<vehicle>.c``, written by ``scripts/generate_vehicles.sh``;
  tests/python/test_generated_vehicles.py checks that the files are what the statements
  generate), so ``hc.ShipModel`` and the others evaluate f, df/dq, G, D, d(G u)/dq, C and the
  error split with it;
* the trajectory planner takes their expressions (exact second derivatives for IPOPT) with the
  parameters of a C++ model object (:func:`symbolic_model`).

The C++ classes add what an expression cannot carry: the checks of their parameters, the keys
of their scenario-file section and, for the ship, the analytic bound of the linearization's
remainder (docs/mathematics.md).
"""

from __future__ import annotations

import pathlib
import re

import numpy as np

from hinf_cpp import _core
from hinf_cpp.models.symbolic import SymbolicModel, _casadi

__all__ = ["STATEMENTS", "auv", "fossen_vessel", "generated_c_source", "hovercraft", "pvtol", "ship", "symbolic_model",
           "write_generated_sources"]

# The measurement of every built-in vehicle: position and heading (or roll angle), with their noise
# on the disturbance channels w4..w6 (whose columns of D are zero).
NOISE_CHANNELS = [3, 4, 5]


def _parameters(ca, names):
    """One scalar symbol per name, in order."""
    return [ca.SX.sym(name) for name in names]


def _pick(indices, n=6):
    """C = the rows of the identity at `indices` (y = q[indices])."""
    C = np.zeros((len(indices), n))
    C[np.arange(len(indices)), indices] = 1.0
    return C


def _body_kinematics(ca, q):
    """eta_dot = R(psi) nu for q = [u, v, r, x, y, psi]: the inertial velocity of a body-frame vessel."""
    u, v, r, psi = q[0], q[1], q[2], q[5]
    return ca.vertcat(u * ca.cos(psi) - v * ca.sin(psi), u * ca.sin(psi) + v * ca.cos(psi), r)


def _values(model, given: dict | None) -> dict:
    """The parameter values of the C++ model object `model` by name, with those `given` in their place."""
    values = dict(model.named_parameters())
    unknown = sorted(set(given or {}) - set(values))
    if unknown:
        raise ValueError(f"the {model.name()} has no parameters {unknown} (its parameters: {', '.join(values)})")
    values.update(given or {})
    return values


def ship(parameter_values: dict | None = None) -> SymbolicModel:
    """The ship's statement: the underactuated surface ship of paper eqs. (1)-(6), as a SymbolicModel.

    q = [u, v, r, x, y, psi] (docs/mathematics.md)::

        du/dt = m_u v r - d_u u + u1 + w1,    dv/dt = m_v u r - d_v v + w2,
        dr/dt = m_r u v - d_r r + u2 + w3,    (dx, dy, dpsi)/dt = R(psi) (u, v) and r,

    with the decomposition of its error dynamics of paper eqs. (26)-(31): q1 = [u, v, x, y],
    q2 = [r, psi] (errors). Measured: x, y, psi.

    Parameters
    ----------
    parameter_values : dict of str to float, optional
        Values of parameters by name; the others keep the defaults of ``hc.ShipModel()``.

    Returns
    -------
    SymbolicModel
        The statement: f, G, D, C (noise on w4..w6), names, position and heading indices.

    Raises
    ------
    ValueError
        `parameter_values` without a value for every parameter, or with an unknown name.

    Examples
    --------
    >>> from hinf_cpp.models import builtin
    >>> ship = builtin.ship()
    >>> ship.parameter_values
    {'m_u': 0.5, 'm_v': -2.0, 'm_r': 0.5, 'd_u': 1.0, 'd_v': 2.0, 'd_r': 1.0}
    >>> ship.state_names, ship.error_split is not None
    (['u', 'v', 'r', 'x', 'y', 'psi'], True)
    """
    ca = _casadi()
    q = ca.SX.sym("q", 6)
    u, v, r = q[0], q[1], q[2]
    m_u, m_v, m_r, d_u, d_v, d_r = _parameters(ca, ["m_u", "m_v", "m_r", "d_u", "d_v", "d_r"])
    f = ca.vertcat(m_u * v * r - d_u * u, m_v * u * r - d_v * v, m_r * u * v - d_r * r, _body_kinematics(ca, q))
    G = np.zeros((6, 2))
    G[0, 0] = G[2, 1] = 1.0
    D = np.zeros((6, 6))
    D[0:3, 0:3] = np.eye(3)

    def error_split(q_d, u_d, q_e):
        ud, vd, rd, psid = q_d[0], q_d[1], q_d[2], q_d[5]
        ue, ve, re, psie = q_e[0], q_e[1], q_e[2], q_e[5]
        c, s, cd, sd = ca.cos(psid + psie), ca.sin(psid + psie), ca.cos(psid), ca.sin(psid)
        # A12 = d alpha1 / d q2 at q2 = 0, A21 = d alpha2 / d q1 at q1 = 0.
        A12_u_r, A12_v_r = m_u * vd, m_v * ud
        A12_x_psi, A12_y_psi = -ud * sd - vd * cd, ud * cd - vd * sd
        A21_r_u, A21_r_v = m_r * vd, m_r * ud
        A = ca.SX.zeros(6, 6)
        A[0, 0], A[0, 1], A[0, 2] = -d_u, m_u * (rd + re), A12_u_r
        A[1, 0], A[1, 1], A[1, 2] = m_v * (rd + re), -d_v, A12_v_r
        A[2, 0], A[2, 1], A[2, 2] = A21_r_u, A21_r_v, -d_r
        A[3, 0], A[3, 1], A[3, 5] = c, -s, A12_x_psi
        A[4, 0], A[4, 1], A[4, 5] = s, c, A12_y_psi
        A[5, 2] = 1.0
        alpha = ca.vertcat(m_u * vd * re - A12_u_r * re,
                           m_v * ud * re - A12_v_r * re,
                           m_r * (ue * vd + ud * ve + ue * ve) - (A21_r_u * ue + A21_r_v * ve),
                           ud * (c - cd) - vd * (s - sd) - A12_x_psi * psie,
                           ud * (s - sd) + vd * (c - cd) - A12_y_psi * psie,
                           0.0)
        return A, alpha

    values = _values(_core.ShipModel(), parameter_values)
    return SymbolicModel("ship", state=q, inputs=2, f=f, G=G, D=D, C=_pick([3, 4, 5]),
                         noise_channels=NOISE_CHANNELS, parameters=ca.vertcat(m_u, m_v, m_r, d_u, d_v, d_r),
                         parameter_values=values, state_names=["u", "v", "r", "x", "y", "psi"],
                         position_indices=[3, 4], heading_index=5, error_split=error_split)


def _matrix_names(name: str) -> list[str]:
    return [f"{name}[{i}][{j}]" for i in range(3) for j in range(3)]


def fossen_vessel(parameter_values: dict | None = None) -> SymbolicModel:
    """Fossen's 3-DOF horizontal-plane vessel, q = [u, v, r, x, y, psi]::

        M nu_dot + C(nu) nu + D nu = B_tau tau + w,    eta_dot = R(psi) nu,

    C(nu) nu = [-a2 r, a1 r, a2 u - a1 v] with a = M nu, B_tau = [e1, e3] (no sway force). The
    parameters are M[i][j] and D[i][j] and the derived M_inv[i][j] = (M^-1)[i][j], which the C++
    class computes once from M (and :func:`symbolic_model` with NumPy), so that the generated code
    multiplies by the inverse instead of solving with M at every evaluation. Measured: x, y, psi.

    Parameters
    ----------
    parameter_values : dict of str to float, optional
        Values of M[i][j] and D[i][j] by name (M_inv is derived from M); the others keep the
        defaults of ``hc.FossenVessel()``.

    Returns
    -------
    SymbolicModel
        The statement: f, G, D, C (noise on w4..w6), names, position and heading indices.

    Raises
    ------
    KeyError
        `parameter_values` without an entry M[i][j] or D[i][j].
    numpy.linalg.LinAlgError
        A singular M.

    Examples
    --------
    >>> from hinf_cpp.models import builtin
    >>> vessel = builtin.fossen_vessel()
    >>> len(vessel.parameter_names), vessel.parameter_names[:2]
    (27, ['M[0][0]', 'M[0][1]'])
    >>> round(vessel.parameter_values["M_inv[0][0]"] * vessel.parameter_values["M[0][0]"], 4)
    1.0
    """
    ca = _casadi()
    q = ca.SX.sym("q", 6)
    names = _matrix_names("M") + _matrix_names("D") + _matrix_names("M_inv")
    symbols = _parameters(ca, names)
    M = ca.reshape(ca.vertcat(*symbols[0:9]), 3, 3).T
    Dmp = ca.reshape(ca.vertcat(*symbols[9:18]), 3, 3).T
    M_inv = ca.reshape(ca.vertcat(*symbols[18:27]), 3, 3).T
    nu = q[0:3]
    a = ca.mtimes(M, nu)
    u, v, r = q[0], q[1], q[2]
    coriolis = ca.vertcat(-a[1] * r, a[0] * r, a[1] * u - a[0] * v)
    f = ca.vertcat(-ca.mtimes(M_inv, coriolis + ca.mtimes(Dmp, nu)), _body_kinematics(ca, q))
    G = ca.vertcat(ca.horzcat(M_inv[:, 0], M_inv[:, 2]), ca.SX.zeros(3, 2))  # surge force, yaw moment
    D = ca.vertcat(ca.horzcat(M_inv, ca.SX.zeros(3, 3)), ca.SX.zeros(3, 6))
    parameter_values = _values(_core.FossenVessel(), parameter_values)
    values = _with_inverse_mass(parameter_values)
    return SymbolicModel("fossen_vessel", state=q, inputs=2, f=f, G=G, D=D, C=_pick([3, 4, 5]),
                         noise_channels=NOISE_CHANNELS, parameters=ca.vertcat(*symbols), parameter_values=values,
                         state_names=["u", "v", "r", "x", "y", "psi"], position_indices=[3, 4], heading_index=5)


def _with_inverse_mass(values: dict) -> dict:
    """M[i][j] and D[i][j] with the derived M_inv[i][j]."""
    M = np.array([[values[f"M[{i}][{j}]"] for j in range(3)] for i in range(3)])
    inverse = np.linalg.inv(M)
    out = {name: float(values[name]) for name in _matrix_names("M") + _matrix_names("D")}
    out.update({f"M_inv[{i}][{j}]": float(inverse[i, j]) for i in range(3) for j in range(3)})
    return out


def hovercraft(parameter_values: dict | None = None) -> SymbolicModel:
    """The hovercraft's statement: the planar hovercraft in inertial coordinates, as a SymbolicModel.

    q = [x, y, psi, vx, vy, r]: thrust F along the heading and torque T, damping d
    (translation) and d_r (rotation), per unit mass and inertia::

        (dx, dy, dpsi)/dt = (vx, vy, r),   dvx/dt = -d vx + F cos(psi) + w1,
        dvy/dt = -d vy + F sin(psi) + w2,   dr/dt = -d_r r + T + w3.

    G depends on the heading (thrust along the body axis). Measured: x, y, psi.

    Parameters
    ----------
    parameter_values : dict of str to float, optional
        Values of parameters by name; the others keep the defaults of ``hc.Hovercraft()``.

    Returns
    -------
    SymbolicModel
        The statement: f, G, D, C (noise on w4..w6), names, position and heading indices.

    Raises
    ------
    ValueError
        `parameter_values` without a value for every parameter, or with an unknown name.

    Examples
    --------
    >>> from hinf_cpp.models import builtin
    >>> hovercraft = builtin.hovercraft()
    >>> hovercraft.parameter_values, hovercraft.state_dependent_inputs
    ({'d': 0.2, 'd_r': 0.5}, True)
    """
    ca = _casadi()
    q = ca.SX.sym("q", 6)
    d, d_r = _parameters(ca, ["d", "d_r"])
    f = ca.vertcat(q[3], q[4], q[5], -d * q[3], -d * q[4], -d_r * q[5])
    G = ca.SX.zeros(6, 2)
    G[3, 0], G[4, 0], G[5, 1] = ca.cos(q[2]), ca.sin(q[2]), 1.0
    D = np.zeros((6, 6))
    D[3:6, 0:3] = np.eye(3)
    return SymbolicModel("hovercraft", state=q, inputs=2, f=f, G=G, D=D, C=_pick([0, 1, 2]),
                         noise_channels=NOISE_CHANNELS, parameters=ca.vertcat(d, d_r),
                         parameter_values=_values(_core.Hovercraft(), parameter_values),
                         state_names=["x", "y", "psi", "vx", "vy", "r"], position_indices=[0, 1], heading_index=2)


def pvtol(parameter_values: dict | None = None) -> SymbolicModel:
    """The planar VTOL's statement: the aircraft of Hauser, Sastry and Meyer (1992), normalized.

    q = [x, y, theta, x_dot, y_dot, theta_dot], u = [thrust u1, rolling moment u2]::

        x_ddot = -u1 sin(theta) + epsilon u2 cos(theta) + w1,
        y_ddot = u1 cos(theta) + epsilon u2 sin(theta) - g + w2,   theta_ddot = u2 + w3.

    The roll angle theta is the heading state. Measured: x, y, theta.

    Parameters
    ----------
    parameter_values : dict of str to float, optional
        Values of parameters by name; the others keep the defaults of ``hc.PlanarVtol()``.

    Returns
    -------
    SymbolicModel
        The statement: f, G, D, C (noise on w4..w6), names, position and heading indices.

    Raises
    ------
    ValueError
        `parameter_values` without a value for every parameter, or with an unknown name.

    Examples
    --------
    >>> from hinf_cpp.models import builtin
    >>> vtol = builtin.pvtol({"g": 1.0, "epsilon": 0.2})
    >>> vtol.parameter_values, vtol.heading_index
    ({'g': 1.0, 'epsilon': 0.2}, 2)
    """
    ca = _casadi()
    q = ca.SX.sym("q", 6)
    g, epsilon = _parameters(ca, ["g", "epsilon"])
    f = ca.vertcat(q[3], q[4], q[5], 0.0, -g, 0.0)
    c, s = ca.cos(q[2]), ca.sin(q[2])
    G = ca.SX.zeros(6, 2)
    G[3, 0], G[3, 1] = -s, epsilon * c
    G[4, 0], G[4, 1] = c, epsilon * s
    G[5, 1] = 1.0
    D = np.zeros((6, 6))
    D[3:6, 0:3] = np.eye(3)
    return SymbolicModel("pvtol", state=q, inputs=2, f=f, G=G, D=D, C=_pick([0, 1, 2]),
                         noise_channels=NOISE_CHANNELS, parameters=ca.vertcat(g, epsilon),
                         parameter_values=_values(_core.PlanarVtol(), parameter_values),
                         state_names=["x", "y", "theta", "x_dot", "y_dot", "theta_dot"], position_indices=[0, 1],
                         heading_index=2)


def auv(parameter_values: dict | None = None) -> SymbolicModel:
    """The AUV's statement: an underactuated AUV in the horizontal plane, as a SymbolicModel.

    Linear and quadratic drag (diagonal mass matrix, no sway thrust), q = [u, v, r, x, y, psi],
    u = [tau_u (N), tau_r (N m)]::

        m11 du/dt = m22 v r - X_u u - X_uu |u| u + tau_u + w1,
        m22 dv/dt = -m11 u r - Y_v v - Y_vv |v| v + w2,
        m33 dr/dt = (m11 - m22) u v - N_r r - N_rr |r| r + tau_r + w3,   eta_dot = R(psi) nu.

    Measured: x, y, psi.

    Parameters
    ----------
    parameter_values : dict of str to float, optional
        Values of parameters by name; the others keep the defaults of ``hc.Auv()``.

    Returns
    -------
    SymbolicModel
        The statement: f, G, D, C (noise on w4..w6), names, position and heading indices.

    Raises
    ------
    ValueError
        `parameter_values` without a value for every parameter, or with an unknown name.

    Examples
    --------
    >>> from hinf_cpp.models import builtin
    >>> auv = builtin.auv()
    >>> auv.parameter_names[:3], auv.parameter_values["m11"]
    (['m11', 'm22', 'm33'], 215.0)
    """
    ca = _casadi()
    q = ca.SX.sym("q", 6)
    names = ["m11", "m22", "m33", "X_u", "X_uu", "Y_v", "Y_vv", "N_r", "N_rr"]
    m11, m22, m33, X_u, X_uu, Y_v, Y_vv, N_r, N_rr = symbols = _parameters(ca, names)
    u, v, r = q[0], q[1], q[2]
    f = ca.vertcat((m22 * v * r - X_u * u - X_uu * ca.fabs(u) * u) / m11,
                   (-m11 * u * r - Y_v * v - Y_vv * ca.fabs(v) * v) / m22,
                   ((m11 - m22) * u * v - N_r * r - N_rr * ca.fabs(r) * r) / m33,
                   _body_kinematics(ca, q))
    G = ca.SX.zeros(6, 2)
    G[0, 0], G[2, 1] = 1.0 / m11, 1.0 / m33
    D = ca.SX.zeros(6, 6)
    D[0, 0], D[1, 1], D[2, 2] = 1.0 / m11, 1.0 / m22, 1.0 / m33
    return SymbolicModel("auv", state=q, inputs=2, f=f, G=G, D=D, C=_pick([3, 4, 5]), noise_channels=NOISE_CHANNELS,
                         parameters=ca.vertcat(*symbols), parameter_values=_values(_core.Auv(), parameter_values),
                         state_names=["u", "v", "r", "x", "y", "psi"], position_indices=[3, 4], heading_index=5)


#: The statement of each built-in vehicle by its scenario-file kind, with the name of the C++ class
#: whose equations it is: kind -> (statement function, class name).
STATEMENTS = {"ship": (ship, "ShipModel"), "fossen_vessel": (fossen_vessel, "FossenVessel"),
              "hovercraft": (hovercraft, "Hovercraft"), "pvtol": (pvtol, "PlanarVtol"), "auv": (auv, "Auv")}

def symbolic_model(model) -> SymbolicModel:
    """The model as a :class:`SymbolicModel` (CasADi expressions), for the planner.

    A SymbolicModel is returned as it is; a built-in vehicle (``ShipModel``, ``FossenVessel``,
    ``Hovercraft``, ``PlanarVtol``, ``Auv``) becomes its statement (:data:`STATEMENTS`) with the
    object's parameters as the parameters' values; a ``LinearModel`` becomes A q, B and D with
    its matrices as constants.

    Parameters
    ----------
    model : hinf_cpp.Model or SymbolicModel
        The model.

    Returns
    -------
    SymbolicModel
        The model's f, G and D (and C with a measurement) as CasADi expressions.

    Raises
    ------
    ValueError
        Any other model (a Python subclass of ``hc.Model``, a ``GeneratedModel`` loaded from
        a file, a ``FleetModel``): its equations are not available as expressions.

    Examples
    --------
    >>> from hinf_cpp.models import symbolic_model
    >>> ship = symbolic_model(hc.ShipModel())
    >>> ship.name, ship.n, ship.m, ship.nw
    ('ship', 6, 2, 6)
    >>> ship.state_names, ship.position_indices, ship.heading_index
    (['u', 'v', 'r', 'x', 'y', 'psi'], [3, 4], 5)
    """
    if isinstance(model, SymbolicModel):
        return model
    for kind, (statement, cpp_class) in STATEMENTS.items():
        if isinstance(model, getattr(_core, cpp_class)):
            return statement(dict(model.named_parameters()))
    if isinstance(model, _core.LinearModel):
        return _linear(model)
    name = model.name() if isinstance(model, _core.Model) else type(model).__name__
    raise ValueError(f"the model '{name}' has no CasADi form: planning needs the model's equations as CasADi "
                     "expressions. Use a built-in model (ship, fossen_vessel, hovercraft, pvtol, auv, linear) or "
                     "state the model as a hinf_cpp.models.symbolic.SymbolicModel (docs/models.md) and pass that")


def _linear(model) -> SymbolicModel:
    """A LinearModel as expressions: f = A q, G = B, D (its matrices as constants)."""
    ca = _casadi()
    A, B, D = (np.asarray(M) for M in (model.A(), model.B(), model.D(0.0, np.zeros(model.n()))))
    q = ca.SX.sym("q", A.shape[0])
    noise = model.noise_channels()
    measurement = dict(C=np.asarray(model.C(0.0)), noise_channels=noise) if noise else {}
    return SymbolicModel(model.name(), state=q, inputs=B.shape[1], f=ca.mtimes(ca.DM(A), q), G=B, D=D,
                         state_names=model.state_names(), position_indices=model.position_indices(),
                         heading_index=model.heading_index(), **measurement)


# CasADi's code generator with the types the C++ core reads (hinf/numerics/generated_function.hpp).
_GENERATOR_OPTIONS = {"casadi_real": "double", "casadi_int": "long long int", "with_header": False}
_EXPORTED = re.compile(r"^CASADI_SYMBOL_EXPORT [^(\n]*?\b(\w+)\(", re.M)


def _c_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _c_array(kind: str, name: str, items: list[str]) -> str:
    return f"static const {kind} {name}[] = {{{', '.join(items) if items else '0'}}};\n"


def generated_c_source(kind: str) -> str:
    """The C file of a built-in vehicle that the C++ core compiles in.

    The code CasADi generates for its statement's functions (f, dfdq, G, D, dGudq, C and, for the
    ship, error_split; each named hinf_<kind>_<function>) and its description
    (cpp/src/models/generated/generated_model.h), hinf_<kind>_model: structure, parameter names and
    defaults, and the table of the generated functions' entry points.

    :func:`write_generated_sources` writes it for every vehicle (``scripts/generate_vehicles.sh``).

    Parameters
    ----------
    kind : str
        The vehicle's scenario-file kind, a key of :data:`STATEMENTS`: ``"ship"``,
        ``"fossen_vessel"``, ``"hovercraft"``, ``"pvtol"`` or ``"auv"``.

    Returns
    -------
    str
        The C source.

    Raises
    ------
    KeyError
        An unknown kind.

    Examples
    --------
    >>> from hinf_cpp.models.builtin import generated_c_source
    >>> source = generated_c_source("pvtol")
    >>> source.splitlines()[0]
    "/* The equations of the built-in vehicle 'pvtol' (the C++ class PlanarVtol), generated by CasADi"
    >>> "const hinf_generated_model hinf_pvtol_model" in source
    True
    """
    ca = _casadi()
    statement, cpp_class = STATEMENTS[kind]
    model = statement()
    prefix = f"hinf_{kind}_"
    generator = ca.CodeGenerator(f"{kind}.c", dict(_GENERATOR_OPTIONS, prefix=prefix))
    for function in model.functions():
        # Dense outputs (structural zeros written as zeros): the C++ core then passes its arrays
        # straight through (GeneratedFunction::passes_through), with nothing to scatter.
        inputs = function.sx_in()
        outputs = [ca.densify(output) for output in function.call(inputs)]
        generator.add(ca.Function(prefix + function.name(), inputs, outputs, function.name_in(), function.name_out()))
    code = generator.dump()
    symbols = _EXPORTED.findall(code)
    defaults = [model.parameter_values[name] for name in model.parameter_names]
    description = (
        '\n/* The description of the model (generated_model.h). */\n#include "generated_model.h"\n\n'
        + _c_array("char* const", f"{prefix}state_names", [_c_string(s) for s in model.state_names])
        + _c_array("int", f"{prefix}position_indices", [str(i) for i in model.position_indices])
        + _c_array("int", f"{prefix}noise_channels", [str(i) for i in model.noise_channels])
        + _c_array("char* const", f"{prefix}parameter_names", [_c_string(s) for s in model.parameter_names])
        + _c_array("double", f"{prefix}parameter_defaults", [repr(float(v)) for v in defaults])
        + f"static const hinf_generated_symbol {prefix}symbols[] = {{\n"
        + "".join(f"    {{{_c_string(s)}, (hinf_generated_address){s}}},\n" for s in symbols)
        + "    {0, 0}};\n\n"
        + f"const hinf_generated_model {prefix}model = {{\n"
        + f"    {_c_string(model.name)}, {model.n}, {model.m}, {model.nw},\n"
        + f"    {prefix}state_names,\n"
        + f"    {len(model.position_indices)}, {prefix}position_indices, {model.heading_index},\n"
        + f"    {len(model.noise_channels)}, {prefix}noise_channels,\n"
        + f"    {int(model.constant_input_matrices)}, {int(model.state_dependent_inputs)}, "
        + f"{int(model.C is not None)}, {int(model.error_split is not None)},\n"
        + f"    {len(model.parameter_names)}, {prefix}parameter_names, {prefix}parameter_defaults,\n"
        + f"    {_c_string(prefix)}, {prefix}symbols}};\n")
    header = (f"/* The equations of the built-in vehicle '{kind}' (the C++ class {cpp_class}), generated by CasADi\n"
              f"   {ca.__version__} from its statement in python/hinf_cpp/models/builtin.py: do not edit, run\n"
              "   bash scripts/generate_vehicles.sh */\n")
    return header + code + description


def write_generated_sources(folder: str | pathlib.Path) -> list[pathlib.Path]:
    """Writes the C file of every built-in vehicle (:func:`generated_c_source`) to ``<folder>/<kind>.c``.

    Parameters
    ----------
    folder : str or pathlib.Path
        The folder (``cpp/src/models/generated`` in the source tree); it must exist.

    Returns
    -------
    list of pathlib.Path
        The files written.

    Examples
    --------
    >>> import pathlib
    >>> from hinf_cpp.models.builtin import write_generated_sources
    >>> pathlib.Path("generated").mkdir()
    >>> [path.name for path in write_generated_sources("generated")]
    ['ship.c', 'fossen_vessel.c', 'hovercraft.c', 'pvtol.c', 'auv.c']
    """
    folder = pathlib.Path(folder)
    written = []
    for kind in STATEMENTS:
        path = folder / f"{kind}.c"
        path.write_text(generated_c_source(kind))
        written.append(path)
    return written
