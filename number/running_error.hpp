#pragma once
// Bounded<T>: a floating value with a running a-priori bound on its absolute
// error, so that a floating pipeline knows which signs it cannot trust.
//
// Statement (Higham, "Accuracy and Stability of Numerical
// Algorithms", 2nd ed., sections 2.2 and 3.1, the standard model
// fl(a op b) = (a op b)(1 + δ), |δ| <= u). The value part is computed by
// exactly the same T operations as plain T, in the same order, so a pipeline
// run in Bounded<T> gives the plain-T answer wherever it is sure. Beside it a
// bound e >= |value - exact| is carried, where "exact" is the same formula
// evaluated exactly on the scene's exact numbers:
//   input q rounded to x:  e = 0 if x == q, else u|x|   (the input's own rounding)
//   a ± b:  e = ea + eb + u|a ± b|
//   a * b:  e = |a| eb + |b| ea + ea eb + u|ab| (+ the smallest subnormal, for underflow)
//   a / b:  e = (|a| eb + |b| ea) / (|b| (|b| - eb)) + u|a/b|, infinite if |b| <= eb
// with u = 2^-p the unit roundoff of the result's precision p. The bound
// itself is computed in E (double for T = double, long double for Mpfr, whose
// bounds would underflow a double's range above ~1000 bits) and enlarged by a
// relative 2^-50 at each step, which covers the rounding of the bound's own
// arithmetic. scalar_traits<Bounded<T>>::sign is Sign::uncertain when
// |value| <= e (and for NaN): the pipelines' uncertain-sign handling turns
// that into "undecided" at that instant.
// Evaluation points (sample instants, a root's approximation, the u of a
// shot) are points chosen by the pipeline, not approximations of an exact
// quantity whose error matters: point_of(x) drops their bound, so that a
// value computed at x is bounded against the exact value at that same x.
// For Mpfr, |x| enters the bound as the top 53 bits of its significand plus
// one unit, read from the leading limb (>= |x|, no conversion call), and the
// rounding of a result x as half a unit in x's last place, from x's exponent
// alone (<= u|x|: the bound is both cheaper and no larger than with u|x|).
// Requirements on T: double or Mpfr. Cost: see reports/performance.md; powers of
// two of a long double come from a table (pow2): std::ldexp of a long double was
// a third of an MPFR independent run (measured: docs/independent-motions.md).
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "number/pow2_scaling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace eccd {

template <class T>
class Bounded {
 public:
  using E = std::conditional_t<std::is_same_v<T, double>, double, long double>;

  Bounded() : v_(T(0)), e_(0) {}
  Bounded(int k) : v_(T(k)), e_(0) {}   // NOLINT: small exact constants, as T(3) in templated code
  Bounded(long k) : v_(T(k)), e_(0) {}  // NOLINT
  Bounded(T v, E e) : v_(std::move(v)), e_(e) {}

  const T& value() const { return v_; }
  E bound() const { return e_; }

