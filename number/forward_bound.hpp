#pragma once
// ForwardBound: plain double with an a-priori (forward) error bound carried
// as a magnitude and a rounding depth, so that a straight-line program of
// +, -, * knows which final signs it can trust at about twice the cost of
// plain double (no branch, no fabs per operation: it vectorises), instead of
// the running error bound of Bounded<double> (number/running_error.hpp).
//
// Statement (Higham, "Accuracy and Stability of Numerical
// Algorithms", 2nd ed., Lemma 3.1 and section 3.1; the semi-static filters
// of Fortune & Van Wyk and CGAL). Each value carries
//   v  the double computed by exactly the plain-double operations,
//   m  the same program evaluated on the absolute values of the leaves, with
//      every subtraction replaced by an addition (the magnitude), and
//   d  the rounding depth: leaf d = the number of roundings that made it
//      (0 for a given double, 2 for 1/(a*a)); a ± b: max(da, db) + 1;
//      a * b: da + db + 1; an integer constant: 0.
// Expanding the program into monomials of the leaves, every monomial of the
// computed v carries at most d factors (1 + δ)^±1, |δ| <= u = 2^-53, so
//   |v - v_exact| <= γ_d M(|x|),  γ_d = d u / (1 - d u),
// where M(|x|) is the magnitude on the exact leaves (Lemma 3.1). The
// computed m is within (1 - u)^d of M on the rounded leaves (no
// cancellation: all its terms are >= 0) and the rounded leaves are within
// (1 + γ_2)^(d + 1) of the exact ones, so for d u <= 2^-10 all these factors
// together are far below 2 and
//   err = 2 d u m   bounds |v - v_exact|
// (the rounding of err's own product, relative u, is inside the factor 2).
// Underflow: a product that underflows has an absolute error up to 2^-1075
// instead of a relative one; each product adds 2^-1022 (the smallest normal)
// to m, and γ_d 2^-1022 >= u 2^-1022 = 2^-1075 covers that error wherever
// it propagates (it is a monomial of m like any other). Sums of doubles that
// underflow are exact. Overflow: m >= |v| everywhere, so an infinite or NaN
// intermediate that reaches the result leaves m infinite or NaN.
// scalar_traits<ForwardBound>::sign is the sign of v when |v| > err and m is
// finite, Sign::zero when m = 0 (every monomial is 0: exactly zero), and
// Sign::uncertain otherwise (also when d u > 2^-10).
// No division: the leaves 1/a² are built by inverse_square_leaf.
// Requirements: none (double only).
#include "number/double_traits.hpp"
#include "number/scalar_traits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace eccd {

class ForwardBound {
 public:
  ForwardBound() : v_(0), m_(0), d_(0) {}
  ForwardBound(int k) : v_(k), m_(std::fabs(double(k))), d_(0) {}  // NOLINT: small exact constants
  ForwardBound(double v, double m, double d) : v_(v), m_(m), d_(d) {}

  // A given double (exact: depth 0).
  static ForwardBound exact(double x) { return ForwardBound(x, std::fabs(x), 0); }
  // 1 / (a * a) rounded twice: (1 + δ1)^-1 (1 + δ2), depth 2 (Lemma 3.1 allows the exponent -1).
  static ForwardBound inverse_square_leaf(double a) {
    double q = 1.0 / (a * a);
    return ForwardBound(q, std::fabs(q), 2);
  }

  double value() const { return v_; }
  double magnitude() const { return m_; }
  double depth() const { return d_; }
  double bound() const { return 2.0 * (d_ * 0x1p-53) * m_; }

  friend ForwardBound operator+(const ForwardBound& a, const ForwardBound& b) {
    return ForwardBound(a.v_ + b.v_, a.m_ + b.m_, std::max(a.d_, b.d_) + 1);
  }
  friend ForwardBound operator-(const ForwardBound& a, const ForwardBound& b) {
    return ForwardBound(a.v_ - b.v_, a.m_ + b.m_, std::max(a.d_, b.d_) + 1);
  }
  friend ForwardBound operator*(const ForwardBound& a, const ForwardBound& b) {
    return ForwardBound(a.v_ * b.v_, a.m_ * b.m_ + 0x1p-1022, a.d_ + b.d_ + 1);
  }
  friend ForwardBound operator*(int k, const ForwardBound& b) { return ForwardBound(k) * b; }
  ForwardBound operator-() const { return ForwardBound(-v_, m_, d_); }
  ForwardBound& operator+=(const ForwardBound& o) { return *this = *this + o; }
  ForwardBound& operator-=(const ForwardBound& o) { return *this = *this - o; }
  ForwardBound& operator*=(const ForwardBound& o) { return *this = *this * o; }

 private:
  double v_, m_, d_;
};

template <>
struct scalar_traits<ForwardBound> {
  static constexpr bool is_exact = false;
  static Sign sign(const ForwardBound& x) {
    const double m = x.magnitude(), v = x.value();
    if (m == 0) return Sign::zero;  // every monomial is 0
    if (!(m <= std::numeric_limits<double>::max()) || !(x.depth() <= 0x1p43)) return Sign::uncertain;
    if (!(std::fabs(v) > x.bound())) return Sign::uncertain;  // also NaN
    return v > 0 ? Sign::positive : Sign::negative;
  }
  static double to_double(const ForwardBound& x) { return x.value(); }
  static ForwardBound abs(const ForwardBound& x) {
    return ForwardBound(std::fabs(x.value()), x.magnitude(), x.depth());
  }
  static int precision(const ForwardBound&) { return 53; }
  static std::string to_string(const ForwardBound& x) { return scalar_traits<double>::to_string(x.value()); }
};

}  // namespace eccd
