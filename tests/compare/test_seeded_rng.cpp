// SeededRng (compare/seeded_rng.hpp): splitmix64 (Steele, Lea, Flood 2014),
// the generator every seeded scene is built from, so its numbers must be the
// same on every standard library and machine.
//  - next() is splitmix64: the outputs for seeds 0 and 1234567 are the
//    published reference vectors of Vigna's splitmix64.c (also recomputed by a
//    three-line Python transcription of that C code, shown below); the state
//    advances by the golden gamma 0x9e3779b97f4a7c15 per draw, modulo 2^64;
//  - uniform(lo, hi) is lo + next() mod (hi - lo + 1): values computed by hand
//    from the seed-42 outputs, every draw within [lo, hi], both ends reached,
//    a one-value range always gives that value;
//  - frac(lo, hi, den) is uniform(lo, hi) / den as a canonical rational
//    (gcd(num, den) = 1, den > 0), checked exactly against mpq arithmetic.
// Python used for the reference values (M = 2^64 - 1):
//   s = (s + 0x9e3779b97f4a7c15) & M; z = s
//   z = ((z ^ (z >> 30)) * 0xbf58476d1ce4e5b9) & M
//   z = ((z ^ (z >> 27)) * 0x94d049bb133111eb) & M; out = z ^ (z >> 31)
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("seeded rng: next() gives splitmix64's reference outputs", "[compare][seeded-rng]") {
  SeededRng zero{0};
  CHECK(zero.next() == 0xe220a8397b1dcdafULL);
  CHECK(zero.next() == 0x6e789e6aa1b965f4ULL);
  CHECK(zero.next() == 0x06c45d188009454fULL);
  SeededRng r{1234567};
  CHECK(r.next() == 0x599ed017fb08fc85ULL);
  CHECK(r.next() == 0x2c73f08458540fa5ULL);
  CHECK(r.next() == 0x883ebce5a3f27c77ULL);
  // The state is a Weyl sequence: seed + n * gamma (mod 2^64) after n draws, wrapping silently.
  SeededRng w{~std::uint64_t(0)};
  for (int n = 0; n < 1000; ++n) w.next();
  CHECK(w.s == ~std::uint64_t(0) + 1000 * 0x9e3779b97f4a7c15ULL);
  // Same seed, same sequence; neighbouring seeds, different outputs.
  SeededRng a{77}, b{77}, c{78};
  bool all_same = true, any_same_as_c = false;
  for (int n = 0; n < 100; ++n) {
    const std::uint64_t x = a.next(), y = b.next(), z = c.next();
    all_same = all_same && x == y;
    any_same_as_c = any_same_as_c || x == z;
  }
  CHECK(all_same);
  CHECK_FALSE(any_same_as_c);
}

TEST_CASE("seeded rng: uniform() is lo + next() mod the range's size, within [lo, hi]", "[compare][seeded-rng]") {
  // Seed 42's first outputs: 0xbdd732262feb6e95, 0x28efe333b266f103, 0x47526757130f9f52, 0x581ce1ff0e4ae394.
  SeededRng r{42};
  CHECK(r.uniform(-5, 5) == 4);     // -5 + 0xbdd732262feb6e95 mod 11 = -5 + 9
  CHECK(r.uniform(0, 999) == 291);  // 0x28efe333b266f103 mod 1000
  CHECK(r.uniform(-7, 7) == -4);    // -7 + 0x47526757130f9f52 mod 15 = -7 + 3
  CHECK(r.uniform(0, 6) == 2);      // 0x581ce1ff0e4ae394 mod 7
  SeededRng s{2024};
  std::set<long> seen;
  bool inside = true;
  for (int n = 0; n < 2000; ++n) {
    const long x = s.uniform(-3, 3);
    inside = inside && x >= -3 && x <= 3;
    seen.insert(x);
  }
  CHECK(inside);
  CHECK(seen.size() == 7);  // both ends and everything between
  for (int n = 0; n < 20; ++n) CHECK(s.uniform(5, 5) == 5);
  // Large ranges stay inside too.
  bool big_inside = true;
  for (int n = 0; n < 2000; ++n) {
    const long x = s.uniform(-1000000000000L, 1000000000000L);
    big_inside = big_inside && x >= -1000000000000L && x <= 1000000000000L;
  }
  CHECK(big_inside);
}

TEST_CASE("seeded rng: frac() is uniform() over den, canonical", "[compare][seeded-rng]") {
  SeededRng r{42};
  r.next(), r.next();
  // The third output of seed 42 gives uniform(-7, 7) = -4, so -4/6 = -2/3.
  const Rational q = r.frac(-7, 7, 6);
  CHECK(q == Rational(-2, 3));
  CHECK(q.get_num() == -2);
  CHECK(q.get_den() == 3);

  SeededRng a{99}, b{99};
  bool equal = true, canonical = true;
  for (int n = 0; n < 2000; ++n) {
    const long den = 1 + n % 12;
    const Rational x = a.frac(-50, 50, den);
    mpq_class expect(b.uniform(-50, 50), den);
    expect.canonicalize();
    equal = equal && x == expect;
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), x.get_num().get_mpz_t(), x.get_den().get_mpz_t());
    canonical = canonical && g == 1 && x.get_den() > 0 && (x != 0 || x.get_den() == 1);
  }
  CHECK(equal);
  CHECK(canonical);
}

}  // namespace ECCD_UNITY_ID
