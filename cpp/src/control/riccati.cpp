#include "hinf/control/riccati.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include "hinf/control/controller.hpp"

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/resources.hpp"
#include "hinf/numerics/cvode.hpp"
#include "hinf/numerics/stepper.hpp"
#include "control/riccati_kernel.hpp"
#include "numerics/definiteness.hpp"
#include "numerics/extremum.hpp"
#include "numerics/lyapunov_newton.hpp"
#include "numerics/size_dispatch.hpp"
#include "numerics/symmetric_extremes.hpp"

namespace hinf {

PackedBlocks::PackedBlocks(const std::vector<int>& sizes) {
  for (int k : sizes) {
    require(k >= 1, "a block of a symmetric matrix needs at least one row, got ", k);
    start.push_back(n);
    size.push_back(k);
    offset.push_back(dim);
    n += k;
    dim += packed_size(k);
  }
}

bool PackedBlocks::all_of_size(int k) const {
  return std::all_of(size.begin(), size.end(), [k](int s) { return s == k; });
}

void PackedBlocks::pack(const Mat& X, double* stored) const {
  for (int b = 0; b < count(); ++b) pack_symmetric(X.block(start[b], start[b], size[b], size[b]), stored + offset[b]);
}

void PackedBlocks::unpack(const double* stored, Mat& X) const {
  X.setZero(n, n);
  for (int b = 0; b < count(); ++b) {
    const double* block = stored + offset[b];
    for (int j = 0, k = 0; j < size[b]; ++j)
      for (int i = 0; i <= j; ++i, ++k) X(start[b] + i, start[b] + j) = X(start[b] + j, start[b] + i) = block[k];
  }
}

void PackedBlocks::expand(const double* stored, double* packed) const {
  std::fill(packed, packed + packed_size(n), 0.0);
  for (int b = 0; b < count(); ++b) {
    const double* block = stored + offset[b];
    for (int j = 0, k = 0; j < size[b]; ++j)
      for (int i = 0; i <= j; ++i) packed[packed_index(start[b] + i, start[b] + j)] = block[k++];
  }
}

namespace {

enum class RiccatiKind { Control, Filter, ClosedLoop };

// The gain K(t) (m x n) of a state-feedback law u ~ u_d - K(t) (q - q_d) whose closed loop is
// analysed: kappa(t) B_e' Z(t) of a design, or -du/dq of a controller at q_d(t). Writes into a
// matrix of that size.
struct ClosedLoopLaw {
  std::function<void(double t, Mat& K)> gain;
};

// The law u = u_d - kappa(t) B_e' Z(t) (q - q_d) of a design.
ClosedLoopLaw design_law(const RiccatiSolution& design, const Signal& kappa) {
  return {[&design, &kappa, cursor = std::size_t{0}](double t, Mat& K) mutable {
    design.gain(t, K.data(), &cursor);
    K *= kappa(t);
  }};
}

// Any controller, linearized along the trajectory: K(t) = -du/dq at (t, q_d(t)).
ClosedLoopLaw controller_law(const Trajectory& trajectory, Controller& controller) {
  return {[&trajectory, &controller, q_d = Vec(trajectory.n())](double t, Mat& K) mutable {
    trajectory.q_d(t, q_d.data());
    controller.control_jacobian(t, q_d, K);
    K = -K;
  }};
}

// The equation's name in messages.
const char* equation_name(RiccatiKind kind) {
  switch (kind) {
    case RiccatiKind::Control: return "GRDE (13)";
    case RiccatiKind::Filter: return "filter Riccati equation (36)";
    case RiccatiKind::ClosedLoop: return "closed-loop Riccati equation of the law";
  }
  return "";
}

// dX/dt = sign (M(t)' X + X M(t) + R(t) - X S(t) X) along a trajectory:
//   Control (GRDE 13):  sign = -1, M = A_e,  R = Q,    S = B B' - gamma^-2 D D';
//   Filter  (eq. 36):   sign = +1, M = A_e', R = D D', S = C' N^-1 C - gamma^-2 Q;
//   ClosedLoop (a law's induced gain, law_escape_time): sign = -1, M = A_e - B K, R = Q + K'K,
//                       S = -gamma^-2 D D', with K(t) = kappa(t) B_e' Z(t) of the law.
// With shift = c > 0 the unknown is instead W = c (X + c I)^-1 (see escape_time), which obeys a
// Riccati equation of the same form:
//   dW/dt = -sign (M_w' W + W M_w + R_w - W S_w W),
//   M_w = (M + c S)',  R_w = -c S,  S_w = M + M' - R / c + c S.
// N is the state dimension when known at compile time (fixed-size Eigen types), else Dynamic.
// With `blocks` (a PackedBlocks of more than one block) the state holds the blocks of X only.
template <int N>
class RiccatiProblem {
 public:
  using MatN = Eigen::Matrix<double, N, N>;
  using VecN = Eigen::Matrix<double, N, 1>;

  RiccatiProblem(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, double gamma,
                 const Mat& N_inv, const ClosedLoopLaw* law, double shift = 0.0, const PackedBlocks* blocks = nullptr)
      : trajectory_(trajectory), model_(trajectory.model()), kind_(kind), law_(law), shift_(shift), n_(trajectory.n()),
        dim_(blocks ? blocks->dim : packed_size(n_)), blocks_(blocks),
        sign_((kind == RiccatiKind::Filter ? 1.0 : -1.0) * (shift > 0.0 ? -1.0 : 1.0)),
        inv_gamma2_(std::isinf(gamma) ? 0.0 : 1.0 / (gamma * gamma)),
        constant_(model_.constant_input_matrices()), Q_(Q), N_inv_(N_inv) {
    for (auto* M : {&M_, &R_, &S_, &R0_, &S0_, &shifted_, &X_, &A_, &T_, &G_}) M->resize(n_, n_);
    q_d_.resize(n_);
    if (kind_ == RiccatiKind::ClosedLoop) K_.resize(model_.m(), n_);
    if (blocks_) {
      if (blocks_->all_of_size(6)) six_.resize(static_cast<std::size_t>(blocks_->count()));
      else
        for (int k : blocks_->size) any_.emplace_back(k);
    }
    if (constant_) set_input_terms(trajectory.t0(), trajectory.q_d0());
    // R and S of a split GRDE with constant input matrices: its blocks copied once.
    fixed_RS_ = blocks_ && constant_ && shift_ == 0.0;
    if (fixed_RS_) {
      if (!six_.empty()) copy_RS_blocks(six_);
      else copy_RS_blocks(any_);
    }
  }

