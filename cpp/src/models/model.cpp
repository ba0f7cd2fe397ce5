#include "hinf/models/model.hpp"

#include <algorithm>
#include <cmath>
#include <typeinfo>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

void Model::dGudq(double, const ConstVecRef&, const ConstVecRef&, MatRef out) const {
  require(!state_dependent_inputs(), "the model '", name(), "' declares input matrices that depend on the state",
          " but does not implement dGudq(t, q, u) = d/dq [G(t, q) u]: implement it");
  out.setZero();
}

void Model::error_split(double t, const ConstVecRef& q_d, const ConstVecRef& u_d, const ConstVecRef& q_e, MatRef A,
                        VecRef alpha) const {
  linearize(*this, t, q_d, u_d, A);
  const Vec q = q_d + q_e;
  Vec f_actual(n()), f_desired(n());
  f(t, q, f_actual);
  f(t, q_d, f_desired);
  alpha = f_actual - f_desired - A * q_e;
  if (state_dependent_inputs()) alpha.noalias() += (G(t, q) - G(t, q_d)) * u_d;
}

void linearize(const Model& model, double t, const ConstVecRef& q, const ConstVecRef& u, MatRef A) {
  model.dfdq(t, q, A);
  if (!model.state_dependent_inputs()) return;
  Mat input_part(model.n(), model.n());
  model.dGudq(t, q, u, input_part);
  A += input_part;
}

namespace {

std::string vector_text(const ConstVecRef& v) {
  std::string text = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) text += str_cat(i == 0 ? "" : ", ", v[i]);
  return text + "]";
}

// "(i, j) = value" of the first non-finite entry, or "" when M is finite.
std::string first_nonfinite(const Mat& M) {
  for (Eigen::Index j = 0; j < M.cols(); ++j)
    for (Eigen::Index i = 0; i < M.rows(); ++i)
      if (!std::isfinite(M(i, j))) return str_cat(M(i, j), " at (", i, ", ", j, ")");
  return "";
}

}  // namespace

void check_finite_outputs(const Model& model, double t, const ConstVecRef& q) {
  const auto fail = [&](const char* what, const std::string& entry) {
    throw InputError(str_cat("the model '", model.name(), "' returned a non-finite ", what, " (", entry, ") at t = ", t,
                             ", q = ", vector_text(q),
                             ": a model must return finite numbers wherever it is evaluated (fix its equations "
                             "there, or keep the states and inputs where they are defined)"));
  };
  if (!q.allFinite()) return;  // a non-finite state is not the model's output
  const int n = model.n();
  Vec f(n);
  model.f(t, q, f);
  if (std::string entry = first_nonfinite(f); !entry.empty()) fail("f(t, q)", entry);
  Mat A(n, n);
  model.dfdq(t, q, A);
  if (std::string entry = first_nonfinite(A); !entry.empty()) fail("df/dq (t, q)", entry);
  if (std::string entry = first_nonfinite(model.G(t, q)); !entry.empty()) fail("G(t, q)", entry);
  if (std::string entry = first_nonfinite(model.D(t, q)); !entry.empty()) fail("D(t, q)", entry);
}

void check_input_matrix_declarations(const Model& model, const std::vector<double>& t, const std::vector<Vec>& q) {
  if (t.empty()) return;
  const auto differ = [](const Mat& a, const Mat& b) {
    // Equal matrices are equal bit for bit when they do not depend on (t, q); the tolerance only
    // keeps round-off of a model that recomputes a constant from being called a dependence.
    return (a - b).cwiseAbs().maxCoeff() > 1e-12 * (1.0 + std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()));
  };
  const auto fail = [&](const char* matrix, double t1, const Vec& q1, double t2, const Vec& q2, const char* fix) {
    throw InputError(str_cat("the model '", model.name(), "' returns another ", matrix, " at t = ", t2, ", q = ",
                             vector_text(q2), " than at t = ", t1, ", q = ", vector_text(q1), ", but ", fix));
  };
  const Mat G0 = model.G(t[0], q[0]), D0 = model.D(t[0], q[0]);
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Mat Gk = model.G(t[k], q[k]), Dk = model.D(t[k], q[k]);
    if (model.constant_input_matrices()) {
      const char* fix = "it declares constant input matrices (constant_input_matrices() is true, the default), so it "
                        "would be evaluated at the first point only: override constant_input_matrices() to return "
                        "false (and state_dependent_inputs() to return true if they depend on q)";
      if (differ(G0, Gk)) fail("G", t[0], q[0], t[k], q[k], fix);
      if (differ(D0, Dk)) fail("D", t[0], q[0], t[k], q[k], fix);
    }
    if (!model.state_dependent_inputs()) {
      // The same time, the state moved in every component by a different amount.
      Vec moved = q[k];
      for (Eigen::Index i = 0; i < moved.size(); ++i)
        moved[i] += (0.1 + 0.05 * static_cast<double>(i)) * std::max(1.0, std::abs(moved[i]));
      const char* fix = "it declares input matrices that do not depend on q (state_dependent_inputs() is false, the "
                        "default), so its linearization would leave out d(G u)/dq: override state_dependent_inputs() "
                        "to return true and constant_input_matrices() to return false";
      if (differ(Gk, model.G(t[k], moved))) fail("G", t[k], q[k], t[k], moved, fix);
      if (differ(Dk, model.D(t[k], moved))) fail("D", t[k], q[k], t[k], moved, fix);
    }
  }
}

