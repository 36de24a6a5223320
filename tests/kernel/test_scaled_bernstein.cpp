// kernel/scaled_bernstein.hpp: the scaled Bernstein form
// p(t) = sum s[i] t^i (1 - t)^(n - i) of 003 section VI-C (Variant 1). Checked
// against that defining sum evaluated directly in mpq at rational t (inside
// and outside [0, 1]), over seeded random polynomials: to_scaled of a
// Bernstein form and back, elevation by r (the same polynomial, one degree
// higher each step), +, -, unary -, int * and the product (a plain
// convolution, no binomial weights: the statement's reason for Variant 1);
// the sign pattern of s is that of the Bernstein coefficients; in double the
// round trip Bernstein -> scaled -> Bernstein is within a few ulps.
#include "kernel/bernstein.hpp"
#include "kernel/scaled_bernstein.hpp"
#include "number/rational_traits.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using test::q;  // a / b in lowest terms (tests/support/exact_values.hpp)

Rational value(const ScaledBern<Rational>& p, const Rational& t) {
  Rational s = 0;
  const int n = p.degree();
  for (int i = 0; i <= n; ++i) {
    Rational term = p.s[i];
    for (int k = 0; k < i; ++k) term *= t;
    for (int k = 0; k < n - i; ++k) term *= 1 - t;
    s += term;
  }
  return s;
}

ScaledBern<Rational> random_scaled(std::mt19937_64& rng) {
  ScaledBern<Rational> p;
  for (int i = 0, n = int(rng() % 6); i <= n; ++i) p.s.push_back(q(long(rng() % 41) - 20, long(rng() % 5) + 1));
  return p;
}

}  // namespace

TEST_CASE("scaled Bernstein: conversions, elevation and ring operations keep the value of the defining sum",
          "[kernel][scaled_bernstein]") {
  std::mt19937_64 rng(4318);
  for (int trial = 0; trial < 100; ++trial) {
    const ScaledBern<Rational> x = random_scaled(rng), y = random_scaled(rng);
    const Bern<Rational> bx = to_bernstein(x);
    CHECK(bx.degree() == x.degree());
    const ScaledBern<Rational> back = to_scaled(bx);
    CHECK(back.s == x.s);
    const int r = int(rng() % 3);
    const ScaledBern<Rational> ex = elevate(x, r);
    CHECK(ex.degree() == x.degree() + r);
    const ScaledBern<Rational> sum = x + y, diff = x - y, neg = -x, prod = x * y, three = 3 * x;
    CHECK(sum.degree() == std::max(x.degree(), y.degree()));
    CHECK(prod.degree() == x.degree() + y.degree());
    for (int k = -2; k <= 6; ++k) {
      const Rational t = q(k, 4);
      const Rational vx = value(x, t), vy = value(y, t);
      INFO("trial " << trial << " t = " << t);
      if (t >= 0 && t <= 1) CHECK(bx(t) == vx);  // the Bernstein form evaluates on [0, 1]
      CHECK(value(ex, t) == vx);
      CHECK(value(sum, t) == vx + vy);
      CHECK(value(diff, t) == vx - vy);
      CHECK(value(neg, t) == -vx);
      CHECK(value(prod, t) == vx * vy);
      CHECK(value(three, t) == 3 * vx);
    }
    // s[i] = C(n, i) b[i] with C(n, i) > 0: the same signs, so the same sign variations.
    for (int i = 0; i <= x.degree(); ++i) CHECK(sgn(x.s[i]) == sgn(bx.b[i]));
  }
}

TEST_CASE("scaled Bernstein in double: the round trip from Bernstein form is within a few ulps",
          "[kernel][scaled_bernstein]") {
  std::mt19937_64 rng(4319);
  std::uniform_real_distribution<double> d(-1, 1);
  for (int trial = 0; trial < 100; ++trial) {
    Bern<double> b;
    for (int i = 0, n = 1 + int(rng() % 20); i <= n; ++i) b.b.push_back(d(rng));
    const Bern<double> back = to_bernstein(to_scaled(b));
    REQUIRE(back.b.size() == b.b.size());
    // one product and one quotient by the same exact binomial (below 2^53 for n <= 20): two roundings.
    for (std::size_t i = 0; i < b.b.size(); ++i) CHECK(std::abs(back.b[i] - b.b[i]) <= 2 * 0x1p-52 * std::abs(b.b[i]));
  }
}

}  // namespace ECCD_UNITY_ID
