// Scaling by powers of two (number/pow2_scaling.hpp), in double and MPFR:
// normalise_pow2 multiplies every value by one power of two, exactly (each
// scaled value times 2^e is the old value, as exact rationals), so that the
// largest has binary exponent 0; a non-finite value leaves everything as it
// was and returns false; binary_exponent is frexp's exponent.
#include "number/mpfr_real.hpp"
#include "number/pow2_scaling.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <climits>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using eccd::test::exact_of;

namespace {

mpq_class pow2(long e) { return e >= 0 ? mpq_class(mpz_class(1) << e) : mpq_class(mpz_class(1), mpz_class(1) << -e); }

template <class T>
void check_normalise(std::vector<T> xs) {
  const std::vector<T> before = xs;
  long top = LONG_MIN;
  for (const T& x : xs) top = std::max(top, binary_exponent(x));
  REQUIRE(normalise_pow2<T>([&](auto f) {
    for (auto& x : xs) f(x);
  }));
  long after = LONG_MIN;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    after = std::max(after, binary_exponent(xs[i]));
    CHECK(exact_of(xs[i]) * pow2(top) == exact_of(before[i]));  // one power of two, no rounding
  }
  CHECK(after == 0);
}

}  // namespace

TEST_CASE("binary_exponent and times_pow2 in double and MPFR", "[number][pow2_scaling]") {
  CHECK(binary_exponent(1.0) == 1);
  CHECK(binary_exponent(0.75) == 0);
  CHECK(binary_exponent(0.5) == 0);
  CHECK(binary_exponent(-6.0) == 3);
  CHECK(binary_exponent(0.0) == LONG_MIN);
  CHECK(binary_exponent(std::numeric_limits<double>::infinity()) == LONG_MIN);
  CHECK(binary_exponent(Mpfr(mpq_class(3, 4), 100)) == 0);
  CHECK(binary_exponent(Mpfr(mpq_class(-6), 100)) == 3);
  CHECK(times_pow2(0.75, 3) == 6.0);
  CHECK(times_pow2(std::ldexp(1.0, -1074), 1074) == 1.0);  // from the smallest subnormal, exactly
  CHECK(exact_of(times_pow2(Mpfr(mpq_class(1, 3), 200), -5)) == exact_of(Mpfr(mpq_class(1, 3), 200)) / 32);
}

TEST_CASE("normalise_pow2 scales by one power of two to a largest exponent 0, exactly", "[number][pow2_scaling]") {
  std::mt19937_64 rng(373);
  std::uniform_real_distribution<double> m(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-600, 600);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> xs;
    const int base = e(rng);
    for (int i = 0; i < 8; ++i) xs.push_back(std::ldexp(m(rng), base + e(rng) / 20));
    if (trial % 4 == 0) xs[2] = 0.0;
    INFO("trial " << trial);
    check_normalise(xs);
    std::vector<Mpfr> ms;
    for (double x : xs) ms.emplace_back(mpq_class(x) / 3, 150);  // not short: any rounding would show
    check_normalise(ms);
  }
  // all zeros: nothing to scale, and that is not a failure
  std::vector<double> zeros(3, 0.0);
  CHECK(normalise_pow2<double>([&](auto f) {
    for (auto& x : zeros) f(x);
  }));
  CHECK(zeros == std::vector<double>(3, 0.0));
}

TEST_CASE("normalise_pow2 refuses a non-finite value and scales nothing", "[number][pow2_scaling]") {
  for (double bad : {std::numeric_limits<double>::infinity(), std::nan("")}) {
    std::vector<double> xs{1024.0, bad, 3.0};
    CHECK_FALSE(normalise_pow2<double>([&](auto f) {
      for (auto& x : xs) f(x);
    }));
    CHECK(xs[0] == 1024.0);
    CHECK(xs[2] == 3.0);
    CHECK_FALSE(all_finite(xs));
  }
  CHECK(all_finite(std::vector<double>{1.0, -2.0, 0.0}));
  Mpfr infinite(mpq_class(1), 80);
  mpfr_set_inf(infinite.get(), 1);
  std::vector<Mpfr> ms{Mpfr(mpq_class(5), 80), infinite};
  CHECK_FALSE(normalise_pow2<Mpfr>([&](auto f) {
    for (auto& x : ms) f(x);
  }));
  CHECK(exact_of(ms[0]) == 5);
}

}  // namespace ECCD_UNITY_ID
