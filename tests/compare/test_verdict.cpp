// Verdicts (compare/verdict.hpp): a floating pipeline's answer judged against
// the certified one, in words and in the counters of the tables of
// `eccd regress --floating` and `eccd certify`.
//  - judge() takes its differences from api/answer_difference.hpp, naming the
//    answer after the pipeline and the reference "certified"; its counters are
//    the comparison's, with splits counted as missed and merges as spurious
//    (checked on hand-made answers whose differences are known: a reference
//    interval cut in two, two reference intervals covered by one, a wrong
//    `collides`, an undecided instant, a missed touch);
//  - "agrees" iff there is no difference; text() says "agrees", "agrees
//    (interval ends within E)" with E printed to 2 significant digits,
//    "differs: a; b" or "failed: message";
//  - to_json() carries the pipeline, agreement, differences, time and the
//    largest end error (null when none), the guard and error only when set;
//  - failed_verdict() never agrees and keeps its message and time.
#include "compare/verdict.hpp"
#include "number/rational_traits.hpp"
#include "tests/support/instants.hpp"

#include <catch2/catch.hpp>

#include <cstdio>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
using test::dec;                   // a floating instant (tests/support/instants.hpp)
Instant cert(const Rational& q) {  // a certified point instant (bracket [q, q])
  return bracketed_instant(q, q, q);
}
Answer floating(std::vector<std::pair<double, double>> ivs, std::vector<double> contacts = {}) {
  Answer a;
  a.collides = !ivs.empty();
  for (auto [x, y] : ivs) a.intervals.push_back({dec(x), dec(y)});
  if (!ivs.empty()) a.first_contact = dec(ivs[0].first);
  for (double c : contacts) a.contacts.push_back(dec(c));
  return a;
}
Rational tenth(long x) {  // x / 10, canonical
  Rational q(x, 10);
  q.canonicalize();
  return q;
}
// A certified answer whose interval ends are the given tenths.
Answer certified(std::vector<std::pair<long, long>> tenths) {
  Answer a;
  a.collides = !tenths.empty();
  for (auto [x, y] : tenths) a.intervals.push_back({cert(tenth(x)), cert(tenth(y))});
  if (!tenths.empty()) a.first_contact = a.intervals[0].first;
  return a;
}
bool mentions(const std::vector<std::string>& ds, const std::string& s) {
  for (const auto& x : ds)
    if (x.find(s) != std::string::npos) return true;
  return false;
}
// judge()'s counters are the comparison's, splits and merges folded in.
void check_counters_follow_comparison(const Verdict& v, const Answer& got, const Answer& ref, double tol) {
  DifferenceOptions o;
  o.tol = tol;
  o.answer_name = v.pipeline;
  o.reference_name = "certified";
  const AnswerDifference d = answer_difference(got, ref, o);
  CHECK(v.agrees == d.agrees);
  CHECK(v.differences == d.differences);
  CHECK(v.wrong_collides == d.collides_differs);
  CHECK(v.missed == d.missed + d.split);
  CHECK(v.spurious == d.spurious + d.merged);
  CHECK(v.endpoints_off == d.endpoints_off);
  CHECK(v.undecided == d.undecided);
  CHECK(v.max_endpoint_error.has_value() == d.max_endpoint_error.has_value());
}
}  // namespace

