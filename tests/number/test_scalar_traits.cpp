// What number/scalar_traits.hpp itself defines: the three-valued Sign, its
// product (an uncertain factor makes an uncertain product; a zero times an
// unknown sign is not claimed to be zero) and its names. The
// specialisations are tests/number/test_double_traits.cpp,
// test_mpfr_real.cpp and test_rational_traits.cpp.
#include "number/scalar_traits.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("signs multiply as numbers, and an uncertain factor makes an uncertain product", "[number][scalar_traits]") {
  const Sign all[] = {Sign::negative, Sign::zero, Sign::positive, Sign::uncertain};
  for (Sign a : all)
    for (Sign b : all) {
      INFO(to_string(a) << " * " << to_string(b));
      if (a == Sign::uncertain || b == Sign::uncertain)
        CHECK((a * b) == Sign::uncertain);
      else
        CHECK((a * b) == sign_of_int(long(a) * long(b)));
    }
  CHECK((Sign::negative * Sign::negative) == Sign::positive);
  CHECK((Sign::zero * Sign::uncertain) == Sign::uncertain);  // 0 times an unknown sign: not claimed
  CHECK(std::string(to_string(Sign::uncertain)) == "uncertain");
}

}  // namespace ECCD_UNITY_ID
