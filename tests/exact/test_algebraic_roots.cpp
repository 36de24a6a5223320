// exact/algebraic_roots.hpp: real roots with certified brackets, exact signs at
// them, refinement; checked against roots known in closed form and against
// Descartes' rule (exact/descartes.hpp) on the brackets and the gaps.
#include "exact/algebraic_roots.hpp"
#include "exact/descartes.hpp"

#include <catch2/catch.hpp>

#include <cstdint>

namespace ECCD_UNITY_ID {
using namespace eccd;
using Q = mpq_class;
using RP = Poly<Rational>;

namespace {

RP poly(std::initializer_list<Q> c) { return RP(std::vector<Rational>(c)); }
RP pow(const RP& p, int k) {
  RP r = poly({1});
  for (int i = 0; i < k; ++i) r = r * p;
  return r;
}
Q two_pow(int e) {  // 2^e, e may be negative
  Q r(1);
  if (e >= 0)
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), e);
  else
    mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), -e);
  return r;
}
Q width(const AlgebraicRoot& r) { return r.hi - r.lo; }

// The bracket holds a root of p of odd multiplicity: p changes sign over it
// (or it is exact and p vanishes there).
bool holds_sign_change(const RP& p, const AlgebraicRoot& r) {
  if (r.is_rational()) return sign(p(r.lo)) == Sign::zero;
  return sgn(p(r.lo)) * sgn(p(r.hi)) < 0;
}

// Every bracket holds exactly one root of its square-free factor, no other
// factor has a root in it, and the gaps between the brackets (within [a, b])
// hold no root of p: a complete exact check of real_roots' guarantee for
// polynomials whose roots are well separated from the gaps' ends.
void check_isolation(const RP& p, const std::vector<AlgebraicRoot>& roots, const Q& a, const Q& b, int bits) {
  const auto F = square_free_factors(p);
  RP sqf = poly({1});
  for (const auto& f : F) sqf = sqf * f.first;
  Q prev = a;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const AlgebraicRoot& r = roots[i];
    INFO("root " << i << " in [" << r.lo.get_str() << ", " << r.hi.get_str() << "]");
    REQUIRE(r.lo <= r.hi);
    CHECK(a <= r.lo);
    CHECK(r.hi <= b);
    CHECK(width(r) <= two_pow(-bits));
    if (i > 0) CHECK(roots[i - 1].hi < r.lo);
    if (r.is_rational()) {
      CHECK(sign(p(r.lo)) == Sign::zero);
    } else {
      CHECK(sign(p(r.lo)) != Sign::zero);
      CHECK(sign(p(r.hi)) != Sign::zero);
      for (const auto& [f, m] : F) CHECK(descartes_variations(f, r.lo, r.hi) == (m == r.multiplicity ? 1 : 0));
    }
    if (prev < r.lo) CHECK(descartes_variations(sqf, prev, r.lo) == 0);
    prev = r.hi;
  }
  if (prev < b) CHECK(descartes_variations(sqf, prev, b) == 0);
}

}  // namespace

TEST_CASE("real_roots: irrational roots in [0, 1] get disjoint certified brackets of width 2^-64",
          "[exact][algebraic_roots]") {
  // (2t^2 - 1)(3t^2 - 1)(t - 2): roots ±1/√2, ±1/√3, 2; in [0, 1]: 1/√3 < 1/√2.
  RP p = poly({-1, 0, 2}) * poly({-1, 0, 3}) * poly({-2, 1});
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 2);
  check_isolation(p, roots, Q(0), Q(1), 64);
  // 1/√3: lo^2 < 1/3 < hi^2; 1/√2: lo^2 < 1/2 < hi^2
  CHECK(roots[0].lo * roots[0].lo < Q(1, 3));
  CHECK(Q(1, 3) < roots[0].hi * roots[0].hi);
  CHECK(roots[1].lo * roots[1].lo < Q(1, 2));
  CHECK(Q(1, 2) < roots[1].hi * roots[1].hi);
  for (const auto& r : roots) CHECK(r.multiplicity == 1);
}

