// Private: the arithmetic of the online controller (online_controller.hpp) between its calls: the
// prediction of the tracking error along the sampled law's tables (state feedback), or the
// estimator (35) and the filter (36) (output feedback), integrated by classical Runge-Kutta
// steps, and the coupling condition's rho(Sigma Z). Fixed-size matrices for the paper's 6 states
// (numerics/size_dispatch.hpp), dynamic ones otherwise; all memory is taken at construction, and
// nothing here allocates, locks or throws afterwards.
#pragma once

#include <memory>

#include "hinf/control/online_controller.hpp"

namespace hinf::detail {

class OnlineEstimator {
 public:
  virtual ~OnlineEstimator() = default;
  // The tables of another law from now on (of the same sizes, gamma and period: the successor of
  // OnlineController::set_successor).
  virtual void set_law(const SampledLaw& law) noexcept = 0;
  // `substeps` equal Runge-Kutta steps from s to end with the command u applied (m): of
  // dx/dt = A_e x + B_e (u - u_d) for state feedback (Sigma and y_e unused), of (35)-(36) for
  // output feedback, the measured error y_e (p) held in the innovation when `innovate`; x (n) and
  // Sigma (n x n) in and out.
  virtual void integrate(double s, double end, int substeps, const Vec& u, const Vec& y_e, bool innovate, Vec& x,
                         Mat& Sigma) noexcept = 0;
  // The sampled-measurement update at t of the measured error y_e (p): Sigma+ = (Sigma^-1 +
  // C' R^-1 C)^-1 with R = N / hold, x += [I - gamma^-2 Sigma+ Z]^-1 Sigma+ C' R^-1 (y_e - C x),
  // the heading's innovation wrapped. Output feedback only. x becomes NaN when Sigma is not
  // positive definite or the gain is singular.
  virtual void update(double t, const Vec& y_e, Vec& x, Mat& Sigma) noexcept = 0;
  // The discrete central controller (MeasurementUpdate::Discrete, digital law): from sample k to
  // k + 1 with the command u_e (m, less u_d) and the measured error y_e of sample k (null: none),
  // x and Sigma in and out. False, leaving them unchanged, when Sigma_k or Pi_k^-1 is not positive
  // definite.
  virtual bool advance(int k, const Vec& u_e, const Vec* y_e, Vec& x, Mat& Sigma) noexcept = 0;
  // The worst-case state of sample k given its measured error y_e (null: none) into out,
  // x + H (gamma^-2 M_k x + C' R^-1 (y_e - C x)), H = (Sigma^-1 + C' R^-1 C - gamma^-2 M_k)^-1
  // (discrete_output_feedback.hpp), and rho(Sigma M_k) as the return value (+inf when Sigma is not
  // positive definite; out is then NaN, as when H^-1 is not positive definite).
  virtual double worst_case_state(int k, const Vec& x, const Mat& Sigma, const Vec* y_e, Vec& out) noexcept = 0;
  // rho(Sigma Z(t)) (+inf when Sigma is not positive definite).
  virtual double coupling(double t, const Mat& Sigma) noexcept = 0;
};

// The arithmetic for `law`: state feedback when filter.enabled() is false, else output feedback
// with the filter's weights (validated by the caller), C the model's measurement matrix and
// heading_row the row of C that measures the heading (or -1).
std::unique_ptr<OnlineEstimator> make_online_estimator(const SampledLaw& law, const OnlineFilter& filter, const Mat& C,
                                                       int heading_row);

}  // namespace hinf::detail
