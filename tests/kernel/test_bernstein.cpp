// Polynomials in Bernstein and scaled Bernstein form (kernel/bernstein.hpp,
// kernel/scaled_bernstein.hpp), in all three arithmetics, checked against
// exact rational arithmetic in power form; de Casteljau in place checked bit
// for bit against the triangle computed step by step.
#include "kernel/bernstein.hpp"
#include "kernel/scaled_bernstein.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <span>
#include <type_traits>
#include <utility>

namespace ECCD_UNITY_ID {
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

namespace {
// Same value and, for Mpfr, same precision: bit for bit what the uncached code computed.
template <class T>
bool same(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, Mpfr>)
    return a.precision() == b.precision() && mpfr_equal_p(a.get(), b.get());
  else
    return a == b;
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

}  // namespace ECCD_UNITY_ID
