// The certificate checker's rational polynomials (certificate/check/qpoly.hpp),
// on products of (d x - n)^m with known rational roots n/d and multiplicities m
// (and an irreducible x² + 1 factor), everything decided in mpq_class:
//   - ring operations and divmod (a = q b + r, deg r < deg b), derivative,
//     gcd = the monic product of the common factors with their smaller
//     multiplicities; division by zero refused;
//   - interpolate_at_integers returns the polynomial through (k, p(k));
//   - integer_multiple / denominator_lcm: l p with integer coefficients;
//     value_at (small and huge integer points), sign_at and scaled_value_at
//     (b^n p(a/b));
//   - sign_on_bracket: a nonzero sign holds at every point of the bracket
//     (no root inside; checked at the ends, the mid-point and the roots);
//   - descartes(p, lo, hi): at least the number of roots in (lo, hi) with
//     multiplicity, of the same parity (so 0 means none and 1 exactly one);
//   - negative_roots and roots_between (Sturm): the number of distinct roots,
//     exactly; bad input (p(0) = 0, a root at an end, an empty interval)
//     refused.
#include "certificate/check/qpoly.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using eccd::check::QPoly;

namespace {

struct Known {
  QPoly p;
  std::map<mpq_class, int> roots;  // root -> multiplicity
};

QPoly linear(const mpq_class& r) {  // d x - n, r = n / d
  return QPoly(std::vector<mpq_class>{mpq_class(-r.get_num()), mpq_class(r.get_den())});
}

Known random_known(SeededRng& rng) {
  Known k;
  k.p = QPoly::constant(rng.frac(1, 9, rng.uniform(1, 5)) * (rng.uniform(0, 1) ? 1 : -1));
  const int factors = int(rng.uniform(1, 5));
  for (int i = 0; i < factors; ++i) {
    const mpq_class r = rng.frac(-30, 30, rng.uniform(1, 7));
    const int m = int(rng.uniform(1, 3));
    for (int j = 0; j < m; ++j) k.p = k.p * linear(r);
    k.roots[r] += m;
  }
  if (rng.uniform(0, 2) == 0) k.p = k.p * QPoly(std::vector<mpq_class>{1, 0, 1});  // x² + 1: no real root
  return k;
}

}  // namespace

TEST_CASE("check QPoly arithmetic, divmod, gcd and interpolation are exact", "[certificate][qpoly]") {
  SeededRng rng{101};
  for (int trial = 0; trial < 60; ++trial) {
    const Known a = random_known(rng), b = random_known(rng);
    QPoly q, r;
    check::divmod(a.p, b.p, q, r);
    CHECK(q * b.p + r == a.p);
    CHECK(r.degree() < b.p.degree());
    // gcd: the common roots with the smaller multiplicity (x² + 1 when both have it), monic
    QPoly want = QPoly::constant(1);
    for (const auto& [root, m] : a.roots) {
      auto it = b.roots.find(root);
      if (it == b.roots.end()) continue;
      for (int j = 0; j < std::min(m, it->second); ++j) want = want * linear(root);
    }
    QPoly ga = check::gcd(a.p, b.p);
    // divide out x² + 1 if it is common (the only non-linear factor)
    const QPoly x2p1(std::vector<mpq_class>{1, 0, 1});
    QPoly qa, ra, qb, rb;
    check::divmod(a.p, x2p1, qa, ra);
    check::divmod(b.p, x2p1, qb, rb);
    if (ra.zero() && rb.zero()) want = want * x2p1;
    want = mpq_class(1 / want.lead()) * want;
    CHECK(ga == want);
    CHECK(ga.lead() == 1);
    // derivative of a product: (a b)' = a' b + a b'
    CHECK(check::derivative(a.p * b.p) == check::derivative(a.p) * b.p + a.p * check::derivative(b.p));
    // interpolation through (k, p(k)), k = 0..deg
    std::vector<mpq_class> values;
    for (int k = 0; k <= a.p.degree(); ++k) values.push_back(a.p(mpq_class(k)));
    CHECK(check::interpolate_at_integers(values) == a.p);
  }
  QPoly q, r;
  CHECK_THROWS_AS(check::divmod(QPoly::constant(1), QPoly(), q, r), std::domain_error);
  CHECK(check::gcd(QPoly(), QPoly()).zero());
  CHECK(check::gcd(QPoly(std::vector<mpq_class>{2, 4}), QPoly()) == QPoly(std::vector<mpq_class>{mpq_class(1, 2), 1}));
  CHECK(QPoly(std::vector<mpq_class>{1, 2, 0, 0}).degree() == 1);  // trimmed
  CHECK(check::interpolate_at_integers({}).zero());
  CHECK(check::interpolate_at_integers({5}) == QPoly::constant(5));
}

