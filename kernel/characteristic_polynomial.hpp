#pragma once
// The characteristic polynomial f(λ;t) = det(λA(t) - B(t)) = sum_k g_k(t) λ^k.
//
// Statement. 003 section III eq. (1) (3x3, cubic in λ) and 002 section 3 /
// 001 section 3 (4x4, quartic). Convention (docs/architecture.md): det(λA - B); the
// solids are separate iff f has two distinct negative roots, touching
// externally iff a negative double root, overlapping iff no negative root.
// (000 writes det(λA + B) and positive roots; not used here.)
// Computation: det is multilinear in the columns, so
//   g_k = (-1)^(N-k) * sum over column sets S with |S| = k of det(C_S),
// C_S taking column j from A if j in S and from B otherwise (2^N determinants),
// in the ring of the entries: power form or Bernstein form (a floating pipeline
// that multiplies in Bernstein form avoids the cancellation of power-form
// coefficients, whose size can exceed the values on [0, 1] by 10^15 and more).
// Requirements on T: ring operations.
#include "kernel/bernstein.hpp"
#include "kernel/poly_matrix.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/ring_determinant.hpp"

#include <bit>
#include <vector>

namespace eccd {

// g_0 .. g_H (f's coefficients in λ, H = dim + 1) with entries in any ring R (Poly<T> or Bern<T>).
//
// The 2^H determinants share their leading minors: det(C_S) expands row by
// row (kernel/ring_determinant.hpp: the sum over placements of the first r
// rows into a set M of columns), and that partial sum depends only on M and
// on which columns of M come from A. So all 2^H expansions run at once over
// the 3^H states (column unused / from B / from A; ternary digit j for column
// j): 208 ring products in 3D instead of 16 x 28 = 448 (measured: g_k over
// heap-allocated Bernstein polynomials took a sixth of a 3D query in double).
// Every state receives the same terms, in the same order, as in ring_det on
// C_S alone, and g_k sums the determinants in the same order as one ring_det
// per S did, so the results are the same to the last bit (and the same
// running error bounds).
template <class R, int H>
std::vector<R> characteristic_coefficients_in(const std::array<std::array<R, H>, H>& a,
                                              const std::array<std::array<R, H>, H>& b, const R& zero) {
  constexpr unsigned N = 1u << H;
  unsigned pow3[H + 1] = {1};
  for (int j = 0; j < H; ++j) pow3[j + 1] = 3 * pow3[j];
  auto index = [&](unsigned mask, unsigned from_a) {
    unsigned x = 0;
    for (int j = 0; j < H; ++j)
      if (mask >> j & 1u) x += ((from_a >> j & 1u) ? 2u : 1u) * pow3[j];
    return x;
  };
  std::vector<R> dp(pow3[H]);  // default-made (no allocation for Bern / Poly): written before read
  std::vector<char> live(pow3[H], 0);
  live[0] = 1;
  for (int r = 0; r < H; ++r)
    for (unsigned mask = 0; mask < N; ++mask) {  // rows 0..r-1 placed into mask, in increasing mask order as ring_det
      if (std::popcount(mask) != r) continue;
      for (unsigned s = mask;; s = (s - 1) & mask) {  // every choice of A-columns within mask
        const unsigned from = index(mask, s);
        if (live[from]) {
          for (int c = 0; c < H; ++c) {
            if (mask >> c & 1u) continue;
            const bool neg = std::popcount(mask >> (c + 1)) % 2;
            for (int src = 0; src < 2; ++src) {
              const R& e = src ? a[r][c] : b[r][c];
              if (is_ring_zero(e)) continue;
              const unsigned to = from + (src ? 2u : 1u) * pow3[c];
              if (!live[to]) {
                dp[to] = zero;
                live[to] = 1;
              }
              if (r == 0) {
                if (neg)
                  dp[to] = dp[to] - e;
                else
                  dp[to] = dp[to] + e;
              } else {
                R term = dp[from] * e;
                if (neg)
                  dp[to] = dp[to] - term;
                else
                  dp[to] = dp[to] + term;
              }
            }
          }
        }
        if (s == 0) break;
      }
    }
  std::vector<R> g(H + 1, zero);
  for (unsigned mask = 0; mask < N; ++mask) {
    const unsigned full = index(N - 1, mask);
    const R& d = live[full] ? dp[full] : zero;
    int k = std::popcount(mask);
    if ((H - k) % 2)
      g[k] = g[k] - d;
    else
      g[k] = g[k] + d;
  }
  return g;
}

template <class T, int H>
std::vector<Poly<T>> characteristic_coefficients(const PolyMatrix<T, H>& a, const PolyMatrix<T, H>& b) {
  return characteristic_coefficients_in<Poly<T>, H>(a, b, Poly<T>());
}

// f's coefficients for a moving pair: in power form from MovingPair, in
// Bernstein form (every product carried out in Bernstein form) from MovingPairBern.
template <class T, int H>
std::vector<Poly<T>> characteristic_of(const MovingPair<T, H>& p) {
  return characteristic_coefficients<T, H>(moving_quadric<T, H>(p.qa, p.na), moving_quadric<T, H>(p.qb, p.nb));
}
template <class T, int H>
std::vector<Bern<T>> characteristic_of(const MovingPairBern<T, H>& p) {
  Bern<T> zero;
  zero.b.push_back(scalar_traits<T>::from_rational(
      mpq_class(0), p.qa[0][0]));  // an exact 0 (not x - x, which carries x's error bound)
  auto a = moving_quadric_in<Bern<T>, T, H>(p.qa, p.na, zero);
  auto b = moving_quadric_in<Bern<T>, T, H>(p.qb, p.nb, zero);
  return characteristic_coefficients_in<Bern<T>, H>(a, b, zero);
}

// g_0 .. g_N in Bernstein form as a floating pipeline sets them up: every
// product in power form and each g_k converted at the end (power_products),
// or every product in Bernstein form from N(t) in Bernstein form. The 3D
// floating pipelines and the harness (compare/) both call this, so the
// harness measures the coefficients the pipelines use.
template <class T, int H>
std::vector<Bern<T>> characteristic_bernstein(const PreparedPair<H>& p, bool power_products, const T& like) {
  if (!power_products) return characteristic_of(to_arithmetic_bernstein<T, H>(p, like));
  std::vector<Bern<T>> out;
  for (const auto& gi : characteristic_of(to_arithmetic<T, H>(p, like))) {
    Bern<T> b = to_bernstein(gi, std::max(gi.degree(), 0));
    if (gi.is_zero()) b.b.assign(1, like - like);
    out.push_back(b);
  }
  return out;
}

}  // namespace eccd
