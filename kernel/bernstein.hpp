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
// elevation, derivative, evaluation and subdivision by de Casteljau. The
// sign variations of the coefficients (kernel/sign_variations.hpp:
// sign_variations(q.b)) bound the roots in (0, 1), with the same parity.
// Cost (the 3D Bézier pipeline calls these in its inner loops): binomial
// rows come from a per-thread cache (kernel/binomial.hpp); evaluation,
// subdivision and restriction work in place on any coefficient storage
// (std::span: a Bern, a row of a BiBern), evaluation of a double polynomial
// of degree < 64 on the stack; elevate_into / derivative_into reuse the
// caller's storage. Every variant performs the same operations in the same
// order as the plain de Casteljau triangle, so results are bit for bit the same.
// Requirements on T: scalar_traits<T>; +, -, *, / by binomial values.
// Known failure modes: power -> Bernstein conversion of high degree in rounded
// arithmetic amplifies errors (Farouki 1991): that is measured, not hidden.
#include "kernel/budget.hpp"
#include "kernel/binomial.hpp"
#include "kernel/polynomial.hpp"
#include "kernel/sign_variations.hpp"
#include "number/bernstein_columns.hpp"
#include "number/halving_step.hpp"
#include "number/running_error_loops.hpp"

#include <algorithm>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace eccd {

// A de Casteljau triangle of degree n over `columns` columns counts its steps
// as work units (kernel/budget.hpp count_work: a work budget follows them).
inline void count_triangle(std::size_t n, std::size_t columns = 1) { count_work(n * (n + 1) / 2 * columns); }

// de Casteljau's triangle in place on w (n + 1 values): after the call w[0]
// is the value at t.
template <class T>
void de_casteljau_in_place(std::span<T> w, const T& t) {
  count_triangle(w.empty() ? 0 : w.size() - 1);
  T s = T(1) - t;
  if constexpr (std::is_same_v<T, Bounded<double>>) {  // the guard's bound in the same pass
    running_error_loops::de_casteljau(w, s, t, nullptr);
    return;
  }
  for (int r = 1; r < int(w.size()); ++r)
    for (int i = 0; i + r < int(w.size()); ++i) {
      T x = s * w[i];
      T y = t * w[i + 1];
      w[i] = x + y;
    }
}

// The value at t of the polynomial with Bernstein coefficients b (any
// storage: a Bern, a row of a BiBern). The working copy lives on the stack
// for plain types (double) of degree < 64, so an evaluation allocates nothing.
template <class T>
T bernstein_value(std::span<const T> b, const T& t) {
  if (b.empty()) return T(0);
  if constexpr (std::is_same_v<T, Bounded<double>>) {  // the guard's bound in the same pass, b read in place
    count_triangle(b.size() - 1);
    return running_error_loops::de_casteljau_value(
        b, T(1) - t, t, b.size() >= 13 && b.size() <= 57 ? binomial_row(int(b.size()) - 1, 1.0).data() : nullptr);
  }
  if constexpr (std::is_trivially_copyable_v<T>) {
    if (b.size() <= 64) {
      T w[64];
      std::copy(b.begin(), b.end(), w);
      de_casteljau_in_place(std::span<T>(w, b.size()), t);
      return w[0];
    }
  }
  std::vector<T> w(b.begin(), b.end());
  de_casteljau_in_place(std::span<T>(w), t);
  return w[0];
}

// MPFR, plain or guarded: a de Casteljau step by a step object (number/halving_step.hpp) instead of the
// written-out products: no temporaries (an MPFR copy allocates), and at 1/2 one addition and an exponent shift.
// The same values bit for bit (the products commute; the sum is the same); the guarded bound is Bounded's own
// formula with the product's factors in the step's order (a times 1 - tau), so it may differ from the written
// order's in its last bits (both bound the same error). The second look's root isolation (128-bit MPFR, a Δ of
// degree up to 240) spent two fifths of its time in the written-out split.
template <class T>
inline constexpr bool kMpfrStep = std::is_same_v<T, Mpfr> || std::is_same_v<T, Bounded<Mpfr>>;

