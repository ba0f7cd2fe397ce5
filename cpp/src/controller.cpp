#include "hinf/controller.hpp"

#include <cmath>

#include "hinf/errors.hpp"

namespace hinf {

void Controller::control_jacobian(double t, const ConstVecRef& q, MatRef dudq) {
  Vec qp = q, up(m()), um(m());
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    const double h = 1e-7 * std::max(1.0, std::abs(q[j]));
    qp[j] = q[j] + h;
    control(t, qp, up);
    qp[j] = q[j] - h;
    control(t, qp, um);
    qp[j] = q[j];
    dudq.col(j) = (up - um) / (2.0 * h);
  }
}

HinfStateFeedback::HinfStateFeedback(RiccatiSolutionPtr solution, Signal kappa)
    : solution_(std::move(solution)), kappa_(std::move(kappa)) {
  require(solution_ != nullptr, "HinfStateFeedback needs a Riccati solution");
  q_e_.resize(solution_->n());
  K_.resize(solution_->m(), solution_->n());
}

std::string HinfStateFeedback::name() const {
  return std::isinf(solution_->gamma()) ? "lqr" : "hinf";
}

void HinfStateFeedback::control(double t, const ConstVecRef& q, VecRef u) {
  const Trajectory& trajectory = solution_->trajectory();
  trajectory.q_d(t, q_e_.data(), &q_cursor_);
  q_e_ = q - q_e_;
  trajectory.u_d(t, u.data());
  solution_->gain(t, K_.data(), &k_cursor_);
  const double kappa = checked_kappa(t);
  const Eigen::Index m = K_.rows(), n = K_.cols();
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < m; ++i) u[i] -= kappa * K_(i, j) * q_e_[j];
}

double HinfStateFeedback::checked_kappa(double t) const {
  const double kappa = kappa_(t);
  if (!(kappa > 0.0) || !std::isfinite(kappa))
    throw InputError(str_cat("kappa(t) must be > 0 (paper eq. 18), got kappa(", t, ") = ", kappa));
  return kappa;
}

void HinfStateFeedback::control_jacobian(double t, const ConstVecRef&, MatRef dudq) {
  solution_->gain(t, K_.data(), &k_cursor_);
  dudq = -checked_kappa(t) * K_;
}

}  // namespace hinf