TEST_CASE("check QPoly integer multiples and exact signs at rationals", "[certificate][qpoly]") {
  SeededRng rng{102};
  for (int trial = 0; trial < 60; ++trial) {
    const Known k = random_known(rng);
    const mpz_class l = check::denominator_lcm(k.p);
    const std::vector<mpz_class> z = check::integer_multiple(k.p, l);
    REQUIRE(z.size() == k.p.c.size());
    for (std::size_t i = 0; i < z.size(); ++i) CHECK(mpq_class(z[i]) == l * k.p.c[i]);
    for (int j = 0; j < 10; ++j) {
      const mpq_class x = rng.frac(-40, 40, rng.uniform(1, 12));
      const mpq_class v = k.p(x);
      CHECK(check::sign_at(z, x) == sgn(v));
      mpz_class bn;
      mpz_pow_ui(bn.get_mpz_t(), x.get_den_mpz_t(), (unsigned long)(z.size() - 1));
      CHECK(mpq_class(check::scaled_value_at(z, x)) == l * v * bn);
      const mpz_class t(rng.uniform(-50, 50));
      CHECK(mpq_class(check::value_at(z, t)) == l * k.p(mpq_class(t)));
    }
    const mpz_class big = mpz_class(1) << 100;  // beyond a long: the general path
    CHECK(mpq_class(check::value_at(z, big)) == l * k.p(mpq_class(big)));
    for (const auto& [root, m] : k.roots) CHECK(check::sign_at(z, root) == 0);
  }
  CHECK(check::sign_at({}, mpq_class(1, 2)) == 0);
}

TEST_CASE("check QPoly sign_on_bracket proves only true signs", "[certificate][qpoly]") {
  SeededRng rng{103};
  long proved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Known k;
    k.p = QPoly::constant(1);
    for (int i = 0; i < int(rng.uniform(1, 4)); ++i) {
      const mpq_class r = rng.frac(-20, 20, 20);  // roots in [-1, 1]
      k.p = k.p * linear(r);
      k.roots[r] += 1;
    }
    const std::vector<mpz_class> z = check::integer_multiple(k.p, check::denominator_lcm(k.p));
    const mpq_class lo = rng.frac(-100, 99, 100);
    const mpq_class hi = lo + rng.frac(1, 20, 1000);
    if (hi > 1) continue;
    const int s = check::sign_on_bracket(z, lo, hi);
    if (s == 0) continue;
    ++proved;
    INFO("[" << lo << ", " << hi << "]");
    for (const auto& [root, m] : k.roots) CHECK_FALSE((lo <= root && root <= hi));
    CHECK(sgn(k.p(lo)) == s);
    CHECK(sgn(k.p(hi)) == s);
    CHECK(sgn(k.p((lo + hi) / 2)) == s);
  }
  CHECK(proved >= 40);
  // outside [-1, 1] or reversed: no answer
  const std::vector<mpz_class> z{-10, 1};  // x - 10
  CHECK(check::sign_on_bracket(z, mpq_class(0), mpq_class(1, 2)) == -1);
  CHECK(check::sign_on_bracket(z, mpq_class(1, 2), mpq_class(2)) == 0);
  CHECK(check::sign_on_bracket(z, mpq_class(1, 2), mpq_class(0)) == 0);
  CHECK(check::sign_on_bracket({}, mpq_class(0), mpq_class(1, 2)) == 0);
}

TEST_CASE("check QPoly root counts: Descartes' bound and Sturm's exact counts", "[certificate][qpoly]") {
  SeededRng rng{104};
  for (int trial = 0; trial < 150; ++trial) {
    const Known k = random_known(rng);
    mpq_class lo = rng.frac(-35, 35, rng.uniform(1, 5)), hi = rng.frac(-35, 35, rng.uniform(1, 5));
    if (lo == hi) continue;
    if (hi < lo) std::swap(lo, hi);
    int with_mult = 0, distinct = 0, negative = 0;
    bool root_at_end = false, root_at_zero = false;
    for (const auto& [root, m] : k.roots) {
      if (lo < root && root < hi) {
        with_mult += m;
        ++distinct;
      }
      if (root == lo || root == hi) root_at_end = true;
      if (root < 0) ++negative;
      if (root == 0) root_at_zero = true;
    }
    INFO("(" << lo << ", " << hi << "), degree " << k.p.degree());
    const int v = check::descartes(k.p, lo, hi);
    CHECK(v >= with_mult);
    CHECK((v - with_mult) % 2 == 0);
    if (!root_at_end) CHECK(check::roots_between(k.p, lo, hi) == distinct);
    if (root_at_end) CHECK_THROWS_AS(check::roots_between(k.p, lo, hi), std::domain_error);
    if (!root_at_zero) CHECK(check::negative_roots(k.p) == negative);
    if (root_at_zero) CHECK_THROWS_AS(check::negative_roots(k.p), std::domain_error);
  }
  // Descartes is exact on a simple root in a small interval and on none
  const QPoly p = linear(mpq_class(1, 3)) * linear(mpq_class(2, 3)) * linear(mpq_class(-5));
  CHECK(check::descartes(p, mpq_class(0), mpq_class(1, 2)) == 1);
  CHECK(check::descartes(p, mpq_class(3, 4), mpq_class(1)) == 0);
  CHECK_THROWS_AS(check::descartes(p, mpq_class(1), mpq_class(1)), std::domain_error);
  CHECK(check::descartes(QPoly::constant(3), mpq_class(0), mpq_class(1)) == 0);
  CHECK(check::negative_roots(QPoly::constant(3)) == 0);
}

}  // namespace ECCD_UNITY_ID
