// From a decided timeline to the scene answer (kernel/collision_timeline.hpp;
// docs/answer-format.md): timelines written by hand, instant, cell, ...,
// instant over [0, 1], with the answer the statement gives for each: no
// collision; an isolated touch (003's example 2: the collision set is the
// single instant 1/2, a contact); an overlap between two touches; an overlap
// from t = 0; a run that starts on a cell (rounding) widened to the
// neighbouring instants; an uncertain instant; continuous touching (a
// contact interval, whose instants are not listed as contacts); and an
// isolated overlapping instant between separate cells, which rounded
// arithmetic turns into an uncertain node and exact arithmetic refuses.
#include "kernel/collision_timeline.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// Nodes from a string: instants are capitals, cells lower case (S/s separate,
// T/t touching, O/o overlapping, U/u uncertain), alternating from an instant;
// the m + 1 instants at k / m, each cell's sample at its middle.
std::vector<TimelineNode> timeline(const std::string& nodes) {
  const std::size_t m = nodes.size() / 2;
  std::vector<TimelineNode> seq;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const char c = nodes[k];
    const bool cell = k % 2 == 1;
    const double t = double(k) / double(2 * m);
    const char up = char(cell ? c - 'a' + 'A' : c);
    const Status s = up == 'S'   ? Status::separate
                     : up == 'T' ? Status::touching
                     : up == 'O' ? Status::overlapping
                                 : Status::uncertain;
    seq.push_back({Instant{std::to_string(t), std::nullopt, std::nullopt, t}, s, cell});
  }
  return seq;
}

Answer answer_of(const std::string& nodes, int* contacts_seen = nullptr) {
  Answer a;
  assemble_answer(timeline(nodes), a, [&](std::size_t) {
    if (contacts_seen) ++*contacts_seen;
  });
  return a;
}

std::vector<std::pair<double, double>> values(const std::vector<std::pair<Instant, Instant>>& xs) {
  std::vector<std::pair<double, double>> out;
  for (const auto& [a, b] : xs) out.emplace_back(a.value, b.value);
  return out;
}
std::vector<double> values(const std::vector<Instant>& xs) {
  std::vector<double> out;
  for (const auto& x : xs) out.push_back(x.value);
  return out;
}
using Pairs = std::vector<std::pair<double, double>>;
using Values = std::vector<double>;

}  // namespace

TEST_CASE("the answer of hand-written timelines", "[kernel][collision_timeline]") {
  SECTION("separate throughout: no collision") {
    const Answer a = answer_of("SsSsS");
    CHECK_FALSE(a.collides);
    CHECK(a.intervals.empty());
    CHECK(a.contacts.empty());
    CHECK_FALSE(a.first_contact);
  }
  SECTION("an isolated touch at 1/2 (003 example 2): the collision set is that instant") {
    int seen = 0;
    const Answer a = answer_of("SsTsS", &seen);
    CHECK(a.collides);
    CHECK(values(a.intervals) == Pairs{{0.5, 0.5}});
    CHECK(values(a.contacts) == Values{0.5});
    CHECK(a.first_contact->value == 0.5);
    CHECK(seen == 1);
  }
  SECTION("an overlap between two touches") {
    const Answer a = answer_of("SsToTsS");
    CHECK(values(a.intervals) == Pairs{{1.0 / 3, 2.0 / 3}});
    CHECK(values(a.contacts) == Values{1.0 / 3, 2.0 / 3});
    CHECK(a.first_contact->value == 1.0 / 3);
    CHECK(a.contact_intervals.empty());
  }
  SECTION("overlapping from t = 0 until a touch, then a second overlap to the end") {
    const Answer a = answer_of("OoTsToO");
    CHECK(values(a.intervals) == Pairs{{0.0, 1.0 / 3}, {2.0 / 3, 1.0}});
    CHECK(values(a.contacts) == Values{1.0 / 3, 2.0 / 3});
    CHECK(a.first_contact->value == 0.0);
  }
  SECTION("a run that starts and ends on a cell is widened to the instants around it") {
    const Answer a = answer_of("SoS");
    CHECK(values(a.intervals) == Pairs{{0.0, 1.0}});
    CHECK(a.contacts.empty());
  }
  SECTION("an uncertain instant is undecided and claims nothing") {
    const Answer a = answer_of("SsUsS");
    CHECK_FALSE(a.collides);
    CHECK(values(a.undecided) == Values{0.5});
    CHECK_FALSE(collides_claim(a).has_value());
  }
  SECTION("continuous touching: a contact interval, its instants not listed as contacts") {
    const Answer a = answer_of("SsTtTsS");
    CHECK(values(a.contact_intervals) == Pairs{{1.0 / 3, 2.0 / 3}});
    CHECK(a.contacts.empty());
    CHECK(values(a.intervals) == Pairs{{1.0 / 3, 2.0 / 3}});
    // two touching cells in a row make one contact interval
    const Answer b = answer_of("StTtS");
    CHECK(values(b.contact_intervals) == Pairs{{0.0, 1.0}});
  }
}

TEST_CASE("an isolated overlapping instant between separate cells", "[kernel][collision_timeline]") {
  std::vector<TimelineNode> seq = timeline("SsOsS");
  CHECK_THROWS_AS(check_isolated_instants(seq, true), std::logic_error);  // exact: impossible
  check_isolated_instants(seq, false);                                    // rounded: not decided
  CHECK(seq[2].status == Status::uncertain);
  // next to an overlapping cell it is a legitimate end of an overlap: kept
  std::vector<TimelineNode> ok = timeline("SsOoS");
  check_isolated_instants(ok, true);
  CHECK(ok[2].status == Status::overlapping);
}

}  // namespace ECCD_UNITY_ID
