#pragma once
// Does a fixed plane separate two moving objects for every t in [0, 1]?
// Frame coherence, paper 000 section 4, as two polynomial sign conditions.
//
// Statement. An object is the solid YᵀQY <= 0 in its own frame, moved by the
// homogeneous polynomial motion M(t) (scene-format.md; world X = M(t)Y, last
// row (0, ..., 0, w(t)), w ≠ 0 on [0, 1]). A world plane pᵀX = 0 is the plane
// q(t)ᵀY = 0 in the object's frame, q(t) = M(t)ᵀp (no denominator: a
// homogeneous plane may be scaled). A plane q misses the solid YᵀQY <= 0 iff
// qᵀQ⁻¹q < 0 (the unit sphere diag(1, .., 1, -1): |n|² - o² < 0, distance
// > 1; every ellipsoid is an affine image of it), i.e., since det Q < 0 for
// an ellipse or ellipsoid (signature (+, .., +, -)), iff
//     h(t) = q(t)ᵀ adj(Q) q(t) > 0.
// So the plane misses a(t) for all t in [0, 1] iff h_a > 0 on [0, 1], and
// likewise h_b (the two polynomial sign conditions, degree 2 deg M). If a
// plane never meets a continuously moving solid, the solid's centre never
// crosses it, so the sides need checking at one instant, t = 0: the centre
// of the object in its frame is Y_c = adj(Q) e_d (its last entry is the
// cofactor det Q_dd > 0, the upper-left block being positive definite), in
// the world M(t)Y_c, and the centre lies on the side sign(pᵀM(t)Y_c)·sign(w(t)).
// The plane separates (a strictly negative, b strictly positive, for every t)
// iff h_a > 0 and h_b > 0 on [0, 1], a's side at 0 is negative and b's positive.
//
// Deciding "h > 0 on [0, 1]" (positive_on_unit_interval):
//  - exact T (a proof): all Bernstein coefficients > 0 suffices; otherwise
//    h(0) > 0 and no root of h in [0, 1] (a Sturm count, kernel/sturm.hpp)
//    decides it, and h(0) <= 0 or a root in [0, 1] refutes it.
//  - T with an error bound (Bounded<double>, Bounded<Mpfr>): the Bernstein
//    coefficients on [0, 1], subdivided at midpoints (de Casteljau) to a
//    fixed depth: a piece whose coefficients are all certainly positive is
//    settled; an end value of a piece that is certainly <= 0 refutes (the
//    plane meets the solid there, within the error bound); what is left
//    after the depth is unknown, with the piece named.
// Requirements on T: scalar_traits<T>, ring operations, division by small
// integers (exact rationals, or Bounded<double>/Bounded<Mpfr>).
#include "kernel/bernstein.hpp"
#include "kernel/poly_matrix.hpp"
#include "kernel/ring_determinant.hpp"
#include "kernel/sturm.hpp"

#include <array>
#include <string>
#include <vector>

namespace eccd {

// adj(Q) of a constant matrix, by cofactors (any ring).
template <class T, int H>
Matrix<T, H> adjugate_of(const Matrix<T, H>& q, const T& zero) {
  Matrix<T, H> adj;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      std::vector<std::vector<T>> minor;
      for (int r = 0; r < H; ++r) {
        if (r == j) continue;  // adj = cofactorᵀ: entry (i, j) is the cofactor of (j, i)
        std::vector<T> row;
        for (int c = 0; c < H; ++c)
          if (c != i) row.push_back(q[r][c]);
        minor.push_back(row);
      }
      T d = ring_det(minor, zero);
      adj[i][j] = ((i + j) % 2) ? T(zero - d) : d;
    }
  return adj;
}

// The polynomials of one object against the plane p (see the statement).
template <class T, int H>
struct PlaneAgainstObject {
  Poly<T> miss;  // h(t) = q(t)ᵀ adj(Q) q(t): > 0 iff the plane misses the object at t
  Poly<T> side;  // pᵀ M(t) adj(Q) e_d: times sign w(t), the side of the object's centre
  Poly<T> w;     // M(t)'s last diagonal entry
};

