// The cycloidal and independent generator families (compare/motion_families.hpp)
// and their harness rows (compare/harness_families.hpp): each kind the seed
// picks is what the pipelines find (the construction checked by the pipelines:
// certified for cycloidal, exact for independent balls, double for ellipsoids),
// and the rows carry the ground truth, or "no ground truth" when it is refused.
#include "api/solve.hpp"
#include "compare/harness_families.hpp"
#include "compare/motion_families.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"
#include "kernel/cycloidal_motion.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

std::string kind_of(const GeneratedScene& g) {
  const std::string note = g.doc["note"].get<std::string>();
  auto p = note.find("kind=");
  REQUIRE(p != std::string::npos);
  return note.substr(p + 5, note.find(' ', p) - p - 5);
}

// The first scene of each kind among the plan's seeds.
std::map<std::string, GeneratedScene> one_per_kind(const std::string& family, int dim, std::size_t kinds) {
  GeneratePlan plan;
  plan.dims = {dim};
  plan.families = {family};
  plan.count = 60;
  std::map<std::string, GeneratedScene> out;
  for (const auto& spec : plan_scenes(plan)) {
    CHECK(spec.family == family);
    CHECK(spec.degree == 1);
    GeneratedScene g = generate_scene(spec);
    out.emplace(kind_of(g), g);
    if (out.size() == kinds) break;
  }
  REQUIRE(out.size() == kinds);
  return out;
}

Scene read(const GeneratedScene& g) { return scene_from_text(g.doc.dump(), g.name); }

}  // namespace

TEST_CASE("cycloidal family: each kind is what the certified pipeline proves", "[cycloidal][report]") {
  auto scenes = one_per_kind("cycloidal", 2, 4);
  CHECK_THROWS_AS(generate_scene(GeneratorSpec{3, 1, "cycloidal", "cycloidal", 0, 0, 1}), std::invalid_argument);
  SolveOptions cert;
  cert.arith = Arithmetic::certified();
  for (const auto& [kind, g] : scenes) {
    INFO(g.name << ": " << g.doc["note"].get<std::string>());
    Scene s = read(g);
    REQUIRE(has_cycloidal_motion(s));
    CHECK(g.doc == generate_scene(g.spec).doc);  // seeded: the same scene again
    Solution r = solve(s, cert);
    if (kind == "colliding") {
      CHECK(r.answer.undecided.empty());
      CHECK(r.answer.collides);
    } else if (kind == "free") {
      CHECK(r.answer.undecided.empty());
      CHECK_FALSE(r.answer.collides);
      CHECK(r.critical.empty());
    } else if (kind == "touch") {
      // a double root of Δ at t0: never proved, never claimed a touch; no collision interval elsewhere
      CHECK_FALSE(r.answer.undecided.empty());
      CHECK(r.answer.intervals.empty());
    } else {  // near-miss: never colliding (proved, or undecided near t0; never a claimed collision)
      CHECK(r.answer.intervals.empty());
    }
  }
}

TEST_CASE("independent family: each kind is what the exact (balls) or double (ellipsoids) pipeline finds",
          "[independent][report]") {
  auto scenes = one_per_kind("independent", 3, 6);
  CHECK_THROWS_AS(generate_scene(GeneratorSpec{4, 1, "independent", "translation", 0, 0, 1}), std::invalid_argument);
  SolveOptions exact;
  for (const auto& [kind, g] : scenes) {
    INFO(g.name << ": " << g.doc["note"].get<std::string>());
    Scene s = read(g);
    REQUIRE(s.independent);
    if (kind.rfind("balls", 0) == 0) {
      Solution r = solve(s, exact);
      REQUIRE(r.answer.independent);
      CHECK(r.answer.collides == (kind == "balls-colliding" || kind == "balls-touch"));
      if (kind == "balls-touch") {  // the swept volumes touch at A(s*), B(t*) only
        const std::string note = g.doc["note"].get<std::string>();
        auto at = [&](const char* key) {
          auto p = note.find(key) + std::string(key).size();
          std::string v = note.substr(p, note.find(' ', p) - p);
          if (!v.empty() && v.back() == '.') v.pop_back();
          return parse_rational(v);
        };
        REQUIRE(r.answer.s_intervals.size() == 1);
        REQUIRE(r.answer.t_intervals.size() == 1);
        const auto& [s0, s1] = r.answer.s_intervals[0];
        const auto& [t0, t1] = r.answer.t_intervals[0];
        CHECK(*s0.lo <= at("s*="));
        CHECK(at("s*=") <= *s1.hi);
        CHECK(*t0.lo <= at("t*="));
        CHECK(at("t*=") <= *t1.hi);
        CHECK(*s1.hi - *s0.lo < mpq_class(1, 1000000));
      }
    } else {
      // Ellipsoids: the proved answer (certified/independent_proof.hpp) must agree with the construction;
      // the double subdivision is not run here (it can take its whole 30 s budget on a crossing pair).
      Solution r = solve(s, exact);
      CHECK(r.answer.collides == (kind == "ellipsoids-colliding"));
    }
  }
}

