#include "hinf/numerics/signal.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

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

namespace {

// Natural cubic spline: the second derivatives m with m_0 = m_{n-1} = 0 (Thomas algorithm).
std::vector<double> natural_spline_second_derivatives(const std::vector<double>& t, const std::vector<double>& v) {
  const std::size_t n = t.size();
  std::vector<double> m2(n, 0.0);
  if (n <= 2) return m2;
  std::vector<double> diag(n - 2), rhs(n - 2), upper(n - 2);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
    diag[i - 1] = 2.0 * (h0 + h1);
    upper[i - 1] = h1;
    rhs[i - 1] = 6.0 * ((v[i + 1] - v[i]) / h1 - (v[i] - v[i - 1]) / h0);
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
  return m2;
}

double sign(double x) { return static_cast<double>((x > 0.0) - (x < 0.0)); }

// SciPy's PchipInterpolator._edge_case: the three-point end slope, kept of the sign of the
// first secant and (where the secants change sign) within 3 times it.
double pchip_end_slope(double h0, double h1, double m0, double m1) {
  const double d = ((2.0 * h0 + h1) * m0 - h0 * m1) / (h0 + h1);
  if (sign(d) != sign(m0)) return 0.0;
  if (sign(m0) != sign(m1) && std::abs(d) > 3.0 * std::abs(m0)) return 3.0 * m0;
  return d;
}

// The slopes d_i at the points (Fritsch and Carlson; Fritsch and Butland's weighted harmonic
// mean of the secants): zero where the secants change sign or one is zero, so each piece is
// monotone between its end values.
std::vector<double> pchip_slopes(const std::vector<double>& t, const std::vector<double>& v) {
  const std::size_t n = t.size();
  std::vector<double> h(n - 1), secant(n - 1), d(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = t[i + 1] - t[i];
    secant[i] = (v[i + 1] - v[i]) / h[i];
  }
  if (n == 2) return {secant[0], secant[0]};
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double s0 = secant[i - 1], s1 = secant[i];
    if (sign(s0) != sign(s1) || s0 == 0.0 || s1 == 0.0) {
      d[i] = 0.0;
      continue;
    }
    const double w1 = 2.0 * h[i] + h[i - 1], w2 = h[i] + 2.0 * h[i - 1];
    d[i] = (w1 + w2) / (w1 / s0 + w2 / s1);
  }
  d[0] = pchip_end_slope(h[0], h[1], secant[0], secant[1]);
  d[n - 1] = pchip_end_slope(h[n - 2], h[n - 3], secant[n - 2], secant[n - 3]);
  return d;
}

}  // namespace

Signal Signal::table(std::vector<double> t, std::vector<double> values, Interpolation interpolation) {
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
  const std::size_t n = t.size();
  std::vector<std::array<double, 4>> pieces(n - 1);
  switch (interpolation) {
    case Interpolation::Hold:
      for (std::size_t i = 0; i + 1 < n; ++i) pieces[i] = {values[i], 0.0, 0.0, 0.0};
      break;
    case Interpolation::Linear:
      for (std::size_t i = 0; i + 1 < n; ++i)
        pieces[i] = {values[i], (values[i + 1] - values[i]) / (t[i + 1] - t[i]), 0.0, 0.0};
      break;
    case Interpolation::Pchip: {
      // The cubic Hermite piece with end values v_i, v_{i+1} and end slopes d_i, d_{i+1}.
      const std::vector<double> d = pchip_slopes(t, values);
      for (std::size_t i = 0; i + 1 < n; ++i) {
        const double h = t[i + 1] - t[i], secant = (values[i + 1] - values[i]) / h;
        pieces[i] = {values[i], d[i], (3.0 * secant - 2.0 * d[i] - d[i + 1]) / h,
                     (d[i] + d[i + 1] - 2.0 * secant) / (h * h)};
      }
      break;
    }
    case Interpolation::Cubic: {
      // The cubic with end values v_i, v_{i+1} and second derivatives m_i, m_{i+1}.
      const std::vector<double> m2 = natural_spline_second_derivatives(t, values);
      for (std::size_t i = 0; i + 1 < n; ++i) {
        const double h = t[i + 1] - t[i];
        pieces[i] = {values[i], (values[i + 1] - values[i]) / h - h * (2.0 * m2[i] + m2[i + 1]) / 6.0,
                     m2[i] / 2.0, (m2[i + 1] - m2[i]) / (6.0 * h)};
      }
      break;
    }
  }
  Signal s;
  s.table_t_ = std::move(t);
  s.table_v_ = std::move(values);
  s.interpolation_ = interpolation;
  s.pieces_ = std::move(pieces);
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
    // A hold takes the last point's value from t_last on (every other piece is continuous).
    if (interpolation_ == Interpolation::Hold && t >= T.back()) return table_v_.back();
    std::size_t i = static_cast<std::size_t>(std::upper_bound(T.begin(), T.end(), t) - T.begin());
    i = std::min(std::max<std::size_t>(i, 1), T.size() - 1) - 1;  // the piece [T[i], T[i+1]]
    const std::array<double, 4>& c = pieces_[i];
    const double s = t - T[i];
    return c[0] + s * (c[1] + s * (c[2] + s * c[3]));
  }
  double value = offset_;
  for (const Harmonic& h : harmonics_) {
    const double arg = h.omega * t + h.phase;
    value += h.amplitude * (h.cosine ? std::cos(arg) : std::sin(arg));
  }
  return value;
}

