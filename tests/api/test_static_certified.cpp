// The certified static test (issue 18 point 5, api/static_status.hpp): a
// filtered predicate, double with its error bound first and exact only where
// that is uncertain. It must give the exact status always — on random pairs
// (mostly decided by the double filter), on touching pairs (where the filter
// cannot decide: a touch is a double root) and near them — and, at a scene's
// instant, the exact pipeline's status (cells, constructed touch instants).
// Its cost next to the double test is measured in bench/eccd_bench.cpp.
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

const Arithmetic kCertified = Arithmetic::certified();

template <class Shape>
void same_as_exact(const Shape& a, const Shape& b, int& filtered) {
  Status ex = static_status(a, b, Arithmetic::exact());
  Status ce = static_status(a, b, kCertified);
  REQUIRE(ce != Status::uncertain);
  CHECK(std::string(to_string(ce)) == to_string(ex));
  filtered += static_status(a, b, Arithmetic::double_precision()) != Status::uncertain;
}

}  // namespace

TEST_CASE("certified static test from two poses equals the exact status on random pairs (2D and 3D)",
          "[api][static][certified]") {
  std::uint64_t seed = test::seed_from_env(180005);
  INFO("seed " << seed << " (set ECCD_TEST_SEED to repeat)");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> axis(0.2, 3), ang(0, 6.3), pos(-4, 4), q(-1, 1);
  int filtered2 = 0, filtered3 = 0;
  const int n = 1500;
  for (int trial = 0; trial < n; ++trial) {
    INFO("trial " << trial);
    same_as_exact(Ellipse{{axis(rng), axis(rng)}, pose2(ang(rng), pos(rng), pos(rng))},
                  Ellipse{{axis(rng), axis(rng)}, pose2(ang(rng), pos(rng), pos(rng))}, filtered2);
    same_as_exact(Ellipsoid{{axis(rng), axis(rng), axis(rng)},
                            pose3({q(rng), q(rng), q(rng), q(rng)}, pos(rng), pos(rng), pos(rng))},
                  Ellipsoid{{axis(rng), axis(rng), axis(rng)},
                            pose3({q(rng), q(rng), q(rng), q(rng)}, pos(rng), pos(rng), pos(rng))},
                  filtered3);
  }
  // The filter does its job: generic pairs are decided in double.
  CHECK(filtered2 > n * 95 / 100);
  CHECK(filtered3 > n * 95 / 100);
}

TEST_CASE("certified static test equals the exact status at and near touching poses, where double cannot decide",
          "[api][static][certified]") {
  // Axis-aligned shapes side by side along x, centres a1 + b1 + eps apart:
  // touching at eps = 0 (both tangent to x = a1), separate for eps > 0,
  // overlapping for eps < 0 (semi-axes k/4: the sums are exact in double).
  std::uint64_t seed = test::seed_from_env(180006);
  INFO("seed " << seed << " (set ECCD_TEST_SEED to repeat)");
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> quarter(1, 12);
  int filtered = 0, touches = 0;
  for (int trial = 0; trial < 150; ++trial) {
    double a1 = quarter(rng) / 4.0, a2 = quarter(rng) / 4.0, a3 = quarter(rng) / 4.0;
    double b1 = quarter(rng) / 4.0, b2 = quarter(rng) / 4.0, b3 = quarter(rng) / 4.0;
    for (double eps : {0.0, 1e-3, -1e-3, 0x1p-40, -0x1p-40}) {
      INFO("trial " << trial << ", eps " << eps);
      double d = a1 + b1 + eps;
      Status want = eps == 0 ? Status::touching : eps > 0 ? Status::separate : Status::overlapping;
      int f = 0;
      Ellipse ea{{a1, a2}, pose2(0, 0, 0)}, eb{{b1, b2}, pose2(0, d, 0)};
      Ellipsoid sa{{a1, a2, a3}, pose3({1, 0, 0, 0}, 0, 0, 0)}, sb{{b1, b2, b3}, pose3({1, 0, 0, 0}, d, 0, 0)};
      CHECK(std::string(to_string(static_status(ea, eb, kCertified))) == to_string(want));
      CHECK(std::string(to_string(static_status(sa, sb, kCertified))) == to_string(want));
      same_as_exact(ea, eb, f);
      same_as_exact(sa, sb, f);
      if (eps == 0) {
        touches += 2;
        filtered += f;
      }
    }
  }
  CHECK(touches == 300);
  CHECK(filtered == 0);  // every touch went to the exact test (the filter never claims a double root)
}

TEST_CASE("certified status of a scene at an instant equals the exact pipeline's, touches included",
          "[api][static][certified]") {
  for (const char* file : {"paper003/example2.json", "paper002/example.json", "spheres/spheres-crossing.json",
                           "touch3d/touch-and-separate.json"}) {
    INFO(file);
    Scene s = read_scene(kCases + file);
    Solution r = solve(s);
    for (const auto& c : r.cells) {
      mpq_class t = *c.sample.lo;
      INFO("t = " << t.get_str());
      CHECK(std::string(to_string(status_at(s, t, kCertified))) == to_string(c.status));
    }
    // The critical instants that are rational points (a constructed touch) and the ends.
    for (const auto& c : r.critical)
      if (c.t.lo && c.t.hi && *c.t.lo == *c.t.hi)
        CHECK(std::string(to_string(status_at(s, *c.t.lo, kCertified))) == to_string(status_at(s, *c.t.lo)));
    for (int end : {0, 1}) CHECK(std::string(to_string(status_at(s, end, kCertified))) == to_string(status_at(s, end)));
  }
  // touch-and-separate: the single external touch at exactly t = 1/2 (cases/touch3d/make_touch3d.py).
  Scene t = read_scene(kCases + "touch3d/touch-and-separate.json");
  CHECK(status_at(t, mpq_class(1, 2), kCertified) == Status::touching);
  CHECK(status_at(t, mpq_class(1, 4), kCertified) == Status::separate);
}

}  // namespace ECCD_UNITY_ID
