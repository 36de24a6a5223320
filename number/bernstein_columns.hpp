#pragma once
// The power-to-Bernstein conversion in column order, for plain double (the
// as-published face) and Bounded<double> (the guarded face).
//
// Statement. The conversion of kernel/bernstein.hpp (to_bernstein; 003
// section VI-C builds Δ from g in Bernstein form), b_k = sum_{i <= min(k, d)}
// C(k, i) a_i / C(n, i) for k = 0..n, with d = deg a <= n, computed term by
// term in the generic loop's operations and order (i ascending for each k:
// term = (C(k, i) a_i) / C(n, i), added to the sum), so the values are bit
// for bit the generic loop's; but term i is added to every output k >= i in
// one pass over k. The outputs are independent, so the compiler runs that
// pass on vectors, where the generic loop's sums over i are one dependent
// chain per output (measured at degree 36: guarded 2.4 -> 1.0 µs, plain
// 1.4 -> 0.6 µs). Both faces take it, so that the guard's cost
// (reports/performance.md) compares like with like.
// The guarded face carries, per output, the bound of
// number/running_error_loops.hpp's sum_of_ratios (the row order it replaces:
// the binomial row C(k, .) as its a, the coefficients as c, C(n, .) as d,
// whose divisor factors are alpha = 0, beta = fl(1 / C(n, i))), in the same
// operations, so the same bound bit for bit for finite inputs (a zero bound's
// terms |c| 0 and 0 ec, which that loop adds, are zeros).
// Applies where the binomials are exact: n <= 56 (C(k, i) < 2^53, Pascal's
// rule in double is exact). Otherwise, or for a non-finite input of the
// guarded face (whose row order gives a NaN bound), the functions return
// false and the caller keeps the row order.
// Requirements: double and Bounded<double> only (Mpfr and rationals keep the
// generic loop).
#include "number/running_error_loops.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace eccd::bernstein_columns {

using BD = Bounded<double>;

inline constexpr int kMaxDegree = 56;

// C(k, i) for 0 <= i <= k <= n at i (n + 1) + k (0 above the diagonal), exact for n <= kMaxDegree; one table
// per n, made once per thread.
inline const double* binomial_columns(int n) {
  thread_local std::vector<std::vector<double>> tables;
  if (int(tables.size()) <= n) tables.resize(n + 1);
  std::vector<double>& t = tables[n];
  if (t.empty()) {
    const std::size_t n1 = std::size_t(n) + 1;
    t.assign(n1 * n1, 0.0);
    for (std::size_t k = 0; k < n1; ++k) {
      t[k] = 1;  // C(k, 0)
      for (std::size_t i = 1; i <= k; ++i) t[i * n1 + k] = t[(i - 1) * n1 + (k - 1)] + t[i * n1 + (k - 1)];
    }
  }
  return t.data();
}

inline bool applies(std::size_t d1, int n, std::size_t out) {
  return n >= 0 && n <= kMaxDegree && d1 > 0 && d1 <= std::size_t(n) + 1 && out == std::size_t(n) + 1;
}

// The values alone: acc (n + 1 entries, zero on entry) receives the sums.
[[gnu::noinline]] inline void plain_columns(std::size_t d1, std::size_t n1, const double* __restrict cols,
                                            const double* __restrict av, double* __restrict acc) {
  const double* __restrict cn = cols + (n1 - 1);  // C(n, i) at cn[i * n1]
  for (std::size_t i = 0; i < d1; ++i) {
    const double a = av[i], dv = cn[i * n1];
    const double* __restrict c = cols + i * n1;
    for (std::size_t k = i; k < n1; ++k) {
      const double term = c[k] * a / dv;
      acc[k] = acc[k] + term;
    }
  }
}

// The values and their bounds: acc, E and mu (n + 1 entries each, zero on entry) receive sum_of_ratios's
// value sums, propagated bounds and sums of |q| + |acc|.
[[gnu::noinline]] inline void bounded_columns(std::size_t d1, std::size_t n1, const double* __restrict cols,
                                              const double* __restrict av, const double* __restrict ae,
                                              double* __restrict acc, double* __restrict E, double* __restrict mu) {
  using running_error_loops::kTiny;
  using running_error_loops::kU;
  const double* __restrict cn = cols + (n1 - 1);
  for (std::size_t i = 0; i < d1; ++i) {
    const double a = av[i], ea = ae[i], dv = cn[i * n1], beta = 1.0 / dv;
    const double* __restrict c = cols + i * n1;
    for (std::size_t k = i; k < n1; ++k) {
      const double p = c[k] * a, q = p / dv;
      const double s = acc[k] + q;
      acc[k] = s;
      const double pa = std::fabs(p);
      const double ep = c[k] * ea + (kU * pa + kTiny);
      E[k] = E[k] + ep * beta;
      mu[k] += std::fabs(q) + std::fabs(s);
    }
  }
}

// a (power form, d + 1 coefficients) to out (Bernstein form of degree n); false where it does not apply.
inline bool to_bernstein_columns(std::span<const double> a, int n, std::span<double> out) {
  if (!applies(a.size(), n, out.size())) return false;
  std::fill(out.begin(), out.end(), 0.0);
  plain_columns(a.size(), out.size(), binomial_columns(n), a.data(), out.data());
  return true;
}

inline bool to_bernstein_columns(std::span<const BD> a, int n, std::span<BD> out) {
  if (!applies(a.size(), n, out.size())) return false;
  const std::size_t d1 = a.size(), n1 = out.size();
  constexpr std::size_t kMax = kMaxDegree + 1;  // on the stack: at most 57 entries each
  double av[kMax], ae[kMax], acc[kMax] = {}, E[kMax] = {}, mu[kMax] = {};
  for (std::size_t i = 0; i < d1; ++i) {
    av[i] = a[i].value();
    ae[i] = a[i].bound();
    if (!std::isfinite(av[i]) || !std::isfinite(ae[i])) return false;
  }
  bounded_columns(d1, n1, binomial_columns(n), av, ae, acc, E, mu);
  using running_error_loops::kTiny;
  using running_error_loops::kU;
  for (std::size_t k = 0; k < n1; ++k) {
    const double terms = double(std::min(k + 1, d1));
    out[k] = BD(acc[k], (E[k] + kU * mu[k] + terms * 2.0 * kTiny) * (1.0 + (terms + 16.0) * 0x1p-50));
  }
  return true;
}

}  // namespace eccd::bernstein_columns
