// The certified ladder (certified/ladder.hpp, --arith certified): its answers
// must be the exact pipeline's on the corpus, escalating where a sign is
// uncertain. The interval arithmetics it runs in are tested in
// tests/number/test_interval.cpp and tests/number/test_mpfi_interval.cpp.
#include "api/solve.hpp"
#include "certified/ladder.hpp"
#include "kernel/prepared_scene.hpp"
#include "io/solution_json.hpp"
#include "compare/regress.hpp"
#include "compare/seeded_rng.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
Answer answer_of(const nlohmann::json& r) {
  return answer_from_json(nlohmann::json::parse(stored_answer_of(r).dump()), "certified", "answer");
}
}  // namespace

TEST_CASE("certified arithmetic names its ladder of MPFI rungs", "[certified]") {
  CHECK(parse_arithmetic("certified").mpfi_rungs == std::vector<int>{256});
  CHECK(parse_arithmetic("certified:none").mpfi_rungs.empty());
  CHECK(parse_arithmetic("certified:128,1024").mpfi_rungs == std::vector<int>{128, 1024});
  CHECK(parse_arithmetic("certified:128,1024").name() == "certified:128,1024");
  CHECK(parse_arithmetic("certified").name() == "certified");
  CHECK_THROWS_AS(parse_arithmetic("certified:512,256"), std::invalid_argument);
  CHECK_THROWS_AS(parse_arithmetic("certified:53"), std::invalid_argument);
  CHECK_THROWS_AS(parse_arithmetic("certified:abc"), std::invalid_argument);
}

TEST_CASE("a scene that intervals of doubles cannot decide is decided by the MPFI rung, with the exact answer",
          "[certified]") {
  // 2D degree-4 colliding scene whose Δ is too ill-conditioned for intervals
  // of doubles near t = 0.8 (found by `eccd regress cases --arith certified`).
  // The MPFI rung decides it when its budget allows (issue 18: by default all
  // MPFI rungs together get at most the interval rung's time, which is far
  // less than this rung needs, so `--arith certified` goes on to exact:
  // tests/certified/test_certified_cost.cpp).
  Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) +
                            "/cases/generated/2d/2d-deg4-colliding-kinematic-572211152701880.json");
  LadderBudget wide;
  wide.mpfi_factor = 1e6;
  Solution sol = run_certified<3>(prepare_pair<3>(s), {256}, Variant::answer, false, wide);
  sol.arith = Arithmetic::certified();
  nlohmann::json r = solution_to_json(sol);
  CHECK(r["decided_in"] == "mpfi:256");
  REQUIRE(r["escalations"].size() == 1);
  CHECK(r["escalations"][0]["rung"] == "interval");
  CHECK(regress_differences(*s.answer, answer_of(r)).empty());
  SolveOptions opt;
  opt.arith = parse_arithmetic("certified");
  nlohmann::json d = solution_to_json(solve(s, opt));
  CHECK(regress_differences(*s.answer, answer_of(d)).empty());
  // Without the MPFI rung the same scene goes from doubles to exact.
  opt.arith = parse_arithmetic("certified:none");
  nlohmann::json e = solution_to_json(solve(s, opt));
  CHECK(e["decided_in"] == "exact");
  CHECK(regress_differences(*s.answer, answer_of(e)).empty());
}

TEST_CASE(
    "certified mode gives the stored exact answers on the 2D corpus and decides most non-touch scenes in intervals",
    "[certified]") {
  SolveOptions opt;
  opt.arith = parse_arithmetic("certified");
  int in_intervals = 0, non_touch = 0, touch_escalated = 0, touch = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(ECCD_SOURCE_DIR) + "/cases/generated/2d")) {
    Scene s = read_scene_file(e.path().string());
    REQUIRE(s.answer);
    INFO(e.path().string());
    nlohmann::json r = solution_to_json(solve(s, opt));
    CHECK(r["certified"] == true);
    CHECK(regress_differences(*s.answer, answer_of(r)).empty());
    bool is_touch = s.note.find("family=touch") != std::string::npos;
    bool esc = r["escalated"].get<bool>();
    if (is_touch) {
      ++touch;
      touch_escalated += esc;
    } else {
      ++non_touch;
      in_intervals += !esc;
    }
    if (!esc) {  // decided in intervals: every instant of the answer has a proper bracket
      for (const auto& iv : r["intervals"])
        for (const auto& end : iv) CHECK(end["lo"].is_string());
    }
  }
  std::printf(
      "certified 2D corpus: %d of %d non-touch scenes decided in interval arithmetic; %d of %d touch scenes "
      "escalated\n",
      in_intervals, non_touch, touch_escalated, touch);
  // A touch-and-separate instant is a double root of Δ: interval isolation cannot prove it, so it must escalate.
  CHECK(touch_escalated == touch);
  CHECK(in_intervals * 2 > non_touch);
}

TEST_CASE("certified mode on paper 002's example keeps both intervals, decided by the Bézier proof in intervals",
          "[certified]") {
  // The projection (degree 72 and more) is too wide in intervals of doubles and used to escalate to exact;
  // the Bézier rung (certified/bezier_proof.hpp) proves the four ends without it.
  SolveOptions opt;
  opt.arith = parse_arithmetic("certified");
  Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper002/example.json");
  nlohmann::json r = solution_to_json(solve(s, opt));
  CHECK(r["decided_in"] == "bezier");
  CHECK(r["escalated"] == false);
  CHECK(r["intervals"].size() == 2);
  CHECK(regress_differences(*s.answer, answer_of(r)).empty());
}

}  // namespace ECCD_UNITY_ID
