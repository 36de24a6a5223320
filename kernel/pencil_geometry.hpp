#pragma once
// The small linear algebra of a pencil λA - B at one instant: the real roots
// of f(λ) = det(λA - B) and the null vector of λA - B at a root. Shared by
// the separating plane (kernel/separating_plane.hpp, 000 section 3) and the
// contact points (kernel/contact_geometry.hpp, 003 Lemma 5 in 2D and its 3D
// analogue).
//
// Statement.
//  - small_real_roots(p): the distinct real roots of a polynomial of degree
//    <= 4 (f has degree dim + 1), by the classical recursion: the real roots
//    of p' split the real line into intervals on which p is monotone; inside
//    the Cauchy bound |z| < 1 + max |c_i / c_n| each interval with a sign
//    change of p holds exactly one root, found down to the precision of T:
//    in double and in Mpfr (256 bits for the contact points, 128 and up for
//    the exact plane) by Newton's method safeguarded by that bracket
//    (Numerical Recipes' rtsafe: a bisection step whenever Newton's step
//    would leave the bracket or did not halve the step before last, so the
//    steps shrink at least as fast as bisection's and the loop ends; it ends
//    when a step or the bracket is below 2^-51 relative in double,
//    2^-(bits - 8) in Mpfr, or a step no longer moves x, or the bracket's
//    midpoint equals an end; in Mpfr the first step is the root of p rounded
//    to double, and the bracket x_d -+ 2^-40 |x_d| where p's signs in Mpfr
//    confirm it). The sign-change bracket is kept throughout; Newton needs a
//    handful of evaluations where bisection needs about one per bit
//    (measured: the certified 3D contact points spent half the query when
//    bisecting to 256 bits, and bisection in double was a quarter of the
//    per-pose mode, where each new separating plane needs f's roots).
//    A root where p has no
//    sign change (an even multiplicity) is found only when p is exactly 0 at
//    a critical point; the callers do not rely on those (the contact point
//    takes the critical point itself).
//  - null_vector(M): for M of rank H - 1, adj(M) = v wᵀ, so every non-zero
//    row of the cofactor matrix is a null vector; the one of largest size is
//    taken (near a rank drop in rounded arithmetic it is the best-conditioned
//    choice). Cofactors are Eigen's closed-form determinants of the minors.
// Nothing here decides anything: the callers check what they build (the
// plane by exact or error-bounded inequalities, api/separate.cpp; contact
// points are for display).
// Requirements on T: double or Mpfr (kernel/eigen_scalar.hpp), a field with
// comparisons and scalar_traits<T>.
#include "kernel/eigen_scalar.hpp"
#include "kernel/poly_matrix.hpp"
#include "kernel/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

