#include "hinf/riccati.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hinf/checks.hpp"
#include "hinf/cvode.hpp"
#include "hinf/dopri5.hpp"
#include "hinf/errors.hpp"

namespace hinf {

namespace {

// Right-hand side and Jacobian of the GRDE in packed form, dZ/dt = F(t, Z) with
//     F = Z S Z - Z A - A' Z - Q = G + G',   G = Z (S Z / 2 - A) - Q / 2,
//     S = B B' - gamma^-2 D D',
// which needs only two n x n products. N is the state dimension when known at compile time
// (fixed-size Eigen types), Eigen::Dynamic otherwise.
template <int N>
class GrdeKernel {
 public:
  using MatN = Eigen::Matrix<double, N, N>;
  using VecN = Eigen::Matrix<double, N, 1>;

  GrdeKernel(const Trajectory& trajectory, const Mat& Q, double gamma)
      : trajectory_(trajectory), model_(trajectory.model()), n_(trajectory.n()),
        inv_gamma2_(std::isinf(gamma) ? 0.0 : 1.0 / (gamma * gamma)),
        constant_S_(model_.constant_input_matrices()) {
    for (auto* M : {&Q_, &S_, &A_, &Z_, &G_, &T_}) M->resize(n_, n_);
    q_d_.resize(n_);
    Q_ = Q;
    if (constant_S_) S_at(trajectory.t0(), S_);
  }

  void rhs(double t, const double* z, double* dz) {
    linearize(t);
    unpack_symmetric(z, Z_);
    T_.noalias() = S_ * Z_;
    T_ = 0.5 * T_ - A_;
    G_.noalias() = Z_ * T_;
    G_ -= 0.5 * Q_;
    int k = 0;
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i <= j; ++i) dz[k++] = G_(i, j) + G_(j, i);
  }

  // dF/dZ in packed coordinates: for a unit symmetric perturbation E of entry (i, j),
  // dF = E M + M' E = P + P' with P = E M, M = S Z - A.
  void jacobian(double t, const double* z, double* J) {
    linearize(t);
    unpack_symmetric(z, Z_);
    T_.noalias() = S_ * Z_;
    T_ -= A_;  // M
    const int p = packed_size(n_);
    G_.setZero();  // P
    int column = 0;
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i <= j; ++i, ++column) {
        G_.row(i) = T_.row(j);
        if (i != j) G_.row(j) = T_.row(i);
        double* Jc = J + static_cast<std::size_t>(column) * p;
        int row = 0;
        for (int l = 0; l < n_; ++l)
          for (int k = 0; k <= l; ++k) Jc[row++] = G_(k, l) + G_(l, k);
        G_.row(i).setZero();
        G_.row(j).setZero();
      }
  }

 private:
  void S_at(double t, MatN& S) const {
    const Mat B = model_.B(t), D = model_.D(t);
    S = B * B.transpose();
    if (inv_gamma2_ > 0.0) S -= inv_gamma2_ * (D * D.transpose());
  }

  void linearize(double t) {
    trajectory_.q_d(t, q_d_.data(), &cursor_);
    model_.dfdq(t, q_d_, A_);
    if (!constant_S_) S_at(t, S_);
  }

  const Trajectory& trajectory_;
  const Model& model_;
  int n_;
  double inv_gamma2_;
  bool constant_S_;
  std::size_t cursor_ = 0;
  VecN q_d_;
  MatN Q_, S_, A_, Z_, G_, T_;
};

double max_abs(const double* y, int p) {
  double value = 0.0;
  for (int i = 0; i < p; ++i) {
    const double a = std::abs(y[i]);
    if (!(a <= value)) value = a;  // propagates NaN
  }
  return value;
}

double norm2(const double* y, int p) {
  double s = 0.0;
  for (int i = 0; i < p; ++i) s += y[i] * y[i];
  return std::sqrt(s);
}

