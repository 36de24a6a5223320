#pragma once
// The Gaussian-circle test of 001 section 4 on doubles: do the given
// gradient directions lie in one open half-plane through the origin (a cone
// narrower than π)? Then the zero set of F(u, t) over the piece has no loop
// and at most one component per side. Decided exactly for the given doubles
// by cross-product signs (fma; exact rationals where a product underflows),
// no angles. The caller rounds the gradients' control points to double; this
// header is double only.
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace eccd {

namespace bezier_detail {

// The sign of a·d − b·c, exact for doubles. Fast path when neither product
// under- or overflows (pointed() below scales each point so that it cannot
// overflow): rounding to nearest is monotone, so p = fl(a·d) > q = fl(b·c)
// implies a·d > b·c; when p == q, a·d − b·c = ep − eq exactly (the fma gives
// the products' rounding errors exactly while |p| >= 2^-960), and comparing
// two doubles is exact. Otherwise (a product below 2^-960 that is not an exact
// zero, or not finite: a tiny coordinate against a small one) the sign of the
// exact rational a·d − b·c.
inline int cross_sign(double a, double b, double c, double d) {
  const double p = a * d, q = b * c;
  auto in_range = [](double x, double y, double xy) {
    return xy == 0 ? (x == 0 || y == 0) : (std::fabs(xy) >= 0x1p-960 && std::isfinite(xy));
  };
  if (!in_range(a, d, p) || !in_range(b, c, q)) {
    const mpq_class r = mpq_class(a) * mpq_class(d) - mpq_class(b) * mpq_class(c);
    return sgn(r);
  }
  if (p != q) return p > q ? 1 : -1;
  const double ep = std::fma(a, d, -p), eq = std::fma(b, c, -q);
  return ep > eq ? 1 : ep < eq ? -1 : 0;
}

// Two non-zero collinear vectors point the same way iff their coordinates have
// the same signs (one is a positive multiple of the other).
inline bool same_way(double x1, double y1, double x2, double y2) {
  return (x1 > 0) == (x2 > 0) && (x1 < 0) == (x2 < 0) && (y1 > 0) == (y2 > 0) && (y1 < 0) == (y2 < 0);
}

// All points strictly inside one open half-plane through the origin (001
// section 4's Gaussian-circle test: the gradients' directions cover less than
// a half circle). Decided by the signs of cross products, no angles (atan2 costs
// 15 % of paper 002's double query): the points are taken in order
// and the cone [lo, hi] (counter-clockwise from lo to hi, narrower than π)
// spanned by those seen so far is kept; a point inside it changes nothing, a
// point less than π counter-clockwise of lo and beyond hi becomes hi (the
// mirror case becomes lo), any other point (on the far side of both, or
// opposite one of them) means no open half-plane holds them all. The cone of
// a finite set in an open half-plane is unique, so the answer does not depend
// on the order, and with exact cross signs it is the exact answer for the
// given doubles (a zero point or a non-finite coordinate: false, i.e. not shown
// loop-free; the caller subdivides).
inline bool pointed(const std::vector<std::pair<double, double>>& pts) {
  double lx = 0, ly = 0, hx = 0, hy = 0;
  bool first = true;
  for (auto [x, y] : pts) {
    const double ax = std::fabs(x), ay = std::fabs(y);
    if (!(ax < 0x1p400 && ay < 0x1p400 && (ax > 0x1p-400 || ay > 0x1p-400))) {  // NaN lands here too
      // outside the range where the products are exact: scaled by a power of two
      if (!std::isfinite(x) || !std::isfinite(y) || (x == 0 && y == 0)) return false;
      const int e = std::ilogb(std::max(ax, ay));
      x = std::ldexp(x, -e);
      y = std::ldexp(y, -e);
    }
    if (first) {
      lx = hx = x;
      ly = hy = y;
      first = false;
      continue;
    }
    const int c1 = cross_sign(lx, ly, x, y), c2 = cross_sign(x, y, hx, hy);  // lo × p, p × hi
    if (c1 >= 0 && c2 >= 0) {                                                // inside [lo, hi], or on one of its lines
      if ((c1 == 0 && !same_way(lx, ly, x, y)) || (c2 == 0 && !same_way(x, y, hx, hy))) return false;
    } else if (c1 > 0 && c2 < 0) {
      hx = x;
      hy = y;
    } else if (c1 < 0 && c2 > 0) {
      lx = x;
      ly = y;
    } else {
      return false;
    }
  }
  return true;
}

}  // namespace bezier_detail

}  // namespace eccd