namespace eccd {

// The binary exponent of x != 0 (x = m 2^e, 1/2 <= |m| < 1), for the relative stopping tests below.
inline long exponent_of(double x) { return long(std::ilogb(x)) + 1; }
inline long exponent_of(const Mpfr& x) { return long(mpfr_get_exp(x.get())); }

// The root of p in (l, r), where p(l) has the sign sl != 0 and p(r) the
// opposite sign, by Newton's method safeguarded by the bracket (see the
// statement; Mpfr first takes a seed from double).
template <class T>
T root_in_bracket(const Poly<T>& p, T l, T r, Sign sl) {
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, Mpfr>, "small_real_roots: double or Mpfr");
  const Poly<T> dp = derivative(p);
  T x = (l + r) / T(2);
  const int bits = scalar_traits<T>::precision(l);
  // A seed from double (this function on p rounded to double), kept only as a proposal: the bracket is
  // narrowed to x_d -+ delta where the signs of p (in T) there confirm it, else left as it is.
  if constexpr (std::is_same_v<T, Mpfr>) {
    if (bits > 64) {
      Poly<double> pd;
      for (const T& c : p.c) pd.c.push_back(scalar_traits<T>::to_double(c));
      const double ld = scalar_traits<T>::to_double(l), rd = scalar_traits<T>::to_double(r);
      if (std::isfinite(ld) && std::isfinite(rd) && ld < rd) {
        const double xd = root_in_bracket<double>(pd, ld, rd, sl);
        const double delta = std::ldexp(std::max(1.0, std::fabs(xd)), -40);
        const T a(xd - delta, bits), b(xd + delta, bits), xs(xd, bits);
        if (l < a && a < b && b < r) {
          const Sign sa = sign(p(a)), sb = sign(p(b));
          if (sa == Sign::zero) return a;
          if (sb == Sign::zero) return b;
          if (sa == sl && sb != sl) {
            l = a;
            r = b;
            x = xs;
          }
        }
      }
    }
  }
  // Rounded evaluation leaves p's sign random within a band of a few ulps around the root (cancellation in
  // Horner), where Newton's steps are noise that never settles on one value: stop when a step or the bracket
  // is below 2^-fine relative (Mpfr: 256 times its precision, bisection's last bits in that band are noise
  // too; double: 2^-51, an ulp or two, as the bisection to the last bit it replaces).
  const long fine = std::is_same_v<T, double> ? 51L : long(bits) - 8;
  auto negligible = [&](const T& dx, const T& ref) {
    if (sign(dx) == Sign::zero) return true;
    if (sign(ref) == Sign::zero || fine <= 0) return false;
    return exponent_of(dx) <= exponent_of(ref) - fine;
  };
  T step_old = r - l, step = step_old;
  for (int it = 0; it < 100000; ++it) {
    const T fx = p(x);
    const Sign sx = sign(fx);
    if (sx == Sign::zero) return x;
    (sx == sl ? l : r) = x;
    const T m = (l + r) / T(2);
    if (!(l < m && m < r)) return m;  // the bracket is down to the precision of T
    if (negligible(T(r - l), abs_of(l) < abs_of(r) ? r : l)) return m;
    const T d = dp(x);
    bool newton = sign(d) != Sign::zero;
    T nx = x;
    if (newton) {
      const T dx = fx / d;
      nx = x - dx;
      // Inside the bracket and at most half the step before last (else bisect).
      newton = l < nx && nx < r && abs_of(T(dx + dx)) <= abs_of(step_old);
      if (newton) {
        step_old = step;
        step = dx;
      }
      if (newton && negligible(dx, x)) return nx;
    }
    if (!newton) {
      step_old = step;
      step = m - x;
      nx = m;
    }
    if (nx == x) return x;  // a step below the precision of T
    x = nx;
  }
  return x;
}

template <class T>
std::vector<T> small_real_roots(const Poly<T>& p) {
  const int n = p.degree();
  if (n <= 0) return {};
  if (n == 1) return {-p.c[0] / p.c[1]};
  std::vector<T> crit = small_real_roots(derivative(p));
  T bound = abs_of(p.c[0] / p.c[n]);
  for (int i = 1; i < n; ++i) bound = std::max(bound, abs_of(p.c[i] / p.c[n]));
  bound = bound + T(1);
  std::vector<T> pts{-bound};
  for (const T& c : crit)
    if (-bound < c && c < bound) pts.push_back(c);
  pts.push_back(bound);
  std::vector<T> roots;
  auto add = [&](const T& r) {
    if (roots.empty() || roots.back() < r) roots.push_back(r);
  };
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    T l = pts[k], r = pts[k + 1];
    Sign sl = sign(p(l)), sr = sign(p(r));
    if (sl == Sign::zero) {
      add(l);
      continue;
    }
    if (sr == Sign::zero || sl == sr) continue;
    add(root_in_bracket(p, l, r, sl));
  }
  if (!pts.empty() && sign(p(pts.back())) == Sign::zero) add(pts.back());
  return roots;
}

template <class T, int H>
EMatrix<T, H> to_eigen(const Matrix<T, H>& m) {
  EMatrix<T, H> e;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) e(i, j) = m[i][j];
  return e;
}
template <class T, int H>
Matrix<T, H> from_eigen(const EMatrix<T, H>& e) {
  Matrix<T, H> m;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) m[i][j] = e(i, j);
  return m;
}

// The row of the cofactor matrix of M with the largest sum of squares: a null
// vector when M has rank H - 1 (zero vector when M has rank < H - 1).
template <class T, int H>
EVector<T, H> null_vector(const EMatrix<T, H>& m) {
  EVector<T, H> best = EVector<T, H>::Zero();
  T best_size = T(0) * m(0, 0);
  for (int i = 0; i < H; ++i) {
    EVector<T, H> row;
    for (int j = 0; j < H; ++j) {
      EMatrix<T, H - 1> minor;
      for (int r = 0, rr = 0; r < H; ++r) {
        if (r == i) continue;
        for (int c = 0, cc = 0; c < H; ++c) {
          if (c == j) continue;
          minor(rr, cc++) = m(r, c);
        }
        ++rr;
      }
      T d = minor.determinant();
      row(j) = ((i + j) % 2) ? T(-d) : d;
    }
    T size = row.squaredNorm();
    if (i == 0 || size > best_size) {
      best = row;
      best_size = size;
    }
  }
  return best;
}

}  // namespace eccd