  static E mag(const T& x) {
    if constexpr (std::is_same_v<T, double>)
      return std::fabs(x);
    else {  // the leading 53 bits of the significand plus one unit in their last place, scaled: >= |x|
      mpfr_srcptr p = x.get();
      if (!mpfr_regular_p(p)) return mpfr_zero_p(p) ? E(0) : std::numeric_limits<E>::infinity();
      return E(leading53_up(p)) * pow2(long(mpfr_get_exp(p)) - 53);
    }
  }
  // unit(x) * mag(x), the rounding error allowed for a result x of x's precision p: for double u|x|; for Mpfr
  // half a unit in the last place of x, 2^(EXP - p - 1) with 2^(EXP-1) <= |x| < 2^EXP, which is <= u|x| and
  // bounds the error of rounding to nearest (the exact result lies in x's binade or, when x = 2^(EXP-1), in
  // the one below, whose half unit is smaller). It needs only x's exponent.
  static E unit_mag(const T& x) {
    if constexpr (std::is_same_v<T, double>)
      return unit(x) * mag(x);
    else {
      mpfr_srcptr p = x.get();
      if (!mpfr_regular_p(p)) return mpfr_zero_p(p) ? E(0) : std::numeric_limits<E>::infinity();
      const long prec = x.precision() > 0 ? long(x.precision()) : long(Mpfr::kConstBits);
      return pow2(long(mpfr_get_exp(p)) - prec - 1);
    }
  }
  // The top 53 bits of a regular MPFR number's significand (read from its leading limb, whose highest bit
  // is set), plus 1: an integer in [2^52, 2^53], exact as a double, with |x| < it * 2^(EXP - 53).
  static double leading53_up(mpfr_srcptr p) {
    static_assert(GMP_NUMB_BITS == 64, "the leading limb holds 64 bits");
    const mp_limb_t top = p->_mpfr_d[(mpfr_get_prec(p) - 1) / GMP_NUMB_BITS];
    return double((top >> (GMP_NUMB_BITS - 53)) + 1);
  }
  // 2^k as E, k clamped to [-20000, 20000] (as std::ldexp(E(1), k), which it replaces in the hot path: ldexp of a
  // long double is a software routine, and was a third of an MPFR independent run's time). A table over
  // long double's exponent range (normal and subnormal), ldexp outside it.
  static E pow2(long k) {
    if constexpr (std::is_same_v<E, double>)
      return std::ldexp(1.0, int(std::clamp<long>(k, -20000, 20000)));
    else {
      constexpr long lo = std::numeric_limits<E>::min_exponent - std::numeric_limits<E>::digits - 1,
                     hi = std::numeric_limits<E>::max_exponent;
      static const std::vector<E> table = [] {
        std::vector<E> t(std::size_t(hi - lo + 1));
        for (long i = lo; i <= hi; ++i) t[std::size_t(i - lo)] = std::ldexp(E(1), int(i));
        return t;
      }();
      if (k < lo || k > hi) return std::ldexp(E(1), int(std::clamp<long>(k, -20000, 20000)));
      return table[std::size_t(k - lo)];
    }
  }
  // The unit roundoff of a result of x's precision.
  static E unit(const T& x) {
    if constexpr (std::is_same_v<T, double>) {
      (void)x;
      return E(0x1p-53);
    } else {
      int p = x.precision() > 0 ? x.precision() : int(Mpfr::kConstBits);
      return std::ldexp(E(1), -p);
    }
  }
  static E grow(E e) { return e + e * E(0x1p-50); }
  static E tiny() {
    if constexpr (std::is_same_v<T, double>)
      return std::numeric_limits<double>::denorm_min();
    else
      return E(0);
  }

  Bounded& operator+=(const Bounded& o) {
    v_ += o.v_;
    e_ = grow(e_ + o.e_ + unit_mag(v_));
    return *this;
  }
  Bounded& operator-=(const Bounded& o) {
    v_ -= o.v_;
    e_ = grow(e_ + o.e_ + unit_mag(v_));
    return *this;
  }
  Bounded& operator*=(const Bounded& o) {
    E e;
    if constexpr (std::is_same_v<T, double>)
      e = mag(v_) * o.e_ + mag(o.v_) * e_ + e_ * o.e_;
    else  // a term whose error factor is 0 is 0 (skipped: each mag reads an MPFR number; a non-finite
          // factor makes the product's unit_mag infinite below anyway)
      e = (o.e_ != 0 ? mag(v_) * o.e_ : E(0)) + (e_ != 0 ? mag(o.v_) * e_ + e_ * o.e_ : E(0));
    v_ *= o.v_;
    e_ = grow(e + unit_mag(v_) + tiny());
    return *this;
  }
  Bounded& operator/=(const Bounded& o) {
    E a = mag(v_), b = mag(o.v_);
    v_ /= o.v_;
    if (!(b > o.e_))
      e_ = std::numeric_limits<E>::infinity();
    else
      e_ = grow((a * o.e_ + b * e_) / (b * (b - o.e_)) + unit_mag(v_) + tiny());
    return *this;
  }
  Bounded operator-() const { return Bounded(-v_, e_); }

