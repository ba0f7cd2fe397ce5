#include "hinf/models/planar_vtol.hpp"

#include <cmath>

#include "hinf/core/errors.hpp"
#include "models/compiled_in.hpp"
#include "models/parameter_checks.hpp"

namespace hinf {

namespace {

const PlanarVtolParameters& checked(const PlanarVtolParameters& p) {
  detail::check_nonnegative(p.g, "PlanarVtol", "g", "gravity");
  require(std::isfinite(p.epsilon), "PlanarVtol: the coupling coefficient epsilon must be finite, got ", p.epsilon,
          "; give a small number (0 for no coupling)");
  return p;
}

}  // namespace

PlanarVtol::PlanarVtol(const PlanarVtolParameters& parameters)
    : BuiltinVehicle(detail::compiled_in_model(hinf_pvtol_model, named_parameters_of(checked(parameters), kPlanarVtolParameterKeys))),
      p_(parameters) {}

}  // namespace hinf
