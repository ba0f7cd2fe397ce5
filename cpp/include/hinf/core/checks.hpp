// Input checks shared by every entry point. Each throws InputError with a message that
// names the argument, says what was expected and what was found.
#pragma once

#include <string>

#include "hinf/core/types.hpp"

namespace hinf {

// The largest dimension (n, m, nw, channels) accepted: one dense n x n matrix then takes
// 800 MB, and packed_size(n) stays far from the int range.
constexpr int kMaxDimension = 10000;

// min <= value <= kMaxDimension (a dimension of a model, controller or signal).
void check_dimension(long long value, int min, const std::string& name);
void check_finite(double value, const std::string& name);
void check_finite(const ConstMatRef& M, const std::string& name);
void check_shape(const ConstMatRef& M, int rows, int cols, const std::string& name);
void check_size(const ConstVecRef& v, int size, const std::string& name);
// Symmetric to 1e-10 relative and positive semidefinite (definite = false) or definite.
void check_symmetric_weight(const ConstMatRef& M, int n, const std::string& name, bool definite);
// Strictly increasing, finite time grid [t0, tf].
void check_horizon(double t0, double tf);

}  // namespace hinf
