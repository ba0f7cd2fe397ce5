#include "hinf/model.hpp"

#include <cmath>

#include "hinf/checks.hpp"
#include "hinf/errors.hpp"

namespace hinf {

void Model::error_split(double t, const ConstVecRef& q_d, const ConstVecRef& q_e, MatRef A,
                        VecRef alpha) const {
  dfdq(t, q_d, A);
  Vec f_actual(n()), f_desired(n());
  f(t, q_d + q_e, f_actual);
  f(t, q_d, f_desired);
  alpha = f_actual - f_desired - A * q_e;
}

double Model::remainder_bound(double, const ConstVecRef&, double) const { return NAN; }

Mat Model::C(double) const {
  throw InputError(str_cat("the model '", name(), "' defines no measurement (C): imperfect",
                           " measurements need a model with C(t) and noise_channels()"));
}

std::vector<std::string> Model::state_names() const { return numbered_state_names(n()); }

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
}

void validate_model(const Model& model, double t) {
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
  check_structure(s);
  const Mat B = model.B(t), D = model.D(t);
  check_shape(B, s.n, s.m, str_cat("B(t) of the model '", s.name, "'"));
  check_finite(B, str_cat("B(t) of the model '", s.name, "'"));
  check_shape(D, s.n, s.nw, str_cat("D(t) of the model '", s.name, "'"));
  check_finite(D, str_cat("D(t) of the model '", s.name, "'"));
}

ShipModel::ShipModel(const ShipParameters& parameters) : p_(parameters) {
  check_finite(p_.m_u, "m_u");
  check_finite(p_.m_v, "m_v");
  check_finite(p_.m_r, "m_r");
  check_finite(p_.d_u, "d_u");
  check_finite(p_.d_v, "d_v");
  check_finite(p_.d_r, "d_r");
}

void ShipModel::f(double, const ConstVecRef& q, VecRef out) const {
  const double u = q[0], v = q[1], r = q[2], psi = q[5];
  const double c = std::cos(psi), s = std::sin(psi);
  out[0] = p_.m_u * v * r - p_.d_u * u;
  out[1] = p_.m_v * u * r - p_.d_v * v;
  out[2] = p_.m_r * u * v - p_.d_r * r;
  out[3] = u * c - v * s;
  out[4] = u * s + v * c;
  out[5] = r;
}

void ShipModel::dfdq(double, const ConstVecRef& q, MatRef J) const {
  const double u = q[0], v = q[1], r = q[2], psi = q[5];
  const double c = std::cos(psi), s = std::sin(psi);
  J.setZero();
  J(0, 0) = -p_.d_u;
  J(0, 1) = p_.m_u * r;
  J(0, 2) = p_.m_u * v;
  J(1, 0) = p_.m_v * r;
  J(1, 1) = -p_.d_v;
  J(1, 2) = p_.m_v * u;
  J(2, 0) = p_.m_r * v;
  J(2, 1) = p_.m_r * u;
  J(2, 2) = -p_.d_r;
  J(3, 0) = c;
  J(3, 1) = -s;
  J(3, 5) = -u * s - v * c;
  J(4, 0) = s;
  J(4, 1) = c;
  J(4, 5) = u * c - v * s;
  J(5, 2) = 1.0;
}

Mat ShipModel::B(double) const {
  Mat B = Mat::Zero(6, 2);
  B(0, 0) = 1.0;
  B(2, 1) = 1.0;
  return B;
}

Mat ShipModel::D(double) const {
  Mat D = Mat::Zero(6, 6);
  D(0, 0) = D(1, 1) = D(2, 2) = 1.0;
  return D;
}

