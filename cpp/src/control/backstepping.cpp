#include "hinf/control/backstepping.hpp"

#include <cmath>

#include "hinf/core/angles.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

namespace {

// Below this |v_c| (m/s) the commanded velocity has no direction: hold the heading.
constexpr double kNoDirection = 1e-9;

}  // namespace

BacksteppingController::BacksteppingController(TrajectoryPtr trajectory, const BacksteppingGains& gains)
    : trajectory_(std::move(trajectory)), gains_(gains) {
  require(trajectory_ != nullptr, "BacksteppingController needs a trajectory");
  const auto* ship = dynamic_cast<const ShipModel*>(&trajectory_->model());
  require(ship != nullptr, "the backstepping controller is written for the ship model; the model is '",
          trajectory_->model().name(), "'");
  p_ = ship->parameters();
  for (double g : {gains.k, gains.k1, gains.k2, gains.k3})
    require(std::isfinite(g) && g > 0.0, "the backstepping gains k, k1, k2, k3 must be finite and > 0, got (",
            gains.k, ", ", gains.k1, ", ", gains.k2, ", ", gains.k3, ")");
  q_d_.resize(6);
  u_d_.resize(2);
}

void BacksteppingController::control(double t, const ConstVecRef& q, VecRef u) {
  check_control_sizes(q, u.size());
  trajectory_->q_d(t, q_d_.data(), &cursor_);
  trajectory_->u_d(t, u_d_.data());
  const double su = q[0], v = q[1], r = q[2], x = q[3], y = q[4], psi = q[5];
  const double ud = q_d_[0], vd = q_d_[1], rd = q_d_[2], xd = q_d_[3], yd = q_d_[4], psid = q_d_[5];
  const double c = std::cos(psi), s = std::sin(psi), cd = std::cos(psid), sd = std::sin(psid);
  // Velocities (earth frame) of the ship and of the desired point, and the desired point's
  // acceleration from the ship's equations under u_d.
  const double px_dot = su * c - v * s, py_dot = su * s + v * c;
  const double pdx_dot = ud * cd - vd * sd, pdy_dot = ud * sd + vd * cd;
  const double ud_dot = p_.m_u * vd * rd - p_.d_u * ud + u_d_[0];
  const double vd_dot = p_.m_v * ud * rd - p_.d_v * vd;
  const double pdx_ddot = (ud_dot - vd * rd) * cd - (vd_dot + ud * rd) * sd;
  const double pdy_ddot = (ud_dot - vd * rd) * sd + (vd_dot + ud * rd) * cd;
  // Commanded velocity and its rate.
  const double k = gains_.k;
  const double vcx = pdx_dot - k * (x - xd), vcy = pdy_dot - k * (y - yd);
  const double vcx_dot = pdx_ddot - k * (px_dot - pdx_dot), vcy_dot = pdy_ddot - k * (py_dot - pdy_dot);
  const double speed2 = vcx * vcx + vcy * vcy, speed = std::sqrt(speed2);
  // The desired sideslip beta_d = atan2(v_d, u_d) and its rate: the heading that makes the
  // commanded course on the desired trajectory, and the surge that makes the commanded speed.
  const double beta_d = std::atan2(vd, ud);
  const double beta_d_dot = (ud * vd_dot - vd * ud_dot) / std::max(ud * ud + vd * vd, kNoDirection);
  const double cb = std::cos(beta_d), sb = std::sin(beta_d);
  const double u_c = speed * cb;
  double psi_c = psi, psi_c_dot = 0.0, u_c_dot = 0.0;
  if (speed > kNoDirection) {
    psi_c = std::atan2(vcy, vcx) - beta_d;
    psi_c_dot = (vcx * vcy_dot - vcy * vcx_dot) / speed2 - beta_d_dot;
    u_c_dot = (vcx * vcx_dot + vcy * vcy_dot) / speed * cb - speed * sb * beta_d_dot;
  }
  const double z1 = wrap_angle(psi - psi_c);
  const double r_c = psi_c_dot - gains_.k1 * z1;
  const double z2 = r - r_c;
  // dr_c/dt is replaced by the desired yaw acceleration (equal on the desired trajectory).
  const double rd_dot = p_.m_r * ud * vd - p_.d_r * rd + u_d_[1];
  u[0] = -p_.m_u * v * r + p_.d_u * su + u_c_dot - gains_.k3 * (su - u_c);
  u[1] = -p_.m_r * su * v + p_.d_r * r + rd_dot - z1 - gains_.k2 * z2;
}

}  // namespace hinf