  int n() const { return n_; }
  // Right-hand sides evaluated so far.
  const long& rhs_evals() const { return rhs_evals_; }
  // The numbers in the integrator's state: packed_size(n), or the blocks' when split.
  int dim() const { return dim_; }
  const PackedBlocks* blocks() const { return blocks_; }

  // X (n x n) to the integrator's state and back.
  void pack(const Mat& X, double* x) const {
    if (blocks_) blocks_->pack(X, x);
    else pack_symmetric(X, x);
  }
  void unpack(const double* x, Mat& X) const {
    if (blocks_) blocks_->unpack(x, X);
    else unpack_symmetric(x, X);
  }
  // A step's dense output as a piece of the whole packed X (itself unless split; the expanded
  // piece lives until the next call).
  DensePiece full_piece(const DensePiece& piece) {
    if (!blocks_) return piece;
    const int p = packed_size(n_);
    const std::size_t needed = static_cast<std::size_t>(piece.degree + 1) * p;
    if (full_piece_.size() < needed) full_piece_.resize(needed);
    for (int j = 0; j <= piece.degree; ++j)
      blocks_->expand(piece.coeffs + static_cast<long>(j) * piece.dim, full_piece_.data() + static_cast<long>(j) * p);
    return {piece.t_start, piece.t_end, piece.degree, p, full_piece_.data()};
  }

  void rhs(double t, const double* x, double* dx) {
    ++rhs_evals_;
    coefficients_at(t);
    if (!blocks_) {
      unpack_symmetric(x, X_);
      detail::riccati_rhs(sign_, M_, R_, S_, X_, T_, G_, dx, diagonal_S_);
    } else if (!six_.empty()) {
      block_rhs(six_, x, dx);
    } else {
      block_rhs(any_, x, dx);
    }
    // One sum tells whether every entry is finite (an overflow of a huge, escaping X also makes
    // it inf: then the model is asked, and only a model that returns non-finite numbers at
    // (t, q_d(t)) is blamed, as the model's InputError instead of a conjugate point).
    double sum = 0.0;
    for (int i = 0; i < dim_; ++i) sum += dx[i];
    if (!std::isfinite(sum)) check_finite_outputs(model_, t, q_d_);
  }

  // M_cl = M - S X of block b (BDF's Newton systems of a split problem).
  void block_closed_loop(double t, const double* x, int b, Mat& M_cl) {
    coefficients_at(t);
    const int s = blocks_->start[b], k = blocks_->size[b];
    Mat X(k, k);
    unpack_symmetric(x + blocks_->offset[b], X);
    M_cl = M_.block(s, s, k, k) - S_.block(s, s, k, k) * X;
  }

  void jacobian(double t, const double* x, double* J) {
    coefficients_at(t);
    unpack_symmetric(x, X_);
    detail::riccati_jacobian(sign_, M_, S_, X_, T_, G_, J);
  }

  // The Jacobian in matrix form: J E = sign (M_cl' E + E M_cl) with M_cl = M - S X.
  double sign() const { return sign_; }
  void closed_loop(double t, const double* x, Mat& M_cl) {
    coefficients_at(t);
    unpack_symmetric(x, X_);
    M_cl = M_ - S_ * X_;
  }

 private:
  // R and S of the equation for X (they depend on t only through B_e, C, D_e), and the parts
  // of the shifted problem that do not depend on A_e. q_d is the desired state at t.
  void set_input_terms(double t, const Vec& q_d) {
    const Mat D = model_.D(t, q_d);
    if (kind_ == RiccatiKind::Control) {
      const Mat B = model_.G(t, q_d);
      R0_ = Q_;
      S0_ = B * B.transpose();
      if (inv_gamma2_ > 0.0) S0_ -= inv_gamma2_ * (D * D.transpose());
    } else if (kind_ == RiccatiKind::ClosedLoop) {
      B_ = model_.G(t, q_d);
      S0_ = -inv_gamma2_ * (D * D.transpose());
      diagonal_S_ = shift_ == 0.0 && detail::is_diagonal(S0_);
      return;  // M and R depend on the law's gain at t: coefficients_at
    } else {
      const Mat C = model_.C(t);
      R0_ = D * D.transpose();
      S0_ = C.transpose() * N_inv_ * C;
      if (inv_gamma2_ > 0.0) S0_ -= inv_gamma2_ * Q_;
    }
    if (shift_ > 0.0) {
      R_ = -shift_ * S0_;
      shifted_ = shift_ * S0_ - R0_ / shift_;  // S_w - (M + M')
      diagonal_S_ = false;
    } else {
      R_ = R0_;
      S_ = S0_;
      diagonal_S_ = detail::is_diagonal(S_);
    }
  }

  void coefficients_at(double t) {
    // Explicit Runge-Kutta stages and Newton iterations often come back to the same t.
    if (t == coefficients_at_) return;
    coefficients_at_ = t;
    trajectory_.q_d(t, q_d_.data(), &cursor_);
    // The GRDE's M is A_e itself: written in place (a split GRDE reads it block by block).
    const bool direct = kind_ == RiccatiKind::Control && shift_ == 0.0;
    trajectory_.A_e(t, q_d_, direct ? M_ : A_);
    if (!constant_) set_input_terms(t, q_d_);
    if (kind_ == RiccatiKind::ClosedLoop) {
      law_->gain(t, K_);
      T_.noalias() = B_ * K_;
      T_ = A_ - T_;  // A_cl
      G_.noalias() = K_.transpose() * K_;
      G_ += Q_;  // Q + K'K
      if (shift_ > 0.0) {
        S_ = T_ + T_.transpose() - G_ / shift_ + shift_ * S0_;
        R_ = -shift_ * S0_;
        T_ += shift_ * S0_;
        M_ = T_.transpose();
      } else {
        M_ = T_;
        R_ = G_;
        S_ = S0_;
      }
      return;
    }
    const bool transpose = kind_ == RiccatiKind::Filter;  // M = A_e (control) or A_e' (filter)
    if (shift_ > 0.0) {
      if (transpose) T_ = A_.transpose();
      else T_ = A_;
      S_ = T_ + T_.transpose() + shifted_;
      T_ += shift_ * S0_;
      M_ = T_.transpose();
    } else if (transpose) {
      M_ = A_.transpose();
    } else if (!direct) {
      M_ = A_;
    }
  }