TEST_CASE("real_roots: multiplicities, and rational roots written exactly", "[exact][algebraic_roots]") {
  // (2t^2 - 1)^2 (t - 1/3)^3 (t + 1) (7t - 2)
  RP p = pow(poly({-1, 0, 2}), 2) * pow(poly({Q(-1, 3), 1}), 3) * poly({1, 1}) * poly({-2, 7});
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 3);
  CHECK(roots[0].is_rational());
  CHECK(roots[0].lo == Q(2, 7));
  CHECK(roots[0].multiplicity == 1);
  CHECK(roots[1].is_rational());
  CHECK(roots[1].lo == Q(1, 3));
  CHECK(roots[1].multiplicity == 3);
  CHECK(!roots[2].is_rational());
  CHECK(roots[2].multiplicity == 2);
  check_isolation(p, roots, Q(0), Q(1), 64);
  // over [-2, 2]: -1/√2, -1 as well
  auto all = real_roots(p, Q(-2), Q(2), 64);
  REQUIRE(all.size() == 5);
  CHECK(all[0].lo == Q(-1));
  CHECK(all[0].is_rational());
  check_isolation(p, all, Q(-2), Q(2), 64);
}

TEST_CASE("real_roots: roots at the ends of the range are exact and included, outside ones are not",
          "[exact][algebraic_roots]") {
  // t (t - 1) (2t^2 - 1) (t - 3/2) (t + 1/5)
  RP p = poly({0, 1}) * poly({-1, 1}) * poly({-1, 0, 2}) * poly({Q(-3, 2), 1}) * poly({Q(1, 5), 1});
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 3);
  CHECK(roots[0].is_rational());
  CHECK(roots[0].lo == 0);
  CHECK(roots[2].is_rational());
  CHECK(roots[2].lo == 1);
  check_isolation(p, roots, Q(0), Q(1), 64);
  // a range whose ends are non-dyadic roots
  auto mid = real_roots(p, Q(-1, 5), Q(3, 2), 64);
  REQUIRE(mid.size() == 5);
  CHECK(mid.front().lo == Q(-1, 5));
  CHECK(mid.back().lo == Q(3, 2));
  // a range just short of them
  auto inner = real_roots(p, Q(-1, 5) + two_pow(-100), Q(3, 2) - two_pow(-100), 64);
  CHECK(inner.size() == 3);
}

TEST_CASE("real_roots: roots 2^-80 apart get disjoint brackets (refined past 2^-64)", "[exact][algebraic_roots]") {
  // (t - 1/2)^2 - 2^-161: roots 1/2 ± 2^-80.5 (irrational), and (t^2 - 1/2) for another factor
  RP close = poly({Q(1, 4) - two_pow(-161), -1, 1});
  RP p = close * poly({Q(-1, 2), 0, 1});
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 3);
  CHECK(roots[0].hi < Q(1, 2));
  CHECK(Q(1, 2) < roots[1].lo);
  for (int i = 0; i < 2; ++i) {
    CHECK(!roots[i].is_rational());
    CHECK(holds_sign_change(close, roots[i]));
  }
  CHECK(roots[0].hi < roots[1].lo);
  CHECK(roots[1].hi < roots[2].lo);
  check_isolation(p, roots, Q(0), Q(1), 64);
}

TEST_CASE("real_roots: a degree-60 product with 30 roots in [0, 1]", "[exact][algebraic_roots]") {
  // prod_{i=1..30} (t^2 - i/31 - 1/997): 30 irrational roots in (0, 1), none near a gap end
  RP p = poly({1});
  for (int i = 1; i <= 30; ++i) p = p * poly({-Q(i, 31) - Q(1, 997), 0, 1});
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 30);
  for (int i = 0; i < 30; ++i) {
    Q v = Q(i + 1, 31) + Q(1, 997);
    CHECK(roots[i].lo * roots[i].lo < v);
    CHECK(v < roots[i].hi * roots[i].hi);
  }
  check_isolation(p, roots, Q(0), Q(1), 64);
  // Wider brackets on request
  auto coarse = real_roots(p, Q(0), Q(1), 8);
  REQUIRE(coarse.size() == 30);
  check_isolation(p, coarse, Q(0), Q(1), 8);
}

