#include "hinf/solver_options.hpp"

#include <cmath>

#include "hinf/errors.hpp"

namespace hinf {

std::string to_string(Method method) {
  switch (method) {
    case Method::BDF: return "bdf";
    case Method::Adams: return "adams";
    case Method::ERK: return "erk";
  }
  return "unknown";
}

Method method_from_string(const std::string& name) {
  if (name == "bdf") return Method::BDF;
  if (name == "adams") return Method::Adams;
  if (name == "erk") return Method::ERK;
  throw InputError(str_cat("unknown solver method '", name,
                           "': use \"bdf\", \"adams\" or \"erk\""));
}

void SolverOptions::validate() const {
  require(std::isfinite(rtol) && rtol > 0.0, "solver rtol must be > 0, got ", rtol);
  require(std::isfinite(atol) && atol > 0.0, "solver atol must be > 0, got ", atol);
  require(rtol >= 1e-14, "solver rtol = ", rtol, " is below what double precision can give; use >= 1e-14");
  require(max_steps > 0, "solver max_steps must be > 0, got ", max_steps);
  require(std::isfinite(escape_norm) && escape_norm > 1.0, "solver escape_norm must be > 1, got ",
          escape_norm);
}

}  // namespace hinf
