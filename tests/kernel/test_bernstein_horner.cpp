// BernsteinHorner (kernel/bernstein_horner.hpp, issue 21): the O(n) value of a
// Bernstein polynomial against its exact rational value, for degrees 1..300,
// in double (the error bound the header states), Bounded<double> (the running
// bound contains the exact value) and MPFR at 200 bits; and its fallbacks to
// de Casteljau outside the degree range and on overflow.
#include "kernel/bernstein_horner.hpp"
#include "number/running_error.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <span>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// p(t) exactly: sum b_i C(n,i) t^i (1-t)^(n-i), and the condition sum |b_i| C(n,i) t^i (1-t)^(n-i).
std::pair<mpq_class, mpq_class> exact_value(const std::vector<double>& b, const mpq_class& t) {
  const int n = int(b.size()) - 1;
  std::vector<mpq_class> tp(n + 1, mpq_class(1)), up(n + 1, mpq_class(1));
  const mpq_class u = 1 - t;
  for (int i = 1; i <= n; ++i) {
    tp[i] = tp[i - 1] * t;
    up[i] = up[i - 1] * u;
  }
  mpz_class c = 1;  // C(n, i)
  mpq_class v = 0, cond = 0;
  for (int i = 0; i <= n; ++i) {
    mpq_class w = mpq_class(c) * tp[i] * up[n - i];
    v += mpq_class(b[i]) * w;
    cond += mpq_class(std::fabs(b[i])) * w;
    c = c * (n - i) / (i + 1);
  }
  return {v, cond};
}

std::vector<int> degrees() {
  std::vector<int> d;
  for (int n = 1; n <= 40; ++n) d.push_back(n);
  for (int n = 47; n <= 300; n += 23) d.push_back(n);
  d.push_back(144);  // Δ of the 2D degree-6 pipeline
  d.push_back(300);
  return d;
}

std::vector<double> points(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> t = {0.0, 1.0, 0.5, 0x1p-20, 1.0 - 0x1p-20, 0.5 + 0x1p-40};
  for (int k = 0; k < 4; ++k) t.push_back(U(rng));
  return t;
}

}  // namespace

TEST_CASE("BernsteinHorner in double is within its stated bound of the exact value, degrees 1..300",
          "[kernel][bernstein][bernstein_horner]") {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> C(-1.0, 1.0);
  int linear_used = 0;
  for (int n : degrees()) {
    std::vector<double> b(n + 1);
    for (auto& x : b) x = C(rng);
    const BernsteinHorner<double> h{std::span<const double>(b)};
    CHECK(h.linear() == (n >= 16));
    linear_used += h.linear();
    for (double t : points(rng)) {
      const auto [v, cond] = exact_value(b, mpq_class(t));
      const double got = h(t);
      // The header's bound: γ_(c n) · sum |b_i| B_i(t) with c about 5; checked with c = 6 (and n + 2 for n small).
      const mpq_class bound = mpq_class(6.0 * (n + 2) * 0x1p-53) * cond;
      INFO("n = " << n << ", t = " << t << ", got " << got << ", exact " << v.get_d());
      CHECK(abs(mpq_class(got) - v) <= bound);
    }
  }
  CHECK(linear_used > 0);
}

TEST_CASE("BernsteinHorner in Bounded<double>: the running bound contains the exact value",
          "[kernel][bernstein][bernstein_horner][running_error]") {
  std::mt19937_64 rng(2121);
  std::uniform_real_distribution<double> C(-1.0, 1.0);
  for (int n : degrees()) {
    std::vector<double> bd(n + 1);
    for (auto& x : bd) x = C(rng);
    std::vector<Bounded<double>> b;
    for (double x : bd) b.emplace_back(x, 0.0);  // exact inputs
    const BernsteinHorner<Bounded<double>> h{std::span<const Bounded<double>>(b)};
    for (double t : points(rng)) {
      const mpq_class v = exact_value(bd, mpq_class(t)).first;
      const Bounded<double> got = h(Bounded<double>(t, 0.0));
      INFO("n = " << n << ", t = " << t << ", value " << got.value() << " ± " << got.bound() << ", exact "
                  << v.get_d());
      REQUIRE(std::isfinite(got.bound()));
      CHECK(abs(mpq_class(got.value()) - v) <= mpq_class(got.bound()));
      // and the bound is not vacuous: within a factor 100 of the double bound checked above
      CHECK(got.bound() <= 100 * 6.0 * (n + 2) * 0x1p-53 * exact_value(bd, mpq_class(t)).second.get_d() + 1e-300);
    }
  }
}

TEST_CASE("BernsteinHorner in MPFR at 200 bits keeps the precision", "[kernel][bernstein][bernstein_horner]") {
  std::mt19937_64 rng(212121);
  std::uniform_real_distribution<double> C(-1.0, 1.0);
  const Mpfr like = test::like<Mpfr>();
  for (int n : {16, 17, 60, 144, 299}) {
    std::vector<double> bd(n + 1);
    for (auto& x : bd) x = C(rng);
    std::vector<Mpfr> b;
    for (double x : bd) b.push_back(scalar_traits<Mpfr>::from_rational(mpq_class(x), like));
    const BernsteinHorner<Mpfr> h{std::span<const Mpfr>(b)};
    REQUIRE(h.linear());
    for (double t : points(rng)) {
      const auto [v, cond] = exact_value(bd, mpq_class(t));
      const Mpfr got = h(scalar_traits<Mpfr>::from_rational(mpq_class(t), like));
      mpq_class gq;
      mpfr_get_q(gq.get_mpq_t(), got.get());
      mpq_class bound = cond * (6 * (n + 2));
      mpz_class two200 = 1;
      two200 <<= 200;
      bound /= two200;
      INFO("n = " << n << ", t = " << t);
      CHECK(abs(gq - v) <= bound);
    }
  }
}

TEST_CASE("BernsteinHorner falls back to de Casteljau: low and high degree, overflowing weights",
          "[kernel][bernstein][bernstein_horner]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> C(-1.0, 1.0);
  for (int n : {0, 1, 15, 513, 700}) {
    std::vector<double> b(n + 1);
    for (auto& x : b) x = C(rng);
    const BernsteinHorner<double> h{std::span<const double>(b)};
    CHECK_FALSE(h.linear());
    for (double t : {0.0, 0.3, 0.7, 1.0}) CHECK(h(t) == bernstein_value(std::span<const double>(b), t));
  }
  // degree 300 with coefficients near the top of the range: C(300,150) b_150 overflows, so no O(n) form;
  // de Casteljau's convex combinations stay finite.
  std::vector<double> big(301);
  for (auto& x : big) x = 1e300 * C(rng);
  const BernsteinHorner<double> hb{std::span<const double>(big)};
  CHECK_FALSE(hb.linear());
  const double v = hb(0.4);
  CHECK(std::isfinite(v));
  CHECK(v == bernstein_value(std::span<const double>(big), 0.4));
  // A value in the underflow range (|p| <= 2^-960, here p = t^n b_n at t = 2^-17, n = 60: 2^-1020): de Casteljau's.
  std::vector<double> tiny(61, 0.0);
  tiny[60] = 1.0;
  const BernsteinHorner<double> ht{std::span<const double>(tiny)};
  REQUIRE(ht.linear());
  CHECK(ht(0x1p-17) == bernstein_value(std::span<const double>(tiny), 0x1p-17));
  CHECK(ht(0x1p-17) > 0);
}

}  // namespace ECCD_UNITY_ID
