#include "hinf/control/output_feedback.hpp"

#include <cmath>
#include <memory>
#include <random>

#include "hinf/control/controller.hpp"
#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/resources.hpp"
#include "hinf/numerics/cvode.hpp"
#include "hinf/numerics/dopri5.hpp"
#include "hinf/numerics/sdirk4.hpp"
#include "hinf/numerics/sparse_matrix.hpp"
#include "control/riccati_kernel.hpp"
#include "numerics/size_dispatch.hpp"
#include "numerics/symmetric_extremes.hpp"

namespace hinf {

long noise_sample_count(double t0, double tf, double period) {
  check_horizon(t0, tf);
  require(std::isfinite(period) && period > 0.0, "the noise sample period must be > 0, got ", period);
  const double intervals = (tf - t0) / period;
  require(intervals <= 1e12, "the noise would need ", intervals, " samples: use a longer [measurement] sample_period");
  return std::max<long>(1, static_cast<long>(std::ceil(intervals - 1e-9)));
}

RowMat standard_normal_samples(std::uint64_t seed, long count, int channels) {
  require(count >= 0 && channels >= 0, "noise sample counts must be >= 0, got ", count, " x ", channels);
  check_memory(8.0 * static_cast<double>(count) * channels, str_cat(count, " x ", channels, " noise samples"),
               "use a longer [measurement] sample_period (or a shorter horizon)");
  std::mt19937_64 engine(seed);
  // Uniform in (-1, 1) from the top 53 bits; Marsaglia's polar method gives pairs.
  auto uniform = [&engine]() { return 2.0 * static_cast<double>(engine() >> 11) * 0x1.0p-53 - 1.0; };
  RowMat samples(count, channels);
  double* out = samples.data();
  const long total = count * channels;
  for (long i = 0; i < total; i += 2) {
    double a, b, s;
    do {
      a = uniform();
      b = uniform();
      s = a * a + b * b;
    } while (s >= 1.0 || s == 0.0);
    const double factor = std::sqrt(-2.0 * std::log(s) / s);
    out[i] = a * factor;
    if (i + 1 < total) out[i + 1] = b * factor;
  }
  return samples;
}

namespace {

// The closed loop of plant, estimator (35) and filter Riccati (36); state
// x = [q (n), q_hat (n), Sigma (packed, n(n+1)/2)]. The vehicle integrated is `plant`, the
// design model or another of its structure; the estimator and the filter use the design model
// (its error split, G(t, q_d), D(t, q_d), C).
template <int N>
class OutputFeedbackSystem {
 public:
  using MatN = Eigen::Matrix<double, N, N>;
  using VecN = Eigen::Matrix<double, N, 1>;