TEST_CASE("sign_at: zero, positive and negative at algebraic numbers, also when the value is tiny",
          "[exact][algebraic_roots]") {
  RP p = poly({-1, 0, 2}) * poly({-2, 1});  // root 1/√2 in [0, 1]
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 1);
  const AlgebraicRoot& r = roots[0];
  CHECK(sign_at(poly({-1, 0, 2}) * poly({5, 1}), r) == Sign::zero);  // shares the root
  CHECK(sign_at(poly({-1, 0, 2, 0, 0, 1}) * poly({0, 1, 1}) - poly({0, 1, 1}) * poly({0, 0, 0, 0, 0, 1}), r) ==
        Sign::zero);
  CHECK(sign_at(poly({-1, 0, 3}), r) == Sign::positive);  // 3/2 - 1
  CHECK(sign_at(poly({1, 0, -3}), r) == Sign::negative);
  CHECK(sign_at(poly({7}), r) == Sign::positive);
  CHECK(sign_at(RP(), r) == Sign::zero);
  // t - c with c a rational 2^-200 above and below 1/√2: the bracket of width
  // 2^-64 cannot decide, refinement must.
  // c = 1/√2 to 210 bits: floor(2^210 / √2) / 2^210 by integer square root
  mpz_class s;
  mpz_class n = mpz_class(1) << 419;       // (2^210)^2 / 2
  mpz_sqrt(s.get_mpz_t(), n.get_mpz_t());  // floor(2^209.5)
  Q below(s, mpz_class(1) << 210), above(s + 1, mpz_class(1) << 210);
  below.canonicalize();
  above.canonicalize();
  REQUIRE(below * below * 2 < 1);
  REQUIRE(above * above * 2 > 1);
  CHECK(sign_at(poly({-below, 1}), r) == Sign::positive);
  CHECK(sign_at(poly({-above, 1}), r) == Sign::negative);
  CHECK(sign_at(poly({above, -1}), r) == Sign::positive);
  // (t - below)(t - above): negative between them
  CHECK(sign_at(poly({-below, 1}) * poly({-above, 1}), r) == Sign::negative);
  // the root itself is unchanged by sign_at (a copy is refined)
  CHECK(width(r) <= two_pow(-64));
  CHECK(width(r) > two_pow(-128));
}

TEST_CASE("sign_at: polynomials whose power-basis coefficients cancel heavily near the root",
          "[exact][algebraic_roots]") {
  // (2t - 1)^60 at 1/√2 is (√2 - 1)^60 ≈ 2^-76, its coefficients up to ~2^117
  // (the mean-value bound on a 2^-64 bracket cannot decide; Taylor terms can).
  RP p = poly({-1, 0, 2}) * poly({-3, 1});
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 1);
  const AlgebraicRoot& r = roots[0];
  RP c = pow(poly({-1, 2}), 60);
  CHECK(sign_at(c, r) == Sign::positive);
  CHECK(sign_at(-1 * c, r) == Sign::negative);
  // (√2 - 1)^60 = u - v√2 with integers u, v (u^2 - 2 v^2 = 1); then c - u + v·(2t) vanishes at 1/√2
  mpz_class u = 1, v = 0;  // (u + v√2)(-1 + √2) = (2v - u) + (u - v)√2, starting from 1
  for (int i = 0; i < 60; ++i) {
    mpz_class nu = 2 * v - u, nv = u - v;
    u = nu;
    v = nv;
  }
  // now (√2 - 1)^60 = u + v√2
  RP z = c - poly({Q(u), Q(2 * v)});  // c(t) - (u + v·2t): zero at t = 1/√2
  CHECK(sign_at(z, r) == Sign::zero);
  CHECK(sign_at(z + poly({two_pow(-300)}), r) == Sign::positive);
  CHECK(sign_at(z - poly({two_pow(-300)}), r) == Sign::negative);
  CHECK(sign_at(c * poly({-2, 1}) + poly({two_pow(-90)}), r) == Sign::negative);  // -1.29·2^-76 + 2^-90
}

TEST_CASE("sign_at and refine at rational roots", "[exact][algebraic_roots]") {
  RP p = poly({Q(-1, 3), 1}) * poly({-1, 0, 2});
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 2);
  REQUIRE(roots[0].is_rational());
  CHECK(sign_at(poly({Q(-1, 3), 1}), roots[0]) == Sign::zero);
  CHECK(sign_at(poly({0, 1}), roots[0]) == Sign::positive);
  CHECK(sign_at(poly({Q(-1, 2), 1}), roots[0]) == Sign::negative);
  AlgebraicRoot x = roots[0];
  refine(x, 200);
  CHECK(x.lo == Q(1, 3));
  CHECK(x.hi == Q(1, 3));
}

