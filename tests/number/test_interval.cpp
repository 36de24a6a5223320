// Interval (number/interval.hpp): intervals of doubles that enclose exact
// results, with certain-or-uncertain signs.
//  - operations and chains of them on random rationals enclose the exact
//    rational results; a sign is uncertain whenever the interval holds 0 and
//    is not the point 0;
//  - interval_of(q) (fast paths for integers and for small fractions) gives
//    exactly MPFR's [RNDD(q), RNDU(q)] on random rationals of every size,
//    including integers near the top of the double range, fractions at the
//    edge of the 53-bit fast path, negative values, dyadics (points) and
//    values with huge denominators (subnormal and underflowing magnitudes);
//  - products and sums of random intervals (normal, huge, subnormal end
//    points) contain the exact product and sum of their end points, or, where
//    an end point overflows to a NaN, claim no sign (number/interval.hpp).
#include "compare/seeded_rng.hpp"
#include "number/interval.hpp"

#include <catch2/catch.hpp>

#include <mpfr.h>

#include <random>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// The reference: MPFR's directed roundings (interval_of's fast paths must give the same end points).
std::pair<double, double> mpfr_enclosure(const mpq_class& q) {
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDD);
  double lo = mpfr_get_d(r, MPFR_RNDD);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDU);
  double hi = mpfr_get_d(r, MPFR_RNDU);
  mpfr_clear(r);
  return {lo, hi};
}

mpz_class random_int(std::mt19937_64& rng, int bits) {
  mpz_class z = 0;
  for (int k = 0; k < bits; k += 32) z = (z << 32) + mpz_class(std::to_string(rng() & 0xffffffffu));
  if (bits % 32) z >>= (32 - bits % 32);
  return z;
}

// Encloses v, or (overflow: inf - inf gives a NaN end point) claims no sign at all.
bool encloses(const Interval& x, const mpq_class& v) {
  if (std::isnan(x.lo) || std::isnan(x.hi)) return scalar_traits<Interval>::sign(x) == Sign::uncertain;
  return (std::isinf(x.lo) || mpq_class(x.lo) <= v) && (std::isinf(x.hi) || v <= mpq_class(x.hi));
}

bool contains(const Interval& x, const Rational& q) {
  Rational lo(x.lo), hi(x.hi);
  return lo <= q && q <= hi;
}

double random_double(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> m(0.5, 1.0);
  std::uniform_int_distribution<int> e(-1070, 1020), coin(0, 5);
  double x = std::ldexp(m(rng), coin(rng) == 0 ? e(rng) : e(rng) / 20);
  if (coin(rng) == 1) x = std::ldexp(double(rng() & 0xfffff), -1074);  // subnormal (or 0)
  return rng() & 1 ? -x : x;
}

}  // namespace

TEST_CASE("interval_of is MPFR's tightest enclosure on every path", "[certified][interval-speed]") {
  std::mt19937_64 rng(1804);
  std::uniform_int_distribution<int> bits(1, 60), big(40, 1100), small(1, 120);
  long points = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    mpq_class q;
    switch (trial % 5) {
      case 0:
        q = mpq_class(random_int(rng, big(rng)));
        break;  // integers, up to past 2^1024
      case 1:
        q = mpq_class(random_int(rng, bits(rng)), random_int(rng, bits(rng)) + 1);
        break;  // around the 53-bit edge
      case 2:
        q = mpq_class(random_int(rng, small(rng)), random_int(rng, small(rng) * 9) + 1);
        break;  // up to subnormal
      case 3:
        q = mpq_class(random_int(rng, bits(rng)), mpz_class(1) << bits(rng));
        break;  // dyadics: points
      default:
        q = mpq_class(random_int(rng, small(rng)), (mpz_class(1) << (1000 + bits(rng))) + 3);
        break;  // underflow
    }
    q.canonicalize();
    if (rng() & 1) q = -q;
    const auto [lo, hi] = mpfr_enclosure(q);
    const Interval x = interval_of(q);
    INFO(q.get_str());
    CHECK(x.lo == lo);
    CHECK(x.hi == hi);
    CHECK(std::signbit(x.lo) == std::signbit(lo));
    if (lo == hi) ++points;
  }
  CHECK(points > 4000);
  // The edges of the fast paths, one by one.
  for (const char* s : {"9007199254740993", "-9007199254740993", "9007199254740992", "1/3", "-1/3",
                        "9007199254740991/9007199254740992", "1/9007199254740991", "9007199254740993/3", "0", "-5/1"}) {
    mpq_class q(s);
    q.canonicalize();
    const auto [lo, hi] = mpfr_enclosure(q);
    INFO(s);
    CHECK(interval_of(q).lo == lo);
    CHECK(interval_of(q).hi == hi);
  }
  const mpq_class huge(mpz_class(1) << 1023);
  CHECK(interval_of(huge).lo == 0x1p1023);
  CHECK(interval_of(huge + 1).hi == std::nextafter(0x1p1023, 2 * 0x1p1023));
}

