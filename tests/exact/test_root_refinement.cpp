// Exact root refinement on dyadic brackets (exact/root_refinement.hpp),
// against mpq_class arithmetic on integer polynomials whose roots are known:
// products of linear factors d x - n (rational roots n / d) and of x^2 - c
// (irrational roots ±√c, located by exact signs).
//   - eval_dyadic is 2^(k n) f(a / 2^k) and sign_at_rational the sign of
//     f(x), both recomputed in mpq_class; dyadic_parts and dyadic invert
//     each other, and refuse a denominator that is not a power of two;
//   - Refiner (QIR, Abbott 2006): from isolating brackets with rational or
//     dyadic ends, refined to 2^-bits, the bracket (A / 2^k, B / 2^k) still
//     holds the root (exactly known, or by the sign of x^2 - c), its FA and
//     FB are f's scaled values at the ends (nonzero, opposite signs, checked
//     in mpq_class), its width is at most 2^-bits; a root on the dyadic grid
//     is returned exactly; a bracket that is not isolating is refused;
//   - is_root (rational root test) agrees with evaluation; certainly_square_free
//     never certifies a polynomial with a square factor and certifies
//     square-free products; compare_root agrees with the known root;
//   - constant_sign: a nonzero answer is the sign of Q on the whole closed
//     bracket (Q's roots are known: none inside, sign at the mid-point), and
//     brackets far from Q's roots get an answer;
//   - a passed deadline (kernel/budget.hpp) stops init and refine with
//     BudgetExhausted, leaving a bracket that still isolates the root.
#include "exact/root_refinement.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::root_refinement;