  OutputFeedbackSystem(const OutputFeedbackProblem& problem, Controller& controller, const Disturbance& disturbance,
                       const OutputFeedbackOptions& options, const Model& plant)
      : grde_(*problem.design), trajectory_(grde_.trajectory()), model_(trajectory_.model()), plant_(plant),
        controller_(controller),
        disturbance_(disturbance), problem_(problem), options_(options), n_(grde_.n()), m_(model_.m()),
        nw_(model_.nw()),
        noise_channels_(model_.noise_channels()), heading_(model_.heading_index()),
        constant_(model_.constant_input_matrices()), state_dependent_(model_.state_dependent_inputs()),
        inv_gamma2_(std::isinf(grde_.gamma()) ? 0.0 : 1.0 / (grde_.gamma() * grde_.gamma())) {
    // The law of this very design (the usual case): u = u_d - kappa B' Z q_hat from the q_d,
    // u_d and Z q_hat already evaluated here, instead of a second lookup of each.
    const auto* law = dynamic_cast<const HinfStateFeedback*>(&controller);
    if (law != nullptr && &law->solution() == &grde_) own_law_ = law;
    for (auto* M : {&Z_, &Sigma_, &A_, &A_f_, &T_, &G_, &DDt_, &S_f_, &gain_lhs_, &CtNinvC_}) M->resize(n_, n_);
    for (auto* v : {&q_d_, &q_hat_, &Zq_, &alpha_, &dq_hat_, &error_, &noise_term_}) v->resize(n_);
    q_estimate_.resize(n_);
    C_ = model_.C(trajectory_.t0());
    p_ = static_cast<int>(C_.rows());
    N_inv_ = problem.N.inverse();
    CtNinv_ = C_.transpose() * N_inv_;
    // The measurement of the heading: the row of C that is the heading's unit row, if any (the
    // ship's C = [0 I3] measures psi in row 2). Its innovation is an angle.
    for (int row = 0; heading_ >= 0 && row < p_; ++row)
      if (C_(row, heading_) == 1.0 && C_.row(row).squaredNorm() == 1.0) heading_row_ = row;
    innovation_.resize(p_);
    u_d_.resize(m_);
    u_.resize(m_);
    u_e_.resize(m_);
    w_.resize(nw_);
    noise_.setZero(p_);
    noise_term_.setZero();
    z_packed_.resize(static_cast<std::size_t>(packed_size(n_)));
    set_matrices(trajectory_.t0(), trajectory_.q_d0());
    if (&plant_ != &model_) {
      // Another vehicle than the design model: its own inputs, and its own measurement matrix
      // if that differs (the same C keeps the innovation C (q - q_d - q_hat) as it is).
      plant_constant_ = plant_.constant_input_matrices();
      if (plant_constant_) {
        const Vec q0 = trajectory_.q_d0();
        plant_G_sparse_ = SparseMatrix(checked_plant_G(trajectory_.t0(), q0));
        plant_D_sparse_ = SparseMatrix(checked_plant_D(trajectory_.t0(), q0));
      }
      const Mat plant_C = plant_.C(trajectory_.t0());
      if (plant_C.rows() != p_ || plant_C.cols() != n_)
        throw InputError(str_cat("the plant '", plant_.name(), "' measures C of shape (", plant_C.rows(), ", ",
                                 plant_C.cols(), "), the design model (", p_, ", ", n_, ")"));
      if (plant_C != C_) plant_C_ = plant_C;
    }
  }

  int n() const { return n_; }
  int p() const { return p_; }
  int dim() const { return 2 * n_ + packed_size(n_); }
  // The noise sample v held now: y = C q + sigma v.
  void set_noise(const double* v) {
    for (int i = 0; i < p_; ++i) noise_[i] = v[i];
    noise_term_.noalias() = problem_.sigma * (CtNinv_ * noise_);  // sigma C' N^-1 v
  }

  void rhs(double t, const double* x, double* dx) {
    evaluate_signals(t, x);
    Eigen::Map<const VecN> q(x, n_);
    Eigen::Map<VecN> dq(dx, n_), dq_hat(dx + n_, n_);
    // Plant, with the control (34) u = u_d - kappa B_e' Z q_hat.
    plant_.f(t, q, dq);
    add_inputs(t, q, dx);
    // Estimator (35); the innovation enters as C' N^-1 (y_e - C q_hat) with
    // y_e - C q_hat = C (q - q_d - q_hat) + sigma v, whose heading component is an angle: it is
    // wrapped after the noise is added (the measured heading is psi + noise, compared with
    // psi_d + psi_hat), so that the estimator never turns the long way round.
    model_.error_split(t, q_d_, u_d_, q_hat_, A_, alpha_);
    error_ = q - q_d_ - q_hat_;
    if (plant_C_.size() > 0) {
      // y = C_plant q + sigma v against the design's C (q_d + q_hat).
      innovation_.noalias() = plant_C_ * q;
      q_estimate_ = q_d_ + q_hat_;
      innovation_.noalias() -= C_ * q_estimate_;
      innovation_ += problem_.sigma * noise_;
      if (heading_row_ >= 0) innovation_[heading_row_] = wrap_angle(innovation_[heading_row_]);
      dq_hat_.noalias() = CtNinv_ * innovation_;
    } else if (heading_row_ >= 0) {
      innovation_.noalias() = C_ * error_;
      innovation_ += problem_.sigma * noise_;
      innovation_[heading_row_] = wrap_angle(innovation_[heading_row_]);
      dq_hat_.noalias() = CtNinv_ * innovation_;
    } else {
      dq_hat_.noalias() = CtNinvC_ * error_;
      dq_hat_ += noise_term_;
    }
    error_.noalias() = Sigma_ * dq_hat_;
    gain_lhs_.setIdentity();
    gain_lhs_.noalias() -= inv_gamma2_ * (Sigma_ * Z_);
    dq_hat = gain_lhs_.partialPivLu().solve(error_);
    dq_hat.noalias() += A_ * q_hat_;
    dq_hat += alpha_;
    // + G (u - u_d) + gamma^-2 D_e D_e' Z q_hat: the control applied and the worst-case
    // disturbance. With state-dependent inputs the control acts through G at the estimated
    // state q_d + q_hat (the error dynamics carry G(t, q) u_e).
    for (int i = 0; i < m_; ++i) u_e_[i] = u_[i] - u_d_[i];
    if (constant_) {
      B_sparse_.add_product(u_e_.data(), dx + n_);
    } else if (state_dependent_) {
      q_estimate_ = q_d_ + q_hat_;
      dq_hat.noalias() += checked_G(t, q_estimate_) * u_e_;
    } else {
      dq_hat.noalias() += B_ * u_e_;
    }
    if (inv_gamma2_ > 0.0) dq_hat.noalias() += inv_gamma2_ * (DDt_ * Zq_);
    // Filter Riccati (36): sign +1, M = A_f', R = D D', S = C' N^-1 C - gamma^-2 Q.
    if (options_.filter_A == FilterLinearization::Estimate) {
      A_f_ = A_.transpose();
    } else {
      trajectory_.A_e(t, q_d_, T_);
      A_f_ = T_.transpose();
    }
    detail::riccati_rhs(1.0, A_f_, DDt_, S_f_, Sigma_, T_, G_, dx + 2 * n_, diagonal_S_f_);
  }

