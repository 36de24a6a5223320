// kernel/trivariate_bernstein.hpp: the ellipsoid function of independent
// motions F(u, s, t) = det((1 - u) A(s) + u B(t)) as a tensor-product
// Bernstein net (001 section 4), and its subdivision. Checked in mpq against:
//   - the determinant of (1 - u) A(s) + u B(t) formed in the test at seeded
//     random rational (u, s, t) (A(s) = N_A(s)ᵀ Q_A N_A(s) multiplied out, the
//     determinant by the Leibniz sum), for random pairs in 2D (H = 3) and 3D
//     (H = 4), with zero entries, motions of different degrees in s and t;
//   - the net's degrees: H in u, at most H times that of A(s) (twice N_A's) in s;
//   - split_half: the halves along each axis are F on the half boxes
//     (F(x/2) and F((1 + x)/2) in the split variable), split_half_into the same;
//   - at_s(x) is F(., x, .); swap_st exchanges s and t;
//   - strict_sign on nets of one sign and mixed signs;
//   - without_positive_factor on a net built as p(s) G(u, t) with p of one
//     strict sign (G returned, negated when p < 0), and refused otherwise.
#include "kernel/trivariate_bernstein.hpp"
#include "tests/support/leibniz.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

Rational small(std::mt19937_64& rng) {
  Rational x(long(rng() % 13) - 6, long(rng() % 3) + 1);
  x.canonicalize();
  return x;
}
Rational unit(std::mt19937_64& rng) {
  Rational x(long(rng() % 65), 64);
  x.canonicalize();
  return x;
}

template <int H>
Rational leibniz(const Matrix<Rational, H>& a) {
  return test::leibniz_det<Rational>(a, H);
}

template <int H>
PreparedPair<H> random_pair(std::mt19937_64& rng, int deg_a, int deg_b) {
  PreparedPair<H> p;
  for (Matrix<Rational, H>* q : {&p.qa, &p.qb})
    for (int i = 0; i < H; ++i)
      for (int j = i; j < H; ++j) (*q)[i][j] = (*q)[j][i] = small(rng);
  for (int k = 0; k < 2; ++k) {
    PolyMatrix<Rational, H>& n = k ? p.nb : p.na;
    const int deg = k ? deg_b : deg_a;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        if (rng() % 5 == 0) continue;
        std::vector<Rational> c;
        for (int e = 0; e <= deg; ++e) c.push_back(small(rng));
        n[i][j] = Poly<Rational>(c);
      }
  }
  return p;
}

template <int H>
Matrix<Rational, H> moved(const Matrix<Rational, H>& q, const PolyMatrix<Rational, H>& n, const Rational& x) {
  Matrix<Rational, H> r{};
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j)
      for (int k = 0; k < H; ++k)
        for (int l = 0; l < H; ++l) r[i][j] += n[k][i](x) * q[k][l] * n[l][j](x);
  return r;
}

template <int H>
Rational direct(const PreparedPair<H>& p, const Rational& u, const Rational& s, const Rational& t) {
  const Matrix<Rational, H> a = moved<H>(p.qa, p.na, s), b = moved<H>(p.qb, p.nb, t);
  Matrix<Rational, H> m{};
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) m[i][j] = (1 - u) * a[i][j] + u * b[i][j];
  return leibniz<H>(m);
}

template <int H>
void check_against_determinant(std::mt19937_64& rng, int trials) {
  for (int trial = 0; trial < trials; ++trial) {
    const int da = 1 + trial % 2, db = trial % 3;
    const PreparedPair<H> p = random_pair<H>(rng, da, db);
    const TriBern<Rational> F = independent_ellipsoid_function<Rational, H>(to_arithmetic_bernstein<Rational, H>(p, 1));
    CHECK(F.n[0] == H);
    CHECK(F.n[1] <= 2 * H * da);  // a product of H entries of A(s), each of degree 2 deg N_A
    CHECK(F.n[2] <= 2 * H * db);
    if (db == 0) CHECK(F.n[2] == 0);  // a static B: no t at all
    for (int k = 0; k < 6; ++k) {
      const Rational u = unit(rng), s = unit(rng), t = unit(rng);
      INFO("H = " << H << " trial " << trial << " (u, s, t) = (" << u << ", " << s << ", " << t << ")");
      CHECK(F(u, s, t) == direct<H>(p, u, s, t));
    }
    // The faces: F(0, s, .) = det A(s), F(1, ., t) = det B(t).
    const Rational s = unit(rng);
    CHECK(F(Rational(0), s, Rational(1, 3)) == leibniz<H>(moved<H>(p.qa, p.na, s)));
    CHECK(F(Rational(1), Rational(1, 3), s) == leibniz<H>(moved<H>(p.qb, p.nb, s)));
  }
}

}  // namespace

TEST_CASE("independent_ellipsoid_function is det((1 - u) A(s) + u B(t))", "[kernel][trivariate_bernstein]") {
  std::mt19937_64 rng(4315);
  check_against_determinant<3>(rng, 12);
  check_against_determinant<4>(rng, 6);
}

