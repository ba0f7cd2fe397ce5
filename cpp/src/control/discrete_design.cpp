#include "hinf/control/discrete_design.hpp"

#include <cmath>
#include <limits>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "hinf/core/resources.hpp"

namespace hinf {

int sample_count(double t0, double tf, double period) {
  require(std::isfinite(period) && period > 0.0, "the sample period T must be finite and > 0, got ", period);
  const double ratio = (tf - t0) / period;
  require(ratio >= 1.0 - 1e-9, "the sample period T = ", period, " s is longer than the horizon [", t0, ", ", tf,
          "]: choose a shorter period or a longer horizon");
  require(ratio <= 1e8, "the horizon [", t0, ", ", tf, "] holds ", ratio,
          " samples of T = ", period, " s: choose a longer period");
  return static_cast<int>(std::floor(ratio + 1e-9));
}

namespace {

// The right-hand side of the variational equations, X = [Phi | G_B | G_D]:
//     dX/dt = A_e(t) X + [0 | B_e(t) | D_e(t)].
class Variational {
 public:
  explicit Variational(const Trajectory& trajectory)
      : trajectory_(trajectory), n_(trajectory.n()), m_(trajectory.m()), nw_(trajectory.model().nw()) {}

  int cols() const { return n_ + m_ + nw_; }
  void operator()(double t, const Mat& X, Mat& dX) const {
    dX.noalias() = trajectory_.A_e(t) * X;
    dX.middleCols(n_, m_) += trajectory_.B_e(t);
    dX.rightCols(nw_) += trajectory_.D_e(t);
  }

