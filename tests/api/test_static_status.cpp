// The API's static tests (api/static_status.hpp): the double path (001 Appendix
// A in 3D, its 3x3 analogue in 2D, in Bounded<double>) against the exact path
// (world quadrics, the generic expansion of det(λA - B), exact Sturm /
// discriminant signs), which is the oracle: on random poses (printed seed;
// ECCD_TEST_SEED repeats a run) double must agree wherever it gives a status
// and say uncertain otherwise, never the wrong status; and the scene at an
// instant agrees with the exact pipeline's cells.
#include "api/solve.hpp"
#include "api/static_status.hpp"
#include "tests/support/arith.hpp"
#include "tests/support/poses.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using eccd::test::pose2;
using eccd::test::pose3;

const std::string kCases = std::string(ECCD_SOURCE_DIR) + "/cases/";

struct Tally {
  int decided = 0, uncertain = 0;
};

// double agrees with exact, or is uncertain.
template <class Shape>
Tally compare(const Shape& a, const Shape& b, Status& exact_out) {
  Status ex = static_status(a, b, Arithmetic::exact());
  Status db = static_status(a, b, Arithmetic::double_precision());
  exact_out = ex;
  REQUIRE(ex != Status::uncertain);  // exact always decides
  Tally t;
  if (db == Status::uncertain)
    ++t.uncertain;
  else {
    ++t.decided;
    CHECK(to_string(db) == std::string(to_string(ex)));
  }
  return t;
}

}  // namespace

TEST_CASE("static test from two poses in 2D: double agrees with exact or says uncertain, on random poses",
          "[api][static]") {
  std::uint64_t seed = test::seed_from_env(160016);
  INFO("seed " << seed << " (set ECCD_TEST_SEED to repeat)");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> axis(0.2, 3), ang(0, 6.3), pos(-4, 4);
  Tally all;
  int by_status[3] = {0, 0, 0};
  for (int trial = 0; trial < 3000; ++trial) {
    Ellipse a{{axis(rng), axis(rng)}, pose2(ang(rng), pos(rng), pos(rng))};
    Ellipse b{{axis(rng), axis(rng)}, pose2(ang(rng), pos(rng), pos(rng))};
    INFO("trial " << trial);
    Status ex;
    Tally t = compare(a, b, ex);
    all.decided += t.decided;
    all.uncertain += t.uncertain;
    if (ex != Status::touching) ++by_status[ex == Status::separate ? 0 : 1];
  }
  // Both outcomes occur, and generic poses are decided in double.
  CHECK(by_status[0] > 300);
  CHECK(by_status[1] > 300);
  CHECK(all.decided >= 2950);
}

TEST_CASE("static test from two poses in 3D: 001 Appendix A in double agrees with exact or says uncertain",
          "[api][static]") {
  std::uint64_t seed = test::seed_from_env(160017);
  INFO("seed " << seed << " (set ECCD_TEST_SEED to repeat)");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> axis(0.2, 3), u(-1, 1), pos(-4, 4);
  Tally all;
  int separate = 0, overlapping = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Ellipsoid a{{axis(rng), axis(rng), axis(rng)},
                pose3({u(rng), u(rng), u(rng), u(rng)}, pos(rng), pos(rng), pos(rng))};
    Ellipsoid b{{axis(rng), axis(rng), axis(rng)},
                pose3({u(rng), u(rng), u(rng), u(rng)}, pos(rng), pos(rng), pos(rng))};
    INFO("trial " << trial);
    Status ex;
    Tally t = compare(a, b, ex);
    all.decided += t.decided;
    all.uncertain += t.uncertain;
    separate += ex == Status::separate;
    overlapping += ex == Status::overlapping;
  }
  CHECK(separate > 200);
  CHECK(overlapping > 200);
  CHECK(all.decided >= 1950);
}

