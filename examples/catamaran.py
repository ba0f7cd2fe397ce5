"""A small catamaran steered by differential thrust, written as a symbolic model (docs/end_to_end.md).

Not one of the built-in vehicles: a small surface vessel with one thruster in each hull, at the
distance b from the centre line. It has no rudder: the two thrusts T_p (port) and
T_s (starboard) give the surge force T_p + T_s and the yaw moment b (T_s - T_p), and nothing
pushes it sideways (underactuated). Surge drag is linear plus quadratic in the speed.

State q = [x, y, psi, u, v, r]: position (m, inertial), heading (rad), surge and sway speed
(m/s, body frame), yaw rate (rad/s). Inputs [T_p, T_s] (N). With the diagonal mass matrix
M = diag(m11, m22, m33) (rigid body plus added mass) and its Coriolis and centripetal terms
(Fossen's form):

    dx/dt   = u cos psi - v sin psi
    dy/dt   = u sin psi + v cos psi
    dpsi/dt = r
    m11 du/dt = m22 v r - X_u u - X_uu |u| u + T_p + T_s + w1
    m22 dv/dt = -m11 u r - Y_v v + w2
    m33 dr/dt = (m11 - m22) u v - N_r r + b (T_s - T_p) + w3

w1..w3 are disturbance force (N), force (N) and moment (N m). The measurement is the position
and the heading, y = [x, y, psi] + noise on w4..w6 (a satellite receiver and a compass); the
columns of D for w4..w6 are zero, the noise enters the measurement only. With the parameters
below the sway and yaw damping keep the boat directionally stable up to 1.8 m/s (Y_v N_r >
m11 (m22 - m11) u^2), and 12 N per thruster cannot drive it faster than 1.7 m/s.

    python examples/catamaran.py OUTPUT_FOLDER     # exports OUTPUT_FOLDER/model.json

and a scenario file names it with ``[model] kind = "casadi"``, ``file = "OUTPUT_FOLDER/model.json"``.
"""

import sys

import casadi as ca

from hinf_cpp.models.symbolic import SymbolicModel

# kg, kg, kg m^2; kg/s, kg/m, kg/s, kg m^2/s; m.
PARAMETERS = {"m11": 16.0, "m22": 22.0, "m33": 2.5, "X_u": 4.0, "X_uu": 6.0, "Y_v": 40.0, "N_r": 8.0, "b": 0.25}


def catamaran() -> SymbolicModel:
    q = ca.SX.sym("q", 6)
    psi, u, v, r = q[2], q[3], q[4], q[5]  # q = [x, y, psi, u, v, r]
    m11, m22, m33, X_u, X_uu, Y_v, N_r, b = (ca.SX.sym(name) for name in PARAMETERS)
    f = ca.vertcat(u * ca.cos(psi) - v * ca.sin(psi),
                   u * ca.sin(psi) + v * ca.cos(psi),
                   r,
                   (m22 * v * r - X_u * u - X_uu * ca.fabs(u) * u) / m11,
                   (-m11 * u * r - Y_v * v) / m22,
                   ((m11 - m22) * u * v - N_r * r) / m33)
    G = ca.vertcat(ca.SX.zeros(3, 2),
                   ca.horzcat(1 / m11, 1 / m11),
                   ca.SX.zeros(1, 2),
                   ca.horzcat(-b / m33, b / m33))
    D = ca.vertcat(ca.SX.zeros(3, 6),
                   ca.horzcat(ca.diag(ca.vertcat(1 / m11, 1 / m22, 1 / m33)), ca.SX.zeros(3, 3)))
    C = ca.horzcat(ca.DM.eye(3), ca.DM.zeros(3, 3))
    return SymbolicModel("catamaran", state=q, inputs=2, f=f, G=G, D=D, C=C, noise_channels=[3, 4, 5],
                         parameters=ca.vertcat(m11, m22, m33, X_u, X_uu, Y_v, N_r, b),
                         parameter_values=PARAMETERS,
                         state_names=["x", "y", "psi", "u", "v", "r"], position_indices=[0, 1], heading_index=2)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: python examples/catamaran.py OUTPUT_FOLDER")
    print(catamaran().export(sys.argv[1]))
