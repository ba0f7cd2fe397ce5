// Angles, and the tracking error of a model whose state has a heading angle.
//
// The heading error psi - psi_d is an angle: wherever it enters a control law, an estimator or
// a metric it is wrapped to (-pi, pi], so that a start at psi_d + 350 degrees is the 10 degree
// error it physically is, and a state 2 pi further round gives the same run.
#pragma once

namespace hinf {

// The angle wrapped to (-pi, pi].
double wrap_angle(double angle);

// q_e = q - q_d (n numbers) with the component heading_index (if >= 0) wrapped to (-pi, pi].
// q_e may alias q or q_d.
inline void tracking_error(int n, int heading_index, const double* q, const double* q_d, double* q_e) {
  for (int i = 0; i < n; ++i) q_e[i] = q[i] - q_d[i];
  if (heading_index >= 0) q_e[heading_index] = wrap_angle(q_e[heading_index]);
}

}  // namespace hinf
