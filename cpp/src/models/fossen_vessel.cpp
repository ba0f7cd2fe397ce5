#include "hinf/models/fossen_vessel.hpp"

#include <cmath>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"
#include "models/compiled_in.hpp"
#include "models/parameter_checks.hpp"

namespace hinf {

Mat FossenVesselParameters::supply_vessel_M() {
  Mat M(3, 3);
  M << 1.1274, 0.0, 0.0,  //
      0.0, 1.8902, -0.0744,  //
      0.0, -0.0744, 0.1278;
  return M;
}

Mat FossenVesselParameters::supply_vessel_D() {
  Mat D(3, 3);
  D << 0.0358, 0.0, 0.0,  //
      0.0, 0.1183, -0.0124,  //
      0.0, -0.0041, 0.0308;
  return D;
}

namespace {

// The parameters of the statement: M[i][j], D[i][j] and M_inv[i][j] = (M^-1)[i][j], computed here
// once so that the generated equations multiply by M^-1 (python/hinf_cpp/models/builtin.py).
detail::NamedValues statement_parameters(const FossenVesselParameters& p) {
  check_shape(p.M, 3, 3, "the FossenVessel mass matrix M");
  check_finite(p.M, "the FossenVessel mass matrix M");
  check_shape(p.D, 3, 3, "the FossenVessel damping matrix D");
  check_finite(p.D, "the FossenVessel damping matrix D");
  const double scale_M = p.M.cwiseAbs().maxCoeff();
  const double asymmetry = (p.M - p.M.transpose()).cwiseAbs().maxCoeff();
  require(asymmetry <= 1e-10 * scale_M, "FossenVessel: the mass matrix M must be symmetric (max |M - M'| = ",
          asymmetry, "): give the same value to M[i][j] and M[j][i] (m23 = m32 for a vessel at rest)");
  const double lambda_M = detail::smallest_symmetric_eigenvalue(p.M);
  require(lambda_M > 1e-12 * scale_M, "FossenVessel: the mass matrix M must be positive definite, its smallest",
          " eigenvalue is ", lambda_M, ": the masses and inertia (rigid body plus added mass) must be > 0 and",
          " larger than the couplings");
  const double lambda_D = detail::smallest_symmetric_eigenvalue(p.D);
  require(lambda_D > 1e-12 * p.D.cwiseAbs().maxCoeff(), "FossenVessel: the damping matrix D must dissipate energy:",
          " its symmetric part (D + D')/2 must be positive definite, its smallest eigenvalue is ", lambda_D,
          "; make the diagonal damping > 0 and larger than the couplings");
  detail::NamedValues values;
  append_matrix_parameters(values, "M", p.M);
  append_matrix_parameters(values, "D", p.D);
  append_matrix_parameters(values, "M_inv", p.M.inverse());
  return values;
}

}  // namespace

FossenVessel::FossenVessel(const FossenVesselParameters& parameters)
    : BuiltinVehicle(detail::compiled_in_model(hinf_fossen_vessel_model, statement_parameters(parameters))),
      p_(parameters) {}

std::vector<std::pair<std::string, double>> FossenVessel::named_parameters() const {
  std::vector<std::pair<std::string, double>> named;
  append_matrix_parameters(named, "M", p_.M);
  append_matrix_parameters(named, "D", p_.D);
  return named;
}

}  // namespace hinf
