// Eigen aliases and the packed storage of symmetric matrices used throughout hinf_cpp.
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

namespace hinf {

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;
// Time series are stored one sample per row (NumPy's (n_times, n) layout).
using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using VecRef = Eigen::Ref<Vec>;
using ConstVecRef = Eigen::Ref<const Vec>;
using MatRef = Eigen::Ref<Mat>;
using ConstMatRef = Eigen::Ref<const Mat>;

// A symmetric n x n matrix is stored as its upper triangle, column by column:
// (0,0), (0,1), (1,1), (0,2), (1,2), (2,2), ...  -- n(n+1)/2 numbers.
constexpr int packed_size(int n) { return n * (n + 1) / 2; }
// Position of S(i, j) (= S(j, i)) in the packed storage.
constexpr int packed_index(int i, int j) {
  return i <= j ? j * (j + 1) / 2 + i : i * (i + 1) / 2 + j;
}

template <class Matrix>
void pack_symmetric(const Matrix& S, double* packed) {
  const int n = static_cast<int>(S.rows());
  int k = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= j; ++i) packed[k++] = S(i, j);
}

template <class Matrix>
void unpack_symmetric(const double* packed, Matrix& S) {
  const int n = static_cast<int>(S.rows());
  int k = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= j; ++i) {
      S(i, j) = packed[k];
      S(j, i) = packed[k];
      ++k;
    }
}

// Scratch space for one packed symmetric n x n matrix: on the stack up to n = 16, on the heap
// beyond (lookups in hot loops should not allocate for the usual sizes).
class PackedScratch {
 public:
  explicit PackedScratch(int n) : size_(packed_size(n)) {
    if (size_ > kOnStack) heap_.resize(static_cast<std::size_t>(size_));
  }
  double* data() { return size_ > kOnStack ? heap_.data() : stack_; }

 private:
  static constexpr int kOnStack = packed_size(16);
  int size_;
  double stack_[kOnStack];
  std::vector<double> heap_;
};

}  // namespace hinf
