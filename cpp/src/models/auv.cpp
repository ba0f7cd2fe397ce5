#include "hinf/models/auv.hpp"

#include <cmath>

#include "hinf/core/errors.hpp"
#include "models/compiled_in.hpp"
#include "models/parameter_checks.hpp"

namespace hinf {

namespace {

const AuvParameters& checked(const AuvParameters& p) {
  detail::check_positive(p.m11, "Auv", "m11", "surge mass");
  detail::check_positive(p.m22, "Auv", "m22", "sway mass");
  detail::check_positive(p.m33, "Auv", "m33", "yaw inertia");
  detail::check_nonnegative(p.X_u, "Auv", "X_u", "linear surge drag");
  detail::check_nonnegative(p.X_uu, "Auv", "X_uu", "quadratic surge drag");
  detail::check_nonnegative(p.Y_v, "Auv", "Y_v", "linear sway drag");
  detail::check_nonnegative(p.Y_vv, "Auv", "Y_vv", "quadratic sway drag");
  detail::check_nonnegative(p.N_r, "Auv", "N_r", "linear yaw drag");
  detail::check_nonnegative(p.N_rr, "Auv", "N_rr", "quadratic yaw drag");
  return p;
}

}  // namespace

Auv::Auv(const AuvParameters& parameters)
    : BuiltinVehicle(detail::compiled_in_model(hinf_auv_model, named_parameters_of(checked(parameters), kAuvParameterKeys))),
      p_(parameters) {}

}  // namespace hinf
