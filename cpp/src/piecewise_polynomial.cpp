#include "hinf/piecewise_polynomial.hpp"

#include <algorithm>
#include <cmath>

#include "hinf/errors.hpp"

namespace hinf {

double PiecewisePolynomial::t_min() const {
  if (empty()) throw InputError("dense output is empty");
  return lower_.front();
}

double PiecewisePolynomial::t_max() const {
  if (empty()) throw InputError("dense output is empty");
  return lower_.back() + std::abs(h_.back());
}

PiecewisePolynomial::PiecewisePolynomial(int dim) : dim_(dim) {
  // A block holds at least 16 pieces of the highest degree (12, CVODE Adams).
  while ((std::size_t{1} << block_shift_) < static_cast<std::size_t>(16 * 13 * std::max(dim, 1))) ++block_shift_;
}

void PiecewisePolynomial::append(double t_start, double h, int degree, const double* coeffs) {
  const std::size_t count = static_cast<std::size_t>((degree + 1) * dim_);
  const std::size_t block_size = std::size_t{1} << block_shift_;
  if (blocks_.empty() || blocks_.back().size() + count > block_size) {
    blocks_.emplace_back();
    blocks_.back().reserve(block_size);
  }
  std::vector<double>& block = blocks_.back();
  offset_.push_back(((blocks_.size() - 1) << block_shift_) | block.size());
  block.insert(block.end(), coeffs, coeffs + count);
  used_ += count;
  t_start_.push_back(t_start);
  h_.push_back(h);
  degree_.push_back(degree);
  lower_.push_back(std::min(t_start, t_start + h));
}

void PiecewisePolynomial::finalize() {
  if (num_pieces() < 2 || lower_.front() < lower_.back()) return;
  std::reverse(t_start_.begin(), t_start_.end());
  std::reverse(h_.begin(), h_.end());
  std::reverse(degree_.begin(), degree_.end());
  std::reverse(offset_.begin(), offset_.end());
  std::reverse(lower_.begin(), lower_.end());
}

std::size_t PiecewisePolynomial::locate(double t, std::size_t* cursor) const {
  const std::size_t count = num_pieces();
  // Fast path: a sweep over sorted times stays in the cursor's piece or moves to a neighbour.
  if (cursor != nullptr && *cursor < count) {
    std::size_t k = *cursor;
    for (int tries = 0; tries < 3; ++tries) {
      const double a = lower_[k];
      if (t >= a && t <= a + std::abs(h_[k])) {  // false for NaN: the range check below
        *cursor = k;
        return k;
      }
      if (t < a && k > 0) --k;
      else if (t > a && k + 1 < count) ++k;
      else break;
    }
  }
  if (count == 0) throw InputError("dense output is empty");
  const double lo = t_min(), hi = t_max();
  const double slack = 1e-12 * std::max({1.0, std::abs(lo), std::abs(hi)});
  if (!(t >= lo - slack && t <= hi + slack))
    throw InputError(str_cat("t = ", t, " is outside the solved interval [", lo, ", ", hi, "]"));
  std::size_t k = static_cast<std::size_t>(std::upper_bound(lower_.begin(), lower_.end(), t) -
                                           lower_.begin());
  k = k == 0 ? 0 : k - 1;
  if (cursor != nullptr) *cursor = k;
  return k;
}

double PiecewisePolynomial::theta(std::size_t k, double t) const {
  return (t - t_start_[k]) / h_[k];
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
  const std::size_t k = locate(t, cursor);
  const double th = theta(k, t);
  const int d = degree_[k];
  const double* c = coefficients(k);
  for (int i = 0; i < dim_; ++i) out[i] = 0.0;
  for (int j = d; j >= 1; --j) {
    const double* cj = c + static_cast<std::size_t>(j * dim_);
    for (int i = 0; i < dim_; ++i) out[i] = out[i] * th + j * cj[i];
  }
  const double inv_h = 1.0 / h_[k];
  for (int i = 0; i < dim_; ++i) out[i] *= inv_h;
}

std::vector<double> PiecewisePolynomial::breakpoints() const {
  std::vector<double> points(lower_);
  if (!empty()) points.push_back(t_max());
  return points;
}

std::size_t PiecewisePolynomial::memory_bytes() const {
  return sizeof(double) * (used_ + t_start_.size() + h_.size() + lower_.size()) +
         sizeof(int) * degree_.size() + sizeof(std::size_t) * offset_.size();
}

}  // namespace hinf
