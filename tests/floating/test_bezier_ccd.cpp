// The Gaussian-circle test of the Bézier zero-set analysis (floating/bezier_ccd.hpp,
// 001 section 4, case 3): bezier_detail::pointed decides "all points in one
// open half-plane through the origin" by signs of cross products. It must
// agree with the definition evaluated in exact rational arithmetic on the
// same doubles: some point p_i has every other point strictly to its left or
// on its own ray (cross(p_i, p_j) > 0, or = 0 with dot > 0), and no point is 0.
// Where the angles (atan2) are clear of the boundary (largest gap between the
// sorted angles further than 1e-9 from π) the old angle test must agree too.
#include "number/double_traits.hpp"
#include "floating/bezier_ccd.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using Pts = std::vector<std::pair<double, double>>;

namespace {
bool by_definition(const Pts& pts) {
  std::vector<std::pair<mpq_class, mpq_class>> q;
  for (auto [x, y] : pts) {
    if (!std::isfinite(x) || !std::isfinite(y) || (x == 0 && y == 0)) return false;
    q.push_back({mpq_class(x), mpq_class(y)});
  }
  if (q.empty()) return true;
  for (std::size_t i = 0; i < q.size(); ++i) {
    bool all = true;
    for (std::size_t j = 0; j < q.size() && all; ++j) {
      const mpq_class c = q[i].first * q[j].second - q[i].second * q[j].first;
      all = sgn(c) > 0 || (sgn(c) == 0 && sgn(q[i].first * q[j].first + q[i].second * q[j].second) > 0);
    }
    if (all) return true;
  }
  return false;
}

// The largest cyclic gap between the sorted angles (the points lie in an open
// half-plane iff it exceeds π): the angle test the cross products replaced.
double max_angle_gap(const Pts& pts) {
  std::vector<double> ang;
  for (auto [x, y] : pts) ang.push_back(std::atan2(y, x));
  std::sort(ang.begin(), ang.end());
  double gap = ang.front() + 2 * M_PI - ang.back();
  for (std::size_t i = 1; i < ang.size(); ++i) gap = std::max(gap, ang[i] - ang[i - 1]);
  return gap;
}
}  // namespace

TEST_CASE("Gaussian-circle test by cross-product signs decides exactly", "[kernel][bezier][gauss]") {
  std::uint64_t seed = test::seed_from_env(1789);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  std::uniform_real_distribution<double> ud(-M_PI, M_PI);
  int agree = 0, yes = 0, total = 0, clear_of_boundary = 0;
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
    bool has_zero = false;
    for (auto [x, y] : pts) has_zero = has_zero || (x == 0 && y == 0);
    if (!has_zero) {
      const double gap = max_angle_gap(pts);
      if (std::fabs(gap - M_PI) > 1e-9) {
        CHECK(fast == (gap > M_PI));
        ++clear_of_boundary;
      }
    }
    agree += fast == def;
    yes += def;
    ++total;
  }
  CHECK(agree == total);
  CHECK(yes > total / 10);  // both answers occur often
  CHECK(yes < total - total / 10);
  CHECK(clear_of_boundary > total / 2);
  // fixed cases
  CHECK(bezier_detail::pointed(Pts{}));
  CHECK(bezier_detail::pointed(Pts{{1, 0}}));
  CHECK_FALSE(bezier_detail::pointed(Pts{{1, 0}, {-1, 0}}));  // opposite: no open half-plane
  CHECK(bezier_detail::pointed(Pts{{1, 1}, {1, -1}, {2, 0.5}}));
  CHECK_FALSE(bezier_detail::pointed(Pts{{1, 0}, {-1, 1}, {-1, -1}}));
  CHECK_FALSE(bezier_detail::pointed(Pts{{1, 0}, {0, 0}}));
  CHECK(bezier_detail::pointed(Pts{{-1, 0.0}, {-1, -0.0}, {-1, 0.5}}));  // around the cut at ±π
  CHECK(bezier_detail::pointed(Pts{{-1, 0.0}, {-1, -0.0}}));             // one direction (signed zeros)
  CHECK_FALSE(bezier_detail::pointed(Pts{{NAN, 1}, {1, 1}}));            // not shown loop-free: the caller subdivides
  CHECK_FALSE(bezier_detail::pointed(Pts{{INFINITY, 1}, {1, 1}}));
  // exactly opposite points whose products round: the fma term decides
  CHECK_FALSE(bezier_detail::pointed(Pts{{0.1, 0.7}, {-0.1, -0.7}}));
  CHECK_FALSE(bezier_detail::pointed(Pts{{1, 1}, {0.1, 0.7}, {-0.1, -0.7}}));
  // a cone just under π, and the same cone closed to exactly π (points on one line through 0)
  CHECK(bezier_detail::pointed(Pts{{1, 1e-300}, {-1, 1e-300}, {0, 1}}));
  CHECK_FALSE(bezier_detail::pointed(Pts{{1, 0}, {-1, 0}, {0, 1}}));
  // points outside 2^±400 are scaled by powers of two: directions kept exactly
  CHECK(bezier_detail::pointed(Pts{{1e300, 1e299}, {-1e300, 1e299}, {1e-300, 1e300}}));
  CHECK_FALSE(bezier_detail::pointed(
      Pts{{std::ldexp(3.0, 900), std::ldexp(7.0, 900)}, {std::ldexp(-3.0, -900), std::ldexp(-7.0, -900)}}));
  const Pts near_opposite{{3e300, 7e300}, {-3e-300, -7e-300}};
  CHECK(bezier_detail::pointed(near_opposite) == by_definition(near_opposite));
}

}  // namespace ECCD_UNITY_ID
