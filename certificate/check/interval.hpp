#pragma once
// Intervals that round outwards, written for the certificate checker alone
// (certificate/check/): MI, MPFI intervals at a stated precision, and DI,
// intervals of doubles widened past the rounding error after every operation.
//
// Statement. Moore, Kearfott, Cloud, "Introduction to Interval Analysis",
// 2009, chapter 2 (the inclusion property): each operation's result holds
// every value of the operation at points of its arguments. MI: MPFI rounds
// each end outwards. DI: IEEE round-to-nearest errs by at most 2^-53 |x|
// (2^-1075 below the normal range), so moving the nearest result by
// 2^-50 |x| + 2^-1074 towards -inf (lo) and +inf (hi) encloses the exact
// value; a rational becomes the interval between the doubles just below and
// above mpq_get_d's (truncated) value. A sign is
// proved when both ends are finite and of one strict sign (sign() gives +1 or
// -1), else 0 ("not proved"). Both types offer the same operations so the
// checker's Bernstein code (certificate/check/bernstein.hpp) is one template.
// Requirements: GMP, MPFR, MPFI. No eccd code outside eccd::check.
#include <gmpxx.h>
#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace eccd::check {

// ------------------------------------------------------------------ MPFI
class MI {
 public:
  MI() {
    mpfi_init2(v_, 64);
    mpfi_set_si(v_, 0);
  }
  MI(const mpq_class& q, int bits) {
    mpfi_init2(v_, bits);
    mpfi_set_q(v_, q.get_mpq_t());
  }
  MI(const mpq_class& lo, const mpq_class& hi, int bits) {
    mpfi_init2(v_, bits);
    mpfi_interv_q(v_, lo.get_mpq_t(), hi.get_mpq_t());
  }
  MI(const MI& o) {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_set(v_, o.v_);
  }
  MI(MI&& o) noexcept {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_swap(v_, o.v_);
  }
  MI& operator=(const MI& o) {
    if (this != &o) {
      mpfi_set_prec(v_, mpfi_get_prec(o.v_));
      mpfi_set(v_, o.v_);
    }
    return *this;
  }
  MI& operator=(MI&& o) noexcept {
    mpfi_swap(v_, o.v_);
    return *this;
  }
  ~MI() { mpfi_clear(v_); }

  int bits() const { return int(mpfi_get_prec(v_)); }
  friend MI operator+(const MI& a, const MI& b) {
    MI r = a.blank(b);
    mpfi_add(r.v_, a.v_, b.v_);
    return r;
  }
  friend MI operator-(const MI& a, const MI& b) {
    MI r = a.blank(b);
    mpfi_sub(r.v_, a.v_, b.v_);
    return r;
  }
  friend MI operator*(const MI& a, const MI& b) {
    MI r = a.blank(b);
    mpfi_mul(r.v_, a.v_, b.v_);
    return r;
  }
  MI& operator+=(const MI& b) {
    mpfi_add(v_, v_, b.v_);
    return *this;
  }
  MI& operator-=(const MI& b) {
    mpfi_sub(v_, v_, b.v_);
    return *this;
  }
  MI operator-() const {
    MI r = *this;
    mpfi_neg(r.v_, v_);
    return r;
  }
  // d = y a + x d and d = y d + x b, in place (y = 1 - x; de Casteljau's steps without an allocation;
  // with point weights this form does not widen: the width of the result is the weighted mean of the widths)
  static void lerp_from(MI& d, const MI& a, const MI& x, const MI& y) {
    mpfi_ptr t = scratch(d);
    mpfi_mul(t, y.v_, a.v_);
    mpfi_mul(d.v_, d.v_, x.v_);
    mpfi_add(d.v_, d.v_, t);
  }
  static void lerp_to(MI& d, const MI& b, const MI& x, const MI& y) {
    mpfi_ptr t = scratch(d);
    mpfi_mul(t, x.v_, b.v_);
    mpfi_mul(d.v_, d.v_, y.v_);
    mpfi_add(d.v_, d.v_, t);
  }
  static MI one_minus(const MI& x) {
    MI r = x;
    mpfi_ui_sub(r.v_, 1, x.v_);
    return r;
  }
  bool finite() const { return mpfr_number_p(&v_[0].left) && mpfr_number_p(&v_[0].right); }
  int sign() const {
    if (!finite()) return 0;
    if (mpfr_sgn(&v_[0].left) > 0) return 1;
    if (mpfr_sgn(&v_[0].right) < 0) return -1;
    return 0;
  }
  mpq_class lower() const {
    mpq_class q;
    mpfr_get_q(q.get_mpq_t(), &v_[0].left);
    return q;
  }
  mpq_class upper() const {
    mpq_class q;
    mpfr_get_q(q.get_mpq_t(), &v_[0].right);
    return q;
  }
  double lo_d() const { return mpfr_get_d(&v_[0].left, MPFR_RNDD); }
  double hi_d() const { return mpfr_get_d(&v_[0].right, MPFR_RNDU); }
  double mid() const { return 0.5 * (lo_d() + hi_d()); }
  MI hull(const MI& o) const {
    MI r = *this;
    if (mpfr_cmp(&o.v_[0].left, &r.v_[0].left) < 0) mpfr_set(&r.v_[0].left, &o.v_[0].left, MPFR_RNDD);
    if (mpfr_cmp(&o.v_[0].right, &r.v_[0].right) > 0) mpfr_set(&r.v_[0].right, &o.v_[0].right, MPFR_RNDU);
    return r;
  }
  mpfi_ptr get() { return v_; }
  mpfi_srcptr get() const { return v_; }

