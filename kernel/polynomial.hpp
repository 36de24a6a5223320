#pragma once
// Poly<T>: univariate polynomials in the power basis, p(t) = sum c[i] t^i.
//
// Statement. The plain representation in which the papers state f(λ;t) and
// Δ(t) (003 eq. (1)-(2); 002 section 3). Paper 003 section VI-C reports that
// building Δ(t) of degree 24k in this basis in double precision loses all
// accuracy above motion degree 2; the workbench measures that claim, it does
// not assume it (compare Bern<T> in kernel/bernstein.hpp).
//
// Requirements on T: scalar_traits<T>; +, -, *, construction from int.
// Division (divide_exact, pseudo-remainders) is used only with exact T.
// Known failure modes: Horner evaluation of high degree in rounded arithmetic
// near a cluster of roots; trim() only drops coefficients that are exactly 0.
#include "kernel/budget.hpp"
#include "number/integer_poly_product.hpp"
#include "number/rational_convolution.hpp"
#include "number/rational_poly_eval.hpp"
#include "number/running_error_loops.hpp"
#include "number/scalar_traits.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace eccd {

template <class T>
struct Poly {
  std::vector<T> c;  // c[i] is the coefficient of t^i; empty = the zero polynomial

  Poly() = default;
  explicit Poly(std::vector<T> coeffs) : c(std::move(coeffs)) { trim(); }
  static Poly constant(const T& v) {
    Poly p;
    p.c.push_back(v);
    p.trim();
    return p;
  }

  int degree() const { return int(c.size()) - 1; }  // -1 for the zero polynomial
  bool is_zero() const { return c.empty(); }
  const T& lead() const { return c.back(); }
  T coeff(int i) const { return (i >= 0 && i < int(c.size())) ? c[i] : T(0); }

  void trim() {
    while (!c.empty() && eccd::is_zero(c.back())) c.pop_back();
  }

  template <class U>
  U operator()(const U& t) const {  // Horner
    if (c.empty()) return U(0);
    count_work(c.size() - 1);  // a step per coefficient (kernel/budget.hpp: a work budget follows them)
    if constexpr (std::is_same_v<T, mpq_class> &&
                  std::is_same_v<U, mpq_class>)  // exact: integer Horner (number/rational_poly_eval.hpp)
      return rational_poly_eval(c, t);
    if constexpr (std::is_same_v<T, Bounded<double>> &&
                  std::is_same_v<U, Bounded<double>>)  // the bound in the same pass
      return running_error_loops::horner(std::span<const T>(c), t);
    U r = U(c.back());
    for (int i = int(c.size()) - 2; i >= 0; --i) {
      r = r * t;
      r = r + U(c[i]);
    }
    return r;
  }

  Poly& operator+=(const Poly& o) {
    if (o.c.size() > c.size()) c.resize(o.c.size(), T(0));
    for (std::size_t i = 0; i < o.c.size(); ++i) c[i] = c[i] + o.c[i];
    trim();
    return *this;
  }
  Poly& operator-=(const Poly& o) {
    if (o.c.size() > c.size()) c.resize(o.c.size(), T(0));
    for (std::size_t i = 0; i < o.c.size(); ++i) c[i] = c[i] - o.c[i];
    trim();
    return *this;
  }
  friend Poly operator+(Poly a, const Poly& b) {
    a += b;
    return a;
  }
  friend Poly operator-(Poly a, const Poly& b) {
    a -= b;
    return a;
  }
  friend Poly operator-(Poly a) {
    for (auto& x : a.c) x = -x;
    return a;
  }
  // A product is where building f, Δ or a subresultant spends its time (degree
  // up to 432 in 3D, millions of MPFR operations): it asks the run's deadline
  // (kernel/budget.hpp check_deadline_product) and throws BudgetExhausted once it has passed.
  friend Poly operator*(const Poly& a, const Poly& b) {
    check_deadline_product(a.c.size() * b.c.size());
    Poly r;
    if (a.c.empty() || b.c.empty()) return r;
    if constexpr (std::is_same_v<T, mpq_class>) {
      // The same canonical rationals either way: long factors by Kronecker substitution
      // (number/integer_poly_product.hpp), short ones over common denominators
      // (number/rational_convolution.hpp, empty when that would not pay).
      if (std::min(a.c.size(), b.c.size()) > 2) {
        r.c = rational_poly_product(a.c, b.c);
        r.trim();
        return r;
      }
      r.c = rational_convolution(a.c, b.c);
      if (!r.c.empty()) {
        r.trim();
        return r;
      }
    }
    r.c.assign(a.c.size() + b.c.size() - 1, T(0));
    if constexpr (std::is_same_v<T, Bounded<double>>)  // the guard's bound in the same pass
      running_error_loops::convolve(std::span<const T>(a.c), std::span<const T>(b.c), std::span<T>(r.c));
    else
      for (std::size_t i = 0; i < a.c.size(); ++i)
        for (std::size_t j = 0; j < b.c.size(); ++j) {
          T p = a.c[i] * b.c[j];
          r.c[i + j] = r.c[i + j] + p;
        }
    r.trim();
    return r;
  }
  friend Poly operator*(const T& s, Poly a) {
    for (auto& x : a.c) x = s * x;
    a.trim();
    return a;
  }
  friend Poly operator*(int s, const Poly& a) { return T(s) * a; }
  friend bool operator==(const Poly& a, const Poly& b) { return a.c == b.c; }
};

template <class T>
Poly<T> derivative(const Poly<T>& p) {
  Poly<T> d;
  for (int i = 1; i <= p.degree(); ++i) d.c.push_back(T(i) * p.c[i]);
  d.trim();
  return d;
}

// The coefficient-wise image of p under a conversion (e.g. exact → double).
template <class U, class T, class F>
Poly<U> map_coeffs(const Poly<T>& p, F f) {
  Poly<U> r;
  r.c.reserve(p.c.size());
  for (const auto& x : p.c) r.c.push_back(f(x));
  r.trim();
  return r;
}

// Polynomial division with remainder; exact arithmetic only (T a field).
template <class T>
void divide(const Poly<T>& a, const Poly<T>& b, Poly<T>& q, Poly<T>& r) {
  static_assert(scalar_traits<T>::is_exact, "polynomial division is exact-only");
  if (b.is_zero()) throw std::domain_error("polynomial division by zero");
  r = a;
  q = Poly<T>();
  if (a.degree() < b.degree()) return;
  q.c.assign(a.degree() - b.degree() + 1, T(0));
  while (!r.is_zero() && r.degree() >= b.degree()) {
    int k = r.degree() - b.degree();
    T f = r.lead() / b.lead();
    q.c[k] = f;
    for (int i = 0; i <= b.degree(); ++i) {
      T p = f * b.c[i];
      r.c[i + k] = r.c[i + k] - p;
    }
    r.c.back() = T(0);  // cancelled exactly
    r.trim();
  }
  q.trim();
}

// Monic gcd over the rationals (Euclid); exact arithmetic only.
template <class T>
Poly<T> gcd(Poly<T> a, Poly<T> b) {
  static_assert(scalar_traits<T>::is_exact, "polynomial gcd is exact-only");
  while (!b.is_zero()) {
    Poly<T> q, r;
    divide(a, b, q, r);
    a = std::move(b);
    b = std::move(r);
  }
  if (!a.is_zero()) {
    T l = a.lead();
    for (auto& x : a.c) x = x / l;
  }
  return a;
}

}  // namespace eccd
