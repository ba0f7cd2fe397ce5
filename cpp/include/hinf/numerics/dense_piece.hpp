// One accepted integrator step as a polynomial of its own dense output.
//
// The step runs from t_start to t_end in the direction of integration (t_end < t_start when
// integrating backward) and, with h = t_end - t_start,
//     y(t_start + theta h) = sum_{j=0..degree} c_j theta^j,   theta in [0, 1].
// t_end is the integrator's own end of the step, exactly (t_start + h may differ from it in the
// last bit), so that the last piece ends exactly at the end of the integration.
// with c_j in R^dim stored contiguously (coefficient j of every component together).
// theta = 0 is where the step starts and theta = 1 where it ends, for every method.
#pragma once

namespace hinf {

struct DensePiece {
  double t_start = 0.0;
  double t_end = 0.0;
  int degree = 0;
  int dim = 0;
  const double* coeffs = nullptr;  // (degree + 1) * dim numbers

  double h() const { return t_end - t_start; }
  double time(double theta) const { return theta >= 1.0 ? t_end : t_start + theta * h(); }
  // theta of time t (clamped to [0, 1]).
  // At t == t_start the start (theta = 0) even for a step shorter than the spacing of doubles
  // (t_end == t_start): the value at the start of an integration is its initial value.
  double theta(double t) const {
    if (t == t_start) return 0.0;
    if (t == t_end) return 1.0;
    const double value = (t - t_start) / h();
    return value < 0.0 ? 0.0 : (value > 1.0 ? 1.0 : value);
  }
  // y at theta (Horner's scheme); out has dim numbers.
  void eval(double theta, double* out) const {
    const double* top = coeffs + static_cast<long>(degree) * dim;
    for (int i = 0; i < dim; ++i) out[i] = top[i];
    for (int j = degree - 1; j >= 0; --j) {
      const double* cj = coeffs + static_cast<long>(j) * dim;
      for (int i = 0; i < dim; ++i) out[i] = out[i] * theta + cj[i];
    }
  }
};

// What a step callback asks the integrator to do next.
enum class StepAction { Continue, Stop };

}  // namespace hinf
