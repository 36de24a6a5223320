// kernel/quartic_status.hpp: the static test for two ellipsoids by the Sturm
// count of the distinct negative roots of f(λ) = det(λA - B) (002 Theorem 1,
// 001 section 3). Checked on quartics built from chosen roots, so the status
// is known by construction: f = g4 (λ - p1)(λ - p2) · q(λ) with g4 < 0
// (det A < 0), two positive roots p1, p2 and q one of: two distinct
// negative roots (separate), a negative double root (touching), a complex
// pair or a positive double root or two more positive roots (overlapping);
// over seeded random roots in mpq (exact) and double (built from the same
// rationals, roots well apart); more than two negative roots (impossible for
// ellipsoids): a logic_error in exact arithmetic, uncertain in double;
// quartic_status_at over Poly and Bern coefficient polynomials whose double
// root crosses at a known instant; more than 5 coefficients refused. The
// guarded face (Bounded<double>) on quartics with a positive double root, as
// every f of two spheres has: the Sturm count cannot read them, the
// negative-axis test (kernel/negative_axis_status.hpp) decides them, and
// neither is ever wrong against the exact status.
#include "kernel/quartic_status.hpp"
#include "number/rational_traits.hpp"
#include "number/running_error.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

using test::q;                                               // a / b in lowest terms (tests/support/exact_values.hpp)
RP lin(const Rational& r) { return RP({-r, Rational(1)}); }  // λ - r

enum class Kind { separate, touching, complex_pair, positive_double, four_positive, three_negative };

RP build(std::mt19937_64& rng, Kind k) {
  auto pos = [&] { return q(long(rng() % 40) + 1, long(rng() % 4) + 1); };  // in (0, 40]
  auto neg = [&]() -> Rational { return -pos(); };
  const Rational g4 = -q(long(rng() % 9) + 1, long(rng() % 3) + 1);
  RP f = RP::constant(g4) * lin(pos()) * lin(pos() + 41);  // two distinct positive roots
  switch (k) {
    case Kind::separate: {
      const Rational a = neg();
      return f * lin(a) * lin(a - q(long(rng() % 5) + 1, 2));
    }
    case Kind::touching: {
      const Rational a = neg();
      return f * lin(a) * lin(a);
    }
    case Kind::complex_pair: {  // (λ - a)² + b², b > 0
      const Rational a = q(long(rng() % 41) - 20, 1), b = pos();
      return f * (lin(a) * lin(a) + RP::constant(b * b));
    }
    case Kind::positive_double: {
      const Rational a = pos() + 100;
      return f * lin(a) * lin(a);
    }
    case Kind::four_positive:
      return f * lin(pos() + 200) * lin(pos() + 300);
    case Kind::three_negative: {  // not an ellipsoid pair: f made of three negative roots and one positive
      const Rational a = neg();
      return RP::constant(g4) * lin(pos()) * lin(a) * lin(a - 1) * lin(a - 2);
    }
  }
  return f;
}

Status expected(Kind k) {
  switch (k) {
    case Kind::separate:
      return Status::separate;
    case Kind::touching:
      return Status::touching;
    default:
      return Status::overlapping;
  }
}

}  // namespace

TEST_CASE("quartic_contact_status counts the distinct negative roots: exact and double", "[kernel][quartic_status]") {
  std::mt19937_64 rng(4323);
  for (int trial = 0; trial < 300; ++trial) {
    const Kind k = Kind(trial % 5);
    const RP f = build(rng, k);
    REQUIRE(f.degree() == 4);
    std::array<Rational, 5> g;
    std::array<double, 5> gd;
    for (int i = 0; i < 5; ++i) {
      g[i] = f.c[i];
      gd[i] = f.c[i].get_d();
    }
    INFO("trial " << trial << " kind " << int(k));
    CHECK(quartic_contact_status(g) == expected(k));
    CHECK(negative_root_count(std::span<const Rational>(g)) == (k == Kind::separate ? 2 : k == Kind::touching));
    const std::vector<Rational> gv(g.begin(), g.end());
    CHECK(quartic_contact_status(gv) == expected(k));
    // In double a double root may split or vanish under rounding: only the well-separated kinds are asked.
    if (k != Kind::touching && k != Kind::positive_double) CHECK(quartic_contact_status(gd) == expected(k));
  }
}

TEST_CASE("quartic_contact_status: more than two negative roots is no ellipsoid pair", "[kernel][quartic_status]") {
  std::mt19937_64 rng(4324);
  for (int trial = 0; trial < 20; ++trial) {
    const RP f = build(rng, Kind::three_negative);
    std::array<Rational, 5> g;
    std::array<double, 5> gd;
    for (int i = 0; i < 5; ++i) {
      g[i] = f.c[i];
      gd[i] = f.c[i].get_d();
    }
    CHECK_THROWS_AS(quartic_contact_status(g), std::logic_error);
    CHECK(quartic_contact_status(gd) == Status::uncertain);
  }
}

