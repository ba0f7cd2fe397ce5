#include "hinf/models/planar_vtol.hpp"

#include <cmath>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "models/vehicle_parts.hpp"

namespace hinf {

PlanarVtol::PlanarVtol(const PlanarVtolParameters& parameters) : p_(parameters) {
  detail::check_nonnegative(p_.g, "PlanarVtol", "g", "gravity");
  require(std::isfinite(p_.epsilon), "PlanarVtol: the coupling coefficient epsilon must be finite, got ",
          p_.epsilon, "; give a small number (0 for no coupling)");
}

void PlanarVtol::f(double, const ConstVecRef& q, VecRef out) const {
  out[0] = q[3];
  out[1] = q[4];
  out[2] = q[5];
  out[3] = 0.0;
  out[4] = -p_.g;
  out[5] = 0.0;
}

void PlanarVtol::dfdq(double, const ConstVecRef&, MatRef J) const {
  J.setZero();
  J(0, 3) = J(1, 4) = J(2, 5) = 1.0;
}

Mat PlanarVtol::G(double, const ConstVecRef& q) const {
  const double c = std::cos(q[2]), s = std::sin(q[2]);
  Mat G = Mat::Zero(6, 2);
  G(3, 0) = -s;
  G(3, 1) = p_.epsilon * c;
  G(4, 0) = c;
  G(4, 1) = p_.epsilon * s;
  G(5, 1) = 1.0;
  return G;
}

// G(q) u = [0, 0, 0, -u1 s + eps u2 c, u1 c + eps u2 s, u2]: only the theta column.
void PlanarVtol::dGudq(double, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const {
  const double c = std::cos(q[2]), s = std::sin(q[2]);
  out.setZero();
  out(3, 2) = -u[0] * c - p_.epsilon * u[1] * s;
  out(4, 2) = -u[0] * s + p_.epsilon * u[1] * c;
}

Mat PlanarVtol::D(double, const ConstVecRef&) const { return detail::disturbance_on_rows(3, Mat::Identity(3, 3)); }

Mat PlanarVtol::C(double) const { return detail::pick_rows(0, 1, 2); }

}  // namespace hinf
