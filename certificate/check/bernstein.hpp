#pragma once
// Tensor Bernstein nets in two variables (u, t) on [0, 1]^2, written for the
// certificate checker alone (certificate/check/).
//
// Statement. Farin, "Curves and Surfaces for CAGD", chapters 5 and 16:
// p(u, t) = Σ c_ij B_i^m(u) B_j^n(t). de Casteljau's algorithm at x splits
// the net of a range into the nets of its two parts (keep_left, keep_right);
// restricting to [a, b] is a split at a, then at (b - a)/(1 - a). By the
// convex hull property every value of p on the net's range lies between the
// least and the greatest control point, so control points of one strict sign
// prove that sign of p there. Derivative nets: ∂p/∂u has c'_ij = m (c_{i+1,j}
// - c_ij). With T an outward-rounding interval type (certificate/check/
// interval.hpp) every control point computed encloses the exact one; with
// T = mpq_class everything is exact.
// Requirements: T with +, -, *, one_minus(x) = 1 - x and the in-place steps
// lerp_from / lerp_to (certificate/check/interval.hpp); make(q) giving the T of a rational.
#include <gmpxx.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace eccd::check {

// d = y a + x d and d = y d + x b in place, y = 1 - x
inline void lerp_from(mpq_class& d, const mpq_class& a, const mpq_class& x, const mpq_class&) { d = a + x * (d - a); }
inline void lerp_to(mpq_class& d, const mpq_class& b, const mpq_class& x, const mpq_class&) { d = d + x * (b - d); }
inline mpq_class one_minus(const mpq_class& x) { return 1 - x; }
template <class T>
void lerp_from(T& d, const T& a, const T& x, const T& y) {
  T::lerp_from(d, a, x, y);
}
template <class T>
void lerp_to(T& d, const T& b, const T& x, const T& y) {
  T::lerp_to(d, b, x, y);
}
template <class T>
T one_minus(const T& x) {
  return T::one_minus(x);
}

template <class T>
struct Net2 {
  int m = 0, n = 0;  // degrees in u and t
  std::vector<T> c;  // c[i * (n + 1) + j]
  T& at(int i, int j) { return c[std::size_t(i) * (n + 1) + j]; }
  const T& at(int i, int j) const { return c[std::size_t(i) * (n + 1) + j]; }

  // every control point of one proved strict sign: +1 or -1; else 0
  int strict_sign() const {
    int s = c.empty() ? 0 : c[0].sign();
    for (const auto& x : c)
      if (x.sign() != s) return 0;
    return s;
  }
};

// de Casteljau on one line of control points (stride st): keep the part right (left) of x.
template <class T>
void keep_right(std::vector<T>& c, std::size_t base, std::size_t st, int deg, const T& x) {
  const T y = one_minus(x);
  for (int r = 1; r <= deg; ++r)
    for (int k = 0; k <= deg - r; ++k) lerp_to(c[base + k * st], c[base + (k + 1) * st], x, y);
}
template <class T>
void keep_left(std::vector<T>& c, std::size_t base, std::size_t st, int deg, const T& x) {
  const T y = one_minus(x);
  for (int r = 1; r <= deg; ++r)
    for (int k = deg; k >= r; --k) lerp_from(c[base + k * st], c[base + (k - 1) * st], x, y);
}

// The net restricted to [a, b] (a < b, a != 1) along axis 0 (u) or 1 (t), reparameterised to [0, 1].
template <class T, class Make>
Net2<T> restrict_to(const Net2<T>& f, int axis, const mpq_class& a, const mpq_class& b, Make&& make) {
  Net2<T> r = f;
  const int deg = axis == 0 ? f.m : f.n;
  const std::size_t st = axis == 0 ? std::size_t(f.n + 1) : 1,
                    lines = axis == 0 ? std::size_t(f.n + 1) : std::size_t(f.m + 1);
  const bool cut_left = sgn(a) != 0,
             cut_right = b != 1;  // outside [0, 1] too: the subdivision is an identity of polynomials
  if (!cut_left && !cut_right) return r;
  const T ta = make(a);
  const T tb = make(cut_right ? mpq_class((b - a) / (1 - a)) : mpq_class(1));
  for (std::size_t l = 0; l < lines; ++l) {
    const std::size_t base = axis == 0 ? l : l * (f.n + 1);
    if (cut_left) keep_right(r.c, base, st, deg, ta);
    if (cut_right) keep_left(r.c, base, st, deg, tb);
  }
  return r;
}

// The two halves of the net along an axis (split at 1/2: `half` is 1/2 in T).
template <class T>
std::pair<Net2<T>, Net2<T>> split_half(const Net2<T>& f, int axis, const T& half) {
  std::pair<Net2<T>, Net2<T>> r{f, f};
  const int deg = axis == 0 ? f.m : f.n;
  const std::size_t st = axis == 0 ? std::size_t(f.n + 1) : 1,
                    lines = axis == 0 ? std::size_t(f.n + 1) : std::size_t(f.m + 1);
  for (std::size_t l = 0; l < lines; ++l) {
    const std::size_t base = axis == 0 ? l : l * (f.n + 1);
    keep_left(r.first.c, base, st, deg, half);
    keep_right(r.second.c, base, st, deg, half);
  }
  return r;
}

// The derivative net along an axis, exactly (degree one lower there; a constant gives the zero net of degree 0).
inline Net2<mpq_class> derivative(const Net2<mpq_class>& f, int axis) {
  Net2<mpq_class> r;
  const int deg = axis == 0 ? f.m : f.n;
  r.m = axis == 0 ? std::max(f.m - 1, 0) : f.m;
  r.n = axis == 1 ? std::max(f.n - 1, 0) : f.n;
  r.c.assign(std::size_t(r.m + 1) * (r.n + 1), mpq_class(0));
  if (deg == 0) return r;
  for (int i = 0; i <= r.m; ++i)
    for (int j = 0; j <= r.n; ++j)
      r.at(i, j) = deg * (axis == 0 ? f.at(i + 1, j) - f.at(i, j) : f.at(i, j + 1) - f.at(i, j));
  return r;
}

// The value at a point (x, y) given in T (de Casteljau: after keep_right at x the first point is the value).
template <class T>
T value_at(const Net2<T>& f, const T& x, const T& y) {
  std::vector<T> row(f.c);
  std::vector<T> col;
  col.reserve(f.n + 1);
  for (int j = 0; j <= f.n; ++j) {
    keep_right(row, std::size_t(j), std::size_t(f.n + 1), f.m, x);
    col.push_back(row[std::size_t(j)]);
  }
  keep_right(col, 0, 1, f.n, y);
  return col[0];
}

template <class T, class Make>
Net2<T> converted(const Net2<mpq_class>& f, Make&& make) {
  Net2<T> r;
  r.m = f.m;
  r.n = f.n;
  r.c.reserve(f.c.size());
  for (const auto& x : f.c) r.c.push_back(make(x));
  return r;
}

}  // namespace eccd::check
