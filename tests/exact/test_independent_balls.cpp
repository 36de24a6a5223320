// Exact answers of independent motions for two balls (discs) on straight
// paths (exact/independent_balls.hpp; paper 001 section 4).
//   - ball_path accepts exactly the shapes diag(k, .., k, -m) with m / k a
//     rational square (radius √(m / k)) under a static motion or a matrix
//     motion [[c I, p(s)], [0, c]] with deg p <= 1 (centre p / c), in 3D and
//     2D, and refuses ellipsoids, off-diagonal terms, irrational radii, a
//     turning or scaling linear block and quadratic paths;
//   - ball_projection: P_s for A on a line against B on a segment, computed
//     here from first principles: A(s) meets B's path iff the distance from
//     A's centre to the segment the centre of B sweeps is at most
//     R = r_A + r_B (the distance to a segment: the nearest point, clamped,
//     in exact rationals). Known ends: rational (1/6, 5/6), irrational
//     ((3 ± √3)/6, located by exact signs of (6s - 3)^2 - 3), a single
//     touching instant (P_s = {1/2}), the whole [0, 1], the empty set, a
//     static B; every end is a certified bracket holding the exact end;
//   - a meets_at that contradicts the exact distance is an internal error.
#include "exact/independent_balls.hpp"

#include <catch2/catch.hpp>

#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

RPoly lin(const Rational& a, const Rational& b) { return RPoly(std::vector<Rational>{a, b}); }

SceneObject ball3(const Rational& k, const Rational& m) {
  SceneObject o;
  o.Q = {{k, 0, 0, 0}, {0, k, 0, 0}, {0, 0, k, 0}, {0, 0, 0, -m}};
  o.motion = StaticMotion{};
  return o;
}

// [[c I, p(s)], [0, c]] with p = c0 + s d (times c), 3D
MatrixMotion translation3(const Rational& c, const std::array<Rational, 3>& c0, const std::array<Rational, 3>& d) {
  MatrixMotion m;
  m.m.assign(4, std::vector<RPoly>(4));
  for (int i = 0; i < 3; ++i) {
    m.m[i][i] = RPoly::constant(c);
    m.m[i][3] = lin(c * c0[i], c * d[i]);
  }
  m.m[3][3] = RPoly::constant(c);
  return m;
}

// A's centre a + s dA, B's centre b + t dB (t in [0, 1]): does A(s) meet some B(t)?
bool meets(const BallPath& A, const BallPath& B, const Rational& s) {
  std::array<Rational, 3> p, q0, q1;
  for (int i = 0; i < 3; ++i) {
    p[i] = A.c0[i] + s * A.d[i];
    q0[i] = B.c0[i];
    q1[i] = B.c0[i] + B.d[i];
  }
  // nearest point of the segment [q0, q1] to p: q0 + t (q1 - q0), t = clamp(((p - q0).(q1 - q0)) / |q1 - q0|^2)
  Rational num = 0, den = 0;
  for (int i = 0; i < 3; ++i) {
    num += (p[i] - q0[i]) * (q1[i] - q0[i]);
    den += (q1[i] - q0[i]) * (q1[i] - q0[i]);
  }
  Rational t = den == 0 ? Rational(0) : Rational(num / den);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  Rational d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const Rational e = p[i] - (q0[i] + t * (q1[i] - q0[i]));
    d2 += e * e;
  }
  const Rational R = A.radius + B.radius;
  return d2 <= R * R;
}

BallPath path(const Rational& r, std::array<Rational, 3> c0, std::array<Rational, 3> d) {
  BallPath b;
  b.radius = r;
  b.c0 = c0;
  b.d = d;
  return b;
}

using Intervals = std::vector<std::pair<Instant, Instant>>;

Intervals project(const BallPath& A, const BallPath& B) {
  return ball_projection(A, B, [&](const Rational& s) { return meets(A, B, s); });
}

// The exact end e lies in the instant's certified bracket; below(x) tells x < e (and x = e never
// happens for an irrational e; for a rational e, `at` names it).
template <class Below>
void check_end(const Instant& x, Below below, std::optional<Rational> at = std::nullopt) {
  REQUIRE(x.certified());
  INFO("bracket [" << *x.lo << ", " << *x.hi << "]");
  CHECK(*x.lo <= *x.hi);
  CHECK((below(*x.lo) || (at && *x.lo == *at)));  // lo <= e
  CHECK(!below(*x.hi));                           // hi >= e
}
void check_end_at(const Instant& x, const Rational& e) {
  check_end(
      x, [&](const Rational& y) { return y < e; }, e);
}

}  // namespace

