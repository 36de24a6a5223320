// Subresultants and the quartic discriminant (kernel/subresultants.hpp,
// kernel/discriminant.hpp), exactly over the rationals.
#include "number/rational_traits.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/subresultants.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("The quartic discriminant is Res(f, f') / lc(f)", "[subresultants]") {
  std::mt19937_64 rng(eccd::test::seed_from_env(7));
  std::uniform_int_distribution<int> c(-20, 20);
  for (int it = 0; it < 200; ++it) {
    std::vector<Rational> f(5);
    for (auto& x : f) x = c(rng);
    if (f[4] == 0) f[4] = 3;
    Rational res = subresultant_coefficient(f, lambda_derivative(f), 0, 0, Rational(0));
    CHECK(res == f[4] * quartic_discriminant(f[4], f[3], f[2], f[1], f[0]));
  }
}

TEST_CASE("The first non-zero psc gives the gcd degree, and S_j is the gcd", "[subresultants]") {
  // f = (λ+2)² (λ-1)(λ-3): gcd(f, f') = λ + 2, so psc_0 = 0, psc_1 ≠ 0, S_1 ∝ λ + 2
  auto mul = [](std::vector<Rational> a, const std::vector<Rational>& b) {
    std::vector<Rational> r(a.size() + b.size() - 1, Rational(0));
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
    return r;
  };
  std::vector<Rational> f = mul(mul(mul({2, 1}, {2, 1}), {-1, 1}), {-3, 1});
  auto fp = lambda_derivative(f);
  CHECK(subresultant_coefficient(f, fp, 0, 0, Rational(0)) == 0);
  Rational s11 = subresultant_coefficient(f, fp, 1, 1, Rational(0)),
           s10 = subresultant_coefficient(f, fp, 1, 0, Rational(0));
  REQUIRE(s11 != 0);
  CHECK(-s10 / s11 == -2);  // the double root
  // f = (λ-1)² (λ+1)²: gcd of degree 2, psc_1 = 0, S_2 ∝ λ² - 1
  std::vector<Rational> h = mul(mul({-1, 1}, {-1, 1}), mul({1, 1}, {1, 1}));
  auto hp = lambda_derivative(h);
  CHECK(subresultant_coefficient(h, hp, 1, 1, Rational(0)) == 0);
  Rational a = subresultant_coefficient(h, hp, 2, 2, Rational(0)),
           b = subresultant_coefficient(h, hp, 2, 1, Rational(0)),
           c0 = subresultant_coefficient(h, hp, 2, 0, Rational(0));
  REQUIRE(a != 0);
  CHECK(b == 0);
  CHECK(c0 / a == -1);
}

}  // namespace ECCD_UNITY_ID
