// The running bound's two readings of an MPFR number (number/running_error.hpp):
// mag(x), the top 53 bits of the significand plus one unit, must be >= |x|
// and within 2^-52 of it; unit_mag(x), half a unit in the last place of a
// result x, must bound the error of rounding any exact result to x at x's
// precision. Checked against exact rationals on random sums, products and
// quotients at 53, 64, 113, 128 and 300 bits; and the bound is not loose by
// a factor 2 (half of it fails somewhere: a tie or near-tie of rounding to
// nearest errs by half a unit), so a weakened bound is caught.
#include "number/running_error.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using eccd::test::exact_of;

namespace {

using BM = Bounded<Mpfr>;

}  // namespace

TEST_CASE("Bounded<Mpfr>: mag is at least |x| and within 2^-52 of it, and unit_mag bounds rounding to nearest",
          "[running-error][mpfr]") {
  std::mt19937_64 rng(33);
  std::uniform_int_distribution<long> num(-(1L << 62), 1L << 62);
  std::uniform_int_distribution<int> shift(-300, 300), op(0, 2);
  int over_half = 0, checks = 0;
  for (int bits : {53, 64, 113, 128, 300})
    for (int k = 0; k < 400; ++k) {
      INFO("bits " << bits << ", case " << k);
      auto draw = [&] {
        mpq_class q(mpz_class(num(rng)) * mpz_class(num(rng)) + 1, mpz_class(num(rng) | 1) * 3);
        q.canonicalize();
        const int s = shift(rng);
        q *= s >= 0 ? mpq_class(mpz_class(1) << s) : mpq_class(1, mpz_class(1) << -s);
        return q;
      };
      const Mpfr a(draw(), bits), b(draw(), bits);
      const mpq_class ea = exact_of(a), eb = exact_of(b);
      for (const Mpfr* x : {&a, &b}) {
        const mpq_class ax = abs(exact_of(*x));
        const mpq_class m = exact_of(BM::mag(*x));
        CHECK(m >= ax);
        CHECK(m <= ax * (1 + mpq_class(1, mpz_class(1) << 52)));
      }
      const int o = op(rng);
      const Mpfr r = o == 0 ? a + b : o == 1 ? a * b : a / b;
      const mpq_class exact = o == 0 ? mpq_class(ea + eb) : o == 1 ? mpq_class(ea * eb) : mpq_class(ea / eb);
      const mpq_class err = abs(exact_of(r) - exact);
      const mpq_class bound = exact_of(BM::unit_mag(r));
      CHECK(err <= bound);
      ++checks;
      if (err * 2 > bound) ++over_half;
    }
  // Half the bound is too small for a good share of the results (products and quotients err anywhere
  // in [0, half a unit]).
  INFO(over_half << " of " << checks << " results err by more than half the bound");
  CHECK(over_half > checks / 10);
}

TEST_CASE("Bounded<Mpfr>: the running bound of a short computation contains the exact result",
          "[running-error][mpfr]") {
  std::mt19937_64 rng(34);
  std::uniform_int_distribution<long> num(-1000000, 1000000);
  for (int bits : {53, 128}) {
    for (int k = 0; k < 200; ++k) {
      INFO("bits " << bits << ", case " << k);
      std::vector<mpq_class> q;
      for (int i = 0; i < 4; ++i) {
        q.emplace_back(num(rng), 7 + 2 * (num(rng) & 1023));
        q.back().canonicalize();
      }
      auto in = [&](int i) { return scalar_traits<BM>::from_rational(q[i], BM(Mpfr(q[i], bits), 0)); };
      // (q0 q1 - q2) / (q3 + 1/2) + q0 * 1/2, the shapes of a de Casteljau step and a ratio
      const BM half = scalar_traits<BM>::from_rational(mpq_class(1, 2), in(0));
      const BM r = (in(0) * in(1) - in(2)) / (in(3) + half) + in(0) * half;
      const mpq_class exact = (q[0] * q[1] - q[2]) / (q[3] + mpq_class(1, 2)) + q[0] * mpq_class(1, 2);
      REQUIRE(std::isfinite(double(r.bound())));
      CHECK(abs(exact_of(r.value()) - exact) <= exact_of(r.bound()));
      CHECK(r.bound() > 0);
    }
  }
}

}  // namespace ECCD_UNITY_ID
