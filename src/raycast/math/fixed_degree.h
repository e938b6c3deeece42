#pragma once
// Polynomial kernels compiled for the degrees the shapes use most (the torus's quartic, degree-6
// surfaces) as well as for any degree: a fixed degree lets the compiler unroll the loops; the
// operations and their order are the same for all, so are the bits.
#include <type_traits>

namespace raycast {

/// The degree argument of a kernel that reads its degree at run time.
inline constexpr int kDynamicDegree = -1;

/// f(std::integral_constant<int, N>{}) with N = degree for the compiled degrees (4 and 6), else
/// N = kDynamicDegree. The kernel takes N as `decltype(n)::value`.
template <class F>
[[gnu::always_inline]] inline decltype(auto) with_fixed_degree(int degree, F&& f) {
  switch (degree) {
    case 4:
      return f(std::integral_constant<int, 4>{});
    case 6:
      return f(std::integral_constant<int, 6>{});
    default:
      return f(std::integral_constant<int, kDynamicDegree>{});
  }
}

}  // namespace raycast
