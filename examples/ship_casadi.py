"""The paper's ship (eqs. 1-6, docs/mathematics.md) written as a symbolic model.

It is the same model as the built-in ``hc.ShipModel``, stated with CasADi symbols the way a
user states their own vehicle: the drift f, the input matrix G, the disturbance matrix D, the
measurement C with its noise channels, the names of the states, which are positions and which
is the heading, and (optionally) the paper's decomposition of the error dynamics (26)-(31).
The Jacobians come from CasADi's automatic differentiation.

    python examples/ship_casadi.py models/ship        # exports models/ship/model.json

and a scenario file then names it: ``[model] kind = "casadi"``, ``file = "models/ship/model.json"``.
Or, in Python: ``ship().compile()`` gives the C++ model directly.
"""

import sys

import casadi as ca

from hinf_cpp.models.symbolic import SymbolicModel

PAPER_PARAMETERS = {"m_u": 0.5, "m_v": -2.0, "m_r": 0.5, "d_u": 1.0, "d_v": 2.0, "d_r": 1.0}


def ship() -> SymbolicModel:
    q = ca.SX.sym("q", 6)
    u, v, r, x, y, psi = (q[i] for i in range(6))
    m_u, m_v, m_r, d_u, d_v, d_r = (ca.SX.sym(name) for name in PAPER_PARAMETERS)
    f = ca.vertcat(m_u * v * r - d_u * u,
                   m_v * u * r - d_v * v,
                   m_r * u * v - d_r * r,
                   u * ca.cos(psi) - v * ca.sin(psi),
                   u * ca.sin(psi) + v * ca.cos(psi),
                   r)
    G = ca.DM([[1, 0], [0, 0], [0, 1], [0, 0], [0, 0], [0, 0]])
    D = ca.diagcat(ca.DM.eye(3), ca.DM.zeros(3, 3))   # w1..w3 on u, v, r; w4..w6: measurement noise
    C = ca.horzcat(ca.DM.zeros(3, 3), ca.DM.eye(3))   # x, y and psi are measured

    def error_split(q_d, u_d, q_e):
        """Paper (26)-(31): q1 = [u, v, x, y], q2 = [r, psi] (docs/mathematics.md)."""
        ud, vd, rd, psid = q_d[0], q_d[1], q_d[2], q_d[5]
        ue, ve, re, psie = q_e[0], q_e[1], q_e[2], q_e[5]
        c, s, cd, sd = ca.cos(psid + psie), ca.sin(psid + psie), ca.cos(psid), ca.sin(psid)
        A12 = {"u_r": m_u * vd, "v_r": m_v * ud, "x_psi": -ud * sd - vd * cd, "y_psi": ud * cd - vd * sd}
        A21 = {"r_u": m_r * vd, "r_v": m_r * ud}
        A = ca.SX.zeros(6, 6)
        A[0, 0], A[0, 1], A[0, 2] = -d_u, m_u * (rd + re), A12["u_r"]
        A[1, 0], A[1, 1], A[1, 2] = m_v * (rd + re), -d_v, A12["v_r"]
        A[3, 0], A[3, 1], A[3, 5] = c, -s, A12["x_psi"]
        A[4, 0], A[4, 1], A[4, 5] = s, c, A12["y_psi"]
        A[2, 0], A[2, 1], A[2, 2] = A21["r_u"], A21["r_v"], -d_r
        A[5, 2] = 1
        alpha = ca.vertcat(m_u * vd * re - A12["u_r"] * re,
                           m_v * ud * re - A12["v_r"] * re,
                           m_r * (ue * vd + ud * ve + ue * ve) - (A21["r_u"] * ue + A21["r_v"] * ve),
                           ud * (c - cd) - vd * (s - sd) - A12["x_psi"] * psie,
                           ud * (s - sd) + vd * (c - cd) - A12["y_psi"] * psie,
                           0)
        return A, alpha

    return SymbolicModel("ship-casadi", state=q, inputs=2, f=f, G=G, D=D, C=C, noise_channels=[3, 4, 5],
                         parameters=ca.vertcat(m_u, m_v, m_r, d_u, d_v, d_r), parameter_values=PAPER_PARAMETERS,
                         state_names=["u", "v", "r", "x", "y", "psi"], position_indices=[3, 4], heading_index=5,
                         error_split=error_split)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: python examples/ship_casadi.py OUTPUT_FOLDER")
    print(ship().export(sys.argv[1]))
