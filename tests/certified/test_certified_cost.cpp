// The cost guarantee of the certified ladder (issue 18 point 1,
// certified/ladder.hpp "Cost guarantee"): each rung runs within its budget —
// the interval rung a fixed one, the MPFI rungs together at most f x the
// interval rung's time — and the ladder goes straight to exact when a rung
// runs out of budget, meets a multiple root or does not converge. What is
// tested is the mechanism (the per-rung accounting in the Solution: budgets,
// reasons, decided_in) and that the answer is the exact pipeline's; how long
// it takes is measured in the benchmark (bench/eccd_bench.cpp, group
// certified-cost), not here.
#include "api/solve.hpp"
#include "certified/ladder.hpp"
#include "compare/regress.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"
#include "kernel/budget.hpp"
#include "kernel/prepared_scene.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <map>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

const std::string kCases = std::string(ECCD_SOURCE_DIR) + "/cases/";

Solution solve_in(const Scene& s, const char* arith) {
  SolveOptions o;
  o.arith = parse_arithmetic(arith);
  return solve(s, o);
}

// The accounting every certified Solution carries, checked against the rules
// of the ladder (not against the clock): the interval rung's budget is B_I;
// an MPFI rung tried is allowed at most f x the interval rung's time, minus
// what earlier MPFI rungs spent; a skipped rung spent nothing; once a rung ran
// out of budget or met a multiple root, every later MPFI rung is skipped;
// decided_in is the rung after the last escalation.
void check_accounting(const Solution& s, const LadderBudget& b = {}) {
  REQUIRE(s.certified);
  if (s.escalations.empty()) {
    CHECK((s.decided_in == "interval" || (s.dim == 3 && s.decided_in == "bezier")));
    return;
  }
  // 3D: the Bézier rung comes first, within its fixed budget B_Z (then the ladder goes on as in 2D)
  std::size_t k0 = 0;
  if (s.escalations.front().rung == "bezier") {
    CHECK(s.dim == 3);
    CHECK(s.escalations.front().budget_ms == Approx(b.bezier_s * 1e3));
    CHECK(s.escalations.front().spent_ms >= 0);
    if (s.escalations.size() == 1) {
      CHECK(s.decided_in == "interval");
      return;
    }
    k0 = 1;
  }
  const Escalation& first = s.escalations[k0];
  CHECK(first.rung == "interval");
  CHECK(first.budget_ms == Approx(b.interval_s * 1e3));
  CHECK(first.spent_ms >= 0);
  double mpfi_spent = 0;
  bool stop = false;  // a rung ran out of budget, met a multiple root or did not converge
  for (std::size_t i = k0 + 1; i < s.escalations.size(); ++i) {
    const Escalation& e = s.escalations[i];
    INFO(e.rung << ": " << e.reason);
    CHECK(e.rung.rfind("mpfi:", 0) == 0);
    bool skipped = e.reason.rfind("skipped", 0) == 0;
    if (stop) CHECK(skipped);
    if (skipped) {
      CHECK(e.spent_ms == 0);
      CHECK(e.budget_ms == 0);
      continue;
    }
    CHECK(e.budget_ms > 0);
    CHECK(e.budget_ms <= b.mpfi_factor * first.spent_ms - mpfi_spent + 1e-9);
    mpfi_spent += e.spent_ms;
    stop =
        e.reason.find("budget exhausted") != std::string::npos || e.reason.find("not converging") != std::string::npos;
  }
  CHECK((s.decided_in == "exact" || s.decided_in.rfind("mpfi:", 0) == 0));
  for (const Escalation& e : s.escalations) CHECK(e.rung != s.decided_in);  // the deciding rung did not give up
}

}  // namespace

TEST_CASE(
    "the short-overlap scene that ran for ten minutes is answered as exact answers it, within the ladder's budgets",
    "[certified][cost]") {
  // Issue 18: "a 3D degree-2 Euler pair with a short overlap (depth about 1e-9,
  // an interval about 1e-5 long) — `--arith certified` was still running after
  // 10 minutes". The interval rung looped in the cell sampling: two root
  // brackets from neighbouring subdivision pieces shared their end point, and
  // no dyadic lies strictly between equal ends (certified_policy.hpp
  // sample_between). Stored answer: the exact pipeline's (`eccd solve --write-answer`).
  for (const auto& e : std::filesystem::directory_iterator(kCases + "short-overlap")) {
    if (e.path().extension() != ".json") continue;
    INFO(e.path().string());
    Scene s = read_scene_file(e.path().string());
    REQUIRE(s.answer);
    CHECK(s.answer->collides);
    REQUIRE(s.answer->intervals.size() == 1);
    // The overlap is short: about 1e-5 (2 sqrt(depth / h) with h of order 1..10).
    double len = s.answer->intervals[0].second.value - s.answer->intervals[0].first.value;
    CHECK(len > 1e-6);
    CHECK(len < 1e-4);
    Solution c = solve_in(s, "certified");
    CHECK(regress_differences(*s.answer, c.answer).empty());
    check_accounting(c);
  }
}

