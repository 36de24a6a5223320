// Binomial rows (kernel/binomial.hpp): the per-thread cache gives, bit for
// bit and at every precision, the rows Pascal's rule computes afresh.
#include "kernel/binomial.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <type_traits>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

namespace {
// The pre-cache Pascal rule (binomial.hpp before the rows were cached): the oracle for the cache.
template <class T>
std::vector<T> pascal_row_uncached(int n, const T& like) {
  T one = scalar_traits<T>::from_rational(mpq_class(1), like);
  std::vector<T> row(1, one);
  for (int m = 1; m <= n; ++m) {
    std::vector<T> next(m + 1, one);
    for (int k = 1; k < m; ++k) next[k] = row[k - 1] + row[k];
    row = std::move(next);
  }
  return row;
}
// Same value and, for Mpfr, same precision: bit for bit what the uncached code computed.
template <class T>
bool same(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, Mpfr>)
    return a.precision() == b.precision() && mpfr_equal_p(a.get(), b.get());
  else
    return a == b;
}
}  // namespace

TEMPLATE_TEST_CASE(
    "binomial rows from the per-thread cache equal Pascal's rule afresh, degrees and precisions interleaved",
    "[kernel][binomial]", double, Mpfr, mpq_class) {
  using T = TestType;
  std::vector<T> likes{like<T>()};
  if constexpr (std::is_same_v<T, Mpfr>)
    likes = {Mpfr(mpq_class(1), 64), Mpfr(mpq_class(1), 200), Mpfr(3), Mpfr(mpq_class(1), 64)};
  for (int n : {60, 3, 0, 150, 57, 1, 149, 200, 56}) {
    for (const T& lk : likes) {
      INFO("n = " << n << ", precision " << scalar_traits<T>::precision(lk));
      const std::vector<T>& row = binomial_row(n, lk);
      std::vector<T> ref = pascal_row_uncached(n, lk);
      REQUIRE(row.size() == ref.size());
      bool all = true;
      for (std::size_t k = 0; k < ref.size(); ++k) all = all && same(row[k], ref[k]);
      CHECK(all);
    }
  }
  // A reference stays valid while later calls extend the cache.
  const std::vector<T>& r10 = binomial_row(10, likes.front());
  (void)binomial_row(400, likes.front());
  CHECK(to_double(r10[5]) == 252.0);
}

}  // namespace ECCD_UNITY_ID
