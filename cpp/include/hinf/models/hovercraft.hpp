// A planar hovercraft in inertial coordinates (its input matrix depends on the heading).
// State order, units and what the built-in vehicles share: models/vehicles.hpp.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/model.hpp"

namespace hinf {

// A planar hovercraft in inertial coordinates (the model of Aguiar, Cremean and Hespanha,
// "Position tracking for a nonlinear underactuated hovercraft: controller design and
// experimental results", IEEE CDC 2003; and of Fantoni, Lozano, Mazenc and Pettersen,
// "Stabilization of a nonlinear underactuated hovercraft", Int. J. Robust Nonlinear Control
// 10(8), 2000), with inputs per unit mass and inertia, u = [F, T]:
//     dvx/dt = F cos(psi) - d vx + w1,   dvy/dt = F sin(psi) - d vy + w2,   dr/dt = T - d_r r + w3,
//     dx/dt = vx,   dy/dt = vy,   dpsi/dt = r.
// No force across the body axis: the thrust acts along the heading. G depends on psi.
struct HovercraftParameters {
  double d = 0.2;    // translational damping per unit mass (1/s), >= 0
  double d_r = 0.5;  // rotational damping per unit inertia (1/s), >= 0
};
// The parameters by their scenario-file keys (the reader, the writer, named_parameters()).
inline constexpr std::array<std::pair<const char*, double HovercraftParameters::*>, 2> kHovercraftParameterKeys{
    {{"d", &HovercraftParameters::d}, {"d_r", &HovercraftParameters::d_r}}};

class Hovercraft final : public Model {
 public:
  // InputError unless d and d_r are finite and >= 0.
  explicit Hovercraft(const HovercraftParameters& parameters = {});
  const HovercraftParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kHovercraftParameterKeys);
  }
  bool same_as(const Model& other) const override { return same_type_and_parameters(*this, other); }

  std::string name() const override { return "hovercraft"; }
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
  std::vector<std::string> state_names() const override { return {"x", "y", "psi", "vx", "vy", "r"}; }
  std::vector<int> position_indices() const override { return {0, 1}; }
  int heading_index() const override { return 2; }

 private:
  HovercraftParameters p_;
};

}  // namespace hinf
