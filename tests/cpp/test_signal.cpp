// Signals: harmonics against std::sin/cos; tables: the natural cubic spline against hand-solved
// and independently assembled splines and finite differences, PCHIP against hand-derived slopes
// in the Hermite basis, linear and hold against their definitions, no overshoot where none is
// promised and the exact overshoot of a spline; the input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "hinf/core/errors.hpp"
#include "hinf/numerics/signal.hpp"
#include "references.hpp"
#include "tolerances.hpp"

namespace {

using hinf::Harmonic;
using hinf::Interpolation;
using hinf::Signal;
using hinf::Vec;
using hinf::VectorSignal;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------- harmonic signals

TEST(Signal, ZeroAndConstant) {
  const Signal zero;
  const Signal c(2.5);
  for (double t : {-3.0, 0.0, 0.7, 1e4}) {
    EXPECT_EQ(zero(t), 0.0);
    EXPECT_EQ(c(t), 2.5);
  }
  EXPECT_TRUE(c.is_constant());
  EXPECT_FALSE(c.is_table());
}

TEST(Signal, HarmonicsMatchStdSinCos) {
  // 0.5 + 2 sin(3 t + 0.25) - 1.5 cos(0.7 t - 1) + 0.1 sin(2 pi 0.2 t)
  std::vector<Harmonic> h(3);
  h[0] = {2.0, 3.0, 0.25, false};
  h[1] = {-1.5, 0.7, -1.0, true};
  h[2] = {0.1, 2.0 * M_PI * 0.2, 0.0, false};
  const Signal s(0.5, h);
  EXPECT_FALSE(s.is_constant());
  for (double t : {-12.3, -1.0, 0.0, 0.1, 1.0, 2.718, 17.0, 40.0, 1234.5}) {
    const double expected = 0.5 + 2.0 * std::sin(3.0 * t + 0.25) - 1.5 * std::cos(0.7 * t - 1.0) +
                            0.1 * std::sin(2.0 * M_PI * 0.2 * t);
    // The library may round omega t + phase differently (fused multiply-add): an ulp of the
    // argument, ~ eps omega |t|, times the amplitudes (3.6 in all), far below this.
    EXPECT_NEAR(s(t), expected, 1e-13 * std::max(1.0, std::abs(t))) << "t = " << t;
  }
}

TEST(Signal, PhaseShiftsSinIntoCos) {
  // sin(w t + pi/2) = cos(w t): the phase is added to w t (not to t).
  const Signal s(0.0, {Harmonic{1.0, 2.0, M_PI / 2, false}});
  const Signal c(0.0, {Harmonic{1.0, 2.0, 0.0, true}});
  // sin(x + pi/2) and cos(x) with pi/2 rounded: round-off of the argument (|x| <= 6).
  for (double t = -3.0; t <= 3.0; t += 0.37) EXPECT_NEAR(s(t), c(t), hinf_test::kRoundoff * (1.0 + std::abs(2.0 * t)));
  // Absolute time: a cos with zero phase is 1 at t = 0 and -1 at t = pi / w.
  EXPECT_NEAR(c(0.0), 1.0, hinf_test::kRoundoff);
  EXPECT_NEAR(c(M_PI / 2.0), -1.0, hinf_test::kRoundoff);
}

TEST(Signal, RejectsNonFiniteParameters) {
  EXPECT_THROW((void)Signal(kNaN), hinf::InputError);
  EXPECT_THROW((void)Signal(kInf), hinf::InputError);
  EXPECT_THROW(Signal(kNaN, {}), hinf::InputError);
  EXPECT_THROW(Signal(0.0, {Harmonic{kNaN, 1.0, 0.0, false}}), hinf::InputError);
  EXPECT_THROW(Signal(0.0, {Harmonic{1.0, kInf, 0.0, false}}), hinf::InputError);
  EXPECT_THROW(Signal(0.0, {Harmonic{1.0, 1.0, kNaN, true}}), hinf::InputError);
}

// ---------------------------------------------------------------- natural cubic spline

// Natural cubic spline through (t, v), assembled as a full (n x n) linear system for the
// second derivatives and solved densely: independent of the library's Thomas algorithm.
struct ReferenceSpline {
  std::vector<double> t, v, m2;
  ReferenceSpline(std::vector<double> tt, std::vector<double> vv) : t(std::move(tt)), v(std::move(vv)) {
    const int n = static_cast<int>(t.size());
    hinf::Mat M = hinf::Mat::Zero(n, n);
    Vec r = Vec::Zero(n);
    M(0, 0) = 1.0;
    M(n - 1, n - 1) = 1.0;
    for (int i = 1; i + 1 < n; ++i) {
      const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
      M(i, i - 1) = h0 / 6.0;
      M(i, i) = (h0 + h1) / 3.0;
      M(i, i + 1) = h1 / 6.0;
      r[i] = (v[i + 1] - v[i]) / h1 - (v[i] - v[i - 1]) / h0;
    }
    const Vec m = M.fullPivLu().solve(r);
    m2.assign(m.data(), m.data() + n);
  }
  // On [t_i, t_{i+1}] the cubic with end values v_i, v_{i+1} and second derivatives m_i,
  // m_{i+1}, written in powers of s = x - t_i.
  double operator()(double x) const {
    std::size_t i = 0;
    while (i + 2 < t.size() && x > t[i + 1]) ++i;
    const double h = t[i + 1] - t[i], s = x - t[i];
    const double c2 = m2[i] / 2.0;
    const double c3 = (m2[i + 1] - m2[i]) / (6.0 * h);
    const double c1 = (v[i + 1] - v[i]) / h - h * (2.0 * m2[i] + m2[i + 1]) / 6.0;
    return v[i] + s * (c1 + s * (c2 + s * c3));
  }
};

TEST(SignalTable, ExactForLinearData) {
  const std::vector<double> t{-1.0, 0.0, 0.5, 2.0, 2.25, 5.0};
  std::vector<double> v;
  for (double x : t) v.push_back(2.0 - 3.0 * x);
  // Every interpolation but the hold reproduces a line (PCHIP: equal secants give the secant as
  // slope, at the ends too; the spline: zero second derivatives solve its equations).
  for (Interpolation interpolation : {Interpolation::Pchip, Interpolation::Linear, Interpolation::Cubic}) {
    const Signal s = Signal::table(t, v, interpolation);
    EXPECT_TRUE(s.is_table());
    EXPECT_EQ(s.interpolation(), interpolation);
    // The solve and evaluation against the line: round-off of the values (|v| <= 17).
    for (double x = -1.0; x <= 5.0; x += 0.0625)
      EXPECT_NEAR(s(x), 2.0 - 3.0 * x, hinf_test::kRoundoff * 17.0) << hinf::to_string(interpolation) << " " << x;
  }
}

TEST(SignalTable, DefaultIsPchip) {
  EXPECT_EQ(Signal::table({0.0, 1.0}, {0.0, 1.0}).interpolation(), Interpolation::Pchip);
}

TEST(SignalTable, TwoPointsIsTheStraightLine) {
  for (Interpolation interpolation : {Interpolation::Pchip, Interpolation::Linear, Interpolation::Cubic}) {
    const Signal s = Signal::table({1.0, 3.0}, {4.0, 0.0}, interpolation);
    for (double x = 1.0; x <= 3.0; x += 0.25) EXPECT_NEAR(s(x), 4.0 - 2.0 * (x - 1.0), hinf_test::kRoundoff * 4.0);
  }
}

// ---------------------------------------------------------------- PCHIP, linear, hold

// The cubic Hermite piece on [t0, t1] with end values y0, y1 and end slopes d0, d1, in the
// Hermite basis (a form the library does not use).
double hermite(double x, double t0, double t1, double y0, double y1, double d0, double d1) {
  const double h = t1 - t0, s = (x - t0) / h;
  const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
  const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  return h00 * y0 + h10 * h * d0 + h01 * y1 + h11 * h * d1;
}

TEST(SignalPchip, StepIsFlatThenSmoothstepThenFlat) {
  // t = [0, 1, 2, 3], v = [0, 0, 1, 1]: secants 0, 1, 0. The interior slopes are 0 (a zero
  // secant beside them); the end slopes ((2 h0 + h1) m0 - h0 m1) / (h0 + h1) = -1/2 have
  // the wrong sign and are set to 0. So 0 on [0, 1], 3 s^2 - 2 s^3 on [1, 2], 1 on [2, 3].
  const Signal s = Signal::table({0.0, 1.0, 2.0, 3.0}, {0.0, 0.0, 1.0, 1.0});
  for (double x = 0.0; x <= 3.0; x += 1.0 / 64.0) {
    const double d = x - 1.0;
    const double truth = x <= 1.0 ? 0.0 : x >= 2.0 ? 1.0 : 3 * d * d - 2 * d * d * d;
    // Dyadic points: the pieces' few operations are exact but for round-off of the terms (<= 3).
    EXPECT_NEAR(s(x), truth, hinf_test::kRoundoff * 3.0) << x;
  }
}

TEST(SignalPchip, HandDerivedSlopesUnequalSpacing) {
  // t = [0, 1, 3], v = [0, 2, 3]: h = [1, 2], secants [2, 1/2].
  //   interior: w1 = 2 h1 + h0 = 5, w2 = h1 + 2 h0 = 4, d1 = (w1 + w2) / (w1/2 + w2/0.5) = 9/10.5 = 6/7;
  //   first end: ((2 h0 + h1) 2 - h0 0.5) / (h0 + h1) = 7.5 / 3 = 2.5 (same sign as the secants: kept);
  //   last end: ((2 h1 + h0) 0.5 - h1 2) / (h0 + h1) = -1.5 / 3 = -1/2: sign flipped, so 0.
  const Signal s = Signal::table({0.0, 1.0, 3.0}, {0.0, 2.0, 3.0});
  for (double x = 0.0; x <= 3.0; x += 0.03125) {
    const double truth = x <= 1.0 ? hermite(x, 0.0, 1.0, 0.0, 2.0, 2.5, 6.0 / 7.0)
                                   : hermite(x, 1.0, 3.0, 2.0, 3.0, 6.0 / 7.0, 0.0);
    // Two evaluations of the same cubic in different bases: round-off of the terms (<= 10).
    EXPECT_NEAR(s(x), truth, hinf_test::kRoundoff * 10.0) << x;
  }
}

TEST(SignalTable, LinearAndHoldByDefinition) {
  const std::vector<double> t{-1.0, 0.5, 2.0, 2.5, 6.0}, v{3.0, -1.0, -1.0, 4.0, 0.5};
  const Signal linear = Signal::table(t, v, Interpolation::Linear);
  const Signal hold = Signal::table(t, v, Interpolation::Hold);
  for (double x = -1.0; x <= 6.0; x += 1.0 / 32.0) {
    std::size_t i = 0;  // the last point at or before x
    while (i + 1 < t.size() && t[i + 1] <= x) ++i;
    EXPECT_EQ(hold(x), v[i]) << x;
    const std::size_t k = std::min(i, t.size() - 2);
    const double line = v[k] + (v[k + 1] - v[k]) * (x - t[k]) / (t[k + 1] - t[k]);
    // Another order of the same operations: round-off of the values (<= 4).
    EXPECT_NEAR(linear(x), line, hinf_test::kRoundoff * 4.0) << x;
  }
  // At the points themselves: the point's value (the hold's jump is taken at the point).
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_EQ(hold(t[i]), v[i]) << i;
    EXPECT_NEAR(linear(t[i]), v[i], hinf_test::kRoundoff * 4.0) << i;
  }
  EXPECT_EQ(hold(std::nextafter(2.5, 0.0)), -1.0);
  EXPECT_EQ(hold(6.0), 0.5);
}

