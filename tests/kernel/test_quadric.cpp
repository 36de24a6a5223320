// kernel/quadric.hpp: the moving quadric A(t) = N(t)ᵀ Q N(t). Checked against
// the products written out in mpq in the test at rational t (moving_quadric,
// quadric_at, and moving_quadric_in over Bern<Rational>), over seeded random
// symmetric Q and N(t) with zero entries, in 2D and 3D; A is symmetric; and
// the header's statement on a translated circle: with N the inverse of the
// translation by (x(t), y(t)), Xᵀ A(t) X = (x - x(t))² + (y - y(t))² - r², so
// the centre is inside (negative) and a point at distance r on the boundary.
#include "kernel/bernstein.hpp"
#include "kernel/quadric.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

Rational small(std::mt19937_64& rng) {
  Rational x(long(rng() % 21) - 10, long(rng() % 3) + 1);
  x.canonicalize();
  return x;
}

template <int H>
void check_random(std::mt19937_64& rng, int trials) {
  for (int trial = 0; trial < trials; ++trial) {
    Matrix<Rational, H> q{};
    for (int i = 0; i < H; ++i)
      for (int j = i; j < H; ++j) q[i][j] = q[j][i] = (rng() % 3 == 0) ? Rational(0) : small(rng);
    PolyMatrix<Rational, H> n{};
    std::array<std::array<Bern<Rational>, H>, H> nb;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        std::vector<Rational> c;
        if (rng() % 4 != 0)
          for (int e = 0, deg = int(rng() % 3); e <= deg; ++e) c.push_back(small(rng));
        n[i][j] = RP(c);
        nb[i][j] = to_bernstein(n[i][j], 2);
      }
    const PolyMatrix<Rational, H> a = moving_quadric<Rational, H>(q, n);
    Bern<Rational> zero;
    zero.b.assign(1, Rational(0));
    const auto ab = moving_quadric_in<Bern<Rational>, Rational, H>(q, nb, zero);
    for (int s = 0; s <= 4; ++s) {
      Rational t(s, 4);
      t.canonicalize();
      Matrix<Rational, H> nt{};
      for (int i = 0; i < H; ++i)
        for (int j = 0; j < H; ++j) nt[i][j] = n[i][j](t);
      const Matrix<Rational, H> qa = quadric_at<Rational, H>(q, n, t);
      for (int i = 0; i < H; ++i)
        for (int j = 0; j < H; ++j) {
          Rational want = 0;
          for (int k = 0; k < H; ++k)
            for (int l = 0; l < H; ++l) want += nt[k][i] * q[k][l] * nt[l][j];
          INFO("H = " << H << " trial " << trial << " t = " << t << " entry " << i << "," << j);
          CHECK(a[i][j](t) == want);
          CHECK(qa[i][j] == want);
          CHECK(ab[i][j](t) == want);
          CHECK(a[i][j] == a[j][i]);
        }
    }
  }
}

}  // namespace

TEST_CASE("moving_quadric, quadric_at and moving_quadric_in are N^T Q N", "[kernel][quadric]") {
  std::mt19937_64 rng(4312);
  check_random<3>(rng, 40);
  check_random<4>(rng, 20);
}

TEST_CASE("moving_quadric of a translated circle is the circle at its moving centre", "[kernel][quadric]") {
  // Circle of radius 2: Q = diag(1, 1, -4). Translation by (x(t), y(t)) = (3t - 1, t²): N = M⁻¹ =
  // [[1, 0, -x], [0, 1, -y], [0, 0, 1]] (det M = 1, so c = 1 and A is the moving circle itself).
  Matrix<Rational, 3> q{};
  q[0][0] = 1;
  q[1][1] = 1;
  q[2][2] = -4;
  PolyMatrix<Rational, 3> n{};
  const RP x({Rational(-1), Rational(3)}), y({Rational(0), Rational(0), Rational(1)});
  n[0][0] = n[1][1] = n[2][2] = RP::constant(Rational(1));
  n[0][2] = -x;
  n[1][2] = -y;
  const auto a = moving_quadric<Rational, 3>(q, n);
  auto form = [&](const Rational& t, const Rational& px, const Rational& py) {
    const Rational v[3] = {px, py, 1};
    Rational s = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s += v[i] * a[i][j](t) * v[j];
    return s;
  };
  for (int s = 0; s <= 8; ++s) {
    Rational t(s, 8);
    t.canonicalize();
    const Rational cx = x(t), cy = y(t);
    INFO("t = " << t);
    CHECK(form(t, cx, cy) == -4);        // the centre: inside
    CHECK(form(t, cx + 2, cy) == 0);     // on the circle
    CHECK(form(t, cx, cy - 2) == 0);     // on the circle
    CHECK(form(t, cx + 1, cy + 1) < 0);  // inside
    CHECK(form(t, cx + 2, cy + 1) > 0);  // outside
    // and the polynomial form for any point: (px - x)² + (py - y)² - 4
    const Rational px(7, 3), py(-1, 2);
    CHECK(form(t, px, py) == (px - cx) * (px - cx) + (py - cy) * (py - cy) - 4);
  }
  CHECK(a[0][2] == -x);
  CHECK(a[2][2] == x * x + y * y - RP::constant(Rational(4)));
}

}  // namespace ECCD_UNITY_ID
