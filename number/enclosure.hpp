#pragma once
// What the cycloidal pipeline (kernel/cycloidal_cd_disc.hpp) needs of an
// enclosing scalar: sin(πx) and cos(πx), the enclosure of a whole interval
// [lo, hi] of t, and an upper bound of |x|.
//
// Statement. Two enclosing types are used, both templated through the same
// code: Bounded<U> (number/running_error.hpp; U = double or Mpfr) read as a
// mid-point v and radius e, the exact value lying in [v - e, v + e]; and
// MpfiInterval (number/mpfi_interval.hpp), outward-rounded end points.
//   sin_cos_pi(Bounded): s, c computed by MPFR, correctly rounded to U's
//     precision p (mpfr_sin_cos) from πv computed at p + 8 bits; since
//     |d sin(πx)/dx| <= π, the radius is π e + π|v| 2^-(p+6) (the argument's
//     rounding, π's included) + 2^-p (the result's rounding), enlarged as
//     Bounded enlarges its bounds. No libm accuracy is assumed (MPFR is
//     correctly rounded), so the double pipeline's bound is proved as well.
//   sin_cos_pi(MpfiInterval): mpfi_const_pi, mpfi_mul, mpfi_sin, mpfi_cos
//     (outward rounded: an enclosure).
//   sin_cos_pi(Dual<T>): (sin πx, π cos πx · x'), (cos πx, -π sin πx · x').
//   range_of(lo, hi, like): [lo, hi] as a T, for evaluating over a cell.
// Requirements: T = Bounded<double>, Bounded<Mpfr>, MpfiInterval, or Dual of one.
#include "number/dual.hpp"
#include "number/mpfi_interval.hpp"
#include "number/mpfr_real.hpp"
#include "number/running_error.hpp"

#include <gmpxx.h>
#include <mpfi.h>
#include <mpfr.h>

#include <cmath>
#include <type_traits>

namespace eccd {

namespace enclosure_detail {
template <class U>
int precision_of(const U& x) {
  if constexpr (std::is_same_v<U, double>) {
    (void)x;
    return 53;
  } else
    return x.precision() > 0 ? x.precision() : int(Mpfr::kConstBits);
}
// An upper bound of a non-negative rational as a long double.
inline long double up(const mpq_class& q) {
  mpfr_t r;
  mpfr_init2(r, 64);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDU);
  long double d = mpfr_get_ld(r, MPFR_RNDU);
  mpfr_clear(r);
  return d;
}
}  // namespace enclosure_detail

template <class U>
void sin_cos_pi(const Bounded<U>& x, Bounded<U>& s, Bounded<U>& c) {
  using B = Bounded<U>;
  using E = typename B::E;
  const int p = enclosure_detail::precision_of(x.value());
  mpfr_t arg, ms, mc;
  mpfr_inits2(p + 8, arg, (mpfr_ptr) nullptr);
  mpfr_inits2(p, ms, mc, (mpfr_ptr) nullptr);
  mpfr_const_pi(arg, MPFR_RNDN);
  if constexpr (std::is_same_v<U, double>)
    mpfr_mul_d(arg, arg, x.value(), MPFR_RNDN);
  else
    mpfr_mul(arg, arg, x.value().get(), MPFR_RNDN);
  mpfr_sin_cos(ms, mc, arg, MPFR_RNDN);
  U sv, cv;
  if constexpr (std::is_same_v<U, double>) {
    sv = mpfr_get_d(ms, MPFR_RNDN);
    cv = mpfr_get_d(mc, MPFR_RNDN);
  } else {
    sv = U(mpq_class(0), p);
    cv = U(mpq_class(0), p);
    mpfr_set(sv.get(), ms, MPFR_RNDN);
    mpfr_set(cv.get(), mc, MPFR_RNDN);
  }
  mpfr_clears(arg, ms, mc, (mpfr_ptr) nullptr);
  const E pi_up = E(3.1415926535897932385L) * (1 + E(0x1p-60));
  E e = pi_up * x.bound() + pi_up * B::mag(x.value()) * std::ldexp(E(1), -(p + 6)) + std::ldexp(E(1), -p);
  e = B::grow(B::grow(e));
  s = B(std::move(sv), e);
  c = B(std::move(cv), e);
}

inline void sin_cos_pi(const MpfiInterval& x, MpfiInterval& s, MpfiInterval& c) {
  const int p = x.precision() > 0 ? x.precision() : int(MpfiInterval::kConstBits);
  MpfiInterval arg(mpq_class(0), p);
  mpfi_const_pi(arg.get());
  mpfi_mul(arg.get(), arg.get(), x.get());
  s = MpfiInterval(mpq_class(0), p);
  c = MpfiInterval(mpq_class(0), p);
  mpfi_sin(s.get(), arg.get());
  mpfi_cos(c.get(), arg.get());
}

template <class T>
void sin_cos_pi(const Dual<T>& x, Dual<T>& s, Dual<T>& c) {
  T sv, cv;
  sin_cos_pi(x.v, sv, cv);
  const T pi = pi_enclosure(x.v);
  T ds = pi * (cv * x.d), dc = -(pi * (sv * x.d));
  s = Dual<T>(sv, ds);
  c = Dual<T>(cv, dc);
}

// π as a T (an enclosure of it).
template <class U>
Bounded<U> pi_enclosure(const Bounded<U>& like) {
  using B = Bounded<U>;
  const int p = enclosure_detail::precision_of(like.value());
  mpfr_t m;
  mpfr_init2(m, p);
  mpfr_const_pi(m, MPFR_RNDN);
  U v;
  if constexpr (std::is_same_v<U, double>)
    v = mpfr_get_d(m, MPFR_RNDN);
  else {
    v = U(mpq_class(0), p);
    mpfr_set(v.get(), m, MPFR_RNDN);
  }
  mpfr_clear(m);
  return B(std::move(v), B::grow(typename B::E(4) * std::ldexp(typename B::E(1), -p)));
}
inline MpfiInterval pi_enclosure(const MpfiInterval& like) {
  MpfiInterval r(mpq_class(0), like.precision() > 0 ? like.precision() : int(MpfiInterval::kConstBits));
  mpfi_const_pi(r.get());
  return r;
}

// [lo, hi] (lo <= hi) as a T.
template <class U>
Bounded<U> range_of(const mpq_class& lo, const mpq_class& hi, const Bounded<U>& like) {
  using B = Bounded<U>;
  B m = scalar_traits<B>::from_rational(mpq_class((lo + hi) / 2), like);
  return B(m.value(), B::grow(m.bound() + typename B::E(enclosure_detail::up(mpq_class((hi - lo) / 2)))));
}
inline MpfiInterval range_of(const mpq_class& lo, const mpq_class& hi, const MpfiInterval& like) {
  return MpfiInterval(lo, hi, like.precision() > 0 ? like.precision() : int(MpfiInterval::kConstBits));
}

// An upper bound of |x| over the enclosure (for the ε of a "touch or near miss" note).
template <class U>
double magnitude_bound(const Bounded<U>& x) {
  return double(Bounded<U>::mag(x.value()) + x.bound()) * (1 + 0x1p-40);
}
inline double magnitude_bound(const MpfiInterval& x) {
  double l = std::fabs(mpfr_get_d(&x.get()->left, MPFR_RNDA)), r = std::fabs(mpfr_get_d(&x.get()->right, MPFR_RNDA));
  return std::max(l, r);
}

}  // namespace eccd