// Step-like tables (runs of equal values with jumps between them) and random ones, seeded.
std::vector<std::pair<std::vector<double>, std::vector<double>>> test_tables() {
  hinf_ref::Rng rng(77);
  std::vector<std::pair<std::vector<double>, std::vector<double>>> tables;
  tables.push_back({{0.0, 10.0, 20.0, 20.5, 30.0, 60.0}, {0.0, 0.0, 0.0, 1.0, 1.0, 1.0}});
  tables.push_back({{0.0, 5.0, 5.1, 12.0, 12.2, 30.0}, {0.2, 0.2, -0.3, -0.3, 0.2, 0.2}});
  for (int k = 0; k < 6; ++k) {
    std::vector<double> t{rng.uniform(-5.0, 5.0)}, v{rng.uniform(-2.0, 2.0)};
    for (int i = 1; i < 12; ++i) {
      t.push_back(t.back() + rng.uniform(0.01, 3.0));
      const bool stay = k % 2 == 0 && rng.uniform(0.0, 1.0) < 0.5;  // step-like: repeat a value
      v.push_back(stay ? v.back() : rng.uniform(-2.0, 2.0));
    }
    tables.push_back({t, v});
  }
  return tables;
}

TEST(SignalTable, PchipLinearAndHoldStayBetweenNeighbouringValues) {
  for (const auto& [t, v] : test_tables()) {
    for (Interpolation interpolation : {Interpolation::Pchip, Interpolation::Linear, Interpolation::Hold}) {
      const Signal s = Signal::table(t, v, interpolation);
      SCOPED_TRACE(hinf::to_string(interpolation));
      // On each interval, between its two values (the definition of no overshoot, piecewise);
      // round-off of the values (|v| <= 2) allowed.
      for (std::size_t i = 0; i + 1 < t.size(); ++i) {
        const double low = std::min(v[i], v[i + 1]), high = std::max(v[i], v[i + 1]);
        for (int k = 0; k <= 200; ++k) {
          const double x = t[i] + (t[i + 1] - t[i]) * k / 200.0;
          EXPECT_GE(s(x), low - hinf_test::kRoundoff * 2.0) << x;
          EXPECT_LE(s(x), high + hinf_test::kRoundoff * 2.0) << x;
        }
      }
      EXPECT_EQ(s.overshoot().first, 0.0);
    }
  }
}

