// A fleet: k independent copies of one model stacked into a block-diagonal model.
//
// The state is q = [q_1; ...; q_k] (vehicle i's states at rows i n_1 .. (i+1) n_1 - 1), likewise
// u and w; f, df/dq, G, D, C and the error split are block-diagonal in the member's. The
// vehicles are not coupled, so a fleet's design is k single designs; it exists as a test bed for
// the cost of the Riccati solves in the state size (n = k n_1) on a time-varying system, and
// for controllers designed on the joint state. The fleet's position components are those of
// every vehicle (the position-error metrics are norms over the fleet); it has no single heading
// (heading_index() = -1: tracking errors of headings are not wrapped).
#pragma once

#include <string>
#include <vector>

#include "hinf/models/model.hpp"

namespace hinf {

class FleetModel final : public Model {
 public:
  // InputError unless member is set and count >= 1 (with count times its size within
  // kMaxDimension).
  FleetModel(ModelPtr member, int count);

  // The model of one vehicle, and the number of vehicles.
  const ModelPtr& member() const { return member_; }
  int count() const { return count_; }

  std::string name() const override;
  int n() const override { return count_ * n1_; }
  int m() const override { return count_ * m1_; }
  int nw() const override { return count_ * nw1_; }
  void f(double t, const ConstVecRef& q, VecRef out) const override;
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override;
  Mat G(double t, const ConstVecRef& q) const override;
  Mat D(double t, const ConstVecRef& q) const override;
  bool constant_input_matrices() const override { return member_->constant_input_matrices(); }
  bool state_dependent_inputs() const override { return member_->state_dependent_inputs(); }
  void dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const override;
  std::string jacobian_method() const override { return member_->jacobian_method(); }
  void error_split(double t, const ConstVecRef& q_d, const ConstVecRef& u_d, const ConstVecRef& q_e, MatRef A,
                   VecRef alpha) const override;
  Mat C(double t) const override;
  std::vector<int> noise_channels() const override;
  // The largest of the members' bounds: |r_i| <= L_i |q_e,i|^2 for each vehicle gives
  // |r| <= max L_i sum |q_e,i|^2 = max L_i |q_e|^2.
  double remainder_bound(double t, const ConstVecRef& q_d, double radius) const override;
  // The member's names with the vehicle's number: "x_1", ..., "x_k".
  std::vector<std::string> state_names() const override;
  std::vector<int> position_indices() const override;
  int heading_index() const override { return -1; }
  // The member's groups, once per vehicle.
  std::vector<int> uncoupled_blocks() const override;
  // The same count of the same member.
  bool same_as(const Model& other) const override;

 private:
  ModelPtr member_;
  int count_;
  int n1_, m1_, nw1_;
};

}  // namespace hinf
