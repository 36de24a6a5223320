// number/rational_convolution.hpp: the product of two rational coefficient
// lists over common denominators. Checked against the coefficient-by-
// coefficient double loop in mpq written in the test, over seeded random
// lists (integers, shared and unrelated denominators, zeros, long numbers):
// the same rationals in the same canonical form, trailing zeros kept (the
// caller trims); and the refusal (an empty result) when the common
// denominator would be far longer than the longest single one (many
// unrelated prime denominators), which the caller takes as "multiply
// coefficient by coefficient".
#include "number/rational_convolution.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

std::vector<mpq_class> naive(const std::vector<mpq_class>& a, const std::vector<mpq_class>& b) {
  std::vector<mpq_class> r(a.size() + b.size() - 1, mpq_class(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
std::vector<mpq_class> random_list(std::mt19937_64& rng, int kind) {
  std::vector<mpq_class> c;
  const long den = long(rng() % 12) + 1;
  for (int i = 0, n = int(rng() % 8); i <= n; ++i) {
    mpq_class x;
    if (rng() % 5 == 0)
      x = 0;
    else if (kind == 0)
      x = mpq_class(long(rng() % 2001) - 1000);
    else if (kind == 1)
      x = mpq_class(long(rng() % 2001) - 1000, den);  // one shared denominator
    else
      x = test::random_rational(rng, 40);
    x.canonicalize();
    c.push_back(x);
  }
  c.push_back(0);  // a trailing zero: kept, as in the naive product
  return c;
}

}  // namespace

TEST_CASE("rational_convolution is the coefficient-by-coefficient product", "[number][rational_convolution]") {
  std::mt19937_64 rng(4341);
  int used = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto a = random_list(rng, trial % 3), b = random_list(rng, (trial / 3) % 3);
    const auto got = rational_convolution(a, b);
    if (got.empty()) {  // refused (the caller multiplies coefficient by coefficient): only with unrelated denominators
      CHECK((trial % 3 == 2 || (trial / 3) % 3 == 2));
      continue;
    }
    const auto want = naive(a, b);
    REQUIRE(got.size() == want.size());
    for (std::size_t k = 0; k < want.size(); ++k) {
      INFO("trial " << trial << " k = " << k);
      CHECK(got[k] == want[k]);
      CHECK(got[k].get_den() == want[k].get_den());  // canonical
    }
    ++used;
  }
  CHECK(used > 180);  // all with integers or one shared denominator, some with unrelated ones
}

TEST_CASE("rational_convolution refuses many unrelated denominators", "[number][rational_convolution]") {
  // 1/p for 16 primes near 2^20: the common denominator has about 320 bits, more than 2 · 21 + 64.
  std::vector<mpq_class> a;
  mpz_class p = mpz_class(1) << 20;
  for (int k = 0; k < 16; ++k) {
    mpz_nextprime(p.get_mpz_t(), p.get_mpz_t());
    a.push_back(mpq_class(mpz_class(1), p));
  }
  CHECK(rational_convolution(a, {mpq_class(1), mpq_class(1)}).empty());
  // a few of them are fine: the common denominator stays short
  const std::vector<mpq_class> few(a.begin(), a.begin() + 2);
  const auto r = rational_convolution(few, {mpq_class(1, 3), mpq_class(2)});
  REQUIRE(r.size() == 3);
  CHECK(r[0] == few[0] / 3);
  CHECK(r[1] == 2 * few[0] + few[1] / 3);
  CHECK(r[2] == 2 * few[1]);
}

}  // namespace ECCD_UNITY_ID
