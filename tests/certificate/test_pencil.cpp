// The checker's pencil λA(t) − B(t) (certificate/check/pencil.hpp), against
// computations written out here:
//   - determinant over Q (elimination) and over Z (Bareiss) equal a Laplace
//     expansion on random matrices, singular ones and ones that need row
//     swaps included; the determinant of integer polynomial matrices equals
//     the pointwise determinant;
//   - primitive_inverse: N(t) M(t) = s(t) I for one scalar polynomial s (so
//     N is c(t) M(t)^-1), and the entries of N have no common factor of
//     positive degree (their gcd is a constant); for M with a common factor
//     in its adjugate (a scaled identity), the factor is divided out;
//     motion_determinant is det M(t) times a positive constant;
//   - moving_quadric is Nᵀ Q N (over Q at rational t, over Z);
//   - pencil_coefficients over Z (H = 3 by cofactors, H = 4 by forward
//     differences) is H! times the rational coefficients, and those satisfy
//     Σ h_k λ^k = det(λA − B) at λ outside the interpolation nodes;
//   - subresultant_at(c, 0, 0) is Res(f, f') = (-1)^(n(n-1)/2) a disc f,
//     with disc f = a^(2n-2) Π (r_i − r_j)² from known roots (cubic and
//     quartic closed forms checked with it); s(j, j) vanishes exactly when
//     deg gcd(f, f') > j (a double root; two double roots).
#include "certificate/check/pencil.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::check;

namespace {

mpq_class laplace(const QMatrix& m) {
  const std::size_t n = m.size();
  if (n == 0) return 1;
  if (n == 1) return m[0][0];
  mpq_class d = 0;
  for (std::size_t c = 0; c < n; ++c) {
    QMatrix minor;
    for (std::size_t r = 1; r < n; ++r) {
      minor.emplace_back();
      for (std::size_t k = 0; k < n; ++k)
        if (k != c) minor.back().push_back(m[r][k]);
    }
    const mpq_class t = m[0][c] * laplace(minor);
    d += c % 2 ? mpq_class(-t) : t;
  }
  return d;
}

QMatrix random_qmatrix(SeededRng& rng, std::size_t n, bool integer) {
  QMatrix m(n, std::vector<mpq_class>(n));
  for (auto& row : m)
    for (auto& x : row) x = integer ? mpq_class(rng.uniform(-9, 9)) : rng.frac(-9, 9, rng.uniform(1, 5));
  return m;
}

QMatrix product(const QMatrix& a, const QMatrix& b) {
  const std::size_t n = a.size();
  QMatrix r(n, std::vector<mpq_class>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

QPoly poly(std::vector<mpq_class> c) { return QPoly(std::move(c)); }

PolyMatrix random_motion(SeededRng& rng, std::size_t H) {
  PolyMatrix M(H, std::vector<QPoly>(H));
  for (std::size_t i = 0; i < H; ++i)
    for (std::size_t j = 0; j < H; ++j)
      M[i][j] = poly({rng.frac(-5, 5, rng.uniform(1, 3)), rng.frac(-5, 5, rng.uniform(1, 3))});
  for (std::size_t i = 0; i < H; ++i) M[i][i] = M[i][i] + QPoly::constant(10);  // mostly invertible
  return M;
}

// disc of a Π (x - r_i): a^(2n-2) Π_{i<j} (r_i - r_j)^2, and the coefficients
std::pair<std::vector<mpq_class>, mpq_class> from_roots(const mpq_class& a, const std::vector<mpq_class>& r) {
  QPoly p = QPoly::constant(a);
  for (const auto& x : r) p = p * poly({-x, 1});
  mpq_class d = 1;
  const int n = int(r.size());
  for (int k = 0; k < 2 * n - 2; ++k) d *= a;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) d *= (r[i] - r[j]) * (r[i] - r[j]);
  return {p.c, d};
}

}  // namespace

TEST_CASE("check pencil determinants over Q, Z and Z[t] agree with Laplace", "[certificate][check_pencil]") {
  SeededRng rng{301};
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = std::size_t(rng.uniform(1, 5));
    QMatrix q = random_qmatrix(rng, n, false), z = random_qmatrix(rng, n, true);
    if (trial % 5 == 0 && n > 1) q[n - 1] = q[0];  // singular
    if (trial % 7 == 0) z[0][0] = 0;               // a swap in Bareiss
    if (trial % 11 == 0 && n > 1) {
      for (auto& x : z[1]) x = 2 * z[0][0];  // maybe singular, maybe not
    }
    CHECK(determinant(q) == laplace(q));
    ZMatrix zi;
    for (const auto& row : z) {
      zi.emplace_back();
      for (const auto& x : row) zi.back().push_back(x.get_num());
    }
    CHECK(mpq_class(determinant(zi)) == laplace(z));
  }
  CHECK(determinant(ZMatrix{}) == 1);
  // a polynomial matrix: the determinant polynomial at t is the determinant at t
  for (int trial = 0; trial < 20; ++trial) {
    const PolyMatrix M = random_motion(rng, std::size_t(rng.uniform(2, 4)));
    const QPoly dm = motion_determinant(M);
    const mpz_class L = denominators_lcm(M);
    mpq_class scale = 1;  // L^H
    for (std::size_t k = 0; k < M.size(); ++k) scale *= L;
    for (int k = 0; k < 5; ++k) {
      const mpq_class t = rng.frac(-3, 3, 7);
      CHECK(dm(t) == scale * laplace(at_point(M, t)));
    }
  }
}

