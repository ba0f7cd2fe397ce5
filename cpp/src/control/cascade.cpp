#include "hinf/control/cascade.hpp"

#include <cmath>

#include "hinf/core/angles.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

CascadeController::CascadeController(TrajectoryPtr trajectory, const CascadeGains& gains)
    : trajectory_(std::move(trajectory)), gains_(gains) {
  require(trajectory_ != nullptr, "CascadeController needs a trajectory");
  const auto* ship = dynamic_cast<const ShipModel*>(&trajectory_->model());
  require(ship != nullptr, "the cascade controller is written for the ship model; the model is '",
          trajectory_->model().name(), "'");
  p_ = ship->parameters();
  require(p_.m_v != 0.0 && p_.d_v != 0.0, "the cascade controller needs m_v != 0 and d_v != 0");
  for (double g : {gains.k, gains.k1, gains.k2})
    require(std::isfinite(g) && g > 0.0, "the cascade gains k, k1, k2 must be > 0, got (", gains.k, ", ",
            gains.k1, ", ", gains.k2, ")");
  q_d_.resize(6);
  u_d_.resize(2);
}

void CascadeController::control(double t, const ConstVecRef& q, VecRef u) {
  check_control_sizes(q, u.size());
  trajectory_->q_d(t, q_d_.data(), &cursor_);
  trajectory_->u_d(t, u_d_.data());
  const double uu = q[0], v = q[1], r = q[2], x = q[3], y = q[4], psi = q[5];
  const double ud = q_d_[0], vd = q_d_[1], rd = q_d_[2], xd = q_d_[3], yd = q_d_[4], psid = q_d_[5];
  const double z1e = (x * std::cos(psi) + y * std::sin(psi)) - (xd * std::cos(psid) + yd * std::sin(psid));
  const double z3e = wrap_angle(psi - psid);
  const double ue = uu - ud, ve = v - vd, re = r - rd;
  const double p = z1e - (p_.m_v / p_.d_v) * ue;
  u[0] = u_d_[0] + (p_.d_u + p_.d_v / p_.m_v) * ue - (p_.m_u + 1.0 / p_.m_v) * rd * ve +
         gains_.k * (p_.d_v / p_.m_v) * p;
  u[1] = u_d_[1] - p_.m_r * (uu * v - ud * vd) + p_.d_r * re - gains_.k1 * z3e - gains_.k2 * re;
}

}  // namespace hinf
