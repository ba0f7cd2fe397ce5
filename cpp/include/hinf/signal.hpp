// Signals of absolute time t (seconds): desired inputs u_d(t), disturbances w(t), kappa(t).
//
// A scalar Signal is either
//   offset + sum_k a_k sin(omega_k t + phase_k)    (or cos, per harmonic), or
//   a table (t_i, v_i) interpolated by a natural cubic spline; evaluating a table outside
//   [t_first, t_last] is an InputError.
// A VectorSignal stacks scalar Signals (one per channel) or wraps any function of t.
#pragma once

#include <functional>
#include <utility>
#include <string>
#include <vector>

#include "hinf/types.hpp"

namespace hinf {

struct Harmonic {
  double amplitude = 0.0;
  double omega = 0.0;  // rad/s
  double phase = 0.0;  // rad
  bool cosine = false; // false: sin(omega t + phase), true: cos(omega t + phase)
};

class Signal {
 public:
  // The zero signal.
  Signal() = default;
  // A constant.
  explicit Signal(double constant);
  Signal(double offset, std::vector<Harmonic> harmonics);
  // Natural cubic spline through (t_i, v_i); at least two points, strictly increasing t.
  static Signal table(std::vector<double> t, std::vector<double> values);

  double operator()(double t) const;
  // The smallest value on [t0, tf] and where it is taken: exact for constants and tables
  // (cubic pieces); for harmonics, sampled at 64 points per period of the fastest term and
  // refined by golden-section search.
  std::pair<double, double> minimum(double t0, double tf) const;

  bool is_table() const { return !table_t_.empty(); }
  bool is_constant() const { return !is_table() && harmonics_.empty(); }
  double offset() const { return offset_; }
  const std::vector<Harmonic>& harmonics() const { return harmonics_; }
  const std::vector<double>& table_t() const { return table_t_; }
  const std::vector<double>& table_values() const { return table_v_; }
  std::string describe() const;

 private:
  double offset_ = 0.0;
  std::vector<Harmonic> harmonics_;
  std::vector<double> table_t_, table_v_, table_m2_;  // m2: spline second derivatives
};

class VectorSignal {
 public:
  using Function = std::function<Vec(double)>;

  VectorSignal() = default;
  explicit VectorSignal(std::vector<Signal> channels);
  // Any function of t returning a vector of length dim (e.g. a Python callable).
  VectorSignal(int dim, Function function);
  // dim zero channels.
  static VectorSignal zeros(int dim);

  int dim() const { return dim_; }
  bool is_function() const { return static_cast<bool>(function_); }
  const std::vector<Signal>& channels() const { return channels_; }
  void eval(double t, double* out) const;
  Vec operator()(double t) const;

 private:
  int dim_ = 0;
  std::vector<Signal> channels_;
  Function function_;
};

}  // namespace hinf