// In place: c becomes the Bernstein coefficients of its polynomial on
// [tau, 1] (keep_right) or [0, tau] (keep_left), reparameterised to [0, 1].
// The same products and sums as split() below, in one buffer.
template <class T>
void keep_right(std::span<T> c, const T& tau) {
  const int n = int(c.size()) - 1;
  count_triangle(std::max(n, 0));
  T s = T(1) - tau;
  if constexpr (std::is_same_v<T, Bounded<double>>) {  // the guard's bound in the same pass
    running_error_loops::de_casteljau(c, s, tau, nullptr);
    return;
  }
  if constexpr (kMpfrStep<T>) {
    HalvingStep<T> step(tau);
    for (int r = 1; r <= n; ++r)
      for (int i = 0; i + r <= n; ++i) step(c[i], c[i + 1]);
    return;
  }
  for (int r = 1; r <= n; ++r)
    for (int i = 0; i + r <= n; ++i) {
      T x = s * c[i];
      T y = tau * c[i + 1];
      c[i] = x + y;
    }
}
template <class T>
void keep_left(std::span<T> c, const T& tau) {
  const int n = int(c.size()) - 1;
  count_triangle(std::max(n, 0));
  T s = T(1) - tau;
  if constexpr (std::is_same_v<T,
                               Bounded<double>>) {  // the guard's bound in the same pass: split's left piece
    thread_local std::vector<T> left;
    left.resize(c.size());
    running_error_loops::de_casteljau(c, s, tau, left.data());
    std::copy(left.begin(), left.end(), c.begin());
    return;
  }
  // round r computes the same values as split()'s, stored one place to the right (c[i + r] for its w[i])
  for (int r = 1; r <= n; ++r)
    for (int i = n; i >= r; --i) {
      T x = s * c[i - 1];
      T y = tau * c[i];
      c[i] = x + y;
    }
}

// Both pieces at once (one de Casteljau triangle instead of two):
// lo and hi (c.size() entries each) receive what keep_left and keep_right
// would leave in a copy of c, with the same products and sums in the same
// order (keep_right on hi, whose first entry after round r is lo's entry r),
// so bit for bit the same values in any arithmetic.
template <class T>
void split_into(std::span<const T> c, const T& tau, std::span<T> lo, std::span<T> hi) {
  const int n = int(c.size()) - 1;
  count_triangle(std::max(n, 0));
  std::copy(c.begin(), c.end(), hi.begin());
  T s = T(1) - tau;
  if constexpr (std::is_same_v<T, Bounded<double>>) {  // the guard's bound in the same pass: split's two pieces
    running_error_loops::de_casteljau(hi, s, tau, lo.data());
    return;
  }
  lo[0] = hi[0];
  if constexpr (kMpfrStep<T>) {
    HalvingStep<T> step(tau);
    for (int r = 1; r <= n; ++r) {
      for (int i = 0; i + r <= n; ++i) step(hi[i], hi[i + 1]);
      lo[r] = hi[0];
    }
    return;
  }
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i + r <= n; ++i) {
      T x = s * hi[i];
      T y = tau * hi[i + 1];
      hi[i] = x + y;
    }
    lo[r] = hi[0];
  }
}

template <class T>
struct Bern {
  std::vector<T> b;  // b.size() == degree + 1; empty only when default-made

  Bern() = default;
  explicit Bern(std::vector<T> coeffs) : b(std::move(coeffs)) {}
  int degree() const { return int(b.size()) - 1; }

