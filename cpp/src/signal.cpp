#include "hinf/signal.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hinf/checks.hpp"
#include "hinf/errors.hpp"

namespace hinf {

Signal::Signal(double constant) : offset_(constant) { check_finite(constant, "signal constant"); }

Signal::Signal(double offset, std::vector<Harmonic> harmonics)
    : offset_(offset), harmonics_(std::move(harmonics)) {
  check_finite(offset, "signal offset");
  for (const Harmonic& h : harmonics_) {
    check_finite(h.amplitude, "harmonic amplitude");
    check_finite(h.omega, "harmonic omega");
    check_finite(h.phase, "harmonic phase");
  }
}

Signal Signal::table(std::vector<double> t, std::vector<double> values) {
  require(t.size() >= 2, "a tabulated signal needs at least two points, got ", t.size());
  require(t.size() == values.size(), "a tabulated signal needs as many values as times: ",
          t.size(), " times, ", values.size(), " values");
  for (std::size_t i = 0; i < t.size(); ++i) {
    check_finite(t[i], "table time");
    check_finite(values[i], "table value");
    if (i > 0)
      require(t[i] > t[i - 1], "table times must be strictly increasing: t[", i - 1,
              "] = ", t[i - 1], ", t[", i, "] = ", t[i]);
  }
  // Natural cubic spline: second derivatives m with m_0 = m_{n-1} = 0 (Thomas algorithm).
  const std::size_t n = t.size();
  std::vector<double> m2(n, 0.0);
  if (n > 2) {
    std::vector<double> diag(n - 2), rhs(n - 2), upper(n - 2);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
      diag[i - 1] = 2.0 * (h0 + h1);
      upper[i - 1] = h1;
      rhs[i - 1] = 6.0 * ((values[i + 1] - values[i]) / h1 - (values[i] - values[i - 1]) / h0);
    }
    for (std::size_t k = 1; k < n - 2; ++k) {
      const double lower = t[k + 1] - t[k];  // h_{k} couples unknown k-1 and k
      const double factor = lower / diag[k - 1];
      diag[k] -= factor * upper[k - 1];
      rhs[k] -= factor * rhs[k - 1];
    }
    for (std::size_t k = n - 2; k-- > 0;) {
      double value = rhs[k];
      if (k + 1 < n - 2) value -= upper[k] * m2[k + 2];
      m2[k + 1] = value / diag[k];
    }
  }
  Signal s;
  s.table_t_ = std::move(t);
  s.table_v_ = std::move(values);
  s.table_m2_ = std::move(m2);
  return s;
}

double Signal::operator()(double t) const {
  if (is_table()) {
    const std::vector<double>& T = table_t_;
    const double span = T.back() - T.front();
    const double slack = 1e-12 * std::max(1.0, std::abs(T.front()) + std::abs(T.back()));
    if (!(t >= T.front() - slack && t <= T.back() + slack))
      throw InputError(str_cat("tabulated signal evaluated at t = ", t, ", outside its table [",
                               T.front(), ", ", T.back(), "] (span ", span,
                               "): extend the table to cover the horizon"));
    std::size_t i = static_cast<std::size_t>(
        std::upper_bound(T.begin(), T.end(), t) - T.begin());
    i = std::min(std::max<std::size_t>(i, 1), T.size() - 1);
    const double h = T[i] - T[i - 1];
    const double a = (T[i] - t) / h, b = (t - T[i - 1]) / h;
    return a * table_v_[i - 1] + b * table_v_[i] +
           ((a * a * a - a) * table_m2_[i - 1] + (b * b * b - b) * table_m2_[i]) * h * h / 6.0;
  }
  double value = offset_;
  for (const Harmonic& h : harmonics_) {
    const double arg = h.omega * t + h.phase;
    value += h.amplitude * (h.cosine ? std::cos(arg) : std::sin(arg));
  }
  return value;
}