TEST(SignalTable, PchipIsC1) {
  for (const auto& [t, v] : test_tables()) {
    const Signal s = Signal::table(t, v);
    // One-sided 4-point first differences (exact for cubics; e below a third of the shortest
    // interval, 0.01): the two sides agree at every interior point to the differences'
    // round-off, ~ 10 eps |v| / e ~ 1e-13, and far below a kink (secants differ by >= 1e-3 here).
    const double e = 0.003;
    for (std::size_t i = 1; i + 1 < t.size(); ++i) {
      auto d1 = [&](double dir) {
        const double h = dir * e, x = t[i];
        return (-11 * s(x) + 18 * s(x + h) - 9 * s(x + 2 * h) + 2 * s(x + 3 * h)) / (6 * h);
      };
      EXPECT_NEAR(d1(-1.0), d1(1.0), 1e-9) << "knot " << i;
    }
  }
}

TEST(SignalTable, CubicSplineOvershootIsExact) {
  // t = [0, 1, 2], v = [0, 1, 1]: m1 = 6 (0 - 1) / 4 = -3/2; on [1, 2], with d = t - 1,
  // S = 1 + d/2 - 3 d^2/4 + d^3/4 = 1 + d (d - 1)(d - 2)/4, largest at d = 1 - 1/sqrt(3):
  // S - 1 = a (1 - a^2) / 4 with a = 1/sqrt(3), i.e. 1 / (6 sqrt(3)). On [0, 1] it rises
  // monotonically (S' = 5/4 - 3 d^2/4 > 0).
  const Signal s = Signal::table({0.0, 1.0, 2.0}, {0.0, 1.0, 1.0}, Interpolation::Cubic);
  const auto [amount, where] = s.overshoot();
  // The pieces' coefficients and the quadratic formula: round-off of the terms (<= 2).
  EXPECT_NEAR(amount, 1.0 / (6.0 * std::sqrt(3.0)), hinf_test::kRoundoff * 2.0);
  EXPECT_NEAR(where, 2.0 - 1.0 / std::sqrt(3.0), 1e-7);  // a maximum: where is known to sqrt(eps)
  const std::string warning = hinf::overshoot_warning(s, "[desired] u1");
  EXPECT_NE(warning.find("[desired] u1"), std::string::npos) << warning;
  EXPECT_NE(warning.find("pchip"), std::string::npos) << warning;
  // The same table with PCHIP stays inside and has no warning.
  EXPECT_EQ(hinf::overshoot_warning(Signal::table({0.0, 1.0, 2.0}, {0.0, 1.0, 1.0}), "u1"), "");
  EXPECT_EQ(hinf::overshoot_warning(Signal(0.0, {Harmonic{1.0, 1.0, 0.0, false}}), "u1"), "");
}

