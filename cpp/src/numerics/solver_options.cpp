#include "hinf/numerics/solver_options.hpp"

#include <cmath>

#include "hinf/core/errors.hpp"

namespace hinf {

void SolverOptions::validate() const {
  // Looser tolerances do not give an answer (rtol = 1 or atol = 1e10 "succeed" with errors of
  // the size of the solution); tighter ones than 1e-14 are below double precision.
  require(std::isfinite(rtol) && rtol >= 1e-14 && rtol <= 1e-3, "solver rtol must be in [1e-14, 1e-3], got ", rtol);
  require(std::isfinite(atol) && atol > 0.0 && atol <= 1e-3,
          "solver atol must be in (0, 1e-3] (about rtol / 100 for solutions of order 1), got ", atol);
  require(max_steps >= 1 && max_steps <= 1000000000L, "solver max_steps must be in [1, 1e9], got ", max_steps);
  require(std::isfinite(escape_norm) && escape_norm > 1.0, "solver escape_norm must be a finite number > 1, got ",
          escape_norm);
}

bool operator==(const SolverOptions& a, const SolverOptions& b) {
  return a.method == b.method && a.rtol == b.rtol && a.atol == b.atol && a.max_steps == b.max_steps &&
         a.escape_norm == b.escape_norm && a.newton_systems == b.newton_systems;
}

}  // namespace hinf
