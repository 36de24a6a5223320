// Descartes' rule of signs on an interval (exact/descartes.hpp), against
// polynomials whose roots are known exactly.
#include "exact/descartes.hpp"
#include "kernel/polynomial.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;
using Q = mpq_class;

TEST_CASE("Descartes on an interval agrees with the number of roots for products of linear factors",
          "[kernel][sign_variations][descartes]") {
  // p = (t - 1/5)(t - 1/2)(t - 4/5)(t - 2): on (0, 1) three simple roots; V = 3 (V - #roots even, >= 0).
  Poly<Q> p({Q(1)});
  for (Q r : {Q(1, 5), Q(1, 2), Q(4, 5), Q(2)}) p = p * Poly<Q>({Q(-r), Q(1)});
  CHECK(descartes_variations(p, Q(0), Q(1)) == 3);
  CHECK(descartes_variations(p, Q(0), Q(3, 10)) == 1);
  CHECK(descartes_variations(p, Q(3, 10), Q(2, 5)) == 0);
}

}  // namespace ECCD_UNITY_ID
