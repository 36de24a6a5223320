// De Casteljau's step at 1/2 for guarded MPFR (number/halving_step.hpp): one
// addition and an exponent shift must give bit for bit the value and the
// running error bound of the four operations written out (copy, times 1 - 1/2,
// copy, times 1/2, plus), on random values with and without error bounds, on
// zeros, at several precisions, and where the shortcut does not apply (mixed
// precisions). TriBern's split_half and split_half_into (reused storage) must
// give the nets the written-out steps give, and both halves must hold the
// exact rational halves within their bounds. The univariate split, split_into
// and keep_right (kernel/bernstein.hpp) take the step for plain and guarded
// MPFR: at 1/2 and at another point, the values the written-out products give
// bit for bit, and the guarded pieces hold the exact pieces within their bounds.
#include "kernel/bernstein.hpp"
#include "kernel/trivariate_bernstein.hpp"
#include "number/halving_step.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using eccd::test::exact_of;

namespace {

using BM = Bounded<Mpfr>;

bool same(const BM& a, const BM& b) {
  return a.value().precision() == b.value().precision() &&
         mpfr_get_prec(a.value().get()) == mpfr_get_prec(b.value().get()) &&
         mpfr_equal_p(a.value().get(), b.value().get()) &&
         mpfr_signbit(a.value().get()) == mpfr_signbit(b.value().get()) && a.bound() == b.bound();
}

// A random value of `bits` precision: exact (bound 0), or a rounded product or sum (bound > 0), or zero.
BM random_value(std::mt19937_64& rng, int bits, mpq_class* exact = nullptr) {
  std::uniform_int_distribution<long> num(-1000000007L, 1000000007L), den(1, 999983L);
  const BM like(Mpfr(mpq_class(1), bits), 0);
  const int kind = int(rng() % 4);
  mpq_class a(num(rng), den(rng)), b(num(rng), den(rng));
  a.canonicalize();
  b.canonicalize();
  BM x = scalar_traits<BM>::from_rational(a, like);
  if (kind == 0) {
    if (exact) *exact = 0;
    return scalar_traits<BM>::from_rational(mpq_class(0), like);
  }
  if (kind == 1) {
    if (exact) *exact = a;
    return x;
  }
  BM y = scalar_traits<BM>::from_rational(b, like);
  if (exact) *exact = kind == 2 ? mpq_class(a * b) : mpq_class(a - b);
  return kind == 2 ? x * y : x - y;
}

}  // namespace

TEST_CASE("guarded MPFR halving step: the written-out steps' value and bound, bit for bit", "[independent][halving]") {
  std::mt19937_64 rng(20261201);
  for (int bits : {53, 64, 128, 300}) {
    const BM half = scalar_traits<BM>::from_rational(mpq_class(1, 2), BM(Mpfr(mpq_class(1), bits), 0));
    HalvingStep<BM> fast(half);
    WrittenHalvingStep<BM> written(half);
    for (int k = 0; k < 2000; ++k) {
      BM a = random_value(rng, bits), b = random_value(rng, bits);
      BM a2 = a;
      fast(a, b);
      written(a2, b);
      REQUIRE(same(a, a2));
    }
    // another precision in one operand: the written-out operations (the result takes the larger precision)
    BM a = random_value(rng, bits), b = random_value(rng, bits + 64);
    BM a2 = a;
    fast(a, b);
    written(a2, b);
    CHECK(same(a, a2));
    CHECK(a.value().precision() == bits + 64);
  }
}

