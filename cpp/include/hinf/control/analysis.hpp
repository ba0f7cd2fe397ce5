// gamma*, conjugate points and the certificates of paper §3.
//
// gamma* (eq. 14) is the infimum of the gammas for which the GRDE (13) has no conjugate point
// on [t0, tf]. Whether a given gamma passes is decided by grde_escape_time(), which follows
// the inverse W = Z^-1 through an escape, so no escape between solver steps is missed. The
// pass/fail answer is monotone in gamma, so gamma* is found by bisection (k-section: one
// evaluation per thread and round).
//
// With imperfect measurements (paper §4) a gamma must also keep the filter Riccati equation
// (36) (here with A = A_e(t)) bounded and positive definite and satisfy the coupling
// condition rho(Sigma Z) < gamma^2 on [t0, tf]; each condition is monotone in gamma too.
#pragma once

#include <string>
#include <vector>

#include "hinf/control/discrete_design.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/core/enum_names.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf {

// Options of the gamma* search (gamma_star, gamma_star_output_feedback). validate() checks
// them: a bracket of finite numbers >= 0 with lower < upper (or both 0), rtol in (0, 1),
// max_evaluations >= 2, threads >= 1, and the solver options.
struct GammaStarOptions {
  double lower = 0.0;        // the bracket's lower end: a gamma that fails (0 with upper: found
                             // automatically)
  double upper = 0.0;        // the bracket's upper end: a gamma that passes; lower = upper = 0:
                             // the bracket is found by doubling / halving from 1
  double rtol = 1e-7;        // stop when upper - lower <= rtol * upper (1e-7: with the integration
                             // error of the default solver options, gamma* is good to 1e-6)
  int max_evaluations = 200;  // gammas evaluated at most, >= 2 (then converged is false)
  int threads = 2;           // gammas evaluated in parallel per round (>= 1); at most the hardware's
                             // threads are used, and fewer when max_evaluations would not
                             // suffice to converge with that many per round
  SolverOptions solver;      // for every Riccati solve
  void validate() const;
};

// The condition a gamma fails.
enum class GammaCondition {
  None,     // passed (or, for the bracket's lower end 0, never evaluated)
  Grde,     // a conjugate point of the GRDE (13), or of its discrete game (gamma_star_discrete)
  Filter,   // the filter Riccati equation (36) escapes or loses positive definiteness
  Coupling  // rho(Sigma Z) >= gamma^2 somewhere on [t0, tf]
};
template <>
struct EnumNames<GammaCondition> {
  static constexpr const char* what = "gamma* condition";
  static constexpr std::array<std::pair<GammaCondition, const char*>, 4> names{
      {{GammaCondition::None, "none"},
       {GammaCondition::Grde, "grde"},
       {GammaCondition::Filter, "filter"},
       {GammaCondition::Coupling, "coupling"}}};
};

// One gamma evaluated by the gamma* search.
struct GammaTrial {
  double gamma = NAN;     // the gamma tried
  bool passed = false;    // no condition failed on [t0, tf]
  double t_escape = NAN;  // failure time (escape, coupling violation, or where a solution too
                          // close to its escape could not be integrated), NaN if passed
  GammaCondition condition = GammaCondition::None;  // what failed; None if passed
  long rhs_evals = 0;  // right-hand sides of the Riccati equations its test evaluated (the
                       // output-feedback search: of the solves that completed; 0 for the
                       // discrete designs, which solve no ODE)
};

// The result of a gamma* search: gamma* (the final bracket's upper end), the bracket, the
// condition that binds, and every gamma tried.
struct GammaStarResult {
  double gamma_star = NAN;  // the upper end of the final bracket: the smallest gamma known to pass
  double lower = NAN;       // final bracket: lower fails (0 when every gamma > 0 passes)
  double upper = NAN;       // final bracket: upper passes (= gamma_star)
  double t_escape_lower = NAN;  // where the lower end fails
  GammaCondition binding = GammaCondition::None;  // the condition that fails at the lower end
  bool converged = false;       // false: max_evaluations reached first
  std::vector<GammaTrial> trials;  // every gamma tried, in the order evaluated
  long rhs_evals = 0;  // the search's cost: the trials' right-hand sides, summed
};

// gamma* of the state-feedback design (trajectory, Q, Qf, horizon).
GammaStarResult gamma_star(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                           const GammaStarOptions& options = {});

// The induced L2 gain of a state-feedback law's closed loop (law_escape_time, riccati.hpp): the
// smallest gamma whose closed-loop Riccati equation has no conjugate point on [t0, tf], found as
// gamma* is (binding Grde). For the H-infinity law at its gamma it lies between gamma* and that
// gamma; the LQR law (a design at gamma = inf) has one too.
GammaStarResult law_gain(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf, const Signal& kappa = Signal(1.0),
                         const GammaStarOptions& options = {});