double Model::remainder_bound(double, const ConstVecRef&, double) const { return NAN; }

Mat Model::C(double) const {
  throw InputError(str_cat("the model '", name(), "' defines no measurement (C): imperfect",
                           " measurements need a model with C(t) and noise_channels()"));
}

std::vector<std::string> Model::state_names() const { return numbered_state_names(n()); }

void append_matrix_parameters(std::vector<std::pair<std::string, double>>& parameters, const std::string& name,
                              const Mat& M) {
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) parameters.emplace_back(str_cat(name, "[", i, "][", j, "]"), M(i, j));
}

bool same_type_and_parameters(const Model& a, const Model& b) {
  return &a == &b || (typeid(a) == typeid(b) && a.named_parameters() == b.named_parameters());
}

std::vector<std::string> Model::numbered_state_names(int n) {
  std::vector<std::string> names;
  for (int i = 0; i < n; ++i) names.push_back("q" + std::to_string(i));
  return names;
}

namespace {

std::string list(const std::vector<int>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i > 0 ? ", " : "") + std::to_string(values[i]);
  return text + "]";
}

// Each index in [0, size) and none twice; `fact` names the model function they come from.
void check_indices(const ModelStructure& s, const std::vector<int>& indices, int size, const char* fact,
                   const char* kind) {
  for (std::size_t i = 0; i < indices.size(); ++i) {
    require(indices[i] >= 0 && indices[i] < size, "the model '", s.name, "': ", fact, " = ", list(indices),
            " holds ", indices[i], ", which is not ", kind, " (0 to ", size - 1, "); fix the model's ", fact);
    for (std::size_t j = 0; j < i; ++j)
      require(indices[j] != indices[i], "the model '", s.name, "': ", fact, " = ", list(indices), " holds ",
              indices[i], " twice; fix the model's ", fact);
  }
}

}  // namespace

void check_dimensions(const ModelStructure& s) {
  const std::string model = str_cat("the model '", s.name, "': ");
  check_dimension(s.n, 1, model + "the number of states n()");
  check_dimension(s.m, 1, model + "the number of inputs m()");
  check_dimension(s.nw, 0, model + "the number of disturbance channels nw()");
}

void check_structure(const ModelStructure& s) {
  check_dimensions(s);
  require(static_cast<int>(s.state_names.size()) == s.n, "the model '", s.name, "': state_names() has ",
          s.state_names.size(), " names, expected one per state (n = ", s.n, ")");
  check_indices(s, s.position_indices, s.n, "position_indices()", "a state index");
  require(s.heading_index == -1 || (s.heading_index >= 0 && s.heading_index < s.n), "the model '", s.name,
          "': heading_index() must be -1 (no heading) or a state index (0 to ", s.n - 1, "), got ",
          s.heading_index);
  check_indices(s, s.noise_channels, s.nw, "noise_channels()", "a disturbance channel");
  require(!(s.constant_input_matrices && s.state_dependent_inputs), "the model '", s.name,
          "' says its input matrices are constant and also that they depend on the state: a model with",
          " state_dependent_inputs() must return false from constant_input_matrices()");
}

ModelStructure structure_of(const Model& model) {
  ModelStructure s;
  s.name = model.name();
  s.n = model.n();
  s.m = model.m();
  s.nw = model.nw();
  check_dimensions(s);
  s.state_names = model.state_names();
  s.position_indices = model.position_indices();
  s.heading_index = model.heading_index();
  s.noise_channels = model.noise_channels();
  s.constant_input_matrices = model.constant_input_matrices();
  s.state_dependent_inputs = model.state_dependent_inputs();
  return s;
}

