// kernel/cycloidal_cd_disc.hpp: CD-DISC for cycloidal motions (003 section V),
// roots of the transcendental Δ(t) isolated by validated subdivision. Checked
// against independent values:
//   - 003 Example 1 (cases/paper003/example1.json) in Bounded<double>: the paper's roots
//     of Δ (0.226, 0.393, 0.600, 0.731), its first contact 0.226 at
//     (-47.605, -33.162) and external touch 0.731 at (-2.469, 2.723), to the
//     three decimals printed;
//   - cycloidal scenes that are also rational (no turning, or a constant turn
//     by π/2, or a turning circle, which a turn about its centre leaves
//     unchanged) against the exact rational pipeline (kernel/cd_disc.hpp with
//     exact/cd_disc_exact.hpp) on the equivalent matrix motions: every
//     proved bracket holds the exact root (the two brackets meet), statuses
//     and intervals agree; in MPFI and in Bounded<double>;
//   - a root of Δ of multiplicity 6 (concentric circles, 003 VI-B) cannot be
//     proved simple: an undecided stretch with a reason, never a touch;
//   - a touch exactly at t = 1 (Δ(1) = 0): the end is left undecided;
//   - the work bound on cells, and the variants of 003 VI-C.
#include "exact/cd_disc_exact.hpp"
#include "io/scene_reader.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/cycloidal_cd_disc.hpp"
#include "kernel/prepared_scene.hpp"
#include "number/mpfi_interval.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

std::string object(const std::string& axes, const std::string& motion) {
  return "{\"shape\": {\"semi_axes\": " + axes + "}, \"motion\": " + motion + "}";
}
std::string cycloidal(const std::string& th0, const std::string& th1, const std::string& x0, const std::string& x1,
                      const std::string& y0, const std::string& y1) {
  return "{\"type\": \"cycloidal\", \"angle_over_pi\": [\"" + th0 + "\", \"" + th1 + "\"], \"translation\": [[\"" + x0 +
         "\", \"" + x1 + "\"], [\"" + y0 + "\", \"" + y1 + "\"]]}";
}
// The same translation (x0 + x1 t, y0 + y1 t) as a rational matrix motion.
std::string matrix(const std::string& x0, const std::string& x1, const std::string& y0, const std::string& y1) {
  return "{\"type\": \"matrix\", \"m\": [[\"1\", \"0\", [\"" + x0 + "\", \"" + x1 + "\"]], [\"0\", \"1\", [\"" + y0 +
         "\", \"" + y1 + "\"]], [\"0\", \"0\", \"1\"]]}";
}
const std::string kStatic = "{\"type\": \"static\"}";
Scene scene_of(const std::string& a, const std::string& b) {
  return parse_scene(
      "{\"format\": \"ellipse-ccd-scene/1\", \"name\": \"t\", \"dim\": 2, \"a\": " + a + ", \"b\": " + b + "}", "test");
}

const MpfiInterval kLike(Rational(0), 128);
CycloidalOptions certified_options() {
  CycloidalOptions o;
  o.certified = true;
  return o;
}
PipelineResult<MpfiInterval> run_mpfi(const Scene& s, Variant v = Variant::answer,
                                      CycloidalOptions o = certified_options()) {
  return cycloidal_cd_disc(cycloidal_pair<MpfiInterval>(s, kLike), kLike, o, v);
}
const Bounded<double> kBounded(0.0, 0);
PipelineResult<Bounded<double>> run_bounded(const Scene& s, Variant v = Variant::answer,
                                            CycloidalOptions o = CycloidalOptions{}) {
  return cycloidal_cd_disc(cycloidal_pair<Bounded<double>>(s, kBounded), kBounded, o, v);
}
PipelineResult<Rational> run_exact(const Scene& s) {
  ExactPolicy pol;
  return cd_disc(to_arithmetic<Rational, H_2D>(prepare_pair<H_2D>(s), Rational(1)), pol);
}
// Two brackets that each provably hold one root of Δ meet iff they hold the same root.
bool meet(const Instant& a, const Instant& b) {
  REQUIRE(a.certified());
  REQUIRE(b.certified());
  return *a.lo <= *b.hi && *b.lo <= *a.hi;
}
// A contact point's coordinate as printed: a decimal, or an interval "[lo, hi]" (MPFI), read at its mid-point.
double num(const std::string& s) {
  if (s.empty() || s[0] != '[') return std::stod(s);
  const std::size_t comma = s.find(',');
  return (std::stod(s.substr(1, comma - 1)) + std::stod(s.substr(comma + 1))) / 2;
}

