// number/enclosure.hpp: sin(πx), cos(πx), π, [lo, hi] and |x| bounds as
// enclosures in Bounded<double>, Bounded<Mpfr> and MpfiInterval (the
// cycloidal pipeline's proofs rest on them). Checked against MPFI at 400 bits
// computed in the test (mpfi_const_pi, mpfi_sin, mpfi_cos: an independent
// enclosure of width about 2^-395): a Bounded result v ± e must meet the
// reference interval (|v - ref| <= e + the reference's width), an MPFI result
// must intersect it and be narrow; also for an argument that is itself an
// enclosure (x = v ± e: sin over the whole range, checked at both ends and
// the middle), for Dual numbers (the derivative π cos(πx) x'), at the exact
// values x = k/2 and k/6, and over seeded random rationals.
#include "number/enclosure.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

constexpr int kRef = 400;

// sin(πq), cos(πq) enclosed at 400 bits, as rational end points.
struct Ref {
  mpq_class slo, shi, clo, chi;
};
Ref reference(const mpq_class& q) {
  mpfi_t x, s, c;
  mpfi_init2(x, kRef);
  mpfi_init2(s, kRef);
  mpfi_init2(c, kRef);
  mpfi_const_pi(x);
  mpfi_mul_q(x, x, q.get_mpq_t());
  mpfi_sin(s, x);
  mpfi_cos(c, x);
  Ref r;
  auto get = [](mpfr_srcptr f) {
    mpq_class out;
    mpfr_get_q(out.get_mpq_t(), f);
    return out;
  };
  r.slo = get(&s->left);
  r.shi = get(&s->right);
  r.clo = get(&c->left);
  r.chi = get(&c->right);
  mpfi_clear(x);
  mpfi_clear(s);
  mpfi_clear(c);
  return r;
}
// v ± e meets [lo, hi]
bool meets(const mpq_class& v, const mpq_class& e, const mpq_class& lo, const mpq_class& hi) {
  return v + e >= lo && v - e <= hi;
}
template <class U>
mpq_class value_of(const Bounded<U>& x) {
  // (test::exact_of on an MPFR zero would shift by MPFR's minimal exponent, 2^30 bits: zero is zero)
  if constexpr (std::is_same_v<U, Mpfr>)
    if (mpfr_zero_p(x.value().get())) return 0;
  return test::exact_of(x.value());
}
template <class U>
mpq_class bound_of(const Bounded<U>& x) {
  return test::exact_of(static_cast<long double>(x.bound()));
}
bool meets(const MpfiInterval& x, const mpq_class& lo, const mpq_class& hi) {
  mpq_class l, h;
  mpfr_get_q(l.get_mpq_t(), &x.get()->left);
  mpfr_get_q(h.get_mpq_t(), &x.get()->right);
  return h >= lo && l <= hi;
}
mpq_class width(const MpfiInterval& x) {
  mpq_class l, h;
  mpfr_get_q(l.get_mpq_t(), &x.get()->left);
  mpfr_get_q(h.get_mpq_t(), &x.get()->right);
  return h - l;
}
std::vector<mpq_class> arguments(std::mt19937_64& rng) {
  std::vector<mpq_class> xs;
  for (int k = -8; k <= 8; ++k) {
    mpq_class h(k, 2), s(k, 6);
    h.canonicalize();
    s.canonicalize();
    xs.push_back(h);
    xs.push_back(s);
  }
  for (int k = 0; k < 60; ++k) {
    mpq_class x(long(rng() % (1 << 21)) - (1 << 20), long(rng() % 1024) + 1);  // |x| up to 2^20
    x.canonicalize();
    xs.push_back(x);
  }
  return xs;
}

}  // namespace

TEST_CASE("sin_cos_pi in Bounded<double> and Bounded<Mpfr> encloses sin and cos of pi x", "[number][enclosure]") {
  std::mt19937_64 rng(4334);
  for (const mpq_class& q : arguments(rng)) {
    {
      // double: the argument rounded to double is the exact argument of the enclosure (bound 0).
      const double xd = q.get_d();
      const Bounded<double> x(xd, 0);
      Bounded<double> s, c;
      sin_cos_pi(x, s, c);
      const Ref r = reference(mpq_class(xd));
      INFO("x = " << xd);
      CHECK(meets(value_of(s), bound_of(s), r.slo, r.shi));
      CHECK(meets(value_of(c), bound_of(c), r.clo, r.chi));
      CHECK(s.bound() < 1e-14 * (1 + std::abs(xd)));  // and tight (the argument's rounding grows with |x|)
    }
    {
      const Bounded<Mpfr> x(Mpfr(q, 200), 0);
      Bounded<Mpfr> s, c;
      sin_cos_pi(x, s, c);
      const Ref r = reference(value_of(x));  // the argument as rounded to 200 bits
      INFO("x = " << q);
      CHECK(meets(value_of(s), bound_of(s), r.slo, r.shi));
      CHECK(meets(value_of(c), bound_of(c), r.clo, r.chi));
      CHECK(bound_of(s) < (1 + abs(q)) / mpq_class(mpz_class(1) << 190));
    }
  }
}

