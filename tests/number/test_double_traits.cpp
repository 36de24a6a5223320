// scalar_traits<double> (number/double_traits.hpp), against exact rationals:
// from_rational is the nearest double on both of its paths (one IEEE division
// for short numerators and denominators, MPFR for long ones), signs are the
// exact signs of the values held (NaN: uncertain), and to_string's 17 digits
// read back as the same double.
#include "number/double_traits.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using eccd::test::abs_q;
using eccd::test::random_rational;

TEST_CASE("scalar_traits<double>::from_rational is the nearest double on both paths", "[number][scalar_traits]") {
  std::mt19937_64 rng(37);
  for (int trial = 0; trial < 400; ++trial) {
    const int bits = trial % 2 == 0 ? 30 : 120;  // the one-division path, then the MPFR path
    const mpq_class q = random_rational(rng, bits);
    const double d = scalar_traits<double>::from_rational(q);
    INFO(q.get_str() << " -> " << d);
    REQUIRE(std::isfinite(d));
    // no double is nearer: both neighbours are at least as far from q
    const mpq_class err = abs_q(mpq_class(d) - q);
    const double up = std::nextafter(d, std::numeric_limits<double>::infinity());
    const double down = std::nextafter(d, -std::numeric_limits<double>::infinity());
    CHECK(err <= abs_q(mpq_class(up) - q));
    CHECK(err <= abs_q(mpq_class(down) - q));
    CHECK(scalar_traits<double>::sign(d) == sign_of_int(sgn(q)));
  }
  CHECK(scalar_traits<double>::from_rational(mpq_class(1, 2)) == 0.5);
  CHECK(scalar_traits<double>::from_rational(mpq_class(-3, 8)) == -0.375);
  CHECK(scalar_traits<double>::precision(1.0) == 53);
  CHECK_FALSE(scalar_traits<double>::is_exact);
  CHECK(scalar_traits<double>::sign(std::nan("")) == Sign::uncertain);
  CHECK(scalar_traits<double>::sign(-0.0) == Sign::zero);
  // to_string prints 17 significant digits: enough to read the same double back
  const double third = scalar_traits<double>::from_rational(mpq_class(1, 3));
  CHECK(std::stod(scalar_traits<double>::to_string(third)) == third);
}

}  // namespace ECCD_UNITY_ID
