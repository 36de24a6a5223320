#pragma once
// BiBern<T>: tensor-product bivariate polynomials in Bernstein form on
// [0, 1] x [0, 1],  F(u, t) = sum_ij b[i][j] B_i^m(u) B_j^n(t).
//
// Statement. 001 section 4 and 002 section 3: the 3D method works on
// F(u, t) = det((u - 1) A(t) - u B(t)) as a tensor-product Bernstein
// polynomial, whose control points bound F (convex hull) and subdivide by de
// Casteljau in either direction. Here: conversion from power form
// (a[i][j] u^i t^j), evaluation, subdivision in u or in t, and the sign test
// "all control points strictly of one sign". Subdivision works in place on
// copies of the control net (no per-row or per-column temporaries), with the
// products and sums of univariate de Casteljau (kernel/bernstein.hpp).
// Requirements on T: those of kernel/bernstein.hpp.
#include "kernel/bernstein.hpp"

#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace eccd {

template <class T>
struct BiBern {
  std::vector<std::vector<T>> b;  // b[i][j]: degree m = b.size()-1 in u, n = b[0].size()-1 in t
  int degree_u() const { return int(b.size()) - 1; }
  int degree_t() const { return b.empty() ? -1 : int(b[0].size()) - 1; }

  T operator()(const T& u, const T& t) const {
    Bern<T> col;  // evaluate every row in t, then the result in u
    col.b.reserve(b.size());
    for (const auto& row : b) col.b.push_back(bernstein_value(std::span<const T>(row), t));
    return col(u);
  }
  // Every control point strictly positive (+1), strictly negative (-1), or neither (0).
  int strict_sign() const {
    Sign s0 = sign(b[0][0]);
    if (s0 != Sign::positive && s0 != Sign::negative) return 0;
    for (const auto& row : b)
      for (const auto& x : row)
        if (sign(x) != s0) return 0;
    return s0 == Sign::positive ? 1 : -1;
  }
};

// From power form: a[i] is the polynomial in t multiplying u^i.
template <class T>
BiBern<T> to_bibernstein(const std::vector<Poly<T>>& a, int m, int n) {
  // convert each t-polynomial to degree-n Bernstein form, then each column in u
  std::vector<Bern<T>> rows;
  for (int i = 0; i <= m; ++i) rows.push_back(to_bernstein(i < int(a.size()) ? a[i] : Poly<T>(), n));
  BiBern<T> r;
  r.b.assign(m + 1, std::vector<T>(n + 1, T(0)));
  for (int j = 0; j <= n; ++j) {
    Poly<T> col;
    for (int i = 0; i <= m; ++i) col.c.push_back(rows[i].b[j]);
    col.trim();
    Bern<T> cb = to_bernstein(col, m);
    for (int i = 0; i <= m; ++i) r.b[i][j] = cb.b[i];
  }
  return r;
}

// de Casteljau in t at tau: the pieces over [0, tau] and [tau, 1] in t.
template <class T>
std::pair<BiBern<T>, BiBern<T>> split_t(const BiBern<T>& f, const T& tau) {
  BiBern<T> lo = f, hi = f;
  for (auto& row : lo.b) keep_left(std::span<T>(row), tau);
  for (auto& row : hi.b) keep_right(std::span<T>(row), tau);
  return {std::move(lo), std::move(hi)};
}

// In place: f becomes its piece over [0, tau] (keep_u_left) or [tau, 1]
// (keep_u_right) in u, reparameterised to [0, 1]: the same products and sums
// as keep_left / keep_right on every column, carried out row by row (no
// column copies). A caller that needs one piece (a guided bisection) computes
// only that one; split_u below is the two together.
template <class T>
void keep_u_right(BiBern<T>& f, const T& tau) {
  const int m = f.degree_u(), n = f.degree_t();
  count_triangle(std::max(m, 0), std::size_t(std::max(n, 0)) + 1);
  T s = T(1) - tau;
  if constexpr (std::is_same_v<T, Bounded<double>>) {  // the guard's bound in the same pass, all columns at once
    running_error_loops::de_casteljau_rows(f.b, s, tau, false);
    return;
  }
  for (int r = 1; r <= m; ++r)
    for (int i = 0; i + r <= m; ++i)
      for (int j = 0; j <= n; ++j) {
        T x = s * f.b[i][j];
        T y = tau * f.b[i + 1][j];
        f.b[i][j] = x + y;
      }
}
template <class T>
void keep_u_left(BiBern<T>& f, const T& tau) {
  const int m = f.degree_u(), n = f.degree_t();
  count_triangle(std::max(m, 0), std::size_t(std::max(n, 0)) + 1);
  T s = T(1) - tau;
  if constexpr (std::is_same_v<T, Bounded<double>>) {  // the guard's bound in the same pass, all columns at once
    running_error_loops::de_casteljau_rows(f.b, s, tau, true);
    return;
  }
  for (int r = 1; r <= m; ++r)
    for (int i = m; i >= r; --i)
      for (int j = 0; j <= n; ++j) {
        T x = s * f.b[i - 1][j];
        T y = tau * f.b[i][j];
        f.b[i][j] = x + y;
      }
}

// de Casteljau in u at tau: the pieces over [0, tau] and [tau, 1] in u.
template <class T>
std::pair<BiBern<T>, BiBern<T>> split_u(const BiBern<T>& f, const T& tau) {
  BiBern<T> lo = f, hi = f;
  keep_u_left(lo, tau);
  keep_u_right(hi, tau);
  return {std::move(lo), std::move(hi)};
}

}  // namespace eccd
