// io/solution_json.hpp: a Solution survives solution_to_json → solution_from_json
// (what `eccd judge` and the report's worker processes read back), including
// the answers a run may legitimately give that a stored answer may not: an
// independent run left undecided with s-intervals proved and no t-interval.
#include "io/solution_json.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
Instant at(long num, long den) {
  mpq_class q(num, den);
  q.canonicalize();
  return bracketed_instant(q, q, q);
}
}  // namespace

TEST_CASE("solution JSON round trip, an undecided independent run with s- but no t-intervals", "[solution-json]") {
  Solution s;
  s.dim = 3;
  s.arith = parse_arithmetic("double");
  s.answer.independent = true;
  s.answer.collides = true;
  s.answer.s_intervals = {{at(1, 4), at(1, 2)}};
  s.answer.undecided = {at(3, 4)};
  s.undecided_reasons = {"t = 0.75: the t-proof could not decide"};
  const nlohmann::json j = solution_to_json(s);
  REQUIRE(j["t_intervals"].is_array());
  REQUIRE(j["t_intervals"].empty());
  Solution back;
  REQUIRE_NOTHROW(back = solution_from_json(j, "round trip"));
  CHECK(back.answer.independent);
  CHECK(back.answer.collides);
  REQUIRE(back.answer.s_intervals.size() == 1);
  CHECK(*back.answer.s_intervals[0].first.lo == mpq_class(1, 4));
  CHECK(back.answer.t_intervals.empty());
  REQUIRE(back.answer.undecided.size() == 1);
  CHECK(*back.answer.undecided[0].lo == mpq_class(3, 4));
}

TEST_CASE("solution JSON, a decided independent run with collides true and an empty list is still refused",
          "[solution-json]") {
  nlohmann::json j = {{"collides", true},
                      {"s_intervals", nlohmann::json::array()},
                      {"t_intervals", nlohmann::json::array()},
                      {"dim", 3},
                      {"arith", "exact"}};
  CHECK_THROWS_WITH(solution_from_json(j, "bad"), Catch::Contains("collides is true but s_intervals is empty"));
}

}  // namespace ECCD_UNITY_ID