// DESIGN.md, "Imperfect measurements": q1 = [u, v, x, y] (indices 0, 1, 3, 4) and
// q2 = [r, psi] (indices 2, 5), all errors; psi = psi_d + psi_e, r = r_d + r_e.
void ShipModel::error_split(double, const ConstVecRef& q_d, const ConstVecRef& q_e, MatRef A,
                            VecRef alpha) const {
  const double ud = q_d[0], vd = q_d[1], rd = q_d[2], psid = q_d[5];
  const double ue = q_e[0], ve = q_e[1], re = q_e[2], psie = q_e[5];
  const double psi = psid + psie;
  const double c = std::cos(psi), s = std::sin(psi), cd = std::cos(psid), sd = std::sin(psid);

  // alpha1(q2) and alpha2(q1) of the DESIGN.md decomposition.
  const double alpha1_u = p_.m_u * vd * re;
  const double alpha1_v = p_.m_v * ud * re;
  const double alpha1_x = ud * (c - cd) - vd * (s - sd);
  const double alpha1_y = ud * (s - sd) + vd * (c - cd);
  const double alpha2_r = p_.m_r * (ue * vd + ud * ve + ue * ve);
  // A12 = d alpha1 / d q2 at q2 = 0, A21 = d alpha2 / d q1 at q1 = 0.
  const double A12_u_r = p_.m_u * vd, A12_v_r = p_.m_v * ud;
  const double A12_x_psi = -ud * sd - vd * cd, A12_y_psi = ud * cd - vd * sd;
  const double A21_r_u = p_.m_r * vd, A21_r_v = p_.m_r * ud;

  A.setZero();
  // Rows of q1: A11(q2) on (u, v, x, y), A12 on (r, psi).
  A(0, 0) = -p_.d_u;
  A(0, 1) = p_.m_u * (rd + re);
  A(0, 2) = A12_u_r;
  A(1, 0) = p_.m_v * (rd + re);
  A(1, 1) = -p_.d_v;
  A(1, 2) = A12_v_r;
  A(3, 0) = c;
  A(3, 1) = -s;
  A(3, 5) = A12_x_psi;
  A(4, 0) = s;
  A(4, 1) = c;
  A(4, 5) = A12_y_psi;
  // Rows of q2: A21 on (u, v, x, y), A22 = [[-d_r, 0], [1, 0]] on (r, psi).
  A(2, 0) = A21_r_u;
  A(2, 1) = A21_r_v;
  A(2, 2) = -p_.d_r;
  A(5, 2) = 1.0;

  alpha[0] = alpha1_u - A12_u_r * re;
  alpha[1] = alpha1_v - A12_v_r * re;
  alpha[3] = alpha1_x - A12_x_psi * psie;
  alpha[4] = alpha1_y - A12_y_psi * psie;
  alpha[2] = alpha2_r - (A21_r_u * ue + A21_r_v * ve);
  alpha[5] = 0.0;
}

// The remainder r = f(q_d + e) - f(q_d) - A_e e of the ship, e = (e_u, e_v, e_r, e_x, e_y, e_psi):
//   r_u = m_u e_v e_r,  r_v = m_v e_u e_r,  r_r = m_r e_u e_v,  r_psi = 0,
//   r_xy = [R(psi_d + e_psi) - R(psi_d) - R'(psi_d) e_psi] (u_d, v_d) + [R(psi_d + e_psi) - R(psi_d)] (e_u, e_v)
// with R the rotation by psi. For rotations |R(a + b) - R(a) - R'(a) b| = |e^{ib} - 1 - ib| <= b^2/2
// and |R(a + b) - R(a)| <= |b|; and |e_i e_j| <= |e|^2 / 2. Hence, with s_d = |(u_d, v_d)|,
//   |r|^2 <= |e|^4 / 4 (m_u^2 + m_v^2 + m_r^2 + (s_d + 1)^2)   for every e (any radius).
double ShipModel::remainder_bound(double, const ConstVecRef& q_d, double) const {
  const double speed = std::hypot(q_d[0], q_d[1]);
  return 0.5 * std::sqrt(p_.m_u * p_.m_u + p_.m_v * p_.m_v + p_.m_r * p_.m_r + (speed + 1.0) * (speed + 1.0));
}

Mat ShipModel::C(double) const {
  Mat C = Mat::Zero(3, 6);
  C(0, 3) = C(1, 4) = C(2, 5) = 1.0;
  return C;
}

std::vector<std::string> ShipModel::state_names() const {
  return {"u", "v", "r", "x", "y", "psi"};
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

std::vector<int> LinearModel::noise_channels() const {
  std::vector<int> channels;
  for (Eigen::Index i = 0; i < C_.rows(); ++i)
    channels.push_back(static_cast<int>(D_.cols() - C_.rows() + i));
  return channels;
}

void LinearModel::f(double, const ConstVecRef& q, VecRef out) const { out.noalias() = A_ * q; }

void LinearModel::dfdq(double, const ConstVecRef&, MatRef out) const { out = A_; }

}  // namespace hinf
