// A constant matrix kept as the list of its nonzeros, for the input and disturbance matrices
// B and D (mostly zeros and ones) whose products sit in hot right-hand sides.
#pragma once

#include <vector>

#include "hinf/core/types.hpp"

namespace hinf {

class SparseMatrix {
 public:
  SparseMatrix() = default;
  explicit SparseMatrix(const Mat& M) : rows_(static_cast<int>(M.rows())), cols_(static_cast<int>(M.cols())) {
    for (int j = 0; j < cols_; ++j)
      for (int i = 0; i < rows_; ++i)
        if (M(i, j) != 0.0) entries_.push_back({i, j, M(i, j)});
  }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  // y += M x
  void add_product(const double* x, double* y) const {
    for (const Entry& e : entries_) y[e.row] += e.value * x[e.col];
  }
  // f(row, col, value) for every nonzero.
  template <class F>
  void for_each(F&& f) const {
    for (const Entry& e : entries_) f(e.row, e.col, e.value);
  }

 private:
  struct Entry {
    int row, col;
    double value;
  };
  int rows_ = 0, cols_ = 0;
  std::vector<Entry> entries_;
};

}  // namespace hinf