 private:
  const Trajectory& trajectory_;
  int n_, m_, nw_;
};

void check_game_input(const SampledLinearization& sampled, const Mat& Q, const Mat& Qf, double gamma) {
  const int n = sampled.trajectory().n();
  check_symmetric_weight(Q, n, "Q", false);
  check_symmetric_weight(Qf, n, "Qf", true);
  require(!std::isnan(gamma) && gamma > 0.0, "gamma must be > 0 (or inf), got ", gamma);
}

// The game Riccati difference equation backward from M_N = Qf (see the header). With store, M_k,
// F_k and W_k are kept; the return value is the latest t_k at which the existence condition
// fails (the recursion stops there), or NaN.
double recursion(const SampledLinearization& sampled, const Mat& Q, const Mat& Qf, double gamma, bool store,
                 std::vector<Mat>* M_out, std::vector<Mat>* F_out, std::vector<Mat>* W_out) {
  const int n = sampled.trajectory().n();
  const int N = sampled.steps();
  const double T = sampled.period();
  const double inv_gamma2 = std::isinf(gamma) ? 0.0 : 1.0 / (gamma * gamma);
  const Mat I = Mat::Identity(n, n);
  Mat M = Qf, S(n, n), X(n, n), XA(n, n);
  if (store) {
    M_out->assign(static_cast<std::size_t>(N) + 1, Mat());
    F_out->assign(static_cast<std::size_t>(N), Mat());
    W_out->assign(static_cast<std::size_t>(N), Mat());
    M_out->back() = M;
  }
  for (int k = N - 1; k >= 0; --k) {
    const Mat& A = sampled.A(k);
    const Mat& B = sampled.B(k);
    const Mat& D = sampled.D(k);
    if (inv_gamma2 > 0.0) {
      // gamma^2 T I - D' M D > 0: the game is concave in w_k.
      const Mat E = gamma * gamma * T * Mat::Identity(D.cols(), D.cols()) - D.transpose() * M * D;
      Eigen::LLT<Mat> llt(E);
      if (llt.info() != Eigen::Success) return sampled.time(k);
    }
    S.noalias() = (B * B.transpose() - inv_gamma2 * (D * D.transpose())) / T;
    // X = M Lambda^-1 = (Lambda^-T M)' with Lambda' = I + M S (M and S symmetric).
    X = (I + M * S).partialPivLu().solve(M).transpose();
    XA.noalias() = X * A;
    M.noalias() = A.transpose() * XA;
    M += T * Q;
    M = 0.5 * (M + M.transpose()).eval();
    if (!M.allFinite()) return sampled.time(k);
    if (store) {
      (*M_out)[static_cast<std::size_t>(k)] = M;
      (*F_out)[static_cast<std::size_t>(k)] = B.transpose() * XA / T;
      (*W_out)[static_cast<std::size_t>(k)] = inv_gamma2 * (D.transpose() * XA) / T;
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

SampledLinearization::SampledLinearization(TrajectoryPtr trajectory, double period)
    : trajectory_(std::move(trajectory)), period_(period) {
  require(trajectory_ != nullptr, "the sampled linearization needs a trajectory");
  const int N = sample_count(trajectory_->t0(), trajectory_->tf(), period);
  const int n = trajectory_->n(), m = trajectory_->m(), nw = trajectory_->model().nw();
  check_memory(8.0 * N * n * (n + m + nw), str_cat(N, " sampled linearizations"),
               "choose a longer sample period (or a shorter horizon)");
  const Variational rhs(*trajectory_);
  const int substeps = std::max(2, static_cast<int>(std::ceil(period / kMaxSubstep - 1e-9)));
  const double h = period / substeps;
  A_.reserve(static_cast<std::size_t>(N));
  B_.reserve(static_cast<std::size_t>(N));
  D_.reserve(static_cast<std::size_t>(N));
  Mat X(n, rhs.cols()), k1(n, rhs.cols()), k2(n, rhs.cols()), k3(n, rhs.cols()), k4(n, rhs.cols());
  for (int k = 0; k < N; ++k) {
    X.setZero();
    X.leftCols(n).setIdentity();
    const double tk = time(k);
    for (int s = 0; s < substeps; ++s) {
      // Times from t_k by multiples of h, so the last substep ends at t_k + T up to round-off.
      const double t = tk + s * h, t_mid = tk + (s + 0.5) * h, t_end = s + 1 == substeps ? tk + period : tk + (s + 1) * h;
      const double dt = t_end - t;
      rhs(t, X, k1);
      rhs(t_mid, X + 0.5 * dt * k1, k2);
      rhs(t_mid, X + 0.5 * dt * k2, k3);
      rhs(t_end, X + dt * k3, k4);
      X += (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    A_.push_back(X.leftCols(n));
    B_.push_back(X.middleCols(n, m));
    D_.push_back(X.rightCols(nw));
  }
}

DiscreteDesign::DiscreteDesign(SampledLinearizationPtr sampled, double gamma, std::vector<Mat> M,
                               std::vector<Mat> F, std::vector<Mat> W)
    : sampled_(std::move(sampled)), gamma_(gamma), M_(std::move(M)), F_(std::move(F)), W_(std::move(W)) {
  require(sampled_ != nullptr, "a discrete design needs its sampled linearization");
  const auto N = static_cast<std::size_t>(sampled_->steps());
  require(M_.size() == N + 1 && F_.size() == N && W_.size() == N, "a discrete design of ", N,
          " samples needs ", N + 1, " matrices M_k and ", N, " gains, got ", M_.size(), " and ", F_.size());
}

const Mat& DiscreteDesign::M(int k) const {
  require(k >= 0 && k <= steps(), "M_k is defined for k = 0 .. ", steps(), ", got k = ", k);
  return M_[static_cast<std::size_t>(k)];
}

const Mat& DiscreteDesign::gain(int k) const {
  require(k >= 0 && k < steps(), "the gain F_k is defined for k = 0 .. ", steps() - 1, ", got k = ", k);
  return F_[static_cast<std::size_t>(k)];
}

const Mat& DiscreteDesign::worst_case_gain(int k) const {
  require(k >= 0 && k < steps(), "the worst-case gain W_k is defined for k = 0 .. ", steps() - 1, ", got k = ", k);
  return W_[static_cast<std::size_t>(k)];
}

int DiscreteDesign::sample_index(double t) const {
  const double T = period();
  const double position = (t - time(0)) / T;
  require(std::isfinite(position) && position >= -1e-9 && position < steps() - 1e-9, "t = ", t,
          " is outside the discrete design's samples [", time(0), ", ", time(steps()), ")");
  return std::max(0, static_cast<int>(std::floor(position + 1e-9)));
}

DiscreteDesignPtr solve_discrete_game(const SampledLinearizationPtr& sampled, const Mat& Q, const Mat& Qf,
                                      double gamma) {
  require(sampled != nullptr, "the discrete game needs a sampled linearization");
  check_game_input(*sampled, Q, Qf, gamma);
  std::vector<Mat> M, F, W;
  const double t_fail = recursion(*sampled, Q, Qf, gamma, true, &M, &F, &W);
  if (!std::isnan(t_fail)) {
    const int k = static_cast<int>(std::lround((t_fail - sampled->time(0)) / sampled->period()));
    throw ConjugatePointError(
        str_cat("discrete conjugate point: gamma^2 T I - D_k' M_{k+1} D_k is not positive definite at k = ", k,
                " (t = ", t_fail, ", T = ", sampled->period(), " s); gamma = ", gamma,
                " is at or below the discrete gamma* for this trajectory, period, horizon and weights. Increase"
                " gamma (gamma_star_discrete() gives the smallest admissible value)"),
        t_fail, gamma);
  }
  return std::make_shared<const DiscreteDesign>(sampled, gamma, std::move(M), std::move(F), std::move(W));
}

DiscreteDesignPtr solve_discrete_game(const TrajectoryPtr& trajectory, double period, const Mat& Q, const Mat& Qf,
                                      double gamma) {
  require(trajectory != nullptr, "the discrete game needs a trajectory");
  return solve_discrete_game(std::make_shared<const SampledLinearization>(trajectory, period), Q, Qf, gamma);
}

double discrete_conjugate_time(const SampledLinearization& sampled, const Mat& Q, const Mat& Qf, double gamma) {
  check_game_input(sampled, Q, Qf, gamma);
  return recursion(sampled, Q, Qf, gamma, false, nullptr, nullptr, nullptr);
}

}  // namespace hinf