// A cycloidal run against the exact run of the same motion: the same timeline, statuses and answer.
template <class T>
void check_same(const PipelineResult<T>& cyc, const PipelineResult<Rational>& ex, bool brackets) {
  REQUIRE(cyc.timeline.size() == ex.timeline.size());
  for (std::size_t k = 0; k < ex.timeline.size(); ++k) {
    INFO("timeline node " << k);
    CHECK(cyc.timeline[k].status == ex.timeline[k].status);
    CHECK(cyc.timeline[k].is_cell == ex.timeline[k].is_cell);
    if (!ex.timeline[k].is_cell) {
      if (brackets)
        CHECK(meet(cyc.timeline[k].t, ex.timeline[k].t));
      else
        CHECK(cyc.timeline[k].t.value == Approx(ex.timeline[k].t.value).margin(1e-9));
    }
  }
  const Answer &a = cyc.answer, &b = ex.answer;
  CHECK(a.collides == b.collides);
  CHECK(a.undecided.empty());
  REQUIRE(a.intervals.size() == b.intervals.size());
  REQUIRE(a.contacts.size() == b.contacts.size());
  for (std::size_t i = 0; i < b.contacts.size(); ++i) {
    if (brackets)
      CHECK(meet(a.contacts[i], b.contacts[i]));
    else
      CHECK(a.contacts[i].value == Approx(b.contacts[i].value).margin(1e-9));
  }
  REQUIRE(a.contact_points.size() == b.contact_points.size());
  for (std::size_t i = 0; i < b.contact_points.size(); ++i)
    for (int j = 0; j < 2; ++j)
      CHECK(num(a.contact_points[i].x[j]) == Approx(num(b.contact_points[i].x[j])).margin(1e-9));
}

}  // namespace

TEST_CASE("cycloidal_cd_disc on 003 Example 1 reproduces the paper's roots, contacts and contact points",
          "[kernel][cycloidal_cd_disc]") {
  const Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example1.json");
  const auto res = run_bounded(s);  // (in MPFI it takes ten times as long, with the same cells)
  // 003 section V, Example 1: the roots of Δ in [0, 1] are 0.226, 0.393, 0.600, 0.731.
  const double roots[4] = {0.226, 0.393, 0.600, 0.731};
  REQUIRE(res.critical.size() == 4);
  for (int i = 0; i < 4; ++i) {
    CHECK(res.critical[i].t.value == Approx(roots[i]).margin(5e-4));
    CHECK(res.critical[i].multiplicity == 1);  // each proved simple
  }
  const Answer& a = res.answer;
  CHECK(a.collides);
  CHECK(a.undecided.empty());
  CHECK(res.undecided_reasons.empty());
  REQUIRE(a.first_contact);
  CHECK(a.first_contact->value == Approx(0.226).margin(5e-4));
  REQUIRE(a.intervals.size() == 1);
  CHECK(a.intervals[0].first.value == Approx(0.226).margin(5e-4));
  CHECK(a.intervals[0].second.value == Approx(0.731).margin(5e-4));
  // Only the first and last roots are external touches; at 0.393 and 0.600 the disks overlap.
  CHECK(res.critical[0].status == Status::touching);
  CHECK(res.critical[1].status == Status::overlapping);
  CHECK(res.critical[2].status == Status::overlapping);
  CHECK(res.critical[3].status == Status::touching);
  // the cells: separate before the first contact and after the last, overlapping in between
  REQUIRE(res.cells.size() == 5);
  const Status cells[5] = {Status::separate, Status::overlapping, Status::overlapping, Status::overlapping,
                           Status::separate};
  for (int i = 0; i < 5; ++i) CHECK(res.cells[i].status == cells[i]);
  REQUIRE(a.contacts.size() == 2);
  REQUIRE(a.contact_points.size() == 2);
  CHECK(num(a.contact_points[0].x[0]) == Approx(-47.605).margin(5e-4));
  CHECK(num(a.contact_points[0].x[1]) == Approx(-33.162).margin(5e-4));
  CHECK(num(a.contact_points[1].x[0]) == Approx(-2.469).margin(5e-4));
  CHECK(num(a.contact_points[1].x[1]) == Approx(2.723).margin(5e-4));
  CHECK(res.status_at_0 == Status::separate);
  bool counted = false;
  for (const auto& [name, n] : res.counters)
    if (name == "cells") counted = n >= 64;  // at least the grid of 64
  CHECK(counted);
}

