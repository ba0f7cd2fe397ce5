// One accepted integrator step as a polynomial of its own dense output.
//
// The step runs from t_start to t_start + h in the direction of integration (h < 0 when
// integrating backward) and
//     y(t_start + theta h) = sum_{j=0..degree} c_j theta^j,   theta in [0, 1],
// with c_j in R^dim stored contiguously (coefficient j of every component together).
// theta = 0 is where the step starts and theta = 1 where it ends, for every method.
#pragma once

namespace hinf {

struct DensePiece {
  double t_start = 0.0;
  double h = 0.0;
  int degree = 0;
  int dim = 0;
  const double* coeffs = nullptr;  // (degree + 1) * dim numbers

  double t_end() const { return t_start + h; }
  double time(double theta) const { return t_start + theta * h; }
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
