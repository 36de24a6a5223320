// The interval Bézier proof (certified/bezier_proof.hpp, issue 18 point 3):
// whenever it decides, its answer is the exact pipeline's (run_exact, or the
// stored answers under cases/, which are the exact pipeline's: `eccd solve
// --write-answer`); it decides named easy scenes; it does not decide a touch
// (a tangency cannot be proved by enclosures) and the ladder then still
// returns exact's answer; the recorded proof's pieces cover [0, 1] in order.
#include "api/answer_difference.hpp"
#include "api/solve.hpp"
#include "certified/bezier_proof.hpp"
#include "certified/ladder.hpp"
#include "compare/regress.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"
#include "kernel/budget.hpp"
#include "kernel/prepared_scene.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <variant>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

const std::string kCases = std::string(ECCD_SOURCE_DIR) + "/cases/";

bool rational_same_t(const Scene& s) {
  if (s.dim != 3 || s.independent) return false;
  for (const SceneObject* o : {&s.a, &s.b})
    if (std::holds_alternative<CycloidalMotion>(o->motion)) return false;
  return true;
}

// The proof's answer against an exact one: same collides, same number of
// intervals, each exact instant's bracket meets the proof's bracket.
void check_against_exact(const Answer& proof, const Answer& exact) {
  CHECK(proof.collides == exact.collides);
  REQUIRE(proof.intervals.size() == exact.intervals.size());
  for (std::size_t i = 0; i < exact.intervals.size(); ++i) {
    for (const auto& [p, x] : {std::pair{proof.intervals[i].first, exact.intervals[i].first},
                               std::pair{proof.intervals[i].second, exact.intervals[i].second}}) {
      REQUIRE(p.certified());
      REQUIRE(x.certified());
      CHECK(*p.lo <= *x.hi);
      CHECK(*x.lo <= *p.hi);
    }
  }
  CHECK(regress_differences(exact, proof).empty());
}

// The recorded pieces: in order, covering [0, 1] without gaps, each piece's claims inside it.
void check_pieces(const BezierProofResult& r) {
  REQUIRE(r.decided);
  REQUIRE_FALSE(r.pieces.empty());
  CHECK(r.pieces.front().lo == 0);
  CHECK(r.pieces.back().hi == 1);
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const BezierPiece& p = r.pieces[i];
    CHECK(p.lo < p.hi);
    if (i > 0) CHECK(p.lo == r.pieces[i - 1].hi);
    REQUIRE_FALSE(p.boxes.empty());
    if (p.kind == BezierPiece::end) {
      // Krawczyk's first box covers the run; the bracket lies in the run
      CHECK(p.boxes.front().t_lo <= p.lo);
      CHECK(p.boxes.front().t_hi >= p.hi);
      CHECK(p.lo <= p.bracket_lo);
      CHECK(p.bracket_lo <= p.bracket_hi);
      CHECK(p.bracket_hi <= p.hi);
      // an end lies between an out and an in piece
      REQUIRE(i > 0);
      REQUIRE(i + 1 < r.pieces.size());
      CHECK(r.pieces[i - 1].kind != BezierPiece::end);
      CHECK(r.pieces[i + 1].kind != BezierPiece::end);
      CHECK(r.pieces[i - 1].kind != r.pieces[i + 1].kind);
    } else {
      for (const BezierBox& b : p.boxes) {
        CHECK(b.t_lo >= p.lo);
        CHECK(b.t_hi <= p.hi);
        CHECK(b.u_lo >= 0);
        CHECK(b.u_hi <= 1);
        CHECK(b.u_lo < b.u_hi);
      }
      std::vector<BezierBox> bs = p.boxes;
      if (p.kind == BezierPiece::in) {  // every box spans [lo, hi]; the u-ranges tile [0, 1]
        std::sort(bs.begin(), bs.end(), [](const BezierBox& a, const BezierBox& b) { return a.u_lo < b.u_lo; });
        CHECK(bs.front().u_lo == 0);
        CHECK(bs.back().u_hi == 1);
        for (std::size_t k = 0; k < bs.size(); ++k) {
          CHECK(bs[k].t_lo == p.lo);
          CHECK(bs[k].t_hi == p.hi);
          if (k > 0) CHECK(bs[k].u_lo == bs[k - 1].u_hi);
        }
      } else {  // out: the t-ranges tile [lo, hi]
        std::sort(bs.begin(), bs.end(), [](const BezierBox& a, const BezierBox& b) { return a.t_lo < b.t_lo; });
        CHECK(bs.front().t_lo == p.lo);
        CHECK(bs.back().t_hi == p.hi);
        for (std::size_t k = 1; k < bs.size(); ++k) CHECK(bs[k].t_lo == bs[k - 1].t_hi);
      }
    }
  }
}

}  // namespace

