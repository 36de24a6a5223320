#pragma once
// HalvingStep<T>: one step of de Casteljau's algorithm at 1/2,
//   a <- (1 - 1/2) a + (1/2) b,
// in place, with the same result in every arithmetic as the four operations
// written out (copy a, times 1 - 1/2, plus a copy of b times 1/2).
//
// Statement. Subdividing a Bernstein net at 1/2 (kernel/bernstein.hpp,
// kernel/trivariate_bernstein.hpp split_half; the subdivision of the Bezier
// method, paper 001 section 4, docs/references.md) repeats this step. For
// T = Bounded<Mpfr> (number/running_error.hpp) the operations as
// written cost two copies and two full multiplications per step, although
// both products are exact: with a and b of precision p and 1/2 held exactly,
// a/2 and b/2 are exact, and RN_p(a/2 + b/2) = RN_p(a + b)/2 (a power of two
// commutes with rounding to nearest; MPFR's exponent range is not left here).
// The specialisation below computes the value as one addition and one
// exponent shift (mpfr_div_2ui), bit for bit the value of the written-out
// steps, and carries exactly the same running error bound: the bound of each
// product and of the sum is evaluated with Bounded's own formulas on the
// magnitudes and exponents those products would have had (mag of the factor,
// half a unit of the product's last place from its exponent), in the same
// order, so the bound is also bit for bit the written-out one (its reads are
// Bounded's, inlined: a power of two built from its bits, not looked up). A
// sign decided on a net subdivided this way is therefore decided on the same
// value and bound as with the written-out operations; only the work changes. Where the shortcut's conditions do
// not hold (a coefficient or the constants of another precision, a 1/2 that
// is not exactly 1/2), the step falls back to the written-out operations.
// Requirements on T: the ring operations and scalar_traits<T>::from_rational;
// the specialisation is for Bounded<Mpfr> only.
#include "number/mpfr_real.hpp"
#include "number/running_error.hpp"

#include <mpfr.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

namespace eccd {

// The step as written: four operations, in any arithmetic.
template <class T>
class WrittenHalvingStep {
 public:
  explicit WrittenHalvingStep(const T& half) : half_(half), other_(T(1) - half), x_(half), y_(half) {}
  // a <- (1 - half) a + half b (compound operations: no temporaries, an MPFR copy allocates)
  void operator()(T& a, const T& b) {
    x_ = a;
    x_ *= other_;
    y_ = b;
    y_ *= half_;
    x_ += y_;
    a = std::move(x_);  // the number types' moves swap: x_ keeps a live value for the next copy
  }

 private:
  T half_, other_, x_, y_;
};

template <class T>
class HalvingStep : public WrittenHalvingStep<T> {
 public:
  using WrittenHalvingStep<T>::WrittenHalvingStep;
};

template <>
class HalvingStep<Bounded<Mpfr>> {
  using B = Bounded<Mpfr>;
  using E = B::E;

 public:
  explicit HalvingStep(const B& half) : half_(half), other_(B(1) - half) {
    prec_ = half_.value().precision();
    exact_ = prec_ > 0 && other_.value().precision() == prec_ && mpfr_get_prec(half_.value().get()) == prec_ &&
             mpfr_get_prec(other_.value().get()) == prec_ && mpfr_cmp_ui_2exp(half_.value().get(), 1, -1) == 0 &&
             mpfr_cmp_ui_2exp(other_.value().get(), 1, -1) == 0;
    mag_half_ = B::mag(half_.value());
    mag_other_ = B::mag(other_.value());
  }

  void operator()(B& a, const B& b) {
    const Mpfr& av = a.value();
    const Mpfr& bv = b.value();
    if (!exact_ || av.precision() != prec_ || bv.precision() != prec_ || mpfr_get_prec(av.get()) != prec_ ||
        mpfr_get_prec(bv.get()) != prec_) {
      if (!slow_) slow_.emplace(half_);
      (*slow_)(a, b);
      return;
    }
    // x = a * other: Bounded::operator*= with v = a, o = other
    const E ea = a.bound(), eb = b.bound(), eo = other_.bound(), eh = half_.bound();
    E ex = (eo != 0 ? mag(av) * eo : E(0)) + (ea != 0 ? mag_other_ * ea + ea * eo : E(0));
    ex = B::grow(ex + unit_mag(av, -1) + B::tiny());
    // y = b * half
    E ey = (eh != 0 ? mag(bv) * eh : E(0)) + (eb != 0 ? mag_half_ * eb + eb * eh : E(0));
    ey = B::grow(ey + unit_mag(bv, -1) + B::tiny());
    // x + y = RN(a + b) / 2, in a's own storage (a is not const: its value is changed in place through
    // its MPFR handle, and the bound written by a move assignment, which swaps limbs and allocates nothing)
    Mpfr& v = const_cast<Mpfr&>(av);
    mpfr_add(v.get(), v.get(), bv.get(), MPFR_RNDN);
    mpfr_div_2ui(v.get(), v.get(), 1, MPFR_RNDN);
    const E e = B::grow(ex + ey + unit_mag(v, 0));
    a = B(std::move(v), e);
  }

 private:
  // B::pow2(k), built from the bits of an x87 extended number where it is a normal one (the same value:
  // a power of two is exact), without B::pow2's table look-up and call.
  static E pow2(long k) {
    constexpr bool x87 =
        std::numeric_limits<E>::digits == 64 && std::numeric_limits<E>::max_exponent == 16384 && sizeof(E) == 16;
    if constexpr (x87) {
      if (k < -16382 || k > 16383) return B::pow2(k);
      struct Bits {
        std::uint64_t significand;  // with the explicit integer bit
        std::uint16_t exponent;     // biased by 16383
        std::uint16_t pad[3];
      };
      return std::bit_cast<E>(Bits{std::uint64_t(1) << 63, std::uint16_t(k + 16383), {0, 0, 0}});
    } else {
      return B::pow2(k);
    }
  }
  // B::mag(x), the same formula: the leading 53 bits of the significand plus one unit, scaled.
  static E mag(const Mpfr& x) {
    mpfr_srcptr p = x.get();
    if (!mpfr_regular_p(p)) return B::mag(x);
    return E(B::leading53_up(p)) * pow2(long(mpfr_get_exp(p)) - 53);
  }
  // B::unit_mag of x 2^shift (x of precision prec_): half a unit in its last place, from x's exponent.
  E unit_mag(const Mpfr& x, long shift) const {
    mpfr_srcptr p = x.get();
    if (!mpfr_regular_p(p)) return B::unit_mag(x);
    return pow2(long(mpfr_get_exp(p)) + shift - long(prec_) - 1);
  }

  std::optional<WrittenHalvingStep<B>> slow_;  // made on first use
  B half_, other_;
  int prec_ = 0;
  bool exact_ = false;
  E mag_half_ = 0, mag_other_ = 0;
};

}  // namespace eccd
