#pragma once
// Quadric classification: what a symmetric (n+1)x(n+1) matrix Q (n = 2 or 3)
// is as a conic (n = 2) or quadric surface (n = 3) X^T Q X = 0, X = (x, 1).
//
// Statement. Write Q = [[A, b], [b^T, c]] with A the upper-left n x n block.
// The affine type is decided by the eigenvalue signs of A (its inertia) and
// the sign of det Q (classical; e.g. Hilbert & Cohn-Vossen, ch. 1). For A
// positive definite the value at the centre is det Q / det A, so the solid
// X^T Q X <= 0 is a real non-degenerate ellipse/ellipsoid iff det Q < 0; that
// is the only kind a scene accepts (../shared/spec/scene-format.md, "Shape").
// The inertia is counted exactly: the characteristic polynomial of the
// symmetric matrix A has only real roots, so Descartes' rule of signs gives
// the exact number of positive and negative eigenvalues.
// Requirements: exact rationals only (mpq_class).
// Known failure modes: none in exact arithmetic; the determinant is computed
// by fraction-exact Gaussian elimination (n + 1 <= 4, no growth concern).
#include "number/rational_traits.hpp"
#include "kernel/ring_determinant.hpp"
#include "kernel/sign_variations.hpp"

#include <string>
#include <utility>
#include <vector>

namespace eccd {
namespace quadric_detail {

// Numbers of positive, negative and zero eigenvalues of a symmetric rational
// matrix of size 1..3 (Descartes' rule on the real-rooted characteristic
// polynomial det(lambda I - A)).
struct Inertia {
  int pos = 0, neg = 0, zero = 0;
};

inline Inertia symmetric_inertia(const std::vector<std::vector<mpq_class>>& a) {
  const int n = int(a.size());
  // p(lambda) = sum_k (-1)^(n-k) e_{n-k} lambda^k, e_m = sum of principal m-minors.
  std::vector<mpq_class> e(n + 1, mpq_class(0));
  e[0] = 1;
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::vector<int> idx;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i)) idx.push_back(i);
    std::vector<std::vector<mpq_class>> sub(idx.size(), std::vector<mpq_class>(idx.size()));
    for (std::size_t i = 0; i < idx.size(); ++i)
      for (std::size_t j = 0; j < idx.size(); ++j) sub[i][j] = a[idx[i]][idx[j]];
    mpq_class m = ring_det(sub, mpq_class(0));  // kernel/ring_determinant.hpp
    e[idx.size()] += m;
  }
  std::vector<mpq_class> c(n + 1);  // c[k]: coefficient of lambda^k
  for (int k = 0; k <= n; ++k) c[k] = ((n - k) % 2) ? mpq_class(-e[n - k]) : e[n - k];
  Inertia r;
  while (r.zero <= n && sgn(c[r.zero]) == 0) ++r.zero;
  auto variations = [&](bool negate_odd) {  // of c[r.zero..n], with c[k] negated for odd k if asked
    return sign_variations_n(std::size_t(n + 1 - r.zero),
                             [&](std::size_t i) {
                               const int k = r.zero + int(i);
                               return sign_of_int((negate_odd && (k % 2)) ? -sgn(c[k]) : sgn(c[k]));
                             })
        .count;
  };
  r.pos = variations(false);
  r.neg = variations(true);
  return r;
}

}  // namespace quadric_detail

enum class QuadricKind {
  real_ellipsoid,         // the only accepted kind: real, non-degenerate, X^T Q X < 0 inside
  wrong_sign,             // -Q is a real ellipse/ellipsoid
  imaginary,              // no real point
  single_point,           // ellipse/ellipsoid shrunk to a point (det Q = 0)
  hyperbola,              // dim 2
  parabola,               // dim 2
  hyperboloid_one_sheet,  // dim 3
  hyperboloid_two_sheets,
  elliptic_paraboloid,
  hyperbolic_paraboloid,
  degenerate,  // det Q = 0, not a point
};

struct QuadricClass {
  QuadricKind kind;
  std::string description;  // "is a hyperbola", ...; empty for real_ellipsoid
  bool ok() const { return kind == QuadricKind::real_ellipsoid; }
};

// Q: (dim+1) x (dim+1), symmetric (the caller checks), dim = 2 or 3.
inline QuadricClass classify_quadric(const std::vector<std::vector<mpq_class>>& Q, int dim) {
  const bool d2 = dim == 2;
  const std::string ell = d2 ? "ellipse" : "ellipsoid";
  std::vector<std::vector<mpq_class>> A(dim, std::vector<mpq_class>(dim));
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) A[i][j] = Q[i][j];
  const quadric_detail::Inertia in = quadric_detail::symmetric_inertia(A);
  const int D = sgn(ring_det(Q, mpq_class(0)));
  using K = QuadricKind;

  if (in.pos == dim || in.neg == dim) {
    // Definite block. For -Q (size dim+1): det(-Q) = (-1)^(dim+1) det Q.
    const bool negated = in.neg == dim;
    const int Dp = negated ? ((dim + 1) % 2 ? -D : D) : D;
    if (Dp == 0) return {K::single_point, "is a single point (a degenerate " + ell + ", det Q = 0)"};
    if (Dp > 0)
      return {K::imaginary,
              "is an imaginary " + ell + " (no real point: the solid X^T Q X <= 0 would be " +
                  (negated ? std::string(d2 ? "the whole plane" : "all of space") : std::string("the empty set")) +
                  ")"};
    if (negated) return {K::wrong_sign, "has the wrong sign: X^T Q X > 0 inside; negate the matrix"};
    return {K::real_ellipsoid, ""};
  }
  if (d2) {
    if (in.pos == 1 && in.neg == 1)
      return D != 0 ? QuadricClass{K::hyperbola, "is a hyperbola"}
                    : QuadricClass{K::degenerate, "is degenerate (det Q = 0): a pair of intersecting lines"};
    if (in.zero == 1)
      return D != 0 ? QuadricClass{K::parabola, "is a parabola"}
                    : QuadricClass{K::degenerate,
                                   "is degenerate (det Q = 0): a pair of parallel lines, a double line, or empty"};
    return {K::degenerate, "is degenerate (det Q = 0): its upper-left 2x2 block is zero (a line or nothing)"};
  }
  // dim 3, A not definite.
  if (in.zero == 0) {  // indefinite, non-singular block
    if (D > 0) return {K::hyperboloid_one_sheet, "is a hyperboloid of one sheet"};
    if (D < 0) return {K::hyperboloid_two_sheets, "is a hyperboloid of two sheets"};
    return {K::degenerate, "is degenerate (det Q = 0): a cone"};
  }
  if (in.zero == 1) {
    const bool elliptic = in.pos == 2 || in.neg == 2;
    if (D != 0)
      return elliptic ? QuadricClass{K::elliptic_paraboloid, "is an elliptic paraboloid"}
                      : QuadricClass{K::hyperbolic_paraboloid, "is a hyperbolic paraboloid"};
    return {K::degenerate, elliptic ? "is degenerate (det Q = 0): an elliptic cylinder, a line, or empty"
                                    : "is degenerate (det Q = 0): a hyperbolic cylinder or a pair of planes"};
  }
  return {K::degenerate, "is degenerate (det Q = 0): a parabolic cylinder, a pair of planes, a plane, or nothing"};
}

}  // namespace eccd