  // rho(Sigma Z) at (t, x).
  double rho(double t, const double* x) {
    evaluate_signals(t, x);
    return rho_of_current();
  }

  // Values on the output grid at (t, x): q_d, u_d, u, w (noise channels included), y and
  // rho(Sigma Z); the extreme eigenvalues of Sigma when sigma_extremes, else NaN.
  void outputs(double t, const double* x, double* q_d, double* u_d, double* u, double* w, double* y,
               bool sigma_extremes, double& sigma_min, double& sigma_max, double& rho) {
    evaluate_signals(t, x);
    for (int i = 0; i < n_; ++i) q_d[i] = q_d_[i];
    for (int i = 0; i < m_; ++i) u_d[i] = u_d_[i];
    for (int i = 0; i < m_; ++i) u[i] = u_[i];
    for (int i = 0; i < nw_; ++i) w[i] = w_[i];
    Eigen::Map<const Vec> q(x, n_);
    Eigen::Map<Vec>(y, p_) = (plant_C_.size() > 0 ? plant_C_ : C_) * q + problem_.sigma * noise_;
    if (heading_row_ >= 0) y[heading_row_] = wrap_angle(y[heading_row_]);  // a measured angle
    sigma_min = sigma_max = NAN;
    if (sigma_extremes) detail::symmetric_eigen_extremes(Sigma_, sigma_min, sigma_max);
    rho = rho_of_current();
  }

  // Whether the Sigma of the last outputs() has a Cholesky factor (is positive definite).
  bool sigma_positive_definite() const { return Eigen::LLT<MatN>(Sigma_).info() == Eigen::Success; }
  // The extreme eigenvalues of the Sigma of the last outputs().
  void sigma_extremes(double& sigma_min, double& sigma_max) const {
    detail::symmetric_eigen_extremes(Sigma_, sigma_min, sigma_max);
  }

 private:
  // rho(Sigma Z) for the Sigma_ and Z_ of the last evaluate_signals.
  double rho_of_current() { return detail::spectral_radius_of_product(Sigma_, Z_, T_, G_); }

  // The design's matrices at t: B_e = G(t, q_d), D_e = D(t, q_d) and what is made of them.
  void set_matrices(double t, const ConstVecRef& q_d) {
    B_ = model_.G(t, q_d);
    D_ = model_.D(t, q_d);
    check_shape(B_, n_, m_, str_cat("G(t, q) at t = ", t, " of the model '", model_.name(), "'"));
    check_shape(D_, n_, nw_, str_cat("D(t, q) at t = ", t, " of the model '", model_.name(), "'"));
    B_sparse_ = SparseMatrix(B_);
    D_sparse_ = SparseMatrix(D_);
    DDt_ = D_ * D_.transpose();
    CtNinvC_ = C_.transpose() * N_inv_ * C_;
    S_f_ = CtNinvC_;
    if (inv_gamma2_ > 0.0) S_f_ -= inv_gamma2_ * problem_.Q;
    diagonal_S_f_ = detail::is_diagonal(S_f_);
  }

