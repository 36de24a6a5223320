// 3D continuous collision detection: the exact projection pipeline against
// paper 002's example, analytic sphere-sphere instants and an independent
// exact oracle; the Bézier pipeline (double, MPFR) against the exact answers.
#include "tests/support/scenes3d.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;

namespace {

double approx(const Instant& i) { return std::stod(i.approx); }

std::vector<std::string> cases_3d() {
  std::vector<std::string> out;
  for (const char* dir : {"paper002", "spheres", "touch3d"})
    for (auto& e : std::filesystem::directory_iterator(case_path(dir)))
      if (e.path().extension() == ".json") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Every instant of the exact answer is certified: a bracket of width <= 2^-64 (or exact).
void check_certified(const Answer& a) {
  const Rational w(1, mpz_class(1) << 64);
  for (const auto& [s, e] : a.intervals)
    for (const Instant* i : {&s, &e}) {
      REQUIRE(i->certified());
      CHECK(*i->lo <= *i->hi);
      CHECK(*i->hi - *i->lo <= w);
    }
}

}  // namespace

TEST_CASE("Paper 002's example: exactly two intervals, the first is the paper's [0.1699, 0.3465]", "[ccd3][exact]") {
  Scene s = read_scene_file(case_path("paper002/example.json"));
  auto r = solve_exact_3d(s);
  check_certified(r.answer);
  CHECK(r.projection_degree == 216);  // Disc of a quartic whose g_i have degree 36 (002 Table I: k_f = 36)
  REQUIRE(r.answer.collides);
  REQUIRE(r.answer.intervals.size() == 2);
  CHECK(std::fabs(approx(r.answer.intervals[0].first) - 0.1699) < 5e-5);
  CHECK(std::fabs(approx(r.answer.intervals[0].second) - 0.3465) < 5e-5);
  // The paper's second interval [0.7055, 0.8544] (IRIT, double) is too short:
  // the independent oracle finds the pair in collision just outside it, at
  // rational instants inside the exact interval [0.70471..., 0.85621...].
  for (const Rational& t : {Rational(7051, 10000), Rational(8550, 10000)}) {
    INFO("t = " << t.get_str());
    CHECK(negative_root_count_3d(s, t) == 0);  // no negative root: overlapping
    bool amb = false;
    CHECK(in_answer_set(r.answer, t, amb));
  }
  CHECK(negative_root_count_3d(s, Rational(7040, 10000)) == 2);  // separate just before the exact start
  CHECK(negative_root_count_3d(s, Rational(8570, 10000)) == 2);  // and just after the exact end
  // As printed (x²/5 + y²/8 + z²/10 = 1) the ellipsoids never meet on these paths.
  CHECK_FALSE(solve_exact_3d(read_scene_file(case_path("paper002/example-as-printed.json"))).answer.collides);
}

TEST_CASE("Sphere-sphere: the projection is psc_1 and the brackets hold the analytic instants", "[ccd3][exact]") {
  struct Case {
    const char* file;
    RPoly q;
    int roots;
  };
  // D(t) = |c_A - c_B|² - (r_A + r_B)², from each scene's note (cases/spheres/make_spheres.py)
  for (const Case& c : {Case{"spheres/spheres-crossing.json", rp({117, -1024, 1024}), 2},
                        Case{"spheres/spheres-overlap-start.json", rp({-7, 8, 16}), 1},
                        Case{"spheres/spheres-overlap-end.json", rp({17, -40, 16}), 1}}) {
    INFO(c.file);
    auto r = solve_exact_3d(read_scene_file(case_path(c.file)));
    CHECK(r.projection_identically_zero);  // Disc ≡ 0: λ = r_A²/r_B² is a double root for every t
    CHECK(r.projection_index >= 1);
    check_certified(r.answer);
    REQUIRE(r.answer.intervals.size() == 1);
    int found = 0;
    for (const Instant* i : {&r.answer.intervals[0].first, &r.answer.intervals[0].second}) {
      if (*i->lo == 0 || *i->hi == 1) continue;
      Rational a = c.q(*i->lo), b = c.q(*i->hi);
      CHECK(sgn(a) * sgn(b) <= 0);  // D changes sign over the bracket: it holds the analytic instant
      ++found;
    }
    CHECK(found == c.roots);
  }
  auto touch = solve_exact_3d(read_scene_file(case_path("spheres/spheres-touch.json")));
  REQUIRE(touch.answer.intervals.size() == 1);
  CHECK(*touch.answer.intervals[0].first.lo == Rational(1, 2));
  CHECK(*touch.answer.intervals[0].first.hi == Rational(1, 2));
  CHECK(touch.answer.contacts.size() == 1);
  CHECK_FALSE(solve_exact_3d(read_scene_file(case_path("spheres/spheres-free.json"))).answer.collides);
}

TEST_CASE("Touch and separate: exact reports the isolated touch at 1/2", "[ccd3][exact]") {
  for (const char* f : {"touch3d/touch-and-separate.json", "touch3d/touch-and-separate-rotated.json"}) {
    INFO(f);
    auto r = solve_exact_3d(read_scene_file(case_path(f)));
    REQUIRE(r.answer.intervals.size() == 1);
    CHECK(*r.answer.intervals[0].first.lo == Rational(1, 2));
    CHECK(*r.answer.intervals[0].second.hi == Rational(1, 2));
    REQUIRE(r.answer.contacts.size() == 1);
    // both neighbouring cells are separate: the touch was decided at the root itself
    for (const auto& c : r.cells) CHECK(c.status == Status::separate);
  }
}

TEST_CASE("Double Bézier gives the exact intervals to within 1e-6 on every 3D case", "[ccd3][bezier]") {
  double worst = 0;
  for (const auto& file : cases_3d()) {
    INFO(file);
    Scene s = read_scene_file(file);
    REQUIRE(s.answer.has_value());
    auto r = solve_bezier_3d<double>(s, 53, 1.0);
    CHECK(r.answer.undecided.empty());
    CHECK(r.answer.collides == s.answer->collides);
    REQUIRE(r.answer.intervals.size() == s.answer->intervals.size());
    for (std::size_t k = 0; k < r.answer.intervals.size(); ++k) {
      double d0 = std::fabs(approx(r.answer.intervals[k].first) - approx(s.answer->intervals[k].first));
      double d1 = std::fabs(approx(r.answer.intervals[k].second) - approx(s.answer->intervals[k].second));
      INFO("interval " << k << ": endpoint errors " << d0 << ", " << d1);
      CHECK(d0 <= 1e-6);
      CHECK(d1 <= 1e-6);
      worst = std::max({worst, d0, d1});
    }
  }
  WARN("double Bezier: largest endpoint error against the stored exact answers " << worst);
}

TEST_CASE("First-contact mode agrees with the first interval of the full answer in every arithmetic",
          "[ccd3][bezier][exact]") {
  for (const auto& file : cases_3d()) {
    INFO(file);
    Scene s = read_scene_file(file);
    auto check = [&](const Answer& full, const Answer& first, const char* arith) {
      INFO(arith);
      REQUIRE(full.collides == first.collides);
      if (!full.collides) return;
      REQUIRE(first.intervals.size() == 1);
      CHECK(first.intervals[0].first.approx == full.intervals[0].first.approx);
      CHECK(first.intervals[0].second.approx == full.intervals[0].second.approx);
      CHECK(first.first_contact->approx == full.first_contact->approx);
    };
    check(solve_exact_3d(s).answer, solve_exact_3d(s, true).answer, "exact");
    check(solve_bezier_3d<double>(s, 53, 1.0).answer, solve_bezier_3d<double>(s, 53, 1.0, true).answer, "double");
    Mpfr like(mpq_class(1), 128);
    check(solve_bezier_3d<Mpfr>(s, 128, like).answer, solve_bezier_3d<Mpfr>(s, 128, like, true).answer, "mpfr:128");
  }
}

TEST_CASE("Random 3D scenes of motion degree 2 and 4: the exact answer agrees with exact Sturm counts",
          "[ccd3][exact][random]") {
  const std::uint64_t seed = seed_from_env(20261121);
  std::mt19937_64 rng(seed);
  WARN("random 3D scenes: seed " << seed << " (set ECCD_TEST_SEED to change it)");
  int collided = 0, checked = 0, bezier_checked = 0;
  for (int k : {1, 1, 1, 1, 1, 1, 2, 2, 2}) {
    Scene s = random_euler_scene(rng, k);
    auto r = solve_exact_3d(s);
    check_certified(r.answer);
    collided += r.answer.collides;
    for (int i = 0; i <= 60; ++i) {
      Rational t(i, 60);
      t.canonicalize();
      bool amb = false;
      bool in = in_answer_set(r.answer, t, amb);
      if (amb) continue;  // t lies in an endpoint's bracket
      INFO("motion degree " << 2 * k << ", t = " << t.get_str());
      CHECK(in == (negative_root_count_3d(s, t) < 2));
      ++checked;
    }
    // The Bézier pipeline in double (001 section 4) may be inexact near an
    // event (the report measures by how much); it must never contradict the
    // exact answer where it claims one: at every instant it has decided (no
    // undecided part) and that lies more than 1e-6 from every interval end of
    // either answer, it says collision iff exact does.
    auto b = solve_bezier_3d<double>(s, 53, 1.0);
    if (!b.answer.undecided.empty()) continue;
    std::vector<double> ends;
    for (const Answer* a : {&b.answer, &r.answer})
      for (const auto& [x, y] : a->intervals) {
        ends.push_back(approx(x));
        ends.push_back(approx(y));
      }
    for (int i = 0; i <= 60; ++i) {
      const double t = i / 60.0;
      bool near = false;
      for (double e : ends) near = near || std::fabs(t - e) <= 1e-6;
      if (near) continue;
      bool in_exact = false, in_double = false;
      for (const auto& [x, y] : r.answer.intervals) in_exact = in_exact || (approx(x) <= t && t <= approx(y));
      for (const auto& [x, y] : b.answer.intervals) in_double = in_double || (approx(x) <= t && t <= approx(y));
      INFO("double Bezier at t = " << t << " (motion degree " << 2 * k << ")");
      CHECK(in_double == in_exact);
      ++bezier_checked;
    }
  }
  CHECK(checked > 400);
  CHECK(bezier_checked > 0);
  WARN("random 3D: " << collided << " of 9 collide; " << checked << " instants checked exactly, " << bezier_checked
                     << " against double Bezier");
}

}  // namespace ECCD_UNITY_ID
