// Signals of absolute time t (seconds): desired inputs u_d(t), disturbances w(t), kappa(t).
//
// A scalar Signal is either
//   offset + sum_k a_k sin(omega_k t + phase_k)    (or cos, per harmonic), or
//   a table (t_i, v_i) interpolated as its Interpolation says (PCHIP by default); evaluating a
//   table outside [t_first, t_last] is an InputError.
// A VectorSignal stacks scalar Signals (one per channel) or wraps any function of t.
#pragma once

#include <array>
#include <functional>
#include <utility>
#include <string>
#include <vector>

#include "hinf/core/enum_names.hpp"
#include "hinf/core/types.hpp"

namespace hinf {

// How a table (t_i, v_i) is interpolated between its points (docs/scenarios.md).
enum class Interpolation {
  Pchip,   // piecewise cubic Hermite with the slopes of Fritsch and Carlson, weighted harmonic
           // mean of Fritsch and Butland (as SciPy's PchipInterpolator): C1, and on each
           // interval between v_i and v_{i+1}: no overshoot (the default)
  Linear,  // straight lines between the points: C0, no overshoot
  Hold,    // zero-order hold: the value of the last point at or before t; no overshoot
  Cubic    // natural cubic spline (second derivative zero at both ends): C2, but it can leave
           // the range of the values (a step rings on both sides)
};

template <>
struct EnumNames<Interpolation> {
  static constexpr const char* what = "interpolation";
  static constexpr std::array<std::pair<Interpolation, const char*>, 4> names{
      {{Interpolation::Pchip, "pchip"},
       {Interpolation::Linear, "linear"},
       {Interpolation::Hold, "hold"},
       {Interpolation::Cubic, "cubic"}}};
};

// One term of a harmonic Signal: amplitude sin(omega t + phase), or the cosine.
struct Harmonic {
  double amplitude = 0.0;  // in the unit of the signal
  double omega = 0.0;  // rad/s
  double phase = 0.0;  // rad
  bool cosine = false; // false: sin(omega t + phase), true: cos(omega t + phase)
};
bool operator==(const Harmonic& a, const Harmonic& b);
inline bool operator!=(const Harmonic& a, const Harmonic& b) { return !(a == b); }

// A scalar signal of absolute time t (s): offset + harmonics, or a table (t_i, v_i)
// interpolated between its points. A Signal is a value: it keeps no state, and may be
// evaluated from several threads at once.
class Signal {
 public:
  // The zero signal.
  Signal() = default;
  // A constant.
  explicit Signal(double constant);
  // offset + the sum of the harmonics.
  Signal(double offset, std::vector<Harmonic> harmonics);
  // The table (t_i, v_i), interpolated as `interpolation` says; at least two points, strictly
  // increasing t.
  static Signal table(std::vector<double> t, std::vector<double> values,
                      Interpolation interpolation = Interpolation::Pchip);

  // The value at t (s); a table outside [t_first, t_last] is an InputError.
  double operator()(double t) const;
  // The smallest value on [t0, tf] and where it is taken: exact for constants and tables
  // (cubic pieces); for harmonics, sampled at 64 points per period of the fastest term and
  // refined by golden-section search.
  std::pair<double, double> minimum(double t0, double tf) const;
  // How far a table's interpolant leaves the range [min v_i, max v_i] of its values on
  // [t_first, t_last], and where (exact: the extremes of each cubic piece); (0, t_first) when
  // it stays inside, and (0, 0) for a signal that is not a table. Only Interpolation::Cubic
  // can overshoot.
  std::pair<double, double> overshoot() const;

  // True for a table, false for offset + harmonics.
  bool is_table() const { return !table_t_.empty(); }
  // True for a constant: no harmonics and not a table.
  bool is_constant() const { return !is_table() && harmonics_.empty(); }
  // The offset of offset + harmonics (0 for a table).
  double offset() const { return offset_; }
  // The harmonics of offset + harmonics (none for a table).
  const std::vector<Harmonic>& harmonics() const { return harmonics_; }
  // A table's times t_i (s), strictly increasing (empty for offset + harmonics).
  const std::vector<double>& table_t() const { return table_t_; }
  // A table's values v_i, one per time (empty for offset + harmonics).
  const std::vector<double>& table_values() const { return table_v_; }
  // How a table is interpolated (Pchip for offset + harmonics, where it means nothing).
  Interpolation interpolation() const { return interpolation_; }
  // The definition in one line: "1 + 0.3 sin(0.2 t + 0)", "table of 5 points on [0, 4], pchip".
  std::string describe() const;

 private:
  // The extreme of sign * s(t) on [t0, tf] (sign = +1: the minimum, -1: the maximum) over the
  // table's cubic pieces, and where it is taken.
  std::pair<double, double> table_extreme(double t0, double tf, double sign) const;

  double offset_ = 0.0;
  std::vector<Harmonic> harmonics_;
  std::vector<double> table_t_, table_v_;
  Interpolation interpolation_ = Interpolation::Pchip;
  // Piece i on [t_i, t_{i+1}]: c0 + c1 s + c2 s^2 + c3 s^3 with s = t - t_i (4 numbers a piece).
  std::vector<std::array<double, 4>> pieces_;
};

// Equal definitions: the same offset and harmonics, or the same table and interpolation.
bool operator==(const Signal& a, const Signal& b);
inline bool operator!=(const Signal& a, const Signal& b) { return !(a == b); }

// A warning when a table's interpolant overshoots the range of its values (see
// Signal::overshoot), naming the signal `name`; empty otherwise.
std::string overshoot_warning(const Signal& signal, const std::string& name);

// A vector signal of absolute time t (s): one scalar Signal per channel, or a function of t.
class VectorSignal {
 public:
  using Function = std::function<Vec(double)>;

  VectorSignal() = default;
  // One Signal per channel.
  explicit VectorSignal(std::vector<Signal> channels);
  // Any function of t returning a vector of length dim (e.g. a Python callable).
  VectorSignal(int dim, Function function);
  // dim zero channels.
  static VectorSignal zeros(int dim);

  // The number of channels.
  int dim() const { return dim_; }
  // True for a function of t, false for channels of Signals.
  bool is_function() const { return static_cast<bool>(function_); }
  // The Signals of the channels (empty for a function of t).
  const std::vector<Signal>& channels() const { return channels_; }
  // The dim() values at t (s) into out.
  void eval(double t, double* out) const;
  Vec operator()(double t) const;
  // True when both are channels with equal signals. A function of t equals no signal, itself
  // included: functions cannot be compared.
  bool same_signals(const VectorSignal& other) const;

 private:
  int dim_ = 0;
  std::vector<Signal> channels_;
  Function function_;
};

}  // namespace hinf