TEST(SignalTable, CubicSplineOfAStepRingsAndPchipDoesNot) {
  // The overshoot example of docs/scenarios.md: zeros, then a step to 1 at t = 20.
  const std::vector<double> t{0.0, 10.0, 20.0, 30.0, 40.0}, v{0.0, 0.0, 1.0, 1.0, 1.0};
  const Signal cubic = Signal::table(t, v, Interpolation::Cubic);
  const Signal pchip = Signal::table(t, v);
  // Dense sampling: a lower bound of the exact overshoot, within O(dt^2) of it at a smooth maximum.
  double sampled = 0.0;
  for (double x = 0.0; x <= 40.0; x += 0.001) sampled = std::max({sampled, cubic(x) - 1.0, -cubic(x)});
  EXPECT_GT(sampled, 0.05);  // the spline rings by several percent of the step
  EXPECT_GE(cubic.overshoot().first, sampled - hinf_test::kRoundoff);
  EXPECT_LE(cubic.overshoot().first, sampled + 1e-6);
  EXPECT_EQ(pchip.overshoot().first, 0.0);
  for (double x = 0.0; x <= 10.0; x += 0.25) EXPECT_EQ(pchip(x), 0.0) << x;  // flat before the step
}

TEST(SignalTable, MinimumOfEveryInterpolation) {
  // minimum() against dense sampling plus the points themselves (where the line and the hold
  // take their extremes): an upper bound of the minimum, within O(dt^2) of it at a smooth
  // minimum; on sub-intervals cut anywhere.
  for (const auto& [t, v] : test_tables()) {
    for (Interpolation interpolation :
         {Interpolation::Pchip, Interpolation::Linear, Interpolation::Hold, Interpolation::Cubic}) {
      const Signal s = Signal::table(t, v, interpolation);
      const double a = t.front() + 0.3 * (t.back() - t.front()), b = t.back() - 0.1;
      double sampled = s(a);
      for (int k = 0; k <= 20000; ++k) sampled = std::min(sampled, s(a + (b - a) * k / 20000.0));
      for (double x : t)
        if (x >= a && x <= b) sampled = std::min(sampled, s(x));
      const auto [low, where] = s.minimum(a, b);
      SCOPED_TRACE(hinf::to_string(interpolation));
      EXPECT_LE(low, sampled + hinf_test::kRoundoff * 2.0);
      EXPECT_GE(low, sampled - 1e-6);
      EXPECT_EQ(s(where), low);
      EXPECT_TRUE(where >= a && where <= b);
    }
  }
}

