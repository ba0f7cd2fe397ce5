// Integrator choice and tolerances, shared by the GRDE, the filter Riccati equation and the
// closed-loop simulations (scenario section [solver]).
#pragma once

#include <string>

#include "hinf/enum_names.hpp"

namespace hinf {

enum class Method {
  BDF,    // CVODE BDF with Newton iteration and a dense direct solver: for stiff problems
  Adams,  // CVODE Adams-Moulton with fixed-point iteration: non-stiff, high order
  ERK     // explicit Dormand-Prince 5(4) with its 4th-order dense output: non-stiff
};

template <>
struct EnumNames<Method> {
  static constexpr const char* what = "solver method";
  static constexpr std::array<std::pair<Method, const char*>, 3> names{
      {{Method::BDF, "bdf"}, {Method::Adams, "adams"}, {Method::ERK, "erk"}}};
};

struct SolverOptions {
  Method method = Method::BDF;
  double rtol = 1e-8;        // relative tolerance, in [1e-14, 1e-3]
  double atol = 1e-10;       // absolute tolerance (about rtol/100 for O(1) solutions), in (0, 1e-3];
                             // Riccati solves use atol * min(1, the solution's scale)
  long max_steps = 500000;   // steps of one whole solve or closed-loop run (all its restarts
                             // included); exceeding it is a SolverError
  // Riccati solves: when |X|_max passes escape_norm times the solution's scale, the escape
  // test (riccati.hpp) decides whether X escapes to infinity (a conjugate point, paper eq. 14)
  // or is only large. Only the cost depends on it.
  double escape_norm = 1e6;

  void validate() const;  // InputError naming the option and its admissible range
};

}  // namespace hinf
