// The needle family (compare/needle_family.hpp): the scenes are checked
// against the construction in the header, by exact arithmetic on the scene
// the reader makes of each document (the exact pipeline's answers on them are
// checked in tests/floating/test_needle_guard.cpp).
//  - the plan is the header's grid: dims {2, 3} x R in {1e0, 1e5, 1e20,
//    1e50, 1e100, 1e200, 1e300} x {miss 1e-3, 1e-6, 1e-9, 1e-12, touch-end,
//    touch-mid}, 84 scenes with distinct names;
//  - the static object is the unit circle/sphere and the needle has semi-axes
//    (1, R[, 1]) (its quadric diag(1, 1/R², [1,] -1) up to a factor);
//  - the needle's centre stays on the x axis and x(t) is the header's
//    polynomial: for a miss x(1/2) = -(2 + 10^-k) exactly and x(t) <= x(1/2)
//    on [0, 1] (a concave parabola with its top at 1/2), so the gap |x| - 2 is
//    smallest at t0 = 1/2 and equal to 10^-k; touch-mid has x(1/2) = -2 and
//    touch-end x(1) = -2 with |x(t)| > 2 before; t0 and the spec's fields
//    (family, degree, motion, d_exponent) say the same;
//  - out-of-range specs are refused with std::invalid_argument.
#include "compare/needle_family.hpp"

#include "io/scene_reader.hpp"
#include "kernel/motion.hpp"

#include <catch2/catch.hpp>

#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
Rational at(long k) {  // k / 32, canonical (GMP's arithmetic needs canonical operands)
  Rational q(k, 32);
  q.canonicalize();
  return q;
}
Rational pow10(int e) {  // 10^e exactly
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, unsigned(e < 0 ? -e : e));
  return e < 0 ? Rational(1) / Rational(p) : Rational(p);
}
// The needle's motion matrix M(t) and its centre x(t) = M[0][dim] / M[dim][dim] at t.
struct Centre {
  RPoly x, y, z, w;
};
Centre centre_of(const Scene& s) {
  Centre c;
  if (s.dim == 2) {
    auto M = motion_matrix<Rational, 3>(s.b.motion, [](const Rational& q) { return q; });
    c = {M[0][2], M[1][2], RPoly(), M[2][2]};
  } else {
    auto M = motion_matrix<Rational, 4>(s.b.motion, [](const Rational& q) { return q; });
    c = {M[0][3], M[1][3], M[2][3], M[3][3]};
  }
  return c;
}
}  // namespace

TEST_CASE("needle family: the plan is the 84-scene grid of the header", "[compare][needle-family]") {
  const auto plan = needle_family_plan();
  CHECK(plan.size() == 2 * 7 * 6);
  std::set<std::string> names;
  std::set<std::tuple<int, int, std::string, int>> cells;
  for (const auto& sp : plan) {
    names.insert(needle_scene(sp).name);
    cells.insert({sp.dim, sp.r_exponent, sp.kind, sp.kind == "miss" ? sp.gap_exponent : 0});
  }
  CHECK(names.size() == plan.size());
  CHECK(cells.size() == plan.size());
  for (int dim : {2, 3})
    for (int r : {0, 5, 20, 50, 100, 200, 300}) {
      for (int g : {3, 6, 9, 12}) CHECK(cells.count({dim, r, "miss", g}) == 1);
      CHECK(cells.count({dim, r, "touch-end", 0}) == 1);
      CHECK(cells.count({dim, r, "touch-mid", 0}) == 1);
    }
}

