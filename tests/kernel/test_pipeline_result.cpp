// kernel/pipeline_result.hpp: what every pipeline run returns. Its logic is
// in two helpers, checked against their statements: undecided_everywhere
// leaves nothing of a previous answer, claims nothing (collides false, both
// ends undecided, so collides_claim is "unknown"), gives the timeline
// instant-cell-instant all uncertain and the reason; result_from_bernstein
// sets the variant from the flag and writes each g_k in power form (the same
// polynomial: values at rational t in mpq against the Bernstein form).
#include "kernel/pipeline_result.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("undecided_everywhere claims nothing and says why", "[kernel][pipeline_result]") {
  PipelineResult<double> r;
  r.answer.collides = true;
  r.answer.intervals.push_back({Instant{}, Instant{}});
  r.answer.contacts.push_back(Instant{});
  r.status_at_0 = Status::separate;
  r.cells.push_back({Instant{}, Status::separate});
  Instant i0, i1;
  i0.value = 0;  // (the instants told apart by value: GCC 12's false -Wrestrict on assigning a literal here)
  i1.value = 1;
  undecided_everywhere(r, i0, i1, "overflow");
  CHECK_FALSE(r.answer.collides);
  CHECK(r.answer.intervals.empty());
  CHECK(r.answer.contacts.empty());
  REQUIRE(r.answer.undecided.size() == 2);
  CHECK(r.answer.undecided[0].value == 0);
  CHECK(r.answer.undecided[1].value == 1);
  CHECK(collides_claim(r.answer) == std::nullopt);
  CHECK(r.status_at_0 == Status::uncertain);
  REQUIRE(r.timeline.size() == 3);
  CHECK_FALSE(r.timeline[0].is_cell);
  CHECK(r.timeline[1].is_cell);
  CHECK_FALSE(r.timeline[2].is_cell);
  for (const auto& n : r.timeline) CHECK(n.status == Status::uncertain);
  REQUIRE(r.cells.size() == 1);
  CHECK(r.cells[0].status == Status::uncertain);
  CHECK(r.undecided_reasons == std::vector<std::string>{"overflow"});
}

TEST_CASE("result_from_bernstein: the variant and g in power form", "[kernel][pipeline_result]") {
  std::vector<Bern<Rational>> g(5);
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i <= k; ++i) g[k].b.push_back(Rational(long(i * i) - long(k), long(k + 1)));
  for (auto& gk : g)
    for (auto& x : gk.b) x.canonicalize();
  for (const bool first : {false, true}) {
    const PipelineResult<Rational> r = result_from_bernstein(g, first);
    CHECK(r.variant == (first ? Variant::first_contact : Variant::answer));
    REQUIRE(r.g.size() == 5);
    for (int k = 0; k < 5; ++k)
      for (int s = 0; s <= 6; ++s) {
        Rational t(s, 6);
        t.canonicalize();
        CHECK(r.g[k](t) == g[k](t));
      }
  }
}

}  // namespace ECCD_UNITY_ID