TEST_CASE("interval sums and products enclose the exact results", "[certified][interval-speed]") {
  std::mt19937_64 rng(27);
  for (int trial = 0; trial < 20000; ++trial) {
    double a = random_double(rng), b = random_double(rng), c = random_double(rng), d = random_double(rng);
    const Interval x(std::min(a, b), std::max(a, b)), y(std::min(c, d), std::max(c, d));
    const Interval p = x * y, s = x + y, m = x - y;
    // every product of end points (the extremes of the exact product set) lies inside
    for (double u : {x.lo, x.hi})
      for (double v : {y.lo, y.hi}) {
        const mpq_class pu(u), pv(v);
        CHECK(encloses(p, pu * pv));
        CHECK(encloses(s, pu + pv));
        CHECK(encloses(m, pu - pv));
      }
    const Interval pt = Interval(a, a) * Interval(c, c);  // the point path
    CHECK(encloses(pt, mpq_class(a) * mpq_class(c)));
  }
  // 0 · inf and NaN: the whole line (never a wrong sign).
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(scalar_traits<Interval>::sign(Interval(0, 1) * Interval(1, inf)) == Sign::uncertain);
  CHECK(scalar_traits<Interval>::sign(Interval(-inf, inf) * Interval(2, 3)) == Sign::uncertain);
  CHECK(scalar_traits<Interval>::sign(Interval(std::nan(""), 1) * Interval(2, 3)) == Sign::uncertain);
  CHECK(scalar_traits<Interval>::sign(Interval(2, 3) * Interval(4, 5)) == Sign::positive);
}

TEST_CASE("Interval operations enclose the exact rational results", "[certified][interval]") {
  SeededRng rng{20261121};
  for (int k = 0; k < 2000; ++k) {
    Rational a = rng.frac(-1000000, 1000000, rng.uniform(1, 999983)),
             b = rng.frac(-1000000, 1000000, rng.uniform(1, 999983));
    Interval A = interval_of(a), B = interval_of(b);
    INFO(a << " " << b);
    REQUIRE(contains(A, a));
    CHECK(contains(A + B, Rational(a + b)));
    CHECK(contains(A - B, Rational(a - b)));
    CHECK(contains(A * B, Rational(a * b)));
    if (b != 0) CHECK(contains(A / B, Rational(a / b)));
    // a chain: (a*b - a) * (b + 1/3)
    Rational third(1, 3);
    CHECK(contains((A * B - A) * (B + interval_of(third)), Rational((a * b - a) * (b + third))));
  }
  // Signs are certain or uncertain, never guessed.
  CHECK(scalar_traits<Interval>::sign(Interval(-1e-300, 1e-300)) == Sign::uncertain);
  CHECK(scalar_traits<Interval>::sign(interval_of(Rational(1, 3)) - interval_of(Rational(1, 3))) == Sign::uncertain);
  CHECK(scalar_traits<Interval>::sign(Interval(0, 0)) == Sign::zero);
  CHECK(scalar_traits<Interval>::sign(Interval(1, 1) / Interval(-1, 1)) == Sign::uncertain);
}

}  // namespace ECCD_UNITY_ID