[[noreturn]] void throw_conjugate_point(double t_escape, double gamma, double t0, double tf,
                                        const std::string& detail) {
  throw ConjugatePointError(
      str_cat("conjugate point: Z(t) of the GRDE escapes to infinity near t = ", t_escape,
              " (integrating backward from tf = ", tf, " toward t0 = ", t0, "); gamma = ", gamma,
              " is at or below gamma* for this trajectory, horizon and weights. Increase gamma"
              " (gamma_star() gives the smallest admissible value)",
              detail),
      t_escape, gamma);
}

template <int N>
RiccatiSolutionPtr solve_impl(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                              double gamma, const SolverOptions& options) {
  GrdeKernel<N> kernel(*trajectory, Q, gamma);
  const int n = trajectory->n();
  const int p = packed_size(n);
  const double t0 = trajectory->t0(), tf = trajectory->tf();
  std::vector<double> z(static_cast<std::size_t>(p)), rate(static_cast<std::size_t>(p));
  pack_symmetric(Qf, z.data());

  auto rhs = [&kernel](double t, const double* y, double* dy) { kernel.rhs(t, y, dy); };
  const double limit = options.escape_norm * std::max(1.0, max_abs(z.data(), p));
  double largest = 0.0;
  // Near a conjugate point Z ~ C / (t - t_c), so |Z| / |dZ/dt| estimates t - t_c.
  auto check_escape = [&](double t, const double* y) {
    largest = max_abs(y, p);
    if (largest <= limit) return;
    kernel.rhs(t, y, rate.data());
    double t_escape = t - norm2(y, p) / norm2(rate.data(), p);
    if (!std::isfinite(t_escape)) t_escape = t;
    throw_conjugate_point(std::clamp(t_escape, t0, t), gamma, t0, tf, "");
  };
  auto on_failure = [&](const SolverError& e) {
    if (largest > std::sqrt(limit))
      throw_conjugate_point(e.t(), gamma, t0, tf, str_cat(" [the integrator stopped: ", e.what(), "]"));
    throw SolverError(str_cat("GRDE backward solve failed: ", e.what()), e.t(), e.flag());
  };

  PiecewisePolynomial dense(p);
  SolveStats stats;
  if (options.method == Method::ERK) {
    Dopri5 stepper(p, options.rtol, options.atol, options.max_steps);
    try {
      stepper.integrate(rhs, tf, t0, z.data(),
                        [&](double t_start, double h, const double* c, const double* y) {
                          dense.append(t_start, h, 4, c);
                          check_escape(t_start + h, y);
                        });
    } catch (const ConjugatePointError&) {
      throw;
    } catch (const SolverError& e) {
      on_failure(e);
    }
    stats.steps = stepper.stats().steps;
    stats.rejected = stepper.stats().rejected;
    stats.rhs_evals = stepper.stats().rhs_evals;
  } else {
    Cvode::Jacobian jacobian = nullptr;
    if (options.method == Method::BDF)
      jacobian = [&kernel](double t, const double* y, const double*, double* J) {
        kernel.jacobian(t, y, J);
      };
    Cvode solver(p, options.method, options.rtol, options.atol, options.max_steps, rhs, jacobian);
    solver.reset(tf, z.data(), t0);
    double t = tf;
    while (t > t0) {
      try {
        t = solver.step(z.data());
      } catch (const SolverError& e) {
        on_failure(e);
      }
      solver.append_last_step(dense);
      check_escape(t, z.data());
    }
    stats.steps = solver.num_steps();
    stats.rejected = solver.num_error_test_failures();
    stats.rhs_evals = solver.num_rhs_evals();
    stats.jac_evals = solver.num_jac_evals();
  }
  dense.finalize();
  stats.memory_bytes = dense.memory_bytes();
  return std::make_shared<const RiccatiSolution>(trajectory, gamma, std::move(dense), stats);
}

}  // namespace

