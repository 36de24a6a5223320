#pragma once
// MpfiInterval: closed intervals with MPFR end points (MPFI), precision
// travelling with the value — the higher-precision rung of `--arith certified`
// between intervals of doubles (number/interval.hpp) and exact rationals.
//
// Statement (interval arithmetic, Moore 1966; MPFI, Revol & Rouillier 2005).
// Every MPFI operation rounds its lower end down and its upper end up, so the
// result encloses the exact result of the operation on any values inside the
// operands. As with `Mpfr` (number/mpfr_real.hpp), a value made by
// `MpfiInterval(q, bits)` carries `bits`; an operation's result carries the
// larger precision of its operands; a small integer constant written in
// templated code (`T(18) * x`) is held exactly ([k, k] at kConstBits bits,
// precision "unset") and adopts its partner's precision. Rationals enter as
// their MPFI enclosure, so the scene's exact numbers are enclosed from the
// start. Division by an interval containing 0 gives MPFI's (-inf, +inf) or a
// NaN end, whose sign is uncertain. sign() is certain only when the interval
// lies on one side of 0 (or is exactly [0, 0]); otherwise it is
// Sign::uncertain and the caller must not decide. Comparisons `<`, `>` hold
// only when certain for every pair of values.
// Requirements: MPFI (Debian libmpfi-dev, which CGAL's GMP+MPFI kernel
// already links).
#include "number/scalar_traits.hpp"

#include <gmpxx.h>
#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

namespace eccd {

class MpfiInterval {
 public:
  static constexpr mpfr_prec_t kConstBits = 128;

  MpfiInterval() : prec_(0) {
    mpfi_init2(v_, kConstBits);
    mpfi_set_si(v_, 0);
  }
  MpfiInterval(int k) : prec_(0) {
    mpfi_init2(v_, kConstBits);
    mpfi_set_si(v_, k);
  }  // NOLINT: constants, exact
  MpfiInterval(const mpq_class& q, int bits) : prec_(bits) {
    mpfi_init2(v_, bits);
    mpfi_set_q(v_, q.get_mpq_t());
  }
  // The hull [lo, hi] of two rationals (lo <= hi), rounded outwards.
  MpfiInterval(const mpq_class& lo, const mpq_class& hi, int bits) : prec_(bits) {
    mpfi_init2(v_, bits);
    mpfi_interv_q(v_, lo.get_mpq_t(), hi.get_mpq_t());
  }
  MpfiInterval(const MpfiInterval& o) : prec_(o.prec_) {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_set(v_, o.v_);
  }
  // A move steals the end points; the moved-from value may only be assigned to or destroyed.
  MpfiInterval(MpfiInterval&& o) noexcept : prec_(o.prec_) {
    v_[0] = o.v_[0];
    o.v_[0].left._mpfr_d = nullptr;
  }
  MpfiInterval& operator=(const MpfiInterval& o) {
    if (this != &o) {
      prec_ = o.prec_;
      if (!v_[0].left._mpfr_d)
        mpfi_init2(v_, mpfi_get_prec(o.v_));
      else
        mpfi_set_prec(v_, mpfi_get_prec(o.v_));
      mpfi_set(v_, o.v_);
    }
    return *this;
  }
  MpfiInterval& operator=(MpfiInterval&& o) noexcept {
    prec_ = o.prec_;
    std::swap(v_[0], o.v_[0]);
    return *this;
  }
  ~MpfiInterval() {
    if (v_[0].left._mpfr_d) mpfi_clear(v_);
  }

  int precision() const { return int(prec_); }
  mpfi_srcptr get() const { return v_; }
  mpfi_ptr get() { return v_; }
  // The exact value when the interval is a single point, else nothing.
  std::optional<mpq_class> point() const {
    if (mpfi_nan_p(v_) || !mpfr_equal_p(&v_[0].left, &v_[0].right) || !mpfr_number_p(&v_[0].left)) return std::nullopt;
    mpq_class q;
    mpfr_get_q(q.get_mpq_t(), &v_[0].left);
    return q;
  }
  double mid() const {
    mpfr_t m;
    mpfr_init2(m, mpfi_get_prec(v_));
    mpfi_mid(m, v_);
    double d = mpfr_get_d(m, MPFR_RNDN);
    mpfr_clear(m);
    return d;
  }

