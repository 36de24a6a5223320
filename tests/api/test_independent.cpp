// Independent motions (issue 20 point 3; scene-format.md "Independent
// motions"; paper 001 section 4): the reader's "parameters" key and the
// answer of such scenes, F(u, s, t) checked exactly against the shared F(u, t)
// on the diagonal s = t, the double pipeline against the analytic answers of
// the sphere cases (cases/independent/make_independent.py), double (every
// scene of cases/independent) and mpfr:128 (the sphere and disc scenes) in
// both faces against the exact pipeline's ends with their work counted, and
// the refusals of every pipeline that treats one shared t.
#include "api/answer_difference.hpp"
#include "api/solve.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "kernel/trivariate_bernstein.hpp"
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
std::string indep(const std::string& name) {
  return std::string(ECCD_SOURCE_DIR) + "/cases/independent/" + name + ".json";
}

std::string scene_text(const std::string& parameters, const std::string& answer = "") {
  std::string t = R"({"format": "ellipse-ccd-scene/1", "name": "x", "dim": 3,)";
  if (!parameters.empty()) t += R"( "parameters": )" + parameters + ",";
  t += R"( "a": {"shape": {"semi_axes": ["1", "1", "1"]}, "motion": {"type": "static"}},
           "b": {"shape": {"semi_axes": ["1", "1", "1"]}, "motion": {"type": "static"}})";
  if (!answer.empty()) t += R"(, "answer": )" + answer;
  return t + "}";
}

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "f.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

double end(const std::pair<Instant, Instant>& iv, int k) { return k ? iv.second.value : iv.first.value; }
}  // namespace

TEST_CASE("the reader takes \"parameters\": \"shared\" (default) or \"independent\" and nothing else",
          "[independent]") {
  CHECK_FALSE(parse_scene(scene_text(""), "f.json").independent);
  CHECK_FALSE(parse_scene(scene_text(R"("shared")"), "f.json").independent);
  CHECK(parse_scene(scene_text(R"("independent")"), "f.json").independent);
  for (const char* bad : {R"("Independent")", R"("both")", "1", "true", "null"}) {
    const std::string e = error_of(scene_text(bad));
    CHECK(e.find("f.json: /parameters: parameters must be \"shared\"") == 0);
  }
}

TEST_CASE("an independent scene's answer is collides, s_intervals, t_intervals", "[independent]") {
  const std::string iv =
      R"([[{"approx": "0.25", "lo": null, "hi": null}, {"approx": "0.5", "lo": "1/2", "hi": "1/2"}]])";
  Scene s = parse_scene(
      scene_text(R"("independent")", R"({"collides": true, "s_intervals": )" + iv + R"(, "t_intervals": )" + iv + "}"),
      "f.json");
  REQUIRE(s.answer);
  CHECK(s.answer->independent);
  REQUIRE(s.answer->s_intervals.size() == 1);
  CHECK(s.answer->t_intervals[0].second.certified());
  // written and read back the same
  const Answer back = answer_from_json(answer_to_json(*s.answer), "g.json", "");
  CHECK(back.independent);
  CHECK(answer_difference(back, *s.answer).agrees);
  // keys of the other kind, and inconsistent lists, are errors at their place
  CHECK(error_of(scene_text(R"("independent")", R"({"collides": true, "intervals": []})"))
            .find("/answer/intervals: \"intervals\" does not apply to independent motions") != std::string::npos);
  CHECK(error_of(scene_text("", R"({"collides": true, "s_intervals": )" + iv + "}"))
            .find("/answer/s_intervals: \"s_intervals\" applies to independent motions only") != std::string::npos);
  CHECK(error_of(scene_text(R"("independent")", R"({"collides": false, "t_intervals": )" + iv + "}"))
            .find("collides is false but t_intervals is not empty") != std::string::npos);
  CHECK(error_of(scene_text(R"("independent")", R"({"collides": true, "s_intervals": []})"))
            .find("collides is true but s_intervals is empty") != std::string::npos);
}

TEST_CASE("answer_difference matches s- and t-intervals like intervals", "[independent]") {
  Answer a;
  a.independent = true;
  a.collides = true;
  a.s_intervals = {{rounded_instant(0.25), rounded_instant(0.5)}};
  a.t_intervals = {{rounded_instant(0.1), rounded_instant(0.2)}};
  Answer b = a;
  CHECK(answer_difference(a, b).agrees);
  b.t_intervals[0].second = rounded_instant(0.3);
  const AnswerDifference d = answer_difference(a, b);
  CHECK_FALSE(d.agrees);
  CHECK(d.endpoints_off == 1);
  REQUIRE(d.differences.size() == 1);
  CHECK(d.differences[0].find("t-interval 1 end off by") == 0);
  Answer shared;
  shared.collides = true;
  CHECK_FALSE(answer_difference(a, shared).agrees);  // different kinds never agree
}

