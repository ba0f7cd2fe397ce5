#include "hinf/models/hovercraft.hpp"

#include <cmath>

#include "hinf/core/errors.hpp"
#include "models/compiled_in.hpp"
#include "models/parameter_checks.hpp"

namespace hinf {

namespace {

const HovercraftParameters& checked(const HovercraftParameters& p) {
  detail::check_nonnegative(p.d, "Hovercraft", "d", "translational damping");
  detail::check_nonnegative(p.d_r, "Hovercraft", "d_r", "rotational damping");
  return p;
}

}  // namespace

Hovercraft::Hovercraft(const HovercraftParameters& parameters)
    : BuiltinVehicle(detail::compiled_in_model(hinf_hovercraft_model, named_parameters_of(checked(parameters), kHovercraftParameterKeys))),
      p_(parameters) {}

}  // namespace hinf