TEST_CASE("needle family: shapes, centre path and t0 are the construction's, exactly", "[compare][needle-family]") {
  for (const auto& sp : needle_family_plan()) {
    const GeneratedScene g = needle_scene(sp);
    INFO(g.name);
    const Scene s = parse_scene(g.doc.dump(), g.name);
    REQUIRE(s.dim == sp.dim);
    CHECK(s.name == g.name);
    CHECK(g.spec.family == "needle");
    CHECK(g.spec.dim == sp.dim);
    CHECK(g.spec.motion == (sp.dim == 3 ? "euler" : "matrix"));
    CHECK(std::holds_alternative<StaticMotion>(s.a.motion));
    // A: the unit circle/sphere, Q = c diag(1, ..., 1, -1).
    const int d = sp.dim;
    for (int i = 0; i < d; ++i) CHECK(s.a.Q[i][i] == -s.a.Q[d][d]);
    // B: semi-axes (1, R[, 1]): Q_yy R^2 = Q_xx = -Q_ww (and Q_zz = Q_xx in 3D).
    const Rational R = pow10(sp.r_exponent);
    CHECK(s.b.Q[0][0] == -s.b.Q[d][d]);
    CHECK(s.b.Q[1][1] * R * R == s.b.Q[0][0]);
    if (d == 3) CHECK(s.b.Q[2][2] == s.b.Q[0][0]);
    // The centre moves along the x axis: y = z = 0, weight constant.
    const Centre c = centre_of(s);
    CHECK(c.y.is_zero());
    CHECK(c.z.is_zero());
    REQUIRE(c.w.degree() == 0);
    const Rational w = c.w(Rational(0));
    auto x = [&](const Rational& t) -> Rational { return c.x(t) / w; };  // a value, not a gmpxx expression
    REQUIRE(g.t0.has_value());
    if (sp.kind == "miss") {
      const Rational gap = pow10(-sp.gap_exponent);
      CHECK(g.spec.degree == 2);
      CHECK(g.spec.d_exponent == sp.gap_exponent);
      CHECK(*g.t0 == Rational(1, 2));
      CHECK(x(Rational(1, 2)) == -(2 + gap));  // closest: the gap is 10^-k
      for (long k = 0; k <= 32; ++k) CHECK(x(at(k)) <= x(Rational(1, 2)));
      CHECK(c.x.degree() == 2);
      CHECK(c.x.c[2] < 0);  // concave: its top is the only maximum
    } else if (sp.kind == "touch-mid") {
      CHECK(g.spec.degree == 2);
      CHECK(*g.t0 == Rational(1, 2));
      CHECK(x(Rational(1, 2)) == -2);
      for (long k = 0; k <= 32; ++k)
        if (k != 16) CHECK(x(at(k)) < -2);
    } else {
      CHECK(sp.kind == "touch-end");
      CHECK(g.spec.degree == 1);
      CHECK(*g.t0 == 1);
      CHECK(x(Rational(1)) == -2);
      CHECK(x(Rational(0)) == -3);
      for (long k = 0; k < 32; ++k) CHECK(x(at(k)) < -2);
    }
  }
}

TEST_CASE("needle family: specs out of range are refused", "[compare][needle-family]") {
  auto refused = [](NeedleSpec sp, const std::string& words) {
    try {
      needle_scene(sp);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).find(words) != std::string::npos;
    }
    return false;
  };
  CHECK(refused({4, 20, "miss", 3}, "dim must be 2 or 3"));
  CHECK(refused({1, 20, "miss", 3}, "dim must be 2 or 3"));
  CHECK(refused({3, -1, "miss", 3}, "0 <= k <= 300"));
  CHECK(refused({2, 301, "touch-end", 0}, "0 <= k <= 300"));
  CHECK(refused({3, 20, "miss", 0}, "k >= 1"));
  CHECK(refused({3, 20, "graze", 3}, "unknown kind 'graze'"));
  // The bounds themselves are accepted; a touch ignores the gap.
  CHECK_NOTHROW(needle_scene({2, 0, "miss", 1}));
  CHECK_NOTHROW(needle_scene({3, 300, "touch-mid", 0}));
  CHECK_NOTHROW(needle_scene({3, 300, "touch-end", -5}));
  // A gap of 10^-1: the scene's x(0) is written "-3.1".
  const Scene s = parse_scene(needle_scene({2, 0, "miss", 1}).doc.dump(), "n");
  const Centre c = centre_of(s);
  CHECK(c.x(Rational(1, 2)) / c.w(Rational(0)) == Rational(-21, 10));
}

}  // namespace ECCD_UNITY_ID