TEST_CASE("F(u, s, t) on the diagonal s = t is the shared F(u, t), exactly", "[independent]") {
  for (const char* name : {"spheres-cross", "ellipsoids-cross"}) {
    Scene sc = read_scene(indep(name));
    sc.independent = false;
    const PreparedPair<4> p = prepare_pair<4>(sc);
    const Rational one(1);
    const TriBern<Rational> F =
        independent_ellipsoid_function<Rational, 4>(to_arithmetic_bernstein<Rational, 4>(p, one));
    const BiBern<Rational> G = ellipsoid_function(characteristic_bernstein<Rational, 4>(p, false, one), one);
    for (const Rational& u : {Rational(1, 7), Rational(1, 2), Rational(5, 6)})
      for (const Rational& t : {Rational(0), Rational(1, 3), Rational(3, 4), Rational(1)}) CHECK(F(u, t, t) == G(u, t));
    // and off the diagonal it is not symmetric in general: F depends on s and t separately
    CHECK(F.n[1] > 0);
    CHECK(F.n[2] > 0);
  }
}

TEST_CASE("double: the sphere cases' s- and t-intervals within 1e-9 of the analytic ends", "[independent]") {
  SolveOptions o;
  o.arith = parse_arithmetic("double");
  const double r5 = std::sqrt(5.0);
  struct Case {
    const char* name;
    double s0, s1, t0, t1;
  };
  for (const Case& c : {Case{"spheres-cross", 0.5 - r5 / 12, 0.5 + r5 / 12, 0.5 - r5 / 8, 0.5 + r5 / 8},
                        Case{"spheres-end", 1.0 / 3, 2.0 / 3, 0.0, (r5 - 1) / 8}}) {
    INFO(c.name);
    const Solution s = solve(read_scene(indep(c.name)), o);
    CHECK(s.answer.independent);
    CHECK(s.answer.collides);
    CHECK(s.answer.undecided.empty());
    REQUIRE(s.answer.s_intervals.size() == 1);
    REQUIRE(s.answer.t_intervals.size() == 1);
    CHECK(std::abs(end(s.answer.s_intervals[0], 0) - c.s0) <= 1e-9);
    CHECK(std::abs(end(s.answer.s_intervals[0], 1) - c.s1) <= 1e-9);
    CHECK(std::abs(end(s.answer.t_intervals[0], 0) - c.t0) <= 1e-9);
    CHECK(std::abs(end(s.answer.t_intervals[0], 1) - c.t1) <= 1e-9);
    CHECK_FALSE(s.answer.s_intervals[0].first.certified());  // floating: no bracket is claimed
  }
}

namespace {
// [lo, hi] holds a root of p (a sign change or a zero at an end), and only roots in [a, b]
void check_bracket(const Instant& i, const RPoly& p, const Rational& a, const Rational& b) {
  REQUIRE(i.certified());
  CHECK(*i.lo >= a);
  CHECK(*i.hi <= b);
  CHECK(sgn(p(*i.lo)) * sgn(p(*i.hi)) <= 0);
  CHECK(*i.hi - *i.lo <= Rational(1, 1000000000));
}
void check_exact(const Instant& i, const Rational& x) {
  REQUIRE(i.certified());
  CHECK(*i.lo <= x);
  CHECK(x <= *i.hi);
}
}  // namespace

TEST_CASE("exact: the sphere cases' brackets contain the analytic ends", "[independent]") {
  SolveOptions o;  // exact
  {
    const Solution s = solve(read_scene(indep("spheres-cross")), o);
    CHECK(s.certified);
    REQUIRE(s.answer.s_intervals.size() == 1);
    REQUIRE(s.answer.t_intervals.size() == 1);
    const RPoly ps(std::vector<Rational>{31, -144, 144}), pt(std::vector<Rational>{11, -64, 64});
    check_bracket(s.answer.s_intervals[0].first, ps, Rational(0), Rational(1, 2));  // 1/2 - sqrt(5)/12
    check_bracket(s.answer.s_intervals[0].second, ps, Rational(1, 2), Rational(1));
    check_bracket(s.answer.t_intervals[0].first, pt, Rational(0), Rational(1, 2));  // 1/2 - sqrt(5)/8
    check_bracket(s.answer.t_intervals[0].second, pt, Rational(1, 2), Rational(1));
  }
  {
    const Solution s = solve(read_scene(indep("spheres-end")), o);
    REQUIRE(s.answer.s_intervals.size() == 1);
    REQUIRE(s.answer.t_intervals.size() == 1);
    check_exact(s.answer.s_intervals[0].first, Rational(1, 3));
    check_exact(s.answer.s_intervals[0].second, Rational(2, 3));
    check_exact(s.answer.t_intervals[0].first, Rational(0));
    check_bracket(s.answer.t_intervals[0].second, RPoly(std::vector<Rational>{-1, 4, 16}), Rational(0),
                  Rational(1, 2));  // (sqrt(5) - 1)/8
  }
}

