// The model interface and the built-in models.
//
// A model is a control-affine system (paper eq. 7 with state-dependent input matrices):
//     dq/dt = f(t, q) + G(t, q) u + D(t, q) w,
// with state q (n), control u (m) and disturbance w (nw). Everything downstream uses only this
// interface: the desired trajectory, the linearization along it (docs/mathematics.md,
// "State-dependent input matrices")
//     A_e(t) = d/dq [f(t, q) + G(t, q) u_d(t)] at q_d(t),  B_e(t) = G(t, q_d(t)),
//     D_e(t) = D(t, q_d(t)),
// the GRDE and filter designed on (A_e, B_e, D_e), and the closed loops, which apply the full
// nonlinear f, G and D. The paper's ship is the special case with constant G = B and D.
//
// Conventions, fixed once for the project:
//   * time t is absolute, in seconds;
//   * the error is q_e = q - q_d (actual minus desired), likewise u_e = u - u_d;
//   * matrices are column-major Eigen objects; G is n x m, D is n x nw.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/core/types.hpp"

namespace hinf {

// The interface every model implements. Its structure (name, sizes, state names, position and
// heading indices, noise channels, the two flags about the input matrices: ModelStructure) must
// not change over the model's life.
class Model {
 public:
  virtual ~Model() = default;

  // The model's name (the results file, tables, messages).
  virtual std::string name() const = 0;
  // The sizes: n states, m control inputs, nw disturbance channels.
  virtual int n() const = 0;
  virtual int m() const = 0;
  virtual int nw() const = 0;

  // Drift f(t, q) (n) and its Jacobian df/dq (n x n).
  virtual void f(double t, const ConstVecRef& q, VecRef out) const = 0;
  virtual void dfdq(double t, const ConstVecRef& q, MatRef out) const = 0;
  // How dfdq and dGudq are obtained, for the results file: "analytic" (written out), or what
  // the model does instead ("automatic differentiation", "complex step", "central differences").
  virtual std::string jacobian_method() const { return "analytic"; }
  // Input matrix G(t, q) (n x m) and disturbance matrix D(t, q) (n x nw).
  virtual Mat G(double t, const ConstVecRef& q) const = 0;
  virtual Mat D(double t, const ConstVecRef& q) const = 0;
  // True when G and D depend on neither t nor q (lets solvers precompute B B' and D D').
  virtual bool constant_input_matrices() const { return true; }
  // True when G or D depend on q (then constant_input_matrices() must be false, and dGudq
  // must be implemented).
  virtual bool state_dependent_inputs() const { return false; }
  // d/dq [G(t, q) u] for a fixed u (n x n): the input's part of the linearization. Zero for
  // models whose G does not depend on q; a model with state_dependent_inputs() overrides it
  // (the default then throws InputError).
  virtual void dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const;

  // Decomposition of the error dynamics (paper eqs. 26-31, with the input's drift):
  //     f_e(t, q_e) := f(t, q_d + q_e) + G(t, q_d + q_e) u_d - f(t, q_d) - G(t, q_d) u_d
  //                  = A(t, q_e) q_e + alpha(t, q_e),
  // with A(t, 0) = A_e(t). q_d and u_d are the desired state and input at t (u_d matters only
  // when G depends on q). The default is the always-valid split A = A_e(t),
  // alpha = f_e - A_e q_e; models with structure (the ship) override it.
  virtual void error_split(double t, const ConstVecRef& q_d, const ConstVecRef& u_d, const ConstVecRef& q_e,
                           MatRef A, VecRef alpha) const;

  // Measurement y = C(t) q + E w (paper eq. 25), C is p x n. The measurement noise is carried
  // by the w channels noise_channels() (p of them): E = sigma [those unit columns], so
  // N = E E' = sigma^2 I. The default model has no measurement (C throws InputError).
  virtual Mat C(double t) const;
  virtual std::vector<int> noise_channels() const { return {}; }