TEST(SignalTable, HandSolvedThreePoints) {
  // (0,0), (1,1), (2,0): 4 m1 = 6 (-1 - 1), m1 = -3, so on [0, 1] S(x) = 1.5 x - 0.5 x^3
  // and S(x) = S(2 - x).
  const Signal s = Signal::table({0.0, 1.0, 2.0}, {0.0, 1.0, 0.0}, Interpolation::Cubic);
  for (double x = 0.0; x <= 2.0; x += 0.05) {
    const double y = x <= 1.0 ? x : 2.0 - x;
    EXPECT_NEAR(s(x), 1.5 * y - 0.5 * y * y * y, hinf_test::kRoundoff) << x;
  }
  EXPECT_NEAR(s(0.5), 0.6875, hinf_test::kRoundoff);
}

TEST(SignalTable, HandSolvedFourPointsUnequalSpacing) {
  // t = [0, 1, 3, 4], v = [0, 2, 1, 3]; h = [1, 2, 1]. Natural: m0 = m3 = 0 and
  //   6 m1 + 2 m2 = 6 ((1 - 2)/2 - (2 - 0)/1) = -15
  //   2 m1 + 6 m2 = 6 ((3 - 1)/1 - (1 - 2)/2) =  15   =>  m1 = -3.75, m2 = 3.75.
  // On [t_i, t_i + h] with d = x - t_i the cubic with end values v_i, v_{i+1} and second
  // derivatives m_i, m_{i+1} is v_i + c1 d + m_i/2 d^2 + (m_{i+1} - m_i)/(6h) d^3,
  // c1 = (v_{i+1} - v_i)/h - h (2 m_i + m_{i+1})/6:
  //   [0,1]: c1 = 2 + 3.75/6 = 2.625,          c2 = 0,      c3 = -0.625
  //   [1,3]: c1 = -0.5 - 2 (-7.5 + 3.75)/6 = 0.75, c2 = -1.875, c3 = 7.5/12 = 0.625
  //   [3,4]: c1 = 2 - 7.5/6 = 0.75,             c2 = 1.875,  c3 = -0.625
  const Signal s = Signal::table({0.0, 1.0, 3.0, 4.0}, {0.0, 2.0, 1.0, 3.0}, Interpolation::Cubic);
  auto truth = [](double x) {
    if (x <= 1.0) return 2.625 * x - 0.625 * x * x * x;
    if (x <= 3.0) {
      const double d = x - 1.0;
      return 2.0 + 0.75 * d - 1.875 * d * d + 0.625 * d * d * d;
    }
    const double d = x - 3.0;
    return 1.0 + 0.75 * d + 1.875 * d * d - 0.625 * d * d * d;
  };
  // The hand-made pieces really are a natural spline: knots, C1 at 1 and 3 (dyadic numbers:
  // exact arithmetic).
  EXPECT_NEAR(truth(1.0), 2.0, 1e-15);
  EXPECT_NEAR(truth(3.0), 1.0, 1e-15);
  EXPECT_NEAR(truth(4.0), 3.0, 1e-15);
  // The library's solve against the hand solution: round-off of the terms (below 10).
  for (double x = 0.0; x <= 4.0; x += 0.03125) EXPECT_NEAR(s(x), truth(x), hinf_test::kRoundoff * 10.0) << x;
}