template <class T, int H>
PlaneAgainstObject<T, H> plane_against_object(const Matrix<T, H>& q, const PolyMatrix<T, H>& m,
                                              const std::array<T, H>& p, const T& zero) {
  const Matrix<T, H> adj = adjugate_of<T, H>(q, zero);
  std::array<Poly<T>, H> qt;  // q(t) = M(t)ᵀ p
  for (int i = 0; i < H; ++i) {
    Poly<T> s;
    for (int j = 0; j < H; ++j)
      if (!m[j][i].is_zero() && !is_zero(p[j])) s += p[j] * m[j][i];
    qt[i] = s;
  }
  PlaneAgainstObject<T, H> out;
  for (int i = 0; i < H; ++i) {
    Poly<T> r;  // (adj q)_i
    for (int j = 0; j < H; ++j)
      if (!is_zero(adj[i][j]) && !qt[j].is_zero()) r += adj[i][j] * qt[j];
    if (!r.is_zero() && !qt[i].is_zero()) out.miss += qt[i] * r;
  }
  constexpr int d = H - 1;
  for (int i = 0; i < H; ++i)   // pᵀ M(t) Y_c, Y_c = adj(Q) e_d = column d of adj
    for (int k = 0; k < H; ++k)
      if (!is_zero(p[i]) && !m[i][k].is_zero() && !is_zero(adj[k][d])) out.side += (p[i] * adj[k][d]) * m[i][k];
  out.w = m[d][d];
  return out;
}

enum class OnInterval { positive, not_positive, unknown };

// Is h > 0 on [0, 1]? See the statement; `where` says what was left unknown.
template <class T>
OnInterval positive_on_unit_interval(const Poly<T>& h, std::string& where, int max_depth = 12) {
  if (h.is_zero()) return OnInterval::not_positive;
  const Bern<T> bern = to_bernstein(h);
  if constexpr (scalar_traits<T>::is_exact) {
    (void)max_depth;
    bool all = true;
    for (const T& c : bern.b) all = all && sign(c) == Sign::positive;
    if (all) return OnInterval::positive;
    const T zero(0), one(1);
    if (sign(h(zero)) != Sign::positive) return OnInterval::not_positive;
    return count_roots_closed(h, zero, one) == 0 ? OnInterval::positive : OnInterval::not_positive;
  } else {
    struct Piece { std::vector<T> b; int depth; double lo, hi; };
    std::vector<Piece> todo{{bern.b, 0, 0.0, 1.0}};
    while (!todo.empty()) {
      Piece pc = std::move(todo.back());
      todo.pop_back();
      if (sign(pc.b.front()) == Sign::negative || sign(pc.b.front()) == Sign::zero ||
          sign(pc.b.back()) == Sign::negative || sign(pc.b.back()) == Sign::zero)
        return OnInterval::not_positive;
      bool all = true;
      for (const T& c : pc.b) all = all && sign(c) == Sign::positive;
      if (all) continue;
      if (pc.depth >= max_depth) {
        where = "t in [" + std::to_string(pc.lo) + ", " + std::to_string(pc.hi) +
                "]: a Bernstein coefficient of the plane's polynomial is within its error bound of 0 or negative after " +
                std::to_string(max_depth) + " subdivisions";
        return OnInterval::unknown;
      }
      // de Casteljau at 1/2: left = first entries of the triangle, right = last ones.
      const std::size_t n = pc.b.size();
      std::vector<T> left(n), right(n), w = pc.b;
      const T half = T(1) / T(2);
      for (std::size_t r = 0; r < n; ++r) {
        left[r] = w[0];
        right[n - 1 - r] = w[n - 1 - r];
        for (std::size_t i = 0; i + 1 < n - r; ++i) w[i] = (w[i] + w[i + 1]) * half;
      }
      const double mid = (pc.lo + pc.hi) / 2;
      todo.push_back({std::move(right), pc.depth + 1, mid, pc.hi});
      todo.push_back({std::move(left), pc.depth + 1, pc.lo, mid});
    }
    return OnInterval::positive;
  }
}

}  // namespace eccd
