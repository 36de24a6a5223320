#pragma once
// Test support: the three arithmetics as types, a `like` value per arithmetic,
// and exact -> T conversion, so that kernel tests are written once.
#include "number/rational_traits.hpp"
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "kernel/polynomial.hpp"

#include <random>
#include <string>

namespace eccd::test {

template <class T>
T like();
template <>
inline double like<double>() {
  return 1.0;
}
template <>
inline Mpfr like<Mpfr>() {
  return Mpfr(mpq_class(1), 200);
}
template <>
inline mpq_class like<mpq_class>() {
  return mpq_class(1);
}

template <class T>
T from_q(const mpq_class& q) {
  return scalar_traits<T>::from_rational(q, like<T>());
}
template <class T>
Poly<T> from_q(const Poly<mpq_class>& p) {
  return map_coeffs<T>(p, [](const mpq_class& q) { return from_q<T>(q); });
}
// A tolerance per arithmetic for comparisons against the exact oracle.
template <class T>
double tolerance() {
  return scalar_traits<T>::is_exact ? 0.0 : (std::is_same_v<T, double> ? 1e-9 : 1e-40);
}

inline Poly<mpq_class> random_poly(std::mt19937_64& rng, int degree, int range = 9) {
  std::uniform_int_distribution<int> d(-range, range);
  Poly<mpq_class> p;
  for (int i = 0; i <= degree; ++i) {
    mpq_class c(d(rng), 1 + (rng() % 4));
    c.canonicalize();  // gmpxx compares canonical forms only
    p.c.push_back(c);
  }
  if (p.c.back() == 0) p.c.back() = 1;
  p.trim();
  return p;
}

inline std::uint64_t seed_from_env(std::uint64_t fallback) {
  if (const char* s = std::getenv("ECCD_TEST_SEED")) return std::stoull(s);
  return fallback;
}

}  // namespace eccd::test
