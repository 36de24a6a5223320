// Mpfr and scalar_traits<Mpfr> (number/mpfr_real.hpp), against exact
// rationals: from_rational rounds to nearest at the value's precision
// (|x - q| <= 2^-bits |q|), a result carries the larger precision of its
// operands and a small constant adopts its partner's, NaN has no sign.
#include "number/mpfr_real.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>

using namespace eccd;

namespace {

mpq_class exact_of(const Mpfr& x) {
  mpz_class m;
  const long e = long(mpfr_get_z_2exp(m.get_mpz_t(), x.get()));
  mpq_class q(m);
  if (e >= 0)
    q *= mpq_class(mpz_class(1) << e);
  else
    q /= mpq_class(mpz_class(1) << -e);
  return q;
}

// A random rational with numerator and denominator of about `bits` bits.
mpq_class random_rational(std::mt19937_64& rng, int bits) {
  mpz_class n = 0, d = 0;
  for (int k = 0; k < bits; k += 30) {
    n = (n << 30) + mpz_class(std::to_string(rng() & ((1u << 30) - 1)));
    d = (d << 30) + mpz_class(std::to_string(rng() & ((1u << 30) - 1)));
  }
  if (d == 0) d = 1;
  if (rng() & 1) n = -n;
  mpq_class q(n, d);
  q.canonicalize();
  return q;
}

mpq_class abs_q(const mpq_class& q) { return q < 0 ? mpq_class(-q) : q; }

}  // namespace

TEST_CASE("scalar_traits<Mpfr>: rounding to nearest at the value's precision, and precision that travels",
          "[number][scalar_traits][mpfr]") {
  std::mt19937_64 rng(38);
  for (int bits : {53, 64, 113, 200}) {
    for (int trial = 0; trial < 100; ++trial) {
      const mpq_class q = random_rational(rng, 2 * bits);
      const Mpfr x = scalar_traits<Mpfr>::from_rational(q, Mpfr(mpq_class(1), bits));
      INFO(bits << " bits: " << q.get_str());
      CHECK(x.precision() == bits);
      // |x - q| <= 2^-bits |q|: half a unit in the last place of a bits-bit significand
      const mpq_class err = abs_q(exact_of(x) - q);
      mpq_class rel = abs_q(q);
      mpz_class scale = mpz_class(1) << bits;
      CHECK(err * mpq_class(scale) <= rel);
      CHECK(scalar_traits<Mpfr>::sign(x) == sign_of_int(sgn(q)));
    }
  }
  const Mpfr a(mpq_class(1, 3), 80), b(mpq_class(1, 3), 200);
  CHECK((a * b).precision() == 200);
  CHECK((a + a).precision() == 80);
  CHECK((Mpfr(3) * a).precision() == 80);  // a small constant adopts its partner's precision
  CHECK(Mpfr(7).precision() == 0);
  CHECK(exact_of(Mpfr(3) * Mpfr(mpq_class(1, 4), 60)) == mpq_class(3, 4));  // exact where the result is short
  // a constant met by a value: from_rational at the constant's working precision
  CHECK(scalar_traits<Mpfr>::from_rational(mpq_class(1, 3), Mpfr(1)).precision() == int(Mpfr::kConstBits));
  Mpfr not_a_number(mpq_class(0), 53);
  mpfr_set_nan(not_a_number.get());
  CHECK(scalar_traits<Mpfr>::sign(not_a_number) == Sign::uncertain);
  // to_string has the digits of the precision: 200 bits print at least 60 significant digits
  CHECK(scalar_traits<Mpfr>::to_string(b).size() >= 60);
}
