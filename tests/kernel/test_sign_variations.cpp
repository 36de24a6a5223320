// Sign variations with an uncertain flag (kernel/sign_variations.hpp): zeros
// are skipped, and a sign that is not known makes the count uncertain instead
// of being skipped.
#include "kernel/sign_variations.hpp"
#include "number/double_traits.hpp"
#include "number/interval.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using Q = mpq_class;

TEST_CASE("sign variations: zeros skipped, exact counts", "[kernel][sign_variations]") {
  CHECK(sign_variations(std::vector<Q>{1, -2, 0, 3, -1}).is(3));
  CHECK(sign_variations(std::vector<Q>{0, 0, 5, 0, 7}).is(0));
  CHECK(sign_variations(std::vector<Q>{}).is(0));
  CHECK(sign_variations(std::vector<double>{-1.0, 0.0, 0.0, 2.0}).is(1));
  CHECK_FALSE(sign_variations(std::vector<Q>{1, -1}).uncertain);
}

TEST_CASE("sign variations report an uncertain sign instead of skipping it", "[kernel][sign_variations]") {
  // [1, [-1, 1], -1]: 1 or 2 changes are possible (the middle sign is unknown);
  // skipping the middle value would claim exactly 1, hence one simple root.
  std::vector<Interval> xs{Interval(1), Interval(-1.0, 1.0), Interval(-1)};
  SignVariations v = sign_variations(xs);
  CHECK(v.uncertain);
  CHECK_FALSE(v.is(1));
  // certain intervals count as their sign
  std::vector<Interval> ys{Interval(1.0, 2.0), Interval(-3.0, -2.0), Interval(0), Interval(1.0, 1.5)};
  CHECK(sign_variations(ys).is(2));
}

}  // namespace ECCD_UNITY_ID
