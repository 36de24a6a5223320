// The real roots of the pencil's small polynomials (kernel/pencil_geometry.hpp), tag [contact].
//
// Issue 21: for Mpfr the roots are found by Newton's method safeguarded by the
// sign-change bracket instead of bisection to the last bit. Checked here
// against exact rational roots (the distance to the true root, a few ulps at
// 256 bits), against the bisection it replaces (a reference copy below, the
// old loop), and on a triple root (a sign change where p' vanishes: Newton
// must hand over to bisection and still end).
#include "kernel/pencil_geometry.hpp"
#include "number/mpfr_real.hpp"

#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

constexpr int kBits = 256;

Mpfr M(const mpq_class& q) { return Mpfr(q, kBits); }

// prod (x - r_i) with rational roots, coefficients in Mpfr at kBits (exact for these small numerators).
Poly<Mpfr> from_roots(const std::vector<mpq_class>& roots, const mpq_class& lead) {
  std::vector<mpq_class> c{lead};
  for (const mpq_class& r : roots) {
    std::vector<mpq_class> n(c.size() + 1, mpq_class(0));
    for (std::size_t i = 0; i < c.size(); ++i) {
      n[i + 1] += c[i];
      n[i] -= r * c[i];
    }
    c = n;
  }
  std::vector<Mpfr> m;
  for (const auto& x : c) m.push_back(M(x));
  return Poly<Mpfr>(m);
}

// |x - q| <= |q| 2^-e + 2^-e (relative, with an absolute floor near 0)
bool close(const Mpfr& x, const mpq_class& q, int e) {
  mpq_class xq;
  mpfr_get_q(xq.get_mpq_t(), x.get());
  mpz_class two = 1;
  two <<= e;
  return abs(mpq_class(xq - q)) <= (abs(q) + 1) / mpq_class(two);
}

// The bisection small_real_roots used for every T before issue 21 (the reference).
Mpfr bisect(const Poly<Mpfr>& p, Mpfr l, Mpfr r) {
  const Sign sl = sign(p(l));
  for (int it = 0; it < 100000; ++it) {
    Mpfr m = (l + r) / Mpfr(2);
    if (!(l < m && m < r)) break;
    Sign sm = sign(p(m));
    if (sm == Sign::zero) return m;
    (sm == sl ? l : r) = m;
  }
  return (l + r) / Mpfr(2);
}

}  // namespace

TEST_CASE("pencil roots in Mpfr: safeguarded Newton gives the exact roots to the last bits", "[contact]") {
  // f of degree 4 with four negative and positive simple roots, as det(λA - B) has; and its derivative's roots
  // against bisection (contact_geometry takes the roots of f').
  const std::vector<std::vector<mpq_class>> sets = {
      {mpq_class(-7, 3), mpq_class(-1, 5), mpq_class(2, 7), mpq_class(11, 2)},
      {mpq_class(-1000), mpq_class(-1, 1000), mpq_class(-1, 999), mpq_class(3)},  // two close roots and a far one
      {mpq_class(-3, 2), mpq_class(-1, 2), mpq_class(1, 3)},
      {mpq_class(1, 8), mpq_class(5, 8)}};
  for (auto rs : sets) {
    std::sort(rs.begin(), rs.end());
    for (const mpq_class& lead : {mpq_class(1), mpq_class(-3, 7), mpq_class(1, 1024)}) {
      const Poly<Mpfr> p = from_roots(rs, lead);
      const std::vector<Mpfr> got = small_real_roots(p);
      REQUIRE(got.size() == rs.size());
      for (std::size_t i = 0; i < rs.size(); ++i) {
        INFO("root " << rs[i].get_str());
        CHECK(close(got[i], rs[i], kBits - 12));
      }
      // the roots of p' (irrational): the same as the old bisection's, each in its bracket between two roots of p
      const Poly<Mpfr> dp = derivative(p);
      const std::vector<Mpfr> crit = small_real_roots(dp);
      REQUIRE(crit.size() + 1 == rs.size());
      for (std::size_t i = 0; i < crit.size(); ++i) {
        const Mpfr ref = bisect(dp, M(rs[i]), M(rs[i + 1]));
        mpq_class rq;
        mpfr_get_q(rq.get_mpq_t(), ref.get());
        CHECK(close(crit[i], rq, kBits - 12));
        CHECK(M(rs[i]) < crit[i]);
        CHECK(crit[i] < M(rs[i + 1]));
      }
    }
  }
}

TEST_CASE("pencil roots in Mpfr: a triple root (p' = 0 there) still ends, inside its bracket", "[contact]") {
  // (x - 1/3)^3 (x + 2): a sign change at 1/3 where p' vanishes; the value of p near 1/3 is ~ (x - 1/3)^3, so the
  // rounded signs fix the root only to about a third of the bits.
  const Poly<Mpfr> p = from_roots({mpq_class(1, 3), mpq_class(1, 3), mpq_class(1, 3), mpq_class(-2)}, mpq_class(1));
  const std::vector<Mpfr> got = small_real_roots(p);
  REQUIRE(got.size() == 2);
  CHECK(close(got[0], mpq_class(-2), kBits - 12));
  CHECK(close(got[1], mpq_class(1, 3), kBits / 3 - 12));
}

TEST_CASE("pencil roots in double: Newton inside the sign-change bracket ends on the root", "[contact]") {
  // (x + 1/2)(x - 1/4)(x - 3): exact in double; the safeguarded Newton steps end on the root or its neighbour.
  const Poly<double> p(std::vector<double>{0.375, -0.875, -2.75, 1.0});
  const std::vector<double> got = small_real_roots(p);
  REQUIRE(got.size() == 3);
  CHECK(std::abs(got[0] + 0.5) <= 1e-15);
  CHECK(std::abs(got[1] - 0.25) <= 1e-15);
  CHECK(std::abs(got[2] - 3) <= 1e-15);
}

}  // namespace ECCD_UNITY_ID
