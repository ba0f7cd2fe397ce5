#include "hinf/disturbance.hpp"

#include <cmath>

#include "hinf/angles.hpp"
#include "hinf/errors.hpp"

namespace hinf {

Disturbance::Disturbance(VectorSignal signals) : signals_(std::move(signals)) {}

Disturbance::Disturbance(VectorSignal signals, RiccatiSolutionPtr design)
    : signals_(std::move(signals)), design_(std::move(design)) {
  require(design_ != nullptr, "the worst-case disturbance needs a design (a GRDE solution)");
  require(std::isfinite(design_->gamma()),
          "the worst-case disturbance gamma^-2 D' Z q_e needs a finite gamma (at gamma = inf it is zero)");
  const Model& model = design_->trajectory().model();
  require(signals_.dim() == model.nw(), "the disturbance has ", signals_.dim(), " channels, the model '",
          model.name(), "' has ", model.nw());
  const int n = model.n();
  q_d_.resize(n);
  z_.resize(packed_size(n));
  Zq_.resize(n);
}

void Disturbance::eval(double t, const double* q, double* w) const {
  signals_.eval(t, w);
  if (!design_) return;
  const Trajectory& trajectory = design_->trajectory();
  const Model& model = trajectory.model();
  const int n = model.n();
  trajectory.q_d(t, q_d_.data(), &q_cursor_);
  tracking_error(n, model.heading_index(), q, q_d_.data(), q_d_.data());  // q_e, in place
  design_->packed(t, z_.data(), &z_cursor_);
  // Z q_e from the packed Z.
  for (int i = 0; i < n; ++i) {
    double s = 0.0;
    for (int j = 0; j < n; ++j) s += z_[packed_index(i, j)] * q_d_[j];
    Zq_[i] = s;
  }
  if (D_.size() == 0 || !model.constant_input_matrices()) D_ = model.D(t);  // D is kept when constant
  const double g2 = 1.0 / (design_->gamma() * design_->gamma());
  for (Eigen::Index c = 0; c < D_.cols(); ++c) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += D_(i, c) * Zq_[i];
    w[c] += g2 * s;
  }
}

}  // namespace hinf
