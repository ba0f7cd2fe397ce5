// Private: extremes of a function of time over an interval, for the bounds and certificates
// (paper eqs. 22-24) that hold "for all t in [t0, tf]".
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace hinf::detail {

// Minimizes sign * f over [a, b] by golden-section search; returns (f at the best point, t).
template <class F>
std::pair<double, double> golden_section(F&& f, double a, double b, double sign) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = sign * f(c), fd = sign * f(d);
  for (int i = 0; i < 60 && (b - a) > 1e-10 * std::max(1.0, std::abs(a) + std::abs(b)); ++i) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = sign * f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = sign * f(d);
    }
  }
  return fc < fd ? std::make_pair(sign * fc, c) : std::make_pair(sign * fd, d);
}

// The solver's step ends and their midpoints: where a dense solution's extremes are sought.
inline std::vector<double> step_samples(const std::vector<double>& breakpoints) {
  std::vector<double> times;
  for (std::size_t k = 0; k + 1 < breakpoints.size(); ++k) {
    times.push_back(breakpoints[k]);
    times.push_back(0.5 * (breakpoints[k] + breakpoints[k + 1]));
  }
  if (!breakpoints.empty()) times.push_back(breakpoints.back());
  return times;
}

// The extreme (sign = +1: minimum, -1: maximum) of f over the samples (increasing times),
// refined by golden-section search between the neighbours of the best sample.
// Returns (value, t).
template <class F>
std::pair<double, double> extremum_over(const std::vector<double>& times, F&& f, double sign) {
  double best = std::numeric_limits<double>::infinity();
  std::size_t arg = 0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double v = sign * f(times[k]);
    if (v < best || std::isnan(v)) {
      best = v;
      arg = k;
      if (std::isnan(v)) return {v, times[k]};
    }
  }
  const double a = times[arg == 0 ? 0 : arg - 1], b = times[std::min(arg + 1, times.size() - 1)];
  std::pair<double, double> result{sign * best, times[arg]};
  if (b > a) {
    const auto refined = golden_section(f, a, b, sign);
    if (sign * refined.first < best) result = refined;
  }
  return result;
}

}  // namespace hinf::detail
