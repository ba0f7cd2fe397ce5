// Dense output of an ODE solve: one polynomial piece per integrator step.
//
// Piece k covers the step from t_k to e_k (e_k < t_k for backward integration) and is
//     y(t) = sum_{j=0..d_k} c_kj theta^j,   theta = (t - t_k) / (e_k - t_k) in [0, 1],
// with c_kj in R^p. The pieces come from the integrator's own interpolant (Dormand-Prince
// dense output, CVODE's Nordsieck history), so y(t) has the integrator's accuracy at every t,
// and their ends are the integrator's own step ends, so the first and last pieces reach the
// ends of the integration exactly. At a time shared by several pieces (a step end, or steps
// shorter than the spacing of doubles) the piece first in integration order is used: y at the
// start of the integration is the initial value exactly.
// Lookups take an optional cursor (index of the last piece used) so that a sweep over sorted
// times costs O(1) per lookup; without it a binary search is used. Const lookups without a
// cursor are thread-safe.
#pragma once

#include <cstddef>
#include <vector>

#include "hinf/numerics/dense_piece.hpp"

namespace hinf {

// The dense output y(t) in R^dim of one solve: one polynomial piece per integrator step.
class PiecewisePolynomial {
 public:
  explicit PiecewisePolynomial(int dim = 0);

  // The number of components of y.
  int dim() const { return dim_; }
  // The number of pieces (integrator steps).
  std::size_t num_pieces() const { return t_start_.size(); }
  // True before the first piece is appended.
  bool empty() const { return t_start_.empty(); }
  // The interval covered, [t_min, t_max] (s).
  double t_min() const;
  double t_max() const;

  // Adds a step's piece (of this dimension); pieces must be appended in integration order.
  void append(const DensePiece& piece);
  // Orders the pieces by increasing time (needed after a backward integration).
  void finalize();

  // Piece k (0 <= k < num_pieces(), in increasing time once finalized), valid while this object
  // lives unchanged: appending the pieces in that order rebuilds an identical dense output.
  DensePiece piece(std::size_t k) const { return {t_start_[k], t_end_[k], degree_[k], dim_, coefficients(k)}; }

  // y(t) into out (dim numbers); t outside [t_min, t_max] is an InputError.
  void eval(double t, double* out, std::size_t* cursor = nullptr) const;
  // dy/dt at t (per second) into out: the derivative of the piece's polynomial.
  void eval_derivative(double t, double* out, std::size_t* cursor = nullptr) const;

  // The ends of the pieces, increasing (num_pieces + 1 values).
  std::vector<double> breakpoints() const;
  // Bytes of the stored solution (coefficients and piece data).
  std::size_t memory_bytes() const;

 private:
  std::size_t locate(double t, std::size_t* cursor) const;
  double theta(std::size_t k, double t) const;
  const double* coefficients(std::size_t k) const {
    return blocks_[offset_[k] >> block_shift_].data() + (offset_[k] & ((std::size_t{1} << block_shift_) - 1));
  }

  int dim_;
  std::vector<double> t_start_, t_end_;
  std::vector<int> degree_;
  // Coefficients live in fixed-size blocks that never move once allocated, so appending never
  // copies what is stored (a solve of unknown length grows without reallocation); offset_ is
  // block << block_shift_ | position in the block.
  int block_shift_ = 14;
  std::vector<std::vector<double>> blocks_;
  std::size_t used_ = 0;  // numbers stored
  std::vector<std::size_t> offset_;
  // lower_[k] = min(t_k, e_k), upper_[k] = max(t_k, e_k), both increasing once finalized.
  std::vector<double> lower_, upper_;
  bool backward_ = false;  // integrated toward decreasing t (the pieces were reversed)
};

}  // namespace hinf