  // A bound L with |f_e(t, q_e) - A_e(t) q_e| <= L |q_e|^2 for all |q_e| <= radius (the
  // remainder of the linearization, paper eqs. 11 and 24), or NaN if the model has none (the
  // certificates then fall back on a sampled estimate, reported as such).
  virtual double remainder_bound(double t, const ConstVecRef& q_d, double radius) const;

  // Names of the state components (for tables, CSV headers and plots).
  virtual std::vector<std::string> state_names() const;
  // Indices of the inertial position components used by the position-error metrics
  // (empty: the model has no position, and those metrics are NaN).
  virtual std::vector<int> position_indices() const { return {}; }
  // Index of the heading angle (rad), or -1.
  virtual int heading_index() const { return -1; }

  // The model's parameters by name, in a fixed order: a number by its key in the model's
  // scenario-file section ([model], [plant]: "d_u" of the ship), an entry of a matrix as
  // NAME[i][j] (row i, column j, from 0: "D[1][2]" of the Fossen vessel). Empty for a model
  // without named parameters. Studies perturb a model from these base values; the results file
  // records them.
  virtual std::vector<std::pair<std::string, double>> named_parameters() const { return {}; }

  // The sizes of consecutive groups of states that no equation of the model couples, in
  // order, summing to n: for every t, q and u, df/dq, G, D and d(G u)/dq are block-diagonal in
  // these groups (a group's inputs and disturbances act on it alone). The Riccati solves split
  // a problem that is also uncoupled in its weights into these blocks. {n} unless the model
  // knows better (a fleet: its vehicles; a linear model: from its matrices).
  virtual std::vector<int> uncoupled_blocks() const { return {n()}; }

  // True when `other` is the same model: the same equations with the same parameters, so that
  // the designs along one desired trajectory are the same for both (run_scenarios shares designs
  // by it). The default is the model itself only (a model that cannot tell, such as one
  // implemented in Python); the built-in models compare their type and named_parameters().
  virtual bool same_as(const Model& other) const { return this == &other; }

