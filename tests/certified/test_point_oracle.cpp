// The exact oracle at a rational instant (certified/point_oracle.hpp).
// tests/certified/test_local_escalation.cpp compares g_at(t) with the exact
// pipeline's characteristic_of(pair) at t; here the oracle's own steps are
// checked against computations written out in the test:
//   - g_at(t) interpolates det(λA(t) − B(t)) on the nodes λ = 0..H; at other
//     λ (random rationals) Σ g_k λ^k must equal the determinant computed by
//     Laplace expansion from A = N(t)ᵀ Q N(t) formed here, for random
//     prepared pairs in 2D (H = 3) and 3D (H = 4), singular matrices included
//     (a zero column in N makes det A(t) = 0, the pivot search's zero path);
//   - status_at on translating unit discs and balls (B's centre at
//     (6t − 3, 0[, 0])): separate, touching exactly at t = 1/6 and 5/6 (centre
//     distance 2 = r_A + r_B), overlapping in between, at non-dyadic
//     instants too.
#include "certified/point_oracle.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

template <int H>
Rational laplace_det(const std::vector<std::vector<Rational>>& m) {
  const int n = int(m.size());
  if (n == 1) return m[0][0];
  Rational d = 0;
  for (int j = 0; j < n; ++j) {
    if (sgn(m[0][j]) == 0) continue;
    std::vector<std::vector<Rational>> minor;
    for (int i = 1; i < n; ++i) {
      std::vector<Rational> row;
      for (int k = 0; k < n; ++k)
        if (k != j) row.push_back(m[i][k]);
      minor.push_back(row);
    }
    const Rational s = laplace_det<H>(minor) * m[0][j];
    d += j % 2 ? Rational(-s) : s;
  }
  return d;
}

template <int H>
std::vector<std::vector<Rational>> quadric(const Matrix<Rational, H>& q, const PolyMatrix<Rational, H>& n,
                                           const Rational& t) {
  std::vector<std::vector<Rational>> nt(H, std::vector<Rational>(H)), a(H, std::vector<Rational>(H, Rational(0)));
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) nt[i][j] = n[i][j].is_zero() ? Rational(0) : n[i][j](t);
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j)
      for (int k = 0; k < H; ++k)
        for (int l = 0; l < H; ++l) a[i][j] += nt[k][i] * q[k][l] * nt[l][j];
  return a;
}

template <int H>
PreparedPair<H> random_pair(SeededRng& rng, bool singular) {
  PreparedPair<H> p;
  for (int i = 0; i < H; ++i)
    for (int j = i; j < H; ++j) {
      p.qa[i][j] = p.qa[j][i] = Rational(rng.uniform(-9, 9));
      p.qb[i][j] = p.qb[j][i] = Rational(rng.uniform(-9, 9));
    }
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      std::vector<Rational> ca, cb;
      for (int d = 0; d <= 2; ++d) {
        ca.push_back(rng.frac(-6, 6, 3));
        cb.push_back(rng.frac(-6, 6, 2));
      }
      p.na[i][j] = RPoly(ca);
      p.nb[i][j] = RPoly(cb);
    }
  if (singular)
    for (int i = 0; i < H; ++i) p.na[i][1] = RPoly();  // a zero column: A(t) singular
  return p;
}

template <int H>
void check_interpolation(std::uint64_t seed) {
  SeededRng rng{seed};
  for (int trial = 0; trial < 12; ++trial) {
    const PreparedPair<H> p = random_pair<H>(rng, trial % 4 == 0);
    PreparedPointOracle<H> oracle(p);
    const Rational t = rng.frac(-5, 12, 7);
    const std::vector<Rational> g = oracle.g_at(t);
    REQUIRE(g.size() == std::size_t(H + 1));
    const auto a = quadric<H>(p.qa, p.na, t), b = quadric<H>(p.qb, p.nb, t);
    for (const Rational& lambda : {Rational(-7, 3), Rational(1, 2), Rational(11, 5), Rational(H + 3)}) {
      std::vector<std::vector<Rational>> m(H, std::vector<Rational>(H));
      for (int i = 0; i < H; ++i)
        for (int j = 0; j < H; ++j) m[i][j] = lambda * a[i][j] - b[i][j];
      Rational f = 0, pw = 1;
      for (const auto& gk : g) {
        f += gk * pw;
        pw *= lambda;
      }
      INFO("H = " << H << ", trial " << trial << ", t = " << t << ", λ = " << lambda);
      CHECK(f == laplace_det<H>(m));
    }
    if (trial % 4 == 0) CHECK(g[H] == 0);  // det A(t) = 0: the leading coefficient vanishes
  }
}

Scene translating_unit_bodies(int dim) {
  Scene s;
  s.dim = dim;
  const int D = dim + 1;
  std::vector<std::vector<Rational>> Q(D, std::vector<Rational>(D, Rational(0)));
  for (int i = 0; i < dim; ++i) Q[i][i] = 1;
  Q[dim][dim] = -1;
  s.a.Q = s.b.Q = Q;
  s.a.motion = StaticMotion{};
  MatrixMotion m;
  m.m.assign(D, std::vector<RPoly>(D));
  for (int i = 0; i < D; ++i) m.m[i][i] = RPoly::constant(Rational(1));
  m.m[0][dim] = RPoly(std::vector<Rational>{-3, 6});
  s.b.motion = m;
  return s;
}

template <int H>
void check_status() {
  const PreparedPair<H> p = prepare_pair<H>(translating_unit_bodies(H - 1));
  PreparedPointOracle<H> oracle(p);
  // centre distance |6t - 3|: > 2 separate, = 2 touching, < 2 overlapping
  for (int k = 0; k <= 42; ++k) {
    Rational t(k, 42);
    t.canonicalize();  // gmpxx's (num, den) constructor does not
    const Rational dist = abs(6 * t - 3);
    const Status want = dist > 2 ? Status::separate : dist == 2 ? Status::touching : Status::overlapping;
    INFO("H = " << H << ", t = " << t);
    CHECK(oracle.status_at(t) == want);
  }
  CHECK(oracle.status_at(Rational(1, 6)) == Status::touching);
  CHECK(oracle.status_at(Rational(5, 6)) == Status::touching);
  CHECK(oracle.status_at(Rational(1, 6) - Rational(1, 1000000)) == Status::separate);
  CHECK(oracle.status_at(Rational(1, 6) + Rational(1, 1000000)) == Status::overlapping);
}

}  // namespace

TEST_CASE("PreparedPointOracle g_at interpolates det(λA − B) exactly", "[certified][point_oracle]") {
  check_interpolation<3>(601);
  check_interpolation<4>(602);
}

TEST_CASE("PreparedPointOracle status_at on translating unit discs and balls", "[certified][point_oracle]") {
  check_status<3>();
  check_status<4>();
}

}  // namespace ECCD_UNITY_ID
