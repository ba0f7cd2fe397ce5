#include "hinf/control/disturbance.hpp"

#include <cmath>

#include "hinf/core/angles.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

Disturbance::Disturbance(VectorSignal signals) : signals_(std::move(signals)) {}

Disturbance::Disturbance(VectorSignal signals, std::shared_ptr<const SymmetricSolution> design)
    : signals_(std::move(signals)), design_(std::move(design)) {
  require(design_ != nullptr, "the worst-case disturbance needs a design (a GRDE solution)");
  require(std::isfinite(design_->gamma()),
          "the worst-case disturbance gamma^-2 D' Z q_e needs a finite gamma (at gamma = inf it is zero)");
  const Model& model = design_->trajectory().model();
  require(signals_.dim() == model.nw(), "the disturbance has ", signals_.dim(), " channels, the model '",
          model.name(), "' has ", model.nw());
  if (model.constant_input_matrices()) D_ = model.D(design_->t0(), design_->trajectory().q_d0());
}

void Disturbance::eval(double t, const double* q, double* w) const {
  signals_.eval(t, w);
  if (!design_) return;
  const Trajectory& trajectory = design_->trajectory();
  const Model& model = trajectory.model();
  const int n = model.n();
  Vec q_d(n), q_e(n), Zq(n);
  trajectory.q_d(t, q_d.data());
  tracking_error(n, model.heading_index(), q, q_d.data(), q_e.data());
  PackedScratch z(n);
  design_->packed(t, z.data());
  // Z q_e from the packed Z.
  for (int i = 0; i < n; ++i) {
    double s = 0.0;
    for (int j = 0; j < n; ++j) s += z.data()[packed_index(i, j)] * q_e[j];
    Zq[i] = s;
  }
  const Mat D = D_.size() > 0 ? D_ : model.D(t, q_d);  // D_e(t), the design's
  const double g2 = 1.0 / (design_->gamma() * design_->gamma());
  for (Eigen::Index c = 0; c < D.cols(); ++c) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += D(i, c) * Zq[i];
    w[c] += g2 * s;
  }
}

}  // namespace hinf