void validate_model(const Model& model, double t, const ConstVecRef& q) {
  const ModelStructure s = structure_of(model);
  check_structure(s);
  check_size(q, s.n, str_cat("the state at which the model '", s.name, "' is checked"));
  const Mat G = model.G(t, q), D = model.D(t, q);
  check_shape(G, s.n, s.m, str_cat("G(t, q) of the model '", s.name, "'"));
  check_finite(G, str_cat("G(t, q) of the model '", s.name, "'"));
  check_shape(D, s.n, s.nw, str_cat("D(t, q) of the model '", s.name, "'"));
  check_finite(D, str_cat("D(t, q) of the model '", s.name, "'"));
}

std::vector<int> merge_coupled_blocks(const std::vector<int>& blocks, const Mat& M, Coupling coupling) {
  const int n = static_cast<int>(M.rows());
  // reach[i]: the last state that state i is joined with; consecutive groups are then the
  // maximal runs whose joins stay inside them (a union of intervals).
  std::vector<int> reach(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) reach[i] = i;
  int start = 0;
  for (int size : blocks) {
    require(size >= 1 && start + size <= n, "merge_coupled_blocks: groups of sizes that do not add up to ", n);
    reach[start] = start + size - 1;
    start += size;
  }
  require(start == n, "merge_coupled_blocks: groups of sizes that do not add up to ", n);
  auto join = [&reach](int a, int b) { reach[std::min(a, b)] = std::max(reach[std::min(a, b)], std::max(a, b)); };
  for (Eigen::Index j = 0; j < M.cols(); ++j) {
    int first = -1, last = -1;
    for (int i = 0; i < n; ++i) {
      if (M(i, j) == 0.0) continue;
      if (coupling == Coupling::Entries) join(i, static_cast<int>(j));
      if (first < 0) first = i;
      last = i;
    }
    if (coupling == Coupling::Columns && first >= 0) join(first, last);
  }
  std::vector<int> merged;
  for (int i = 0, begin = 0, end = 0; i < n; ++i) {
    end = std::max(end, reach[i]);
    if (i == end) {
      merged.push_back(end - begin + 1);
      begin = i + 1;
    }
  }
  return merged;
}

std::vector<int> LinearModel::uncoupled_blocks() const {
  const std::vector<int> each_state(static_cast<std::size_t>(n()), 1);
  std::vector<int> blocks = merge_coupled_blocks(each_state, A_, Coupling::Entries);
  blocks = merge_coupled_blocks(blocks, B_, Coupling::Columns);
  return merge_coupled_blocks(blocks, D_, Coupling::Columns);
}

LinearModel::LinearModel(Mat A, Mat B, Mat D, Mat C)
    : A_(std::move(A)), B_(std::move(B)), D_(std::move(D)), C_(std::move(C)) {
  const int n = static_cast<int>(A_.rows());
  require(n >= 1, "LinearModel needs at least one state");
  check_shape(A_, n, n, "A");
  check_finite(A_, "A");
  require(B_.rows() == n, "Incompatible dimensions of B: expected ", n, " rows but found ",
          B_.rows());
  require(D_.rows() == n, "Incompatible dimensions of D: expected ", n, " rows but found ",
          D_.rows());
  check_finite(B_, "B");
  check_finite(D_, "D");
  if (C_.size() > 0) {
    require(C_.cols() == n, "Incompatible dimensions of C: expected ", n, " columns but found ",
            C_.cols());
    check_finite(C_, "C");
    const Eigen::Index processes = D_.cols();
    D_.conservativeResize(n, processes + C_.rows());
    D_.rightCols(C_.rows()).setZero();
  }
}

Mat LinearModel::C(double t) const {
  if (C_.size() == 0) return Model::C(t);
  return C_;
}

std::vector<std::pair<std::string, double>> LinearModel::named_parameters() const {
  std::vector<std::pair<std::string, double>> named;
  append_matrix_parameters(named, "A", A_);
  append_matrix_parameters(named, "B", B_);
  append_matrix_parameters(named, "D", process_D());
  append_matrix_parameters(named, "C", C_);
  return named;
}

std::vector<int> LinearModel::noise_channels() const {
  std::vector<int> channels;
  for (Eigen::Index i = 0; i < C_.rows(); ++i)
    channels.push_back(static_cast<int>(D_.cols() - C_.rows() + i));
  return channels;
}

void LinearModel::f(double, const ConstVecRef& q, VecRef out) const { out.noalias() = A_ * q; }

void LinearModel::dfdq(double, const ConstVecRef&, MatRef out) const { out = A_; }

}  // namespace hinf
