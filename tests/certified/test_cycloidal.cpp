// Cycloidal motions (003 section V, Example 1; issue 20): double, mpfr:128
// and certified agree with the paper's printed digits, the certified
// brackets are proved and contain the paper's values as printed, and a true
// double root (a touch) is never claimed: it is undecided with its bound.
#include "api/solve.hpp"
#include "api/static_status.hpp"
#include "io/scene_reader.hpp"
#include "kernel/cycloidal_motion.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
const std::string kExample1 = std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example1.json";

Solution solve_in(const Scene& s, Arithmetic a) {
  SolveOptions o;
  o.arith = a;
  return solve(s, o);
}
// The printed value p (3 decimals) is what x rounds to: |x - p| <= 0.0005.
bool prints_as(double x, double p) { return std::fabs(x - p) <= 0.0005; }
// A plain decimal ("-0.226", "0.22609491260372101997") as an exact rational.
mpq_class decimal(std::string x) {
  bool neg = !x.empty() && x[0] == '-';
  if (neg) x = x.substr(1);
  std::size_t dot = x.find('.');
  std::string digits = dot == std::string::npos ? x : x.substr(0, dot) + x.substr(dot + 1);
  std::size_t scale = dot == std::string::npos ? 0 : x.size() - dot - 1;
  mpq_class q{mpz_class(digits, 10)};
  mpz_class ten;
  mpz_ui_pow_ui(ten.get_mpz_t(), 10, scale);
  q /= ten;
  return neg ? mpq_class(-q) : q;
}
bool prints_as(const mpq_class& x, const char* p) {
  mpq_class d = x - decimal(p);
  return abs(d) <= mpq_class(1, 2000);
}
}  // namespace

TEST_CASE("003 Example 1: double, mpfr:128 and certified reproduce the paper's roots, first contact and contact points",
          "[cycloidal]") {
  const Scene s = read_scene(kExample1);
  // The paper (003 section V, Example 1, Maple): roots of Δ at 0.226, 0.393, 0.600, 0.731; first contact 0.226 at
  // (-47.605, -33.162); the other external touch at 0.731 at (-2.469, 2.723).
  const double roots[4] = {0.226, 0.393, 0.600, 0.731};
  for (Arithmetic a : {Arithmetic::double_precision(), Arithmetic::mpfr(128), Arithmetic::certified()}) {
    INFO(a.name());
    Solution r = solve_in(s, a);
    REQUIRE(r.answer.undecided.empty());
    REQUIRE(r.critical.size() == 4);
    for (int k = 0; k < 4; ++k) CHECK(prints_as(r.critical[k].t.value, roots[k]));
    CHECK(r.critical[0].status == Status::touching);
    CHECK(r.critical[1].status == Status::overlapping);  // roots of Δ that are not contacts (003 VI-B)
    CHECK(r.critical[2].status == Status::overlapping);
    CHECK(r.critical[3].status == Status::touching);
    CHECK(r.answer.collides);
    REQUIRE(r.answer.first_contact);
    CHECK(prints_as(r.answer.first_contact->value, 0.226));
    REQUIRE(r.answer.intervals.size() == 1);
    CHECK(prints_as(r.answer.intervals[0].second.value, 0.731));
    REQUIRE(r.answer.contacts.size() == 2);
    REQUIRE(r.answer.contact_points.size() == 2);
    auto coord = [&](int c, int i) {
      std::string x = r.answer.contact_points[c].x[i];
      if (!x.empty() && x[0] == '[') x = x.substr(1);  // an interval "[lo, hi]": its lower end
      return std::stod(x);
    };
    CHECK(prints_as(coord(0, 0), -47.605));
    CHECK(prints_as(coord(0, 1), -33.162));
    CHECK(prints_as(coord(1, 0), -2.469));
    CHECK(prints_as(coord(1, 1), 2.723));
  }
}

TEST_CASE(
    "003 Example 1, certified: proved brackets, containing the paper's printed values as printed, and the floating "
    "approximations",
    "[cycloidal][certified]") {
  const Scene s = read_scene(kExample1);
  Solution c = solve_in(s, Arithmetic::certified());
  REQUIRE(c.certified);
  REQUIRE(c.critical.size() == 4);
  const char* printed[4] = {"0.226", "0.393", "0.600", "0.731"};
  Solution d = solve_in(s, Arithmetic::double_precision()), m = solve_in(s, Arithmetic::mpfr(128));
  REQUIRE(d.critical.size() == 4);
  REQUIRE(m.critical.size() == 4);
  for (int k = 0; k < 4; ++k) {
    const Instant& t = c.critical[k].t;
    REQUIRE(t.certified());
    CHECK(*t.lo < *t.hi);
    CHECK(*t.hi - *t.lo <= mpq_class(1, mpz_class(1) << 60));
    CHECK(prints_as(*t.lo, printed[k]));
    CHECK(prints_as(*t.hi, printed[k]));
    // floating approximations: mpfr:128 to 1e-25 of the bracket, double to 1e-9
    CHECK(std::fabs(m.critical[k].t.value - t.value) < 1e-15);
    CHECK(std::fabs(d.critical[k].t.value - t.value) < 1e-9);
    mpq_class mq = decimal(m.critical[k].t.approx);
    CHECK(mq >= *t.lo - mpq_class(1, mpz_class(1) << 83));
    CHECK(mq <= *t.hi + mpq_class(1, mpz_class(1) << 83));
  }
  // the stored answer of the case is this certified answer
  REQUIRE(s.answer);
  REQUIRE(s.answer->contacts.size() == 2);
  CHECK(*s.answer->contacts[0].lo == *c.answer.contacts[0].lo);
  CHECK(*s.answer->contacts[1].hi == *c.answer.contacts[1].hi);
}

