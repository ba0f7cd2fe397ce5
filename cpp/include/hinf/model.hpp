// The model interface and the built-in models.
//
// A model is the control-affine system of paper eq. (7):
//     dq/dt = f(t, q) + B(t) u + D(t) w,
// with state q (n), control u (m) and disturbance w (nw). Everything downstream
// (trajectory, linearization A_e(t) = df/dq along q_d(t), the GRDE, the closed loop)
// uses only this interface: the ship is one model among others.
//
// Conventions, fixed once for the project:
//   * time t is absolute, in seconds;
//   * the error is q_e = q - q_d (actual minus desired), likewise u_e = u - u_d;
//   * matrices are column-major Eigen objects; B is n x m, D is n x nw.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hinf/errors.hpp"
#include "hinf/types.hpp"

namespace hinf {

class Model {
 public:
  virtual ~Model() = default;

  virtual std::string name() const = 0;
  virtual int n() const = 0;   // states
  virtual int m() const = 0;   // control inputs
  virtual int nw() const = 0;  // disturbance channels

  // Drift f(t, q) (n) and its Jacobian df/dq (n x n).
  virtual void f(double t, const ConstVecRef& q, VecRef out) const = 0;
  virtual void dfdq(double t, const ConstVecRef& q, MatRef out) const = 0;
  // Input and disturbance matrices.
  virtual Mat B(double t) const = 0;
  virtual Mat D(double t) const = 0;
  // True when B and D do not depend on t (lets solvers precompute B B' and D D').
  virtual bool constant_input_matrices() const { return true; }

  // Decomposition of the error dynamics (paper eqs. 26-31):
  //     f_e(t, q_e) := f(t, q_d + q_e) - f(t, q_d) = A(t, q_e) q_e + alpha(t, q_e),
  // with A(t, 0) = A_e(t). q_d is the desired state at t. The default is the always-valid
  // split A = A_e(t), alpha = f_e - A_e q_e; models with structure (the ship) override it.
  virtual void error_split(double t, const ConstVecRef& q_d, const ConstVecRef& q_e, MatRef A,
                           VecRef alpha) const;

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

  // "q0", "q1", ..., the default state_names().
  static std::vector<std::string> numbered_state_names(int n);
};

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
};

// InputError unless n >= 1, m >= 1 and nw >= 0 (all at most kMaxDimension): checked before
// anything sized by them is read.
void check_dimensions(const ModelStructure& structure);
// check_dimensions, and: n state names, position indices distinct and in [0, n), heading
// index -1 or in [0, n), noise channels distinct and in [0, nw). InputError naming the
// first fault.
void check_structure(const ModelStructure& structure);

// The check of a model where it enters the library (the Trajectory constructor,
// compute_metrics, Scenario): its structure (check_structure), and B(t) (n x m) and D(t)
// (n x nw) with finite entries. A C++ model is trusted to keep its structure afterwards; a
// model implemented in Python is read once and validated (the Python bindings).
void validate_model(const Model& model, double t);

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
  Mat B(double) const override { return B_; }
  Mat D(double) const override { return D_; }
  Mat C(double t) const override;
  std::vector<int> noise_channels() const override;
  double remainder_bound(double, const ConstVecRef&, double) const override { return 0.0; }
  const Mat& A() const { return A_; }
  // The matrices as given to the constructor: D without the noise channels, C empty if none.
  Mat process_D() const { return D_.leftCols(D_.cols() - C_.rows()); }
  const Mat& measurement_C() const { return C_; }

 private:
  Mat A_, B_, D_, C_;
};

}  // namespace hinf