TEST_CASE("ball_path reads balls and discs on straight paths and refuses the rest", "[exact][independent_balls]") {
  // diag(4, 4, 4, -9): radius 3/2, static
  auto b = ball_path(ball3(4, 9));
  REQUIRE(b);
  CHECK(b->radius == Rational(3, 2));
  for (int i = 0; i < 3; ++i) CHECK((b->c0[i] == 0 && b->d[i] == 0));
  // a matrix motion with c = 2: centre (1, -1/2, 3) + s (2, 0, -1/4)
  SceneObject o = ball3(1, Rational(1, 9));
  o.motion = translation3(2, {1, Rational(-1, 2), 3}, {2, 0, Rational(-1, 4)});
  b = ball_path(o);
  REQUIRE(b);
  CHECK(b->radius == Rational(1, 3));
  CHECK(b->c0 == std::array<Rational, 3>{1, Rational(-1, 2), 3});
  CHECK(b->d == std::array<Rational, 3>{2, 0, Rational(-1, 4)});
  // a disc: diag(1, 1, -25/4), radius 5/2; its centre's z stays 0
  SceneObject disc;
  disc.Q = {{1, 0, 0}, {0, 1, 0}, {0, 0, Rational(-25, 4)}};
  disc.motion = StaticMotion{};
  b = ball_path(disc);
  REQUIRE(b);
  CHECK(b->radius == Rational(5, 2));
  MatrixMotion dm;
  dm.m.assign(3, std::vector<RPoly>(3));
  dm.m[0][0] = dm.m[1][1] = dm.m[2][2] = RPoly::constant(Rational(1));
  dm.m[0][2] = lin(-1, 2);
  dm.m[1][2] = lin(Rational(1, 2), 0);
  disc.motion = dm;
  b = ball_path(disc);
  REQUIRE(b);
  CHECK(b->c0 == std::array<Rational, 3>{-1, Rational(1, 2), 0});
  CHECK(b->d == std::array<Rational, 3>{2, 0, 0});

  CHECK_FALSE(ball_path(ball3(1, 2)));  // radius √2: not rational
  SceneObject e = ball3(1, 1);
  e.Q[1][1] = 2;  // an ellipsoid
  CHECK_FALSE(ball_path(e));
  e = ball3(1, 1);
  e.Q[0][1] = e.Q[1][0] = Rational(1, 10);  // off-diagonal
  CHECK_FALSE(ball_path(e));
  CHECK_FALSE(ball_path(ball3(-1, -1)));  // not a solid ball
  e = ball3(1, 1);
  MatrixMotion turn = translation3(1, {0, 0, 0}, {1, 0, 0});
  turn.m[0][1] = RPoly::constant(Rational(1, 2));  // the linear block is not c I
  e.motion = turn;
  CHECK_FALSE(ball_path(e));
  MatrixMotion quad = translation3(1, {0, 0, 0}, {1, 0, 0});
  quad.m[0][3] = RPoly(std::vector<Rational>{0, 0, 1});  // a parabolic path
  e.motion = quad;
  CHECK_FALSE(ball_path(e));
  MatrixMotion grow = translation3(1, {0, 0, 0}, {1, 0, 0});
  grow.m[3][3] = lin(1, 1);  // c not constant
  e.motion = grow;
  CHECK_FALSE(ball_path(e));
}

TEST_CASE("ball_projection: rational and irrational ends of P_s", "[exact][independent_balls]") {
  // B sweeps the segment y = z = 0, x in [-5, 5]; radii 1 + 1 = 2
  const BallPath B = path(1, {-5, 0, 0}, {10, 0, 0});
  {  // A crosses the segment at x = 0: |y| = |6s - 3| <= 2 iff s in [1/6, 5/6]
    const BallPath A = path(1, {0, -3, 0}, {0, 6, 0});
    const Intervals out = project(A, B);
    REQUIRE(out.size() == 1);
    check_end_at(out[0].first, Rational(1, 6));
    check_end_at(out[0].second, Rational(5, 6));
  }
  {  // A passes beyond the end x = 5 at x = 6: 1 + (6s - 3)^2 <= 4 iff s in [(3 - √3)/6, (3 + √3)/6]
    const BallPath A = path(1, {6, -3, 0}, {0, 6, 0});
    const Intervals out = project(A, B);
    REQUIRE(out.size() == 1);
    auto q = [](const Rational& s) -> Rational { return (6 * s - 3) * (6 * s - 3) - 3; };  // > 0 outside the two ends
    const Rational h(1, 2);
    check_end(out[0].first, [&](const Rational& x) { return x < h && q(x) > 0; });
    check_end(out[0].second, [&](const Rational& x) { return x < h || q(x) < 0; });
    // the brackets are narrow enough to tell the ends from their decimal neighbours
    CHECK(*out[0].first.hi - *out[0].first.lo < Rational(1, 1000));
  }
  {  // A's centre (2s - 1, 2, 0) runs beside the segment at distance 2 throughout: P_s = [0, 1], touching
    const BallPath A = path(1, {-1, 2, 0}, {2, 0, 0});
    const Intervals out = project(A, B);
    REQUIRE(out.size() == 1);
    check_end_at(out[0].first, Rational(0));
    check_end_at(out[0].second, Rational(1));
  }
}

