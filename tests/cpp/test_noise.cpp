// The measurement-noise generator of paper §4 (standard_normal_samples, noise_sample_count):
// reproducible for a seed, standard normal (moments, tails, Kolmogorov-Smirnov against the
// normal distribution function), independent across channels, within the generator's pairs
// and between consecutive samples, different for different seeds.
//
// Statistical bounds: every statistic is compared with its expectation at 5 standard deviations
// of its own sampling distribution (or, for Kolmogorov-Smirnov, at a level of 1e-5): a
// correct generator fails one of them with a probability of order 1e-6 per statistic, and the
// seeds are fixed, so the outcome is reproducible.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "hinf/control/output_feedback.hpp"
#include "hinf/core/errors.hpp"

namespace {

using hinf::RowMat;

constexpr long kRows = 100000;
constexpr int kChannels = 3;
const std::uint64_t kSeeds[] = {0, 1, 20000601, (std::uint64_t{1} << 63) + 12345};

double mean(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

// Pearson correlation of two equally long samples.
double correlation(const std::vector<double>& x, const std::vector<double>& y) {
  const double mx = mean(x), my = mean(y);
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxy / std::sqrt(sxx * syy);
}

std::vector<double> column(const RowMat& x, int j) {
  std::vector<double> c(static_cast<std::size_t>(x.rows()));
  for (Eigen::Index i = 0; i < x.rows(); ++i) c[static_cast<std::size_t>(i)] = x(i, j);
  return c;
}

std::vector<double> squares(std::vector<double> x) {
  for (double& v : x) v *= v;
  return x;
}

// The Kolmogorov-Smirnov statistic sup |F_n - Phi| of a sample against the standard normal
// distribution function Phi(x) = erfc(-x / sqrt 2) / 2.
double ks_statistic(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double phi = 0.5 * std::erfc(-x[i] / std::sqrt(2.0));
    d = std::max({d, static_cast<double>(i + 1) / n - phi, phi - static_cast<double>(i) / n});
  }
  return d;
}

TEST(NoiseSamples, ReproducibleBitForBitForASeed) {
  for (std::uint64_t seed : kSeeds) {
    const RowMat a = hinf::standard_normal_samples(seed, 4000, kChannels);
    const RowMat b = hinf::standard_normal_samples(seed, 4000, kChannels);
    ASSERT_EQ(a.rows(), 4000);
    ASSERT_EQ(a.cols(), kChannels);
    // The same code on the same input: equal, bit for bit.
    for (Eigen::Index i = 0; i < a.size(); ++i) ASSERT_EQ(a.data()[i], b.data()[i]) << seed << " " << i;
    EXPECT_TRUE(a.allFinite());
  }
  const RowMat none = hinf::standard_normal_samples(7, 0, kChannels);
  EXPECT_EQ(none.rows(), 0);
  EXPECT_EQ(none.cols(), kChannels);
  // An odd number of values (the generator makes pairs): still the requested shape.
  EXPECT_EQ(hinf::standard_normal_samples(7, 5, 3).size(), 15);
  EXPECT_THROW(hinf::standard_normal_samples(7, -1, 3), hinf::InputError);
  EXPECT_THROW(hinf::standard_normal_samples(7, 3, -1), hinf::InputError);
}

TEST(NoiseSamples, MeanVarianceKurtosisAndTailsOfEachChannel) {
  const double n = static_cast<double>(kRows);
  for (std::uint64_t seed : kSeeds) {
    const RowMat x = hinf::standard_normal_samples(seed, kRows, kChannels);
    for (int j = 0; j < kChannels; ++j) {
      const std::vector<double> c = column(x, j);
      const double m = mean(c);
      double m2 = 0.0, m4 = 0.0;
      long beyond3 = 0;
      for (double v : c) {
        m2 += (v - m) * (v - m);
        m4 += v * v * v * v;
        if (std::abs(v) > 3.0) ++beyond3;
      }
      const double var = m2 / (n - 1.0);
      m4 /= n;
      // Mean: standard deviation 1 / sqrt(n).
      EXPECT_LT(std::abs(m), 5.0 / std::sqrt(n)) << seed << " channel " << j;
      // Sample variance of N(0, 1): standard deviation sqrt(2 / (n - 1)).
      EXPECT_LT(std::abs(var - 1.0), 5.0 * std::sqrt(2.0 / (n - 1.0))) << seed << " channel " << j;
      // E x^4 = 3, Var x^4 = E x^8 - 9 = 105 - 9 = 96.
      EXPECT_LT(std::abs(m4 - 3.0), 5.0 * std::sqrt(96.0 / n)) << seed << " channel " << j;
      // P(|x| > 3) = erfc(3 / sqrt 2) = 0.0026998: binomial standard deviation sqrt(p (1 - p) / n).
      const double p3 = std::erfc(3.0 / std::sqrt(2.0));
      EXPECT_LT(std::abs(static_cast<double>(beyond3) / n - p3), 5.0 * std::sqrt(p3 * (1.0 - p3) / n))
          << seed << " channel " << j;
      // Kolmogorov-Smirnov: P(sqrt(n) D > 2.5) ~ 2 exp(-2 * 2.5^2) = 7.5e-6.
      EXPECT_LT(std::sqrt(n) * ks_statistic(c), 2.5) << seed << " channel " << j;
    }
  }
}

TEST(NoiseSamples, ChannelsPairsAndConsecutiveSamplesAreIndependent) {
  // Under independence a sample correlation of K pairs has standard deviation ~ 1 / sqrt(K),
  // for the values and for their squares (which catches pairs sharing a radius).
  for (std::uint64_t seed : kSeeds) {
    const RowMat x = hinf::standard_normal_samples(seed, kRows, kChannels);
    const double limit = 5.0 / std::sqrt(static_cast<double>(kRows));
    for (int i = 0; i < kChannels; ++i) {
      const std::vector<double> ci = column(x, i);
      for (int j = i + 1; j < kChannels; ++j) {
        const std::vector<double> cj = column(x, j);
        EXPECT_LT(std::abs(correlation(ci, cj)), limit) << seed << " channels " << i << ", " << j;
        EXPECT_LT(std::abs(correlation(squares(ci), squares(cj))), limit) << seed << " channels " << i << ", " << j;
      }
      // Consecutive samples of one channel (lag 1 in time).
      const std::vector<double> now(ci.begin(), ci.end() - 1), next(ci.begin() + 1, ci.end());
      EXPECT_LT(std::abs(correlation(now, next)), limit) << seed << " channel " << i;
      EXPECT_LT(std::abs(correlation(squares(now), squares(next))), limit) << seed << " channel " << i;
    }
    // The values in storage order taken two by two (whatever the generator pairs).
    std::vector<double> even, odd;
    for (Eigen::Index k = 0; k + 1 < x.size(); k += 2) {
      even.push_back(x.data()[k]);
      odd.push_back(x.data()[k + 1]);
    }
    const double pair_limit = 5.0 / std::sqrt(static_cast<double>(even.size()));
    EXPECT_LT(std::abs(correlation(even, odd)), pair_limit) << seed;
    EXPECT_LT(std::abs(correlation(squares(even), squares(odd))), pair_limit) << seed;
  }
}

TEST(NoiseSamples, DifferentSeedsGiveDifferentUncorrelatedSequences) {
  const RowMat a = hinf::standard_normal_samples(20000601, kRows, kChannels);
  for (std::uint64_t other : {std::uint64_t{20000602}, std::uint64_t{0}, std::uint64_t{1} << 40}) {
    const RowMat b = hinf::standard_normal_samples(other, kRows, kChannels);
    const std::vector<double> va(a.data(), a.data() + a.size()), vb(b.data(), b.data() + b.size());
    EXPECT_LT(std::abs(correlation(va, vb)), 5.0 / std::sqrt(static_cast<double>(va.size()))) << other;
    long equal = 0;
    for (std::size_t i = 0; i < va.size(); ++i) equal += va[i] == vb[i];
    EXPECT_EQ(equal, 0) << other;
  }
}

TEST(NoiseSampleCount, CeilOfTheHorizonOverThePeriod) {
  // ceil((tf - t0) / T) samples, the last one possibly partial.
  EXPECT_EQ(hinf::noise_sample_count(0.0, 40.0, 0.01), 4000);
  EXPECT_EQ(hinf::noise_sample_count(0.0, 1.0, 0.3), 4);
  EXPECT_EQ(hinf::noise_sample_count(0.0, 1.0, 0.25), 4);
  EXPECT_EQ(hinf::noise_sample_count(2.0, 3.0, 0.1), 10);  // (3 - 2) / 0.1 = 10.000000000000002
  EXPECT_EQ(hinf::noise_sample_count(0.0, 0.7, 0.1), 7);   // 0.7 / 0.1 = 6.999999999999999
  EXPECT_EQ(hinf::noise_sample_count(0.0, 40.0, 0.03), 1334);
  EXPECT_EQ(hinf::noise_sample_count(0.0, 1.0, 5.0), 1);
  for (double bad : {0.0, -0.01, std::nan("")}) EXPECT_THROW(hinf::noise_sample_count(0.0, 1.0, bad), hinf::InputError);
  EXPECT_THROW(hinf::noise_sample_count(1.0, 1.0, 0.1), hinf::InputError);
}

}  // namespace
