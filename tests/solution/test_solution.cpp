// solution/solution.hpp: the typed result of a solve. Checked on a real
// pipeline run (the exact CD-DISC of two unit circles passing through each
// other, whose roots of Δ 1/6, 1/2, 5/6 and cells are derived by hand in
// tests/kernel/test_cd_disc.cpp) and on built PipelineResults: solution_of
// carries the answer, variant, status at 0, the critical instants with their
// status and multiplicity, the cells, the reasons, the counters, the time in
// milliseconds and the projection's name ("discriminant", "psc_k") and degree,
// and nothing of what was run (the caller's); decided() is "nothing
// undecided"; variant_name gives the JSON's names.
#include "exact/cd_disc_exact.hpp"
#include "io/scene_reader.hpp"
#include "solution/solution.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("solution_of carries a CD-DISC run's answer and diagnostics", "[solution][solution]") {
  const Scene s = parse_scene(
      "{\"format\": \"ellipse-ccd-scene/1\", \"name\": \"t\", \"dim\": 2, "
      "\"a\": {\"shape\": {\"semi_axes\": [\"1\", \"1\"]}, \"motion\": {\"type\": \"matrix\", \"m\": "
      "[[\"1\", \"0\", [\"-3\", \"6\"]], [\"0\", \"1\", \"0\"], [\"0\", \"0\", \"1\"]]}}, "
      "\"b\": {\"shape\": {\"semi_axes\": [\"1\", \"1\"]}, \"motion\": {\"type\": \"static\"}}}",
      "test");
  ExactPolicy pol;
  const auto r = cd_disc(to_arithmetic<Rational, H_2D>(prepare_pair<H_2D>(s), Rational(1)), pol);
  const Solution sol = solution_of(r, 2);
  CHECK(sol.dim == 2);
  CHECK(sol.projection == "discriminant");
  CHECK(sol.projection_degree == 8);  // Δ = c⁶(c² - 4), c = 6t - 3
  CHECK_FALSE(sol.projection_identically_zero);
  CHECK(sol.status_at_0 == Status::separate);
  REQUIRE(sol.critical.size() == 3);
  const Rational roots[3] = {Rational(1, 6), Rational(1, 2), Rational(5, 6)};
  const Status st[3] = {Status::touching, Status::overlapping, Status::touching};
  const int mult[3] = {1, 6, 1};
  for (int i = 0; i < 3; ++i) {
    CHECK(*sol.critical[i].t.lo <= roots[i]);
    CHECK(roots[i] <= *sol.critical[i].t.hi);
    CHECK(sol.critical[i].status == st[i]);
    CHECK(sol.critical[i].multiplicity == mult[i]);
  }
  REQUIRE(sol.cells.size() == 4);
  CHECK(sol.cells[0].status == Status::separate);
  CHECK(sol.cells[3].status == Status::separate);
  CHECK(sol.answer.collides);
  CHECK(sol.answer.contacts.size() == 2);
  CHECK(sol.decided());
  CHECK(sol.time_ms == Approx(r.seconds * 1e3));
  // what was run is the caller's to fill
  CHECK(sol.scene.empty());
  CHECK(sol.method.empty());
  CHECK(sol.basis.empty());
}

TEST_CASE("solution_of on built results: psc_k, variants, reasons, counters, undecided", "[solution][solution]") {
  PipelineResult<double> r;
  r.projection_index = 2;
  r.projection_degree = 17;
  r.variant = Variant::first_contact;
  r.counters = {{"pieces", 12}, {"splits", 3}};
  r.undecided_reasons = {"why"};
  r.answer.undecided.push_back(Instant{});
  r.seconds = 0.25;
  const Solution s = solution_of(r, 3);
  CHECK(s.dim == 3);
  CHECK(s.projection == "psc_2");
  CHECK(s.projection_degree == 17);
  CHECK(s.variant == Variant::first_contact);
  CHECK(s.work == r.counters);
  CHECK(s.undecided_reasons == std::vector<std::string>{"why"});
  CHECK(s.time_ms == 250);
  CHECK_FALSE(s.decided());
  CHECK(std::string(variant_name(Variant::answer)) == "answer");
  CHECK(std::string(variant_name(Variant::collides)) == "collides");
  CHECK(std::string(variant_name(Variant::first_contact)) == "first-contact");
  CHECK(std::string(variant_name(Variant::all_contacts)) == "all-contacts");
}

}  // namespace ECCD_UNITY_ID
