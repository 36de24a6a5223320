#pragma once
// Static (a-priori) error bounds for a straight-line program in plain double:
// the program is written once as a template and run with three scalar types,
//   double        the value v̂ (the program exactly as written),
//   Magnitude     the magnitude M: the same program on the absolute values of
//                 the leaves with every subtraction replaced by an addition,
//   StaticDepth   the rounding depth d, at compile time (constexpr): leaf
//                 d = 0 (a given double), a ± b: max(da, db) + 1, a * b:
//                 da + db + 1, an exact constant (int): 0, -a: da.
// so no bound object travels through the program (so the batched
// static test's lane loop is plain double arrays and vectorises).
//
// Statement (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd
// ed., Lemma 3.1 and section 3.1; the semi-static filters of Fortune & Van
// Wyk and CGAL). Expanding the program into monomials of its leaves (with
// repetitions: nothing cancels), each monomial of the computed v̂ carries at
// most d factors (1 + δ)^±1, |δ| <= u = 2^-53, as long as no product
// underflows, so
//   |v̂ - v| <= γ_d M,   γ_d = d u / (1 - d u),
// with M the magnitude on the exact leaves. The Magnitude run is the same
// sum of non-negative monomials computed in double: within (1 + u)^d of M
// (no cancellation). FMA contraction (GCC's default -ffp-contract=fast
// outside ISO mode) fuses a * b + c into one rounding: a monomial then carries
// fewer factors than d counts, so d stays an upper bound, and the magnitude
// run is still within (1 + u)^d of M. For d u <= 2^-10 all these factors are
// far below 2, so
//   err = 2 d u M̂ + τ   bounds |v̂ - v|,
// where τ is an absolute term that the caller derives for underflow (a
// product that underflows has an absolute error up to 2^-1075 instead of a
// relative one; the caller bounds how far such an error can propagate from
// its input ranges: kernel/static_filter3d.hpp). Overflow: M̂ >= |v̂| for
// every node, so an infinite or NaN node that reaches the result leaves M̂
// infinite or NaN, and the caller refuses a sign then.
// Leaves that are rounded (e.g. a product of two given doubles made once at
// the top of a program) are not leaves here: the program starts from the
// given doubles, so their rounding is counted in d.
// Requirements: none (double only). StaticDepth is constexpr; Magnitude's
// leaves are made by magnitude_leaf (fabs).
#include <algorithm>
#include <cmath>

namespace eccd {

class Magnitude {
 public:
  constexpr Magnitude() = default;
  constexpr Magnitude(int k) : m_(k < 0 ? -double(k) : double(k)) {}  // NOLINT: small exact constants
  static Magnitude leaf(double x) {
    Magnitude r;
    r.m_ = std::fabs(x);
    return r;
  }
  constexpr double value() const { return m_; }
  friend constexpr Magnitude operator+(Magnitude a, Magnitude b) { return raw(a.m_ + b.m_); }
  friend constexpr Magnitude operator-(Magnitude a, Magnitude b) { return raw(a.m_ + b.m_); }
  friend constexpr Magnitude operator*(Magnitude a, Magnitude b) { return raw(a.m_ * b.m_); }
  friend constexpr Magnitude operator*(int k, Magnitude b) { return Magnitude(k) * b; }
  constexpr Magnitude operator-() const { return *this; }

 private:
  static constexpr Magnitude raw(double m) {
    Magnitude r;
    r.m_ = m;
    return r;
  }
  double m_ = 0;
};

// The value and the magnitude runs side by side in one SSE2 register (GCC vector extension, two doubles):
// +, * and - are one instruction each on both (- flips lane 0's sign bit of b, then adds), so the magnitude
// costs almost nothing next to the value. Lane 0 rounds exactly as the double run, lane 1 as the Magnitude run.
class ValueMagnitude {
 public:
  using V2 = double __attribute__((vector_size(16)));
  ValueMagnitude() : x_{0, 0} {}
  ValueMagnitude(int k) : x_{double(k), k < 0 ? -double(k) : double(k)} {}  // NOLINT: small exact constants
  static ValueMagnitude leaf(double x) { return raw(V2{x, std::fabs(x)}); }
  double value() const { return x_[0]; }
  double magnitude() const { return x_[1]; }
  friend ValueMagnitude operator+(ValueMagnitude a, ValueMagnitude b) { return raw(a.x_ + b.x_); }
  friend ValueMagnitude operator-(ValueMagnitude a, ValueMagnitude b) { return raw(a.x_ + flip0(b.x_)); }
  friend ValueMagnitude operator*(ValueMagnitude a, ValueMagnitude b) { return raw(a.x_ * b.x_); }
  friend ValueMagnitude operator*(int k, ValueMagnitude b) { return ValueMagnitude(k) * b; }
  ValueMagnitude operator-() const { return raw(flip0(x_)); }

 private:
  using U2 = long long __attribute__((vector_size(16)));
  static V2 flip0(V2 x) { return (V2)((U2)x ^ U2{(long long)(1ULL << 63), 0}); }
  static ValueMagnitude raw(V2 x) {
    ValueMagnitude r;
    r.x_ = x;
    return r;
  }
  V2 x_;
};

class StaticDepth {
 public:
  constexpr StaticDepth() = default;
  constexpr StaticDepth(int) {}  // NOLINT: an exact constant has depth 0
  static constexpr StaticDepth leaf(double) { return StaticDepth(); }
  constexpr int value() const { return d_; }
  friend constexpr StaticDepth operator+(StaticDepth a, StaticDepth b) { return raw(std::max(a.d_, b.d_) + 1); }
  friend constexpr StaticDepth operator-(StaticDepth a, StaticDepth b) { return raw(std::max(a.d_, b.d_) + 1); }
  friend constexpr StaticDepth operator*(StaticDepth a, StaticDepth b) { return raw(a.d_ + b.d_ + 1); }
  friend constexpr StaticDepth operator*(int, StaticDepth b) { return raw(b.d_ + 1); }
  constexpr StaticDepth operator-() const { return *this; }

 private:
  static constexpr StaticDepth raw(int d) {
    StaticDepth r;
    r.d_ = d;
    return r;
  }
  int d_ = 0;
};

// The leaf of a given double in each of the three runs.
template <class T>
inline T static_leaf(double x) {
  if constexpr (std::is_same_v<T, double>)
    return x;
  else
    return T::leaf(x);
}

}  // namespace eccd
