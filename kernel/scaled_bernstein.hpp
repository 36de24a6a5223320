#pragma once
// ScaledBern<T>: polynomials in the scaled Bernstein form of degree n,
// p(t) = sum s[i] t^i (1-t)^(n-i)   (s[i] = C(n,i) b[i]).
//
// Statement. Paper 003 section VI-C, Variant 1: the g_i(t) are converted to
// this form and Δ(t) is built in it, because a product is a plain convolution
// (no binomial weights), which is why Variant 1 builds Δ faster than
// Variants 2 and 3. The sign pattern of s equals that of the Bernstein
// coefficients, so sign variations bound the roots in (0, 1) the same way.
// Requirements on T: +, -, *, construction from int.
#include "kernel/budget.hpp"
#include "kernel/bernstein.hpp"

namespace eccd {

template <class T>
struct ScaledBern {
  std::vector<T> s;
  int degree() const { return int(s.size()) - 1; }
};

template <class T>
ScaledBern<T> to_scaled(const Bern<T>& q) {
  ScaledBern<T> r;
  std::vector<T> cn = binomial_row(q.degree(), like_of(q.b));
  for (int i = 0; i <= q.degree(); ++i) r.s.push_back(cn[i] * q.b[i]);
  return r;
}
template <class T>
Bern<T> to_bernstein(const ScaledBern<T>& q) {
  Bern<T> r;
  std::vector<T> cn = binomial_row(q.degree(), like_of(q.s));
  for (int i = 0; i <= q.degree(); ++i) r.b.push_back(q.s[i] / cn[i]);
  return r;
}

// Elevation by one multiplies by t + (1 - t): s'_i = s_i + s_{i-1}.
template <class T>
ScaledBern<T> elevate(const ScaledBern<T>& q, int r) {
  ScaledBern<T> e = q;
  for (int k = 0; k < r; ++k) {
    std::vector<T> n(e.s.size() + 1, T(0));
    for (std::size_t i = 0; i < e.s.size(); ++i) {
      n[i] = n[i] + e.s[i];
      n[i + 1] = n[i + 1] + e.s[i];
    }
    e.s = std::move(n);
  }
  return e;
}
template <class T>
ScaledBern<T> operator+(const ScaledBern<T>& x, const ScaledBern<T>& y) {
  int n = std::max(x.degree(), y.degree());
  ScaledBern<T> a = elevate(x, n - x.degree()), c = elevate(y, n - y.degree());
  for (int i = 0; i <= n; ++i) a.s[i] = a.s[i] + c.s[i];
  return a;
}
template <class T>
ScaledBern<T> operator-(const ScaledBern<T>& x) {
  ScaledBern<T> r = x;
  for (auto& v : r.s) v = -v;
  return r;
}
template <class T>
ScaledBern<T> operator-(const ScaledBern<T>& x, const ScaledBern<T>& y) {
  return x + (-y);
}
template <class T>
ScaledBern<T> operator*(int k, ScaledBern<T> x) {
  for (auto& v : x.s) v = T(k) * v;
  return x;
}
template <class T>
ScaledBern<T> operator*(const ScaledBern<T>& x, const ScaledBern<T>& y) {
  check_deadline_product(x.s.size() * y.s.size());  // as Poly<T>::operator* (kernel/polynomial.hpp)
  ScaledBern<T> r;
  r.s.assign(x.s.size() + y.s.size() - 1, T(0));
  for (std::size_t i = 0; i < x.s.size(); ++i)
    for (std::size_t j = 0; j < y.s.size(); ++j) {
      T p = x.s[i] * y.s[j];
      r.s[i + j] = r.s[i + j] + p;
    }
  return r;
}

}  // namespace eccd
