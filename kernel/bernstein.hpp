#pragma once
// Bern<T>: univariate polynomials in the Bernstein basis of degree n on [0, 1],
// p(t) = sum b[i] C(n,i) t^i (1-t)^(n-i).
//
// Statement. Paper 003 section VI-C builds Δ(t) "by computing with polynomials
// in the Bernstein form" after converting the low-degree g_i(t), because the
// Bernstein basis is better conditioned on [0, 1] than the power basis
// (Farouki and Rajan 1987; Farouki 1991). Its coefficients also bound the
// polynomial (convex hull property), which the root isolation by de Casteljau
// subdivision uses (003 VI-C, Variants 2 and 3; 001 section 4).
//
// Operations: conversion to and from power form, sum and product carried out
// in Bernstein form (degrees are elevated to match for a sum), degree
// elevation, derivative, evaluation and subdivision by de Casteljau.
// Requirements on T: scalar_traits<T>; +, -, *, / by binomial values.
// Known failure modes: power -> Bernstein conversion of high degree in rounded
// arithmetic amplifies errors (Farouki 1991): that is measured, not hidden.
#include "kernel/binomial.hpp"
#include "kernel/polynomial.hpp"

#include <utility>
#include <vector>

namespace eccd {

template <class T>
struct Bern {
  std::vector<T> b;  // b.size() == degree + 1; empty only when default-made

  Bern() = default;
  explicit Bern(std::vector<T> coeffs) : b(std::move(coeffs)) {}
  int degree() const { return int(b.size()) - 1; }

  // p(t) at one value by de Casteljau (stable, no power form involved).
  T operator()(const T& t) const {
    if (b.empty()) return T(0);
    std::vector<T> w = b;
    T s = T(1) - t;
    for (int r = 1; r < int(w.size()); ++r)
      for (int i = 0; i + r < int(w.size()); ++i) { T x = s * w[i]; T y = t * w[i + 1]; w[i] = x + y; }
    return w[0];
  }
  // Number of sign changes of the coefficient sequence (zeros skipped): an
  // upper bound on the number of roots in (0, 1), equal to it modulo 2.
  int sign_variations() const {
    int v = 0;
    Sign last = Sign::zero;
    for (const auto& x : b) {
      Sign s = eccd::sign(x);
      if (s == Sign::zero || s == Sign::uncertain) continue;
      if (last != Sign::zero && s != last) ++v;
      last = s;
    }
    return v;
  }
};

template <class T>
const T& like_of(const std::vector<T>& v) {
  static const T zero = T(0);
  return v.empty() ? zero : v.front();
}

template <class T>
Bern<T> to_bernstein(const Poly<T>& p, int n) {  // n >= degree(p)
  Bern<T> r;
  r.b.assign(n + 1, T(0));
  if (p.is_zero()) return r;
  const T& like = p.c.front();
  std::vector<T> cn = binomial_row(n, like);
  std::vector<T> ck(1, cn[0]);
  for (int k = 0; k <= n; ++k) {
    if (k > 0) ck = binomial_row(k, like);
    T acc = T(0);
    for (int i = 0; i <= k && i <= p.degree(); ++i) { T term = ck[i] * p.c[i] / cn[i]; acc = acc + term; }
    r.b[k] = acc;
  }
  return r;
}
template <class T>
Bern<T> to_bernstein(const Poly<T>& p) { return to_bernstein(p, std::max(p.degree(), 0)); }

template <class T>
Poly<T> to_power(const Bern<T>& q) {
  int n = q.degree();
  Poly<T> r;
  if (n < 0) return r;
  const T& like = q.b.front();
  std::vector<T> cn = binomial_row(n, like);
  r.c.assign(n + 1, T(0));
  for (int i = 0; i <= n; ++i) {
    std::vector<T> ci = binomial_row(i, like);
    T acc = T(0);
    for (int k = 0; k <= i; ++k) {
      T term = ci[k] * q.b[k];
      if ((i - k) % 2) acc = acc - term; else acc = acc + term;
    }
    r.c[i] = cn[i] * acc;
  }
  r.trim();
  return r;
}

// Degree elevation by r: the same polynomial in the basis of degree n + r.
template <class T>
Bern<T> elevate(const Bern<T>& q, int r) {
  if (r <= 0) return q;
  int n = q.degree();
  const T& like = q.b.front();
  std::vector<T> cn = binomial_row(n, like), cr = binomial_row(r, like), cnr = binomial_row(n + r, like);
  Bern<T> e;
  e.b.assign(n + r + 1, T(0));
  for (int k = 0; k <= n + r; ++k) {
    T acc = T(0);
    for (int j = std::max(0, k - r); j <= std::min(n, k); ++j) { T term = cn[j] * cr[k - j] * q.b[j]; acc = acc + term; }
    e.b[k] = acc / cnr[k];
  }
  return e;
}

template <class T>
Bern<T> operator+(const Bern<T>& x, const Bern<T>& y) {
  int n = std::max(x.degree(), y.degree());
  Bern<T> a = elevate(x, n - x.degree()), c = elevate(y, n - y.degree());
  for (int i = 0; i <= n; ++i) a.b[i] = a.b[i] + c.b[i];
  return a;
}
template <class T>
Bern<T> operator-(const Bern<T>& x) { Bern<T> r = x; for (auto& v : r.b) v = -v; return r; }
template <class T>
Bern<T> operator-(const Bern<T>& x, const Bern<T>& y) { return x + (-y); }
template <class T>
Bern<T> operator*(const T& s, Bern<T> x) { for (auto& v : x.b) v = s * v; return x; }
template <class T>
Bern<T> operator*(int s, const Bern<T>& x) { return T(s) * x; }

// Product in Bernstein form: c_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j.
template <class T>
Bern<T> operator*(const Bern<T>& x, const Bern<T>& y) {
  int m = x.degree(), n = y.degree();
  const T& like = x.b.front();
  std::vector<T> cm = binomial_row(m, like), cn = binomial_row(n, like), cmn = binomial_row(m + n, like);
  std::vector<T> xs(m + 1, T(0)), ys(n + 1, T(0));
  for (int i = 0; i <= m; ++i) xs[i] = cm[i] * x.b[i];
  for (int j = 0; j <= n; ++j) ys[j] = cn[j] * y.b[j];
  Bern<T> r;
  r.b.assign(m + n + 1, T(0));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) { T p = xs[i] * ys[j]; r.b[i + j] = r.b[i + j] + p; }
  for (int k = 0; k <= m + n; ++k) r.b[k] = r.b[k] / cmn[k];
  return r;
}

template <class T>
Bern<T> derivative(const Bern<T>& q) {
  int n = q.degree();
  Bern<T> d;
  if (n <= 0) { d.b.assign(1, T(0)); return d; }
  for (int i = 0; i < n; ++i) { T diff = q.b[i + 1] - q.b[i]; d.b.push_back(T(n) * diff); }
  return d;
}

// de Casteljau subdivision at tau: the pieces on [0, tau] and [tau, 1], each
// reparameterised to [0, 1].
template <class T>
std::pair<Bern<T>, Bern<T>> split(const Bern<T>& q, const T& tau) {
  int n = q.degree();
  std::vector<T> w = q.b;
  Bern<T> left, right;
  left.b.resize(n + 1);
  right.b.resize(n + 1);
  left.b[0] = w[0];
  right.b[n] = w[n];
  T s = T(1) - tau;
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i + r <= n; ++i) { T x = s * w[i]; T y = tau * w[i + 1]; w[i] = x + y; }
    left.b[r] = w[0];
    right.b[n - r] = w[n - r];
  }
  return {left, right};
}

}  // namespace eccd
