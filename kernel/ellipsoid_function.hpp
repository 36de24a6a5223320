#pragma once
// F(u, t) = det((u - 1) A(t) - u B(t)): the characteristic quartic of two
// moving ellipsoids on (0, 1) x [0, 1], in tensor-product Bernstein form.
//
// Statement. 001 section 4: reparameterise λ = (u - 1) / u, which maps
// λ ∈ (-∞, 0) to u ∈ (0, 1); then F(u, t) = u⁴ f((u-1)/u; t)
// = sum_i g_i(t) (u - 1)^i u^(4-i). Since (u-1)^i u^(4-i) = (-1)^i B⁴_{4-i}(u) / C(4, i),
// the u-Bernstein coefficient of index j is (-1)^(4-j) g_{4-j}(t) / C(4, j),
// then each is written in the degree-n Bernstein basis in t (n = max deg g_i).
// The ellipsoids are separate at t0 iff F(u, t0) > 0 for some u in (0, 1)
// (F(0, t) = det A(t) < 0 and F(1, t) = det B(t) < 0 for ellipsoids),
// touching iff max F(., t0) = 0 on (0, 1), overlapping iff F(., t0) < 0 there.
// Positive roots of f (e.g. the permanent λ = 1 of two spheres) lie outside
// (0, 1), so this test sees only the negative roots that matter.
// Requirements on T: a field (division by C(4, j), exact for rationals,
// rounded once otherwise), scalar_traits<T>.
#include "kernel/bernstein.hpp"
#include "kernel/bivariate_bernstein.hpp"
#include "kernel/polynomial.hpp"

#include <algorithm>
#include <span>
#include <vector>

namespace eccd {

inline int binomial4(int j) {
  static const int c[5] = {1, 4, 6, 4, 1};
  return c[j];
}

// Each polynomial in Bernstein form of its own degree (the zero polynomial as [0]).
template <class T>
std::vector<Bern<T>> to_bernstein_all(const std::vector<Poly<T>>& g, const T& like) {
  std::vector<Bern<T>> out;
  for (const auto& gi : g) {
    Bern<T> b = to_bernstein(gi);
    if (gi.is_zero()) b.b.assign(1, like - like);
    out.push_back(b);
  }
  return out;
}

// g[0..4] in Bernstein form in t (any degrees); the result has degree
// n = max deg g_i in t.
template <class T>
BiBern<T> ellipsoid_function(const std::vector<Bern<T>>& g, const T& like) {
  int n = 0;
  for (const auto& gi : g) n = std::max(n, gi.degree());
  BiBern<T> F;
  for (int j = 0; j <= 4; ++j) {
    Bern<T> c = elevate(g[4 - j], n - g[4 - j].degree());
    T s = scalar_traits<T>::from_rational(mpq_class((4 - j) % 2 ? -1 : 1, binomial4(j)), like);
    for (auto& x : c.b) x = x * s;
    F.b.push_back(c.b);
  }
  return F;
}

// g[0..4] in power form in t: converted to Bernstein form first.
template <class T>
BiBern<T> ellipsoid_function(const std::vector<Poly<T>>& g, const T& like) {
  return ellipsoid_function(to_bernstein_all(g, like), like);
}

// F(., t0) as a quartic in Bernstein form in u.
template <class T>
Bern<T> ellipsoid_function_at(const BiBern<T>& F, const T& t0) {
  Bern<T> r;
  r.b.reserve(F.b.size());
  for (const auto& row : F.b) r.b.push_back(bernstein_value(std::span<const T>(row), t0));
  return r;
}

// F(u0, .) as a polynomial in Bernstein form in t (same t-interval as F).
// Every column of F (a polynomial in u, of degree 4) evaluated at u0 by de Casteljau's triangle, all columns at
// once: F restricted to [u0, 1] in u (keep_u_right, on a copy) has row 0 = F(u0, .), reached by the same products
// and sums per column as bernstein_value's triangle, so the same values bit for bit in every arithmetic, and under
// the guard's bound (Bounded<double>) the same bounds (de Casteljau's rows take the step and the factor that a
// value of degree below 13 takes). One setup and one pass over rows for all n + 1 columns, where a value per
// column repeated the setup (measured in the guarded 3D method: the column values were 5 % of paper 002's run).
template <class T>
Bern<T> ellipsoid_function_along(const BiBern<T>& F, const T& u0) {
  BiBern<T> c = F;
  keep_u_right(c, u0);
  return Bern<T>(std::move(c.b.front()));
}

}  // namespace eccd
