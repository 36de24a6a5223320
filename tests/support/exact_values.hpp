#pragma once
// Test support: the exact rational value of a rounded number (an MPFR value,
// a double, a long double bound), and random rationals of a given size, for
// tests that compare a rounded computation with exact arithmetic.
#include "number/mpfr_real.hpp"

#include <gmpxx.h>

#include <cmath>
#include <random>
#include <string>

namespace eccd::test {

// x exactly: its significand times a power of two.
inline mpq_class exact_of(const Mpfr& x) {
  if (mpfr_zero_p(x.get())) return 0;  // its exponent is MPFR's least: no shift of 2^30 bits
  mpz_class m;
  const long e = long(mpfr_get_z_2exp(m.get_mpz_t(), x.get()));
  mpq_class q(m);
  if (e >= 0)
    q *= mpq_class(mpz_class(1) << e);
  else
    q /= mpq_class(mpz_class(1) << -e);
  return q;
}

inline mpq_class exact_of(double x) { return mpq_class(x); }

// a / b in lowest terms (gmpxx's mpq_class(a, b) is not reduced, and == then compares unreduced fractions).
inline mpq_class q(long a, long b) {
  mpq_class x(a, b);
  x.canonicalize();
  return x;
}

// A long double bound as a rational, exactly (64-bit significand).
inline mpq_class exact_of(long double e) {
  int ex = 0;
  const long double f = std::frexp(e, &ex);  // e = f 2^ex, 1/2 <= f < 1
  const mpz_class m(static_cast<unsigned long>(std::ldexp(f, 64)));
  ex -= 64;
  mpq_class q(m);
  if (ex >= 0)
    q *= mpq_class(mpz_class(1) << ex);
  else
    q /= mpq_class(mpz_class(1) << -ex);
  return q;
}

// A random rational with numerator and denominator of about `bits` bits, either sign.
inline mpq_class random_rational(std::mt19937_64& rng, int bits) {
  mpz_class n = 0, d = 0;
  for (int k = 0; k < bits; k += 30) {
    n = (n << 30) + mpz_class(std::to_string(rng() & ((1u << 30) - 1)));
    d = (d << 30) + mpz_class(std::to_string(rng() & ((1u << 30) - 1)));
  }
  if (d == 0) d = 1;
  if (rng() & 1) n = -n;
  mpq_class q(n, d);
  q.canonicalize();
  return q;
}

inline mpq_class abs_q(const mpq_class& q) { return q < 0 ? mpq_class(-q) : q; }

}  // namespace eccd::test
