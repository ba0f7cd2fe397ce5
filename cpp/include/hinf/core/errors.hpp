// The exceptions of hinf_cpp.
//
//   InputError             bad input: wrong shape, NaN, non-symmetric or indefinite weight,
//                          gamma <= 0, tf <= t0, unknown scenario key ...   (Python: ValueError)
//   SolverError            an integrator failed (step size too small, too many steps,
//                          non-finite values); carries the time and the solver's flag.
//   ConjugatePointError    the GRDE (paper eq. 13) escaped to infinity: gamma is at or below
//                          gamma* (eq. 14) for this trajectory and horizon; carries the time.
//   CouplingConditionError the output-feedback coupling condition rho(Sigma Z) < gamma^2
//                          (paper §4) failed; carries the time and rho.
// SolverError, ConjugatePointError and CouplingConditionError derive from HinfError
// (Python: hinf_cpp.HinfError, a RuntimeError).
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace hinf {

class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& what) : std::invalid_argument(what) {}
};

class HinfError : public std::runtime_error {
 public:
  explicit HinfError(const std::string& what) : std::runtime_error(what) {}
};

class SolverError : public HinfError {
 public:
  SolverError(const std::string& what, double t, std::string flag)
      : HinfError(what), t_(t), flag_(std::move(flag)) {}
  double t() const { return t_; }
  const std::string& flag() const { return flag_; }

 private:
  double t_;
  std::string flag_;
};

class ConjugatePointError : public HinfError {
 public:
  ConjugatePointError(const std::string& what, double t_escape, double gamma)
      : HinfError(what), t_escape_(t_escape), gamma_(gamma) {}
  // Estimated time at which Z(t) escapes to infinity (integrating backward from tf).
  double t_escape() const { return t_escape_; }
  double gamma() const { return gamma_; }

 private:
  double t_escape_;
  double gamma_;
};

class CouplingConditionError : public HinfError {
 public:
  CouplingConditionError(const std::string& what, double t, double rho, double gamma)
      : HinfError(what), t_(t), rho_(rho), gamma_(gamma) {}
  double t() const { return t_; }
  double rho() const { return rho_; }
  double gamma() const { return gamma_; }

 private:
  double t_;
  double rho_;
  double gamma_;
};

// Builds a message from streamable pieces: str_cat("gamma = ", g, " must be > 0").
template <class... Parts>
std::string str_cat(const Parts&... parts) {
  std::ostringstream os;
  os.precision(10);
  (os << ... << parts);
  return os.str();
}

// Input checks that are never compiled out.
template <class... Parts>
void require(bool condition, const Parts&... message) {
  if (!condition) throw InputError(str_cat(message...));
}

}  // namespace hinf