TEST_CASE("cycloidal_cd_disc agrees with the exact pipeline when the cycloidal motion is rational",
          "[kernel][cycloidal_cd_disc]") {
  SECTION("an ellipse translating past a static circle, no turn") {
    const Scene cyc = scene_of(object("[\"2\", \"1\"]", cycloidal("0", "0", "-5", "10", "1/2", "0")),
                               object("[\"1\", \"1\"]", kStatic));
    const Scene ex =
        scene_of(object("[\"2\", \"1\"]", matrix("-5", "10", "1/2", "0")), object("[\"1\", \"1\"]", kStatic));
    const auto e = run_exact(ex);
    REQUIRE(e.answer.contacts.size() == 2);  // enters and leaves
    check_same(run_mpfi(cyc), e, true);
    check_same(run_bounded(cyc), e, false);
  }
  SECTION("a constant turn by π/2 swaps the semi-axes") {
    const Scene cyc = scene_of(object("[\"3\", \"1\"]", cycloidal("1/2", "0", "1/3", "0", "-6", "12")),
                               object("[\"2\", \"1\"]", kStatic));
    const Scene ex =
        scene_of(object("[\"1\", \"3\"]", matrix("1/3", "0", "-6", "12")), object("[\"2\", \"1\"]", kStatic));
    const auto e = run_exact(ex);
    REQUIRE(e.answer.contacts.size() == 2);
    check_same(run_mpfi(cyc), e, true);
  }
  SECTION("a turning circle is the translating circle: the turn is about its centre") {
    const Scene cyc = scene_of(object("[\"1\", \"1\"]", cycloidal("0", "7/3", "-4", "9", "1", "-1")),
                               object("[\"3\", \"1\"]", kStatic));
    const Scene ex =
        scene_of(object("[\"1\", \"1\"]", matrix("-4", "9", "1", "-1")), object("[\"3\", \"1\"]", kStatic));
    const auto e = run_exact(ex);
    REQUIRE(e.answer.contacts.size() == 2);
    check_same(run_mpfi(cyc), e, true);
  }
}

TEST_CASE("cycloidal_cd_disc leaves a multiple root of Δ undecided with its bound, never a touch",
          "[kernel][cycloidal_cd_disc]") {
  // Two unit circles, A centred at (6t - 3, 0): Δ = c⁶(c² - 4), c = 6t - 3 (kernel/test_cd_disc.cpp): simple
  // roots at the touches 1/6 and 5/6, a sixfold root at 1/2 (concentric, overlap) that no sign proves simple.
  const Scene s =
      scene_of(object("[\"1\", \"1\"]", cycloidal("0", "0", "-3", "6", "0", "0")), object("[\"1\", \"1\"]", kStatic));
  CycloidalOptions o = certified_options();
  o.max_depth = 10;  // cells of 2^-10 around the sixfold root (at 2^-40 this takes a minute)
  const auto res = run_mpfi(s, Variant::answer, o);
  const Answer& a = res.answer;
  REQUIRE(a.contacts.size() == 2);
  CHECK(*a.contacts[0].lo <= Rational(1, 6));
  CHECK(Rational(1, 6) <= *a.contacts[0].hi);
  CHECK(*a.contacts[1].lo <= Rational(5, 6));
  CHECK(Rational(5, 6) <= *a.contacts[1].hi);
  bool stretch = false;
  for (const auto& c : res.critical) {
    if (c.status != Status::uncertain) continue;
    // The undecided stretch holds t = 1/2 and is reported as a cluster, not a simple root.
    CHECK(c.multiplicity == 2);
    CHECK(*c.t.lo <= Rational(1, 2));
    CHECK(Rational(1, 2) <= *c.t.hi);
    stretch = true;
  }
  CHECK(stretch);
  REQUIRE_FALSE(res.undecided_reasons.empty());
  CHECK(res.undecided_reasons[0].find("Δ has no proved sign") != std::string::npos);
  // The overlap on both sides of 1/2 is proved: the claim is a collision.
  CHECK(a.collides);
  CHECK(collides_claim(a) == std::optional<bool>(true));
}

