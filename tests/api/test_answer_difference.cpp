// The one answer comparison (api/answer_difference.hpp) on hand-made answers
// whose differences are known, and on the exact pipeline's answers.
#include "api/answer_difference.hpp"
#include "number/rational_traits.hpp"
#include "tests/support/instants.hpp"

#include <catch2/catch.hpp>

#include <cstdio>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
using test::dec;                                // a floating instant (tests/support/instants.hpp)
Instant cert(const char* lo, const char* hi) {  // a certified instant
  Instant i;
  i.lo = Rational(lo);
  i.hi = Rational(hi);
  i.lo->canonicalize();
  i.hi->canonicalize();
  i.value = Rational((*i.lo + *i.hi) / 2).get_d();
  i.approx = decimal_string(Rational((*i.lo + *i.hi) / 2));
  return i;
}
Answer answer(bool collides, std::vector<std::pair<double, double>> ivs, std::vector<double> contacts) {
  Answer a;
  a.collides = collides;
  for (auto [x, y] : ivs) a.intervals.push_back({dec(x), dec(y)});
  if (!ivs.empty()) a.first_contact = dec(ivs[0].first);
  for (double c : contacts) a.contacts.push_back(dec(c));
  return a;
}
bool mentions(const AnswerDifference& d, const std::string& s) {
  for (const auto& x : d.differences)
    if (x.find(s) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST_CASE("answer difference: a missed touch, ends off, false and missed collisions, undecided",
          "[answer-difference]") {
  // Reference: an isolated touch at 0.2, then an interval [0.5, 0.6].
  Answer ref = answer(true, {{0.2, 0.2}, {0.5, 0.6}}, {0.2, 0.5, 0.6});
  SECTION("the touch at 0.2 is missed") {
    AnswerDifference d = answer_difference(answer(true, {{0.5, 0.6 + 1e-9}}, {0.5, 0.6 + 1e-9}), ref);
    CHECK_FALSE(d.agrees);
    CHECK_FALSE(d.collides_differs);
    CHECK(d.intervals == 1);
    CHECK(d.reference_intervals == 2);
    CHECK(d.missed == 1);  // the touch, once (as an interval, not again as a contact)
    CHECK(d.missed_contacts == 1);
    CHECK(d.false_contacts == 0);
    REQUIRE(d.first_contact_error);
    CHECK(*d.first_contact_error == Approx(0.3));
    CHECK_FALSE(d.max_endpoint_error);  // not one to one
    CHECK(mentions(d, "missed contact near"));
  }
  SECTION("same structure, ends off by 1e-9: agrees within 1e-6, not within 1e-10") {
    Answer got = answer(true, {{0.2, 0.2}, {0.5 - 1e-9, 0.6}}, {0.2, 0.5 - 1e-9, 0.6});
    AnswerDifference d = answer_difference(got, ref);
    CHECK(d.agrees);
    REQUIRE(d.max_endpoint_error);
    CHECK(*d.max_endpoint_error == Approx(1e-9).epsilon(1e-6));
    DifferenceOptions tight;
    tight.tol = 1e-10;
    AnswerDifference t = answer_difference(got, ref, tight);
    CHECK_FALSE(t.agrees);
    CHECK(t.endpoints_off == 1);
    CHECK(t.missed_contacts == 1);
    CHECK(t.false_contacts == 1);
    CHECK(t.missed == 0);  // the contact at the start of interval 2 was reported through the interval
    CHECK(mentions(t, "collision interval 2 start off by"));
  }
  SECTION("wrong collides both ways, and undecided") {
    AnswerDifference fn = answer_difference(answer(false, {}, {}), ref);
    CHECK(fn.collides_differs);
    CHECK(fn.missed == 2);
    Answer free = answer(false, {}, {});
    AnswerDifference fp = answer_difference(answer(true, {{0.4, 0.4}}, {0.4}), free);
    CHECK(fp.collides_differs);
    CHECK(fp.spurious == 1);
    CHECK(fp.false_contacts == 1);
    Answer unsure = answer(false, {}, {});
    unsure.undecided.push_back(dec(0.3));
    AnswerDifference u = answer_difference(unsure, free);
    CHECK_FALSE(u.agrees);
    CHECK(u.undecided == 1);
    CHECK(mentions(u, "undecided near t ≈ 0.3"));
  }
  SECTION("split and merged intervals") {
    AnswerDifference s =
        answer_difference(answer(true, {{0.5, 0.54}, {0.56, 0.6}}, {0.5, 0.6}), answer(true, {{0.5, 0.6}}, {0.5, 0.6}));
    CHECK(s.split == 1);
    CHECK(mentions(s, "splits collision interval"));
    AnswerDifference m =
        answer_difference(answer(true, {{0.5, 0.6}}, {0.5, 0.6}), answer(true, {{0.5, 0.54}, {0.56, 0.6}}, {0.5, 0.6}));
    CHECK(m.merged == 1);
  }
}

TEST_CASE("answer difference: certified brackets match exactly when they overlap, decimals within tol of a bracket",
          "[answer-difference]") {
  Instant a = cert("1/3", "1/2"), b = cert("1/2", "2/3"), c = cert("2/3", "3/4");
  CHECK(instants_match(a, b, 0));        // they share 1/2
  CHECK_FALSE(instants_match(a, c, 1));  // disjoint brackets never match, whatever the tolerance
  CHECK(instants_match(dec(0.5 + 1e-13), a, 1e-12));
  CHECK_FALSE(instants_match(dec(0.5 + 1e-11), a, 1e-12));
  CHECK(instants_match(dec(0.25), dec(0.25 + 1e-7), 1e-6));
  CHECK_FALSE(instants_match(dec(0.25), dec(0.25 + 1e-5), 1e-6));

  // A stored answer against a recomputed one (regress): one end moved outside its bracket.
  Answer stored, got;
  stored.collides = got.collides = true;
  stored.intervals.push_back({cert("1/4", "1/4"), cert("9/10", "9/10")});
  got.intervals.push_back({cert("1/4", "1/4"), cert("1", "1")});
  stored.first_contact = got.first_contact = cert("1/4", "1/4");
  DifferenceOptions names;
  names.answer_name = "recomputed";
  names.reference_name = "stored";
  names.tol = 1e-12;
  AnswerDifference d = answer_difference(got, stored, names);
  REQUIRE(d.differences.size() == 1);
  CHECK(d.differences[0].find("collision interval 1 end off by 0.1 (stored 0.9, recomputed 1)") == 0);
  // Continuous touching counts.
  got.intervals[0].second = cert("9/10", "9/10");
  got.contact_intervals.push_back({cert("1/4", "1/4"), cert("9/10", "9/10")});
  AnswerDifference t = answer_difference(got, stored, names);
  REQUIRE(t.differences.size() == 1);
  CHECK(t.differences[0].find("contact_intervals: stored 0, recomputed 1") == 0);
}

}  // namespace ECCD_UNITY_ID
