#include "hinf/control/receding_horizon.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Eigenvalues>

#include "hinf/control/controller.hpp"
#include "hinf/core/angles.hpp"
#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "control/run_series.hpp"

namespace hinf {

void RecedingHorizonOptions::validate() const {
  require(std::isfinite(window) && window > 0.0, "the receding horizon's window must be a finite number of seconds > 0, got ",
          window);
  require(std::isfinite(update) && update > 0.0 && update <= window,
          "the receding horizon's update period must be in (0, window] = (0, ", window, "] s, got ", update);
}

std::size_t HorizonWindow::memory_bytes() const {
  return (trajectory ? trajectory->dense().memory_bytes() : 0) + (design ? design->dense().memory_bytes() : 0);
}

RecedingHorizon::RecedingHorizon(ModelPtr model, Vec q_d0, VectorSignal u_d, double t0, Mat Q, Mat Qf, double gamma,
                                 RecedingHorizonOptions options, SolverOptions solver, TrajectoryOptions trajectory)
    : model_(std::move(model)),
      q_d0_(std::move(q_d0)),
      u_d_(std::move(u_d)),
      t0_(t0),
      Q_(std::move(Q)),
      Qf_(std::move(Qf)),
      gamma_(gamma),
      options_(options),
      solver_(solver),
      trajectory_options_(trajectory) {
  require(model_ != nullptr, "the receding horizon needs a model");
  require(std::isfinite(t0_), "the receding horizon's t0 must be finite, got ", t0_);
  options_.validate();
  solver_.validate();
  const int n = model_->n();
  check_size(q_d0_, n, "the desired initial state q_d0");
  check_symmetric_weight(Q_, n, "Q", false);
  check_symmetric_weight(Qf_, n, "Qf", true);
  require(gamma_ > 0.0, "gamma must be > 0 (may be inf), got ", gamma_);
}

namespace {

// The first node's state of a desired trajectory given as states, after the checks of
// Trajectory's states form (trajectory.hpp), made before anything is integrated.
Vec first_node(const ModelPtr& model, const std::vector<double>& t_nodes, const RowMat& q_nodes) {
  require(model != nullptr, "the receding horizon needs a model");
  require(t_nodes.size() >= 2, "a desired trajectory given as states needs at least two nodes, got ", t_nodes.size());
  for (std::size_t k = 0; k < t_nodes.size(); ++k)
    require(std::isfinite(t_nodes[k]) && (k == 0 || t_nodes[k] > t_nodes[k - 1]),
            "the node times must be finite and increasing: node ", k, " is not");
  require(q_nodes.rows() == static_cast<Eigen::Index>(t_nodes.size()) && q_nodes.cols() == model->n() &&
              q_nodes.allFinite(),
          "the node states need one finite row of ", model->n(), " numbers per node time (", t_nodes.size(), " x ",
          model->n(), "), got ", q_nodes.rows(), " x ", q_nodes.cols());
  return q_nodes.row(0).transpose();
}

}  // namespace

RecedingHorizon::RecedingHorizon(ModelPtr model, std::vector<double> t_nodes, RowMat q_nodes, VectorSignal u_d,
                                 Mat Q, Mat Qf, double gamma, RecedingHorizonOptions options, SolverOptions solver,
                                 TrajectoryOptions trajectory)
    : RecedingHorizon(model, first_node(model, t_nodes, q_nodes), std::move(u_d), t_nodes.empty() ? 0.0 : t_nodes[0],
                      std::move(Q), std::move(Qf), gamma, options, solver, trajectory) {
  node_t_ = std::move(t_nodes);
  node_q_ = std::move(q_nodes);
}

int RecedingHorizon::window_at(double t) const {
  require(std::isfinite(t) && t >= t0_, "t = ", t, " is before the receding horizon's t0 = ", t0_);
  const double position = (t - t0_) / options_.update;
  require(position < 2e9, "t = ", t, " is more than 2e9 update periods after t0");
  return static_cast<int>(std::floor(position + 1e-9));
}

std::shared_ptr<const RecedingHorizon> RecedingHorizon::with_path_change(double t_join, VectorSignal u_d) const {
  require(std::isfinite(t_join) && t_join > t0_, "a path change joins after t0 = ", t0_, " s, got t_join = ", t_join);
  const int j = window_at(t_join);
  require(std::abs(window_start(j) - t_join) <= 1e-9 * std::max(1.0, std::abs(t_join)),
          "a path change joins at a window's start t0 + j * update (update = ", options_.update, " s), got t_join = ",
          t_join, " (the nearest: ", window_start(j), " s)");
  require(changes_.empty() || t_join > changes_.back().first, "a path change joins after the last one (at ",
          changes_.empty() ? t0_ : changes_.back().first, " s), got t_join = ", t_join);
  require(u_d.dim() == model_->m(), "the new path's u_d has ", u_d.dim(), " channels, the model '", model_->name(),
          "' has ", model_->m(), " inputs");
  auto changed = std::make_shared<RecedingHorizon>(*this);
  changed->changes_.emplace_back(window_start(j), std::move(u_d));
  return changed;
}

const VectorSignal& RecedingHorizon::window_inputs(int j) const {
  const double t = window_start(j) + 1e-9 * options_.update;
  for (auto it = changes_.rbegin(); it != changes_.rend(); ++it)
    if (it->first <= t) return it->second;
  return u_d_;
}

TrajectoryPtr RecedingHorizon::states_trajectory(double t_a, const Vec& q_a, double t_b, const VectorSignal& u) const {
  // Nodes within this distance of t_a or t_b are those ends (a window's start on a node).
  const double near = 1e-9 * options_.update;
  std::vector<double> t{t_a};
  std::vector<Eigen::Index> rows;
  Vec start = q_a;
  const auto first = std::upper_bound(node_t_.begin(), node_t_.end(), t_a - near);
  if (first != node_t_.end() && *first <= t_a + near) start = node_q_.row(first - node_t_.begin()).transpose();
  for (auto it = first; it != node_t_.end() && *it < t_b - near; ++it)
    if (*it > t_a + near) {
      t.push_back(*it);
      rows.push_back(it - node_t_.begin());
    }
  // The end: the node there, or the integration from the last node before it (the last
  // interval's defect is then zero).
  const auto end = std::lower_bound(node_t_.begin(), node_t_.end(), t_b - near);
  Vec last;
  if (end != node_t_.end() && *end <= t_b + near) {
    last = node_q_.row(end - node_t_.begin()).transpose();
  } else {
    const Vec from = rows.empty() ? start : Vec(node_q_.row(rows.back()).transpose());
    last = Trajectory(model_, from, u, t.back(), t_b, trajectory_options_).q_d(t_b);
  }
  t.push_back(t_b);
  RowMat q(static_cast<Eigen::Index>(t.size()), n());
  q.row(0) = start.transpose();
  for (std::size_t k = 0; k < rows.size(); ++k) q.row(static_cast<Eigen::Index>(k + 1)) = node_q_.row(rows[k]);
  q.row(q.rows() - 1) = last.transpose();
  return std::make_shared<const Trajectory>(model_, std::move(t), q, u, trajectory_options_);
}

TrajectoryPtr RecedingHorizon::window_trajectory(int j, const Vec& q_d_start) const {
  require(j >= 0, "a receding-horizon window's index must be >= 0, got ", j);
  check_size(q_d_start, n(), str_cat("the desired state at the start of window ", j));
  const double t_start = window_start(j), t_end = t_start + options_.window;
  // The states hold for the path they were given with: until the first path change.
  const bool on_states = !node_t_.empty() && (changes_.empty() || window_start(j) < changes_.front().first -
                                                                      1e-9 * options_.update);
  if (on_states) return states_trajectory(t_start, q_d_start, t_end, window_inputs(j));
  return std::make_shared<const Trajectory>(model_, q_d_start, window_inputs(j), t_start, t_end, trajectory_options_);
}

Mat RecedingHorizon::terminal_weight(int j, const Trajectory& window) const {
  if (options_.terminal == TerminalWeight::Qf) return Qf_;
  const double t_end = window.tf();
  const std::string where = str_cat("receding-horizon window ", j, ": the stationary terminal weight at t = ", t_end,
                                    " s: ");
  Mat P;
  try {
    P = solve_game_are(window.A_e(t_end), window.B_e(t_end), window.D_e(t_end), Q_, gamma_);
  } catch (const InputError& e) {
    throw InputError(str_cat(where, e.what(), "; or use the terminal weight Qf (terminal = \"qf\")"));
  }
  // solve_grde needs a definite weight: a mode Q leaves unweighted and that needs no control
  // gives P a zero eigenvalue.
  const double smallest = Eigen::SelfAdjointEigenSolver<Mat>(P, Eigen::EigenvaluesOnly).eigenvalues()(0);
  require(smallest > 1e-12 * std::max(1.0, P.norm()), where, "the game ARE's solution is only semidefinite (smallest"
          " eigenvalue ", smallest, "): weight every state in Q, or use the terminal weight Qf (terminal = \"qf\")");
  return P;
}

Vec RecedingHorizon::desired_state(double t) const {
  const int last = window_at(t);
  Vec q = q_d0_;
  for (int j = 0; j < last; ++j) q = window_trajectory(j, q)->q_d(window_start(j + 1));
  return last == 0 && t == t0_ ? q : window_trajectory(last, q)->q_d(t);
}

TrajectoryPtr RecedingHorizon::reference(double tf) const {
  check_horizon(t0_, tf);
  if (changes_.empty() && !node_t_.empty()) return states_trajectory(t0_, q_d0_, tf, u_d_);
  if (changes_.empty()) return std::make_shared<const Trajectory>(model_, q_d0_, u_d_, t0_, tf, trajectory_options_);
  std::vector<double> t_nodes;
  std::vector<Vec> q_nodes;
  Vec q = q_d0_;
  for (int j = 0; window_start(j) < tf; ++j) {
    t_nodes.push_back(window_start(j));
    q_nodes.push_back(q);
    q = window_trajectory(j, q)->q_d(std::min(window_start(j + 1), tf));
  }
  t_nodes.push_back(tf);
  q_nodes.push_back(q);
  RowMat q_rows(static_cast<Eigen::Index>(q_nodes.size()), n());
  for (std::size_t k = 0; k < q_nodes.size(); ++k) q_rows.row(static_cast<Eigen::Index>(k)) = q_nodes[k].transpose();
  // The inputs in effect at t: those of the last change at or before t (as window_inputs).
  auto inputs = [base = u_d_, changes = changes_](double t) {
    const VectorSignal* in_effect = &base;
    for (const auto& [t_join, u_d] : changes)
      if (t_join <= t) in_effect = &u_d;
    return (*in_effect)(t);
  };
  return std::make_shared<const Trajectory>(model_, std::move(t_nodes), q_rows, VectorSignal(m(), inputs),
                                            trajectory_options_);
}

HorizonWindow RecedingHorizon::window(int j, const Vec& q_d_start) const {
  HorizonWindow w;
  w.index = j;
  w.t_start = window_start(j);
  w.t_use_end = window_start(j + 1);
  w.trajectory = window_trajectory(j, q_d_start);
  const Mat Z_end = terminal_weight(j, *w.trajectory);
  try {
    w.design = solve_grde(w.trajectory, Q_, Z_end, gamma_, solver_);
  } catch (const ConjugatePointError& e) {
    throw ConjugatePointError(str_cat("receding-horizon window ", j, " [", w.t_start, ", ", w.t_start + options_.window,
                                      "] s: ", e.what()),
                              e.t_escape(), e.gamma());
  }
  return w;
}

HorizonWindow RecedingHorizon::next(const HorizonWindow& previous) const {
  require(previous.trajectory != nullptr, "the window before has no trajectory");
  return window(previous.index + 1, previous.trajectory->q_d(window_start(previous.index + 1)));
}

namespace {

// Appends the rows of `piece` after its first (the time the series already end with) to `all`.
void append_rows(RowMat& all, const RowMat& piece, bool first) {
  const Eigen::Index skip = first ? 0 : 1, rows = piece.rows() - skip;
  if (rows <= 0) return;
  const Eigen::Index old = all.rows();
  all.conservativeResize(old + rows, piece.cols());
  all.bottomRows(rows) = piece.bottomRows(rows);
}

}  // namespace

SimulationResult simulate_receding_horizon(const RecedingHorizon& horizon, const Disturbance& disturbance,
                                           const Vec& q0, double tf, const SimulationOptions& options,
                                           const Model* plant, const Signal& kappa, RecedingHorizonReport* report) {
  const double t0 = horizon.t0();
  check_horizon(t0, tf);
  options.validate();
  const Model& model = horizon.model();
  check_size(q0, model.n(), "the initial state q0");
  const int heading = model.heading_index();
  RecedingHorizonReport summary;
  summary.options = horizon.options();

  Vec q_e0(model.n());
  tracking_error(model.n(), heading, q0.data(), horizon.q_d0().data(), q_e0.data());
  const double scale = std::max(1.0, q_e0.cwiseAbs().maxCoeff());
  PathScale path(horizon.model());  // the path's extent over the windows run so far

  SimulationResult result;
  result.heading_index = heading;
  Vec q = q0;
  HorizonWindow current = horizon.first();
  for (bool first = true;; first = false) {
    ++summary.windows;
    summary.grde.steps += current.design->stats().steps;
    summary.grde.rejected += current.design->stats().rejected;
    summary.grde.rhs_evals += current.design->stats().rhs_evals;
    summary.grde.jac_evals += current.design->stats().jac_evals;
    summary.grde.method = current.design->stats().method;
    summary.grde.memory_bytes = std::max(summary.grde.memory_bytes, current.design->stats().memory_bytes);
    summary.largest_window_bytes = std::max(summary.largest_window_bytes, current.memory_bytes());

    // The loop on [t_j, t_{j+1}] (the last piece ends at tf) along the window's trajectory.
    const double t_end = std::min(current.t_use_end, tf);
    const bool last = t_end >= tf;
    const Trajectory& window = *current.trajectory;
    const Trajectory piece(horizon.model_ptr(), window.q_d(current.t_start), window.u_d_signal(), current.t_start,
                           t_end, window.dense(), window.stats());
    path.add(piece, output_grid(current.t_start, t_end, options.output_dt));
    summary.divergence_bound = options.divergence_factor * std::max(scale, path.scale());
    HinfStateFeedback law(current.design, kappa);
    const SimulationResult part =
        detail::simulate_state_feedback(piece, law, disturbance, q, options, plant, summary.divergence_bound);

    const Eigen::Index skip = first ? 0 : 1, rows = part.t.size() - skip;
    if (rows > 0) {
      const Eigen::Index old = result.t.size();
      result.t.conservativeResize(old + rows);
      result.t.tail(rows) = part.t.tail(rows);
    }
    append_rows(result.q, part.q, first);
    append_rows(result.q_d, part.q_d, first);
    append_rows(result.u, part.u, first);
    append_rows(result.u_d, part.u_d, first);
    append_rows(result.w, part.w, first);
    result.integrator = part.integrator;
    result.stats.steps += part.stats.steps;
    result.stats.rejected += part.stats.rejected;
    result.stats.rhs_evals += part.stats.rhs_evals;
    result.stats.jac_evals += part.stats.jac_evals;
    if (part.status != RunStatus::Completed) {
      result.status = part.status;
      result.status_message = part.status_message;
      break;
    }
    if (last) break;
    q = part.q.row(part.q.rows() - 1).transpose();
    // The next window is solved while the one in use is still held: two at most.
    HorizonWindow next = horizon.next(current);
    summary.peak_bytes = std::max(summary.peak_bytes, current.memory_bytes() + next.memory_bytes());
    current = std::move(next);
  }
  summary.peak_bytes = std::max(summary.peak_bytes, summary.largest_window_bytes);
  if (report != nullptr) *report = summary;
  return result;
}

WindowGammaStar receding_horizon_gamma_star(const RecedingHorizon& horizon, double tf, const GammaStarOptions& options) {
  check_horizon(horizon.t0(), tf);
  GammaStarOptions search = options;
  search.solver = horizon.solver();
  search.validate();
  WindowGammaStar worst;
  Vec q_start = horizon.q_d0();
  for (int j = 0; horizon.window_start(j) < tf; ++j) {
    const TrajectoryPtr trajectory = horizon.window_trajectory(j, q_start);
    GammaStarResult r = gamma_star(trajectory, horizon.Q(), horizon.terminal_weight(j, *trajectory), search);
    ++worst.windows;
    worst.converged = worst.converged && r.converged;
    if (!(r.gamma_star <= worst.gamma_star)) {  // also the first window (NaN)
      worst.gamma_star = r.gamma_star;
      worst.window = j;
      worst.t_start = horizon.window_start(j);
      worst.result = std::move(r);
    }
    q_start = trajectory->q_d(horizon.window_start(j + 1));
  }
  return worst;
}

}  // namespace hinf