TEST_CASE("guarded: a positive double root (two spheres) is decided on the negative axis, never wrongly",
          "[kernel][quartic_status]") {
  using B = Bounded<double>;
  std::mt19937_64 rng(4325);
  auto pos = [&] { return q(long(rng() % 40) + 1, long(rng() % 6) + 1); };  // thirds and fifths: rounded inputs
  int asked = 0, sturm_open = 0, decided = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Rational g4 = -q(long(rng() % 9) + 1, long(rng() % 3) + 1);
    const Rational p = pos();
    RP f = RP::constant(g4) * lin(p) * lin(p);  // the positive double root of two spheres
    const Rational a = -pos();
    Status want = Status::separate;
    switch (trial % 4) {
      case 0:  // two distinct negative roots
        f = f * lin(a) * lin(a - q(long(rng() % 5) + 1, 3));
        break;
      case 1:  // a complex pair: overlapping
        f = f * (lin(a) * lin(a) + RP::constant(q(long(rng() % 7) + 1, 7)));
        want = Status::overlapping;
        break;
      case 2:  // two more positive roots: overlapping
        f = f * lin(p + q(1, 3)) * lin(p + 2);
        want = Status::overlapping;
        break;
      default:  // a negative double root: touching (never provable with a bound)
        f = f * lin(a) * lin(a);
        want = Status::touching;
    }
    REQUIRE(f.degree() == 4);
    std::array<Rational, 5> g;
    std::array<B, 5> gb;
    for (int i = 0; i < 5; ++i) {
      g[i] = f.c[i];
      gb[i] = scalar_traits<B>::from_rational(f.c[i], B(0));
    }
    INFO("trial " << trial << " kind " << trial % 4);
    REQUIRE(quartic_contact_status(g) == want);
    const Status s = quartic_contact_status(gb);
    CHECK((s == Status::uncertain || s == want));
    if (want == Status::touching) {
      CHECK(negative_axis_status(std::span<const B>(gb)) == Status::uncertain);
      continue;
    }
    ++asked;
    sturm_open += negative_root_count(std::span<const B>(gb)) < 0;
    decided += s != Status::uncertain;
  }
  INFO(sturm_open << " of " << asked << " left open by the Sturm count; " << decided << " decided");
  CHECK(sturm_open > asked / 2);  // the case the negative-axis test is for
  CHECK(decided == asked);
}

TEST_CASE("quartic_status_at over Poly and Bern coefficients: the double root at a known instant",
          "[kernel][quartic_status]") {
  // f(λ; t) = -(λ - 1)(λ - 2)(λ + 1)(λ + 3/2 - t): negative roots -1 and t - 3/2, double at t = 1/2;
  // for t > 1/2 the second root t - 3/2 > -1 and they stay distinct and negative up to t = 1.
  const RP t({Rational(0), Rational(1)});
  std::vector<RP> g(5);
  // expand in λ: coefficients are polynomials in t. Build as a product of Poly<Poly> by hand:
  // h(λ) = -(λ² - 3λ + 2)(λ + 1) = -(λ³ - 2λ² - λ + 2); times (λ + c), c = 3/2 - t.
  const RP c = RP::constant(q(3, 2)) - t;
  const std::vector<RP> h = {RP::constant(Rational(-2)), RP::constant(Rational(1)), RP::constant(Rational(2)),
                             RP::constant(Rational(-1))};  // -2 + λ + 2λ² - λ³
  for (int i = 0; i < 5; ++i) {
    RP s;
    if (i <= 3) s = s + c * h[i];
    if (i >= 1) s = s + h[i - 1];
    g[i] = s;
  }
  std::vector<Bern<Rational>> gb;
  for (const auto& gi : g) gb.push_back(to_bernstein(gi, 1));
  const std::pair<Rational, Status> want[] = {{Rational(0), Status::separate},
                                              {q(1, 4), Status::separate},
                                              {q(1, 2), Status::touching},
                                              {q(3, 4), Status::separate},
                                              {Rational(1), Status::separate}};
  for (const auto& [at, st] : want) {
    INFO("t = " << at);
    CHECK(quartic_status_at(g, at) == st);
    CHECK(quartic_status_at(gb, at) == st);
  }
  std::vector<RP> six(6, RP::constant(Rational(1)));
  CHECK_THROWS_AS(quartic_status_at(six, Rational(0)), std::invalid_argument);
}

}  // namespace ECCD_UNITY_ID