  Mat checked_G(double t, const ConstVecRef& q) const {
    Mat G = model_.G(t, q);
    check_shape(G, n_, m_, str_cat("G(t, q) at t = ", t, " of the model '", model_.name(), "'"));
    return G;
  }

  Mat checked_plant_G(double t, const ConstVecRef& q) const {
    Mat G = plant_.G(t, q);
    check_shape(G, n_, m_, str_cat("G(t, q) at t = ", t, " of the plant '", plant_.name(), "'"));
    return G;
  }
  Mat checked_plant_D(double t, const ConstVecRef& q) const {
    Mat D = plant_.D(t, q);
    check_shape(D, n_, nw_, str_cat("D(t, q) at t = ", t, " of the plant '", plant_.name(), "'"));
    return D;
  }

  // dx[0:n] += G(t, q) u + D(t, q) w, the plant's inputs.
  void add_inputs(double t, const ConstVecRef& q, double* dx) {
    if (&plant_ != &model_) {
      if (plant_constant_) {
        plant_G_sparse_.add_product(u_.data(), dx);
        plant_D_sparse_.add_product(w_.data(), dx);
      } else {
        Eigen::Map<Vec>(dx, n_) += checked_plant_G(t, q) * u_ + checked_plant_D(t, q) * w_;
      }
      return;
    }
    if (constant_) {
      B_sparse_.add_product(u_.data(), dx);
      D_sparse_.add_product(w_.data(), dx);
    } else if (state_dependent_) {
      Mat D = model_.D(t, q);
      check_shape(D, n_, nw_, str_cat("D(t, q) at t = ", t, " of the model '", model_.name(), "'"));
      Eigen::Map<Vec>(dx, n_) += checked_G(t, q) * u_ + D * w_;
    } else {
      Eigen::Map<Vec>(dx, n_) += B_ * u_ + D_ * w_;
    }
  }

  // q_d, u_d, Z, Sigma, q_hat, Z q_hat, u and w at (t, x).
  void evaluate_signals(double t, const double* x) {
    // What depends on t alone is kept: Runge-Kutta stages and output times repeat t.
    if (t != signals_at_) {
      signals_at_ = t;
      trajectory_.q_d(t, q_d_.data(), &q_cursor_);
      if (!constant_) set_matrices(t, q_d_);
      trajectory_.u_d(t, u_d_.data());
      grde_.packed(t, z_packed_.data(), &z_cursor_);
      unpack_symmetric(z_packed_.data(), Z_);
    }
    unpack_symmetric(x + 2 * n_, Sigma_);
    for (int i = 0; i < n_; ++i) q_hat_[i] = x[n_ + i];
    Zq_.noalias() = Z_ * q_hat_;
    // The control at the estimated state (for the H-infinity law: u_d - kappa B_e' Z q_hat).
    if (own_law_ != nullptr) {
      const double kappa = own_law_->checked_kappa(t);
      u_.noalias() = u_d_ - kappa * (B_.transpose() * Zq_);
    } else {
      q_estimate_ = q_d_ + q_hat_;
      controller_.control(t, q_estimate_, u_);
    }
    disturbance_.eval(t, x, w_.data());
    // E w = sigma v on the noise channels: w carries v there, or nothing when sigma = 0.
    for (int i = 0; i < p_; ++i)
      w_[noise_channels_[static_cast<std::size_t>(i)]] = problem_.sigma > 0.0 ? noise_[i] : 0.0;
  }