TEST_CASE("check pencil primitive_inverse is c(t) M(t)^-1 with coprime entries", "[certificate][check_pencil]") {
  SeededRng rng{302};
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t H = std::size_t(rng.uniform(3, 4));
    const PolyMatrix M = random_motion(rng, H);
    const PolyMatrix N = primitive_inverse(M);
    // N M = s(t) I: at several t, a scalar matrix with one s for all entries
    for (int k = 0; k < 4; ++k) {
      const mpq_class t = rng.frac(-4, 4, 5);
      const QMatrix P = product(at_point(N, t), at_point(M, t));
      for (std::size_t i = 0; i < H; ++i)
        for (std::size_t j = 0; j < H; ++j) CHECK(P[i][j] == (i == j ? P[0][0] : mpq_class(0)));
    }
    QPoly g;
    for (const auto& row : N)
      for (const auto& e : row)
        if (!e.zero()) g = g.zero() ? e : gcd(g, e);
    CHECK(g.degree() == 0);
  }
  // M = (1 + t) I3 with a translation row: adj M has the factor (1 + t)^k; divided out, N(t) M(t) = (1 + t) I
  PolyMatrix M(3, std::vector<QPoly>(3));
  for (int i = 0; i < 3; ++i) M[i][i] = poly({1, 1});
  M[0][2] = poly({0, 2, 2});  // (1 + t) 2t: the translation 2t after dividing by w = 1 + t
  const PolyMatrix N = primitive_inverse(M);
  for (const auto& row : N)
    for (const auto& e : row) CHECK(e.degree() <= 1);
  const QMatrix P = product(at_point(N, mpq_class(1, 3)), at_point(M, mpq_class(1, 3)));
  CHECK(P[0][0] != 0);
  CHECK(P[0][1] == 0);
  CHECK(P[1][1] == P[0][0]);
}

