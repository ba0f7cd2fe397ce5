// The planar VTOL aircraft of Hauser, Sastry and Meyer (its input matrix depends on the roll angle).
// State order, units and what the built-in vehicles share: models/vehicles.hpp.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/model.hpp"

namespace hinf {

// The planar vertical take-off and landing aircraft of Hauser, Sastry and Meyer, "Nonlinear
// control design for slightly non-minimum phase systems: application to V/STOL aircraft",
// Automatica 28(4), 665-679, 1992, in their normalized form, u = [u1, u2] (thrust, rolling
// moment):
//     x_ddot = -u1 sin(theta) + epsilon u2 cos(theta) + w1,
//     y_ddot =  u1 cos(theta) + epsilon u2 sin(theta) - g + w2,
//     theta_ddot = u2 + w3.
// Gravity is part of f; G depends on theta. epsilon couples the rolling moment into the lateral
// acceleration (the slightly non-minimum-phase effect).
struct PlanarVtolParameters {
  double g = 1.0;        // gravity (1: the normalized form), >= 0
  double epsilon = 0.1;  // coupling of the rolling moment into the translation, finite
};
// The parameters by their scenario-file keys (the reader, the writer, named_parameters()).
inline constexpr std::array<std::pair<const char*, double PlanarVtolParameters::*>, 2> kPlanarVtolParameterKeys{
    {{"g", &PlanarVtolParameters::g}, {"epsilon", &PlanarVtolParameters::epsilon}}};

class PlanarVtol final : public Model {
 public:
  // InputError unless g is finite and >= 0 and epsilon finite.
  explicit PlanarVtol(const PlanarVtolParameters& parameters = {});
  const PlanarVtolParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kPlanarVtolParameterKeys);
  }
  bool same_as(const Model& other) const override { return same_type_and_parameters(*this, other); }

  std::string name() const override { return "pvtol"; }
  int n() const override { return 6; }
  int m() const override { return 2; }
  int nw() const override { return 6; }
  void f(double t, const ConstVecRef& q, VecRef out) const override;
  void dfdq(double t, const ConstVecRef& q, MatRef out) const override;
  Mat G(double t, const ConstVecRef& q) const override;
  Mat D(double t, const ConstVecRef& q) const override;
  bool constant_input_matrices() const override { return false; }
  bool state_dependent_inputs() const override { return true; }
  void dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const override;
  Mat C(double t) const override;
  std::vector<int> noise_channels() const override { return {3, 4, 5}; }
  std::vector<std::string> state_names() const override {
    return {"x", "y", "theta", "x_dot", "y_dot", "theta_dot"};
  }
  std::vector<int> position_indices() const override { return {0, 1}; }
  int heading_index() const override { return 2; }

 private:
  PlanarVtolParameters p_;
};

}  // namespace hinf
