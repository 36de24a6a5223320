// primitive_integer_multiple (exact/integer_polynomial.hpp): for a rational
// polynomial p, integers z_i with gcd 1 and z = λ p for a rational λ > 0.
// Checked on random rational polynomials (mpq_class): z_i integers, gcd of
// the z_i equal to 1, z_i p_j = z_j p_i for all i, j (proportional), and z_i
// of the sign of p_i (λ > 0); hand-worked cases; zero coefficients inside,
// the zero polynomial (all zeros, nothing divided), a constant, integers with
// a common factor, negative leading coefficient (the sign is kept).
#include "compare/seeded_rng.hpp"
#include "exact/integer_polynomial.hpp"

#include <catch2/catch.hpp>

#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("primitive_integer_multiple is a positive primitive integer multiple", "[exact][integer_polynomial]") {
  SeededRng rng{4242};
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Rational> c;
    const int n = int(rng.uniform(0, 8));
    for (int i = 0; i <= n; ++i)
      c.push_back(rng.uniform(0, 4) == 0 ? Rational(0) : rng.frac(-5000, 5000, rng.uniform(1, 720)));
    if (sgn(c.back()) == 0) c.back() = Rational(3, 7);
    const Poly<Rational> p(c);
    const std::vector<mpz_class> z = primitive_integer_multiple(p);
    REQUIRE(z.size() == p.c.size());
    mpz_class g = 0;
    for (const auto& x : z) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x.get_mpz_t());
    CHECK(g == 1);
    for (std::size_t i = 0; i < z.size(); ++i) {
      CHECK(sgn(z[i]) == sgn(p.c[i]));
      for (std::size_t j = i + 1; j < z.size(); ++j) CHECK(Rational(z[i]) * p.c[j] == Rational(z[j]) * p.c[i]);
    }
  }
}

TEST_CASE("primitive_integer_multiple on hand-worked and degenerate polynomials", "[exact][integer_polynomial]") {
  using Z = std::vector<mpz_class>;
  // 1/2 - (2/3) x + (5/6) x²: lcm 6 -> 3, -4, 5
  CHECK(primitive_integer_multiple(
            Poly<Rational>(std::vector<Rational>{Rational(1, 2), Rational(-2, 3), Rational(5, 6)})) == Z{3, -4, 5});
  // 6 + 0 x - 9 x³: integers with gcd 3 -> 2, 0, 0, -3 (the negative leading sign is kept)
  CHECK(primitive_integer_multiple(Poly<Rational>(std::vector<Rational>{6, 0, 0, -9})) == Z{2, 0, 0, -3});
  // a constant: 1 or -1
  CHECK(primitive_integer_multiple(Poly<Rational>::constant(Rational(-22, 7))) == Z{-1});
  // the zero polynomial: no coefficients; zeros stay zeros
  CHECK(primitive_integer_multiple(Poly<Rational>()).empty());
  Poly<Rational> zeros;
  zeros.c = {0, 0, 0};  // not trimmed: every entry 0, no division by the gcd 0
  CHECK(primitive_integer_multiple(zeros) == Z{0, 0, 0});
  // huge denominators: 1/2^100 + x/3^50
  const Rational a(mpz_class(1), mpz_class(1) << 100);
  mpz_class p3;
  mpz_ui_pow_ui(p3.get_mpz_t(), 3, 50);
  const Z z = primitive_integer_multiple(Poly<Rational>(std::vector<Rational>{a, Rational(mpz_class(1), p3)}));
  CHECK(z == Z{p3, mpz_class(1) << 100});
}

}  // namespace ECCD_UNITY_ID
