#pragma once
// Mpfr: an MPFR number whose precision travels with the value.
//
// Statement. The workbench runs the same templated pipeline at any MPFR
// precision from 53 to (at least) 4096 bits, chosen per run and written into
// every report. There is no global default precision: a value made by
// `Mpfr(q, bits)` carries `bits`; the result of an operation carries the
// larger precision of its operands, rounded to nearest. A small integer
// constant written in templated code (`T(18) * x`) is held exactly and adopts
// the precision of the value it meets ("unset" precision, reported as 0).
//
// Requirements: none beyond MPFR. Known failure modes: an operation between
// two unset constants is carried out at kConstBits bits; templated code only
// multiplies constants into values that carry a precision.
#include "number/scalar_traits.hpp"

#include <mpfr.h>

#include <algorithm>
#include <string>
#include <utility>

namespace eccd {

class Mpfr {
 public:
  static constexpr mpfr_prec_t kConstBits = 128;

  Mpfr() : prec_(0) {
    mpfr_init2(v_, kConstBits);
    mpfr_set_zero(v_, 1);
  }
  Mpfr(int k) : prec_(0) {
    mpfr_init2(v_, kConstBits);
    mpfr_set_si(v_, k, MPFR_RNDN);
  }  // NOLINT: implicit by design
  Mpfr(long k) : prec_(0) {
    mpfr_init2(v_, kConstBits);
    mpfr_set_si(v_, k, MPFR_RNDN);
  }  // NOLINT
  Mpfr(const mpq_class& q, int bits) : prec_(bits) {
    mpfr_init2(v_, bits);
    mpfr_set_q(v_, q.get_mpq_t(), MPFR_RNDN);
  }
  Mpfr(double d, int bits) : prec_(bits) {
    mpfr_init2(v_, bits);
    mpfr_set_d(v_, d, MPFR_RNDN);
  }
  Mpfr(const Mpfr& o) : prec_(o.prec_) {
    mpfr_init2(v_, mpfr_get_prec(o.v_));
    mpfr_set(v_, o.v_, MPFR_RNDN);
  }
  // A move steals the limbs (no allocation: half the cost of MPFR arithmetic
  // here was malloc/free); the moved-from value owns nothing and may only be
  // assigned to or destroyed.
  Mpfr(Mpfr&& o) noexcept : prec_(o.prec_) {
    v_[0] = o.v_[0];
    o.v_[0]._mpfr_d = nullptr;
  }
  Mpfr& operator=(const Mpfr& o) {
    if (this != &o) {
      prec_ = o.prec_;
      if (!v_[0]._mpfr_d)
        mpfr_init2(v_, mpfr_get_prec(o.v_));
      else
        mpfr_set_prec(v_, mpfr_get_prec(o.v_));
      mpfr_set(v_, o.v_, MPFR_RNDN);
    }
    return *this;
  }
  Mpfr& operator=(Mpfr&& o) noexcept {
    prec_ = o.prec_;
    std::swap(v_[0], o.v_[0]);
    return *this;
  }
  ~Mpfr() {
    if (v_[0]._mpfr_d) mpfr_clear(v_);
  }

  int precision() const { return int(prec_); }
  mpfr_srcptr get() const { return v_; }
  mpfr_ptr get() { return v_; }

  Mpfr& operator+=(const Mpfr& o) { return apply(o, mpfr_add); }
  Mpfr& operator-=(const Mpfr& o) { return apply(o, mpfr_sub); }
  Mpfr& operator*=(const Mpfr& o) { return apply(o, mpfr_mul); }
  Mpfr& operator/=(const Mpfr& o) { return apply(o, mpfr_div); }
  Mpfr operator-() const {
    Mpfr r(*this);
    mpfr_neg(r.v_, r.v_, MPFR_RNDN);
    return r;
  }

  friend Mpfr operator+(Mpfr a, const Mpfr& b) {
    a += b;
    return a;
  }
  friend Mpfr operator-(Mpfr a, const Mpfr& b) {
    a -= b;
    return a;
  }
  friend Mpfr operator*(Mpfr a, const Mpfr& b) {
    a *= b;
    return a;
  }
  friend Mpfr operator/(Mpfr a, const Mpfr& b) {
    a /= b;
    return a;
  }
  friend bool operator<(const Mpfr& a, const Mpfr& b) { return mpfr_less_p(a.v_, b.v_); }
  friend bool operator>(const Mpfr& a, const Mpfr& b) { return mpfr_greater_p(a.v_, b.v_); }
  friend bool operator<=(const Mpfr& a, const Mpfr& b) { return mpfr_lessequal_p(a.v_, b.v_); }
  friend bool operator>=(const Mpfr& a, const Mpfr& b) { return mpfr_greaterequal_p(a.v_, b.v_); }
  friend bool operator==(const Mpfr& a, const Mpfr& b) { return mpfr_equal_p(a.v_, b.v_); }
  friend bool operator!=(const Mpfr& a, const Mpfr& b) { return !mpfr_equal_p(a.v_, b.v_); }

 private:
  template <class Op>
  Mpfr& apply(const Mpfr& o, Op op) {
    mpfr_prec_t p = std::max(prec_, o.prec_);
    if (p == 0) {  // two constants: stay a constant
      op(v_, v_, o.v_, MPFR_RNDN);
      return *this;
    }
    if (p != mpfr_get_prec(v_)) mpfr_prec_round(v_, p, MPFR_RNDN);
    prec_ = p;
    op(v_, v_, o.v_, MPFR_RNDN);
    return *this;
  }
  mpfr_prec_t prec_;  // 0: an exact small constant that adopts its partner's precision
  mpfr_t v_;
};

template <>
struct scalar_traits<Mpfr> {
  static constexpr bool is_exact = false;
  static Sign sign(const Mpfr& x) {
    if (mpfr_nan_p(x.get())) return Sign::uncertain;
    return sign_of_int(mpfr_sgn(x.get()));
  }
  static double to_double(const Mpfr& x) { return mpfr_get_d(x.get(), MPFR_RNDN); }
  static Mpfr from_rational(const mpq_class& q, const Mpfr& like) {
    return Mpfr(q, like.precision() > 0 ? like.precision() : int(Mpfr::kConstBits));
  }
  static Mpfr abs(const Mpfr& x) {
    Mpfr r(x);
    mpfr_abs(r.get(), r.get(), MPFR_RNDN);
    return r;
  }
  static int precision(const Mpfr& x) { return x.precision(); }
  static std::string to_string(const Mpfr& x) {
    char* s = nullptr;
    int digits = std::max(17, int(double(std::max(x.precision(), 53)) * 0.30103) + 2);
    mpfr_asprintf(&s, "%.*Rg", digits, x.get());
    std::string r(s);
    mpfr_free_str(s);
    return r;
  }
};

}  // namespace eccd