  MpfiInterval& operator+=(const MpfiInterval& o) { return apply(o, mpfi_add); }
  MpfiInterval& operator-=(const MpfiInterval& o) { return apply(o, mpfi_sub); }
  MpfiInterval& operator*=(const MpfiInterval& o) { return apply(o, mpfi_mul); }
  MpfiInterval& operator/=(const MpfiInterval& o) { return apply(o, mpfi_div); }
  MpfiInterval operator-() const {
    MpfiInterval r(*this);
    mpfi_neg(r.v_, r.v_);
    return r;
  }
  // Binary operators write straight into a result of the right precision
  // (no copy of the left operand), or reuse an expiring left operand.
  friend MpfiInterval operator+(const MpfiInterval& a, const MpfiInterval& b) { return make(a, b, mpfi_add); }
  friend MpfiInterval operator-(const MpfiInterval& a, const MpfiInterval& b) { return make(a, b, mpfi_sub); }
  friend MpfiInterval operator*(const MpfiInterval& a, const MpfiInterval& b) { return make(a, b, mpfi_mul); }
  friend MpfiInterval operator/(const MpfiInterval& a, const MpfiInterval& b) { return make(a, b, mpfi_div); }
  friend MpfiInterval operator+(MpfiInterval&& a, const MpfiInterval& b) {
    a += b;
    return std::move(a);
  }
  friend MpfiInterval operator-(MpfiInterval&& a, const MpfiInterval& b) {
    a -= b;
    return std::move(a);
  }
  friend MpfiInterval operator*(MpfiInterval&& a, const MpfiInterval& b) {
    a *= b;
    return std::move(a);
  }
  friend MpfiInterval operator/(MpfiInterval&& a, const MpfiInterval& b) {
    a /= b;
    return std::move(a);
  }
  // Certainly less / greater for every pair of values.
  friend bool operator<(const MpfiInterval& a, const MpfiInterval& b) {
    return mpfr_less_p(&a.v_[0].right, &b.v_[0].left);
  }
  friend bool operator>(const MpfiInterval& a, const MpfiInterval& b) {
    return mpfr_greater_p(&a.v_[0].left, &b.v_[0].right);
  }
  friend bool operator<=(const MpfiInterval& a, const MpfiInterval& b) {
    return mpfr_lessequal_p(&a.v_[0].right, &b.v_[0].left);
  }
  friend bool operator>=(const MpfiInterval& a, const MpfiInterval& b) {
    return mpfr_greaterequal_p(&a.v_[0].left, &b.v_[0].right);
  }

 private:
  template <class Op>
  MpfiInterval& apply(const MpfiInterval& o, Op op) {
    mpfr_prec_t p = std::max(prec_, o.prec_);
    if (p == 0) {  // two constants: stay a constant (exact at kConstBits for the small integers used)
      op(v_, v_, o.v_);
      return *this;
    }
    if (p != mpfi_get_prec(v_)) mpfi_round_prec(v_, p);  // outward rounding: still an enclosure
    prec_ = p;
    op(v_, v_, o.v_);
    return *this;
  }
  struct Uninitialised {};
  MpfiInterval(Uninitialised, mpfr_prec_t p, mpfr_prec_t storage) : prec_(p) { mpfi_init2(v_, storage); }
  template <class Op>
  static MpfiInterval make(const MpfiInterval& a, const MpfiInterval& b, Op op) {
    mpfr_prec_t p = std::max(a.prec_, b.prec_);
    MpfiInterval r(Uninitialised{}, p, p == 0 ? kConstBits : p);
    op(r.v_, a.v_, b.v_);
    return r;
  }
  mpfr_prec_t prec_;  // 0: an exact small constant that adopts its partner's precision
  mpfi_t v_;
};

// What the certified policy needs of an interval type (also for Interval):
// the hull of two rationals at `like`'s precision, and a point's exact value.
inline MpfiInterval interval_hull(const mpq_class& lo, const mpq_class& hi, const MpfiInterval& like) {
  return MpfiInterval(lo, hi, like.precision() > 0 ? like.precision() : int(MpfiInterval::kConstBits));
}
inline std::optional<mpq_class> exact_point(const MpfiInterval& x) { return x.point(); }

template <>
struct scalar_traits<MpfiInterval> {
  static constexpr bool is_exact = false;
  static Sign sign(const MpfiInterval& x) {
    mpfi_srcptr v = x.get();
    if (mpfi_nan_p(v)) return Sign::uncertain;
    if (mpfr_sgn(&v->left) > 0) return Sign::positive;
    if (mpfr_sgn(&v->right) < 0) return Sign::negative;
    if (mpfr_zero_p(&v->left) && mpfr_zero_p(&v->right)) return Sign::zero;
    return Sign::uncertain;
  }
  static double to_double(const MpfiInterval& x) { return x.mid(); }  // display only
  static MpfiInterval from_rational(const mpq_class& q, const MpfiInterval& like) {
    return MpfiInterval(q, like.precision() > 0 ? like.precision() : int(MpfiInterval::kConstBits));
  }
  static MpfiInterval abs(const MpfiInterval& x) {
    MpfiInterval r(x);
    mpfi_abs(r.get(), x.get());
    return r;
  }
  static int precision(const MpfiInterval& x) { return x.precision(); }
  static std::string to_string(const MpfiInterval& x) {
    char* s = nullptr;
    mpfr_asprintf(&s, "[%.20Rg, %.20Rg]", &x.get()->left, &x.get()->right);
    std::string r(s);
    mpfr_free_str(s);
    return r;
  }
};

}  // namespace eccd