  // The workspace of one block of a split problem (fixed-size for blocks of 6, the ship's).
  template <int B>
  struct BlockWork {
    using MatB = Eigen::Matrix<double, B, B>;
    explicit BlockWork(int k = B) : M(k, k), R(k, k), S(k, k), X(k, k), T(k, k), G(k, k) {}
    MatB M, R, S, X, T, G;
  };

  template <int B>
  void copy_RS_blocks(std::vector<BlockWork<B>>& work) {
    for (int b = 0; b < blocks_->count(); ++b) {
      const int s = blocks_->start[b], k = blocks_->size[b];
      work[static_cast<std::size_t>(b)].R = R_.block(s, s, k, k);
      work[static_cast<std::size_t>(b)].S = S_.block(s, s, k, k);
    }
  }

  template <int B>
  void block_rhs(std::vector<BlockWork<B>>& work, const double* x, double* dx) {
    if (!fixed_RS_) copy_RS_blocks(work);
    for (int b = 0; b < blocks_->count(); ++b) {
      BlockWork<B>& w = work[static_cast<std::size_t>(b)];
      const int s = blocks_->start[b], k = blocks_->size[b], at = blocks_->offset[b];
      w.M = M_.block(s, s, k, k);
      unpack_symmetric(x + at, w.X);
      detail::riccati_rhs(sign_, w.M, w.R, w.S, w.X, w.T, w.G, dx + at, diagonal_S_);
    }
  }

  const Trajectory& trajectory_;
  const Model& model_;
  RiccatiKind kind_;
  const ClosedLoopLaw* law_;  // ClosedLoop only
  double shift_;
  int n_;
  int dim_;
  const PackedBlocks* blocks_;
  bool fixed_RS_ = false;
  long rhs_evals_ = 0;
  std::vector<BlockWork<6>> six_;
  std::vector<BlockWork<Eigen::Dynamic>> any_;
  std::vector<double> full_piece_;
  double sign_;
  double inv_gamma2_;
  bool constant_;
  bool diagonal_S_ = false;
  Mat Q_, N_inv_;
  std::size_t cursor_ = 0;
  double coefficients_at_ = NAN;  // the t of M_ (and of R_, S_ for time-varying input matrices)
  VecN q_d_;
  MatN M_, R_, S_, R0_, S0_, shifted_, X_, A_, T_, G_;
  Mat B_, K_;  // ClosedLoop: B_e(t) and the law's gain K(t)
};

// BDF's Newton systems of a Riccati problem as Lyapunov equations (lyapunov_newton.hpp).
template <int N>
class RiccatiNewton final : public NewtonSystem {
 public:
  explicit RiccatiNewton(RiccatiProblem<N>& problem) : problem_(problem), lyapunov_(problem.n()) {}
  void refresh(double t, const double* y) override {
    problem_.closed_loop(t, y, M_cl_);
    lyapunov_.factor(M_cl_);
  }
  bool solve(double gamma, const double* b, double* x) override {
    return lyapunov_.solve(gamma * problem_.sign(), b, x);
  }

 private:
  RiccatiProblem<N>& problem_;
  detail::LyapunovNewton lyapunov_;
  Mat M_cl_;
};

// The Newton systems of a split problem: one Lyapunov equation per block.
template <int N>
class BlockRiccatiNewton final : public NewtonSystem {
 public:
  explicit BlockRiccatiNewton(RiccatiProblem<N>& problem) : problem_(problem) {
    for (int k : problem.blocks()->size) lyapunov_.emplace_back(k);
  }
  void refresh(double t, const double* y) override {
    for (int b = 0; b < problem_.blocks()->count(); ++b) {
      problem_.block_closed_loop(t, y, b, M_cl_);
      lyapunov_[static_cast<std::size_t>(b)].factor(M_cl_);
    }
  }
  bool solve(double gamma, const double* b, double* x) override {
    const std::vector<int>& offset = problem_.blocks()->offset;
    for (std::size_t k = 0; k < lyapunov_.size(); ++k)
      if (!lyapunov_[k].solve(gamma * problem_.sign(), b + offset[k], x + offset[k])) return false;
    return true;
  }