// The same for any state-feedback controller of the trajectory's model, linearized along it
// (controller_escape_time, riccati.hpp): the ship baselines have one too. The
// gammas are tried one at a time (the controller is called from this thread only).
GammaStarResult controller_gain(const TrajectoryPtr& trajectory, Controller& controller, const Mat& Q, const Mat& Qf,
                                const GammaStarOptions& options = {});

// The smallest gamma for the output-feedback design: no conjugate point of the GRDE, the
// filter Riccati equation (36) with A_e(t) bounded and positive definite from Sigma0, and
// rho(Sigma Z) < gamma^2 on [t0, tf]. binding names the condition that limits it.
GammaStarResult gamma_star_output_feedback(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                                           const Mat& N, const Mat& Sigma0,
                                           const GammaStarOptions& options = {});

// The discrete gamma*_d of the digital design at the sampled linearization's period
// (discrete_design.hpp): the smallest gamma that keeps gamma^2 T I - D_k' M_{k+1} D_k > 0 at every
// sample. binding is Grde (the discrete conjugate point) and t_escape_lower the latest sample
// time where the lower end fails. The recursion is exact: options.solver is not used.
GammaStarResult gamma_star_discrete(const SampledLinearizationPtr& sampled, const Mat& Q, const Mat& Qf,
                                    const GammaStarOptions& options = {});

// The smallest gamma of the digital output feedback (discrete_output_feedback.hpp): the discrete
// game exists (binding Grde), its filter exists from Sigma0 (Filter) and rho(Sigma_k M_k) < gamma^2
// at every sample (Coupling); C, R (the covariance of one measurement) and Sigma0 as for
// solve_discrete_output_feedback. The recursions are exact: options.solver is not used.
GammaStarResult gamma_star_discrete_output_feedback(const SampledLinearizationPtr& sampled, const Mat& Q,
                                                    const Mat& Qf, const Mat& C, const Mat& R, const Mat& Sigma0,
                                                    const GammaStarOptions& options = {});

// The largest value of rho(Sigma(t) Z(t)) on [t0, tf] and where it is taken.
std::pair<double, double> max_rho_sigma_z(const RiccatiSolution& Z, const FilterRiccatiSolution& Sigma);

// The certificates of paper §3 for a design Z and a gain scaling kappa(t).
struct Certificates {
  double m = NAN, M = NAN;  // m I <= Z(t) <= M I on [t0, tf] (eq. 22)
  double kappa_min = NAN;   // min kappa(t); the proof needs kappa >= 1/2
  // Smallest eigenvalue over [t0, tf] of P(t) = Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z:
  // V = q_e' Z q_e has dV/dt = -q_e' P q_e + 2 q_e' Z r(q_e) (eq. 23).
  double p_min = NAN, p_min_t = NAN;  // p_min, and p_min_t the time (s) where it is taken
  // L with |r(q_e)| <= L |q_e|^2, r the remainder of the error dynamics beyond A_e q_e (with
  // state-dependent inputs it includes (G(q) - B_e) u_e; analysis.cpp).
  double remainder_L = NAN;  // the largest L over [t0, tf]
  std::string remainder_method;  // how L was obtained (see Model::remainder_bound)
  bool remainder_is_bound = false;  // false: a sampled estimate, not a proof
  // Radius of eq. (24): with |r| <= L |q_e|^2 and |q_e| < epsilon = min_t p(t) / (4 M L(t)),
  // |r| <= p |q_e| / (4 M), so dV/dt <= -(p/2) |q_e|^2 (exponential decay).
  double epsilon = NAN, epsilon_t = NAN;  // epsilon, and epsilon_t the time (s) of the minimum
  // Initial errors with |q_e(t0)| < epsilon sqrt(m / M) never leave the epsilon-ball (V decays).
  double attraction_radius = NAN;  // a bound on the Euclidean norm |q_e(t0)|
  // V(t) <= V(t0) exp(-decay_rate (t - t0)) inside the ball: decay_rate = p_min / (2 M).
  double decay_rate = NAN;  // in 1/s
};

// The certificates of the design Z (its trajectory and gamma) for the law (17)/(18) with gain
// scaling kappa(t), and Q, the weight of the GRDE (n x n, symmetric positive semidefinite;
// InputError otherwise). L is the model's remainder_bound where it has one, else a sampled
// estimate (remainder_is_bound false).
Certificates certify(const RiccatiSolution& Z, const Signal& kappa, const Mat& Q);

}  // namespace hinf
