#include "hinf/core/angles.hpp"

#include <cmath>

namespace hinf {

double wrap_angle(double angle) {
  double wrapped = std::remainder(angle, 2.0 * M_PI);  // in [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

}  // namespace hinf
