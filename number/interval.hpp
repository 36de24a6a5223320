#pragma once
// Interval: closed intervals of doubles that provably enclose the exact
// result of every operation, and scalar_traits<Interval> whose sign() is
// certain or `uncertain` (the scalar of `--arith certified`).
//
// Statement (interval arithmetic, Moore 1966; e.g. the filters of CGAL and
// Kettner et al. 2004). Each operation computes its end points in
// round-to-nearest and then moves them outwards by |x|·2^-51 + 2^-1073: the
// rounding error of one operation is below |x|·2^-52 (plus half the smallest
// subnormal), and the widening step's own rounding is below |x|·2^-53, so the
// exact result of the operation on any values inside the operands lies inside
// the result. (std::nextafter would widen by one ulp but costs a library call
// per end point: it was half the run time.) NaN end points (inf - inf) make
// the sign uncertain; products and quotients with a NaN are (-inf, inf), and
// so is a product whose end point would be 0 · inf (a product takes the two
// end-point products that the signs of the operands name, not all four). Rationals enter as [RNDD, RNDU] roundings
// (MPFR), so the scene's exact numbers are enclosed from the start. Division
// by an interval that contains 0 gives (-inf, inf). The sign of an interval is
// certain when it lies on one side of 0 (or is exactly [0, 0]); otherwise it
// is Sign::uncertain and the caller must not decide (docs/architecture.md,
// "Uncertain is a fourth sign"). Comparisons `<`, `>` hold only when
// certain for every pair of values.
// Requirements: IEEE double with round-to-nearest (the default); no
// -ffast-math.
#include "number/scalar_traits.hpp"

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

namespace eccd {

struct Interval {
  double lo = 0, hi = 0;

  Interval() = default;
  Interval(int k) : lo(k), hi(k) {}  // NOLINT: small integer constants, exact
  Interval(double l, double h) : lo(l), hi(h) {}

  static double down(double x) { return x - (std::fabs(x) * 0x1p-51 + 0x1p-1073); }
  static double up(double x) { return x + (std::fabs(x) * 0x1p-51 + 0x1p-1073); }
  static Interval entire() {
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  }

  bool contains_zero() const { return lo <= 0 && hi >= 0; }
  double width() const { return hi - lo; }
  double mid() const { return lo + 0.5 * (hi - lo); }

