// --arith certified: interval arithmetic that encloses exact results
// (number/interval.hpp), and the certified policy's answers, which must be
// the exact pipeline's on the corpus, escalating where a sign is uncertain.
#include "api/solve.hpp"
#include "certified/ladder.hpp"
#include "kernel/prepared_scene.hpp"
#include "io/solution_json.hpp"
#include "compare/regress.hpp"
#include "compare/seeded_rng.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace eccd;

namespace {
bool contains(const Interval& x, const Rational& q) {
  Rational lo(x.lo), hi(x.hi);
  return lo <= q && q <= hi;
}
bool contains(const MpfiInterval& x, const Rational& q) {
  mpq_class v(q);
  return mpfi_is_inside_q(v.get_mpq_t(), x.get()) > 0;
}
Answer answer_of(const nlohmann::json& r) {
  return answer_from_json(nlohmann::json::parse(stored_answer_of(r).dump()), "certified", "answer");
}
}  // namespace

TEST_CASE("Interval operations enclose the exact rational results", "[certified][interval]") {
  SeededRng rng{20261121};
  for (int k = 0; k < 2000; ++k) {
    Rational a = rng.frac(-1000000, 1000000, rng.uniform(1, 999983)),
             b = rng.frac(-1000000, 1000000, rng.uniform(1, 999983));
    Interval A = interval_of(a), B = interval_of(b);
    INFO(a << " " << b);
    REQUIRE(contains(A, a));
    CHECK(contains(A + B, Rational(a + b)));
    CHECK(contains(A - B, Rational(a - b)));
    CHECK(contains(A * B, Rational(a * b)));
    if (b != 0) CHECK(contains(A / B, Rational(a / b)));
    // a chain: (a*b - a) * (b + 1/3)
    Rational third(1, 3);
    CHECK(contains((A * B - A) * (B + interval_of(third)), Rational((a * b - a) * (b + third))));
  }
  // Signs are certain or uncertain, never guessed.
  CHECK(scalar_traits<Interval>::sign(Interval(-1e-300, 1e-300)) == Sign::uncertain);
  CHECK(scalar_traits<Interval>::sign(interval_of(Rational(1, 3)) - interval_of(Rational(1, 3))) == Sign::uncertain);
  CHECK(scalar_traits<Interval>::sign(Interval(0, 0)) == Sign::zero);
  CHECK(scalar_traits<Interval>::sign(Interval(1, 1) / Interval(-1, 1)) == Sign::uncertain);
}

TEST_CASE("MPFI intervals enclose the exact rational results and carry their precision", "[certified][interval]") {
  SeededRng rng{20261122};
  for (int k = 0; k < 500; ++k) {
    Rational a = rng.frac(-1000000, 1000000, rng.uniform(1, 999983)),
             b = rng.frac(-1000000, 1000000, rng.uniform(1, 999983));
    MpfiInterval A(a, 80), B(b, 200);
    INFO(a << " " << b);
    REQUIRE(contains(A, a));
    CHECK(contains(A + B, Rational(a + b)));
    CHECK(contains(A - B, Rational(a - b)));
    CHECK(contains(A * B, Rational(a * b)));
    CHECK((A * B).precision() == 200);
    CHECK((A * MpfiInterval(3)).precision() == 80);  // a small constant adopts its partner's precision
    if (b != 0) CHECK(contains(A / B, Rational(a / b)));
    Rational third(1, 3);
    MpfiInterval chain = (A * B - A) * (B + MpfiInterval(third, 80));
    CHECK(contains(chain, Rational((a * b - a) * (b + third))));
    // a long chain stays an enclosure: sum of (a*b)/(k+1)
    MpfiInterval acc(0);
    Rational exact(0);
    for (int i = 0; i < 50; ++i) {
      acc = acc + A * B / MpfiInterval(Rational(i + 1), 80);
      exact += a * b / Rational(i + 1);
    }
    CHECK(contains(acc, exact));
  }
  CHECK(scalar_traits<MpfiInterval>::sign(MpfiInterval(Rational(1, 3), 300) - MpfiInterval(Rational(1, 3), 300)) ==
        Sign::uncertain);
  CHECK(scalar_traits<MpfiInterval>::sign(MpfiInterval(0)) == Sign::zero);
  CHECK(scalar_traits<MpfiInterval>::sign(MpfiInterval(Rational(-1, 7), 60)) == Sign::negative);
  CHECK(scalar_traits<MpfiInterval>::sign(MpfiInterval(1) / (MpfiInterval(Rational(1, 3), 60) -
                                                             MpfiInterval(Rational(1, 3), 60))) == Sign::uncertain);
  CHECK(exact_point(MpfiInterval(Rational(3, 8), 60)) == Rational(3, 8));
  CHECK(!exact_point(MpfiInterval(Rational(1, 3), 60)));
}

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
