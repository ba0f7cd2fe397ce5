#include "hinf/models/fleet.hpp"

#include <algorithm>
#include <cmath>

#include "hinf/core/checks.hpp"

namespace hinf {

namespace {

// Block-diagonal matrix of count copies of block.
Mat block_diagonal(const Mat& block, int count) {
  Mat out = Mat::Zero(count * block.rows(), count * block.cols());
  for (int i = 0; i < count; ++i) out.block(i * block.rows(), i * block.cols(), block.rows(), block.cols()) = block;
  return out;
}

// Block-diagonal matrix of the blocks matrix(i) (rows x cols each), i = 0 .. count - 1.
template <class Block>
Mat block_diagonal(int count, int rows, int cols, const Block& matrix) {
  Mat out = Mat::Zero(count * rows, count * cols);
  for (int i = 0; i < count; ++i) out.block(i * rows, i * cols, rows, cols) = matrix(i);
  return out;
}

}  // namespace

FleetModel::FleetModel(ModelPtr member, int count) : member_(std::move(member)), count_(count) {
  require(member_ != nullptr, "FleetModel: no member model given");
  require(count_ >= 1, "FleetModel: the number of vehicles must be at least 1, got ", count_);
  n1_ = member_->n(), m1_ = member_->m(), nw1_ = member_->nw();
  require(static_cast<long>(count_) * std::max({n1_, m1_, nw1_}) <= kMaxDimension, "FleetModel: ", count_,
          " vehicles of ", n1_, " states, ", m1_, " inputs and ", nw1_, " disturbance channels exceed the ",
          kMaxDimension, " components the library sizes arrays for");
}

std::vector<int> FleetModel::uncoupled_blocks() const {
  const std::vector<int> one = member_->uncoupled_blocks();
  std::vector<int> blocks;
  for (int i = 0; i < count_; ++i) blocks.insert(blocks.end(), one.begin(), one.end());
  return blocks;
}

std::string FleetModel::name() const { return str_cat("fleet of ", count_, " ", member_->name()); }

void FleetModel::f(double t, const ConstVecRef& q, VecRef out) const {
  for (int i = 0; i < count_; ++i) member_->f(t, q.segment(i * n1_, n1_), out.segment(i * n1_, n1_));
}

void FleetModel::dfdq(double t, const ConstVecRef& q, MatRef out) const {
  out.setZero();
  for (int i = 0; i < count_; ++i)
    member_->dfdq(t, q.segment(i * n1_, n1_), out.block(i * n1_, i * n1_, n1_, n1_));
}

Mat FleetModel::G(double t, const ConstVecRef& q) const {
  return block_diagonal(count_, n1_, m1_, [&](int i) { return member_->G(t, q.segment(i * n1_, n1_)); });
}
Mat FleetModel::D(double t, const ConstVecRef& q) const {
  return block_diagonal(count_, n1_, nw1_, [&](int i) { return member_->D(t, q.segment(i * n1_, n1_)); });
}
Mat FleetModel::C(double t) const { return block_diagonal(member_->C(t), count_); }

void FleetModel::dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const {
  out.setZero();
  for (int i = 0; i < count_; ++i)
    member_->dGudq(t, q.segment(i * n1_, n1_), u.segment(i * m1_, m1_), out.block(i * n1_, i * n1_, n1_, n1_));
}

void FleetModel::error_split(double t, const ConstVecRef& q_d, const ConstVecRef& u_d, const ConstVecRef& q_e,
                             MatRef A, VecRef alpha) const {
  A.setZero();
  for (int i = 0; i < count_; ++i)
    member_->error_split(t, q_d.segment(i * n1_, n1_), u_d.segment(i * m1_, m1_), q_e.segment(i * n1_, n1_),
                         A.block(i * n1_, i * n1_, n1_, n1_), alpha.segment(i * n1_, n1_));
}

std::vector<int> FleetModel::noise_channels() const {
  std::vector<int> out;
  const std::vector<int> one = member_->noise_channels();
  for (int i = 0; i < count_; ++i)
    for (const int channel : one) out.push_back(i * nw1_ + channel);
  return out;
}

double FleetModel::remainder_bound(double t, const ConstVecRef& q_d, double radius) const {
  double bound = 0.0;
  for (int i = 0; i < count_; ++i) {
    const double member_bound = member_->remainder_bound(t, q_d.segment(i * n1_, n1_), radius);
    if (std::isnan(member_bound)) return NAN;  // the member has no bound
    bound = std::max(bound, member_bound);
  }
  return bound;
}

std::vector<std::string> FleetModel::state_names() const {
  std::vector<std::string> out;
  const std::vector<std::string> one = member_->state_names();
  for (int i = 0; i < count_; ++i)
    for (const std::string& name : one) out.push_back(str_cat(name, "_", i + 1));
  return out;
}

std::vector<int> FleetModel::position_indices() const {
  std::vector<int> out;
  const std::vector<int> one = member_->position_indices();
  for (int i = 0; i < count_; ++i)
    for (const int index : one) out.push_back(i * n1_ + index);
  return out;
}

bool FleetModel::same_as(const Model& other) const {
  const auto* fleet = dynamic_cast<const FleetModel*>(&other);
  return fleet != nullptr && fleet->count_ == count_ && member_->same_as(*fleet->member_);
}

}  // namespace hinf
