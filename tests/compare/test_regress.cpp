// Regression against stored answers (compare/regress.hpp): a stored answer
// and a recomputed exact one agree iff api/answer_difference.hpp finds no
// difference, the recomputed answer judged against the stored one with
// tol = 1e-12.
//  - certified instants match iff their brackets overlap, exactly: brackets
//    that touch at one point match, brackets 2^-100 apart (far below 1e-12)
//    do not;
//  - a stored decimal without a bracket is read exactly and must lie within
//    the recomputed bracket widened by 1e-12 (3.3e-13 away: agrees;
//    2.3e-12 away: differs);
//  - the words name the two answers "stored" and "recomputed", e.g. the
//    header's own example "collision interval 1 end off by 0.1 (stored 0.9,
//    recomputed 1)";
//  - a stored answer read from JSON without "contact_intervals" has none: a
//    recomputed continuous touch is a difference; wrong `collides`, missed and
//    false contacts and first contacts are differences;
//  - on real cases (cases/paper002, paper003, touch3d) the stored answer agrees with the exact
//    pipeline's, and a stored answer with a shifted interval end does not.
#include "compare/regress.hpp"

#include "api/judge.hpp"
#include "api/solve.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
Rational q(const char* s) {
  Rational x(s);
  x.canonicalize();
  return x;
}
Instant bracket(const Rational& lo, const Rational& hi) { return bracketed_instant((lo + hi) / 2, lo, hi); }
Instant decimal(const std::string& text) {  // a stored decimal, no bracket
  Instant i;
  i.approx = text;
  i.value = std::stod(text);
  return i;
}
Answer one_interval(Instant a, Instant b) {
  Answer x;
  x.collides = true;
  x.first_contact = a;
  x.intervals.push_back({std::move(a), std::move(b)});
  return x;
}
bool mentions(const std::vector<std::string>& ds, const std::string& s) {
  for (const auto& x : ds)
    if (x.find(s) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST_CASE("regress: certified brackets match when they overlap, with no tolerance", "[compare][regress]") {
  const Rational e = q("1/1267650600228229401496703205376");  // 2^-100
  const Instant one = bracketed_instant(Rational(1), Rational(1), Rational(1));
  // Recomputed: [1/3, 1] with the start bracketed in [1/3, 1/3 + 2^-64].
  const Rational lo = q("1/3"), hi = lo + q("1/18446744073709551616");
  const Answer recomputed = one_interval(bracket(lo, hi), one);
  SECTION("the same brackets") { CHECK(regress_differences(one_interval(bracket(lo, hi), one), recomputed).empty()); }
  SECTION("a stored bracket that only touches the recomputed one at its end") {
    CHECK(regress_differences(one_interval(bracket(hi, hi + e), one), recomputed).empty());
  }
  SECTION("a stored bracket 2^-100 past the recomputed one: they hold different instants") {
    const auto d = regress_differences(one_interval(bracket(hi + e, hi + 2 * e), one), recomputed);
    CHECK_FALSE(d.empty());
    CHECK(mentions(d, "collision interval 1 start off by"));
  }
}

TEST_CASE("regress: a stored decimal is read exactly and matched within 1e-12 of the bracket", "[compare][regress]") {
  // Recomputed start: 1/3 exactly (a point bracket); end 1.
  const Instant third = bracketed_instant(q("1/3"), q("1/3"), q("1/3"));
  const Instant one = bracketed_instant(Rational(1), Rational(1), Rational(1));
  const Answer recomputed = one_interval(third, one);
  // 0.3333333333330 is 1/3 - 3.33e-13; 0.333333333331 is 1/3 - 2.33e-12; 0.333333333333333333333 is within 1e-21.
  CHECK(regress_differences(one_interval(decimal("0.333333333333333333333"), decimal("1")), recomputed).empty());
  CHECK(regress_differences(one_interval(decimal("0.3333333333330"), decimal("1")), recomputed).empty());
  const auto d = regress_differences(one_interval(decimal("0.333333333331"), decimal("1")), recomputed);
  CHECK_FALSE(d.empty());
  CHECK(mentions(d, "collision interval 1 start off by"));
  CHECK(mentions(d, "(stored 0.3333333333, recomputed 0.3333333333)"));  // %.10g
  // The header's example, word for word: the stored end 0.9, the recomputed 1.
  const auto e = regress_differences(one_interval(decimal("0.3333333333333333"), decimal("0.9")), recomputed);
  REQUIRE(e.size() >= 1);
  CHECK(e[0] == "collision interval 1 end off by 0.1 (stored 0.9, recomputed 1)");
}

TEST_CASE("regress: collides, contacts, first contact and continuous touching are compared", "[compare][regress]") {
  const char* stored_text = R"({"collides": true,
      "intervals": [[{"approx": "0.25", "lo": "1/4", "hi": "1/4"}, {"approx": "0.5", "lo": "1/2", "hi": "1/2"}]],
      "first_contact": {"approx": "0.25", "lo": "1/4", "hi": "1/4"},
      "contacts": [{"approx": "0.25", "lo": "1/4", "hi": "1/4"}, {"approx": "0.5", "lo": "1/2", "hi": "1/2"}]})";
  const Answer stored = answer_from_text(stored_text, "stored.json").answer;
  REQUIRE(stored.contact_intervals.empty());  // no key: none
  const Answer same = stored;
  CHECK(regress_differences(stored, same).empty());

  SECTION("a recomputed continuous touch the stored answer does not have") {
    Answer r = stored;
    r.contact_intervals.push_back(r.intervals[0]);
    r.contacts.clear();
    const auto d = regress_differences(stored, r);
    CHECK(mentions(d, "contact_intervals: stored 0, recomputed 1"));
  }
  SECTION("recomputed collides false") {
    Answer r;
    const auto d = regress_differences(stored, r);
    CHECK(mentions(d, "collides: stored true, recomputed false"));
    CHECK(mentions(d, "first contact: stored t = 1/4, recomputed none"));
  }
  SECTION("an extra recomputed contact at 3/4") {
    Answer r = stored;
    r.contacts.push_back(bracketed_instant(q("3/4"), q("3/4"), q("3/4")));
    const auto d = regress_differences(stored, r);
    REQUIRE(d.size() == 1);
    CHECK(d[0] == "false contact near t = 3/4");
  }
}

TEST_CASE("regress: stored answers of the cases agree with the exact pipeline", "[compare][regress]") {
  for (const char* name : {"paper003/example2.json", "touch3d/touch-and-separate.json",
                           "touch3d/touch-then-overlap.json", "paper002/example.json"}) {
    const std::string path = std::string(ECCD_SOURCE_DIR) + "/cases/" + name;
    INFO(path);
    const Scene s = read_scene(path);
    REQUIRE(s.answer.has_value());
    const Answer recomputed = solve(s).answer;
    CHECK(regress_differences(*s.answer, recomputed).empty());
    // The stored answer with its first interval's end moved by 1e-6 (a decimal, no bracket) no longer agrees.
    if (!s.answer->intervals.empty()) {
      Answer moved = *s.answer;
      Instant& end = moved.intervals[0].second;
      end.lo.reset();
      end.hi.reset();
      end.value = end.value > 0.5 ? end.value - 1e-6 : end.value + 1e-6;
      char b[40];
      std::snprintf(b, sizeof b, "%.17g", end.value);
      end.approx = b;
      const auto d = regress_differences(moved, recomputed);
      CHECK(mentions(d, "collision interval 1 end off by 1e-06"));
    }
  }
}

}  // namespace ECCD_UNITY_ID
