#pragma once
// Dual<T>: a value and its derivative (forward automatic differentiation),
// so that one templated formula gives Δ(t) and Δ'(t) (the cycloidal
// pipeline, kernel/cycloidal_cd_disc.hpp, needs Δ' to prove a root simple
// and a cell monotone).
//
// Statement. (a, a') ± (b, b') = (a ± b, a' ± b'), (a, a')(b, b') = (ab,
// a'b + ab'); sin/cos of π x: number/enclosure.hpp. With T an enclosing type
// (Bounded<U>: mid-point and radius, MpfiInterval: end points) every part of
// the result encloses the exact value or derivative: the rules are applied
// in T's own enclosing arithmetic. Division is not provided (the cycloidal
// formulas are polynomial in t, cos and sin).
// Requirements on T: ring operations and T(int) for small constants.
#include "number/scalar_traits.hpp"

#include <utility>

namespace eccd {

template <class T>
struct Dual {
  T v, d;
  Dual() : v(0), d(0) {}
  Dual(int k) : v(k), d(0) {}  // NOLINT: small exact constants, as T(3) in templated code
  Dual(T value, T deriv) : v(std::move(value)), d(std::move(deriv)) {}

  friend Dual operator+(const Dual& a, const Dual& b) { return Dual(a.v + b.v, a.d + b.d); }
  friend Dual operator-(const Dual& a, const Dual& b) { return Dual(a.v - b.v, a.d - b.d); }
  friend Dual operator*(const Dual& a, const Dual& b) { return Dual(a.v * b.v, a.d * b.v + a.v * b.d); }
  Dual operator-() const { return Dual(-v, -d); }
  Dual& operator+=(const Dual& o) { return *this = *this + o; }
  Dual& operator-=(const Dual& o) { return *this = *this - o; }
  Dual& operator*=(const Dual& o) { return *this = *this * o; }
};

}  // namespace eccd
