// The certificate checker's own intervals (certificate/check/interval.hpp):
// MI (MPFI at a stated precision) and DI (doubles widened past the rounding
// error after each operation), against exact rational arithmetic.
// The inclusion property (Moore, Kearfott, Cloud 2009, chapter 2): on random
// rational operands (point and wide intervals, all signs, 64 and 200 bits for
// MI, magnitudes from 2^-1000 to 2^1000 for DI) every result of +, -, *,
// negation (MI), one_minus, lerp_from, lerp_to and hull contains the exact result
// of the operation at the operands' end points (for lerp with point weights:
// at the exact weights); de Casteljau chains built from lerp_* enclose the
// exact value of a Bernstein polynomial. DI::of encloses rationals of every
// size (subnormal, beyond the double range: the whole line). sign() is
// ±1 only for a finite interval of one strict sign. MI's lerp with point
// weights does not widen (the width is the weighted mean of the widths, up
// to rounding).
#include "certificate/check/interval.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using eccd::check::DI;
using eccd::check::MI;

namespace {

mpq_class random_q(SeededRng& rng, int max_exp) {
  mpq_class q = rng.frac(-1000000, 1000000, rng.uniform(1, 999983));
  const long e = rng.uniform(-max_exp, max_exp);
  if (e >= 0)
    q *= mpq_class(mpz_class(1) << e);
  else
    q /= mpq_class(mpz_class(1) << -e);
  return q;
}

// q lies in x. A DI whose product overflows can be [inf, inf] (both products rounded to +inf although
// the exact value is finite): such an interval is not finite, claims no sign (sign() is 0 unless both
// ends are finite) and stays not finite under every operation, so it is no claim and is skipped here.
bool holds(const DI& x, const mpq_class& q) {
  if (!x.finite()) return x.sign() == 0;
  return mpq_class(x.lo) <= q && q <= mpq_class(x.hi);
}
bool holds(const MI& x, const mpq_class& q) {
  const mpfr_srcptr lo = &x.get()->left, hi = &x.get()->right;
  if (mpfr_nan_p(lo) || mpfr_nan_p(hi)) return false;
  auto exact = [](mpfr_srcptr e) {
    mpq_class r;
    mpfr_get_q(r.get_mpq_t(), e);
    return r;
  };
  return (mpfr_inf_p(lo) ? mpfr_sgn(lo) < 0 : exact(lo) <= q) && (mpfr_inf_p(hi) ? mpfr_sgn(hi) > 0 : q <= exact(hi));
}

template <class X>
X make(const mpq_class& lo, const mpq_class& hi, int bits);
template <>
MI make<MI>(const mpq_class& lo, const mpq_class& hi, int bits) {
  return lo == hi ? MI(lo, bits) : MI(lo, hi, bits);
}
template <>
DI make<DI>(const mpq_class& lo, const mpq_class& hi, int) {
  return DI(DI::of(lo).lo, DI::of(hi).hi);
}

// The exact range of a·b over the boxes: the extremes of the four end-point products.
std::pair<mpq_class, mpq_class> product_range(const mpq_class& a0, const mpq_class& a1, const mpq_class& b0,
                                              const mpq_class& b1) {
  const std::array<mpq_class, 4> p{a0 * b0, a0 * b1, a1 * b0, a1 * b1};
  return {*std::min_element(p.begin(), p.end()), *std::max_element(p.begin(), p.end())};
}

template <class X>
void check_ops(std::uint64_t seed, int bits, int max_exp) {
  SeededRng rng{seed};
  for (int k = 0; k < 2000; ++k) {
    mpq_class a0 = random_q(rng, max_exp), b0 = random_q(rng, max_exp);
    mpq_class a1 = k % 3 == 0 ? a0 : mpq_class(a0 + abs(random_q(rng, max_exp)));
    mpq_class b1 = k % 4 == 0 ? b0 : mpq_class(b0 + abs(random_q(rng, max_exp)));
    const X a = make<X>(a0, a1, bits), b = make<X>(b0, b1, bits);
    INFO("a = [" << a0 << ", " << a1 << "], b = [" << b0 << ", " << b1 << "]");
    REQUIRE(holds(a, a0));
    REQUIRE(holds(a, a1));
    const X s = a + b, d = a - b, p = a * b, om = X::one_minus(a), h = a.hull(b);
    CHECK(holds(s, a0 + b0));
    CHECK(holds(s, a1 + b1));
    CHECK(holds(d, a0 - b1));
    CHECK(holds(d, a1 - b0));
    const auto [plo, phi] = product_range(a0, a1, b0, b1);
    CHECK(holds(p, plo));
    CHECK(holds(p, phi));
    if constexpr (std::is_same_v<X, MI>) {  // negation: MI only
      const X n = -a;
      CHECK(holds(n, -a0));
      CHECK(holds(n, -a1));
    }
    CHECK(holds(om, 1 - a0));
    CHECK(holds(om, 1 - a1));
    CHECK(holds(h, std::min(a0, b0)));
    CHECK(holds(h, std::max(a1, b1)));
    // a sign claimed is the sign of every point
    for (const X* x : {&s, &d, &p}) {
      if (x->sign() == 1) CHECK(x->lower() > 0);
      if (x->sign() == -1) CHECK(x->upper() < 0);
    }
    // lerp at a rational weight x in [0, 1]: d = (1 - x) a + x d and d = (1 - x) d + x b
    const mpq_class w = rng.frac(0, 1000, 1000);
    const X xw = make<X>(w, w, bits), yw = X::one_minus(xw);
    X l1 = b;
    X::lerp_from(l1, a, xw, yw);
    CHECK(holds(l1, (1 - w) * a0 + w * b0));
    CHECK(holds(l1, (1 - w) * a1 + w * b1));
    X l2 = a;
    X::lerp_to(l2, b, xw, yw);
    CHECK(holds(l2, (1 - w) * a0 + w * b0));
    CHECK(holds(l2, (1 - w) * a1 + w * b1));
  }
}

}  // namespace