TEST_CASE("whenever the Bézier proof decides a 3D scene of cases/, it gives the stored exact answer", "[bezier]") {
  int decided = 0, scenes = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kCases)) {
    if (e.path().extension() != ".json") continue;
    const std::string path = e.path().string();
    if (path.find("/animations/") != std::string::npos) continue;
    Scene s;
    try {
      s = read_scene_file(path);
    } catch (const std::exception&) {
      continue;  // not a scene (a manifest, an animation)
    }
    if (!rational_same_t(s) || !s.answer) continue;
    INFO(path);
    ++scenes;
    BezierProofResult r = prove_bezier(prepare_pair<4>(s), BezierProofOptions{});
    if (!r.decided) {
      CHECK_FALSE(r.reason.empty());
      continue;
    }
    ++decided;
    CHECK(r.answer.collides == s.answer->collides);
    CHECK(r.answer.intervals.size() == s.answer->intervals.size());
    CHECK(regress_differences(*s.answer, r.answer).empty());
  }
  CHECK(scenes >= 30);
  CHECK(decided >= 15);  // 32 of them decide at the time of writing (the ladder's "bezier" count in regress)
}

TEST_CASE("whenever the Bézier proof decides a generated 3D scene, it agrees with run_exact", "[bezier]") {
  std::uint64_t seed = 1803;
  int decided = 0, n = 0;
  for (int deg = 1; deg <= 4; ++deg)
    for (const char* family : {"colliding", "free", "near-miss", "touch"}) {
      if (deg == 1 && std::string(family) != "colliding" && std::string(family) != "free") continue;
      GeneratorSpec g;
      g.dim = 3;
      g.degree = deg;
      g.family = family;
      g.motion = "euler";
      g.d_exponent = std::string(family) == "near-miss" ? 6 : 0;
      g.seed = ++seed;
      GeneratedScene gs = generate_scene(g);
      INFO(gs.name);
      ++n;
      Scene s = scene_from_text(gs.doc.dump(), gs.name);
      PreparedPair<4> p = prepare_pair<4>(s);
      BezierProofResult r = prove_bezier(p, BezierProofOptions{});
      if (std::string(family) == "touch") CHECK_FALSE(r.decided);  // a tangency is never claimed
      if (!r.decided) continue;
      ++decided;
      check_against_exact(r.answer, run_exact<4>(p, Variant::answer, false).answer);
    }
  CHECK(decided >= n / 2);
}