TEST_CASE("cycloidal_cd_disc leaves a root of Δ at t = 1 undecided: no sign is proved at the end",
          "[kernel][cycloidal_cd_disc]") {
  // A unit circle from (-4, 1) to (4, 0) past the static ellipse x²/9 + y² <= 1: at t = 1 it touches it at
  // (3, 0) (the exact pipeline proves the touch there); Δ(1) = 0, so no cell ending at 1 is proved root-free
  // or holding a simple root: the end stays undecided, with its bound, and is not called separate.
  const std::string a = object("[\"1\", \"1\"]", cycloidal("0", "0", "-4", "8", "1", "-1"));
  const std::string b = object("[\"3\", \"1\"]", kStatic);
  const auto e = run_exact(scene_of(object("[\"1\", \"1\"]", matrix("-4", "8", "1", "-1")), b));
  REQUIRE(e.timeline.back().status == Status::touching);
  CycloidalOptions o = certified_options();
  o.max_depth = 24;
  const auto res = run_mpfi(scene_of(a, b), Variant::answer, o);
  CHECK(res.timeline.back().status == Status::uncertain);
  REQUIRE_FALSE(res.undecided_reasons.empty());
  CHECK(res.undecided_reasons[0].find(", 1] (|Δ| <= ") != std::string::npos);
  // The earlier part is decided as the exact pipeline decides it: the touch on entry, the overlap after.
  REQUIRE(res.answer.contacts.size() >= 1);
  CHECK(meet(res.answer.contacts[0], e.answer.contacts[0]));
  CHECK(res.answer.collides);
}

TEST_CASE("cycloidal_cd_disc at its work bound and in the variants of 003 VI-C", "[kernel][cycloidal_cd_disc]") {
  const Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example1.json");
  SECTION("the work bound on cells leaves the rest undecided, with a reason") {
    CycloidalOptions o;
    o.max_cells = 20;
    const auto res = run_bounded(s, Variant::answer, o);
    bool said = false;
    for (const auto& r : res.undecided_reasons) said = said || r.find("work bound reached") != std::string::npos;
    CHECK(said);
    // Nothing unproved is claimed: no "collision-free", no contact outside the paper's two.
    CHECK(collides_claim(res.answer) != std::optional<bool>(false));
    for (const auto& c : res.answer.contacts) {
      const bool known = c.value == Approx(0.226).margin(5e-4) || c.value == Approx(0.731).margin(5e-4);
      CHECK(known);
    }
  }
  SECTION("variants 1 and 2 keep collides and the first contact, 3 the contacts and their points") {
    for (Variant v : {Variant::collides, Variant::first_contact}) {
      const auto res = run_bounded(s, v);
      CHECK(res.variant == v);
      CHECK(res.answer.collides);
      REQUIRE(res.answer.first_contact);
      CHECK(res.answer.first_contact->value == Approx(0.226).margin(5e-4));
      CHECK(res.answer.intervals.empty());
      CHECK(res.answer.contacts.empty());
      CHECK(res.answer.contact_points.empty());
    }
    const auto all = run_bounded(s, Variant::all_contacts);
    CHECK(all.answer.intervals.empty());
    CHECK(all.answer.contacts.size() == 2);
    CHECK(all.answer.contact_points.size() == 2);
  }
}

}  // namespace ECCD_UNITY_ID
