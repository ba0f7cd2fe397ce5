// A program of its own on the installed hinf_cpp library: a model defined here, its desired
// trajectory, the GRDE design and the closed loop under the H-infinity state feedback, each
// checked against what is known in closed form. Exit status 0 when every check passes.
//
// The model is the double integrator
//     dp/dt = v,   dv/dt = u + w,   q = (p, v),
// i.e. A = [0 1; 0 0], B = D = [0; 1]. Its error dynamics are linear and time-invariant, so
// over a long horizon the GRDE solution Z(t0) is the stabilizing solution of the algebraic
// Riccati equation 0 = A'Z + ZA + Q - Z (BB' - gamma^-2 DD') Z. With Q = I and
// s = 1 - gamma^-2, its entries solve 1 = s z12^2, z11 = s z12 z22, 2 z12 + 1 = s z22^2.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <hinf/control/controller.hpp>
#include <hinf/control/riccati.hpp>
#include <hinf/control/simulation.hpp>
#include <hinf/control/trajectory.hpp>

namespace {

class DoubleIntegrator final : public hinf::Model {
 public:
  std::string name() const override { return "double integrator"; }
  int n() const override { return 2; }
  int m() const override { return 1; }
  int nw() const override { return 1; }
  void f(double, const hinf::ConstVecRef& q, hinf::VecRef out) const override { out << q(1), 0.0; }
  void dfdq(double, const hinf::ConstVecRef&, hinf::MatRef out) const override { out << 0.0, 1.0, 0.0, 0.0; }
  hinf::Mat G(double, const hinf::ConstVecRef&) const override { return input(); }
  hinf::Mat D(double, const hinf::ConstVecRef&) const override { return input(); }
  double remainder_bound(double, const hinf::ConstVecRef&, double) const override { return 0.0; }
  std::vector<std::string> state_names() const override { return {"p", "v"}; }
  std::vector<int> position_indices() const override { return {0}; }

 private:
  static hinf::Mat input() {
    hinf::Mat b(2, 1);
    b << 0.0, 1.0;
    return b;
  }
};

int failures = 0;

}  // namespace

int deprecated_paths_work();  // deprecated_paths.cpp

namespace {

// Prints the check; counts a failure unless value <= bound (a NaN fails).
void check_below(const char* what, double value, double bound) {
  const bool ok = value <= bound;
  std::printf("%s %s: %.3g (at most %.3g)\n", ok ? "ok  " : "FAIL", what, value, bound);
  if (!ok) ++failures;
}

// The trapezoidal integral of the samples y over the times t.
double integral(const hinf::Vec& t, const hinf::Vec& y) {
  double sum = 0.0;
  for (Eigen::Index k = 1; k < t.size(); ++k) sum += 0.5 * (t(k) - t(k - 1)) * (y(k) + y(k - 1));
  return sum;
}

}  // namespace