TEST_CASE("check pencil moving quadric and pencil coefficients", "[certificate][check_pencil]") {
  SeededRng rng{303};
  for (int trial = 0; trial < 30; ++trial) {
    const std::size_t H = trial % 2 ? 3 : 4;
    QMatrix Qa = random_qmatrix(rng, H, true), Qb = random_qmatrix(rng, H, true);
    for (std::size_t i = 0; i < H; ++i)
      for (std::size_t j = 0; j < i; ++j) {
        Qa[i][j] = Qa[j][i];
        Qb[i][j] = Qb[j][i];
      }
    const PolyMatrix Na = random_motion(rng, H), Nb = random_motion(rng, H);
    const mpq_class t = rng.frac(0, 6, 6);
    const QMatrix A = moving_quadric(Qa, Na, t), B = moving_quadric(Qb, Nb, t);
    // Nᵀ Q N by hand
    QMatrix n = at_point(Na, t), nt(H, std::vector<mpq_class>(H));
    for (std::size_t i = 0; i < H; ++i)
      for (std::size_t j = 0; j < H; ++j) nt[i][j] = n[j][i];
    CHECK(A == product(product(nt, Qa), n));
    // rational coefficients: the polynomial det(λA - B) at λ off the nodes
    const std::vector<mpq_class> h = pencil_coefficients(A, B);
    REQUIRE(h.size() == H + 1);
    for (const mpq_class& lambda : {mpq_class(-5, 2), mpq_class(7, 3), mpq_class(11)}) {
      QMatrix m(H, std::vector<mpq_class>(H));
      for (std::size_t i = 0; i < H; ++i)
        for (std::size_t j = 0; j < H; ++j) m[i][j] = lambda * A[i][j] - B[i][j];
      mpq_class v = 0, p = 1;
      for (const auto& c : h) {
        v += c * p;
        p *= lambda;
      }
      CHECK(v == laplace(m));
    }
    // integers: H! h for integer A, B (N at an integer t, Q integer)
    const mpz_class ti(rng.uniform(0, 3));
    const ZMatrix Az = moving_quadric(integer_matrix(Qa), at_point(integer_matrix(Na), ti)),
                  Bz = moving_quadric(integer_matrix(Qb), at_point(integer_matrix(Nb), ti));
    QMatrix Aq, Bq;
    for (std::size_t i = 0; i < H; ++i) {
      Aq.emplace_back();
      Bq.emplace_back();
      for (std::size_t j = 0; j < H; ++j) {
        Aq.back().emplace_back(Az[i][j]);
        Bq.back().emplace_back(Bz[i][j]);
      }
    }
    const std::vector<mpz_class> hz = pencil_coefficients(Az, Bz);
    const std::vector<mpq_class> hq = pencil_coefficients(Aq, Bq);
    const int factorial = H == 3 ? 6 : 24;
    for (std::size_t k = 0; k <= H; ++k) CHECK(mpq_class(hz[k]) == factorial * hq[k]);
  }
}

TEST_CASE("check pencil subresultants and discriminants against known roots", "[certificate][check_pencil]") {
  SeededRng rng{304};
  for (int trial = 0; trial < 40; ++trial) {
    const int n = trial % 2 ? 3 : 4;
    std::vector<mpq_class> r;
    for (int i = 0; i < n; ++i) r.push_back(rng.frac(-9, 9, rng.uniform(1, 4)));
    const mpq_class a = rng.frac(1, 5, rng.uniform(1, 3)) * (trial % 3 ? 1 : -1);
    const auto [c, disc] = from_roots(a, r);
    const mpq_class res = subresultant_at(c, 0, 0);  // Res(f, f')
    const int sign = (n * (n - 1) / 2) % 2 ? -1 : 1;
    CHECK(res == sign * a * disc);
    if (n == 3) CHECK(cubic_discriminant_at(c) == disc);
    // integer versions on an integer multiple
    mpz_class l = 1;
    for (const auto& x : c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
    std::vector<mpz_class> z;
    for (const auto& x : c) z.push_back(mpq_class(x * l).get_num());
    mpq_class ln = 1;  // l^(2n - 2) for the discriminant, l^(2n - 1) for the resultant (degree 2n - 2, 2n - 1)
    for (int k = 0; k < 2 * n - 2; ++k) ln *= l;
    if (n == 4) CHECK(mpq_class(quartic_discriminant_at(z)) == ln * disc);
    if (n == 3) CHECK(mpq_class(cubic_discriminant_at(z)) == ln * disc);
    CHECK(mpq_class(subresultant_at(z, 0, 0)) == ln * l * res);
  }
  // s(j, j) = 0 iff deg gcd(f, f') > j
  const auto [one_double, d1] = from_roots(mpq_class(1), {1, 1, 2, -3});
  CHECK(d1 == 0);
  CHECK(subresultant_at(one_double, 0, 0) == 0);
  CHECK(subresultant_at(one_double, 1, 1) != 0);
  const auto [two_double, d2] = from_roots(mpq_class(2), {1, 1, 2, 2});
  CHECK(subresultant_at(two_double, 1, 1) == 0);
  CHECK(subresultant_at(two_double, 2, 2) != 0);
  const auto [triple, d3] = from_roots(mpq_class(1), {mpq_class(1, 2), mpq_class(1, 2), mpq_class(1, 2)});
  CHECK(subresultant_at(triple, 1, 1) == 0);
  CHECK(cubic_discriminant_at(triple) == 0);
}

}  // namespace ECCD_UNITY_ID
