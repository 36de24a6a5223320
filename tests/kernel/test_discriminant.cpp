// The discriminants of kernel/discriminant.hpp against the product formula:
// for f = a ∏ (λ - r_i) of degree n, disc(f) = a^(2n-2) ∏_{i<j} (r_i - r_j)²
// (the cubic of 003 section III eq. (2), the quartic of 002 section III), on
// random rational roots in exact arithmetic; and the double root of a cubic
// is P / (2D) (003 section VI-B), its triple root the case D = 0; a cubic
// whose coefficients are polynomials in t with a double root for every t has
// Δ ≡ 0 in power and in Bernstein form.
#include "kernel/discriminant.hpp"
#include "kernel/bernstein.hpp"
#include "number/rational_traits.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

namespace {

// The coefficients of a ∏ (λ - r_i), highest first.
std::vector<Rational> from_roots(const Rational& a, const std::vector<Rational>& roots) {
  std::vector<Rational> c{a};  // highest first
  for (const Rational& r : roots) {
    std::vector<Rational> next(c.size() + 1, Rational(0));
    for (std::size_t i = 0; i < c.size(); ++i) {
      next[i] += c[i];
      next[i + 1] -= r * c[i];
    }
    c = next;
  }
  return c;
}

Rational product_formula(const Rational& a, const std::vector<Rational>& roots) {
  Rational p = 1;
  const int n = int(roots.size());
  for (int k = 0; k < 2 * n - 2; ++k) p *= a;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) p *= (roots[i] - roots[j]) * (roots[i] - roots[j]);
  return p;
}

Rational random_rational(std::mt19937_64& rng) {
  std::uniform_int_distribution<long> n(-40, 40), d(1, 12);
  Rational q(n(rng), d(rng));
  q.canonicalize();
  return q;
}

}  // namespace

TEST_CASE("the cubic and quartic discriminants equal the product of squared root differences",
          "[kernel][discriminant][exact]") {
  std::mt19937_64 rng(376);
  for (int trial = 0; trial < 300; ++trial) {
    Rational a = random_rational(rng);
    if (a == 0) a = 1;
    std::vector<Rational> r3{random_rational(rng), random_rational(rng), random_rational(rng)};
    if (trial % 5 == 0) r3[1] = r3[0];  // a double root: Δ = 0
    const auto g = from_roots(a, r3);
    INFO("trial " << trial);
    CHECK(cubic_discriminant(g[0], g[1], g[2], g[3]) == product_formula(a, r3));
    std::vector<Rational> r4 = r3;
    r4.push_back(random_rational(rng));
    const auto q = from_roots(a, r4);
    CHECK(quartic_discriminant(q[0], q[1], q[2], q[3], q[4]) == product_formula(a, r4));
  }
  // a known value: λ³ - λ = λ(λ - 1)(λ + 1), Δ = (0 - 1)² (0 + 1)² (1 + 1)² = 4
  CHECK(cubic_discriminant(Rational(1), Rational(0), Rational(-1), Rational(0)) == 4);
}

TEST_CASE("the double root of a cubic is P / (2D), and D = 0 at a triple root", "[kernel][discriminant][exact]") {
  std::mt19937_64 rng(377);
  for (int trial = 0; trial < 200; ++trial) {
    Rational a = random_rational(rng), r = random_rational(rng), s = random_rational(rng);
    if (a == 0) a = 1;
    if (s == r) s += 1;
    const auto g = from_roots(a, {r, r, s});
    const Rational P = double_root_numerator(g[0], g[1], g[2], g[3]);
    const Rational D = double_root_denominator(g[0], g[1], g[2]);
    INFO("double root " << r.get_str() << ", simple root " << s.get_str());
    REQUIRE(D != 0);
    CHECK(P / (2 * D) == r);
    const auto t = from_roots(a, {r, r, r});
    CHECK(double_root_denominator(t[0], t[1], t[2]) == 0);
    CHECK(cubic_discriminant(t[0], t[1], t[2], t[3]) == 0);
  }
}

TEST_CASE("the cubic discriminant vanishes exactly on a double root, in every representation",
          "[kernel][discriminant]") {
  std::mt19937_64 rng(seed_from_env(11));
  for (int trial = 0; trial < 10; ++trial) {
    // f(λ) = (λ - r(t))² (λ - s(t)) with r, s polynomials in t: Δ ≡ 0.
    Poly<Q> r = random_poly(rng, 2), s = random_poly(rng, 1), one({Q(1)});
    Poly<Q> g3 = one, g2 = Q(-1) * (2 * r + s), g1 = r * r + 2 * (r * s), g0 = Q(-1) * (r * r * s);
    CHECK(cubic_discriminant(g3, g2, g1, g0).is_zero());
    Bern<Q> b3 = to_bernstein(g3, 0), b2 = to_bernstein(g2), b1 = to_bernstein(g1), b0 = to_bernstein(g0);
    Bern<Q> db = cubic_discriminant(b3, b2, b1, b0);
    for (const auto& c : db.b) CHECK(c == 0);
    // and the double root is P / (2D)
    Q t = Q(2, 7);
    Q lam = double_root_numerator(g3(t), g2(t), g1(t), g0(t)) / (2 * double_root_denominator(g3(t), g2(t), g1(t)));
    if (r(t) != s(t)) CHECK(lam == r(t));
  }
  // Distinct roots 1, 2, 3: Δ = ((1-2)(1-3)(2-3))² = 4.
  CHECK(cubic_discriminant(Q(1), Q(-6), Q(11), Q(-6)) == 4);
}

}  // namespace ECCD_UNITY_ID
