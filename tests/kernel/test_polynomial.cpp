// Polynomials in power, Bernstein and scaled Bernstein form, in all three
// arithmetics, checked against exact rational arithmetic; the allocation-free
// paths (cached binomial rows, de Casteljau in place, fixed-capacity Sturm)
// checked bit for bit against the straightforward computations.
#include "kernel/bernstein.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/scaled_bernstein.hpp"
#include "kernel/sturm.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <random>
#include <span>
#include <type_traits>
#include <utility>

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

TEST_CASE("the cubic discriminant vanishes exactly on a double root, in every representation",
          "[kernel][discriminant]") {
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

TEMPLATE_TEST_CASE("Sturm counts distinct real roots of a square-free polynomial", "[kernel][sturm]", double, Mpfr,
                   mpq_class) {
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

namespace {
// The pre-cache Pascal rule (binomial.hpp before the rows were cached): the oracle for the cache.
template <class T>
std::vector<T> pascal_row_uncached(int n, const T& like) {
  T one = scalar_traits<T>::from_rational(mpq_class(1), like);
  std::vector<T> row(1, one);
  for (int m = 1; m <= n; ++m) {
    std::vector<T> next(m + 1, one);
    for (int k = 1; k < m; ++k) next[k] = row[k - 1] + row[k];
    row = std::move(next);
  }
  return row;
}
// Same value and, for Mpfr, same precision: bit for bit what the uncached code computed.
template <class T>
bool same(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, Mpfr>)
    return a.precision() == b.precision() && mpfr_equal_p(a.get(), b.get());
  else
    return a == b;
}
}  // namespace

TEMPLATE_TEST_CASE(
    "binomial rows from the per-thread cache equal Pascal's rule afresh, degrees and precisions interleaved",
    "[kernel][binomial]", double, Mpfr, mpq_class) {
  using T = TestType;
  std::vector<T> likes{like<T>()};
  if constexpr (std::is_same_v<T, Mpfr>)
    likes = {Mpfr(mpq_class(1), 64), Mpfr(mpq_class(1), 200), Mpfr(3), Mpfr(mpq_class(1), 64)};
  for (int n : {60, 3, 0, 150, 57, 1, 149, 200, 56}) {
    for (const T& lk : likes) {
      INFO("n = " << n << ", precision " << scalar_traits<T>::precision(lk));
      const std::vector<T>& row = binomial_row(n, lk);
      std::vector<T> ref = pascal_row_uncached(n, lk);
      REQUIRE(row.size() == ref.size());
      bool all = true;
      for (std::size_t k = 0; k < ref.size(); ++k) all = all && same(row[k], ref[k]);
      CHECK(all);
    }
  }
  // A reference stays valid while later calls extend the cache.
  const std::vector<T>& r10 = binomial_row(10, likes.front());
  (void)binomial_row(400, likes.front());
  CHECK(to_double(r10[5]) == 252.0);
}

TEMPLATE_TEST_CASE(
    "de Casteljau in place (bernstein_value, keep_left, keep_right, split) equals the triangle step by step",
    "[kernel][bernstein]", double, Mpfr, mpq_class) {
  using T = TestType;
  std::mt19937_64 rng(seed_from_env(424242));
  for (int n : {0, 1, 4, 36, 63, 64, 100}) {
    Poly<Q> p = random_poly(rng, n);
    std::vector<T> b = to_bernstein(from_q<T>(p), n).b;
    for (Q tq : {Q(0), Q(1, 3), Q(7, 8), Q(1)}) {
      T tau = from_q<T>(tq);
      INFO("degree " << n << ", tau = " << tq.get_str());
      // the triangle as split() computed it before (one working row w, pieces read off its ends)
      std::vector<T> w = b, left(n + 1), right(n + 1);
      left[0] = w[0];
      right[n] = w[n];
      T s = T(1) - tau;
      for (int r = 1; r <= n; ++r) {
        for (int i = 0; i + r <= n; ++i) {
          T x = s * w[i];
          T y = tau * w[i + 1];
          w[i] = x + y;
        }
        left[r] = w[0];
        right[n - r] = w[n - r];
      }
      CHECK(same(bernstein_value(std::span<const T>(b), tau), left[n]));
      std::vector<T> kl = b, kr = b;
      keep_left(std::span<T>(kl), tau);
      keep_right(std::span<T>(kr), tau);
      auto [sl, sr] = split(Bern<T>(b), tau);
      bool all = true;
      for (int i = 0; i <= n; ++i)
        all = all && same(kl[i], left[i]) && same(kr[i], right[i]) && same(sl.b[i], left[i]) && same(sr.b[i], right[i]);
      CHECK(all);
    }
  }
}

TEMPLATE_TEST_CASE("fixed-capacity Sturm (count_roots_inline) counts as the Poly<T> version", "[kernel][sturm]", double,
                   Mpfr, mpq_class) {
  using T = TestType;
  std::mt19937_64 rng(seed_from_env(31337));
  for (int trial = 0; trial < 200; ++trial) {
    Poly<Q> pq = random_poly(rng, trial % 5);
    if (trial % 7 == 0)
      pq = Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 3), Q(1)}) * random_poly(rng, trial % 3);  // a double root
    std::vector<T> c;
    for (int i = 0; i <= 4; ++i) c.push_back(from_q<T>(pq.coeff(i)));  // zero leading coefficients included
    Poly<T> p(c);
    INFO("trial " << trial << ", degree " << pq.degree());
    for (auto [a, b] : {std::pair<std::optional<Q>, std::optional<Q>>{std::nullopt, Q(0)},
                        {std::nullopt, std::nullopt},
                        {Q(-1), Q(1, 3)},
                        {Q(0), Q(1)}}) {
      std::optional<T> at = a ? std::optional<T>(from_q<T>(*a)) : std::nullopt;
      std::optional<T> bt = b ? std::optional<T>(from_q<T>(*b)) : std::nullopt;
      CHECK(count_roots_inline<5, T>(std::span<const T>(c), at, bt) == count_roots(p, at, bt));
    }
  }
  if constexpr (scalar_traits<T>::is_exact) {
    // (t - 1/3)² (t + 2): the gcd division counts the double root at an end once
    Poly<Q> p = Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(2), Q(1)});
    CHECK(count_roots_inline<5, Q>(std::span<const Q>(p.c), Q(-3), Q(1, 3)) == 2);
    CHECK(count_roots_inline<5, Q>(std::span<const Q>(p.c), Q(1, 3), std::nullopt) == 0);
  }
  if constexpr (std::is_same_v<T, double>) {  // an uncertain sign (NaN): no count, as for intervals
    std::vector<double> c{1.0, std::nan(""), -3.0, 0.5, 1.0};
    CHECK(count_roots_inline<5, double>(std::span<const double>(c), std::nullopt, 0.0) == -2);
    CHECK(count_roots(Poly<double>(c), std::optional<double>(), std::optional<double>(0.0)) == -2);
  }
  std::vector<T> zero(3, from_q<T>(Q(0)));
  CHECK(count_roots_inline<5, T>(std::span<const T>(zero), std::nullopt, std::nullopt) == -1);
  std::vector<T> six(6, from_q<T>(Q(1)));
  auto too_many = [&] { return count_roots_inline<5, T>(std::span<const T>(six), std::nullopt, std::nullopt); };
  CHECK_THROWS_AS(too_many(), std::length_error);
}
