// Numerical Jacobians, for models and controllers that do not give analytic ones.
//
//   central differences  column j = (F(x + h_j e_j) - F(x - h_j e_j)) / (2 h_j),
//                        h_j = eps^(1/3) max(1, |x_j|): the truncation error O(h^2) and the
//                        round-off O(eps / h) balance there, so a column is good to about
//                        eps^(2/3) (5e-11) of the scale of F and its third derivative.
//   complex step         column j = Im F(x + i h e_j) / h, h = 1e-20: no difference is taken,
//                        so there is no cancellation and the Jacobian is exact to round-off, for
//                        an F that is analytic and written to accept complex arguments (no abs,
//                        no comparisons, no real-only functions in its path).
// Each costs 2n (central) or n (complex step) evaluations of F for x of n numbers. A value of F
// of another size than `rows` is an InputError.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "hinf/core/errors.hpp"
#include "hinf/core/types.hpp"

namespace hinf {

// The Jacobian (rows x n) of F at x by central differences; F(const Vec&) returns `rows` numbers.
template <class Function>
Mat central_difference_jacobian(const Vec& x, Eigen::Index rows, const Function& F) {
  const double base_step = std::cbrt(std::numeric_limits<double>::epsilon());
  Mat J(rows, x.size());
  Vec point = x;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    const double h = base_step * std::max(1.0, std::abs(x[j]));
    point[j] = x[j] + h;
    const Vec ahead = F(point);
    point[j] = x[j] - h;
    const Vec behind = F(point);
    point[j] = x[j];
    require(ahead.size() == rows && behind.size() == rows, "central differences: the function returned ",
            ahead.size(), " numbers, expected ", rows);
    J.col(j) = (ahead - behind) / (2.0 * h);
  }
  return J;
}

// The Jacobian (rows x n) of F at x by the complex step; F(const Eigen::VectorXcd&) returns
// `rows` complex numbers.
template <class Function>
Mat complex_step_jacobian(const Vec& x, Eigen::Index rows, const Function& F) {
  constexpr double h = 1e-20;
  Mat J(rows, x.size());
  Eigen::VectorXcd point = x.cast<std::complex<double>>();
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    point[j] = std::complex<double>(x[j], h);
    const Eigen::VectorXcd value = F(point);
    point[j] = x[j];
    require(value.size() == rows, "complex step: the function returned ", value.size(), " numbers, expected ", rows);
    J.col(j) = value.imag() / h;
  }
  return J;
}

}  // namespace hinf
