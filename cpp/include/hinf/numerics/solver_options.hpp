// Integrator choice and tolerances, shared by the GRDE, the filter Riccati equation and the
// closed-loop simulations (scenario section [solver]).
#pragma once

#include <string>

#include "hinf/core/enum_names.hpp"

namespace hinf {

// The integrator of the Riccati equations (13) and (36) and of the closed loops
// (SolverOptions::method; the desired trajectory is always integrated by Dormand-Prince).
enum class Method {
  Auto,   // Dormand-Prince while the problem is not stiff; once its stiffness test fires (15
          // accepted steps in a row limited by stability), BDF from there on (the default)
  BDF,    // CVODE BDF with Newton iteration: for stiff problems. The Riccati equations solve
          // the Newton systems as Lyapunov equations (O(n^3)) beyond small n, else densely
  Adams,  // CVODE Adams-Moulton with fixed-point iteration: non-stiff, high order
  ERK     // explicit Dormand-Prince 5(4) with its 4th-order dense output: non-stiff
};

template <>
struct EnumNames<Method> {
  static constexpr const char* what = "solver method";
  static constexpr std::array<std::pair<Method, const char*>, 4> names{
      {{Method::Auto, "auto"}, {Method::BDF, "bdf"}, {Method::Adams, "adams"}, {Method::ERK, "erk"}}};
};

// How BDF solves the Newton systems of the Riccati equations (13) and (36).
enum class NewtonSystems {
  Auto,      // densely up to kDenseNewtonMaxStates states, as Lyapunov equations beyond
  Dense,     // the packed Jacobian (n(n+1)/2 unknowns) and LU: O(n^6) per factorization
  Lyapunov   // Schur form and Bartels-Stewart: O(n^3) per factorization and per solve
};
template <>
struct EnumNames<NewtonSystems> {
  static constexpr const char* what = "Newton systems";
  static constexpr std::array<std::pair<NewtonSystems, const char*>, 3> names{
      {{NewtonSystems::Auto, "auto"}, {NewtonSystems::Dense, "dense"}, {NewtonSystems::Lyapunov, "lyapunov"}}};
};
// NewtonSystems::Auto solves densely up to this state size: measured, the dense path is faster
// up to n = 6 and the Lyapunov path from n = 8 (4.3 ms against 5.1 ms on a random stable LTI
// system of 8 states, horizon 20; benchmarks/README.md).
constexpr int kDenseNewtonMaxStates = 7;

// Integrator and tolerances of one solve or closed loop (scenario section [solver]). Each
// field says its admissible range; validate() checks them.
struct SolverOptions {
  Method method = Method::Auto;  // the integrator
  double rtol = 1e-8;        // relative tolerance, in [1e-14, 1e-3]
  double atol = 1e-10;       // absolute tolerance (about rtol/100 for O(1) solutions), in (0, 1e-3];
                             // Riccati solves use atol * min(1, the solution's scale)
  long max_steps = 500000;   // steps of one whole solve or closed-loop run (all its restarts
                             // included), in [1, 1e9]; exceeding it is a SolverError
  // Riccati solves: when |X|_max passes escape_norm times the solution's scale, the escape
  // test (riccati.hpp) decides whether X escapes to infinity (a conjugate point, paper eq. 14)
  // or is only large, on W = c (X + c I)^-1, which stays smooth through a tall peak of X. A
  // larger value follows X itself further into the peak: near gamma* that takes tiny steps
  // (gamma* of SLICOT's SB10FD system: 2.7 s at 1e6, 11 ms at 1e3) and is less accurate.
  double escape_norm = 1e3;  // finite and > 1
  NewtonSystems newton_systems = NewtonSystems::Auto;  // Riccati equations with BDF

  void validate() const;  // InputError naming the option and its admissible range
};
bool operator==(const SolverOptions& a, const SolverOptions& b);
inline bool operator!=(const SolverOptions& a, const SolverOptions& b) { return !(a == b); }

}  // namespace hinf
