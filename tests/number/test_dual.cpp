// Dual<T> (number/dual.hpp): forward differentiation. A polynomial evaluated
// at Dual(t, 1) gives its value and its derivative at t; in exact rationals
// both equal what the polynomial and its formal derivative give, and the
// product rule holds term by term.
#include "kernel/polynomial.hpp"
#include "number/dual.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("Dual<Rational>: a polynomial at (t, 1) is its value and its derivative", "[number][dual]") {
  std::mt19937_64 rng(374);
  std::uniform_int_distribution<long> c(-50, 50), d(1, 9);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Rational> cs;
    for (int i = 0; i <= 1 + trial % 7; ++i) cs.push_back(Rational(c(rng), d(rng)));
    for (auto& x : cs) x.canonicalize();
    const Poly<Rational> p(cs);
    Rational t(c(rng), d(rng));
    t.canonicalize();
    // Horner in Dual<Rational>
    Dual<Rational> acc(0);
    for (std::size_t i = cs.size(); i-- > 0;) acc = acc * Dual<Rational>(t, Rational(1)) + Dual<Rational>(cs[i], 0);
    // the formal derivative, exactly
    Rational deriv = 0, power = 1;
    for (std::size_t i = 1; i < cs.size(); ++i) {
      deriv += Rational(long(i)) * cs[i] * power;
      power *= t;
    }
    INFO("trial " << trial);
    CHECK(acc.v == p(t));
    CHECK(acc.d == deriv);
  }
}

TEST_CASE("Dual: sums, differences, products and negation follow the rules of derivatives", "[number][dual]") {
  const Dual<Rational> a(Rational(3), Rational(5)), b(Rational(-2, 3), Rational(7));
  const Dual<Rational> p = a * b;
  CHECK(p.v == Rational(-2));
  CHECK(p.d == Rational(5) * Rational(-2, 3) + Rational(3) * Rational(7));  // a'b + ab'
  CHECK((a - b).d == Rational(-2));
  CHECK((-a).v == Rational(-3));
  CHECK((-a).d == Rational(-5));
  Dual<Rational> x = a;
  x *= Dual<Rational>(2);  // a constant: derivative 0
  CHECK(x.v == Rational(6));
  CHECK(x.d == Rational(10));
  x += b;
  CHECK(x.d == Rational(17));
  x -= b;
  CHECK(x.v == Rational(6));
}

}  // namespace ECCD_UNITY_ID
