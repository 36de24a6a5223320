// kernel/quartic_sign_status.hpp: the static test for two ellipsoids from the
// sign of the quartic's discriminant and Descartes' rule. Checked on quartics
// built from chosen roots (so the status is known by construction, as in
// test_quartic_status.cpp): f = g4 (λ - p1)(λ - p2) q(λ), g4 < 0, p1, p2 > 0,
// q with two distinct negative roots (separate), a negative double root
// (touching, Δ = 0), a complex pair (Δ < 0: overlapping), a positive double
// root (Δ = 0, overlapping) or two more positive roots (Δ > 0, no sign
// change: overlapping); in mpq (every kind, and the same status as the Sturm
// test kernel/quartic_status.hpp), in double (Δ = 0 kinds aside) and in
// ForwardBound (a certain sign is the exact one; with Δ = 0 never a decision
// other than uncertain). ForwardBound refuses inputs whose bound is not small
// (ρ > 2^-20) or that are not finite; Δ > 0 with one or three sign changes
// (impossible for ellipsoids) throws in mpq.
#include "kernel/quartic_sign_status.hpp"
#include "number/rational_traits.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

using test::q;                                               // a / b in lowest terms (tests/support/exact_values.hpp)
RP lin(const Rational& r) { return RP({-r, Rational(1)}); }  // λ - r

enum class Kind { separate, touching, complex_pair, positive_double, four_positive };

RP build(std::mt19937_64& rng, Kind k) {
  auto pos = [&]() -> Rational { return q(long(rng() % 40) + 1, long(rng() % 4) + 1); };
  auto neg = [&]() -> Rational { return -pos(); };
  const Rational g4 = -q(long(rng() % 9) + 1, long(rng() % 3) + 1);
  const RP f = RP::constant(g4) * lin(pos()) * lin(pos() + 41);
  switch (k) {
    case Kind::separate: {
      const Rational a = neg();
      return f * lin(a) * lin(a - q(long(rng() % 5) + 1, 2));
    }
    case Kind::touching: {
      const Rational a = neg();
      return f * lin(a) * lin(a);
    }
    case Kind::complex_pair: {
      const Rational a = q(long(rng() % 41) - 20, 1), b = pos();
      return f * (lin(a) * lin(a) + RP::constant(b * b));
    }
    case Kind::positive_double: {
      const Rational a = pos() + 100;
      return f * lin(a) * lin(a);
    }
    case Kind::four_positive:
      return f * lin(pos() + 200) * lin(pos() + 300);
  }
  return f;
}
Status expected(Kind k) {
  return k == Kind::separate ? Status::separate : k == Kind::touching ? Status::touching : Status::overlapping;
}

}  // namespace

TEST_CASE("quartic_sign_status decides every kind exactly, as the Sturm test does", "[kernel][quartic_sign_status]") {
  std::mt19937_64 rng(4325);
  for (int trial = 0; trial < 250; ++trial) {
    const Kind k = Kind(trial % 5);
    const RP f = build(rng, k);
    std::array<Rational, 5> g;
    for (int i = 0; i < 5; ++i) g[i] = f.c[i];
    INFO("trial " << trial << " kind " << int(k));
    const Sign ds = quartic_discriminant_sign(g);
    CHECK(ds == (k == Kind::touching || k == Kind::positive_double ? Sign::zero
                 : k == Kind::complex_pair                         ? Sign::negative
                                                                   : Sign::positive));
    CHECK(quartic_sign_status(g) == expected(k));
    CHECK(quartic_sign_status(g) == quartic_contact_status(g));
  }
}

TEST_CASE("quartic_sign_status in double and ForwardBound: only exact answers, uncertain at Δ = 0",
          "[kernel][quartic_sign_status]") {
  std::mt19937_64 rng(4326);
  int decided = 0;
  for (int trial = 0; trial < 250; ++trial) {
    const Kind k = Kind(trial % 5);
    const RP f = build(rng, k);
    std::array<double, 5> gd;
    std::array<ForwardBound, 5> gf;
    for (int i = 0; i < 5; ++i) {
      gd[i] = f.c[i].get_d();
      // a rounded rational: a leaf with its one rounding (depth 1)
      gf[i] = f.c[i].get_den() == 1 && Rational(gd[i]) == f.c[i] ? ForwardBound::exact(gd[i])
                                                                 : ForwardBound(gd[i], std::fabs(gd[i]), 1);
    }
    INFO("trial " << trial << " kind " << int(k));
    const Status sf = quartic_sign_status(gf);
    if (k == Kind::touching || k == Kind::positive_double) {
      CHECK(sf == Status::uncertain);  // Δ = 0: a rounded arithmetic does not decide
    } else {
      CHECK(quartic_sign_status(gd) == expected(k));  // Δ far from 0: plain double gets it right
      CHECK((sf == expected(k) || sf == Status::uncertain));
      decided += sf == expected(k);
    }
  }
  CHECK(decided > 100);  // the filter decides the clear cases
  // A leaf whose bound is not below its value, a large relative bound, a non-finite value: uncertain.
  std::array<ForwardBound, 5> bad;
  for (int i = 0; i < 5; ++i) bad[i] = ForwardBound::exact(double(i + 1));
  bad[2] = ForwardBound(3.0, 3.0, 0x1p53);  // bound 2 d u m = 6 above the value 3
  CHECK(quartic_discriminant_sign(bad) == Sign::uncertain);
  bad[2] = ForwardBound(3.0, 3.0, 0x1p33);  // ρ = 2 d u = 2^-19 > 2^-20
  CHECK(quartic_discriminant_sign(bad) == Sign::uncertain);
  bad[2] = ForwardBound(3.0, std::numeric_limits<double>::infinity(), 0);
  CHECK(quartic_discriminant_sign(bad) == Sign::uncertain);
  bad[2] = ForwardBound::exact(0.0);  // a zero coefficient: |v| > e fails, uncertain
  CHECK(quartic_discriminant_sign(bad) == Sign::uncertain);
}

TEST_CASE("quartic_sign_status: a sign pattern impossible for ellipsoids throws in exact arithmetic",
          "[kernel][quartic_sign_status]") {
  // Four distinct real roots -1, -2, -3, 5 (Δ > 0) times g4 = -1: f(-λ)'s coefficients change sign 3 times.
  const RP f =
      RP::constant(Rational(-1)) * lin(Rational(-1)) * lin(Rational(-2)) * lin(Rational(-3)) * lin(Rational(5));
  std::array<Rational, 5> g;
  std::array<double, 5> gd;
  for (int i = 0; i < 5; ++i) {
    g[i] = f.c[i];
    gd[i] = f.c[i].get_d();
  }
  CHECK(quartic_discriminant_sign(g) == Sign::positive);
  CHECK_THROWS_AS(quartic_sign_status(g), std::logic_error);
  CHECK(quartic_sign_status(gd) == Status::uncertain);
}

}  // namespace ECCD_UNITY_ID