  // p(t) at one value by de Casteljau (stable, no power form involved).
  T operator()(const T& t) const { return bernstein_value(std::span<const T>(b), t); }
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
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, Bounded<double>>)  // column order, on vectors
    if (bernstein_columns::to_bernstein_columns(std::span<const T>(p.c), n, std::span<T>(r.b))) return r;
  const T& like = p.c.front();
  const std::vector<T>& cn = binomial_row(n, like);
  // The guard's bound factors per C(n, i), so that a term's bound needs no division (number/running_error_loops.hpp).
  [[maybe_unused]] const running_error_loops::DivisorFactors* factors = nullptr;
  if constexpr (std::is_same_v<T, Bounded<double>>) {
    thread_local running_error_loops::DivisorFactors row_factors;
    if (running_error_loops::divisor_factors(std::span<const T>(cn), row_factors)) factors = &row_factors;
  }
  for (int k = 0; k <= n; ++k) {
    const std::vector<T>& ck = binomial_row(k, like);
    if constexpr (std::is_same_v<T, Bounded<double>>) {  // the guard's bound in the same pass
      r.b[k] =
          running_error_loops::sum_of_ratios(ck.data(), p.c.data(), cn.data(), std::min(k, p.degree()) + 1, factors);
      continue;
    }
    T acc = T(0);
    for (int i = 0; i <= k && i <= p.degree(); ++i) {
      T term = ck[i] * p.c[i] / cn[i];
      acc = acc + term;
    }
    r.b[k] = acc;
  }
  return r;
}
template <class T>
Bern<T> to_bernstein(const Poly<T>& p) {
  return to_bernstein(p, std::max(p.degree(), 0));
}

template <class T>
Poly<T> to_power(const Bern<T>& q) {
  int n = q.degree();
  Poly<T> r;
  if (n < 0) return r;
  const T& like = q.b.front();
  const std::vector<T>& cn = binomial_row(n, like);
  r.c.assign(n + 1, T(0));
  for (int i = 0; i <= n; ++i) {
    const std::vector<T>& ci = binomial_row(i, like);
    T acc = T(0);
    for (int k = 0; k <= i; ++k) {
      T term = ci[k] * q.b[k];
      if ((i - k) % 2)
        acc = acc - term;
      else
        acc = acc + term;
    }
    r.c[i] = cn[i] * acc;
  }
  r.trim();
  return r;
}

// Degree elevation by r >= 1 of the coefficients q into e (e's storage is
// reused: callers in loops keep one e): the same polynomial in the basis of
// degree n + r.
template <class T>
void elevate_into(std::span<const T> q, int r, std::vector<T>& e) {
  int n = int(q.size()) - 1;
  const T& like = q.front();
  const std::vector<T>& cn = binomial_row(n, like);
  const std::vector<T>& cr = binomial_row(r, like);
  const std::vector<T>& cnr = binomial_row(n + r, like);
  if constexpr (std::is_same_v<T, Bounded<double>>)  // exact binomial rows: the guard's a-priori bound
    if (n + r <= 56 && cnr[(n + r) / 2].bound() == 0) {
      running_error_loops::elevate_exact_binomials(q, r, cn.data(), cr.data(), cnr.data(), e);
      return;
    }
  e.resize(n + r + 1);
  for (int k = 0; k <= n + r; ++k) {
    T acc = T(0);
    for (int j = std::max(0, k - r); j <= std::min(n, k); ++j) {
      T term = cn[j] * cr[k - j] * q[j];
      acc = acc + term;
    }
    e[k] = acc / cnr[k];
  }
}
// Degree elevation by r: the same polynomial in the basis of degree n + r.
template <class T>
Bern<T> elevate(const Bern<T>& q, int r) {
  if (r <= 0) return q;
  Bern<T> e;
  elevate_into(std::span<const T>(q.b), r, e.b);
  return e;
}