  // "q0", "q1", ..., the default state_names().
  static std::vector<std::string> numbered_state_names(int n);
};

// NAME[i][j] = M(i, j), row by row, appended to `parameters` (named_parameters of a matrix).
void append_matrix_parameters(std::vector<std::pair<std::string, double>>& parameters, const std::string& name,
                              const Mat& M);

// The named parameters of a struct of numbers from its table of (scenario-file key, member).
template <class Parameters, std::size_t N>
std::vector<std::pair<std::string, double>> named_parameters_of(
    const Parameters& p, const std::array<std::pair<const char*, double Parameters::*>, N>& keys) {
  std::vector<std::pair<std::string, double>> named;
  for (const auto& [key, member] : keys) named.emplace_back(key, p.*member);
  return named;
}

// Model::same_as of a model that its type and named_parameters() describe completely (the
// built-in models): the same dynamic type and equal named parameters.
bool same_type_and_parameters(const Model& a, const Model& b);

using ModelPtr = std::shared_ptr<const Model>;

// What a model says about itself that depends on neither t nor q. Everything downstream
// sizes its arrays and indexes its states by these numbers, so a model must keep them fixed.
struct ModelStructure {
  std::string name;
  int n = 0;
  int m = 0;
  int nw = 0;
  std::vector<std::string> state_names;
  std::vector<int> position_indices;
  int heading_index = -1;
  std::vector<int> noise_channels;
  bool constant_input_matrices = true;
  bool state_dependent_inputs = false;
};

// InputError unless n >= 1, m >= 1 and nw >= 0 (all at most kMaxDimension): checked before
// anything sized by them is read.
void check_dimensions(const ModelStructure& structure);
// check_dimensions, and: n state names, position indices distinct and in [0, n), heading
// index -1 or in [0, n), noise channels distinct and in [0, nw), and not both constant and
// state-dependent input matrices. InputError naming the first fault.
void check_structure(const ModelStructure& structure);

// How a matrix couples states: by its entries (n x n: entry (i, j) couples states i and j) or
// by its columns (n x k input matrix: each column couples the states it acts on).
enum class Coupling { Entries, Columns };
// The coarsest merge of the consecutive groups `blocks` (sizes summing to M.rows()) that M does
// not couple: groups joined by a nonzero of M become one group (Model::uncoupled_blocks).
std::vector<int> merge_coupled_blocks(const std::vector<int>& blocks, const Mat& M, Coupling coupling);

// What the model says about itself (n, m, nw checked first by check_dimensions, since the
// rest is sized by them); check_structure checks the rest.
ModelStructure structure_of(const Model& model);

// The check of a model where it enters the library (the Trajectory constructor,
// compute_metrics, Scenario): its structure (check_structure), and G(t, q) (n x m) and
// D(t, q) (n x nw) with finite entries at the state q (n). A C++ model is trusted to keep its
// structure afterwards; a model implemented in Python is read once and validated (the Python
// bindings).
void validate_model(const Model& model, double t, const ConstVecRef& q);

// The linearization of the drift with the input held at u: A = d/dq [f(t, q) + G(t, q) u]
// (n x n) = df/dq, plus dGudq when the inputs depend on the state. At (q_d(t), u_d(t)) this is
// A_e(t).
void linearize(const Model& model, double t, const ConstVecRef& q, const ConstVecRef& u, MatRef A);

// An InputError naming the first of f, df/dq, G and D of the model that is not finite at (t, q)
// (with t and q), and what to do; nothing when all four are finite. The integrators call it
// where a right-hand side or a solution stops being finite, so that the model's own failure is
// reported as the model's, not as a step size, a conjugate point or a metric.
void check_finite_outputs(const Model& model, double t, const ConstVecRef& q);

// An InputError when the model says its input matrices are constant (constant_input_matrices())
// but G or D differ between the points (t_k, q_k), or says they do not depend on the state
// (!state_dependent_inputs()) but G or D change when q moves at a fixed t: such a model would be
// evaluated at (t0, q0) only, or linearized without d(G u)/dq, and give wrong results silently.
// The message names the model, the matrix, the two points and the declaration to change.
void check_input_matrix_declarations(const Model& model, const std::vector<double>& t,
                                     const std::vector<Vec>& q);

// A linear time-invariant model dq/dt = A q + B u + D w (for LTI studies and tests).
// With a measurement matrix C (p x n), w gets p more channels for the measurement noise:
// w = [process disturbance (D.cols()), measurement noise (p)], and D is padded with zeros.
class LinearModel final : public Model {
 public:
  LinearModel(Mat A, Mat B, Mat D, Mat C = Mat());
  std::string name() const override { return "linear"; }
  int n() const override { return static_cast<int>(A_.rows()); }
  int m() const override { return static_cast<int>(B_.cols()); }
  int nw() const override { return static_cast<int>(D_.cols()); }
  void f(double t, const ConstVecRef& q, VecRef out) const override;
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override;
  Mat G(double, const ConstVecRef&) const override { return B_; }
  Mat D(double, const ConstVecRef&) const override { return D_; }
  Mat C(double t) const override;
  std::vector<int> noise_channels() const override;
  double remainder_bound(double, const ConstVecRef&, double) const override { return 0.0; }
  // The groups of states that A, B and D leave uncoupled, read from their nonzeros.
  std::vector<int> uncoupled_blocks() const override;
  // A (n x n) and B (n x m) as given to the constructor.
  const Mat& A() const { return A_; }
  const Mat& B() const { return B_; }
  // The matrices as given to the constructor: D without the noise channels, C empty if none.
  Mat process_D() const { return D_.leftCols(D_.cols() - C_.rows()); }
  const Mat& measurement_C() const { return C_; }
  // A[i][j], B[i][j], D[i][j] (process D), C[i][j]: the entries of the scenario file's matrices.
  std::vector<std::pair<std::string, double>> named_parameters() const override;
  bool same_as(const Model& other) const override { return same_type_and_parameters(*this, other); }

 private:
  Mat A_, B_, D_, C_;
};

}  // namespace hinf
