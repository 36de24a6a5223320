// The Gaussian-circle test on doubles (floating/gauss_cone.hpp; paper 001
// section 4): cross_sign, same_way and pointed against exact rational
// arithmetic (every double is a rational, so mpq_class decides exactly).
// tests/floating/test_bezier_ccd.cpp compares pointed with an angle-based
// definition on unit-sized random directions; this file checks the claim of
// exactness at the edges of the double range:
//   - cross_sign(a, b, c, d) is the exact sign of a·d − b·c, on random
//     doubles and on constructed near-ties (d = fl(b·c / a) and its
//     neighbours), where the two products round to the same double;
//   - same_way is "positive multiple" for collinear vectors (signed zeros);
//   - pointed is the exact answer "0 is not in the convex hull" (the
//     separation theorem: a finite set of non-zero vectors lies in an open
//     half-plane through 0 iff 0 is not in its convex hull, decided with
//     Carathéodory's three points and exact cross products), for directions
//     at every scale pointed() rescales (2^±600, subnormal) and near-opposite
//     pairs, and it does not depend on the order of the points;
//   - a product that underflows: two points whose coordinates differ by
//     2^-500 in size (cross_sign then takes the exact rational sign).
#include "compare/seeded_rng.hpp"
#include "floating/gauss_cone.hpp"

#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using bezier_detail::cross_sign;
using bezier_detail::pointed;
using bezier_detail::same_way;
using Pts = std::vector<std::pair<double, double>>;

namespace {

int exact_cross(double a, double b, double c, double d) {
  const mpq_class v = mpq_class(a) * mpq_class(d) - mpq_class(b) * mpq_class(c);
  return sgn(v);
}

// 0 in the closed convex hull of the points, exactly (Carathéodory: at most three of them).
bool zero_in_hull(const Pts& p) {
  const std::size_t n = p.size();
  auto cr = [&](std::size_t i, std::size_t j) { return exact_cross(p[i].first, p[i].second, p[j].first, p[j].second); };
  auto dot = [&](std::size_t i, std::size_t j) {
    return sgn(mpq_class(p[i].first) * p[j].first + mpq_class(p[i].second) * p[j].second);
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (p[i].first == 0 && p[i].second == 0) return true;
    for (std::size_t j = i + 1; j < n; ++j) {
      if (cr(i, j) == 0 && dot(i, j) < 0) return true;  // opposite: 0 on the segment
      for (std::size_t k = j + 1; k < n; ++k) {
        const int s1 = cr(i, j), s2 = cr(j, k), s3 = cr(k, i);
        if (s1 == 0 && s2 == 0 && s3 == 0) continue;  // all on a line through 0: the pairs decide
        if ((s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0)) return true;
      }
    }
  }
  return false;
}

double random_double(SeededRng& rng, int emin, int emax) {
  const double m = 1 + double(rng.next() >> 11) * 0x1p-53;  // [1, 2)
  const double x = std::ldexp(m, int(rng.uniform(emin, emax)));
  return rng.next() & 1 ? -x : x;
}

}  // namespace

TEST_CASE("cross_sign is the exact sign of ad - bc, near ties included", "[floating][gauss_cone]") {
  SeededRng rng{1234};
  long ties = 0;
  for (int k = 0; k < 20000; ++k) {
    const double a = random_double(rng, -60, 60), b = random_double(rng, -60, 60), c = random_double(rng, -60, 60);
    double d = random_double(rng, -60, 60);
    if (k % 2 == 0) {  // near a tie: d about b c / a, and a few neighbours
      d = b * c / a;
      for (int s = int(rng.uniform(-2, 2)); s != 0; s += s > 0 ? -1 : 1)
        d = std::nextafter(d, s > 0 ? INFINITY : -INFINITY);
    }
    ties += a * d == b * c;
    INFO(a << " " << b << " " << c << " " << d);
    REQUIRE(cross_sign(a, b, c, d) == exact_cross(a, b, c, d));
  }
  CHECK(ties > 1000);  // the fma branch is exercised
  CHECK(cross_sign(0.1, 0.7, 0.1, 0.7) == 0);
  CHECK(cross_sign(3, 1, 6, 2) == 0);
  CHECK(cross_sign(-0.0, 0.0, 0.0, -0.0) == 0);
}