TEST(SignalTable, MatchesIndependentlySolvedSplineAndIsC2Natural) {
  hinf_ref::Rng rng(2024);
  std::vector<double> t{-0.7}, v{rng.uniform(-3.0, 3.0)};
  for (int i = 1; i < 9; ++i) {
    t.push_back(t.back() + rng.uniform(0.05, 1.5));
    v.push_back(rng.uniform(-3.0, 3.0));
  }
  const Signal s = Signal::table(t, v, Interpolation::Cubic);
  const ReferenceSpline ref(t, v);
  // Interpolates the knots (|v| <= 3): round-off.
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(s(t[i]), v[i], hinf_test::kRoundoff * 3.0) << i;
  // Matches the dense-solve reference everywhere: two solves of the same diagonally dominant
  // system, whose round-off grows with the ratio of the longest to the shortest interval.
  double h_min = kInf, h_max = 0.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    h_min = std::min(h_min, t[i + 1] - t[i]);
    h_max = std::max(h_max, t[i + 1] - t[i]);
  }
  const double tol = hinf_test::kRoundoff * 3.0 * (h_max / h_min);
  for (int k = 0; k < 500; ++k) {
    const double x = rng.uniform(t.front(), t.back());
    EXPECT_NEAR(s(x), ref(x), tol) << x;
  }
  // One-sided 4-point differences, exact for cubics (so only round-off remains): the
  // first and second derivative at x from the side dir = +1 (right) or -1 (left), using
  // points inside one spline piece (3 e < the shortest interval, 0.05).
  const double e = 0.01;
  auto d1 = [&](double x, double dir) {
    const double h = dir * e;
    return (-11 * s(x) + 18 * s(x + h) - 9 * s(x + 2 * h) + 2 * s(x + 3 * h)) / (6 * h);
  };
  auto d2 = [&](double x, double dir) {
    return (2 * s(x) - 5 * s(x + dir * e) + 4 * s(x + 2 * dir * e) - s(x + 3 * dir * e)) / (e * e);
  };
  // Natural: second derivative zero at both ends (a clamped or not-a-knot end would have
  // |S''| of order |v| / h^2, 2 to 46 for these knots; the differences' round-off is
  // ~ 12 eps |S| / e^2 ~ 1e-10).
  EXPECT_LT(std::abs(d2(t.front(), +1.0)), 1e-7);
  EXPECT_LT(std::abs(d2(t.back(), -1.0)), 1e-7);
  // C1 and C2 at the interior knots: the derivatives from each side agree.
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    EXPECT_NEAR(d1(t[i], -1.0), d1(t[i], +1.0), 1e-8) << "knot " << i;
    EXPECT_NEAR(d2(t[i], -1.0), d2(t[i], +1.0), 1e-6) << "knot " << i;
  }
}