TEST_CASE("ball_projection: a single touching instant, all of [0, 1], nothing, a static B",
          "[exact][independent_balls]") {
  const BallPath B0 = path(1, {0, 0, 0}, {0, 0, 0});  // static at the origin
  {  // A's centre (2s - 1, 2, 0): distance sqrt((2s - 1)^2 + 4) >= 2, equal at s = 1/2 only
    const BallPath A = path(1, {-1, 2, 0}, {2, 0, 0});
    const Intervals out = project(A, B0);
    REQUIRE(out.size() == 1);
    check_end_at(out[0].first, Rational(1, 2));
    check_end_at(out[0].second, Rational(1, 2));
  }
  {  // A stays within distance 1 of the origin
    const BallPath A = path(1, {Rational(-1, 2), 0, 0}, {1, 0, 0});
    const Intervals out = project(A, B0);
    REQUIRE(out.size() == 1);
    CHECK(*out[0].first.hi == 0);
    CHECK(*out[0].second.lo == 1);
  }
  {  // far away: no s
    const BallPath A = path(1, {10, 10, 10}, {1, 0, 0});
    CHECK(project(A, B0).empty());
    // a meets_at that says otherwise contradicts the exact distance: an internal error
    CHECK_THROWS_AS(ball_projection(A, B0, [](const Rational&) { return true; }), std::logic_error);
  }
  {  // static B, A enters and stays: centre (4 - 4s, 0, 0), distance <= 2 iff s >= 1/2
    const BallPath A = path(1, {4, 0, 0}, {-4, 0, 0});
    const Intervals out = project(A, B0);
    REQUIRE(out.size() == 1);
    check_end_at(out[0].first, Rational(1, 2));
    CHECK(*out[0].second.lo == 1);
  }
}

TEST_CASE("ball_projection agrees with the exact distance at many instants", "[exact][independent_balls]") {
  // random lines against random segments: inside an interval iff meets() at rational samples
  std::uint64_t seed = 77;
  auto next = [&seed](long lo, long hi) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + long((seed >> 33) % std::uint64_t(hi - lo + 1));
  };
  int nonempty = 0, partial = 0;
  auto half = [](long n) {
    Rational h(n, 2);
    h.canonicalize();  // gmpxx's (num, den) constructor does not
    return h;
  };
  for (int trial = 0; trial < 25; ++trial) {
    auto v = [&](long m) {  // a vector with coordinates in [-m, m] / 2
      return std::array<Rational, 3>{half(next(-m, m)), half(next(-m, m)), half(next(-m, m))};
    };
    // starts near each other, longer moves: both answers occur
    const BallPath A = path(half(next(1, 4)), v(3), v(8)), B = path(half(next(1, 4)), v(3), v(8));
    const Intervals out = project(A, B);
    nonempty += !out.empty();
    for (const auto& [a, b] : out) partial += *a.lo > 0 || *b.hi < 1;
    CHECK(out.size() <= 1);  // a line against the convex neighbourhood of a segment: one interval at most
    for (int k = 0; k <= 40; ++k) {
      Rational s(k, 40);
      s.canonicalize();
      bool inside = false, maybe = false;
      for (const auto& [a, b] : out) {
        inside = inside || (*a.hi <= s && s <= *b.lo);
        maybe = maybe || (*a.lo <= s && s <= *b.hi);
      }
      INFO("trial " << trial << ", s = " << s);
      if (inside) CHECK(meets(A, B, s));
      if (!maybe) CHECK_FALSE(meets(A, B, s));
    }
  }
  CHECK(nonempty >= 5);
  CHECK(partial >= 3);  // ends inside (0, 1), not only the whole interval
}

}  // namespace ECCD_UNITY_ID
