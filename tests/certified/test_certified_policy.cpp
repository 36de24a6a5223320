// The certified policy (certified/certified_policy.hpp) on its own: what it
// does with signs it cannot prove. Its contract shared with the other
// pipeline policies is tests/kernel/test_pipeline_policy.cpp.
#include "certified/certified_policy.hpp"
#include "number/interval.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("the certified policy does not take an uncertain count for one root",
          "[kernel][sign_variations][certified]") {
  // The middle coefficients' signs stay unknown on every piece: the policy
  // must escalate, never report a bracket it has not proved.
  Bern<Interval> q({Interval(1), Interval(-1.0, 1.0), Interval(-1.0, 1.0), Interval(-1)});
  CertifiedPolicy<Interval> pol(Interval(1));
  pol.max_depth = 12;
  CHECK_THROWS_AS(pol.roots(q, false), Escalate);
}

}  // namespace ECCD_UNITY_ID
