"""The built-in C++ models as symbolic models (CasADi expressions), for the trajectory planner.

The planner (``hinf_cpp.planning.planner``, docs/planning.md) optimizes over the model's dynamics with
IPOPT, which needs the dynamics as CasADi expressions: exact first and second derivatives by
automatic differentiation. A model written by the user in CasADi (a
:class:`~hinf_cpp.models.symbolic.SymbolicModel`) has them; the built-in models are C++ code with
analytic first derivatives only. :func:`symbolic_model` states each built-in model again in
CasADi, with the parameters of the given C++ object, as the equations of
``cpp/include/hinf/models/ship.hpp``, ``vehicles.hpp`` and ``model.hpp`` write them; the tests
(tests/python/test_planner.py) check f, G, D, C and df/dq of every one against the C++ model to
round-off, so the two statements cannot drift apart unnoticed.
"""

from __future__ import annotations

import numpy as np

from hinf_cpp import _core
from hinf_cpp.models.symbolic import SymbolicModel, _casadi

__all__ = ["symbolic_model"]


def symbolic_model(model) -> SymbolicModel:
    """The model as a :class:`SymbolicModel` (CasADi expressions), for the planner.

    A SymbolicModel is returned as it is; a built-in model (``ShipModel``, ``LinearModel``,
    ``FossenVessel``, ``Hovercraft``, ``PlanarVtol``, ``Auv``) becomes its CasADi statement
    with the object's parameters (as constants), with the same state names, position indices,
    heading index and measurement.

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
    for kind, build in _BUILDERS:
        if isinstance(model, kind):
            return build(model)
    name = model.name() if isinstance(model, _core.Model) else type(model).__name__
    raise ValueError(f"the model '{name}' has no CasADi form: planning needs the model's equations as CasADi "
                     "expressions. Use a built-in model (ship, fossen_vessel, hovercraft, pvtol, auv, linear) or "
                     "state the model as a hinf_cpp.models.symbolic.SymbolicModel (docs/models.md) and pass that")


def _common(model) -> dict:
    """The structure of a C++ model, as SymbolicModel's keyword arguments."""
    return dict(state_names=model.state_names(), position_indices=model.position_indices(),
                heading_index=model.heading_index())


def _measurement(model) -> dict:
    noise = model.noise_channels()
    return dict(C=np.asarray(model.C(0.0)), noise_channels=noise) if noise else {}


def _body_kinematics(ca, q):
    """eta_dot = R(psi) nu for q = [u, v, r, x, y, psi]."""
    u, v, r, psi = q[0], q[1], q[2], q[5]
    return ca.vertcat(u * ca.cos(psi) - v * ca.sin(psi), u * ca.sin(psi) + v * ca.cos(psi), r)


def _ship(model) -> SymbolicModel:
    ca = _casadi()
    p = model.parameters()
    q = ca.SX.sym("q", 6)
    u, v, r = q[0], q[1], q[2]
    f = ca.vertcat(p.m_u * v * r - p.d_u * u, p.m_v * u * r - p.d_v * v, p.m_r * u * v - p.d_r * r,
                   _body_kinematics(ca, q))
    G = np.zeros((6, 2))
    G[0, 0] = G[2, 1] = 1.0
    D = np.diag([1.0, 1.0, 1.0, 0.0, 0.0, 0.0])
    return SymbolicModel(model.name(), state=q, inputs=2, f=f, G=G, D=D, **_measurement(model), **_common(model))


