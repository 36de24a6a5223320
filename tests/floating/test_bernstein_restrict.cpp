// Restriction of Bernstein polynomials to a sub-interval
// (floating/bernstein_restrict.hpp): restrict_to, restrict_in_place and
// restrict_t re-express q on [a, b] over [0, 1].
//   - exact: over mpq_class, the restricted polynomial r satisfies
//     r(x) = q(a + (b - a) x) at random rational x, for random polynomials
//     and random [a, b] including a = 0, b = 1, [0, 1] itself (the copy is
//     q) and a point interval a = b (every coefficient is q(a));
//   - its end coefficients are q(a) and q(b) (a Bernstein polynomial
//     interpolates at its ends);
//   - rounded: in double and MPFR the same identity holds within a bound of
//     the coefficients' size times a small multiple of the unit roundoff;
//   - restrict_t on a BiBern restricts every row in t: r(u, x) = f(u, a + (b - a) x)
//     exactly (mpq_class), u untouched.
#include "compare/seeded_rng.hpp"
#include "floating/bernstein_restrict.hpp"
#include "number/mpfr_real.hpp"

#include <catch2/catch.hpp>

#include <mpfr.h>

#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

Bern<mpq_class> random_bern(SeededRng& rng, int n) {
  Bern<mpq_class> q;
  for (int i = 0; i <= n; ++i) q.b.push_back(rng.frac(-1000, 1000, rng.uniform(1, 50)));
  return q;
}

mpq_class exact(double x) { return mpq_class(x); }
mpq_class exact(const Mpfr& x) {
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), x.get());
  return q;
}
double to_t(const mpq_class& q, double) { return q.get_d(); }
Mpfr to_t(const mpq_class& q, const Mpfr&) { return Mpfr(q, 120); }

}  // namespace

TEST_CASE("restrict_to is exact reparameterisation over rationals", "[floating][bernstein_restrict]") {
  SeededRng rng{2024};
  for (int trial = 0; trial < 80; ++trial) {
    const int n = int(rng.uniform(0, 7));
    const Bern<mpq_class> q = random_bern(rng, n);
    mpq_class a = rng.frac(0, 64, 64), b = rng.frac(0, 64, 64);
    if (a > b) std::swap(a, b);
    if (trial % 8 == 0) a = 0;
    if (trial % 8 == 1) b = 1;
    if (trial % 8 == 2) b = a;  // a point: the constant q(a)
    const Bern<mpq_class> r = restrict_to(q, a, b);
    REQUIRE(r.degree() == n);
    INFO("[" << a << ", " << b << "], degree " << n);
    CHECK(r.b.front() == q(a));
    CHECK(r.b.back() == q(b));
    for (int k = 0; k < 6; ++k) {
      const mpq_class x = rng.frac(0, 97, 97);
      CHECK(r(x) == q(a + (b - a) * x));
    }
    if (a == b)
      for (const auto& c : r.b) CHECK(c == q(a));
    // in place, with the explicit one: the same coefficients
    Bern<mpq_class> s = q;
    restrict_in_place(std::span<mpq_class>(s.b), a, b, mpq_class(1));
    CHECK(s.b == r.b);
  }
  // [0, 1]: nothing changes
  const Bern<mpq_class> q = random_bern(rng, 5);
  CHECK(restrict_to(q, mpq_class(0), mpq_class(1)).b == q.b);
}

TEMPLATE_TEST_CASE("restrict_to in rounded arithmetic stays within rounding of the exact restriction",
                   "[floating][bernstein_restrict]", double, Mpfr) {
  SeededRng rng{2025};
  const TestType like = to_t(mpq_class(0), TestType());
  // unit roundoff of the type: 2^-53 (double) or 2^-120 (Mpfr at 120 bits)
  const mpq_class unit(1, mpz_class(1) << (std::is_same_v<TestType, double> ? 53 : 120));
  for (int trial = 0; trial < 40; ++trial) {
    const int n = int(rng.uniform(1, 6));
    const Bern<mpq_class> q = random_bern(rng, n);
    mpq_class a = rng.frac(0, 64, 64), b = rng.frac(0, 64, 64);
    if (a >= b) continue;
    Bern<TestType> qt;
    mpq_class size = 0;
    for (const auto& c : q.b) {
      qt.b.push_back(to_t(c, like));
      size = std::max(size, mpq_class(abs(c)));
    }
    // a and b are dyadic with 6 bits: exact in both types, so only the arithmetic rounds
    const Bern<TestType> r = restrict_to(qt, to_t(a, like), to_t(b, like));
    const Bern<mpq_class> re = restrict_to(q, a, b);
    // de Casteljau takes convex combinations: each of the 2n rounds adds at most a few units of size,
    // and the division (b - a) / (1 - a) one more; 16 n + 16 units is a generous cover
    const mpq_class tol = size * unit * (16 * n + 16);
    for (int i = 0; i <= n; ++i) {
      INFO("coefficient " << i << " of degree " << n << " on [" << a << ", " << b << "]");
      CHECK(abs(exact(r.b[i]) - re.b[i]) <= tol);
    }
  }
}

TEST_CASE("restrict_t restricts every row of a bivariate net in t", "[floating][bernstein_restrict]") {
  SeededRng rng{2026};
  for (int trial = 0; trial < 20; ++trial) {
    BiBern<mpq_class> f;
    const int m = int(rng.uniform(0, 4)), n = int(rng.uniform(0, 5));
    for (int i = 0; i <= m; ++i) f.b.push_back(random_bern(rng, n).b);
    mpq_class a = rng.frac(0, 30, 30), b = rng.frac(0, 30, 30);
    if (a > b) std::swap(a, b);
    const BiBern<mpq_class> r = restrict_t(f, a, b);
    REQUIRE(r.degree_u() == m);
    REQUIRE(r.degree_t() == n);
    for (int k = 0; k < 5; ++k) {
      const mpq_class u = rng.frac(0, 11, 11), x = rng.frac(0, 13, 13);
      CHECK(r(u, x) == f(u, a + (b - a) * x));
    }
    // with the explicit one
    CHECK(restrict_t(f, a, b, mpq_class(1)).b == r.b);
  }
}

}  // namespace ECCD_UNITY_ID