TEST_CASE("TriBern split_half, at_s, swap_st and strict_sign are F on sub-boxes and slices",
          "[kernel][trivariate_bernstein]") {
  std::mt19937_64 rng(4316);
  const PreparedPair<3> p = random_pair<3>(rng, 2, 1);
  const TriBern<Rational> F = independent_ellipsoid_function<Rational, 3>(to_arithmetic_bernstein<Rational, 3>(p, 1));
  const Rational half(1, 2);
  for (int axis = 0; axis < 3; ++axis) {
    const auto [lo, hi] = F.split_half(axis, half);
    TriBern<Rational> moved_net = F, lo2;
    HalvingStep<Rational> step(half);
    moved_net.split_half_into(axis, step, lo2);
    CHECK(lo2.c == lo.c);
    CHECK(moved_net.c == hi.c);
    for (int k = 0; k < 8; ++k) {
      std::array<Rational, 3> x = {unit(rng), unit(rng), unit(rng)};
      std::array<Rational, 3> xl = x, xh = x;
      xl[axis] = x[axis] / 2;
      xh[axis] = (1 + x[axis]) / 2;
      INFO("axis " << axis);
      CHECK(lo(x[0], x[1], x[2]) == F(xl[0], xl[1], xl[2]));
      CHECK(hi(x[0], x[1], x[2]) == F(xh[0], xh[1], xh[2]));
    }
  }
  const TriBern<Rational> G = F.swap_st();
  CHECK(G.n[1] == F.n[2]);
  CHECK(G.n[2] == F.n[1]);
  for (int k = 0; k < 8; ++k) {
    const Rational u = unit(rng), s = unit(rng), t = unit(rng);
    CHECK(G(u, s, t) == F(u, t, s));
    const TriBern<Rational> S = F.at_s(s);
    CHECK(S.n[1] == 0);
    CHECK(S(u, Rational(0), t) == F(u, s, t));
    CHECK(S(u, Rational(1), t) == F(u, s, t));
  }
  TriBern<Rational> pos;
  pos.n = {1, 1, 0};
  pos.c = {Rational(1), Rational(2), Rational(1, 3), Rational(5)};
  CHECK(pos.strict_sign() == 1);
  for (auto& x : pos.c) x = -x;
  CHECK(pos.strict_sign() == -1);
  pos.c[2] = 0;
  CHECK(pos.strict_sign() == 0);
  pos.c[2] = 1;
  CHECK(pos.strict_sign() == 0);
}

TEST_CASE("TriBern without_positive_factor splits off a factor of one sign along s or t",
          "[kernel][trivariate_bernstein]") {
  std::mt19937_64 rng(4317);
  // G(u, t) of degree (2, 2), p(s) of degree 2 with Bernstein coefficients of one sign.
  TriBern<Rational> g;
  g.n = {2, 0, 2};
  for (int i = 0; i < 9; ++i) g.c.push_back(small(rng));
  g.c[0] = 3;  // a non-zero first line
  for (const long sp : {1L, -1L}) {
    const std::vector<Rational> p = {Rational(2 * sp), Rational(sp, 3), Rational(5 * sp)};
    TriBern<Rational> f;
    f.n = {2, 2, 2};
    f.c.resize(27);
    for (int i = 0; i <= 2; ++i)
      for (int j = 0; j <= 2; ++j)
        for (int k = 0; k <= 2; ++k) f.at(i, j, k) = p[j] * g.at(i, 0, k);
    const auto r = f.without_positive_factor(1);
    REQUIRE(r);
    CHECK(r->n == std::array<int, 3>{2, 0, 2});
    // Each line divided by the first non-zero line's first point p[0] G(0, 0) = 3 p[0], negated when that is
    // negative: r = sign(p) G / 3, whose signs are F's at every s (p has one sign).
    for (int i = 0; i <= 2; ++i)
      for (int k = 0; k <= 2; ++k) CHECK(r->at(i, 0, k) == Rational(sp) * g.at(i, 0, k) / 3);
    for (int k = 0; k < 6; ++k) {
      const Rational u = unit(rng), s = unit(rng), t = unit(rng);
      CHECK(sgn(f(u, s, t)) == sgn((*r)(u, Rational(0), t)));
    }
    CHECK_FALSE(f.without_positive_factor(2));  // along t the lines are not proportional
  }
  // p with coefficients of both signs (a root in (0, 1) possible): refused.
  TriBern<Rational> f;
  f.n = {2, 1, 2};
  f.c.resize(18);
  for (int i = 0; i <= 2; ++i)
    for (int k = 0; k <= 2; ++k) {
      f.at(i, 0, k) = g.at(i, 0, k);
      f.at(i, 1, k) = -g.at(i, 0, k);
    }
  CHECK_FALSE(f.without_positive_factor(1));
  // degree 0 along the axis: nothing to split off
  CHECK_FALSE(g.without_positive_factor(1));
}

}  // namespace ECCD_UNITY_ID