std::pair<double, double> Signal::table_extreme(double t0, double tf, double sign) const {
  double best = sign * (*this)(t0), best_t = t0;
  auto consider = [&](double t) {
    const double v = sign * (*this)(t);
    if (v < best) best = v, best_t = t;
  };
  consider(tf);
  // On each piece the signal is a cubic: its extremes are at an end or where the derivative
  // c1 + 2 c2 s + 3 c3 s^2 vanishes. (A hold's value at t_{i+1} is the next piece's, which is
  // taken there too.)
  const std::vector<double>& T = table_t_;
  for (std::size_t i = 1; i < T.size(); ++i) {
    const double a = std::max(T[i - 1], t0), b = std::min(T[i], tf);
    if (a > b) continue;
    consider(a);
    consider(b);
    const double c1 = pieces_[i - 1][1], c2 = pieces_[i - 1][2], c3 = pieces_[i - 1][3];
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
  return {sign * best, best_t};
}

std::pair<double, double> Signal::minimum(double t0, double tf) const {
  require(tf >= t0, "Signal::minimum needs t0 <= tf");
  if (is_constant()) return {offset_, t0};
  if (is_table()) return table_extreme(t0, tf, 1.0);
  double best = (*this)(t0), best_t = t0;
  auto consider = [&](double t) {
    const double v = (*this)(t);
    if (v < best) best = v, best_t = t;
  };
  consider(tf);
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

std::pair<double, double> Signal::overshoot() const {
  if (!is_table()) return {0.0, 0.0};
  const auto [low, high] = std::minmax_element(table_v_.begin(), table_v_.end());
  const auto [minimum, t_min] = table_extreme(table_t_.front(), table_t_.back(), 1.0);
  const auto [maximum, t_max] = table_extreme(table_t_.front(), table_t_.back(), -1.0);
  const double below = *low - minimum, above = maximum - *high;
  // Round-off of the pieces' evaluation is no overshoot.
  const double tolerance = 1e-9 * std::max(*high - *low, std::max(std::abs(*low), std::abs(*high)));
  if (std::max(below, above) <= tolerance) return {0.0, table_t_.front()};
  return below > above ? std::make_pair(below, t_min) : std::make_pair(above, t_max);
}

std::string overshoot_warning(const Signal& signal, const std::string& name) {
  const auto [amount, t] = signal.overshoot();
  if (amount == 0.0) return "";
  const auto [low, high] = std::minmax_element(signal.table_values().begin(), signal.table_values().end());
  return str_cat(name, ": the ", to_string(signal.interpolation()), " interpolation of the table leaves the range [",
                 *low, ", ", *high, "] of its values by ", amount, " (at t = ", t,
                 "); interpolation = \"pchip\" (the default) or \"linear\" stays inside it");
}

std::string Signal::describe() const {
  std::ostringstream os;
  if (is_table()) {
    os << "table of " << table_t_.size() << " points on [" << table_t_.front() << ", "
       << table_t_.back() << "], " << to_string(interpolation_);
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

bool operator==(const Harmonic& a, const Harmonic& b) {
  return a.amplitude == b.amplitude && a.omega == b.omega && a.phase == b.phase && a.cosine == b.cosine;
}

bool operator==(const Signal& a, const Signal& b) {
  return a.offset() == b.offset() && a.harmonics() == b.harmonics() && a.table_t() == b.table_t() &&
         a.table_values() == b.table_values() && (!a.is_table() || a.interpolation() == b.interpolation());
}

bool VectorSignal::same_signals(const VectorSignal& other) const {
  return !is_function() && !other.is_function() && dim_ == other.dim_ && channels_ == other.channels_;
}

}  // namespace hinf
