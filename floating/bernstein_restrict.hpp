#pragma once
// Restriction of a Bernstein polynomial to a sub-interval, in place or as a
// copy: c on [a, b] ⊂ [0, 1] re-expressed over [0, 1] by two de Casteljau
// splits (keep_right at a, then keep_left at (b - a) / (1 - a); 001 section 4
// subdivides F(u, t) in t this way). Univariate (Bern) and in t only for a
// bivariate BiBern (each row in u's index is a polynomial in t).
// Requirements on T: scalar_traits<T>, ring operations, division, comparison.
#include "kernel/bernstein.hpp"
#include "kernel/bivariate_bernstein.hpp"
#include "number/scalar_traits.hpp"

#include <span>

namespace eccd {

// c restricted to [a, b] ⊂ [0, 1] in place (two de Casteljau splits, each
// keeping one piece); `one` is 1 at a's precision.
template <class T>
void restrict_in_place(std::span<T> c, const T& a, const T& b, const T& one) {
  const T zero = a - a;
  if (a > zero) keep_right(c, a);
  if (b < one) {
    T tau = (b - a) / (one - a);
    keep_left(c, tau);
  }
}

// q restricted to [a, b] ⊂ [0, 1].
template <class T>
Bern<T> restrict_to(const Bern<T>& q, const T& a, const T& b, const T& one) {
  Bern<T> r = q;
  restrict_in_place(std::span<T>(r.b), a, b, one);
  return r;
}
template <class T>
Bern<T> restrict_to(const Bern<T>& q, const T& a, const T& b) {
  return restrict_to(q, a, b, scalar_traits<T>::from_rational(mpq_class(1), a));
}

template <class T>
BiBern<T> restrict_t(const BiBern<T>& f, const T& a, const T& b, const T& one) {
  BiBern<T> r = f;
  for (auto& row : r.b) restrict_in_place(std::span<T>(row), a, b, one);
  return r;
}
template <class T>
BiBern<T> restrict_t(const BiBern<T>& f, const T& a, const T& b) {
  return restrict_t(f, a, b, scalar_traits<T>::from_rational(mpq_class(1), a));
}

}  // namespace eccd