 private:
  RiccatiProblem<N>& problem_;
  std::vector<detail::LyapunovNewton> lyapunov_;
  Mat M_cl_;
};

// integrate() of the Riccati problem with its Newton systems solved the cheaper way (a split
// problem: per block); the method used, with the Newton solver of BDF, is in the stats.
template <int N, class OnStep>
StepStats integrate_problem(RiccatiProblem<N>& problem, const SolverOptions& options, double t_start,
                            double t_end, double* x, OnStep&& on_step) {
  const bool split = problem.blocks() != nullptr;
  const bool lyapunov = split || options.newton_systems == NewtonSystems::Lyapunov ||
                        (options.newton_systems == NewtonSystems::Auto && problem.n() > kDenseNewtonMaxStates);
  std::unique_ptr<NewtonSystem> newton;
  if (split) newton = std::make_unique<BlockRiccatiNewton<N>>(problem);
  else if (lyapunov) newton = std::make_unique<RiccatiNewton<N>>(problem);
  StepStats stats = integrate(
      options, problem.dim(), [&problem](double t, const double* y, double* dy) { problem.rhs(t, y, dy); },
      [&problem](double t, const double* y, const double*, double* J) { problem.jacobian(t, y, J); }, t_start,
      t_end, x, on_step, newton.get());
  const std::string newton_kind = lyapunov ? "bdf (Lyapunov Newton)" : "bdf (dense Newton)";
  const std::size_t at = stats.method.find("bdf");
  if (at != std::string::npos) stats.method.replace(at, 3, newton_kind);
  if (split) stats.method += str_cat(" in ", problem.blocks()->count(), " uncoupled blocks");
  return stats;
}

double max_abs(const double* y, int p) {
  double value = 0.0;
  for (int i = 0; i < p; ++i) {
    const double a = std::abs(y[i]);
    if (!(a <= value)) value = a;  // propagates NaN
  }
  return value;
}

double largest_eigenvalue(const Mat& M) {
  return Eigen::SelfAdjointEigenSolver<Mat>(0.5 * (M + M.transpose()), Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

// The integration runs from t_start to t_end: backward from tf for the GRDE, forward from t0
// for the filter.
double start_of(const Trajectory& trajectory, RiccatiKind kind) {
  return kind == RiccatiKind::Filter ? trajectory.t0() : trajectory.tf();
}
double end_of(const Trajectory& trajectory, RiccatiKind kind) {
  return kind == RiccatiKind::Filter ? trajectory.tf() : trajectory.t0();
}

// A scale of X over the horizon: the larger of X_start and the constant term R integrated over
// the time scale of the dynamics, min(horizon, 1 / |A_e(t_start)|_F) (Q for the GRDE, D D' for
// the filter): for a stable system X settles at about R / |A|, for an unstable or slow one it
// grows with the horizon. The escape test's accuracy depends on it: W = c (X + c I)^-1 carries
// X with the relative accuracy of W times (1 + c / x), so c should not exceed X's scale by much.
double solution_scale(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, const ClosedLoopLaw* law,
                      const Mat& X_start) {
  const double t_start = start_of(trajectory, kind);
  const double time_scale = std::min(trajectory.tf() - trajectory.t0(), 1.0 / std::max(trajectory.A_e(t_start).norm(), 1e-300));
  double R_scale = 0.0;
  if (kind == RiccatiKind::Control) {
    R_scale = largest_eigenvalue(Q);
  } else if (kind == RiccatiKind::ClosedLoop) {
    Mat K(trajectory.model().m(), trajectory.n());
    law->gain(t_start, K);
    R_scale = largest_eigenvalue(Q + K.transpose() * K);
  } else {
    const Mat D = trajectory.D_e(t_start);
    R_scale = largest_eigenvalue(D * D.transpose());
  }
  return std::max({largest_eigenvalue(X_start), R_scale * time_scale, std::numeric_limits<double>::min()});
}

// A solve that fails or escapes where the model's linearization is not finite is the model's
// failure: an InputError naming it (check_finite_outputs) instead of a conjugate point.
void blame_model_if_not_finite(const Trajectory& trajectory, std::initializer_list<double> times) {
  for (double t : times)
    if (t >= trajectory.t0() && t <= trajectory.tf()) check_finite_outputs(trajectory.model(), t, trajectory.q_d(t));
}

[[noreturn]] void throw_escape(RiccatiKind kind, double t_escape, double gamma, double t0, double tf,
                               const std::string& detail) {
  if (kind == RiccatiKind::Control)
    throw ConjugatePointError(
        str_cat("conjugate point: Z(t) of the GRDE (13) escapes to infinity at t = ", t_escape,
                " (integrating backward from tf = ", tf, " toward t0 = ", t0, "); gamma = ", gamma,
                " is at or below gamma* for this trajectory, horizon and weights. Increase gamma"
                " (gamma_star() gives the smallest admissible value)",
                detail),
        t_escape, gamma);
  if (kind == RiccatiKind::ClosedLoop)
    throw ConjugatePointError(
        str_cat("the closed-loop Riccati equation of the law escapes to infinity at t = ", t_escape,
                " (integrating backward from tf = ", tf, " toward t0 = ", t0, "); gamma = ", gamma,
                " is at or below the law's induced L2 gain on this horizon (law_gain gives it): the law has no worst"
                " case at this gamma; raise gamma", detail),
        t_escape, gamma);
  throw ConjugatePointError(
      str_cat("the filter Riccati equation (36) escapes to infinity at t = ", t_escape,
              " (integrating forward from t0 = ", t0, " toward tf = ", tf, "); gamma = ", gamma,
              " is too small for this filter. Increase gamma or Q0 - eta I", detail),
      t_escape, gamma);
}

bool is_too_much_work(const SolverError& e) { return e.flag().find("TOO_MUCH_WORK") != std::string::npos; }

// Adds a count to *total when it goes out of scope, also when an escape or a failure is thrown.
struct CountInto {
  const long& count;
  long* total;
  ~CountInto() {
    if (total) *total += count;
  }
};

// Where, between t_from and t_end, does the solution X of the Riccati problem escape to
// infinity (a conjugate point, paper eq. 14)? X_from = X(t_from) is large (or could not be
// integrated further). Returns the first escape time, or NaN if X stays finite up to t_end.
//
// Decided on W = c (X + c I)^-1, c = solution_scale(): while X is finite and X >= 0 (X is
// bounded below by the gamma = inf solution, which is >= 0 for Q, D D' >= 0), W is smooth with
// 0 < W <= I, and W loses positive definiteness exactly where X escapes; W itself passes
// smoothly through the escape. Every accepted step is searched with the certified test of
// definiteness.hpp, which also finds a dip of lambda_min(W) below zero and back within one
// step (a tangential conjugate point just below gamma*). The absolute tolerance of W is set
// relative to its smallest eigenvalue at t_from, c / (lambda_max(X_from) + c), so that a large
// X that keeps growing without escaping (lambda_min(W) -> 0+) is not mistaken for an escape.
template <int N>
double escape_after(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, double gamma, const Mat& N_inv,
                    const ClosedLoopLaw* law, const Mat& X_from, double t_from, double t_end, double c,
                    const SolverOptions& options, const PackedBlocks* blocks, long* rhs_evals) {
  const int n = static_cast<int>(X_from.rows());
  RiccatiProblem<N> problem(trajectory, kind, Q, gamma, N_inv, law, c, blocks);
  const CountInto count{problem.rhs_evals(), rhs_evals};
  const Mat shifted = 0.5 * (X_from + X_from.transpose()) + c * Mat::Identity(n, n);
  const Eigen::LLT<Mat> llt(shifted);
  if (llt.info() != Eigen::Success) return t_from;  // X_from has an eigenvalue <= -c: past an escape
  const Mat W0 = c * llt.solve(Mat::Identity(n, n));
  std::vector<double> w(static_cast<std::size_t>(problem.dim()));
  problem.pack(0.5 * (W0 + W0.transpose()), w.data());
  SolverOptions o = options;
  o.atol = 1e-2 * options.rtol * c / (largest_eigenvalue(X_from) + c);
  detail::DefinitenessSearch<N> search(n);
  double found = NAN;
  try {
    integrate_problem(problem, o, t_from, t_end, w.data(), [&](const DensePiece& piece) {
      const double theta = search.first_loss(problem.full_piece(piece));
      if (std::isnan(theta)) return StepAction::Continue;
      found = piece.time(theta);
      return StepAction::Stop;
    });
  } catch (const SolverError& e) {
    if (is_too_much_work(e))
      throw SolverError(str_cat("the conjugate-point test of the ", equation_name(kind),
                                " could not be completed: ", e.what()),
                        e.t(), e.flag());
    // W is bounded while X is finite and >= 0; it can fail to continue only past an escape of
    // X (where X reaches -c I), between the last accepted step and e.t().
    return e.t();
  }
  return found;
}

// Integrates the Riccati problem over the trajectory's horizon with the chosen method. When
// |X|_max passes escape_norm * solution_scale(), or when the integration fails, escape_after()
// decides from there whether X escapes (ConjugatePointError at the escape time) or is only
// large. With store = true the dense output is kept and a large X that does not escape is
// followed through its peak; with store = false (the escape test) the answer "no escape" ends
// the integration and an empty dense output is returned.
template <int N>
std::pair<PiecewisePolynomial, SolveStats> integrate_riccati(const Trajectory& trajectory, RiccatiKind kind,
                                                             const Mat& Q, double gamma, const Mat& N_inv,
                                                             const ClosedLoopLaw* law, const Mat& X_start,
                                                             const SolverOptions& options, bool store,
                                                             const PackedBlocks* blocks, long* rhs_evals) {
  const int n = static_cast<int>(X_start.rows());
  const double t_start = start_of(trajectory, kind), t_end = end_of(trajectory, kind);
  const double t0 = trajectory.t0(), tf = trajectory.tf();
  RiccatiProblem<N> problem(trajectory, kind, Q, gamma, N_inv, law, 0.0, blocks);
  const CountInto count{problem.rhs_evals(), rhs_evals};
  const int p = problem.dim();
  std::vector<double> x(static_cast<std::size_t>(p));
  problem.pack(X_start, x.data());
  blame_model_if_not_finite(trajectory, {t_start});  // the scale below is taken there
  const double scale = solution_scale(trajectory, kind, Q, law, X_start);
  // atol is meant for solutions of order 1: a smaller solution gets a proportionally smaller one
  // (Qf = 1e-8 I and Q = 4e-5 I with atol = 1e-10 put gamma* 1.5e-5 too high).
  SolverOptions x_options = options;
  x_options.atol = options.atol * std::min(1.0, scale);

  // With gamma = inf, S >= 0 and X cannot escape (it only grows without bound in infinite time).
  const bool can_escape = std::isfinite(gamma);
  bool no_escape = !can_escape;  // established: by the escape test, or because none is possible
  double t_last = t_start;       // the time of x (the last accepted step)
  // Decides from (t_last, x) whether X escapes before t_end; throws ConjugatePointError if so.
  auto decide_escape = [&]() {
    if (no_escape) return;
    Mat X(n, n);
    problem.unpack(x.data(), X);
    const double t_escape =
        escape_after<N>(trajectory, kind, Q, gamma, N_inv, law, X, t_last, t_end, scale, options, blocks, rhs_evals);
    if (!std::isnan(t_escape)) {
      blame_model_if_not_finite(trajectory, {t_last, t_escape});
      throw_escape(kind, t_escape, gamma, t0, tf, "");
    }
    no_escape = true;
  };
  const double limit = options.escape_norm * scale;
  bool large = false;  // X has passed the threshold once
  // Once X is large (and does not escape), it is followed through its peak. A continuation that
  // has taken far more steps than the whole solve before it AND whose pace since then would
  // need more than max_steps to reach t_end (the step size collapsing under the huge X) is
  // stopped as a failure instead of grinding on to max_steps; a large X integrated at a normal
  // pace (a long horizon) is not affected.
  long steps_taken = 0, steps_when_large = 0, step_budget_after_large = 0;
  double t_large = t_start;
  PiecewisePolynomial dense(p);
  StepStats step_stats;
  try {
    step_stats = integrate_problem(problem, x_options, t_start, t_end, x.data(), [&](const DensePiece& piece) {
          const double t = piece.t_end;
          const double largest = max_abs(x.data(), p);
          if (!std::isfinite(largest)) throw SolverError("the solution became non-finite", t, "NOT_FINITE");
          t_last = t;
          ++steps_taken;
          if (store) {
            dense.append(piece);
            if (steps_taken % 1024 == 0)
              check_memory(static_cast<double>(dense.memory_bytes()), "the stored Riccati solution",
                           "loosen the solver tolerances or shorten the horizon");
          }
          if (large && steps_taken > step_budget_after_large) {
            const double steps_since = static_cast<double>(steps_taken - steps_when_large);
            const double pace = std::abs(t - t_large) / steps_since;  // mean step since X became large
            const double projected =
                static_cast<double>(steps_taken) + std::abs(t_end - t) / std::max(pace, 1e-300);
            if (projected > static_cast<double>(options.max_steps))
              throw SolverError(str_cat(steps_taken - steps_when_large,
                                        " steps in the peak of the solution near t = ", t,
                                        " (the step size collapsed: at this pace max_steps = ", options.max_steps,
                                        " would not reach t = ", t_end, ")"),
                                t, "TOO_MUCH_WORK");
          }
          if (large || largest <= limit) return StepAction::Continue;
          decide_escape();
          if (!store) return StepAction::Stop;  // the question "does X escape?" is answered: no
          large = true;
          steps_when_large = steps_taken;
          t_large = t;
          step_budget_after_large = steps_taken + std::max(2000L, 20 * steps_taken);
          return StepAction::Continue;
        });
  } catch (const SolverError& e) {
    blame_model_if_not_finite(trajectory, {t_last, e.t()});
    // A failure may be an escape that the threshold has not caught yet: a step size that
    // collapses, or running out of steps while X grows. Out of steps with a moderate X is only
    // that, and is reported as such.
    const bool growing = max_abs(x.data(), p) > 1e3 * scale;
    if (growing || !is_too_much_work(e)) {
      try {
        decide_escape();
      } catch (const SolverError&) {
        // The escape test could not be completed either: report the solve's own failure.
      }
    }
    std::string cause = e.what();
    while (!cause.empty() && (cause.back() == '.' || cause.back() == ' ')) cause.pop_back();
    std::string advice;
    if (std::isinf(gamma))
      advice = ". The solution grows too large to integrate (gamma = inf): rescale the weights or the model";
    else if (no_escape && (growing || large))
      advice = str_cat(". The solution has no conjugate point (checked on W = c (X + c I)^-1 from t = ", t_last,
                       ") but grows too large to integrate near t = ", e.t(), ": gamma = ", gamma,
                       " is very close to the smallest admissible value; increase it");
    // The escape test covered the rest of the horizon: the question "does X escape?" is answered.
    if (!store && no_escape) return {PiecewisePolynomial(p), SolveStats{}};
    throw SolverError(str_cat(equation_name(kind), store ? " solve failed: " : " conjugate-point test failed: ",
                              cause, advice),
                      e.t(), e.flag());
  }
  dense.finalize();
  SolveStats stats;
  stats.steps = step_stats.steps;
  stats.rejected = step_stats.rejected;
  stats.rhs_evals = step_stats.rhs_evals;
  stats.jac_evals = step_stats.jac_evals;
  stats.memory_bytes = dense.memory_bytes();
  stats.method = step_stats.method;
  return {std::move(dense), stats};
}

// Solves (store = true: keeps the dense output) or only integrates (store = false: enough to
// find escapes) the Riccati problem of `kind` over the trajectory's horizon.
// The blocks a GRDE splits into: the model's uncoupled groups of states, joined where Q or the
// start Qf couple them; one block for the other equations, or when BDF is told to solve its
// Newton systems densely.
std::vector<int> riccati_blocks(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, const Mat& X_start,
                                const SolverOptions& options) {
  const Model& model = trajectory.model();
  const int n = trajectory.n();
  if (kind != RiccatiKind::Control || options.newton_systems == NewtonSystems::Dense) return {n};
  std::vector<int> blocks = model.uncoupled_blocks();
  int total = 0;
  for (int k : blocks) {
    require(k >= 1, "the model '", model.name(), "' gives a group of ", k, " states in uncoupled_blocks()");
    total += k;
  }
  require(total == n, "the model '", model.name(), "' gives uncoupled_blocks() of ", total,
          " states in all; it has n = ", n);
  blocks = merge_coupled_blocks(blocks, Q, Coupling::Entries);
  return merge_coupled_blocks(blocks, X_start, Coupling::Entries);
}

// A solve's dense output in the storage of `blocks` (PackedBlocks), and its counts.
struct Solved {
  PiecewisePolynomial X;
  SolveStats stats;
  std::vector<int> blocks;
};

// rhs_evals: the right-hand sides evaluated are added to it.
Solved solve(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, double gamma, const Mat& N_inv,
             const Mat& X_start, const SolverOptions& options, bool store = true, const ClosedLoopLaw* law = nullptr,
             long* rhs_evals = nullptr) {
  const PackedBlocks blocks(riccati_blocks(trajectory, kind, Q, X_start, options));
  if (blocks.count() > 1) {
    auto [X, stats] = integrate_riccati<Eigen::Dynamic>(trajectory, kind, Q, gamma, N_inv, law, X_start, options,
                                                        store, &blocks, rhs_evals);
    return {std::move(X), stats, blocks.size};
  }
  auto [X, stats] = detail::with_state_size(trajectory.n(), [&](auto size) {
    return integrate_riccati<decltype(size)::value>(trajectory, kind, Q, gamma, N_inv, law, X_start, options, store,
                                                    nullptr, rhs_evals);
  });
  return {std::move(X), stats, {}};
}

// Escape time of an integration without storage, NaN when there is none.
EscapeTest escape_or_nan(const Trajectory& trajectory, RiccatiKind kind, const Mat& Q, double gamma,
                         const Mat& N_inv, const Mat& X_start, const SolverOptions& options,
                         const ClosedLoopLaw* law = nullptr) {
  EscapeTest test;
  if (std::isinf(gamma)) return test;  // S >= 0: no finite escape
  try {
    solve(trajectory, kind, Q, gamma, N_inv, X_start, options, /*store=*/false, law, &test.rhs_evals);
  } catch (const ConjugatePointError& e) {
    test.t_escape = e.t_escape();
  }
  return test;
}

void check_gamma(double gamma) {
  require(!std::isnan(gamma) && gamma > 0.0, "gamma must be > 0 (or inf), got ", gamma);
}

Mat symmetrized(const Mat& M) { return 0.5 * (M + M.transpose()); }

template <int N>
void extremes_over(const SymmetricSolution& X, const std::vector<double>& times, double& lambda_min,
                   double& lambda_max) {
  const int n = X.n();
  std::vector<double> p(static_cast<std::size_t>(packed_size(n)));
  Eigen::Matrix<double, N, N> Xt(n, n);
  std::size_t cursor = 0;
  for (double t : times) {
    X.packed(t, p.data(), &cursor);
    unpack_symmetric(p.data(), Xt);
    double lo = 0.0, hi = 0.0;
    detail::symmetric_eigen_extremes(Xt, lo, hi);
    lambda_min = std::min(lambda_min, lo);
    lambda_max = std::max(lambda_max, hi);
  }
}

template <int N>
void extremes_at(const SymmetricSolution& X, double t, double& lo, double& hi) {
  const int n = X.n();
  PackedScratch packed(n);
  X.packed(t, packed.data());
  Eigen::Matrix<double, N, N> Xt(n, n);
  unpack_symmetric(packed.data(), Xt);
  detail::symmetric_eigen_extremes(Xt, lo, hi);
}

template <int N>
void continuous_bounds(const SymmetricSolution& X, double& lambda_min, double& lambda_max) {
  const std::vector<double> times = detail::step_samples(X.dense().breakpoints());
  auto smallest = [&X](double t) {
    double lo = 0.0, hi = 0.0;
    extremes_at<N>(X, t, lo, hi);
    return lo;
  };
  auto largest = [&X](double t) {
    double lo = 0.0, hi = 0.0;
    extremes_at<N>(X, t, lo, hi);
    return hi;
  };
  lambda_min = detail::extremum_over(times, smallest, 1.0).first;
  lambda_max = detail::extremum_over(times, largest, -1.0).first;
}

}  // namespace

void SymmetricSolution::eigenvalue_bounds(double& lambda_min, double& lambda_max) const {
  detail::with_state_size(n_, [&](auto size) { continuous_bounds<decltype(size)::value>(*this, lambda_min, lambda_max); });
}

SymmetricSolution::SymmetricSolution(TrajectoryPtr trajectory, double gamma, PiecewisePolynomial X,
                                     SolveStats stats, std::vector<int> blocks)
    : trajectory_(std::move(trajectory)), n_(trajectory_->n()), gamma_(gamma), X_(std::move(X)),
      stats_(stats), blocks_(blocks.empty() ? std::vector<int>{n_} : blocks) {
  require(blocks_.n == n_, "a Riccati solution of n = ", n_, " cannot be stored in blocks of ", blocks_.n,
          " states in all");
  require(blocks_.dim == X_.dim(), "a Riccati solution of n = ", n_, " stored in ", blocks_.count(), " block(s) needs ",
          blocks_.dim, " components, got ", X_.dim());
}

Mat SymmetricSolution::value(double t) const { return unpacked(t, false); }

Mat SymmetricSolution::derivative(double t) const { return unpacked(t, true); }

Mat SymmetricSolution::unpacked(double t, bool derivative) const {
  std::vector<double> p(static_cast<std::size_t>(blocks_.dim));
  if (derivative) X_.eval_derivative(t, p.data());
  else X_.eval(t, p.data());
  Mat out(n_, n_);
  blocks_.unpack(p.data(), out);
  return out;
}

void SymmetricSolution::packed(double t, double* out, std::size_t* cursor) const {
  if (blocks_.count() == 1) {
    X_.eval(t, out, cursor);
    return;
  }
  PackedScratch stored(n_);  // blocks_.dim <= packed_size(n_)
  X_.eval(t, stored.data(), cursor);
  blocks_.expand(stored.data(), out);
}

void SymmetricSolution::eigenvalue_range(const std::vector<double>& times, double& lambda_min,
                                         double& lambda_max) const {
  require(!times.empty(), "eigenvalue_range needs at least one time");
  lambda_min = std::numeric_limits<double>::infinity();
  lambda_max = -std::numeric_limits<double>::infinity();
  detail::with_state_size(n_, [&](auto size) { extremes_over<decltype(size)::value>(*this, times, lambda_min, lambda_max); });
}

RiccatiSolution::RiccatiSolution(TrajectoryPtr trajectory, double gamma, PiecewisePolynomial Z,
                                 SolveStats stats, std::vector<int> blocks)
    : SymmetricSolution(std::move(trajectory), gamma, std::move(Z), stats, std::move(blocks)), m_(trajectory_->m()) {
  const Model& model = trajectory_->model();
  constant_B_ = model.constant_input_matrices();
  if (constant_B_) B_ = SparseMatrix(model.G(trajectory_->t0(), trajectory_->q_d0()));
}

Mat RiccatiSolution::gain(double t) const {
  Mat K(m_, n_);
  gain(t, K.data());
  return K;
}

void RiccatiSolution::gain(double t, double* out, std::size_t* cursor) const {
  if (constant_B_) {
    // K(j, c) = sum_i B(i, j) Z(i, c), column-major m x n.
    PackedScratch whole(n_);
    double* z = whole.data();
    packed(t, z, cursor);
    for (int k = 0; k < m_ * n_; ++k) out[k] = 0.0;
    const int n = n_, m = m_;
    B_.for_each([&](int i, int j, double b) {
      for (int c = 0; c < n; ++c) out[j + c * m] += b * z[packed_index(i, c)];
    });
    return;
  }
  Eigen::Map<Mat>(out, m_, n_) = trajectory_->B_e(t).transpose() * Z(t);
}

namespace {

void check_grde_input(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, double gamma,
                      const SolverOptions& options) {
  require(trajectory != nullptr, "the GRDE needs a trajectory");
  const int n = trajectory->n();
  check_symmetric_weight(Q, n, "Q", false);
  check_symmetric_weight(Qf, n, "Qf", true);
  check_gamma(gamma);
  options.validate();
}

// The inverse of N, after the checks of the filter Riccati equation's input.
Mat check_filter_input(const TrajectoryPtr& trajectory, const Mat& N, const Mat& Q, double gamma,
                       const Mat& Sigma0, const SolverOptions& options) {
  require(trajectory != nullptr, "the filter Riccati equation needs a trajectory");
  const Model& model = trajectory->model();
  const int n = trajectory->n();
  const int p = static_cast<int>(model.C(trajectory->t0()).rows());
  check_symmetric_weight(N, p, "N", true);
  check_symmetric_weight(Q, n, "Q", false);
  check_symmetric_weight(Sigma0, n, "Sigma0", true);
  check_gamma(gamma);
  options.validate();
  return symmetrized(N).inverse();
}

}  // namespace

RiccatiSolutionPtr solve_grde(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                              double gamma, const SolverOptions& options) {
  check_grde_input(trajectory, Q, Qf, gamma, options);
  auto [dense, stats, blocks] = solve(*trajectory, RiccatiKind::Control, symmetrized(Q), gamma, Mat(),
                              symmetrized(Qf), options);
  return std::make_shared<const RiccatiSolution>(trajectory, gamma, std::move(dense), stats, blocks);
}


FilterRiccatiSolutionPtr solve_filter_riccati(const TrajectoryPtr& trajectory, const Mat& N,
                                              const Mat& Q, double gamma, const Mat& Sigma0,
                                              const SolverOptions& options) {
  const Mat N_inv = check_filter_input(trajectory, N, Q, gamma, Sigma0, options);
  auto [dense, stats, blocks] = solve(*trajectory, RiccatiKind::Filter, symmetrized(Q), gamma, N_inv,
                              symmetrized(Sigma0), options);
  return std::make_shared<const FilterRiccatiSolution>(trajectory, gamma, std::move(dense), stats, blocks);
}

EscapeTest grde_escape_test(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, double gamma,
                            const SolverOptions& options) {
  check_grde_input(trajectory, Q, Qf, gamma, options);
  return escape_or_nan(*trajectory, RiccatiKind::Control, symmetrized(Q), gamma, Mat(), symmetrized(Qf),
                       options);
}

double grde_escape_time(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf, double gamma,
                        const SolverOptions& options) {
  return grde_escape_test(trajectory, Q, Qf, gamma, options).t_escape;
}

double filter_escape_time(const TrajectoryPtr& trajectory, const Mat& N, const Mat& Q, double gamma,
                          const Mat& Sigma0, const SolverOptions& options) {
  const Mat N_inv = check_filter_input(trajectory, N, Q, gamma, Sigma0, options);
  return escape_or_nan(*trajectory, RiccatiKind::Filter, symmetrized(Q), gamma, N_inv, symmetrized(Sigma0),
                       options)
      .t_escape;
}

namespace {

void check_law_input(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf, double gamma, const Signal& kappa,
                     const SolverOptions& options) {
  require(law != nullptr, "the closed loop of a law needs the law's design (a RiccatiSolution)");
  check_grde_input(law->trajectory_ptr(), Q, Qf, gamma, options);
  for (double t : {law->t0(), law->tf()})
    require(kappa(t) > 0.0, "the law's gain scaling kappa must be > 0, got ", kappa(t), " at t = ", t);
}

}  // namespace

EscapeTest law_escape_test(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf, double gamma,
                           const Signal& kappa, const SolverOptions& options) {
  check_law_input(law, Q, Qf, gamma, kappa, options);
  const ClosedLoopLaw closed = design_law(*law, kappa);
  return escape_or_nan(law->trajectory(), RiccatiKind::ClosedLoop, symmetrized(Q), gamma, Mat(), symmetrized(Qf),
                       options, &closed);
}

double law_escape_time(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf, double gamma, const Signal& kappa,
                       const SolverOptions& options) {
  return law_escape_test(law, Q, Qf, gamma, kappa, options).t_escape;
}

std::shared_ptr<const SymmetricSolution> solve_law_riccati(const RiccatiSolutionPtr& law, const Mat& Q, const Mat& Qf,
                                                           double gamma, const Signal& kappa,
                                                           const SolverOptions& options) {
  check_law_input(law, Q, Qf, gamma, kappa, options);
  const ClosedLoopLaw closed = design_law(*law, kappa);
  auto [dense, stats, blocks] = solve(law->trajectory(), RiccatiKind::ClosedLoop, symmetrized(Q), gamma, Mat(),
                              symmetrized(Qf), options, /*store=*/true, &closed);
  return std::make_shared<const SymmetricSolution>(law->trajectory_ptr(), gamma, std::move(dense), stats, blocks);
}

namespace {

void check_controller_input(const TrajectoryPtr& trajectory, const Controller& controller, const Mat& Q, const Mat& Qf,
                            double gamma, const SolverOptions& options) {
  check_grde_input(trajectory, Q, Qf, gamma, options);
  const Model& model = trajectory->model();
  require((controller.n() == 0 || controller.n() == model.n()) && controller.m() == model.m(), "the ",
          controller.name(), " controller takes q of ", controller.n(), " numbers and gives u of ", controller.m(),
          "; the model '", model.name(), "' has n = ", model.n(), " and m = ", model.m());
}

}  // namespace

EscapeTest controller_escape_test(const TrajectoryPtr& trajectory, Controller& controller, const Mat& Q,
                                  const Mat& Qf, double gamma, const SolverOptions& options) {
  check_controller_input(trajectory, controller, Q, Qf, gamma, options);
  const ClosedLoopLaw closed = controller_law(*trajectory, controller);
  return escape_or_nan(*trajectory, RiccatiKind::ClosedLoop, symmetrized(Q), gamma, Mat(), symmetrized(Qf), options,
                       &closed);
}

double controller_escape_time(const TrajectoryPtr& trajectory, Controller& controller, const Mat& Q, const Mat& Qf,
                              double gamma, const SolverOptions& options) {
  return controller_escape_test(trajectory, controller, Q, Qf, gamma, options).t_escape;
}

std::shared_ptr<const SymmetricSolution> solve_controller_riccati(const TrajectoryPtr& trajectory,
                                                                  Controller& controller, const Mat& Q, const Mat& Qf,
                                                                  double gamma, const SolverOptions& options) {
  check_controller_input(trajectory, controller, Q, Qf, gamma, options);
  const ClosedLoopLaw closed = controller_law(*trajectory, controller);
  auto [dense, stats, blocks] = solve(*trajectory, RiccatiKind::ClosedLoop, symmetrized(Q), gamma, Mat(), symmetrized(Qf),
                              options, /*store=*/true, &closed);
  return std::make_shared<const SymmetricSolution>(trajectory, gamma, std::move(dense), stats, blocks);
}

}  // namespace hinf
