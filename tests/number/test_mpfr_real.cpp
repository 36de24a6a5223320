// Mpfr and scalar_traits<Mpfr> (number/mpfr_real.hpp), against exact
// rationals: from_rational rounds to nearest at the value's precision
// (|x - q| <= 2^-bits |q|), a result carries the larger precision of its
// operands and a small constant adopts its partner's, NaN has no sign.
#include "number/mpfr_real.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using eccd::test::abs_q;
using eccd::test::exact_of;
using eccd::test::random_rational;

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

}  // namespace ECCD_UNITY_ID
