// rounded_instant's shortcut for doubles (kernel/answer.hpp, issue 21): the
// instant's text for T = double and T = Bounded<double> must be exactly what
// the general rule gives, round_decimal(to_string(t), precision_digits(53)),
// the MPFR round trip the shortcut skips. Checked on every power of two and
// its predecessor (normal and subnormal), zeros, infinities, NaN, and random
// bit patterns and random values in [0, 1] (where instants live).
#include "kernel/answer.hpp"
#include "number/double_traits.hpp"
#include "number/running_error.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
std::string general_rule(double x) { return round_decimal(scalar_traits<double>::to_string(x), precision_digits(53)); }
}  // namespace

TEST_CASE("rounded_instant of a double gives the general rule's text exactly", "[answer][bezier]") {
  static_assert(prints_as_double<double>() && prints_as_double<Bounded<double>>());
  std::vector<double> xs = {0.0,
                            -0.0,
                            1.0,
                            0.5,
                            0.1,
                            0.25,
                            1e-5,
                            1e-300,
                            1e300,
                            1e16,
                            1e17,
                            1e21,
                            123456789012345678.0,
                            std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::max()};
  for (int e = -1074; e < 1024; ++e) {
    xs.push_back(std::ldexp(1.0, e));
    xs.push_back(std::nextafter(std::ldexp(1.0, e), 0.0));
  }
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t b = rng();
    double x;
    std::memcpy(&x, &b, sizeof x);
    xs.push_back(x);
    xs.push_back(unit(rng));
  }
  long differing = 0;
  for (double x : xs) {
    const std::string want = general_rule(x);
    const Instant a = rounded_instant(x), b = rounded_instant(Bounded<double>(x, 0));
    if (a.approx != want || b.approx != want) {
      ++differing;
      CHECK(a.approx == want);  // the first ones shown with their values
      CHECK(b.approx == want);
      if (differing > 5) break;
    }
  }
  CHECK(differing == 0);
}

}  // namespace ECCD_UNITY_ID