TEST_CASE("verdict: an answer equal to the certified one agrees, and says how close its ends are",
          "[compare][verdict]") {
  const Answer ref = certified({{2, 4}, {6, 8}});
  // The same intervals as decimals 1e-9 off: within tol 1e-6, the largest end error is 1e-9.
  const Answer got = floating({{0.2, 0.4 + 1e-9}, {0.6, 0.8}});
  const Verdict v = judge("double/power", got, ref, 1e-6, 12.5);
  check_counters_follow_comparison(v, got, ref, 1e-6);
  CHECK(v.agrees);
  CHECK(v.differences.empty());
  CHECK(v.error.empty());
  CHECK(v.pipeline == "double/power");
  CHECK(v.time_ms == 12.5);
  CHECK_FALSE(v.wrong_collides);
  CHECK(v.missed == 0);
  CHECK(v.spurious == 0);
  REQUIRE(v.max_endpoint_error);
  // |0.4 + 1e-9 - 0.4| in doubles: 1e-9 up to the rounding of the two decimals (a few 1e-17).
  CHECK(std::fabs(*v.max_endpoint_error - 1e-9) < 1e-15);
  CHECK(v.text() == "agrees (interval ends within 1e-09)");

  // The same answer with a tolerance below its error: one end off.
  const Verdict t = judge("double/power", got, ref, 1e-10);
  check_counters_follow_comparison(t, got, ref, 1e-10);
  CHECK_FALSE(t.agrees);
  CHECK(t.endpoints_off == 1);
  CHECK(t.text().rfind("differs: ", 0) == 0);
  CHECK(mentions(t.differences, "collision interval 1 end off by"));

  // No intervals on either side: agrees, with no end error to report.
  const Verdict none = judge("double/power", floating({}), certified({}), 1e-6);
  CHECK(none.agrees);
  CHECK_FALSE(none.max_endpoint_error);
  CHECK(none.text() == "agrees");
}

TEST_CASE("verdict: a split interval counts as missed, merged intervals as spurious", "[compare][verdict]") {
  SECTION("the certified [0.2, 0.8] reported as [0.2, 0.4] and [0.6, 0.8]: a split") {
    const Answer ref = certified({{2, 8}});
    const Answer got = floating({{0.2, 0.4}, {0.6, 0.8}});
    const Verdict v = judge("mpfr:128/bernstein", got, ref, 1e-6);
    check_counters_follow_comparison(v, got, ref, 1e-6);
    const AnswerDifference d = answer_difference(got, ref, DifferenceOptions{1e-6, "x", "y"});
    REQUIRE(d.split == 1);  // the case is a split, not a plain miss
    CHECK(v.missed >= 1);
    CHECK(v.spurious == d.spurious + d.merged);
    CHECK_FALSE(v.agrees);
    CHECK(mentions(v.differences, "splits collision interval"));
  }
  SECTION("the certified [0.2, 0.4] and [0.6, 0.8] reported as one [0.2, 0.8]: a merge") {
    const Answer ref = certified({{2, 4}, {6, 8}});
    const Answer got = floating({{0.2, 0.8}});
    const Verdict v = judge("double/bezier", got, ref, 1e-6);
    check_counters_follow_comparison(v, got, ref, 1e-6);
    const AnswerDifference d = answer_difference(got, ref, DifferenceOptions{1e-6, "x", "y"});
    REQUIRE(d.merged == 1);
    CHECK(v.spurious >= 1);
    CHECK_FALSE(v.agrees);
    CHECK(mentions(v.differences, "merges 2 collision intervals"));
  }
}

TEST_CASE("verdict: wrong collides, a missed touch and undecided instants are named after the pipeline",
          "[compare][verdict]") {
  SECTION("collides: certified true, the pipeline false") {
    const Answer ref = certified({{3, 5}});
    const Answer got = floating({});
    const Verdict v = judge("double/power", got, ref, 1e-6);
    check_counters_follow_comparison(v, got, ref, 1e-6);
    CHECK(v.wrong_collides);
    CHECK(v.missed == 1);
    CHECK(mentions(v.differences, "collides: certified true, double/power false"));
  }
  SECTION("a false collision") {
    const Answer ref = certified({});
    const Answer got = floating({{0.3, 0.5}});
    const Verdict v = judge("double/power/published", got, ref, 1e-6);
    check_counters_follow_comparison(v, got, ref, 1e-6);
    CHECK(v.wrong_collides);
    CHECK(v.spurious == 1);
    CHECK(v.missed == 0);
    CHECK(mentions(v.differences, "collides: certified false, double/power/published true"));
  }
  SECTION("an undecided instant is a difference even when all else agrees") {
    const Answer ref = certified({{3, 5}});
    Answer got = floating({{0.3, 0.5}});
    got.undecided.push_back(dec(0.75));
    const Verdict v = judge("double/power", got, ref, 1e-6);
    check_counters_follow_comparison(v, got, ref, 1e-6);
    CHECK_FALSE(v.agrees);
    CHECK(v.undecided == 1);
    CHECK_FALSE(v.wrong_collides);
    CHECK(v.text() == "differs: " + v.differences[0]);
    CHECK(mentions(v.differences, "undecided near t ≈ 0.75"));
  }
  SECTION("a missed isolated touch at 1/5, and text() joins two differences with '; '") {
    Answer ref = certified({{2, 2}, {5, 6}});
    ref.contacts = {cert(tenth(2))};
    Answer got = floating({{0.5, 0.6}});
    got.undecided.push_back(dec(0.9));
    const Verdict v = judge("double/power", got, ref, 1e-6);
    check_counters_follow_comparison(v, got, ref, 1e-6);
    CHECK(v.missed == 1);  // the touch, once (as an interval, not again as a contact)
    REQUIRE(v.differences.size() >= 2);
    std::string joined = "differs: " + v.differences[0];
    for (std::size_t i = 1; i < v.differences.size(); ++i) joined += "; " + v.differences[i];
    CHECK(v.text() == joined);
  }
}