TEST_CASE("cycloidal: a true touch (a double root of Δ) is never claimed, it is undecided with its proved bound",
          "[cycloidal][certified]") {
  // A: x²/4 + y² <= 1 translated to (-1 + 2t, 3), not turning; B: x² + y²/4 <= 1 fixed. At t = 1/2 A's lowest point
  // (0, 2) is B's highest: they touch externally there and are separate before and after (Δ has a double root).
  const std::string text = R"({"format": "ellipse-ccd-scene/1", "name": "touch", "dim": 2,
    "a": {"shape": {"semi_axes": ["2", "1"]},
          "motion": {"type": "cycloidal", "angle_over_pi": ["0", "0"], "translation": [["-1", "2"], ["3", "0"]]}},
    "b": {"shape": {"semi_axes": ["1", "2"]}, "motion": {"type": "static"}}})";
  const Scene s = scene_from_text(text, "touch");
  for (Arithmetic a : {Arithmetic::double_precision(), Arithmetic::mpfr(128), Arithmetic::certified()}) {
    INFO(a.name());
    Solution r = solve_in(s, a);
    CHECK(r.answer.contacts.empty());  // no claimed touch
    CHECK(!r.certified);
    REQUIRE(r.answer.undecided.size() >= 1);
    bool near_half = false;
    for (const auto& u : r.answer.undecided) near_half = near_half || std::fabs(u.value - 0.5) < 1e-6;
    CHECK(near_half);
    bool said = false;
    for (const auto& w : r.undecided_reasons) said = said || w.find("touch or near miss") != std::string::npos;
    CHECK(said);
  }
}

TEST_CASE("cycloidal: a touch at t = 0 leaves t = 0 undecided, and the rest of [0, 1] is decided",
          "[cycloidal][certified]") {
  // As above with A at (2t, 3): touching at t = 0, separate after.
  const std::string text = R"({"format": "ellipse-ccd-scene/1", "name": "touch0", "dim": 2,
    "a": {"shape": {"semi_axes": ["2", "1"]},
          "motion": {"type": "cycloidal", "angle_over_pi": ["0", "0"], "translation": [["0", "2"], ["3", "0"]]}},
    "b": {"shape": {"semi_axes": ["1", "2"]}, "motion": {"type": "static"}}})";
  const Scene s = scene_from_text(text, "touch0");
  for (Arithmetic a : {Arithmetic::double_precision(), Arithmetic::certified()}) {
    INFO(a.name());
    Solution r = solve_in(s, a);
    CHECK(r.answer.contacts.empty());
    CHECK(!r.answer.collides);
    REQUIRE(r.answer.undecided.size() == 1);
    CHECK(r.answer.undecided[0].value == 0.0);
    REQUIRE(!r.cells.empty());
    CHECK(r.cells.back().status == Status::separate);
  }
}

TEST_CASE("cycloidal: exact arithmetic refuses, pointing to what solves it", "[cycloidal]") {
  const Scene s = read_scene(kExample1);
  try {
    solve_in(s, Arithmetic::exact());
    FAIL("exact arithmetic solved a cycloidal scene");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("double, mpfr:BITS or certified") != std::string::npos);
  }
}

TEST_CASE("cycloidal: status_at agrees with the cells of 003 Example 1 in double, mpfr:128 and certified",
          "[cycloidal][api]") {
  const Scene s = read_scene(kExample1);
  for (Arithmetic a : {Arithmetic::double_precision(), Arithmetic::mpfr(128), Arithmetic::certified()}) {
    INFO(a.name());
    CHECK(status_at(s, mpq_class(1, 10), a) == Status::separate);
    CHECK(status_at(s, mpq_class(3, 10), a) == Status::overlapping);
    CHECK(status_at(s, mpq_class(1, 2), a) == Status::overlapping);
    CHECK(status_at(s, mpq_class(9, 10), a) == Status::separate);
  }
}

TEST_CASE("cycloidal beside a rational motion: refused with a message that says what is supported", "[cycloidal]") {
  const std::string text = R"({"format": "ellipse-ccd-scene/1", "name": "mixed", "dim": 2,
    "a": {"shape": {"semi_axes": ["2", "1"]},
          "motion": {"type": "cycloidal", "angle_over_pi": ["0", "1"], "translation": [["0", "2"], ["3", "0"]]}},
    "b": {"shape": {"semi_axes": ["1", "2"]}, "motion": {"type": "kinematic", "d": [["0"], ["0"], ["1"], ["0", "1"]]}}})";
  const Scene s = scene_from_text(text, "mixed");
  for (Arithmetic a : {Arithmetic::double_precision(), Arithmetic::certified()}) {
    INFO(a.name());
    try {
      solve_in(s, a);
      FAIL("a cycloidal motion beside a kinematic one was solved");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).find("only static and cycloidal motions can be combined") != std::string::npos);
    }
  }
}

}  // namespace ECCD_UNITY_ID