namespace {

IntPoly mul(const IntPoly& a, const IntPoly& b) {
  IntPoly r(a.size() + b.size() - 1, mpz_class(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

mpq_class value(const IntPoly& f, const mpq_class& x) {
  mpq_class r = 0, p = 1;
  for (const auto& c : f) {
    r += c * p;
    p *= x;
  }
  return r;
}

mpq_class dy(const mpz_class& a, unsigned long k) {
  mpq_class q(a, mpz_class(1) << k);
  q.canonicalize();  // gmpxx's (num, den) constructor does not
  return q;
}

int sgn_q(const mpq_class& q) { return sgn(q); }

// Checks a refined bracket of f against the root predicate `below(x)`: true when x < the root.
template <class Below>
void check_bracket(const IntPoly& f, const Dyadic& d, long bits, Below below) {
  const unsigned long n = f.size() - 1;
  const mpq_class lo = dy(d.A, d.k), hi = dy(d.B, d.k);
  INFO("bracket (" << lo << ", " << hi << ")");
  REQUIRE(d.A < d.B);
  const mpq_class scale(mpz_class(1) << (d.k * n));
  CHECK(mpq_class(d.FA) == scale * value(f, lo));
  CHECK(mpq_class(d.FB) == scale * value(f, hi));
  CHECK(sgn(d.FA) != 0);
  CHECK(sgn(d.FA) == -sgn(d.FB));
  CHECK(below(lo));
  CHECK_FALSE(below(hi));
  CHECK(hi - lo <= mpq_class(1, mpz_class(1) << bits));
}

}  // namespace

TEST_CASE("root_refinement eval_dyadic, sign_at_rational and the dyadic helpers are exact",
          "[exact][root_refinement]") {
  SeededRng rng{4711};
  for (int trial = 0; trial < 40; ++trial) {
    IntPoly f;
    const int n = int(rng.uniform(0, 6));
    for (int i = 0; i <= n; ++i) f.push_back(mpz_class(rng.uniform(-1000, 1000)));
    if (f.back() == 0) f.back() = 7;
    const mpz_class a(rng.uniform(-5000, 5000));
    const unsigned long k = static_cast<unsigned long>(rng.uniform(0, 70));
    mpz_class out;
    eval_dyadic(out, f, a, k);
    CHECK(mpq_class(out) == mpq_class(mpz_class(1) << (k * unsigned(n))) * value(f, dy(a, k)));
    const mpq_class x = rng.frac(-3000, 3000, rng.uniform(1, 999));
    CHECK(sign_at_rational(f, x) == sgn_q(value(f, x)));
  }
  CHECK(sign_at_rational(IntPoly{}, mpq_class(3)) == 0);
  CHECK(sign_at_rational(IntPoly{-6, 1, 1}, mpq_class(2)) == 0);  // (x + 3)(x - 2)
  CHECK(sign_at_rational(IntPoly{-6, 1, 1}, mpq_class(-7, 2)) == 1);

  mpz_class a;
  unsigned long j = 99;
  REQUIRE(dyadic_parts(mpq_class(-5, 8), a, j));
  CHECK(a == -5);
  CHECK(j == 3);
  CHECK(dyadic(a, j) == mpq_class(-5, 8));
  REQUIRE(dyadic_parts(mpq_class(12), a, j));
  CHECK((a == 12 && j == 0));
  REQUIRE(dyadic_parts(mpq_class(0), a, j));
  CHECK((a == 0 && j == 0));
  CHECK_FALSE(dyadic_parts(mpq_class(1, 3), a, j));
  CHECK_FALSE(dyadic_parts(mpq_class(5, 12), a, j));
  CHECK(dyadic(mpz_class(6), 2) == mpq_class(3, 2));
}

TEST_CASE("root_refinement Refiner keeps the exact rational root in its bracket", "[exact][root_refinement]") {
  SeededRng rng{4712};
  long exact_hits = 0, refined = 0;
  for (int trial = 0; trial < 30; ++trial) {
    // three distinct roots n / d with small d (some dyadic, found exactly), square-free product
    std::vector<mpq_class> roots;
    IntPoly f{1};
    while (roots.size() < 3) {
      mpq_class r = rng.frac(-200, 200, rng.uniform(1, 12));
      bool fresh = true;
      for (const auto& s : roots) fresh = fresh && s != r;
      if (!fresh) continue;
      roots.push_back(r);
      f = mul(f, IntPoly{-r.get_num(), r.get_den()});
    }
    std::sort(roots.begin(), roots.end());
    for (std::size_t i = 0; i < roots.size(); ++i) {
      // an isolating bracket with rational ends between the neighbours
      const mpq_class lo =
          i == 0 ? mpq_class(roots[0] - mpq_class(1, 7)) : mpq_class((2 * roots[i - 1] + roots[i]) / 3);
      const mpq_class hi =
          i + 1 == roots.size() ? mpq_class(roots[i] + mpq_class(2, 9)) : mpq_class((roots[i] + 2 * roots[i + 1]) / 3);
      if (sign_at_rational(f, lo) == 0 || sign_at_rational(f, hi) == 0) continue;
      Refiner R(f);
      Dyadic d;
      std::optional<Rational> exact;
      const long bits = rng.uniform(5, 120);
      bool ok = R.init(lo, hi, d, exact);
      if (ok) ok = R.refine(d, bits, exact);
      if (!ok) {
        REQUIRE(exact);
        CHECK(*exact == roots[i]);
        ++exact_hits;
        continue;
      }
      ++refined;
      check_bracket(f, d, bits, [&](const mpq_class& x) { return x < roots[i]; });
    }
  }
  CHECK(refined >= 30);
  CHECK(exact_hits >= 5);  // roots with power-of-two denominators land on the grid
}

TEST_CASE("root_refinement Refiner narrows brackets of irrational roots", "[exact][root_refinement]") {
  // f = (x^2 - c)(3x - 1): roots ±√c and 1/3; √c for c = 2, 3, 5, 7, 1000003 (no grid point is a root)
  for (long c : {2L, 3L, 5L, 7L, 1000003L}) {
    const IntPoly f = mul(IntPoly{-c, 0, 1}, IntPoly{-1, 3});
    const double r = std::sqrt(double(c));
    for (long bits : {1L, 10L, 64L, 300L, 2000L}) {
      for (int side : {1, -1}) {
        // rational ends around ±√c, away from 1/3
        const mpq_class lo = side > 0 ? mpq_class(std::floor(r)) : mpq_class(-std::ceil(r) - mpq_class(1, 3));
        const mpq_class hi = side > 0 ? mpq_class(std::ceil(r) + mpq_class(1, 5)) : mpq_class(-std::floor(r));
        Refiner R(f);
        Dyadic d;
        std::optional<Rational> exact;
        REQUIRE(R.init(lo, hi, d, exact));
        REQUIRE(R.refine(d, bits, exact));
        // x < side √c iff (side > 0: x < 0 or x^2 < c; side < 0: x < 0 and x^2 > c)
        auto below = [&](const mpq_class& x) { return side > 0 ? (x < 0 || x * x < c) : (x < 0 && x * x > c); };
        INFO("c = " << c << ", bits = " << bits << ", side " << side);
        check_bracket(f, d, bits, below);
        // refining an already narrow bracket further keeps it
        REQUIRE(R.refine(d, bits + 7, exact));
        check_bracket(f, d, bits + 7, below);
      }
    }
  }
}

TEST_CASE("root_refinement Refiner refuses a bracket that is not isolating", "[exact][root_refinement]") {
  const IntPoly f = mul(IntPoly{-1, 3}, IntPoly{-2, 1});  // roots 1/3 and 2
  Refiner R(f);
  Dyadic d;
  std::optional<Rational> exact;
  // f > 0 below 1/3, f < 0 on (1/3, 2), f > 0 above 2
  CHECK_THROWS_AS(R.init(mpq_class(0), mpq_class(3), d, exact), std::logic_error);        // two roots, dyadic ends
  CHECK_THROWS_AS(R.init(mpq_class(1, 2), mpq_class(3, 2), d, exact), std::logic_error);  // none, dyadic ends
  CHECK_THROWS_AS(R.init(mpq_class(1, 3), mpq_class(1), d, exact), std::logic_error);     // a root at an end
  CHECK_THROWS_AS(R.init(mpq_class(2, 5), mpq_class(7, 5), d, exact), std::logic_error);  // none, rational ends
  REQUIRE_NOTHROW(R.init(mpq_class(1, 10), mpq_class(5, 10), d, exact));
  REQUIRE_NOTHROW(R.init(mpq_class(1, 4), mpq_class(1, 2), d, exact));
}

TEST_CASE("root_refinement is_root, certainly_square_free and compare_root", "[exact][root_refinement]") {
  SeededRng rng{4713};
  // 6x^3 - 5x^2 - 2x + 1 = (x - 1)(2x + 1)(3x - 1)
  const IntPoly f = mul(mul(IntPoly{-1, 1}, IntPoly{1, 2}), IntPoly{-1, 3});
  for (int k = 0; k < 200; ++k) {
    const mpq_class q = rng.frac(-12, 12, rng.uniform(1, 6));
    CHECK(is_root(f, q) == (value(f, q) == 0));
  }
  CHECK(is_root(f, mpq_class(-1, 2)));
  CHECK(is_root(IntPoly{0, 5, 1}, mpq_class(0)));
  CHECK_FALSE(is_root(f, mpq_class(0)));

  CHECK(certainly_square_free(f));
  CHECK(certainly_square_free(IntPoly{-2, 0, 1}));
  CHECK_FALSE(certainly_square_free(IntPoly{5}));                                 // degree 0
  CHECK_FALSE(certainly_square_free(mul(f, IntPoly{1, 2})));                      // (2x + 1)^2
  CHECK_FALSE(certainly_square_free(mul(IntPoly{-2, 0, 1}, IntPoly{-2, 0, 1})));  // (x^2 - 2)^2
  for (int trial = 0; trial < 40; ++trial) {
    IntPoly g{1};
    std::vector<mpq_class> roots;
    for (int i = 0; i < 4; ++i) {
      const mpq_class r = rng.frac(-50, 50, rng.uniform(1, 9));
      roots.push_back(r);
      g = mul(g, IntPoly{-r.get_num(), r.get_den()});
    }
    bool distinct = true;
    for (std::size_t i = 0; i < roots.size(); ++i)
      for (std::size_t j = i + 1; j < roots.size(); ++j) distinct = distinct && roots[i] != roots[j];
    // never claims square-free for a repeated root; for distinct ones the modular gcd is 1 unless the
    // prime near 2^62 divides the discriminant (not so for these seeded polynomials)
    if (!distinct) CHECK_FALSE(certainly_square_free(g));
    if (distinct) CHECK(certainly_square_free(g));
  }

  // the root 1/3 of f in the bracket (0, 1/2), f(0) = 1 > 0
  const mpq_class lo(0), hi(1, 2);
  for (int k = 0; k < 100; ++k) {
    const mpq_class c = rng.frac(-20, 40, rng.uniform(1, 40));
    const int want = c < mpq_class(1, 3) ? 1 : c == mpq_class(1, 3) ? 0 : -1;
    CHECK(compare_root(f, lo, hi, 1, c) == want);
  }
  CHECK(compare_root(f, lo, hi, 1, mpq_class(1, 3)) == 0);
}

TEST_CASE("root_refinement constant_sign proves only true signs", "[exact][root_refinement]") {
  SeededRng rng{4714};
  long proved = 0, asked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<mpq_class> roots;
    IntPoly Q{long(rng.uniform(1, 3)) * (rng.uniform(0, 1) ? 1 : -1)};
    const int deg = int(rng.uniform(1, 9));
    for (int i = 0; i < deg; ++i) {
      const mpq_class r = rng.frac(-40, 40, rng.uniform(1, 16));
      roots.push_back(r);
      Q = mul(Q, IntPoly{-r.get_num(), r.get_den()});
    }
    for (int b = 0; b < 20; ++b) {
      Dyadic d;
      d.k = static_cast<unsigned long>(rng.uniform(0, 12));
      d.A = rng.uniform(-45L << d.k, 45L << d.k);
      d.B = d.A + rng.uniform(1, 64);
      const mpq_class lo = dy(d.A, d.k), hi = dy(d.B, d.k);
      bool root_inside = false;
      for (const auto& r : roots) root_inside = root_inside || (lo <= r && r <= hi);
      const int s = constant_sign(Q, d);
      ++asked;
      if (s != 0) {
        ++proved;
        INFO("Q of degree " << deg << " on [" << lo << ", " << hi << "]");
        CHECK_FALSE(root_inside);
        CHECK(s == sgn_q(value(Q, (lo + hi) / 2)));
        CHECK(s == sgn_q(value(Q, lo)));
        CHECK(s == sgn_q(value(Q, hi)));
      }
    }
  }
  CHECK(proved >= asked / 4);
  // a line far from its root: the mean-value bound already decides
  Dyadic d;
  d.k = 4;
  d.A = 0;
  d.B = 16;
  CHECK(constant_sign(IntPoly{-10, 1}, d) == -1);
  CHECK(constant_sign(IntPoly{10, 1}, d) == 1);
  // a root at an end of the closed bracket: never a sign
  CHECK(constant_sign(IntPoly{-1, 1}, d) == 0);
  CHECK(constant_sign(IntPoly{0, 1}, d) == 0);
}

TEST_CASE("root_refinement stops at a passed deadline with BudgetExhausted", "[exact][root_refinement]") {
  const IntPoly f = mul(IntPoly{-2, 0, 1}, IntPoly{-1, 3});  // roots ±√2, 1/3
  Refiner R(f);
  Dyadic d;
  std::optional<Rational> exact;
  REQUIRE(R.init(mpq_class(1), mpq_class(2), d, exact));
  {
    ScopedDeadline gone(1e-9);
    while (!deadline_passed()) {}
    CHECK_THROWS_AS(R.refine(d, 100, exact), BudgetExhausted);
    Dyadic d2;
    CHECK_THROWS_AS(R.init(mpq_class(11, 10), mpq_class(19, 10), d2, exact), BudgetExhausted);
  }
  // the bracket is still an isolating bracket of √2 and refines once the deadline is gone
  REQUIRE(R.refine(d, 100, exact));
  check_bracket(f, d, 100, [](const mpq_class& x) { return x < 0 || x * x < 2; });
}

}  // namespace ECCD_UNITY_ID