TEST_CASE(
    "static test near and at a touch: exact says touching at the tangent pose, double never gives the wrong status",
    "[api][static]") {
  // Axis-aligned shapes side by side along x: a's extreme point (a1, 0) meets
  // b's (-b1, 0) when the centres are a1 + b1 apart (both tangent to x = a1,
  // on opposite sides): touching; eps > 0 apart separate, eps < 0 overlapping.
  std::uint64_t seed = test::seed_from_env(160018);
  INFO("seed " << seed << " (set ECCD_TEST_SEED to repeat)");
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> quarter(1, 12);  // semi-axes k/4: sums are exact in double
  int uncertain_at_touch = 0, touches = 0;
  for (int trial = 0; trial < 200; ++trial) {
    double a1 = quarter(rng) / 4.0, a2 = quarter(rng) / 4.0, a3 = quarter(rng) / 4.0;
    double b1 = quarter(rng) / 4.0, b2 = quarter(rng) / 4.0, b3 = quarter(rng) / 4.0;
    for (double eps : {0.0, 1e-3, -1e-3, 0x1p-40, -0x1p-40}) {
      INFO("trial " << trial << ", eps " << eps);
      double d = a1 + b1 + eps;
      Status ex2, ex3;
      Tally t2 = compare(Ellipse{{a1, a2}, pose2(0, 0, 0)}, Ellipse{{b1, b2}, pose2(0, d, 0)}, ex2);
      Tally t3 = compare(Ellipsoid{{a1, a2, a3}, pose3({1, 0, 0, 0}, 0, 0, 0)},
                         Ellipsoid{{b1, b2, b3}, pose3({1, 0, 0, 0}, d, 0, 0)}, ex3);
      Status want = eps == 0 ? Status::touching : eps > 0 ? Status::separate : Status::overlapping;
      CHECK(to_string(ex2) == std::string(to_string(want)));
      CHECK(to_string(ex3) == std::string(to_string(want)));
      if (eps == 0) {
        touches += 2;
        uncertain_at_touch += t2.uncertain + t3.uncertain;
      }
    }
  }
  // A touch is a multiple root: double's bound cannot prove it (it never guesses).
  CHECK(uncertain_at_touch == touches);
}

TEST_CASE("static test from two poses: bad shapes and poses are refused with the reason", "[api][static]") {
  Ellipse ok{{1, 2}, pose2(0, 0, 0)};
  Ellipse flat{{0, 2}, pose2(0, 0, 0)};
  Ellipse singular{{1, 1}, {{{1, 2, 0}, {2, 4, 0}, {0, 0, 1}}}};
  Ellipse projective{{1, 1}, {{{1, 0, 0}, {0, 1, 0}, {0.5, 0, 1}}}};
  CHECK_THROWS_WITH(static_status(ok, flat), Catch::Contains("object b: semi-axis"));
  CHECK_THROWS_WITH(static_status(singular, ok), Catch::Contains("object a: the pose is singular"));
  CHECK_THROWS_WITH(static_status(ok, singular, Arithmetic::exact()),
                    Catch::Contains("object b: the pose is singular"));
  CHECK_THROWS_WITH(static_status(projective, ok), Catch::Contains("not affine"));
  CHECK_THROWS_AS(static_status(ok, ok, Arithmetic::mpfr(128)), std::invalid_argument);
}

TEST_CASE("status of a scene at an instant: exact equals the exact pipeline's cells, double agrees or is uncertain",
          "[api][static]") {
  for (const char* file : {"paper003/example2.json", "paper002/example.json", "spheres/spheres-crossing.json"}) {
    INFO(file);
    Scene s = read_scene(kCases + file);
    Solution r = solve(s);
    REQUIRE(r.cells.size() >= 2);
    int decided = 0;
    for (const auto& c : r.cells) {
      REQUIRE(c.sample.certified());
      REQUIRE(*c.sample.lo == *c.sample.hi);  // a cell's sample is a rational point
      mpq_class t = *c.sample.lo;
      INFO("t = " << t.get_str());
      CHECK(to_string(status_at(s, t)) == std::string(to_string(c.status)));
      Status d = status_at(s, t, Arithmetic::double_precision());
      if (d != Status::uncertain) {
        ++decided;
        CHECK(to_string(d) == std::string(to_string(c.status)));
      }
      Status m = status_at(s, t, Arithmetic::mpfr(256));
      if (m != Status::uncertain) CHECK(to_string(m) == std::string(to_string(c.status)));
    }
    // Two spheres: f has the positive double root 1 at every t (Δ ≡ 0), which
    // double's Sturm count cannot prove, so it says uncertain; the others decide.
    if (std::string(file).find("spheres") == std::string::npos) CHECK(decided > 0);
  }
  Scene s = read_scene(kCases + "paper003/example2.json");
  CHECK_THROWS_AS(status_at(s, mpq_class(3, 2)), std::invalid_argument);
}

}  // namespace ECCD_UNITY_ID
