// Private: the one place where a state size known at compile time is chosen. Fixed-size Eigen
// matrices are several times faster than dynamic ones in the small, hot right-hand sides; the
// paper's ship has 6 states. Every other size runs the same code with dynamic sizes.
#pragma once

#include <Eigen/Core>
#include <type_traits>

namespace hinf::detail {

// f(std::integral_constant<int, N>{}) with N = n for the sizes compiled in, else Eigen::Dynamic.
template <class F>
decltype(auto) with_state_size(int n, F&& f) {
  if (n == 6) return f(std::integral_constant<int, 6>{});
  return f(std::integral_constant<int, Eigen::Dynamic>{});
}

}  // namespace hinf::detail