  const RiccatiSolution& grde_;
  const Trajectory& trajectory_;
  const Model& model_;  // the design model
  const Model& plant_;  // the vehicle integrated (may be model_)
  bool plant_constant_ = false;
  SparseMatrix plant_G_sparse_, plant_D_sparse_;  // a plant's constant G and D
  Mat plant_C_;         // a plant's C when it differs from the design model's (else empty)
  Controller& controller_;
  const HinfStateFeedback* own_law_ = nullptr;
  const Disturbance& disturbance_;
  const OutputFeedbackProblem& problem_;
  const OutputFeedbackOptions& options_;
  int n_, m_, nw_, p_ = 0;
  std::vector<int> noise_channels_;
  int heading_;
  bool constant_, state_dependent_;
  double inv_gamma2_;
  bool diagonal_S_f_ = false;
  std::size_t q_cursor_ = 0, z_cursor_ = 0;
  double signals_at_ = NAN;  // the t of q_d_, u_d_ and Z_
  Mat B_, D_, C_, N_inv_, CtNinv_;  // B_e(t), D_e(t) (model.hpp), C, N^-1, C' N^-1
  SparseMatrix B_sparse_, D_sparse_;
  MatN Z_, Sigma_, A_, A_f_, T_, G_, DDt_, S_f_, gain_lhs_, CtNinvC_;
  VecN q_d_, q_hat_, Zq_, alpha_, dq_hat_, error_, noise_term_;
  Vec innovation_;        // y_e - C q_hat (p), heading wrapped
  int heading_row_ = -1;  // the row of C that measures the heading, or -1
  Vec q_estimate_;
  Vec u_d_, u_, u_e_ = Vec(0), w_, noise_;
  std::vector<double> z_packed_;
};

// The cubic Hermite interpolant of a step from (y0, f0) to (y1, f1) of size h as a DensePiece
// (coefficients written into coeffs, 4 * dim numbers).
DensePiece hermite_piece(double t_start, double h, int dim, const double* y0, const double* f0, const double* y1,
                         const double* f1, std::vector<double>& coeffs) {
  coeffs.resize(static_cast<std::size_t>(4 * dim));
  double *c0 = coeffs.data(), *c1 = c0 + dim, *c2 = c1 + dim, *c3 = c2 + dim;
  for (int i = 0; i < dim; ++i) {
    c0[i] = y0[i];
    c1[i] = h * f0[i];
    c2[i] = 3.0 * (y1[i] - y0[i]) - h * (2.0 * f0[i] + f1[i]);
    c3[i] = 2.0 * (y0[i] - y1[i]) + h * (f0[i] + f1[i]);
  }
  return DensePiece{t_start, t_start + h, 3, dim, coeffs.data()};
}

template <int N>
SimulationResult simulate_impl(const OutputFeedbackProblem& problem, Controller& controller,
                               const Disturbance& disturbance, const Vec& q0, const OutputFeedbackOptions& options,
                               const SimulationOptions& simulation, const Model& plant) {
  OutputFeedbackSystem<N> system(problem, controller, disturbance, options, plant);
  const RiccatiSolution& grde = *problem.design;
  const RowMat& noise = problem.noise;
  const SolverOptions& solver = simulation.solver;
  const Trajectory& trajectory = grde.trajectory();
  const Model& model = trajectory.model();
  const int n = system.n(), p = system.p(), dim = system.dim(), m = model.m(), nw = model.nw();
  const double t0 = trajectory.t0(), tf = trajectory.tf(), T = problem.sample_period;
  const long samples = noise_sample_count(t0, tf, T);
  const long count = output_count(t0, tf, simulation.output_dt);
  check_memory(8.0 * static_cast<double>(count) * (4 + 3 * n + 2 * m + nw + p),
               str_cat("the time series on the output grid of ", count, " points"),
               "increase [output] dt (or shorten the horizon)");
  const std::vector<double> grid = output_grid(t0, tf, simulation.output_dt);
  const double gamma2 = grde.gamma() * grde.gamma();
  const double bound = divergence_bound(trajectory, q0, grid, simulation.divergence_factor);
  const int heading = model.heading_index();

  SimulationResult r;
  r.heading_index = heading;
  EstimatorSeries& est = r.estimator.emplace();
  // Sizes every per-output-time series to `rows` (keeping the first rows when `keep`).
  const auto size_series = [&](Eigen::Index rows, bool keep) {
    const auto matrix = [&](RowMat& series, Eigen::Index cols) {
      if (keep) series.conservativeResize(rows, cols);
      else series.resize(rows, cols);
    };
    const auto vector = [&](Vec& series) {
      if (keep) series.conservativeResize(rows);
      else series.resize(rows);
    };
    matrix(r.q, n), matrix(est.q_hat, n), matrix(r.q_d, n), matrix(r.u, m), matrix(r.u_d, m), matrix(r.w, nw);
    matrix(est.y, p);
    vector(est.sigma_min_eig), vector(est.sigma_max_eig), vector(est.rho_sigma_z);
  };
  size_series(count, false);

  auto coupling_error = [&](double t, double rho, const std::string& detail) {
    return CouplingConditionError(
        str_cat("coupling condition violated at t = ", t, ": rho(Sigma Z) = ", rho, " >= gamma^2 = ", gamma2,
                " (paper §4: I - gamma^-2 Sigma Z must stay invertible). Increase gamma, or make Sigma(t0) ="
                " (Q0 - eta I)^-1 smaller (larger Q0 - eta I)",
                detail.empty() ? "; or ask to continue and only flag it" : detail),
        t, rho, grde.gamma());
  };
  // Records output time k from the state x; the noise sample is the one held at grid[k].
  auto record = [&](long k, const double* x) {
    const double t = grid[static_cast<std::size_t>(k)];
    const long sample = std::min(samples - 1, static_cast<long>(std::floor((t - t0) / T + 1e-9)));
    system.set_noise(noise.row(sample).data());
    for (int i = 0; i < n; ++i) {
      r.q(k, i) = x[i];
      est.q_hat(k, i) = x[n + i];
    }
    system.outputs(t, x, r.q_d.row(k).data(), r.u_d.row(k).data(), r.u.row(k).data(), r.w.row(k).data(),
                   est.y.row(k).data(), options.sigma_eigenvalues, est.sigma_min_eig[k], est.sigma_max_eig[k],
                   est.rho_sigma_z[k]);
    const double rho = est.rho_sigma_z[k];
    // Sigma >= 0 may decay to about zero (no process noise); beyond round-off below zero it has
    // lost definiteness. Without the eigenvalue series, a Cholesky factor settles the common
    // case (positive definite: the test passes) and the extremes are computed only otherwise.
    double sigma_min = est.sigma_min_eig[k], sigma_max = est.sigma_max_eig[k];
    const bool known_definite = !options.sigma_eigenvalues && system.sigma_positive_definite();
    if (!options.sigma_eigenvalues && !known_definite) system.sigma_extremes(sigma_min, sigma_max);
    if (!known_definite && !(sigma_min >= -kSemidefiniteTolerance * std::abs(sigma_max)))
      throw SolverError(str_cat("the filter Riccati solution Sigma(t) lost positive definiteness at t = ",
                                t, " (smallest eigenvalue ", sigma_min,
                                "); tighten the solver tolerances or increase gamma"),
                        t, "SIGMA_NOT_POSITIVE_DEFINITE");
    if (!(rho < gamma2) && std::isnan(est.coupling_violation_t)) {
      est.coupling_violation_t = t;
      if (options.on_coupling_violation == CouplingPolicy::Error) throw coupling_error(t, rho, "");
    }
  };

  std::vector<double> x(static_cast<std::size_t>(dim), 0.0);
  for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = q0[i];
  pack_symmetric(problem.Sigma0, x.data() + 2 * n);
  record(0, x.data());
  long next = 1;  // next output time to record
  auto rhs = [&system](double t, const double* y, double* dy) { system.rhs(t, y, dy); };

  auto interval_start = [&](long k) { return t0 + static_cast<double>(k) * T; };
  auto interval_end = [&](long k) {
    return k + 1 == samples ? tf : std::min(tf, t0 + static_cast<double>(k + 1) * T);
  };
  // Steps per hold interval are capped (on top of max_steps for the whole run): a closed loop
  // stuck near a singular estimator gain fails fast instead of spending max_steps.
  const long per_interval = std::min<long>(solver.max_steps, 20000);
  long steps_in_interval = 0;
  std::vector<double> at_grid(static_cast<std::size_t>(dim));
  Vec q_d(n), q_e(n);
  std::size_t q_cursor = 0;
  // After each accepted step of hold interval k (x holds the state at its end): records the
  // output times the step covers, then stops the run if it diverged.
  auto on_step = [&](const DensePiece& piece, long k) {
    const double slack = 1e-12 * std::max(1.0, std::abs(piece.t_end));
    while (next < count && grid[static_cast<std::size_t>(next)] <= piece.t_end + slack) {
      piece.eval(piece.theta(grid[static_cast<std::size_t>(next)]), at_grid.data());
      record(next, at_grid.data());
      system.set_noise(noise.row(k).data());
      ++next;
    }
    if (++steps_in_interval > per_interval)
      throw SolverError(str_cat("more than ", per_interval, " steps in the noise hold interval [", interval_start(k),
                                ", ", interval_end(k), "] (stopped at t = ", piece.t_end, ")"),
                        piece.t_end, "TOO_MUCH_WORK");
    trajectory.q_d(piece.t_end, q_d.data(), &q_cursor);
    tracking_error(n, heading, x.data(), q_d.data(), q_e.data());
    const double error = q_e.cwiseAbs().maxCoeff();
    if (error <= bound) return StepAction::Continue;
    r.status = RunStatus::Diverged;
    r.status_message = str_cat("the tracking error |q - q_d|_inf = ", error, " exceeded the divergence bound ", bound,
                               " at t = ", piece.t_end,
                               ": the closed loop left the neighbourhood of the desired trajectory where the"
                               " linearized design is meaningful (reduce the disturbance or the initial error,"
                               " or raise [solver] divergence_factor)");
    return StepAction::Stop;
  };
  auto add_stats = [&r](const StepStats& s) {
    r.stats.steps += s.steps;
    r.stats.rejected += s.rejected;
    r.stats.rhs_evals += s.rhs_evals;
    r.stats.jac_evals += s.jac_evals;
  };

  try {
    if (solver.method != Method::Adams) {
      // Dormand-Prince per hold interval; for "bdf", a switch to the L-stable SDIRK4 once
      // Dormand-Prince's stiffness test fires.
      Dopri5 explicit_stepper(dim, solver.rtol, solver.atol, solver.max_steps);
      std::unique_ptr<Sdirk4> implicit_stepper;
      std::vector<double> hermite;
      r.integrator = "dormand-prince 5(4) per hold interval";
      for (long k = 0; k < samples && r.status == RunStatus::Completed; ++k) {
        const double ta = interval_start(k), tb = interval_end(k);
        system.set_noise(noise.row(k).data());
        steps_in_interval = 0;
        if (solver.method != Method::ERK && !implicit_stepper && explicit_stepper.stiff()) {
          const StepStats& used = explicit_stepper.stats();
          implicit_stepper = std::make_unique<Sdirk4>(dim, solver.rtol, solver.atol,
                                                      std::max(1L, solver.max_steps - used.steps - used.rejected));
          r.integrator += str_cat(", then SDIRK4 from t = ", ta, " (stiffness detected)");
        }
        if (implicit_stepper) {
          implicit_stepper->integrate(
              rhs, ta, tb, x.data(),
              [&](double ts, double h, const double* y0, const double* f0, const double* y1, const double* f1) {
                return on_step(hermite_piece(ts, h, dim, y0, f0, y1, f1, hermite), k);
              });
        } else {
          explicit_stepper.integrate(rhs, ta, tb, x.data(), [&](const DensePiece& piece) { return on_step(piece, k); });
        }
      }
      add_stats(explicit_stepper.stats());
      if (implicit_stepper) add_stats(implicit_stepper->stats());
    } else {
      // Adams: CVODE restarted at every sample (a multistep method restarts at first order).
      r.integrator = "CVODE Adams restarted per hold interval";
      Cvode cvode(dim, solver.method, solver.rtol, solver.atol, solver.max_steps, rhs);
      for (long k = 0; k < samples && r.status == RunStatus::Completed; ++k) {
        const double ta = interval_start(k), tb = interval_end(k);
        system.set_noise(noise.row(k).data());
        steps_in_interval = 0;
        cvode.reset(ta, x.data(), tb);
        for (double t = ta; t < tb;) {
          t = cvode.step(x.data());
          if (on_step(cvode.last_step_piece(), k) == StepAction::Stop) break;
        }
      }
      r.stats.steps = cvode.num_steps();
      r.stats.rhs_evals = cvode.num_rhs_evals();
      r.stats.rejected = cvode.num_error_test_failures();
    }
  } catch (const SolverError& e) {
    // x holds the last accepted state. Near a coupling violation the estimator gain
    // [I - gamma^-2 Sigma Z]^-1 blows up and the integration stops before the next output time.
    if (!std::isnan(est.coupling_violation_t))
      throw SolverError(str_cat("output-feedback closed loop stopped at t = ", e.t(), " after the coupling condition",
                                " rho(Sigma Z) < gamma^2 was violated at t = ", est.coupling_violation_t,
                                " (flagged): past the violation the estimator gain [I - gamma^-2 Sigma Z]^-1",
                                " becomes singular. Increase gamma or Q0 - eta I. [", e.what(), "]"),
                        e.t(), "COUPLING_VIOLATED");
    const double rho = system.rho(e.t(), x.data());
    if (rho >= (1.0 - 1e-3) * gamma2 && options.on_coupling_violation == CouplingPolicy::Flag)
      throw SolverError(str_cat("output-feedback closed loop stopped at t = ", e.t(), ", where the coupling condition",
                                " rho(Sigma Z) < gamma^2 is violated (flagged; rho(Sigma Z) = ", rho, ", gamma^2 = ",
                                gamma2, "): there the estimator gain [I - gamma^-2 Sigma Z]^-1 is singular and the",
                                " loop cannot go on. Increase gamma or Q0 - eta I. [", e.what(), "]"),
                        e.t(), "COUPLING_VIOLATED");
    if (rho >= (1.0 - 1e-3) * gamma2)
      throw coupling_error(e.t(), rho, str_cat(" (between output times: the integration stopped there, ", e.what(), ")"));
    throw SolverError(str_cat("output-feedback closed loop: ", e.what()), e.t(), e.flag());
  }
  if (r.status == RunStatus::Completed && next != count)
    throw SolverError(str_cat("output-feedback closed loop: ", next, " of ", count,
                              " output times recorded at the end of the horizon"),
                      tf, "INTERNAL");
  if (r.status != RunStatus::Completed) {
    // Keep the output times recorded before the run stopped.
    size_series(next, true);
  }
  r.t = Eigen::Map<const Vec>(grid.data(), next);
  return r;
}

}  // namespace

SimulationResult simulate_output_feedback(const OutputFeedbackProblem& problem, Controller& controller,
                                          const Disturbance& disturbance, const Vec& q0,
                                          const OutputFeedbackOptions& options, const SimulationOptions& simulation,
                                          const Model* plant) {
  require(problem.design != nullptr, "the output-feedback problem needs a design (a GRDE solution)");
  const RiccatiSolution& grde = *problem.design;
  const Trajectory& trajectory = grde.trajectory();
  const Model& model = trajectory.model();
  const Model& vehicle = plant != nullptr ? *plant : model;
  check_plant_sizes(model, vehicle);
  const int n = model.n();
  const Mat C = model.C(trajectory.t0());
  const int p = static_cast<int>(C.rows());
  const std::vector<int> channels = model.noise_channels();
  require(static_cast<int>(channels.size()) == p, "the model '", model.name(), "' measures ", p,
          " outputs but has ", channels.size(), " noise channels");
  for (int c : channels)
    require(c >= 0 && c < model.nw(), "noise channel ", c, " is not a disturbance channel of the model");
  check_size(q0, n, "the initial state q0");
  require(disturbance.dim() == model.nw(), "the disturbance has ", disturbance.dim(),
          " channels, the model '", model.name(), "' has ", model.nw());
  require(std::isfinite(problem.sigma) && problem.sigma >= 0.0, "[measurement] sigma must be >= 0, got ",
          problem.sigma);
  check_symmetric_weight(problem.N, p, "N", true);
  check_symmetric_weight(problem.Sigma0, n, "Sigma0", true);
  check_symmetric_weight(problem.Q, n, "Q", false);
  simulation.validate();
  const long samples = noise_sample_count(trajectory.t0(), trajectory.tf(), problem.sample_period);
  require(problem.noise.rows() == samples && problem.noise.cols() == p, "the noise must have ", samples,
          " rows (one per ", problem.sample_period, " s sample) and ", p, " columns, got (", problem.noise.rows(),
          ", ", problem.noise.cols(), ")");
  check_finite(problem.noise, "noise");
  require(controller.m() == model.m(), "the controller gives ", controller.m(), " inputs, the model has ",
          model.m());
  require(controller.n() == 0 || controller.n() == n, "the controller acts on states of ", controller.n(),
          " numbers, the model '", model.name(), "' has ", n);
  return detail::with_state_size(n, [&](auto size) {
    return simulate_impl<decltype(size)::value>(problem, controller, disturbance, q0, options, simulation, vehicle);
  });
}

}  // namespace hinf