TEST_CASE(
    "exact and certified: a body turning in place (ball-turning, disc-turning) is answered on the static body's "
    "problem",
    "[independent]") {
  // A turns about its own fixed centre (an euler motion in 3D, a rational rotation in 2D): it does not move as a
  // set, so every s meets B alike (s-intervals [0, 1]) and the t-ends are the static ball's:
  // ball-turning 36 t^2 - 42 t + 11 = 0 ((7 -+ sqrt(5)) / 12), disc-turning 144 t^2 - 144 t + 31 = 0 (1/2 -+
  // sqrt(5)/12)
  const std::pair<const char*, RPoly> cases[] = {{"ball-turning", RPoly(std::vector<Rational>{11, -42, 36})},
                                                 {"disc-turning", RPoly(std::vector<Rational>{31, -144, 144})}};
  for (const auto& [name, p] : cases)
    for (const char* arith : {"exact", "certified"}) {
      INFO(name << ", " << arith);
      SolveOptions o;
      o.arith = parse_arithmetic(arith);
      const Solution s = solve(read_scene(indep(name)), o);
      for (const auto& r : s.undecided_reasons) UNSCOPED_INFO("reason: " << r);
      CHECK(s.certified);
      CHECK(s.answer.undecided.empty());
      CHECK(s.answer.collides);
      REQUIRE(s.answer.s_intervals.size() == 1);
      REQUIRE(s.answer.t_intervals.size() == 1);
      check_exact(s.answer.s_intervals[0].first, Rational(0));
      check_exact(s.answer.s_intervals[0].second, Rational(1));
      check_bracket(s.answer.t_intervals[0].first, p, Rational(1, 4), Rational(1, 2));
      check_bracket(s.answer.t_intervals[0].second, p, Rational(1, 2), Rational(1));
    }
}

TEST_CASE("double and MPFR: ellipsoids on parallel paths never meet", "[independent]") {
  for (const char* arith : {"double", "mpfr:128"}) {
    SolveOptions o;
    o.arith = parse_arithmetic(arith);
    const Solution s = solve(read_scene(indep("ellipsoids-apart")), o);
    CHECK_FALSE(s.answer.collides);
    CHECK(s.answer.undecided.empty());
    CHECK(s.answer.s_intervals.empty());
  }
}

TEST_CASE("independent scenes: certify and plot take them, the shared-parameter commands refuse them with exit 3",
          "[independent][cli]") {
  using namespace eccd::clitest;
  const std::string f = q(indep("spheres-end"));
  // (exact and certified solve them: tests/certified/test_independent_proof.cpp)
  // certify writes eccd-independent-certificate/3 (certificate/write/independent_certificate.hpp;
  // tests/certificate/test_independent_certificate.cpp)
  TempDir w;  // (an output is never a device: certify refuses --out /dev/null)
  Run cert = run_eccd("certify " + f + " --out " + q((w.path / "c.json").string()));
  CHECK(cert.code == 0);
  CHECK(cert.out.find("s_intervals") != std::string::npos);
  // plot draws an independent scene (issue 20 point 5): where A(s) meets B(t) in the (s, t) square
  const std::string png =
      (std::filesystem::temp_directory_path() / ("eccd-indep-plot-" + std::to_string(::getpid()) + ".png")).string();
  Run plot = run_eccd("plot " + f + " --output " + q(png));
  CHECK(plot.code == 0);
  CHECK(std::filesystem::file_size(png) > 1000);
  std::filesystem::remove(png);
  // the JSON of a double solve carries the independent answer's keys and no shared ones
  Run ok = run_eccd("solve " + q(indep("ellipsoids-apart")) + " --arith double --json");
  REQUIRE(ok.code == 0);
  const auto j = nlohmann::json::parse(ok.out);
  CHECK(j["parameters"] == "independent");
  CHECK(j["s_intervals"].is_array());
  CHECK_FALSE(j.contains("intervals"));
  CHECK_FALSE(j.contains("first_contact"));
}