std::pair<double, double> Signal::minimum(double t0, double tf) const {
  require(tf >= t0, "Signal::minimum needs t0 <= tf");
  if (is_constant()) return {offset_, t0};
  double best = (*this)(t0), best_t = t0;
  auto consider = [&](double t) {
    const double v = (*this)(t);
    if (v < best) best = v, best_t = t;
  };
  consider(tf);
  if (is_table()) {
    // On each spline piece the signal is a cubic: its minimum is at an end or where the
    // derivative (a quadratic) vanishes.
    const std::vector<double>& T = table_t_;
    for (std::size_t i = 1; i < T.size(); ++i) {
      const double a = std::max(T[i - 1], t0), b = std::min(T[i], tf);
      if (a > b) continue;
      consider(a);
      consider(b);
      const double h = T[i] - T[i - 1];
      // s(t) with u = t - T[i-1]: derivative = c1 + 2 c2 u + 3 c3 u^2.
      const double m0 = table_m2_[i - 1], m1 = table_m2_[i];
      const double c1 = (table_v_[i] - table_v_[i - 1]) / h - h * (2.0 * m0 + m1) / 6.0;
      const double c2 = m0 / 2.0, c3 = (m1 - m0) / (6.0 * h);
      std::vector<double> roots;
      if (std::abs(c3) > 1e-300) {
        const double disc = 4.0 * c2 * c2 - 12.0 * c3 * c1;
        if (disc >= 0.0) {
          roots.push_back((-2.0 * c2 + std::sqrt(disc)) / (6.0 * c3));
          roots.push_back((-2.0 * c2 - std::sqrt(disc)) / (6.0 * c3));
        }
      } else if (std::abs(c2) > 1e-300) {
        roots.push_back(-c1 / (2.0 * c2));
      }
      for (double u : roots)
        if (T[i - 1] + u >= a && T[i - 1] + u <= b) consider(T[i - 1] + u);
    }
    return {best, best_t};
  }
  double omega_max = 0.0;
  for (const Harmonic& h : harmonics_) omega_max = std::max(omega_max, std::abs(h.omega));
  if (omega_max == 0.0) return {best, best_t};
  const double step = 2.0 * M_PI / omega_max / 64.0;
  const long count = std::min<long>(10'000'000, static_cast<long>(std::ceil((tf - t0) / step)));
  for (long k = 0; k <= count; ++k) consider(std::min(tf, t0 + static_cast<double>(k) * step));
  // Golden-section refinement around the best sample.
  double a = std::max(t0, best_t - step), b = std::min(tf, best_t + step);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 80 && b - a > 1e-13 * std::max(1.0, std::abs(best_t)); ++i) {
    const double c = b - ratio * (b - a), d = a + ratio * (b - a);
    if ((*this)(c) < (*this)(d)) b = d;
    else a = c;
  }
  consider(0.5 * (a + b));
  return {best, best_t};
}

std::string Signal::describe() const {
  std::ostringstream os;
  if (is_table()) {
    os << "table of " << table_t_.size() << " points on [" << table_t_.front() << ", "
       << table_t_.back() << "]";
    return os.str();
  }
  os << offset_;
  for (const Harmonic& h : harmonics_)
    os << " + " << h.amplitude << (h.cosine ? " cos(" : " sin(") << h.omega << " t + "
       << h.phase << ")";
  return os.str();
}

VectorSignal::VectorSignal(std::vector<Signal> channels)
    : dim_(static_cast<int>(channels.size())), channels_(std::move(channels)) {
  check_dimension(static_cast<long long>(channels_.size()), 0, "the number of channels of a vector signal");
}

VectorSignal::VectorSignal(int dim, Function function) : dim_(dim), function_(std::move(function)) {
  check_dimension(dim, 0, "the dimension of a vector signal");
  require(static_cast<bool>(function_), "a vector signal needs a callable");
}

VectorSignal VectorSignal::zeros(int dim) {
  check_dimension(dim, 0, "the dimension of a vector signal");
  return VectorSignal(std::vector<Signal>(static_cast<std::size_t>(dim)));
}

void VectorSignal::eval(double t, double* out) const {
  if (function_) {
    const Vec v = function_(t);
    if (v.size() != dim_)
      throw InputError(str_cat("a signal function returned a vector of length ", v.size(),
                               " at t = ", t, ", expected ", dim_));
    for (int i = 0; i < dim_; ++i) {
      if (!std::isfinite(v[i]))
        throw InputError(str_cat("a signal function returned a non-finite value at t = ", t));
      out[i] = v[i];
    }
    return;
  }
  for (int i = 0; i < dim_; ++i) out[i] = channels_[static_cast<std::size_t>(i)](t);
}

Vec VectorSignal::operator()(double t) const {
  Vec out(dim_);
  eval(t, out.data());
  return out;
}

}  // namespace hinf