TEST_CASE("check::MI operations enclose the exact results", "[certificate][check_interval]") {
  check_ops<MI>(11, 64, 200);
  check_ops<MI>(12, 200, 2000);
}

TEST_CASE("check::DI operations enclose the exact results at every magnitude", "[certificate][check_interval]") {
  check_ops<DI>(13, 53, 60);
  check_ops<DI>(14, 53, 1000);
}

TEST_CASE("check::DI::of encloses rationals from subnormal to beyond the double range",
          "[certificate][check_interval]") {
  SeededRng rng{15};
  for (int k = 0; k < 3000; ++k) {
    const mpq_class q = random_q(rng, 1100);
    const DI x = DI::of(q);
    INFO(q.get_d());
    CHECK(x.lo <= x.hi);
    if (x.finite()) {
      CHECK(x.lower() <= q);
      CHECK(q <= x.upper());
    } else {
      CHECK(x.lo == -std::numeric_limits<double>::infinity());
      CHECK(x.hi == std::numeric_limits<double>::infinity());
    }
  }
  const mpq_class tiny(mpz_class(1), mpz_class(1) << 1200);  // below the smallest subnormal
  CHECK(DI::of(tiny).lower() < tiny);
  CHECK(DI::of(tiny).upper() > tiny);
  CHECK(DI::of(tiny).sign() == 0);
  const mpq_class huge(mpz_class(1) << 1100);
  CHECK_FALSE(DI::of(huge).finite());
  CHECK(DI::of(huge).sign() == 0);
  // 0 * inf is NaN: the product is the whole line
  const DI inf(1, std::numeric_limits<double>::infinity());
  const DI p = DI(0, 0) * inf;
  CHECK_FALSE(p.finite());
  CHECK(p.sign() == 0);
  // an overflowing product: [inf, inf] although 2^2000 is finite; it claims nothing, and neither does
  // anything computed from it
  const DI big(0x1p1000, 0x1p1000), sq = big * big;
  CHECK_FALSE(sq.finite());
  CHECK(sq.sign() == 0);
  CHECK_FALSE((sq - sq).finite());
  CHECK_FALSE((sq * DI(0, 0)).finite());
  CHECK_FALSE((sq + DI(-1, -1)).finite());
  CHECK(DI::down(std::nan("")) == -std::numeric_limits<double>::infinity());
  CHECK(DI::up(std::nan("")) == std::numeric_limits<double>::infinity());
}

