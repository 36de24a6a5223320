// kernel/quartic_touch_rule.hpp: whether the characteristic quartic has a
// negative multiple root, from signs of subresultant coefficients of f and
// f' (002 section III, 001 section 4). Checked on quartics built from chosen
// multiple roots, so the answer is known by construction:
//   j = 1: f = g4 (λ - r)² (λ - a)(λ - b), the double root r = -s10/s11;
//   j = 2: f = g4 (λ - r1)² (λ - r2)² (both signs, a root at 0), a double
//          complex pair (λ² + c)², a triple root (λ - r)³ (λ - a);
//   j = 3: f = g4 (λ - r)⁴, the root r = -s32 / (3 s33);
// with exact signs of subresultant_evidence (mpq) as sign_of, for seeded
// random roots; the projection index k = 1 (two spheres: psc_0 ≡ 0); an
// uncertain sign propagates; the evidence names a certificate uses.
#include "kernel/quartic_touch_rule.hpp"
#include "kernel/polynomial.hpp"
#include "number/rational_traits.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

using test::q;  // a / b in lowest terms (tests/support/exact_values.hpp)
RP lin(const Rational& r) { return RP({-r, Rational(1)}); }

std::vector<Rational> coeffs(const RP& f) {
  std::vector<Rational> g(f.c);
  g.resize(5, Rational(0));
  return g;
}
Sign rule(const std::vector<Rational>& g, int k = 0) {
  return negative_multiple_root(k, [&](int j, int i) { return sign(subresultant_evidence(g, j, i)); });
}
Sign want(bool negative) { return negative ? Sign::positive : Sign::zero; }

}  // namespace

TEST_CASE("negative_multiple_root on quartics with chosen multiple roots", "[kernel][quartic_touch_rule]") {
  std::mt19937_64 rng(4327);
  auto root = [&]() -> Rational { return q(long(rng() % 41) - 20, long(rng() % 4) + 1); };
  int cases = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Rational g4 = -q(long(rng() % 5) + 1, 1);
    const Rational r = root();
    Rational a = root(), b = root();
    while (a == r) a += q(1, 3);
    while (b == r || b == a) b += q(1, 5);
    INFO("trial " << trial << " r = " << r << " a = " << a << " b = " << b);
    {  // j = 1: one double root r
      const auto g = coeffs(RP::constant(g4) * lin(r) * lin(r) * lin(a) * lin(b));
      CHECK(sign(subresultant_evidence(g, 0, 0)) == Sign::zero);  // psc_0 = 0: the projection vanishes
      CHECK(-subresultant_evidence(g, 1, 0) / subresultant_evidence(g, 1, 1) == r);
      CHECK(rule(g) == want(r < 0));
    }
    {  // j = 2: two double roots r and a
      const auto g = coeffs(RP::constant(g4) * lin(r) * lin(r) * lin(a) * lin(a));
      CHECK(sign(subresultant_evidence(g, 1, 1)) == Sign::zero);
      CHECK(rule(g) == want(r < 0 || a < 0));
    }
    {  // j = 2: a triple root (gcd (λ - r)², its discriminant 0)
      const auto g = coeffs(RP::constant(g4) * lin(r) * lin(r) * lin(r) * lin(a));
      CHECK(sign(subresultant_evidence(g, 2, -1)) == Sign::zero);
      CHECK(rule(g) == want(r < 0));
    }
    {  // j = 3: a quadruple root
      const auto g = coeffs(RP::constant(g4) * lin(r) * lin(r) * lin(r) * lin(r));
      CHECK(-subresultant_evidence(g, 3, 2) / (3 * subresultant_evidence(g, 3, 3)) == r);
      CHECK(rule(g) == want(r < 0));
    }
    ++cases;
  }
  CHECK(cases == 60);
}

TEST_CASE("negative_multiple_root: complex double pairs, a root at 0, two spheres, uncertainty",
          "[kernel][quartic_touch_rule]") {
  // (λ² + 4)²: a double complex pair: no real multiple root.
  const RP sq = lin(Rational(0)) * lin(Rational(0)) + RP::constant(Rational(4));
  CHECK(rule(coeffs(RP::constant(Rational(-1)) * sq * sq)) == Sign::zero);
  // ((λ + 1)² + 4)²: complex pair with negative real part: still no real root.
  const RP sq2 = lin(Rational(-1)) * lin(Rational(-1)) + RP::constant(Rational(4));
  CHECK(rule(coeffs(RP::constant(Rational(-1)) * sq2 * sq2)) == Sign::zero);
  // double roots 0 and -2 (s20 = 0 branch), 0 and 3.
  CHECK(rule(coeffs(lin(Rational(0)) * lin(Rational(0)) * lin(Rational(-2)) * lin(Rational(-2)))) == Sign::positive);
  CHECK(rule(coeffs(lin(Rational(0)) * lin(Rational(0)) * lin(Rational(3)) * lin(Rational(3)))) == Sign::zero);
  // Two spheres: λ = 1 is a double root for every t, so psc_0 ≡ 0 and the projection is psc_1 (k = 1); at its root
  // a second double root r appears and j = 2 decides: touching iff r < 0.
  for (const long r : {-3L, 2L}) {
    const auto g =
        coeffs(RP::constant(Rational(-1)) * lin(Rational(1)) * lin(Rational(1)) * lin(Rational(r)) * lin(Rational(r)));
    CHECK(rule(g, 1) == want(r < 0));
  }
  // An uncertain sign anywhere on the path: uncertain.
  CHECK(negative_multiple_root(0, [](int, int) { return Sign::uncertain; }) == Sign::uncertain);
  CHECK(negative_multiple_root(0, [](int j, int i) { return j == 1 && i == 1 ? Sign::positive : Sign::uncertain; }) ==
        Sign::uncertain);
  // Every psc_j zero (impossible with g4 ≠ 0): uncertain, never a claim.
  CHECK(negative_multiple_root(0, [](int, int) { return Sign::zero; }) == Sign::uncertain);
  CHECK(subresultant_evidence_name(1, 0) == "s(1,0)");
  CHECK(subresultant_evidence_name(3, 3) == "s(3,3)");
  CHECK(subresultant_evidence_name(2, -1) == "disc(S_2)");
}

}  // namespace ECCD_UNITY_ID
