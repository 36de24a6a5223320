// kernel/modular_coprime.hpp: a proof of coprimality from one gcd modulo
// p = 2^61 - 1. Checked against:
//   - the field operations modulo p against mpz arithmetic (mul, sub,
//     inverse: a · a⁻¹ ≡ 1, residue of negative integers in [0, p));
//   - soundness over seeded random pairs: whenever coprime_mod_p says true, the
//     exact gcd over Q (kernel/polynomial.hpp) is a constant; pairs built with
//     a common factor are never called coprime;
//   - an unlucky prime: t and t + p are coprime over Q but not modulo p, so the
//     answer is "not proved" (false), as the statement allows; a denominator
//     or a leading numerator divisible by p is refused (false);
//   - content_is_constant on matrices with and without a common factor.
#include "kernel/modular_coprime.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;
const mpz_class kP = mpz_class((unsigned long)modp::kPrime);

RP random_poly(std::mt19937_64& rng, int deg) {
  std::vector<Rational> c;
  for (int i = 0; i <= deg; ++i) {
    Rational x(long(rng() % 61) - 30, long(rng() % 7) + 1);
    x.canonicalize();
    c.push_back(x);
  }
  if (c.back() == 0) c.back() = 1;
  return RP(c);
}

}  // namespace

TEST_CASE("modp arithmetic agrees with mpz arithmetic modulo 2^61 - 1", "[kernel][modular_coprime]") {
  std::mt19937_64 rng(4331);
  for (int k = 0; k < 2000; ++k) {
    const std::uint64_t a = rng() % modp::kPrime, b = rng() % modp::kPrime;
    const mpz_class za((unsigned long)a), zb((unsigned long)b);
    mpz_class prod = (za * zb) % kP, diff = ((za - zb) % kP + kP) % kP;
    CHECK(mpz_class((unsigned long)modp::mul(a, b)) == prod);
    CHECK(mpz_class((unsigned long)modp::sub(a, b)) == diff);
    if (a != 0) CHECK(modp::mul(a, modp::inverse(a)) == 1);
  }
  CHECK(modp::mul(modp::kPrime - 1, modp::kPrime - 1) == 1);  // (-1)² = 1
  CHECK(modp::residue(mpz_class(-1)) == modp::kPrime - 1);
  CHECK(modp::residue(kP * 5 + 3) == 3);
  CHECK(modp::residue(-(kP * 5) - 3) == modp::kPrime - 3);
}

TEST_CASE("coprime_mod_p is sound: true only for pairs whose exact gcd is constant", "[kernel][modular_coprime]") {
  std::mt19937_64 rng(4332);
  int proved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const RP a = random_poly(rng, 1 + int(rng() % 4)), b = random_poly(rng, 1 + int(rng() % 4));
    const bool said = coprime_mod_p(a, b);
    const bool exact = gcd(a, b).degree() == 0;
    INFO("trial " << trial);
    if (said) CHECK(exact);
    proved += said;
    // with a built-in common factor h of degree >= 1: never called coprime
    const RP h = random_poly(rng, 1 + int(rng() % 2));
    CHECK_FALSE(coprime_mod_p(h * a, h * b));
  }
  CHECK(proved > 150);  // random pairs are coprime, and the filter proves most of them
}

TEST_CASE("coprime_mod_p: edge cases and an unlucky prime", "[kernel][modular_coprime]") {
  const RP t({Rational(0), Rational(1)});
  CHECK_FALSE(coprime_mod_p(RP(), t));                                // zero
  CHECK(coprime_mod_p(RP::constant(Rational(5)), t));                 // a non-zero constant
  CHECK(coprime_mod_p(t, RP({Rational(1), Rational(1)})));            // t and t + 1
  const RP tp({Rational(kP), Rational(1)});                           // t + p
  CHECK(gcd(t, tp).degree() == 0);                                    // coprime over Q
  CHECK_FALSE(coprime_mod_p(t, tp));                                  // but t ≡ t + p mod p: not proved
  CHECK_FALSE(coprime_mod_p(RP({Rational(1), Rational(1, kP)}), t));  // p divides a denominator
  CHECK_FALSE(coprime_mod_p(RP({Rational(1), Rational(kP * 3)}), t + RP::constant(Rational(2))));  // p | lc
}

TEST_CASE("content_is_constant on polynomial matrices", "[kernel][modular_coprime]") {
  const RP t({Rational(0), Rational(1)}), h({Rational(2), Rational(1)});  // h = t + 2
  std::array<std::array<RP, 2>, 2> m{};
  m[0][0] = h * t;
  m[0][1] = h * (t * t + RP::constant(Rational(1)));
  m[1][1] = h;
  CHECK_FALSE(content_is_constant(m));  // the common factor t + 2
  m[1][0] = t - RP::constant(Rational(3));
  CHECK(content_is_constant(m));  // t - 3 is coprime to (t + 2) t
  std::array<std::array<RP, 2>, 2> z{};
  CHECK_FALSE(content_is_constant(z));  // all zero
  z[1][0] = RP::constant(Rational(-7));
  CHECK(content_is_constant(z));  // one constant entry
}

}  // namespace ECCD_UNITY_ID