TEST_CASE("refine: narrower brackets of the same root, from dyadic and from arbitrary rational brackets",
          "[exact][algebraic_roots]") {
  RP p = poly({-1, 0, 2}) * poly({-1, 0, 3});
  auto roots = real_roots(p, Q(0), Q(1), 64);
  REQUIRE(roots.size() == 2);
  AlgebraicRoot r = roots[1];  // 1/√2
  Q lo0 = r.lo, hi0 = r.hi;
  refine(r, 300);
  CHECK(width(r) <= two_pow(-300));
  CHECK(lo0 <= r.lo);
  CHECK(r.hi <= hi0);
  CHECK(r.lo * r.lo * 2 < 1);
  CHECK(r.hi * r.hi * 2 > 1);
  refine(r, 100);  // already narrower: unchanged
  CHECK(width(r) <= two_pow(-300));
  // A bracket with non-dyadic ends (any isolating bracket is allowed).
  AlgebraicRoot s = roots[1];
  s.lo = Q(2, 3);
  s.hi = Q(5, 7);
  refine(s, 80);
  CHECK(width(s) <= two_pow(-80));
  CHECK(s.lo * s.lo * 2 < 1);
  CHECK(s.hi * s.hi * 2 > 1);
  AlgebraicRoot u = roots[1];
  u.lo = Q(2, 3);
  u.hi = Q(5, 7);
  CHECK(sign_at(poly({Q(-7, 10), 1}), u) == Sign::positive);
  CHECK(sign_at(poly({-1, 0, 2}), u) == Sign::zero);
}

TEST_CASE("square_free_factors and polynomial_gcd", "[exact][algebraic_roots]") {
  RP a = poly({-1, 0, 2}), b = poly({Q(-1, 3), 1}), c = poly({1, 1, 1});
  RP p = a * pow(b, 2) * pow(c, 3);
  auto F = square_free_factors(p);
  REQUIRE(F.size() == 3);
  CHECK(F[0].second == 1);
  CHECK(F[1].second == 2);
  CHECK(F[2].second == 3);
  CHECK(F[0].first == a);
  CHECK(F[1].first == poly({-1, 3}));
  CHECK(F[2].first == c);
  CHECK(polynomial_gcd(p, a * poly({5, 1})) == a);
}

TEST_CASE("real_roots on [0, 1] (square-free fast path) agrees with the general isolation on random products",
          "[exact][algebraic_roots]") {
  // Products of linear factors k t - m (roots in and around [0, 1], including
  // 0, 1 and dyadic midpoints that the bisection hits exactly), k t^2 - m
  // (irrational roots), t^2 + 1 and roots < 0, scaled by a big rational;
  // some with a repeated factor (not square-free: the general path). The
  // [0, 1] answer must pass the complete isolation check and match, root by
  // root, the general path's on q(s) = p(s / 2) over [0, 2] (the same roots,
  // doubled: the general path runs for every range other than [0, 1]).
  std::uint64_t state = 12345;
  auto next = [&state](std::uint64_t m) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (state >> 33) % m;
  };
  for (int trial = 0; trial < 60; ++trial) {
    RP p = poly({Q(1)});
    const int factors = 2 + int(next(6));
    for (int f = 0; f < factors; ++f) {
      switch (next(5)) {
        case 0:
          p = p * poly({Q(-long(next(9)), 8), 1});
          break;  // m/8: 0, 1/2, 1, ... exact
        case 1:
          p = p * poly({Q(-long(next(2001))), Q(long(1 + next(1000)))});
          break;  // m/k in [0, 2]
        case 2:
          p = p * poly({Q(-long(1 + next(97)), long(1 + next(97))), 0, 1});
          break;  // t^2 - c
        case 3:
          p = p * poly({1, 0, 1});
          break;  // ±i
        default:
          p = p * poly({Q(long(3 + next(5))), 1});
          break;  // a root < 0
      }
    }
    if (next(4) == 0) p = p * poly({Q(-1, 3), 1}) * poly({Q(-1, 3), 1});  // a double root at 1/3
    p = Q(long(1 + next(1000000)), long(1 + next(1000))) * p;
    INFO("trial " << trial << ", degree " << p.degree());
    auto fast = real_roots(p, Q(0), Q(1), 64);
    check_isolation(p, fast, Q(0), Q(1), 64);
    RP q = p;
    for (int i = 0; i <= q.degree(); ++i) q.c[i] *= two_pow(-i);
    auto general = real_roots(q, Q(0), Q(2), 64);
    REQUIRE(fast.size() == general.size());
    for (std::size_t i = 0; i < fast.size(); ++i) {
      CHECK(fast[i].multiplicity == general[i].multiplicity);
      CHECK(fast[i].is_rational() == general[i].is_rational());
      CHECK(2 * fast[i].lo <= general[i].hi);  // the brackets of one root overlap
      CHECK(general[i].lo <= 2 * fast[i].hi);
    }
  }
}

}  // namespace ECCD_UNITY_ID
