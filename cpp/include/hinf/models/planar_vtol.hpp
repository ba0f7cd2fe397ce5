// The planar VTOL aircraft of Hauser, Sastry and Meyer (its input matrix depends on the roll angle).
// State order, units and what the built-in vehicles share: models/vehicles.hpp.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hinf/models/builtin_vehicle.hpp"
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

// Its equations are generated from its statement (python/hinf_cpp/models/builtin.py, pvtol();
// models/builtin_vehicle.hpp).
class PlanarVtol final : public BuiltinVehicle {
 public:
  // InputError unless g is finite and >= 0 and epsilon finite.
  explicit PlanarVtol(const PlanarVtolParameters& parameters = {});
  // The parameters it was made with.
  const PlanarVtolParameters& parameters() const { return p_; }
  std::vector<std::pair<std::string, double>> named_parameters() const override {
    return named_parameters_of(p_, kPlanarVtolParameterKeys);
  }

 private:
  PlanarVtolParameters p_;
};

}  // namespace hinf