// The bisection of an end in double: one point test may use a tenth of the run's box tests
// (IndependentOptions::point_share). On ball-turning one value of the bisection lies too close to t's end to be
// decided at any depth the point test tries; without the share it took 39 M of the run's 40 M box tests. The ends
// are (7 -+ sqrt(5)) / 12 (the scene's note: 36 t^2 - 42 t + 11 = 0), in both faces.
TEST_CASE("double: an end whose bisection meets an undecidable value stays located, within a share of the work",
          "[independent]") {
  const double r5 = std::sqrt(5.0);
  for (const char* guard : {"bound", "none"}) {
    INFO(guard);
    SolveOptions o;
    o.arith = parse_arithmetic("double");
    o.guard = parse_guard(guard);
    const Solution s = solve(read_scene(indep("ball-turning")), o);
    CHECK(s.answer.collides);
    CHECK(s.answer.undecided.empty());
    REQUIRE(s.answer.t_intervals.size() == 1);
    CHECK(std::abs(end(s.answer.t_intervals[0], 0) - (7 - r5) / 12) <= 1e-9);
    CHECK(std::abs(end(s.answer.t_intervals[0], 1) - (7 + r5) / 12) <= 1e-9);
    long tests = -1;
    for (const auto& [name, count] : s.work)
      if (name == "box_tests") tests = count;
    CHECK(tests > 0);
    CHECK(tests < 10000000);  // the whole bound is 40 M; the share is 4 M, the rest of the run about 1 M
  }
}

namespace {
// The ends of an answer's s- and t-intervals in order (s first), as doubles: a bracket's mid-point, else the value.
std::vector<double> ends_of(const Answer& a) {
  std::vector<double> v;
  auto at = [](const Instant& i) { return i.certified() ? nearest_double((*i.lo + *i.hi) / 2) : i.value; };
  for (const auto* ivs : {&a.s_intervals, &a.t_intervals})
    for (const auto& [lo, hi] : *ivs) {
      v.push_back(at(lo));
      v.push_back(at(hi));
    }
  return v;
}
long box_tests(const Solution& s) {
  for (const auto& [name, count] : s.work)
    if (name == "box_tests") return count;
  return -1;
}
}  // namespace

namespace {
// One floating run of `sc` (arithmetic `arith`, face `guard`) against the exact answer: nothing undecided, the same
// collides and number of s-intervals, every end within 1e-9 of the exact pipeline's (proved brackets, each
// narrower than 1e-9), at most 1 M box tests (a work count, not a time).
void check_ends_located(const char* name, const Scene& sc, const Solution& exact, const char* arith,
                        const char* guard) {
  INFO(name << ", " << arith << ", guard " << guard);
  SolveOptions o;
  o.arith = parse_arithmetic(arith);
  o.guard = parse_guard(guard);
  const Solution s = solve(sc, o);
  for (const auto& r : s.undecided_reasons) UNSCOPED_INFO("reason: " << r);
  CHECK(s.answer.undecided.empty());
  CHECK(s.answer.collides == exact.answer.collides);
  CHECK(s.answer.s_intervals.size() == exact.answer.s_intervals.size());
  const std::vector<double> want = ends_of(exact.answer), got = ends_of(s.answer);
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) CHECK(std::abs(got[i] - want[i]) <= 1e-9);
  CHECK(box_tests(s) >= 0);
  CHECK(box_tests(s) <= 1000000);
}
}  // namespace

// The floating runs locate every end of cases/independent at a bounded cost (floating/independent_ccd.hpp: the
// u-pieces of a t-piece at most u_lead deeper than it, the edges t = 0 and 1 tried alone): in double, both faces.
// The point tests near an end took up to 40 M box tests (the run's whole bound, one end then undecided on
// ellipses-turning) when each t-piece was searched in u down to the depth limit.
TEST_CASE("double, both faces: every scene of cases/independent within 1e-9 of the exact ends, at bounded work",
          "[independent][independent-ends]") {
  for (const char* name :
       {"ball-turning", "disc-turning", "discs-end", "ellipse-static", "ellipses-turning", "ellipsoid-static",
        "ellipsoids-apart", "ellipsoids-cross", "ellipsoids-turning", "spheres-cross", "spheres-end"}) {
    const Scene sc = read_scene(indep(name));
    const Solution exact = solve(sc, SolveOptions{});
    REQUIRE(exact.answer.undecided.empty());
    for (const char* guard : {"bound", "none"}) check_ends_located(name, sc, exact, "double", guard);
  }
}

// mpfr:128 on the scenes where it stopped at its work bound (2 M box tests) with ends undecided that double decided
// (spheres-cross 4, spheres-end 2, discs-end 1): both faces now locate every end as double does.
TEST_CASE("mpfr:128, both faces: every end of the sphere and disc scenes located within 1e-9 of the exact ends",
          "[independent][independent-ends]") {
  for (const char* name : {"spheres-cross", "spheres-end", "discs-end"}) {
    const Scene sc = read_scene(indep(name));
    const Solution exact = solve(sc, SolveOptions{});
    REQUIRE(exact.answer.undecided.empty());
    CHECK(exact.answer.collides);
    for (const char* guard : {"bound", "none"}) check_ends_located(name, sc, exact, "mpfr:128", guard);
  }
}

}  // namespace ECCD_UNITY_ID
