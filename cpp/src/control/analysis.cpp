#include "hinf/control/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <random>
#include <system_error>
#include <thread>

#include "hinf/control/discrete_output_feedback.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "numerics/extremum.hpp"
#include "numerics/size_dispatch.hpp"
#include "numerics/symmetric_extremes.hpp"

namespace hinf {

void GammaStarOptions::validate() const {
  require(std::isfinite(lower) && std::isfinite(upper) && lower >= 0.0 && upper >= 0.0,
          "the gamma* bracket must be finite and >= 0, got [", lower, ", ", upper, "]");
  require((lower == 0.0 && upper == 0.0) || upper > lower,
          "the gamma* bracket [", lower, ", ", upper, "] is empty or inverted: give lower < upper (or both 0 to",
          " search automatically)");
  require(std::isfinite(rtol) && rtol > 0.0 && rtol < 1.0, "the gamma* tolerance rtol must be in (0, 1), got ",
          rtol);
  require(max_evaluations >= 2, "max_evaluations must be >= 2, got ", max_evaluations);
  require(threads >= 1, "threads must be >= 1, got ", threads);
  solver.validate();
}

namespace {

using Test = std::function<GammaTrial(double)>;

// Evaluates the test at each gamma, in parallel (one thread each; the first on this thread),
// in order of gamma. When the system cannot create another thread, the remaining gammas run on
// this thread.
std::vector<GammaTrial> evaluate(const Test& test, const std::vector<double>& gammas) {
  std::vector<GammaTrial> results(gammas.size());
  std::vector<std::exception_ptr> errors(gammas.size());
  auto run = [&](std::size_t i) {
    try {
      results[i] = test(gammas[i]);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  std::size_t started = 1;
  for (; started < gammas.size(); ++started) {
    try {
      workers.emplace_back(run, started);
    } catch (const std::system_error&) {
      break;
    }
  }
  run(0);
  for (std::size_t i = started; i < gammas.size(); ++i) run(i);
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return results;
}

// Interior points per k-section round: at most the threads asked for and the hardware's
// threads, and few enough that the rounds needed to shrink the bracket [lower, upper] to
// rtol * upper fit in the evaluations left.
int points_per_round(const GammaStarOptions& o, double lower, double upper, int evaluations_left) {
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int k = std::min(o.threads, hardware);
  const double shrink = std::max(1.0, (upper - lower) / (o.rtol * upper));
  for (; k > 1; --k) {
    const double rounds = std::ceil(std::log(shrink) / std::log(k + 1.0));
    if (rounds * k <= evaluations_left) break;
  }
  return k;
}

GammaStarResult bisect(const Test& test, const GammaStarOptions& o) {
  o.validate();
  GammaStarResult r;
  auto run = [&](const std::vector<double>& gammas) {
    std::vector<GammaTrial> trials = evaluate(test, gammas);
    r.trials.insert(r.trials.end(), trials.begin(), trials.end());
    for (const GammaTrial& t : trials) r.rhs_evals += t.rhs_evals;
    return trials;
  };
  GammaTrial low, high;  // low fails, high passes
  if (o.upper > 0.0) {
    const std::vector<GammaTrial> ends = run(o.lower > 0.0 ? std::vector<double>{o.lower, o.upper}
                                                           : std::vector<double>{o.upper});
    high = ends.back();
    require(high.passed, "gamma = ", o.upper, " (the upper end of the bracket) fails too (", to_string(high.condition),
            " at t = ", high.t_escape, "): raise the upper end");
    if (o.lower > 0.0) {
      low = ends.front();
      require(!low.passed, "gamma = ", o.lower, " (the lower end of the bracket) passes already: gamma* <= ",
              o.lower, "; lower the lower end");
    } else {
      low = GammaTrial{0.0, false, NAN, GammaCondition::None};
    }
  } else {
    // Automatic bracket: from 1, double until a gamma passes or halve until one fails.
    GammaTrial trial = run({1.0}).front();
    if (trial.passed) {
      high = trial;
      for (;;) {
        if (high.gamma < 1e-12) {  // every gamma passes: gamma* = 0 (no gamma-dependent term)
          r.gamma_star = 0.0;
          r.lower = 0.0;
          r.upper = high.gamma;
          r.converged = true;
          return r;
        }
        if (static_cast<int>(r.trials.size()) >= o.max_evaluations) {  // out of evaluations: what is known
          r.gamma_star = r.upper = high.gamma;
          r.lower = 0.0;
          return r;
        }
        trial = run({high.gamma / 2.0}).front();
        if (!trial.passed) break;
        high = trial;
      }
      low = trial;
    } else {
      low = trial;
      for (;;) {
        require(low.gamma < 1e12, "no gamma up to 1e12 passes (", to_string(low.condition), " fails at t = ",
                low.t_escape, ")");
        if (static_cast<int>(r.trials.size()) >= o.max_evaluations)
          throw SolverError(str_cat("gamma*: max_evaluations = ", o.max_evaluations,
                                    " reached while looking for a gamma that passes (every gamma up to ", low.gamma,
                                    " fails: ", to_string(low.condition), " at t = ", low.t_escape,
                                    "); give the bracket's upper end or raise max_evaluations"),
                            low.t_escape, "MAX_EVALUATIONS");
        trial = run({low.gamma * 2.0}).front();
        if (trial.passed) break;
        low = trial;
      }
      high = trial;
    }
  }
  // k-section: k interior points per round, evaluated in parallel.
  const int k = points_per_round(o, low.gamma, high.gamma, o.max_evaluations - static_cast<int>(r.trials.size()));
  while (high.gamma - low.gamma > o.rtol * high.gamma &&
         static_cast<int>(r.trials.size()) + k <= o.max_evaluations) {
    std::vector<double> gammas;
    for (int i = 1; i <= k; ++i) gammas.push_back(low.gamma + (high.gamma - low.gamma) * i / (k + 1));
    for (const GammaTrial& t : run(gammas)) {
      if (t.passed) {
        high = t;
        break;
      }
      low = t;
    }
  }
  r.converged = high.gamma - low.gamma <= o.rtol * high.gamma;
  r.gamma_star = high.gamma;
  r.lower = low.gamma;
  r.upper = high.gamma;
  r.t_escape_lower = low.t_escape;
  r.binding = low.condition;
  return r;
}

GammaTrial fail(double gamma, double t, GammaCondition condition) { return GammaTrial{gamma, false, t, condition}; }
GammaTrial pass(double gamma) { return GammaTrial{gamma, true, NAN, GammaCondition::None}; }
// The trial of an escape test (binding Grde), with its work.
GammaTrial trial(double gamma, const EscapeTest& test) {
  GammaTrial t = std::isnan(test.t_escape) ? pass(gamma) : fail(gamma, test.t_escape, GammaCondition::Grde);
  t.rhs_evals = test.rhs_evals;
  return t;
}

template <int N>
double rho_at(const RiccatiSolution& Z, const FilterRiccatiSolution& Sigma, double t) {
  const int n = Z.n();
  Eigen::Matrix<double, N, N> z(n, n), s(n, n), factor(n, n), product(n, n);
  z = Z.Z(t);
  s = Sigma.Sigma(t);
  return detail::spectral_radius_of_product(s, z, factor, product);
}

std::vector<double> merged_samples(const SymmetricSolution& a, const SymmetricSolution& b) {
  std::vector<double> times = detail::step_samples(a.dense().breakpoints());
  const std::vector<double> more = detail::step_samples(b.dense().breakpoints());
  times.insert(times.end(), more.begin(), more.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

}  // namespace

std::pair<double, double> max_rho_sigma_z(const RiccatiSolution& Z, const FilterRiccatiSolution& Sigma) {
  require(Z.n() == Sigma.n(), "max_rho_sigma_z: Z is ", Z.n(), " x ", Z.n(), " but Sigma is ", Sigma.n(), " x ",
          Sigma.n(), ": pass the GRDE and filter solutions of the same model");
  require(Z.t0() == Sigma.t0() && Z.tf() == Sigma.tf(), "max_rho_sigma_z: Z is on [", Z.t0(), ", ", Z.tf(),
          "] but Sigma on [", Sigma.t0(), ", ", Sigma.tf(), "]: pass solutions of the same horizon");
  const std::vector<double> times = merged_samples(Z, Sigma);
  return detail::with_state_size(Z.n(), [&](auto size) {
    return detail::extremum_over(times, [&](double t) { return rho_at<decltype(size)::value>(Z, Sigma, t); }, -1.0);
  });
}

GammaStarResult gamma_star(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                           const GammaStarOptions& options) {
  require(trajectory != nullptr, "gamma_star needs a trajectory");
  options.validate();
  grde_escape_time(trajectory, Q, Qf, std::numeric_limits<double>::infinity(), options.solver);  // input checks
  return bisect([&](double gamma) {
    return trial(gamma, grde_escape_test(trajectory, Q, Qf, gamma, options.solver));
  }, options);
}

GammaStarResult law_gain(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf, const Signal& kappa,
                         const GammaStarOptions& options) {
  options.validate();
  law_escape_time(law, Q, Qf, std::numeric_limits<double>::infinity(), kappa, options.solver);  // input checks
  return bisect([&](double gamma) {
    return trial(gamma, law_escape_test(law, Q, Qf, gamma, kappa, options.solver));
  }, options);
}

GammaStarResult controller_gain(const TrajectoryPtr& trajectory, Controller& controller, const Mat& Q, const Mat& Qf,
                                const GammaStarOptions& options) {
  options.validate();
  controller_escape_time(trajectory, controller, Q, Qf, std::numeric_limits<double>::infinity(), options.solver);
  // One gamma at a time: the controller keeps lookup state and is called from this thread only.
  GammaStarOptions serial = options;
  serial.threads = 1;
  return bisect([&](double gamma) {
    return trial(gamma, controller_escape_test(trajectory, controller, Q, Qf, gamma, options.solver));
  }, serial);
}

GammaStarResult gamma_star_discrete(const SampledLinearizationPtr& sampled, const Mat& Q, const Mat& Qf,
                                    const GammaStarOptions& options) {
  require(sampled != nullptr, "gamma_star_discrete needs a sampled linearization");
  options.validate();
  discrete_conjugate_time(*sampled, Q, Qf, std::numeric_limits<double>::infinity());  // input checks
  return bisect([&](double gamma) {
    const double t = discrete_conjugate_time(*sampled, Q, Qf, gamma);
    return std::isnan(t) ? pass(gamma) : fail(gamma, t, GammaCondition::Grde);
  }, options);
}

GammaStarResult gamma_star_discrete_output_feedback(const SampledLinearizationPtr& sampled, const Mat& Q,
                                                    const Mat& Qf, const Mat& C, const Mat& R, const Mat& Sigma0,
                                                    const GammaStarOptions& options) {
  require(sampled != nullptr, "gamma_star_discrete_output_feedback needs a sampled linearization");
  options.validate();
  const double inf = std::numeric_limits<double>::infinity();
  solve_discrete_output_feedback(solve_discrete_game(sampled, Q, Qf, inf), C, R, Sigma0, Q);  // input checks
  return bisect([&](double gamma) {
    DiscreteDesignPtr design;
    try {
      design = solve_discrete_game(sampled, Q, Qf, gamma);
    } catch (const ConjugatePointError& e) {
      return fail(gamma, e.t_escape(), GammaCondition::Grde);
    }
    try {
      solve_discrete_output_feedback(design, C, R, Sigma0, Q);
    } catch (const ConjugatePointError& e) {
      return fail(gamma, e.t_escape(), GammaCondition::Filter);
    } catch (const CouplingConditionError& e) {
      return fail(gamma, e.t(), GammaCondition::Coupling);
    }
    return pass(gamma);
  }, options);
}

GammaStarResult gamma_star_output_feedback(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                                           const Mat& N, const Mat& Sigma0, const GammaStarOptions& options) {
  require(trajectory != nullptr, "gamma_star_output_feedback needs a trajectory");
  options.validate();
  const double inf = std::numeric_limits<double>::infinity();
  grde_escape_time(trajectory, Q, Qf, inf, options.solver);             // input checks
  solve_filter_riccati(trajectory, N, Q, inf, Sigma0, options.solver);  // input checks
  return bisect([&](double gamma) {
    RiccatiSolutionPtr Z;
    FilterRiccatiSolutionPtr Sigma;
    try {
      Z = solve_grde(trajectory, Q, Qf, gamma, options.solver);
    } catch (const ConjugatePointError& e) {
      return fail(gamma, e.t_escape(), GammaCondition::Grde);
    } catch (const SolverError& e) {
      // Just above the GRDE's threshold Z is finite but too large to integrate and store:
      // such a gamma cannot be certified, so it fails with "grde" as the binding condition.
      return fail(gamma, e.t(), GammaCondition::Grde);
    }
    // The work counted: the solves that completed.
    auto with_work = [](GammaTrial trial, long rhs_evals) {
      trial.rhs_evals = rhs_evals;
      return trial;
    };
    try {
      Sigma = solve_filter_riccati(trajectory, N, Q, gamma, Sigma0, options.solver);
    } catch (const ConjugatePointError& e) {
      return with_work(fail(gamma, e.t_escape(), GammaCondition::Filter), Z->stats().rhs_evals);
    } catch (const SolverError& e) {
      return with_work(fail(gamma, e.t(), GammaCondition::Filter), Z->stats().rhs_evals);
    }
    const long work = Z->stats().rhs_evals + Sigma->stats().rhs_evals;
    double lo = 0.0, hi = 0.0;
    Sigma->eigenvalue_bounds(lo, hi);
    // Sigma >= 0 may decay to about zero (no process noise); below zero beyond round-off it lost
    // definiteness.
    if (!(lo >= -kSemidefiniteTolerance * std::abs(hi))) return with_work(fail(gamma, NAN, GammaCondition::Filter), work);
    const auto [rho, t] = max_rho_sigma_z(*Z, *Sigma);
    return with_work(rho < gamma * gamma ? pass(gamma) : fail(gamma, t, GammaCondition::Coupling), work);
  }, options);
}

namespace {

// L(t) for the certificate: the model's bound, or a sampled estimate of
// max |r(e)| / |e|^2 over random directions at a few radii (not a bound). r is the remainder of
// the closed loop's error dynamics: with F(q) = f(t, q) + G(t, q) u_d,
//     r(e) = F(q_d + e) - F(q_d) - A_e e + (G(t, q_d + e) - B_e) u_e(e),  u_e = -K e,
// whose last term (the input acting through a state-dependent G) is zero for constant G.
double remainder_estimate(const Model& model, double t, const Vec& q_d, const Vec& u_d, const Mat& K,
                          std::mt19937_64& rng) {
  const int n = model.n();
  const bool state_dependent = model.state_dependent_inputs();
  Mat A(n, n);
  linearize(model, t, q_d, u_d, A);
  const Mat B_e = state_dependent ? model.G(t, q_d) : Mat();
  auto drift = [&](const Vec& q, Vec& out) {
    model.f(t, q, out);
    if (state_dependent) out.noalias() += model.G(t, q) * u_d;
  };
  Vec f0(n), f1(n), e(n), q(n);
  drift(q_d, f0);
  std::normal_distribution<double> normal;
  double worst = 0.0;
  for (double radius : {1e-2, 1e-1, 0.5}) {
    for (int k = 0; k < 32; ++k) {
      for (int i = 0; i < n; ++i) e[i] = normal(rng);
      e *= radius / e.norm();
      q = q_d + e;
      drift(q, f1);
      Vec r = f1 - f0 - A * e;
      if (state_dependent) r.noalias() -= (model.G(t, q) - B_e) * (K * e);
      worst = std::max(worst, r.norm() / (radius * radius));
    }
  }
  return worst;
}

}  // namespace

Certificates certify(const RiccatiSolution& Z, const Signal& kappa, const Mat& Q) {
  const Trajectory& trajectory = Z.trajectory();
  const Model& model = trajectory.model();
  const int n = Z.n();
  check_symmetric_weight(Q, n, "Q", false);
  Certificates c;
  Z.eigenvalue_bounds(c.m, c.M);
  c.kappa_min = kappa.minimum(Z.t0(), Z.tf()).first;
  const double inv_gamma2 = std::isinf(Z.gamma()) ? 0.0 : 1.0 / (Z.gamma() * Z.gamma());
  const std::vector<double> times = detail::step_samples(Z.dense().breakpoints());

  // p(t) = lambda_min(Q + (2 kappa - 1) Z B B' Z + gamma^-2 Z D D' Z), eq. (23).
  auto p_at = [&](double t) {
    const Mat Zt = Z.Z(t), B = trajectory.B_e(t), D = trajectory.D_e(t);
    const Mat ZB = Zt * B, ZD = Zt * D;
    Mat P = Q + (2.0 * kappa(t) - 1.0) * ZB * ZB.transpose() + inv_gamma2 * ZD * ZD.transpose();
    P = 0.5 * (P + P.transpose());
    double lo = 0.0, hi = 0.0;
    detail::symmetric_eigen_extremes(P, lo, hi);
    return lo;
  };
  std::tie(c.p_min, c.p_min_t) = detail::extremum_over(times, p_at, 1.0);

  // L(t) and epsilon = min_t p(t) / (4 M L(t)), eq. (24).
  const Vec q_d0 = trajectory.q_d(Z.t0());
  const bool bounded = !std::isnan(model.remainder_bound(Z.t0(), q_d0, 1.0));
  c.remainder_is_bound = bounded;
  c.remainder_method = bounded ? "the model's remainder_bound (an analytic bound)"
                               : "sampled estimate: max |r(e)| / |e|^2 over random e at radii 0.01, 0.1, 0.5"
                                 " (not a bound)";
  std::mt19937_64 rng(12345);
  auto L_at = [&](double t) {
    const Vec q_d = trajectory.q_d(t);
    if (bounded) return model.remainder_bound(t, q_d, std::numeric_limits<double>::infinity());
    const Mat K = kappa(t) * Z.gain(t);  // u_e = -kappa B_e' Z q_e
    return remainder_estimate(model, t, q_d, trajectory.u_d(t), K, rng);
  };
  c.remainder_L = detail::extremum_over(times, L_at, -1.0).first;
  if (c.p_min > 0.0) {
    auto eps_at = [&](double t) {
      const double L = L_at(t);
      return L > 0.0 ? p_at(t) / (4.0 * c.M * L) : std::numeric_limits<double>::infinity();
    };
    std::tie(c.epsilon, c.epsilon_t) = detail::extremum_over(times, eps_at, 1.0);
    c.attraction_radius = c.m > 0.0 ? c.epsilon * std::sqrt(c.m / c.M) : 0.0;
    c.decay_rate = c.p_min / (2.0 * c.M);
  } else {
    c.epsilon = 0.0;
    c.attraction_radius = 0.0;
    c.decay_rate = 0.0;
  }
  return c;
}

}  // namespace hinf