TEST_CASE("check::MI and DI signs, de Casteljau chains and MI's lerp width", "[certificate][check_interval]") {
  CHECK(MI(mpq_class(1, 3), 64).sign() == 1);
  CHECK(MI(mpq_class(-1, 3), 64).sign() == -1);
  CHECK(MI(mpq_class(0), 64).sign() == 0);
  CHECK(MI(mpq_class(-1, 3), mpq_class(1, 3), 64).sign() == 0);
  CHECK(DI(0, 1).sign() == 0);
  CHECK(DI(1e-300, 1).sign() == 1);
  CHECK(DI(-std::numeric_limits<double>::infinity(), -1).sign() == 0);  // not finite: not proved
  CHECK(MI(mpq_class(1), mpq_class(2), 64).bits() == 64);
  CHECK((MI(mpq_class(1), 64) + MI(mpq_class(1), 200)).bits() == 200);  // the larger precision

  // de Casteljau by lerp_from on a cubic's coefficients at x = 3/7: encloses the exact value
  SeededRng rng{16};
  for (int k = 0; k < 100; ++k) {
    std::vector<mpq_class> c;
    for (int i = 0; i < 6; ++i) c.push_back(rng.frac(-500, 500, rng.uniform(1, 97)));
    const mpq_class x = rng.frac(0, 97, 97);
    std::vector<mpq_class> e = c;  // exact de Casteljau
    for (std::size_t r = 1; r < e.size(); ++r)
      for (std::size_t i = 0; i + r < e.size(); ++i) e[i] = (1 - x) * e[i] + x * e[i + 1];
    std::vector<MI> m;
    std::vector<DI> d;
    for (const auto& q : c) {
      m.emplace_back(q, 80);
      d.push_back(DI::of(q));
    }
    const MI mx(x, 80), my = MI::one_minus(mx);
    const DI dx = DI::of(x), dy = DI::one_minus(dx);
    for (std::size_t r = 1; r < c.size(); ++r)
      for (std::size_t i = 0; i + r < c.size(); ++i) {
        // e[i] = y e[i] + x e[i + 1]: lerp_to on d = e[i] with b = e[i + 1]
        MI::lerp_to(m[i], m[i + 1], mx, my);
        DI::lerp_to(d[i], d[i + 1], dx, dy);
      }
    CHECK(holds(m[0], e[0]));
    CHECK(holds(d[0], e[0]));
    CHECK(m[0].upper() - m[0].lower() < mpq_class(1, mpz_class(1) << 60));
  }

  // point weights: the width of y a + x d is y width(a) + x width(d), up to a few units of 2^-200
  const MI a(mpq_class(1), mpq_class(2), 200), dd(mpq_class(3), mpq_class(7), 200);
  const MI x(mpq_class(1, 4), 200), y = MI::one_minus(x);
  MI r = dd;
  MI::lerp_from(r, a, x, y);
  const mpq_class width = r.upper() - r.lower(), want = mpq_class(3, 4) * 1 + mpq_class(1, 4) * 4;
  CHECK(width >= want);
  CHECK(width - want < mpq_class(1, mpz_class(1) << 190));
}

}  // namespace ECCD_UNITY_ID