  friend Interval operator+(const Interval& a, const Interval& b) { return {down(a.lo + b.lo), up(a.hi + b.hi)}; }
  friend Interval operator-(const Interval& a, const Interval& b) { return {down(a.lo - b.hi), up(a.hi - b.lo)}; }
  friend Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
  friend Interval operator*(const Interval& a, const Interval& b) {
    if (a.lo == a.hi && b.lo == b.hi) {  // point operands (constants, exact dyadics): one product
      double p = a.lo * b.lo;
      if (p == 0 && (a.lo == 0 || b.lo == 0)) return {0, 0};
      return {down(p), up(p)};
    }
    // By the signs of the end points (the classical nine cases, Moore 1966): the
    // extremes of {x·y} are the two products named; two products instead of four.
    double lo, hi;
    if (a.lo >= 0) {
      if (b.lo >= 0) {
        lo = a.lo * b.lo;
        hi = a.hi * b.hi;
      } else if (b.hi <= 0) {
        lo = a.hi * b.lo;
        hi = a.lo * b.hi;
      } else {
        lo = a.hi * b.lo;
        hi = a.hi * b.hi;
      }
    } else if (a.hi <= 0) {
      if (b.lo >= 0) {
        lo = a.lo * b.hi;
        hi = a.hi * b.lo;
      } else if (b.hi <= 0) {
        lo = a.hi * b.hi;
        hi = a.lo * b.lo;
      } else {
        lo = a.lo * b.hi;
        hi = a.lo * b.lo;
      }
    } else {  // 0 inside a (or a NaN end point: every comparison false)
      const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
      if (std::isnan(p1) || std::isnan(p2) || std::isnan(p3) || std::isnan(p4)) return entire();
      lo = std::min({p1, p2, p3, p4});
      hi = std::max({p1, p2, p3, p4});
    }
    if (std::isnan(lo) || std::isnan(hi)) return entire();  // 0 · inf, or a NaN end point of b
    return {down(lo), up(hi)};
  }
  friend Interval operator/(const Interval& a, const Interval& b) {
    if (b.contains_zero() || std::isnan(b.lo) || std::isnan(b.hi) || std::isnan(a.lo) || std::isnan(a.hi))
      return entire();
    double q1 = a.lo / b.lo, q2 = a.lo / b.hi, q3 = a.hi / b.lo, q4 = a.hi / b.hi;
    return {down(std::min({q1, q2, q3, q4})), up(std::max({q1, q2, q3, q4}))};
  }
  Interval& operator+=(const Interval& b) { return *this = *this + b; }
  Interval& operator-=(const Interval& b) { return *this = *this - b; }
  Interval& operator*=(const Interval& b) { return *this = *this * b; }
  Interval& operator/=(const Interval& b) { return *this = *this / b; }
  // Certainly less / greater for every pair of values.
  friend bool operator<(const Interval& a, const Interval& b) { return a.hi < b.lo; }
  friend bool operator>(const Interval& a, const Interval& b) { return a.lo > b.hi; }
  friend bool operator<=(const Interval& a, const Interval& b) { return a.hi <= b.lo; }
  friend bool operator>=(const Interval& a, const Interval& b) { return a.lo >= b.hi; }
};

// Interval from an exact rational, rounded outwards: [RNDD(q), RNDU(q)], the
// tightest enclosure by doubles (a point when q is a double).
// Fast paths, which give exactly these two doubles (measured: the MPFR
// conversion is otherwise most of the cost of entering the interval rung):
//  - q an integer of at most 1000 bits: mpz_get_d truncates towards 0 (GMP
//    manual), so d = RZ(q); mpz_cmp_d(q, d) == 0 says d = q exactly (a
//    point); otherwise q lies strictly between d and the next double away
//    from 0, nextafter(d, ±inf), which are then RNDD(q) and RNDU(q);
//  - q = n/d with |n| and d below 2^53 (both exact doubles, q >= 2^-53 in
//    magnitude: no underflow; d > 0): x = n / d in round-to-nearest, and the
//    remainder x·d - n is exactly a double (the remainder of a correctly
//    rounded quotient is representable, Boldo & Daumas 2003, "Representable
//    correcting terms for possibly underflowing floating point operations"),
//    so fma(x, d, -n) is computed exactly and its sign is the sign of x - q
//    (d > 0): 0 gives the point [x, x], > 0 gives [nextafter(x, -inf), x],
//    < 0 gives [x, nextafter(x, +inf)].
// Anything else goes through MPFR's directed roundings.
inline Interval interval_of(const mpq_class& q) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const mpz_srcptr num = q.get_num_mpz_t(), den = q.get_den_mpz_t();
  if (mpz_cmp_ui(den, 1) == 0 && mpz_sizeinbase(num, 2) <= 1000) {
    const double d = mpz_get_d(num);
    const int c = mpz_cmp_d(num, d);
    if (c == 0) return {d, d};
    return c > 0 ? Interval(d, std::nextafter(d, inf)) : Interval(std::nextafter(d, -inf), d);
  }
  if (mpz_sgn(den) > 0 && mpz_sizeinbase(num, 2) <= 53 && mpz_sizeinbase(den, 2) <= 53) {
    const double n = mpz_get_d(num), d = mpz_get_d(den);  // exact
    const double x = n / d;
    const double r = std::fma(x, d, -n);
    if (r == 0) return {x, x};
    return r > 0 ? Interval(std::nextafter(x, -inf), x) : Interval(x, std::nextafter(x, inf));
  }
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDD);
  double lo = mpfr_get_d(r, MPFR_RNDD);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDU);
  double hi = mpfr_get_d(r, MPFR_RNDU);
  mpfr_clear(r);
  return {lo, hi};
}

// What the certified policy needs of an interval type (also for MpfiInterval):
// the hull of two rationals, and a point's exact value.
inline Interval interval_hull(const mpq_class& lo, const mpq_class& hi, const Interval& /*like*/) {
  return {interval_of(lo).lo, interval_of(hi).hi};
}
inline std::optional<mpq_class> exact_point(const Interval& x) {
  if (x.lo != x.hi || !std::isfinite(x.lo)) return std::nullopt;
  return mpq_class(x.lo);
}

template <>
struct scalar_traits<Interval> {
  static constexpr bool is_exact = false;
  static Sign sign(const Interval& x) {
    if (std::isnan(x.lo) || std::isnan(x.hi)) return Sign::uncertain;
    if (x.lo > 0) return Sign::positive;
    if (x.hi < 0) return Sign::negative;
    if (x.lo == 0 && x.hi == 0) return Sign::zero;
    return Sign::uncertain;
  }
  static double to_double(const Interval& x) { return x.mid(); }  // display only
  static Interval from_rational(const mpq_class& q, const Interval& /*like*/ = Interval()) { return interval_of(q); }
  static Interval abs(const Interval& x) {
    if (x.lo >= 0) return x;
    if (x.hi <= 0) return -x;
    return {0, std::max(-x.lo, x.hi)};
  }
  static int precision(const Interval&) { return 53; }
  static std::string to_string(const Interval& x) {
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", x.mid());
    return b;
  }
};

}  // namespace eccd