template <class T>
Bern<T> operator+(const Bern<T>& x, const Bern<T>& y) {
  int n = std::max(x.degree(), y.degree());
  Bern<T> a = elevate(x, n - x.degree());
  if (y.degree() == n) {
    for (int i = 0; i <= n; ++i) a.b[i] = a.b[i] + y.b[i];
  } else {
    Bern<T> c = elevate(y, n - y.degree());
    for (int i = 0; i <= n; ++i) a.b[i] = a.b[i] + c.b[i];
  }
  return a;
}
template <class T>
Bern<T> operator-(const Bern<T>& x) {
  Bern<T> r = x;
  for (auto& v : r.b) v = -v;
  return r;
}
template <class T>
Bern<T> operator-(const Bern<T>& x, const Bern<T>& y) {
  return x + (-y);
}
template <class T>
Bern<T> operator*(const T& s, Bern<T> x) {
  for (auto& v : x.b) v = s * v;
  return x;
}
template <class T>
Bern<T> operator*(int s, const Bern<T>& x) {
  return T(s) * x;
}

// Product in Bernstein form: c_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j.
template <class T>
Bern<T> operator*(const Bern<T>& x, const Bern<T>& y) {
  check_deadline_product(x.b.size() * y.b.size());  // as Poly<T>::operator* (kernel/polynomial.hpp)
  int m = x.degree(), n = y.degree();
  const T& like = x.b.front();
  const std::vector<T>& cm = binomial_row(m, like);
  const std::vector<T>& cn = binomial_row(n, like);
  const std::vector<T>& cmn = binomial_row(m + n, like);
  std::vector<T> xs(m + 1, T(0)), ys(n + 1, T(0));
  for (int i = 0; i <= m; ++i) xs[i] = cm[i] * x.b[i];
  for (int j = 0; j <= n; ++j) ys[j] = cn[j] * y.b[j];
  Bern<T> r;
  r.b.assign(m + n + 1, T(0));
  if constexpr (std::is_same_v<T, Bounded<double>>)  // the guard's bound in the same pass
    running_error_loops::convolve(std::span<const T>(xs), std::span<const T>(ys), std::span<T>(r.b));
  else
    for (int i = 0; i <= m; ++i)
      for (int j = 0; j <= n; ++j) {
        T p = xs[i] * ys[j];
        r.b[i + j] = r.b[i + j] + p;
      }
  for (int k = 0; k <= m + n; ++k) r.b[k] = r.b[k] / cmn[k];
  return r;
}

// The derivative's coefficients into d (storage reused, as elevate_into).
template <class T>
void derivative_into(std::span<const T> q, std::vector<T>& d) {
  int n = int(q.size()) - 1;
  d.clear();
  if (n <= 0) {
    d.push_back(T(0));
    return;
  }
  for (int i = 0; i < n; ++i) {
    T diff = q[i + 1] - q[i];
    d.push_back(T(n) * diff);
  }
}
template <class T>
Bern<T> derivative(const Bern<T>& q) {
  Bern<T> d;
  derivative_into(std::span<const T>(q.b), d.b);
  return d;
}

// de Casteljau subdivision at tau: the pieces on [0, tau] and [tau, 1], each
// reparameterised to [0, 1].
// (The working row of the triangle ends as the right piece: round r leaves
// w[n - r] final, so right is computed in place.)
template <class T>
std::pair<Bern<T>, Bern<T>> split(const Bern<T>& q, const T& tau) {
  int n = q.degree();
  count_triangle(std::max(n, 0));
  Bern<T> left, right(q.b);
  std::vector<T>& w = right.b;
  left.b.resize(n + 1);
  left.b[0] = w[0];
  T s = T(1) - tau;
  if constexpr (std::is_same_v<T, Bounded<double>>) {  // the guard's bound in the same pass
    running_error_loops::de_casteljau(std::span<T>(w), s, tau, left.b.data());
    return {std::move(left), std::move(right)};
  }
  if constexpr (kMpfrStep<T>) {
    HalvingStep<T> step(tau);
    for (int r = 1; r <= n; ++r) {
      for (int i = 0; i + r <= n; ++i) step(w[i], w[i + 1]);
      left.b[r] = w[0];
    }
    return {std::move(left), std::move(right)};
  }
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i + r <= n; ++i) {
      T x = s * w[i];
      T y = tau * w[i + 1];
      w[i] = x + y;
    }
    left.b[r] = w[0];
  }
  return {std::move(left), std::move(right)};
}

}  // namespace eccd