def _fossen_vessel(model) -> SymbolicModel:
    ca = _casadi()
    p = model.parameters()
    M, Dmp = np.asarray(p.M), np.asarray(p.D)
    M_inverse = np.linalg.inv(M)
    q = ca.SX.sym("q", 6)
    nu = q[0:3]
    a = ca.mtimes(ca.DM(M), nu)
    u, v, r = q[0], q[1], q[2]
    coriolis = ca.vertcat(-a[1] * r, a[0] * r, a[1] * u - a[0] * v)  # C(nu) nu
    f = ca.vertcat(-ca.mtimes(ca.DM(M_inverse), coriolis + ca.mtimes(ca.DM(Dmp), nu)), _body_kinematics(ca, q))
    G = np.zeros((6, 2))
    G[0:3, 0], G[0:3, 1] = M_inverse[:, 0], M_inverse[:, 2]  # surge force, yaw moment
    D = np.zeros((6, 6))
    D[0:3, 0:3] = M_inverse
    return SymbolicModel(model.name(), state=q, inputs=2, f=f, G=G, D=D, **_measurement(model), **_common(model))


def _hovercraft(model) -> SymbolicModel:
    ca = _casadi()
    p = model.parameters()
    q = ca.SX.sym("q", 6)  # [x, y, psi, vx, vy, r]
    f = ca.vertcat(q[3], q[4], q[5], -p.d * q[3], -p.d * q[4], -p.d_r * q[5])
    G = ca.SX.zeros(6, 2)
    G[3, 0], G[4, 0], G[5, 1] = ca.cos(q[2]), ca.sin(q[2]), 1
    D = np.zeros((6, 6))
    D[3:6, 0:3] = np.eye(3)
    return SymbolicModel(model.name(), state=q, inputs=2, f=f, G=G, D=D, **_measurement(model), **_common(model))


def _pvtol(model) -> SymbolicModel:
    ca = _casadi()
    p = model.parameters()
    q = ca.SX.sym("q", 6)  # [x, y, theta, x_dot, y_dot, theta_dot]
    f = ca.vertcat(q[3], q[4], q[5], 0, -p.g, 0)
    c, s = ca.cos(q[2]), ca.sin(q[2])
    G = ca.SX.zeros(6, 2)
    G[3, 0], G[3, 1] = -s, p.epsilon * c
    G[4, 0], G[4, 1] = c, p.epsilon * s
    G[5, 1] = 1
    D = np.zeros((6, 6))
    D[3:6, 0:3] = np.eye(3)
    return SymbolicModel(model.name(), state=q, inputs=2, f=f, G=G, D=D, **_measurement(model), **_common(model))


def _auv(model) -> SymbolicModel:
    ca = _casadi()
    p = model.parameters()
    q = ca.SX.sym("q", 6)
    u, v, r = q[0], q[1], q[2]
    f = ca.vertcat((p.m22 * v * r - p.X_u * u - p.X_uu * ca.fabs(u) * u) / p.m11,
                   (-p.m11 * u * r - p.Y_v * v - p.Y_vv * ca.fabs(v) * v) / p.m22,
                   ((p.m11 - p.m22) * u * v - p.N_r * r - p.N_rr * ca.fabs(r) * r) / p.m33,
                   _body_kinematics(ca, q))
    G = np.zeros((6, 2))
    G[0, 0], G[2, 1] = 1.0 / p.m11, 1.0 / p.m33
    D = np.zeros((6, 6))
    D[0:3, 0:3] = np.diag([1.0 / p.m11, 1.0 / p.m22, 1.0 / p.m33])
    return SymbolicModel(model.name(), state=q, inputs=2, f=f, G=G, D=D, **_measurement(model), **_common(model))


def _linear(model) -> SymbolicModel:
    ca = _casadi()
    A, B, D = (np.asarray(M) for M in (model.A(), model.B(), model.D(0.0, np.zeros(model.n()))))
    q = ca.SX.sym("q", A.shape[0])
    return SymbolicModel(model.name(), state=q, inputs=B.shape[1], f=ca.mtimes(ca.DM(A), q), G=B, D=D,
                         **_measurement(model), **_common(model))


_BUILDERS = [(_core.ShipModel, _ship), (_core.FossenVessel, _fossen_vessel), (_core.Hovercraft, _hovercraft),
             (_core.PlanarVtol, _pvtol), (_core.Auv, _auv), (_core.LinearModel, _linear)]
