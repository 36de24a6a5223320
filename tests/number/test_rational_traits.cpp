// scalar_traits<mpq_class> (number/rational_traits.hpp): exact rationals, the
// workbench's ground truth: from_rational is the identity, signs and
// absolute values are exact, the precision is 0 ("exact").
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("scalar_traits<mpq_class> is exact", "[number][scalar_traits]") {
  const mpq_class q(-22, 7);
  CHECK(scalar_traits<mpq_class>::is_exact);
  CHECK(scalar_traits<mpq_class>::from_rational(q) == q);
  CHECK(scalar_traits<mpq_class>::sign(q) == Sign::negative);
  CHECK(scalar_traits<mpq_class>::sign(mpq_class(0)) == Sign::zero);
  CHECK(scalar_traits<mpq_class>::abs(q) == mpq_class(22, 7));
  CHECK(scalar_traits<mpq_class>::precision(q) == 0);
  CHECK(scalar_traits<mpq_class>::to_string(q) == "-22/7");
}

}  // namespace ECCD_UNITY_ID
