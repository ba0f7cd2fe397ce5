// A planar hovercraft in inertial coordinates (its input matrix depends on the heading).
// State order, units and what the built-in vehicles share: models/vehicles.hpp.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/builtin_vehicle.hpp"
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

// Its equations are generated from its statement (python/hinf_cpp/models/builtin.py,
// hovercraft(); models/builtin_vehicle.hpp).
class Hovercraft final : public BuiltinVehicle {
 public:
  // InputError unless d and d_r are finite and >= 0.
  explicit Hovercraft(const HovercraftParameters& parameters = {});
  // The parameters it was made with.
  const HovercraftParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kHovercraftParameterKeys);
  }

 private:
  HovercraftParameters p_;
};

}  // namespace hinf
