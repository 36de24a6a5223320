#pragma once
// Determinants over any commutative ring: scalars, Poly<T> (power form),
// Bern<T> (Bernstein form) or ScaledBern<T>.
//
// Statement. det a = sum over permutations σ of sgn(σ) prod_r a[r][σ(r)],
// accumulated row by row over the set of columns used so far (O(2^k k) ring
// products for a k x k matrix, no division): the same code builds the
// characteristic polynomial (kernel/characteristic_polynomial.hpp) and the
// subresultants (kernel/subresultants.hpp) in whichever basis a pipeline
// computes in, so that the basis, not the formula, is what the harness varies.
// Requirements on R: R + R, R - R, R * R, and a zero element passed in.
// field_det: the same determinant of a scalar matrix over a field (exact
// rationals or rounded T) by Gaussian elimination with partial pivoting by
// magnitude, O(k^3): the size of det A(t) for balancing a pencil
// (kernel/prepared_scene.hpp, floating/rounded_input.hpp). Requirements on T:
// a field and scalar_traits<T> (abs, from_rational); exact T gives the exact
// determinant whatever the pivots.
#include "number/scalar_traits.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

namespace eccd {

// Whether a ring element is known to be zero (skips work in sparse matrices).
template <class R>
bool is_ring_zero(const R& x) {
  if constexpr (requires { x.is_zero(); }) {
    return x.is_zero();
  } else if constexpr (requires { x.b.size(); }) {
    for (const auto& c : x.b)
      if (!is_zero(c)) return false;
    return true;
  } else if constexpr (requires { x.s.size(); }) {
    for (const auto& c : x.s)
      if (!is_zero(c)) return false;
    return true;
  } else {
    return is_zero(x);
  }
}

// det of a k x k matrix over R (entries a[r][c]), k <= 20.
template <class R>
R ring_det(const std::vector<std::vector<R>>& a, const R& zero) {
  const int k = int(a.size());
  if (k == 0) return zero;
  // dp[mask]: signed sum over placements of the first popcount(mask) rows
  // into the columns of mask. Row r goes to column c; the sign flips once per
  // already used column greater than c (one inversion each).
  std::vector<R> dp(std::size_t(1) << k, zero);
  std::vector<char> live(dp.size(), 0);
  std::vector<std::vector<std::uint32_t>> by_count(k + 1);
  for (std::uint32_t m = 0; m < dp.size(); ++m) by_count[std::popcount(m)].push_back(m);
  live[0] = 1;
  for (int r = 0; r < k; ++r)
    for (std::uint32_t mask : by_count[r]) {
      if (!live[mask]) continue;
      for (int c = 0; c < k; ++c) {
        if (mask >> c & 1u) continue;
        const R& e = a[r][c];
        if (is_ring_zero(e)) continue;
        std::uint32_t nm = mask | (1u << c);
        R term = r == 0 ? e : dp[mask] * e;
        if (std::popcount(mask >> (c + 1)) % 2)
          dp[nm] = dp[nm] - term;
        else
          dp[nm] = dp[nm] + term;
        live[nm] = 1;
      }
    }
  return live.back() ? dp.back() : zero;
}

template <class T, int H>
T field_det(std::array<std::array<T, H>, H> m) {
  T d = scalar_traits<T>::from_rational(mpq_class(1), m[0][0]);
  for (int c = 0; c < H; ++c) {
    int p = c;
    for (int r = c + 1; r < H; ++r)
      if (scalar_traits<T>::abs(m[r][c]) > scalar_traits<T>::abs(m[p][c])) p = r;
    if (is_zero(m[p][c])) return m[p][c];
    if (p != c) {
      std::swap(m[p], m[c]);
      d = -d;
    }
    d = d * m[c][c];
    for (int i = c + 1; i < H; ++i) {
      T f = m[i][c] / m[c][c];
      for (int j = c; j < H; ++j) m[i][j] = m[i][j] - f * m[c][j];
    }
  }
  return d;
}

}  // namespace eccd
