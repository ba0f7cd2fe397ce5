// The library of underactuated vehicles (docs/vehicles.md), each a Model with an analytic
// Jacobian, for tracking studies beyond the paper's ship (models/ship.hpp); one header each:
//
//   FossenVessel  3-DOF surface vessel in Fossen's matrix form (supply vessel preset)
//   Hovercraft    planar hovercraft in inertial coordinates (input matrix depends on the heading)
//   PlanarVtol    the planar VTOL aircraft of Hauser, Sastry and Meyer (input matrix depends on
//                 the roll angle)
//   Auv           AUV in the horizontal plane with quadratic drag (Sirene preset)
//
// State orders and units, fixed here once:
//   FossenVessel, Auv: q = [u, v, r, x, y, psi] (the ship's order): surge and sway speed in the
//       body frame, yaw rate, inertial position, heading. FossenVessel is in Fossen's
//       dimensionless bis units (length L, time sqrt(L / g), mass of the ship); Auv in SI
//       (m/s, rad/s, m, rad; inputs in N and N m).
//   Hovercraft: q = [x, y, psi, vx, vy, r]: inertial position (m), heading (rad), inertial
//       velocity (m/s), yaw rate (rad/s); inputs per unit mass (m/s^2) and inertia (rad/s^2).
//   PlanarVtol: q = [x, y, theta, x_dot, y_dot, theta_dot]: lateral and vertical position, roll
//       angle (rad), their rates; normalized units (gravity g, 1 by default).
//
// Common to all four: m = 2 inputs (one short of the 3 degrees of freedom); nw = 6: w1..w3 are
// process disturbances on the three velocity equations (forces and moment where the model has
// masses), w4..w6 the measurement-noise channels (D has zero columns there); the measurement is
// y = C q = [x, y, heading] (position and heading or roll angle), noise on w4..w6; the tracking
// error of the heading (roll) angle is wrapped. The error split is the Model default and there
// is no analytic remainder bound (NaN: certificates use their sampled estimate).
#pragma once

#include "hinf/models/auv.hpp"
#include "hinf/models/fossen_vessel.hpp"
#include "hinf/models/hovercraft.hpp"
#include "hinf/models/planar_vtol.hpp"
