// Polynomials in power, Bernstein and scaled Bernstein form, in all three
// arithmetics, checked against exact rational arithmetic.
#include "kernel/bernstein.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/scaled_bernstein.hpp"
#include "kernel/sturm.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

namespace {
template <class T>
double max_diff(const Poly<T>& a, const Poly<mpq_class>& exact) {
  double m = 0;
  for (int i = 0; i <= std::max(a.degree(), exact.degree()); ++i) {
    T x = a.coeff(i) - from_q<T>(exact.coeff(i));  // the difference in T, then converted
    m = std::max(m, std::abs(to_double(x)));
  }
  return m;
}
}  // namespace

TEMPLATE_TEST_CASE("power <-> Bernstein conversion, product, elevation and derivative agree with exact power form",
                   "[kernel][bernstein]", double, Mpfr, mpq_class) {
  using T = TestType;
  std::uint64_t seed = seed_from_env(20261121);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 20; ++trial) {
    Poly<Q> p = random_poly(rng, 1 + trial % 6), q = random_poly(rng, trial % 4);
    INFO("p = " << p.c.size() << " coefficients, q = " << q.c.size());
    Bern<T> bp = to_bernstein(from_q<T>(p)), bq = to_bernstein(from_q<T>(q));
    // round trip
    CHECK(max_diff(to_power(bp), p) <= tolerance<T>() * 100);
    // the product carried out in Bernstein form is the power-form product
    Poly<Q> pq = p * q;
    CHECK(max_diff(to_power(bp * bq), pq) <= tolerance<T>() * 1000);
    // sums of different degrees (elevation inside operator+)
    CHECK(max_diff(to_power(bp + bq), p + q) <= tolerance<T>() * 100);
    CHECK(max_diff(to_power(elevate(bp, 3)), p) <= tolerance<T>() * 100);
    CHECK(max_diff(to_power(derivative(bp)), derivative(p)) <= tolerance<T>() * 1000);
    // scaled Bernstein: products are convolutions
    ScaledBern<T> sp = to_scaled(bp), sq = to_scaled(bq);
    CHECK(max_diff(to_power(to_bernstein(sp * sq)), pq) <= tolerance<T>() * 1000);
    // de Casteljau: both halves evaluate like p at the matching parameters
    T tau = from_q<T>(Q(1, 3));
    auto [l, r] = split(bp, tau);
    for (Q u : {Q(0), Q(1, 7), Q(1, 2), Q(1)}) {
      T tu = from_q<T>(u);
      Q left_t = u / 3, right_t = Q(1, 3) + u * Q(2, 3);
      T dl = l(tu) - from_q<T>(p(left_t)), dr = r(tu) - from_q<T>(p(right_t));
      CHECK(std::abs(to_double(dl)) <= tolerance<T>() * 100);
      CHECK(std::abs(to_double(dr)) <= tolerance<T>() * 100);
    }
  }
}

TEST_CASE("exact Bernstein arithmetic is exact", "[kernel][bernstein][exact]") {
  std::mt19937_64 rng(seed_from_env(7));
  for (int trial = 0; trial < 10; ++trial) {
    Poly<Q> p = random_poly(rng, 5), q = random_poly(rng, 7);
    CHECK(to_power(to_bernstein(p) * to_bernstein(q)) == p * q);
    CHECK(to_power(to_bernstein(to_scaled(to_bernstein(p)) * to_scaled(to_bernstein(q)))) == p * q);
  }
}

TEST_CASE("the cubic discriminant vanishes exactly on a double root, in every representation", "[kernel][discriminant]") {
  std::mt19937_64 rng(seed_from_env(11));
  for (int trial = 0; trial < 10; ++trial) {
    // f(λ) = (λ - r(t))² (λ - s(t)) with r, s polynomials in t: Δ ≡ 0.
    Poly<Q> r = random_poly(rng, 2), s = random_poly(rng, 1), one({Q(1)});
    Poly<Q> g3 = one, g2 = Q(-1) * (2 * r + s), g1 = r * r + 2 * (r * s), g0 = Q(-1) * (r * r * s);
    CHECK(cubic_discriminant(g3, g2, g1, g0).is_zero());
    Bern<Q> b3 = to_bernstein(g3, 0), b2 = to_bernstein(g2), b1 = to_bernstein(g1), b0 = to_bernstein(g0);
    Bern<Q> db = cubic_discriminant(b3, b2, b1, b0);
    for (const auto& c : db.b) CHECK(c == 0);
    // and the double root is P / (2D)
    Q t = Q(2, 7);
    Q lam = double_root_numerator(g3(t), g2(t), g1(t), g0(t)) / (2 * double_root_denominator(g3(t), g2(t), g1(t)));
    if (r(t) != s(t)) CHECK(lam == r(t));
  }
  // Distinct roots 1, 2, 3: Δ = ((1-2)(1-3)(2-3))² = 4.
  CHECK(cubic_discriminant(Q(1), Q(-6), Q(11), Q(-6)) == 4);
}

TEMPLATE_TEST_CASE("Sturm counts distinct real roots of a square-free polynomial", "[kernel][sturm]", double, Mpfr, mpq_class) {
  using T = TestType;
  // (t - 1/3) (t - 1/2) (t + 2) (t - 3/2)
  Poly<Q> p = Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 2), Q(1)}) * Poly<Q>({Q(2), Q(1)}) * Poly<Q>({Q(-3, 2), Q(1)});
  CHECK(count_roots_closed(from_q<T>(p), from_q<T>(Q(0)), from_q<T>(Q(1))) == 2);
  CHECK(count_roots<T>(from_q<T>(p), std::optional<T>(), std::optional<T>(from_q<T>(Q(0)))) == 1);
  CHECK(count_roots<T>(from_q<T>(p), std::optional<T>(), std::optional<T>()) == 4);
  CHECK(count_roots_closed(from_q<T>(p), from_q<T>(Q(2, 5)), from_q<T>(Q(1))) == 1);
  if constexpr (scalar_traits<T>::is_exact)  // a root exactly at an end: decidable only exactly
    CHECK(count_roots_closed(from_q<T>(p), from_q<T>(Q(1, 2)), from_q<T>(Q(1))) == 1);
}

TEST_CASE("exact Sturm counts distinct roots of a polynomial with a multiple root", "[kernel][sturm][exact]") {
  // (t - 1/3)² (t - 1/2) (t + 2): distinct roots in [0, 1]: 1/3 and 1/2. (In
  // rounded arithmetic a multiple root makes the Sturm sequence ill-posed.)
  Poly<Q> p = Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 2), Q(1)}) * Poly<Q>({Q(2), Q(1)});
  CHECK(count_roots_closed(p, Q(0), Q(1)) == 2);
  CHECK(count_roots<Q>(p, std::optional<Q>(), std::optional<Q>(Q(0))) == 1);
  CHECK(count_roots<Q>(p, std::optional<Q>(), std::optional<Q>()) == 3);
  CHECK(count_roots_closed(p, Q(1, 3), Q(1, 2)) == 2);
}
