// Tolerances shared by the C++ tests.
//
// Two DIFFERENT evaluations of one exact formula (the library's code against a formula written
// in the test, another summation order or vectorization, with or without fused multiply-add,
// another eigenvalue algorithm) each differ from the exact value by a few units in the last
// place (ulps) of the size of the terms per operation: tens of ulps for the short computations
// compared in these tests (matrices of order <= 8, a few dozen operations). They are compared
// at kRoundoff times the size of the terms: a factor of ten or more above that on any IEEE
// machine and compiler, and still about 1e10 below the effect of any mistake in a formula.
// The same code on the same input is compared exactly (EXPECT_EQ).
#pragma once

#include <limits>

namespace hinf_test {

constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2.2e-16, one ulp of 1.0
constexpr double kRoundoff = 1000.0 * kEps;                      // 2.2e-13

}  // namespace hinf_test