int main() {
  const double t0 = 0.0, tf = 20.0, gamma = 2.0;
  const hinf::Mat Q = hinf::Mat::Identity(2, 2), Qf = hinf::Mat::Identity(2, 2);

  // Desired trajectory from rest under u_d = sin t: q_d(t) = (t - sin t, 1 - cos t).
  auto model = std::make_shared<const DoubleIntegrator>();
  const hinf::Signal u_d(0.0, {hinf::Harmonic{1.0, 1.0, 0.0, false}});
  auto trajectory = std::make_shared<const hinf::Trajectory>(
      model, hinf::Vec::Zero(2), hinf::VectorSignal(std::vector<hinf::Signal>{u_d}), t0, tf);
  hinf::Vec q_d_exact(2);
  q_d_exact << tf - std::sin(tf), 1.0 - std::cos(tf);
  const double trajectory_error = (trajectory->q_d(tf) - q_d_exact).cwiseAbs().maxCoeff();
  check_below("trajectory: |q_d(tf) - closed form|", trajectory_error, 1e-7);

  // The design: Z(t0) against the algebraic Riccati equation's solution (the horizon is
  // 20 closed-loop time constants long, so what is left of Z(tf) = Qf is far below 1e-6).
  const hinf::RiccatiSolutionPtr design = hinf::solve_grde(trajectory, Q, Qf, gamma);
  const double s = 1.0 - 1.0 / (gamma * gamma);
  const double z12 = 1.0 / std::sqrt(s), z22 = std::sqrt((2.0 * z12 + 1.0) / s);
  hinf::Mat Z_are(2, 2);
  Z_are << s * z12 * z22, z12, z12, z22;
  const double riccati_error = (design->Z(t0) - Z_are).cwiseAbs().maxCoeff() / Z_are.cwiseAbs().maxCoeff();
  check_below("GRDE: |Z(t0) - closed form| / |Z|", riccati_error, 1e-6);

  // Closed loop from an initial error, no disturbance: the error dies out, and
  // V = q_e' Z(t) q_e never grows (dV/dt = -q_e'(Q + Z BB' Z + gamma^-2 Z DD' Z) q_e).
  hinf::HinfStateFeedback law(design);
  hinf::Vec q0(2);
  q0 << 1.0, -0.5;
  const hinf::SimulationOptions options;  // output every 0.01 s, CVODE BDF
  const hinf::SimulationResult free_run =
      hinf::simulate_state_feedback(*trajectory, law, hinf::VectorSignal::zeros(1), q0, options);
  check_below("closed loop: diverged (0 = no)", free_run.status == hinf::RunStatus::Completed ? 0 : 1, 0);
  const hinf::RowMat q_e = free_run.q_e();
  const double final_error =
      q_e.bottomRows(1).cwiseAbs().maxCoeff() / q_e.topRows(1).cwiseAbs().maxCoeff();
  check_below("closed loop: |q_e(tf)| / |q_e(t0)|", final_error, 1e-6);
  double V_before = INFINITY, largest_rise = 0.0;
  for (Eigen::Index k = 0; k < q_e.rows(); ++k) {
    const hinf::Vec e = q_e.row(k).transpose();
    const double V = e.dot(design->Z(free_run.t(k)) * e);
    largest_rise = std::max(largest_rise, V - V_before);
    V_before = V;
  }
  check_below("closed loop: largest rise of V between samples", largest_rise, 1e-9);

  // Closed loop from no error under a disturbance: the H-infinity bound of the design,
  //     integral(q_e'Q q_e + |u - u_d|^2) + q_e(tf)'Qf q_e(tf) <= gamma^2 integral(|w|^2).
  const hinf::Signal w(0.0, {hinf::Harmonic{1.0, 3.0, 0.0, false}, hinf::Harmonic{0.5, 0.7, 0.0, true}});
  const hinf::SimulationResult disturbed = hinf::simulate_state_feedback(
      *trajectory, law, hinf::VectorSignal(std::vector<hinf::Signal>{w}), trajectory->q_d(t0), options);
  check_below("disturbed loop: diverged (0 = no)", disturbed.status == hinf::RunStatus::Completed ? 0 : 1, 0);
  const hinf::RowMat e = disturbed.q_e();
  const hinf::RowMat u_e = disturbed.u - disturbed.u_d;
  const hinf::Vec cost_rate = e.rowwise().squaredNorm() + u_e.rowwise().squaredNorm();  // Q = I
  const hinf::Vec e_final = e.bottomRows(1).transpose();
  const double cost = integral(disturbed.t, cost_rate) + e_final.dot(Qf * e_final);
  const double energy = integral(disturbed.t, disturbed.w.rowwise().squaredNorm());
  check_below("disturbed loop: L2 gain from w to (q_e, u - u_d)", std::sqrt(cost / energy), gamma);

  // The include paths of 0.1 (deprecated_paths.cpp) still build and link.
  check_below("programs written for the include paths of 0.1 still work", deprecated_paths_work(), 0.0);

  std::printf("%s\n", failures == 0 ? "all checks passed" : "some checks FAILED");
  return failures == 0 ? 0 : 1;
}
