// The Gaussian-circle test of the Bézier zero-set analysis (floating/bezier_ccd.hpp,
// 001 section 4, case 3): bezier_detail::pointed decides "all points in one
// open half-plane through the origin" without sorting; it must agree to the
// last bit with its definition, max gap between the sorted angles > π.
#include "number/double_traits.hpp"
#include "floating/bezier_ccd.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

using namespace eccd;
using Pts = std::vector<std::pair<double, double>>;

namespace {
bool by_definition(const Pts& pts) {
  if (pts.empty()) return true;
  std::vector<double> ang;
  for (auto [x, y] : pts) {
    if (x == 0 && y == 0) return false;
    ang.push_back(std::atan2(y, x));
  }
  return bezier_detail::max_angle_gap(ang) > M_PI;
}
}  // namespace

TEST_CASE("Gaussian-circle test without a sort decides as the sorted angles do", "[kernel][bezier][gauss]") {
  std::uint64_t seed = test::seed_from_env(1789);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  std::uniform_real_distribution<double> ud(-M_PI, M_PI);
  int agree = 0, yes = 0, total = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Pts pts;
    int n = 1 + trial % 40;
    double centre = ud(rng), spread = (trial % 7 + 1) * 0.5;  // from a narrow cone to the whole circle
    for (int k = 0; k < n; ++k) {
      double a = centre + spread * (std::uniform_real_distribution<double>(-1, 1)(rng));
      double r = std::exp(nd(rng));
      pts.push_back({r * std::cos(a), r * std::sin(a)});
    }
    // the awkward directions: on the axes, +0 / -0, the cut at ±π, exactly opposite points
    if (trial % 5 == 0) pts.push_back({1.0, 0.0});
    if (trial % 11 == 0) pts.push_back({-1.0, 0.0});
    if (trial % 13 == 0) pts.push_back({-1.0, -0.0});
    if (trial % 17 == 0) pts.push_back({0.0, trial % 2 ? 1.0 : -1.0});
    if (trial % 19 == 0) pts.push_back({-pts[0].first, -pts[0].second});
    if (trial % 97 == 0) pts.push_back({0.0, 0.0});
    bool fast = bezier_detail::pointed(pts), def = by_definition(pts);
    INFO("trial " << trial << ", " << pts.size() << " points");
    CHECK(fast == def);
    agree += fast == def;
    yes += def;
    ++total;
  }
  CHECK(agree == total);
  CHECK(yes > total / 10);        // both answers occur often
  CHECK(yes < total - total / 10);
  // fixed cases
  CHECK(bezier_detail::pointed(Pts{}));
  CHECK(bezier_detail::pointed(Pts{{1, 0}}));
  CHECK_FALSE(bezier_detail::pointed(Pts{{1, 0}, {-1, 0}}));        // opposite: no open half-plane
  CHECK(bezier_detail::pointed(Pts{{1, 1}, {1, -1}, {2, 0.5}}));
  CHECK_FALSE(bezier_detail::pointed(Pts{{1, 0}, {-1, 1}, {-1, -1}}));
  CHECK_FALSE(bezier_detail::pointed(Pts{{1, 0}, {0, 0}}));
  CHECK(bezier_detail::pointed(Pts{{-1, 0.0}, {-1, -0.0}, {-1, 0.5}}));  // around the cut at ±π
  CHECK(bezier_detail::pointed(Pts{{-1, 0.0}, {-1, -0.0}}) == by_definition(Pts{{-1, 0.0}, {-1, -0.0}}));
  CHECK(bezier_detail::pointed(Pts{{NAN, 1}, {1, 1}}) == by_definition(Pts{{NAN, 1}, {1, 1}}));
}