TEST_CASE("the Bézier proof decides easy 3D scenes, with proved ends and pieces covering [0, 1]", "[bezier]") {
  for (const char* rel :
       {"spheres/spheres-crossing.json", "spheres/spheres-free.json", "spheres/spheres-overlap-end.json",
        "generated/3d-euler/3d-deg4-colliding-euler-8020579862790034.json",
        "generated/3d-euler/3d-deg4-free-euler-638809522882267.json", "paper002/example.json"}) {
    INFO(rel);
    Scene s = read_scene_file(kCases + rel);
    REQUIRE(s.answer);
    PreparedPair<4> p = prepare_pair<4>(s);
    BezierProofOptions o;
    o.record = true;
    BezierProofResult r = prove_bezier(p, o);
    INFO(r.reason);
    REQUIRE(r.decided);
    check_pieces(r);
    check_against_exact(r.answer, run_exact<4>(p, Variant::answer, false).answer);
    // proved ends: as many end pieces as interval ends inside (0, 1)
    long ends = 0;
    for (const BezierPiece& pc : r.pieces) ends += pc.kind == BezierPiece::end;
    CHECK(std::size_t(ends) == r.answer.contacts.size());
    // the ladder decides it in the Bézier rung
    Solution c = run_certified<4>(p, {256}, Variant::answer, false);
    CHECK(c.decided_in == "bezier");
    CHECK(c.method == "bezier");
    CHECK(c.certified);
    CHECK(c.escalations.empty());
    CHECK(regress_differences(*s.answer, c.answer).empty());
  }
}

TEST_CASE("paper 002's example (two intervals): first contact stops after the first interval, as exact does",
          "[bezier]") {
  Scene s = read_scene_file(kCases + "paper002/example.json");
  PreparedPair<4> p = prepare_pair<4>(s);
  BezierProofOptions o;
  o.first_contact = true;
  BezierProofResult r = prove_bezier(p, o);
  REQUIRE(r.decided);
  REQUIRE(r.answer.intervals.size() == 1);
  Answer x = run_exact<4>(p, Variant::answer, true).answer;
  check_against_exact(r.answer, x);
  CHECK(r.answer.contacts.size() == x.contacts.size());
}

TEST_CASE("the Bézier proof does not decide a touch, the ladder still returns exact's answer", "[bezier]") {
  for (const char* rel :
       {"touch3d/touch-and-separate.json", "generated/3d-euler/3d-deg4-touch-euler-2609545266629497.json"}) {
    INFO(rel);
    Scene s = read_scene_file(kCases + rel);
    REQUIRE(s.answer);
    PreparedPair<4> p = prepare_pair<4>(s);
    BezierProofResult r = prove_bezier(p, BezierProofOptions{});
    CHECK_FALSE(r.decided);
    CHECK_FALSE(r.reason.empty());
    CHECK(r.answer.intervals.empty());
    Solution c = run_certified<4>(p, {256}, Variant::answer, false);
    REQUIRE_FALSE(c.escalations.empty());
    CHECK(c.escalations.front().rung == "bezier");
    CHECK(c.decided_in != "bezier");
    CHECK(regress_differences(*s.answer, c.answer).empty());
  }
}

TEST_CASE("the Bézier rung keeps its budget B_Z, the caller's deadline still ends a 3D certified run",
          "[bezier][cost]") {
  Scene s = read_scene_file(kCases + "spheres/spheres-crossing.json");
  REQUIRE(s.answer);
  PreparedPair<4> p = prepare_pair<4>(s);
  // A Bézier budget already spent: the rung gives up at once with that reason, and the ladder goes on
  // (intervals of doubles, MPFI, exact) to the same answer.
  LadderBudget none;
  none.bezier_s = 1e-9;
  Solution c = run_certified<4>(p, {256}, Variant::answer, false, none);
  REQUIRE_FALSE(c.escalations.empty());
  CHECK(c.escalations.front().rung == "bezier");
  CHECK_THAT(c.escalations.front().reason, Catch::StartsWith("rung budget exhausted"));
  CHECK(c.escalations.front().budget_ms == Approx(1e-6));
  CHECK(c.decided_in != "bezier");
  CHECK(regress_differences(*s.answer, c.answer).empty());
  // The caller's own deadline is not an escalation: the whole run ends.
  ScopedDeadline caller(1e-9);
  CHECK_THROWS_AS(run_certified<4>(p, {256}, Variant::answer, false), BudgetExhausted);
}

}  // namespace ECCD_UNITY_ID