TEST_CASE("independent family in 2D: each kind is what the exact pipeline finds", "[independent][report]") {
  auto scenes = one_per_kind("independent", 2, 6);
  SolveOptions exact;
  for (const auto& [kind, g] : scenes) {
    INFO(g.name << ": " << g.doc["note"].get<std::string>());
    CHECK(g.name.rfind("2d-independent-" + kind + "-", 0) == 0);
    CHECK(g.doc == generate_scene(g.spec).doc);  // seeded: the same scene again
    Scene s = read(g);
    REQUIRE(s.independent);
    REQUIRE(s.dim == 2);
    Solution r = solve(s, exact);
    REQUIRE(r.answer.independent);
    const bool meets = kind == "discs-colliding" || kind == "ellipses-colliding" || kind == "discs-touch";
    if (kind == "ellipses-colliding" || kind == "ellipses-free") {
      // the proved route (certified/independent_proof.hpp): what it decides agrees with the construction
      if (r.answer.undecided.empty())
        CHECK(r.answer.collides == meets);
      else
        CHECK_FALSE(kind == "ellipses-free");  // a separation by a line with a gap is always proved
      continue;
    }
    CHECK(r.answer.undecided.empty());  // two discs on lines: exact/independent_balls.hpp
    CHECK(r.answer.collides == meets);
    if (kind == "discs-touch") {  // the swept areas touch at A(1), B(t*) only
      const std::string note = g.doc["note"].get<std::string>();
      auto p = note.find("t*=") + 3;
      std::string v = note.substr(p, note.find(' ', p) - p);
      if (!v.empty() && v.back() == '.') v.pop_back();
      const mpq_class ts = parse_rational(v);
      REQUIRE(r.answer.s_intervals.size() == 1);
      REQUIRE(r.answer.t_intervals.size() == 1);
      const auto& [s0, s1] = r.answer.s_intervals[0];
      const auto& [t0, t1] = r.answer.t_intervals[0];
      CHECK(*s0.lo <= 1);
      CHECK(*s1.hi == 1);
      CHECK(*s1.hi - *s0.lo < mpq_class(1, 1000000));
      CHECK(*t0.lo <= ts);
      CHECK(ts <= *t1.hi);
      CHECK(*t1.hi - *t0.lo < mpq_class(1, 1000000));
    }
  }
}

