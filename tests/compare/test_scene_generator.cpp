// The scene generators (compare/scene_generator.hpp): reproducible, of the
// requested degree, accepted by the scene reader, and of the kind their
// construction promises, checked against the exact pipeline.
#include "api/solve.hpp"
#include "io/solution_json.hpp"
#include "compare/harness.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
nlohmann::json solve_exact(const Scene& s) {
  SolveOptions o;
  o.arith = parse_arithmetic("exact");
  return solution_to_json(solve(s, o));
}
}  // namespace

TEST_CASE("generated scenes are reproducible, readable and of the requested degree", "[generator]") {
  GeneratePlan plan;
  plan.families = {"colliding", "free", "touch", "near-miss"};
  plan.degrees = {2, 5};
  plan.d_exponents = {3};
  plan.seed = 11;
  auto specs = plan_scenes(plan);
  // 2D: 4 families; 3D: euler 4 families, affine 3 (no near-miss).
  CHECK(specs.size() == 2 * (4 + 4 + 3));
  for (const auto& sp : specs) {
    INFO(sp.dim << "D degree " << sp.degree << " " << sp.family << " " << sp.motion << " seed " << sp.seed);
    GeneratedScene a = generate_scene(sp), b = generate_scene(sp);
    CHECK(a.doc.dump() == b.doc.dump());
    Scene s = parse_scene(a.doc.dump(), a.name);
    CHECK(scene_degree(s) == sp.degree);
    auto back = spec_from_note(s.note);
    REQUIRE(back);
    CHECK(back->family == sp.family);
    CHECK(back->motion == sp.motion);
    CHECK(back->degree == sp.degree);
    CHECK(back->seed == sp.seed);
    CHECK(back->d_exponent == (sp.family == "near-miss" ? 3 : 0));
  }
  // Another run seed gives other scenes.
  plan.seed = 12;
  CHECK(generate_scene(plan_scenes(plan)[0]).doc.dump() != generate_scene(specs[0]).doc.dump());
}

TEST_CASE("each family has the answer its construction promises, by the exact pipeline", "[generator][exact]") {
  GeneratePlan plan;
  plan.families = {"colliding", "free", "touch", "near-miss"};
  plan.degrees = {2, 3};
  plan.d_exponents = {2, 12};
  plan.seed = 20261121;
  int checked = 0;
  for (const auto& sp : plan_scenes(plan)) {
    GeneratedScene g = generate_scene(sp);
    INFO(g.name);
    Scene s = parse_scene(g.doc.dump(), g.name);
    nlohmann::json r = solve_exact(s);
    if (sp.family == "colliding") {
      CHECK(r["collides"].get<bool>());
    } else if (sp.family == "free" || sp.family == "near-miss") {
      CHECK_FALSE(r["collides"].get<bool>());
    } else {  // touch: exactly {t0}, one external contact, certified
      REQUIRE(g.t0);
      const std::string t0 = g.t0->get_str();
      REQUIRE(r["intervals"].size() == 1);
      CHECK(r["intervals"][0][0]["lo"] == t0);
      CHECK(r["intervals"][0][0]["hi"] == t0);
      CHECK(r["intervals"][0][1]["lo"] == t0);
      REQUIRE(r["contacts"].size() == 1);
      CHECK(r["contacts"][0]["lo"] == t0);
    }
    ++checked;
  }
  CHECK(checked == 2 * (4 + 4 + 3) + 2 * 2);  // near-miss: two separations, 2D and 3D euler
}

TEST_CASE("the generator refuses what it cannot build", "[generator]") {
  GeneratorSpec s;
  s.dim = 3;
  s.motion = "kinematic";
  CHECK_THROWS_AS(generate_scene(s), std::invalid_argument);
  s.motion = "affine";
  s.family = "near-miss";
  s.d_exponent = 4;
  CHECK_THROWS_AS(generate_scene(s), std::invalid_argument);
  s.motion = "euler";
  s.family = "grazing";
  CHECK_THROWS_AS(generate_scene(s), std::invalid_argument);
}

}  // namespace ECCD_UNITY_ID