 private:
  static mpfi_ptr scratch(const MI& like) {  // a per-thread temporary at like's precision
    thread_local MI t;
    if (mpfi_get_prec(t.v_) != mpfi_get_prec(like.v_)) mpfi_set_prec(t.v_, mpfi_get_prec(like.v_));
    return t.v_;
  }
  MI blank(const MI& b) const {
    MI r;
    mpfi_set_prec(r.v_, std::max(mpfi_get_prec(v_), mpfi_get_prec(b.v_)));
    return r;
  }
  mpfi_t v_;
};

// ------------------------------------------------------------------ doubles, widened
struct DI {
  double lo = 0, hi = 0;
  DI() = default;
  DI(double l, double h) : lo(l), hi(h) {}
  // Outwards past the rounding error of a nearest-rounded x: |error| <= 2^-53 |x| (normal) or 2^-1075 (subnormal);
  // moving by 2^-50 |x| + 2^-1074 (itself rounded by at most half an ulp) clears it. NaN widens to everything.
  static double down(double x) {
    if (std::isnan(x)) return -std::numeric_limits<double>::infinity();
    if (!std::isfinite(x)) return x;
    return x - (std::fabs(x) * 0x1p-50 + 0x1p-1074);
  }
  static double up(double x) {
    if (std::isnan(x)) return std::numeric_limits<double>::infinity();
    if (!std::isfinite(x)) return x;
    return x + (std::fabs(x) * 0x1p-50 + 0x1p-1074);
  }
  static DI of(const mpq_class& q) {
    const double d =
        mpq_get_d(q.get_mpq_t());  // truncated: the exact value lies between d and the next double away from 0
    if (!std::isfinite(d)) return DI(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
    return DI(std::nextafter(d, -std::numeric_limits<double>::infinity()),
              std::nextafter(d, std::numeric_limits<double>::infinity()));
  }
  static DI of(const MI& x) { return DI(x.lo_d(), x.hi_d()); }  // MPFR rounds each end outwards
  friend DI operator+(const DI& a, const DI& b) { return DI(down(a.lo + b.lo), up(a.hi + b.hi)); }
  friend DI operator-(const DI& a, const DI& b) { return DI(down(a.lo - b.hi), up(a.hi - b.lo)); }
  friend DI operator*(const DI& a, const DI& b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    double l = p[0], h = p[0];
    for (double x : p) {
      if (std::isnan(x)) return DI(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
      l = std::min(l, x);
      h = std::max(h, x);
    }
    return DI(down(l), up(h));
  }
  static void lerp_from(DI& d, const DI& a, const DI& x, const DI& y) { d = y * a + x * d; }
  static void lerp_to(DI& d, const DI& b, const DI& x, const DI& y) { d = y * d + x * b; }
  static DI one_minus(const DI& x) { return DI(1, 1) - x; }
  bool finite() const { return std::isfinite(lo) && std::isfinite(hi); }
  int sign() const {
    if (!finite()) return 0;
    if (lo > 0) return 1;
    if (hi < 0) return -1;
    return 0;
  }
  double mid() const { return 0.5 * lo + 0.5 * hi; }
  mpq_class lower() const { return mpq_class(lo); }  // a finite double is an exact rational
  mpq_class upper() const { return mpq_class(hi); }
  DI hull(const DI& o) const { return DI(std::min(lo, o.lo), std::max(hi, o.hi)); }
};

}  // namespace eccd::check
