// Simplest rationals in an interval (number/simplest_rational.hpp), against
// brute force in exact arithmetic: simplest_dyadic_between(a, b) is strictly
// inside (a, b) and no dyadic with a smaller power of two is;
// simplest_rational_in(lo, hi) is in [lo, hi] and has the smallest
// denominator of any rational there (found by trying denominators 1, 2, ...).
#include "number/rational_traits.hpp"
#include "number/simplest_rational.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// The smallest k such that some m / 2^k lies strictly inside (a, b).
unsigned smallest_dyadic_power(const Rational& a, const Rational& b) {
  for (unsigned k = 0;; ++k) {
    const mpz_class den = mpz_class(1) << k;
    const Rational scaled = a * Rational(den);
    mpz_class m;
    mpz_fdiv_q(m.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());  // floor(a 2^k)
    Rational c(m + 1, den);
    c.canonicalize();
    if (c < b) return k;
  }
}

// The smallest d such that some n / d lies in [lo, hi].
mpz_class smallest_denominator(const Rational& lo, const Rational& hi) {
  for (mpz_class d = 1;; ++d) {
    const Rational scaled = lo * Rational(d);
    mpz_class n;
    mpz_cdiv_q(n.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());  // ceil(lo d)
    Rational c(n, d);
    c.canonicalize();
    if (c <= hi) return d;
  }
}

Rational random_fraction(std::mt19937_64& rng) {
  std::uniform_int_distribution<long> num(-5000, 5000), den(1, 997);
  Rational q(num(rng), den(rng));
  q.canonicalize();
  return q;
}

}  // namespace

TEST_CASE("simplest_dyadic_between: known values and the shortest dyadic on random intervals",
          "[number][simplest_rational]") {
  CHECK(simplest_dyadic_between(Rational(1, 3), Rational(2, 3)) == Rational(1, 2));
  CHECK(simplest_dyadic_between(Rational(1, 3), Rational(2, 5)) == Rational(3, 8));
  CHECK(simplest_dyadic_between(Rational(0), Rational(1)) == Rational(1, 2));
  CHECK(simplest_dyadic_between(Rational(-1, 2), Rational(3)) == Rational(0));
  CHECK(simplest_dyadic_between(Rational(1, 2), Rational(1)) == Rational(3, 4));  // strictly inside: not 1/2
  std::mt19937_64 rng(371);
  for (int trial = 0; trial < 500; ++trial) {
    Rational a = random_fraction(rng), b = random_fraction(rng);
    if (a == b) continue;
    if (b < a) std::swap(a, b);
    if (trial % 3 == 0) b = a + Rational(1, 1000000 + trial);  // narrow intervals
    const Rational c = simplest_dyadic_between(a, b);
    INFO("(" << a.get_str() << ", " << b.get_str() << ") -> " << c.get_str());
    CHECK((a < c && c < b));
    // c's denominator is 2^k with k the smallest possible
    const unsigned k = smallest_dyadic_power(a, b);
    CHECK(c.get_den() == (mpz_class(1) << k));
  }
}

TEST_CASE("simplest_rational_in: the smallest denominator in [lo, hi]", "[number][simplest_rational]") {
  CHECK(simplest_rational_in(Rational(33, 100), Rational(34, 100)) == Rational(1, 3));
  CHECK(simplest_rational_in(Rational(3, 2), Rational(7, 4)) == Rational(3, 2));
  CHECK(simplest_rational_in(Rational(2), Rational(2)) == Rational(2));
  // π's convergent 355/113 is the simplest rational in [3.14159, 3.14160]
  CHECK(simplest_rational_in(Rational(314159, 100000), Rational(314160, 100000)) == Rational(355, 113));
  std::mt19937_64 rng(372);
  for (int trial = 0; trial < 500; ++trial) {
    Rational lo = random_fraction(rng), hi = random_fraction(rng);
    if (hi < lo) std::swap(lo, hi);
    if (trial % 2 == 0) hi = lo + Rational(1, 10000 + trial);
    const Rational r = simplest_rational_in(lo, hi);
    INFO("[" << lo.get_str() << ", " << hi.get_str() << "] -> " << r.get_str());
    CHECK((lo <= r && r <= hi));
    CHECK(r.get_den() == smallest_denominator(lo, hi));
  }
}

}  // namespace ECCD_UNITY_ID
