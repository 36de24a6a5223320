// number/rational_poly_eval.hpp: p(t) over the integers with one reduction.
// Checked against Horner's scheme in mpq written in the test (and the sum of
// c_i t^i), for seeded random coefficient lists (integer and fractional,
// zeros inside and at either end, long numbers) at integer, fractional,
// negative and zero points: the same rational and the same canonical
// representation (numerator and denominator), as the statement says.
#include "number/rational_poly_eval.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

mpq_class horner(const std::vector<mpq_class>& c, const mpq_class& t) {
  mpq_class r = 0;
  for (int i = int(c.size()) - 1; i >= 0; --i) r = r * t + c[i];
  return r;
}

}  // namespace

TEST_CASE("rational_poly_eval is mpq Horner, in canonical form", "[number][rational_poly_eval]") {
  std::mt19937_64 rng(4340);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<mpq_class> c;
    const int n = int(rng() % 12);
    const bool integer = trial % 3 == 0;
    for (int i = 0; i <= n; ++i) {
      if (rng() % 4 == 0) {
        c.push_back(0);
        continue;
      }
      mpq_class x = test::random_rational(rng, trial % 5 == 0 ? 100 : 20);
      if (integer) x = mpq_class(x.get_num());
      c.push_back(x);
    }
    std::vector<mpq_class> ts = {0, 1, -1, mpq_class(long(rng() % 1000) - 500), test::random_rational(rng, 20)};
    for (const auto& t : ts) {
      const mpq_class got = rational_poly_eval(c, t), want = horner(c, t);
      INFO("trial " << trial << " t = " << t);
      CHECK(got == want);
      CHECK(got.get_num() == want.get_num());
      CHECK(got.get_den() == want.get_den());
      ++checked;
    }
  }
  CHECK(checked == 2000);
  CHECK(rational_poly_eval({mpq_class(3, 4)}, mpq_class(7)) == mpq_class(3, 4));  // a constant
  CHECK(rational_poly_eval({0, 0, 0}, mpq_class(2, 3)) == 0);                     // the zero list
  // 1/2 + 0 t + (1/3) t² at t = -3/2: 1/2 + 3/4 = 5/4
  CHECK(rational_poly_eval({mpq_class(1, 2), 0, mpq_class(1, 3)}, mpq_class(-3, 2)) == mpq_class(5, 4));
}

}  // namespace ECCD_UNITY_ID
