// MpfiInterval (number/mpfi_interval.hpp): MPFI intervals whose precision
// travels with the value. On random rationals every operation and a long
// chain of them enclose the exact rational result, a result carries the
// larger precision of its operands (a small constant adopts its partner's),
// signs are certain or uncertain, and exact_point is a point's exact value.
#include "compare/seeded_rng.hpp"
#include "number/mpfi_interval.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
bool contains(const MpfiInterval& x, const Rational& q) {
  mpq_class v(q);
  return mpfi_is_inside_q(v.get_mpq_t(), x.get()) > 0;
}
}  // namespace

TEST_CASE("MPFI intervals enclose the exact rational results and carry their precision", "[certified][interval]") {
  SeededRng rng{20261122};
  for (int k = 0; k < 500; ++k) {
    Rational a = rng.frac(-1000000, 1000000, rng.uniform(1, 999983)),
             b = rng.frac(-1000000, 1000000, rng.uniform(1, 999983));
    MpfiInterval A(a, 80), B(b, 200);
    INFO(a << " " << b);
    REQUIRE(contains(A, a));
    CHECK(contains(A + B, Rational(a + b)));
    CHECK(contains(A - B, Rational(a - b)));
    CHECK(contains(A * B, Rational(a * b)));
    CHECK((A * B).precision() == 200);
    CHECK((A * MpfiInterval(3)).precision() == 80);  // a small constant adopts its partner's precision
    if (b != 0) CHECK(contains(A / B, Rational(a / b)));
    Rational third(1, 3);
    MpfiInterval chain = (A * B - A) * (B + MpfiInterval(third, 80));
    CHECK(contains(chain, Rational((a * b - a) * (b + third))));
    // a long chain stays an enclosure: sum of (a*b)/(k+1)
    MpfiInterval acc(0);
    Rational exact(0);
    for (int i = 0; i < 50; ++i) {
      acc = acc + A * B / MpfiInterval(Rational(i + 1), 80);
      exact += a * b / Rational(i + 1);
    }
    CHECK(contains(acc, exact));
  }
  CHECK(scalar_traits<MpfiInterval>::sign(MpfiInterval(Rational(1, 3), 300) - MpfiInterval(Rational(1, 3), 300)) ==
        Sign::uncertain);
  CHECK(scalar_traits<MpfiInterval>::sign(MpfiInterval(0)) == Sign::zero);
  CHECK(scalar_traits<MpfiInterval>::sign(MpfiInterval(Rational(-1, 7), 60)) == Sign::negative);
  CHECK(scalar_traits<MpfiInterval>::sign(MpfiInterval(1) / (MpfiInterval(Rational(1, 3), 60) -
                                                             MpfiInterval(Rational(1, 3), 60))) == Sign::uncertain);
  CHECK(exact_point(MpfiInterval(Rational(3, 8), 60)) == Rational(3, 8));
  CHECK(!exact_point(MpfiInterval(Rational(1, 3), 60)));
}

}  // namespace ECCD_UNITY_ID