TEST_CASE("sin_cos_pi of an argument with a bound covers the whole range", "[number][enclosure]") {
  std::mt19937_64 rng(4335);
  for (int k = 0; k < 60; ++k) {
    const double v = std::ldexp(double(rng() % 4096), -10) - 2, e = std::ldexp(double(rng() % 64 + 1), -20);
    Bounded<double> s, c;
    sin_cos_pi(Bounded<double>(v, e), s, c);
    for (const double x : {v - e, v, v + e}) {  // exact in double: small dyadics
      const Ref r = reference(mpq_class(x));
      INFO("v = " << v << " e = " << e << " x = " << x);
      CHECK(meets(value_of(s), bound_of(s), r.slo, r.shi));
      CHECK(meets(value_of(c), bound_of(c), r.clo, r.chi));
    }
  }
}

TEST_CASE("sin_cos_pi in MPFI and for Dual numbers, pi_enclosure, range_of, magnitude_bound", "[number][enclosure]") {
  std::mt19937_64 rng(4336);
  for (const mpq_class& q : arguments(rng)) {
    const MpfiInterval x(q, 128);
    MpfiInterval s, c;
    sin_cos_pi(x, s, c);
    const Ref r = reference(q);
    INFO("x = " << q);
    CHECK(meets(s, r.slo, r.shi));
    CHECK(meets(c, r.clo, r.chi));
    CHECK(width(s) < (1 + abs(q)) / mpq_class(mpz_class(1) << 110));  // the argument πx carries 128 bits
    // Dual: d/dt sin(π x(t)) = π cos(π x) x', with x' = 3
    Dual<MpfiInterval> xd(x, MpfiInterval(mpq_class(3), 128)), sd, cd;
    sin_cos_pi(xd, sd, cd);
    CHECK(meets(sd.v, r.slo, r.shi));
    mpq_class pi_lo, pi_hi;  // π to 400 bits
    {
      mpfi_t p;
      mpfi_init2(p, kRef);
      mpfi_const_pi(p);
      mpfr_get_q(pi_lo.get_mpq_t(), &p->left);
      mpfr_get_q(pi_hi.get_mpq_t(), &p->right);
      mpfi_clear(p);
    }
    // 3π cos(πx) lies between the products of the end points (π > 0; cos may have either sign)
    std::vector<mpq_class> ends = {3 * pi_lo * r.clo, 3 * pi_lo * r.chi, 3 * pi_hi * r.clo, 3 * pi_hi * r.chi};
    CHECK(meets(sd.d, *std::min_element(ends.begin(), ends.end()), *std::max_element(ends.begin(), ends.end())));
    std::vector<mpq_class> ends_c = {-3 * pi_lo * r.slo, -3 * pi_lo * r.shi, -3 * pi_hi * r.slo, -3 * pi_hi * r.shi};
    CHECK(
        meets(cd.d, *std::min_element(ends_c.begin(), ends_c.end()), *std::max_element(ends_c.begin(), ends_c.end())));
    // π itself
    CHECK(meets(pi_enclosure(x), pi_lo, pi_hi));
    const Bounded<double> pb = pi_enclosure(Bounded<double>(1.0, 0));
    CHECK(meets(value_of(pb), bound_of(pb), pi_lo, pi_hi));
  }
  // range_of: both ends inside; magnitude_bound >= the largest |x| of the enclosure.
  const mpq_class lo(-1, 3), hi(5, 7);
  const Bounded<double> rb = range_of(lo, hi, Bounded<double>(0.0, 0));
  CHECK(abs(value_of(rb) - lo) <= bound_of(rb));
  CHECK(abs(value_of(rb) - hi) <= bound_of(rb));
  const MpfiInterval ri = range_of(lo, hi, MpfiInterval(mpq_class(0), 64));
  CHECK(meets(ri, lo, lo));
  CHECK(meets(ri, hi, hi));
  CHECK(magnitude_bound(ri) >= 5.0 / 7);
  CHECK(magnitude_bound(rb) >= 5.0 / 7);
  CHECK(magnitude_bound(Bounded<double>(-2.0, 0.5)) >= 2.5);
}

}  // namespace ECCD_UNITY_ID