TEST_CASE("a rung that runs out of its budget sends the ladder straight to exact, with the exact answer",
          "[certified][cost]") {
  // A 2D degree-4 colliding scene that intervals of doubles decide (no touch, no ill-conditioned root).
  Scene s = read_scene_file(kCases + "generated/2d/2d-deg4-colliding-kinematic-4950076459645545.json");
  REQUIRE(s.answer);
  PreparedPair<3> p = prepare_pair<3>(s);
  // A budget already spent when the interval rung starts: it gives up at once.
  LadderBudget none;
  none.interval_s = 1e-9;
  Solution c = run_certified<3>(p, {256}, Variant::answer, false, none);
  CHECK(c.decided_in == "exact");
  REQUIRE(c.escalations.size() == 2);
  CHECK(c.escalations[0].rung == "interval");
  CHECK_THAT(c.escalations[0].reason, Catch::StartsWith("rung budget exhausted"));
  CHECK(c.escalations[0].budget_ms == Approx(1e-6));
  CHECK(c.escalations[1].rung == "mpfi:256");
  CHECK_THAT(c.escalations[1].reason, Catch::StartsWith("skipped: the rung below ran out of its budget"));
  CHECK(regress_differences(*s.answer, c.answer).empty());
  check_accounting(c, none);
  // With the default budget the same scene is decided in intervals of doubles.
  Solution d = run_certified<3>(p, {256}, Variant::answer, false);
  CHECK(d.decided_in == "interval");
  CHECK(d.escalations.empty());
  CHECK(regress_differences(*s.answer, d.answer).empty());
}

TEST_CASE("the MPFI rungs share a budget of f times the interval rung's time, and f = 0 skips them",
          "[certified][cost]") {
  // A 2D degree-4 scene whose Δ is too ill-conditioned for intervals of
  // doubles near t = 0.8 (tests/certified/test_ladder.cpp): the interval
  // rung gives up on precision, and the MPFI rung is tried.
  Scene s = read_scene_file(kCases + "generated/2d/2d-deg4-colliding-kinematic-572211152701880.json");
  REQUIRE(s.answer);
  PreparedPair<3> p = prepare_pair<3>(s);
  LadderBudget zero;
  zero.mpfi_factor = 0;
  Solution c = run_certified<3>(p, {128, 256}, Variant::answer, false, zero);
  CHECK(c.decided_in == "exact");
  REQUIRE(c.escalations.size() == 3);
  for (int i : {1, 2}) CHECK_THAT(c.escalations[i].reason, Catch::StartsWith("skipped: the MPFI budget"));
  CHECK(regress_differences(*s.answer, c.answer).empty());
  check_accounting(c, zero);
  // A generous factor: the MPFI rungs are tried, each within what is left of f x the interval rung's time.
  LadderBudget wide;
  wide.mpfi_factor = 1e6;
  Solution w = run_certified<3>(p, {128, 256}, Variant::answer, false, wide);
  CHECK(w.decided_in != "interval");
  REQUIRE(w.escalations.size() >= 1);
  CHECK(regress_differences(*s.answer, w.answer).empty());
  check_accounting(w, wide);
}

TEST_CASE("the caller's deadline still ends a certified run (no rung turns it into an escalation)",
          "[certified][cost]") {
  Scene s = read_scene_file(kCases + "paper003/example2.json");
  PreparedPair<3> p = prepare_pair<3>(s);
  ScopedDeadline caller(1e-9);
  CHECK_THROWS_AS(run_certified<3>(p, {256}, Variant::answer, false), BudgetExhausted);
}

TEST_CASE(
    "certified equals exact on a sample of short overlaps, near misses and grazes (2D and 3D, degrees 1-4), "
    "within the ladder's budgets",
    "[certified][cost]") {
  // The generator's families (compare/scene_generator.hpp): near-miss (gap
  // 10^-e at t0, never colliding; degrees 2..), overlap (linear translations,
  // depth 10^-e) and graze (touch at t0 only); e = 3, 6, 9, 12.
  std::vector<GeneratorSpec> specs;
  std::uint64_t seed = 1818;
  for (int dim : {2, 3})
    for (int e : {3, 6, 9, 12}) {
      for (int deg : dim == 2 ? std::vector<int>{2, 4} : std::vector<int>{2, 3}) {
        GeneratorSpec g;
        g.dim = dim;
        g.degree = deg;
        g.family = "near-miss";
        g.motion = dim == 2 ? "kinematic" : "euler";
        g.d_exponent = e;
        g.seed = ++seed;
        specs.push_back(g);
      }
      GeneratorSpec o;
      o.dim = dim;
      o.degree = 1;
      o.family = "overlap";
      o.motion = "translation";
      o.d_exponent = e;
      o.seed = ++seed;
      specs.push_back(o);
    }
  for (int dim : {2, 3}) {
    GeneratorSpec g;
    g.dim = dim;
    g.degree = 1;
    g.family = "graze";
    g.motion = "translation";
    g.seed = ++seed;
    specs.push_back(g);
  }
  std::map<std::string, int> decided_in;
  for (const GeneratorSpec& g : specs) {
    GeneratedScene gs = generate_scene(g);
    INFO(gs.name);
    Scene s = scene_from_text(gs.doc.dump(), gs.name);
    Solution x = solve_in(s, "exact");
    Solution c = solve_in(s, "certified");
    CHECK(regress_differences(x.answer, c.answer).empty());
    check_accounting(c);
    ++decided_in[c.decided_in];
  }
  for (const auto& [rung, n] : decided_in)
    std::printf("certified cost sample: %d scene(s) decided in %s\n", n, rung.c_str());
}

}  // namespace ECCD_UNITY_ID