TEST_CASE("harness rows of the motion families: ground truth certified / exact, or no ground truth",
          "[cycloidal][independent][report]") {
  HarnessOptions o;
  o.mpfr_bits = {};  // double only: the MPFR rows are the same code at another precision (and cost seconds each)
  o.isolate = false;
  o.fcl = false;
  o.budget_s = 20;
  // A cycloidal colliding scene: certified ground truth (its row says so), double compared with it.
  const GeneratedScene cyc = one_per_kind("cycloidal", 2, 4).at("colliding");
  const Scene cs = read(cyc);
  auto rows = run_motion_family_scene(cs, scene_info(cs, "generated"), o);
  REQUIRE(rows.size() == 2);  // a cycloidal pipeline has the guarded face only
  CHECK(rows[0].pipeline == "certified");
  CHECK(rows[1].guard == "bound");
  CHECK(rows[0].reason.rfind("ground truth:", 0) == 0);
  CHECK(rows[1].pipeline == "double/cycloidal");
  CHECK(rows[1].input == "rounded");
  CHECK(rows[0].scene.family == "cycloidal");
  CHECK(rows[0].scene.degree == 1);
  for (const auto& r : rows) {
    INFO(r.pipeline << ": " << r.reason);
    CHECK(r.m.outcome == "correct");
    CHECK(r.m.exact_collides);
  }
  CHECK(results_csv_line(rows[1]).find("double/cycloidal,double,53,pointwise,cd-disc-cycloidal") != std::string::npos);

  // Two balls crossing (generated, seed 943992915424628): exact ground truth, s- and t-intervals compared.
  const GeneratedScene bg = generate_scene(GeneratorSpec{3, 1, "independent", "translation", 0, 0, 943992915424628ULL});
  REQUIRE(kind_of(bg) == "balls-colliding");
  const Scene balls = read(bg);
  rows = run_motion_family_scene(balls, scene_info(balls, "generated"), o);
  REQUIRE(rows.size() == 3);  // exact, then double as published and guarded
  CHECK(rows[0].pipeline == "exact");
  CHECK(rows[0].guard.empty());
  CHECK(rows[1].pipeline == "double/independent/published");
  CHECK(rows[1].guard == "none");
  CHECK(rows[2].pipeline == "double/independent");
  CHECK(rows[2].guard == "bound");
  CHECK(rows[0].m.exact_intervals == 2);  // one s-interval, one t-interval
  for (std::size_t k : {std::size_t(1), std::size_t(2)}) {
    INFO(rows[k].pipeline << ": " << rows[k].reason);
    CHECK(rows[k].m.outcome == "correct");
    CHECK(rows[k].m.structure_ok);  // ends within 1e-6 of the exact brackets
    REQUIRE(rows[k].m.endpoint_err);
    CHECK(*rows[k].m.endpoint_err < 1e-6);
  }

  // Two discs crossing in the plane (the first discs-colliding of the 2D plan): the same rows, both faces.
  {
    const GeneratedScene dg = one_per_kind("independent", 2, 6).at("discs-colliding");
    const Scene discs = read(dg);
    rows = run_motion_family_scene(discs, scene_info(discs, "generated"), o);
    REQUIRE(rows.size() == 3);
    CHECK(rows[0].pipeline == "exact");
    CHECK(rows[0].scene.dim == 2);
    CHECK(rows[0].scene.family == "independent");
    CHECK(rows[1].pipeline == "double/independent/published");
    CHECK(rows[1].guard == "none");
    CHECK(rows[2].pipeline == "double/independent");
    CHECK(rows[2].guard == "bound");
    CHECK(rows[0].m.exact_intervals == 2);
    for (std::size_t k : {std::size_t(1), std::size_t(2)}) {
      INFO(rows[k].pipeline << ": " << rows[k].reason);
      CHECK(rows[k].m.outcome == "correct");
      CHECK(rows[k].m.structure_ok);
      REQUIRE(rows[k].m.endpoint_err);
      CHECK(*rows[k].m.endpoint_err < 1e-6);
    }
  }

  // Ellipsoids: exact refuses them today, so no ground truth: every row says so, nothing is guessed.
  Scene ell = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/independent/ellipsoids-cross.json");
  bool exact_refuses = false;
  try {
    solve(ell, SolveOptions{});
  } catch (const std::invalid_argument&) {
    exact_refuses = true;
  }
  if (exact_refuses) {
    o.budget_s = 2;
    rows = run_motion_family_scene(ell, scene_info(ell, "cases"), o);
    REQUIRE(rows.size() == 3);
    std::vector<std::string> lines;
    for (const auto& r : rows) {
      INFO(r.pipeline);
      CHECK(r.m.outcome == kNoGroundTruthOutcome);
      CHECK(r.reason.rfind(kNoGroundTruthReason, 0) == 0);
      lines.push_back(results_csv_line(r));
      CHECK(lines.back().find(",no_ground_truth,") != std::string::npos);
    }
    nlohmann::json m = no_ground_truth_meta(lines);
    CHECK(m["scenes"] == 1);
    CHECK(m["list"][0]["scene"] == "ellipsoids-cross");
  }
}

}  // namespace ECCD_UNITY_ID