RiccatiSolution::RiccatiSolution(TrajectoryPtr trajectory, double gamma, PiecewisePolynomial Z,
                                 SolveStats stats)
    : trajectory_(std::move(trajectory)), n_(trajectory_->n()), m_(trajectory_->m()),
      gamma_(gamma), Z_(std::move(Z)), stats_(stats) {
  const Model& model = trajectory_->model();
  constant_B_ = model.constant_input_matrices();
  if (constant_B_) {
    const Mat B = model.B(trajectory_->t0());
    for (int j = 0; j < B.cols(); ++j)
      for (int i = 0; i < B.rows(); ++i)
        if (B(i, j) != 0.0) B_nonzeros_.emplace_back(i, j, B(i, j));
  }
}

Mat RiccatiSolution::Z(double t) const {
  std::vector<double> packed(static_cast<std::size_t>(packed_size(n_)));
  Z_.eval(t, packed.data());
  Mat out(n_, n_);
  unpack_symmetric(packed.data(), out);
  return out;
}

Mat RiccatiSolution::dZdt(double t) const {
  std::vector<double> packed(static_cast<std::size_t>(packed_size(n_)));
  Z_.eval_derivative(t, packed.data());
  Mat out(n_, n_);
  unpack_symmetric(packed.data(), out);
  return out;
}

void RiccatiSolution::Z_packed(double t, double* out, std::size_t* cursor) const {
  Z_.eval(t, out, cursor);
}

Mat RiccatiSolution::gain(double t) const {
  Mat K(m_, n_);
  gain(t, K.data());
  return K;
}

void RiccatiSolution::gain(double t, double* out, std::size_t* cursor) const {
  if (constant_B_) {
    // K(j, c) = sum_i B(i, j) Z(i, c), column-major m x n.
    double packed[kMaxPackedOnStack];
    std::vector<double> heap;
    double* z = packed;
    if (packed_size(n_) > kMaxPackedOnStack) {
      heap.resize(static_cast<std::size_t>(packed_size(n_)));
      z = heap.data();
    }
    Z_.eval(t, z, cursor);
    for (int k = 0; k < m_ * n_; ++k) out[k] = 0.0;
    for (const auto& [i, j, b] : B_nonzeros_)
      for (int c = 0; c < n_; ++c) out[j + c * m_] += b * z[packed_index(i, c)];
    return;
  }
  Eigen::Map<Mat>(out, m_, n_) = trajectory_->model().B(t).transpose() * Z(t);
}

void RiccatiSolution::eigenvalue_range(const std::vector<double>& times, double& lambda_min,
                                       double& lambda_max) const {
  lambda_min = std::numeric_limits<double>::infinity();
  lambda_max = -std::numeric_limits<double>::infinity();
  std::vector<double> packed(static_cast<std::size_t>(packed_size(n_)));
  Mat Zt(n_, n_);
  Eigen::SelfAdjointEigenSolver<Mat> eig(n_);
  std::size_t cursor = 0;
  for (double t : times) {
    Z_.eval(t, packed.data(), &cursor);
    unpack_symmetric(packed.data(), Zt);
    eig.compute(Zt, Eigen::EigenvaluesOnly);
    lambda_min = std::min(lambda_min, eig.eigenvalues()(0));
    lambda_max = std::max(lambda_max, eig.eigenvalues()(n_ - 1));
  }
}

RiccatiSolutionPtr solve_grde(const TrajectoryPtr& trajectory, const Mat& Q, const Mat& Qf,
                              double gamma, const SolverOptions& options) {
  require(trajectory != nullptr, "solve_grde needs a trajectory");
  const int n = trajectory->n();
  check_symmetric_weight(Q, n, "Q", false);
  check_symmetric_weight(Qf, n, "Qf", true);
  require(!std::isnan(gamma) && gamma > 0.0, "gamma must be > 0 (or inf for LQR), got ", gamma);
  options.validate();
  const Mat Q_sym = 0.5 * (Q + Q.transpose());
  const Mat Qf_sym = 0.5 * (Qf + Qf.transpose());
  if (n == 6) return solve_impl<6>(trajectory, Q_sym, Qf_sym, gamma, options);
  return solve_impl<Eigen::Dynamic>(trajectory, Q_sym, Qf_sym, gamma, options);
}

}  // namespace hinf