TEST(SignalTable, OutsideTheTableThrows) {
  const Signal s = Signal::table({1.0, 2.0, 4.0}, {0.0, 1.0, 0.5});
  EXPECT_NO_THROW(s(1.0));
  EXPECT_NO_THROW(s(4.0));
  EXPECT_THROW(s(0.999), hinf::InputError);
  EXPECT_THROW(s(4.001), hinf::InputError);
  EXPECT_THROW(s(-100.0), hinf::InputError);
  EXPECT_THROW(s(kNaN), hinf::InputError);
  // Inside a VectorSignal as well.
  const VectorSignal vs(std::vector<Signal>{Signal(1.0), s});
  EXPECT_THROW(vs(5.0), hinf::InputError);
}

TEST(SignalTable, BadTablesThrow) {
  EXPECT_THROW(Signal::table({}, {}), hinf::InputError);
  EXPECT_THROW(Signal::table({1.0}, {2.0}), hinf::InputError);
  EXPECT_THROW(Signal::table({0.0, 1.0, 1.0}, {0.0, 1.0, 2.0}), hinf::InputError);   // repeated t
  EXPECT_THROW(Signal::table({0.0, 2.0, 1.0}, {0.0, 1.0, 2.0}), hinf::InputError);   // decreasing
  EXPECT_THROW(Signal::table({0.0, kNaN, 2.0}, {0.0, 1.0, 2.0}), hinf::InputError);  // NaN time
  EXPECT_THROW(Signal::table({0.0, 1.0, 2.0}, {0.0, kNaN, 2.0}), hinf::InputError);  // NaN value
  EXPECT_THROW(Signal::table({0.0, 1.0, kInf}, {0.0, 1.0, 2.0}), hinf::InputError);
  EXPECT_THROW(Signal::table({0.0, 1.0, 2.0}, {0.0, 1.0}), hinf::InputError);        // lengths
}

// ---------------------------------------------------------------- vector signals

TEST(VectorSignal, StacksChannels) {
  const VectorSignal vs(std::vector<Signal>{
      Signal(1.0), Signal(0.0, {Harmonic{0.3, 0.2, 0.0, false}}), Signal()});
  EXPECT_EQ(vs.dim(), 3);
  EXPECT_FALSE(vs.is_function());
  for (double t : {0.0, 1.5, 39.0}) {
    const Vec v = vs(t);
    ASSERT_EQ(v.size(), 3);
    EXPECT_EQ(v[0], 1.0);
    EXPECT_NEAR(v[1], 0.3 * std::sin(0.2 * t), hinf_test::kRoundoff * 0.3);
    EXPECT_EQ(v[2], 0.0);
    double raw[3];
    vs.eval(t, raw);
    EXPECT_EQ(raw[1], v[1]);  // the same code on the same t
  }
  const VectorSignal z = VectorSignal::zeros(4);
  EXPECT_EQ(z.dim(), 4);
  EXPECT_EQ(z(3.0).cwiseAbs().maxCoeff(), 0.0);
}

TEST(VectorSignal, WrapsAFunction) {
  const VectorSignal vs(2, [](double t) {
    Vec v(2);
    v << std::exp(-t), t * t;
    return v;
  });
  EXPECT_TRUE(vs.is_function());
  EXPECT_EQ(vs.dim(), 2);
  const Vec v = vs(1.5);
  EXPECT_EQ(v[0], std::exp(-1.5));
  EXPECT_EQ(v[1], 2.25);
}

TEST(VectorSignal, FunctionWithWrongLengthOrNonFiniteValueThrows) {
  const VectorSignal too_short(3, [](double) { return Vec::Ones(2); });
  EXPECT_THROW(too_short(0.0), hinf::InputError);
  const VectorSignal too_long(1, [](double) { return Vec::Ones(2); });
  double out[2];
  EXPECT_THROW(too_long.eval(0.0, out), hinf::InputError);
  const VectorSignal nan_after_one(2, [](double t) {
    Vec v = Vec::Zero(2);
    if (t > 1.0) v[1] = kNaN;
    return v;
  });
  EXPECT_NO_THROW(nan_after_one(0.5));
  EXPECT_THROW(nan_after_one(1.5), hinf::InputError);
  const VectorSignal inf_value(1, [](double) { return Vec::Constant(1, kInf); });
  EXPECT_THROW(inf_value(0.0), hinf::InputError);
  EXPECT_THROW(VectorSignal(2, VectorSignal::Function()), hinf::InputError);  // no callable
  EXPECT_THROW(VectorSignal(-1, [](double) { return Vec(); }), hinf::InputError);
}

}  // namespace
