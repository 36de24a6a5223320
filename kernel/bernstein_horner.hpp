#pragma once
// BernsteinHorner<T>: the value of a polynomial in Bernstein form at many
// points in O(n) operations each (de Casteljau's triangle takes n(n+1)/2).
//
// Statement. With u = 1 - t and C(n,i) the binomials,
//   p(t) = sum b_i C(n,i) t^i u^(n-i)
//        = u^n  * sum (C(n,i) b_i) s^i,       s = t / u,  for t <= 1/2,
//        = t^n  * sum (C(n,i) b_i) r^(n-i),   r = u / t,  for t >  1/2,
// so one Horner pass in s (or r), both in [0, 1], and one power by repeated
// squaring give the value (the "Horner-Bernstein" or VS scheme of Schumaker
// and Volk 1986; Delgado and Peña 2009 compare its error with de Casteljau's).
// The weighted coefficients a_i = C(n,i) b_i are formed once per polynomial
// (the root refinement in floating/bernstein_roots.hpp evaluates one piece
// ~15 times: measured, 62 % of the 2D degree-6 double pipeline went to
// de Casteljau evaluations at n = 144).
//
// Stability (what this relies on). Higham, "Accuracy and Stability of
// Numerical Algorithms" (2nd ed.), eq. (5.3): Horner's rule at x has forward
// error at most γ_2n sum |a_i| |x|^i. Here x = s in [0, 1] carries a
// relative error of at most 2u (one subtraction, one division), which moves
// s^i by at most 2iu; a_i one of at most (n - 55)u (the binomial row is
// built by Pascal's rule, kernel/binomial.hpp, exact up to n = 56 in double,
// and each later row adds at most one rounding to positive sums) plus one
// product; the power one of at most γ_(2 log2 n). Added up, the error is
// at most γ_(c n) sum |b_i| C(n,i) t^i u^(n-i) with c about 5: the same
// condition number, sum |b_i| B_i(t), as de Casteljau's bound γ_2n sum |b_i|
// B_i(t) (Farouki and Rajan 1987; Mainar and Peña 1999), with a constant
// about 2.5 times larger. So a root is located to within the same order of
// the working precision; the last bits of a double root may differ from the
// triangle's. The choice of s <= 1 (mirror above 1/2) is what keeps every
// Horner term below the term it is added to in magnitude ratio, as in the
// bound above.
// A running error bound (T = Bounded<double>, number/running_error.hpp)
// stays sound: its operations bound every step against the exact value at
// the same evaluation point, whatever the order of the operations.
// Range (never silent): in double the binomials overflow above n = 1029 and
// 2^-n underflows above n ~ 1000, so this form is used only for
// 16 <= n <= 512 (below 16 the triangle is as cheap and stays bit for bit
// what it was: the 3D Bézier callers' low-degree pieces); a non-finite a_i
// (an overflowing product) makes the object fall back to de Casteljau for
// every point, and so does a result that is not finite or not above 2^-960 in
// magnitude (zero included): an underflow in a Horner step perturbs the
// result by at most n·2^-1074 absolutely, which is below a relative 2^-100
// of any result above 2^-960. MPFR has no such range limits at these
// degrees (its exponent range is ±2^62), and its binomials and products
// carry the run's precision, so an MPFR evaluation keeps its precision.
// Requirements on T: +, -, *, /, comparison, scalar_traits<T>,
// is_finite_value (number/pow2_scaling.hpp, number/running_error.hpp).
#include "kernel/bernstein.hpp"
#include "kernel/binomial.hpp"
#include "number/pow2_scaling.hpp"
#include "number/running_error.hpp"

#include <cmath>
#include <span>
#include <type_traits>
#include <vector>

namespace eccd {

namespace horner_detail {
// t^n by repeated squaring (about 2 log2 n products).
template <class T>
T power(T base, int n, const T& one) {
  T r = one;
  while (n > 0) {
    if (n & 1) r = r * base;
    n >>= 1;
    if (n > 0) base = base * base;
  }
  return r;
}
// sum c_i x^i for x >= 0 by four interleaved Horner chains in x^4 (chain k
// holds c_k, c_(k+4), ...), joined by Horner in x: the same terms with the same
// kind of rounding as one chain (every term c_i x^i is formed by products of
// nonnegative factors and sums), so the same bound up to the constant, but four
// independent multiply-add chains instead of one, which is what a step of the
// root refinement waits on.
template <class T>
T chained(const std::vector<T>& c, const T& x, const T& zero) {
  const int n = int(c.size()) - 1;
  const T x2 = x * x;
  const T x4 = x2 * x2;
  int top = n - (n % 4);  // the chains' last full block starts here
  T h[4] = {c[top], top + 1 <= n ? c[top + 1] : zero, top + 2 <= n ? c[top + 2] : zero,
            top + 3 <= n ? c[top + 3] : zero};
  for (int j = top - 4; j >= 0; j -= 4)
    for (int k = 0; k < 4; ++k) {
      T y = h[k] * x4;
      h[k] = y + c[j + k];
    }
  T r = h[3] * x;
  r = r + h[2];
  r = r * x;
  r = r + h[1];
  r = r * x;
  return r + h[0];
}
// A Horner result that can be trusted to the bound above: finite, and in
// double not near the underflow range (zero included; the caller then uses de Casteljau).
inline bool usable(double x) { return std::fabs(x) > 0x1p-960 && std::isfinite(x); }
inline bool usable(const Mpfr& x) { return is_finite_value(x) && !mpfr_zero_p(x.get()); }
template <class T>
bool usable(const Bounded<T>& x) {
  return usable(x.value()) && std::isfinite(x.bound());
}
}  // namespace horner_detail

template <class T>
class BernsteinHorner {
 public:
  static constexpr int kMinDegree = 16;
  static constexpr int kMaxDegree = 512;

  // b: the Bernstein coefficients (kept by reference: b must outlive this object).
  explicit BernsteinHorner(std::span<const T> b) : b_(b) {
    const int n = int(b.size()) - 1;
    if (n < kMinDegree || n > kMaxDegree) return;
    const T& like = b.front();
    const std::vector<T>& c = binomial_row(n, like);
    a_.resize(n + 1);
    for (int i = 0; i <= n; ++i) {
      a_[i] = c[i] * b[i];
      if (!is_finite_value(a_[i])) {
        a_.clear();
        return;
      }
    }
    rev_.assign(a_.rbegin(), a_.rend());
    one_ = c[0];  // the run's one (binomial_row starts from it)
    half_ = times_pow2(one_, -1L);
    zero_ = times_pow2(one_, -1L) - half_;
  }

  // True when the O(n) form is in use (else every value comes from de Casteljau).
  bool linear() const { return !a_.empty(); }

  T operator()(const T& t) const {
    if (a_.empty()) return bernstein_value(b_, t);
    const int n = int(a_.size()) - 1;
    const T u = one_ - t;
    const bool low = !(t > half_);
    // t <= 1/2: u^n A(t/u) with A's coefficients a_0..a_n; else t^n A~(u/t) with them reversed.
    T r = horner_detail::chained(low ? a_ : rev_, low ? T(t / u) : T(u / t), zero_) *
          horner_detail::power(low ? u : t, n, one_);
    if (!horner_detail::usable(r)) return bernstein_value(b_, t);
    return r;
  }

 private:
  std::span<const T> b_;
  std::vector<T> a_;           // C(n,i) b_i; empty: de Casteljau
  std::vector<T> rev_;         // the same, last first (the mirrored Horner above t = 1/2)
  T one_{}, half_{}, zero_{};  // exact constants at the run's precision
};

}  // namespace eccd
