// The cascaded tracking baseline for the ship (models/ship.hpp): a law of the type of Lefeber,
// Pettersen & Nijmeijer, written for the ship's equations and parameters.
#pragma once

#include <cstddef>
#include <string>

#include "hinf/control/controller.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/models/ship.hpp"

namespace hinf {

// The gains of the cascade law (CascadeController), each finite and > 0.
struct CascadeGains {
  double k = 0.2;   // surge/position loop (0.2 converges fastest on the paper's path)
  double k1 = 2.0;  // heading
  double k2 = 3.0;  // yaw rate
};

// A cascaded tracking controller for the ship, of the type of Lefeber, Pettersen & Nijmeijer
// (IEEE TCST 11(1), 2003), used as a baseline. With z1 = x cos(psi) + y sin(psi) (the same for
// the desired state), z1e = z1 - z1d, z3e = psi - psi_d wrapped to (-pi, pi], u_e = u - u_d,
// v_e = v - v_d, r_e = r - r_d and gains k, k1, k2 > 0:
//     p  = z1e - (m_v / d_v) u_e,
//     u1 = u1d + (d_u + d_v / m_v) u_e - (m_u + 1 / m_v) r_d v_e + k (d_v / m_v) p,
//     u2 = u2d - m_r (u v - u_d v_d) + d_r r_e - k1 z3e - k2 r_e.
// The yaw loop is an exact feedback linearization; the surge loop relies on the desired yaw
// rate r_d being persistently exciting: on a straight line (r_d = 0) a lateral offset is not
// corrected (docs/baselines.md). Needs the ShipModel (it uses its parameters).
class CascadeController final : public Controller {
 public:
  // InputError unless the trajectory's model is a ShipModel (with m_v != 0 and d_v != 0) and
  // the gains are finite and > 0.
  CascadeController(TrajectoryPtr trajectory, const CascadeGains& gains = {});
  std::string name() const override { return "cascade"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  void control(double t, const ConstVecRef& q, VecRef u) override;
  // The gains it was made with.
  const CascadeGains& gains() const { return gains_; }

 private:
  TrajectoryPtr trajectory_;
  ShipParameters p_;
  CascadeGains gains_;
  std::size_t cursor_ = 0;
  Vec q_d_, u_d_;
};

}  // namespace hinf