TEST_CASE(
    "guarded MPFR TriBern halves: as the written-out steps, reused storage alike, and within their bounds of the exact "
    "halves",
    "[independent][halving]") {
  std::mt19937_64 rng(7);
  const int bits = 128;
  const BM half = scalar_traits<BM>::from_rational(mpq_class(1, 2), BM(Mpfr(mpq_class(1), bits), 0));
  TriBern<BM> f;
  TriBern<Rational> q;
  f.n = q.n = {4, 2, 3};
  for (int i = 0; i < 5 * 3 * 4; ++i) {
    mpq_class e;
    f.c.push_back(random_value(rng, bits, &e));
    q.c.push_back(Rational(e));
  }
  TriBern<BM> reused_lo = f;  // storage of the right size from an earlier net
  for (int axis = 0; axis < 3; ++axis) {
    auto [lo, hi] = f.split_half(axis, half);
    // written out: the same loops with WrittenHalvingStep
    TriBern<BM> wlo = f, whi = f;
    WrittenHalvingStep<BM> w(half);
    const std::size_t st = f.stride(axis), len = std::size_t(f.n[axis]) + 1;
    for (std::size_t base = 0; base < f.c.size(); ++base) {
      if ((base / st) % len != 0) continue;
      for (std::size_t r = 1; r < len; ++r) {
        for (std::size_t i = 0; i + r < len; ++i) w(whi.c[base + i * st], whi.c[base + (i + 1) * st]);
        wlo.c[base + r * st] = whi.c[base];
      }
    }
    TriBern<BM> g = f;
    HalvingStep<BM> step(half);
    g.split_half_into(axis, step, reused_lo);
    auto [qlo, qhi] = q.split_half(axis, Rational(mpq_class(1, 2)));
    for (std::size_t i = 0; i < f.c.size(); ++i) {
      REQUIRE(same(lo.c[i], wlo.c[i]));
      REQUIRE(same(hi.c[i], whi.c[i]));
      REQUIRE(same(reused_lo.c[i], wlo.c[i]));
      REQUIRE(same(g.c[i], whi.c[i]));
      // the bound holds: |value - exact| <= bound, for the exact halves of the exact net
      const mpq_class dlo = abs(exact_of(lo.c[i].value()) - qlo.c[i]);
      const mpq_class dhi = abs(exact_of(hi.c[i].value()) - qhi.c[i]);
      CHECK(dlo <= exact_of(lo.c[i].bound()));
      CHECK(dhi <= exact_of(hi.c[i].bound()));
    }
  }
}

TEST_CASE("univariate split of MPFR nets by the step: the written-out values, and the exact pieces within the bounds",
          "[halving]") {
  std::mt19937_64 rng(55);
  const int bits = 128, n = 40;
  const BM like(Mpfr(mpq_class(1), bits), 0);
  for (const mpq_class& tau_q : {mpq_class(1, 2), mpq_class(3, 7)}) {
    Bern<BM> f;
    Bern<Rational> q;
    Bern<Mpfr> plain;
    for (int i = 0; i <= n; ++i) {
      mpq_class e;
      f.b.push_back(random_value(rng, bits, &e));
      q.b.push_back(Rational(e));
      plain.b.push_back(f.b.back().value());
    }
    const BM tau = scalar_traits<BM>::from_rational(tau_q, like);
    auto [lo, hi] = split(f, tau);
    auto [plo, phi] = split(plain, tau.value());
    auto [qlo, qhi] = split(q, Rational(tau_q));
    // the written-out products and sums, in plain MPFR
    std::vector<Mpfr> w = plain.b, wlo(n + 1);
    const Mpfr t = tau.value(), s = Mpfr(1) - t;
    wlo[0] = w[0];
    for (int r = 1; r <= n; ++r) {
      for (int i = 0; i + r <= n; ++i) w[i] = s * w[i] + t * w[i + 1];
      wlo[r] = w[0];
    }
    std::vector<BM> klo(n + 1), khi(n + 1), kright = f.b;
    split_into(std::span<const BM>(f.b), tau, std::span<BM>(klo), std::span<BM>(khi));
    keep_right(std::span<BM>(kright), tau);
    CHECK((tau.bound() == 0) == (tau_q == mpq_class(1, 2)));
    for (int i = 0; i <= n; ++i) {
      INFO("tau " << tau_q << ", coefficient " << i);
      REQUIRE(mpfr_equal_p(plo.b[i].get(), wlo[i].get()));
      REQUIRE(mpfr_equal_p(phi.b[i].get(), w[i].get()));
      REQUIRE(mpfr_equal_p(lo.b[i].value().get(), wlo[i].get()));
      REQUIRE(mpfr_equal_p(hi.b[i].value().get(), w[i].get()));
      REQUIRE(same(klo[i], lo.b[i]));
      REQUIRE(same(khi[i], hi.b[i]));
      REQUIRE(same(kright[i], hi.b[i]));
      // the exact pieces at the exact point (3/7 is rounded: tau's own bound carries that error)
      CHECK(abs(exact_of(lo.b[i].value()) - qlo.b[i]) <= exact_of(lo.b[i].bound()));
      CHECK(abs(exact_of(hi.b[i].value()) - qhi.b[i]) <= exact_of(hi.b[i].bound()));
    }
  }
}

}  // namespace ECCD_UNITY_ID
