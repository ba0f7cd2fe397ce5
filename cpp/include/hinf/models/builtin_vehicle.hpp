// The base of the built-in vehicles (models/ship.hpp, models/vehicles.hpp): their equations are
// the C code that CasADi generates from each vehicle's statement (python/hinf_cpp/models/builtin.py)
// and that is compiled into the library (cpp/src/models/generated), so a vehicle is stated once
// for the C++ core, the planner and a C export alike. f, df/dq (by automatic differentiation,
// exact), G, D, d(G u)/dq, C, the error split and the structure (name, sizes, state names,
// position, heading, noise channels) all come from it; each vehicle class adds its parameters
// (a struct, its checks, its scenario-file keys) and what an expression cannot carry (the
// ship's analytic remainder bound).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hinf/models/generated_model.hpp"
#include "hinf/models/model.hpp"

namespace hinf {

class BuiltinVehicle : public Model {
 public:
  std::string name() const override { return equations_->name(); }
  int n() const override { return equations_->n(); }
  int m() const override { return equations_->m(); }
  int nw() const override { return equations_->nw(); }
  void f(double t, const ConstVecRef& q, VecRef out) const override { equations_->f(t, q, out); }
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override { equations_->dfdq(t, q, out); }
  std::string jacobian_method() const override { return equations_->jacobian_method(); }
  Mat G(double t, const ConstVecRef& q) const override { return equations_->G(t, q); }
  Mat D(double t, const ConstVecRef& q) const override { return equations_->D(t, q); }
  bool constant_input_matrices() const override { return equations_->constant_input_matrices(); }
  bool state_dependent_inputs() const override { return equations_->state_dependent_inputs(); }
  void dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const override {
    equations_->dGudq(t, q, u, out);
  }
  void error_split(double t, const ConstVecRef& q_d, const ConstVecRef& u_d, const ConstVecRef& q_e, MatRef A,
                   VecRef alpha) const override {
    equations_->error_split(t, q_d, u_d, q_e, A, alpha);
  }
  Mat C(double t) const override { return equations_->C(t); }
  std::vector<int> noise_channels() const override { return equations_->noise_channels(); }
  std::vector<std::string> state_names() const override { return equations_->state_names(); }
  std::vector<int> position_indices() const override { return equations_->position_indices(); }
  int heading_index() const override { return equations_->heading_index(); }
  // The same vehicle with the same parameters.
  bool same_as(const Model& other) const override { return same_type_and_parameters(*this, other); }

 protected:
  explicit BuiltinVehicle(std::shared_ptr<const GeneratedModel> equations) : equations_(std::move(equations)) {}

 private:
  std::shared_ptr<const GeneratedModel> equations_;
};

}  // namespace hinf
