#pragma once
// Simplest rationals in an interval: the short sample points and exact
// roots every exact stage writes (one definition for the pipeline, the
// certificate writer, the root isolator and the scene reader's messages).
//
// Statement. simplest_dyadic_between(a, b), a < b: the dyadic m / 2^k with
// the smallest k strictly inside (a, b) (a cell's sample point: short, so the
// static test there is cheap). simplest_rational_in(lo, hi), lo <= hi: the
// rational with the smallest denominator in [lo, hi], by continued fractions
// (a rational root with a small denominator is then written exactly).
// Requirements: GMP rationals (number/rational_traits.hpp). Exact; no double.
#include "number/rational_traits.hpp"

namespace eccd {

inline Rational simplest_dyadic_between(const Rational& a, const Rational& b) {
  for (unsigned k = 0;; ++k) {
    mpz_class den = mpz_class(1) << k;
    Rational scaled = a * Rational(den);
    mpz_class m;
    mpz_fdiv_q(m.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());
    m += 1;
    Rational c(m, den);
    c.canonicalize();
    if (c < b) return c;
  }
}

inline Rational simplest_rational_in(const Rational& lo, const Rational& hi) {
  // an integer in [lo, hi] if there is one
  mpz_class fl;
  mpz_fdiv_q(fl.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
  if (Rational(fl) == lo) return lo;
  mpz_class c = fl + 1;
  if (Rational(c) <= hi) return Rational(c);
  // lo and hi share the integer part fl: recurse on the reciprocals of the fractional parts
  Rational a = lo - Rational(fl), b = hi - Rational(fl);
  Rational inner = simplest_rational_in(1 / b, 1 / a);
  Rational r = Rational(fl) + 1 / inner;
  return r;
}

}  // namespace eccd
