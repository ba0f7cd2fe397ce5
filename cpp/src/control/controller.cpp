#include "hinf/control/controller.hpp"

#include <cmath>

#include "hinf/core/errors.hpp"
#include "hinf/numerics/numdiff.hpp"

namespace hinf {

void Controller::control_jacobian(double t, const ConstVecRef& q, MatRef dudq) {
  if (dudq.rows() != m() || dudq.cols() != q.size())
    throw InputError(str_cat("control_jacobian: du/dq must be (", m(), ", ", q.size(), "), got (", dudq.rows(),
                             ", ", dudq.cols(), ")"));
  dudq = central_difference_jacobian(q, m(), [&](const Vec& x) {
    Vec u(m());
    control(t, x, u);
    return u;
  });
}

HinfStateFeedback::HinfStateFeedback(RiccatiSolutionPtr solution, Signal kappa)
    : solution_(std::move(solution)), kappa_(std::move(kappa)) {
  require(solution_ != nullptr, "HinfStateFeedback needs a Riccati solution");
  heading_ = solution_->trajectory().model().heading_index();
  q_d_.resize(solution_->n());
  q_e_.resize(solution_->n());
  u_d_.resize(solution_->m());
  K_.resize(solution_->m(), solution_->n());
}

std::string HinfStateFeedback::name() const {
  return std::isinf(solution_->gamma()) ? "lqr" : "hinf";
}

void HinfStateFeedback::evaluate_at(double t) {
  // Runge-Kutta stages come back to the same t: q_d, u_d, K and kappa depend on t alone.
  if (t == evaluated_at_) return;
  const Trajectory& trajectory = solution_->trajectory();
  trajectory.q_d(t, q_d_.data(), &q_cursor_);
  trajectory.u_d(t, u_d_.data());
  solution_->gain(t, K_.data(), &k_cursor_);
  kappa_now_ = checked_kappa(t);
  evaluated_at_ = t;
}

void HinfStateFeedback::control(double t, const ConstVecRef& q, VecRef u) {
  check_control_sizes(q, u.size());
  evaluate_at(t);
  tracking_error(static_cast<int>(q_e_.size()), heading_, q.data(), q_d_.data(), q_e_.data());
  const Eigen::Index m = K_.rows(), n = K_.cols();
  for (Eigen::Index i = 0; i < m; ++i) u[i] = u_d_[i];
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < m; ++i) u[i] -= kappa_now_ * K_(i, j) * q_e_[j];
}

double HinfStateFeedback::checked_kappa(double t) const {
  const double kappa = kappa_(t);
  if (!(kappa > 0.0) || !std::isfinite(kappa))
    throw InputError(str_cat("kappa(t) must be > 0 (paper eq. 18), got kappa(", t, ") = ", kappa));
  return kappa;
}

void HinfStateFeedback::control_jacobian(double t, const ConstVecRef& q, MatRef dudq) {
  check_control_sizes(q, dudq.rows());
  require(dudq.cols() == q.size(), "control_jacobian: du/dq needs ", q.size(), " columns, got ", dudq.cols());
  evaluate_at(t);
  dudq = -kappa_now_ * K_;
}

}  // namespace hinf
