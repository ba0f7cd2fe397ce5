#include "hinf/numerics/piecewise_polynomial.hpp"

#include <algorithm>
#include <cmath>

#include "hinf/core/errors.hpp"

namespace hinf {

double PiecewisePolynomial::t_min() const {
  if (empty()) throw InputError("dense output is empty");
  return lower_.front();
}

double PiecewisePolynomial::t_max() const {
  if (empty()) throw InputError("dense output is empty");
  return upper_.back();
}

PiecewisePolynomial::PiecewisePolynomial(int dim) : dim_(dim) {
  // A block holds at least 16 pieces of the highest degree (12, CVODE Adams).
  while ((std::size_t{1} << block_shift_) < static_cast<std::size_t>(16 * 13 * std::max(dim, 1))) ++block_shift_;
}

void PiecewisePolynomial::append(const DensePiece& piece) {
  require(piece.dim == dim_, "dense output of dimension ", dim_, " given a piece of dimension ", piece.dim);
  const std::size_t count = static_cast<std::size_t>((piece.degree + 1) * dim_);
  const std::size_t block_size = std::size_t{1} << block_shift_;
  if (blocks_.empty() || blocks_.back().size() + count > block_size) {
    blocks_.emplace_back();
    blocks_.back().reserve(block_size);
  }
  std::vector<double>& block = blocks_.back();
  offset_.push_back(((blocks_.size() - 1) << block_shift_) | block.size());
  block.insert(block.end(), piece.coeffs, piece.coeffs + count);
  used_ += count;
  t_start_.push_back(piece.t_start);
  t_end_.push_back(piece.t_end);
  degree_.push_back(piece.degree);
  lower_.push_back(std::min(piece.t_start, piece.t_end));
  upper_.push_back(std::max(piece.t_start, piece.t_end));
  if (piece.t_end < piece.t_start) backward_ = true;
}

void PiecewisePolynomial::finalize() {
  if (!backward_ || num_pieces() < 2 || lower_.front() < lower_.back()) return;
  std::reverse(t_start_.begin(), t_start_.end());
  std::reverse(t_end_.begin(), t_end_.end());
  std::reverse(degree_.begin(), degree_.end());
  std::reverse(offset_.begin(), offset_.end());
  std::reverse(lower_.begin(), lower_.end());
  std::reverse(upper_.begin(), upper_.end());
}

std::size_t PiecewisePolynomial::locate(double t, std::size_t* cursor) const {
  const std::size_t count = num_pieces();
  // Fast path: a sweep over sorted times stays in the cursor's piece or moves to a neighbour.
  // A time on a piece's end goes to the binary search, which settles ties.
  if (cursor != nullptr && *cursor < count) {
    std::size_t k = *cursor;
    for (int tries = 0; tries < 3; ++tries) {
      if (t < lower_[k]) {
        if (k == 0) break;
        --k;
      } else if (t > upper_[k]) {
        if (k + 1 == count) break;
        ++k;
      } else if (t > lower_[k] && t < upper_[k]) {  // (false for NaN: the search below refuses it)
        *cursor = k;
        return k;
      } else {
        break;
      }
    }
  }
  if (count == 0) throw InputError("dense output is empty");
  const double lo = t_min(), hi = t_max();
  const double slack = 1e-12 * std::max({1.0, std::abs(lo), std::abs(hi)});
  if (!(t >= lo - slack && t <= hi + slack))
    throw InputError(str_cat("t = ", t, " is outside the solved interval [", lo, ", ", hi, "]"));
  std::size_t k;
  if (backward_) {
    // First in integration order = the last piece (in increasing time) starting at or before t.
    k = static_cast<std::size_t>(std::upper_bound(lower_.begin(), lower_.end(), t) - lower_.begin());
    k = k == 0 ? 0 : k - 1;
  } else {
    // The first piece ending at or after t.
    k = static_cast<std::size_t>(std::lower_bound(upper_.begin(), upper_.end(), t) - upper_.begin());
    k = std::min(k, count - 1);
  }
  if (cursor != nullptr) *cursor = k;
  return k;
}

double PiecewisePolynomial::theta(std::size_t k, double t) const {
  return DensePiece{t_start_[k], t_end_[k], 0, 0, nullptr}.theta(t);
}

void PiecewisePolynomial::eval(double t, double* out, std::size_t* cursor) const {
  const std::size_t k = locate(t, cursor);
  const double th = theta(k, t);
  const int d = degree_[k];
  const double* c = coefficients(k);
  const double* top = c + static_cast<std::size_t>(d * dim_);
  for (int i = 0; i < dim_; ++i) out[i] = top[i];
  for (int j = d - 1; j >= 0; --j) {
    const double* cj = c + static_cast<std::size_t>(j * dim_);
    for (int i = 0; i < dim_; ++i) out[i] = out[i] * th + cj[i];
  }
}

void PiecewisePolynomial::eval_derivative(double t, double* out, std::size_t* cursor) const {
  std::size_t k = locate(t, cursor);
  // A step shorter than the spacing of doubles has no slope of its own: the next piece in
  // integration order that has a length gives it.
  while (t_end_[k] == t_start_[k]) {
    const std::size_t next = backward_ ? k - 1 : k + 1;
    if (k == (backward_ ? 0 : num_pieces() - 1) || lower_[next] > t || upper_[next] < t) break;
    k = next;
  }
  if (t_end_[k] == t_start_[k]) {
    for (int i = 0; i < dim_; ++i) out[i] = 0.0;
    return;
  }
  const double th = theta(k, t);
  const int d = degree_[k];
  const double* c = coefficients(k);
  for (int i = 0; i < dim_; ++i) out[i] = 0.0;
  for (int j = d; j >= 1; --j) {
    const double* cj = c + static_cast<std::size_t>(j * dim_);
    for (int i = 0; i < dim_; ++i) out[i] = out[i] * th + j * cj[i];
  }
  const double inv_h = 1.0 / (t_end_[k] - t_start_[k]);
  for (int i = 0; i < dim_; ++i) out[i] *= inv_h;
}

std::vector<double> PiecewisePolynomial::breakpoints() const {
  std::vector<double> points(lower_);
  if (!empty()) points.push_back(t_max());
  return points;
}

std::size_t PiecewisePolynomial::memory_bytes() const {
  return sizeof(double) * (used_ + t_start_.size() + t_end_.size() + lower_.size() + upper_.size()) +
         sizeof(int) * degree_.size() + sizeof(std::size_t) * offset_.size();
}

}  // namespace hinf