TEST_CASE("verdict: JSON and text of agreeing, differing and failed verdicts", "[compare][verdict]") {
  const Answer ref = certified({{3, 5}});
  Verdict v = judge("double/bernstein", floating({{0.3, 0.5}}), ref, 1e-6, 3.25);
  nlohmann::json j = v.to_json();
  CHECK(j["pipeline"] == "double/bernstein");
  CHECK(j["agrees"] == true);
  CHECK(j["differences"].is_array());
  CHECK(j["differences"].empty());
  CHECK(j["time_ms"] == 3.25);
  REQUIRE(j["max_endpoint_error"].is_number());
  CHECK(j["max_endpoint_error"].get<double>() == *v.max_endpoint_error);
  CHECK_FALSE(j.contains("guard"));  // no face named: no key
  CHECK_FALSE(j.contains("error"));
  v.guard = "bound";
  CHECK(v.to_json()["guard"] == "bound");

  const Verdict miss = judge("double/bernstein", floating({}), ref, 1e-6);
  nlohmann::json jm = miss.to_json();
  CHECK(jm["agrees"] == false);
  CHECK(jm["max_endpoint_error"].is_null());
  CHECK(jm["differences"].size() == miss.differences.size());
  CHECK(jm["differences"][0] == miss.differences[0]);

  const Verdict f = failed_verdict("mpfr:64/power", "degree 0 after rounding", 7);
  CHECK_FALSE(f.agrees);
  CHECK(f.differences.empty());
  CHECK(f.time_ms == 7);
  CHECK(f.text() == "failed: degree 0 after rounding");
  nlohmann::json jf = f.to_json();
  CHECK(jf["error"] == "degree 0 after rounding");
  CHECK(jf["agrees"] == false);
  CHECK(jf["max_endpoint_error"].is_null());
  // The text of a failed run is its failure, even if agreement had been set.
  Verdict g = f;
  g.agrees = true;
  CHECK(g.text() == "failed: degree 0 after rounding");
}

// An answer that leaves instants undecided claims nothing about `collides` where it proved no collision
// (kernel/answer.hpp, collides_claim: nullopt, written null), so it cannot have a wrong `collides`: the comparison
// (api/answer_difference.cpp) compares the claims, and such a run is undecided, not wrong (wrongC of
// `regress --floating`, "wrong collides" of `eccd judge`).
TEST_CASE("verdict: an undecided answer that claims nothing about collides is not a wrong collides",
          "[compare][verdict]") {
  const Answer ref = certified({{5, 5}});
  Answer got = floating({});
  got.undecided.push_back(dec(0.5));
  REQUIRE_FALSE(collides_claim(got).has_value());  // the answer says "unknown"
  const Verdict v = judge("double/power", got, ref, 1e-6);
  CHECK_FALSE(v.agrees);
  CHECK(v.undecided == 1);
  CHECK_FALSE(v.wrong_collides);
}

}  // namespace ECCD_UNITY_ID