TEST_CASE("same_way tells a positive multiple from a negative one", "[floating][gauss_cone]") {
  CHECK(same_way(1, 2, 3, 6));
  CHECK_FALSE(same_way(1, 2, -3, -6));
  CHECK(same_way(-1, 0.0, -5, -0.0));  // signed zeros are the same zero
  CHECK_FALSE(same_way(0.0, 1, 0.0, -1));
  CHECK_FALSE(same_way(1, 0, -1, 0));
}

TEST_CASE("pointed is the exact half-plane test at every scale and in every order", "[floating][gauss_cone]") {
  SeededRng rng{5678};
  long yes = 0, total = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Pts p;
    const int n = int(rng.uniform(1, 7));
    // the scale of this set's points: the plain range, beyond 2^400 or below 2^-400 (rescaled), subnormal
    const int scale = std::array<int, 5>{0, 600, -600, -1060, 900}[trial % 5];
    // directions in a cone of random width around a random axis, so that both answers occur
    const double axis = double(rng.uniform(0, 6283)) / 1000, width = double(rng.uniform(1, 4000)) / 1000;
    for (int k = 0; k < n; ++k) {
      const double t = axis + width * (double(rng.uniform(-1000, 1000)) / 1000);
      const double r = std::ldexp(1 + double(rng.uniform(0, 1000)) / 100, scale + int(rng.uniform(-3, 3)));
      p.push_back({r * std::cos(t), r * std::sin(t)});
    }
    if (trial % 7 == 0) p.push_back({-p[0].first, -p[0].second});  // an exactly opposite pair
    if (trial % 11 == 0)                                           // a nearly opposite one
      p.push_back({-p[0].first, std::nextafter(-p[0].second, INFINITY)});
    bool zero = false;
    for (auto [x, y] : p) zero = zero || (x == 0 && y == 0);
    if (zero) continue;  // subnormal cos/sin can round to 0: a zero point is not this test's subject
    const bool want = !zero_in_hull(p);
    INFO("trial " << trial << ", scale 2^" << scale << ", " << p.size() << " points");
    CHECK(pointed(p) == want);
    std::reverse(p.begin(), p.end());
    CHECK(pointed(p) == want);
    std::rotate(p.begin(), p.begin() + (p.size() / 2), p.end());
    CHECK(pointed(p) == want);
    yes += want;
    ++total;
  }
  CHECK(yes > total / 5);
  CHECK(yes < total - total / 5);
  // the largest and smallest doubles: rescaled, not overflowing
  const double big = 0x1.fffffffffffffp1023, tiny = 0x1p-1074;
  CHECK(pointed(Pts{{big, big}, {big, -big}}));
  CHECK_FALSE(pointed(Pts{{big, big}, {-big, -big}}));
  CHECK(pointed(Pts{{tiny, 0}, {tiny, tiny}}));
  CHECK_FALSE(pointed(Pts{{tiny, tiny}, {-tiny, -tiny}}));
  CHECK(pointed(Pts{{big, 1}, {tiny, tiny}}));  // both in the first quadrant
}

// pointed() rescales a point only when a coordinate lies outside [2^-400, 2^400]; within that range a
// point may still pair a coordinate near 2^-300 with one near 2^-800, and a cross product of two such
// points underflows (2^-1101 is below the smallest subnormal), so cross_sign reads 0 where the exact
// sign is not. Here lo = (2^-300, 2^-800) and p = (2^-300, 2^-801) (p clockwise of lo by about
// 2^-501 rad) are taken as collinear, p is dropped, and r = (-1, -3·2^-502), which is less than π
// counter-clockwise of lo but more than π from p, is accepted: pointed answers true although the
// three directions leave no gap wider than π (the exact test below). The answer "true" is the one the
// caller trusts (no loop in the zero set): cross_sign takes such a product's sign exactly, and pointed says false.
TEST_CASE("pointed with a cross product that underflows", "[floating][gauss_cone]") {
  const Pts p{{0x1p-300, 0x1p-800}, {0x1p-300, 0x1p-801}, {-1, -3 * 0x1p-502}};
  REQUIRE(zero_in_hull(p));  // exactly: no open half-plane holds the three
  CHECK(exact_cross(0x1p-300, 0x1p-800, 0x1p-300, 0x1p-801) == -1);
  CHECK_FALSE(pointed(p));
}

}  // namespace ECCD_UNITY_ID