  friend Bounded operator+(Bounded a, const Bounded& b) {
    a += b;
    return a;
  }
  friend Bounded operator-(Bounded a, const Bounded& b) {
    a -= b;
    return a;
  }
  friend Bounded operator*(Bounded a, const Bounded& b) {
    a *= b;
    return a;
  }
  friend Bounded operator/(Bounded a, const Bounded& b) {
    a /= b;
    return a;
  }
  friend bool operator<(const Bounded& a, const Bounded& b) { return a.v_ < b.v_; }
  friend bool operator>(const Bounded& a, const Bounded& b) { return a.v_ > b.v_; }
  friend bool operator<=(const Bounded& a, const Bounded& b) { return a.v_ <= b.v_; }
  friend bool operator>=(const Bounded& a, const Bounded& b) { return a.v_ >= b.v_; }
  friend bool operator==(const Bounded& a, const Bounded& b) { return a.v_ == b.v_; }
  friend bool operator!=(const Bounded& a, const Bounded& b) { return a.v_ != b.v_; }

 private:
  T v_;
  E e_;
};

template <class T>
struct is_bounded : std::false_type {};
template <class T>
struct is_bounded<Bounded<T>> : std::true_type {};
template <class T>
inline constexpr bool has_error_bound_v = is_bounded<T>::value;

// An evaluation point: the same value, error bound 0 (see the header prose).
template <class T>
inline T point_of(const T& x) {
  return x;
}
template <class T>
inline Bounded<T> point_of(const Bounded<T>& x) {
  return Bounded<T>(x.value(), 0);
}
// The value alone, in the underlying type (plain T: itself): for steps that read only values' exponents.
template <class T>
inline const T& value_only(const T& x) {
  return x;
}
template <class T>
inline const T& value_only(const Bounded<T>& x) {
  return x.value();
}

// The plain arithmetic under a running bound, for work whose result is a
// point or a location and not a sign (a root's refinement, a witness's search,
// a picture's directions): PlainOf<Bounded<V>>::type is V, of(x) the value
// (bit for bit the plain-V result of the same operations), lift(v) an
// evaluation point (bound 0, as point_of); PlainOf<T> is T itself otherwise.
template <class T>
struct PlainOf {
  using type = T;
  static const T& of(const T& x) { return x; }
  static T lift(const T& x) { return x; }
};
template <class V>
struct PlainOf<Bounded<V>> {
  using type = V;
  static const V& of(const Bounded<V>& x) { return x.value(); }
  static Bounded<V> lift(const V& x) { return Bounded<V>(x, 0); }
};

// The sign of the value held, ignoring the bound (for best-effort refinement
// of something already proved, e.g. a simple root's location).
template <class T>
inline Sign value_sign(const T& x) {
  return sign(x);
}
template <class T>
inline Sign value_sign(const Bounded<T>& x) {
  return sign(x.value());
}

template <class T>
struct scalar_traits<Bounded<T>> {
  using B = Bounded<T>;
  static constexpr bool is_exact = false;
  static Sign sign(const B& x) {
    Sign s = scalar_traits<T>::sign(x.value());
    if (s == Sign::uncertain || !(x.bound() == x.bound())) return Sign::uncertain;
    if (x.bound() == 0) return s;
    if (!(B::mag(x.value()) > x.bound())) return Sign::uncertain;
    return s;
  }
  static double to_double(const B& x) { return scalar_traits<T>::to_double(x.value()); }
  static B from_rational(const mpq_class& q, const B& like) {
    T v = scalar_traits<T>::from_rational(q, like.value());
    bool exact;
    if constexpr (std::is_same_v<T, double>)
      exact = std::isfinite(v) && mpq_class(v) == q;
    else
      exact = mpfr_number_p(v.get()) && mpfr_cmp_q(v.get(), q.get_mpq_t()) == 0;
    typename B::E e = exact ? 0 : B::grow(B::unit_mag(v) + B::tiny());
    return B(std::move(v), e);
  }
  static B abs(const B& x) { return B(scalar_traits<T>::abs(x.value()), x.bound()); }
  static int precision(const B& x) { return scalar_traits<T>::precision(x.value()); }
  static std::string to_string(const B& x) { return scalar_traits<T>::to_string(x.value()); }
};

template <class T>
inline bool is_finite_value(const Bounded<T>& x) {
  return is_finite_value(x.value()) && std::isfinite(x.bound());
}
template <class T>
inline long binary_exponent(const Bounded<T>& x) {
  return binary_exponent(x.value());
}
template <class T>
inline Bounded<T> times_pow2(const Bounded<T>& x, long k) {
  return Bounded<T>(times_pow2(x.value(), k), std::ldexp(x.bound(), int(std::clamp(k, -20000L, 20000L))));
}

}  // namespace eccd
