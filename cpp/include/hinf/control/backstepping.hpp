// The backstepping tracking baseline for the ship (models/ship.hpp): a law of the type of
// Godhavn (paper reference [3]: Godhavn, "Nonlinear tracking of underactuated surface vessels",
// IEEE CDC 1996, and his thesis, NTNU 1997), which steers the ship's velocity towards the
// desired position: it turns the ship to point where it must go, so a ship ahead of its desired
// point turns around (the paper's claim (i) contrasts its own law with this behaviour).
#pragma once

#include <cstddef>
#include <string>

#include "hinf/control/controller.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/models/ship.hpp"

namespace hinf {

// The gains of the backstepping law (BacksteppingController), each finite and > 0.
struct BacksteppingGains {
  double k = 0.5;   // position: commanded velocity p_d' - k (p - p_d) (1/s)
  double k1 = 1.0;  // heading towards the commanded velocity (1/s)
  double k2 = 2.0;  // yaw rate (1/s)
  double k3 = 1.0;  // surge speed (1/s)
};

// With p = (x, y), the commanded earth-frame velocity v_c = dp_d/dt - k (p - p_d) gives the
// heading command psi_c = atan2(v_c) - beta_d and the surge command u_c = |v_c| cos(beta_d),
// beta_d = atan2(v_d, u_d) the desired sideslip (the heading and surge that make the commanded
// course and speed on the desired trajectory); the yaw rate is backstepped through
// r_c = dpsi_c/dt - k1 z1:
//     z1 = wrap(psi - psi_c),  z2 = r - r_c,
//     u2 = -m_r u v + d_r r + dr_d/dt - z1 - k2 z2,
//     u1 = -m_u v r + d_u u + du_c/dt - k3 (u - u_c),
// with dpsi_c/dt and du_c/dt exact (from dv_c/dt = d2p_d/dt2 - k (dp/dt - dp_d/dt)) and dr_c/dt
// replaced by the desired yaw acceleration dr_d/dt, equal on the desired trajectory: the desired
// trajectory is a solution of the closed loop. The sideslip is the desired one, not the
// measured atan2(v, u): fed back, the measured one makes the sway's zero dynamics
// (1 + m_v) dv/dt = -d_v v + ... unstable for m_v < -1 (the paper's ship has m_v = -2). The
// ship moves forward (u_c >= 0 while |beta_d| < pi/2), so a desired point behind it is reached
// by turning round. Where |v_c| vanishes the heading command holds the heading. Needs the
// ShipModel (its parameters). Written from the ship's equations after Godhavn's construction
// (position as the output, the commanded velocity's direction as the heading command,
// backstepping through the yaw rate), not transcribed from his text.
class BacksteppingController final : public Controller {
 public:
  // InputError unless the trajectory's model is a ShipModel and the gains are finite and > 0.
  BacksteppingController(TrajectoryPtr trajectory, const BacksteppingGains& gains = {});
  std::string name() const override { return "backstepping"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  void control(double t, const ConstVecRef& q, VecRef u) override;
  // The gains it was made with.
  const BacksteppingGains& gains() const { return gains_; }

 private:
  TrajectoryPtr trajectory_;
  ShipParameters p_;
  BacksteppingGains gains_;
  std::size_t cursor_ = 0;
  Vec q_d_, u_d_;
};

}  // namespace hinf
